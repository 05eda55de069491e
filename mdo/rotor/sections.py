"""Section aerodynamics seen by the rotor.

The BEMT takes any object with ``cl(alpha_rad, reynolds, mach)`` and
``cd(alpha_rad, reynolds, mach)`` that works elementwise on floats, NumPy arrays
and CasADi SX/MX (the interface of ``mdo.airfoil.Airfoil``).  ``section(name)``
returns the airfoil surrogate of that name; ``AnalyticSection`` is a closed-form
section (thin-airfoil lift, smooth stall to a flat plate) for tests and for
checks that must not depend on polar data.
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from ..core.errors import InputError
from ..core.smooth import sigmoid, smooth_abs, smooth_max, softplus, xp

__all__ = ["AnalyticSection", "SpanwiseBlend", "SpanwiseSections", "RotationalAugmentation", "section",
           "available_sections", "STALL_DELAY_MODELS"]


class AnalyticSection:
    """Thin-airfoil lift with a smooth stall into flat-plate behaviour.

    Pre-stall (attached flow), with the Prandtl-Glauert factor
    ``beta_M = sqrt(max(1 - M^2, 0.1))`` (corner rounded over 0.02):

        cl_att = a0 (alpha - alpha0) / beta_M,    cd_att = cd0 + k cl_att^2

    Post-stall, a flat plate (Hoerner): ``cl_fp = cd90 sin a cos a``,
    ``cd_fp = cd0 + cd90 sin^2 a``.  The two are blended with the logistic weight
    ``w = sigmoid((|alpha - alpha0| - alpha_stall) / width)`` (|.| smoothed over
    0.01 rad), so value and every derivative are continuous.  ``cm`` is a
    constant.  Defaults: a0 = 2 pi, alpha0 = 0, cd0 = 0.01, k = 0.01,
    alpha_stall = 14 deg, width = 2 deg, cd90 = 2.0.
    """

    def __init__(self, lift_slope=2 * math.pi, alpha0_rad=0.0, cd0=0.01, k_drag=0.01,
                 alpha_stall_rad=math.radians(14.0), stall_width_rad=math.radians(2.0),
                 cd90=2.0, cm0=0.0, mach_correction=True, name="analytic"):
        self.lift_slope = float(lift_slope)
        self.alpha0_rad = float(alpha0_rad)
        self.cd0 = float(cd0)
        self.k_drag = float(k_drag)
        self.alpha_stall_rad = float(alpha_stall_rad)
        self.stall_width_rad = float(stall_width_rad)
        self.cd90 = float(cd90)
        self.cm0 = float(cm0)
        self.mach_correction = bool(mach_correction)
        self.name = name

    def _parts(self, alpha, mach):
        lib = xp(alpha, mach)
        if self.mach_correction:
            beta = lib.sqrt(smooth_max(1.0 - mach * mach, 0.1, 0.02))
        else:
            beta = 1.0
        cl_att = self.lift_slope * (alpha - self.alpha0_rad) / beta
        w = sigmoid(smooth_abs(alpha - self.alpha0_rad, 0.01) - self.alpha_stall_rad, self.stall_width_rad)
        return lib, cl_att, w

    def cl(self, alpha, reynolds=1e6, mach=0.0):
        lib, cl_att, w = self._parts(alpha, mach)
        cl_fp = self.cd90 * lib.sin(alpha) * lib.cos(alpha)
        return (1.0 - w) * cl_att + w * cl_fp

    def cd(self, alpha, reynolds=1e6, mach=0.0):
        lib, cl_att, w = self._parts(alpha, mach)
        cd_att = self.cd0 + self.k_drag * cl_att * cl_att
        cd_fp = self.cd0 + self.cd90 * lib.sin(alpha) ** 2
        return (1.0 - w) * cd_att + w * cd_fp

    def cm(self, alpha, reynolds=1e6, mach=0.0):
        return 0.0 * alpha + self.cm0

    def __repr__(self):
        return (f"AnalyticSection(a0={self.lift_slope:.4g}, alpha0={math.degrees(self.alpha0_rad):.3g} deg, "
                f"cd0={self.cd0:g}, k={self.k_drag:g}, stall={math.degrees(self.alpha_stall_rad):.3g} deg)")


class SpanwiseBlend:
    """Two sections blended along the blade: ``inner`` inboard, ``outer`` outboard.

    ``c = (1 - w) c_inner + w c_outer`` with ``w = sigmoid((x - x_mid)/width)``,
    ``x = r/R`` (C-infinity; w = 0.018 / 0.982 at x_mid -+ 4 width).  The BEMT
    passes ``x`` through ``coefficients(alpha, Re, M, x)`` (``spanwise = True``).
    APC's thin-electric propellers, for instance, blend the low-Reynolds E63
    inboard into a Clark-Y-like section outboard (apcprop.com, "Engineering").
    """

    spanwise = True

    def __init__(self, inner, outer, x_mid: float = 0.5, width: float = 0.05):
        if not (0.0 < x_mid < 1.0) or not (width > 0):
            raise InputError("airfoil", f"blend position must lie in (0, 1) and width > 0, got {x_mid}, {width}")
        self.inner, self.outer = inner, outer
        self.x_mid, self.width = float(x_mid), float(width)
        self.name = f"{getattr(inner, 'name', inner)}:{x_mid:g}:{getattr(outer, 'name', outer)}"
        self.alpha0_rad = 0.5 * (float(getattr(inner, "alpha0_rad", 0.0)) + float(getattr(outer, "alpha0_rad", 0.0)))

    def weight(self, x):
        return sigmoid(x - self.x_mid, self.width)

    def coefficients(self, alpha, reynolds, mach=0.0, x=0.5):
        w = self.weight(x)
        a = _coefficients(self.inner, alpha, reynolds, mach)
        b = _coefficients(self.outer, alpha, reynolds, mach)
        return tuple((1.0 - w) * ai + w * bi for ai, bi in zip(a, b))

    def cl(self, alpha, reynolds, mach=0.0, x=0.5):
        return self.coefficients(alpha, reynolds, mach, x)[0]

    def cd(self, alpha, reynolds, mach=0.0, x=0.5):
        return self.coefficients(alpha, reynolds, mach, x)[1]

    def __repr__(self):
        return f"SpanwiseBlend({self.inner!r} -> {self.outer!r} at r/R = {self.x_mid:g})"


class SpanwiseSections:
    """Any number of sections along the blade: ``[(x_0, sec_0), (x_1, sec_1), ...]``
    with ``x = r/R`` increasing.  Between two neighbours the weight moves smoothly
    from one to the next: ``c = sum_k w_k c_k``, ``w_k = s_k - s_{k+1}``,
    ``s_k = sigmoid((x - (x_{k-1} + x_k)/2)/width)`` (``s_0 = 1``, ``s_K = 0``), a
    C-infinity partition of unity; section k is (to within 2 %) pure at its own
    station when neighbours are 8 widths apart.  Thickness varies along the blade
    by naming sections of different thickness (e.g. NACA 4418 at the root, 4409
    at the tip).  Text form: ``"naca4418:0.3:naca4412:0.8:naca4409"`` puts the
    section changes (the mid-points) at r/R = 0.3 and 0.8.
    """

    spanwise = True
    # stations known when the graph is built (``_coefficients_at``): weights below this
    # are dropped (a change of the blend by at most 1e-6 of the neighbours' difference)
    WEIGHT_FLOOR = 1e-6

    def __init__(self, sections, changes, width: float = 0.05):
        sections, changes = list(sections), [float(c) for c in changes]
        if len(sections) != len(changes) + 1 or not sections:
            raise InputError("airfoil", "need one more section than change positions")
        if any(not (0.0 < c < 1.0) for c in changes) or any(b <= a for a, b in zip(changes, changes[1:])):
            raise InputError("airfoil", f"section change positions r/R must increase inside (0, 1), got {changes}")
        if not width > 0:
            raise InputError("airfoil", f"blend width must be > 0, got {width}")
        self.sections, self.changes, self.width = sections, changes, float(width)
        parts = [str(getattr(sections[0], "name", sections[0]))]
        for c, sec in zip(changes, sections[1:]):
            parts += [f"{c:g}", str(getattr(sec, "name", sec))]
        self.name = ":".join(parts) + ("" if self.width == 0.05 else f";width={self.width:g}")
        self.alpha0_rad = float(np.mean([float(getattr(sc, "alpha0_rad", 0.0)) for sc in sections]))

    def weights(self, x):
        s = [1.0] + [sigmoid(x - c, self.width) for c in self.changes] + [0.0]
        return [s[k] - s[k + 1] for k in range(len(self.sections))]

    def coefficients(self, alpha, reynolds, mach=0.0, x=0.5):
        if _numeric(x):
            return self._coefficients_at(alpha, reynolds, mach, np.asarray(x.full() if isinstance(x, ca.DM) else x,
                                                                           float))
        out = None
        for w, sec in zip(self.weights(x), self.sections):
            c = _coefficients(sec, alpha, reynolds, mach)
            out = [w * ci for ci in c] if out is None else [o + w * ci for o, ci in zip(out, c)]
        return tuple(out)

    def station_weights(self, x) -> np.ndarray:
        """Weights (sections x stations) at numeric ``x = r/R``: below ``WEIGHT_FLOOR``
        dropped, the rest renormalised to sum 1."""
        xs = np.atleast_1d(np.asarray(x, float)).ravel()
        w = np.array([np.broadcast_to(np.asarray(wk, float), xs.shape) for wk in self.weights(xs)])
        w[w < self.WEIGHT_FLOOR] = 0.0
        return w / w.sum(axis=0)

    def _coefficients_at(self, alpha, reynolds, mach, x):
        """The blend at stations whose ``x`` is known when the graph is built (a BEMT or
        Adkins-Liebeck Function given its hub fraction): each section is evaluated only at
        the elements where it carries weight, so a blade of K sections costs about one
        section call per element, not K.  ``x`` has one entry per element (or one for all)."""
        w = self.station_weights(x)
        symbolic = any(isinstance(v, (ca.SX, ca.MX)) for v in (alpha, reynolds, mach))
        if w.shape[1] == 1 or not symbolic:
            out = None
            for wk, sec in zip(w, self.sections):
                if not wk.any():
                    continue
                # several stations only with numeric alpha (np.ndim on a CasADi value warns)
                wk = wk[0] if wk.size == 1 else wk.reshape((-1,) + (1,) * max(np.ndim(alpha) - 1, 0))
                c = _coefficients(sec, alpha, reynolds, mach)
                out = [wk * ci for ci in c] if out is None else [o + wk * ci for o, ci in zip(out, c)]
            return tuple(out)
        n_el = w.shape[1]
        pick = (lambda v, idx: v[idx] if isinstance(v, (ca.SX, ca.MX)) and v.numel() == n_el else v)
        acc = None
        for wk, sec in zip(w, self.sections):
            idx = [int(i) for i in np.nonzero(wk)[0]]
            if not idx:
                continue
            c = _coefficients(sec, pick(alpha, idx), pick(reynolds, idx), pick(mach, idx))
            if acc is None:
                acc = [[0.0] * n_el for _ in c]
            for j, cj in enumerate(c):
                for jj, i in enumerate(idx):
                    acc[j][i] = acc[j][i] + wk[i] * (cj[jj] if cj.numel() > 1 else cj)
        return tuple(ca.vertcat(*a) for a in acc)

    def cl(self, alpha, reynolds, mach=0.0, x=0.5):
        return self.coefficients(alpha, reynolds, mach, x)[0]

    def cd(self, alpha, reynolds, mach=0.0, x=0.5):
        return self.coefficients(alpha, reynolds, mach, x)[1]

    def linear_lift(self, x):
        """(alpha0 [rad], lift slope [1/rad]) at r/R = x (Re 1e6 values, weighted)."""
        a0 = sl = 0.0
        for w, sec in zip(self.weights(x), self.sections):
            a, b = _linear_lift(sec)
            a0, sl = a0 + w * a, sl + w * b
        return a0, sl

    def __repr__(self):
        return f"SpanwiseSections({self.name})"


STALL_DELAY_MODELS = ("snel", "du_selig")


class RotationalAugmentation:
    """Rotational stall delay of a rotating blade section (lift only).

    ``cl_3D = cl_2D + f g sp(cl_lin - cl_2D)`` (sp: softplus of width 0.02, i.e. only
    where the 2-D lift has fallen below the linear one: stall delay), with the linear
    (potential-flow) lift ``cl_lin = cl_2D(alpha_r) + a (alpha - alpha_r)`` anchored to
    the 2-D polar at ``alpha_r = alpha0 + 5 deg`` (attached at every Re, so the low-Re
    zero-lift shift is not mistaken for stall), and

    * Snel (Snel, Houwink & Bosschers 1994, ECN-C--93-052; Snel et al., EWEC 1993):
      ``f = 3 (c/r)^2``;
    * Du & Selig (AIAA 98-0021, 1998), with ``Lambda = Omega R / sqrt(V^2 + (Omega R)^2)``
      and their a = b = d = 1:
      ``f = 1/(2 pi) [1.6 (c/r)/0.1267 (1 - (c/r)^(R/(Lambda r))) / (1 + (c/r)^(R/(Lambda r))) - 1]``.

    ``f`` is limited smoothly to [0, 1] (``f - sp(f - 1)``, softplus width 0.05,
    and ``sp(f)`` of width 0.01 below, a floor of 0.007: inboard of props c/r exceeds 0.5 where Snel's fit was never
    meant to go).  ``g = sigmoid((alpha_end - (alpha - alpha0))/2 deg)`` with
    alpha_end = 30 deg fades the correction back to the 2-D (plate) values in deep
    stall, where the rotational boundary layer no longer adds lift; below alpha_r
    nothing is augmented (``g`` times ``sigmoid((alpha - alpha_r)/1 deg)``).  alpha0, a: the
    section's Re = 1e6 linear-range values.  The BEMT passes ``c/r`` and the tip-speed ratio.

    **Drag** (``drag="normal"``, default): the augmentation is a normal force.  The delayed
    separation restores suction over the aft upper surface, whose pressure acts normal to
    the chord; measured 3-D pressure distributions show the rotational increment in the
    normal-force coefficient, with the chordwise one small (Bak, Johansen & Andersen,
    "Three-dimensional corrections of airfoil characteristics based on pressure
    distributions", EWEC 2006: ``dcl = dCn cos(alpha) + dCt sin(alpha)``, ``dcd = dCn sin(alpha)
    - dCt cos(alpha)``).  With ``dCt = 0`` the lift increment ``dcl`` carries the drag
    ``dcd = dcl tan(alpha)``.  Measured: on both APC Thin Electric props it moves the static
    power from 6-9 % low to within 2-4 % (``results/validation/apc*_summary.md``).
    ``drag="2d"`` leaves the drag 2-D (Snel's and Du & Selig's own cd corrections are small
    and of uncertain sign), as before 2026-12-05.
    """

    spanwise = True
    rotational = True

    def __init__(self, sec, model: str = "snel", alpha_end_rad: float = math.radians(30.0), drag: str = "normal"):
        if model not in STALL_DELAY_MODELS:
            raise InputError("stall_delay", f"must be one of {', '.join(STALL_DELAY_MODELS)}, got {model!r}")
        if drag not in ("normal", "2d"):
            raise InputError("stall_delay drag", f"'normal' or '2d', got {drag!r}")
        self.sec, self.model, self.alpha_end_rad, self.drag = sec, model, float(alpha_end_rad), drag
        self.anchor_rad = math.radians(5.0)
        self.name = f"{getattr(sec, 'name', sec)}+{model}"
        self.alpha0_rad = float(getattr(sec, "alpha0_rad", 0.0))

    def factor(self, c_over_r, x=0.5, tip_speed_ratio=1.0):
        if self.model == "snel":
            f = 3.0 * c_over_r * c_over_r
        else:
            e = c_over_r ** (1.0 / (tip_speed_ratio * x))
            f = (1.6 * c_over_r / 0.1267 * (1.0 - e) / (1.0 + e) - 1.0) / (2.0 * math.pi)
        f = softplus(f, 0.01)
        return f - softplus(f - 1.0, 0.05)

    def coefficients(self, alpha, reynolds, mach=0.0, x=0.5, c_over_r=0.0, tip_speed_ratio=1.0):
        cl, cd = section_coefficients(self.sec, alpha, reynolds, mach, x)
        # the linear lift is anchored to the 2-D section itself at alpha0 + 5 deg (attached at
        # every Re), so that the low-Re zero-lift shift of the polar is not "augmented"; the
        # anchor cl(alpha_r, Re) is a 1-D spline in ln Re per section (cheap, see _Anchor)
        a0, cl_lin = _linear_lift_anchored(self.sec, alpha, reynolds, mach, x, self.anchor_rad)
        d = alpha - a0
        g = sigmoid(self.alpha_end_rad - d, math.radians(2.0)) * sigmoid(d - self.anchor_rad, math.radians(1.0))
        f = self.factor(c_over_r, x, tip_speed_ratio)
        dcl = f * g * softplus(cl_lin - cl, 0.02)
        if self.drag == "2d":
            return cl + dcl, cd
        # a normal-force increment (Bak et al. 2006, dCt = 0): dcd = dcl tan(alpha); g fades it
        # out by alpha0 + 30 deg, so tan stays finite where dcl is not zero
        return cl + dcl, cd + dcl * xp(alpha).tan(alpha)

    def cl(self, alpha, reynolds, mach=0.0, x=0.5):
        return self.coefficients(alpha, reynolds, mach, x)[0]

    def cd(self, alpha, reynolds, mach=0.0, x=0.5):
        return self.coefficients(alpha, reynolds, mach, x)[1]

    def __repr__(self):
        return f"RotationalAugmentation({self.sec!r}, {self.model}, drag={self.drag})"


def _numeric(x) -> bool:
    """True when ``x`` is a number or a NumPy array (not a CasADi expression)."""
    return isinstance(x, (int, float, np.ndarray, np.number, ca.DM))


class _Anchor:
    """``cl(alpha0 + anchor, Re, M = 0)`` of one (non-blended) section as a cubic
    B-spline in ln Re on 41 points over Re 1e3..1e8 (one call node in SX graphs, as
    the airfoil surrogate's), times the Prandtl-Glauert factor of ``mdo.airfoil``
    (M capped smoothly at 0.7).  ln Re is limited smoothly to the spline's range."""

    LO, HI = math.log(1e3), math.log(1e8)

    def __init__(self, sec, anchor_rad):
        import casadi as ca
        from scipy.interpolate import make_interp_spline

        self.a0, self.slope = _linear_lift(sec)
        self.a_ref = self.a0 + anchor_rad
        grid = np.linspace(self.LO, self.HI, 41)
        vals = np.array([float(np.asarray(_coefficients(sec, self.a_ref, float(np.exp(r)), 0.0)[0])) for r in grid])
        spl = make_interp_spline(grid, vals, k=3)
        self._np = spl
        b = ca.Function.bspline(f"anchor_{id(self)}_bspline", [spl.t.tolist()], spl.c.tolist(), [3], 1)
        xs = ca.MX.sym("lnre")
        self._ca = ca.Function(f"anchor_{id(self)}", [xs], [b(xs)], {"never_inline": True})

    def cl_ref(self, reynolds, mach):
        import casadi as ca
        lib = xp(reynolds, mach)
        r = 0.5 * lib.log(reynolds * reynolds + 1.0)
        r = r - softplus(r - (self.HI - 0.3), 0.05) + softplus((self.LO + 0.3) - r, 0.05)
        if lib is ca:
            val = self._ca(r)
        else:
            val = self._np(r)
        m_e = mach - softplus(mach - 0.7, 0.03)
        return val / lib.sqrt(1.0 - m_e * m_e)


_ANCHORS: dict = {}


def _leaves(sec, x):
    """[(weight, leaf section)] of a (possibly blended) section at r/R = x."""
    if isinstance(sec, SpanwiseBlend):
        w = sec.weight(x)
        return [(1.0 - w, sec.inner), (w, sec.outer)]
    if isinstance(sec, SpanwiseSections):
        return list(zip(sec.weights(x), sec.sections))
    return [(1.0, sec)]


def _linear_lift_anchored(sec, alpha, reynolds, mach, x, anchor_rad):
    """Blended (alpha0, cl_lin(alpha)) with cl_lin = sum_k w_k [cl_k(a_ref,k, Re) + a_k (alpha - a_ref,k)]."""
    a0 = cl_lin = 0.0
    for w, leaf in _leaves(sec, x):
        key = (id(leaf), anchor_rad)
        if key not in _ANCHORS:
            _ANCHORS[key] = _Anchor(leaf, anchor_rad)
        an = _ANCHORS[key]
        a0 = a0 + w * an.a0
        cl_lin = cl_lin + w * (an.cl_ref(reynolds, mach) + an.slope * (alpha - an.a_ref))
    return a0, cl_lin


def _linear_lift(sec, x=0.5):
    """(alpha0, lift slope) of a section object (Re 1e6 linear range)."""
    if hasattr(sec, "linear_lift"):
        return sec.linear_lift(x)
    if isinstance(sec, SpanwiseBlend):
        w = sec.weight(x)
        a_i, s_i = _linear_lift(sec.inner)
        a_o, s_o = _linear_lift(sec.outer)
        return (1.0 - w) * a_i + w * a_o, (1.0 - w) * s_i + w * s_o
    return float(getattr(sec, "alpha0_rad", 0.0)), float(getattr(sec, "lift_slope_per_rad", 2.0 * math.pi))


def _coefficients(sec, alpha, reynolds, mach):
    if hasattr(sec, "coefficients"):
        out = sec.coefficients(alpha, reynolds, mach)
        return out[0], out[1]
    return sec.cl(alpha, reynolds, mach), sec.cd(alpha, reynolds, mach)


def section_coefficients(sec, alpha, reynolds, mach, x=None, c_over_r=None, tip_speed_ratio=None):
    """``(cl, cd)`` of any section object; ``x = r/R`` for spanwise blends, ``c/r`` and
    ``Omega R/sqrt(V^2 + (Omega R)^2)`` for rotational augmentation."""
    if getattr(sec, "rotational", False):
        if c_over_r is None:   # no blade context (e.g. the Adkins-Liebeck design point): 2-D
            return section_coefficients(sec.sec, alpha, reynolds, mach, x)
        return sec.coefficients(alpha, reynolds, mach, x, c_over_r, tip_speed_ratio)[:2]
    if getattr(sec, "spanwise", False):
        return sec.coefficients(alpha, reynolds, mach, x)[:2]
    return _coefficients(sec, alpha, reynolds, mach)


_NAMED: dict = {}  # one object per name, so that built CasADi Functions can be cached by section


def available_sections() -> list[str]:
    """Names accepted by ``section``: the airfoil surrogates plus ``analytic``."""
    names = ["analytic"]
    try:
        from ..airfoil import available
        names = list(available()) + names
    except ImportError:
        pass
    return names


def section(spec, stall_delay: str | None = None):
    """A section object from a name, or pass an object through.

    Names: a shipped ``mdo.airfoil`` name, ``"analytic"``, a generated section
    (``"NACA 23012"``, ``"naca4412@ncrit=5"``, ``"clarky@xtr=0.1"``, a coordinate file;
    see ``mdo.airfoil.generate``), or a radial distribution
    ``"A:X1:B[:X2:C ...]"`` (sections A, B, C... changing at r/R = X1, X2, ...; the
    two-section ``"e63:0.5:clark_y"`` is the familiar blend), optionally followed by
    ``";width=W"``, the width in r/R over which one section turns into the next
    (default 0.05).  A suffix ``"+snel"`` or
    ``"+du_selig"`` (or ``stall_delay=``) adds rotational augmentation
    (``RotationalAugmentation``).  Raises ``InputError("airfoil", ...)`` for unknown names.
    """
    if stall_delay is not None:
        return _with_stall_delay(section(spec), stall_delay)
    if not isinstance(spec, str):
        if not (hasattr(spec, "cl") and hasattr(spec, "cd")):
            raise InputError("airfoil", f"a section needs cl() and cd() methods, got {spec!r}")
        return spec
    name = spec.strip()
    if "+" in name:
        base, model = name.rsplit("+", 1)
        return _with_stall_delay(section(base), model.strip().lower())
    width = None
    if ";" in name:   # A:X1:B[...];width=W, the blend width in r/R
        name, opt = (t.strip() for t in name.split(";", 1))
        key, _, val = opt.partition("=")
        try:
            width = float(val)
        except ValueError:
            width = None
        if key.strip() != "width" or width is None or not width > 0 or name.count(":") < 2:
            raise InputError("airfoil", f"a section distribution's option is ';width=W' (W > 0, in r/R) after "
                                        f"A:R_OVER_R:B[...], got {spec!r}")
    if name.count(":") >= 2:   # A:X1:B[:X2:C...], a radial distribution of sections
        parts = name.split(":")
        if len(parts) % 2 == 0:
            raise InputError("airfoil", f"a section distribution is A:R_OVER_R:B[:R_OVER_R:C...], got {name!r}")
        try:
            xs = [float(x) for x in parts[1::2]]
        except ValueError as exc:
            raise InputError("airfoil", f"section distribution is A:R_OVER_R:B[:R_OVER_R:C...], got {name!r}") from exc
        names = [p.strip() for p in parts[0::2]]
        key = ":".join(f"{n}" if i % 2 == 0 else f"{float(n):g}" for i, n in enumerate(parts))
        w = {} if width is None else {"width": width}
        key += f";width={width:g}" if w else ""
        if key not in _NAMED:
            if len(names) == 2:
                if not (0.0 < xs[0] < 1.0):
                    raise InputError("airfoil", f"blend position must lie in (0, 1), got {xs[0]}")
                _NAMED[key] = SpanwiseBlend(section(names[0]), section(names[1]), xs[0], **w)
            else:
                _NAMED[key] = SpanwiseSections([section(n) for n in names], xs, **w)
        return _NAMED[key]
    if name in _NAMED:
        return _NAMED[name]
    if name.lower() == "analytic":
        _NAMED[name] = AnalyticSection()
        return _NAMED[name]
    try:
        from ..airfoil import Airfoil
    except ImportError as exc:
        raise InputError("airfoil", f"no airfoil surrogates are installed (mdo.airfoil missing); "
                                    f"use 'analytic' ({exc})") from exc
    try:
        _NAMED[name] = Airfoil.from_name(name)
        return _NAMED[name]
    except InputError:
        raise
    except (KeyError, ValueError, FileNotFoundError) as exc:
        raise InputError("airfoil", f"unknown airfoil {name!r}; known: {', '.join(available_sections())}") from exc


def _with_stall_delay(sec, model):
    key = (id(sec), model)
    if key not in _NAMED:
        _NAMED[key] = RotationalAugmentation(sec, model)
    return _NAMED[key]
