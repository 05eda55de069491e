"""Full profiles of Table 5 end to end, the problem file through the run harness, and the
vehicle protocol with a vehicle written from scratch (multi-row unknowns, residuals, two states)."""
import csv
import json
import math
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

from mdo.core import InputError, density
from mdo.core.units import KWH, LB, MPH, NMI, RPM
from mdo.mission import Mission
from mdo.mission import segments as S
from mdo.mission.profiles import evtol_mission, ga_mission
from mdo.nlp import Problem, load_problem_file, run_problem
from mdo.vehicle import G0, NodeEvaluation, Output, PolarVehicle, ResidualGroup, State, Unknown, Vehicle

ROOT = Path(__file__).resolve().parents[1]


def test_polar_ga_problem_file_runs_and_writes_the_mission_report(tmp_path):
    prob = load_problem_file(ROOT / "problems" / "polar_ga_mission.py")
    sol = run_problem(prob, tmp_path / "run", verbose=False)
    assert sol.success, sol.status
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert summary["battery_energy_kWh"] == pytest.approx(sol.objective)
    assert 40 < summary["battery_energy_kWh"] < 90          # an X-57-sized airplane over the GA profile
    # range: 50 + 5 nmi of cruise plus the horizontal distance of the other segments
    assert 80 < summary["mission_range_nmi"] < 100
    rows = list(csv.DictReader(open(tmp_path / "run" / "mission.csv")))
    assert {r["segment"] for r in rows} == {"DER", "ICA", "CL", "CR", "D", "DL", "RCL", "RCR", "RD", "BL", "FA"}
    soc = np.array([float(r["state_of_charge"]) for r in rows])
    assert soc[0] == 1.0 and np.all(np.diff(soc) <= 1e-12) and soc[-1] > 0.3
    segs = list(csv.DictReader(open(tmp_path / "run" / "mission_segments.csv")))
    assert sum(float(s["energy_kWh"]) for s in segs) == pytest.approx(summary["battery_energy_kWh"], rel=1e-9)
    assert (tmp_path / "run" / "mission.png").exists()


def test_polar_ga_problem_file_optimizes_wing_area_and_analysis_freezes_it(tmp_path):
    opt = load_problem_file(ROOT / "problems" / "polar_ga_mission.py", options={"design_wing_area": True})
    sol = opt.solve(verbose=False)
    ana = load_problem_file(ROOT / "problems" / "polar_ga_mission.py", analysis=True,
                            options={"design_wing_area": True})
    base = ana.solve(verbose=False)
    assert sol.success and base.success
    assert base["ga_polar.wing_area"] == pytest.approx(14.76)
    assert sol["ga_polar.wing_area"] < 14.76                    # no wing weight in this polar: a smaller wing
    assert sol["battery_energy_kWh"] < base["battery_energy_kWh"]


def test_evtol_profile_with_a_tilt_wing_polar_vehicle(tmp_path):
    m_kg = 4850 * LB
    veh = PolarVehicle("ttw_polar", mass_kg=m_kg, wing_area_m2=21.7, CD0=0.03, aspect_ratio=9.6 ** 2 / 10.85,
                       oswald_efficiency=0.8, CL_max=1.5, flat_plate_drag_coefficient=1.2, wing_tilts=True,
                       propulsive_efficiency=0.8, chain_efficiency=0.9, disk_area_m2=8 * math.pi * 1.2 ** 2,
                       min_thrust_N=-0.5 * m_kg * G0, battery_capacity_J=150 * 120 * 3.55 * 3.6 * 3600)
    p = Problem("evtol")
    m = evtol_mission(veh).build(p)
    p.minimize(m.energy_used_J / KWH, unit="kWh")
    sol = p.solve(verbose=False)
    assert sol.success, sol.violation_report()
    m.report(sol, tmp_path)
    rows = list(csv.DictReader(open(tmp_path / "mission.csv")))
    vc = [r for r in rows if r["segment"] == "VC"]
    assert all(abs(float(r["body_angle_deg"])) < 1e-6 for r in vc)          # rotors vertical, thrust = W + drag
    assert all(float(r["wing_mounted_angle_deg"]) == pytest.approx(90) for r in vc)
    cr = [r for r in rows if r["segment"] == "CR"]
    assert all(float(r["pitch_command_deg"]) == pytest.approx(20) for r in cr)
    # the vertical climb draws more than the 175 mph cruise (momentum theory vs wing-borne flight)
    p_vc = np.mean([float(r["battery_power_W"]) for r in vc])
    p_cr = np.mean([float(r["battery_power_W"]) for r in cr])
    assert p_vc > 1.3 * p_cr


class TwoRotorVehicle:
    """A vehicle written against the protocol only: two rotor groups (front, rear) with
    thrust T_i = c_T rho Omega_i^2 as residuals, power c_Q rho Omega_i^3, and two states."""

    name = "two_rotor"
    parameters = {}
    reference_mass_kg = 1200.0

    def __init__(self):
        self.cT, self.cQ, self.S, self.CD0, self.k, self.cla = 0.05, 0.004, 12.0, 0.03, 0.05, 5.0
        self.capacity_C = 3600.0 * 200.0
        self.voltage = 400.0

    def setup(self, problem):
        pass

    def unknowns(self):
        return [Unknown("rotor_speed", unit="rad/s", scale=200.0, lower=1.0, upper=600.0, rows=2,
                        row_labels=["front", "rear"]),
                Unknown("group_thrust", unit="N", scale=500.0, lower=0.0, rows=2, row_labels=["front", "rear"])]

    def states(self):
        return [State("energy", unit="J", scale=1e7, initial=0.0), State("charge", unit="C", scale=1e5, initial=0.0)]

    def energy_used_J(self, initial, final):
        return final["energy"] - initial["energy"]

    def initial_guess(self, nodes):
        K = nodes.size
        return {"rotor_speed": np.full((2, K), 100.0), "group_thrust": np.full((2, K), 600.0),
                "body_angle_rad": np.full(K, 0.05)}

    def evaluate(self, nodes, unknowns):
        rho = density(nodes.altitude_m)
        W = unknowns["rotor_speed"]
        T = unknowns["group_thrust"]
        q = 0.5 * rho * nodes.speed_mps ** 2
        a = nodes.body_angle_rad - nodes.flight_path_angle_rad
        CL = self.cla * a
        L, D = q * self.S * CL, q * self.S * (self.CD0 + self.k * CL ** 2)
        Tsum = T[0, :] + T[1, :]
        P = self.cQ * ca.repmat(rho, 2, 1) * W ** 3
        Ptot = P[0, :] + P[1, :]
        return NodeEvaluation(
            mass_kg=self.reference_mass_kg, force_along_path_N=Tsum * ca.cos(a) - D,
            force_normal_N=Tsum * ca.sin(a) + L, force_scale_N=self.reference_mass_kg * G0,
            residuals=[ResidualGroup("rotor_thrust", T - self.cT * ca.repmat(rho, 2, 1) * W ** 2, scale=500.0,
                                     unit="N", row_labels=["front", "rear"])],
            state_derivatives={"energy": Ptot, "charge": Ptot / self.voltage},
            outputs={"rotor_speed_rpm": Output(W / RPM, "rpm"), "battery_power_W": Output(Ptot, "W"),
                     "thrust_N": Output(Tsum, "N")})


def test_a_vehicle_written_against_the_protocol(tmp_path):
    veh = TwoRotorVehicle()
    assert isinstance(veh, Vehicle)                               # the runtime-checkable protocol
    segs = [S.LinearSpeedConstantRate("CL", altitude_start_m=100.0, altitude_end_m=600.0, speed_start_mps=40.0,
                                      speed_end_mps=50.0, climb_rate_mps=2.5),
            S.ConstantSpeedConstantAltitude("CR", distance_m=10e3)]
    p = Problem("proto")
    m = Mission(veh, segs, nodes=5).build(p)
    p.minimize(m.energy_used_J / 1e6, unit="MJ")
    sol = p.solve(verbose=False)
    assert sol.success, sol.violation_report()
    w = sol["rotor_speed"]
    assert w.shape == (2, 10)
    np.testing.assert_allclose(w[0], w[1], rtol=1e-6)            # P ~ Omega^3 is convex: equal split is optimal
    assert "rotor_thrust" in p.groups and p.groups["rotor_thrust"].labels[:2] == ["CL node 0 front",
                                                                                   "CL node 0 rear"]
    E, Q = sol.value(m.final_states["energy"]), sol.value(m.final_states["charge"])
    assert Q == pytest.approx(E / veh.voltage, rel=1e-9)
    m.report(sol, tmp_path)
    header = open(tmp_path / "mission.csv").readline().strip().split(",")
    assert "rotor_speed_rpm[0]" in header and "rotor_speed_rpm[1]" in header and "charge" in header


def test_vehicle_missing_a_state_derivative_is_reported():
    veh = TwoRotorVehicle()
    orig = veh.evaluate

    def broken(nodes, unknowns):
        ev = orig(nodes, unknowns)
        ev.state_derivatives.pop("charge")
        return ev

    veh.evaluate = broken
    with pytest.raises(InputError, match="charge"):
        Mission(veh, [S.ConstantSpeedConstantAltitude("CR", speed_mps=50, altitude_m=100, distance_m=1e4)],
                nodes=4).build(Problem("x"))
