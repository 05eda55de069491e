"""The blade-passage-averaged (axisymmetric) helical wake: the NLP's wake.

Why it is exact in form
-----------------------
Averaging the helical fixed wake (mdo.wake.helical) over the blade azimuth φ0
averages its vorticity; by the linearity of Biot–Savart the averaged velocity is
the field of the averaged vorticity, which is axisymmetric about e_a:

* each trailing helix of strength −spin·(Γ_{j−1} − Γ_j) at radius r_j, pitch p = V_w/Ω,
  becomes a cylindrical sheet from the disk (x = 0) downstream with
  - azimuthal vorticity B·ΔΓ_j/(2πp) per unit length (its helix winding), and
  - axial vorticity B·ΔΓ_j/(2π r_j) per unit length of circumference;
* the bound vortices become a sheet of radial vorticity on the disk.

Meridional vorticity (axial, radial) induces only swirl, azimuthal vorticity only
axial and radial velocity.  Hence, with ΔΓ_j = Γ_j − Γ_{j−1} the jump of the blade
circulation at edge j (Γ_{−1} = Γ_N = 0) and x, ρ the axial and radial coordinates of
a field point:

    swirl (Stokes: circulation = axial-vorticity flux through the circle at x, ρ)
        u_θ = spin · B/(2πρ) · Σ_j ΔΓ_j H(ρ − r_j) · S(x)
    axial and radial (superposed semi-infinite vortex cylinders, Branlard & Gaunaa 2015)
        (u_x, u_ρ) = −B/(2π p) · Σ_j ΔΓ_j · K(x/r_j, ρ/r_j)

with H and S unit steps (rounded by the filament core: H = ½(1 + h/√(h² + δ²)),
S likewise across the disk) and K = (K_x, K_ρ) the field of the unit semi-infinite
vortex cylinder, radially smeared by the same core, tabulated once
(data/cylinder_table_core005.npz and ..._core010.npz, one per core size, from
data/generate_cylinder_table.py) and evaluated
as a cubic tensor B-spline (casadi ``Function.bspline``).  Velocity fields of vortex
sheets are scale-free, so one 2-D table serves every edge radius, rotor radius,
advance ratio and loading; the advance ratio enters only through 1/p, the loading
only linearly through ΔΓ.  Far downstream inside the slipstream this gives
u_x = BΓΩ/(2πV_w) and u_θ = BΓ/(2πρ): the vortex-theory (Betz/Goldstein) relations.

What the NLP evaluates
----------------------
The table depends only on geometry (field points relative to the rotor, R, the
edges), so for a mission it is evaluated once per design:

    u_p = e_a·[Ax (Γ/p)]_p + rvec_p·[Ar (Γ/p)]_p + tdir_p·[At Γ]_p   (Ax, Ar, At: M × N)

and at every node only three matrix–vector products remain (:func:`influence_function`,
:func:`apply_influence`).
The semi-infinite wake stands for the paper's "few rotations"; at the GA-2P cruise
(J = 1, five rotations ≈ 11 R) the truncated end changes the velocity at the wing by
well under 1 % (bench).  Smoothness: the table is C² (cubic), even in ρ (mirrored
data), its arguments are clamped smoothly to its range (tanh), and the axis is
regularized (ρ → √(ρ² + (10⁻³R)²)), so the field is C² in the rotor position and
radius, the points and the operating point.
"""
from __future__ import annotations

import functools
import math
from pathlib import Path

import casadi as ca
import numpy as np

from ..core.errors import InputError
from .frames import rotor_frame
from .rotor import DEFAULT_CORE_REL

__all__ = ["unit_cylinder", "influence_function", "influence", "strip_averaged_influence", "apply_influence", "influence_parts",
           "mean_wake_velocity", "jump_matrix", "TABLE_CORE_REL", "table_core_rels", "checked_table_core",
           "DEFAULT_STRIP_SAMPLES"]

_DATA = Path(__file__).with_name("data")
TABLE_CORE_REL = DEFAULT_CORE_REL  # the default table: the one of the default core
_AXIS_REG = 1e-3  # ρ regularization / R


@functools.lru_cache(maxsize=None)
def table_core_rels() -> tuple:
    """The core sizes (core / radius) for which a mean-wake table ships, ascending."""
    return tuple(sorted(float(np.load(f)["core_rel"]) for f in _DATA.glob("cylinder_table_core*.npz")))


def checked_table_core(core_rel, field: str = "core_rel") -> float:
    """``core_rel`` if a mean-wake table ships for it, else an InputError naming ``field`` and the
    allowed values (the one check for the wake's rotors, the aircraft's option and the CLI)."""
    allowed = table_core_rels()
    if not any(abs(float(core_rel) - c) < 1e-9 for c in allowed):
        raise InputError(field, "one of " + ", ".join(f"{c:g}" for c in allowed)
                         + f" (the mean-wake tables that ship), got {core_rel!r}")
    return float(core_rel)


@functools.lru_cache(maxsize=None)
def _table(core_rel: float = TABLE_CORE_REL):
    name = _DATA / f"cylinder_table_core{round(checked_table_core(core_rel) * 100):03d}.npz"
    d = np.load(name)
    tx, ty = d["knots_xi"], d["knots_eta"]
    cx = np.asarray(d["coef_ux"], float).ravel(order="F")
    cg = np.asarray(d["coef_g"], float).ravel(order="F")
    coef = np.stack([cx, cg], axis=0).ravel(order="F")
    f = ca.Function.bspline("unit_cylinder_bspline", [tx.tolist(), ty.tolist()], coef.tolist(), [3, 3], 2, {})
    return f, float(d["xi"].max()), float(d["eta"].max()), float(d["core_rel"])


@functools.lru_cache(maxsize=None)
def unit_cylinder(core_rel: float = TABLE_CORE_REL) -> ca.Function:
    """MX Function ``unit_cylinder(xi, eta) -> (ux, g)``: axial velocity and g = u_ρ/η of a
    unit semi-infinite vortex cylinder (radius 1, unit azimuthal vorticity per length,
    from ξ = 0 to +∞), at axial ξ and radius η (in radii), smeared by the core.
    ξ and η are row vectors (1×n); the table's range (±400, 400 radii) is reached
    through a smooth tanh clamp."""
    bs, xmax, emax, _ = _table(core_rel)
    n = ca.MX.sym("n")  # placeholder for docs; the map is built per call size
    del n
    xi = ca.MX.sym("xi")
    eta = ca.MX.sym("eta")
    lx, le = 0.95 * xmax, 0.95 * emax
    out = bs(ca.vertcat(lx * ca.tanh(xi / lx), le * ca.tanh(eta / le)))
    return ca.Function("unit_cylinder", [xi, eta], [out[0], out[1]], ["xi", "eta"], ["ux", "g"])


def jump_matrix(n_stations: int) -> np.ndarray:
    """(N+1)×N matrix D with ΔΓ = D·Γ: ΔΓ_j = Γ_j − Γ_{j−1}, Γ_{−1} = Γ_N = 0."""
    d = np.zeros((n_stations + 1, n_stations))
    for j in range(n_stations + 1):
        if j < n_stations:
            d[j, j] += 1.0
        if j > 0:
            d[j, j - 1] -= 1.0
    return d


@functools.lru_cache(maxsize=None)
def influence_function(n_points: int, n_stations: int, blades: int, core_rel: float = TABLE_CORE_REL) -> ca.Function:
    """Function ``mean_wake_influence(points, center, axis, radius_m, s_edges, spin)
    -> (Ax, Ar, At, e_a, rvec, tdir)``: the averaged wake in factored form,

        u_p = e_a · [Ax (Γ/p)]_p + rvec_p · [Ar (Γ/p)]_p + tdir_p · [At Γ]_p,

    for blade circulations Γ (N,) on the elements bounded by ``s_edges`` (N+1, r/R),
    p = V_w/Ω (m/rad).  Ax, Ar, At: M×N (the edge jumps folded in: ΔΓ = D Γ);
    e_a: 3×1 unit wake axis; rvec: 3×M radial offsets of the points from the axis;
    tdir: 3×M swirl directions e_a × rvec/(ρ² + ε²) (|tdir| ≈ 1/ρ).  Depends on
    geometry only; nothing 3M×N is formed (the NLP multiplies M×N by N×K).
    """
    m, n, e = n_points, n_stations, n_stations + 1
    pts = ca.MX.sym("points", 3, m)
    center = ca.MX.sym("center", 3)
    axis = ca.MX.sym("axis", 3)
    radius = ca.MX.sym("radius_m")
    s_edges = ca.MX.sym("s_edges", e)
    spin = ca.MX.sym("spin")
    e_a, _, _ = rotor_frame(axis)
    d = pts - ca.repmat(center, 1, m)
    x = ca.mtimes(e_a.T, d)                                   # 1×M
    rvec = d - ca.mtimes(e_a, x)                              # 3×M
    eps = _AXIS_REG * radius
    rho_t2 = ca.sum1(rvec**2)                                 # 1×M, true ρ²
    rho = ca.sqrt(rho_t2 + eps**2)
    r_e = radius * s_edges                                    # E×1
    inv_re = 1.0 / r_e
    xi = ca.mtimes(inv_re, x)                                 # E×M
    eta = ca.mtimes(inv_re, rho)                              # E×M
    cyl = unit_cylinder(core_rel).map(e * m)
    kx, g = cyl(ca.reshape(xi, 1, e * m), ca.reshape(eta, 1, e * m))
    kx = ca.reshape(kx, e, m)
    g = ca.reshape(g, e, m) * ca.repmat(inv_re, 1, m)          # u_ρ vector = g·ρvec/r_e
    # swirl: H_e(ρ) with the core of edge e, written in ρ² so that it is smooth on the axis
    dr2 = ca.repmat(rho_t2, e, 1) - ca.repmat(r_e**2, 1, m)
    w2 = ca.repmat((2 * core_rel * r_e**2) ** 2, 1, m)
    h = 0.5 * (1 + dr2 / ca.sqrt(dr2**2 + w2))                 # E×M
    s_x = 0.5 * (1 + x / ca.sqrt(x**2 + (core_rel * radius) ** 2))  # 1×M, swirl step across the disk
    eps_h = core_rel * radius * s_edges[0]
    tdir = ca.cross(ca.repmat(e_a, 1, m), rvec) / ca.repmat(rho_t2 + eps_h**2, 3, 1)  # 3×M
    k = blades / (2 * math.pi)
    dmat = ca.DM(jump_matrix(n))                               # E×N
    ax = -k * ca.mtimes(kx.T, dmat)                            # M×N
    ar = -k * ca.mtimes(g.T, dmat)
    at = (spin * k) * ca.mtimes(h.T * ca.repmat(s_x.T, 1, e), dmat)
    return ca.Function("mean_wake_influence", [pts, center, axis, radius, s_edges, spin],
                       [ax, ar, at, e_a, rvec, tdir],
                       ["points", "center", "axis", "radius_m", "s_edges", "spin"],
                       ["Ax", "Ar", "At", "e_a", "rvec", "tdir"])


def influence_parts(infl, gamma_over_p, gamma):
    """The velocity of :func:`apply_influence` in two parts, each (vx, vy, vz) M×K: the
    component along the rotor axis, and the rest (radial and swirl) — so that callers
    needing both the whole wake and the wake without its axial part share the products."""
    if isinstance(infl, dict):   # strip-averaged: the directions are folded into the matrices
        ua = ca.mtimes(infl["Bx"], gamma_over_p)
        axial = tuple(infl["e_a"][c] * ua for c in range(3))
        rest = tuple(ca.mtimes(infl["Br"][c], gamma_over_p) + ca.mtimes(infl["Bt"][c], gamma) for c in range(3))
        return axial, rest
    ax, ar, at, e_a, rvec, tdir = infl
    ua = ca.mtimes(ax, gamma_over_p)                           # M×K
    ur = ca.mtimes(ar, gamma_over_p)
    ut = ca.mtimes(at, gamma)
    k = ua.shape[1]
    axial = tuple(e_a[c] * ua for c in range(3))
    rest = tuple(ca.repmat(rvec[c, :].T, 1, k) * ur + ca.repmat(tdir[c, :].T, 1, k) * ut for c in range(3))
    return axial, rest


def apply_influence(infl, gamma_over_p, gamma, axial_factor=1.0):
    """Velocity components (vx, vy, vz), each M×K, from the factored influence ``infl``
    (the 6 outputs of :func:`influence_function`, or a :func:`strip_averaged_influence`)
    and per-node Γ/p and Γ (N×K).
    ``axial_factor`` scales the component along the rotor axis (1: the wake as is)."""
    axial, rest = influence_parts(infl, gamma_over_p, gamma)
    return tuple(axial_factor * a + r for a, r in zip(axial, rest))


def _col(x):
    if isinstance(x, (ca.MX, ca.SX, ca.DM)):
        return ca.reshape(x, x.numel(), 1)
    return ca.DM(np.asarray(x, dtype=float).reshape(-1, 1))


def _pts(points):
    if isinstance(points, (ca.MX, ca.SX, ca.DM)):
        return points
    return ca.DM(np.asarray(points, float).reshape(3, -1))


def influence(points, rotor):
    """Factored influence (:func:`influence_function`) of a :class:`WakeRotor` at ``points`` (3×M)."""
    pts = _pts(points)
    f = influence_function(pts.shape[1], rotor.n_stations, rotor.blades, rotor.core_rel)
    return f(pts, _col(rotor.center), _col(rotor.axis), rotor.radius_m,
             ca.DM(np.asarray(rotor.s_edges)), rotor.spin)


#: wake samples across each lattice strip (:func:`strip_averaged_influence`).  With the default core
#: (``DEFAULT_CORE_REL``, 0.1) seven keep the strip-mean velocity from rippling as a slipstream edge
#: moves across a strip: on a GA-2P-like strip row the ripple's slope in the scrubbed dynamic
#: pressure is 0.4 times its trend's with seven, 3.7 times with five (tests/test_wake_coupling.py).
DEFAULT_STRIP_SAMPLES = 7


def strip_averaged_influence(points, spans, rotor, samples: int = DEFAULT_STRIP_SAMPLES):
    """The factored influence averaged over each lattice strip's span.

    A control point sees the wake at one spanwise station, but its strip's flow
    tangency stands for the whole strip: when a slipstream edge (a few cm wide)
    crosses a control point, that strip's loading jumps, and the mission energy
    ripples with the period of the lattice as a rotor moves (measured on GA-2P: ±0.35
    kWh over 0.03 of the semispan, ``tests/bench/position_sweep.py``).  Here the
    velocity is the mean over ``samples`` points p + ((s + ½)/S − ½) l, s = 0..S−1,
    spread along ``spans`` l (3×M, e.g. each panel's bound-vortex vector), a midpoint
    rule across the strip.  Returns a dict for :func:`apply_influence`: the averages
    of the three velocity components with the point-dependent directions folded in,
    ``Bx`` (times e_a), ``Br[c]``, ``Bt[c]`` (M×N each).
    """
    pts, spans = _pts(points), _pts(spans)
    m, S = pts.shape[1], int(samples)
    if S < 1:
        raise InputError("samples", f"must be >= 1, got {samples}")
    sub = ca.horzcat(*[pts + ((s + 0.5) / S - 0.5) * spans for s in range(S)])   # 3×(M·S), sample-major
    ax, ar, at, e_a, rvec, tdir = influence(sub, rotor)
    W = ca.repmat(ca.DM.eye(m), 1, S) / S                                        # M×(M·S) mean
    n = ax.shape[1]
    return {"e_a": e_a, "Bx": ca.mtimes(W, ax),
            "Br": [ca.mtimes(W, ca.repmat(rvec[c, :].T, 1, n) * ar) for c in range(3)],
            "Bt": [ca.mtimes(W, ca.repmat(tdir[c, :].T, 1, n) * at) for c in range(3)]}


def mean_wake_velocity(points, rotor, gamma, omega_radps, v_wake_mps):
    """Blade-passage-averaged induced velocity (3×M, m/s) of ``rotor`` at ``points``.

    Same inputs as :func:`mdo.wake.helical.full_wake_velocity`.  Numbers in → NumPy
    array out; MX in → MX out.
    """
    pts = _pts(points)
    infl = influence(pts, rotor)
    g = _col(gamma)
    vx, vy, vz = apply_influence(infl, g * (omega_radps / v_wake_mps), g)
    u = ca.horzcat(vx, vy, vz).T
    if isinstance(u, ca.DM):
        return np.array(u)
    return u
