"""Smooth replacements for the kinks IPOPT must not see.

Every function here accepts Python floats, NumPy arrays and CasADi SX/MX/DM
expressions and returns the same kind.  Each has a ``width`` that states how far
from the kink the smooth form departs from the exact one; choose it in the units
of the argument (e.g. 0.01 rad, 1 m/s).

Error of each form against the exact kink, for a given width ``w``:

==================  =====================================  ===========================
function            smooth form                            worst error (at the kink)
==================  =====================================  ===========================
softplus(x, w)      w * log(1 + exp(x / w))                w * ln 2 (at x = 0)
smooth_abs(x, w)    sqrt(x^2 + w^2)                        w (at x = 0), ~w^2/(2|x|) far
smooth_max(a, b, w) (a + b + smooth_abs(a - b, w)) / 2     w / 2
smooth_min(a, b, w) (a + b - smooth_abs(a - b, w)) / 2     w / 2
soft_min(x, w)      -w log sum exp(-x_i / w) over a vector   below min by 0 ... w ln n
sigmoid(x, w)       1 / (1 + exp(-x / w))                  0.5 (step), 0.12 at x = +-2w
blend(x, x0, w,..)  (1 - s) f_lo + s f_hi, s = sigmoid     C-infinity weight
==================  =====================================  ===========================
"""
from __future__ import annotations

import casadi as ca
import numpy as np

__all__ = [
    "is_symbolic",
    "xp",
    "softplus",
    "smooth_abs",
    "smooth_max",
    "smooth_min",
    "smooth_clip",
    "soft_min",
    "sigmoid",
    "blend",
]

_CASADI_TYPES = (ca.SX, ca.MX, ca.DM)


def is_symbolic(*args) -> bool:
    """True if any argument is a CasADi SX/MX/DM object."""
    return any(isinstance(a, _CASADI_TYPES) for a in args)


def xp(*args):
    """The array namespace for the arguments: ``casadi`` if any is CasADi, else ``numpy``.

    Lets one physics function serve numbers and symbols: ``xp(x).sqrt(x)``.
    """
    return ca if is_symbolic(*args) else np


def softplus(x, width=1.0):
    """Smooth ramp ``max(x, 0)``: ``w*log(1 + exp(x/w))``, overflow-safe.

    Written as ``relu(x) + w*log1p(exp(-|x|/w))``: the kinks of the two terms cancel
    exactly, so the result and all its derivatives are continuous.
    """
    lib = xp(x)
    z = x / width
    if lib is ca:
        return width * (ca.fmax(z, 0) + ca.log1p(ca.exp(-ca.fabs(z))))
    return width * (np.maximum(z, 0) + np.log1p(np.exp(-np.abs(z))))


def smooth_abs(x, width=1.0):
    """``|x|`` as ``sqrt(x^2 + w^2)``; exceeds |x| by at most ``w`` (at x = 0)."""
    return xp(x).sqrt(x * x + width * width)


def smooth_max(a, b, width=1.0):
    """``max(a, b)`` with the corner rounded over about ``width``; error <= w/2."""
    return 0.5 * (a + b + smooth_abs(a - b, width))


def smooth_min(a, b, width=1.0):
    """``min(a, b)`` with the corner rounded over about ``width``; error <= w/2."""
    return 0.5 * (a + b - smooth_abs(a - b, width))


def soft_min(x, width=1.0):
    """Smallest entry of the column ``x`` (CasADi or NumPy): ``-w log sum exp(-x_i / w)``,
    written about a pairwise smooth minimum (symbolic; within n w / 2 of the minimum) or the
    minimum (numeric), an exact identity that keeps every exponent below n / 2; below the
    minimum by at most ``w ln n``, and by ``w ln k`` where k entries tie at it."""
    if is_symbolic(x):
        m = x[0]
        for i in range(1, x.shape[0]):
            m = smooth_min(m, x[i], width)
        return m - width * ca.log(ca.sum1(ca.exp(-(x - m) / width)))
    a = np.asarray(x, float).ravel()
    m = a.min()
    return float(m - width * np.log(np.sum(np.exp(-(a - m) / width))))


def smooth_clip(x, lower, upper, width=1.0):
    """Clip ``x`` to [lower, upper] with both corners rounded (error <= w/2 at each)."""
    return smooth_min(smooth_max(x, lower, width), upper, width)


def sigmoid(x, width=1.0):
    """Logistic step from 0 to 1 centred at 0 with scale ``width``: ``1/(1+exp(-x/w))``.

    Written through ``tanh`` so that large |x|/w does not overflow.
    """
    return 0.5 * (1.0 + xp(x).tanh(0.5 * x / width))


def blend(x, x0, width, f_low, f_high):
    """C-infinity switch from ``f_low`` (x << x0) to ``f_high`` (x >> x0).

    The weight is ``sigmoid(x - x0, width)``; value and every derivative are
    continuous.  At ``x0 -+ 4 w`` the weight is 0.018 / 0.982.
    """
    s = sigmoid(x - x0, width)
    return (1.0 - s) * f_low + s * f_high
