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


from ..core.errors import InputError
from ..core.smooth import sigmoid, smooth_abs, smooth_max, xp

__all__ = ["AnalyticSection", "SpanwiseBlend", "section", "available_sections"]


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


def _coefficients(sec, alpha, reynolds, mach):
    if hasattr(sec, "coefficients"):
        out = sec.coefficients(alpha, reynolds, mach)
        return out[0], out[1]
    return sec.cl(alpha, reynolds, mach), sec.cd(alpha, reynolds, mach)


def section_coefficients(sec, alpha, reynolds, mach, x=None):
    """``(cl, cd)`` of any section object; ``x = r/R`` for spanwise blends."""
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


def section(spec):
    """A section object from a name (``mdo.airfoil``), ``"analytic"``, or pass an object through.

    Raises ``InputError("airfoil", ...)`` listing the known names for an unknown name.
    """
    if not isinstance(spec, str):
        if not (hasattr(spec, "cl") and hasattr(spec, "cd")):
            raise InputError("airfoil", f"a section needs cl() and cd() methods, got {spec!r}")
        return spec
    name = spec.strip()
    if name.count(":") == 2:   # INNER:X:OUTER, a spanwise blend
        inner, x, outer = name.split(":")
        try:
            xv = float(x)
        except ValueError as exc:
            raise InputError("airfoil", f"blend spec is INNER:R_OVER_R:OUTER, got {name!r}") from exc
        key = f"{inner.strip()}:{xv:g}:{outer.strip()}"
        if key not in _NAMED:
            _NAMED[key] = SpanwiseBlend(section(inner), section(outer), xv)
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
