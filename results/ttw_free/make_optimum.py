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
converged point (``FROM_BASELINE_OPTIONS``, with the divergence watch).  Why not ``mdo run -o trajectory=free``:
the TTW's baseline analysis does not converge from scratch (``results/ttw/README.md``),
and a free-trajectory baseline from the prescribed baseline's mission ended after 300
iterations without converging (adaptive barrier, 2026-12-04; the Table 5 profile ends its
climb at a 5 % gradient where the envelope asks 8.3 %).
"""
import argparse
import csv
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.nlp.ipopt import FROM_BASELINE_OPTIONS, DivergenceWatch  # noqa: E402
from mdo.nlp.problem import read_solution  # noqa: E402
from mdo.nlp.run import _import_file, solve_into  # noqa: E402



def continuous_tilt_start(problem, start_folder):
    """With ``--tilt control`` from a fixed-tilt solution: the tilt starts continuous (linear
    in time within each controlled segment between its joins: a prescribed neighbour's
    angle, else the later segment's Table 5 angle; Table 5 steps between segments, which the
    control's continuity forbids), and the body angle moves by the opposite amount, so the
    wing and rotors see the start's angles (body + tilt) and its forces."""
    rows = list(csv.DictReader(open(Path(start_folder) / "mission.csv")))
    seg = [r["segment"] for r in rows]
    wma = np.radians([float(r["wing_mounted_angle_deg"]) for r in rows])
    body = np.radians([float(r["body_angle_deg"]) for r in rows])
    on = np.array([float(r["wing_tilt_control"]) > 0 for r in rows])
    names = list(dict.fromkeys(seg))
    first = {n: seg.index(n) for n in names}
    last = {n: len(seg) - 1 - seg[::-1].index(n) for n in names}
    tilt = wma.copy()
    for i, n in enumerate(names):
        a, b = first[n], last[n]
        if not on[a]:
            continue
        prev = names[i - 1] if i > 0 else None
        nxt = names[i + 1] if i + 1 < len(names) else None
        t0 = wma[a] if prev is None or on[first[prev]] else wma[last[prev]]
        t1 = wma[b] if nxt is None else (wma[first[nxt]])
        t = np.array([float(rows[k]["time_s"]) for k in range(a, b + 1)])
        tilt[a:b + 1] = t0 + (t1 - t0) * (t - t[0]) / (t[-1] - t[0])
    var = problem.variables["wing_tilt"]
    index = {f"{r['segment']} node {r['node']}": k for k, r in enumerate(rows)}
    problem.set_initial("wing_tilt", np.array([[tilt[index[lab]] for lab in var.labels]]))
    problem.set_initial("body_angle", (body + wma - tilt).reshape(1, -1))


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
start_names = {v["name"] for v in read_solution(Path(args.start))["variables"]}
if args.tilt == "control" and "wing_tilt" not in start_names:
    continuous_tilt_start(problem, Path(args.start).parent)   # a fixed-tilt start
# the monotone barrier from a converged point, as committed (problems/ttw.py's own adaptive start is
# for its prescribed optimization from its baseline, 2026-12-06 fifteenth session)
problem.ipopt_options.update(FROM_BASELINE_OPTIONS)
problem.divergence_watch = DivergenceWatch()
sol = solve_into(problem, args.out, verbose=True, max_iter=400)
print(sol.status, sol.iterations, sol.objective, flush=True)
