"""Smooth helpers: accuracy against the exact kink at the stated width, smoothness."""
import casadi as ca
import numpy as np
import pytest

from mdo.core import blend, sigmoid, smooth_abs, smooth_clip, smooth_max, smooth_min, softplus


def test_softplus_limits_and_overflow():
    x = np.array([-1e4, -5.0, 0.0, 5.0, 1e4])
    y = softplus(x, 0.1)
    assert np.all(np.isfinite(y))
    assert y[0] == pytest.approx(0.0, abs=1e-12)
    assert y[2] == pytest.approx(0.1 * np.log(2))
    assert y[3] == pytest.approx(5.0, abs=1e-12)
    assert y[4] == pytest.approx(1e4)


@pytest.mark.parametrize("w", [1e-3, 0.1, 1.0])
def test_smooth_max_min_abs_error_bounded_by_width(w):
    a = np.linspace(-3, 3, 601)
    b = 0.3
    assert np.max(np.abs(smooth_max(a, b, w) - np.maximum(a, b))) <= w / 2 + 1e-15
    assert np.max(np.abs(smooth_min(a, b, w) - np.minimum(a, b))) <= w / 2 + 1e-15
    assert np.max(np.abs(smooth_abs(a, w) - np.abs(a))) <= w + 1e-15
    c = smooth_clip(a, -1, 1, w)
    assert np.max(np.abs(c - np.clip(a, -1, 1))) <= w / 2 + 1e-12


def test_symbolic_and_numeric_agree_and_derivatives_finite():
    x = ca.SX.sym("x")
    for f in (lambda z: softplus(z, 0.05), lambda z: smooth_abs(z, 0.05),
              lambda z: smooth_max(z, 0.2, 0.05), lambda z: sigmoid(z, 0.05),
              lambda z: blend(z, 0.1, 0.02, z ** 2, 3 * z)):
        e = f(x)
        F = ca.Function("f", [x], [e, ca.jacobian(e, x), ca.hessian(e, x)[0]])
        for xv in np.linspace(-2, 2, 41):
            v, d, h = (float(o) for o in F(xv))
            assert np.isfinite(v) and np.isfinite(d) and np.isfinite(h)
            assert v == pytest.approx(float(f(np.array(xv))), rel=1e-12, abs=1e-14)


def test_blend_endpoints():
    assert blend(-1.0, 0.0, 0.01, 2.0, 5.0) == pytest.approx(2.0)
    assert blend(1.0, 0.0, 0.01, 2.0, 5.0) == pytest.approx(5.0)
    assert blend(0.0, 0.0, 0.01, 2.0, 5.0) == pytest.approx(3.5)
