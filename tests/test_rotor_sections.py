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
