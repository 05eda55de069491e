"""The section model: fitted polars + post-stall + compressibility, written once
for NumPy arrays and CasADi SX expressions.

Given alpha [rad], Re and M (arrays of one common length n, or SX columns):

1. ``r = ln Re`` is smoothly limited to the data's range widened by ``re_margin``
   (softplus corners of width ``re_width``):  ``r_c = r - sp(r - r_hi) + sp(r_lo - r)``.
   The polars are interpolated at ``r_c`` by a natural cubic spline through the
   Reynolds levels (see :mod:`mdo.airfoil.fit`); outside the data ``ln cd``
   continues as a power law,
   ``ln cd += n_lo sp(r_lo - r) - n_hi sp(r - r_hi)`` (laminar Blasius exponent 1/2
   below, the local exponent of Schlichting's turbulent skin friction
   ``0.455/(log10 Re)^2.58``, 2.58/ln Re ~ 0.16 at 1e7, above).
2. The attached-flow fit ``cl_f, ln cd_f, cm_f``: one tensor-product cubic
   B-spline in (alpha, ln Re) (C2: continuous value, slope and curvature), evaluated
   at alpha smoothly clipped to the knot range so that it stays bounded for any alpha.
   In CasADi it is ``casadi.Function.bspline`` behind a never-inlined wrapper, i.e.
   one call node in an SX graph with exact first and second derivatives; in NumPy
   SciPy's ``NdBSpline`` on the same knots and coefficients.
3. Compressibility of the attached part: Prandtl-Glauert ``cl/beta`` and ``cm/beta``
   with ``beta = sqrt(1 - M_e^2)`` and ``M_e = M - sp(M - mach_cap)`` (smooth cap,
   so a rotor tip at M 0.8 gives a finite factor <= 1/sqrt(1 - mach_cap^2));
   skin-friction drag scaled by the turbulent flat-plate ratio
   ``(1 + 0.144 M^2)^-0.65`` (Raymer, Aircraft Design, eq. 12.27); wave drag by
   Lock's fourth-power law ``cd_w = 20 (M - M_crit)_+^4`` with
   ``M_crit = M_dd - (0.1/80)^(1/3)`` and the Korn equation
   ``M_dd = kappa_A - t/c - |cl|/10`` (Mason, Configuration Aerodynamics, ch. 7).
4. Post-stall (full circle): a flat-plate-like model with Spera's (AERODAS,
   NASA/CR-2008-215434) thickness-dependent maxima,
   ``cl_p = CL2max sin 2a``, ``CL2max = 1.190 (1 - (t/c)^2)``;
   ``cd_p = cd_rev + (CD90 - cd_rev) sin^2 a``, ``CD90 = 1.98 exp(-(0.65 t/c)^0.9)``
   (Spera's thickness factor, scaled to Hoerner's 2-D flat plate 1.98);
   ``cm_p = -CD90 sin a * 0.25 (1 - cos a)`` (centre of pressure moving from c/4 to
   mid-chord at 90 deg).  Near each stall edge ``a_s`` of the data it is anchored to
   the fitted value there and relaxes to the plate over ``anchor_decay``:
   ``cl_p += (cl_s - cl_p(a_s)) g``, ``ln cd_p += ln(cd_s / cd_p(a_s)) g``,
   ``g = exp(-((a - a_s)/L)^2)`` (the Viterna-Corrigan idea of matching the stall
   point, in a form without the 1/sin a pole).
5. Blend: ``c = w c_attached + (1 - w) c_post`` with
   ``w = sigmoid((a - a_lo + o)/b) sigmoid((a_hi + o - a)/b)``: C-infinity, so value
   and slope (and every derivative) are continuous across both stall edges.
"""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..core.smooth import sigmoid, softplus
from .fit import SurrogateTables

__all__ = ["ModelSettings", "SplineSet", "evaluate", "post_stall_maxima"]


@dataclass(frozen=True)
class ModelSettings:
    blend_width_deg: float = 1.5        # b: width of the attached/post-stall sigmoid
    blend_offset_deg: float = 3.0       # o: sigmoid centre past the last data point
    anchor_decay_deg: float = 8.0       # L: relaxation of the stall-edge anchor
    alpha_clip_width_deg: float = 0.5   # softplus corner of the alpha clip of the fit
    re_margin: float = 0.15             # data range in ln Re widened by this before limiting
    re_width: float = 0.05              # softplus corner width in ln Re
    n_laminar: float = 0.5              # cd ~ Re^-n below the data
    n_turbulent: float = 0.16           # cd ~ Re^-n above the data
    mach_cap: float = 0.7               # Prandtl-Glauert Mach limit
    mach_cap_width: float = 0.03
    kappa_korn: float = 0.87            # Korn technology factor (conventional sections)
    wave_width: float = 0.01            # softplus corner of (M - M_crit)_+
    cd_reverse: float = 0.03            # plate drag at 0 / 180 deg (reverse flow)


def post_stall_maxima(thickness_to_chord: float):
    """Spera's 2-D maxima: (CL2max at ~45 deg, CD90) for a section of t/c."""
    tc = float(thickness_to_chord)
    cl2max = 1.190 * (1.0 - tc * tc)
    cd90 = 1.98 * np.exp(-((0.65 * tc) ** 0.9))
    return cl2max, cd90


def _cols(lib, cols):
    return ca.horzcat(*cols) if lib is ca else np.stack(cols, axis=-1)


def _mm(lib, a, b):
    return ca.mtimes(a, ca.DM(b)) if lib is ca else a @ b


def _rowsum(lib, a):
    return ca.sum2(a) if lib is ca else a.sum(axis=-1)


class SplineSet:
    """The fitted surfaces of one airfoil as cubic B-splines, for both back ends.

    * ``surface``: (alpha, ln Re) -> (cl, ln cd, cm), tensor product;
    * ``edges``: ln Re -> (alpha_hi, alpha_lo, cl/ln cd/cm at alpha_hi, at alpha_lo).

    CasADi: ``casadi.Function.bspline`` objects (C2 piecewise cubics evaluated by
    de Boor's algorithm in C++; inside an SX graph each call is one call node with
    exact first and second derivatives).  NumPy: SciPy's ``NdBSpline``/``BSpline``
    on the same knots and coefficients (equal to rounding; tested).
    Arguments must lie inside the knot ranges (the model clips them smoothly first).
    """

    def __init__(self, tab: SurrogateTables):
        from scipy.interpolate import BSpline, NdBSpline

        self.tab = tab
        self._np_surface = NdBSpline((tab.knots, tab.knots_re), tab.coef_2d, 3)
        self._np_edges = BSpline(tab.knots_re, tab.coef_edges, 3)
        surface = ca.Function.bspline(
            f"polar_{tab.name}_bspline", [tab.knots.tolist(), tab.knots_re.tolist()],
            np.transpose(tab.coef_2d, (2, 0, 1)).ravel(order="F").tolist(), [3, 3], 3)
        edges = ca.Function.bspline(
            f"polar_edges_{tab.name}_bspline", [tab.knots_re.tolist()],
            tab.coef_edges.T.ravel(order="F").tolist(), [3], 8)
        # ``Function.bspline`` is an MX node; wrapped in a never-inlined Function it
        # becomes a single call node inside SX graphs (with exact derivatives).
        x2, x1 = ca.MX.sym("alpha_lnre", 2), ca.MX.sym("lnre")
        self.ca_surface = ca.Function(f"polar_{tab.name}", [x2], [surface(x2)],
                                      ["alpha_lnre"], ["cl_lncd_cm"], {"never_inline": True})
        self.ca_edges = ca.Function(f"polar_edges_{tab.name}", [x1], [edges(x1)],
                                    ["lnre"], ["edges"], {"never_inline": True})
        self._maps = {}

    def _mapped(self, f, n):
        if n == 1:
            return f
        key = (f.name(), n)
        if key not in self._maps:
            self._maps[key] = f.map(n)
        return self._maps[key]

    def surface(self, lib, a, r, n):
        if lib is ca:
            out = self._mapped(self.ca_surface, n)(ca.horzcat(a, r).T).T  # n x 3
            return out[:, 0], out[:, 1], out[:, 2]
        out = self._np_surface(np.stack([a, r], axis=-1))
        return out[:, 0], out[:, 1], out[:, 2]

    def edges(self, lib, r, n):
        if lib is ca:
            out = self._mapped(self.ca_edges, n)(r.T).T  # n x 8
            return [out[:, k] for k in range(8)]
        out = self._np_edges(r)
        return [out[:, k] for k in range(8)]


def splines_of(tab: SurrogateTables) -> SplineSet:
    if getattr(tab, "_splines", None) is None:
        tab._splines = SplineSet(tab)
    return tab._splines


def evaluate(tab: SurrogateTables, thickness_to_chord: float, alpha, reynolds, mach,
             lib, n: int, settings: ModelSettings = ModelSettings()):
    """cl, cd, cm at n stations; ``alpha``, ``reynolds``, ``mach`` are length-n
    NumPy vectors (``lib`` = numpy) or n x 1 SX/MX columns (``lib`` = casadi)."""
    s = settings
    deg = np.pi / 180.0
    spl = splines_of(tab)
    # --- 1. Reynolds number: ln Re limited to the data range +- re_margin
    # ln Re, written ln sqrt(Re^2 + 1) so that an NLP iterate with Re <= 0 stays finite
    # (relative change < 1e-10 for Re > 1e4)
    r = 0.5 * lib.log(reynolds * reynolds + 1.0)
    r_lo = tab.log_re[0] - s.re_margin
    r_hi = tab.log_re[-1] + s.re_margin
    sp_hi = softplus(r - r_hi, s.re_width)
    sp_lo = softplus(r_lo - r, s.re_width)
    r_c = r - sp_hi + sp_lo

    # --- 2. attached-flow fit at the smoothly clipped alpha
    wa = s.alpha_clip_width_deg * deg
    a_lo_c, a_hi_c = tab.alpha_clip
    a_c = alpha - softplus(alpha - (a_hi_c - 4 * wa), wa) + softplus((a_lo_c + 4 * wa) - alpha, wa)
    cl_f, lncd_f, cm_f = spl.surface(lib, a_c, r_c, n)
    a_hi, a_lo, cl_hi, lncd_hi, cm_hi, cl_lo, lncd_lo, cm_lo = spl.edges(lib, r_c, n)
    cd_re = s.n_laminar * sp_lo - s.n_turbulent * sp_hi   # power law beyond the data
    lncd_f, lncd_hi, lncd_lo = lncd_f + cd_re, lncd_hi + cd_re, lncd_lo + cd_re

    # --- 3. compressibility of the attached part
    m_e = mach - softplus(mach - s.mach_cap, s.mach_cap_width)
    pg = 1.0 / lib.sqrt(1.0 - m_e * m_e)
    ln_friction = -0.65 * lib.log(1.0 + 0.144 * mach * mach)
    cl_f, cm_f = cl_f * pg, cm_f * pg
    cl_hi, cm_hi, cl_lo, cm_lo = cl_hi * pg, cm_hi * pg, cl_lo * pg, cm_lo * pg
    lncd_f, lncd_hi, lncd_lo = lncd_f + ln_friction, lncd_hi + ln_friction, lncd_lo + ln_friction

    # --- 4. post-stall: plate with Spera's maxima, anchored at both data edges
    cl2max, cd90 = post_stall_maxima(thickness_to_chord)

    def plate(a):
        sa, ca_ = lib.sin(a), lib.cos(a)
        return (2.0 * cl2max * sa * ca_,
                lib.log(s.cd_reverse + (cd90 - s.cd_reverse) * sa * sa),
                -cd90 * sa * 0.25 * (1.0 - ca_))

    cl_p, lncd_p, cm_p = plate(alpha)
    L = s.anchor_decay_deg * deg
    for a_s, cl_s, lncd_s, cm_s in ((a_hi, cl_hi, lncd_hi, cm_hi), (a_lo, cl_lo, lncd_lo, cm_lo)):
        g = lib.exp(-((alpha - a_s) / L) ** 2)
        cl_ps, lncd_ps, cm_ps = plate(a_s)
        cl_p = cl_p + (cl_s - cl_ps) * g
        lncd_p = lncd_p + (lncd_s - lncd_ps) * g
        cm_p = cm_p + (cm_s - cm_ps) * g

    # --- 5. blend
    b = s.blend_width_deg * deg
    o = s.blend_offset_deg * deg
    w = sigmoid(alpha - (a_lo - o), b) * sigmoid((a_hi + o) - alpha, b)
    cl = w * cl_f + (1.0 - w) * cl_p
    cd = w * lib.exp(lncd_f) + (1.0 - w) * lib.exp(lncd_p)
    cm = w * cm_f + (1.0 - w) * cm_p

    # wave drag (Korn + Lock) on the total
    m_dd = s.kappa_korn - thickness_to_chord - lib.sqrt(cl * cl + 1e-4) / 10.0
    m_crit = m_dd - (0.1 / 80.0) ** (1.0 / 3.0)
    cd = cd + 20.0 * softplus(mach - m_crit, s.wave_width) ** 4
    return cl, cd, cm
