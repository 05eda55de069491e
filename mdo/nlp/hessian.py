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

__all__ = ["HESSIAN_KINDS", "general_rows", "global_variables", "lagrangian_hessian_functions"]

HESSIAN_KINDS = ("full", "split")


def global_variables(problem) -> list:
    """The variables that are not per node: shape (n, 1) - design, blade, TOGW, durations."""
    return [v for v in problem.variables.values() if v.shape[1] == 1]


def _positions(problem, x) -> dict:
    """Each variable's entries as indices into the solver's ``x``."""
    out, seen = {}, 0
    for v in problem.variables.values():
        sp = ca.Function("pos", [x], [ca.vec(v.scaled)]).jac_sparsity(0, 0)
        rows, cols = sp.get_triplet()
        idx = np.empty(v.size, dtype=int)
        idx[np.asarray(rows, int)] = np.asarray(cols, int)
        out[v.name] = idx
        seen += v.size
    if seen != x.numel():
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


def lagrangian_hessian_functions(problem, kind: str = "split", *, simple_bounds: bool = True,
                                 skip_fixed: bool = True) -> ca.Function:
    """``nlp_hess_l(x, p, lam_f, lam_g) -> triu(H)`` of ``problem``'s Opti.

    ``kind``: ``"full"`` (CasADi's own, one colouring of x) or ``"split"`` (module
    docstring).  ``simple_bounds``: the solver detects simple bounds (the
    ``detect_simple_bounds`` plugin option, as ``Problem.solve`` sets it), so
    ``lam_g`` holds only the general rows (:func:`general_rows`).  Give the result to
    IPOPT as the ``hess_lag`` plugin option.  ``skip_fixed``: leave out the rows of frozen
    global variables (module docstring; only right while IPOPT removes fixed variables)."""
    if kind not in HESSIAN_KINDS:
        raise InputError("hessian", f"one of {', '.join(HESSIAN_KINDS)}, got {kind!r}")
    opti = problem.opti
    x, g, f, p = opti.x, opti.g, opti.f, opti.p
    if simple_bounds:
        g = g[[int(i) for i in general_rows(x, p, g)]]
    lam_f, lam_g = ca.MX.sym("lam_f"), ca.MX.sym("lam_g", g.numel())
    L = lam_f * f + (ca.dot(lam_g, g) if g.numel() else 0)
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
