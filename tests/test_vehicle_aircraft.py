"""The paper's aircraft at mission nodes: a short GA-2P mission, analysis and optimization,
checked against physics that does not depend on the solver."""
import numpy as np
import pytest

from mdo.core import units as u
from mdo.core.atmosphere import density
from mdo.mission import Mission
from mdo.mission.segments import ConstantSpeedConstantAltitude, LinearSpeedConstantRate
from mdo.nlp import Problem
from mdo.vehicle.aircraft import Aircraft
from mdo.vehicle.catalog import ga2p


def _short_mission(nodes=4, free=("rotor", "wing", "positions"), analysis=False):
    # analysis: the frozen design's design-level limits reported, not enforced (as `mdo run --analysis`):
    # Table 3's blade exceeds the tip-Mach limit in this 160 mph climb with the P2006T's drag
    p = Problem("ga2p_short")
    v = Aircraft(ga2p(), n_stations=10, wing_strips=12, tail_strips=3, free=free,
                 design_point_constraints=not analysis)
    segs = [
        LinearSpeedConstantRate("CL", altitude_start_m=500 * u.FT, altitude_end_m=1500 * u.FT,
                                speed_start_mps=150 * u.MPH, speed_end_mps=160 * u.MPH, climb_rate_mps=500 * u.FT_PER_MIN,
                                nodes=nodes),
        ConstantSpeedConstantAltitude("CR", distance_m=10 * u.NMI, nodes=nodes),
    ]
    m = Mission(v, segs, nodes=nodes).build(p)
    p.minimize(m.energy_used_J / u.KWH, unit="kWh", scale=1.0)
    return p, v, m


@pytest.fixture(scope="module")
def analysis():
    p, v, m = _short_mission(analysis=True)
    p.freeze_design()
    sol = p.solve(verbose=False)
    return p, v, m, sol


def test_analysis_converges_and_balances_forces(analysis):
    p, v, m, sol = analysis
    assert sol.success, sol.status
    ev = m.evaluation.outputs
    L = np.asarray(sol.value(ev["lift_N"].expr)).ravel()
    T = np.asarray(sol.value(ev["thrust_N"].expr)).ravel()
    D = np.asarray(sol.value(ev["drag_N"].expr)).ravel()
    W = float(sol.value(v.togw)) * 9.80665
    cr = [i for i, lab in enumerate(m.labels) if lab.startswith("CR")]
    # level cruise: lift carries the weight and thrust the drag (the rotor axis is within
    # a degree or two of the path, so within 1 %)
    assert L[cr] == pytest.approx(W, rel=0.01)
    assert T[cr] == pytest.approx(D[cr], rel=0.01)
    # a plausible GA airplane at 160 mph: L/D between 10 and 25, propeller efficiency 0.75-0.95
    assert 10 < np.mean(L[cr] / D[cr]) < 25
    eta = np.asarray(sol.value(ev["propulsive_efficiency"].expr)).ravel()[cr]
    assert np.all((eta > 0.75) & (eta < 0.95))


def test_cruise_energy_equals_power_times_time(analysis):
    p, v, m, sol = analysis
    ev = m.evaluation.outputs
    Pb = np.asarray(sol.value(ev["battery_power_W"].expr)).ravel()
    cr = [i for i, lab in enumerate(m.labels) if lab.startswith("CR")]
    t_cr = 10 * u.NMI / (160 * u.MPH)
    seg = np.asarray(sol.value(m.segment_energy_J)).ravel()
    # battery power is nearly constant in cruise (the pack voltage sags slowly)
    assert seg[1] == pytest.approx(np.mean(Pb[cr]) * t_cr, rel=2e-3)


def test_mass_and_geometry_follow_the_design(analysis):
    p, v, m, sol = analysis
    from mdo.vehicle.mass import MassDesign, solve_togw
    # the design is frozen but the motors and the wing's design lift are sized: the gross
    # weight is the build-up at the solved motor rating and design lift (not the catalog's)
    gm = v.groups[0]
    md = MassDesign.baseline(v.config)
    md.motor_rated_power_W = {gm.name: float(sol.value(gm.design["P_rated"]))}
    md.motor_rated_speed_radps = {gm.name: float(sol.value(gm.design["omega_rated"]))}
    md.wing_design_lift_N = {w: float(sol.value(F)) for w, F in v.wing_design_lift.items()}
    assert md.wing_design_lift_N      # the default WingStructure sizes each lifting wing
    assert float(sol.value(v.togw)) == pytest.approx(solve_togw(v.config, md), rel=1e-6)
    # the sized rating meets the largest shaft power the mission asks of a motor (within 1e-6),
    # the climb at the short-time rating (1.2 x, catalog GA_MOTOR), and is active there
    P = np.asarray(sol.value(m.evaluation.outputs["shaft_power_W"].expr)).ravel() / gm.config.count
    f = gm.short_time_row(m.cond)
    assert f[0] == pytest.approx(1.2) and f[-1] == 1.0
    assert float(sol.value(gm.design["P_rated"])) == pytest.approx((P / f).max(), rel=1e-5)
    # reference area held at 14.76 m^2 by the constant-area planform, whatever the span
    from mdo.wing import planform_area
    assert float(np.asarray(sol.value(planform_area(v.vlm.surfaces[0])))) == pytest.approx(14.76, rel=1e-9)


def test_short_optimization_improves_and_keeps_constraints():
    # two stages, as `mdo run` does (DESIGN rule 7): the baseline analysis, then the
    # optimization warm-started from it
    base_p, *_ = _short_mission(free=("rotor", "wing"), analysis=True)
    base_p.freeze_design()
    base = base_p.solve(verbose=False)
    assert base.success, base.status
    p, v, m = _short_mission(free=("rotor", "wing"))
    p.warm_start(base)
    sol = p.solve(verbose=False, max_iter=300)
    assert sol.success, sol.status
    e0, e1 = base.summary_values()["battery_energy_kWh"], sol.summary_values()["battery_energy_kWh"]
    assert e1 < e0
    assert float(sol.value(v.tip_mach_design)) <= 0.6 + 1e-6
    assert max(vv["scaled"] for vv in sol.violations) < 1e-5
