"""Robustness study (issue 11): GA-2P from 20 random starts.

    python tests/bench/robustness.py [--starts 20] [--seed 2026] [--spread 0.15] [--problem ga2p]
                                     [--from-baseline RUN_FOLDER]
                                     [--factor F] [--first K] [--out PATH]

Each start draws every design variable (every element of the twist vector) uniformly
within +-spread of its baseline value (fixed seed; clipped to the bounds), then runs
the documented two-stage continuation: the mission analysis with that design frozen
(mission unknowns from the vehicle's physics-based guesses), then the optimization
warm-started from it.  Reports how many converge and the spread of the optimized
energy and design; writes results/robustness/<problem>.md (and .json: every start's
drawn and optimized design).  Not collected by pytest.
"""
from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.nlp.run import _import_file, optimize_from_baseline  # noqa: E402


def _draw(probe, rng, spread, factor=None):
    """Every free design variable times 1 + U(-spread, spread) (or times ``factor``), clipped to its bounds."""
    start = {}
    for v in probe.variables.values():
        if v.design and np.any(v.lower != v.upper):
            f = factor * np.ones(v.init.shape) if factor else 1.0 + rng.uniform(-spread, spread, size=v.init.shape)
            start[v.name] = np.clip(v.init * f, v.lower, v.upper)
    return start


def _optimize(module, warm, start=None):
    """Stage 2 as ``mdo run``: the monotone barrier from the baseline, the adaptive barrier
    if that does not converge (``mdo.nlp.run.optimize_from_baseline``, shared with the CLI)."""
    op = module.build(analysis=False)

    def from_start():
        op.warm_start(warm)
        for k, val in (start or {}).items():
            op.set_initial(k, val)

    return optimize_from_baseline(op, from_start, lambda adaptive: op.solve(verbose=False))


def one_start(module, rng, spread, from_baseline=None, factor=None):
    """One start: the analysis at the drawn design, then the optimization from it; or, with
    ``from_baseline`` (a converged baseline's run folder), the optimization started from
    that baseline's mission with the drawn design (for problems whose baseline needs a
    script of its own, the TTW)."""
    probe = module.build(analysis=True)
    start = _draw(probe, rng, spread, factor)
    t0 = time.perf_counter()
    if from_baseline is not None:
        s_an = None
        s = _optimize(module, Path(from_baseline) / "solution.json", start)
    else:
        an = module.build(analysis=True)
        for k, val in start.items():
            an.set_initial(k, val)
        an.freeze_design()
        s_an = an.solve(verbose=False)
        with tempfile.TemporaryDirectory() as tmp:
            s_an.save(tmp)
            s = _optimize(module, Path(tmp) / "solution.json")
    wall = time.perf_counter() - t0
    design = {v["name"]: v["value"] for v in s.variables if v["design"]}
    return start, s_an, s, design, wall



def _write_report(args, rows) -> list:
    """The report (markdown and per-start json) of the starts done so far; returns its lines."""
    ok = [r for r in rows if r[3] == "Solve_Succeeded"]
    es = np.array([r[5] for r in ok])
    drawn = (f"Every design variable x {args.factor:g} (clipped to the bounds); " if args.factor else
             f"Design variables drawn uniformly within +-{100 * args.spread:g} % of the baseline (seed "
             f"{args.seed}, clipped to the bounds); ")
    lines = [f"# Robustness: {args.problem} from {len(rows)} " + ("start" if args.factor else "random starts"), "",
             drawn
             + (f"each optimization started from the mission of the converged baseline `{args.from_baseline}` with "
                f"the drawn design" if args.from_baseline else
                "two-stage continuation per start (mission analysis at the drawn design, then the optimization "
                "warm-started from it)")
             + "; the monotone barrier first, the adaptive barrier if it does not converge, as `mdo run`.  "
             f"Produced by `python tests/bench/robustness.py {' '.join(sys.argv[1:])}`.", "",
             f"**{len(ok)} of {len(rows)} converged** (IPOPT Solve_Succeeded)."]
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
    out = Path(args.out) if args.out else \
        ROOT / "results" / "robustness" / (f"{args.problem}" + (f"_x{args.factor:g}" if args.factor else "") + ".md")
    out.parent.mkdir(exist_ok=True)
    out.write_text("\n".join(lines) + "\n")
    # every start's drawn and optimized design, so that distinct optima can be compared later
    per_start = [{"start": r[0], "analysis_status": r[1], "optimization_status": r[3], "iterations": r[4],
                  "battery_energy_kWh": r[5], "wall_s": r[6],
                  "drawn": {k: np.asarray(v, float).tolist() for k, v in r[8].items()},
                  "optimized": {k: np.asarray(v, float).tolist() for k, v in r[7].items()}} for r in rows]
    out.with_suffix(".json").write_text(json.dumps(per_start, indent=1) + "\n")
    return lines

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--problem", default="ga2p")
    ap.add_argument("--starts", type=int, default=20)
    ap.add_argument("--seed", type=int, default=2026)
    ap.add_argument("--spread", type=float, default=0.15)
    ap.add_argument("--factor", type=float, default=None,
                    help="one start with every design variable times this factor (e.g. 1.15)")
    ap.add_argument("--first", type=int, default=0,
                    help="skip the first K draws of the seed (to continue a study in another process)")
    ap.add_argument("--out", default=None, help="the report's path (default results/robustness/<problem>.md)")
    ap.add_argument("--from-baseline", default=None,
                    help="a converged baseline run folder: start each optimization from its mission")
    args = ap.parse_args()
    module = _import_file(ROOT / "problems" / f"{args.problem}.py")
    rng = np.random.default_rng(args.seed)
    if args.factor:
        args.starts = 1
    rows = []
    if args.first:   # the same draws as a study from start 0: discard the first K
        probe = module.build(analysis=True)
        for _ in range(args.first):
            _draw(probe, rng, args.spread, args.factor)
        del probe
    for i in range(args.first, args.first + args.starts):
        start, s_an, s, design, wall = one_start(module, rng, args.spread, args.from_baseline, args.factor)
        e = s.summary_values().get("battery_energy_kWh", float("nan"))
        an_status, an_it = (s_an.status, s_an.iterations) if s_an is not None else ("(baseline's mission)", 0)
        fb = s.barrier.get("fallback_from")
        it = f"{fb['iterations']} monotone + {s.iterations} adaptive" if fb else str(s.iterations)
        rows.append((i, an_status, an_it, s.status, it, e, wall, design, start))
        print(f"start {i:2d}: analysis {an_status} ({an_it} it), optimization {s.status} "
              f"({it} it), {e:.4f} kWh, {wall:.0f} s", flush=True)
        lines = _write_report(args, rows)   # after every start: a stopped study keeps what it has
    print("\n".join(lines[:8]))


if __name__ == "__main__":
    main()
