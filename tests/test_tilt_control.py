"""A control that takes over a segment parameter (the tilt-wing's wing-mounted angle):
continuity at segment joins, the rate limit, and what it is worth.

The toy vehicle flies level with its thrust and wing turned by a tilt ``delta`` against
the body: the wing's lift and the thrust see ``a + delta`` (a the body's angle of attack),
the fuselage's drag sees ``a`` alone, so a free tilt lets the cabin fly level while the
wing sits at its own best angle, and the schedule (delta = 0) cannot.
"""
import math
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

from mdo.core import InputError, density
from mdo.mission import Mission
from mdo.mission import segments as S
from mdo.nlp import Problem
from mdo.vehicle import G0, NodeEvaluation, Output, State, Unknown

MAX_RATE = math.radians(0.1)   # slow enough that the actuator shapes the whole of segment B


class TiltingToy:
    name = "tilting_toy"
    parameters = {"tilt_rad": 0.0, "tilt_free": 0.0}
    reference_mass_kg = 1000.0

    def __init__(self, control=True):
        self.control = control
        self.S, self.cla, self.CD0, self.k, self.k_body = 10.0, 5.0, 0.02, 0.05, 2.0

    def setup(self, problem):
        pass

    def unknowns(self):
        out = [Unknown("thrust", unit="N", scale=1e3, lower=0.0, upper=1e5)]
        if self.control:
            out.append(Unknown("tilt", unit="rad", scale=0.1, lower=-0.5, upper=0.5, only_where="tilt_free",
                               replaces="tilt_rad", max_rate=MAX_RATE))
        return out

    def states(self):
        return [State("energy", unit="J", scale=1e7, initial=0.0)]

    def energy_used_J(self, initial, final):
        return final["energy"] - initial["energy"]

    def initial_guess(self, nodes):
        K = nodes.size
        return {"thrust": np.full(K, 800.0), "body_angle_rad": np.full(K, 0.05), "tilt": np.zeros(K)}

    def evaluate(self, nodes, unknowns):
        K = nodes.size
        on = np.asarray(nodes.parameters["tilt_free"], float).ravel() * np.ones(K) > 0
        tilt = nodes.parameters["tilt_rad"]
        if self.control:
            tilt = unknowns["tilt"] + ca.DM((1.0 - on).reshape(1, -1)) * tilt
        a = nodes.body_angle_rad - nodes.flight_path_angle_rad
        q = 0.5 * density(nodes.altitude_m) * nodes.speed_mps ** 2
        CL = self.cla * (a + tilt)
        D = q * self.S * (self.CD0 + self.k * CL ** 2 + self.k_body * a ** 2)   # the fuselage sees a only
        T = unknowns["thrust"]
        return NodeEvaluation(
            mass_kg=self.reference_mass_kg, force_along_path_N=T * ca.cos(a + tilt) - D,
            force_normal_N=T * ca.sin(a + tilt) + q * self.S * CL, force_scale_N=self.reference_mass_kg * G0,
            residuals=[], state_derivatives={"energy": T * nodes.speed_mps},
            outputs={"tilt_deg": Output(tilt * ca.DM.ones(1, K) * 180 / math.pi, "deg")})


def _fly(control):
    segs = [S.ConstantSpeedConstantAltitude("A", speed_mps=40.0, altitude_m=500.0, distance_m=2000.0,
                                            parameters={"tilt_rad": 0.0}),
            S.ConstantSpeedConstantAltitude("B", distance_m=4000.0, parameters={"tilt_rad": 0.0, "tilt_free": 1.0})]
    p = Problem("tilt_toy")
    m = Mission(TiltingToy(control), segs, nodes=8).build(p)
    p.minimize(m.energy_used_J / 1e6, unit="MJ")
    sol = p.solve(verbose=False)
    assert sol.success, sol.violation_report()
    return p, m, sol


def test_a_tilt_control_is_continuous_rate_limited_and_buys_a_level_cabin():
    p_s, m_s, sol_s = _fly(False)
    p, m, sol = _fly(True)
    tilt = np.asarray(sol.value(m.report_rows()["tilt_deg"][0])).ravel()
    nB = slice(8, 16)
    # continuity: B starts where A's schedule ends (0), then tilts at no more than the rate
    assert tilt[8] == pytest.approx(0.0, abs=1e-8)
    assert "tilt continuity" in p.groups and p.groups["tilt continuity"].labels == ["A/B"]
    T_B = 4000.0 / 40.0
    from mdo.core import Collocation
    rate = np.radians(tilt[nB]) @ Collocation(8).D.T / T_B
    assert np.max(np.abs(rate)) <= MAX_RATE * (1 + 1e-6)
    assert np.max(np.abs(rate)) == pytest.approx(MAX_RATE, rel=1e-4)     # the actuator limits it
    # the free tilt flies a more level cabin and needs less energy than the schedule
    theta_B = np.asarray(sol.value(m.theta)).ravel()[nB]
    theta_s = np.asarray(sol_s.value(m_s.theta)).ravel()[nB]
    assert abs(theta_B[-1]) < 0.2 * abs(theta_s[-1])
    assert tilt[15] > 1.0
    assert sol.objective < sol_s.objective * (1 - 1e-3)


def test_a_replacing_control_names_a_parameter_the_mission_knows():
    class Bad(TiltingToy):
        def unknowns(self):
            return [Unknown("thrust", unit="N", scale=1e3, lower=0.0),
                    Unknown("tilt", unit="rad", only_where="tilt_free", replaces="no_such_parameter",
                            max_rate=MAX_RATE)]
    segs = [S.ConstantSpeedConstantAltitude("A", speed_mps=40.0, altitude_m=500.0, distance_m=2000.0,
                                            parameters={"tilt_free": 1.0})]
    with pytest.raises(InputError, match="no_such_parameter"):
        Mission(Bad(), segs, nodes=5).build(Problem("bad"))


def test_the_tilt_wing_flies_its_transitions_tilt_as_a_control():
    """The TTW with ``tilt="control"``: the wing_tilt variable exists at the transition
    nodes only, is continuous at every join of a transition with its neighbours, rate-limited
    by the wings' actuator, and the rotors of every tilt-controlled node are azimuth-averaged
    (AT's scheduled angle is 0, where the schedule flies them axial)."""
    from mdo.mission.profiles import evtol_mission
    from mdo.vehicle.aircraft import Aircraft
    from mdo.vehicle.catalog import ttw

    cfg = ttw()
    v = Aircraft(cfg, free=(), n_stations=6, n_azimuth=2, wing_strips=4, tail_strips=2, limits=False,
                 design_point_constraints=False, tilt="control")
    p = Problem("ttw_tilt")
    m = evtol_mission(v, nodes=3).build(p)
    assert p.groups["wing_tilt continuity"].labels == ["VC/VT", "VT/CT1", "CT1/CT2", "CT2/CL", "RD/AT", "AT/DT",
                                                       "DT/VD"]
    from mdo.core import Collocation
    between = Collocation(3).between_nodes()                # the nodes and 3 points inside each interval
    assert p.groups["wing_tilt rate"].size == 2 * 5 * len(between) == 2 * 5 * 9
    assert p.groups["wing_tilt rate"].labels[:2] == ["VT node 0 rising", "VT s=0.125 rising"]
    var = p.variables["wing_tilt"]
    assert var.shape == (1, 5 * 3)
    np.testing.assert_allclose(var.lower, 0.0)
    np.testing.assert_allclose(var.upper, math.pi / 2)                 # WingConfig.tilt_range_deg (0, 90)
    assert var.labels[0] == "VT node 0" and var.labels[-1] == "DT node 2"
    assert "rotors BEMT (azimuth-averaged)" in p.groups
    at_nodes = [i for i, lab in enumerate(m.labels) if lab.startswith("AT ")]
    assert set(at_nodes) <= set(int(c) for c in v.tilt_control_nodes(m.cond.parameters, m.K).nonzero()[0])
    with pytest.raises(InputError, match="tilt"):
        Aircraft(cfg, tilt="sometimes")


def _ttw_problem_file():
    import importlib.util
    root = Path(__file__).resolve().parents[1]
    spec = importlib.util.spec_from_file_location("ttw_problem_file", root / "problems" / "ttw.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod, root


def test_the_ttw_keeps_its_cabin_in_a_passenger_airplanes_attitude_envelope_by_default():
    """problems/ttw.py: with the transitions' tilt a control (default) the body's attitude is bounded
    to the cabin envelope (15 deg nose-down, 30 deg nose-up) at every node; on Table 5's schedule the
    eVTOL profile's own box; a stated limit is symmetric."""
    from mdo.mission.profiles import CABIN_ATTITUDE_ENVELOPE_RAD
    mod, _ = _ttw_problem_file()
    assert mod.cabin_attitude_bounds_rad("control", None) == CABIN_ATTITUDE_ENVELOPE_RAD
    np.testing.assert_allclose(np.degrees(CABIN_ATTITUDE_ENVELOPE_RAD), (-15.0, 30.0))
    assert mod.cabin_attitude_bounds_rad("schedule", None) is None
    np.testing.assert_allclose(mod.cabin_attitude_bounds_rad("schedule", 20.0), np.radians((-20.0, 20.0)))
    assert mod.OPTIONS["tilt"][1] == "control"
    assert [step["tilt"] for step in mod.RELAXED_OPTIONS] == ["schedule", "schedule"]
    assert mod.RELAXED_OPTIONS[0]["limits"] is False and "limits" not in mod.RELAXED_OPTIONS[1]


def test_a_schedule_flown_start_hands_its_excess_attitude_to_the_wing_tilt():
    """The relaxed start flies Table 5's tilt schedule; ``attitude_into_tilt`` clips the body angle to
    the cabin envelope, holds it level within each transition (its mean there: no pitch rate) and adds
    what it moved to the schedule's wing-mounted angle, so the wing and the rotors keep their angle to
    the flight path (body + tilt unchanged at every transition node)."""
    import json
    from mdo.mission.profiles import CABIN_ATTITUDE_ENVELOPE_RAD, evtol_segments
    mod, root = _ttw_problem_file()
    run = root / "results" / "ttw" / "tilt_schedule" / "analysis"
    sol = json.loads((run / "solution.json").read_text())
    body0 = next(v for v in sol["variables"] if v["name"] == "body_angle")
    theta0, labels = np.asarray(body0["value"], float).ravel(), list(body0["labels"])
    assert theta0.max() > math.radians(60)            # the schedule pitched the cabin to 64 deg
    out = mod.attitude_into_tilt(run, sol, CABIN_ATTITUDE_ENVELOPE_RAD)
    var = {v["name"]: v for v in out["variables"]}
    theta = np.asarray(var["body_angle"]["value"], float).ravel()
    lo, hi = CABIN_ATTITUDE_ENVELOPE_RAD
    assert lo <= theta.min() and theta.max() <= hi
    wma = {s.name: s.parameters["wing_mounted_angle_rad"] for s in evtol_segments()
           if s.parameters.get("wing_tilt_control")}
    tilt = np.asarray(var["wing_tilt"]["value"], float).ravel()
    tilted = [lab for lab in labels if lab.split()[0] in wma]
    assert tilt.size == len(tilted) == 30
    for k, lab in enumerate(tilted):
        i = labels.index(lab)
        assert theta[i] + tilt[k] == pytest.approx(theta0[i] + wma[lab.split()[0]], abs=1e-12)
    keep = [i for i, lab in enumerate(labels) if lo <= theta0[i] <= hi and lab.split()[0] not in wma]
    np.testing.assert_array_equal(theta[keep], theta0[keep])
    for seg in wma:                                   # level within each transition
        k = [i for i, lab in enumerate(labels) if lab.split()[0] == seg]
        assert np.ptp(theta[k]) == 0.0


@pytest.mark.parametrize("limits", [False, True])
def test_the_ttw_hook_resizes_the_motors_only_after_a_step_flown_without_limits(tmp_path, limits):
    """``relaxed_start`` reads how the step it hands on from was flown (its summary.json options):
    after the limit-free step the motors are re-sized to that mission; after the step with every
    limit on (the tilt schedule's baseline) the converged ratings are kept; with the next solve's
    tilt a control the attitude goes into the tilt either way."""
    import json
    import shutil
    from mdo.nlp.run import build_options
    mod, root = _ttw_problem_file()
    run = tmp_path / "step"
    shutil.copytree(root / "results" / "ttw" / "tilt_schedule" / "analysis", run)
    summary = json.loads((run / "summary.json").read_text())
    summary["options"] = build_options(mod, {"limits": limits, "tilt": "schedule"}, analysis=True)
    (run / "summary.json").write_text(json.dumps(summary))
    sol = json.loads((run / "solution.json").read_text())
    before = {v["name"]: np.ravel(v["value"]).tolist() for v in sol["variables"]}
    out = mod.relaxed_start(run, sol, build_options(mod, {}, analysis=True))
    after = {v["name"]: np.ravel(v["value"]).tolist() for v in out["variables"]}
    assert (after["rotors.motor_rated_power"] == before["rotors.motor_rated_power"]) == limits
    assert "wing_tilt" in after and max(after["body_angle"]) <= math.radians(30) + 1e-12



def _decelerate(max_rate):
    """Level flight at 40 m/s (A), then a deceleration to 25 m/s (B) on the tilt schedule: the
    body angle is the wing's only angle, so it pitches up through B as the speed falls."""
    segs = [S.ConstantSpeedConstantAltitude("A", speed_mps=40.0, altitude_m=500.0, distance_m=2000.0),
            S.ConstantAccelerationConstantAltitude("B", speed_end_mps=25.0, acceleration_mps2=-0.15)]
    p = Problem("pitch_rate_toy")
    m = Mission(TiltingToy(False), segs, nodes=8, max_body_pitch_rate_radps=max_rate).build(p)
    p.minimize(m.energy_used_J / 1e6, unit="MJ")
    return p, m, p.solve(verbose=False)


def test_a_body_pitch_rate_limit_holds_at_every_free_node():
    p0, m0, sol0 = _decelerate(None)
    assert sol0.success and "body pitch rate" not in p0.groups
    rate0 = np.asarray(sol0.value(m0.report_rows()["body_pitch_rate_radps"][0])).ravel()
    theta0 = np.asarray(sol0.value(m0.theta)).ravel()
    from mdo.core import Collocation
    assert np.allclose(rate0[8:], theta0[8:] @ Collocation(8).D.T / 100.0, atol=1e-10)   # B lasts 100 s
    q_nat = float(np.max(np.abs(rate0)))
    assert q_nat > math.radians(0.02)                  # the deceleration pitches the body up
    p, m, sol = _decelerate(2.0 * q_nat)               # a loose limit leaves the optimum alone
    assert sol.success and len(p.groups["body pitch rate"].labels) == 2 * 2 * 29    # 8 nodes + 7 x 3 between
    assert sol.objective == pytest.approx(sol0.objective, rel=1e-8)
    p, m, sol = _decelerate(0.5 * q_nat)               # a tight one: the wing's angle cannot follow
    assert not sol.success
    assert "body pitch rate" in sol.violation_report()


def test_a_body_pitch_rate_limit_names_its_range():
    segs = [S.ConstantSpeedConstantAltitude("A", speed_mps=40.0, altitude_m=500.0, distance_m=2000.0)]
    with pytest.raises(InputError, match="max_body_pitch_rate_radps"):
        Mission(TiltingToy(True), segs, max_body_pitch_rate_radps=-0.1)
