"""Benchmark of ``mdo sweep``: the same 8-point sweep serial, on 2 Dask workers, and on 2
workers with warm starts from the nearest finished neighbour.

Problem: ``problems/polar_ga_mission.py`` with the wing area as a design variable (so
every point is a real two-stage ``mdo run``: baseline analysis, then optimization),
cruise distance 30 ... 100 nmi.  Reported: wall time of each sweep, speed-up, the
points' summed wall and solve times (the difference is the start-up of each ``mdo run``
subprocess: interpreter, imports, problem build, reports), IPOPT iterations with and
without warm start, the largest objective difference between the three sweeps, and the
machine's load (``os.getloadavg``, ``os.cpu_count``): the machine is shared, so read
the speed-up against the load.

    python tests/bench/sweep.py [--out results/sweeps/benchmark.md]
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PROBLEM = ROOT / "problems" / "polar_ga_mission.py"
GRID = "cruise_distance_nmi=" + ",".join(f"{d:.1f}" for d in range(30, 101, 10))


def _sweep(out: Path, *extra) -> dict:
    cmd = [sys.executable, "-m", "mdo.cli", "sweep", str(PROBLEM), "--grid", GRID, "-o", "design_wing_area=true",
           "--out", str(out), *extra]
    load0 = os.getloadavg()[0]
    t0 = time.time()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t0
    if proc.returncode != 0:
        raise SystemExit(f"sweep failed ({proc.returncode}):\n{proc.stdout}\n{proc.stderr}")
    sys.path.insert(0, str(ROOT))
    from mdo.sweep.table import read_table
    rows = read_table(out / "sweep.csv")
    return {"wall_s": wall, "rows": rows, "load": (load0, os.getloadavg()[0]),
            "point_wall_s": sum(r["wall_time_s"] for r in rows), "solve_s": sum(r["solve_time_s"] for r in rows),
            "iterations": sum(r["iterations"] + (r["iterations_baseline"] or 0) for r in rows),
            "warm": sum(1 for r in rows if r["warm_start_from"])}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", help="write the markdown table here as well")
    args = ap.parse_args()
    tmp = Path(tempfile.mkdtemp(prefix="mdo_sweep_bench_"))
    try:
        runs = {"serial (--workers 0)": _sweep(tmp / "serial", "--workers", "0"),
                "2 workers": _sweep(tmp / "dask2", "--workers", "2"),
                "2 workers, --warm-start": _sweep(tmp / "warm2", "--workers", "2", "--warm-start")}
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    ref = {r["point"]: r["objective"] for r in runs["serial (--workers 0)"]["rows"]}
    serial = runs["serial (--workers 0)"]["wall_s"]
    lines = [f"8-point sweep of polar_ga_mission.py (design_wing_area=true, {GRID}); "
             f"{os.cpu_count()} CPUs, shared; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}", "",
             "| sweep | wall s | speed-up | sum of point wall s | sum of IPOPT s | start-up s/point | "
             "IPOPT iterations (all stages) | warm-started points | max rel. objective diff vs serial | "
             "load avg (start -> end) |", "|---|---|---|---|---|---|---|---|---|---|"]
    for name, r in runs.items():
        diff = max(abs(x["objective"] - ref[x["point"]]) / abs(ref[x["point"]]) for x in r["rows"])
        lines.append(f"| {name} | {r['wall_s']:.1f} | {serial / r['wall_s']:.2f} | {r['point_wall_s']:.1f} | "
                     f"{r['solve_s']:.1f} | {(r['point_wall_s'] - r['solve_s']) / len(r['rows']):.1f} | "
                     f"{r['iterations']} | {r['warm']} | {diff:.1e} | {r['load'][0]:.1f} -> {r['load'][1]:.1f} |")
    text = "\n".join(lines)
    print(text)
    if args.out:
        Path(args.out).write_text(text + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
