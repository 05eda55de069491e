"""Free trajectory (issue 22): speeds and durations as controls, the envelope as constraints.

The optima are checked against steady-flight optima computed independently here (scipy
on the polar vehicle's force balance), not against the NLP's own numbers."""
import math

import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

from mdo.core.atmosphere import density
from mdo.core.errors import InputError
from mdo.core.units import KWH
from mdo.mission.segments import (ConstantAccelerationConstantAltitude as Accel,
                                  ConstantSpeedConstantAltitude as Cruise, LinearSpeedConstantRate as Climb,
                                  VerticalAscent)
from mdo.mission.trajectory import Envelope
from mdo.mission.transcription import Mission
from mdo.nlp import Problem
from mdo.vehicle import PolarVehicle

S_M2, MASS_KG = 15.0, 1500.0
W = MASS_KG * 9.80665


def _vehicle(**kw):
    return PolarVehicle(mass_kg=MASS_KG, wing_area_m2=S_M2, CD0=0.025, aspect_ratio=9, oswald_efficiency=0.8, **kw)


def _solve(vehicle, segs, **mission_kw):
    p = Problem("free_trajectory")
    m = Mission(vehicle, segs, **mission_kw).build(p)
    p.minimize(m.energy_used_J / KWH, unit="kWh")
    sol = p.solve(verbose=False)
    assert sol.success, sol.status
    return p, m, sol


def _axial_power_W(veh, V, rho, climb_rate=0.0, accel=0.0):
    """Steady flight of the polar vehicle at V: thrust along the body axis (alpha = theta -
    gamma, no incidences), T cos(a) - D - W sin(g) = 0, L + T sin(a) - W cos(g) = 0;
    returns T V cos(a), the vehicle's ideal power (its battery power x efficiencies)."""
    g = math.asin(climb_rate / V)
    q = 0.5 * rho * V ** 2

    def forces(a):
        CL = veh.CL_alpha * a
        T = (q * S_M2 * (veh.CD0 + veh.k * CL ** 2) + W * math.sin(g) + MASS_KG * accel) / math.cos(a)
        return T, q * S_M2 * CL + T * math.sin(a) - W * math.cos(g)

    a = brentq(lambda a: forces(a)[1], 0.0, 0.75, xtol=1e-14)
    return forces(a)[0] * V * math.cos(a)


def test_free_cruise_flies_the_independent_best_range_speed():
    """1000 km at 1000 m between two short free transitions from and back to 60 m/s: the
    cruise speed is the speed of least thrust power per metre (best range at constant
    efficiencies), found here by scipy on the steady force balance: 47.94 m/s."""
    veh = _vehicle()
    segs = [Accel("A", speed_start_mps=60.0, speed_end_mps=55.0, altitude_m=1000.0, distance_m=5e3),
            Cruise("CR", distance_m=1000e3), Accel("B", speed_end_mps=60.0, distance_m=5e3)]
    _, m, sol = _solve(veh, segs, trajectory="free")
    V = np.asarray(sol.value(m.cond.speed_mps)).ravel()
    cr = [k for k, s in enumerate(m.segment_of_node) if s == "CR"]
    rho = float(density(1000.0))
    best = minimize_scalar(lambda v: _axial_power_W(veh, v, rho) / v, bounds=(30, 80), method="bounded",
                           options={"xatol": 1e-8}).x
    assert np.ptp(V[cr]) < 1e-9                        # a constant-speed kind keeps one speed
    assert abs(V[cr[0]] - best) / best < 5e-4, (V[cr[0]], best)
    # the trip's ground distance is the profile's
    assert abs(float(sol.value(m.range_m)) - 1010e3) < 1e-3


def test_free_climb_speed_follows_the_independent_minimum_power_speed():
    """A 3000 m climb at the prescribed 2.5 m/s (``"speed"``: duration kept, speed free,
    linear in time): at every node the speed is within 0.6 % of the steady minimum-power
    speed at that node's altitude (the profile is linear, V_mp(h) slightly convex)."""
    veh = _vehicle()
    segs = [Accel("A", speed_start_mps=31.0, speed_end_mps=32.0, altitude_m=0.0, duration_s=30.0),
            Climb("CL", altitude_end_m=3000.0, climb_rate_mps=2.5, speed_end_mps=35.0),
            Accel("B", speed_end_mps=36.0, duration_s=30.0)]
    p, m, sol = _solve(veh, segs, trajectory={"A": "free", "CL": "speed", "B": "free"}, legs=[], nodes=8,
                       envelope=Envelope(min_climb_gradient=0.0))
    V = np.asarray(sol.value(m.cond.speed_mps)).ravel()
    h = np.asarray(m.cond.altitude_m).ravel()
    cl = [k for k, s in enumerate(m.segment_of_node) if s == "CL"]
    assert "CL.duration" not in p.variables and "A.duration" in p.variables   # the climb's duration is kept
    for k in cl:
        rho = float(density(h[k]))
        v_mp = minimize_scalar(lambda v: _axial_power_W(veh, v, rho, 2.5), bounds=(15, 60), method="bounded",
                               options={"xatol": 1e-8}).x
        assert abs(V[k] - v_mp) / v_mp < 6e-3, (k, h[k], V[k], v_mp)
    # the node power is the independent power at the node's speed and acceleration (the
    # path-angle rate's share of the normal force, ~1e-5 g, is left out here)
    P = np.asarray(sol.value(m.evaluation.outputs["battery_power_W"].expr)).ravel()
    accel = (V[cl[-1]] - V[cl[0]]) / 1200.0
    for k in cl:
        ref = _axial_power_W(veh, V[k], float(density(h[k])), 2.5, accel) / (veh.eta_p * veh.eta_chain)
        assert abs(P[k] - ref) / ref < 1e-4, (k, P[k], ref)


def test_envelope_holds_at_every_node_and_the_block_time_binds():
    """A climb-cruise-descent mission, free: stall margin, climb gradient, rates and load
    factor hold at every node; a block-time limit shorter than the free optimum's
    duration binds and costs energy."""
    veh = _vehicle(CL_max=1.6)
    segs = [Climb("CL", altitude_start_m=0.0, speed_start_mps=45.0, altitude_end_m=1000.0, climb_rate_mps=4.0,
                  speed_end_mps=55.0),
            Cruise("CR", distance_m=100e3),
            Climb("D", altitude_end_m=0.0, climb_rate_mps=-3.0, speed_end_mps=45.0)]
    p, m, sol = _solve(veh, segs, trajectory="free")
    env = Envelope()
    V = np.asarray(sol.value(m.cond.speed_mps)).ravel()
    gam = np.asarray(sol.value(m.cond.flight_path_angle_rad)).ravel()
    h = np.asarray(m.cond.altitude_m).ravel()
    vs = np.sqrt(2 * W * np.cos(gam) / (density(h) * S_M2 * 1.6))
    assert np.all(V >= env.stall_speed_factor * vs - 1e-6)
    hdot = V * np.sin(gam)
    assert np.all(hdot <= env.max_climb_rate_mps + 1e-6) and np.all(hdot >= -env.max_descent_rate_mps - 1e-6)
    cl = [k for k, s in enumerate(m.segment_of_node) if s == "CL"]
    assert np.all(np.sin(gam[cl]) >= env.min_climb_gradient - 1e-7)
    for g in ("stall speed margin", "climb gradient", "climb rate", "descent rate", "normal load factor",
              "ground distance"):
        assert g in p.groups, g
    t_free, e_free = float(sol.value(m.duration_s)), sol.objective
    _, m2, sol2 = _solve(veh, segs, trajectory="free", envelope=Envelope(max_block_time_s=0.9 * t_free))
    assert float(sol2.value(m2.duration_s)) <= 0.9 * t_free + 1e-6
    assert sol2.objective > e_free
    assert any(a["name"] == "block time" for a in sol2.active)


def test_prescribed_is_the_default_and_adds_nothing():
    veh = _vehicle()
    segs = [Cruise("CR", speed_mps=50.0, altitude_m=500.0, distance_m=20e3)]
    p = Problem("prescribed")
    Mission(veh, segs).build(p)
    assert not any(n.endswith(".speed_end") or n.endswith(".duration") for n in p.variables)
    assert "ground distance" not in p.groups


@pytest.mark.parametrize("trajectory, legs, field", [
    ({"XX": "free"}, None, "trajectory"),
    ({"CR": "fast"}, None, "trajectory['CR']"),
    ({"VC": "free"}, None, "trajectory['VC']"),
    ("loose", None, "trajectory"),
    ("free", [["CR", "VC"]], "legs"),
    ("free", [["VC"], ["VC"]], "legs"),
])
def test_bad_trajectory_input_names_the_field(trajectory, legs, field):
    veh = _vehicle(disk_area_m2=4.0)
    segs = [VerticalAscent("VC", altitude_start_m=0.0, altitude_end_m=10.0, climb_rate_mps=1.0),
            Cruise("CR", speed_mps=50.0, distance_m=20e3)]
    with pytest.raises(InputError) as exc:
        Mission(veh, segs, trajectory=trajectory, legs=legs)
    assert exc.value.field == field


def test_envelope_values_are_checked():
    with pytest.raises(InputError, match="envelope.stall_speed_factor"):
        Envelope(stall_speed_factor=0.5)
    with pytest.raises(InputError, match="envelope.duration_range"):
        Envelope(duration_range=(2.0, 3.0))


def test_the_problems_climb_gradient_rule_is_an_option():
    """`-o min_climb_gradient_pct=G` (percent) reaches the envelope; out of range is refused."""
    from mdo.studies import TRAJECTORY_OPTIONS, trajectory_envelope
    assert trajectory_envelope().min_climb_gradient == pytest.approx(0.083)
    assert trajectory_envelope(None, 3.0).min_climb_gradient == pytest.approx(0.03)
    assert trajectory_envelope(40.0, 5.0).max_block_time_s == pytest.approx(2400.0)
    assert TRAJECTORY_OPTIONS["min_climb_gradient_pct"] == (float, 0.0, 50.0)
    with pytest.raises(InputError, match="envelope.min_climb_gradient"):
        trajectory_envelope(None, 60.0)
