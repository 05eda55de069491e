"""The derivatives in two threads (mdo.nlp.threads) are the same matrices: the Hessian of
the Lagrangian to the bit, the constraint Jacobian to round-off, at random points (with a
frozen global too), and IPOPT takes the same path to the same optimum."""
import casadi as ca
import numpy as np
import pytest

from mdo.core import InputError
from mdo.nlp.hessian import _positions, constraint_jacobian_function, general_rows, lagrangian_hessian_functions
from mdo.nlp.ipopt import check_threads, default_threads
from test_hessian_split import _frozen_problem


def _problem(freeze=False):
    """test_hessian_split's brachistochrone with two globals (duration; end height, a design
    variable) and simple rows the solver turns into bounds; the analysis freezes the design."""
    p = _frozen_problem(nodes=14)
    if freeze:
        p.freeze_design()
    return p


def _dense(m):
    return np.asarray(ca.DM(m).full())


@pytest.mark.parametrize("freeze", [False, True])
def test_two_threads_give_the_same_hessian_and_jacobian(freeze):
    """The Hessian in two threads (an optimization) or one (an analysis: its frozen global's
    few rows would not pay for a thread), and the Jacobian in two threads or one, against
    CasADi's own Jacobian of the rows IPOPT keeps; a frozen column is zeros, not computed."""
    p = _problem(freeze=freeze)
    x, g = p.opti.x, p.opti.g
    rows = general_rows(x, p.opti.p, g)
    gr = g[[int(i) for i in rows]]
    ref = ca.Function("ref", [x, p.opti.p], [gr, ca.jacobian(gr, x)])
    H1, H2 = (lagrangian_hessian_functions(p, "split", threads=t) for t in (1, 2))
    J1, J2 = (constraint_jacobian_function(p, threads=t) for t in (1, 2))
    assert ("ThreadMap" in {f.class_name() for f in H2.find_functions()}) == (not freeze)
    assert "ThreadMap" in {f.class_name() for f in J2.find_functions()}
    f = int(_positions(p, x)["end_height"][0])
    rng = np.random.default_rng(3)
    x0 = np.asarray(p.opti.debug.value(x, p.opti.initial()), float).ravel()
    for _ in range(3):
        xr = x0 * (1 + 0.1 * rng.normal(size=x0.size))
        lam = rng.normal(size=rows.size)
        a, b = _dense(H1(xr, [], 0.9, lam)), _dense(H2(xr, [], 0.9, lam))
        assert np.array_equal(a, b)        # to the bit: the same IPOPT path
        g0, j0 = ref(xr, [])
        for J in (J1, J2):
            gj, jj = J(xr, [])
            assert jj.sparsity() == j0.sparsity()      # what IPOPT is told, and nlp_size reports
            assert np.max(np.abs(_dense(gj) - _dense(g0))) == 0.0
            a, b = _dense(j0), _dense(jj)
            if freeze:   # the frozen design's column: zeros (IPOPT removes fixed variables)
                assert np.abs(a[:, f]).max() > 0 and np.abs(b[:, f]).max() == 0
                a, b = np.delete(a, f, axis=1), np.delete(b, f, axis=1)
            assert np.max(np.abs(a - b)) <= 1e-13 * np.max(np.abs(a))


def test_two_threads_take_the_same_ipopt_path():
    sols = {t: _problem().solve(verbose=False, threads=t) for t in (1, 2)}
    assert sols[1].success and sols[2].success
    assert sols[1].iterations == sols[2].iterations
    assert sols[2].objective == pytest.approx(sols[1].objective, rel=1e-10)


def test_thread_count_is_checked(monkeypatch):
    with pytest.raises(InputError, match="threads"):
        _problem().solve(verbose=False, threads=3)
    with pytest.raises(InputError, match="MDO_THREADS"):
        monkeypatch.setenv("MDO_THREADS", "four")
        default_threads()
    monkeypatch.setenv("MDO_THREADS", "1")
    assert default_threads() == 1
    assert check_threads("2") == 2


def test_threads_set_for_a_run_are_restored_after_it(monkeypatch):
    """``mdo run --threads`` sets MDO_THREADS for its run only (the guess's numeric BEMT reads
    it too), and puts back what was there."""
    from mdo.core.parallel import threads_set_to
    monkeypatch.delenv("MDO_THREADS", raising=False)
    with threads_set_to(1):
        assert default_threads() == 1
    assert "MDO_THREADS" not in __import__("os").environ
    monkeypatch.setenv("MDO_THREADS", "2")
    with threads_set_to(1):
        assert default_threads() == 1
    assert default_threads() == 2
    with threads_set_to(None):
        assert default_threads() == 2
    with pytest.raises(InputError, match="threads"):
        with threads_set_to(3):
            pass
