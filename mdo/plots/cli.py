"""``mdo plot RUN_DIR``: figures from a run folder.

Draws what the folder's readable files allow; each figure whose input is missing
a column, empty, binary, oversized or not a regular file (a FIFO is never opened)
is skipped with one warning line (``mdo.plots.render``).  Exit 0 when at least one
figure was drawn, 2 when none could be.
"""
from __future__ import annotations

import sys
from pathlib import Path

from ..core.errors import InputError


def _cmd_plot(args) -> int:
    from .render import render_run
    run = Path(args.run_dir)
    if not run.is_dir():
        raise InputError("RUN_DIR", f"{run} is not a folder (expected a run folder written by mdo run)")
    skipped = []

    def warn(text):
        skipped.append(text)
        print(f"mdo plot: warning: {text}", file=sys.stderr)

    made = render_run(run, units=args.units, warn=warn)
    if not made:
        what = f"{len(skipped)} figure(s) skipped, see the warnings above" if skipped else \
            "ipopt.log, mission.csv, loading.csv, blade.csv"
        raise InputError("RUN_DIR", f"{run} holds no data to plot ({what})")
    for p in made:
        print(p)
    return 0


def register(sub):
    p = sub.add_parser("plot", help="render the figures of a run folder",
                       description="Render mission profile, spanwise loading, rotor performance, geometry, "
                                   "three-view and IPOPT convergence figures (PNG), convergence.csv, the design "
                                   "checks and report.html into a run folder, from its files; a figure whose data is "
                                   "damaged is skipped with a one-line warning.")
    p.add_argument("run_dir", metavar="RUN_DIR", help="a run folder written by mdo run")
    p.add_argument("--units", choices=("si", "aviation"), default="si",
                   help="unit system of every figure: si (m, m/s, kN, kW) or aviation (ft, kt TAS/EAS, lbf, kW)")
    p.set_defaults(func=_cmd_plot)
