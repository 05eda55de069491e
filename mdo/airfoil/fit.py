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

which is exactly the same C2 piecewise cubic but costs one ``fmax`` per knot in a
CasADi SX graph (all knots share it) instead of a table look-up.

Reynolds number: the per-level values are combined with the cardinal functions of
a natural cubic spline in ``ln Re`` (C2, exact at the data levels, linear beyond the
end levels), also in truncated-power form ``W_j(r) = a_j + b_j r + sum_i E_ij (r - r_i)_+^3``.
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
    lam_cl: float = 3e-2               # P-spline penalties inside the data (per data point)
    lam_logcd: float = 3e-2
    lam_cm: float = 3e-2
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


def _penalised_fit(basis, y, penalty_rows, weights_rows, lam):
    bt = basis.T
    p = penalty_rows * weights_rows[:, None]
    lhs = bt @ basis + lam * len(y) * (penalty_rows.T @ p)
    return np.linalg.solve(lhs, bt @ y)


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
    dmat = np.zeros((nb - 2, nb))
    for i in range(nb - 2):
        dmat[i, i:i + 3] = [1.0, -2.0, 1.0]
    centres = t[2:nb] + 0.0  # Greville-ish location of each second difference
    coef = {q: np.zeros((nb, len(polars))) for q in ("cl", "logcd", "cm")}
    lam = {"cl": settings.lam_cl, "logcd": settings.lam_logcd, "cm": settings.lam_cm}
    alpha_hi = np.zeros(len(polars))
    alpha_lo = np.zeros(len(polars))
    for j, p in enumerate(polars):
        a = np.radians(p.alpha_deg)
        basis = BSpline.design_matrix(a, t, 3).toarray()
        inside = (centres >= a.min() - 0.5 * h) & (centres <= a.max() + 0.5 * h)
        wrow = np.where(inside, 1.0, settings.lam_outside)
        for q, y in (("cl", p.cl), ("logcd", np.log(p.cd)), ("cm", p.cm)):
            coef[q][:, j] = _penalised_fit(basis, y, dmat, wrow, lam[q])
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
    return SurrogateTables(
        name=name, knots=t, alpha_clip=clip,
        d_cl=d["cl"], d_logcd=d["logcd"], d_cm=d["cm"],
        log_re=log_re, w_a=w_a, w_b=w_b, w_e=w_e,
        alpha_hi=alpha_hi, alpha_lo=alpha_lo, edge_hi=edge_hi, edge_lo=edge_lo,
        bspline={q: (t, c) for q, c in coef.items()},
    )
