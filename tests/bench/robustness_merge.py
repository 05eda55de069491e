"""Merge one-start robustness reports (``robustness.py --first K --starts 1 --out ...``)
into one study: the per-start table, the converged count, the energy spread, the troughs
(optima within ``--trough`` % of each other) and the spread of the optimized design.

    python tests/bench/robustness_merge.py results/robustness/ttw_2026-12-05_start*.json \
        --title "TTW, 2026-12-05" --out results/robustness/ttw.md [--committed 110.851]

The JSON files are those ``robustness.py`` writes beside each report.  Not collected by pytest.
"""
from __future__ import annotations

import argparse
import json
import statistics
from pathlib import Path

import numpy as np


def troughs(energies, rel):
    """Groups of sorted energies whose neighbours lie within ``rel`` of each other."""
    groups = []
    for e in sorted(energies):
        if groups and e <= groups[-1][-1] * (1.0 + rel):
            groups[-1].append(e)
        else:
            groups.append([e])
    return groups


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("files", nargs="+")
    ap.add_argument("--title", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--committed", type=float, default=None, help="the committed optimum (kWh), for comparison")
    ap.add_argument("--trough", type=float, default=0.5, help="percent: optima this close form one trough")
    args = ap.parse_args(argv)
    rows = []
    for f in args.files:
        rows += json.loads(Path(f).read_text())
    rows.sort(key=lambda r: r["start"])
    ok = [r for r in rows if r["optimization_status"] == "Solve_Succeeded"]
    es = np.array([r["battery_energy_kWh"] for r in ok])
    folders = sorted({str(Path(f).parent) for f in args.files})
    lines = [f"# Robustness: {args.title}", "",
             f"Merged by `python tests/bench/robustness_merge.py` from {len(args.files)} one-start runs of "
             f"`tests/bench/robustness.py` in {', '.join(f'`{d}/`' for d in folders)} (each report there gives its "
             f"command and commit).", "",
             f"**{len(ok)} of {len(rows)} converged** (IPOPT Solve_Succeeded)."]
    if len(ok):
        lines.append(f"Optimized energy: min {es.min():.4f}, median {np.median(es):.4f}, max {es.max():.4f} kWh; "
                     f"spread {100 * (es.max() - es.min()) / es.min():.2f} %"
                     + (f"; committed optimum {args.committed:.4f} kWh" if args.committed else "") + ".")
        lines.append(f"Wall time per start: median {statistics.median(r['wall_s'] for r in rows):.0f} s "
                     f"(two starts at a time and other jobs on the 2 cores: upper bounds).")
        groups = troughs(es, args.trough / 100.0)
        lines += ["", f"Troughs (optima within {args.trough:g} % of a neighbour):", "",
                  "| trough | starts | energy (kWh) |", "|---:|---:|---|"]
        for i, g in enumerate(groups):
            lines.append(f"| {i + 1} | {len(g)} | {min(g):.4f}" + (f" - {max(g):.4f}" if len(g) > 1 else "") + " |")
        lines += ["", "Spread of the optimized design over the converged starts:", "",
                  "| variable | min | median | max |", "|---|---:|---:|---:|"]
        for name in ok[0]["optimized"]:
            vals = np.array([np.asarray(r["optimized"][name], float).ravel() for r in ok])
            for j in range(vals.shape[1]):
                col = vals[:, j]
                lab = name + (f"[{j}]" if vals.shape[1] > 1 else "")
                lines.append(f"| {lab} | {col.min():.5g} | {np.median(col):.5g} | {col.max():.5g} |")
    lines += ["", "| start | optimization | iterations | energy (kWh) | wall (s) |", "|---:|---|---|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['start']} | {r['optimization_status']} | {r['iterations']} | "
                     f"{r['battery_energy_kWh']:.4f} | {r['wall_s']:.0f} |")
    out = Path(args.out)
    out.write_text("\n".join(lines) + "\n")
    out.with_suffix(".json").write_text(json.dumps(rows, indent=1) + "\n")
    print("\n".join(lines[:12]))


if __name__ == "__main__":
    main()
