"""Benchmark for issue 18: the rotor block before/after, one process per code version.

    python tests/bench/rotor_compare.py [--repeats N] [SECTION ...]

For each section name: (a) the 20-station APC 10x7 50-point J sweep as one mapped
analysis call (``analysis_function``), (b) 100 nodes x 20 stations of the NLP-mode
BEMT with free chord/twist (as ``rotor_nlp.py``): constraint Jacobian and Hessian of
the Lagrangian.  Run it once with the old code (``PYTHONPATH=<old checkout>``) and
once with the new one, back to back (the machine is shared: compare medians taken
at the same time).  Sections the code does not know are reported and skipped.
"""
from __future__ import annotations

import argparse
import math
import statistics
import sys
import time
from pathlib import Path

import casadi as ca
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from rotor_nlp import measure  # noqa: E402

from mdo.rotor import RotorGeometry, adkins_liebeck, analysis_function, bemt_function, section  # noqa: E402
from mdo.rotor.analysis import _broadcast_inputs, operating_inputs  # noqa: E402
from mdo.rotor.geometry import DATA_DIR  # noqa: E402


def sweep_time(sec, repeats, K=50, n=20):
    rotor = RotorGeometry.from_csv(DATA_DIR / "apce_10x7_geometry.csv", diameter_m=0.254, blades=2, airfoil=sec)
    J = np.linspace(0.0, 0.9, K)
    n_rev = 5000 / 60
    inputs, _ = operating_inputs(rotor, omega_radps=np.full(K, 2 * math.pi * n_rev),
                                 v_axial_mps=J * n_rev * rotor.diameter_m, n_stations=n)
    arr, _ = _broadcast_inputs(inputs, n)
    f = analysis_function(sec, n, K)
    args = {k: arr[k] for k in f.name_in()}
    f(**args)
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        f(**args)
        ts.append(time.perf_counter() - t0)
    return statistics.median(ts)


def nlp_times(sec, repeats, K=100, n=20):
    d = adkins_liebeck(airfoil=sec, blades=3, radius_m=0.97, speed_mps=60.35, thrust_N=900.0, tip_mach=0.6,
                       altitude_m=762.0, cl_design=0.7, n_stations=n)
    rho, mu, a_s = d["inputs"]["rho_kgpm3"], d["inputs"]["mu_Pas"], d["inputs"]["a_mps"]
    fmap = bemt_function(sec, n, 1).map(K)
    phi, om, v = ca.MX.sym("phi", n, K), ca.MX.sym("om", 1, K), ca.MX.sym("v", 1, K)
    chord, twist = ca.MX.sym("chord", n), ca.MX.sym("twist", n)
    o = fmap(radius_m=0.97, hub_fraction=0.12, blades=3, chord_m=chord, twist_rad=twist, pitch_rad=0.0,
             omega_radps=om, v_axial_mps=v, v_inplane_mps=0.0, rho_kgpm3=rho, mu_Pas=mu, a_mps=a_s,
             spin=1.0, phi_rad=phi)
    g = ca.vertcat(ca.vec(o["residual"]), ca.vec(o["thrust_N"]), ca.vec(o["power_W"]))
    x = ca.vertcat(ca.vec(phi), ca.vec(om), ca.vec(v), chord, twist)
    x0 = np.concatenate([np.tile(d["phi_rad"][:, None], (1, K)).ravel(order="F"),
                         d["omega_radps"] * np.linspace(0.8, 1.05, K), np.linspace(40.0, 78.0, K),
                         d["chord_m"], d["twist_rad"]])
    return measure(f"NLP 100x20 free chord/twist", x, x0, g, repeats)


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("sections", nargs="*", default=["e63:0.5:clark_y", "e63:0.5:clark_y+du_selig",
                                                     "naca4412", "naca4412+du_selig"])
    a = ap.parse_args(argv)
    import mdo
    print(f"code: {Path(mdo.__file__).resolve().parent}")
    for name in a.sections:
        try:
            sec = section(name)
        except Exception as exc:   # an older code version without this section kind
            print(f"{name}: skipped ({type(exc).__name__}: {exc})")
            continue
        ts = sweep_time(sec, a.repeats)
        print(f"{name}: 50-point J sweep {ts * 1e3:.1f} ms")
        nlp_times(sec, a.repeats)


if __name__ == "__main__":
    main()
