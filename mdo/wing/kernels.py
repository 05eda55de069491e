"""Biot–Savart kernels of the vortex lattice, as small SX ``casadi.Function``s.

Each kernel returns the velocity induced at a point ``P`` by one straight vortex
filament of unit circulation (m/s per m^2/s, i.e. 1/m).  They are mapped over
(control point, filament) pairs by :mod:`mdo.wing.vlm` and called from MX.

Finite segment A -> B (paper Eq. 2, Katz & Plotkin 2001 Eq. 10.115)::

    r0 = B - A,  r1 = P - A,  r2 = P - B
    v  = 1/(4 pi) * (r1 x r2) / |r1 x r2|^2 * r0 . (r1/|r1| - r2/|r2|)

Semi-infinite filament from A along the unit vector u (the limit B -> A + L u,
L -> infinity, of the same formula)::

    v  = 1/(4 pi) * (u x r1) / |u x r1|^2 * (1 + u . r1/|r1|)

Vortex core.  Eq. 2 is singular on the filament's line.  The square of the
distance to the line, ``d^2`` (written ``|r1 x r2|^2/|r0|^2`` or ``|u x r1|^2``),
is replaced by ``sqrt(d^4 + delta^4)``: smooth everywhere, and the relative
change of the velocity at a distance d is delta^4/(2 d^4) (1e-4 at d = 8.4 delta),
so with a core of a few percent of the strip width the lattice's own
interactions are untouched while a control point lying on another surface's
trailing leg (a tail in the wing's wake) sees a finite, smooth velocity.
``|r1|`` and ``|r2|`` carry a 1e-12 m floor only to keep the expression finite
when a point coincides with a filament end (never the case for control points).
"""
from __future__ import annotations

import functools
import math

import casadi as ca

__all__ = ["segment_velocity", "semi_infinite_velocity", "INV4PI"]

INV4PI = 1.0 / (4.0 * math.pi)
_TINY2 = 1e-24  # m^2
_TINY8 = 1e-48  # m^8: keeps a zero-length segment (pointed tip) at exactly zero velocity


def _cross(a, b):
    return ca.vertcat(a[1] * b[2] - a[2] * b[1],
                      a[2] * b[0] - a[0] * b[2],
                      a[0] * b[1] - a[1] * b[0])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


@functools.lru_cache(maxsize=None)
def segment_velocity() -> ca.Function:
    """SX Function ``(P[3], A[3], B[3], core) -> v[3]``: unit-circulation finite segment."""
    P = ca.SX.sym("P", 3)
    A = ca.SX.sym("A", 3)
    B = ca.SX.sym("B", 3)
    core = ca.SX.sym("core")
    r0 = B - A
    r1 = P - A
    r2 = P - B
    c = _cross(r1, r2)
    c2 = _dot(c, c)
    l2 = _dot(r0, r0)
    # |r1 x r2|^2 = |r0|^2 d^2  ->  |r0|^2 sqrt(d^4 + core^4)
    den = ca.sqrt(c2 * c2 + (l2 * core * core) ** 2 + _TINY8)
    n1 = ca.sqrt(_dot(r1, r1) + _TINY2)
    n2 = ca.sqrt(_dot(r2, r2) + _TINY2)
    k = INV4PI * (_dot(r0, r1) / n1 - _dot(r0, r2) / n2) / den
    return ca.Function("segment_velocity", [P, A, B, core], [k * c],
                       ["P", "A", "B", "core"], ["v"])


@functools.lru_cache(maxsize=None)
def semi_infinite_velocity() -> ca.Function:
    """SX Function ``(P[3], A[3], u[3], core) -> v[3]``: filament from A to infinity along unit u."""
    P = ca.SX.sym("P", 3)
    A = ca.SX.sym("A", 3)
    u = ca.SX.sym("u", 3)
    core = ca.SX.sym("core")
    r1 = P - A
    c = _cross(u, r1)
    d2 = _dot(c, c)
    den = ca.sqrt(d2 * d2 + core ** 4 + _TINY8)
    n1 = ca.sqrt(_dot(r1, r1) + _TINY2)
    k = INV4PI * (1.0 + _dot(u, r1) / n1) / den
    return ca.Function("semi_infinite_velocity", [P, A, u, core], [k * c],
                       ["P", "A", "u", "core"], ["v"])
