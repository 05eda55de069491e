"""Benchmark: cost of the symbolic vortex lattice inside an NLP (function, Jacobian, Hessian).

The GA-2P main wing (5 sections, S_ref fixed, Fig. 12 parameterization) with 7
design variables (span, taper, 5 section twists) as MX symbols, solved for K
operating points (alpha_k, V_k as MX symbols) in one dense LU solve.  Measured:

* build: VLM construction (SX geometry Function, mapped influence kernels) + outputs;
* f:     CL and CDi of all K nodes;
* J:     Jacobian of [CL; CDi] (2K rows) w.r.t. all 7 + 2K variables;
* H:     exact Hessian of sum_k (CL_k + CDi_k) w.r.t. all variables (what IPOPT's
         Lagrangian Hessian costs for this block).

Medians of ``--repeat`` evaluations; the machine load average is printed because
the machine is shared.  Usage: ``python tests/bench/wing_vlm.py [--quick] [--json FILE]``.
"""
from __future__ import annotations

import argparse
import json
import os
import time

import casadi as ca
import numpy as np

from mdo.wing import VLM, constant_area


def median_time(fun, arg, repeat):
    ts = []
    for _ in range(repeat):
        t = time.perf_counter()
        fun(arg)
        ts.append(time.perf_counter() - t)
    return float(np.median(ts))


def case(nspan, nchord, K, repeat, symmetric=True, flat=False):
    t0 = time.perf_counter()
    b = ca.MX.sym("span")
    lam = ca.MX.sym("taper")
    tw = ca.MX.sym("twist", 5)
    w = constant_area("main", 14.76, b, lam, [tw[i] for i in range(5)], nspan=nspan, nchord=nchord,
                      airfoil="naca63412", anchor_sections=False)
    v = VLM([w], S_ref=14.76, symmetric=symmetric, flat_lattice=flat)
    al = ca.MX.sym("alpha", 1, K)
    V = ca.MX.sym("V", 1, K)
    r = v.solve(al, V, rho=1.0, mach=0.2)
    x = ca.vertcat(b, lam, tw, al.T, V.T)
    out = ca.vertcat(r["CL"].T, r["CDi"].T)
    obj = ca.sum1(out)
    f = ca.Function("f", [x], [out])
    J = ca.Function("J", [x], [ca.jacobian(out, x)])
    H = ca.Function("H", [x], [ca.hessian(obj, x)[0]])
    build = time.perf_counter() - t0
    x0 = np.concatenate([[11.4, 0.7], np.radians([3, 2.75, 2.5, 2.25, 2.0]),
                         np.radians(np.linspace(0, 4, K)), np.linspace(50, 80, K)])
    t1 = time.perf_counter()
    H(x0)                                   # first call (allocations)
    first_h = time.perf_counter() - t1
    res = {
        "panels_total": 2 * nspan * nchord if symmetric else v.n_panels, "unknowns": v.n_panels,
        "nspan": nspan, "nchord": nchord, "K": K, "symmetric": symmetric, "flat_lattice": flat,
        "variables": int(x.shape[0]), "build_s": build, "hessian_first_call_s": first_h,
        "f_ms": 1e3 * median_time(f, x0, repeat), "J_ms": 1e3 * median_time(J, x0, repeat),
        "H_ms": 1e3 * median_time(H, x0, max(2, repeat - 1)),
    }
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="only 100 and 200 panels")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--json", default=None, help="also write the results to this file")
    args = ap.parse_args()
    grid = [(25, 2), (50, 2)] if args.quick else [(25, 2), (40, 2), (50, 2), (63, 2)]
    print(f"load average before: {os.getloadavg()}  (2 cores, shared machine)")
    rows = []
    for nspan, nchord in grid:
        for K in (1, 100):
            r = case(nspan, nchord, K, args.repeat)
            rows.append(r)
            print(f"panels {r['panels_total']:4d} (unknowns {r['unknowns']:3d}) K {K:3d} vars {r['variables']:3d}: "
                  f"build {r['build_s']:.2f} s | f {r['f_ms']:7.1f} ms | J {r['J_ms']:7.1f} ms | "
                  f"H {r['H_ms']:7.1f} ms (first call {r['hessian_first_call_s']:.2f} s)", flush=True)
    for extra in ({"symmetric": False}, {"flat": True}):
        r = case(50, 2, 100, args.repeat, **extra)
        rows.append(r)
        print(f"panels {r['panels_total']:4d} (unknowns {r['unknowns']:3d}) K 100 {extra}: f {r['f_ms']:.1f} ms | "
              f"J {r['J_ms']:.1f} ms | H {r['H_ms']:.1f} ms", flush=True)
    print(f"load average after: {os.getloadavg()}")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"load_average_end": os.getloadavg(), "rows": rows}, fh, indent=1)


if __name__ == "__main__":
    main()
