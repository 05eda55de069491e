"""How results/ttw/ (the trimmed optimum) was made (2026-12-03), from the repository root:

    python results/ttw/finish_optimization.py OUT_DIR results/ttw/analysis

The optimization from the trimmed baseline with IPOPT's adaptive barrier (what `mdo run`
falls back to; its first choice, the monotone barrier from the baseline, neared an optimum
at 114.8 kWh by iteration 92 and then left it when mu fell from 1e-3 to 3e-5, wandering
at a primal infeasibility of 0.1-0.16 for 70 iterations; stopped by hand at 167):
"Optimal Solution Found" after 171 iterations, 1773 s with two other solves on the 2 cores.
The baseline folder is copied into OUT_DIR/analysis.
"""
import json
import shutil
import sys
from pathlib import Path

from mdo.nlp.run import load_problem_file, load_warm_start, solve_into

out, base = sys.argv[1], sys.argv[2]
p = load_problem_file("problems/ttw.py", analysis=False, options={})
load_warm_start(p, json.loads((Path(base) / "solution.json").read_text()))
p.ipopt_options.update({"mu_strategy": "adaptive"})
sol = solve_into(p, out, verbose=True, max_iter=400)
shutil.copytree(base, Path(out) / "analysis")
print(sol.status, sol.iterations, sol.objective, flush=True)
