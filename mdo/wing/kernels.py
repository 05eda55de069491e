"""Biot–Savart kernels of the vortex lattice, as small SX ``casadi.Function``s.

Each kernel returns the velocity induced at a point ``P`` by one straight vortex
filament of unit circulation (m/s per m^2/s, i.e. 1/m).  The ``*_column`` functions
map them over all points at once (one column of the lattice's influence, velocity or
Trefftz matrices per filament), with the 2-D Trefftz-plane kernels (a point vortex;
the mean of ln r over a segment); :mod:`mdo.wing.vlm` calls them from MX.

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

__all__ = ["segment_velocity", "semi_infinite_velocity", "INV4PI", "TWO_PI_INV", "segment_column", "semi_column",
           "velocity_columns", "trefftz_column", "log_segment_column", "log_point_column"]

INV4PI = 1.0 / (4.0 * math.pi)
TWO_PI_INV = 1.0 / (2.0 * math.pi)
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


# --- the kernels mapped over many points (the columns of the lattice's matrices) -------------
@functools.lru_cache(maxsize=None)
def segment_column(n_cp: int) -> ca.Function:
    """(P[3 x n], nrm[3 x n], A[3], B[3], core) -> w[n x 1]: n_i . v(P_i) of a unit segment A->B."""
    P = ca.SX.sym("P", 3, n_cp)
    N = ca.SX.sym("n", 3, n_cp)
    A = ca.SX.sym("A", 3)
    B = ca.SX.sym("B", 3)
    core = ca.SX.sym("core")
    f = segment_velocity()
    v = f.map(n_cp)(P, ca.repmat(A, 1, n_cp), ca.repmat(B, 1, n_cp), core)
    w = ca.sum1(v * N).T
    return ca.Function("segment_column", [P, N, A, B, core], [w], ["P", "n", "A", "B", "core"], ["w"])


@functools.lru_cache(maxsize=None)
def semi_column(n_cp: int) -> ca.Function:
    """(P, nrm, A[3], core) -> w[n x 1]: n_i . v(P_i) of a unit filament from A to infinity along +x."""
    P = ca.SX.sym("P", 3, n_cp)
    N = ca.SX.sym("n", 3, n_cp)
    A = ca.SX.sym("A", 3)
    core = ca.SX.sym("core")
    f = semi_infinite_velocity()
    u = ca.DM([1.0, 0.0, 0.0])
    v = f.map(n_cp)(P, ca.repmat(A, 1, n_cp), ca.repmat(u, 1, n_cp), core)
    w = ca.sum1(v * N).T
    return ca.Function("semi_column", [P, N, A, core], [w], ["P", "n", "A", "core"], ["w"])


@functools.lru_cache(maxsize=None)
def velocity_columns(n_pts: int, semi: bool) -> ca.Function:
    """(P[3 x n], A[3], B[3] or nothing, core) -> vx, vy, vz [n x 1]: velocity of a unit filament."""
    P = ca.SX.sym("P", 3, n_pts)
    A = ca.SX.sym("A", 3)
    B = ca.SX.sym("B", 3)
    core = ca.SX.sym("core")
    if semi:
        u = ca.DM([1.0, 0.0, 0.0])
        v = semi_infinite_velocity().map(n_pts)(P, ca.repmat(A, 1, n_pts), ca.repmat(u, 1, n_pts), core)
        ins, names = [P, A, core], ["P", "A", "core"]
    else:
        v = segment_velocity().map(n_pts)(P, ca.repmat(A, 1, n_pts), ca.repmat(B, 1, n_pts), core)
        ins, names = [P, A, B, core], ["P", "A", "B", "core"]
    return ca.Function("velocity_columns", ins, [v[0, :].T, v[1, :].T, v[2, :].T], names, ["vx", "vy", "vz"])


@functools.lru_cache(maxsize=None)
def trefftz_column(n_mid: int) -> ca.Function:
    """(mid[2 x n], nds[2 x n], e[2], core) -> w[n x 1]: nds_s . v_2D(mid_s) of a unit 2-D vortex at e."""
    M = ca.SX.sym("mid", 2, n_mid)
    Nd = ca.SX.sym("nds", 2, n_mid)
    e = ca.SX.sym("e", 2)
    core = ca.SX.sym("core")
    dy = M[0, :] - e[0]
    dz = M[1, :] - e[1]
    r2 = dy * dy + dz * dz
    k = TWO_PI_INV / ca.sqrt(r2 * r2 + core**4)      # 1/(2 pi r^2), with the smooth core
    vy = -k * dz
    vz = k * dy
    w = (vy * Nd[0, :] + vz * Nd[1, :]).T
    return ca.Function("trefftz_column", [M, Nd, e, core], [w], ["mid", "nds", "e", "core"], ["w"])


@functools.lru_cache(maxsize=None)
def log_segment_column(n_pts: int) -> ca.Function:
    """(pts[2 x n], a[2], b[2]) -> w[n x 1]: mean of ln|p - r'| over the segment a-b, for each point p.

    Closed form (2-D): with x along the segment from the foot of p and v the
    distance to its line, integral ln sqrt(x^2 + v^2) dx = x ln sqrt(x^2+v^2) - x + v atan(x/v);
    v carries a 1e-9 m floor (smooth; the points never lie on the segment).
    """
    Pt = ca.SX.sym("pts", 2, n_pts)
    a = ca.SX.sym("a", 2)
    b = ca.SX.sym("b", 2)
    d = b - a
    L = ca.sqrt(ca.sumsqr(d))
    t = d / L
    rx = Pt[0, :] - a[0]
    ry = Pt[1, :] - a[1]
    u = rx * t[0] + ry * t[1]
    v = rx * t[1] - ry * t[0]
    av = ca.sqrt(v * v + 1e-18)

    def F(x):
        return 0.5 * x * ca.log(x * x + av * av) - x + av * ca.atan(x / av)

    w = ((F(L - u) - F(-u)) / L).T
    return ca.Function("log_segment_column", [Pt, a, b], [w], ["pts", "a", "b"], ["w"])


@functools.lru_cache(maxsize=None)
def log_point_column(n_pts: int) -> ca.Function:
    """(pts[2 x n], q[2]) -> ln|p - q| for each point (far-field pairs of the Trefftz energy)."""
    Pt = ca.SX.sym("pts", 2, n_pts)
    q = ca.SX.sym("q", 2)
    d2 = (Pt[0, :] - q[0]) ** 2 + (Pt[1, :] - q[1]) ** 2
    return ca.Function("log_point_column", [Pt, q], [0.5 * ca.log(d2 + 1e-18).T], ["pts", "q"], ["w"])
