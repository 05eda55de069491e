"""The airfoils shipped with mdo: coordinate file and polar files of each.

Keys are lower-case alphanumerics; ``normalize`` maps user spellings
("NACA 4412", "naca_4412", "Clark-Y", "NACA 63-412") onto them.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from .data_io import DATA_DIR

__all__ = ["CATALOG", "AirfoilEntry", "normalize"]


@dataclass(frozen=True)
class AirfoilEntry:
    key: str
    title: str
    coordinates: str           # file in data/coordinates
    polar_prefix: str          # polar files data/polars/<prefix>_polar_Re_<Re>.txt
    used_for: str
    aliases: tuple = ()

    @property
    def coordinate_path(self):
        return DATA_DIR / "coordinates" / self.coordinates

    @property
    def shipped(self) -> bool:
        """Coordinates and at least one polar present."""
        return self.coordinate_path.exists() and bool(self.polar_paths())

    def polar_paths(self, ncrit: float | None = None):
        """The shipped polars (XFOIL, Ncrit 9), or the shipped set at another Ncrit
        (``<prefix>_ncrit<N>_polar_Re_*.txt``; empty where none ships)."""
        if ncrit is None:
            return sorted((DATA_DIR / "polars").glob(f"{self.polar_prefix}_polar_Re_*.txt"))
        if float(ncrit) != round(float(ncrit)):
            return []
        return sorted((DATA_DIR / "polars").glob(f"{self.polar_prefix}_ncrit{int(round(ncrit))}_polar_Re_*.txt"))


CATALOG = {
    e.key: e for e in (
        AirfoilEntry("naca4412", "NACA 4412", "NACA_4412.txt", "NACA_4412",
                     "GA propellers and tilt-wing rotors (SUAVE X-57 propeller)"),
        AirfoilEntry("clarky", "Clark-Y", "Clark_y.txt", "Clark_y",
                     "propellers (classic 11.7 % section)"),
        AirfoilEntry("naca63412", "NACA 63-412", "NACA_63_412.txt", "NACA_63_412",
                     "GA wing (SUAVE X-57 model)"),
        AirfoilEntry("e63", "Eppler E63", "E63.txt", "E63",
                     "thin low-Re section of small APC-type propellers"),
        AirfoilEntry("naca0015", "NACA 0015", "NACA_0015.txt", "NACA_0015",
                     "symmetric stand-in for the PROWIM wing's NACA 64(2)-015A"),
    )
}


def normalize(name: str) -> str:
    """Lower-case alphanumerics only: 'NACA 63-412' -> 'naca63412'."""
    return re.sub(r"[^0-9a-z]", "", str(name).lower())
