"""The lattice near and beyond stall: each strip's lift follows its section polar.

A vortex lattice is linear in the angle of attack; a wing near cl_max is not.  The
viscous correction used here is the "alpha method" of the nonlinear lifting-line
and lattice literature (Tseng & Lan, NASA CR-4182, 1988; van Dam, Vander Kam & Paris,
J. Aircraft 38(2), 2001; Gallay & Laurendeau, AIAA J. 53(7), 2015): every strip s
gets an angle shift Delta_s, applied as a rotation of its panels' boundary condition
(an upwash V Delta_s along each panel normal, so the whole lattice - induced angles,
spanwise load, induced drag - responds to it), and the shifts solve

    R_s = cl_s(Delta) - cl_section(alpha_e,s, Re_s, M) = 0                       (V1)
    alpha_e,s = beta(M) cl_s / (2 pi) + alpha_0,s - Delta_s                         (V2)

(V2) reads the strip as the lattice's own 2-D section: a strip of the lattice at the
effective angle alpha_e + Delta carries cl = (2 pi / beta)(alpha_e + Delta - alpha_0),
with alpha_0 the zero-lift angle of the discrete lattice on the section's camber
line (:func:`lattice_zero_lift_angles`; the thin-airfoil value for the 1/4-3/4 rule,
-z'(3/4) for one chordwise panel) and beta = sqrt(1 - M^2) (Prandtl-Glauert, as
the lattice).  Where the section polar is linear with slope 2 pi / beta and zero-lift
angle alpha_0, (V1) gives Delta = 0 and the lattice is unchanged; elsewhere the
lattice's lift follows the section's slope, zero-lift angle and cl_max, and past
stall the strip's cl falls with the section's while its neighbours carry the
redistributed load.  Past stall (V1) may have several roots (the negative
section slope); :func:`solve_viscous` continues along the angle of attack from the
last converged shifts, as the cited methods do.

Streamwise strips, no sweep correction (simple sweep theory is not applied): for a
swept wing the section's stall is read at the streamwise effective angle.
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from .camber import camber_line

__all__ = ["lattice_zero_lift_angles", "shift_velocity", "effective_angle", "viscous_residual", "solve_viscous"]


def lattice_zero_lift_angles(vlm) -> np.ndarray:
    """Zero-lift angle (rad) of each strip's 2-D lattice section: ``nc`` vortices at
    x/c = (r + 1/4)/nc and control points at (r + 3/4)/nc on the camber line of the
    strip's airfoil (the inboard section's, as ``VLM.strip_airfoil``), solved in 2-D.
    For one chordwise panel this is z'(3/4); for a flat section 0."""
    out = np.zeros(vlm.n_strips)
    cache = {}
    for s in range(vlm.n_strips):
        name = vlm.strip_airfoil[s]
        nc = len(vlm.strip_panels[s])
        key = (str(name), nc)
        if key not in cache:
            cam = camber_line(name if name is not None else vlm.surfaces[vlm.strip_surface[s]].airfoil)
            xv = (np.arange(nc) + 0.25) / nc
            xc = (np.arange(nc) + 0.75) / nc
            # 2-D point vortices: downwash at control point i per unit circulation at j (chord 1)
            W = 1.0 / (2.0 * math.pi * (xc[:, None] - xv[None, :]))
            gam = np.linalg.solve(W, -np.asarray(cam.slope(xc), float))   # alpha = 0, V = 1
            cl0 = 2.0 * gam.sum()                                         # cl = 2 Gamma / (V c)
            cache[key] = -cl0 / (2.0 * math.pi)
        out[s] = cache[key]
    return out


def _row(x, K):
    if isinstance(x, (ca.MX, ca.SX, ca.DM)):
        return x if x.shape[1] == K else ca.repmat(x, 1, K)
    return ca.DM(np.broadcast_to(np.asarray(x, float).reshape(1, -1), (1, K)))


def shift_velocity(vlm, shift, V):
    """External velocity (vx, vy, vz), each N x K (m/s), that turns every panel of strip s
    nose-up by ``shift[s]`` (rad, n_strips x K) in the linearized boundary condition: an
    upwash V shift_s along each panel's normal, so the flow-tangency right-hand side changes
    by -V shift_s (a rotation to first order: sin(a) + d for sin(a + d))."""
    K = shift.shape[1]
    per_panel = ca.mtimes(vlm.strip_sum.T, shift) * ca.repmat(_row(V, K), vlm.n_panels, 1)
    n = vlm.geometry["normal"]
    return tuple(ca.repmat(n[i, :].T, 1, K) * per_panel for i in range(3))


def effective_angle(cl, shift, alpha0, mach):
    """(V2), elementwise (numbers, NumPy or CasADi): alpha_e = beta cl / (2 pi) + alpha_0 - shift."""
    return ca.sqrt(1 - mach * mach) * cl / (2 * math.pi) + alpha0 - shift


def viscous_residual(vlm, r, shift, section_cl, mach, alpha0=None):
    """(V1) for every strip: (R n_strips x K, alpha_e n_strips x K).

    r : ``VLM.solve`` result of the shifted lattice (its ``cl_local``: the strip's cl on its
        local velocity); shift : n_strips x K (rad); section_cl(alpha_e) -> n_strips x K,
        the section's cl at the strips' Reynolds and Mach numbers (the caller binds them);
        mach : 1 x K or scalar; alpha0 : :func:`lattice_zero_lift_angles` (computed if None).
    """
    K = shift.shape[1]
    if alpha0 is None:
        alpha0 = lattice_zero_lift_angles(vlm)
    cl = r["cl_local"]
    S = vlm.n_strips
    alpha_e = effective_angle(cl, shift, ca.repmat(ca.DM(alpha0), 1, K), ca.repmat(_row(mach, K), S, 1))
    return cl - section_cl(alpha_e), alpha_e


def solve_viscous(vlm, alphas, section_cl, *, V=1.0, rho=1.225, mach=0.0, tol=1e-10, max_iter=200):
    """The viscous-corrected lattice at each angle of attack in ``alphas`` (rad, in the
    order given: each starts from the previous point's shifts), numbers in, numbers out.

    section_cl(alpha_e) : CasADi-callable on an n_strips x 1 column.  Levenberg-Marquardt
    on (V1) (the damping falls to a Newton step where the Jacobian is regular, and rises
    where the section's negative post-stall slope makes it nearly singular).  Returns a
    list of dicts: alpha, CL, CDi, cl, alpha_e, shift, iterations, residual (max |R|),
    converged (residual < 1e3 tol; where not, (V1) has no root near the previous one and
    the point is reported, not raised).
    """
    S = vlm.n_strips
    a_sym, d_sym = ca.MX.sym("alpha"), ca.MX.sym("shift", S, 1)
    r = vlm.solve(a_sym, V, rho=rho, mach=mach, v_ext=shift_velocity(vlm, d_sym, V),
                  v_ext_bound=(ca.DM.zeros(vlm.n_panels, 1),) * 3)
    R, a_e = viscous_residual(vlm, r, d_sym, section_cl, mach)
    f = ca.Function("viscous", [a_sym, d_sym], [R, ca.jacobian(R, d_sym), r["CL"], r["CDi"], r["cl_local"], a_e])

    def resid(a, d):
        return np.array(f(a, d)[0], float).ravel()

    d = np.zeros(S)
    out = []
    for a in np.atleast_1d(np.asarray(alphas, float)):
        mu, it, res = 1e-3, 0, np.inf
        for it in range(1, max_iter + 1):
            Rv, J = (np.array(x, float) for x in f(a, d)[:2])
            Rv = Rv.ravel()
            res = float(np.max(np.abs(Rv)))
            if res < tol:
                break
            while mu < 1e8:   # damped Gauss-Newton step; accept when |R|^2 falls
                step = np.linalg.solve(J.T @ J + mu * np.eye(S), -J.T @ Rv)
                Rn = resid(a, d + step)
                if Rn @ Rn < Rv @ Rv:
                    d, mu = d + step, max(mu / 3.0, 1e-12)
                    break
                mu *= 4.0
            if mu >= 1e8:
                break
        _, _, CL, CDi, cl, ae = (np.array(x, float) for x in f(a, d))
        out.append({"alpha": float(a), "CL": float(CL.ravel()[0]), "CDi": float(CDi.ravel()[0]), "cl": cl.ravel(),
                    "alpha_e": ae.ravel(), "shift": d.copy(), "iterations": it, "residual": res,
                    "converged": res < 1e3 * tol})
    return out
