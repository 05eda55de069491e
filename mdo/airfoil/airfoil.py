"""``Airfoil``: section cl, cd, cm at any alpha, Re, M for numbers and CasADi symbols."""
from __future__ import annotations

import re
from functools import lru_cache

import casadi as ca
import numpy as np

from ..core.errors import InputError, check_positive, check_range
from .catalog import CATALOG, normalize
from .data_io import camber_line, read_polar, thickness_camber
from .fit import FitSettings, SurrogateTables, fit_tables
from .model import ModelSettings, evaluate, post_stall_maxima

__all__ = ["Airfoil", "available"]

REFERENCE_REYNOLDS = 1.0e6


def available() -> list[str]:
    """Names accepted by :meth:`Airfoil.from_name` (airfoils whose polars are shipped)."""
    return sorted(k for k, e in CATALOG.items() if e.shipped)


class Airfoil:
    """Smooth section aerodynamics of one airfoil over the full circle of alpha.

    ``cl``, ``cd``, ``cm`` (about the quarter chord, nose-up positive) take
    ``alpha_rad`` [rad], ``reynolds`` [-] (chord-based, > 0) and ``mach`` [-]
    (default 0) as floats, NumPy arrays (broadcast together) or CasADi SX/MX
    expressions (elementwise; an MX call goes through one mapped SX Function).
    The model and its accuracy are described in ``mdo/airfoil/README.md`` and
    :mod:`mdo.airfoil.model`.
    """

    def __init__(self, key: str, title: str, tables: SurrogateTables, thickness_to_chord: float,
                 max_camber: float, polars: list, settings: ModelSettings = ModelSettings()):
        self.key = key
        self.name = key
        self.title = title
        self.tables = tables
        self.thickness_to_chord = float(thickness_to_chord)
        self.max_camber = float(max_camber)
        self.polars = polars
        self.settings = settings
        self.reynolds_range = (float(np.exp(tables.log_re[0])), float(np.exp(tables.log_re[-1])))
        self.cl2max, self.cd90 = post_stall_maxima(self.thickness_to_chord)
        self._function = None
        self._maps = {}
        self._alpha0 = {}
        self.coordinate_path = None   # set by the loaders
        self.spec = None              # SectionSpec of a generated section

    def __repr__(self):
        lo, hi = self.reynolds_range
        return (f"Airfoil({self.title!r}, t/c={self.thickness_to_chord:.3f}, "
                f"{len(self.polars)} polars Re {lo:.3g}-{hi:.3g})")

    # ------------------------------------------------------------------ loading
    @classmethod
    def from_name(cls, name: str) -> "Airfoil":
        """The shipped airfoil ``name`` (case, spaces, '-' and '_' ignored); see :func:`available`."""
        key = normalize(name)
        entry = CATALOG.get(key)
        if entry is not None and entry.shipped and "@" not in str(name):
            return _load(key)
        shipped_ncrit = _shipped_variant(name)
        if shipped_ncrit is not None:   # "clarky@ncrit=7": XFOIL polars at that Ncrit ship
            return _load(shipped_ncrit[0], shipped_ncrit[1])
        return cls.from_spec(name)

    @classmethod
    def from_spec(cls, spec) -> "Airfoil":
        """A generated section (``mdo.airfoil.generate``): a ``SectionSpec`` or its text form,
        e.g. ``"NACA 23012"``, ``"naca4412@ncrit=5"``, ``"clarky@xtr=0.1"`` (a shipped
        section's coordinates with another transition setting), ``"my.dat@ncrit=7"``.
        Polars come from NeuralFoil (cached); the fit and model are the shipped ones.  (A
        shipped section at an Ncrit whose XFOIL polars ship, ``"clarky@ncrit=7"``, is read
        from those by :meth:`from_name`.)"""
        from .generate import SectionSpec, parse_spec
        if not isinstance(spec, SectionSpec):
            text = str(spec)
            geom = text.split("@", 1)[0]
            entry = CATALOG.get(normalize(geom))
            # a shipped section is read from its coordinates unless its name is a valid NACA
            # 4- or 5-digit code (the 6-series "NACA_63_412" is not: 5-digit codes have 0/1 third)
            if entry is not None and entry.shipped and not re.fullmatch(r"naca(\d{4}|\d\d[01]\d\d)", normalize(geom)):
                # a shipped section with another transition setting: its own coordinates
                from .data_io import read_coordinates
                _, up, lo = read_coordinates(entry.coordinate_path)
                opts = parse_spec("naca0012" + (text[len(geom):] if "@" in text else ""))
                spec = SectionSpec(coordinates=tuple(map(tuple, np.vstack([up[::-1], lo[1:]]).round(7))),
                                   ncrit=opts.ncrit, xtr_upper=opts.xtr_upper, xtr_lower=opts.xtr_lower,
                                   title=entry.title)
            else:
                try:
                    spec = parse_spec(text)
                except InputError as exc:
                    raise InputError("airfoil", f"unknown airfoil {text!r}; available: {', '.join(available())}, "
                                                f"a NACA 4/5-digit code or a coordinate file ({exc.args[-1]})") from exc
        return _load_spec(spec)

    # ------------------------------------------------------------------ evaluation
    def coefficients(self, alpha_rad, reynolds, mach=0.0):
        """``(cl, cd, cm)`` together (one evaluation of the fitted surface and the blends)."""
        if any(isinstance(v, ca.MX) for v in (alpha_rad, reynolds, mach)):
            return self._call_mx(alpha_rad, reynolds, mach)
        if any(isinstance(v, ca.SX) for v in (alpha_rad, reynolds, mach)):
            return self._eval_sx(alpha_rad, reynolds, mach)
        as_dm = any(isinstance(v, ca.DM) for v in (alpha_rad, reynolds, mach))
        a, re_, m = (np.asarray(v, dtype=float) if not isinstance(v, ca.DM) else np.asarray(v.full())
                     for v in (alpha_rad, reynolds, mach))
        check_range("alpha_rad", a)
        check_positive("reynolds", re_)
        check_range("mach", m, 0.0, 0.95)
        a, re_, m = np.broadcast_arrays(a, re_, m)
        shape = a.shape
        out = evaluate(self.tables, self.thickness_to_chord, a.ravel(), re_.ravel(), m.ravel(),
                       np, a.size, self.settings)
        out = tuple(o.reshape(shape) for o in out)
        if as_dm:
            return tuple(ca.DM(o) for o in out)
        if shape == ():
            return tuple(float(o) for o in out)
        return out

    def cl(self, alpha_rad, reynolds, mach=0.0):
        """Lift coefficient [-]."""
        return self.coefficients(alpha_rad, reynolds, mach)[0]

    def cd(self, alpha_rad, reynolds, mach=0.0):
        """Drag coefficient [-] (profile + wave)."""
        return self.coefficients(alpha_rad, reynolds, mach)[1]

    def cm(self, alpha_rad, reynolds, mach=0.0):
        """Quarter-chord pitching-moment coefficient [-], nose-up positive."""
        return self.coefficients(alpha_rad, reynolds, mach)[2]

    def casadi_function(self) -> ca.Function:
        """Scalar SX Function ``airfoil_<key>(alpha_rad, reynolds, mach) -> (cl, cd, cm)``.

        Use ``.map(n)`` for n stations (inputs 1 x n), or call :meth:`coefficients`
        with SX symbols to inline the expressions into your own SX kernel.
        """
        if self._function is None:
            a, r, m = ca.SX.sym("alpha_rad"), ca.SX.sym("reynolds"), ca.SX.sym("mach")
            cl, cd, cm = evaluate(self.tables, self.thickness_to_chord, a, r, m, ca, 1, self.settings)
            self._function = ca.Function(f"airfoil_{self.key}", [a, r, m], [cl, cd, cm],
                                         ["alpha_rad", "reynolds", "mach"], ["cl", "cd", "cm"])
        return self._function

    # ------------------------------------------------------------------ derived numbers
    def zero_lift_angle(self, reynolds: float = REFERENCE_REYNOLDS, mach: float = 0.0) -> float:
        """alpha [rad] where cl = 0 at this Re and M (numeric root)."""
        key = (float(reynolds), float(mach))
        if key not in self._alpha0:
            from scipy.optimize import brentq
            self._alpha0[key] = brentq(lambda a: self.cl(a, reynolds, mach),
                                       np.radians(-10.0), np.radians(5.0), xtol=1e-10)
        return self._alpha0[key]

    def lift_slope(self, reynolds: float = REFERENCE_REYNOLDS, mach: float = 0.0) -> float:
        """dcl/dalpha [1/rad] of the linear range: least-squares slope over alpha_0 - 2 .. alpha_0 + 6 deg."""
        a0 = self.zero_lift_angle(reynolds, mach)
        a = a0 + np.radians(np.linspace(-2.0, 6.0, 33))
        return float(np.polyfit(a, self.cl(a, reynolds, mach), 1)[0])

    @property
    def alpha0_rad(self) -> float:
        """Zero-lift angle [rad] at Re = 1e6, M = 0."""
        return self.zero_lift_angle()

    @property
    def lift_slope_per_rad(self) -> float:
        """Linear-range lift slope [1/rad] at Re = 1e6, M = 0."""
        return self.lift_slope()

    def camber_line(self, x_over_c):
        """``(z/c, dz/dx)`` of the mean line at chord stations ``x/c`` (from the coordinates)."""
        return camber_line(self.coordinate_path, x_over_c)

    def best_lift_to_drag(self, reynolds: float = REFERENCE_REYNOLDS, mach: float = 0.0):
        """``(alpha_rad, cl, cd)`` at the maximum of cl/cd (a design point for Adkins-Liebeck)."""
        a = np.radians(np.linspace(-5.0, 20.0, 2001))
        cl, cd, _ = self.coefficients(a, reynolds, mach)
        i = int(np.argmax(cl / cd))
        return float(a[i]), float(cl[i]), float(cd[i])

    def cl_max(self, reynolds: float = REFERENCE_REYNOLDS, mach: float = 0.0):
        """``(alpha_rad, cl_max)``: the attached-flow maximum of the surrogate."""
        a = np.radians(np.linspace(0.0, 30.0, 3001))
        cl = self.cl(a, reynolds, mach)
        i = int(np.argmax(cl))
        return float(a[i]), float(cl[i])

    # ------------------------------------------------------------------ symbolic plumbing
    def _eval_sx(self, alpha, reynolds, mach):
        args = [v if isinstance(v, ca.SX) else ca.SX(ca.DM(np.asarray(v, dtype=float)))
                for v in (alpha, reynolds, mach)]
        shape, n, cols = _broadcast_columns(args, ca.SX)
        out = evaluate(self.tables, self.thickness_to_chord, *cols, ca, n, self.settings)
        return tuple(ca.reshape(o, *shape) for o in out)

    def _call_mx(self, alpha, reynolds, mach):
        args = [v if isinstance(v, ca.MX) else ca.MX(ca.DM(np.asarray(v, dtype=float)))
                if not isinstance(v, ca.SX) else None for v in (alpha, reynolds, mach)]
        if any(a is None for a in args):
            raise InputError("alpha_rad/reynolds/mach", "cannot mix SX and MX arguments")
        shape, n, cols = _broadcast_columns(args, ca.MX)
        if n not in self._maps:
            self._maps[n] = self.casadi_function() if n == 1 else self.casadi_function().map(n)
        res = self._maps[n](*(c.T for c in cols))
        return tuple(ca.reshape(o, *shape) for o in res)


def _broadcast_columns(args, kind):
    sizes = [a.numel() for a in args]
    n = max(sizes)
    shape = (1, 1)
    for a in args:
        if a.numel() == n:
            shape = a.shape
            break
    cols = []
    for a, k in zip(args, sizes):
        if k == n:
            cols.append(ca.vec(a))
        elif k == 1:
            cols.append(ca.repmat(a, n, 1))
        else:
            raise InputError("alpha_rad/reynolds/mach",
                             f"sizes must be 1 or a common n, got {sizes}")
    return shape, n, cols


_GENERATED: dict = {}


def _load_spec(spec) -> Airfoil:
    """Generate (or read cached) polars of ``spec``, fit them like the shipped ones."""
    from .generate import generate_polars
    if spec.key in _GENERATED:
        return _GENERATED[spec.key]
    paths = generate_polars(spec)
    polars = sorted((read_polar(p) for p in paths), key=lambda p: p.reynolds)
    coords = paths[0].parent / f"{spec.key}_coordinates.txt"
    tc, _, camber = thickness_camber(coords)
    tables = fit_tables(spec.key, polars, FitSettings())
    af = Airfoil(spec.key, spec.title or spec.key, tables, tc, camber, polars)
    af.coordinate_path = coords
    af.spec = spec
    _GENERATED[spec.key] = af
    return af


def _shipped_variant(name: str):
    """``(key, ncrit)`` when ``name`` is a shipped section with only ``@ncrit=N`` and XFOIL
    polars at that Ncrit ship (``AirfoilEntry.polar_paths(ncrit)``); else None (NeuralFoil)."""
    text = str(name)
    if "@" not in text:
        return None
    geom, opts = text.split("@", 1)
    entry = CATALOG.get(normalize(geom))
    if entry is None or not entry.shipped:
        return None
    from .generate import parse_spec
    spec = parse_spec("naca0012@" + opts)   # the options' own parser (and its errors)
    if spec.xtr_upper < 1.0 or spec.xtr_lower < 1.0:
        return None
    return (entry.key, spec.ncrit) if entry.polar_paths(spec.ncrit) else None


@lru_cache(maxsize=None)
def _load(key: str, ncrit: float | None = None) -> Airfoil:
    entry = CATALOG[key]
    polars = sorted((read_polar(p) for p in entry.polar_paths(ncrit)), key=lambda p: p.reynolds)
    tc, _, camber = thickness_camber(entry.coordinate_path)
    name = key if ncrit is None else f"{key}_ncrit{int(round(ncrit))}"   # a valid CasADi name
    tables = fit_tables(name, polars, FitSettings())
    af = Airfoil(name, entry.title + ("" if ncrit is None else f" (XFOIL, Ncrit {ncrit:g})"), tables, tc, camber,
                 polars)
    af.coordinate_path = entry.coordinate_path
    return af
