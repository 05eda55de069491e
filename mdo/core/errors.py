"""Input errors raised at the edges (problem files, CLI options, data files).

``InputError`` is a ``ValueError`` whose message names the field and the allowed
range; the CLI turns it into one line on stderr and exit code 2.  Disciplines
check their numeric inputs with ``check_positive`` / ``check_range`` when they are
given numbers (never on symbolic expressions, which IPOPT handles with bounds).
"""
from __future__ import annotations

import numpy as np

__all__ = ["InputError", "check_positive", "check_range"]


class InputError(ValueError):
    """Bad user input: the message names the field and the allowed range."""

    def __init__(self, field: str, message: str):
        self.field = field
        super().__init__(f"{field}: {message}")


def _numeric(value):
    import casadi as ca
    if isinstance(value, (ca.SX, ca.MX)):
        return None  # symbolic: bounds are IPOPT's business
    if isinstance(value, (list, tuple)) and any(isinstance(v, (ca.SX, ca.MX)) for v in value):
        return None
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return None


def check_positive(field: str, value, unit: str = "") -> None:
    """Raise ``InputError`` unless every element of a numeric ``value`` is finite and > 0."""
    a = _numeric(value)
    if a is None:
        return  # symbolic: bounds are IPOPT's business
    u = f" {unit}" if unit else ""
    if not np.all(np.isfinite(a)):
        raise InputError(field, f"must be a finite number > 0{u}, got {value!r}")
    if np.any(a <= 0):
        raise InputError(field, f"must be > 0{u}, got {a.min():g}{u}")


def check_range(field: str, value, lower=-np.inf, upper=np.inf, unit: str = "",
                inclusive: bool = True) -> None:
    """Raise ``InputError`` unless a numeric ``value`` lies in [lower, upper]."""
    a = _numeric(value)
    if a is None:
        return
    u = f" {unit}" if unit else ""
    if not np.all(np.isfinite(a)):
        raise InputError(field, f"must be finite, got {value!r}")
    lo_bad = np.any(a < lower) if inclusive else np.any(a <= lower)
    hi_bad = np.any(a > upper) if inclusive else np.any(a >= upper)
    if lo_bad or hi_bad:
        br = ("[", "]") if inclusive else ("(", ")")
        bad = a.min() if lo_bad else a.max()
        raise InputError(field, f"allowed range {br[0]}{lower:g}, {upper:g}{br[1]}{u}, got {bad:g}{u}")
