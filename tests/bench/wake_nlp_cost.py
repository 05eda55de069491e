"""Benchmark: cost of the propeller wake inside a mission NLP (not collected by pytest).

    /work/venv/bin/python tests/bench/wake_nlp_cost.py [--nodes 100] [--repeats 5]

GA-2P-like layout: two 3-bladed rotors (R = 0.97 m, 20 blade elements) at 23 %
semispan, 0.93 m ahead of a wing of 11.4 m span whose control points form a
2 × 40 × 4 grid (M = 320).  Design variables d = (R, y_rotor); per node the rotor
state (Γ (20), Ω, V_w) of each rotor are variables.  The wake velocity at all
control points and nodes, U (3M × K), is contracted with fixed weights λ to a
scalar so that value, gradient and Hessian can be timed as IPOPT would need them.

Forms:
* mean: the averaged wake of mdo.wake.mean, U = C1(d)·(Γ Ω/V_w) + C2(d)·Γ — the
  table is evaluated once per design, each node costs two mat-vecs;
* full: the helical fixed wake (5 rotations × 36 steps, 1 phase) at every node,
  Biot–Savart over all filaments, built for K_full nodes (default 1) and quoted
  per node.
Reports median wall times of several repeats, graph sizes and Hessian nonzeros.
"""
from __future__ import annotations

import argparse
import statistics
import time

import casadi as ca
import numpy as np

from mdo.wake import WakeRotor, influence_function
from mdo.wake.mean import apply_influence
from mdo.wake.helical import full_wake_function


def timeit(fn, repeats):
    """Median wall time and median CPU time (s) of ``repeats`` calls (the machine is
    shared: CPU time is the steadier figure)."""
    ts, cs = [], []
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        fn()
        ts.append(time.perf_counter() - t0)
        cs.append(time.process_time() - c0)
    return statistics.median(ts), statistics.median(cs)


def wing_points(n_span=40, n_chord=4, semispan=5.7, c_root=1.523, c_tip=1.066, sides=(1, -1)):
    ys = (1 - np.cos(np.linspace(0, np.pi / 2, n_span + 1))) * semispan
    ym = 0.5 * (ys[1:] + ys[:-1])
    pts = []
    for side in sides:
        for y in ym:
            c = c_root + (c_tip - c_root) * y / semispan
            for j in range(n_chord):
                pts.append([(j + 0.75) / n_chord * c, side * y, 0.0])
    return np.array(pts).T


def build(kind, n_nodes, pts, n_st=20, blades=3):
    R = ca.MX.sym("R")
    yp = ca.MX.sym("y_rotor")
    d = ca.vertcat(R, yp)
    s_edges = 0.12 + 0.88 * 0.5 * (1 - np.cos(np.pi * np.arange(n_st + 1) / n_st))
    states, u_total = [], 0
    m = pts.shape[1]
    for side in (1, -1):
        g = ca.MX.sym(f"gamma{side}", n_st, n_nodes)
        om = ca.MX.sym(f"omega{side}", 1, n_nodes)
        vw = ca.MX.sym(f"vw{side}", 1, n_nodes)
        states += [ca.vec(g), om.T, vw.T]
        center = ca.vertcat(-0.93, side * yp, -0.226)
        spin = -side  # inboard-up
        if kind == "mean":
            infl = influence_function(m, n_st, blades)(pts, center, ca.DM([1, 0, 0]), R, s_edges, spin)
            u = ca.vertcat(*apply_influence(infl, g * ca.repmat(om / vw, n_st, 1), g))
        else:
            f = full_wake_function(m, blades, n_st)
            cols = [ca.vec(f(pts, center, ca.DM([1, 0, 0]), R, s_edges, g[:, k], om[k], vw[k], spin, 0.0, 0.05))
                    for k in range(n_nodes)]
            u = ca.horzcat(*cols)
        u_total = u_total + u
    x = ca.vertcat(*states)
    lam = ca.DM(np.random.default_rng(0).normal(size=(3 * m, n_nodes)))  # same weights for both layouts
    obj = ca.sum1(ca.sum2(lam * u_total))
    z = ca.vertcat(d, x)
    f = ca.Function("f", [z], [obj])
    g = ca.Function("g", [z], [ca.gradient(obj, z)])
    hess, _ = ca.hessian(obj, z)
    h = ca.Function("h", [z], [hess])
    z0 = np.concatenate([[0.97, 1.311]] + [np.concatenate([np.tile(0.6 * np.sin(np.pi * np.linspace(0.05, 0.95, n_st)), n_nodes),
                                                          np.full(n_nodes, 253.4), np.full(n_nodes, 80.0)])
                                           for _ in (1, -1)])
    return f, g, h, z0, hess.nnz()


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--nodes", type=int, default=100)
    ap.add_argument("--full-nodes", type=int, default=1)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--skip-full", action="store_true")
    args = ap.parse_args(argv)
    runs = [("mean", args.nodes, wing_points(sides=(1,)), "right half, symmetric VLM"),
            ("mean", args.nodes, wing_points(), "both halves")]
    if not args.skip_full:
        runs.append(("full", args.full_nodes, wing_points(), "both halves"))
    print("rotors 2 x (3 blades, 20 elements); times: median wall (median CPU)")
    for kind, k, pts, label in runs:
        t0 = time.perf_counter()
        f, g, h, z0, nnz = build(kind, k, pts)
        t_build = time.perf_counter() - t0
        tf = timeit(lambda: f(z0), args.repeats)
        tg = timeit(lambda: g(z0), args.repeats)
        th = timeit(lambda: h(z0), max(1, args.repeats // 2))
        print(f"{kind:5s} M = {pts.shape[1]:3d} ({label}), K = {k:3d}: build {t_build:5.1f} s | "
              f"value {tf[0] * 1e3:8.1f} ({tf[1] * 1e3:8.1f}) ms | gradient {tg[0] * 1e3:8.1f} ({tg[1] * 1e3:8.1f}) ms | "
              f"Hessian {th[0] * 1e3:9.1f} ({th[1] * 1e3:9.1f}) ms, nnz {nnz}; per node: value "
              f"{tf[1] / k * 1e3:.3f} ms, Hessian {th[1] / k * 1e3:.2f} ms CPU")


if __name__ == "__main__":
    main()
