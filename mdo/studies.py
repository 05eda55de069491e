"""Glue shared by the aircraft problem files: the paper's objective and the run-folder
reports.  Sits on top of the disciplines (like ``cli``); problem files call it after
building their vehicle and mission."""
from __future__ import annotations

from .core.units import KWH
from .plots import figure_report
from .vehicle.reports import add_vehicle_reports

__all__ = ["minimize_battery_energy"]


def minimize_battery_energy(problem, vehicle, mission, *, max_iter: int = 500):
    """Objective E_EOF of Eq. 7 (kWh, scaled by 10 kWh) and every report: mission.csv and
    mission.png, mass, energy breakdown, loading, blade, design, geometry, and the
    figures of ``mdo plot``."""
    problem.minimize(mission.energy_used_J / KWH, unit="kWh", scale=10.0, name="battery energy used")
    problem.ipopt_options["max_iter"] = int(max_iter)
    problem.add_report(mission.report)
    add_vehicle_reports(problem, vehicle, mission)
    problem.add_report(figure_report)
    return problem
