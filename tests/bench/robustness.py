"""Robustness study (issue 11): GA-2P from 20 random starts.

    python tests/bench/robustness.py [--starts 20] [--seed 2026] [--spread 0.15] [--problem ga2p]

Each start draws every design variable (every element of the twist vector) uniformly
within +-spread of its baseline value (fixed seed; clipped to the bounds), then runs
the documented two-stage continuation: the mission analysis with that design frozen
(mission unknowns from the vehicle's physics-based guesses), then the optimization
warm-started from it.  Reports how many converge and the spread of the optimized
energy and design; writes results/robustness/<problem>.md.  Not collected by pytest.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.nlp.run import _import_file  # noqa: E402


def one_start(module, rng, spread):
    probe = module.build(analysis=True)
    start = {}
    for v in probe.variables.values():
        if v.design and np.any(v.lower != v.upper):
            f = 1.0 + rng.uniform(-spread, spread, size=v.init.shape)
            start[v.name] = np.clip(v.init * f, v.lower, v.upper)
    an = module.build(analysis=True)
    for k, val in start.items():
        an.set_initial(k, val)
    an.freeze_design()
    t0 = time.perf_counter()
    s_an = an.solve(verbose=False)
    with tempfile.TemporaryDirectory() as tmp:
        s_an.save(tmp)
        op = module.build(analysis=False)
        op.warm_start(Path(tmp) / "solution.json")
        op.start_from_baseline()     # as mdo run's stage 2
        s = op.solve(verbose=False)
    wall = time.perf_counter() - t0
    design = {v["name"]: v["value"] for v in s.variables if v["design"]}
    return start, s_an, s, design, wall


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--problem", default="ga2p")
    ap.add_argument("--starts", type=int, default=20)
    ap.add_argument("--seed", type=int, default=2026)
    ap.add_argument("--spread", type=float, default=0.15)
    args = ap.parse_args()
    module = _import_file(ROOT / "problems" / f"{args.problem}.py")
    rng = np.random.default_rng(args.seed)
    rows = []
    for i in range(args.starts):
        start, s_an, s, design, wall = one_start(module, rng, args.spread)
        e = s.summary_values().get("battery_energy_kWh", float("nan"))
        rows.append((i, s_an.status, s_an.iterations, s.status, s.iterations, e, wall, design, start))
        print(f"start {i:2d}: analysis {s_an.status} ({s_an.iterations} it), optimization {s.status} "
              f"({s.iterations} it), {e:.4f} kWh, {wall:.0f} s", flush=True)
    ok = [r for r in rows if r[3] == "Solve_Succeeded"]
    es = np.array([r[5] for r in ok])
    lines = [f"# Robustness: {args.problem} from {args.starts} random starts", "",
             f"Design variables drawn uniformly within +-{100 * args.spread:g} % of the baseline (seed "
             f"{args.seed}, clipped to the bounds); two-stage continuation per start (mission analysis at the "
             f"drawn design, then the optimization warm-started from it).  Produced by "
             f"`python tests/bench/robustness.py`.", "",
             f"**{len(ok)} of {args.starts} converged** (IPOPT Solve_Succeeded)."]
    if len(ok):
        spread_pct = 100 * (es.max() - es.min()) / es.min()
        lines += [f"Optimized energy: min {es.min():.4f}, median {np.median(es):.4f}, max {es.max():.4f} kWh; "
                  f"spread {spread_pct:.3f} % (goal 0.5 %).",
                  f"Wall time per start (both stages): median {statistics.median(r[6] for r in rows):.0f} s.", "",
                  "Spread of the optimized design over the converged starts:", "",
                  "| variable | min | median | max |", "|---|---:|---:|---:|"]
        for name in ok[0][7]:
            vals = np.array([np.asarray(r[7][name], float).ravel() for r in ok])
            for j in range(vals.shape[1]):
                col = vals[:, j]
                lab = name + (f"[{j}]" if vals.shape[1] > 1 else "")
                lines.append(f"| {lab} | {col.min():.5g} | {np.median(col):.5g} | {col.max():.5g} |")
    lines += ["", "| start | analysis | it | optimization | it | energy (kWh) | wall (s) |",
              "|---:|---|---:|---|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r[0]} | {r[1]} | {r[2]} | {r[3]} | {r[4]} | {r[5]:.4f} | {r[6]:.0f} |")
    out = ROOT / "results" / "robustness" / f"{args.problem}.md"
    out.parent.mkdir(exist_ok=True)
    out.write_text("\n".join(lines) + "\n")
    print("\n".join(lines[:8]))


if __name__ == "__main__":
    main()
