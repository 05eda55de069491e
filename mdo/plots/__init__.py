"""Figures from run folders: IPOPT convergence, mission profile, spanwise loading,
rotor performance.  ``mdo plot RUN_DIR`` renders every figure whose data the folder has."""
from .convergence import parse_ipopt_log, plot_convergence
from .figures import plot_loading, plot_mission, plot_rotor, read_csv
from .render import figure_report, render_run

__all__ = ["parse_ipopt_log", "plot_convergence", "render_run", "figure_report", "plot_loading", "plot_mission",
           "plot_rotor", "read_csv"]
