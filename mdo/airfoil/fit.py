"""Fit of XFOIL polars to the tables the symbolic surrogate evaluates.

Runs once per airfoil when it is loaded (NumPy/SciPy, a few milliseconds); the
result is a :class:`SurrogateTables` of plain arrays.

Angle of attack: at every Reynolds level ``j`` of the data, ``cl``, ``ln cd`` and
``cm`` are fitted with a penalised cubic B-spline (a P-spline, Eilers & Marx 1996)
on knots common to all levels (uniform spacing ``h``).  The penalty on second
differences of the coefficients is light inside the level's data range and heavy
outside it, so the fit extrapolates almost linearly a few degrees past the data
(the post-stall blend takes over there).  The B-spline is converted to the
truncated-power form

    s(alpha) = sum_i d_i (alpha - t_i)_+^3,   (x)_+ = max(x, 0),

kept for cross-checks and for the benchmark's comparison of representations.

Reynolds number: the per-level values are combined with the cardinal functions of
a natural cubic spline in ``ln Re`` (C2, exact at the data levels, linear beyond the
end levels), ``W_j(r) = a_j + b_j r + sum_i E_ij (r - r_i)_+^3``.

What the model evaluates is the product of the two: one tensor-product cubic
B-spline (uniform knots in alpha, clamped knots at the data levels +- ``RE_PAD``
in ln Re) whose coefficients are ``coef_alpha @ M_re^T``, exact (to rounding) for
the construction above.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from math import comb

import numpy as np
from scipy.interpolate import BSpline, CubicSpline

from .data_io import Polar

__all__ = ["FitSettings", "SurrogateTables", "fit_tables", "natural_spline_weights"]


@dataclass(frozen=True)
class FitSettings:
    """Knobs of the fit (angles in degrees)."""

    knot_spacing_deg: float = 1.0
    margin_deg: float = 8.0            # knots reach this far past the widest data range
    lam_cl: float = 1e-3               # P-spline penalties inside the data (per data point)
    lam_logcd: float = 1e-3
    lam_cm: float = 1e-3
    lam_outside: float = 1e3           # penalty where a level has no data (near-linear extrapolation)


@dataclass
class SurrogateTables:
    """Arrays evaluated by :mod:`mdo.airfoil.model` (angles in rad, r = ln Re)."""

    name: str
    knots: np.ndarray              # truncated-power knots t_i in alpha [rad]
    alpha_clip: tuple              # fit is evaluated at alpha smoothly clipped to this [rad]
    d_cl: np.ndarray               # (n_knots, n_re) truncated-power coefficients
    d_logcd: np.ndarray
    d_cm: np.ndarray
    log_re: np.ndarray             # data levels r_j = ln Re_j
    w_a: np.ndarray                # W_j(r) = a_j + b_j r + sum_i E_ij (r - r_i)_+^3
    w_b: np.ndarray
    w_e: np.ndarray                # (n_re, n_re): E[i, j]
    # Per level: data edges [rad] and the fitted values there (anchors of the post-stall model)
    alpha_hi: np.ndarray
    alpha_lo: np.ndarray
    edge_hi: np.ndarray            # (3, n_re): cl, ln cd, cm at alpha_hi
    edge_lo: np.ndarray
    bspline: dict = field(default_factory=dict)  # per quantity: (t, c (n_basis, n_re)) for checks
    # The same surface as one tensor-product cubic B-spline (what the model evaluates):
    knots_re: np.ndarray = None    # clamped knots in ln Re: data levels inside, +-RE_PAD beyond
    coef_2d: np.ndarray = None     # (n_basis_alpha, n_basis_re, 3): cl, ln cd, cm
    coef_edges: np.ndarray = None  # (n_basis_re, 8): alpha_hi, alpha_lo, edge_hi[0:3], edge_lo[0:3]


def natural_spline_weights(x: np.ndarray):
    """Cardinal natural cubic splines through ``x`` in truncated-power form.

    Returns ``a, b, E`` with ``W_j(r) = a_j + b_j r + sum_i E[i, j] (r - x_i)_+^3``; each
    ``W_j`` is the natural spline with ``W_j(x_k) = delta_jk``, linear outside
    ``[x_0, x_-1]`` (C2 everywhere).
    """
    n = len(x)
    a = np.zeros(n)
    b = np.zeros(n)
    e = np.zeros((n, n))
    if n == 1:
        a[0] = 1.0
        return a, b, e
    if n == 2:
        b[:] = np.array([-1.0, 1.0]) / (x[1] - x[0])
        a[:] = np.array([x[1], -x[0]]) / (x[1] - x[0])
        return a, b, e
    for j in range(n):
        y = np.zeros(n)
        y[j] = 1.0
        cs = CubicSpline(x, y, bc_type="natural")
        # third derivative per interval = 6 * c[0]; zero outside (linear extension)
        d3 = np.concatenate([[0.0], 6.0 * cs.c[0], [0.0]])
        e[:, j] = np.diff(d3) / 6.0
        # left of x_0 the spline is the line through (x_0, y_0) with slope s'(x_0)
        slope0 = cs(x[0], 1)
        b[j] = slope0
        a[j] = y[0] - slope0 * x[0]
    return a, b, e


RE_PAD = 1.0  # ln Re: the Re-direction B-spline extends this far beyond the data levels


def natural_spline_bspline(x: np.ndarray, pad: float = RE_PAD):
    """The cardinal natural splines of :func:`natural_spline_weights` (linear beyond the
    end levels) as exact cubic B-splines on clamped knots ``[x_0 - pad]*4, x_0..x_-1, [x_-1 + pad]*4``.

    Returns ``(knots, M)`` with ``W_j(r) = sum_k M[k, j] B_k(r)`` on ``[x_0 - pad, x_-1 + pad]``.
    Every ``W_j`` is a cubic spline with knots at the data levels, so the
    representation is exact (least squares on dense samples recovers it to rounding).
    """
    t = np.concatenate([[x[0] - pad] * 4, x, [x[-1] + pad] * 4])
    r = np.linspace(x[0] - pad, x[-1] + pad, 40 * (len(x) + 8))
    basis = BSpline.design_matrix(r, t, 3).toarray()
    a, b, e = natural_spline_weights(x)
    w = a[None, :] + r[:, None] * b[None, :] + (np.fmax(r[:, None] - x[None, :], 0.0) ** 3) @ e
    m, *_ = np.linalg.lstsq(basis, w, rcond=None)
    return t, m


def _bspline_to_truncated_power(coef: np.ndarray, h: float) -> np.ndarray:
    """Truncated-power coefficients of a uniform cubic B-spline (knots t_0 + k h).

    ``B_k(x) = (6 h^3)^-1 sum_{m=0..4} (-1)^m C(4, m) (x - t_{k+m})_+^3``, so the
    coefficient of ``(x - t_i)_+^3`` is ``(6 h^3)^-1 sum_m (-1)^m C(4, m) c_{i-m}``.
    """
    nb = coef.shape[0]
    d = np.zeros((nb + 4,) + coef.shape[1:])
    for m in range(5):
        d[m:m + nb] += (-1) ** m * comb(4, m) * coef
    return d / (6.0 * h ** 3)


def _penalised_fit(basis, y, penalty, lam):
    """min |B c - y|^2 + lam n |P c|^2 (rows of P carry their own weights)."""
    lhs = basis.T @ basis + lam * len(y) * (penalty.T @ penalty)
    return np.linalg.solve(lhs, basis.T @ y)


def fit_tables(name: str, polars: list[Polar], settings: FitSettings = FitSettings()) -> SurrogateTables:
    """Fit the polars of one airfoil (any number of Reynolds levels, Mach 0)."""
    polars = sorted(polars, key=lambda p: p.reynolds)
    h = np.radians(settings.knot_spacing_deg)
    a_min = min(p.alpha_deg.min() for p in polars)
    a_max = max(p.alpha_deg.max() for p in polars)
    lo = np.radians(a_min - settings.margin_deg)
    hi = np.radians(a_max + settings.margin_deg)
    n_int = int(np.ceil((hi - lo) / h))
    # uniform knots with 3 extra on each side so that [lo, hi] is fully supported
    t = lo + h * np.arange(-3, n_int + 4)
    nb = len(t) - 4
    # second differences (curvature) inside the data, first differences (slope)
    # outside: the fit continues nearly flat past the last data point
    d2 = np.zeros((nb - 2, nb))
    for i in range(nb - 2):
        d2[i, i:i + 3] = [1.0, -2.0, 1.0]
    d1 = np.zeros((nb - 1, nb))
    for i in range(nb - 1):
        d1[i, i:i + 2] = [-1.0, 1.0]
    greville = t[2:nb + 2]  # Greville abscissa (t_{k+1}+t_{k+2}+t_{k+3})/3 = t_{k+2} for uniform knots
    coef = {q: np.zeros((nb, len(polars))) for q in ("cl", "logcd", "cm")}
    lam = {"cl": settings.lam_cl, "logcd": settings.lam_logcd, "cm": settings.lam_cm}
    alpha_hi = np.zeros(len(polars))
    alpha_lo = np.zeros(len(polars))
    for j, p in enumerate(polars):
        a = np.radians(p.alpha_deg)
        basis = BSpline.design_matrix(a, t, 3).toarray()
        g2 = greville[1:-1]
        g1 = 0.5 * (greville[1:] + greville[:-1])
        in2 = (g2 >= a.min()) & (g2 <= a.max())
        out1 = (g1 < a.min() - 0.5 * h) | (g1 > a.max() + 0.5 * h)
        pen = np.vstack([d2 * np.sqrt(in2)[:, None], d1 * np.sqrt(settings.lam_outside * out1)[:, None]])
        for q, y in (("cl", p.cl), ("logcd", np.log(p.cd)), ("cm", p.cm)):
            coef[q][:, j] = _penalised_fit(basis, y, pen, lam[q])
        alpha_hi[j] = a.max()
        alpha_lo[j] = a.min()
    d = {q: _bspline_to_truncated_power(c, h) for q, c in coef.items()}
    edge_hi = np.zeros((3, len(polars)))
    edge_lo = np.zeros((3, len(polars)))
    for k, q in enumerate(("cl", "logcd", "cm")):
        for j in range(len(polars)):
            spl = BSpline(t, coef[q][:, j], 3)
            edge_hi[k, j] = spl(alpha_hi[j])
            edge_lo[k, j] = spl(alpha_lo[j])
    log_re = np.log([p.reynolds for p in polars])
    w_a, w_b, w_e = natural_spline_weights(log_re)
    clip = (lo + 2 * h, hi - 2 * h)
    t_re, m_re = natural_spline_bspline(log_re)
    coef_2d = np.stack([coef[q] @ m_re.T for q in ("cl", "logcd", "cm")], axis=-1)
    edges = np.vstack([alpha_hi, alpha_lo, edge_hi, edge_lo])  # (8, n_re)
    coef_edges = (edges @ m_re.T).T
    return SurrogateTables(
        name=name, knots=t, alpha_clip=clip,
        d_cl=d["cl"], d_logcd=d["logcd"], d_cm=d["cm"],
        log_re=log_re, w_a=w_a, w_b=w_b, w_e=w_e,
        alpha_hi=alpha_hi, alpha_lo=alpha_lo, edge_hi=edge_hi, edge_lo=edge_lo,
        bspline={q: (t, c) for q, c in coef.items()},
        knots_re=t_re, coef_2d=coef_2d, coef_edges=coef_edges,
    )
