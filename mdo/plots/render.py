"""Render every figure a run folder has data for, then its ``report.html``.

Everything is drawn from the folder's files (``ipopt.log``, ``mission.csv``,
``loading.csv``, ``blade.csv``, ``geometry.json`` ...), so ``mdo plot RUN_DIR`` redoes
what the run wrote, in either unit system (``units="si"|"aviation"``).
"""
from __future__ import annotations

import inspect
from pathlib import Path

from .convergence import plot_convergence, write_convergence_csv
from .figures import plot_loading, plot_mission, plot_rotor, run_title
from .units import unit_system

__all__ = ["render_run", "RENDERERS", "figure_report", "register_renderer"]


def _convergence(run: Path, units="si"):
    log = run / "ipopt.log"
    if log.exists():
        write_convergence_csv(log, run / "convergence.csv")   # the table from the same lines as the figure
        return [plot_convergence(log, run / "convergence.png")]
    return []


def _mission(run: Path, units="si"):
    if (run / "mission.csv").exists():
        return [plot_mission(run / "mission.csv", run / "mission.png", units=units)]
    return []


def _loading(run: Path, units="si"):
    if (run / "loading.csv").exists():
        base = run / "analysis" / "loading.csv"
        return [plot_loading(run / "loading.csv", run / "loading.png", baseline=base if base.exists() else None,
                             units=units)]
    return []


def _rotor(run: Path, units="si"):
    if (run / "blade.csv").exists():
        return [plot_rotor(run, run / "rotor.png", units=units)]
    return []


def _geometry(run: Path, units="si"):
    g = run / "geometry.json"
    if not g.exists():
        return []
    from .geometry import plot_geometry, plot_planform, read_geometry
    name = read_geometry(g).get("name", "")
    base = run / "analysis" / "geometry.json"
    return [plot_geometry(g, run / "geometry.png", title=run_title(run, f"{name} geometry"), units=units),
            plot_planform(g, run / "planform.png", baseline=base if base.exists() else None, units=units,
                          title=run_title(run, f"{name} three-view" + (", baseline dashed" if base.exists()
                                                                       else "")))]


def _checks(run: Path, units="si"):
    if (run / "summary.json").exists():
        from .checks import write_design_checks
        write_design_checks(run)
    return []


RENDERERS = [_convergence, _mission, _loading, _rotor, _geometry, _checks]


def figure_report(solution, out_dir):
    """A problem report (``problem.add_report(figure_report)``) that renders every figure."""
    return render_run(out_dir)


def register_renderer(fn):
    """Disciplines add figure makers ``fn(run_dir) -> [png paths]`` (empty if no data);
    a ``units`` keyword, if ``fn`` has one, receives the unit system's name."""
    RENDERERS.append(fn)
    return fn


def render_run(run_dir, units: str = "si", html: bool = True) -> list:
    """Every figure the folder has data for (paths), then ``report.html`` (with ``html``)."""
    run = Path(run_dir)
    us = unit_system(units)
    made = []
    for fn in RENDERERS:
        takes_units = "units" in inspect.signature(fn).parameters
        made += fn(run, units=us.name) if takes_units else fn(run)
    if html and made:
        from .report_html import write_report_html
        made.append(write_report_html(run))
    return made
