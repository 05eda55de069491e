"""Airfoil surrogate: continuity of value and slope across every blend, finite
first and second derivatives over alpha in [-180, 180] deg, Re in [2e4, 1e7],
M in [0, 0.8] (issue 3), derivatives checked against finite differences."""
import casadi as ca
import numpy as np
import pytest

from mdo.airfoil import Airfoil

NAMES = ["clarky", "e63", "naca0015", "naca4412", "naca63412"]


def _derivative_functions(af):
    """SX function: values, Jacobian d/d(alpha, ln Re, M), stacked Hessians."""
    a, lr, m = ca.SX.sym("a"), ca.SX.sym("lr"), ca.SX.sym("m")
    cl, cd, cm = af.coefficients(a, ca.exp(lr), m)
    y = ca.vertcat(cl, cd, cm)
    x = ca.vertcat(a, lr, m)
    jac = ca.jacobian(y, x)
    hess = ca.vertcat(*[ca.vec(ca.hessian(y[k], x)[0]) for k in range(3)])
    return ca.Function("d", [a, lr, m], [y, jac, hess])


def _alpha_derivatives(af):
    """SX function: values, d/dalpha and d2/dalpha2 of (cl, cd, cm)."""
    a, lr, m = ca.SX.sym("a"), ca.SX.sym("lr"), ca.SX.sym("m")
    y = ca.vertcat(*af.coefficients(a, ca.exp(lr), m))
    d1 = ca.jacobian(y, a)
    d2 = ca.jacobian(d1, a)
    return ca.Function("da", [a, lr, m], [y, d1, d2])


@pytest.mark.parametrize("name", NAMES)
def test_finite_first_and_second_derivatives(name):
    af = Airfoil.from_name(name)
    f = _derivative_functions(af)
    alpha = np.radians(np.concatenate([np.linspace(-180, 180, 145), [-90.0, 0.0, 90.0, 179.999]]))
    lre = np.log(np.array([2e4, 3e4, 6e4, 2e5, 1e6, 3e6, 7.5e6, 1e7]))
    mach = np.array([0.0, 0.3, 0.6, 0.7, 0.75, 0.8])
    A, R, M = (g.ravel()[None, :] for g in np.meshgrid(alpha, lre, mach, indexing="ij"))
    out = f.map(A.size)(A, R, M)
    for o in out:
        assert np.all(np.isfinite(np.array(o))), name


@pytest.mark.parametrize("name", NAMES)
def test_value_and_slope_continuous_over_full_circle(name):
    """On a 0.01 deg grid over the full circle, consecutive values differ by no more
    than the step times the largest slope, and consecutive slopes by no more than the
    step times the largest curvature: a jump in value or slope anywhere (a blend
    seam, the +-180 deg wrap) would break these bounds."""
    af = Airfoil.from_name(name)
    f = _alpha_derivatives(af)
    h = np.radians(0.01)
    alpha = np.arange(-np.pi, np.pi + h / 2, h)
    n = alpha.size
    fm = f.map(n)
    for re_, m in ((3e4, 0.0), (2e5, 0.2), (1e6, 0.5), (8e6, 0.7)):
        y, d1, d2 = (np.array(o) for o in fm(alpha[None], np.full((1, n), np.log(re_)),
                                                   np.full((1, n), m)))
        for k in range(3):
            dv = np.abs(np.diff(y[k]))
            bound_v = h * np.maximum(np.abs(d1[k, :-1]), np.abs(d1[k, 1:])) * 1.05 + 1e-12
            assert np.all(dv <= bound_v + 0.5 * h ** 2 * np.abs(d2[k]).max()), (name, re_, m, k)
            ds = np.abs(np.diff(d1[k]))
            bound_s = h * np.maximum(np.abs(d2[k, :-1]), np.abs(d2[k, 1:])) * 1.05 + 1e-9
            excess = ds - bound_s
            # allow the third-derivative term of a Taylor step
            assert np.all(excess <= 0.01 * h * np.abs(d2[k]).max() + 1e-8), (name, re_, m, k)
        # the +-180 deg seam: value and slope agree within one grid step
        assert np.allclose(y[:, 0], y[:, -1], atol=1e-9)
        assert np.allclose(d1[:, 0], d1[:, -1], atol=1e-6)


def test_derivatives_match_finite_differences():
    af = Airfoil.from_name("naca4412")
    f = _derivative_functions(af)
    rng = np.random.default_rng(7)
    pts = np.column_stack([np.radians(rng.uniform(-180, 180, 40)),
                           np.log(10 ** rng.uniform(4.3, 7.0, 40)), rng.uniform(0, 0.8, 40)])
    # include the stall seams and the data edges of one level
    pts = np.vstack([pts, [[np.radians(a), np.log(1e6), 0.3] for a in (-20, -16, 17, 19, 22, 25)]])
    eps = np.array([1e-6, 1e-6, 1e-6])
    for p in pts:
        y, jac, hess = (np.array(o) for o in f(*p))
        for i in range(3):
            dp = np.zeros(3)
            dp[i] = eps[i]
            yp, jp = (np.array(o) for o in f(*(p + dp))[:2])
            ym, jm = (np.array(o) for o in f(*(p - dp))[:2])
            fd = (yp - ym).ravel() / (2 * eps[i])
            assert np.allclose(jac[:, i], fd, rtol=1e-5, atol=1e-6), (p, i)
            fd2 = (jp - jm)[:, :] / (2 * eps[i])  # d(jac)/dx_i -> column i of each Hessian
            h3 = hess.reshape(3, 3, 3)  # output k, vec(H_k) column-major
            for k in range(3):
                assert np.allclose(h3[k][:, i], fd2[k], rtol=1e-4, atol=1e-4 * (1 + np.abs(fd2[k]).max())), (p, i, k)


def test_usable_inside_sx_kernel_mapped_from_mx():
    """The pattern the rotor uses: an SX kernel over blade stations that calls the
    airfoil, mapped over mission nodes and called with MX; exact Hessian exists."""
    af = Airfoil.from_name("naca4412")
    ns = 8
    a = ca.SX.sym("a", ns)
    w = ca.SX.sym("w", ns)   # relative speed [m/s]
    chord = 0.1
    re_ = w * chord / 1.5e-5
    cl, cd, _ = af.coefficients(a, re_, w / 340.0)
    kernel = ca.Function("stations", [a, w], [ca.sum1(0.5 * w ** 2 * chord * (cl - 0.1 * cd))])
    nodes = 5
    A = ca.MX.sym("A", ns, nodes)
    W = ca.MX.sym("W", ns, nodes)
    total = ca.sum2(kernel.map(nodes)(A, W))
    x = ca.vertcat(ca.vec(A), ca.vec(W))
    H = ca.Function("H", [A, W], [ca.hessian(total, x)[0]])
    a0 = np.radians(np.linspace(-5, 25, ns * nodes)).reshape(ns, nodes)
    w0 = np.linspace(20, 230, ns * nodes).reshape(ns, nodes)
    hval = np.array(H(a0, w0))
    assert hval.shape == (2 * ns * nodes, 2 * ns * nodes) and np.all(np.isfinite(hval))
