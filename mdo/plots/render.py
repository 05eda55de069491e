"""Render every figure a run folder has data for."""
from __future__ import annotations

from pathlib import Path

from .convergence import plot_convergence
from .figures import plot_loading, plot_mission, plot_rotor

__all__ = ["render_run", "RENDERERS"]


def _convergence(run: Path):
    log = run / "ipopt.log"
    if log.exists():
        return [plot_convergence(log, run / "convergence.png")]
    return []


def _mission(run: Path):
    if (run / "mission.csv").exists():
        return [plot_mission(run / "mission.csv", run / "mission.png")]
    return []


def _loading(run: Path):
    if (run / "loading.csv").exists():
        base = run / "analysis" / "loading.csv"
        return [plot_loading(run / "loading.csv", run / "loading.png", baseline=base if base.exists() else None)]
    return []


def _rotor(run: Path):
    if (run / "blade.csv").exists():
        return [plot_rotor(run, run / "rotor.png")]
    return []


RENDERERS = [_convergence, _mission, _loading, _rotor]


def figure_report(solution, out_dir):
    """A problem report (``problem.add_report(figure_report)``) that renders every figure."""
    return render_run(out_dir)


def register_renderer(fn):
    """Disciplines add figure makers ``fn(run_dir) -> [png paths]`` (empty if no data)."""
    RENDERERS.append(fn)
    return fn


def render_run(run_dir) -> list:
    run = Path(run_dir)
    made = []
    for fn in RENDERERS:
        made += fn(run)
    return made
