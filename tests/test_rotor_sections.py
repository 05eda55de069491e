"""Radial distributions of sections and rotational augmentation (stall delay)."""
import math

import casadi as ca
import numpy as np
import pytest

from mdo.core.errors import InputError
from mdo.rotor import RotorGeometry, analyze, bemt_function, section
from mdo.rotor.geometry import DATA_DIR
from mdo.rotor.sections import AnalyticSection, RotationalAugmentation, SpanwiseSections


def test_distribution_weights_partition_of_unity():
    secs = [AnalyticSection(alpha0_rad=-0.05), AnalyticSection(alpha0_rad=0.0), AnalyticSection(alpha0_rad=0.05)]
    d = SpanwiseSections(secs, [0.3, 0.7], width=0.03)
    x = np.linspace(0.0, 1.0, 101)
    w = np.array(d.weights(x))
    assert np.allclose(w.sum(axis=0), 1.0) and (w > -1e-12).all()
    assert w[0, 0] > 0.99 and w[1, 50] > 0.99 and w[2, -1] > 0.99
    # each station sees its own section's zero lift
    for xi, a0 in ((0.05, -0.05), (0.5, 0.0), (0.95, 0.05)):
        assert abs(d.cl(a0, 1e6, 0.0, xi)) < 0.02


def test_distribution_from_text_and_errors():
    s = section("naca4412:0.4:clark_y:0.8:e63")
    assert isinstance(s, SpanwiseSections) and s.changes == [0.4, 0.8]
    assert section("naca4412:0.4:clark_y:0.8:e63") is s               # cached by name
    for bad in ("naca4412:0.4:clark_y:0.8", "naca4412:0.8:clark_y:0.4:e63", "naca4412:x:clark_y:0.8:e63",
                "naca4412:1.2:clark_y"):
        with pytest.raises(InputError):
            section(bad)
    with pytest.raises(InputError):
        section("naca4412+nosuchmodel")


def test_distribution_width_from_text():
    s = section("naca4412:0.4:clark_y:0.8:e63;width=0.01")
    assert isinstance(s, SpanwiseSections) and s.width == 0.01 and s.name.endswith(";width=0.01")
    assert s is not section("naca4412:0.4:clark_y:0.8:e63")           # another object: another blend
    for bad in ("naca4412:0.4:clark_y;width=0", "naca4412:0.4:clark_y;span=0.1", "naca4412;width=0.01",
                "naca4412:0.4:clark_y;width=x"):
        with pytest.raises(InputError, match="width"):
            section(bad)


def _bemt_outputs(f, n, m):
    args = dict(radius_m=1.0, hub_fraction=0.12, blades=3, chord_m=np.full(n, 0.1),
                twist_rad=np.linspace(0.8, 0.3, n), pitch_rad=0.0, omega_radps=150.0, v_axial_mps=50.0,
                v_inplane_mps=5.0, rho_kgpm3=1.1, mu_Pas=1.8e-5, a_mps=340.0, spin=1.0,
                phi_rad=np.full(n * m, 0.4))
    return {k: np.asarray(v).ravel() for k, v in f(**args).items()}


def test_distribution_placed_at_the_stations_is_the_blend_at_a_fraction_of_the_cost():
    """A BEMT Function given its hub fraction places the sections at the stations when it is
    built: each section is evaluated only where it carries weight.  Same loads to the
    dropped weights (< 1e-6), far fewer operations than one call per section per element."""
    sec = section("naca4412:0.35:clark_y:0.6:naca4412@xtr=0.1:0.85:e63;width=0.005")   # shipped polars
    n, m = 20, 4
    full = bemt_function(sec, n, m, outputs="nlp")
    placed = bemt_function(sec, n, m, outputs="nlp", hub_fraction=0.12)
    a, b = _bemt_outputs(full, n, m), _bemt_outputs(placed, n, m)
    for k in ("residual", "thrust_N", "torque_Nm", "gamma_m2ps"):
        assert np.allclose(a[k], b[k], rtol=1e-6, atol=1e-9), k
    single = bemt_function(section("naca4412"), n, m, outputs="nlp", hub_fraction=0.12)
    # measured: 1.2x one section's operations placed, 3x with the four sections everywhere
    assert placed.n_instructions() < 2.0 * single.n_instructions() < full.n_instructions()


def test_analysis_places_the_sections_as_the_nlp_does():
    """The numeric analysis (the mission's initial guess) given the hub fraction solves with
    one kernel per group of stations sharing a blend: the same loads as the blend everywhere
    (to the dropped weights), and in the elements' kernels a fraction of the operations."""
    from mdo.rotor.analysis import _station_groups, analyze_inputs, solve_kernel
    sec = section("naca4412:0.35:clark_y:0.6:naca4412@xtr=0.1:0.85:e63;width=0.005")
    n, K, hub = 20, 4, 0.12
    inputs = dict(radius_m=1.0, hub_fraction=hub, blades=3, chord_m=np.full(n, 0.1),
                  twist_rad=np.linspace(0.8, 0.3, n), pitch_rad=np.array([0.0, 0.1, -0.9, 0.2]),
                  omega_radps=150.0, v_axial_mps=np.array([0.0, 30.0, 50.0, 60.0]), v_inplane_mps=0.0,
                  rho_kgpm3=1.1, mu_Pas=1.8e-5, a_mps=340.0, spin=1.0)
    a = analyze_inputs(sec, inputs, n, 1)
    b = analyze_inputs(sec, inputs, n, 1, hub_fraction=hub)
    assert a.converged.all() and b.converged.all()    # the -0.9 rad pitch exercises the fallback
    for k in ("thrust_N", "torque_Nm", "power_W"):
        assert np.allclose(a.values[k], b.values[k], rtol=1e-6), k
    groups = _station_groups(sec, n, 1, hub)
    assert 1 < len(groups) < n and sorted(i for _, idx in groups for i in idx) == list(range(n))
    ops = sum(len(idx) * solve_kernel(sec, x_station=x).n_instructions() for x, idx in groups)
    assert ops < 0.6 * n * solve_kernel(sec).n_instructions()


@pytest.mark.parametrize("model", ["snel", "du_selig"])
def test_stall_delay_only_past_the_linear_range(model):
    base = section("clark_y")
    aug = section("clark_y", stall_delay=model)
    assert isinstance(aug, RotationalAugmentation)
    a = np.radians(np.array([-2.0, 0.0, 2.0, 18.0, 25.0, 60.0]))
    cl2, cd2 = base.cl(a, 1e5), base.cd(a, 1e5)
    cl3, cd3 = aug.coefficients(a, 1e5, 0.0, 0.3, 0.4, 0.9)
    # the lift increment is a normal force: its drag is dcl tan(alpha) (Bak et al. 2006)
    assert np.allclose(cd3, cd2 + (cl3 - cl2) * np.tan(a), atol=1e-12)
    assert np.all(cd3[3:5] > cd2[3:5] + 0.01)
    cl2d, cd2d = RotationalAugmentation(base, model, drag="2d").coefficients(a, 1e5, 0.0, 0.3, 0.4, 0.9)
    assert np.allclose(cd2d, cd2) and np.allclose(cl2d, cl3)   # drag="2d": drag stays 2-D
    assert np.all(np.abs(cl3[:3] - cl2[:3]) < 0.01)            # attached: unchanged
    assert cl3[3] > cl2[3] + 0.05 and cl3[4] > cl2[4] + 0.05   # stall delayed at c/r = 0.4
    assert abs(cl3[5] - cl2[5]) < 0.02                         # deep stall: back to 2-D
    # the correction vanishes outboard (c/r -> small)
    assert abs(aug.coefficients(a[3], 1e5, 0.0, 0.95, 0.02, 0.9)[0] - cl2[3]) < 0.02
    f = aug.factor(np.linspace(0.0, 2.0, 41), 0.5, 0.9)
    assert np.all(f >= -1e-8) and np.all(f <= 1.0)


def test_stall_delay_in_the_bemt_is_smooth_and_raises_static_thrust():
    rot = RotorGeometry.from_csv(DATA_DIR / "apce_10x7_geometry.csv", diameter_m=0.254, blades=2,
                                 airfoil="e63:0.5:clark_y")
    om = 2 * math.pi * 5000 / 60
    r2 = analyze(rot, omega_radps=om, v_axial_mps=np.array([0.0, 8.0]))
    r3 = analyze(rot, omega_radps=om, v_axial_mps=np.array([0.0, 8.0]), section=section("e63:0.5:clark_y+du_selig"))
    assert r3.converged.all()
    assert r3["CT"][0] > 1.03 * r2["CT"][0]
    f = bemt_function(section("e63:0.5:clark_y+du_selig"), 8)
    x = ca.SX.sym("phi", 8)
    st = rot.stations(8)
    args = dict(radius_m=0.127, hub_fraction=rot.hub_fraction, blades=2, chord_m=st["chord_m"],
                twist_rad=st["beta_rad"], pitch_rad=0.0, omega_radps=om, v_axial_mps=0.0, v_inplane_mps=0.0,
                rho_kgpm3=1.225, mu_Pas=1.79e-5, a_mps=340.0, spin=1.0, phi_rad=x)
    res = f(**args)["residual"]
    h = ca.Function("h", [x], [ca.hessian(ca.sumsqr(res), x)[0]])
    assert np.all(np.isfinite(np.array(h(np.full(8, 0.2)))))


def test_adkins_liebeck_with_a_stall_delay_section():
    """The design point is attached: a stall-delay section designs like its 2-D base."""
    from mdo.rotor import adkins_liebeck
    kw = dict(blades=2, radius_m=0.5, speed_mps=20.0, thrust_N=50.0, rpm=3000, cl_design=0.6, n_stations=10)
    a = adkins_liebeck(airfoil="naca4412", **kw)
    b = adkins_liebeck(airfoil="naca4412+du_selig", **kw)
    np.testing.assert_allclose(b["chord_m"], a["chord_m"], rtol=1e-9)


def test_full_scale_propellers_thin_toward_the_tip():
    """The catalog's propeller blades (issue 17 item 5): thickness falls from root to tip,
    0.08 at 0.7 R as the NACA full-scale series (catalog.py cites it); the design point's
    stall bound sees each station's own section (thin tips stall earlier)."""
    from mdo.rotor.design import station_clmax
    from mdo.vehicle.catalog import PROP_AIRFOIL, VEHICLES
    from mdo.vehicle.rotor_group import section_name
    assert {g.airfoil for make in VEHICLES.values() for g in make().rotor_groups} == {PROP_AIRFOIL}
    sec = section(section_name(PROP_AIRFOIL))
    x = np.linspace(0.15, 1.0, 35)
    t = np.array([sum(w * leaf.thickness_to_chord for w, leaf in zip(np.ravel(sec.station_weights(xi)), sec.sections))
                  for xi in x])
    assert (np.diff(t) <= 1e-9).all() and t[0] == pytest.approx(0.18, abs=1e-3) and t[-1] == pytest.approx(0.06, abs=1e-3)
    assert np.interp(0.7, x, t) == pytest.approx(0.08, abs=1e-3)
    fits = station_clmax(sec, 20, 0.12)
    assert fits[-1](2e6) < fits[len(fits) // 2](2e6) - 0.1      # the 6 % tip below the 12 % mid-blade
