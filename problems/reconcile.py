"""Term-by-term reconciliation of our baselines with the paper's (issue 17 item 7).

    python problems/reconcile.py [ga2p ga8p ttw] [--steps 0,1,s] [--table]

Flies each aircraft's baseline (``mdo run problems/<p>.py --analysis``: Table 3's
initial design frozen, the motors sized) with our models, then undoes one of our modelling
choices at a time, cumulatively, towards the assumptions of the paper's SUAVE model:
the DC motor behind a flat 0.95 ESC, the free-transition XFOIL section polars, the old
parasite-drag allowances (5 % leakage, nacelles and the wing's blown strips at the freestream's dynamic
pressure, no cooling drag), no
operating limits with the swirl credit unbounded and no approach drag device, and a fixed
gross weight; the TTW also flies Table 5's tilt and collective schedules, as the paper did, once the limits
are off.  Each step
is a run folder (pruned to its summary, energy breakdown and
mission table) under ``results/reconciliation/<p>/``; the table with each step's energy,
its change and the cruise figures is written to ``results/table3_reconciliation.md``.
Not a problem file (no ``build``): a study over ``mdo run`` commands.
"""
from __future__ import annotations

import csv
import json
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "results" / "reconciliation"
KEEP = {"summary.json", "summary.md", "energy.md", "mission.csv", "mission_segments.csv"}

# (folder, what is undone at this step, the -o options of the step, cumulative)
STEPS = [
    ("0_ours", "ours: tripped sections, drag build-up, PMSM + inverter, every limit", {}),
    ("1_dc_motor", "the paper's DC motor behind a 0.95 ESC", {"motor_model": "dc"}),
    ("2_free_transition", "free-transition polars (wing, tail, propeller; XFOIL's, NeuralFoil's at Ncrit 9 for the "
                          "propeller's 18, 8 and 6 % sections)", {"sections": "free_transition"}),
    ("3_old_allowances", "5 % leakage, nacelles and wing strips at the freestream's q, no cooling drag",
     {"leakage_fraction": 0.05, "nacelle_slipstream": False, "blown_profile_drag": False, "cooling_drag": False}),
    ("4_no_limits", "no operating limits, unbounded swirl credit, no approach drag device",
     {"limits": False, "swirl_recovery": "unbounded", "approach_drag_area_m2": 0.0}),
    ("5_fixed_weight", "gross weight fixed at the initial design's build-up (the motors no longer add their "
                       "sized mass)", {"mass_model": "fixed"}),
]
# one-at-a-time from ours (not cumulative): the energy's sensitivity to a calibration
SENSITIVITY = [("s_calibration_1.16", "mass calibration 1.16 (the paper's Table 1 level, the catalog's until "
                                     "2026-12-06) instead of the raw regressions",
                {"airframe_calibration": 1.16}, "airframe_calibration"),
               ("s_leakage_0.1", "Raymer's 10 % leakage allowance instead of the P2006T calibration to its flight "
                                 "manual (catalog.P2006T_LEAKAGE_FRACTION)",
                {"leakage_fraction": 0.1}, "leakage_fraction")]
PAPER_BASELINE_KWH = {"ga2p": 61.01, "ga8p": 40.51, "ttw": 114.77}     # Clarke et al., Table 3
NAMES = {"ga2p": "GA-2P", "ga8p": "GA-8P", "ttw": "TTW"}

# The TTW flies Table 5's schedules in the paper: a step undoes our tilt and collective controls (and with
# them the cabin's envelope and pitch-rate limit, which a scheduled tilt-wing cannot meet).  It comes after the
# limits are off: with every limit on, Table 5's collective schedule on the baseline's hover-designed blade did
# not converge (the schedules' second relaxed step ran to a dual infeasibility of 8e18 in 60 iterations,
# stopped; 2026-12-07, twenty-third session)
TTW_SCHEDULES = ("schedules", "Table 5's tilt and collective-pitch schedules (the cabin then pitches within the "
                 "eVTOL profile's -60/+85 deg, no pitch-rate limit)", {"pitch": "schedule", "tilt": "schedule"})
# its mass calibration (Table 1's TTW gross weight) is the one a sensitivity is asked for; its leakage
# allowance is Raymer's 10 % already
TTW_SENSITIVITY = [("s_calibration_0.8", "mass calibration 0.8 instead of the catalog's calibration to Table 1's "
                                        "gross weight", {"airframe_calibration": 0.8}, "airframe_calibration"),
                   ("s_calibration_1.0", "the raw mass regressions (calibration 1.0) instead of the catalog's "
                                        "calibration to Table 1's gross weight", {"airframe_calibration": 1.0},
                    "airframe_calibration")]
# a sensitivity that did not converge, as measured (its folder keeps the log)
SENSITIVITY_FAILED = {("ttw", "s_calibration_1.0"):
                      "did not converge: IPOPT's 500 iterations ran out at 194.5 kWh with TOGW 3403 kg (18 % above "
                      "the baseline's), the rotors' lifted loads at AT node 2 and the mass build-up still violated by "
                      "up to 5 % (scaled; 2026-12-07, twenty-third session)"}


def steps_of(problem) -> list:
    """The cumulative steps of ``problem`` (folder, what is undone, -o options): STEPS, with the TTW's
    schedules once the limits are off (folders renumbered)."""
    if problem != "ttw":
        return STEPS
    k = next(i for i, (f, _, o) in enumerate(STEPS) if o.get("limits") is False) + 1
    rest = STEPS[:k] + [TTW_SCHEDULES] + STEPS[k:]
    return [rest[0]] + [(f"{i}_{f.split('_', 1)[1] if f[0].isdigit() else f}", w, o)
                        for i, (f, w, o) in enumerate(rest) if i > 0]


STEP_NOTES = {"ttw": "The TTW's steps with its controls start from the committed baseline's solution "
                     "(`WARM_START`); the steps on Table 5's schedules from the problem's own guess, through its "
                     "relaxed continuation (started from the controls-flown baseline, the schedules' step was still "
                     "in IPOPT's restoration phase after 166 iterations, stopped).  Table 5's "
                     "schedules come once the limits are off: with every limit on, its collective schedule on the "
                     "baseline's hover-designed blade did not converge (the cold start's second relaxed step ran to "
                     "a dual infeasibility of 8e18).  On that blade the schedule's +20 deg cruise collective is what "
                     "the cruise propulsive efficiency column shows; the paper's 114.77 kWh is no step's."}

# Where a problem's step starts: its committed baseline's solution (the variables it shares; the TTW's cold
# start, a continuation of three solves, wandered for the mass calibration's sensitivity: its second relaxed step
# was at iteration 154 with a primal infeasibility of 9.5 after 6 minutes, stopped; 2026-12-07).  None: the
# problem's own initial guess.
WARM_START = {"ttw": ROOT / "results" / "ttw" / "analysis" / "solution.json"}


def sensitivities_of(problem) -> list:
    return TTW_SENSITIVITY if problem == "ttw" else SENSITIVITY


def _accepted(problem, opts: dict) -> dict:
    """The options ``problems/<problem>.py`` takes (its OPTIONS): a step's option the problem does not have
    (the GA's approach drag device on the TTW) is left out, there being nothing to undo."""
    from mdo.nlp.run import problem_module
    known = getattr(problem_module(ROOT / "problems" / f"{problem}.py"), "OPTIONS", {})
    return {k: v for k, v in opts.items() if k in known}


def _opts(problem, step_index):
    merged = {}
    for _, _, o in steps_of(problem)[:step_index + 1]:
        merged.update(o)
    out = []
    for k, v in _accepted(problem, merged).items():
        out += ["-o", f"{k}={str(v).lower() if isinstance(v, bool) else v}"]
    return out


def _solve(problem, dest: Path, options: list, warm=None) -> None:
    """``mdo run problems/<problem>.py --analysis`` into ``dest`` with the -o ``options``.  A converged
    folder is pruned to ``KEEP``; one that did not converge keeps every file (its logs name the cause)
    and the command's last output is printed."""
    start = [] if warm is None else ["--warm-start", str(warm.relative_to(ROOT)), "--warm-start-partial"]
    cmd = [sys.executable, "-m", "mdo.cli", "run", f"problems/{problem}.py", "--analysis", "--quiet",
           "--out", str(dest), "--force", *start, *options]
    print(" ".join(cmd[2:]), flush=True)
    r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    summary = dest / "summary.json"
    ok = r.returncode == 0 and summary.exists() and json.loads(summary.read_text()).get("success", False)
    if not ok:
        print(f"{dest.name}: exit {r.returncode}\n{(r.stdout + r.stderr)[-3000:]}", file=sys.stderr, flush=True)
    elif dest.exists():
        for f in dest.iterdir():
            if f.name not in KEEP:
                shutil.rmtree(f) if f.is_dir() else f.unlink()
    dest.mkdir(parents=True, exist_ok=True)
    (dest / "command.txt").write_text("mdo " + " ".join(cmd[3:]) + "\n")


def run(problem, only=None):
    """Solve the steps (indices ``only``, default all) and the sensitivities (with ``only`` None or
    containing "s") of ``problem``."""
    schedules = TTW_SCHEDULES[2].items()
    for i, (folder, _, _) in enumerate(steps_of(problem)):
        if only is None or str(i) in only:
            merged = {k: v for _, _, o in steps_of(problem)[:i + 1] for k, v in o.items()}
            # the schedules' steps start from the problem's guess (STEP_NOTES)
            warm = None if any(merged.get(k) == v for k, v in schedules) else WARM_START.get(problem)
            _solve(problem, OUT / problem / folder, _opts(problem, i), warm)
    if only is not None and "s" not in only:
        return
    for folder, _, opts, _ in sensitivities_of(problem):
        _solve(problem, OUT / problem / folder, [x for k, v in opts.items() for x in ("-o", f"{k}={v}")],
               WARM_START.get(problem))


def _cruise(folder):
    rows = [r for r in csv.DictReader((folder / "mission.csv").open()) if r["segment"] == "CR"]
    mean = lambda k: sum(float(r[k]) for r in rows) / len(rows)  # noqa: E731
    drive = next(k for k in rows[0] if k.endswith(".drive_efficiency"))   # the (first) rotor group's
    return {"CDp": mean("CDp"), "LD": mean("CL") / mean("CD"), "eta_p": mean("propulsive_efficiency"),
            "eta_d": mean(drive)}


def table(problems):
    lines = ["# Reconciliation of the baselines with the paper's assumptions (issue 17 item 7)", "",
             "`python problems/reconcile.py`: each aircraft's baseline analysis (Table 3's initial design "
             "frozen, the motors sized with the mission), then one of our modelling choices undone at a time, "
             "cumulatively (the options of each step are in its folder's `command.txt`).  Cruise figures "
             "are the means over the CR nodes.", ""]
    for p in problems:
        lines += [f"## {NAMES[p]} (paper's baseline: {PAPER_BASELINE_KWH[p]:.2f} kWh)", "",
                  "| step | undone | status | energy (kWh) | change (kWh) | TOGW (kg) | cruise CD0 | cruise L/D "
                  "| cruise prop. eff. | cruise motor + inverter/ESC eff. |",
                  "|---|---|---|---:|---:|---:|---:|---:|---:|---:|"]
        prev = None
        for folder, what, _ in steps_of(p):
            d = OUT / p / folder
            s = json.loads((d / "summary.json").read_text())
            e = s["objective"]["value"]
            c = _cruise(d)
            change = "" if prev is None else f"{e - prev:+.2f}"
            lines.append(f"| {folder} | {what} | {s['status']} | {e:.2f} | {change} | {s.get('togw_kg', 0):.0f} "
                         f"| {c['CDp']:.4f} | {c['LD']:.1f} | {c['eta_p']:.3f} | {c['eta_d']:.3f} |")
            prev = e
        base = json.loads((OUT / p / STEPS[0][0] / "summary.json").read_text())["objective"]["value"]
        for folder, what, opts, key in sensitivities_of(p):
            path = OUT / p / folder / "summary.json"
            s = json.loads(path.read_text()) if path.exists() else {"success": False}
            if not s.get("success"):
                lines += ["", f"Sensitivity ({folder}): {what}: {SENSITIVITY_FAILED.get((p, folder), 'did not converge')}."]
                continue
            e = s["objective"]["value"]
            ours = _catalog_value(p, key)
            slope = (base - e) / (ours - opts[key])
            lines += ["", f"Sensitivity ({folder}): {what}: {e:.2f} kWh ({s['status']}, TOGW "
                          f"{s.get('togw_kg', 0):.0f} kg) against {base:.2f} with {key} = {ours:g}, i.e. "
                          f"dE/d({key}) = {slope:.1f} kWh per unit."]
        lines += ["", STEP_NOTES[p]] if p in STEP_NOTES else []
        lines.append("")
    if {"ga2p", "ga8p"} <= set(problems):
        e = {p: [json.loads((OUT / p / f / "summary.json").read_text())["objective"]["value"] for f, _, _ in STEPS]
             for p in ("ga2p", "ga8p")}
        paper = PAPER_BASELINE_KWH["ga8p"] / PAPER_BASELINE_KWH["ga2p"]
        lines += ["## GA-8P / GA-2P baseline energy", "", "| step | ours | paper |", "|---|---:|---:|"]
        lines += [f"| {f} | {a / b:.3f} | {paper:.3f} |" for (f, _, _), a, b in zip(STEPS, e["ga8p"], e["ga2p"])]
        eta = {p: [_cruise(OUT / p / f)["eta_p"] for f, _, _ in STEPS] for p in ("ga2p", "ga8p")}
        lines += ["", f"No step brings the ratio near the paper's {paper:.3f}: with every model choice undone our "
                  f"GA-8P still needs more energy than GA-2P (its propellers' cruise efficiency is "
                  f"{min(eta['ga8p']):.2f}-{max(eta['ga8p']):.2f} against {min(eta['ga2p']):.2f}-"
                  f"{max(eta['ga2p']):.2f}; see the GA-8P propeller discussion in results/table3.md).", ""]
    if {"ga2p", "ttw"} <= set(problems):
        lines += _ttw_ratio_lines()
    lines += ["What no step undoes: the nacelle interference factor (1.5 now, 1.3 before; Raymer's value for a "
              "nacelle on the wing), the packaged battery (cells x 1.42; the paper's Table 1 gross weight, 3549 "
              "lb for GA-2P, cannot carry it), our 50 nmi + 5 nmi cruise distances (the paper gives none), the "
              "mission's Table 5 segments as we read them, and the models themselves (BEMT with our sections, "
              "vortex lattice with the averaged helical wake, the NMC cell fit).  Each remaining difference to "
              "the paper's figure is the sum of these, which its text does not let us separate.", ""]
    (ROOT / "results" / "table3_reconciliation.md").write_text("\n".join(lines))


def _energy(problem, folder) -> float:
    return json.loads((OUT / problem / folder / "summary.json").read_text())["objective"]["value"]


def _ttw_ratio_lines() -> list:
    """The TTW / GA-2P baseline energy at each TTW step, beside the paper's: each TTW step against the
    GA-2P step that undoes the same choice (the schedules, which the GA-2P does not fly, against its
    own models)."""
    ga = {f.split("_", 1)[1]: f for f, _, _ in STEPS}
    paper = PAPER_BASELINE_KWH["ttw"] / PAPER_BASELINE_KWH["ga2p"]
    lines = ["## TTW / GA-2P baseline energy", "", "| TTW step | GA-2P step | TTW (kWh) | GA-2P (kWh) | ours | paper |",
             "|---|---|---:|---:|---:|---:|"]
    last = STEPS[0][0]
    for f, _, _ in steps_of("ttw"):
        last = ga.get(f.split("_", 1)[1], last)
        a, b = _energy("ttw", f), _energy("ga2p", last)
        lines.append(f"| {f} | {last} | {a:.2f} | {b:.2f} | {a / b:.3f} | {paper:.3f} |")
    return lines + [""]


def _catalog_value(problem, key):
    """The catalog's value of a calibration the SENSITIVITY list varies (an -o option's name)."""
    from mdo.vehicle.catalog import VEHICLES
    where = {"airframe_calibration": lambda cfg: cfg.mass_inputs["airframe_calibration"],
             "leakage_fraction": lambda cfg: cfg.drag.leakage_protuberance_fraction}
    return float(where[key](VEHICLES[problem]()))


def main(argv) -> None:
    """``[PROBLEM ...] [--steps 0,1,s] [--table]``: solve (the given steps of) each problem, then write
    the table of every problem named (``--table``: the table only, from the folders there are)."""
    args = list(argv)
    only = None
    if "--steps" in args:
        k = args.index("--steps")
        only = set(args[k + 1].split(","))
        del args[k:k + 2]
    table_only = "--table" in args
    problems = [a for a in args if a != "--table"] or ["ga2p", "ga8p", "ttw"]
    if not table_only:
        for p in problems:
            run(p, only)
    table(problems)


if __name__ == "__main__":
    main(sys.argv[1:])
