"""Biot–Savart kernels (Eqs. 2, 4) against closed forms."""
import math

import casadi as ca
import numpy as np
import pytest

from mdo.wake import filament_velocity, ring_kernel, ring_velocity


def _segment_closed_form(a, b, p, gamma=1.0):
    """Singular straight-segment law Γ/(4πh)(cos θ1 − cos θ2) along ê = (r1×r2)/|r1×r2|."""
    r0, r1, r2 = b - a, p - a, p - b
    c = np.cross(r1, r2)
    h = np.linalg.norm(c) / np.linalg.norm(r0)
    cos1 = r0 @ r1 / (np.linalg.norm(r0) * np.linalg.norm(r1))
    cos2 = r0 @ r2 / (np.linalg.norm(r0) * np.linalg.norm(r2))
    return gamma / (4 * math.pi * h) * (cos1 - cos2) * c / np.linalg.norm(c)


def test_straight_filament_matches_closed_form():
    rng = np.random.default_rng(1)
    for _ in range(20):
        a, b = rng.normal(size=3), rng.normal(size=3)
        p = rng.normal(size=3) * 2
        v = np.array(filament_velocity(a, b, 2.5, 1e-9, p)).ravel()
        np.testing.assert_allclose(v, _segment_closed_form(a, b, p, 2.5), rtol=1e-9, atol=1e-12)


def test_infinite_line_limit_and_direction():
    # a long filament along +x: v = Γ/(2πh) along +z at a point on +y (right-hand rule)
    v = np.array(filament_velocity([-1e4, 0, 0], [1e4, 0, 0], 1.0, 1e-9, [0, 0.5, 0])).ravel()
    np.testing.assert_allclose(v, [0, 0, 1 / (2 * math.pi * 0.5)], rtol=1e-7, atol=1e-12)


def test_core_is_scully_and_finite_on_the_filament():
    gamma, h, core = 1.0, 0.05, 0.05
    v = np.array(filament_velocity([-1e4, 0, 0], [1e4, 0, 0], gamma, core, [0, h, 0])).ravel()
    assert v[2] == pytest.approx(gamma / (2 * math.pi) * h / (h**2 + core**2), rel=1e-7)  # half at h = δ
    on = np.array(filament_velocity([-1, 0, 0], [1, 0, 0], gamma, core, [[0.3, 0, 0], [1, 0, 0]])).T
    assert np.all(np.isfinite(on)) and np.abs(on).max() < 1e-9


def test_square_ring_on_axis():
    # square loop of half-side a in the plane x = 0, circulation right-handed about +x
    a, gamma = 0.7, 1.3
    A, B, C, D = (np.array(v, float) for v in ([0, -a, -a], [0, a, -a], [0, a, a], [0, -a, a]))
    xs = np.array([-2.0, -0.3, 0.0, 0.5, 3.0])
    pts = np.vstack([xs, np.zeros_like(xs), np.zeros_like(xs)])
    v = np.array(ring_velocity((A[:, None], B[:, None], C[:, None], D[:, None]), [gamma], 1e-9, pts))
    exact = 2 * gamma * a**2 / (math.pi * (a**2 + xs**2) * np.sqrt(2 * a**2 + xs**2))
    np.testing.assert_allclose(v[0], exact, rtol=1e-9)
    np.testing.assert_allclose(v[1:], 0, atol=1e-12)


def test_circular_ring_on_axis():
    # a 720-gon stands for the circle: on-axis velocity Γa²/(2(a² + x²)^{3/2})
    a, gamma, n = 0.5, 2.0, 720
    th = 2 * math.pi * np.arange(n + 1) / n
    ring = np.vstack([np.zeros(n + 1), a * np.cos(th), a * np.sin(th)])
    xs = np.array([-1.0, 0.0, 0.2, 2.0])
    pts = np.vstack([xs, np.zeros_like(xs), np.zeros_like(xs)])
    v = np.array(filament_velocity(ring[:, :-1], ring[:, 1:], gamma, 1e-9, pts))
    exact = gamma * a**2 / (2 * (a**2 + xs**2) ** 1.5)
    np.testing.assert_allclose(v[0], exact, rtol=2e-5)  # polygon vs circle: (π/n)²/6
    np.testing.assert_allclose(v[1:], 0, atol=1e-10)


def test_ring_kernel_is_sum_of_four_filaments_and_symbolic():
    rng = np.random.default_rng(3)
    A, B, C, D, P = (rng.normal(size=3) for _ in range(5))
    f = ring_kernel()
    v_ring = np.array(f(A, B, C, D, P, 0.01)).ravel()
    v_fil = sum(np.array(filament_velocity(s, e, 1.0, 0.01, P)).ravel()
                for s, e in ((A, B), (B, C), (C, D), (D, A)))
    np.testing.assert_allclose(v_ring, v_fil, rtol=1e-12)
    # symbolic: derivative w.r.t. a corner against central differences
    x = ca.MX.sym("x", 3)
    jac = ca.Function("j", [x], [ca.jacobian(f(x, B, C, D, P, 0.01), x)])
    J = np.array(jac(A))
    eps = 1e-6
    for i in range(3):
        dA = np.zeros(3)
        dA[i] = eps
        fd = (np.array(f(A + dA, B, C, D, P, 0.01)) - np.array(f(A - dA, B, C, D, P, 0.01))).ravel() / (2 * eps)
        np.testing.assert_allclose(J[:, i], fd, rtol=1e-5, atol=1e-8)
