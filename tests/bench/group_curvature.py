"""Which constraint groups make the Lagrangian Hessian indefinite (issue 20 item 2).

    python tests/bench/group_curvature.py ttw results/ttw/analysis/solution.json 60

Builds PROBLEM's optimization, starts it from BASELINE (a converged analysis' solution.json, as
``mdo run --from-baseline`` does), runs ITERATIONS of IPOPT in this process, and prints for
every constraint group the extreme eigenvalues of its multiplier-weighted Hessian
``sum_i lam_i d2g_i/dx2`` (in IPOPT's scaled variables) and its largest multiplier, and the
same for the objective.  A group whose multipliers have run away (an inactive inequality
far above its barrier value mu / slack) and whose rows are curved shows up as a large
negative eigenvalue.  Not collected by pytest.  The groups' own curvature, not the reduced
Hessian's inertia: a pointer, not a proof.
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

import casadi as ca
import numpy as np
import scipy.sparse as sps
from scipy.sparse.linalg import eigsh

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.nlp.run import _import_file  # noqa: E402


def extreme_eigenvalues(opti, expr, x, par) -> tuple[float, float]:
    H = ca.Function("group_hessian", [opti.x, opti.p], [ca.hessian(expr, opti.x)[0]])(x, par)
    r, c = H.sparsity().get_triplet()
    if not r:
        return 0.0, 0.0
    M = sps.csc_matrix((np.asarray(H.nonzeros()), (r, c)), shape=H.shape)
    M = 0.5 * (M + M.T)
    pick = lambda which: float(eigsh(M, k=1, which=which, tol=1e-4, maxiter=20000,  # noqa: E731
                                     return_eigenvectors=False)[0])
    return pick("SA"), pick("LA")


def main():
    problem, baseline, iterations = sys.argv[1], sys.argv[2], int(sys.argv[3])
    p = _import_file(ROOT / "problems" / f"{problem}.py").build(analysis=False)
    p.warm_start(baseline)
    p.start_from_baseline()
    sol = p.solve(verbose=False, max_iter=iterations, threads=1)
    opti = p.opti
    x = np.asarray(opti.debug.value(opti.x), float).ravel()
    par = np.asarray(opti.debug.value(opti.p, opti.value_parameters()), float).ravel() if opti.np else []
    print(f"{problem}: {sol.status} after {sol.iterations} iterations")
    print(f"{'group':45s} {'min eig':>11s} {'max eig':>11s} {'max |lam|':>10s}")
    rows = []
    for name, g in p.groups.items():
        if g.con is None:
            continue
        lam = np.asarray(opti.debug.value(opti.dual(g.con)), float).ravel()
        if not np.any(lam):
            continue
        t = time.perf_counter()
        lo, hi = extreme_eigenvalues(opti, ca.dot(ca.DM(lam), ca.vec(g.residual)), x, par)
        rows.append((lo, hi, name, float(np.abs(lam).max()), time.perf_counter() - t))
    for lo, hi, name, lam, _ in sorted(rows):
        print(f"{name:45s} {lo:11.3g} {hi:11.3g} {lam:10.3g}")
    lo, hi = extreme_eigenvalues(opti, opti.f, x, par)
    print(f"{'objective':45s} {lo:11.3g} {hi:11.3g}")


if __name__ == "__main__":
    main()
