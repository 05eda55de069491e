"""Robustness study (issue 11): GA-2P from 20 random starts.

    python tests/bench/robustness.py [--starts 20] [--seed 2026] [--spread 0.15] [--problem ga2p]
                                     [--from-baseline RUN_FOLDER]
                                     [--factor F] [--first K] [--out PATH] [--timeout S]

Each start draws every design variable (every element of the twist vector) uniformly
within +-spread of its baseline value (fixed seed; clipped to the bounds), then runs
the documented two-stage continuation: the mission analysis with that design frozen
(mission unknowns from the vehicle's physics-based guesses), then the optimization
warm-started from it.  Reports how many converge and the spread of the optimized
energy and design; writes results/robustness/<problem>.md (and .json: every start's
drawn and optimized design).  Not collected by pytest.

Each start runs in its own process (this script with ``--one K``), so that a start whose
IPOPT iteration does not end (one was seen spending 26 minutes inside the linear solver,
where no signal handler runs) can be killed after ``--timeout S`` seconds and recorded as
stopped, and the study goes on.  Every start's IPOPT logs (analysis and optimization) and
its output are kept in ``<report>_logs/start_K/`` (not committed).
"""
from __future__ import annotations

import argparse
import json
import statistics
import subprocess
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


def _optimize(module, warm, start=None, logs=None):
    """Stage 2 as ``mdo run``: the problem's first barrier from the baseline (monotone unless it
    chose another), the other barrier if that does not converge (``mdo.nlp.run.optimize_from_baseline``, shared with the CLI)."""
    op = module.build(analysis=False)

    def from_start():
        op.warm_start(warm)
        for k, val in (start or {}).items():
            op.set_initial(k, val)

    def solve(fallback):
        log = None if logs is None else logs / f"optimization{'_' + op.barrier_order[1] if fallback else ''}.log"
        return op.solve(verbose=False, log_path=log)

    return optimize_from_baseline(op, from_start, solve)


def one_start(module, rng, spread, from_baseline=None, factor=None, logs=None):
    """One start: the analysis at the drawn design, then the optimization from it; or, with
    ``from_baseline`` (a converged baseline's run folder), the optimization started from
    that baseline's mission with the drawn design (for problems whose baseline needs a
    script of its own, the TTW)."""
    probe = module.build(analysis=True)
    start = _draw(probe, rng, spread, factor)
    t0 = time.perf_counter()
    if from_baseline is not None:
        s_an = None
        s = _optimize(module, Path(from_baseline) / "solution.json", start, logs)
    else:
        an = module.build(analysis=True)
        for k, val in start.items():
            an.set_initial(k, val)
        an.freeze_design()
        s_an = an.solve(verbose=False, log_path=None if logs is None else logs / "analysis.log")
        with tempfile.TemporaryDirectory() as tmp:
            s_an.save(tmp)
            s = _optimize(module, Path(tmp) / "solution.json", logs=logs)
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
             + "; the problem's first barrier (monotone unless it chose adaptive first), the other barrier if that "
             "does not converge, as `mdo run`.  "
             f"Produced by `python tests/bench/robustness.py {' '.join(sys.argv[1:])}` (each start in its own "
             "process" + (f", killed after {args.timeout:g} s" if args.timeout else "") + ").", "",
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
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text("\n".join(lines) + "\n")
    # every start's drawn and optimized design, so that distinct optima can be compared later
    per_start = [{"start": r[0], "analysis_status": r[1], "optimization_status": r[3], "iterations": r[4],
                  "battery_energy_kWh": r[5], "wall_s": r[6],
                  "drawn": {k: np.asarray(v, float).tolist() for k, v in r[8].items()},
                  "optimized": {k: np.asarray(v, float).tolist() for k, v in r[7].items()}} for r in rows]
    out.with_suffix(".json").write_text(json.dumps(per_start, indent=1) + "\n")
    return lines

def _row_of(i, s_an, s, design, wall, start) -> list:
    e = s.summary_values().get("battery_energy_kWh", float("nan"))
    an_status, an_it = (s_an.status, s_an.iterations) if s_an is not None else ("(baseline's mission)", 0)
    fb = s.barrier.get("fallback_from")
    it = f"{fb['iterations']} {fb['mu_strategy']} + {s.iterations} {s.barrier.get('mu_strategy', '?')}" if fb \
        else str(s.iterations)
    return [i, an_status, an_it, s.status, it, e, wall,
            {k: np.asarray(v, float).tolist() for k, v in design.items()},
            {k: np.asarray(v, float).tolist() for k, v in start.items()}]


def _run_one(args, module, k: int) -> list:
    """``--one K``: start K of the seed (the first K draws discarded) in this process."""
    rng = np.random.default_rng(args.seed)
    probe = module.build(analysis=True)
    for _ in range(k):
        _draw(probe, rng, args.spread, args.factor)
    del probe
    logs = Path(args.logs) if args.logs else None
    if logs is not None:
        logs.mkdir(parents=True, exist_ok=True)
    start, s_an, s, design, wall = one_start(module, rng, args.spread, args.from_baseline, args.factor, logs)
    return _row_of(k, s_an, s, design, wall, start)


def _spawn(args, k: int, logs: Path) -> list:
    """Start K in a child process with the study's budget; a row whatever happens."""
    logs.mkdir(parents=True, exist_ok=True)
    row_file = logs / "row.json"
    row_file.unlink(missing_ok=True)
    cmd = [sys.executable, __file__, "--problem", args.problem, "--seed", str(args.seed),
           "--spread", str(args.spread), "--one", str(k), "--logs", str(logs)]
    cmd += ["--factor", str(args.factor)] if args.factor else []
    cmd += ["--from-baseline", str(args.from_baseline)] if args.from_baseline else []
    t0 = time.perf_counter()
    with open(logs / "output.txt", "w") as out:
        try:
            code = subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT, timeout=args.timeout).returncode
        except subprocess.TimeoutExpired:   # subprocess.run kills the child (SIGKILL)
            code = None
    wall = time.perf_counter() - t0
    if code == 0 and row_file.exists():
        return json.loads(row_file.read_text())
    why = f"stopped after {args.timeout:g} s (--timeout)" if code is None else f"crashed (exit {code})"
    if not any(logs.glob("optimization*.log")) and not args.from_baseline:   # it never left the analysis
        return [k, why, 0, "(not started)", "-", float("nan"), wall, {}, {}]
    return [k, "-", 0, why, "-", float("nan"), wall, {}, {}]


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
    ap.add_argument("--timeout", type=float, default=None,
                    help="wall-time budget of each start in seconds: a start still going is killed and "
                         "recorded as stopped")
    ap.add_argument("--one", type=int, default=None, help=argparse.SUPPRESS)    # the child's start
    ap.add_argument("--logs", default=None, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.timeout is not None and not args.timeout > 0:
        ap.error(f"--timeout: must be > 0 seconds, got {args.timeout:g}")
    module = _import_file(ROOT / "problems" / f"{args.problem}.py")
    if args.one is not None:
        row = _run_one(args, module, args.one)
        (Path(args.logs) / "row.json").write_text(json.dumps(row) + "\n")
        return
    if args.factor:
        args.starts = 1
    report = Path(args.out) if args.out else \
        ROOT / "results" / "robustness" / (f"{args.problem}" + (f"_x{args.factor:g}" if args.factor else "") + ".md")
    logs_root = report.with_name(report.stem + "_logs")
    rows = []
    for i in range(args.first, args.first + args.starts):
        r = _spawn(args, i, logs_root / f"start_{i}")
        rows.append(r)
        print(f"start {i:2d}: analysis {r[1]} ({r[2]} it), optimization {r[3]} "
              f"({r[4]} it), {r[5]:.4f} kWh, {r[6]:.0f} s", flush=True)
        lines = _write_report(args, rows)   # after every start: a stopped study keeps what it has
    print("\n".join(lines[:8]))


if __name__ == "__main__":
    main()
