"""The ``mdo`` command.

``mdo run PROBLEM.py`` solves a problem file; the disciplines add their own
sub-commands (``mdo rotor ...``, ``mdo wing ...``, ``mdo battery ...``) through a
``register(subparsers)`` function in their ``cli`` module, listed in
``_DISCIPLINE_CLIS``.

Exit codes: 0 success, 1 a solve that did not converge (report printed, log and
last iterate kept), 2 bad input (one line naming the field; ``--debug`` for the
traceback).
"""
from __future__ import annotations

import argparse
import importlib
import json
import sys
import traceback
from pathlib import Path

from .core.errors import InputError

_DISCIPLINE_CLIS = (
    "mdo.airfoil.cli",
    "mdo.rotor.cli",
    "mdo.wing.cli",
    "mdo.wake.cli",
    "mdo.powertrain.cli",
    "mdo.plots.cli",
    "mdo.sweep.cli",
)


def _parse_option(text: str):
    if "=" not in text:
        raise InputError("--option", f"expected KEY=VALUE, got {text!r}")
    key, value = text.split("=", 1)
    try:
        value = json.loads(value)
    except json.JSONDecodeError:
        pass
    return key.strip(), value


def _cmd_run(args) -> int:
    from .nlp.run import check_out_dir, default_out_dir, load_problem_file

    if args.max_iter is not None and args.max_iter < 0:
        raise InputError("--max-iter", f"must be >= 0, got {args.max_iter}")
    options = dict(_parse_option(o) for o in (args.option or []))
    out = Path(args.out or default_out_dir(args.problem, analysis=args.analysis))
    check_out_dir(out, args.force)  # refuse before spending time on the build
    problem = load_problem_file(args.problem, analysis=args.analysis, options=options)
    warm_start = args.warm_start
    # DESIGN rule 7, continuation: an optimization with design variables first flies the
    # baseline (design frozen) and starts from that converged mission
    staged = (not args.analysis and warm_start is None and not args.no_baseline
              and any(v.design and not v.frozen for v in problem.variables.values()))
    if staged:
        base_out = out / "analysis"
        check_out_dir(base_out, args.force)
        baseline = load_problem_file(args.problem, analysis=True, options=options)
        code, _ = _solve_stage(baseline, base_out, args, None, "stage 1 of 2: baseline analysis, design frozen")
        del baseline
        if code != 0:
            print(f"mdo: the baseline analysis did not converge, so the optimization was not started; "
                  f"fix the baseline or pass --no-baseline", file=sys.stderr)
            return code
        warm_start = base_out / "solution.json"
    what = "analysis, design frozen" if args.analysis else "optimization"
    if staged:
        what = f"stage 2 of 2: {what}, from the baseline"
    code, _ = _solve_stage(problem, out, args, warm_start, what)
    return code


def _solve_stage(problem, out, args, warm_start, what) -> tuple:
    from .nlp.run import run_problem

    size = problem.size()
    print(f"mdo: {problem.name} ({what}): {size['variables']} variables, {size['constraints']} constraints -> {out}")
    sol = run_problem(problem, out, force=args.force, max_iter=args.max_iter,
                      warm_start=warm_start, verbose=not args.quiet,
                      solve_options={"hessian": args.hessian})
    print(f"\nmdo: {problem.name}: {sol.status} after {sol.iterations} iterations, "
          f"{sol.wall_time_s:.1f} s; {sol.objective_name} = {sol.objective:.6g} {sol.objective_unit}")
    for k, v in sol.summary_values().items():
        print(f"  {k} = {v}")
    print(f"  results in {out}")
    if sol.status == "Interrupted_By_User":
        print(f"mdo: interrupted; log and last iterate kept in {out}", file=sys.stderr)
        print(sol.violation_report(), file=sys.stderr)
        return 130, sol
    if not sol.success:
        print(f"mdo: solve did not converge ({sol.status}); log and last iterate kept in {out}",
              file=sys.stderr)
        print(sol.violation_report(), file=sys.stderr)
        return 1, sol
    return 0, sol


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="mdo", description="Whole-mission design optimization of propeller-driven aircraft.")
    parser.add_argument("--debug", action="store_true", help="show tracebacks on errors")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    run = sub.add_parser("run", help="solve a problem file (build(**options) -> Problem)",
                         description="Solve a problem file and write its run folder.")
    run.add_argument("problem", help="path to a problem file, e.g. problems/ga2p.py")
    run.add_argument("--out", help="run folder (default results/<problem>/, or .../analysis/)")
    run.add_argument("--max-iter", type=int, help="IPOPT iteration limit")
    run.add_argument("--warm-start", metavar="FILE", help="solution.json of an earlier run")
    run.add_argument("--no-baseline", action="store_true",
                     help="optimize straight from the problem's initial guess (default for a problem with "
                          "design variables: first solve the baseline analysis into OUT/analysis, then "
                          "warm-start the optimization from it)")
    run.add_argument("--analysis", action="store_true",
                     help="freeze the design variables at their initial values; solve the mission only")
    run.add_argument("--force", action="store_true", help="replace an existing run folder")
    run.add_argument("--option", "-o", action="append", metavar="KEY=VALUE",
                     help="keyword passed to build(); VALUE parsed as JSON when it can be")
    run.add_argument("--quiet", action="store_true", help="no IPOPT log on the terminal (still in the file)")
    run.add_argument("--hessian", choices=("exact", "limited-memory"), default="exact",
                     help="exact Hessian of the Lagrangian (default) or IPOPT's L-BFGS approximation")
    run.set_defaults(func=_cmd_run)

    for modname in _DISCIPLINE_CLIS:
        try:
            mod = importlib.import_module(modname)
        except ModuleNotFoundError as exc:
            if exc.name and modname.startswith(exc.name):
                continue  # discipline not present in this checkout
            raise
        mod.register(sub)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    from .nlp.run import RunError
    try:
        return int(args.func(args) or 0)
    except (InputError, RunError, FileNotFoundError) as exc:
        if args.debug:
            traceback.print_exc()
        print(f"mdo: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("mdo: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
