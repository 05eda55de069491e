"""One grid point: one ``mdo run`` in its own run folder, as a subprocess.

A point runs exactly the command a user would type (``python -m mdo.cli run PROBLEM
--out DIR/<point> -o key=value ...``), so a sweep point *is* ``mdo run`` (baseline and
optimization, the two-stage logic of ``mdo/cli.py``) and nothing is re-implemented
here.  The subprocess also isolates the solve: a crash, a segfault in a solver
library or a leak ends that process, not the Dask worker, and its memory is freed.
The measured cost is the interpreter and import start-up, about 1-2 s a point
(``tests/bench/sweep.py``), against solves of seconds to minutes.

Files a point leaves beside its run folder (not inside: ``mdo run`` keeps its run
folders to its own files):

``DIR/.points/<point>.log``   the point's stdout and stderr
``DIR/.points/<point>.json``  the sweep's record (inputs, command, exit code, wall time, warm start),
                written atomically (temporary file + rename) when the run ends, so a
                killed sweep never leaves a half-written record.

A point is *finished* when its ``summary.json`` is complete (parses and has a status)
or its record (``.points/<point>.json``) records an ``mdo run`` that ended by itself (exit 0, 1 or 2);
finished points are skipped by a resumed sweep.
"""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

__all__ = ["record_path", "log_path", "run_point", "read_json", "finished", "point_status", "write_json_atomic", "git_commit"]

# exit codes of `mdo run` that mean it ended by itself (see mdo/cli.py)
_ENDED = (0, 1, 2)


def record_path(run_dir) -> Path:
    run_dir = Path(run_dir)
    return run_dir.parent / ".points" / f"{run_dir.name}.json"


def log_path(run_dir) -> Path:
    run_dir = Path(run_dir)
    return run_dir.parent / ".points" / f"{run_dir.name}.log"


def read_json(path):
    """The parsed JSON file, or None when it is missing or incomplete (a killed write)."""
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def write_json_atomic(path, data) -> None:
    path = Path(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    with open(tmp, "w") as f:
        json.dump(data, f, indent=1)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def _complete_summary(run_dir: Path):
    s = read_json(run_dir / "summary.json")
    return s if isinstance(s, dict) and "status" in s and "objective" in s else None


def finished(run_dir) -> bool:
    run_dir = Path(run_dir)
    if _complete_summary(run_dir) is not None:
        return True
    rec = read_json(record_path(run_dir))
    # a point stopped by its time budget (--point-timeout) ended as the user asked: kept, not re-run
    return isinstance(rec, dict) and (rec.get("returncode") in _ENDED or bool(rec.get("timed_out")))


def point_status(run_dir) -> str:
    """``Solve_Succeeded`` etc. from summary.json, or what went wrong before it."""
    run_dir = Path(run_dir)
    s = _complete_summary(run_dir)
    if s is not None:
        return s["status"]
    base = _complete_summary(run_dir / "analysis")
    if base is not None and base.get("success") is False:
        return f"baseline {base['status']}"
    rec = read_json(record_path(run_dir))
    if rec is None:
        return "not run"
    code = rec.get("returncode")
    if code == 2:
        return "input error"
    if rec.get("timed_out"):
        return f"stopped after {rec['timeout_s']:g} s (--point-timeout)"
    return f"crashed (exit {code})"


def git_commit() -> str:
    """The model version a point ran with: the commit of the checkout holding ``mdo``
    (with '+dirty' when mdo/ or problems/ have uncommitted changes), '' outside git."""
    root = Path(__file__).resolve().parents[2]
    try:
        commit = subprocess.run(["git", "-C", str(root), "rev-parse", "HEAD"], capture_output=True,
                                text=True, timeout=10).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain", "--", "mdo", "problems"],
                               capture_output=True, text=True, timeout=10).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return ""
    return commit + ("+dirty" if dirty and commit else "")


def _die_with_parent():
    """Child side of fork: SIGTERM the solve when the task's worker dies (Linux
    PR_SET_PDEATHSIG), so a killed sweep leaves no orphan solves behind."""
    try:
        import ctypes
        ctypes.CDLL("libc.so.6", use_errno=True).prctl(1, signal.SIGTERM)
    except (OSError, AttributeError):
        pass


def _command(problem, run_dir, point, fixed, warm_start, run_args):
    cmd = [sys.executable, "-m", "mdo.cli", "run", str(problem), "--out", str(run_dir), "--quiet"]
    for k, v in {**fixed, **point}.items():
        cmd += ["-o", f"{k}={json.dumps(v)}"]
    if warm_start is not None:
        cmd += ["--warm-start", str(warm_start)]
    return cmd + list(run_args)


def run_point(problem, run_dir, point: dict, fixed: dict | None = None, warm_start=None,
              run_args=(), timeout_s: float | None = None) -> dict:
    """Run one point (blocking) and return its record (also written to ``DIR/.points/<point>.json``).

    ``warm_start``: a neighbour's ``solution.json``; then ``mdo run --warm-start`` skips the
    baseline stage.  If that run does not converge, the point is run again cold (baseline
    and optimization) in the same folder, so a warm start can only save time, never
    lose a point.  ``run_args``: extra ``mdo run`` flags (``--max-iter``, ``--hessian``).
    ``timeout_s``: the point's wall-time budget (``mdo sweep --point-timeout``).  A run still going
    then is killed (SIGKILL: one IPOPT iteration can spend many minutes inside the linear solver,
    where no signal handler runs), the point is recorded as stopped (its log and the killed run's
    folder are kept) and, being the user's choice, is not re-run cold nor on resume.
    """
    run_dir = Path(run_dir)
    log_path(run_dir).parent.mkdir(parents=True, exist_ok=True)
    record_path(run_dir).unlink(missing_ok=True)
    t0 = time.time()
    attempts = []
    timed_out = False
    for ws in ([warm_start, None] if warm_start is not None else [None]):
        cmd = _command(problem, run_dir, point, fixed or {}, ws, run_args)
        # --force: leftovers of an interrupted or warm attempt are replaced
        cmd.append("--force")
        t1 = time.time()
        with open(log_path(run_dir), "a") as log:
            log.write(f"$ {' '.join(cmd)}\n")
            log.flush()
            try:
                code = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, timeout=timeout_s,
                                      preexec_fn=_die_with_parent if sys.platform.startswith("linux") else None,
                                      env={**os.environ, "PYTHONUNBUFFERED": "1"}).returncode
            except subprocess.TimeoutExpired:
                code = -int(signal.SIGKILL)
                timed_out = True
                log.write(f"mdo sweep: stopped after {timeout_s:g} s (--point-timeout)\n")
        attempts.append({"warm_start": None if ws is None else str(ws), "returncode": code,
                         "wall_time_s": round(time.time() - t1, 3)})
        if code == 0 or timed_out:
            break
    record = {"point": point, "fixed": fixed or {}, "problem": str(problem), "command": cmd,
              "returncode": attempts[-1]["returncode"], "attempts": attempts,
              "timed_out": timed_out, "timeout_s": timeout_s,
              "warm_start": attempts[0]["warm_start"], "warm_start_used": attempts[-1]["warm_start"],
              "wall_time_s": round(time.time() - t0, 3), "host": os.uname().nodename,
              "git_commit": git_commit(),
              "finished_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}
    write_json_atomic(record_path(run_dir), record)
    record["status"] = point_status(run_dir)
    return record
