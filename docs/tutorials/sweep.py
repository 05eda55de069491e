"""Tutorial 5: run a sweep — the same problem at several option values.

    python docs/tutorials/sweep.py [OUT_DIR]

Battery energy of the fixed-polar GA airplane (``problems/polar_ga_mission.py``)
against the cruise distance: one run folder per point, each warm-started from the
previous point's ``solution.json`` (the solution of a neighbouring problem is a good
initial guess).  The energy grows linearly with distance once the climb and descent
are paid; the slope is the cruise energy per nautical mile.
"""
import sys
from pathlib import Path

import numpy as np

from mdo.nlp import load_problem_file, run_problem

REPO = Path(__file__).resolve().parents[2]
out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("tutorial_runs") / "sweep"
distances_nmi = [30.0, 50.0, 70.0]
energy = []
previous = None
for d in distances_nmi:
    problem = load_problem_file(REPO / "problems" / "polar_ga_mission.py", options={"cruise_distance_nmi": d})
    if previous is not None:
        problem.warm_start(previous / "solution.json")
    run = out / f"cruise_{d:g}nmi"
    sol = run_problem(problem, run, force=True, verbose=False)
    energy.append(sol.objective)
    previous = run
    print(f"cruise {d:5.1f} nmi: {sol.status}, {sol.objective:.3f} kWh, {sol.iterations} iterations")
slope = np.polyfit(distances_nmi, energy, 1)[0]
print(f"cruise energy {slope:.4f} kWh per nmi")
