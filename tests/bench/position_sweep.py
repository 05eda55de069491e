"""Mission energy against the propeller span position, everything else frozen.

    python tests/bench/position_sweep.py [--from results/ga2p/solution.json]
        [--eta 0.14 0.26 13] [-o KEY=VALUE ...] [--csv FILE]

Takes the GA-2P design of a solution, sets the propellers' span position to each
value of a sweep, freezes the design and re-solves the mission (warm-started from
that solution).  A smooth model gives a smooth curve; ripples with the period of the
lattice strips would make the optimum depend on the start (results/robustness.md).
Not collected by pytest.
"""
from __future__ import annotations

import argparse
import csv
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.cli import _parse_option  # noqa: E402
from mdo.nlp import load_problem_file  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--from", dest="start", default=str(ROOT / "results" / "ga2p" / "solution.json"))
    ap.add_argument("--eta", nargs=3, type=float, default=[0.14, 0.26, 13], metavar=("LO", "HI", "N"))
    ap.add_argument("--option", "-o", action="append", default=[])
    ap.add_argument("--csv")
    a = ap.parse_args()
    options = dict(_parse_option(o) for o in a.option)
    rows = []
    for eta in np.linspace(a.eta[0], a.eta[1], int(a.eta[2])):
        t = time.perf_counter()
        p = load_problem_file(ROOT / "problems" / "ga2p.py", options=options)
        p.warm_start(a.start)
        p.set_initial("propellers.span_eta", eta)
        p.freeze_design()
        sol = p.solve(verbose=False)
        e = sol.summary_values().get("battery_energy_kWh")
        rows.append((eta, e, sol.status, time.perf_counter() - t))
        print(f"span_eta {eta:.4f}  energy {e:.5f} kWh  {sol.status}  {rows[-1][3]:.0f} s", flush=True)
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["span_eta", "battery_energy_kWh", "status"])
            w.writerows(r[:3] for r in rows)


if __name__ == "__main__":
    main()
