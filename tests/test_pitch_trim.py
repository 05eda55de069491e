"""Longitudinal balance: pitching moment about the CG, neutral point, static margin, pitch trim."""
import math
from dataclasses import replace

import casadi as ca
import numpy as np
import pytest

from mdo.core import units as u
from mdo.core.errors import InputError
from mdo.mission import Mission
from mdo.mission.segments import ConstantSpeedConstantAltitude, LinearSpeedConstantRate, VerticalAscent
from mdo.nlp import Problem
from mdo.vehicle.aircraft import Aircraft
from mdo.vehicle.balance import neutral_point_x, pitching_moment_about_cg
from mdo.vehicle.catalog import ga2p, ttw
from mdo.vehicle.config import FuselageConfig, WingConfig
from mdo.wing import VLM, trapezoid

SMALL = dict(n_stations=8, wing_strips=10, tail_strips=3)
NO_FUSELAGE = FuselageConfig(length_m=8.0, width_m=1.0, height_m=1.5, wetted_area_m2=30.0, tail_arm_m=4.0,
                             pitching_moment_factor=0.0)


def _lattice(with_tail: bool):
    surfaces = [trapezoid("wing", 10.0, 1.0, 1.0, nspan=16, origin=(2.0, 0.0, 1.0))]
    if with_tail:
        surfaces.append(trapezoid("tail", 3.0, 0.8, 1.0, nspan=6, origin=(6.0, 0.0, 0.3)))
    return VLM(surfaces, S_ref=10.0, c_ref=1.0, b_ref=10.0, r_ref=(2.25, 0.0, 1.0), mach_ref=0.2)


def test_neutral_point_of_a_lone_rectangular_wing_is_its_quarter_chord():
    """A straight rectangular lattice wing carries its load on the quarter-chord line."""
    x_np = float(neutral_point_x(_lattice(False), NO_FUSELAGE, z_cg=1.0))
    assert x_np == pytest.approx(2.25, abs=1e-3)


def test_neutral_point_is_the_centroid_of_the_lift_increments():
    """The formula's neutral point equals an independent sum over the strips: the x of
    each strip's bound vortex weighted by its lift increment with angle of attack
    (CG on the lattice's reference height, where the drag's arm vanishes to first order)."""
    vlm = _lattice(True)
    x_np = float(neutral_point_x(vlm, NO_FUSELAGE, z_cg=1.0))
    a = math.radians(1.0)
    r = vlm.solve(ca.DM([[-a, a]]), 1.0, rho=1.0)
    g = vlm.geometry
    dcl = np.asarray(r["cl"][:, 1] - r["cl"][:, 0], float).ravel()
    cw = (np.asarray(g["strip_chord"], float) * np.asarray(g["strip_width"], float)).ravel()
    x_strip = np.asarray(ca.mtimes(vlm.strip_sum, g["rb"][0, :].T), float).ravel() / \
        np.asarray(ca.mtimes(vlm.strip_sum, ca.DM.ones(vlm.n_panels, 1)), float).ravel()
    x_sum = float(np.sum(x_strip * dcl * cw) / np.sum(dcl * cw))
    assert x_np == pytest.approx(x_sum, abs=0.01)     # 1 % of the chord: drag's arm, strip lift vs F_z
    assert 2.25 < x_np < 6.2                           # the tail moves it aft of the wing's quarter chord
    # the fuselage's destabilizing moment moves it forward by dM_fus / dF_z
    fus = replace(NO_FUSELAGE, pitching_moment_factor=0.012)
    shift = x_np - float(neutral_point_x(vlm, fus, z_cg=1.0))
    dFz = float((r["F"][2, 1] - r["F"][2, 0]) / (2 * a))
    assert shift == pytest.approx(0.5 * 0.012 * 1.0 * 8.0 * 180 / math.pi / dFz, rel=1e-9)


def test_rotor_thrust_above_the_cg_pitches_nose_down():
    vlm = _lattice(False)
    z = ca.DM.zeros(1, 1)
    r = {"F": ca.DM.zeros(3, 1), "M": ca.DM.zeros(3, 1), "V_local": ca.DM.ones(vlm.n_strips, 1)}
    T = ca.DM([[1000.0]])
    m = pitching_moment_about_cg(vlm, r, 1.2, 50.0, 0.0, 2.5, 0.4, None, NO_FUSELAGE,
                                 [(1.0, 1.2, T, z, 0.0, 2)])
    assert float(m) == pytest.approx(-2 * 1000.0 * 0.8)
    # a lifting rotor (axis at 90 deg) ahead of the CG pitches nose up
    m = pitching_moment_about_cg(vlm, r, 1.2, 50.0, 0.0, 2.5, 0.4, None, NO_FUSELAGE,
                                 [(1.0, 0.4, T, z, math.pi / 2, 1)])
    assert float(m) == pytest.approx(1000.0 * 1.5)


def _segments(nodes=3):
    return [LinearSpeedConstantRate("CL", altitude_start_m=500 * u.FT, altitude_end_m=1500 * u.FT,
                                    speed_start_mps=110 * u.MPH, speed_end_mps=130 * u.MPH,
                                    climb_rate_mps=700 * u.FT_PER_MIN, nodes=nodes),
            ConstantSpeedConstantAltitude("CR", distance_m=5 * u.NMI, nodes=nodes)]


def _solve(trim: bool):
    p = Problem("trim")
    v = Aircraft(ga2p(), trim=trim, design_point_constraints=False, **SMALL)
    m = Mission(v, _segments()).build(p)
    p.minimize(m.energy_used_J / u.KWH, unit="kWh")
    p.freeze_design()
    sol = p.solve(verbose=False, max_iter=200)
    assert sol.success, sol.status
    return p, v, m, sol


def test_ga2p_trims_at_every_node_with_its_stabilator():
    p, v, m, sol = _solve(True)
    K = len(m.labels)
    g = p.groups["pitch trim"]
    assert g.kind == "==" and g.size == K and g.unit == "N m"
    moment = np.asarray(sol.value(g.residual), float) * g.scale
    assert np.max(np.abs(moment)) < 1e-3 * v.togw_baseline_kg * 9.81   # N m, at a 1 m arm: 0.1 % of W
    delta = np.asarray(sol.value(m.evaluation.outputs["horizontal_tail.trim_incidence_deg"].expr)).ravel()
    lo, hi = ga2p().wing("horizontal_tail").trim_incidence_range_deg
    assert np.all(delta > lo) and np.all(delta < hi) and np.ptp(delta) > 0.1
    # the frozen baseline CG sits 5 % of MAC ahead of the required margin
    assert float(sol.value(p.outputs["static_margin"].expr)) == pytest.approx(0.10, abs=1e-9)
    # the stabilator's strips are in the stall margin
    assert any("horizontal_tail eta" in lbl for lbl in map(str, p.groups["stall margin"].labels))
    tail_lift = np.asarray(sol.value(m.evaluation.outputs["horizontal_tail.lift_N"].expr)).ravel()
    # the cruise's tail load is small beside the weight (the CG close to the neutral point)
    assert np.max(np.abs(tail_lift)) < 0.05 * v.togw_baseline_kg * 9.81
    off, v_off, m_off, sol_off = _solve(False)
    assert "pitch trim" not in off.groups and "static_margin" not in off.outputs
    assert "horizontal_tail.trim_incidence" not in [s.name for s in v_off.unknowns()]


def test_trim_input_errors():
    with pytest.raises(InputError, match="trim_incidence_range_deg"):
        WingConfig("t", span_m=3.0, area_m2=2.0, taper=1.0, section_eta=(0.0, 1.0), twist_deg=(0.0, 0.0),
                   airfoil="NACA_0015", role="horizontal_tail", trim_incidence_range_deg=(5.0, 10.0))
    cfg = ttw()
    wings = tuple(replace(w, trim_incidence_range_deg=(-10.0, 10.0)) if w.role == "tandem" else w
                  for w in cfg.wings)
    # a tilt-wing trims where its wings are level; a tilted segment must say pitch_trim = 0
    hover = VerticalAscent("VC", altitude_start_m=0.0, altitude_end_m=10.0, climb_rate_mps=1.5, nodes=3,
                           parameters={"wing_mounted_angle_rad": math.pi / 2})
    with pytest.raises(InputError, match="tilt-wing trims in pitch only where its wings are level"):
        Mission(Aircraft(replace(cfg, wings=wings), **SMALL), [hover]).build(Problem("t"))
    hover = VerticalAscent("VC", altitude_start_m=0.0, altitude_end_m=10.0, climb_rate_mps=1.5, nodes=3,
                           parameters={"wing_mounted_angle_rad": math.pi / 2, "pitch_trim": 0.0})
    p = Problem("t")
    Mission(Aircraft(replace(cfg, wings=wings), **SMALL), [hover]).build(p)
    assert "pitch trim" not in p.groups
    with pytest.raises(InputError, match="static_margin_min"):
        replace(ga2p(), static_margin_min=0.9)
