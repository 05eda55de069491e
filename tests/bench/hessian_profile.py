"""Where the exact Hessian of a whole-mission problem spends its time.

    python tests/bench/hessian_profile.py [ga2p|ga8p|ttw] [--analytic-section]

Builds the optimization problem (not solved) and times, at its initial point:
the NLP's Hessian-of-the-Lagrangian function built from scratch (its build is what
IPOPT's setup pays), its evaluation, the Hessian restricted to the non-design
variables (what the design directions add), the star colouring of the sparsity, and
the Hessian of each constraint group alone.  ``--analytic-section`` replaces the
airfoil B-spline surfaces by a cheap analytic section (cl = 6 a + 0.4,
ln cd = ln(0.008 + a^2/2)) to bound what any faster surrogate could gain.  Not
collected by pytest; times are the best of 3 evaluations.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import casadi as ca
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))


def _analytic_section():
    import mdo.airfoil.model as model
    orig_s, orig_e = model.SplineSet.surface, model.SplineSet.edges

    def surface(self, lib, a, r, n):
        if lib is not ca:
            return orig_s(self, lib, a, r, n)
        return 6.0 * a + 0.4 + 0.0 * r, ca.log(0.008 + 0.5 * a * a) - 0.1 * (r - 13.0), -0.1 + 0.0 * a

    def edges(self, lib, r, n):
        if lib is not ca:
            return orig_e(self, lib, r, n)
        z = 0.0 * r
        return [z + 0.28, z - 0.2, z + 1.5, z - 3.0, z - 0.1, z - 0.8, z - 3.5, z - 0.05]

    model.SplineSet.surface, model.SplineSet.edges = surface, edges


def best(f, *args, n=3):
    f(*args)
    ts = []
    for _ in range(n):
        t = time.perf_counter()
        f(*args)
        ts.append(time.perf_counter() - t)
    return min(ts)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("problem", nargs="?", default="ga2p")
    ap.add_argument("--analytic-section", action="store_true")
    ap.add_argument("--option", "-o", action="append", default=[], metavar="KEY=VALUE",
                    help="keyword for the problem's build()")
    ap.add_argument("--groups", action="store_true", help="also time each constraint group's Hessian alone")
    ap.add_argument("--without", action="append", default=[], metavar="VAR[,VAR...]",
                    help="also time the Hessian w.r.t. all variables but these (repeatable)")
    a = ap.parse_args()
    if a.analytic_section:
        _analytic_section()
    from mdo.cli import _parse_option
    from mdo.nlp import load_problem_file

    t = time.perf_counter()
    prob = load_problem_file(ROOT / "problems" / f"{a.problem}.py", options=dict(_parse_option(o) for o in a.option))
    print(f"{a.problem}: build {time.perf_counter() - t:.1f} s")
    o = prob.opti
    x0 = np.array(o.debug.value(o.x, o.initial())).ravel()
    p0 = np.array(o.debug.value(o.p, o.value_parameters())).ravel() if o.p.shape[0] else np.zeros(0)
    lam = ca.MX.sym("lam", o.g.shape[0])
    L = o.f + ca.dot(lam, o.g)
    l0 = np.random.default_rng(0).uniform(size=o.g.shape[0])

    t = time.perf_counter()
    H = ca.Function("H", [o.x, o.p, lam], [ca.triu(ca.hessian(L, o.x)[0])])
    t_build = time.perf_counter() - t
    sp = H.sparsity_out(0)
    colours = ca.Sparsity(sp + sp.T).star_coloring().size2()
    G = ca.Function("G", [o.x, o.p], [o.g])
    J = ca.Function("J", [o.x, o.p], [ca.jacobian(o.g, o.x)])
    print(f"variables {o.x.shape[0]}, constraints {o.g.shape[0]}, Hessian nnz (upper) {sp.nnz()}, "
          f"star colours {colours}")
    print(f"Hessian function build {t_build:.1f} s")
    print(f"constraints {best(G, x0, p0) * 1e3:.1f} ms, Jacobian {best(J, x0, p0) * 1e3:.0f} ms, "
          f"Hessian {best(H, x0, p0, l0) * 1e3:.0f} ms")

    nd = ca.vertcat(*[ca.vec(v.scaled) for v in prob.variables.values() if not v.design])
    Hn = ca.Function("Hn", [o.x, o.p, lam], [ca.triu(ca.hessian(L, nd)[0])])
    spn = Hn.sparsity_out(0)
    cn = ca.Sparsity(spn + spn.T).star_coloring().size2()
    print(f"Hessian w.r.t. the {nd.shape[0]} non-design variables only: {best(Hn, x0, p0, l0) * 1e3:.0f} ms "
          f"({cn} colours)")

    for spec in a.without:
        drop = set(spec.split(","))
        xs = ca.vertcat(*[ca.vec(v.scaled) for v in prob.variables.values() if v.name not in drop])
        Hw = ca.Function("Hw", [o.x, o.p, lam], [ca.triu(ca.hessian(L, xs)[0])])
        print(f"Hessian without {sorted(drop)}: {best(Hw, x0, p0, l0) * 1e3:.0f} ms")

    if a.groups:
        rows = []
        for name, g in prob.groups.items():
            lg = ca.MX.sym("l", g.size)
            Hg = ca.Function("Hg", [o.x, o.p, lg], [ca.triu(ca.hessian(ca.dot(lg, g.residual), o.x)[0])])
            rows.append((best(Hg, x0, p0, np.ones(g.size), n=2), name, g.size))
        print("constraint group alone: Hessian time")
        for tg, name, n in sorted(rows, reverse=True):
            print(f"  {tg * 1e3:8.0f} ms  {name} ({n} rows)")


if __name__ == "__main__":
    main()
