"""Running a problem file: load it, build, solve, write the run folder.

A problem file is a Python file with a function ``build(**options)`` that
returns a :class:`mdo.nlp.Problem`.  ``run_problem`` solves it and writes, into
the run folder (``results/<problem-file-stem>/`` by default, ``.../analysis/`` for
``--analysis``):

``ipopt.log``        the whole IPOPT log
``solution.json``    every variable: name, unit, value (and every output)
``summary.json``     status, objective with unit, iterations, wall time, NLP size, the
                     build() options it was made with (defaults included), the problem's
                     summary outputs (e.g. battery_energy_kWh)
``summary.md``       the same for people, with the worst constraint violations
``convergence.csv``  the iteration lines of ipopt.log (objective, inf_pr, inf_du, lg_mu ...)
``report.html``      one self-contained page: status, objective, constraints, design, figures
plus whatever the problem's reports write (figures, mission.csv, ...).

An existing run folder is never overwritten: ``force=True`` moves it aside to
``NAME.old-<timestamp>`` once the new run is complete.  See ``RunFolder`` for the
lock, the staging folder and what a killed or failed run leaves.
"""
from __future__ import annotations

import contextlib
import errno
import fcntl
import importlib.util
import inspect
import json
import os
import shutil
import signal
import sys
import tempfile
import time
import traceback
from pathlib import Path

from ..core.errors import InputError
from .options import check_options
from .problem import INTERRUPT_STATUS, Problem, Solution, WarmStartError, write_atomic

__all__ = ["RunError", "ResultWriteError", "RunFolder", "load_problem_file", "default_out_dir",
           "optimize_from_baseline",
           "run_problem", "solve_into", "RESULT_FILES"]

RESULT_FILES = ("summary.json", "solution.json", "ipopt.log")
RUN_MARKER = ".mdo-run"   # written into every finished run folder


class RunError(Exception):
    """A problem that cannot be run as asked (bad file, bad option, existing results)."""


class ResultWriteError(RunError):
    """The solve finished but its results could not be written (exit 1, not 2)."""

    def __init__(self, error: RunError, solution: Solution):
        super().__init__(str(error))
        self.solution = solution


def _import_file(path: Path):
    name = "mdo_problem_" + "".join(c if c.isalnum() else "_" for c in path.stem)
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise RunError(f"problem file {path}: not a Python file that can be imported")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except SystemExit as exc:
        raise RunError(f"problem file {path} called sys.exit({exc.code!r}) while being imported; "
                       f"a problem file defines build(**options) and returns") from None
    except Exception as exc:  # the user's file: report, do not crash
        raise RunError(f"problem file {path} failed to import: {type(exc).__name__}: {exc}") from exc
    return module


def problem_module(path):
    """The imported problem file (its module-level settings, e.g. ``RELAXED_OPTIONS``)."""
    return _import_file(Path(path))


def _with_analysis(build, options, analysis: bool) -> dict:
    """``options`` with ``analysis`` added where ``build()`` takes it."""
    options = dict(options or {})
    params = inspect.signature(build).parameters
    if "analysis" in params or any(p.kind == p.VAR_KEYWORD for p in params.values()):
        options["analysis"] = analysis
    return options


def _with_defaults(build, options: dict) -> dict:
    """``build()``'s defaults, overridden by ``options``."""
    params = inspect.signature(build).parameters
    return {**{k: p.default for k, p in params.items() if p.default is not p.empty}, **options}


def build_options(module, options: dict | None = None, *, analysis: bool = False) -> dict:
    """Every option ``build()`` of the imported problem file ``module`` gets with these ``-o``
    ``options`` (checked) in this mode: what ``load_problem_file`` builds with and records in
    ``Problem.build_options``, defaults included."""
    build = module.build
    return _with_defaults(build, check_options(module, build, _with_analysis(build, options, analysis),
                                               getattr(module, "__file__", "problem file")))


def load_problem_file(path, *, analysis: bool = False, options: dict | None = None) -> Problem:
    """Import ``path``, call its ``build(**options)`` and check it returns a Problem."""
    path = Path(path)
    try:
        if not path.exists():
            raise RunError(f"problem file {path} does not exist")
        if path.suffix != ".py" or not path.is_file():
            raise RunError(f"problem file {path}: expected a .py file")
        with open(path, "rb"):
            pass
    except OSError as exc:
        raise fs_error(exc, "problem file", path) from exc
    module = _import_file(path)
    build = getattr(module, "build", None)
    if build is None or not callable(build):
        raise RunError(f"problem file {path} has no function build(**options) returning an mdo.nlp.Problem")
    options = check_options(module, build, _with_analysis(build, options, analysis), path)  # keys, types, ranges
    try:
        problem = build(**options)
    except RunError:
        raise
    except SystemExit as exc:
        raise RunError(f"problem file {path}: build() called sys.exit({exc.code!r}) instead of "
                       f"returning an mdo.nlp.Problem") from None
    except Exception as exc:
        raise RunError(f"problem file {path}: build() failed: {type(exc).__name__}: {exc}") from exc
    if not isinstance(problem, Problem):
        got = "nothing (None)" if problem is None else type(problem).__name__
        raise RunError(f"problem file {path}: build() returned {got}, "
                       f"expected an mdo.nlp.Problem")
    # what built it, defaults included (summary.json "options"): the run can be repeated, and a
    # relaxed-start hook can read how the stage it hands on from was flown
    problem.build_options = _with_defaults(build, options)
    if analysis:
        problem.freeze_design()
    return problem


def default_out_dir(path, analysis: bool = False, root="results") -> Path:
    out = Path(root) / Path(path).stem
    return out / "analysis" if analysis else out


def fs_error(exc: OSError, what: str, path=None) -> "RunError":
    """One line for a file-system error: what was being done, the path, why."""
    where = path if path is not None else (exc.filename or "?")
    reason = exc.strerror or str(exc)
    if exc.errno == errno.ENAMETOOLONG:
        reason = "name too long for the file system"
    elif exc.errno == errno.ENOSPC:
        reason = "no space left on the device"
    elif exc.errno in (errno.EROFS, errno.EACCES, errno.EPERM):
        reason = f"not writable ({exc.strerror})"
    return RunError(f"{what} {where}: {reason}")


def _is_run(folder: Path) -> bool:
    return (folder / RUN_MARKER).exists() or any((folder / f).exists() for f in RESULT_FILES) or \
        any((folder / "analysis" / f).exists() for f in RESULT_FILES)


def _links_in(folder: Path, limit: int = 10000):
    """The first symbolic link inside ``folder`` (not followed), or None."""
    seen = 0
    for root, dirs, files in os.walk(folder, followlinks=False):
        for name in dirs + files:
            seen += 1
            if os.path.islink(os.path.join(root, name)):
                return Path(root) / name
            if seen > limit:
                return None
    return None


def check_out_dir(out_dir, force: bool) -> Path:
    """Refuse an output folder that cannot take a new run (one line naming why)."""
    out = Path(out_dir)
    try:
        if out.is_symlink():
            raise RunError(f"--out {out}: is a symbolic link; give the real folder")
        if out.exists() and not out.is_dir():
            raise RunError(f"--out {out}: exists and is not a folder")
        if out.is_dir():
            link = _links_in(out)
            if link is not None:
                raise RunError(f"--out {out}: holds a symbolic link {link}; mdo does not write through "
                               f"links (remove it or choose another folder)")
            if _is_run(out):
                if not force:
                    existing = [f for f in RESULT_FILES if (out / f).exists()] or \
                        [f"analysis/{f}" for f in RESULT_FILES if (out / "analysis" / f).exists()]
                    raise RunError(f"{out} already holds a run ({', '.join(existing) or RUN_MARKER}); "
                                   f"pass --force to move it aside or --out to write elsewhere")
            elif any(out.iterdir()):
                first = sorted(p.name for p in out.iterdir())[0]
                raise RunError(f"--out {out}: holds files that are not an mdo run (e.g. {first}); "
                               f"choose a new or empty folder")
    except OSError as exc:
        raise fs_error(exc, "--out") from exc
    return out


class RunFolder:
    """An output folder written safely (#19 item 1).

    * an exclusive ``flock`` on ``PARENT/.NAME.lock`` for the whole run: a second run
      into the same folder is refused at once;
    * everything is written into a fresh sibling ``NAME.incomplete-XXXX`` (with an
      ``INCOMPLETE.txt`` saying so) and renamed into place only when complete, so a
      killed run (even ``kill -9``) leaves the earlier run untouched;
    * on success an earlier run is moved aside to ``NAME.old-<timestamp>`` (never
      deleted, never mixed with the new files); a failed or interrupted run goes to
      ``NAME.failed-<timestamp>`` / ``NAME.interrupted-<timestamp>`` when an earlier
      run is in place, else into ``NAME``;
    * the parent is made and the staging folder written before anything is built, so
      an unwritable ``--out`` is one line, early.  ``abort()`` removes what it made.
    """

    def __init__(self, out_dir, force: bool = False):
        self.out = Path(out_dir)
        self.force = force
        self.stage = None
        self.moved_aside = None
        self._lock = None
        self._lock_path = None
        self._made = []

    # ------------------------------------------------------------ open
    def open(self) -> "RunFolder":
        check_out_dir(self.out, self.force)
        parent = self.out.parent
        try:
            missing = []
            p = parent
            while not p.exists():
                missing.append(p)
                p = p.parent
            parent.mkdir(parents=True, exist_ok=True)
            self._made = missing
            self._acquire(parent)
            check_out_dir(self.out, self.force)   # again, under the lock: another run may have finished
            self.stage = Path(tempfile.mkdtemp(prefix=f"{self.out.name}.incomplete-", dir=parent))
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(self.stage, 0o777 & ~umask)   # mkdtemp makes it private; a run folder is not
            (self.stage / "INCOMPLETE.txt").write_text(
                f"An mdo run into {self.out} (pid {os.getpid()}, started {time.ctime()}) is writing here.\n"
                f"If no run is going on, it was killed: this folder is incomplete; delete it.\n")
        except RunError:
            self.abort()
            raise
        except OSError as exc:
            self.abort()
            raise fs_error(exc, "--out", self.out) from exc
        return self

    def _acquire(self, parent: Path):
        path = parent / f".{self.out.name}.lock"
        for _ in range(10):
            fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                os.close(fd)
                raise RunError(f"--out {self.out}: another mdo run is writing it (lock {path} held); "
                               f"wait for it or choose another --out") from None
            # the lock file may have been unlinked by the run that just finished: retry on the new one
            try:
                same = os.fstat(fd).st_ino == os.stat(path).st_ino
            except FileNotFoundError:
                same = False
            if same:
                self._lock, self._lock_path = fd, path
                return
            os.close(fd)
        raise RunError(f"--out {self.out}: could not take the lock {path}")

    def _release(self):
        if self._lock is not None:
            with contextlib.suppress(OSError):
                os.unlink(self._lock_path)
            os.close(self._lock)
            self._lock = None

    # ------------------------------------------------------------ close
    def commit(self, success: bool, status: str = "") -> Path:
        """Move the finished run into place; returns where it now is."""
        wait_for_figures()
        try:
            (self.stage / "INCOMPLETE.txt").unlink()
            write_atomic(self.stage / RUN_MARKER, json.dumps(
                {"folder": str(self.out), "status": status, "success": success, "finished": time.ctime()}) + "\n")
            stamp = time.strftime("%Y%m%d-%H%M%S")
            earlier = self.out.exists() and _is_run(self.out)
            if earlier and success:
                self.moved_aside = _free_name(self.out, f"old-{stamp}")
                os.rename(self.out, self.moved_aside)
                target = self.out
            elif earlier:
                target = _free_name(self.out, f"{'interrupted' if status in INTERRUPT_STATUS else 'failed'}-{stamp}")
            else:
                target = self.out
            os.rename(self.stage, target)   # onto a missing or empty folder: atomic
        except OSError as exc:
            raise fs_error(exc, "moving the finished run into place:", self.out) from exc
        finally:
            self._release()
        self.stage = None
        return target

    def abort(self):
        """Nothing happened: remove the staging folder, the parents made, the lock."""
        wait_for_figures()
        if self.stage is not None:
            shutil.rmtree(self.stage, ignore_errors=True)
            self.stage = None
        self._release()
        for p in self._made:
            with contextlib.suppress(OSError):
                p.rmdir()
        self._made = []

    def keep_incomplete(self):
        """A failure while writing: leave the staging folder (it says it is incomplete)."""
        wait_for_figures()
        self._release()


def _free_name(out: Path, tag: str) -> Path:
    cand = out.with_name(f"{out.name}.{tag}")
    k = 1
    while cand.exists():
        k += 1
        cand = out.with_name(f"{out.name}.{tag}-{k}")
    return cand


# Figures drawn in a forked child while the parent goes on (``solve_into(...,
# figures="background")``: ``mdo run`` draws the baseline's figures during stage 2, on the
# second core; 2-3 s of matplotlib per folder).  Every RunFolder waits for them before it
# moves, keeps or removes its staging folder, so no figure is written into a moved folder.
_BACKGROUND: list = []


def wait_for_figures() -> None:
    """Wait for the figure children of this process (``solve_into``'s background mode)."""
    while _BACKGROUND:
        pid = _BACKGROUND.pop()
        with contextlib.suppress(ChildProcessError):
            os.waitpid(pid, 0)


def _fork_figures(problem, solution, folder, verbose) -> bool:
    """Draw ``folder``'s figures in a child process; False if this platform cannot fork."""
    if not hasattr(os, "fork") or os.environ.get("MDO_FIGURES_IN_PROCESS"):
        return False
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid:
        _BACKGROUND.append(pid)
        return True
    code = 0
    try:   # the child: no signal of the terminal's (the parent handles them and waits for this)
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        signal.signal(signal.SIGTERM, signal.SIG_DFL)
        _draw_figures(problem, solution, folder, verbose)
    except BaseException:   # noqa: BLE001 - a figure must never take the run down
        code = 1
    finally:
        with contextlib.suppress(Exception):
            sys.stdout.flush()
            sys.stderr.flush()
        os._exit(code)


def _draw_figures(problem, solution, folder, verbose) -> None:
    for report in problem.reports:
        try:
            report(solution, folder)
        except Exception as exc:  # a broken figure must not lose the solve
            print(f"warning: report {getattr(report, '__name__', report)} failed: "
                  f"{type(exc).__name__}: {exc}", file=sys.stderr)
            if verbose:
                traceback.print_exc()
    try:   # the page a designer opens, from the files just written (as ``mdo plot`` makes it)
        from ..plots.report_html import write_report_html
        write_report_html(folder)
    except Exception as exc:
        print(f"warning: report.html failed: {type(exc).__name__}: {exc}", file=sys.stderr)


def solve_into(problem: Problem, folder, *, max_iter: int | None = None, verbose: bool = True,
               solve_options: dict | None = None, progress=None, figures: str = "now") -> Solution:
    """Solve ``problem`` and write its files into ``folder`` (no folder management: a
    staging folder of a ``RunFolder``).  An ``OSError`` while writing the results is
    raised as ``ResultWriteError`` (exit 1: the solve happened).  ``figures="background"``
    draws the figures and ``report.html`` in a forked child once the data files are
    written (``wait_for_figures`` waits for it; without ``os.fork`` they are drawn now)."""
    if figures not in ("now", "background"):
        raise InputError("figures", f"'now' or 'background', got {figures!r}")
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    solution = problem.solve(log_path=folder / "ipopt.log", max_iter=max_iter, verbose=verbose,
                             progress=progress, **(solve_options or {}))
    try:
        solution.save(folder)
    except OSError as exc:
        raise ResultWriteError(fs_error(exc, "writing the results into", folder), solution) from exc
    if figures == "background" and _fork_figures(problem, solution, folder, verbose):
        return solution
    _draw_figures(problem, solution, folder, verbose)
    return solution


def optimize_from_baseline(problem: Problem, start, solve, *, on_fallback=None,
                           iteration_limit_is_final: bool = False) -> Solution:
    """The second stage of DESIGN rule 7's continuation, with its fallback.

    ``start()`` puts the starting point into ``problem`` (the converged baseline's mission,
    plus any initial values of the caller); ``solve(fallback) -> Solution`` solves it.
    The first attempt uses the first barrier of ``problem.barrier_order`` (monotone unless
    the problem chose another; ``Problem.start_from_baseline``), unless the problem set its
    own barrier.  If it ends without an optimum -- not interrupted, and not at an iteration
    limit the caller set when ``iteration_limit_is_final`` -- ``on_fallback(failed)`` runs
    (``mdo run`` moves the attempt's files aside, into a folder named after its barrier), and
    the second attempt starts again from ``start()`` with the other barrier
    (``Problem.fallback_barrier_after``; the new solution's ``barrier["fallback_from"]``
    records the failed attempt).  ``mdo run`` and the robustness study share this one policy."""
    start()
    first = problem.start_from_baseline()
    sol = solve(False)
    retry = (first and not sol.success and sol.status not in INTERRUPT_STATUS
             and not (iteration_limit_is_final and sol.status == "Maximum_Iterations_Exceeded"))
    if not retry:
        return sol
    if on_fallback is not None:
        on_fallback(sol)
    problem.fallback_barrier_after(sol, problem.barrier_order[0])
    start()
    return solve(True)


def load_warm_start(problem: Problem, source, *, partial: bool = False):
    """``problem.warm_start`` with its errors as one ``RunError`` line."""
    try:
        return problem.warm_start(source, partial=partial)
    except WarmStartError as exc:
        raise RunError(f"--{exc}") from exc


def run_problem(problem: Problem, out_dir, *, force: bool = False, max_iter: int | None = None,
                warm_start=None, warm_start_partial: bool = False, verbose: bool = True,
                solve_options: dict | None = None) -> Solution:
    """Solve ``problem`` and write its run folder safely (``RunFolder``); returns the
    Solution (check ``.success``).  The warm start is checked before anything is made."""
    if warm_start is not None:
        ws = load_warm_start(problem, warm_start, partial=warm_start_partial)
        if verbose:
            print(f"warm start from {warm_start}: {ws.describe()}"
                  + ("; multipliers loaded" if ws.multipliers else ""))
    folder = RunFolder(out_dir, force).open()
    try:
        solution = solve_into(problem, folder.stage, max_iter=max_iter, verbose=verbose,
                              solve_options=solve_options)
    except ResultWriteError:
        folder.keep_incomplete()
        raise
    except BaseException:
        folder.abort()
        raise
    solution.folder = folder.commit(solution.success, solution.status)
    solution.moved_aside = folder.moved_aside
    return solution
