"""The split Hessian (mdo.nlp.hessian) is the exact Hessian: the same matrix as
CasADi's own to round-off, with the multipliers of the rows IPOPT keeps after
simple-bound detection, and the same IPOPT path."""
import casadi as ca
import numpy as np
import pytest

from mdo.core import Collocation, InputError
from mdo.nlp import Problem
from mdo.nlp.hessian import _positions, general_rows, global_variables, lagrangian_hessian_functions

G = 9.80665


def _problem(nodes=16):
    """The brachistochrone with the mission's layout: node rows 1 x K, a global duration,
    bounds, and simple rows (the start conditions) that the solver turns into bounds."""
    p = Problem("brachistochrone_rows")
    c = Collocation(nodes)
    D = ca.DM(c.D).T
    tf = p.variable("final_time", unit="s", lower=0.1, upper=10.0, init=2.0, design=True)
    x = p.variable("x", (1, nodes), scale=10.0, lower=0, upper=10, init=10 * c.s)
    y = p.variable("y", (1, nodes), scale=10.0, lower=0, upper=10, init=10 - 5 * c.s)
    v = p.variable("v", (1, nodes), scale=10.0, lower=0, upper=100, init=9.9 * c.s)
    th = p.variable("theta", (1, nodes), lower=0.0, upper=np.pi, init=np.full(nodes, 1.5))
    p.constrain("x dynamics", ca.mtimes(x, D) - tf * v * ca.sin(th), scale=10.0)
    p.constrain("y dynamics", ca.mtimes(y, D) + tf * v * ca.cos(th), scale=10.0)
    p.constrain("v dynamics", ca.mtimes(v, D) - tf * G * ca.cos(th), scale=10.0)
    p.constrain("start", ca.vertcat(x[0], y[0] - 10.0, v[0]))
    p.constrain("end", ca.vertcat(x[-1] - 10.0, y[-1] - 5.0))
    p.minimize(tf, unit="s")
    return p


def test_split_equals_full_at_random_points():
    p = _problem()
    assert [v.name for v in global_variables(p)] == ["final_time"]
    rows = general_rows(p.opti.x, p.opti.p, p.opti.g)
    assert 0 < rows.size < p.opti.ng          # the bounds and start rows are simple
    full, split = (lagrangian_hessian_functions(p, k) for k in ("full", "split"))
    assert full.sparsity_out(0).nnz() == split.sparsity_out(0).nnz()
    rng = np.random.default_rng(0)
    x0 = np.asarray(p.opti.debug.value(p.opti.x, p.opti.initial()), float).ravel()
    for _ in range(3):
        x = x0 * (1 + 0.1 * rng.normal(size=x0.size))
        lam = rng.normal(size=rows.size)
        a, b = (np.asarray(ca.DM(f(x, [], 1.3, lam)).full()) for f in (full, split))
        assert np.max(np.abs(a - b)) <= 1e-12 * np.max(np.abs(a))


def test_split_solve_follows_the_solvers_own_hessian():
    """IPOPT with the split Hessian takes the same iterations as with CasADi's own
    (which sees only the general rows); a wrong multiplier mapping would not."""
    sols = {k: _problem().solve(verbose=False, hessian=k) for k in ("exact", "full")}
    assert sols["exact"].success and sols["full"].success
    assert sols["exact"].iterations == sols["full"].iterations
    assert sols["exact"].objective == pytest.approx(1.8016, abs=2e-3)
    assert sols["exact"].objective == pytest.approx(sols["full"].objective, rel=1e-9)


def test_bad_hessian_choice_names_the_field():
    with pytest.raises(InputError, match="hessian"):
        _problem().solve(verbose=False, hessian="approximate")


def test_optimization_from_the_baseline_uses_a_monotone_barrier_unless_the_problem_chose():
    from mdo.nlp.problem import FROM_BASELINE_OPTIONS
    p = _problem()
    p.start_from_baseline()
    assert {k: p.ipopt_options[k] for k in FROM_BASELINE_OPTIONS} == FROM_BASELINE_OPTIONS
    q = _problem()
    q.ipopt_options["mu_strategy"] = "monotone"
    q.ipopt_options["mu_init"] = 0.5
    q.start_from_baseline()
    assert q.ipopt_options["mu_init"] == 0.5


def _frozen_problem(nodes=12):
    """The brachistochrone with a second global (the end height, a design variable) that an
    analysis freezes: its Hessian rows are left out of the split."""
    p = Problem("brachistochrone_frozen")
    c = Collocation(nodes)
    D = ca.DM(c.D).T
    tf = p.variable("final_time", unit="s", lower=0.1, upper=10.0, init=2.0)
    yf = p.variable("end_height", unit="m", lower=1.0, upper=9.0, init=5.0, design=True)
    x = p.variable("x", (1, nodes), scale=10.0, lower=0, upper=10, init=10 * c.s)
    y = p.variable("y", (1, nodes), scale=10.0, lower=0, upper=10, init=10 - 5 * c.s)
    v = p.variable("v", (1, nodes), scale=10.0, lower=0, upper=100, init=9.9 * c.s)
    th = p.variable("theta", (1, nodes), lower=0.0, upper=np.pi, init=np.full(nodes, 1.5))
    p.constrain("x dynamics", ca.mtimes(x, D) - tf * v * ca.sin(th), scale=10.0)
    p.constrain("y dynamics", ca.mtimes(y, D) + tf * v * ca.cos(th), scale=10.0)
    p.constrain("v dynamics", ca.mtimes(v, D) - tf * G * ca.cos(th), scale=10.0)
    p.constrain("start", ca.vertcat(x[0], y[0] - 10.0, v[0]))
    p.constrain("end", ca.vertcat(x[-1] - 10.0, y[-1] - yf * ca.cos(0.1 * tf)))
    p.minimize(tf + 0.01 * yf * yf * tf, unit="s")
    return p


def test_frozen_globals_rows_are_left_out_and_the_analysis_path_is_unchanged(monkeypatch):
    """An analysis (design frozen) gets the split without the frozen rows: the same matrix
    on every other entry, zeros on the frozen rows, and IPOPT (which removes fixed
    variables) takes the same iterations to the same point as with those rows computed."""
    p = _frozen_problem()
    p.freeze_design()
    rows = general_rows(p.opti.x, p.opti.p, p.opti.g)
    full = lagrangian_hessian_functions(p, "full")
    skip, keep = (lagrangian_hessian_functions(p, "split", skip_fixed=s) for s in (True, False))
    assert skip.sparsity_out(0).nnz() < keep.sparsity_out(0).nnz()
    x0 = np.asarray(p.opti.debug.value(p.opti.x, p.opti.initial()), float).ravel()
    lam = np.random.default_rng(1).normal(size=rows.size)
    a, b, c = (np.asarray(ca.DM(f(x0, [], 0.7, lam)).full()) for f in (full, skip, keep))
    j = int(_positions(p, p.opti.x)["end_height"][0])
    assert np.max(np.abs(a - c)) <= 1e-12 * np.max(np.abs(a))
    assert np.abs(a[j]).max() > 0 and np.abs(b[j]).max() == 0 and np.abs(b[:, j]).max() == 0
    mask = np.ones(a.shape[0], bool)
    mask[j] = False
    assert np.max(np.abs((a - b)[np.ix_(mask, mask)])) <= 1e-12 * np.max(np.abs(a))
    import mdo.nlp.problem as problem_module
    sols = {}
    for skip_fixed in (True, False):
        monkeypatch.setattr(problem_module, "lagrangian_hessian_functions",
                            lambda prob, kind, skip_fixed_=skip_fixed, **kw: lagrangian_hessian_functions(
                                prob, kind, skip_fixed=skip_fixed_))
        q = _frozen_problem()
        q.freeze_design()
        sols[skip_fixed] = q.solve(verbose=False)
    assert sols[True].success and sols[True].iterations == sols[False].iterations
    assert sols[True].objective == sols[False].objective
