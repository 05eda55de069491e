"""Run-folder reports of an :class:`~mdo.vehicle.aircraft.Aircraft` mission: mass build-up."""
from __future__ import annotations

from pathlib import Path

from .mass import mass_table_markdown

__all__ = ["add_vehicle_reports"]


def add_vehicle_reports(problem, vehicle, mission):
    def mass_report(solution, out_dir):
        Path(out_dir, "mass.md").write_text(mass_table_markdown(vehicle.config))
    problem.add_report(mass_report)
