"""Camber lines of wing sections, for placing the lattice on the mean line.

The vortex lattice follows the camber line (paper section III.A): bound vortices
and control points sit on it and the control-point normals are perpendicular to
its local slope.  Camber is a property of the section, not a design variable, so
it is evaluated here with NumPy at the fixed chordwise stations of the lattice and
scaled by the (possibly symbolic) chord in :mod:`mdo.wing.geometry`.

Sources of a camber line, by name (case and punctuation ignored):

* ``flat`` / ``none`` / any symmetric NACA section (``naca0012``,
  ``naca64(2)-015a`` ...): zero camber.
* NACA 4-digit ``naccMPTT``: the analytic mean line (Abbott & von Doenhoff 1959,
  section 6.2): ``z = m/p^2 (2 p x - x^2)`` for ``x < p``,
  ``z = m/(1-p)^2 (1 - 2p + 2 p x - x^2)`` aft.
* Coordinate files in ``mdo/wing/data/airfoils`` (Clark-Y, NACA 4412,
  NACA 63-412, Eppler E63; see ``data/SOURCES.md``): the mean of the upper and
  lower surfaces, least-squares fitted by ``z = x (1 - x) sum_k a_k x^k``
  (degree 6) so that the slope is smooth (on the 18-point NACA 4412 file the fit
  is within 2e-3 chord of the analytic mean line; 4-digit names use the analytic
  line).
* ``mdo.airfoil`` (issue 3), when it is installed and knows the name, only through
  its public ``Airfoil.from_name``: if that object exposes ``coordinates`` (N x 2,
  Selig order) the camber line is taken from them.
"""
from __future__ import annotations

import functools
import re
from importlib import resources

import numpy as np

from ..core.errors import InputError

__all__ = ["CamberLine", "camber_line", "known_camber_names"]

_FILES = {
    "clarky": "Clark_y.txt",
    "naca4412": "NACA_4412.txt",
    "naca63412": "NACA_63_412.txt",
    "e63": "E63.txt",
}


def _key(name: str) -> str:
    return re.sub(r"[^a-z0-9]", "", name.lower())


class CamberLine:
    """Mean line ``z/c`` and its slope as functions of ``x/c`` in [0, 1] (NumPy)."""

    def __init__(self, name: str, z, dz):
        self.name = name
        self._z = z
        self._dz = dz

    def z(self, x):
        return self._z(np.asarray(x, dtype=float))

    def slope(self, x):
        return self._dz(np.asarray(x, dtype=float))

    @property
    def is_flat(self) -> bool:
        xs = np.linspace(0, 1, 21)
        return bool(np.all(self.z(xs) == 0) and np.all(self.slope(xs) == 0))


def _flat(name="flat"):
    return CamberLine(name, lambda x: 0.0 * x, lambda x: 0.0 * x)


def _naca4(name, m, p):
    if m == 0 or p == 0:
        return _flat(name)

    def z(x):
        return np.where(x < p, m / p**2 * (2 * p * x - x**2),
                        m / (1 - p) ** 2 * (1 - 2 * p + 2 * p * x - x**2))

    def dz(x):
        return np.where(x < p, 2 * m / p**2 * (p - x), 2 * m / (1 - p) ** 2 * (p - x))

    return CamberLine(name, z, dz)


def _read_coordinates(text: str) -> np.ndarray:
    rows = []
    for line in text.splitlines():
        parts = line.split()
        if len(parts) != 2:
            continue
        try:
            rows.append((float(parts[0]), float(parts[1])))
        except ValueError:
            continue
    a = np.array(rows)
    if len(a) and a[0, 0] > 1.5:   # Lednicer header "N. N."
        a = a[1:]
    return a


def _split_surfaces(xy: np.ndarray):
    """Upper and lower surfaces, each sorted by x, from Selig or Lednicer order."""
    x = xy[:, 0]
    if x[0] < 0.5 * (x.min() + x.max()):   # Lednicer: upper LE->TE, then lower LE->TE
        jumps = np.where(np.diff(x) < 0)[0]
        k = jumps[0] + 1
        up, lo = xy[:k], xy[k:]
    else:                                    # Selig: TE->LE upper, LE->TE lower
        i_le = int(np.argmin(x))
        up, lo = xy[: i_le + 1][::-1], xy[i_le:]
    up = up[np.argsort(up[:, 0], kind="stable")]
    lo = lo[np.argsort(lo[:, 0], kind="stable")]
    if np.mean(up[:, 1]) < np.mean(lo[:, 1]):
        up, lo = lo, up
    return up, lo


def camber_from_coordinates(name: str, xy: np.ndarray, degree: int = 6) -> CamberLine:
    """Least-squares smooth mean line from airfoil coordinates (any chord, LE at min x)."""
    xy = np.asarray(xy, dtype=float)
    x0, x1 = xy[:, 0].min(), xy[:, 0].max()
    c = x1 - x0
    xy = np.column_stack([(xy[:, 0] - x0) / c, xy[:, 1] / c])
    up, lo = _split_surfaces(xy)
    xs = 0.5 * (1 - np.cos(np.linspace(0, np.pi, 81)))
    zu = np.interp(xs, up[:, 0], up[:, 1])
    zl = np.interp(xs, lo[:, 0], lo[:, 1])
    zte = 0.5 * (zu[-1] + zl[-1])
    zle = 0.5 * (zu[0] + zl[0])
    zc = 0.5 * (zu + zl) - (zle + (zte - zle) * xs)   # mean line relative to the chord line
    basis = np.column_stack([xs * (1 - xs) * xs**k for k in range(degree)])
    coef, *_ = np.linalg.lstsq(basis, zc, rcond=None)

    def z(x):
        return sum(a * x * (1 - x) * x**k for k, a in enumerate(coef))

    def dz(x):
        return sum(a * ((k + 1) * x**k - (k + 2) * x ** (k + 1)) for k, a in enumerate(coef))

    return CamberLine(name, z, dz)


def known_camber_names() -> list[str]:
    """Names with a camber line available without the airfoil package."""
    return sorted(_FILES) + ["flat", "naca4-digit (e.g. naca2412)", "symmetric NACA (e.g. naca0012)"]


@functools.lru_cache(maxsize=None)
def camber_line(name: str | None) -> CamberLine:
    """The camber line of section ``name`` (see module doc); ``InputError`` if unknown."""
    if name is None:
        return _flat()
    key = _key(str(name).split("@", 1)[0])   # the geometry; "@xtr=..." sets transition, not camber
    if key in ("", "flat", "none", "flatplate", "plate"):
        return _flat(key or "flat")
    m4 = re.fullmatch(r"naca(\d)(\d)(\d\d)", key)
    if m4:   # analytic mean line, exact (preferred to the 4412 coordinate file)
        return _naca4(key, int(m4.group(1)) / 100.0, int(m4.group(2)) / 10.0)
    if key in _FILES:
        text = (resources.files(__package__).joinpath("data").joinpath("airfoils")
                .joinpath(_FILES[key]).read_text())
        return camber_from_coordinates(key, _read_coordinates(text))
    if re.fullmatch(r"naca6\d\d?0\d\d[a-z]?", key) or re.fullmatch(r"naca00\d\d", key):
        return _flat(key)   # symmetric 6-series (e.g. 64(2)-015A) and 4-digit 00xx
    try:   # the airfoil discipline, if present and it exposes coordinates
        from ..airfoil import Airfoil  # noqa: WPS433 (optional dependency at run time)
        af = Airfoil.from_name(name)
        xy = getattr(af, "coordinates", None)
        if xy is not None:
            return camber_from_coordinates(key, np.asarray(xy))
    except (ImportError, ValueError, KeyError, AttributeError):
        pass
    raise InputError("airfoil", f"unknown section {name!r}; known: {', '.join(known_camber_names())}")
