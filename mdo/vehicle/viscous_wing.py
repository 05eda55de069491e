"""The aircraft's lattice with its strips on their section polars (``Aircraft(wing_viscous=True)``).

At every node each lattice strip s carries an angle shift ``wing_viscous_shift`` (rad, an NLP
unknown, n_strips x K), applied as an upwash V Delta_s along its panels' normals in the flow
tangency (not in the Kutta-Joukowski velocity), and the residual group "wing viscous correction"
(the strips' cl lifted as ``wing_strip_cl`` with its defining equality)

    cl_s - cl_section(alpha_e,s, Re_s, M) = 0,   alpha_e,s = beta cl_s / (2 pi) + alpha_0,s - Delta_s

(:mod:`mdo.wing.viscous`, validated through stall on Graf et al. 2014).  cl_s is the strip's cl on
its local velocity (slipstreams included), Re_s = rho V c / mu (freestream, as the stall margin's
cl_max(Re)), the section the strip's airfoil surrogate (``mdo.airfoil``), one SX kernel per section.
The strips' lift, induced drag, moments and stall margin then follow the section polars: cl_max and
the margin below it mean the section's.  Strips inside the fuselage (``Aircraft.strip_exposed``
False, as for the stall margin) keep the linear lattice.

On by default for airplanes; a tilt-wing flies its one-pass post-stall strips (``wing_stall``)
instead, and with both the correction applies at the wing-borne nodes only
(``Aircraft.post_stall_nodes``).  Cost and effect: ``results/table3.md`` (2026-12-05, sixth) and
``results/benchmark.md``.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..wing.viscous import effective_angle, lattice_zero_lift_angles, shift_velocity
from .base import ResidualGroup, Unknown

__all__ = ["viscous_unknowns", "viscous_upwash", "viscous_rows"]

NAME = "wing_viscous_shift"
CL = "wing_strip_cl"


def viscous_unknowns(ac) -> list:
    if not ac.wing_viscous:
        return []
    n = ac.vlm.n_strips
    labels = [f"strip {i}" for i in range(n)]
    return [Unknown(NAME, unit="rad", scale=0.02, lower=-0.6, upper=0.6, rows=n, row_labels=labels,
                    description="each lattice strip's angle shift of the viscous correction (mdo.wing.viscous)"),
            Unknown(CL, unit="-", scale=0.5, rows=n, row_labels=labels,
                    description="each lattice strip's cl on its local velocity (lifted)")]


def viscous_upwash(ac, unknowns, v_cp, V):
    """``v_cp`` (vx, vy, vz; N x K) plus the strips' shifts as upwash."""
    if not ac.wing_viscous:
        return v_cp
    dv = shift_velocity(ac.vlm, unknowns[NAME], V)
    return tuple(a + b for a, b in zip(v_cp, dv))


def viscous_rows(ac, r, unknowns, rho, mu, V, mach, flap=None, on=None) -> list:
    """The residual group (V1) of every strip at every node, from the lattice result ``r``.

    ``flap``: the segments' flap deflection (K numbers, 0-1).  A deflected flap enters the
    lattice as an incidence increment d_f = delta dcl_max / (2 pi) of its strips
    (``Aircraft.flap_upwash``); the flapped section is the clean one with its lift raised by
    2 pi d_f at every angle (the cl_max increment of the stall margin), so d_f is taken out of
    the effective angle and its lift added to the section's: a flap the linear lattice carries
    is not undone by the correction (Delta = 0 where the section is linear).  ``on`` (K
    booleans): the nodes where the correction applies; elsewhere the shifts are held at zero
    (a tilt-wing's transitions, which keep the post-stall strips); all nodes if None."""
    if not ac.wing_viscous:
        return []
    vlm = ac.vlm
    if getattr(ac, "_alpha0_lattice", None) is None:
        ac._alpha0_lattice = lattice_zero_lift_angles(vlm)
    # the strips' cl lifted (its equality is linear in the shifts at a fixed design), so the
    # section's curvature touches only its own strip and node; Re on the freestream speed, as
    # the stall margin's cl_max(Re) (mdo.vehicle.stall)
    cl, shift = unknowns[CL], unknowns[NAME]
    S, K = cl.shape
    Re = ca.repmat(vlm.geometry["strip_chord"].T, 1, K) * ca.repmat(rho * V / mu, S, 1)
    d_f = np.zeros((S, K))
    if flap is not None and np.any(flap):
        d_f = np.outer(ac._flap_strip_dalpha(), np.asarray(flap, float).ravel() * np.ones(K))
    a0 = np.repeat(np.asarray(ac._alpha0_lattice, float).reshape(-1, 1), K, axis=1)
    M = ca.repmat(mach, S, 1)
    exposed = np.asarray(ac.strip_exposed, bool)
    names = [str(a) for a in vlm.strip_airfoil]
    rows = [ca.DM.zeros(1, K)] * S
    for name in sorted(set(names)):
        idx = [i for i, a in enumerate(names) if a == name and exposed[i]]
        if not idx:
            continue
        f = _kernel(name).map(len(idx) * K)
        args = [_flat(x[idx, :]) for x in (cl, shift, M, Re)] + [_flat(ca.DM(z[idx, :])) for z in (a0, d_f)]
        R = ca.reshape(f(*args), len(idx), K)
        for j, i in enumerate(idx):
            rows[i] = R[j, :]
    # where the correction does not apply the shift is held at zero: strips inside the fuselage
    # (the wing's carry-through, no exposed section to stall) and, with ``on``, the nodes that
    # keep the post-stall strips
    active = np.outer(exposed, np.ones(K, bool) if on is None else np.asarray(on, bool))
    R = ca.vertcat(*rows)
    if not active.all():
        m = ca.DM(active.astype(float))
        R = m * R + (1.0 - m) * (2 * np.pi * shift)
    labels = [f"strip {i} ({vlm.surfaces[vlm.strip_surface[i]].name})" for i in range(vlm.n_strips)]
    return [ResidualGroup("wing strip cl (lifted)", cl - r["cl_local"], scale=0.5, unit="-", defines=CL,
                          row_labels=labels),
            ResidualGroup("wing viscous correction", R, scale=0.1, unit="-", row_labels=labels)]


_KERNELS: dict = {}


def _kernel(airfoil: str) -> ca.Function:
    """SX kernel of (V1) for one strip and node, the section inlined (its derivatives stay
    scalar): R = cl - cl_section(alpha_e - d_f, Re, M) - 2 pi d_f."""
    if airfoil not in _KERNELS:
        from ..airfoil import Airfoil
        cl, d, m, re, a0, df = (ca.SX.sym(n) for n in ("cl", "shift", "mach", "reynolds", "alpha0", "flap_angle"))
        a_e = effective_angle(cl, d, a0, m) - df
        sec = Airfoil.from_name(airfoil).coefficients(a_e, re, m)[0]
        _KERNELS[airfoil] = ca.Function("viscous_strip_" + str(len(_KERNELS)), [cl, d, m, re, a0, df],
                                        [cl - sec - 2 * np.pi * df])
    return _KERNELS[airfoil]


def _flat(x):
    """n x K -> 1 x nK (column-major, as ``ca.reshape`` back)."""
    return ca.reshape(x, 1, x.shape[0] * x.shape[1])
