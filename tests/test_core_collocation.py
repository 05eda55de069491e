"""CGL collocation: exactness on polynomials, spectral convergence on smooth functions."""
import numpy as np
import pytest

from mdo.core import Collocation, cgl_nodes, differentiation_matrix, integration_matrix


@pytest.mark.parametrize("n", [2, 3, 5, 8, 16])
@pytest.mark.parametrize("interval", [(-1.0, 1.0), (0.0, 1.0), (3.0, 10.5)])
def test_exact_for_polynomials_up_to_degree_n_minus_1(n, interval):
    t0, tf = interval
    t = cgl_nodes(n, t0, tf)
    D = differentiation_matrix(n, t0, tf)
    I = integration_matrix(n, t0, tf)
    assert t[0] == pytest.approx(t0) and t[-1] == pytest.approx(tf)
    assert np.all(np.diff(t) > 0)
    for k in range(n):
        f = t ** k
        df = k * t ** (k - 1) if k > 0 else 0 * t
        F = (t ** (k + 1) - t0 ** (k + 1)) / (k + 1)
        scale = max(1.0, abs(tf)) ** k
        assert np.max(np.abs(D @ f - df)) <= 1e-9 * scale * n ** 2
        assert np.max(np.abs(I @ f - F)) <= 1e-11 * scale * abs(tf - t0) * max(1.0, abs(tf))


def test_degree_n_not_exact():
    n = 5
    t = cgl_nodes(n)
    assert np.max(np.abs(differentiation_matrix(n) @ t ** n - n * t ** (n - 1))) > 1e-3


def test_spectral_convergence_on_smooth_function():
    errs_d, errs_i = [], []
    ns = [4, 8, 12, 16, 20, 24, 28]
    for n in ns:
        t = cgl_nodes(n, 0.0, 2.0)
        f = np.exp(np.sin(2 * t))
        df = 2 * np.cos(2 * t) * f
        errs_d.append(np.max(np.abs(differentiation_matrix(n, 0, 2) @ f - df)))
        # integral reference by a fine CGL quadrature (converged to round-off)
        errs_i.append(abs(integration_matrix(n, 0, 2)[-1] @ f - integration_matrix(60, 0, 2)[-1]
                          @ np.exp(np.sin(2 * cgl_nodes(60, 0, 2)))))
    # exponential decay: each 4 more nodes gains more than a decade until round-off
    assert errs_d[-1] < 1e-8 and errs_i[-1] < 1e-11
    for a, b in zip(errs_d[:-1], errs_d[1:]):
        assert b < a / 10


def test_collocation_object_unit_interval():
    c = Collocation(7)
    assert c.s[0] == 0 and c.s[-1] == 1
    assert c.weights.sum() == pytest.approx(1.0)
    assert np.allclose(c.D @ c.s ** 3, 3 * c.s ** 2)
    # duration scaling: d/dt = D / T for t = T s
    T = 42.0
    assert np.allclose((c.D / T) @ (T * c.s) ** 2, 2 * T * c.s)


def test_too_few_nodes_is_an_error():
    with pytest.raises(ValueError, match="n >= 2"):
        cgl_nodes(1)


def test_the_interpolants_derivative_anywhere_and_the_points_a_rate_limit_holds_at():
    from mdo.core.collocation import Collocation
    col = Collocation(6)
    np.testing.assert_allclose(col.derivative_at(col.s), col.D, atol=1e-12)     # E = D at the nodes
    s = col.between_nodes(3)
    assert len(s) == 6 + 5 * 3 and np.all(np.diff(s) > 0) and s[0] == 0.0 and s[-1] == 1.0
    f = lambda x: x ** 5 - 2 * x ** 3 + x            # noqa: E731  degree 5: exact with 6 nodes
    np.testing.assert_allclose(col.derivative_at(s) @ f(col.s), 5 * s ** 4 - 6 * s ** 2 + 1, atol=1e-12)
    # a degree-5 interpolant whose node derivatives stay within 1 can exceed it between them
    bump = np.array([0.0, 0.0, 0.0, 1.0, 1.0, 1.0])
    assert np.max(np.abs(col.derivative_at(s) @ bump)) > np.max(np.abs(col.D @ bump))
