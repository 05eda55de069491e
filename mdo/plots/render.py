"""Render every figure a run folder has data for."""
from __future__ import annotations

from pathlib import Path

from .convergence import plot_convergence

__all__ = ["render_run", "RENDERERS"]


def _convergence(run: Path):
    log = run / "ipopt.log"
    if log.exists():
        return [plot_convergence(log, run / "convergence.png")]
    return []


RENDERERS = [_convergence]


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
