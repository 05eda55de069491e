"""The ``mdo`` command.

``mdo run PROBLEM.py`` solves a problem file; the disciplines add their own
sub-commands (``mdo rotor ...``, ``mdo wing ...``, ``mdo battery ...``) through a
``register(subparsers)`` function in their ``cli`` module, listed in
``_DISCIPLINE_CLIS``.

Exit codes: 0 success, 1 a solve that did not converge or whose results could not
be written (report printed, log and last iterate kept), 2 bad input or a
file-system error before the solve (one line naming the field or path; ``--debug``
for the traceback), 130 / 143 interrupted by SIGINT / SIGTERM (last iterate kept
when a solve was running).  ``mdo check RUN_DIR``: 0 within limits, 1 a limit
exceeded, 2 an unreadable folder; 141 output pipe closed by its reader (no traceback).
``mdo --version`` prints the version; ``mdo run FILE --options`` the problem's options.
"""
from __future__ import annotations

import argparse
import contextlib
import importlib
import json
import os
import re
import shutil
import signal
import sys
import time
import traceback
from pathlib import Path

from .core.errors import InputError, parse_int
from .core.signals import exit_code, interrupt_signal, raise_interrupt

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


class _Progress:
    """'mdo: [  3.2 s] building ...' lines through the silent phases (stdout, flushed);
    ``--quiet`` keeps only the one line per stage (``always=True``)."""

    def __init__(self, quiet: bool):
        self.quiet = quiet
        self.t0 = time.perf_counter()

    def __call__(self, text: str, always: bool = False):
        if always or not self.quiet:
            print(f"mdo: [{time.perf_counter() - self.t0:6.1f} s] {text}", flush=True)


def _cmd_run(args) -> int:
    """``mdo run``: check the warm-start file, take the output folder (lock, staging
    sibling, writable) before anything is built, solve the stage(s) into the staging
    folder, move it into place (see ``mdo.nlp.run.RunFolder``)."""
    from .core.parallel import threads_set_to
    from .nlp.problem import WarmStartError, read_solution
    from .nlp.run import ResultWriteError, RunError, RunFolder, default_out_dir

    if args.options:
        return _cmd_options(args)
    if args.max_iter is not None:
        args.max_iter = parse_int("--max-iter", args.max_iter, 0, 100000)
    options = dict(_parse_option(o) for o in (args.option or []))
    out = Path(args.out or default_out_dir(args.problem, analysis=args.analysis))
    ws_data = None
    if args.warm_start is not None:   # validated before anything is created
        try:
            ws_data = read_solution(args.warm_start)
        except WarmStartError as exc:
            raise RunError(f"--{exc}") from exc
    args._baseline = _read_baseline(args) if args.from_baseline is not None else None
    with contextlib.suppress(ValueError):
        signal.signal(signal.SIGTERM, raise_interrupt)   # timeout, job schedulers: as Ctrl-C, exit 143
    folder = RunFolder(out, args.force).open()
    try:
        with threads_set_to(args.threads):   # the whole run's numeric work, not only the Hessian
            return _run_stages(args, options, folder, ws_data, _Progress(args.quiet))
    except ResultWriteError:
        folder.keep_incomplete()
        raise
    except KeyboardInterrupt:
        folder.abort()
        print(f"mdo: no solve was running; {out} was not touched", file=sys.stderr)
        raise
    except BaseException:
        folder.abort()
        raise


def _read_baseline(args) -> dict:
    """``--from-baseline DIR``: the converged analysis run folder the optimization starts
    from instead of solving stage 1 (checked before anything is created)."""
    from .nlp.problem import WarmStartError, read_solution
    from .nlp.run import RunError

    for flag, on in (("--warm-start", args.warm_start is not None), ("--analysis", args.analysis),
                     ("--no-baseline", args.no_baseline)):
        if on:
            raise RunError(f"--from-baseline: not with {flag} (it starts the optimization from DIR's baseline)")
    path = Path(args.from_baseline) / "solution.json"
    try:
        data = read_solution(path)
    except WarmStartError as exc:
        raise RunError(f"--from-baseline: {exc}") from exc
    if data.get("mode") != "analysis" or not data.get("success"):
        raise RunError(f"--from-baseline: {args.from_baseline} is not a converged baseline analysis "
                       f"(mode {data.get('mode')!r}, status {data.get('status')!r}); allowed: the folder "
                       f"of a successful `mdo run --analysis` of this problem")
    return data


def _run_stages(args, options, folder, ws_data, progress) -> int:
    from .nlp.run import load_problem_file, load_warm_start

    progress(f"building {args.problem}" + (" (design frozen)" if args.analysis else ""))
    problem = load_problem_file(args.problem, analysis=args.analysis, options=options)
    progress(f"built {problem.name}: {problem.size()['variables']} variables, "
             f"{problem.size()['constraints']} constraints")
    if ws_data is not None:
        ws = load_warm_start(problem, ws_data, partial=args.warm_start_partial)
        print(f"mdo: warm start from {args.warm_start}: {ws.describe()}"
              + ("; multipliers loaded (IPOPT warm_start_init_point)" if ws.multipliers else ""))
    # DESIGN rule 7, continuation: an optimization with design variables first flies the
    # baseline (design frozen) and starts from that converged mission
    monotone = False
    staged = (not args.analysis and ws_data is None and not args.no_baseline
              and any(v.design and not v.frozen for v in problem.variables.values()))
    given = getattr(args, "_baseline", None)
    if given is not None and not staged:
        from .nlp.run import RunError
        raise RunError(f"--from-baseline: {args.problem} has no free design variables to optimize")
    if staged and given is not None:   # --from-baseline: stage 1 is the user's converged analysis (copied)
        shutil.copytree(args.from_baseline, folder.stage / "analysis")
        load_warm_start(problem, given)   # checked before anything else happens
        print(f"mdo: stage 1 of 2 taken from {args.from_baseline} (copied into analysis/): "
              f"{given['objective']['value']:.6g} {given['objective'].get('unit', '')}")
        baseline_sol = given
    elif ws_data is None and (staged or args.analysis):
        code = _relaxed_start(args, options, problem if args.analysis else None, folder, progress)
        if code is not None:
            return code
    if staged and given is None:
        progress(f"building {args.problem} (baseline: design frozen)")
        baseline = load_problem_file(args.problem, analysis=True, options=options)
        if getattr(args, "_relaxed", None) is not None:
            load_warm_start(baseline, args._relaxed, partial=True)
        what = "stage 1 of 2: baseline analysis, design frozen"
        # its figures are drawn in a child process while stage 2 builds and solves
        code, sol = _solve_stage(baseline, folder.stage / "analysis", args, what, progress, figures="background")
        del baseline
        if code != 0:
            where = folder.commit(False, sol.status)
            _final_report(sol, where, folder, code, what)
            if code == 1:
                print("mdo: the baseline analysis did not converge, so the optimization was not started; "
                      "fix the baseline or pass --no-baseline", file=sys.stderr)
            return code
        baseline_sol = sol
    what = "analysis, design frozen" if args.analysis else "optimization"
    if staged:
        code, sol = _optimize_from(problem, baseline_sol, folder, args, f"stage 2 of 2: {what}, from the baseline",
                                   progress)
    else:
        code, sol = _solve_stage(problem, folder.stage, args, what, progress)
    where = folder.commit(sol.success, sol.status)
    _final_report(sol, where, folder, code, what)
    return code


def _optimize_from(problem, baseline_sol, folder, args, what, progress) -> tuple:
    """Stage 2 from the converged baseline with DESIGN rule 7's fallback
    (``mdo.nlp.run.optimize_from_baseline``): the first barrier of ``problem.barrier_order``
    (monotone, unless the problem chose adaptive first: the TTW); if it ends without an
    optimum (not an interrupt, not an iteration limit the user set with --max-iter; the
    problem's own limit counts as a failure: GA-2P at 170 mph wanders 500 iterations with
    the monotone barrier), its files move to ``monotone/`` (or ``adaptive/``) in the stage and
    the optimization starts again from the baseline with the other barrier (GA-4P: monotone
    ends in a local infeasibility, adaptive converges)."""
    from .nlp.run import load_warm_start, optimize_from_baseline

    codes = []

    def solve(fallback):
        label = f"{what}, {problem.barrier_order[1]} barrier" if fallback else what
        code, sol = _solve_stage(problem, folder.stage, args, label, progress)
        codes.append(code)
        return sol

    def keep_failed(failed):
        first, second = problem.barrier_order
        kept = folder.stage / first
        kept.mkdir()
        for f in list(folder.stage.iterdir()):
            if f.name not in ("analysis", first, "INCOMPLETE.txt"):
                f.rename(kept / f.name)
        why = f" ({failed.stopped_because})" if failed.stopped_because else ""
        print(f"mdo: the {first} barrier ended {failed.status} after {failed.iterations} iterations{why} "
              f"(kept in {first}/); starting again from the baseline with the {second} barrier")

    sol = optimize_from_baseline(problem, lambda: load_warm_start(problem, baseline_sol), solve,
                                 on_fallback=keep_failed, iteration_limit_is_final=args.max_iter is not None)
    return codes[-1], sol


def _relaxed_start(args, options, analysis_problem, folder, progress):
    """A problem file's ``RELAXED_OPTIONS`` (e.g. ``{"limits": False}``): first solve the
    analysis with those options into ``relaxed/`` beside the analysis, then start the
    analysis from it (through the file's ``relaxed_start(run_dir, solution, options)`` if it
    has one; ``options`` are every ``build()`` option of the solve it starts, defaults included:
    the run's own, without the relaxed ones) - a continuation for a baseline that does not
    converge from the initial guess.
    A list of such dicts is a continuation in steps: each solved in turn (``relaxed/``,
    ``relaxed_2/``, ...), each started from the one before through the same hook (its
    ``options`` then the run's own with the next step's).
    Returns an exit code if a solve failed, else None (``args._relaxed`` holds the start)."""
    from .nlp.run import build_options, load_problem_file, load_warm_start, problem_module

    module = problem_module(args.problem)
    steps = getattr(module, "RELAXED_OPTIONS", None)
    args._relaxed = None
    if not steps:
        return None
    steps = [steps] if isinstance(steps, dict) else list(steps)
    if not all(isinstance(s, dict) and s for s in steps):
        raise InputError("RELAXED_OPTIONS", f"{args.problem}: a dict of build() options or a list of such "
                                            f"dicts, none empty; got {steps!r}")
    hook = getattr(module, "relaxed_start", None)
    start = None
    for i, opts in enumerate(steps):
        progress(f"building {args.problem} (relaxed start{f' {i + 1} of {len(steps)}' if len(steps) > 1 else ''}: "
                 f"{opts})")
        relaxed = load_problem_file(args.problem, analysis=True, options={**options, **opts})
        if start is not None:
            load_warm_start(relaxed, start, partial=True)
        name = "relaxed" if i == 0 else f"relaxed_{i + 1}"
        where = folder.stage / (name if args.analysis else f"analysis/{name}")
        what = f"relaxed start of the baseline ({', '.join(f'{k}={v}' for k, v in opts.items())})"
        code, sol = _solve_stage(relaxed, where, args, what, progress)
        del relaxed
        if code != 0:
            out = folder.commit(False, sol.status)
            _final_report(sol, out, folder, code, what)
            return code
        start = sol.to_dict()
        if callable(hook):
            following = {**options, **steps[i + 1]} if i + 1 < len(steps) else options
            start = hook(where, start, build_options(module, following, analysis=True))
    args._relaxed = start
    if analysis_problem is not None:
        load_warm_start(analysis_problem, start, partial=True)
    return None


def _solve_stage(problem, stage_dir, args, what, progress, figures: str = "now") -> tuple:
    """Solve one stage into ``stage_dir``; (exit code, Solution).  ``figures``: as
    ``mdo.nlp.run.solve_into``'s."""
    from .nlp.problem import INTERRUPT_STATUS
    from .nlp.run import solve_into

    size = problem.size()
    progress(f"{problem.name} ({what}): {size['variables']} variables, {size['constraints']} constraints",
             always=True)
    sol = solve_into(problem, stage_dir, max_iter=args.max_iter, verbose=not args.quiet,
                     solve_options={"hessian": args.hessian, "threads": args.threads}, progress=progress,
                     figures=figures)
    print(f"\nmdo: {problem.name}: {sol.status} after {sol.iterations} iterations, "
          f"{sol.wall_time_s:.1f} s; {sol.objective_name} = {sol.objective:.6g} {sol.objective_unit}")
    for k, v in sol.summary_values().items():
        print(f"  {k} = {v}")
    if sol.status in INTERRUPT_STATUS:
        return INTERRUPT_STATUS[sol.status][1], sol
    return (0 if sol.success else 1), sol


def _final_report(sol, where, folder, code, what):
    """Where the run went, and for a failure why (on stderr)."""
    from .nlp.problem import INTERRUPT_STATUS

    print(f"  results in {where}")
    if folder.moved_aside is not None:
        print(f"  the earlier run was moved to {folder.moved_aside}")
    if code == 0:
        return
    if where != folder.out:
        print(f"mdo: the earlier run in {folder.out} is kept; this one is in {where}", file=sys.stderr)
    if sol.status in INTERRUPT_STATUS:
        print(f"mdo: interrupted by {INTERRUPT_STATUS[sol.status][0]} during {what}; "
              f"log and last iterate kept in {where}", file=sys.stderr)
    else:
        print(f"mdo: solve did not converge ({sol.status}); log and last iterate kept in {where}",
              file=sys.stderr)
    print(sol.violation_report(), file=sys.stderr)


def _cmd_check(args) -> int:
    from .nlp.check import check_run
    return check_run(args.run_dir, tol=args.tol)


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
    run.add_argument("--warm-start", metavar="FILE",
                     help="solution.json of an earlier run of the same problem (checked: problem name, "
                          "variable names and sizes, finite values; multipliers used when it fits fully)")
    run.add_argument("--warm-start-partial", action="store_true",
                     help="accept a warm-start file that matches only some variables (the rest keep the "
                          "problem's guess)")
    run.add_argument("--from-baseline", metavar="DIR",
                     help="the run folder of a converged baseline analysis of this problem (mdo run "
                          "--analysis): copied into OUT/analysis, and the optimization starts from it as "
                          "from its own stage 1 (monotone barrier with an adaptive fallback, unless the problem chose its own barrier)")
    run.add_argument("--no-baseline", action="store_true",
                     help="optimize straight from the problem's initial guess (default for a problem with "
                          "design variables: first solve the baseline analysis into OUT/analysis, then "
                          "warm-start the optimization from it)")
    run.add_argument("--analysis", action="store_true",
                     help="freeze the design variables at their initial values; solve the mission only")
    run.add_argument("--force", action="store_true",
                     help="replace an existing run folder: once the new run is complete the old one is "
                          "moved to OUT.old-<timestamp> (never deleted, never mixed)")
    run.add_argument("--option", "-o", action="append", metavar="KEY=VALUE",
                     help="keyword passed to build(); VALUE parsed as JSON when it can be, checked against "
                          "the option's type and range (list them with --options)")
    run.add_argument("--options", action="store_true",
                     help="list the problem's options (type, default, allowed values, documentation) and exit")
    run.add_argument("--quiet", action="store_true", help="no IPOPT log on the terminal (still in the file)")
    run.add_argument("--hessian", choices=("exact", "full", "limited-memory"), default="exact",
                     help="exact Hessian of the Lagrangian, split into its node block and global rows "
                          "(default); full: the same matrix by one colouring of all variables (slower); "
                          "limited-memory: IPOPT's L-BFGS approximation")
    run.add_argument("--threads", type=int, choices=(1, 2), default=None,
                     help="threads for the exact Hessian, computed in two parts, and for the initial guess's numeric "
                          "BEMT (default: MDO_THREADS, else 2 on a machine with two or more cores); the same "
                          "numbers to the bit, less wall time")
    run.set_defaults(func=_cmd_run)

    chk = sub.add_parser("check", help="check a run folder against its limits (exit 1 if one is exceeded)",
                         description="Read RUN_DIR/solution.json and print, per constraint group and per "
                                     "variable-bound group, the worst element and its margin.")
    chk.add_argument("run_dir", help="a run folder written by mdo run")
    chk.add_argument("--tol", type=float, default=None,
                     help="allowed scaled violation (default 1e-4 = IPOPT's constr_viol_tol; a group's "
                          "scaled violation is its violation divided by the group's scale)")
    chk.set_defaults(func=_cmd_check)

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
    code = _main(argv)
    from .nlp.problem import FRAGILE
    if FRAGILE and argv is None:
        # CasADi segfaults destroying a solver that ended with Invalid_Option: every file is
        # written and closed; leave without running the destructors so the exit code stays
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(code)
    return code


def _main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    from .nlp.run import ResultWriteError, RunError
    try:
        code = int(args.func(args) or 0)
        sys.stdout.flush()   # a closed pipe shows here, not as an error at interpreter exit
        return code
    except BrokenPipeError:   # before OSError, of which it is one
        return _closed_pipe()
    except ResultWriteError as exc:   # the solve ran; its files could not be written
        if args.debug:
            traceback.print_exc()
        print(f"mdo: error: {exc} (the solve had ended: {exc.solution.status}; an earlier run in the "
              f"output folder is untouched)", file=sys.stderr)
        return 1
    except (InputError, RunError) as exc:
        if args.debug:
            traceback.print_exc()
        print(f"mdo: error: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:   # any file-system error left: one line naming the path
        if args.debug:
            traceback.print_exc()
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"mdo: error: {where}{exc.strerror or exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:
        sig, code = exit_code(interrupt_signal(exc))
        print(f"mdo: interrupted by {sig}", file=sys.stderr)
        return code


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
