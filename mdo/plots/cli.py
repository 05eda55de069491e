"""``mdo plot RUN_DIR``: figures from a run folder."""
from __future__ import annotations

from pathlib import Path

from ..core.errors import InputError


def _cmd_plot(args) -> int:
    from .render import render_run
    run = Path(args.run_dir)
    if not run.is_dir():
        raise InputError("RUN_DIR", f"{run} is not a folder (expected a run folder written by mdo run)")
    made = render_run(run, units=args.units)
    if not made:
        raise InputError("RUN_DIR", f"{run} holds no data to plot (ipopt.log, mission.csv, loading.csv, rotor.csv)")
    for p in made:
        print(p)
    return 0


def register(sub):
    p = sub.add_parser("plot", help="render the figures of a run folder",
                       description="Render mission profile, spanwise loading, rotor performance, geometry, "
                                   "three-view and IPOPT convergence figures (PNG), convergence.csv, the design "
                                   "checks and report.html into a run folder, from its files.")
    p.add_argument("run_dir", metavar="RUN_DIR")
    p.add_argument("--units", choices=("si", "aviation"), default="si",
                   help="unit system of every figure: si (m, m/s, kN, kW) or aviation (ft, kt TAS/EAS, lbf, kW)")
    p.set_defaults(func=_cmd_plot)
