"""What the wake needs to know about a rotor: placement, size, blade elements, sense."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.errors import InputError

__all__ = ["WakeRotor", "element_edges", "DEFAULT_CORE_REL"]

# filament core / radius of its helix (mean-wake tables ship for 0.05 and 0.1).  0.1: the
# blade-passage-averaged slipstream edge is then smoothed over about 0.27 R (10-90 %), wider than
# the spacing of an aircraft's wake samples across a strip (GA-2P: 0.09 R), so the mission energy
# does not ripple as a rotor moves along the span (mdo/README.md, "the slipstream's edge").
DEFAULT_CORE_REL = 0.10


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

    @classmethod
    def from_geometry(cls, geometry, center, *, n_stations: int = 20, axis=None, radius_m=None,
                      core_rel: float = DEFAULT_CORE_REL, name: str | None = None) -> "WakeRotor":
        """Adapter from an ``mdo.rotor.RotorGeometry``.

        The BEMT (mdo.rotor) evaluates Γ at the midpoints of its panels; their edges,
        ``geometry.station_edges(n_stations)`` (``mdo.rotor.geometry``, the one definition of
        the layout), are the ring edges here.
        ``geometry.rotation`` is the sense about the thrust direction, the wake axis is
        opposite to it, so spin = −rotation.  ``axis`` is the wake axis in the wing's
        frame (default +x: a tractor rotor in cruise; the geometry's own ``axis`` is in
        its owner's frame and is not used); ``radius_m`` (e.g. a design variable)
        defaults to the geometry's radius.
        """
        edges = np.asarray(geometry.station_edges(n_stations), dtype=float)
        ax = axis if axis is not None else (1.0, 0.0, 0.0)
        return cls(center=center, axis=ax, radius_m=geometry.radius_m if radius_m is None else radius_m,
                   s_edges=edges, blades=int(geometry.blades), spin=-int(geometry.rotation),
                   core_rel=core_rel, name=name if name is not None else getattr(geometry, "name", ""))


def element_edges(r_over_R, hub_fraction: float, tip: float = 1.0) -> np.ndarray:
    """Edges of the blade elements around BEMT stations ``r_over_R`` (increasing):
    midpoints between stations, the hub at ``hub_fraction`` and the tip at ``tip``."""
    r = np.asarray(r_over_R, dtype=float).ravel()
    if np.any(np.diff(r) <= 0):
        raise InputError("r_over_R", "stations must increase")
    if not (0 <= hub_fraction < r[0]) or r[-1] >= tip + 1e-12:
        raise InputError("hub_fraction", f"must lie below the first station {r[0]:g}, tip above the last")
    return np.concatenate([[hub_fraction], 0.5 * (r[1:] + r[:-1]), [tip]])
