"""The flattest directions of an optimum (issues 19, 20): where the optimizer can move
at almost no cost, and which variables move together.

    python tests/bench/kkt_directions.py ga2p results/ga2p/solution.json [--k 12] [--active 1e-4]

Builds the problem's optimization, warm-starts it from the solution (with its multipliers)
and lets IPOPT re-converge (a few iterations), then forms the KKT matrix of the reduced
problem at that point,

    K = [[H, J_a'], [J_a, 0]],   H = Hessian of f + lam' g,

with ``J_a`` the equality rows and the inequality rows whose multiplier exceeds
``--active`` (IPOPT's scaling).  Its eigenvalues nearest zero (shift-invert Lanczos,
``scipy.sparse.linalg.eigsh``) and their eigenvectors' largest entries name the
near-redundant directions: small |eigenvalue| with an eigenvector mostly in x is a
direction the objective barely sees (a flat valley: several starts end at different
points of it); an eigenvector mostly in the multipliers is a dependent set of active rows.
Not collected by pytest.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import casadi as ca
import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import eigsh

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.nlp import load_problem_file  # noqa: E402
from mdo.nlp.hessian import _positions  # noqa: E402


def _csc(M) -> sp.csc_matrix:
    M = ca.DM(M)
    r, c = M.sparsity().get_triplet()
    return sp.csc_matrix((np.asarray(M.nonzeros()).ravel(), (r, c)), shape=M.shape)


def kkt_at_solution(problem, active: float):
    """(K, n, m): the reduced KKT matrix at the problem's converged point, the number of x and of active rows."""
    opti = problem.opti
    x = np.asarray(opti.debug.value(opti.x)).ravel()
    lam = np.asarray(opti.debug.value(opti.lam_g)).ravel()
    p = np.asarray(opti.debug.value(opti.p)).ravel() if opti.np else np.zeros(0)
    lbg = np.asarray(opti.debug.value(opti.lbg)).ravel()
    ubg = np.asarray(opti.debug.value(opti.ubg)).ravel()
    L = opti.f + ca.dot(ca.DM(lam), opti.g)
    H = _csc(ca.Function("H", [opti.x, opti.p], [ca.triu(ca.hessian(L, opti.x)[0])])(x, p))
    H = H + sp.triu(H, 1).T
    J = _csc(ca.Function("J", [opti.x, opti.p], [ca.jacobian(opti.g, opti.x)])(x, p)).tocsr()
    rows = np.flatnonzero(np.isclose(lbg, ubg) | (np.abs(lam) > active))
    return sp.bmat([[H, J[rows].T], [J[rows], None]]).tocsc(), H.shape[0], rows.size


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("problem")
    ap.add_argument("solution")
    ap.add_argument("--k", type=int, default=12, help="eigenvalues to report")
    ap.add_argument("--active", type=float, default=1e-4, help="multiplier above which an inequality is active")
    ap.add_argument("--max-iter", type=int, default=50)
    args = ap.parse_args()
    problem = load_problem_file(ROOT / "problems" / f"{args.problem}.py")
    problem.warm_start(args.solution)
    problem.start_from_baseline()
    sol = problem.solve(verbose=False, max_iter=args.max_iter)
    print(f"{args.problem}: re-converged {sol.status} in {sol.iterations} iterations, "
          f"energy {sol.summary_values().get('battery_energy_kWh'):.4f} kWh")
    K, n, m = kkt_at_solution(problem, args.active)
    print(f"KKT: {n} variables, {m} active rows")
    vals, vecs = eigsh(K, k=args.k, sigma=1e-9, which="LM")
    name, index = np.empty(n, dtype=object), np.zeros(n, int)
    for var, ii in _positions(problem, problem.opti.x).items():
        name[ii], index[ii] = var, np.arange(len(ii))
    print("| eigenvalue | share in x | largest entries (normalized) |\n|---:|---:|---|")
    for i in np.argsort(np.abs(vals)):
        v = vecs[:n, i]
        nv = np.linalg.norm(v)
        top = np.argsort(-np.abs(v))[:6]
        desc = ", ".join(f"{name[j]}[{index[j]}] {v[j] / max(nv, 1e-300):+.2f}" for j in top)
        print(f"| {vals[i]:+.2e} | {nv:.2f} | {desc} |")


if __name__ == "__main__":
    main()
