"""Geometry: constant-area parameterization, planform numbers, strip layout, camber lines."""
import math

import casadi as ca
import numpy as np
import pytest

from mdo.core import InputError
from mdo.wing import (Section, Surface, VLM, camber_line, constant_area, mean_aerodynamic_chord,
                      planform_area, trapezoid)
from mdo.wing.geometry import interpolation_weights


def test_constant_area_holds_s_ref_for_any_span_and_taper():
    for b, lam in ((11.4, 0.7), (13.0, 0.54), (9.6, 1.0), (12.3, 0.85)):
        w = constant_area("w", 14.76, b, lam, [0.0] * 5)
        assert planform_area(w) == pytest.approx(14.76, rel=1e-12)
        assert w.sections[-1].chord == pytest.approx(lam)
    # symbolic: area is constant, root chord responds
    b = ca.SX.sym("b")
    w = constant_area("w", 14.76, b, 0.7, [0.0] * 5)
    dS = ca.Function("dS", [b], [ca.jacobian(planform_area(w), b)])(11.4)
    assert abs(float(dS)) < 1e-12


def test_planform_numbers_of_a_trapezoid():
    w = trapezoid("w", 10.0, 2.0, 0.5)
    assert planform_area(w) == pytest.approx(15.0)
    lam = 0.5
    assert mean_aerodynamic_chord(w) == pytest.approx(2 / 3 * 2.0 * (1 + lam + lam**2) / (1 + lam))


def test_interpolation_weights_exact_numeric_and_smooth_symbolic():
    knots = [0.0, 0.3, 0.7, 1.0]
    vals = np.array([1.0, 0.9, 0.5, 0.4])
    x = ca.SX.sym("x")
    f = ca.Function("f", [x], [ca.dot(ca.vertcat(*interpolation_weights(x, knots, 1e-3)), ca.DM(vals))])
    for e in np.linspace(0, 1, 23):
        exact = np.interp(e, knots, vals)
        assert np.dot(interpolation_weights(e, knots, 1e-3), vals) == pytest.approx(exact, abs=1e-14)
        assert float(f(e)) == pytest.approx(exact, abs=1e-3 * math.log(2) * 0.75)
    g = ca.Function("g", [x], [ca.hessian(f(x), x)[0]])
    assert math.isfinite(float(g(0.3))) and float(g(0.3)) > 0   # the kink is rounded, not cut


def test_strip_layout_anchors_and_cosine_spacing():
    w = constant_area("w", 14.76, 11.4, 0.7, [0.0] * 5, nspan=12, breaks=[0.35], anchor_sections=True)
    anchors = [a[0] for a in w.anchors()]
    assert anchors == [0.0, 0.25, 0.35, 0.5, 0.75, 1.0]
    assert sum(w.panel_counts()) == 12
    v = VLM([trapezoid("t", 10.0, 1.0, 1.0, nspan=8)])
    y = np.array(v.geometry["strip_y"])
    edges = np.concatenate([y[0], y[1, -1:]])
    assert np.allclose(edges, 5.0 * np.sin(0.5 * np.pi * np.arange(9) / 8))   # full-span cosine


def test_input_errors_name_the_field():
    with pytest.raises(InputError, match="span"):
        trapezoid("w", -1.0, 1.0, 0.5)
    with pytest.raises(InputError, match="taper"):
        trapezoid("w", 10.0, 1.0, 0.0)
    with pytest.raises(InputError, match="sections"):
        Surface("w", 10.0, 1.0, [Section(0.0), Section(0.5)])
    with pytest.raises(InputError, match="airfoil"):
        camber_line("not-an-airfoil")
    with pytest.raises(InputError, match="breaks"):
        Surface("w", 10.0, 1.0, breaks=[ca.SX.sym("e")])


def test_camber_lines():
    c = camber_line("naca2412")
    assert c.z(0.4) == pytest.approx(0.02)
    assert c.slope(0.4) == pytest.approx(0.0, abs=1e-12)
    for name, zmax in (("clark_y", 0.034), ("NACA 63-412", 0.022), ("e63", 0.055)):
        z = camber_line(name).z(np.linspace(0, 1, 201))
        assert z.max() == pytest.approx(zmax, abs=0.003)
        assert abs(z[0]) < 1e-12 and abs(z[-1]) < 1e-12
    assert camber_line("naca0012").is_flat and camber_line(None).is_flat


def test_camber_gives_negative_zero_lift_angle():
    """NACA 2412 on a high-AR wing: zero-lift angle near thin-airfoil theory (-2.08 deg)."""
    w = trapezoid("w", 20.0, 1.0, 1.0, airfoil="naca2412", nspan=12, nchord=6)
    r = VLM([w]).solve([0.0, math.radians(2.0)], 1.0)
    cl = np.array(r["CL"]).ravel()
    a0 = -cl[0] / ((cl[1] - cl[0]) / 2.0)
    assert a0 == pytest.approx(-2.08, abs=0.15)
