"""The aircraft's lattice with its strips on their section polars (``Aircraft(wing_viscous=True)``).

At every node each lattice strip s carries an angle shift ``wing_viscous_shift`` (rad, an NLP
unknown, n_strips x K), applied as an upwash V Delta_s along its panels' normals in the flow
tangency (not in the Kutta-Joukowski velocity), and the residual group "wing viscous correction"

    cl_s - cl_section(alpha_e,s, Re_s, M) = 0,   alpha_e,s = beta cl_s / (2 pi) + alpha_0,s - Delta_s

(:mod:`mdo.wing.viscous`, validated through stall on Graf et al. 2014).  cl_s is the strip's cl on
its local velocity (slipstreams included), Re_s = rho V_local c / mu, the section the strip's
airfoil surrogate (``mdo.airfoil``).  The strips' lift, induced drag, moments and stall margin then
follow the section polars: cl_max and the margin below it mean the section's.  It replaces the
tilt-wing's one-pass post-stall strips (``wing_stall``).  Off by default (the committed results
fly the linear lattice); cost and effect measured in issue 17's notes.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..wing.viscous import lattice_zero_lift_angles, shift_velocity, viscous_residual
from .base import ResidualGroup, Unknown

__all__ = ["viscous_unknowns", "viscous_upwash", "viscous_rows"]

NAME = "wing_viscous_shift"


def viscous_unknowns(ac) -> list:
    if not ac.wing_viscous:
        return []
    n = ac.vlm.n_strips
    return [Unknown(NAME, unit="rad", scale=0.02, lower=-0.6, upper=0.6, rows=n,
                    row_labels=[f"strip {i}" for i in range(n)],
                    description="each lattice strip's angle shift of the viscous correction (mdo.wing.viscous)")]


def viscous_upwash(ac, unknowns, v_cp, V):
    """``v_cp`` (vx, vy, vz; N x K) plus the strips' shifts as upwash."""
    if not ac.wing_viscous:
        return v_cp
    dv = shift_velocity(ac.vlm, unknowns[NAME], V)
    return tuple(a + b for a, b in zip(v_cp, dv))


def viscous_rows(ac, r, unknowns, rho, mu, mach, flap=None) -> list:
    """The residual group (V1) of every strip at every node, from the lattice result ``r``.

    ``flap``: the segments' flap deflection (K numbers, 0-1).  A deflected flap enters the
    lattice as an incidence increment d_f = delta dcl_max / (2 pi) of its strips
    (``Aircraft.flap_upwash``); the flapped section is the clean one with its lift raised by
    2 pi d_f at every angle (the cl_max increment of the stall margin), so d_f is taken out of
    the effective angle and its lift added to the section's: a flap the linear lattice carries
    is not undone by the correction (Delta = 0 where the section is linear)."""
    if not ac.wing_viscous:
        return []
    vlm = ac.vlm
    if getattr(ac, "_alpha0_lattice", None) is None:
        ac._alpha0_lattice = lattice_zero_lift_angles(vlm)
    K = r["cl_local"].shape[1]
    chord = ca.repmat(vlm.geometry["strip_chord"].T, 1, K)
    Re = chord * r["V_local"] * ca.repmat(rho / mu, vlm.n_strips, 1)
    names = [str(a) for a in vlm.strip_airfoil]
    groups = {n: [i for i, a in enumerate(names) if a == n] for n in sorted(set(names))}
    M = ca.repmat(mach, 1, 1)

    def section_cl(alpha_e):
        from ..airfoil import Airfoil
        rows = [None] * vlm.n_strips
        for name, idx in groups.items():
            cl = Airfoil.from_name(name).coefficients(alpha_e[idx, :], Re[idx, :], ca.repmat(M, len(idx), 1))[0]
            for j, i in enumerate(idx):
                rows[i] = cl[j, :]
        return ca.vertcat(*rows)

    d_f = None
    if flap is not None and np.any(flap) and np.any(ac._flap_strip_dalpha()):
        d_f = ca.DM(np.outer(ac._flap_strip_dalpha(), np.asarray(flap, float).ravel() * np.ones(K)))
    if d_f is None:
        sec = section_cl
    else:
        def sec(alpha_e):
            return section_cl(alpha_e - d_f) + 2 * np.pi * d_f
    R, _ = viscous_residual(vlm, r, unknowns[NAME], sec, mach, alpha0=ac._alpha0_lattice)
    labels = [f"strip {i} ({vlm.surfaces[vlm.strip_surface[i]].name})" for i in range(vlm.n_strips)]
    return [ResidualGroup("wing viscous correction", R, scale=0.1, unit="-", row_labels=labels)]
