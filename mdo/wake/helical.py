"""The helical fixed wake (paper §III.B, Eqs. 2, 4, 6b): vortex rings shed from each
blade's quarter-chord line at fixed time steps, convected along the rotor axis.

Geometry
--------
Blade b of B sits at azimuth ψ_b(t) = φ0 + 2πb/B + spin·Ω·t about the wake axis e_a
(frames.rotor_frame).  Its quarter-chord line is radial; the ring edges lie at the
radii r_j = R·s_j, j = 0..N (hub to tip; ``s_edges``), bounding the N blade elements
whose circulations Γ_i the BEMT gives.  Vorticity shed at time step k (k = 0 at the
blade, Δψ = 2π/steps_per_rotation) has turned back to azimuth ψ_b − spin·k·Δψ and
travelled x_k = p·k·Δψ downstream, where

    p = V_w / Ω   (m/rad),   V_w = V∞·e_a + v̄_a,

the freestream along the axis plus the mean induced axial velocity of the BEMT (the
paper's choice).  No contraction: the helix radius stays R (fixed wake, as in the
paper's HFW; momentum contraction at the wing, x ≈ 1–2 R, is 3–6 % of R at the GA-2P
cruise loading and is left out so that the geometry does not depend on the node's
thrust; the comparison in tests/bench/wake_full_vs_table.py is at equal geometry).
Vertices: X(b,k,j) = c + x_k e_a + r_j (cos ψ e_1 + sin ψ e_2).

Strengths
---------
Ring (b, i, k) has corners X(b,k,i) → X(b,k,i+1) → X(b,k+1,i+1) → X(b,k+1,i) and
circulation −spin·Γ_i (the bound edge points tip→hub for spin = +1, which is the sense
that makes Kutta–Joukowski thrust point along −e_a).  The rings of a steady rotor
carry the same Γ_i at every time step, so adjacent rings cancel on their common
shed edges and share their trailing edges: the net filaments ("lattice" form) are

* the bound vortex X(b,0,i) → X(b,0,i+1), strength −spin·Γ_i,
* trailing helices X(b,k,j) → X(b,k+1,j), strength −spin·(Γ_{j−1} − Γ_j), i.e. the
  difference between neighbouring stations (Γ_{−1} = Γ_N = 0),
* the closing edge at the wake's end X(b,K,i+1) → X(b,K,i), strength −spin·Γ_i.

Both forms are implemented: ``form="rings"`` sums Eq. 4 over every ring (the paper
literally), ``form="lattice"`` sums the net filaments (same field to rounding, about
4N/(N+1) ≈ 4× fewer kernel calls).  The induced velocity at field points is the
Biot–Savart sum (Eq. 2, Scully core).

Phase
-----
The field of a discrete wake depends on the blade azimuth φ0.  The paper's wake is a
snapshot; the wing responds to its blade-passage average.  ``phases=n`` averages n
snapshots at φ0 + m·2π/(B n), m = 0..n−1, which converges to the axisymmetric mean
field of mdo.wake.mean as n grows.
"""
from __future__ import annotations

import functools
import math

import casadi as ca
import numpy as np

from .biot_savart import filament_sum
from .frames import rotor_frame

__all__ = ["wake_segments_function", "full_wake_function", "full_wake_velocity",
           "DEFAULT_ROTATIONS", "DEFAULT_STEPS_PER_ROTATION"]

DEFAULT_ROTATIONS = 5
DEFAULT_STEPS_PER_ROTATION = 36


def _vertices(center, e_a, e_1, e_2, radius, s_edges, pitch, spin, phase, blades, n_edges, n_steps, dpsi):
    """3 × (B·(K+1)·(N+1)) vertices, index ((b·(K+1) + k)·(N+1) + j)."""
    kk = np.arange(n_steps + 1)
    bb = np.arange(blades)
    cb = np.repeat(2 * math.pi * bb / blades, n_steps + 1)          # per (b, k)
    ck = np.tile(kk * dpsi, blades)                                  # per (b, k)
    psi = phase + ca.DM(cb).T - spin * ca.DM(ck).T                   # 1 × B(K+1)
    ones_j = ca.DM.ones(1, n_edges)
    r = radius * ca.reshape(s_edges, 1, n_edges)                     # 1 × (N+1)
    rc = ca.kron(ca.cos(psi), r)
    rs = ca.kron(ca.sin(psi), r)
    x = pitch * ca.kron(ca.DM(ck).T, ones_j)
    n_v = blades * (n_steps + 1) * n_edges
    return (ca.repmat(center, 1, n_v) + ca.mtimes(e_a, x) + ca.mtimes(e_1, rc) + ca.mtimes(e_2, rs))


@functools.lru_cache(maxsize=None)
def wake_segments_function(blades: int, n_stations: int, n_rotations: float = DEFAULT_ROTATIONS,
                           steps_per_rotation: int = DEFAULT_STEPS_PER_ROTATION,
                           phases: int = 1, form: str = "lattice") -> ca.Function:
    """Function ``helical_wake(center, axis, radius_m, s_edges, gamma, pitch_m, spin,
    phase_rad, core_rel) -> (A, B, strength, core)``: the wake's straight filaments.

    A, B (3×S) filament ends; ``strength`` (1×S, m²/s) includes −spin and 1/phases;
    ``core`` (1×S, m): core_rel·r_j for filaments along the helix at r_j, core_rel·R
    for radial ones.  ``form="lattice"``: the net filaments; ``form="rings"``: the four
    sides of every ring (Eq. 4).  Inputs: ``gamma`` (N) blade circulation per element
    (m²/s, > 0 for thrust), ``s_edges`` (N+1) element edges r/R, ``pitch_m`` = V_w/Ω
    (m/rad), ``spin`` ±1, ``phase_rad`` blade-0 azimuth.
    """
    if form not in ("lattice", "rings"):
        raise ValueError(form)
    n = n_stations
    n_edges = n + 1
    k_steps = int(round(n_rotations * steps_per_rotation))
    dpsi = 2 * math.pi / steps_per_rotation

    center = ca.MX.sym("center", 3)
    axis = ca.MX.sym("axis", 3)
    radius = ca.MX.sym("radius_m")
    s_edges = ca.MX.sym("s_edges", n_edges)
    gamma = ca.MX.sym("gamma", n)
    pitch = ca.MX.sym("pitch_m")
    spin = ca.MX.sym("spin")
    phase = ca.MX.sym("phase_rad")
    core_rel = ca.MX.sym("core_rel")
    e_a, e_1, e_2 = rotor_frame(axis)

    def vidx(b, k, j):
        return (b * (k_steps + 1) + k) * n_edges + j

    g_row = ca.reshape(gamma, 1, n)
    g_ext = ca.horzcat(ca.DM.zeros(1, 1), g_row, ca.DM.zeros(1, 1))        # Γ_{-1}, Γ_0..Γ_{N-1}, Γ_N
    d_gamma = g_ext[:, :-1] - g_ext[:, 1:]                                  # Γ_{j-1} − Γ_j, j = 0..N

    # cores: a filament along the helix at radius r_j has core core_rel·r_j, a radial
    # one (bound, shed, closing) core_rel·R — the same rule the mean-wake table uses
    c_edge = core_rel * radius * ca.reshape(s_edges, 1, n_edges)
    c_rad = core_rel * radius * ca.DM.ones(1, n)
    As, Bs, Gs, Cs = [], [], [], []
    for m in range(phases):
        ph = phase + 2 * math.pi * m / (blades * phases)
        X = _vertices(center, e_a, e_1, e_2, radius, s_edges, pitch, spin, ph, blades, n_edges, k_steps, dpsi)
        ia, ib, gs, cs = [], [], [], []
        for b in range(blades):
            if form == "lattice":
                ia += [vidx(b, 0, i) for i in range(n)]
                ib += [vidx(b, 0, i + 1) for i in range(n)]
                gs.append(g_row)
                cs.append(c_rad)
                for k in range(k_steps):
                    ia += [vidx(b, k, j) for j in range(n_edges)]
                    ib += [vidx(b, k + 1, j) for j in range(n_edges)]
                gs.append(ca.repmat(d_gamma, 1, k_steps))
                cs.append(ca.repmat(c_edge, 1, k_steps))
                ia += [vidx(b, k_steps, i + 1) for i in range(n)]
                ib += [vidx(b, k_steps, i) for i in range(n)]
                gs.append(g_row)
                cs.append(c_rad)
            else:  # Eq. 4 per ring: AB + BC + CD + DA, each with the ring's Γ_i
                for k in range(k_steps):
                    a_ = [vidx(b, k, i) for i in range(n)]
                    b_ = [vidx(b, k, i + 1) for i in range(n)]
                    c_ = [vidx(b, k + 1, i + 1) for i in range(n)]
                    d_ = [vidx(b, k + 1, i) for i in range(n)]
                    ia += a_ + b_ + c_ + d_
                    ib += b_ + c_ + d_ + a_
                    gs.append(ca.repmat(g_row, 1, 4))
                    cs += [c_rad, c_edge[:, 1:], c_rad, c_edge[:, :-1]]
        As.append(X[:, ia])
        Bs.append(X[:, ib])
        Gs.append(ca.horzcat(*gs))
        Cs.append(ca.horzcat(*cs))
    A = ca.horzcat(*As)
    B = ca.horzcat(*Bs)
    strength = -spin * ca.horzcat(*Gs) / phases
    cores = ca.horzcat(*Cs)
    return ca.Function(
        f"helical_wake_{form}", [center, axis, radius, s_edges, gamma, pitch, spin, phase, core_rel],
        [A, B, strength, cores],
        ["center", "axis", "radius_m", "s_edges", "gamma", "pitch_m", "spin", "phase_rad", "core_rel"],
        ["A", "B", "strength", "core"])


@functools.lru_cache(maxsize=None)
def full_wake_function(n_points: int, blades: int, n_stations: int,
                       n_rotations: float = DEFAULT_ROTATIONS,
                       steps_per_rotation: int = DEFAULT_STEPS_PER_ROTATION,
                       phases: int = 1, form: str = "lattice", jit: bool = False) -> ca.Function:
    """Function ``full_wake(points, center, axis, radius_m, s_edges, gamma, omega_radps,
    v_wake_mps, spin, phase_rad, core_rel) -> v`` (3×M, m/s): the induced velocity of one
    rotor's helical fixed wake at ``points`` (3×M).  Symbolic in every input; the
    structure (blades, stations, time steps, phases, points) is fixed at build."""
    geo = wake_segments_function(blades, n_stations, n_rotations, steps_per_rotation, phases, form)
    pts = ca.MX.sym("points", 3, n_points)
    center = ca.MX.sym("center", 3)
    axis = ca.MX.sym("axis", 3)
    radius = ca.MX.sym("radius_m")
    s_edges = ca.MX.sym("s_edges", n_stations + 1)
    gamma = ca.MX.sym("gamma", n_stations)
    omega = ca.MX.sym("omega_radps")
    v_wake = ca.MX.sym("v_wake_mps")
    spin = ca.MX.sym("spin")
    phase = ca.MX.sym("phase_rad")
    core_rel = ca.MX.sym("core_rel")
    A, B, g, c = geo(center, axis, radius, s_edges, gamma, v_wake / omega, spin, phase, core_rel)
    s = geo.size_out(0)[1]
    v = filament_sum(s, n_points, jit)(A, B, g, c, pts)
    return ca.Function(
        f"full_wake_{form}",
        [pts, center, axis, radius, s_edges, gamma, omega, v_wake, spin, phase, core_rel], [v],
        ["points", "center", "axis", "radius_m", "s_edges", "gamma", "omega_radps", "v_wake_mps",
         "spin", "phase_rad", "core_rel"], ["v"])


def full_wake_velocity(points, rotor, gamma, omega_radps, v_wake_mps, *, phase_rad=0.0,
                       n_rotations=DEFAULT_ROTATIONS, steps_per_rotation=DEFAULT_STEPS_PER_ROTATION,
                       phases=1, form="lattice", core_rel=None):
    """Induced velocity (3×M, m/s) of ``rotor``'s helical fixed wake at ``points`` (3×M).

    ``rotor``: a :class:`mdo.wake.WakeRotor`; ``gamma``: blade circulation per element
    (N,), m²/s; ``omega_radps``: rotor speed; ``v_wake_mps``: convection speed along
    the axis (V∞·e_a + mean induced axial velocity).  Numbers or CasADi MX.
    ``core_rel``: filament core radius / R (default: the rotor's ``core_rel``).
    """
    pts = points if isinstance(points, (ca.MX, ca.SX, ca.DM)) else ca.DM(np.asarray(points, float).reshape(3, -1))
    numeric = not any(isinstance(v, (ca.MX, ca.SX)) for v in
                      (pts, rotor.center, rotor.axis, rotor.radius_m, gamma, omega_radps, v_wake_mps))
    n = len(rotor.s_edges) - 1
    f = full_wake_function(pts.shape[1], rotor.blades, n, n_rotations, steps_per_rotation, phases, form,
                           jit=numeric)
    core = rotor.core_rel if core_rel is None else core_rel
    out = f(pts, _col(rotor.center), _col(rotor.axis), rotor.radius_m, ca.DM(np.asarray(rotor.s_edges, float)),
            _col(gamma), omega_radps, v_wake_mps, rotor.spin, phase_rad, core)
    return np.array(out) if numeric else out


def _col(x):
    if isinstance(x, (ca.MX, ca.SX, ca.DM)):
        return ca.reshape(x, x.numel(), 1)
    return ca.DM(np.asarray(x, dtype=float).reshape(-1, 1))
