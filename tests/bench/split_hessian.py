"""Split Hessian (issue 20): the exact Hessian of the Lagrangian in two parts, the
node-variable block with the global variables held fixed, and the global rows.

    python tests/bench/split_hessian.py [--problem ga2p] [--repeats 3]

Builds the problem's optimization, then (1) the Hessian IPOPT would get by default
(``hessian(L, x)``, one symmetric colouring of the whole x) and (2) ``split_hessian``
of ``mdo.nlp.problem`` (node block, plus the global rows); checks they agree at the
initial point with random multipliers and reports build and evaluation times
(medians, wall and CPU).  Not collected by pytest.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import casadi as ca
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.nlp.hessian import lagrangian_hessian_functions  # noqa: E402
from mdo.nlp.run import _import_file  # noqa: E402


def timed(fn, repeats):
    walls, cpus = [], []
    for _ in range(repeats):
        w, c = time.perf_counter(), time.process_time()
        out = fn()
        walls.append(time.perf_counter() - w)
        cpus.append(time.process_time() - c)
    return statistics.median(walls), statistics.median(cpus), out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--problem", default="ga2p")
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    module = _import_file(ROOT / "problems" / f"{args.problem}.py")
    p = module.build(analysis=False)
    opti = p.opti
    x0 = np.asarray(opti.debug.value(opti.x, opti.initial()), float).ravel()
    rng = np.random.default_rng(1)
    from mdo.nlp.hessian import general_rows
    lam = rng.normal(size=general_rows(opti.x, opti.p, opti.g).size)
    par = np.asarray(opti.debug.value(opti.p, opti.value_parameters()), float).ravel() if opti.np else []
    rows = []
    ref = None
    for kind in ("full", "split"):
        t = time.perf_counter()
        f = lagrangian_hessian_functions(p, kind)
        build = time.perf_counter() - t
        wall, cpu, out = timed(lambda: f(x0, par, 1.0, lam), args.repeats)
        H = ca.sparse(out) if not isinstance(out, ca.DM) else out
        Hn = np.asarray(ca.DM(H).full())
        if ref is None:
            ref = Hn
        err = float(np.max(np.abs(Hn - ref)) / max(1e-300, np.max(np.abs(ref))))
        rows.append((kind, build, wall, cpu, int(f.sparsity_out(0).nnz()), err))
    print(f"{args.problem}: {opti.nx} variables, {opti.ng} constraints")
    print("| Hessian | build s | eval wall s | eval CPU s | nnz | max rel diff to full |")
    print("|---|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r[0]} | {r[1]:.1f} | {r[2]:.2f} | {r[3]:.2f} | {r[4]} | {r[5]:.1e} |")


if __name__ == "__main__":
    main()
