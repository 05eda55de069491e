"""Blade geometry: definition stations, BEMT stations, CSV input and output.

A blade is defined at stations ``r/R`` (hub to tip) by chord ``c/R`` and blade
angle ``beta`` (the angle of the section's zero-reference line to the rotor
plane, the twist *including* the built-in pitch).  A collective pitch offset
``pitch_offset_rad`` (the paper's blade pitch command beta_c) is added to every
station at analysis time.

BEMT stations
-------------
The BEMT is evaluated at ``n`` stations that are the midpoints (in angle) of a
cosine-spaced set of panel edges between hub and tip,

    e_k = (1 - cos(pi k / n)) / 2,          k = 0..n,
    s_i = (1 - cos(pi (i + 1/2) / n)) / 2,  ds_i = e_{i+1} - e_i,
    r_i = R (h + (1 - h) s_i),              dr_i = R (1 - h) ds_i,

with h = R_hub/R.  No station sits on the hub or the tip, where the Prandtl
factors vanish; panels shrink towards both ends where the loading changes
fastest.  Integrals over the blade are the midpoint sums ``sum f(r_i) dr_i``.
Because ``s_i`` and ``ds_i`` are fixed numbers, ``R`` and ``h`` may be symbolic
(design variables) while the station layout stays the same.
"""
from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from ..core.errors import InputError

__all__ = [
    "RotorGeometry",
    "station_layout",
    "station_r_over_R",
    "station_edges_r_over_R",
    "placed_stations",
    "read_geometry_csv",
    "write_geometry_csv",
    "DATA_DIR",
]

DATA_DIR = Path(__file__).resolve().parent / "data"
GEOMETRY_COLUMNS = ("r_over_R", "c_over_R", "beta_deg")


def _twice_edges(n) -> np.ndarray:
    """``2 e_k = 1 - cos(pi k / n)``, k = 0..n: the panel edges, the one definition of the layout's
    spacing (the BEMT's stations and panel widths, the wake's ring edges)."""
    if int(n) != n or n < 2:
        raise InputError("n_stations", f"must be an integer >= 2, got {n!r}")
    return 1.0 - np.cos(np.pi * np.arange(int(n) + 1) / int(n))


def station_layout(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Nondimensional BEMT stations ``s_i`` in (0, 1) and panel widths ``ds_i`` (sum 1)."""
    edges = 0.5 * _twice_edges(n)
    n = int(n)
    s = 0.5 * (1.0 - np.cos(np.pi * (np.arange(n) + 0.5) / n))
    return s, np.diff(edges)


def station_edges_r_over_R(n: int, hub_fraction: float) -> np.ndarray:
    """r/R of the ``n + 1`` panel edges around the ``n`` BEMT stations, ``h + (1 - h) e_k``: the
    ring edges of the rotor's wake (``mdo.wake.WakeRotor.from_geometry``), so that each ring
    sheds the circulation of its own station."""
    return hub_fraction + (1.0 - hub_fraction) * 0.5 * _twice_edges(n)


def station_r_over_R(n: int, hub_fraction: float) -> np.ndarray:
    """r/R of the ``n`` BEMT stations of a blade whose hub is at ``hub_fraction`` R:
    ``h + (1 - h) s_i``."""
    return hub_fraction + (1.0 - hub_fraction) * station_layout(n)[0]


def placed_stations(sec, n: int, hub_fraction) -> np.ndarray | None:
    """r/R of the ``n`` stations at which a radial distribution of sections (``sec.spanwise``)
    is placed when a BEMT or Adkins-Liebeck graph is built for a rotor with this hub; None
    when no hub is given or the section does not vary along the blade."""
    if hub_fraction is None or not getattr(sec, "spanwise", False):
        return None
    return station_r_over_R(n, float(hub_fraction))


def _as_float_array(field_name: str, values) -> np.ndarray:
    try:
        a = np.asarray(values, dtype=float).ravel()
    except (TypeError, ValueError) as exc:
        raise InputError(field_name, f"must be numbers, got {values!r}") from exc
    if a.size == 0:
        raise InputError(field_name, "is empty")
    if not np.all(np.isfinite(a)):
        raise InputError(field_name, "must be finite numbers")
    return a


@dataclass
class RotorGeometry:
    """A rotor: blade definition plus the scalars that place and spin it.

    Attributes (SI):
        radius_m: tip radius R [m].
        blades: number of blades B.
        r_over_R, chord_over_R, beta_rad: definition stations (hub to tip).
        hub_fraction: R_hub / R (default: the first definition station).
        airfoil: section name (``mdo.airfoil``) or a section object with
            ``cl/cd(alpha_rad, reynolds, mach)``.
        t_over_c: thickness ratio per definition station (recorded, passed to
            no model yet: the section object carries its own thickness).
        rotation: +1 if the blades turn right-handed about the thrust direction
            (clockwise seen from behind the rotor, looking along the thrust, the
            usual "right-hand" tractor propeller), -1 for the opposite sense.
        pitch_offset_rad: collective pitch added to beta at every station.
        axis: thrust direction in the owner's frame (informational: the BEMT works
            in the rotor frame; the vehicle and the wake use it).
        name: label.
    """

    radius_m: float
    blades: int
    r_over_R: np.ndarray
    chord_over_R: np.ndarray
    beta_rad: np.ndarray
    hub_fraction: float | None = None
    airfoil: object = "clark_y"
    t_over_c: np.ndarray | None = None
    rotation: int = 1
    pitch_offset_rad: float = 0.0
    axis: tuple = (1.0, 0.0, 0.0)
    name: str = "rotor"
    _checked: bool = field(default=False, repr=False)

    def __post_init__(self):
        self.r_over_R = _as_float_array("r_over_R", self.r_over_R)
        self.chord_over_R = _as_float_array("c_over_R", self.chord_over_R)
        self.beta_rad = _as_float_array("beta", self.beta_rad)
        if self.hub_fraction is None:
            self.hub_fraction = float(self.r_over_R[0])
        if self.t_over_c is not None:
            self.t_over_c = _as_float_array("t_over_c", self.t_over_c)
        self.check()

    # ---------------------------------------------------------------- checks
    def check(self) -> None:
        """Raise ``InputError`` naming the field for any impossible geometry."""
        R = self.radius_m
        if not (isinstance(R, (int, float, np.floating, np.integer)) and math.isfinite(R) and R > 0):
            raise InputError("radius_m", f"must be a finite number > 0 m, got {R!r}")
        B = self.blades
        if not (isinstance(B, (int, np.integer)) or (isinstance(B, float) and B.is_integer())) or B < 1:
            raise InputError("blades", f"must be an integer >= 1, got {B!r}")
        self.blades = int(B)
        n = self.r_over_R.size
        if n < 2:
            raise InputError("r_over_R", f"needs at least 2 stations, got {n}")
        if self.chord_over_R.size != n or self.beta_rad.size != n:
            raise InputError("geometry", f"r_over_R, c_over_R and beta must have the same length "
                                         f"({n}, {self.chord_over_R.size}, {self.beta_rad.size})")
        if np.any(np.diff(self.r_over_R) <= 0):
            raise InputError("r_over_R", "must be strictly increasing from hub to tip")
        if self.r_over_R[0] <= 0 or self.r_over_R[-1] > 1.0 + 1e-9:
            raise InputError("r_over_R", f"allowed range (0, 1], got {self.r_over_R[0]:g}..{self.r_over_R[-1]:g}")
        if self.r_over_R[-1] < 0.9:
            raise InputError("r_over_R", f"the last station must reach at least 0.9 (the tip is r/R = 1), "
                                         f"got {self.r_over_R[-1]:g}")
        if np.any(self.chord_over_R <= 0):
            i = int(np.argmin(self.chord_over_R))
            raise InputError("c_over_R", f"must be > 0 at every station, got {self.chord_over_R[i]:g} "
                                         f"at r/R = {self.r_over_R[i]:g}")
        if np.any(np.abs(self.beta_rad) >= np.pi / 2):
            raise InputError("beta", "blade angles must lie in (-90, 90) deg")
        h = self.hub_fraction
        if not (isinstance(h, (int, float, np.floating)) and math.isfinite(h)):
            raise InputError("hub_fraction", f"must be a number, got {h!r}")
        if not (0.0 < h < 1.0):
            raise InputError("hub_fraction", f"hub radius must lie between 0 and the tip radius: allowed "
                                             f"(0, 1) of R, got {h:g}")
        if h >= self.r_over_R[-1]:
            raise InputError("hub_fraction", f"hub ({h:g} R) must lie inside the blade (last station "
                                             f"{self.r_over_R[-1]:g} R)")
        if self.rotation not in (1, -1):
            raise InputError("rotation", f"must be +1 or -1, got {self.rotation!r}")
        if not math.isfinite(self.pitch_offset_rad) or abs(self.pitch_offset_rad) >= np.pi / 2:
            raise InputError("pitch_offset", "must be finite and within (-90, 90) deg")

    # ------------------------------------------------------------ properties
    @property
    def diameter_m(self) -> float:
        return 2.0 * self.radius_m

    @property
    def hub_radius_m(self) -> float:
        return self.hub_fraction * self.radius_m

    def solidity(self) -> float:
        """Thrust-weighted (r^2) solidity ``B c_e / (pi R)``, c_e = 3 int c (r/R)^2 d(r/R)."""
        x, c = self.r_over_R, self.chord_over_R
        ce = 3.0 * np.trapezoid(c * x * x, x) if hasattr(np, "trapezoid") else 3.0 * np.trapz(c * x * x, x)
        return self.blades * ce / np.pi

    def beta75_rad(self) -> float:
        """Blade angle at 0.75 R (without the pitch offset)."""
        return float(self._interp(self.beta_rad, np.array([0.75]))[0])

    def pitch_reference_offset_rad(self, nominal_pitch_m: float, at_r_over_R: float = 0.75) -> float:
        """Collective offset [rad] that makes the geometric pitch ``2 pi r tan(beta)`` at
        ``at_r_over_R`` equal a stated (e.g. the maker's quoted) pitch:
        ``atan(P / (2 pi x R)) - beta(x)``.  Use with ``with_pitch`` when the tabulated
        blade angles and the quoted pitch disagree (they refer to different lines)."""
        if not (nominal_pitch_m > 0 and math.isfinite(nominal_pitch_m)):
            raise InputError("nominal_pitch", f"must be a finite number > 0 m, got {nominal_pitch_m!r}")
        if not (self.r_over_R[0] <= at_r_over_R <= self.r_over_R[-1]):
            raise InputError("at_r_over_R", f"must lie in the geometry's range "
                                            f"[{self.r_over_R[0]:g}, {self.r_over_R[-1]:g}], got {at_r_over_R}")
        beta = float(self._interp(self.beta_rad, np.array([at_r_over_R]))[0])
        return math.atan(nominal_pitch_m / (2.0 * math.pi * at_r_over_R * self.radius_m)) - beta

    def with_pitch(self, pitch_offset_rad: float) -> "RotorGeometry":
        return replace(self, pitch_offset_rad=float(pitch_offset_rad), _checked=False)

    # --------------------------------------------------------------- stations
    def _interp(self, values: np.ndarray, x: np.ndarray) -> np.ndarray:
        """Shape-preserving cubic (PCHIP) inside the definition range, constant outside."""
        from scipy.interpolate import PchipInterpolator

        xr = self.r_over_R
        xc = np.clip(x, xr[0], xr[-1])
        return PchipInterpolator(xr, values, extrapolate=False)(xc)

    def station_edges(self, n: int = 20) -> np.ndarray:
        """r/R of the panel edges around the ``n`` BEMT stations (:func:`station_edges_r_over_R`)."""
        return station_edges_r_over_R(n, self.hub_fraction)

    def stations(self, n: int = 20) -> dict:
        """Geometry at the ``n`` BEMT stations (see module docstring).

        Returns a dict with ``s``, ``ds`` (nondimensional layout), ``r_m``,
        ``dr_m``, ``chord_m``, ``beta_rad`` (twist without the pitch offset).
        """
        s, ds = station_layout(n)
        x = station_r_over_R(n, self.hub_fraction)
        chord = self._interp(self.chord_over_R, x) * self.radius_m
        beta = self._interp(self.beta_rad, x)
        return {
            "s": s, "ds": ds, "r_over_R": x,
            "r_m": x * self.radius_m,
            "dr_m": (1.0 - self.hub_fraction) * ds * self.radius_m,
            "chord_m": chord, "beta_rad": beta,
        }

    # -------------------------------------------------------------------- io
    @classmethod
    def from_csv(cls, path, *, diameter_m: float, blades: int, airfoil="clark_y",
                 hub_fraction: float | None = None, pitch_offset_rad: float = 0.0,
                 rotation: int = 1, name: str | None = None) -> "RotorGeometry":
        """Read ``r_over_R,c_over_R,beta_deg`` (optionally ``t_over_c``) from a CSV file."""
        if not (isinstance(diameter_m, (int, float)) and math.isfinite(diameter_m) and diameter_m > 0):
            raise InputError("diameter", f"must be a finite number > 0 m, got {diameter_m!r}")
        cols = read_geometry_csv(path)
        return cls(radius_m=0.5 * float(diameter_m), blades=blades, r_over_R=cols["r_over_R"],
                   chord_over_R=cols["c_over_R"], beta_rad=np.radians(cols["beta_deg"]),
                   hub_fraction=hub_fraction, airfoil=airfoil, t_over_c=cols.get("t_over_c"),
                   pitch_offset_rad=pitch_offset_rad, rotation=rotation,
                   name=name or Path(str(path)).stem)

    def to_csv(self, path=None) -> str:
        """Write the definition stations in the input format; returns the text."""
        return write_geometry_csv(path, self.r_over_R, self.chord_over_R, np.degrees(self.beta_rad),
                                  t_over_c=self.t_over_c)


def read_geometry_csv(path) -> dict:
    """Columns of a geometry CSV as float arrays; ``InputError`` for anything malformed."""
    p = Path(str(path))
    if not p.is_file():
        raise InputError("--geometry", f"file not found: {path}")
    try:
        text = p.read_text()
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError("--geometry", f"cannot read {path}: {exc}") from exc
    rows = [r for r in csv.reader(io.StringIO(text)) if r and any(c.strip() for c in r)
            and not r[0].lstrip().startswith("#")]
    if not rows:
        raise InputError("--geometry", f"{path} is empty")
    header = [h.strip() for h in rows[0]]
    missing = [c for c in GEOMETRY_COLUMNS if c not in header]
    if missing:
        raise InputError("--geometry", f"{path} must have the columns {','.join(GEOMETRY_COLUMNS)} "
                                       f"(missing {','.join(missing)}; found {','.join(header)})")
    wanted = list(GEOMETRY_COLUMNS) + (["t_over_c"] if "t_over_c" in header else [])
    idx = {c: header.index(c) for c in wanted}
    out = {c: [] for c in wanted}
    for line_no, row in enumerate(rows[1:], start=2):
        if len(row) < len(header):
            raise InputError("--geometry", f"{path} line {line_no}: expected {len(header)} values, got {len(row)}")
        for c in wanted:
            try:
                v = float(row[idx[c]])
            except ValueError as exc:
                raise InputError("--geometry", f"{path} line {line_no}: column {c} is not a number: "
                                               f"{row[idx[c]]!r}") from exc
            if not math.isfinite(v):
                raise InputError("--geometry", f"{path} line {line_no}: column {c} is not finite")
            out[c].append(v)
    if len(out["r_over_R"]) < 2:
        raise InputError("--geometry", f"{path} needs at least 2 stations")
    return {c: np.asarray(v) for c, v in out.items()}


def write_geometry_csv(path, r_over_R, c_over_R, beta_deg, t_over_c=None) -> str:
    buf = io.StringIO()
    cols = list(GEOMETRY_COLUMNS) + (["t_over_c"] if t_over_c is not None else [])
    buf.write(",".join(cols) + "\n")
    for i in range(len(r_over_R)):
        vals = [f"{r_over_R[i]:.6g}", f"{c_over_R[i]:.6g}", f"{beta_deg[i]:.6g}"]
        if t_over_c is not None:
            vals.append(f"{t_over_c[i]:.6g}")
        buf.write(",".join(vals) + "\n")
    text = buf.getvalue()
    if path is not None:
        Path(str(path)).write_text(text)
    return text
