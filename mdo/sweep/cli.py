"""``mdo sweep``: trade studies (README "Trade studies").

    mdo sweep PROBLEM.py --grid KEY=V1,V2,... [--grid ...] [--out DIR] [--workers N]
              [--scheduler ADDRESS] [--warm-start] [--retry-failed] [-o KEY=VALUE] [--max-iter N]
    mdo sweep plot DIR --x KEY [--y COLUMN] [--carpet KEY2] [--out FILE]

Everything is checked before anything starts (keys against ``build()``'s
signature, the grid, the scheduler): bad input is one line and exit 2.  Exit 0
when every point converged, 1 when some did not (each has its status in
``sweep.csv``), 130 when interrupted (finished points kept; the same command resumes).
"""
from __future__ import annotations

import argparse
from pathlib import Path

from ..core.errors import InputError

__all__ = ["register"]


def register(sub):
    p = sub.add_parser(
        "sweep", help="trade study: one `mdo run` per grid point, in parallel on Dask",
        description="Run PROBLEM.py at every point of a grid of build() options (each a full `mdo run` in "
                    "DIR/<key=value,...>/), on a local Dask cluster or any Dask scheduler; or "
                    "`mdo sweep plot DIR --x KEY` to draw a finished sweep.",
        formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("target", metavar="PROBLEM.py|plot", help="the problem file, or `plot`")
    p.add_argument("sweep_dir", nargs="?", metavar="DIR", help="(plot) the sweep folder")
    p.add_argument("--grid", action="append", metavar="KEY=V1,V2,...",
                   help="a build() option and its values (JSON numbers/true/false or words); repeat for a product")
    p.add_argument("--option", "-o", action="append", metavar="KEY=VALUE", help="a fixed build() option")
    p.add_argument("--out", help="sweep folder (default results/sweeps/<problem>); for plot: the PNG file")
    p.add_argument("--workers", type=int, default=2,
                   help="local cluster size, single-threaded worker processes (default 2); 0 = serial, no Dask")
    p.add_argument("--scheduler", metavar="ADDRESS", help="a running Dask scheduler, e.g. tcp://host:8786")
    p.add_argument("--scheduler-timeout", type=float, default=10.0, metavar="S",
                   help="seconds to wait for --scheduler (default 10)")
    p.add_argument("--warm-start", action="store_true",
                   help="start each point from its nearest converged neighbour's solution (same values of the "
                        "non-float keys), skipping its baseline; a point that then fails is re-run cold")
    p.add_argument("--retry-failed", action="store_true", help="re-run finished points that did not converge")
    p.add_argument("--max-iter", type=int, help="IPOPT iteration limit of every point")
    p.add_argument("--hessian", choices=("exact", "full", "limited-memory"), help="as `mdo run --hessian`")
    p.add_argument("--threads", type=int, choices=(1, 2),
                   help="as `mdo run --threads` (the Hessian's threads) for every point (default: 1 when the "
                        "points run in parallel on Dask workers, one core each; mdo run's default with --workers 0)")
    p.add_argument("--point-timeout", type=float, metavar="S",
                   help="wall-time budget of each point in seconds: a run still going then is killed and the "
                        "point recorded as stopped (its log kept), and the sweep goes on")
    p.add_argument("--x", help="(plot) grid key on the horizontal axis")
    p.add_argument("--y", help="(plot) column of sweep.csv (default objective)")
    p.add_argument("--carpet", metavar="KEY2", help="(plot) second grid key: a carpet plot")
    p.set_defaults(func=_cmd_sweep)


def _cmd_sweep(args) -> int:
    if args.target == "plot":
        return _cmd_plot(args)
    if args.sweep_dir:
        raise InputError("sweep", f"unexpected argument {args.sweep_dir!r} (one PROBLEM.py per sweep)")
    for flag in ("x", "y", "carpet"):
        if getattr(args, flag):
            raise InputError(f"--{flag}", "belongs to `mdo sweep plot DIR`")
    from ..cli import _parse_option
    from .grid import build_parameters, check_keys, expand, parse_grid

    grid = parse_grid(args.grid)
    fixed = dict(_parse_option(o) for o in (args.option or []))
    params = build_parameters(args.target)
    check_keys(grid, params, fixed)
    if args.workers < 0:
        raise InputError("--workers", f"must be >= 0, got {args.workers}")
    if args.max_iter is not None and args.max_iter < 0:
        raise InputError("--max-iter", f"must be >= 0, got {args.max_iter}")
    if args.point_timeout is not None and not args.point_timeout > 0:
        raise InputError("--point-timeout", f"must be > 0 seconds, got {args.point_timeout:g}")
    points = expand(grid, params)
    out = Path(args.out or Path("results") / "sweeps" / Path(args.target).stem)
    if out.exists() and not out.is_dir():
        raise InputError("--out", f"{out} exists and is not a folder")
    run_args = (["--max-iter", str(args.max_iter)] if args.max_iter is not None else []) + \
               (["--hessian", args.hessian] if args.hessian else [])
    threads = args.threads if args.threads is not None else (1 if args.workers > 0 or args.scheduler else None)
    run_args += ["--threads", str(threads)] if threads is not None else []
    client = None
    if args.workers > 0 or args.scheduler:
        from .runner import connect
        client = connect(args.scheduler, args.workers, args.scheduler_timeout)  # before any point starts
    return _run(args, grid, points, out, fixed, run_args, client)


def _run(args, grid, points, out, fixed, run_args, client) -> int:
    from .runner import run_sweep

    try:
        rows = run_sweep(args.target, grid, points, out, fixed=fixed, workers=args.workers,
                         warm_start=args.warm_start, retry_failed=args.retry_failed, run_args=run_args,
                         client=client, point_timeout_s=args.point_timeout)
    except KeyboardInterrupt:
        print(f"mdo sweep: interrupted; finished points kept in {out} (sweep.csv is current); "
              f"run the same command to resume", flush=True)
        return 130
    finally:
        if client is not None:
            cluster = getattr(client, "cluster", None)
            client.close()
            if cluster is not None:
                cluster.close()
    bad = [r for r in rows if not r.get("success")]
    print(f"mdo sweep: {len(rows) - len(bad)}/{len(rows)} points converged; table {out / 'sweep.csv'}")
    for r in bad:
        print(f"  {r['point']}: {r['status']}")
    return 1 if bad else 0


def _cmd_plot(args) -> int:
    from .plot import plot_sweep

    if not args.sweep_dir:
        raise InputError("DIR", "usage: mdo sweep plot DIR --x KEY [--y COLUMN] [--carpet KEY2]")
    if not args.x:
        raise InputError("--x", "give the grid key for the horizontal axis")
    if args.grid:
        raise InputError("--grid", "belongs to `mdo sweep PROBLEM.py`, not to plot")
    path = plot_sweep(args.sweep_dir, args.x, args.y, args.carpet, args.out)
    print(f"mdo sweep plot: {path}")
    return 0
