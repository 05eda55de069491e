"""Tutorial 1: run a paper aircraft and open its report.

    python docs/tutorials/run_paper_aircraft.py [PROBLEM.py] [OUT_DIR]

The paper's aircraft are problem files: ``problems/ga2p.py`` (GA-2P, about a minute
on 2 cores), ``problems/ga8p.py``, ``problems/ttw.py``.  The command line does the
same as this script: ``mdo run problems/ga2p.py --out results/my_ga2p``.  The test
suite runs this tutorial with the fast fixed-polar airplane
``problems/polar_ga_mission.py`` (the GA profile of Table 5, well under a minute).
"""
import sys
from pathlib import Path

from mdo.nlp import load_problem_file, run_problem

REPO = Path(__file__).resolve().parents[2]
problem_file = Path(sys.argv[1]) if len(sys.argv) > 1 else REPO / "problems" / "ga2p.py"
out = Path(sys.argv[2]) if len(sys.argv) > 2 else Path("tutorial_runs") / problem_file.stem

problem = load_problem_file(problem_file)                 # calls the file's build(**options)
solution = run_problem(problem, out, force=True, verbose=False)   # solve, write the run folder
print(f"{solution.problem_name}: {solution.status}, {solution.objective_name} = "
      f"{solution.objective:.3f} {solution.objective_unit} after {solution.iterations} iterations")
for name in ("summary.md", "mission.csv", "convergence.csv", "report.html"):
    print(f"  {out / name}: {'written' if (out / name).exists() else 'missing'}")
print(f"open {out / 'report.html'} in a browser; `mdo plot {out} --units aviation` redraws the figures")
