"""Unit systems for figures and tables: one per figure, chosen by ``units="si"|"aviation"``.

Run folders are SI (``mission.csv``: m, m/s, W, N ...); the conversion happens here,
at the edge, and nowhere else.  ``aviation`` is what a pilot's instruments and an
aircraft's flight manual use: altitude and lengths in ft, airspeed in kt (true
airspeed, TAS, and equivalent airspeed, EAS = TAS sqrt(rho/rho0), both stated on the
axis), power in kW (as motor ratings are given), thrust in lbf, mass in lb.

Ratios that are undefined (an efficiency where the output or the input power is not
positive) are ``nan`` here, so that figures leave a gap and tables print "—".
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.errors import InputError
from ..core.units import FT, KNOT, LB, LBF

__all__ = ["UnitSystem", "unit_system", "UNIT_SYSTEMS", "defined_ratio", "equivalent_airspeed", "DASH"]

DASH = "—"   # a table cell whose quantity is undefined


@dataclass(frozen=True)
class UnitSystem:
    """Scale factors (SI value / factor = displayed value) and labels of one unit system."""
    name: str
    length: float
    length_unit: str
    altitude: float
    altitude_unit: str
    speed: float
    speed_unit: str
    force: float
    force_unit: str
    power: float
    power_unit: str
    mass: float
    mass_unit: str

    def conv(self, quantity: str, si_value):
        """SI value(s) of ``quantity`` ('length', 'altitude', 'speed', 'force', 'power', 'mass')
        in this system."""
        return np.asarray(si_value, float) / getattr(self, quantity)

    def label(self, text: str, quantity: str) -> str:
        """Axis label 'text (unit)'."""
        return f"{text} ({getattr(self, quantity + '_unit')})"


UNIT_SYSTEMS = {
    "si": UnitSystem("si", 1.0, "m", 1.0, "m", 1.0, "m/s", 1e3, "kN", 1e3, "kW", 1.0, "kg"),
    "aviation": UnitSystem("aviation", FT, "ft", FT, "ft", KNOT, "kt", LBF, "lbf", 1e3, "kW", LB, "lb"),
}


def unit_system(name: str | UnitSystem = "si") -> UnitSystem:
    """The unit system named ``name`` ("si" or "aviation"); InputError otherwise."""
    if isinstance(name, UnitSystem):
        return name
    key = str(name).lower()
    if key not in UNIT_SYSTEMS:
        raise InputError("units", f"got {name!r}; allowed: {', '.join(UNIT_SYSTEMS)}")
    return UNIT_SYSTEMS[key]


def defined_ratio(output, input_, *, tol: float = 0.0):
    """``output / input_`` where both are > ``tol``, ``nan`` elsewhere.

    An efficiency (thrust power / shaft power, shaft / battery power) means
    something only while power flows forward: with a windmilling propeller both
    are negative and their ratio (1.4 on the GA-2P base leg) is no efficiency.
    """
    num = np.asarray(output, float)
    den = np.asarray(input_, float)
    ok = (num > tol) & (den > tol)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(ok, num / np.where(ok, den, 1.0), np.nan)


def equivalent_airspeed(tas_mps, altitude_m):
    """EAS = TAS sqrt(rho(h)/rho0), standard atmosphere (m/s)."""
    from ..core.atmosphere import density
    h = np.asarray(altitude_m, float)
    rho = np.array([float(density(float(x))) for x in h.ravel()]).reshape(h.shape)
    return np.asarray(tas_mps, float) * np.sqrt(rho / float(density(0.0)))
