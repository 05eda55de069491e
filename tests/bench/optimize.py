"""Benchmark of the whole-mission optimizations (issues 10, 20): wall and CPU time,
IPOPT iterations, NLP size, where the time goes and peak resident memory, per problem.

    python tests/bench/optimize.py [ga2p ga8p ttw] [--repeats N]

Each repeat builds the problem, runs the baseline analysis (design frozen) and
the optimization warm-started from it with the barrier ``mdo run`` uses there
(``Problem.start_from_baseline``; before 2026-12-03 the benchmark used IPOPT's adaptive
barrier in stage 2, so its iteration counts differ from the committed runs'), as ``mdo run`` does
without its report files and figures; times are
medians over the repeats.  CPU time is ``time.process_time`` of this process (all
its threads); peak memory is ``ru_maxrss`` of this process, the high-water mark
since it started (so with several problems in one call, run one problem per
call for a per-problem figure).  Not collected by pytest.
"""
from __future__ import annotations

import argparse
import resource
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.nlp import load_problem_file  # noqa: E402


def one(problem: str):
    path = ROOT / "problems" / f"{problem}.py"
    t0, c0 = time.perf_counter(), time.process_time()
    an = load_problem_file(path, analysis=True)
    t_build_an = time.perf_counter() - t0
    sol_an = an.solve(verbose=False)
    with tempfile.TemporaryDirectory() as tmp:
        ws = Path(tmp) / "solution.json"
        sol_an.save(tmp)
        t1 = time.perf_counter()
        op = load_problem_file(path)
        t_build = time.perf_counter() - t1
        op.warm_start(ws)
        op.start_from_baseline()   # the barrier mdo run uses from a converged baseline
        sol = op.solve(verbose=False)
    tm = sol.timing
    fun = sum(tm.get(f"t_wall_nlp_{k}", 0.0) for k in ("f", "g"))
    der = sum(tm.get(f"t_wall_nlp_{k}", 0.0) for k in ("grad_f", "jac_g", "hess_l"))
    def cpu(stats):
        return sum(stats.get(f"t_proc_nlp_{k}", 0.0) for k in ("f", "g", "grad_f", "jac_g", "hess_l"))
    return {
        "total_cpu_s": time.process_time() - c0,
        "peak_rss_MB": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
        "eval_cpu_s": cpu(tm), "analysis_eval_cpu_s": cpu(sol_an.timing),
        "analysis_status": sol_an.status, "analysis_iterations": sol_an.iterations,
        "analysis_wall_s": sol_an.wall_time_s, "analysis_build_s": t_build_an,
        "status": sol.status, "iterations": sol.iterations, "solve_wall_s": sol.wall_time_s,
        "build_s": t_build, "total_wall_s": time.perf_counter() - t0,
        "energy_kWh": sol.summary_values().get("battery_energy_kWh"),
        "baseline_energy_kWh": sol_an.summary_values().get("battery_energy_kWh"),
        "function_eval_s": fun, "derivative_eval_s": der,
        "jacobian_s": tm.get("t_wall_nlp_jac_g", 0.0), "hessian_s": tm.get("t_wall_nlp_hess_l", 0.0),
        "n_hessian": tm.get("n_call_nlp_hess_l", 0), "n_jacobian": tm.get("n_call_nlp_jac_g", 0),
        "ipopt_total_s": tm.get("t_wall_total", 0.0), **{f"nlp_{k}": v for k, v in sol.nlp_size.items()},
    }


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("problems", nargs="*", default=["ga2p", "ga8p", "ttw"])
    ap.add_argument("--repeats", type=int, default=1)
    args = ap.parse_args()
    for prob in args.problems:
        runs = [one(prob) for _ in range(args.repeats)]
        med = lambda k: statistics.median(r[k] for r in runs)  # noqa: E731
        r = runs[-1]
        print(f"\n== {prob} ({args.repeats} repeat(s); medians)")
        print(f"baseline analysis: {r['analysis_status']}, {r['analysis_iterations']} iterations, "
              f"build {med('analysis_build_s'):.1f} s, solve {med('analysis_wall_s'):.1f} s, "
              f"{r['baseline_energy_kWh']:.3f} kWh")
        print(f"optimization:      {r['status']}, {r['iterations']} iterations, build {med('build_s'):.1f} s, "
              f"solve {med('solve_wall_s'):.1f} s, {r['energy_kWh']:.3f} kWh")
        print(f"total wall (both stages, builds included): {med('total_wall_s'):.1f} s; "
              f"CPU {med('total_cpu_s'):.1f} s (function and derivative evaluations "
              f"{med('analysis_eval_cpu_s'):.1f} s + {med('eval_cpu_s'):.1f} s)")
        print(f"peak resident memory: {max(r_['peak_rss_MB'] for r_ in runs):.0f} MB")
        print(f"NLP: {r['nlp_variables']} variables, {r.get('nlp_constraints_ipopt', r['nlp_constraints'])} "
              f"constraints, Jacobian nnz {r.get('nlp_jacobian_nnz')}, Hessian nnz {r.get('nlp_hessian_nnz')}")
        print(f"of the {med('solve_wall_s'):.1f} s solve: function evaluations {med('function_eval_s'):.2f} s, "
              f"derivatives {med('derivative_eval_s'):.2f} s (Jacobian {med('jacobian_s'):.2f} s over "
              f"{r['n_jacobian']} calls, Hessian {med('hessian_s'):.2f} s over {r['n_hessian']} calls), "
              f"the rest (IPOPT's linear algebra, CasADi's solver setup) "
              f"{med('solve_wall_s') - med('function_eval_s') - med('derivative_eval_s'):.2f} s")


if __name__ == "__main__":
    main()
