"""How the optimization's barrier start from a converged baseline sets its iteration count
(issue 20: fewer iterations).  Not collected by pytest.

    python tests/bench/barrier_start.py [ga2p ga8p] [--mu 1e-2 1e-3 1e-4] [-o KEY=VALUE ...]

For each problem and each ``mu_init``, builds the optimization, warm-starts it from the
committed baseline analysis (``results/<p>/analysis/solution.json``) as ``mdo run`` does,
with the first barrier of the problem's ``barrier_order`` (monotone for the GA problems,
adaptive for the TTW) started at that ``mu_init``, and solves it; prints iterations, wall
time of the solve and the optimum.  The committed GA runs use ``FROM_BASELINE_OPTIONS``
(monotone, mu_init 1e-4).  IPOPT's adaptive rule sets mu itself from its first iteration:
the TTW from its baseline takes the same 75 iterations from 1e-2 and 1e-3 as from 0.1.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.cli import _parse_option  # noqa: E402
from mdo.nlp import load_problem_file  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("problems", nargs="*", default=["ga2p", "ga8p"])
    ap.add_argument("--mu", type=float, nargs="+", default=[1e-2, 1e-3, 1e-4])
    ap.add_argument("-o", dest="options", action="append", default=[],
                    help="a problem option, as mdo run's -o (e.g. trim=false for the X-57's committed runs)")
    args = ap.parse_args()
    options = dict(_parse_option(o) for o in args.options)
    print("| problem | mu_init | status | iterations | solve wall (s) | energy (kWh) |")
    print("|---|---:|---|---:|---:|---:|")
    for prob in args.problems:
        for mu in args.mu:
            op = load_problem_file(ROOT / "problems" / f"{prob}.py", options=options)
            op.warm_start(ROOT / "results" / prob / "analysis" / "solution.json")
            op.start_from_baseline()
            op.ipopt_options["mu_init"] = mu
            s = op.solve(verbose=False)
            e = s.summary_values().get("battery_energy_kWh", float("nan"))
            print(f"| {prob} | {mu:g} | {s.status} | {s.iterations} | {s.wall_time_s:.1f} | {e:.4f} |", flush=True)


if __name__ == "__main__":
    main()
