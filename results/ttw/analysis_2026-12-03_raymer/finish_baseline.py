"""How results/ttw/analysis/ (the trimmed baseline) was made, from the repository root:

    python results/ttw/analysis/finish_baseline.py OUT_DIR [START_SOLUTION_JSON]

The TTW baseline with pitch trim in its wing-borne segments (mdo/vehicle/balance.py; the CG
frozen at a 10 % static margin), started from a converged baseline's solution.json (default
this folder's own; a partial warm start: variables the file lacks start at their guesses or,
lifted ones, at their definitions), without multipliers, with the monotone barrier from
mu = 1e-4 and the bounds pushed in by 1e-8 only.  History: 2026-12-03 from the untrimmed
baseline (results/ttw/untrimmed/analysis/): 26 iterations, 171.53 kWh; later the same day,
after issue 20's formulation change (no blade unknowns, lifted rotor loads), from that
baseline's solution.json (main c73f935): 20 iterations, 89 s, 171.528 kWh.
`mdo run problems/ttw.py --analysis` from scratch does not converge (results/ttw/README.md).
"""
import sys

from mdo.nlp.run import load_problem_file, solve_into

p = load_problem_file("problems/ttw.py", analysis=True, options={})
start = sys.argv[2] if len(sys.argv) > 2 else "results/ttw/analysis/solution.json"
print(p.warm_start(start, multipliers=False, partial=True).describe())
p.ipopt_options.update({"mu_strategy": "monotone", "mu_init": 1e-4, "bound_push": 1e-8, "bound_frac": 1e-8})
sol = solve_into(p, sys.argv[1], verbose=True, max_iter=150)
print(sol.status, sol.iterations, sol.objective, flush=True)
