"""Benchmark: the powertrain at K mission nodes (graph size, evaluation, derivatives, a solve).

Run: python tests/bench/powertrain_node.py [K ...]   (default K = 100)
Prints medians of several repeats (wall time, 2-core machine shared with others).
"""
import statistics
import sys
import time

import casadi as ca
import numpy as np

from mdo.core import Collocation
from mdo.nlp import Problem
from mdo.vehicle import catalog


def median_time(fn, repeats=7):
    ts = []
    for _ in range(repeats):
        t = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t)
    return statistics.median(ts)


def bench(K, name="TTW"):
    t = time.perf_counter()
    pt = {"GA-2P": catalog.ga2p, "GA-8P": catalog.ga8p, "TTW": catalog.ttw}[name]().powertrain()
    f = pt.node_function()
    t_build = time.perf_counter() - t
    m = pt.motor
    x = ca.MX.sym("x", 4 * K)
    Q, W, S, I = (x[k * K:(k + 1) * K] for k in range(4))
    out = pt.evaluate(Q, W, S, I)
    g = ca.vertcat(*(ca.vec(out[k]) for k in ("power_balance_W", "voltage_margin_V", "cell_current_A",
                                                   "cell_voltage_V", "soc_rate_per_s")))
    lam = ca.MX.sym("lam", g.numel())
    G = ca.Function("G", [x], [g])
    J = ca.Function("J", [x], [ca.jacobian(g, x)])
    H = ca.Function("H", [x, lam], [ca.hessian(ca.dot(lam, g), x)[0]])
    q = np.linspace(0.2, 0.5, K) * m.rated_torque_Nm   # within the 8 A cell-current limit
    w = np.linspace(0.8, 1.0, K) * m.rated_speed_radps
    s = np.linspace(1.0, 0.3, K)
    ib = pt.analyze(q, w, s)["battery_current_A"]
    x0 = np.concatenate([q, w, s, ib])
    l0 = np.ones(g.numel())
    t_g = median_time(lambda: G(x0))
    t_j = median_time(lambda: J(x0))
    t_h = median_time(lambda: H(x0, l0))
    jnnz = J(x0).nnz()
    hnnz = H(x0, l0).nnz()
    t_an = median_time(lambda: pt.analyze(q, w, s), repeats=3)

    # a mission-like NLP: torque/speed profile over K CGL nodes, state of charge collocated
    def solve():
        col = Collocation(K)
        p = Problem("bench")
        soc = p.variable("soc", K, lower=0.0, upper=1.0, init=0.8)
        o, _ = pt.add_to_problem(p, q, w, soc, init_battery_current_A=float(np.mean(ib)))
        p.constrain("soc0", soc[0], rhs=1.0)
        p.constrain("dyn", ca.mtimes(ca.DM(col.D[1:]), soc) - 600.0 * o["soc_rate_per_s"][1:].T,
                    scale=600.0 * pt.soc_rate_scale_per_s)
        p.minimize(pt.energy_used_J(soc[0], soc[-1]), scale=1e7)
        return p.solve(verbose=False)
    t = time.perf_counter()
    sol = solve()
    t_nlp = time.perf_counter() - t
    print(f"{name}, K = {K} nodes")
    print(f"  node Function: {f.n_instructions()} SX instructions, built in {1e3 * t_build:.1f} ms")
    print(f"  constraints (5 groups x K) eval  : {1e3 * t_g:.3f} ms")
    print(f"  Jacobian ({jnnz} nnz)            : {1e3 * t_j:.3f} ms")
    print(f"  Hessian of Lagrangian ({hnnz} nnz): {1e3 * t_h:.3f} ms")
    print(f"  numeric analysis (bracketed I_b) : {1e3 * t_an:.1f} ms")
    print(f"  NLP (K soc + K current variables): {sol.status}, {sol.iterations} iterations, "
          f"{t_nlp:.2f} s incl. build")


if __name__ == "__main__":
    for K in [int(a) for a in sys.argv[1:]] or [100]:
        bench(K)
