"""The exact Hessian of the Lagrangian, split by the problem's structure (issue 20).

IPOPT asks for ``H = d2/dx2 (lam_f f + lam_g' g)`` every iteration.  CasADi's default
colours the whole ``x`` at once; the design variables couple every node, so every
colour's forward-over-reverse sweep runs through the design-dependent blocks (the
lattice influence matrix and its factorization, the wake tables, the blade).

The split computes the same matrix in two parts:

* ``H_yy``: the node variables ``y`` (every variable with more than one column: the
  per-node unknowns, controls and states) with the global ones held fixed, so the
  sweeps skip every path that depends only on the design;
* the global rows ``[H_dy, H_dd]``: ``jacobian(grad_d L, x)`` for the few global
  variables ``d`` (column vectors and scalars: the design, the blade unknowns, the
  gross weight, free durations).

Both are exact; which variables are "global" changes only the cost, never the
value (checked against the default to round-off in ``tests/test_hessian_split.py``;
timings in ``tests/bench/split_hessian.py``).

A *frozen* global (a design variable of an analysis, ``Problem.freeze_design``) has equal
bounds, so IPOPT takes it out of its problem (``fixed_variable_treatment`` at its default
``make_parameter``) and never reads its Hessian rows: they are left out (structural
zeros), which takes 13 of GA-2P's 16 global rows out of every analysis iteration.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..core.errors import InputError
from .threads import nonzero_index, scatter, two_thread_sum, upper_entries

__all__ = ["HESSIAN_KINDS", "constraint_jacobian_function", "general_rows", "global_variables", "lagrangian",
           "lagrangian_hessian_functions"]

HESSIAN_KINDS = ("full", "split")


def global_variables(problem) -> list:
    """The variables that are not per node: shape (n, 1) - design, blade, TOGW, durations."""
    return [v for v in problem.variables.values() if v.shape[1] == 1]


def _positions(problem, x) -> dict:
    """Each variable's entries as indices into the solver's ``x``."""
    variables = list(problem.variables.values())
    sp = ca.Function("pos", [x], [ca.veccat(*[v.scaled for v in variables])]).jac_sparsity(0, 0)
    rows, cols = (np.asarray(a, int) for a in sp.get_triplet())
    where = np.full(sp.size1(), -1, dtype=int)
    where[rows] = cols
    out, seen = {}, 0
    for v in variables:
        out[v.name] = where[seen:seen + v.size]
        seen += v.size
    if seen != x.numel() or (where < 0).any():
        raise InputError("hessian", f"{x.numel() - seen} solver variables are not problem variables; use 'full'")
    return out


def general_rows(x, p, g) -> np.ndarray:
    """Indices of the rows of ``g`` that are not simple bounds.

    With ``detect_simple_bounds`` the solver moves every row that depends on one entry
    of ``x`` only, linearly, into the variable bounds (CasADi's Nlpsol rule: one
    nonzero in its Jacobian row, and no second-order dependence on ``x``); the
    multipliers ``lam_g`` the Hessian receives are those of the remaining rows, in
    order."""
    if g.numel() == 0:
        return np.zeros(0, dtype=int)
    sp = ca.Function("rows", [x, p], [g]).jac_sparsity(0, 0)
    per_row = np.diff(np.asarray(sp.T.colind(), int))
    nonlinear = np.asarray(ca.which_depends(g, x, 2, True), bool)
    return np.flatnonzero(~((per_row == 1) & ~nonlinear))


def lagrangian(problem, simple_bounds: bool = True) -> tuple:
    """``(x, p, lam_f, lam_g, L)``: the solver's variables and parameters, the multiplier
    symbols and ``L = lam_f f + lam_g' g`` over the general rows (:func:`general_rows`) when
    the solver detects simple bounds, over every row otherwise."""
    opti = problem.opti
    x, g, f, p = opti.x, opti.g, opti.f, opti.p
    if simple_bounds:
        g = g[[int(i) for i in general_rows(x, p, g)]]
    lam_f, lam_g = ca.MX.sym("lam_f"), ca.MX.sym("lam_g", g.numel())
    return x, p, lam_f, lam_g, lam_f * f + (ca.dot(lam_g, g) if g.numel() else 0)


def lagrangian_hessian_functions(problem, kind: str = "split", *, simple_bounds: bool = True,
                                 skip_fixed: bool = True, threads: int = 1) -> ca.Function:
    """``nlp_hess_l(x, p, lam_f, lam_g) -> triu(H)`` of ``problem``'s Opti.

    ``kind``: ``"full"`` (CasADi's own, one colouring of x) or ``"split"`` (module
    docstring).  ``simple_bounds``: the solver detects simple bounds (the
    ``detect_simple_bounds`` plugin option, as ``Problem.solve`` sets it), so
    ``lam_g`` holds only the general rows (:func:`general_rows`).  Give the result to
    IPOPT as the ``hess_lag`` plugin option.  ``skip_fixed``: leave out the rows of frozen
    global variables (module docstring; only right while IPOPT removes fixed variables).
    ``threads=2``: the split's two parts, the node block and the global rows, each in its own
    thread (:mod:`mdo.nlp.threads`; the same matrix)."""
    if kind not in HESSIAN_KINDS:
        raise InputError("hessian", f"one of {', '.join(HESSIAN_KINDS)}, got {kind!r}")
    x, p, lam_f, lam_g, L = lagrangian(problem, simple_bounds)
    glob = {v.name for v in global_variables(problem)}
    if kind == "full" or not glob or len(glob) == len(problem.variables):
        H = ca.hessian(L, x)[0]          # nothing to split
    else:
        pos = _positions(problem, x)
        node_vars = [v for v in problem.variables.values() if v.name not in glob]
        glob_vars = [v for v in problem.variables.values() if v.name in glob]
        fixed = [v for v in glob_vars if skip_fixed and v.frozen]
        glob_vars = [v for v in glob_vars if not (skip_fixed and v.frozen)]
        Y = ca.veccat(*[v.scaled for v in node_vars])
        D = ca.veccat(*[v.scaled for v in glob_vars])
        ny, nd, nf = Y.numel(), D.numel(), sum(v.size for v in fixed)
        if threads > 1 and nd and not nf:
            # an analysis (frozen globals) keeps one thread: its few global rows would not pay
            # for the second thread (GA-2P 0.31 -> 0.39 s per call measured)
            return _two_thread_hessian(x, p, lam_f, lam_g, L, Y, D, node_vars, glob_vars, pos)
        H_yy = ca.hessian(L, Y)[0]
        H_d = ca.jacobian(ca.gradient(L, D), ca.vertcat(Y, D))         # [H_dy, H_dd]
        H_blk = ca.vertcat(ca.horzcat(H_yy, H_d[:, :ny].T), H_d)
        if nf:   # the frozen globals' rows and columns: structural zeros
            H_blk = ca.diagcat(H_blk, ca.MX(nf, nf))
        # [Y; D; F] = P x  ->  H_x = P' H_blk P
        perm = np.concatenate([pos[v.name] for v in node_vars + glob_vars + fixed])
        n = x.numel()
        P = ca.DM(ca.Sparsity.triplet(n, n, list(range(n)), [int(i) for i in perm]), 1.0)
        H = ca.mtimes(ca.mtimes(P.T, H_blk), P)
    return ca.Function("nlp_hess_l", [x, p, lam_f, lam_g], [ca.triu(H)],
                       ["x", "p", "lam_f", "lam_g"], ["triu_hess_gamma_x_x"])


def _two_thread_hessian(x, p, lam_f, lam_g, L, Y, D, node_vars, glob_vars, pos) -> ca.Function:
    """The split Hessian with its node block and its global rows in two threads."""
    ny = Y.numel()
    iy = np.concatenate([pos[v.name] for v in node_vars])
    idd = np.concatenate([pos[v.name] for v in glob_vars])
    H_yy = ca.hessian(L, Y)[0]                                          # symmetric: keep r <= c
    sa, ra, ca_ = upper_entries(H_yy, iy, iy, np.ones(ny, bool))
    R = ca.jacobian(ca.gradient(L, D), ca.vertcat(Y, D))                # [H_dy, H_dd]
    # the node columns' mirrors are rows of no part; the global columns' are rows of R
    sb, rb, cb = upper_entries(R, idd, np.concatenate([iy, idd]),
                               np.concatenate([np.zeros(ny, bool), np.ones(idd.size, bool)]))
    n = x.numel()
    sp = ca.Sparsity.triplet(n, n, [int(k) for k in np.concatenate([ra, rb])],
                             [int(k) for k in np.concatenate([ca_, cb])])

    def where(r, c):
        return nonzero_index(sp, r, c)

    parts = [scatter(H_yy.nz[[int(k) for k in sa]], where(ra, ca_), sp.nnz()),
             scatter(R.nz[[int(k) for k in sb]], where(rb, cb), sp.nnz())]
    syms, nz = two_thread_sum("nlp_hess_l", [x, p, lam_f, lam_g], parts, sp.nnz())
    return ca.Function("nlp_hess_l", syms, [ca.MX(sp, nz)],
                       ["x", "p", "lam_f", "lam_g"], ["triu_hess_gamma_x_x"])


def constraint_jacobian_function(problem, *, simple_bounds: bool = True, threads: int = 1,
                                 skip_fixed: bool = True) -> ca.Function:
    """``nlp_jac_g(x, p) -> (g, jac_g_x)`` of ``problem``'s Opti.  With ``threads=2`` its node
    columns (the global variables held fixed, as for the Hessian's node block) and its
    global columns each in their own thread (:mod:`mdo.nlp.threads`; the same matrix).  With
    ``skip_fixed`` a frozen global's columns are zeros, not computed, in one thread or two (an
    analysis: GA-2P 0.24 -> 0.18 s per call).  Give the result to IPOPT as the ``jac_g``
    plugin option (``simple_bounds`` and ``skip_fixed`` as for
    :func:`lagrangian_hessian_functions`)."""
    opti = problem.opti
    x, g, p = opti.x, opti.g, opti.p
    if simple_bounds:
        g = g[[int(i) for i in general_rows(x, p, g)]]
    m = g.numel()
    glob = [v for v in global_variables(problem) if not (skip_fixed and v.frozen)]
    frozen = len(glob) < len(global_variables(problem))
    node_vars = [v for v in problem.variables.values() if v.shape[1] != 1]
    if (threads <= 1 and not frozen) or m == 0 or not node_vars or not (glob or frozen):
        return ca.Function("nlp_jac_g", [x, p], [g, ca.jacobian(g, x)], ["x", "p"], ["g", "jac_g_x"])
    pos = _positions(problem, x)
    # the whole Jacobian's sparsity, as CasADi's own nlp_jac_g has it; a frozen global's
    # columns stay in it with zeros (IPOPT removes fixed variables and never reads them)
    sp = ca.Function("jac_pattern", [x, p], [g]).jac_sparsity(0, 0)
    n_nz = sp.nnz()
    vecs = []
    for k, group in enumerate([grp for grp in (node_vars, glob) if grp]):
        Jk = ca.jacobian(g, ca.veccat(*[v.scaled for v in group]))
        i, j = Jk.sparsity().get_triplet()
        at = nonzero_index(sp, i, np.concatenate([pos[v.name] for v in group])[np.asarray(j, int)])
        if (at < 0).any():
            raise RuntimeError("nlp_jac_g: a column block has entries outside the Jacobian's sparsity")
        vecs.append(ca.vertcat(g if k == 0 else ca.MX.zeros(m, 1), scatter(Jk.nz[:], at, n_nz)))
    if threads <= 1 or len(vecs) == 1:   # the frozen columns skipped, in one thread
        both = sum(vecs[1:], vecs[0])
        return ca.Function("nlp_jac_g", [x, p], [both[:m], ca.MX(sp, both[m:])], ["x", "p"], ["g", "jac_g_x"])
    syms, both = two_thread_sum("nlp_jac_g", [x, p], vecs, m + n_nz)
    return ca.Function("nlp_jac_g", syms, [both[:m], ca.MX(sp, both[m:])], ["x", "p"], ["g", "jac_g_x"])
