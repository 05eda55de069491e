"""Lifting-surface geometry: segmented wings, tails and tandem wings, symbolic in the design.

A :class:`Surface` is a segmented wing described as the paper does (Fig. 12):
sections at fixed fractions ``eta`` of the semispan, each with a chord given as a
fraction of the root chord, a twist and an airfoil (camber line); straight
segments between sections with their own quarter-chord sweep and dihedral; an
incidence (plus, for a tilt wing, the wing-mounted angle ``tilt``) about a
spanwise axis; an origin; mirrored about the vehicle's symmetry plane or not
(vertical tails).  Every number may be a float or a CasADi expression (SX or MX):
span, root chord, chord fractions, twists, sweeps, dihedrals, incidence, tilt,
origin and extra strip boundaries (``breaks``, e.g. the edges of a propeller
slipstream whose position is a design variable).

Conventions (as AVL): body axes x aft, y right, z up; angles in rad.  ``span`` of
a mirrored surface is the projected tip-to-tip span (y extent), of an unmirrored
surface its root-to-tip extent (height of a vertical tail).  Sweep is that of
the quarter-chord line.  Sections are streamwise cuts (x-z planes of the
surface's own frame, as in SUAVE), so that the two halves of a mirrored surface
share their root section exactly even with dihedral; twist and incidence are
positive nose up, twist a rotation of the section in its plane about its
quarter-chord point (the quarter-chord line, hence the sweep, is unchanged by
twist).  With dihedral phi the twist seen normal to the surface is
atan(tan(twist) cos(phi)) (AVL's Ainc rotates about the inclined spanwise axis
instead: AVL's Ainc = atan(tan(twist) cos(phi))).
Geometry between sections is linear in ``eta`` (chord, twist, quarter-chord
point, dihedral angle of the section plane, camber line), as in AVL and SUAVE.

Reference area held constant (paper Eq. 7, Fig. 12): :func:`constant_area`
makes the chord fractions functions of the taper ratio and the root chord
``c_r = S / (b * integral f(eta) d eta)``, so span and taper change the
planform "proportionately" at fixed S.

Strip layout.  Spanwise strip boundaries run between *anchors*: the sections
(unless ``anchor_sections=False``) and the ``breaks``.  Each interval between
anchors gets cosine spacing (dense at both anchors; the interval that starts at
the root of a mirrored surface is half-cosine, dense only outboard, so that a
single-interval wing has full-span cosine spacing).  When an anchor is
symbolic, the geometry at the moving boundaries is interpolated through the
sections with a smooth hinge (the piecewise-linear interpolant written with
``softplus`` ramps of width ``eta_smoothing`` = 1e-3 semispan: exact away from
sections, off by at most 0.0007 x (slope change) at a section), so that IPOPT
never sees the kink of a piecewise-linear look-up.  Anchors are ordered by
their numeric value, or by ``break_nominal`` for symbolic breaks; the optimizer
must keep them ordered with bounds (a slipstream edge may not cross a section
that is an anchor; use ``anchor_sections=False`` to let it).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Sequence

import casadi as ca
import numpy as np

from ..core.errors import InputError
from ..core.errors import check_positive as _core_check_positive
from ..core.errors import check_range as _core_check_range
from ..core.smooth import is_symbolic
from .camber import camber_line

__all__ = [
    "Section", "Surface", "trapezoid", "constant_area", "planform_area",
    "mean_aerodynamic_chord", "aspect_ratio", "Params",
]

SPACINGS = ("cosine", "uniform", "sine")


# mdo.core's checks turn an SX scalar into NaN (np.asarray(SX) succeeds); skip expressions here
def check_positive(field, value, unit=""):
    if not isinstance(value, (ca.SX, ca.MX)):
        _core_check_positive(field, value, unit)


def check_range(field, value, lower=-np.inf, upper=np.inf, unit="", inclusive=True):
    if not isinstance(value, (ca.SX, ca.MX)):
        _core_check_range(field, value, lower, upper, unit, inclusive)


@dataclass
class Section:
    """One wing section.

    eta     : spanwise station, fraction of the semispan (0 root, 1 tip); a number.
    chord   : chord as a fraction of the surface's root chord (float or expression).
    twist   : rad, positive nose up, in the streamwise plane about the section's quarter chord.
    airfoil : name of the section (camber line, profile drag); None = surface default.
    """
    eta: float
    chord: Any = 1.0
    twist: Any = 0.0
    airfoil: str | None = None


@dataclass
class Surface:
    """A lifting surface (see module docstring for conventions).

    nspan : panels per semispan (int, distributed over the anchor intervals in
            proportion to their length) or a list with one count per interval.
    nchord: chordwise panels (uniform chordwise spacing, the 1/4-3/4 rule).
    core  : vortex-core size as a fraction of the local strip width (kernels.py).
    thickness_to_chord : only for the flat-plate profile-drag fallback (drag.py).
    """
    name: str
    span: Any
    root_chord: Any
    sections: Sequence[Section] = field(default_factory=lambda: [Section(0.0), Section(1.0)])
    sweep: Any = 0.0
    dihedral: Any = 0.0
    origin: Sequence[Any] = (0.0, 0.0, 0.0)
    incidence: Any = 0.0
    tilt: Any = 0.0
    pivot: Sequence[Any] = (0.0, 0.0, 0.0)
    mirrored: bool = True
    vertical: bool = False
    airfoil: str | None = None
    nspan: int | Sequence[int] = 16
    nchord: int = 1
    spacing: str = "cosine"
    breaks: Sequence[Any] = ()
    break_nominal: Sequence[float] | None = None
    anchor_sections: bool = True
    core: float = 0.05
    eta_smoothing: float = 1e-3
    thickness_to_chord: float = 0.12

    def __post_init__(self):
        self.sections = list(self.sections)
        if len(self.sections) < 2:
            raise InputError(f"{self.name}.sections", "need at least a root and a tip section")
        etas = [s.eta for s in self.sections]
        if any(is_symbolic(e) for e in etas):
            raise InputError(f"{self.name}.sections", "section eta must be numbers (use breaks for moving boundaries)")
        etas = np.array(etas, dtype=float)
        if abs(etas[0]) > 1e-12 or abs(etas[-1] - 1) > 1e-12 or np.any(np.diff(etas) <= 0):
            raise InputError(f"{self.name}.sections",
                             f"eta must increase strictly from 0 to 1, got {etas.tolist()}")
        check_positive(f"{self.name}.span", self.span, "m")
        check_positive(f"{self.name}.root_chord", self.root_chord, "m")
        for k, s in enumerate(self.sections):
            if k < len(self.sections) - 1:
                check_positive(f"{self.name}.sections[{k}].chord", s.chord)
            else:   # a pointed tip (elliptic planform) is allowed
                check_range(f"{self.name}.sections[{k}].chord", s.chord, 0.0, np.inf)
        nseg = len(self.sections) - 1
        for attr in ("sweep", "dihedral"):
            v = getattr(self, attr)
            vals = list(v) if isinstance(v, (list, tuple, np.ndarray)) else [v] * nseg
            if len(vals) != nseg:
                raise InputError(f"{self.name}.{attr}", f"need one value per segment ({nseg}), got {len(vals)}")
            for x in vals:
                check_range(f"{self.name}.{attr}", x, -np.radians(80), np.radians(80), "rad")
            setattr(self, attr, vals)
        if self.spacing not in SPACINGS:
            raise InputError(f"{self.name}.spacing", f"one of {SPACINGS}, got {self.spacing!r}")
        if int(self.nchord) < 1:
            raise InputError(f"{self.name}.nchord", f"must be >= 1, got {self.nchord}")
        self.nchord = int(self.nchord)
        check_range(f"{self.name}.core", self.core, 0.0, 0.5)
        if self.break_nominal is not None and len(self.break_nominal) != len(self.breaks):
            raise InputError(f"{self.name}.break_nominal", "one nominal value per break")
        for k, b in enumerate(self.breaks):
            if is_symbolic(b) and self.break_nominal is None:
                raise InputError(f"{self.name}.breaks", "symbolic breaks need break_nominal (for ordering)")
            if not is_symbolic(b):
                check_range(f"{self.name}.breaks[{k}]", b, 0.0, 1.0)

    @property
    def semispan(self):
        return self.span / 2 if self.mirrored else self.span

    @property
    def n_segments(self) -> int:
        return len(self.sections) - 1

    # --- layout ----------------------------------------------------------------
    def anchors(self) -> list[tuple[float, Any]]:
        """Strip-layout anchors as (nominal eta, value) sorted by nominal eta."""
        items = []
        if self.anchor_sections:
            items += [(float(s.eta), float(s.eta)) for s in self.sections]
        else:
            items += [(0.0, 0.0), (1.0, 1.0)]
        for k, b in enumerate(self.breaks):
            nom = float(self.break_nominal[k]) if self.break_nominal is not None else float(b)
            items.append((nom, b))
        items.sort(key=lambda t: t[0])
        out = []
        for nom, val in items:
            if out and abs(nom - out[-1][0]) < 1e-9:
                if is_symbolic(val):   # a symbolic break replaces a coincident number
                    out[-1] = (nom, val)
                continue
            out.append((nom, val))
        return out

    def panel_counts(self) -> list[int]:
        anchors = self.anchors()
        lengths = np.diff([a[0] for a in anchors])
        n_int = len(lengths)
        if isinstance(self.nspan, (list, tuple, np.ndarray)):
            counts = [int(n) for n in self.nspan]
            if len(counts) != n_int or min(counts) < 1:
                raise InputError(f"{self.name}.nspan",
                                 f"need {n_int} counts >= 1 (one per interval between anchors), got {counts}")
            return counts
        n = int(self.nspan)
        if n < n_int:
            raise InputError(f"{self.name}.nspan", f"need at least {n_int} panels (one per interval), got {n}")
        raw = lengths / lengths.sum() * n
        counts = np.maximum(1, np.floor(raw)).astype(int)
        while counts.sum() < n:
            counts[np.argmax(raw - counts)] += 1
        while counts.sum() > n:
            i = np.argmax(np.where(counts > 1, counts - raw, -np.inf))
            counts[i] -= 1
        return counts.tolist()

    def spacing_fractions(self, n: int, starts_at_root: bool) -> np.ndarray:
        j = np.arange(n + 1) / n
        if self.spacing == "uniform":
            return j
        if self.spacing == "sine" or (starts_at_root and self.mirrored):
            return np.sin(0.5 * np.pi * j)
        return 0.5 * (1 - np.cos(np.pi * j))


# --- constructors -------------------------------------------------------------------
def trapezoid(name: str, span, root_chord, taper=1.0, sweep=0.0, dihedral=0.0,
              twist_root=0.0, twist_tip=0.0, airfoil=None, **kw) -> Surface:
    """Single-segment (trapezoidal) surface: chord fraction ``taper`` and ``twist_tip`` at the tip."""
    check_range(f"{name}.taper", taper, 0.0, 2.0, inclusive=True)
    if not is_symbolic(taper) and float(taper) <= 0:
        raise InputError(f"{name}.taper", f"allowed range (0, 2], got {float(taper):g}")
    secs = [Section(0.0, 1.0, twist_root, airfoil), Section(1.0, taper, twist_tip, airfoil)]
    return Surface(name, span, root_chord, secs, sweep=sweep, dihedral=dihedral, airfoil=airfoil, **kw)


def constant_area(name: str, area, span, taper, twists, eta=None, chord_fractions=None,
                  airfoil=None, **kw) -> Surface:
    """Surface at fixed planform ``area`` (paper Fig. 12, Eq. 7: S_ref constant).

    twists          : one twist (rad) per section; sections at ``eta`` (default
                      equally spaced, e.g. 5 sections for the GA wing of Table 3).
    chord_fractions : chord/root chord per section; default the straight taper
                      ``f_k = 1 - (1 - taper) eta_k``; may be a callable ``f(taper)``
                      returning the list (e.g. a cranked planform scaled with taper).
    The root chord is ``c_r = area / (span_factor * semispan * integral f d eta)``
    (trapezoidal rule over the sections, exact for linear segments).
    """
    twists = list(twists)
    if eta is None:
        eta = np.linspace(0.0, 1.0, len(twists))
    eta = [float(e) for e in eta]
    if len(eta) != len(twists):
        raise InputError(f"{name}.twists", f"need one twist per section ({len(eta)}), got {len(twists)}")
    if callable(chord_fractions):
        fr = list(chord_fractions(taper))
    elif chord_fractions is None:
        fr = [1.0 - (1.0 - taper) * e for e in eta]
    else:
        fr = list(chord_fractions)
    mirrored = kw.get("mirrored", True)
    semispan = span / 2 if mirrored else span
    integral = sum(0.5 * (fr[k] + fr[k + 1]) * (eta[k + 1] - eta[k]) for k in range(len(eta) - 1))
    factor = 2.0 if mirrored else 1.0
    root_chord = area / (factor * semispan * integral)
    secs = [Section(e, f, t, airfoil) for e, f, t in zip(eta, fr, twists)]
    return Surface(name, span, root_chord, secs, airfoil=airfoil, **kw)


# --- planform quantities (symbolic-capable) -------------------------------------------
def _chords(s: Surface):
    return [s.root_chord * sec.chord for sec in s.sections]


def planform_area(s: Surface):
    """Projected planform area (m^2), both halves of a mirrored surface."""
    c = _chords(s)
    eta = [sec.eta for sec in s.sections]
    half = sum(0.5 * (c[k] + c[k + 1]) * (eta[k + 1] - eta[k]) for k in range(len(c) - 1)) * s.semispan
    return 2 * half if s.mirrored else half


def mean_aerodynamic_chord(s: Surface):
    """MAC = (1/S) integral c^2 dy over the surface (m); exact for linear segments."""
    c = _chords(s)
    eta = [sec.eta for sec in s.sections]
    half = sum((c[k] ** 2 + c[k] * c[k + 1] + c[k + 1] ** 2) / 3 * (eta[k + 1] - eta[k])
               for k in range(len(c) - 1)) * s.semispan
    area = planform_area(s)
    return (2 * half if s.mirrored else half) / area


def aspect_ratio(s: Surface):
    """span^2 / planform area (for an unmirrored fin: height^2 / area)."""
    return s.span * s.span / planform_area(s)


# --- parameters: numbers stay constants, expressions become inputs ---------------------
class Params:
    """Collects the symbolic values of a vehicle description.

    ``p(value, name)`` returns a float for numbers, or a new SX placeholder for a
    CasADi expression (remembering the expression), so that the lattice is built
    once as an SX Function of the placeholders and called with the expressions.
    """

    def __init__(self):
        self.symbols: list[ca.SX] = []
        self.values: list = []
        self.names: list[str] = []

    def __call__(self, value, name: str):
        if isinstance(value, ca.DM):
            value = np.array(value)
        if isinstance(value, (ca.SX, ca.MX)):
            if value.numel() != 1:
                raise InputError(name, "expected a scalar expression")
            sym = ca.SX.sym(name)
            self.symbols.append(sym)
            self.values.append(value)
            self.names.append(name)
            return sym
        a = np.asarray(value, dtype=float)
        if a.size != 1:
            raise InputError(name, "expected a scalar")
        return float(a)

    @property
    def sx(self) -> ca.SX:
        return ca.vertcat(*self.symbols) if self.symbols else ca.SX(0, 1)

    def value_vector(self):
        """The expressions (or numbers) the placeholders stand for, as one column."""
        if not self.values:
            return ca.DM(0, 1)
        if any(isinstance(v, ca.MX) for v in self.values):
            return ca.vertcat(*[v if isinstance(v, ca.MX) else ca.MX(v) for v in self.values])
        return ca.vertcat(*self.values)


# --- interpolation weights ------------------------------------------------------------------
def _pl_basis_matrix(knots: np.ndarray) -> np.ndarray:
    """L with f(eta) = (L f) . [1, eta-k0, ramp(eta-k1), ..., ramp(eta-k_{n-2})]."""
    n = len(knots)
    h = np.diff(knots)
    L = np.zeros((n, n))
    L[0, 0] = 1.0
    slope = np.zeros((n - 1, n))
    for k in range(n - 1):
        slope[k, k] = -1.0 / h[k]
        slope[k, k + 1] = 1.0 / h[k]
    L[1] = slope[0]
    for k in range(1, n - 1):
        L[k + 1] = slope[k] - slope[k - 1]
    return L


def interpolation_weights(eta, knots: Sequence[float], smoothing: float):
    """Weights w (list, len(knots)) with value(eta) = sum w_k value_k, piecewise linear.

    Numeric eta: the exact piecewise-linear weights.  Symbolic eta: the same
    interpolant with each ramp max(x, 0) replaced by w*log(1 + exp(x/w)),
    w = ``smoothing`` (C-infinity in eta).
    """
    knots = np.asarray(knots, dtype=float)
    n = len(knots)
    if not is_symbolic(eta):
        e = float(eta)
        w = np.zeros(n)
        k = int(np.clip(np.searchsorted(knots, e, side="right") - 1, 0, n - 2))
        t = (e - knots[k]) / (knots[k + 1] - knots[k])
        w[k], w[k + 1] = 1 - t, t
        return [float(x) for x in w]
    L = _pl_basis_matrix(knots)
    basis = [1.0, eta - knots[0]]
    for k in range(1, n - 1):
        x = (eta - knots[k]) / smoothing
        basis.append(smoothing * (ca.fmax(x, 0) + ca.log1p(ca.exp(-ca.fabs(x)))))
    return [sum(L[i, k] * basis[i] for i in range(n) if L[i, k] != 0) for k in range(n)]
