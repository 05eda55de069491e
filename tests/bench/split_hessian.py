"""Split Hessian (issue 20): the exact Hessian of the Lagrangian in two parts, the
node-variable block with the global variables held fixed, and the global rows.

    python tests/bench/split_hessian.py [--problem ga2p] [--repeats 3]

Builds the problem's optimization, then (1) the Hessian IPOPT would get by default
(``hessian(L, x)``, one symmetric colouring of the whole x) and (2) ``split_hessian``
of ``mdo.nlp.problem`` (node block, plus the global rows); checks they agree at the
initial point with random multipliers and reports build and evaluation times
(medians, wall and CPU).  With ``--parts``: each part of the split alone (one thread, at the
same point) - the node block ``H_yy``, the global rows ``R`` as committed (reverse over
reverse), ``R`` by forward over reverse (``jacobian(grad_x L, D)'``) and the constraint
Jacobian; ``--per-global`` adds ``R``'s rows of each global variable alone, with whether they
equal the whole ``R``'s to the bit (``results/benchmark.md``, twenty-fourth session).  Not
collected by pytest.
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
    ap.add_argument("--parts", action="store_true", help="time the split's parts alone (not the full Hessian)")
    ap.add_argument("--per-global", action="store_true", help="with --parts: R's rows of each global alone")
    args = ap.parse_args()
    module = _import_file(ROOT / "problems" / f"{args.problem}.py")
    p = module.build(analysis=False)
    opti = p.opti
    x0 = np.asarray(opti.debug.value(opti.x, opti.initial()), float).ravel()
    rng = np.random.default_rng(1)
    from mdo.nlp.hessian import general_rows
    lam = rng.normal(size=general_rows(opti.x, opti.p, opti.g).size)
    par = np.asarray(opti.debug.value(opti.p, opti.value_parameters()), float).ravel() if opti.np else []
    if args.parts:
        return parts(p, x0, par, lam, args)
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


def parts(p, x0, par, lam, args):
    """Each part of the split Hessian alone, and R's two AD modes (module docstring)."""
    from mdo.nlp.hessian import general_rows, global_variables, lagrangian
    opti = p.opti
    x, pp, lam_f, lam_g, L = lagrangian(p)
    glob = [v for v in global_variables(p) if not v.frozen]
    names = {v.name for v in glob}
    Y = ca.veccat(*[v.scaled for v in p.variables.values() if v.name not in names])
    D = ca.veccat(*[v.scaled for v in glob])

    def run(name, expr):
        f = ca.Function(name, [x, pp, lam_f, lam_g], [expr])
        f(x0, par, 1.0, lam)
        wall, cpu, out = timed(lambda: f(x0, par, 1.0, lam), args.repeats)
        print(f"| {name} | {wall:.3f} | {cpu:.3f} |")
        return np.asarray(ca.DM(out).full())

    print(f"{args.problem}: {opti.nx} variables, {D.numel()} globals ({len(glob)} variables)")
    print("| part | eval wall s | eval CPU s |")
    print("|---|---:|---:|")
    run("node_block_H_yy", ca.hessian(L, Y)[0])
    R = run("global_rows_R", ca.jacobian(ca.gradient(L, D), ca.vertcat(Y, D)))
    Rt = run("R_forward_over_reverse", ca.jacobian(ca.gradient(L, ca.vertcat(Y, D)), D).T)
    run("constraint_jacobian", ca.jacobian(opti.g[[int(i) for i in general_rows(x, pp, opti.g)]], x))
    print(f"R's two modes: max abs difference {np.max(np.abs(R - Rt)):.2e} of {np.max(np.abs(R)):.2e}")
    at = 0
    for v in glob if args.per_global else []:
        Rv = run(f"R_rows_{v.name.replace('.', '_')}", ca.jacobian(ca.gradient(L, v.scaled), ca.vertcat(Y, D)))
        print(f"  ({v.size} rows; the same bits as the whole R's: {np.array_equal(Rv, R[at:at + v.size])})")
        at += v.size


if __name__ == "__main__":
    main()
