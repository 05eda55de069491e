"""The wing near and beyond stall: section cl_max(Re), the stall margin, the post-stall strips.

**cl_max(Re)** of a section is read off its surrogate (``mdo.airfoil.Airfoil``: the
largest cl of the attached-to-stall range, scanned over alpha at Reynolds numbers
1e5 ... 2e7) and fitted, once per airfoil, as a cubic in ``ln Re`` (within 0.08 in cl of
the scanned values for the five shipped sections); in the NLP
it is evaluated at each strip's Reynolds number ``rho V c / mu`` (chord from the
design), with ``ln Re`` smoothly held inside the fitted range (softplus ramps of
width 0.1).  The fit error is reported by :func:`clmax_fit` (``max_error``).
Mach effects on cl_max are not modelled (M < 0.3 at every GA node where it matters).

**Stall margin** (a limit of every airplane-mode node): each lifting strip's section
cl (from the lattice, on the local dynamic pressure) obeys

    cl_strip <= cl_max(Re_strip) + delta_flap * dcl_flap - margin             (S1)

``margin`` is the segment parameter ``stall_margin_cl`` (default 0.1 from the
vehicle; a negative value switches the limit off: tilt-wing transitions keep their
post-stall model instead).  ``delta_flap`` in [0, 1] is the segment parameter
``flap_deflection``; a wing's flaps (``WingConfig`` ``flap_span_eta`` and
``flap_clmax_increment``) raise the strips inside their span: a flap lowers the
angle of attack for a given cl and moves stall to a higher cl; the lattice itself
stays clean (the flap's camber is not in the lattice, so lift at a given attitude
and the flap drag are not modelled - the flapped strips only gain stall margin).

**Post-stall strips** (``stall_correction``, tilt-wing transitions): a strip past
cl_max is read as a section at the equivalent attached angle and given the
full-circle section coefficients there (AERODAS/flat plate), switched by a logistic
weight of width 0.1 in cl.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..airfoil.clmax import fit_clmax

__all__ = ["clmax_fit", "clmax_of_re", "stall_limits", "stall_correction", "stall_margin_rows"]

_CACHE: dict = {}


def _airfoil(name: str):
    from ..airfoil import Airfoil
    return Airfoil.from_name(name)


def clmax_fit(airfoil: str) -> dict:
    """Cubic fit of the surrogate's cl_max in ln Re (``mdo.airfoil.clmax``, Re 1e5-2e7):
    {"coef", "lnre_range", "max_error", "re", "clmax", "fit"}."""
    if airfoil not in _CACHE:
        af = _airfoil(airfoil)
        fit = fit_clmax(lambda a, re: af.cl(a, re), re_range=(1e5, 2e7))
        _CACHE[airfoil] = {"coef": fit.coef, "lnre_range": fit.lnre_range, "max_error": fit.max_error,
                           "re": fit.reynolds, "clmax": fit.clmax, "fit": fit}
    return _CACHE[airfoil]


def clmax_of_re(airfoil: str, reynolds):
    """cl_max at ``reynolds`` (numbers or CasADi), from :func:`clmax_fit`."""
    return clmax_fit(airfoil)["fit"](reynolds)


def stall_limits(airfoil: str) -> tuple:
    """(Airfoil, alpha0, lift slope, cl_min, cl_max) of a section at Re 1e6 (numbers, cached)."""
    key = ("limits", airfoil)
    if key not in _CACHE:
        af = _airfoil(airfoil)
        a = np.radians(np.linspace(-30.0, 30.0, 601))
        cl = np.asarray(af.cl(a, 1e6), float).ravel()
        _CACHE[key] = (af, float(af.alpha0_rad), float(af.lift_slope_per_rad), float(cl[a < 0].min()),
                       float(cl[a > 0].max()))
    return _CACHE[key]


def stall_correction(vlm, r, pd, rho, V, width: float = 0.1, counted=None):
    """Lift and drag corrections (N, 1 x K) of strips past stall (module docstring).

    A strip past stall trades the attached profile drag the build-up counted for the
    full-circle section's drag at ``r``'s local dynamic pressure.  ``counted``: the
    (lattice result, profile drag) pair the build-up counted, when not ``(r, pd)``
    (the strips scrubbed on the whole wake, ``Aircraft.blown_profile_drag``)."""
    g = vlm.geometry
    r_c, pd_c = counted if counted is not None else (r, pd)
    cl_loc = r["cl_local"]
    K = cl_loc.shape[1]
    Vl = r["V_local"]
    c = g["strip_chord"].T
    w = g["strip_width"].T
    dL = 0.0
    dD = 0.0
    names = [str(a) for a in vlm.strip_airfoil]
    for name in sorted(set(names)):
        if name == "None":
            continue
        idx = [i for i, a in enumerate(names) if a == name]
        af, a0, slope, cl_min, cl_max = stall_limits(name)
        cl_i = cl_loc[idx, :]
        alpha_e = a0 + cl_i / slope
        cl_af, cd_af, _ = af.coefficients(alpha_e, pd["Re"][idx, :])
        wgt = 0.5 * (1 + ca.tanh(0.5 * (cl_i - cl_max) / width)) + 0.5 * (1 + ca.tanh(0.5 * (cl_min - cl_i) / width))
        q_loc = 0.5 * ca.repmat(rho, len(idx), 1) * Vl[idx, :] ** 2
        q_c = 0.5 * ca.repmat(rho, len(idx), 1) * r_c["V_local"][idx, :] ** 2
        area = ca.repmat(c[idx] * w[idx], 1, K)
        dL = dL + ca.mtimes(ca.DM.ones(1, len(idx)), wgt * (cl_af - cl_i) * q_loc * area)
        dD = dD + ca.mtimes(ca.DM.ones(1, len(idx)), wgt * (cd_af * q_loc - pd_c["cd"][idx, :] * q_c) * area)
    factor = 2.0 if vlm.symmetric else 1.0
    return factor * dL, factor * dD


def stall_margin_rows(vlm, r, wings, strip_eta, rho, V, mu, margin_row, flap_row, columns, exposed=None):
    """Rows of (S1) as ``cl - cl_max - delta dcl + margin`` (<= 0) for the strips of the
    lifting ``wings`` (WingConfig) at nodes ``columns``.  ``strip_eta``: each strip's
    position as a fraction of its wing's semispan (numbers; strips sit at fixed
    fractions of the span whatever the design).  ``exposed``: per strip, False for strips
    inside the fuselage (no exposed section to stall).

    Returns (expr n_lifting_strips x len(columns), row labels) or (None, []) if none.
    """
    g = vlm.geometry
    names = [s.name for s in vlm.surfaces]
    by_name = {w.name: w for w in wings}
    idx = [i for i, si in enumerate(vlm.strip_surface) if names[si] in by_name
           and (exposed is None or exposed[i])]
    if not idx or not len(columns):
        return None, []
    cols = [int(k) for k in columns]
    cl = r["cl_local"][idx, :][:, cols]
    chord = ca.reshape(g["strip_chord"].T[idx], len(idx), 1)
    Re = ca.mtimes(chord, _sel(rho, cols) * _sel(V, cols) / _sel(mu, cols))
    margin, flap = _sel(margin_row, cols), _sel(flap_row, cols)
    rows, labels = [], []
    for j, i in enumerate(idx):
        w = by_name[names[vlm.strip_surface[i]]]
        lo, hi = w.flap_span_eta
        in_flap = 1.0 if (w.flap_clmax_increment > 0 and lo <= float(strip_eta[i]) <= hi) else 0.0
        cmax = clmax_of_re(str(vlm.strip_airfoil[i]), Re[j, :])
        rows.append(cl[j, :] - cmax - in_flap * w.flap_clmax_increment * flap + margin)
        labels.append(f"{w.name} eta {float(strip_eta[i]):.2f}")
    return ca.vertcat(*rows), labels


def _sel(row, cols):
    if isinstance(row, (ca.MX, ca.SX, ca.DM)):
        return row[:, cols] if row.shape[1] > 1 else ca.repmat(row, 1, len(cols))
    a = np.asarray(row, float).reshape(1, -1)
    return ca.DM(a[:, cols] if a.shape[1] > 1 else np.repeat(a, len(cols), axis=1))
