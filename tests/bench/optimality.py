"""Is it a true optimum?  (issue 10, item 5)

    python tests/bench/optimality.py ga2p [--solution results/ga2p/solution.json] [--step 0.05]

Reads IPOPT's first-order optimality at the solution from the run's ipopt.log,
then freezes the optimized design, perturbs each design variable (each element of
a vector) by +-step of its value (of its scale where the value is ~0) and re-solves
the mission for each.  A true optimum never gets lower energy from a perturbation
that stays inside the bounds and the design constraints; a perturbation past an
active bound may (that is what "active" means) and is reported as such.
Writes results/<problem>/optimality.md.  Not collected by pytest.
"""
from __future__ import annotations

import argparse
import json
import re
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.nlp.run import _import_file  # noqa: E402


def ipopt_optimality(log: Path) -> dict:
    text = log.read_text(errors="replace")
    out = {}
    for key in ("Dual infeasibility", "Constraint violation", "Complementarity", "Overall NLP error"):
        m = re.findall(rf"{key}\.*:\s+(\S+)\s+(\S+)", text)
        if m:
            out[key] = float(m[-1][1])
    m = re.findall(r"EXIT: (.*)", text)
    out["exit"] = m[-1].strip() if m else "?"
    return out


def summary_line(n, lower, infeasible) -> str:
    """The verdict: feasible perturbations that lowered the energy, and the ones whose
    frozen mission could not be flown (their energy is that of the last iterate)."""
    out = []
    if lower:
        out.append(f"**{len(lower)} feasible perturbation(s) inside the bounds lowered the energy** (by at "
                   f"most {-min(r[5] for r in lower):.4f} kWh).")
    else:
        out.append(f"No feasible perturbation inside the bounds lowered the energy ({n} perturbations).")
    if infeasible:
        out.append(f"{len(infeasible)} perturbation(s) inside the bounds made the frozen mission infeasible "
                   f"({', '.join(sorted({r[0] for r in infeasible}))}): the design sits on an implicit "
                   "constraint of the mission (see the report of a failed solve for where); their energies "
                   "are last iterates, not mission energies.")
    return " ".join(out)


def solve_frozen(module, solution_json, changes):
    p = module.build(analysis=True)
    p.warm_start(solution_json)
    for name, value in changes.items():
        p.set_initial(name, value)
    p.freeze_design()
    sol = p.solve(verbose=False)
    return sol


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("problem")
    ap.add_argument("--solution", default=None)
    ap.add_argument("--step", type=float, default=0.05)
    args = ap.parse_args()
    run = ROOT / "results" / args.problem
    sol_path = Path(args.solution) if args.solution else run / "solution.json"
    data = json.loads(sol_path.read_text())
    module = _import_file(ROOT / "problems" / f"{args.problem}.py")
    opt = ipopt_optimality(sol_path.parent / "ipopt.log")
    t0 = time.perf_counter()
    ref = solve_frozen(module, sol_path, {})
    E0 = ref.summary_values()["battery_energy_kWh"]
    probe = module.build(analysis=True)
    rows = []
    for v in data["variables"]:
        if not v["design"]:
            continue
        var = probe.variables[v["name"]]
        val = np.asarray(v["value"], float).reshape(var.shape)
        for i in range(val.size):
            for sgn in (+1, -1):
                new = val.copy()
                x = new.flat[i]
                dx = args.step * (abs(x) if abs(x) > 1e-3 else float(var.scale.flat[i]))
                new.flat[i] = x + sgn * dx
                lo, hi = var.lower.flat[i], var.upper.flat[i]
                outside = new.flat[i] < lo - 1e-12 or new.flat[i] > hi + 1e-12
                fixed = lo == hi
                if fixed:
                    continue
                s = solve_frozen(module, sol_path, {v["name"]: new})
                E = s.summary_values().get("battery_energy_kWh", float("nan"))
                rows.append((v["name"] + (f"[{i}]" if val.size > 1 else ""), x, new.flat[i], s.status, E,
                             E - E0, outside))
                print(f"{rows[-1][0]:32s} {x:10.4g} -> {new.flat[i]:10.4g}  {s.status:24s} {E:9.4f} kWh "
                      f"({E - E0:+.4f}){'  past a bound' if outside else ''}", flush=True)
    solved = ("Solve_Succeeded", "Feasible_Point_Found", "Solved_To_Acceptable_Level")
    lower = [r for r in rows if r[3] in solved and r[5] < -1e-6 and not r[6]]
    infeasible = [r for r in rows if r[3] not in solved and not r[6]]
    lines = [f"# {args.problem}: optimality check", "",
             f"IPOPT at the solution ({sol_path}): {opt.get('exit')}; dual infeasibility "
             f"{opt.get('Dual infeasibility', float('nan')):.2e}, constraint violation "
             f"{opt.get('Constraint violation', float('nan')):.2e}, complementarity "
             f"{opt.get('Complementarity', float('nan')):.2e}.", "",
             f"Mission re-solved with the optimized design frozen: {E0:.4f} kWh ({ref.status}).",
             f"Each design variable perturbed by +-{100 * args.step:g} % of its value (of its scale near 0), "
             f"mission re-solved ({len(rows)} solves, {time.perf_counter() - t0:.0f} s):", "",
             "| variable | optimum | perturbed | status | energy (kWh) | change (kWh) | note |",
             "|---|---:|---:|---|---:|---:|---|"]
    for r in rows:
        lines.append(f"| {r[0]} | {r[1]:.5g} | {r[2]:.5g} | {r[3]} | {r[4]:.4f} | {r[5]:+.4f} | "
                     f"{'past an active bound' if r[6] else ''} |")
    lines += ["", summary_line(len(rows), lower, infeasible)]
    (run / "optimality.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines[-1:]))


if __name__ == "__main__":
    main()
