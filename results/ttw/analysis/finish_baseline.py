"""How results/ttw/analysis/ (the trimmed baseline) was made (2026-12-03), from the repository root:

    python results/ttw/analysis/finish_baseline.py OUT_DIR

The TTW baseline with pitch trim in its wing-borne segments (mdo/vehicle/balance.py; the CG
frozen at a 10 % static margin) started from the converged untrimmed baseline
(results/ttw/untrimmed/analysis/solution.json, every variable but the front wing's trim
incidence, which starts at 0), without multipliers, with the monotone barrier from
mu = 1e-4 and the bounds pushed in by 1e-8 only: "Optimal Solution Found" in 26
iterations, 171.53 kWh.  `mdo run problems/ttw.py --analysis` from scratch does not
converge (results/ttw/README.md).
"""
import sys

from mdo.nlp.run import load_problem_file, solve_into

p = load_problem_file("problems/ttw.py", analysis=True, options={})
print(p.warm_start("results/ttw/untrimmed/analysis/solution.json", multipliers=False, partial=True).describe())
p.ipopt_options.update({"mu_strategy": "monotone", "mu_init": 1e-4, "bound_push": 1e-8, "bound_frac": 1e-8})
sol = solve_into(p, sys.argv[1], verbose=True, max_iter=150)
print(sol.status, sol.iterations, sol.objective, flush=True)
