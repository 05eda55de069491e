"""Run the points of a sweep on Dask distributed (or serially), resumable and fault tolerant.

* **Cluster.**  By default a ``LocalCluster`` of ``workers`` single-threaded worker
  processes on this machine; ``scheduler`` connects to any running Dask scheduler
  instead (``dask-jobqueue``'s SLURMCluster/PBSCluster, ``dask scheduler`` + ``dask
  worker`` by hand; README "Trade studies").  ``workers=0`` runs the points one after
  another in this process, without Dask (the benchmark's serial reference).
* **Scheduling.**  The driver keeps as many points in flight as the cluster has
  worker threads and submits the next one when one ends, so the order can follow
  the results: with ``warm_start=True`` the next point is the pending one nearest to
  a finished point, and it starts from that neighbour's ``solution.json``.
* **Resume.**  Finished points (see ``mdo.sweep.point.finished``) are skipped; a point
  whose task died (worker lost, sweep killed) is simply run again next time.
* **Faults.**  A point's failure is its record (status, exit code); it never stops
  the others.  ``sweep.csv`` is rewritten after every point, so killing the sweep
  loses no finished point and leaves a current table.
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

from ..core.errors import InputError
from .grid import point_name, structural_keys
from .point import finished, git_commit, read_json, run_point, write_json_atomic
from .table import write_table

__all__ = ["connect", "run_sweep", "nearest_neighbour"]


def connect(scheduler: str | None, workers: int, timeout_s: float = 10.0):
    """A Dask ``Client``: to ``scheduler`` (address) or to a new LocalCluster of ``workers``
    single-threaded processes.  An unreachable scheduler raises ``InputError`` after
    ``timeout_s``."""
    try:
        from distributed import Client, LocalCluster
    except ImportError as exc:  # the optional extra is missing
        raise InputError("--workers", "Dask is not installed: pip install 'mdo[sweep]' "
                                      "(or use --workers 0 to run the points serially)") from exc
    if scheduler:
        try:
            return Client(scheduler, timeout=f"{timeout_s}s")
        except (OSError, TimeoutError, ValueError) as exc:
            raise InputError("--scheduler", f"no Dask scheduler reachable at {scheduler!r} within "
                                            f"{timeout_s:g} s ({type(exc).__name__})") from exc
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                           dashboard_address=None, silence_logs=40)
    return Client(cluster)


def _distance(a: dict, b: dict, grid: dict) -> float:
    """Distance of two points in grid steps (each key's values indexed 0, 1, 2, ...)."""
    return sum(abs(grid[k].index(a[k]) - grid[k].index(b[k])) for k in grid)


def nearest_neighbour(point: dict, done: list, grid: dict):
    """The finished, converged point nearest to ``point`` among those with the same values of
    the structural keys (``mdo.sweep.grid.structural_keys``), or None."""
    fixed = structural_keys(grid)
    cands = [d for d in done if all(d["point"][k] == point[k] for k in fixed)]
    if not cands:
        return None
    return min(cands, key=lambda d: _distance(point, d["point"], grid))


def _next_point(pending: list, done: list, grid: dict, warm_start: bool):
    """Index in ``pending`` of the point to run next and its warm-start neighbour."""
    if not warm_start:
        return 0, None
    best = None
    for i, p in enumerate(pending):
        nb = nearest_neighbour(p, done, grid)
        if nb is not None:
            d = _distance(p, nb["point"], grid)
            if best is None or d < best[0]:
                best = (d, i, nb)
    if best is None:
        return 0, None
    return best[1], best[2]


class _Progress:
    """One line per finished point, readable in a log (no carriage returns)."""

    def __init__(self, total: int, skipped: int, stream):
        self.total, self.done, self.failed = total, skipped, 0
        self.t0 = time.time()
        self.stream = stream

    def report(self, rec: dict, running: int, objective: str = "") -> None:
        self.done += 1
        ok = rec.get("returncode") == 0
        self.failed += 0 if ok else 1
        el = time.time() - self.t0
        ws = " (warm)" if rec.get("warm_start_used") else ""
        print(f"sweep [{self.done}/{self.total}] {point_name(rec['point'])}: {rec['status']}{ws}, "
              f"{rec['wall_time_s']:.1f} s{objective} | running {running}, failed {self.failed}, "
              f"elapsed {el:.0f} s", file=self.stream, flush=True)


def _objective_text(run_dir: Path) -> str:
    s = read_json(run_dir / "summary.json")
    if not isinstance(s, dict):
        return ""
    o = s.get("objective", {})
    return f", {o.get('name', 'objective')} {o.get('value', float('nan')):.6g} {o.get('unit', '')}"


def _converged(run_dir: Path) -> bool:
    s = read_json(run_dir / "summary.json")
    return isinstance(s, dict) and bool(s.get("success")) and (run_dir / "solution.json").exists()


def _shown(path: Path) -> str:
    """``path`` relative to the working directory when below it (portable sweep.json)."""
    try:
        return str(path.relative_to(Path.cwd()))
    except ValueError:
        return str(path)


def run_sweep(problem, grid: dict, points: list, out, *, fixed: dict | None = None, workers: int = 2,
              scheduler: str | None = None, warm_start: bool = False, retry_failed: bool = False,
              run_args=(), client=None, stream=None, point_timeout_s: float | None = None) -> list:
    """Run every unfinished point of ``points`` into ``out/<point name>/``; returns the table rows.

    ``client``: an existing Dask client (tests); otherwise one from :func:`connect`,
    closed at the end.  ``sweep.json`` records the call; ``sweep.csv`` is rewritten
    after each point.  ``point_timeout_s``: each point's wall-time budget (``run_point``).
    """
    stream = stream or sys.stdout
    out = Path(out)
    problem = Path(problem).resolve()
    dirs = {point_name(p): out / point_name(p) for p in points}
    pending = [p for p in points if not finished(dirs[point_name(p)])
               or (retry_failed and not _converged(dirs[point_name(p)]))]
    done = [{"point": p, "dir": dirs[point_name(p)]} for p in points
            if p not in pending and _converged(dirs[point_name(p)])]
    out.mkdir(parents=True, exist_ok=True)
    write_json_atomic(out / "sweep.json", {"problem": _shown(problem), "grid": grid, "fixed": fixed or {},
                                           "run_args": list(run_args), "warm_start": warm_start,
                                           "point_timeout_s": point_timeout_s,
                                           "git_commit": git_commit()})
    progress = _Progress(len(points), len(points) - len(pending), stream)
    print(f"sweep: {len(points)} points, {len(points) - len(pending)} already finished, "
          f"{len(pending)} to run -> {out}", file=stream, flush=True)

    def submit(runner):
        i, nb = _next_point(pending, done, grid, warm_start)
        p = pending.pop(i)
        ws = nb["dir"] / "solution.json" if nb is not None else None
        return p, runner(problem, dirs[point_name(p)], p, fixed or {}, ws, tuple(run_args), point_timeout_s)

    def finish(p, rec, running):
        rec["status"] = rec.get("status") or "lost"
        if _converged(dirs[point_name(p)]):
            done.append({"point": p, "dir": dirs[point_name(p)]})
        progress.report(rec, running, _objective_text(dirs[point_name(p)]))
        write_table(out, points)

    if workers == 0 and scheduler is None and client is None:
        while pending:
            p, rec = submit(run_point)
            finish(p, rec, 0)
    else:
        _run_dask(client, scheduler, workers, pending, submit, finish)
    return write_table(out, points)


def _run_dask(client, scheduler, workers, pending, submit, finish) -> None:
    """Keep one point per worker thread in flight; a lost task is a failed point, not a stop."""
    from distributed import wait

    own = client is None
    client = client or connect(scheduler, workers)
    try:
        slots = max(1, sum(client.nthreads().values()))
        inflight = {}

        def runner(problem, run_dir, p, fixed, ws, run_args, timeout_s):
            return client.submit(run_point, str(problem), str(run_dir), p, fixed, None if ws is None else str(ws),
                                 run_args, timeout_s, pure=False, key=f"mdo-sweep-{run_dir.name}-{time.time_ns()}")

        while pending or inflight:
            while pending and len(inflight) < slots:
                p, fut = submit(runner)
                inflight[fut] = p
            finished_now = wait(list(inflight), return_when="FIRST_COMPLETED").done
            for fut in finished_now:
                p = inflight.pop(fut)
                try:
                    rec = fut.result()
                except Exception as exc:  # worker died, task lost: record it, go on
                    rec = {"point": p, "returncode": None, "wall_time_s": 0.0,
                           "status": f"task failed ({type(exc).__name__})"}
                finish(p, rec, len(inflight))
    finally:
        if own:
            cluster = getattr(client, "cluster", None)
            client.close()
            if cluster is not None:
                cluster.close()
