"""What the wake needs to know about a rotor: placement, size, blade elements, sense."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..core.errors import InputError

__all__ = ["WakeRotor", "element_edges", "DEFAULT_CORE_REL"]

DEFAULT_CORE_REL = 0.1  # filament core / radius; the shipped mean-wake table is built for it


@dataclass(frozen=True)
class WakeRotor:
    """One rotor as seen by its wake.

    center: disk centre (3,), m, in the wing's frame (x aft, y starboard, z up).
    axis: wake axis (3,), the direction the slipstream convects (opposite to thrust);
        need not be unit length.  Tilted with the wing or nacelle as the caller wants.
    radius_m: tip radius R.
    s_edges: (N+1,) radial edges r/R of the N blade elements, hub to tip, increasing
        (see :func:`element_edges` to get them from BEMT station positions).
    blades: blade count B.
    spin: ±1, sign of the angular velocity about ``axis`` (frames.spin_for).
    core_rel: vortex core radius / R of the wake filaments.

    center, axis and radius_m may be CasADi expressions (design variables); the
    others fix the structure.
    """
    center: object
    axis: object
    radius_m: object
    s_edges: tuple
    blades: int
    spin: int
    core_rel: float = DEFAULT_CORE_REL
    name: str = ""

    def __post_init__(self):
        s = np.asarray(self.s_edges, dtype=float)
        if s.ndim != 1 or s.size < 2 or np.any(np.diff(s) <= 0) or s[0] < 0 or s[-1] > 1.0 + 1e-12:
            raise InputError("s_edges", "must increase strictly within [0, 1] (hub to tip), at least 2 values")
        object.__setattr__(self, "s_edges", tuple(float(v) for v in s))
        if int(self.blades) != self.blades or self.blades < 1:
            raise InputError("blades", f"must be a positive integer, got {self.blades!r}")
        if self.spin not in (1, -1):
            raise InputError("spin", f"must be +1 or -1, got {self.spin!r}")
        if not (0 < self.core_rel < 0.5):
            raise InputError("core_rel", f"allowed range (0, 0.5), got {self.core_rel}")

    @property
    def n_stations(self) -> int:
        return len(self.s_edges) - 1


def element_edges(r_over_R, hub_fraction: float, tip: float = 1.0) -> np.ndarray:
    """Edges of the blade elements around BEMT stations ``r_over_R`` (increasing):
    midpoints between stations, the hub at ``hub_fraction`` and the tip at ``tip``."""
    r = np.asarray(r_over_R, dtype=float).ravel()
    if np.any(np.diff(r) <= 0):
        raise InputError("r_over_R", "stations must increase")
    if not (0 <= hub_fraction < r[0]) or r[-1] >= tip + 1e-12:
        raise InputError("hub_fraction", f"must lie below the first station {r[0]:g}, tip above the last")
    return np.concatenate([[hub_fraction], 0.5 * (r[1:] + r[:-1]), [tip]])
