"""How results/ttw_free/ (the TTW optimized with a free trajectory) was made, from the repository root:

    python results/ttw_free/make_optimum.py OUT_DIR [--segments SEGMENTS] [--start SOLUTION_JSON]
                                                    [--tilt control] [--max-block-time-min T]
                                                    [--cabin-attitude-deg X] [--max-span-m B]
                                                    [--min-climb-gradient-pct G]

--segments: ``all`` (default: ``-o trajectory=free``, every forward-flight segment the
rules allow, the transitions included) or a comma-separated list of Table 5 segments to
free (e.g. ``CL,CR,D,RCL,RCR,RD``: the wing-borne ones; the others keep Table 5).

``--tilt control``: the transitions' wing tilt (WMA) a control too (issue 22 item 3).
``--max-block-time-min T``: the mission (departure to landing) within T minutes.
``--cabin-attitude-deg X``: the body attitude within +-X deg at every node (``-o cabin_attitude_deg``).
``--max-span-m B``: both wings' span at most B (``-o max_span_m``: a vertiport's limit).
``--min-climb-gradient-pct G``: the freed climbs' gradient rule (default 8.3 %).

The optimization (design free) starts from the prescribed-profile optimum
(default ``--start results/ttw/solution.json``: a partial warm start, the freed speeds and
durations starting at Table 5's values) with the monotone barrier ``mdo run`` uses from a
converged point (``Problem.start_from_baseline``).  Why not ``mdo run -o trajectory=free``:
the TTW's baseline analysis does not converge from scratch (``results/ttw/README.md``),
and a free-trajectory baseline from the prescribed baseline's mission ended after 300
iterations without converging (adaptive barrier, 2026-12-04; the Table 5 profile ends its
climb at a 5 % gradient where the envelope asks 8.3 %).
"""
import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.nlp.run import _import_file, solve_into  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("out")
ap.add_argument("--segments", default="all")
ap.add_argument("--start", default=str(ROOT / "results/ttw/solution.json"))
ap.add_argument("--tilt", default="schedule", choices=("schedule", "control"))
ap.add_argument("--max-block-time-min", type=float, default=None, help="the mission duration limit (min)")
ap.add_argument("--cabin-attitude-deg", type=float, default=None, help="body attitude bounds +-X deg")
ap.add_argument("--max-span-m", type=float, default=None, help="both wings' span limit (m)")
ap.add_argument("--min-climb-gradient-pct", type=float, default=None, help="the climb-gradient rule (%%)")
args = ap.parse_args()
trajectory = "free" if args.segments == "all" else {s: "free" for s in args.segments.split(",")}
problem = _import_file(ROOT / "problems" / "ttw.py").build(analysis=False, trajectory=trajectory, tilt=args.tilt,
                                                       max_block_time_min=args.max_block_time_min,
                                                       cabin_attitude_deg=args.cabin_attitude_deg,
                                                       max_span_m=args.max_span_m,
                                                       min_climb_gradient_pct=args.min_climb_gradient_pct)
print(problem.size(), flush=True)
print(problem.warm_start(args.start, partial=True, multipliers=False).describe(), flush=True)
problem.start_from_baseline()
sol = solve_into(problem, args.out, verbose=True, max_iter=400)
print(sol.status, sol.iterations, sol.objective, flush=True)
