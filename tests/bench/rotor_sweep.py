"""Benchmark: a 20-station rotor, 50-point J sweep as ONE mapped CasADi call.

    /work/venv/bin/python tests/bench/rotor_sweep.py [--airfoil NAME] [--repeats N]

Times (medians of the repeats, wall clock):
* the mapped analysis Function (bracketed solve + every output, 50 points in
  one call: ``mdo.rotor.analysis_function``);
* ``mdo.rotor.sweep_J`` (the Python entry point: input checks, the same solve,
  the fallback quadrants when needed, the output evaluation);
and the build time and instruction counts.  Default rotor: APC 10x7 Thin
Electric with the validation's sections (E63 inboard, Clark-Y outboard).
"""
from __future__ import annotations

import argparse
import math
import statistics
import time

import numpy as np

from mdo.rotor import RotorGeometry, analysis_function, section, sweep_J
from mdo.rotor.analysis import _broadcast_inputs, operating_inputs, solve_kernel
from mdo.rotor.geometry import DATA_DIR


def median_time(fn, repeats):
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return statistics.median(ts), min(ts)


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--airfoil", default="e63:0.5:clark_y")
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--points", type=int, default=50)
    ap.add_argument("--stations", type=int, default=20)
    a = ap.parse_args(argv)
    K, n = a.points, a.stations
    t0 = time.perf_counter()
    sec = section(a.airfoil)
    t_sec = time.perf_counter() - t0
    rotor = RotorGeometry.from_csv(DATA_DIR / "apce_10x7_geometry.csv", diameter_m=0.254, blades=2, airfoil=sec)
    rpm = 5000.0
    J = np.linspace(0.0, 0.9, K)
    n_rev = rpm / 60
    inputs, _ = operating_inputs(rotor, omega_radps=np.full(K, 2 * math.pi * n_rev),
                                 v_axial_mps=J * n_rev * rotor.diameter_m, n_stations=n)
    arr, _ = _broadcast_inputs(inputs, n)

    t0 = time.perf_counter()
    f = analysis_function(sec, n, K)
    t_build = time.perf_counter() - t0
    args = {k: arr[k] for k in f.name_in()}
    t0 = time.perf_counter()
    out = f(**args)
    t_first = time.perf_counter() - t0
    found = np.array(out["found"])
    t_map, t_map_min = median_time(lambda: f(**args), a.repeats)
    sweep_J(rotor, J, rpm=rpm, n_stations=n)     # warm the caches
    t_sweep, t_sweep_min = median_time(lambda: sweep_J(rotor, J, rpm=rpm, n_stations=n), a.repeats)
    res = sweep_J(rotor, J, rpm=rpm, n_stations=n)
    kern = solve_kernel(sec)
    print(f"rotor sweep benchmark: {n} stations x {K} J points (APC 10x7, sections {a.airfoil})")
    print(f"  section load/fit            {t_sec * 1e3:8.1f} ms")
    print(f"  build mapped analysis fn    {t_build * 1e3:8.1f} ms  (element solve kernel {kern.n_instructions()} SX instructions; "
          f"first call {t_first * 1e3:.1f} ms)")
    print(f"  mapped call (one sweep)     {t_map * 1e3:8.2f} ms median ({t_map_min * 1e3:.2f} min) "
          f"= {t_map / K * 1e3:.3f} ms per point, {t_map / (K * n) * 1e6:.1f} us per station")
    print(f"  sweep_J (checks+fallback)   {t_sweep * 1e3:8.2f} ms median ({t_sweep_min * 1e3:.2f} min) "
          f"= {t_sweep / K * 1e3:.3f} ms per point")
    print(f"  brackets found in (0, pi/2]: {int(found.sum())}/{found.size}; converged points "
          f"{int(res.converged.sum())}/{K}; max |residual| {res.residual_max.max():.1e}")


if __name__ == "__main__":
    main()
