"""How results/ttw/untrimmed/analysis/ was made (2026-12-03, main 46fab24, before pitch trim existed;
with today's code the option trim=False below reproduces that model), from the repository root:

    python results/ttw/untrimmed/analysis/finish_baseline.py OUT_DIR

The TTW baseline analysis (Table 3's design frozen, every limit on) started from the last
iterate of the unconverged attempt of 2026-12-02 (results/ttw/drag_pmsm_attempt/, feasible,
dual infeasibility noisy between 1e-3 and 4 under the adaptive barrier), without its
multipliers, with the monotone barrier held from mu = 1e-5 and the bounds pushed in by
1e-8 only (as results/ttw/acceptable/finish.py): converged ("Optimal Solution Found",
tol 1e-4) in 18 iterations.  `mdo run problems/ttw.py --analysis` from scratch does not
converge (results/ttw/README.md).
"""
import sys

from mdo.nlp.run import load_problem_file, solve_into

p = load_problem_file("problems/ttw.py", analysis=True, options={"trim": False})
p.warm_start("results/ttw/drag_pmsm_attempt/solution.json", multipliers=False)
p.ipopt_options.update({"mu_strategy": "monotone", "mu_init": 1e-5, "bound_push": 1e-8, "bound_frac": 1e-8})
sol = solve_into(p, sys.argv[1], verbose=True, max_iter=100)
print(sol.status, sol.iterations, sol.objective, flush=True)
