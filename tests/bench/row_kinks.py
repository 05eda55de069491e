"""Constraint rows that jump or kink along an IPOPT step (issue 20 item 2).

    python tests/bench/row_kinks.py ttw results/ttw/analysis/solution.json 99 100

Builds PROBLEM's optimization, starts it from BASELINE (as ``mdo run --from-baseline`` does),
runs IPOPT to iteration TO keeping the iterates FROM and TO, and evaluates every constraint row
and the objective at 161 points on the line through them (t from -0.5 to 1.5; 0 is FROM, 1 is
TO).  It prints the rows whose largest second difference along the line stands out from their
median (a jump or a kink: a model that is not smooth where the iterates go), with the place on
the line.  Two iterates an IPOPT run steps back and forth between are the natural pair.
``--iterates FILE.npz``: the two iterates are saved there after the solve, and read from there
(no solve) when it exists - so a model change can be traced along the same line.
Not collected by pytest.
"""
from __future__ import annotations

import sys
from pathlib import Path

import casadi as ca
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.nlp.run import _import_file  # noqa: E402


class _Keep:
    """Stands in for the divergence watch: IPOPT's iteration callback keeps the iterates."""
    reason = None

    def __init__(self, problem, first: int):
        self.problem, self.first, self.kept = problem, first, {}

    def check(self, log_path, iteration: int) -> None:
        if iteration >= self.first:
            opti = self.problem.opti
            self.kept[iteration] = np.asarray(opti.debug.value(opti.x), float).ravel().copy()


def row_labels(p) -> list:
    """Every row of ``opti.g`` labelled with its constraint group (variable bounds: None)."""
    opti = p.opti
    opti.solver("ipopt")
    adv = opti.advanced
    adv.bake()
    labels = [None] * int(opti.ng)
    for name, g in p.groups.items():
        start = adv.get_meta_con(g.con).start
        for j, lab in enumerate(g.labels):
            labels[start + j] = f"{name} | {lab}"
    return labels


def main():
    args = sys.argv[1:]
    saved = None
    if "--iterates" in args:
        i = args.index("--iterates")
        saved = Path(args[i + 1])
        del args[i:i + 2]
    problem, baseline, first, last = args[0], args[1], int(args[2]), int(args[3])
    p = _import_file(ROOT / "problems" / f"{problem}.py").build(analysis=False)
    p.warm_start(baseline)
    p.start_from_baseline()
    opti = p.opti
    if saved is not None and saved.exists():
        z = np.load(saved)
        xa, xb = z["xa"], z["xb"]
        print(f"{problem}: iterates {first} and {last} read from {saved}")
    else:
        keep = _Keep(p, first)
        p.divergence_watch = keep
        log = Path(f"/tmp/row_kinks_{problem}_ipopt.log")
        sol = p.solve(verbose=False, max_iter=last, threads=2, log_path=log)
        print(f"{problem}: {sol.status} after {sol.iterations} iterations (IPOPT log {log})")
        xa, xb = keep.kept[first], keep.kept[last]
        if saved is not None:
            np.savez(saved, xa=xa, xb=xb)
    par = np.asarray(opti.value(opti.p, opti.value_parameters()), float).ravel() if opti.np else np.zeros(0)
    labels = row_labels(p)
    G = ca.Function("g", [opti.x, opti.p], [opti.g, opti.f])
    ts = np.linspace(-0.5, 1.5, 161)
    rows, f = [], []
    for t in ts:
        g, fv = G(xa + t * (xb - xa), par)
        rows.append(np.asarray(g).ravel())
        f.append(float(fv))
    V = np.array(rows)
    d1 = np.abs(np.diff(V, axis=0)).max(axis=0)
    d2 = np.abs(np.diff(V, 2, axis=0))
    spike = d2.max(axis=0) / (np.median(d2, axis=0) + 1e-3 * d1 + 1e-15)
    spike[d1 < 1e-8] = 0.0
    print(f"step norm {np.linalg.norm(xb - xa):.3g}; objective's largest second difference "
          f"{np.abs(np.diff(f, 2)).max():.3g}")
    print(f"{'spike':>8s}  row (largest second difference, where on the line)")
    for i in np.argsort(-spike)[:20]:
        k = int(np.argmax(d2[:, i]))
        print(f"{spike[i]:8.3g}  {labels[i] or f'bound row {i}'}: {d2[k, i]:.3g} at t = {ts[k + 1]:.3f} "
              f"(median {np.median(d2[:, i]):.3g})")


if __name__ == "__main__":
    main()
