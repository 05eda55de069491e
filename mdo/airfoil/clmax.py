"""A section's maximum lift coefficient as a smooth function of Reynolds number.

cl_max(Re) is read off a section's cl(alpha, Re) (any callable: a shipped surrogate, a
generated section, a rotor blend at one radius) as the largest cl of the attached-to-stall
range, scanned over alpha 0-25 deg at Reynolds numbers spaced geometrically over
``re_range``, and fitted as a cubic in ``ln Re``.  In an NLP the fit is evaluated with
``ln Re`` smoothly held inside the fitted range (softplus ramps of width 0.1), so it can
take a variable Reynolds number.  ``max_error`` is the fit's largest deviation from the
scanned values.  Mach effects on cl_max are not modelled.

Used by the wing's stall margin (``mdo.vehicle.stall``) and the propeller design point's
stall limit (``mdo.rotor.design.design_cl_stall_rows``): one definition of cl_max(Re).
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..core.smooth import softplus

__all__ = ["ClmaxFit", "fit_clmax"]

_ALPHA = np.radians(np.linspace(0.0, 25.0, 251))


class ClmaxFit:
    """cl_max = cubic(ln Re) with ``ln Re`` held in ``lnre_range``; see the module docstring."""

    def __init__(self, coef, lnre_range, max_error, reynolds, clmax):
        self.coef = np.asarray(coef, float)
        self.lnre_range = (float(lnre_range[0]), float(lnre_range[1]))
        self.max_error = float(max_error)
        self.reynolds = np.asarray(reynolds, float)
        self.clmax = np.asarray(clmax, float)

    def __call__(self, reynolds):
        """cl_max at ``reynolds`` (numbers or CasADi expressions)."""
        lo, hi = self.lnre_range
        if isinstance(reynolds, (ca.MX, ca.SX, ca.DM)):
            x = ca.log(reynolds)
            x = lo + softplus(x - lo, 0.1)
            x = hi - softplus(hi - x, 0.1)
            out = 0.0
            for c in self.coef:    # Horner
                out = out * x + float(c)
            return out
        x = np.clip(np.log(np.asarray(reynolds, float)), lo, hi)
        return np.polyval(self.coef, x)


def fit_clmax(cl_of, re_range=(1e5, 2e7), n_re: int = 25) -> ClmaxFit:
    """Fit cl_max(Re) of ``cl_of(alpha_rad [array], reynolds [float]) -> cl [array]``."""
    re = np.geomspace(re_range[0], re_range[1], n_re)
    clmax = np.array([float(np.max(np.asarray(cl_of(_ALPHA, r), float))) for r in re])
    x = np.log(re)
    coef = np.polyfit(x, clmax, 3)
    err = float(np.max(np.abs(np.polyval(coef, x) - clmax)))
    return ClmaxFit(coef, (x[0], x[-1]), err, re, clmax)
