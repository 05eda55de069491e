"""The ``mdo`` command.

``mdo run PROBLEM.py`` solves a problem file; the disciplines add their own
sub-commands (``mdo rotor ...``, ``mdo wing ...``, ``mdo battery ...``) through a
``register(subparsers)`` function in their ``cli`` module, listed in
``_DISCIPLINE_CLIS``.

Exit codes: 0 success, 1 a solve that did not converge (report printed, log and
last iterate kept), 2 bad input (one line naming the field; ``--debug`` for the
traceback), 141 output pipe closed by its reader (no traceback).
``mdo --version`` prints the version; ``mdo run FILE --options`` the problem's options.
"""
from __future__ import annotations

import argparse
import importlib
import json
import os
import re
import sys
import traceback
from pathlib import Path

from .core.errors import InputError, parse_int

_DISCIPLINE_CLIS = (
    "mdo.airfoil.cli",
    "mdo.rotor.cli",
    "mdo.wing.cli",
    "mdo.wake.cli",
    "mdo.powertrain.cli",
    "mdo.plots.cli",
)


def _parse_option(text: str):
    """``KEY=VALUE`` -> (key, value), VALUE read as JSON when it is JSON (4, 2.5, true,
    "text"), else kept as text; the type and range are checked against the problem's
    ``build()`` (``mdo.nlp.options``).  NaN and Infinity, which Python's JSON reads, are
    kept as text so that a number option refuses them by name."""
    if "=" not in text:
        raise InputError("-o", f"expected KEY=VALUE, got {text!r}")
    key, value = text.split("=", 1)
    if not key.strip():
        raise InputError("-o", f"expected KEY=VALUE with a non-empty KEY, got {text!r}")
    try:
        value = json.loads(value, parse_constant=lambda c: c)
    except (json.JSONDecodeError, RecursionError):
        pass
    return key.strip(), value


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (``mdo ...: error: ...``, exit 2, like every other bad
    input) and negative numbers as values: ``--y -1:1:0.25``, ``--x -1e-3``."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        # a token starting "-<digit>" or "-.<digit>" is a value, never an option (no mdo
        # option looks like a number); argparse's own pattern knows only -1 and -1.5
        self._negative_number_matcher = re.compile(r"^-\.?\d")

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} -h)\n")


def _cmd_options(args) -> int:
    from .nlp.options import describe_options
    print(describe_options(args.problem))
    return 0


def _cmd_run(args) -> int:
    from .nlp.run import check_out_dir, default_out_dir, load_problem_file

    if args.options:
        return _cmd_options(args)
    if args.max_iter is not None:
        args.max_iter = parse_int("--max-iter", args.max_iter, 0, 100000)
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
    from . import __version__

    parser = _Parser(
        prog="mdo", description="Whole-mission design optimization of propeller-driven aircraft.")
    parser.add_argument("--debug", action="store_true", help="show tracebacks on errors")
    parser.add_argument("--version", action="version", version=f"mdo {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    run = sub.add_parser("run", help="solve a problem file (build(**options) -> Problem)",
                         description="Solve a problem file and write its run folder.")
    run.add_argument("problem", help="path to a problem file, e.g. problems/ga2p.py")
    run.add_argument("--out", help="run folder (default results/<problem>/, or .../analysis/)")
    run.add_argument("--max-iter", metavar="N", help="IPOPT iteration limit, an integer in [0, 100000]")
    run.add_argument("--warm-start", metavar="FILE", help="solution.json of an earlier run")
    run.add_argument("--no-baseline", action="store_true",
                     help="optimize straight from the problem's initial guess (default for a problem with "
                          "design variables: first solve the baseline analysis into OUT/analysis, then "
                          "warm-start the optimization from it)")
    run.add_argument("--analysis", action="store_true",
                     help="freeze the design variables at their initial values; solve the mission only")
    run.add_argument("--force", action="store_true", help="replace an existing run folder")
    run.add_argument("--option", "-o", action="append", metavar="KEY=VALUE",
                     help="keyword passed to build(); VALUE parsed as JSON when it can be, checked against "
                          "the option's type and range (list them with --options)")
    run.add_argument("--options", action="store_true",
                     help="list the problem's options (type, default, allowed values, documentation) and exit")
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
        code = int(args.func(args) or 0)
        sys.stdout.flush()   # a closed pipe shows here, not as an error at interpreter exit
        return code
    except BrokenPipeError:
        return _closed_pipe()
    except (InputError, RunError, FileNotFoundError) as exc:
        if args.debug:
            traceback.print_exc()
        print(f"mdo: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("mdo: interrupted", file=sys.stderr)
        return 130


def _closed_pipe() -> int:
    """The reader went away (``mdo airfoil list | head``): stop quietly, as ``cat`` does.
    stdout is pointed at /dev/null so that Python's final flush does not complain."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass
    return 141   # 128 + SIGPIPE, what a shell reports for a program the pipe closed on


if __name__ == "__main__":
    sys.exit(main())
