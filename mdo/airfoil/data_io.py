"""Readers for the airfoil data shipped in ``mdo/airfoil/data/``.

* XFOIL polar files (``PACC`` output): header, then columns
  ``alpha CL CD CDp CM Top_Xtr Bot_Xtr [Top_Itr Bot_Itr]``; Reynolds and Mach
  numbers are read from the ``Mach = ... Re = ... e 6`` header line.
* Coordinate files in Selig order (one loop from the trailing edge over the upper
  surface to the leading edge and back along the lower surface) or Lednicer order
  (a line with the two point counts, then upper and lower surfaces each from the
  leading edge).

These run only when an airfoil is loaded (never inside a symbolic expression).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..core.errors import InputError

DATA_DIR = Path(__file__).resolve().parent / "data"

__all__ = ["DATA_DIR", "Polar", "read_polar", "read_coordinates", "thickness_camber", "camber_line"]


@dataclass(frozen=True)
class Polar:
    """One XFOIL polar at fixed Reynolds and Mach number (angles in degrees)."""

    reynolds: float
    mach: float
    ncrit: float
    alpha_deg: np.ndarray
    cl: np.ndarray
    cd: np.ndarray
    cm: np.ndarray
    source: str


_RE_LINE = re.compile(
    r"Mach\s*=\s*([-\d.]+)\s+Re\s*=\s*([-\d.]+)\s*e\s*([-+]?\d+)\s+Ncrit\s*=\s*([-\d.]+)")


def read_polar(path) -> Polar:
    """Read an XFOIL polar file; points are sorted by angle, duplicates dropped."""
    path = Path(path)
    text = path.read_text().splitlines()
    reynolds = mach = ncrit = None
    rows = []
    in_table = False
    for line in text:
        m = _RE_LINE.search(line)
        if m:
            mach = float(m.group(1))
            reynolds = float(m.group(2)) * 10.0 ** int(m.group(3))
            ncrit = float(m.group(4))
            continue
        if line.strip().startswith("------"):
            in_table = True
            continue
        if in_table:
            parts = line.split()
            if len(parts) >= 5:
                try:
                    rows.append([float(p) for p in parts[:5]])
                except ValueError:
                    pass
    if reynolds is None or not rows:
        raise InputError(str(path), "not an XFOIL polar file (no 'Re =' header or no table)")
    data = np.array(rows)
    order = np.argsort(data[:, 0], kind="stable")
    data = data[order]
    keep = np.concatenate([[True], np.diff(data[:, 0]) > 1e-9])
    data = data[keep]
    return Polar(reynolds=reynolds, mach=mach, ncrit=ncrit, alpha_deg=data[:, 0],
                 cl=data[:, 1], cd=data[:, 2], cm=data[:, 4], source=path.name)


def read_coordinates(path):
    """Return ``(name, upper, lower)``: arrays of (x, y), each ordered from the leading edge."""
    path = Path(path)
    lines = [ln.strip() for ln in path.read_text().splitlines()]
    name = lines[0]
    pts = []
    for ln in lines[1:]:
        parts = ln.split()
        if len(parts) >= 2:
            try:
                pts.append((float(parts[0]), float(parts[1])))
            except ValueError:
                continue
    pts = np.array(pts)
    if pts[0, 0] > 1.5 and pts[0, 1] > 1.5:  # Lednicer: point counts first
        n_up, n_lo = int(pts[0, 0]), int(pts[0, 1])
        upper = pts[1:1 + n_up]
        lower = pts[1 + n_up:1 + n_up + n_lo]
    else:  # Selig: TE -> upper -> LE -> lower -> TE
        i_le = int(np.argmin(pts[:, 0]))
        upper = pts[:i_le + 1][::-1]
        lower = pts[i_le:]
    return name, upper, lower


def thickness_camber(path, n: int = 400):
    """Max thickness/chord, its chordwise station, and max camber/chord of a coordinate file."""
    _, upper, lower = read_coordinates(path)
    x = 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, n)))
    x0 = min(upper[:, 0].min(), lower[:, 0].min())
    x1 = max(upper[:, 0].max(), lower[:, 0].max())
    x = x0 + (x1 - x0) * x
    yu = np.interp(x, upper[:, 0], upper[:, 1])
    yl = np.interp(x, lower[:, 0], lower[:, 1])
    t = yu - yl
    i = int(np.argmax(t))
    chord = x1 - x0
    camber = 0.5 * (yu + yl)
    return float(t[i] / chord), float((x[i] - x0) / chord), float(camber.max() / chord)


def camber_line(path, x_over_c):
    """Mean line ``z/c`` and its slope ``dz/dx`` at stations ``x/c`` (chord from the
    coordinate file's leading to trailing edge); slope by central differences of a
    0.1 %-chord step, ends one-sided."""
    _, upper, lower = read_coordinates(path)
    x0 = min(upper[:, 0].min(), lower[:, 0].min())
    x1 = max(upper[:, 0].max(), lower[:, 0].max())
    c = x1 - x0

    def z(xc):
        x = x0 + c * np.clip(xc, 0.0, 1.0)
        return 0.5 * (np.interp(x, upper[:, 0], upper[:, 1]) + np.interp(x, lower[:, 0], lower[:, 1])) / c

    xc = np.asarray(x_over_c, dtype=float)
    h = 1e-3
    lo = np.clip(xc - h, 0.0, 1.0)
    hi = np.clip(xc + h, 0.0, 1.0)
    return z(xc), (z(hi) - z(lo)) / (hi - lo)
