"""Figures from run folders: IPOPT convergence, mission profile, spanwise loading,
rotor performance.  ``mdo plot RUN_DIR`` renders every figure whose data the folder has."""
from .convergence import parse_ipopt_log, plot_convergence
from .render import render_run

__all__ = ["parse_ipopt_log", "plot_convergence", "render_run"]
