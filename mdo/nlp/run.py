"""Running a problem file: load it, build, solve, write the run folder.

A problem file is a Python file with a function ``build(**options)`` that
returns a :class:`mdo.nlp.Problem`.  ``run_problem`` solves it and writes, into
the run folder (``results/<problem-file-stem>/`` by default, ``.../analysis/`` for
``--analysis``):

``ipopt.log``        the whole IPOPT log
``solution.json``    every variable: name, unit, value (and every output)
``summary.json``     status, objective with unit, iterations, wall time, NLP size,
                     the problem's summary outputs (e.g. battery_energy_kWh)
``summary.md``       the same for people, with the worst constraint violations
``convergence.csv``  objective, primal and dual infeasibility per iteration
plus whatever the problem's reports write (figures, mission.csv, ...).

An existing run folder is never overwritten unless ``force=True``.
"""
from __future__ import annotations

import importlib.util
import inspect
import sys
import traceback
from pathlib import Path

from .options import check_options
from .problem import Problem, Solution

__all__ = ["RunError", "load_problem_file", "default_out_dir", "run_problem", "RESULT_FILES"]

RESULT_FILES = ("summary.json", "solution.json", "ipopt.log")


class RunError(Exception):
    """A problem that cannot be run as asked (bad file, bad option, existing results)."""


def _import_file(path: Path):
    name = "mdo_problem_" + "".join(c if c.isalnum() else "_" for c in path.stem)
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise RunError(f"problem file {path}: not a Python file that can be imported")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except (Exception, SystemExit) as exc:  # the user's file: report, do not crash (nor exit 0 with it)
        raise RunError(f"problem file {path} failed to import: {_failure(exc)}") from exc
    return module


def _failure(exc) -> str:
    if isinstance(exc, SystemExit):
        return f"it called sys.exit({exc.code!r}); a problem file must not exit"
    return f"{type(exc).__name__}: {exc}"


def load_problem_file(path, *, analysis: bool = False, options: dict | None = None) -> Problem:
    """Import ``path``, call its ``build(**options)`` and check it returns a Problem."""
    path = Path(path)
    if not path.exists():
        raise RunError(f"problem file {path} does not exist")
    if path.suffix != ".py" or not path.is_file():
        raise RunError(f"problem file {path}: expected a .py file")
    module = _import_file(path)
    build = getattr(module, "build", None)
    if build is None or not callable(build):
        raise RunError(f"problem file {path} has no function build(**options) returning an mdo.nlp.Problem")
    options = dict(options or {})
    params = inspect.signature(build).parameters
    takes_kwargs = any(p.kind == p.VAR_KEYWORD for p in params.values())
    if "analysis" in params or takes_kwargs:
        options["analysis"] = analysis
    options = check_options(module, build, options, path)  # keys, types, ranges (mdo.nlp.options)
    try:
        problem = build(**options)
    except RunError:
        raise
    except (Exception, SystemExit) as exc:
        raise RunError(f"problem file {path}: build() failed: {_failure(exc)}") from exc
    if problem is None:
        raise RunError(f"problem file {path}: build() returned nothing (None), expected an mdo.nlp.Problem")
    if not isinstance(problem, Problem):
        raise RunError(f"problem file {path}: build() returned {type(problem).__name__}, "
                       f"expected an mdo.nlp.Problem")
    if analysis:
        problem.freeze_design()
    return problem


def default_out_dir(path, analysis: bool = False, root="results") -> Path:
    out = Path(root) / Path(path).stem
    return out / "analysis" if analysis else out


def check_out_dir(out_dir, force: bool) -> Path:
    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise RunError(f"--out {out}: exists and is not a folder")
    existing = [f for f in RESULT_FILES if (out / f).exists()]
    if existing and not force:
        raise RunError(f"{out} already holds a run ({', '.join(existing)}); "
                       f"pass --force to replace it or --out to write elsewhere")
    return out


def run_problem(problem: Problem, out_dir, *, force: bool = False, max_iter: int | None = None,
                warm_start=None, verbose: bool = True, solve_options: dict | None = None) -> Solution:
    """Solve ``problem`` and write its run folder; returns the Solution (check ``.success``)."""
    out = check_out_dir(out_dir, force)
    out.mkdir(parents=True, exist_ok=True)
    if warm_start is not None:
        ws = Path(warm_start)
        if not ws.exists():
            raise RunError(f"--warm-start {ws}: file does not exist")
        try:
            used = problem.warm_start(ws)
        except Exception as exc:
            raise RunError(f"--warm-start {ws}: not a readable solution.json ({type(exc).__name__}: {exc})") from exc
        if verbose:
            print(f"warm start from {ws}: {len(used)} variables set")
    log = out / "ipopt.log"
    if log.exists():
        log.unlink()
    solution = problem.solve(log_path=log, max_iter=max_iter, verbose=verbose, **(solve_options or {}))
    solution.save(out)
    for report in problem.reports:
        try:
            report(solution, out)
        except Exception as exc:  # a broken figure must not lose the solve
            print(f"warning: report {getattr(report, '__name__', report)} failed: "
                  f"{type(exc).__name__}: {exc}", file=sys.stderr)
            if verbose:
                traceback.print_exc()
    return solution
