"""The wing's bending material (issue 16 item 4): span, taper, thickness and lift share
move the wing mass through the physics, and the sizing lift is the wing's own."""
import math
import sys
from dataclasses import replace
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

from mdo.core.errors import InputError
from mdo.vehicle.catalog import ga2p, ttw
from mdo.vehicle.mass import MassDesign, mass_table_markdown, mass_terms, solve_togw
from mdo.vehicle.wing_structure import WingStructure, bending_material_kg, elliptic_shear_moment, wing_box_breakdown

sys.path.insert(0, str(Path(__file__).parent))
from test_vehicle_definition import _built, _segments  # noqa: E402

CAPS_ONLY = WingStructure(non_optimum_factor=1.0, web_stress_Pa=5e9, quadrature_points=24,
                          max_tip_deflection_fraction=None)   # S3: strength alone  # webs ~0.1-0.3 %


def test_elliptic_loads_match_the_integrated_load():
    s, L_half = 5.0, 1000.0
    V0, M0 = elliptic_shear_moment(0.0, L_half, s)
    assert V0 == pytest.approx(L_half, rel=1e-12)
    assert M0 == pytest.approx(4 * L_half * s / (3 * math.pi), rel=1e-12)   # centroid 4s/(3 pi)
    # M(u) is the integral of V from u to the tip (dM/dy = -V)
    u = np.linspace(0.0, 1.0, 4001)
    V, M = elliptic_shear_moment(u, L_half, s)
    M_int = np.array([np.trapezoid(V[i:], u[i:] * s) for i in (0, 1000, 2000, 3000)])
    assert np.allclose(M_int, M[[0, 1000, 2000, 3000]], rtol=2e-4)


def test_caps_grow_like_span_cubed_at_constant_area_and_linearly_with_lift():
    m1 = bending_material_kg(CAPS_ONLY, 14.76, 11.4, 1.0, 0.12, 5.7, 18000.0)
    m16 = bending_material_kg(CAPS_ONLY, 14.76, 1.6 * 11.4, 1.0, 0.12, 5.7, 18000.0)
    assert m16 / m1 == pytest.approx(1.6 ** 3, rel=0.01)
    assert bending_material_kg(CAPS_ONLY, 14.76, 11.4, 1.0, 0.12, 5.7, 9000.0) == pytest.approx(0.5 * m1, rel=1e-9)
    # thicker box, less material (1/(t/c)); lower taper: a deeper root where the moment is
    assert bending_material_kg(CAPS_ONLY, 14.76, 11.4, 1.0, 0.15, 5.7, 18000.0) == pytest.approx(m1 * 0.8, rel=3e-3)
    assert bending_material_kg(CAPS_ONLY, 14.76, 11.4, 0.4, 0.12, 5.7, 18000.0) < m1


def test_rectangular_wing_caps_against_the_closed_form():
    # rectangular box (constant depth h): m = 2 halves x rho x 2 caps x int_0^s M dy / (sigma h)
    S, b, tc, n, F = 10.0, 10.0, 0.12, 5.7, 20000.0
    s, c = b / 2, S / b
    h = CAPS_ONLY.box_depth_fraction * tc * c
    L_half = 0.5 * n * F
    y = np.linspace(0, s, 20001)
    _, M = elliptic_shear_moment(y / s, L_half, s)
    expect = 2 * CAPS_ONLY.density_kgpm3 * 2 * np.trapezoid(M, y) / (CAPS_ONLY.cap_stress_Pa * h)
    assert bending_material_kg(CAPS_ONLY, S, b, 1.0, tc, n, F) == pytest.approx(expect, rel=5e-3)   # + the webs at 5 GPa, 0.2 %


def test_stiffness_caps_meet_the_tip_deflection_and_leave_a_short_wing_alone():
    """S4: the caps are the larger of the strength caps and the least-mass caps that hold the
    limit-load tip deflection to f s; the deflection is checked here by integrating the
    curvature M / (E I) twice along the span (an independent route to S4's closed form)."""
    ws = WingStructure(non_optimum_factor=1.0, web_stress_Pa=5e9, quadrature_points=48)
    strength_only = replace(ws, max_tip_deflection_fraction=None)
    def tip_deflection_fraction(S, b, taper, tc=0.12, n=5.7, F=14000.0):
        s = b / 2
        c_r = 2 * S / (b * (1 + taper))
        u = np.linspace(0.0, 1.0, 20001)
        _, M = elliptic_shear_moment(u, 0.5 * n * F, s)
        h = ws.box_depth_fraction * tc * c_r * (1 - (1 - taper) * u)
        A_s = M / (ws.cap_stress_Pa * h)
        g = np.sqrt((1 - u) * M / ws.factor_of_safety) / h
        lam = 2 * s * np.trapezoid(g, u) / (ws.youngs_modulus_Pa * ws.max_tip_deflection_fraction)
        A = np.maximum(A_s, lam * g)
        M, A = M[:-1], A[:-1]        # the tip station: no moment, no cap
        u, h = u[:-1], h[:-1]
        kappa = (M / ws.factor_of_safety) / (ws.youngs_modulus_Pa * A * h ** 2 / 2)   # limit load
        slope = np.concatenate([[0.0], np.cumsum(0.5 * (kappa[1:] + kappa[:-1]) * np.diff(u * s))])
        w = np.trapezoid(slope, u * s)
        caps = 2 * ws.density_kgpm3 * 2 * s * np.trapezoid(A, u)
        return w / s, caps
    # an AR-30 wing: stiffness governs; the tip deflects at most f s, and within 15 % of it
    frac, caps = tip_deflection_fraction(10.85, 18.0, 0.25)
    assert 0.85 * 0.2 < frac <= 0.2 * 1.001
    b = bending_material_kg(ws, 10.85, 18.0, 0.25, 0.12, 5.7, 14000.0)
    b0 = bending_material_kg(strength_only, 10.85, 18.0, 0.25, 0.12, 5.7, 14000.0)
    assert b == pytest.approx(caps, rel=0.02)        # 48-point quadrature and the 1 % rounding of S4
    assert b > 1.5 * b0
    # the P2006T's wing (AR 8.8): strength governs; S4 adds at most 2 % (the rounding and the
    # tip stations, where the stiffness caps of least mass exceed the strength caps)
    short = bending_material_kg(ws, 14.76, 11.4, 0.7, 0.12, 5.7, 14000.0)
    assert bending_material_kg(strength_only, 14.76, 11.4, 0.7, 0.12, 5.7, 14000.0) < short < 1.02 * \
        bending_material_kg(strength_only, 14.76, 11.4, 0.7, 0.12, 5.7, 14000.0)
    assert wing_box_breakdown(ws, 14.76, 11.4, 0.7, 0.12, 5.7, 14000.0)["strength_tip_deflection_fraction"] \
        == pytest.approx(0.13, abs=0.005)


def test_rotor_masses_relieve_the_bending_smoothly():
    ws = WingStructure()
    bare = bending_material_kg(ws, 14.76, 11.4, 0.6, 0.12, 5.7, 18000.0)
    outboard = bending_material_kg(ws, 14.76, 11.4, 0.6, 0.12, 5.7, 18000.0, [(60.0, 4.0)])
    inboard = bending_material_kg(ws, 14.76, 11.4, 0.6, 0.12, 5.7, 18000.0, [(60.0, 1.0)])
    assert outboard < inboard < bare
    y = ca.MX.sym("y")
    f = ca.Function("f", [y], [ca.jacobian(bending_material_kg(ws, 14.76, 11.4, 0.6, 0.12, 5.7, 18000.0,
                                                               [(60.0, y)]), y)])
    slopes = np.array([float(f(v)) for v in np.linspace(0.2, 5.6, 55)])
    assert np.all(np.isfinite(slopes)) and np.all(slopes < 0)   # further out, more relief, everywhere


def test_baseline_mass_is_raymers_and_the_lift_share_moves_it():
    cfg = replace(ttw(), wing_structure=None)
    bend = replace(cfg, wing_structure=WingStructure())
    W0 = solve_togw(cfg)
    assert solve_togw(bend) == pytest.approx(W0, rel=1e-9)      # the level is the regression's
    d = MassDesign.baseline(bend)
    front, rear = (w.name for w in bend.lifting_wings)
    share = {front: 0.84, rear: 0.16}
    d.wing_design_lift_N = {k: v * 9.80665 * W0 for k, v in share.items()}
    t = mass_terms(bend, W0, d)
    t0 = mass_terms(cfg, W0)
    assert t[f"wing: {front}"] > t0[f"wing: {front}"] > t[f"wing: {rear}"]
    # stretching the wing that carries more lift costs more
    def span_slope(name):
        d2 = MassDesign(dict(d.wing_span_m), dict(d.wing_taper), d.rotor_radius_m,
                        wing_design_lift_N=d.wing_design_lift_N)
        d2.wing_span_m[name] *= 1.1
        return float(mass_terms(bend, W0, d2)[f"wing: {name}"] - t[f"wing: {name}"])
    assert span_slope(front) > 2.0 * span_slope(rear)
    assert "bending material" in mass_table_markdown(bend, d)


def test_the_calibration_scales_the_regressions_level_not_the_bending_physics():
    """A calibrated airframe keeps its calibrated baseline wing, but stretching the wing costs
    the same bending material whatever the calibration (issue 17: calibration only where a
    regression is known to be off)."""
    W = 2800.0

    def wing_mass_and_slope(f_cal):
        cfg = replace(ttw(), mass_inputs={**ttw().mass_inputs, "airframe_calibration": f_cal})
        d = MassDesign.baseline(cfg)
        name = cfg.lifting_wings[0].name
        m0 = float(mass_terms(cfg, W, d)[f"wing: {name}"])
        d.wing_span_m[name] *= 1.2
        return cfg, m0, float(mass_terms(cfg, W, d)[f"wing: {name}"]) - m0
    _, _, slope_raw = wing_mass_and_slope(1.0)
    assert slope_raw > 1.0
    for f_cal in (0.7, 1.16):
        cfg, m0, slope = wing_mass_and_slope(f_cal)
        raymer = replace(cfg, wing_structure=None)
        assert solve_togw(cfg) == pytest.approx(solve_togw(raymer), rel=1e-9)   # the level: calibrated
        assert slope == pytest.approx(slope_raw, rel=1e-9)                      # the physics: not scaled


def test_a_structure_heavier_than_the_regression_is_refused():
    with pytest.raises(InputError, match="wing_structure"):
        solve_togw(replace(ga2p(), wing_structure=WingStructure(cap_stress_Pa=20e6)))
    with pytest.raises(InputError, match="wing_structure.box_depth_fraction"):
        WingStructure(box_depth_fraction=1.5)


def test_the_design_lift_is_sized_by_the_wings_lift_and_holds_the_span():
    """A short GA-2P climb and cruise, wing free: with the bending material the span stops
    inside its box and short of where Raymer's AR^0.6 alone puts it, and the design lift is
    the largest lift of the wing over the nodes."""
    p0, v0, _ = _built(replace(ga2p(), wing_structure=None), _segments())
    s0 = p0.solve(verbose=False)
    assert s0.status == "Solve_Succeeded"
    span_raymer = float(np.ravel(s0.value(v0.design["wings"]["main_wing"]["span"]))[0])
    cfg = replace(ga2p(), wing_structure=WingStructure())
    p, v, m = _built(cfg, _segments())
    assert "main_wing design lift" in p.groups
    s = p.solve(verbose=False)
    assert s.status == "Solve_Succeeded"
    span = s.value(v.design["wings"]["main_wing"]["span"])
    upper = p.variables["main_wing.span"].upper
    assert float(np.ravel(span)[0]) < 0.95 * float(np.ravel(upper)[0])
    assert float(np.ravel(span)[0]) < 0.97 * span_raymer
    # the sizing is active: at the node of the largest lift, the wing's lift is its design lift
    r = np.asarray(s.value(p.groups["main_wing design lift"].residual)).ravel()
    assert -1e-5 < r.max() < 1e-6


def test_tilt_wing_sizes_on_wing_borne_nodes_and_checks_the_limit_load_elsewhere():
    from mdo.core import units as u
    from mdo.mission import Mission
    from mdo.mission.profiles import evtol_segments
    from mdo.nlp import Problem
    from mdo.vehicle.aircraft import Aircraft
    p = Problem("ttw_small")
    v = Aircraft(replace(ttw(), wing_structure=WingStructure()), n_stations=6, n_azimuth=2, wing_strips=6)
    m = Mission(v, evtol_segments(nodes=3), nodes=3).build(p)
    p.minimize(m.energy_used_J / u.KWH, unit="kWh")
    for wing in ("main_wing", "tandem_wing"):
        sized, limit = p.groups[f"{wing} design lift"].labels, p.groups[f"{wing} limit load"].labels
        assert any(lab.startswith("CR") for lab in sized)
        assert not any(lab.startswith(("VT", "AT", "VC")) for lab in sized)
        assert any(lab.startswith("AT") for lab in limit) and not any(lab.startswith("CR") for lab in limit)
        # every wing's aspect ratio and strength-sized deflection reach summary.json, not the main wing's alone
        for out in (f"{wing}.aspect_ratio", f"{wing}.strength_sized_tip_deflection"):
            assert p.outputs[out].summary
    ar = p.opti.debug.value(p.outputs["tandem_wing.aspect_ratio"].expr, p.opti.initial())
    assert float(ar) == pytest.approx(9.6 ** 2 / 10.85, rel=1e-9)      # the baseline's, at the initial guess


def test_a_vehicle_not_in_the_paper_with_two_rotor_groups_on_its_renamed_wing():
    """The bending material reads the definition, not the catalog: a wing named "wing"
    carrying wing-tip propellers and four inboard ones (``two_group_vehicle``)."""
    from test_vehicle_definition import two_group_vehicle
    cfg = replace(two_group_vehicle(), wing_structure=WingStructure())
    W0 = solve_togw(replace(cfg, wing_structure=None))
    assert solve_togw(cfg) == pytest.approx(W0, rel=1e-9)
    # both groups relieve the wing: moving the tip propellers inboard makes it heavier
    d = MassDesign.baseline(cfg)
    inboard = MassDesign(d.wing_span_m, d.wing_taper, d.rotor_radius_m, rotor_span_eta={"tips": [0.5]})
    assert mass_terms(cfg, W0, inboard)["wing: wing"] > mass_terms(cfg, W0, d)["wing: wing"]
    p, v, m = _built(cfg, _segments(cruise_parameters={"inboard.active": 0.0}))
    assert "wing design lift" in p.groups
    assert all(np.isfinite(x["max_violation"]) for x in p.initial_violations())


def test_the_wing_mass_options_of_the_problem_files():
    """``-o wing_mass=raymer`` drops the structure; ``-o max_tip_deflection_pct`` sets S4's limit."""
    from mdo.studies import airframe_variant
    assert ga2p().wing_structure == WingStructure()                       # the default wing mass
    assert airframe_variant(ga2p(), wing_mass="raymer").wing_structure is None
    stiff = airframe_variant(ga2p(), max_tip_deflection_pct=10.0).wing_structure
    assert stiff.max_tip_deflection_fraction == pytest.approx(0.10)
    W = solve_togw(ga2p())
    d = MassDesign.baseline(ga2p())
    d.wing_span_m = {"main_wing": 16.0}
    heavier = mass_terms(replace(ga2p(), wing_structure=stiff), W, d)["wing: main_wing"]
    assert heavier > mass_terms(ga2p(), W, d)["wing: main_wing"]         # a stiffer wing of AR 17 weighs more
