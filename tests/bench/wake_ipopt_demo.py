"""Benchmark/demo: the averaged wake inside IPOPT (not collected by pytest).

    /work/venv/bin/python tests/bench/wake_ipopt_demo.py [--nodes 20]

GA-2P wing (problems/validation/wake_rotation.py, no tail), two inboard-up
propellers whose spanwise position y_p and radius R are design variables
(bounds 0.8–4.5 m and 0.8–1.1 m), K operating points with different blade
circulation (the cruise Γ scaled by 0.6 … 1.4) and one angle of attack each.
Minimize the summed induced drag (Trefftz + the external near-field part, "swirl"
coupling) subject to CL = 0.5 at every node.  Exact Hessian vs limited memory.
This exercises what the mission NLP needs: the per-design table evaluation
(symbolic in y_p and R), one VLM factorization for all nodes, smoothness for IPOPT.
"""
from __future__ import annotations

import argparse
import importlib.util
import math
import sys
import time
from pathlib import Path

import casadi as ca
import numpy as np

import mdo.wake as wake
from mdo.wing.vlm import VLM

ROOT = Path(__file__).resolve().parents[2]
spec = importlib.util.spec_from_file_location("wake_rotation", ROOT / "problems" / "validation" / "wake_rotation.py")
study = importlib.util.module_from_spec(spec)
sys.modules["wake_rotation"] = study
spec.loader.exec_module(study)


def build(n_nodes, hessian):
    at = study.atmos()
    veh = study.ga2p(nspan=32, nchord=3)
    vlm = VLM(veh.surfaces[:1], mach_ref=study.V_MPS / at["a"], lift_velocity=wake.COUPLINGS["swirl"][0],
              S_ref=veh.S_ref)
    geom, omega = study.design_rotor(veh, at)
    q = 0.5 * at["rho"] * study.V_MPS**2
    st = study.trimmed_state(geom, omega, math.radians(3.0), q * veh.S_ref * study.CD_CRUISE / 2, at)
    edges = wake.WakeRotor.from_geometry(geom, (0, 0, 0)).s_edges
    opti = ca.Opti()
    yp = opti.variable()
    R = opti.variable()
    alpha = opti.variable(1, n_nodes)
    rotors = [wake.WakeRotor(center=ca.vertcat(-0.93, s * yp, -0.226), axis=(1, 0, 0), radius_m=R,
                             s_edges=edges, blades=3, spin=-s) for s in (1, -1)]
    scale = np.linspace(0.6, 1.4, n_nodes)
    G = ca.DM(np.outer(st["gamma"], scale))
    kw = wake.vlm_wake_inputs(vlm, rotors, [G, G], [st["omega"]] * 2, [st["v_wake"]] * 2, bound_points="cp")
    out = vlm.solve(alpha, study.V_MPS, rho=at["rho"], **kw)
    opti.minimize(1e3 * ca.sum2(out["CDi"]))
    opti.subject_to(out["CL"] == 0.5)
    opti.subject_to(opti.bounded(0.8, yp, 4.5))
    opti.subject_to(opti.bounded(0.8, R, 1.1))
    opti.set_initial(yp, 0.23 * 5.7)
    opti.set_initial(R, 0.97)
    opti.set_initial(alpha, math.radians(1.0))
    opts = {"ipopt.print_level": 0, "print_time": False, "ipopt.sb": "yes"}
    if hessian == "limited-memory":
        opts["ipopt.hessian_approximation"] = "limited-memory"
    opti.solver("ipopt", opts)
    return opti, yp, R, alpha, out


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--nodes", type=int, default=20)
    args = ap.parse_args(argv)
    for hess in ("exact", "limited-memory"):
        t0 = time.perf_counter()
        opti, yp, R, alpha, out = build(args.nodes, hess)
        t_build = time.perf_counter() - t0
        t0 = time.perf_counter()
        sol = opti.solve()
        t_solve = time.perf_counter() - t0
        stats = sol.stats()
        print(f"{hess:15s}: {stats['return_status']}, {stats['iter_count']} iterations, solve {t_solve:.1f} s "
              f"(build {t_build:.1f} s); y_p = {float(sol.value(yp)):.3f} m "
              f"({float(sol.value(yp)) / 5.7:.3f} semispan), R = {float(sol.value(R)):.3f} m, "
              f"sum CDi = {float(sol.value(ca.sum2(out['CDi']))):.6f}")


if __name__ == "__main__":
    main()
