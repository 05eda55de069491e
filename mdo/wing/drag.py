"""Drag build-up: profile drag of lifting surfaces (strip method) and parasite drag of bodies.

Profile drag, strip method.  Each VLM strip is a 2-D section at its own lift
coefficient ``cl_local`` (lift per unit span over the *local* dynamic pressure
and chord, so a blown strip is a section in the slipstream) and its own
Reynolds number ``Re = rho V_local c / mu``; its drag per unit span is
``q_local c cd(cl_local, Re)``.  The section law ``cd(cl, Re)`` is the inverse
polar of the airfoil surrogate (:mod:`mdo.airfoil`, issue 3): for each of 17
Reynolds numbers (1e4 .. 1e8, log-spaced) the surrogate is sampled over its
attached branch (from the negative to the positive cl maximum, 0.05 deg steps;
where the polar dips below a level it already reached, the first crossing is kept),
``cd`` is tabulated against ``cl`` on a fixed grid and, beyond the attached range,
continued by ``cd_end + s (cl - cl_end) + k (cl - cl_end)^2`` (slope s of the
polar's end, k = 2: the stall drag rise a linear VLM cannot see); the table is
one cubic B-spline in (cl, ln Re) (``casadi.interpolant``), C2 and cheap inside
an NLP.  Mach number is not a table dimension (the surrogate's compressibility
correction changes cd by < 1 % below M 0.3; the missions fly M < 0.3).
Strips whose airfoil has no polar (e.g. a symmetric tail section) use Raymer's
flat-plate build-up ``cd = Cf(Re) FF_wing (S_wet/S)`` with the surface's t/c.

Bodies (fuselage, nacelles, booms): Raymer, *Aircraft Design: A Conceptual
Approach*, 6th ed., sec. 12.5 (component build-up method)::

    D = q Cf FF Q S_wet
    Cf_lam  = 1.328 / sqrt(Re)                                   (laminar flat plate)
    Cf_turb = 0.455 / ((log10 Re)^2.58 (1 + 0.144 M^2)^0.65)     (turbulent, Schlichting fit)
    Cf      = f_lam Cf_lam + (1 - f_lam) Cf_turb                  (laminar fraction f_lam)
    Re      = min(rho V l / mu, 38.21 (l/k)^1.053)               (roughness cut-off, k = 6.34e-6 m, smooth paint)
    FF_fuselage = 1 + 60/f^3 + f/400,   FF_nacelle = 1 + 0.35/f,  f = l/d
    FF_wing     = (1 + 0.6/(x/c)_m t/c + 100 (t/c)^4) 1.34 M^0.18 cos(sweep_m)^0.28
    S_wet(body) = pi d l (1 - 2/f)^(2/3) (1 + 1/f^2)            (Torenbeek 1982, app. F; fuselage)
    S_wet(boom, nacelle) = pi d l                                   (cylinder)

Smooth where IPOPT looks: ``Re -> sqrt(Re^2 + 1e4^2)`` and ``M -> sqrt(M^2 + 0.01^2)``
keep log10 and M^0.18 finite and differentiable down to hover (V = 0, where q = 0
anyway), and the roughness cut-off is a smooth minimum of width 5 % of the
cut-off Reynolds number.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..core.errors import InputError
from .geometry import check_positive, check_range
from ..core.smooth import is_symbolic, smooth_abs, smooth_min, xp

__all__ = [
    "section_drag_table", "section_cd", "profile_drag", "skin_friction", "form_factor_body",
    "form_factor_nacelle", "form_factor_wing", "body_wetted_area", "Body", "body_drag", "crossflow_normal_force",
]

RE_GRID = np.exp(np.linspace(np.log(1e4), np.log(1e8), 17))
CL_GRID = np.round(np.arange(-1.2, 2.4001, 0.05), 6)
STALL_CURVATURE = 2.0
ROUGHNESS_M = 6.34e-6          # Raymer Table 12.5: smooth paint, 2.08e-5 ft


def _lib(*args):
    return xp(*args)


# --- section law cd(cl, Re) -------------------------------------------------------------------
def _attached_branch(af, re):
    """(cl, cd) along alpha from the negative to the positive cl maximum, cl strictly increasing.

    Where the polar has a plateau or dip below its maximum (laminar-bubble kinks at low
    Re), each cl is taken at the smallest |alpha| that reaches it (the first crossing).
    """
    a = np.radians(np.arange(-20.0, 25.0001, 0.05))
    cl, cd, _ = af.coefficients(a, np.full_like(a, re), np.zeros_like(a))
    i0 = int(np.argmin(np.abs(a - af.zero_lift_angle(min(max(re, 2e4), 1e7)))))
    i_hi = i0 + int(np.argmax(cl[i0:]))
    i_lo = int(np.argmin(cl[:i0 + 1]))
    up = [i0]
    for i in range(i0 + 1, i_hi + 1):
        if cl[i] > cl[up[-1]]:
            up.append(i)
    down = [i0]
    for i in range(i0 - 1, i_lo - 1, -1):
        if cl[i] < cl[down[-1]]:
            down.append(i)
    idx = down[::-1] + up[1:]
    return cl[idx], cd[idx]


def _column(cl_b, cd_b):
    """cd on CL_GRID from one attached branch, with the quadratic stall continuation."""
    span = cl_b[-1] - cl_b[0]
    margin = min(0.05, 0.1 * span)
    lo_c, hi_c = cl_b[0] + margin, cl_b[-1] - margin
    inside = (cl_b >= lo_c) & (cl_b <= hi_c)
    cl_i, cd_i = cl_b[inside], cd_b[inside]
    out = np.interp(CL_GRID, cl_i, cd_i)
    for end, sign in ((hi_c, 1), (lo_c, -1)):
        sel = (cl_i >= end - 0.1) if sign > 0 else (cl_i <= end + 0.1)
        s = np.polyfit(cl_i[sel], cd_i[sel], 1)[0] if sel.sum() >= 2 else 0.0
        cd_end = np.interp(end, cl_i, cd_i)
        beyond = (CL_GRID > end) if sign > 0 else (CL_GRID < end)
        d = CL_GRID[beyond] - end
        out[beyond] = cd_end + s * d + STALL_CURVATURE * d * d
    return out


@functools.lru_cache(maxsize=None)
def section_drag_table(airfoil: str) -> ca.Function:
    """``cd(cl, ln Re)`` of airfoil ``airfoil`` as a casadi B-spline Function (see module doc).
    Valid on ``CL_GRID``'s range only: a casadi B-spline is zero beyond its grid
    (:func:`section_cd` continues it)."""
    from ..airfoil import Airfoil   # the airfoil discipline (issue 3)
    af = Airfoil.from_name(airfoil)
    table = np.column_stack([_column(*_attached_branch(af, re)) for re in RE_GRID])
    return ca.interpolant(f"cd_of_cl_{af.key}", "bspline", [CL_GRID, np.log(RE_GRID)],
                          table.ravel(order="F"))


@functools.lru_cache(maxsize=None)
def _table_ends(airfoil: str) -> ca.Function:
    """ln Re -> the table's d cd/d cl and d2 cd/d cl2 at the low and the high end of
    ``CL_GRID`` (4 outputs stacked).  Along an end the tensor B-spline is a cubic spline in
    ln Re on ``RE_GRID``'s knots, so the same interpolant through its values there is exact."""
    f = section_drag_table(airfoil)
    c, r = ca.MX.sym("cl"), ca.MX.sym("ln_re")
    y = f(ca.vertcat(c, r))
    d1 = ca.jacobian(y, c)
    d = ca.Function("d", [c, r], [d1, ca.jacobian(d1, c)])
    rows = []
    for lre in np.log(RE_GRID):
        lo, hi = (d(float(e), lre) for e in (CL_GRID[0], CL_GRID[-1]))
        rows.append([float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1])])
    return ca.interpolant(f.name().replace("cd_of_cl", "cd_ends"), "bspline", [np.log(RE_GRID)],
                          np.array(rows).ravel())


def _continued_cd(f, ends, cl, lre, lib):
    """The table beyond its ``cl`` range, C2 at each end (a casadi B-spline is zero past its
    grid, so a strip beyond ``CL_GRID`` - a tilt-wing's strip in hover, on the small local
    dynamic pressure of a slipstream edge - had no profile drag, with a jump to it):

        cd(end + x) = cd_e + s_e x + d2_e x^2/2 + (2 k - d2_e)/2 x^3/(x + w),   x = |cl - end|

    (``cd_e``, ``s_e``, ``d2_e`` the table's value, slope and curvature at the end), which joins
    the table C2 and grows as the module's stall continuation ``k x^2`` (k = ``STALL_CURVATURE``)
    once x >> w = one grid step.  Inside the range ``cl`` reaches the table unchanged (the
    clamps below are exactly the identity there).  ``_table_ends`` matches the table's own
    end derivatives to 5e-14 (checked over ln Re)."""
    lo, hi = float(CL_GRID[0]), float(CL_GRID[-1])
    w, k = float(CL_GRID[1] - CL_GRID[0]), STALL_CURVATURE
    fmax, fmin = (ca.fmax, ca.fmin) if lib is ca else (np.maximum, np.minimum)
    x_hi, x_lo = fmax(cl - hi, 0.0), fmax(lo - cl, 0.0)
    cd = f(fmin(fmax(cl, lo), hi), lre)      # the table's argument held at its ends exactly
    e = ends(lre)            # 4 x n: slope and curvature at the low end, then at the high end
    for x, s_e, d2_e, sgn in ((x_lo, e[0, :], e[1, :], -1.0), (x_hi, e[2, :], e[3, :], 1.0)):
        cd = cd + sgn * s_e * x + 0.5 * d2_e * x * x + 0.5 * (2.0 * k - d2_e) * x ** 3 / (x + w)
    return cd


def _has_polar(airfoil) -> bool:
    if airfoil is None:
        return False
    try:
        from ..airfoil import Airfoil
        Airfoil.from_name(airfoil)
        return True
    except (ImportError, InputError):
        return False


def section_cd(airfoil, cl, reynolds, mach=0.0, thickness_to_chord=0.12):
    """Section profile drag at lift coefficient ``cl`` and ``reynolds`` (elementwise).

    Floats, NumPy arrays (same shape) or CasADi expressions.  Airfoils without a
    polar use the flat-plate build-up of the module doc (then ``cl`` is ignored).
    """
    re_s = _smooth_re(reynolds)
    if not _has_polar(airfoil):
        m = _smooth_mach(mach)
        return skin_friction(re_s, m) * form_factor_wing(thickness_to_chord, 0.3, m) * \
            (1.977 + 0.52 * thickness_to_chord)
    f, ends = section_drag_table(airfoil), _table_ends(airfoil)
    if isinstance(cl, (ca.MX, ca.SX)) or isinstance(reynolds, (ca.MX, ca.SX)):
        kind = ca.MX if ca.MX in (type(cl), type(reynolds)) else ca.SX
        cl_ = cl if isinstance(cl, kind) else kind(ca.DM(np.asarray(cl, dtype=float)))
        lre = ca.log(re_s if isinstance(re_s, kind) else kind(ca.DM(np.asarray(re_s, dtype=float))))
        n = max(cl_.numel(), lre.numel())
        shape = cl_.shape if cl_.numel() == n else lre.shape
        c = ca.vec(cl_) if cl_.numel() == n else ca.repmat(cl_, n, 1)
        r = ca.vec(lre) if lre.numel() == n else ca.repmat(lre, n, 1)
        fm, em = (f.map(n), ends.map(n)) if n > 1 else (f, ends)
        out = _continued_cd(lambda cc, rr: fm(ca.vertcat(cc, rr)), em, c.T, r.T, ca)
        return ca.reshape(out, *shape)
    cl_a = np.asarray(cl, dtype=float)
    re_a = np.broadcast_to(np.log(np.asarray(re_s, dtype=float)), cl_a.shape)
    m = cl_a.size
    fm, em = f.map(m), ends.map(m)
    out = _continued_cd(lambda cc, rr: np.array(fm(np.vstack([cc, rr]))).ravel(),
                        lambda rr: np.array(em(rr.reshape(1, -1))).reshape(4, -1),
                        cl_a.ravel(), re_a.ravel(), np)
    out = np.asarray(out).reshape(cl_a.shape)
    return float(out) if out.shape == () else out


def profile_drag(vlm, result: dict, rho, mu, mach=0.0) -> dict:
    """Strip-method profile drag of every surface of ``vlm`` for a :meth:`VLM.solve` result.

    rho (kg/m^3), mu (Pa s), mach: scalars or 1 x K rows.  Returns D_p (1 x K, N,
    along the freestream), CD_p (on the VLM's S_ref and freestream q), and per
    strip cd, Re (n_strips x K).  In symmetric mode the left halves are included.
    """
    g = vlm.geometry
    Kn = result["cl_local"].shape[1]
    rho_r, mu_r = (_as_row(x, Kn) for x in (rho, mu))
    Vl = result["V_local"]
    c = g["strip_chord"].T
    w = g["strip_width"].T
    S = vlm.n_strips
    ones_K = ca.DM.ones(1, Kn)
    Re = Vl * ca.repmat(c, 1, Kn) * ca.repmat(rho_r / mu_r, S, 1)
    cds = []
    rows = []
    for name in sorted(set(map(str, vlm.strip_airfoil))):
        idx = [i for i, a in enumerate(vlm.strip_airfoil) if str(a) == name]
        tc = [vlm.surfaces[vlm.strip_surface[i]].thickness_to_chord for i in idx]
        af = None if name == "None" else name
        cd_g = section_cd(af, result["cl_local"][idx, :], Re[idx, :], mach,
                          thickness_to_chord=float(np.mean(tc)))
        cds.append(cd_g)
        rows += idx
    perm = ca.DM.triplet(rows, list(range(S)), ca.DM.ones(S), S, S)   # back to strip order
    cd = ca.mtimes(perm, ca.vertcat(*[ca.DM(x) if not isinstance(x, (ca.MX, ca.SX, ca.DM)) else x
                                      for x in cds]))
    q_loc = 0.5 * ca.repmat(rho_r, S, 1) * Vl * Vl
    Dp = ca.mtimes(ca.DM.ones(1, S), q_loc * ca.repmat(c * w, 1, Kn) * cd)
    if vlm.symmetric:
        Dp = 2 * Dp
    q_inf = 0.5 * rho_r * _as_row(result.get("V", ca.DM.ones(1, Kn)), Kn) ** 2
    out = {"D_p": Dp, "cd": cd, "Re": Re}
    if "V" in result:
        out["CD_p"] = Dp / (q_inf * g["S_ref"])
    return out


def _as_row(x, K):
    if isinstance(x, (ca.MX, ca.SX, ca.DM)):
        x = x if x.shape[0] == 1 else x.T
        return x if x.shape[1] == K else ca.repmat(x, 1, K)
    a = np.atleast_1d(np.asarray(x, dtype=float)).ravel()
    return ca.DM(np.broadcast_to(a, (K,))).T


# --- component build-up (Raymer sec. 12.5) -------------------------------------------------------
def _smooth_re(re):
    return _lib(re).sqrt(re * re + 1e4 * 1e4)


def _smooth_mach(m):
    return _lib(m).sqrt(m * m + 0.01 * 0.01)


def skin_friction(reynolds, mach=0.0, laminar_fraction=0.0):
    """Flat-plate skin-friction coefficient (Raymer 12.5): laminar/turbulent mix."""
    lib = _lib(reynolds, mach, laminar_fraction)
    re = _smooth_re(reynolds)
    lam = 1.328 / lib.sqrt(re)
    turb = 0.455 / ((lib.log(re) / math.log(10.0)) ** 2.58 * (1 + 0.144 * mach * mach) ** 0.65)
    return laminar_fraction * lam + (1 - laminar_fraction) * turb


def cutoff_reynolds(length, roughness=ROUGHNESS_M):
    """Raymer's subsonic cut-off Reynolds number 38.21 (l/k)^1.053 (surface roughness k, m)."""
    return 38.21 * (length / roughness) ** 1.053


def form_factor_body(fineness):
    """Fuselage / smooth canopy: 1 + 60/f^3 + f/400 (Raymer 12.5)."""
    return 1 + 60 / fineness**3 + fineness / 400


def form_factor_nacelle(fineness):
    """Nacelle / smooth external store: 1 + 0.35/f (Raymer 12.5)."""
    return 1 + 0.35 / fineness


def form_factor_wing(thickness_to_chord, x_max_thickness=0.3, mach=0.0, sweep_max_thickness=0.0):
    """Wing, tail, strut: (1 + 0.6/(x/c)_m t/c + 100 (t/c)^4) 1.34 M^0.18 cos(L_m)^0.28 (Raymer 12.5)."""
    lib = _lib(thickness_to_chord, mach, sweep_max_thickness)
    tc = thickness_to_chord
    m = _smooth_mach(mach)
    return (1 + 0.6 / x_max_thickness * tc + 100 * tc**4) * 1.34 * m**0.18 * \
        lib.cos(sweep_max_thickness) ** 0.28


def body_wetted_area(length, diameter, kind="fuselage"):
    """Wetted area (m^2): streamlined fuselage (Torenbeek) or cylinder (boom, nacelle)."""
    if kind == "fuselage":
        f = length / diameter
        return math.pi * diameter * length * (1 - 2 / f) ** (2.0 / 3.0) * (1 + 1 / f**2)
    return math.pi * diameter * length


@dataclass
class Body:
    """A non-lifting component for the parasite-drag build-up.

    kind: 'fuselage', 'nacelle' or 'boom'; Q: interference factor (Raymer:
    fuselage 1.0, nacelle on the wing 1.3-1.5, boom ~1.0); count: identical copies.
    """
    name: str
    length: float
    diameter: float
    kind: str = "fuselage"
    interference: float = 1.0
    laminar_fraction: float = 0.0
    count: int = 1
    wetted_area: float | None = None

    def __post_init__(self):
        check_positive(f"{self.name}.length", self.length, "m")
        check_positive(f"{self.name}.diameter", self.diameter, "m")
        if self.kind not in ("fuselage", "nacelle", "boom"):
            raise InputError(f"{self.name}.kind", f"'fuselage', 'nacelle' or 'boom', got {self.kind!r}")
        check_range(f"{self.name}.laminar_fraction", self.laminar_fraction, 0.0, 1.0)
        if self.kind == "fuselage" and not is_symbolic(self.length) and self.length / self.diameter <= 2:
            raise InputError(f"{self.name}.length", "fuselage fineness l/d must exceed 2")

    @property
    def fineness(self):
        return self.length / self.diameter

    def form_factor(self):
        return form_factor_body(self.fineness) if self.kind == "fuselage" else form_factor_nacelle(self.fineness)

    def s_wet(self):
        return self.wetted_area if self.wetted_area is not None else \
            body_wetted_area(self.length, self.diameter, self.kind)


def crossflow_normal_force(alpha_rad, q_Pa, planform_area_m2, eta=0.6, cd_crossflow=1.2, width=0.01):
    """Viscous crossflow normal force (N) of a slender body at angle of attack ``alpha_rad``.

    Allen & Perkins (NACA TR 1048, 1951): each cross-section of the body sees the
    crossflow ``V sin(alpha)`` and carries the drag of a 2-D cylinder in it, reduced by the
    finite-length factor ``eta`` (Jorgensen, NASA TR R-474, 1977)::

        N = q eta c_dc S_p sin(alpha) |sin(alpha)|

    normal to the body axis, upward for a positive angle (its drag ``N sin(alpha)`` grows as
    alpha^3, its lift ``N cos(alpha)`` as alpha^2).  ``|sin(alpha)|`` is smooth,
    ``sqrt(sin^2 + width^2)`` (width 0.01: a lift slope of ``q eta c_dc S_p 0.01`` per rad
    at zero, 0.2 % of a wing's of the same area).  The body's potential (Munk) moment is not
    here: it is the fuselage term of the pitching moment (``mdo.vehicle.balance``)."""
    s = xp(alpha_rad).sin(alpha_rad)
    return q_Pa * eta * cd_crossflow * planform_area_m2 * s * smooth_abs(s, width)


def body_drag(bodies, V, rho, mu, mach=0.0):
    """Parasite drag (N) and drag area D/q (m^2) of ``bodies`` at speed V (m/s), any shape of V."""
    total = 0.0
    for b in bodies:
        re = rho * V * b.length / mu
        re_c = cutoff_reynolds(b.length)
        re_eff = smooth_min(_smooth_re(re), re_c, 0.05 * re_c)
        cf = skin_friction(re_eff, mach, b.laminar_fraction)
        total = total + b.count * cf * b.form_factor() * b.interference * b.s_wet()
    q = 0.5 * rho * V * V
    return q * total, total
