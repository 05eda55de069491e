"""Trade studies: ``mdo sweep`` runs a problem file over a grid of its options on Dask.

Public API: :func:`parse_grid`, :func:`expand`, :func:`point_name` (grid),
:func:`run_point` (one point = one ``mdo run`` subprocess), :func:`run_sweep` and
:func:`connect` (the parallel driver), :func:`write_table` / :func:`read_table`
(``sweep.csv``), :func:`line_plot` / :func:`carpet_plot`. See the README section "Trade studies".
Dask is imported only when a sweep runs in parallel.
"""
from .grid import expand, parse_grid, point_name
from .point import finished, point_status, run_point
from .runner import connect, run_sweep
from .table import read_table, write_table
from .plot import carpet_plot, line_plot

__all__ = ["parse_grid", "expand", "point_name", "run_point", "finished", "point_status", "connect",
           "run_sweep", "write_table", "read_table", "line_plot", "carpet_plot"]
