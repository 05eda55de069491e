from mdo.nlp.run import load_problem_file, solve_into
p = load_problem_file("problems/ttw.py", analysis=False, options={})
p.warm_start("/work/runs/ttw_pco/monotone/solution.json", multipliers=False)
p.ipopt_options.update({"mu_strategy": "monotone", "mu_init": 1e-5, "bound_push": 1e-8, "bound_frac": 1e-8})
sol = solve_into(p, "/work/runs/ttw_finish", verbose=False, max_iter=120)
print(sol.status, sol.iterations, sol.objective, flush=True)
