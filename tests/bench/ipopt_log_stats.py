"""What an IPOPT log says about a solve's path (issue 20, item 2: why the TTW needs so
many iterations).  Not collected by pytest.

    python tests/bench/ipopt_log_stats.py RUN_FOLDER_OR_LOG [...]

Per log (a run folder's ``ipopt.log``, or ``monotone/ipopt.log`` of a failed first
attempt): iterations; how many had the Hessian regularized (IPOPT's ``lg(rg)`` column:
the inertia of the KKT matrix was wrong, so ``delta_w I`` was added to the Hessian of the
Lagrangian - a non-convex step, taken closer to steepest descent the larger ``delta_w``);
the median ``lg(rg)``; the restoration iterations (``r``); the iterations whose primal
step was cut below 0.1 by the line search.  Prints a markdown table.
"""
from __future__ import annotations

import re
import statistics
import sys
from pathlib import Path

ROW = re.compile(r"^\s*(\d+)(r?)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+?)[a-zA-Z]?\s+(\d+)\s*$")


def iterations(log: Path) -> list:
    """(iteration, restoration, lg_mu, lg_rg or None, alpha_pr) of every iteration row."""
    out = []
    for line in log.read_text(errors="replace").splitlines():
        m = ROW.match(line)
        if not m:
            continue
        try:
            float(m.group(3))
        except ValueError:
            continue
        rg = None if m.group(8) == "-" else float(m.group(8))
        out.append((int(m.group(1)), m.group(2) == "r", float(m.group(6)), rg, float(m.group(10))))
    return out


def stats(log: Path) -> dict:
    rows = iterations(log)
    rg = [r[3] for r in rows if r[3] is not None]
    return {"iterations": len(rows), "regularized": len(rg),
            "median_lg_rg": statistics.median(rg) if rg else None,
            "restoration": sum(r[1] for r in rows), "short_steps": sum(r[4] < 0.1 for r in rows)}


def main(paths):
    print("| log | iterations | Hessian regularized | median lg(rg) | restoration | alpha_pr < 0.1 |")
    print("|---|---:|---:|---:|---:|---:|")
    for p in map(Path, paths):
        log = p / "ipopt.log" if p.is_dir() else p
        s = stats(log)
        med = "-" if s["median_lg_rg"] is None else f"{s['median_lg_rg']:.1f}"
        share = 100.0 * s["regularized"] / max(s["iterations"], 1)
        print(f"| `{log}` | {s['iterations']} | {s['regularized']} ({share:.0f} %) | {med} | "
              f"{s['restoration']} | {s['short_steps']} |")


if __name__ == "__main__":
    main(sys.argv[1:] or ["results/ga2p", "results/ga8p", "results/ttw"])
