"""Input errors raised at the edges (problem files, CLI options, data files).

``InputError`` is a ``ValueError`` whose message names the field and the allowed
range; the CLI turns it into one line on stderr and exit code 2.  Disciplines
check their numeric inputs with ``check_positive`` / ``check_range`` when they are
given numbers (never on symbolic expressions, which IPOPT handles with bounds).
The command line parses what users type with ``parse_float`` / ``parse_int`` /
``parse_choice`` / ``parse_grid``, each with a finite range that the message names.
"""
from __future__ import annotations

import numpy as np

__all__ = ["InputError", "check_positive", "check_range", "parse_float", "parse_int", "parse_choice",
           "parse_grid", "range_text", "check_finite_result"]


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


# ---------------------------------------------------------------- checked parsers (CLI and options)
# Each takes the text a user typed (or a number already parsed) and returns a value
# inside a finite, stated range, or raises InputError naming the field and the range:
#   parse_int("--points", "1e12", 2, 100000)
#   -> InputError: "--points: an integer in [2, 100000], got '1e12'"

def range_text(lower, upper, unit: str = "", lower_open: bool = False, upper_open: bool = False) -> str:
    """``[lo, hi] unit`` / ``(lo, hi)`` as the messages print a range."""
    u = f" {unit}" if unit else ""
    return f"{'(' if lower_open else '['}{lower:g}, {upper:g}{')' if upper_open else ']'}{u}"


def _shown(text) -> str:
    return repr(text) if isinstance(text, str) else f"{text!r}"


def parse_float(field: str, text, lower: float, upper: float, unit: str = "", *,
                lower_open: bool = False, upper_open: bool = False) -> float:
    """A finite number in [lower, upper] (ends open on request) from text or a number."""
    want = f"a number in {range_text(lower, upper, unit, lower_open, upper_open)}"
    if isinstance(text, bool):
        raise InputError(field, f"{want}, got {_shown(text)}")
    try:
        value = float(text)
    except (TypeError, ValueError):
        raise InputError(field, f"{want}, got {_shown(text)}") from None
    low_bad = value <= lower if lower_open else value < lower
    high_bad = value >= upper if upper_open else value > upper
    if not np.isfinite(value) or low_bad or high_bad:
        raise InputError(field, f"{want}, got {_shown(text)}")
    return value


def parse_int(field: str, text, lower: int, upper: int) -> int:
    """An integer in [lower, upper] from text or a number; '2.5', '1e3', True are refused."""
    want = f"an integer in [{lower}, {upper}]"
    if isinstance(text, bool) or (isinstance(text, float) and not text.is_integer()):
        raise InputError(field, f"{want}, got {_shown(text)}")
    if isinstance(text, float):
        value = int(text)
    else:
        try:
            value = int(str(text).strip())   # int('2.5'), int('1e12') raise: not integers as typed
        except (TypeError, ValueError):
            raise InputError(field, f"{want}, got {_shown(text)}") from None
    if not lower <= value <= upper:
        raise InputError(field, f"{want}, got {_shown(text)}")
    return value


def parse_choice(field: str, text, choices):
    """One of ``choices`` (compared as given); the message lists them."""
    for c in choices:
        if text == c or (isinstance(c, str) and str(text) == c):
            return c
    raise InputError(field, f"one of {', '.join(str(c) for c in choices)}, got {_shown(text)}")


def parse_grid(field: str, text, lower: float, upper: float, max_points: int, unit: str = "") -> np.ndarray:
    """``START:STOP:STEP`` -> array from START to STOP (included when on the grid), every value
    in [lower, upper], STEP > 0, at most ``max_points`` points."""
    parts = str(text).split(":")
    form = f"START:STOP:STEP with values in {range_text(lower, upper, unit)}, STEP > 0, at most {max_points} points"
    if len(parts) != 3:
        raise InputError(field, f"expected {form}, got {_shown(text)}")
    try:
        start, stop, step = (float(p) for p in parts)
    except ValueError:
        raise InputError(field, f"expected {form}, got {_shown(text)}") from None
    if not all(np.isfinite(v) for v in (start, stop, step)):
        raise InputError(field, f"values must be finite: {form}, got {_shown(text)}")
    if step <= 0:
        raise InputError(field, f"STEP must be > 0, got {step:g}")
    if stop < start:
        raise InputError(field, f"STOP must be >= START, got {start:g}:{stop:g}")
    if start < lower or stop > upper:
        raise InputError(field, f"values must lie in {range_text(lower, upper, unit)}, got {_shown(text)}")
    count = int(np.floor((stop - start) / step + 1e-9)) + 1
    if count > max_points:
        raise InputError(field, f"{count} points is too many (at most {max_points})")
    return start + step * np.arange(count)


def check_finite_result(field: str, **arrays) -> None:
    """Refuse to print results that are not finite (a model pushed outside its range):
    ``InputError`` naming the inputs (``field``) and the first non-finite output."""
    for name, a in arrays.items():
        v = np.asarray(a, dtype=float)
        if not np.all(np.isfinite(v)):
            raise InputError(field, f"the model gives non-finite {name} for these inputs; "
                                    f"nothing written (bring the inputs nearer the usual ranges)")
