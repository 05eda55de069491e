"""Benchmark: the BEMT as the mission NLP sees it (K nodes x n stations).

    /work/venv/bin/python tests/bench/rotor_nlp.py [--airfoil NAME] [--nodes K] [--stations n]

One rotor group over K mission nodes: unknowns phi (n x K), per-node rotor
speed and axial speed, and the blade (chord, twist at n stations) either as
free design variables or from the Adkins-Liebeck design (residual form with
w and alpha_i as unknowns, or the unrolled explicit form).  For each variant the
script prints the instruction count of the per-node SX Function and the
medians of: one evaluation of [residuals; T; P], the constraint Jacobian, and
the Hessian of the Lagrangian (CasADi's generated functions, what IPOPT calls).
"""
from __future__ import annotations

import argparse
import statistics
import time

import casadi as ca
import numpy as np

from mdo.rotor import (DESIGN_INPUTS, adkins_liebeck, adkins_liebeck_function, adkins_liebeck_unrolled,
                       bemt_function, section)


def med(fn, repeats):
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return statistics.median(ts)


def measure(name, x, x0, g, repeats):
    lam = ca.MX.sym("lam", g.shape[0])
    t0 = time.perf_counter()
    f = ca.Function("bench_g", [x], [g])
    J = ca.Function("bench_jac", [x], [ca.jacobian(g, x)])
    L = ca.dot(lam, g)
    H = ca.Function("bench_hess", [x, lam], [ca.hessian(L, x)[0]])
    t_build = time.perf_counter() - t0
    lam0 = np.random.default_rng(0).standard_normal(g.shape[0]) * 1e-2
    f(x0)
    J(x0)
    H(x0, lam0)
    te = med(lambda: f(x0), repeats)
    tj = med(lambda: J(x0), repeats)
    th = med(lambda: H(x0, lam0), repeats)
    nnz_j = J.sparsity_out(0).nnz()
    nnz_h = H.sparsity_out(0).nnz()
    print(f"  {name:34s} x {x.shape[0]:5d}  g {g.shape[0]:5d} | eval {te * 1e3:7.2f} ms  jac {tj * 1e3:7.2f} ms "
          f"(nnz {nnz_j})  hess {th * 1e3:8.2f} ms (nnz {nnz_h})  build {t_build:.2f} s")
    return te, tj, th


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--airfoil", default="naca4412")
    ap.add_argument("--nodes", type=int, default=100)
    ap.add_argument("--stations", type=int, default=20)
    ap.add_argument("--repeats", type=int, default=5)
    a = ap.parse_args(argv)
    K, n = a.nodes, a.stations
    sec = section(a.airfoil)
    # a GA-2P-like design and mission-like operating points around it
    d = adkins_liebeck(airfoil=sec, blades=3, radius_m=0.97, speed_mps=60.35, thrust_N=900.0, tip_mach=0.6,
                       altitude_m=762.0, cl_design=0.7, n_stations=n)
    rho, mu, a_s = d["inputs"]["rho_kgpm3"], d["inputs"]["mu_Pas"], d["inputs"]["a_mps"]
    om0 = d["omega_radps"] * np.linspace(0.8, 1.05, K)
    v0 = np.linspace(40.0, 78.0, K)

    print(f"BEMT in the NLP: {K} nodes x {n} stations, section {a.airfoil}")
    for m in (1, 4):
        f = bemt_function(sec, n, m)
        print(f"  per-node SX Function, {m} azimuth(s): {f.n_instructions()} instructions "
              f"({f.n_instructions() / (n * m):.0f} per element)")

    f = bemt_function(sec, n, 1)
    fmap = f.map(K)
    phi = ca.MX.sym("phi", n, K)
    om = ca.MX.sym("om", 1, K)
    v = ca.MX.sym("v", 1, K)
    chord = ca.MX.sym("chord", n)
    twist = ca.MX.sym("twist", n)
    phi0 = np.tile(d["phi_rad"][:, None], (1, K))

    def nodes(ch, tw):
        o = fmap(radius_m=0.97, hub_fraction=0.12, blades=3, chord_m=ch, twist_rad=tw, pitch_rad=0.0,
                 omega_radps=om, v_axial_mps=v, v_inplane_mps=0.0, rho_kgpm3=rho, mu_Pas=mu, a_mps=a_s,
                 spin=1.0, phi_rad=phi)
        return ca.vertcat(ca.vec(o["residual"]), ca.vec(o["thrust_N"]), ca.vec(o["power_W"]))

    base = [ca.vec(phi), ca.vec(om), ca.vec(v)]
    base0 = [phi0.ravel(order="F"), om0, v0]
    x = ca.vertcat(*base, chord, twist)
    x0 = np.concatenate(base0 + [d["chord_m"], d["twist_rad"]])
    measure("free chord/twist (design vars)", x, x0, nodes(chord, twist), a.repeats)

    # Adkins-Liebeck, residual form: design inputs + (w, alpha) unknowns
    p = {k: ca.MX.sym(k) for k in ("target", "speed_mps", "radius_m", "cl_design")}
    fixed = {"omega_radps": d["omega_radps"], "rho_kgpm3": rho, "mu_Pas": mu, "a_mps": a_s,
             "hub_fraction": 0.12, "blades": 3.0}
    w = ca.MX.sym("w")
    al = ca.MX.sym("al", n)
    fal = adkins_liebeck_function(sec, n)
    print(f"  A-L residual form SX Function: {fal.n_instructions()} instructions")
    o = fal(**{**p, **fixed}, w_mps=w, alpha_rad=al)
    g = ca.vertcat(o["residual"], nodes(o["chord_m"], o["twist_rad"]))
    xd = ca.vertcat(*base, p["target"], p["speed_mps"], p["radius_m"], p["cl_design"], w, al)
    xd0 = np.concatenate(base0 + [[900.0, 60.35, 0.97, 0.7, d["w_mps"]], d["alpha_rad"]])
    measure("A-L residual form + nodes", xd, xd0, g, a.repeats)

    for it in (4, 8):
        fu = adkins_liebeck_unrolled(sec, n, n_newton=it)
        print(f"  A-L unrolled ({it} Newton steps) SX Function: {fu.n_instructions()} instructions")
        o = fu(**{**p, **fixed})
        g = nodes(o["chord_m"], o["twist_rad"])
        xu = ca.vertcat(*base, p["target"], p["speed_mps"], p["radius_m"], p["cl_design"])
        xu0 = np.concatenate(base0 + [[900.0, 60.35, 0.97, 0.7]])
        measure(f"A-L unrolled x{it} + nodes", xu, xu0, g, a.repeats)
        # accuracy of the unrolled design at the reference point
        num = fu(**{"target": 900.0, "speed_mps": 60.35, "radius_m": 0.97, "cl_design": 0.7, **fixed})
        print(f"    unrolled x{it}: max |chord - chord_solved| = "
              f"{np.abs(np.array(num['chord_m']).ravel() - d['chord_m']).max():.1e} m, "
              f"|residual| = {np.abs(np.array(num['residual'])).max():.1e}")
    assert set(DESIGN_INPUTS) == set(list(p) + list(fixed))


if __name__ == "__main__":
    main()
