"""Benchmark: section coefficients at 10^4 stations (not collected by pytest).

    /work/venv/bin/python tests/bench/airfoil_eval.py [--airfoil naca4412] [--repeats 7]

Measures (median of repeats, wall time):
1. NumPy evaluation of ``Airfoil.coefficients`` on 10^4 stations;
2. the SX ``casadi_function()`` mapped over 10^4 stations: value, and the
   Jacobian/Hessian of a scalar sum over stations (``sum(cl + 10 cd)``) with
   respect to the 3 x 10^4 inputs (alpha, Re, M), as IPOPT would evaluate them;
3. the attached-flow surface (alpha, ln Re) -> (cl, ln cd, cm) built three ways,
   to choose the representation:
   (a) shipped: ``casadi.Function.bspline`` with the fitted knots/coefficients,
       wrapped never-inline so that it is one call node inside SX graphs;
   (b) the same piecewise cubics in truncated-power form written out as SX
       expressions (one ``fmax`` per knot, dense contraction over Re levels);
   (c) ``casadi.interpolant(..., 'bspline', ...)`` on a 0.25 deg x 0.1 ln Re grid
       sampled from (a) (also an SX call node).
   Reports graph sizes (SX instructions) and times of value/gradient/Hessian.
"""
from __future__ import annotations

import argparse
import statistics
import time

import casadi as ca
import numpy as np

from mdo.airfoil import Airfoil
from mdo.airfoil.model import _cols, _mm, _rowsum, splines_of


def timeit(fn, repeats):
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return statistics.median(ts)


def stations(n, seed=0):
    rng = np.random.default_rng(seed)
    alpha = np.radians(rng.uniform(-10.0, 20.0, n))
    re_ = 10 ** rng.uniform(4.5, 6.8, n)
    mach = rng.uniform(0.0, 0.7, n)
    return alpha, re_, mach


def derivative_functions(f_scalar, n, name):
    """Mapped value, and gradient / Hessian of sum(cl + 10 cd) over n stations."""
    fm = f_scalar.map(n)
    a = ca.MX.sym("a", 1, n)
    r = ca.MX.sym("r", 1, n)
    m = ca.MX.sym("m", 1, n)
    out = fm(a, r, m)
    obj = ca.sum2(out[0] + 10 * out[1])
    x = ca.vertcat(a.T, r.T, m.T)
    # Hessian w.r.t. (alpha, ln Re-like scaled inputs): pass scaled variables like an NLP would
    grad = ca.Function(f"{name}_grad", [a, r, m], [ca.gradient(obj, x)])
    hess = ca.Function(f"{name}_hess", [a, r, m], [ca.hessian(obj, x)[0]])
    val = ca.Function(f"{name}_val", [a, r, m], list(out))
    return val, grad, hess


def attached_sx(af):
    """(a) the attached-flow fit of the shipped model as an SX function of (alpha, ln Re)."""
    tab = af.tables
    a = ca.SX.sym("a")
    r = ca.SX.sym("r")
    tr = [ca.fmax(r - ri, 0.0) ** 3 for ri in tab.log_re]
    W = ca.mtimes(ca.horzcat(*tr), ca.DM(tab.w_e)) + ca.DM(tab.w_a).T + r * ca.DM(tab.w_b).T
    ta = _cols(ca, [ca.fmax(a - ti, 0.0) ** 3 for ti in tab.knots])
    outs = [_rowsum(ca, _mm(ca, ta, d) * W) for d in (tab.d_cl, tab.d_logcd, tab.d_cm)]
    return ca.Function("att_sx", [a, r], [ca.vertcat(*outs)])


def attached_interpolant(af, f_sx):
    """(b) casadi bspline interpolant on a grid (0.25 deg x 0.1 ln Re) of the same fit."""
    tab = af.tables
    ag = np.arange(tab.alpha_clip[0], tab.alpha_clip[1], np.radians(0.25))
    rg = np.arange(tab.log_re[0] - 0.3, tab.log_re[-1] + 0.3, 0.1)
    A, R = np.meshgrid(ag, rg, indexing="ij")
    fm = f_sx.map(A.size)
    v = np.array(fm(A.ravel()[None, :], R.ravel()[None, :]))  # 3 x N
    data = np.stack([v[k].reshape(A.shape) for k in range(3)], axis=-1)  # (na, nr, 3)
    # casadi wants the grid values with the first dimension fastest and outputs innermost
    coeffs = np.transpose(data, (2, 0, 1)).ravel(order="F")
    interp = ca.interpolant("att_bspline", "bspline", [ag, rg], coeffs.tolist())
    a = ca.SX.sym("a")
    r = ca.SX.sym("r")
    return ca.Function("att_interp", [a, r], [interp(ca.vertcat(a, r))]), (len(ag), len(rg))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--airfoil", default="naca4412")
    ap.add_argument("--n", type=int, default=10_000)
    ap.add_argument("--repeats", type=int, default=7)
    args = ap.parse_args()
    af = Airfoil.from_name(args.airfoil)
    n = args.n
    alpha, re_, mach = stations(n)
    print(f"{af}; {n} stations, median of {args.repeats} repeats")

    t = timeit(lambda: af.coefficients(alpha, re_, mach), args.repeats)
    print(f"numpy coefficients:                  {t * 1e3:8.2f} ms  ({t / n * 1e6:.2f} us/station)")

    f = af.casadi_function()
    print(f"SX kernel: {f.n_instructions()} instructions, {f.n_nodes()} nodes (per station, cl+cd+cm)")
    val, grad, hess = derivative_functions(f, n, "full")
    A, R, M = alpha[None, :], re_[None, :], mach[None, :]
    for label, fn in (("value", val), ("gradient of sum", grad), ("Hessian of sum", hess)):
        fn(A, R, M)
        t = timeit(lambda: fn(A, R, M), args.repeats)
        print(f"casadi mapped {label:18s}  {t * 1e3:8.2f} ms")

    # per-station kernel derivative sizes (what the rotor's SX kernel inlines)
    a, r, m = ca.SX.sym("a"), ca.SX.sym("r"), ca.SX.sym("m")
    cl, cd, cm = af.coefficients(a, r, m)
    x = ca.vertcat(a, r, m)
    j = ca.Function("j", [a, r, m], [ca.jacobian(ca.vertcat(cl, cd, cm), x)])
    h = ca.Function("h", [a, r, m], [ca.hessian(cl + 10 * cd, x)[0]])
    print(f"SX per-station Jacobian (3x3): {j.n_instructions()} instructions; "
          f"Hessian (3x3): {h.n_instructions()} instructions")
    for label, fn in (("per-station Jacobian 3x3", j.map(n)), ("per-station Hessian 3x3", h.map(n))):
        fn(A, R, M)
        t = timeit(lambda: fn(A, R, M), args.repeats)
        print(f"casadi mapped {label:26s}  {t * 1e3:8.2f} ms")

    print("\nAttached-flow fit only, (alpha, ln Re) -> (cl, ln cd, cm):")
    f_sx = attached_sx(af)
    surf = splines_of(af.tables).ca_surface
    aa, rr = ca.SX.sym("aa"), ca.SX.sym("rr")
    f_shipped = ca.Function("att_shipped", [aa, rr], [surf(ca.vertcat(aa, rr))])
    f_int, grid = attached_interpolant(af, f_shipped)
    ra = np.clip(np.log(re_), af.tables.log_re[0], af.tables.log_re[-1])  # inside (c)'s grid
    for label, fk in (("(a) Function.bspline call node", f_shipped), ("(b) truncated-power SX", f_sx),
                      (f"(c) bspline interpolant {grid[0]}x{grid[1]}", f_int)):
        aa, rr = ca.SX.sym("aa"), ca.SX.sym("rr")
        e = fk(aa, rr)
        g = ca.Function("g", [aa, rr], [ca.jacobian(e, ca.vertcat(aa, rr))])
        hh = ca.Function("hh", [aa, rr], [ca.hessian(e[0] + e[1], ca.vertcat(aa, rr))[0]])
        fm, gm, hm = fk.map(n), g.map(n), hh.map(n)
        times = []
        for fn in (fm, gm, hm):
            fn(alpha[None, :], ra[None, :])
            times.append(timeit(lambda: fn(alpha[None, :], ra[None, :]), args.repeats))
        print(f"  {label:34s} instr {fk.n_instructions():5d} / jac {g.n_instructions():5d} / "
              f"hess {hh.n_instructions():5d};  10^4 stations: value {times[0] * 1e3:7.2f} ms, "
              f"jac {times[1] * 1e3:7.2f} ms, hess {times[2] * 1e3:7.2f} ms")
    ref = np.array(f_shipped.map(n)(alpha[None, :], ra[None, :]))
    for label, fk in (("(b)", f_sx), ("(c)", f_int)):
        diff = np.abs(np.array(fk.map(n)(alpha[None, :], ra[None, :])) - ref).max(axis=1)
        print(f"  max |{label} - (a)| over the stations (cl, ln cd, cm): {diff}")


if __name__ == "__main__":
    main()
