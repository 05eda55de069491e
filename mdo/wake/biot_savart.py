"""Biot–Savart kernels: a straight vortex filament with a small core (Eq. 2) and
a quadrilateral vortex ring (Eq. 4), as SX ``casadi.Function``s mapped over
segments and field points.

Straight filament A→B of circulation Γ at field point P (paper Eq. 2, Katz &
Plotkin 2001 §10.4.5), with r0 = B − A, r1 = P − A, r2 = P − B:

    v = Γ/(4π) · (r1 × r2) / (|r1 × r2|² + δ²|r0|²) · r0·(r1/|r1| − r2/|r2|)

The δ²|r0|² term is the vortex core: since |r1 × r2| = h|r0| (h the distance of P
from the filament's line), the magnitude becomes Γ/(4π) · h/(h² + δ²) · (cos θ1 −
cos θ2), a Scully (n = 1) core of radius δ in metres, independent of the segment
length.  It keeps the kernel finite and smooth (C∞) everywhere: on the filament
the velocity is zero, at distance h = δ it is half the singular value, beyond a
few δ it is the singular law to (δ/h)².  |r1|, |r2| are regularized as
sqrt(|r|² + (10⁻² δ)²) so that a field point on a vertex gives a finite value.

Vortex ring A→B→C→D→A (Eq. 4): v_ring = v_AB + v_BC + v_CD + v_DA, circulation
positive by the right-hand rule about the circuit's order.

All kernels are per unit circulation; strengths multiply outside so that the
induced velocity is linear in Γ (the influence coefficients C of Eq. 6b).
"""
from __future__ import annotations

import functools
import math

import casadi as ca

__all__ = [
    "filament_kernel",
    "ring_kernel",
    "filament_sum",
    "filament_velocity",
    "ring_velocity",
]

_VERTEX_REG = 1e-2  # vertex regularization as a fraction of the core radius


def _filament_expr(a, b, p, core):
    r0 = b - a
    r1 = p - a
    r2 = p - b
    cross = ca.cross(r1, r2)
    den = ca.dot(cross, cross) + core**2 * ca.dot(r0, r0)
    eps2 = (_VERTEX_REG * core) ** 2
    n1 = ca.sqrt(ca.dot(r1, r1) + eps2)
    n2 = ca.sqrt(ca.dot(r2, r2) + eps2)
    return cross * (ca.dot(r0, r1 / n1 - r2 / n2) / (4 * math.pi * den))


@functools.lru_cache(maxsize=None)
def filament_kernel() -> ca.Function:
    """SX Function ``filament(A, B, P, core) -> v``: velocity (m/s per m²/s of Γ) at P
    induced by a unit-circulation straight filament A→B with Scully core ``core`` (m)."""
    a, b, p = ca.SX.sym("A", 3), ca.SX.sym("B", 3), ca.SX.sym("P", 3)
    core = ca.SX.sym("core")
    return ca.Function("filament", [a, b, p, core], [_filament_expr(a, b, p, core)],
                       ["A", "B", "P", "core"], ["v"])


@functools.lru_cache(maxsize=None)
def ring_kernel() -> ca.Function:
    """SX Function ``ring(A, B, C, D, P, core) -> v``: unit ring A→B→C→D→A (Eq. 4)."""
    a, b, c, d, p = (ca.SX.sym(n, 3) for n in "ABCDP")
    core = ca.SX.sym("core")
    v = (_filament_expr(a, b, p, core) + _filament_expr(b, c, p, core)
         + _filament_expr(c, d, p, core) + _filament_expr(d, a, p, core))
    return ca.Function("ring", [a, b, c, d, p, core], [v], ["A", "B", "C", "D", "P", "core"], ["v"])


@functools.lru_cache(maxsize=None)
def _weighted_filament() -> ca.Function:
    a, b, p = ca.SX.sym("A", 3), ca.SX.sym("B", 3), ca.SX.sym("P", 3)
    gamma, core = ca.SX.sym("gamma"), ca.SX.sym("core")
    return ca.Function("filament_w", [a, b, gamma, core, p],
                       [gamma * _filament_expr(a, b, p, core)],
                       ["A", "B", "gamma", "core", "P"], ["v"])


@functools.lru_cache(maxsize=None)
def _segment_sum(n_segments: int, jit: bool) -> ca.Function:
    """The weighted kernel mapped over segments with the output summed (``reduce_out``):
    ``(A 3×S, B 3×S, gamma 1×S, core 1×S, P 3×1) -> v 3×1``."""
    f = _weighted_filament().map("segment_sum", "serial", n_segments, [4], [0])
    return _maybe_jit(f) if jit else f


@functools.lru_cache(maxsize=None)
def filament_sum(n_segments: int, n_points: int, jit: bool = False) -> ca.Function:
    """Function ``filament_sum(A, B, gamma, core, P) -> V``.

    A, B: 3×S segment end points; gamma: 1×S circulations (m²/s); core: 1×S core
    radii (m); P: 3×M field points.  V: 3×M induced velocity (m/s), the sum over the
    segments.  The SX kernel is mapped over segments with the output summed
    (``reduce_out``, memory O(S)), and called once per field point from MX (a
    nested ``map`` with shared inputs costs seconds to build at S ~ 10⁴, M ~ 10²;
    M call nodes cost milliseconds and evaluate as fast).  ``jit=True`` compiles
    the segment loop to C when a compiler is available (about 7× faster numerically;
    measured in tests/bench/wake_full_vs_table.py).
    """
    seg = _segment_sum(n_segments, jit)
    a, b = ca.MX.sym("A", 3, n_segments), ca.MX.sym("B", 3, n_segments)
    g, c = ca.MX.sym("gamma", 1, n_segments), ca.MX.sym("core", 1, n_segments)
    p = ca.MX.sym("P", 3, n_points)
    v = ca.horzcat(*[seg(a, b, g, c, p[:, i]) for i in range(n_points)])
    return ca.Function("filament_sum", [a, b, g, c, p], [v], ["A", "B", "gamma", "core", "P"], ["V"])


_JIT_OK = None


def _maybe_jit(f: ca.Function) -> ca.Function:
    """JIT-compile ``f`` to C with the system compiler; return ``f`` itself if that fails."""
    global _JIT_OK
    if _JIT_OK is False:
        return f
    try:
        opts = {"jit": True, "compiler": "shell", "jit_cleanup": True,
                "jit_options": {"flags": ["-O3"], "verbose": False}}
        fj = ca.Function(f.name() + "_jit", f.mx_in(), f.call(f.mx_in()), f.name_in(), f.name_out(), opts)
        _JIT_OK = True
        return fj
    except Exception:  # no compiler: the VM evaluates the same graph
        _JIT_OK = False
        return f


@functools.lru_cache(maxsize=None)
def _ring_map(n_rings: int, n_points: int) -> ca.Function:
    a, b, c, d, p = (ca.SX.sym(n, 3) for n in "ABCDP")
    gamma, core = ca.SX.sym("gamma"), ca.SX.sym("core")
    f = ca.Function("ring_w", [a, b, c, d, gamma, core, p],
                    [gamma * ring_kernel()(a, b, c, d, p, core)])
    seg = f.map("ring_sum", "serial", n_rings, [6], [0])
    syms = [ca.MX.sym(n, 3, n_rings) for n in "ABCD"] + [ca.MX.sym("gamma", 1, n_rings),
                                                           ca.MX.sym("core", 1, n_rings)]
    p = ca.MX.sym("P", 3, n_points)
    v = ca.horzcat(*[seg(*syms, p[:, i]) for i in range(n_points)])
    return ca.Function("ring_sum", syms + [p], [v], ["A", "B", "C", "D", "gamma", "core", "P"], ["V"])


def filament_velocity(a, b, gamma, core, points):
    """Induced velocity (3×M) of straight filaments (3×S ends ``a``→``b``, strengths
    ``gamma`` (S,), cores (S,) or scalar) at ``points`` (3×M). Numbers or CasADi."""
    a, b, points = (_as_3xn(v) for v in (a, b, points))
    s, m = a.shape[1], points.shape[1]
    gamma = _row(gamma, s)
    core = _row(core, s)
    numeric = not any(isinstance(v, (ca.SX, ca.MX)) for v in (a, b, gamma, core, points))
    return filament_sum(s, m, numeric)(a, b, gamma, core, points)


def ring_velocity(corners, gamma, core, points):
    """Induced velocity (3×M) of vortex rings (Eq. 4). ``corners``: tuple of four
    3×N arrays (A, B, C, D); ``gamma``: (N,) circulations; ``core``: scalar (m)."""
    a, b, c, d = (_as_3xn(v) for v in corners)
    points = _as_3xn(points)
    n, m = a.shape[1], points.shape[1]
    return _ring_map(n, m)(a, b, c, d, _row(gamma, n), _row(core, n), points)


def _as_3xn(x):
    if isinstance(x, (ca.SX, ca.MX, ca.DM)):
        if x.shape[0] != 3 and x.shape[1] == 3:
            return x.T
        return x
    import numpy as np
    x = np.asarray(x, dtype=float)
    if x.ndim == 1:
        x = x.reshape(3, 1)
    if x.shape[0] != 3 and x.shape[-1] == 3:
        x = x.T
    return ca.DM(x)


def _row(x, n):
    if isinstance(x, (ca.SX, ca.MX, ca.DM)):
        if x.numel() == 1:
            return ca.repmat(x, 1, n)
        return ca.reshape(x, 1, n)
    import numpy as np
    x = np.asarray(x, dtype=float).ravel()
    if x.size == 1:
        x = np.full(n, x[0])
    return ca.DM(x.reshape(1, n))
