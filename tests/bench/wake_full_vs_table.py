"""Benchmark: the NLP's averaged-wake table against the full helical fixed wake on the
GA-2P cruise geometry (not collected by pytest).

    /work/venv/bin/python tests/bench/wake_full_vs_table.py [--repeats 3] [--rotations 5]

GA-2P (problems/validation/wake_rotation.py): wing 11.4 m span, S 14.76 m², taper
0.7, twist 3°→2°, NACA 63-412, horizontal tail; two 3-bladed propellers D = 1.94 m
at 23 % semispan, 0.93 m ahead of the wing, all inboard-up; 175 mph at 2500 ft,
α = 3°, J = 1, each propeller trimmed to 771 N.  The VLM (mdo.wing) takes the wake
velocity at its control points and bound-vortex midpoints.

Compared, as spanwise sectional cl of the main wing:
* full helical wake (5 rotations, 36 steps/rotation), one snapshot (the paper) and
  averaged over 8 blade positions (what the wing feels on average),
* the averaged-wake table of mdo.wake.mean (the NLP form).
Reported: max |Δcl| over the span relative to the peak cl (goal ≤ 2 %) and to the
peak wake-induced Δcl; and the cost of one evaluation of the wake velocity at the
VLM points for one operating point (numeric, JIT-compiled full wake vs table) —
the NLP costs (value, gradient, Hessian for 100 nodes) are in wake_nlp_cost.py.
"""
from __future__ import annotations

import argparse
import importlib.util
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np

import mdo.wake as wake
from mdo.wing.vlm import VLM

ROOT = Path(__file__).resolve().parents[2]
spec = importlib.util.spec_from_file_location("wake_rotation", ROOT / "problems" / "validation" / "wake_rotation.py")
study = importlib.util.module_from_spec(spec)
sys.modules["wake_rotation"] = study   # dataclasses look the module up while the file executes
spec.loader.exec_module(study)


def timeit(fn, repeats):
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return statistics.median(ts)


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--rotations", type=float, default=5)
    ap.add_argument("--nspan", type=int, default=40)
    args = ap.parse_args(argv)
    at = study.atmos()
    veh = study.ga2p(nspan=args.nspan)
    vlm = VLM(veh.surfaces, mach_ref=study.V_MPS / at["a"], lift_velocity="freestream", S_ref=veh.S_ref)
    geom, omega = study.design_rotor(veh, at)
    q = 0.5 * at["rho"] * study.V_MPS**2
    st = study.trimmed_state(geom, omega, math.radians(study.ALPHA_DEG), q * veh.S_ref * study.CD_CRUISE / 2, at)
    rotors = study.wake_rotors(veh, geom, ["inboard_up"])
    g = vlm.geometry
    pts = np.hstack([np.array(g["cp"]), np.array(g["rb"])])
    print(f"GA-2P: {vlm.n_panels} panels (right half), {pts.shape[1]} wake points, thrust {st['thrust_N']:.0f} N, "
          f"CT {st['CT']:.4f}, pitch {st['pitch_deg']:+.2f} deg, V_w {st['v_wake']:.1f} m/s")
    k = len(rotors)
    args_w = (pts, rotors, [st["gamma"]] * k, [st["omega"]] * k, [st["v_wake"]] * k)

    def mean_vel():
        return wake.external_velocity(*args_w, model="mean")

    def full_vel(phases):
        return wake.external_velocity(*args_w, model="full", phases=phases, n_rotations=args.rotations)

    n = np.array(g["cp"]).shape[1]
    out0, _ = study.solve(vlm, [], st, at)
    y, cl0, surf = study.strip_curves(vlm, out0)
    wing = surf == 0
    res = {}
    for label, fn in (("table", mean_vel), ("full, snapshot", lambda: full_vel(1)),
                      ("full, 8 phases", lambda: full_vel(8))):
        v = fn()
        o = vlm.solve(math.radians(study.ALPHA_DEG), study.V_MPS, rho=at["rho"], mach=study.V_MPS / at["a"],
                      v_ext=tuple(c[:n] for c in v), v_ext_bound=tuple(c[n:] for c in v))
        res[label] = (np.array(o["cl"])[:, 0], float(np.ravel(np.array(o["CL"]))[0]),
                      float(np.ravel(np.array(o["CDi"]))[0]))
    peak = np.abs(res["full, 8 phases"][0][wing]).max()
    dpeak = np.abs(res["full, 8 phases"][0][wing] - cl0[wing]).max()
    print(f"peak cl {peak:.4f}; peak wake-induced |dcl| {dpeak:.4f}")
    for ref in ("full, 8 phases", "full, snapshot"):
        d = np.abs(res["table"][0][wing] - res[ref][0][wing])
        print(f"table vs {ref:15s}: max |dcl| = {d.max():.5f} = {100 * d.max() / peak:.2f} % of peak cl "
              f"({100 * d.max() / dpeak:.1f} % of the peak wake effect), RMS {np.sqrt(np.mean(d**2)):.5f}; "
              f"CL {res['table'][1]:.5f} vs {res[ref][1]:.5f}, CDi {res['table'][2]:.6f} vs {res[ref][2]:.6f}")
    d = np.abs(res["full, snapshot"][0][wing] - res["full, 8 phases"][0][wing])
    print(f"snapshot vs 8 phases       : max |dcl| = {d.max():.5f} = {100 * d.max() / peak:.2f} % of peak cl")
    # costs of one evaluation at one operating point (numeric)
    t_mean = timeit(mean_vel, args.repeats)
    infl = wake.wake_influences(pts, rotors)
    t_apply = timeit(lambda: wake.external_velocity(*args_w, model="mean", influences=infl), args.repeats)
    t_full1 = timeit(lambda: full_vel(1), args.repeats)
    t_full8 = timeit(lambda: full_vel(8), max(1, args.repeats - 1))
    segs = rotors[0].blades * ((rotors[0].n_stations + 1) * int(round(args.rotations * 36)) + 2 * rotors[0].n_stations)
    print(f"cost per evaluation (numeric, median of {args.repeats}): table {1e3 * t_mean:.1f} ms "
          f"(of which per node, influences reused: {1e3 * t_apply:.2f} ms); full snapshot {1e3 * t_full1:.0f} ms "
          f"(JIT C, {segs} filaments per rotor x {pts.shape[1]} points x {k} rotors); full 8 phases {1e3 * t_full8:.0f} ms")


if __name__ == "__main__":
    main()
