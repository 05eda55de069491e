"""Adkins-Liebeck minimum-induced-loss design, symbolic and differentiable.

Adkins & Liebeck, "Design of optimum propellers", J. Propulsion Power 10(5),
1994 (A-L below), turn (B, R, R_hub, Omega, V, T or P, design cl, airfoil,
atmosphere) into chord and blade angle.  Their design condition (Betz) is a
rigid helical wake moving back with the displacement velocity ``v' = zeta V``:

    tan(phi) = (V + v'/2) / (Omega r)                         (A-L Eq. 21, 8)

Written with the displacement velocity ``w = v' = zeta V`` [m/s] instead of
``zeta`` every A-L relation stays finite as V -> 0, which is what the paper's
"adapted to large inflow angles" needs (the TTW rotors are designed at
10 m/s with a wake velocity of ~35 m/s, zeta ~ 3.5; a hover design has
zeta = inf but a finite w):

    G  = F Omega r cos(phi) sin(phi) / V        (A-L Eq. 13, x = Omega r/V)
    W c = 4 pi F r cos(phi) sin(phi) w / (B cl)                 (A-L Eq. 16 x V)
    u  = a V = (w/2) cos^2(phi) (1 - eps tan(phi))              (A-L Eq. 17)
    W  = (V + u) / sin(phi),  c = (W c)/W,  beta = alpha + phi  (A-L Eqs. 19-20)
    eps = cd/cl at the section's alpha for the design cl (A-L step 4)

Two choices differ from the paper's procedure, both so that the designed blade
is an exact solution of this package's BEMT (``bemt.py``) at the design point:

* the Prandtl factor is the BEMT's, ``F = F_tip F_hub`` with the local inflow
  angle (A-L use the tip factor with phi_tip: the two agree near the tip; the
  hub factor is what the analysis applies);
* instead of A-L's fixed-point update of zeta through the quadratic
  ``Tc = I1 zeta - I2 zeta^2`` (which has no real root for heavily loaded
  designs -- SUAVE clips Tc there), the thrust (or power) of the design is
  computed directly as the BEMT sum ``T(w) = sum B 1/2 rho W^2 c (cl cos phi -
  cd sin phi) dr`` and ``T(w) = T_design`` is a residual in w.

The section angle of attack that gives the design cl at each station's
Reynolds and Mach number, ``cl(alpha_i, Re_i, M_i) = cl_design``, is n more
residuals.  Re uses the BEMT's convention ``W0 = sqrt(V^2 + (Omega r)^2)`` and
the chord from the drag-free induction (``eps = 0``), an O(eps) approximation
in Re only.

Unknowns ``w`` and ``alpha_i`` (n + 1) with residuals of the same count:
``adkins_liebeck_function`` exposes them (NLP mode: add them as variables, one
set per rotor *design*, not per mission node); ``adkins_liebeck`` solves them
with a damped Newton method (analysis mode); ``adkins_liebeck_unrolled``
gives the design as an explicit function with a fixed number of Newton steps
(larger graph; see README for the measured comparison).
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from ..core.atmosphere import check_altitude, density, dynamic_viscosity, speed_of_sound
from ..core.errors import InputError
from ..airfoil.clmax import fit_clmax
from .geometry import RotorGeometry, placed_stations, station_layout, station_r_over_R
from .sections import section as make_section, section_coefficients

__all__ = ["adkins_liebeck_function", "adkins_liebeck", "adkins_liebeck_unrolled",
           "adkins_liebeck_implicit", "add_adkins_liebeck", "DESIGN_INPUTS", "design_guess",
           "station_clmax", "design_cl_stall_rows"]

DESIGN_INPUTS = ("target", "speed_mps", "radius_m", "omega_radps", "cl_design", "rho_kgpm3",
                 "mu_Pas", "a_mps", "hub_fraction", "blades")
_CACHE: dict = {}


def _section_hub(sec, hub_fraction):
    """The hub at which a radial distribution is placed (``geometry.placed_stations``), for the
    cache keys; None for a section that does not vary along the blade."""
    return None if placed_stations(sec, 2, hub_fraction) is None else float(hub_fraction)


def _design_state(sec, n, w, alpha, p, tip_loss=True, hub_loss=True, x_sections=None):
    """All design quantities for displacement velocity ``w`` and section angles ``alpha``."""
    V, R, Om, cl_d = p["speed_mps"], p["radius_m"], p["omega_radps"], p["cl_design"]
    rho, mu, a_s, h, B = p["rho_kgpm3"], p["mu_Pas"], p["a_mps"], p["hub_fraction"], p["blades"]
    s, ds = station_layout(n)
    xi = h + (1.0 - h) * ca.DM(s)
    r = R * xi
    dr = R * (1.0 - h) * ca.DM(ds)
    vy = Om * r
    phi = ca.atan2(V + 0.5 * w, vy)                        # A-L Eq. 21 with Eq. 8
    sphi, cphi = ca.sin(phi), ca.cos(phi)
    F = 1.0
    if tip_loss:
        F = F * (2.0 / math.pi) * ca.acos(ca.exp(-0.5 * B * (R - r) / (r * sphi)))
    if hub_loss:
        F = F * (2.0 / math.pi) * ca.acos(ca.exp(-0.5 * B * (r - R * h) / (R * h * sphi)))
    w0 = ca.sqrt(V * V + vy * vy)
    mach = w0 / a_s
    circ = 4.0 * math.pi * F * r * cphi * sphi * w / B     # = W c cl
    u0 = 0.5 * w * cphi * cphi
    c0 = circ / cl_d / ((V + u0) / sphi)
    reynolds = rho * w0 * c0 / mu
    cl, cd = section_coefficients(sec, alpha, reynolds, mach, xi if x_sections is None else x_sections)
    eps = cd / cl
    u = 0.5 * w * cphi * cphi * (1.0 - eps * sphi / cphi)   # A-L Eq. 17 (a V)
    W = (V + u) / sphi
    chord = circ / cl / W
    dyn = 0.5 * rho * W * W * chord
    dTdr = B * dyn * (cl * cphi - cd * sphi)
    dQdr = B * dyn * (cl * sphi + cd * cphi) * r
    T = ca.dot(dTdr, dr)
    Q = ca.dot(dQdr, dr)
    return {
        "phi": phi, "F": F, "chord": chord, "twist": alpha + phi, "cl": cl, "cd": cd,
        "reynolds": reynolds, "mach": mach, "W": W, "u": u, "thrust": T, "torque": Q,
        "power": Q * Om, "r": r, "dTdr": dTdr, "gamma": 0.5 * circ,
    }


def _params_sym():
    return {k: ca.SX.sym(k) for k in DESIGN_INPUTS}


def adkins_liebeck_function(sec, n_stations: int = 20, *, target: str = "thrust",
                            tip_loss=True, hub_loss=True, hub_fraction: float | None = None) -> ca.Function:
    """The A-L design as residuals: an SX Function.

    Inputs ``DESIGN_INPUTS`` + ``w_mps`` (displacement velocity) + ``alpha_rad``
    [n]: ``target`` is the design thrust [N] (``target="thrust"``) or power [W]
    (``target="power"``); ``speed_mps`` design speed V (>= 0); ``radius_m``;
    ``omega_radps``; ``cl_design``; air ``rho_kgpm3, mu_Pas, a_mps``;
    ``hub_fraction``; ``blades``.
    Outputs: ``residual`` [n+1] (first ``T/T_design - 1`` or ``P/P_design - 1``,
    then ``cl_i - cl_design``), ``chord_m`` [n], ``twist_rad`` [n] (blade angle at
    the BEMT stations, for ``bemt_function`` with pitch 0), ``phi_rad`` [n] (the
    design inflow angles = the BEMT solution at the design point, a good NLP
    initial guess), ``thrust_N``, ``power_W``, ``torque_Nm``, ``eta`` (T V/P),
    ``reynolds`` [n], ``mach`` [n], ``gamma_m2ps`` [n].
    ``hub_fraction`` (a number): a radial distribution of sections is placed at the
    stations when the graph is built (as ``bemt_function``'s); the input must equal it.
    """
    hub_fraction = _section_hub(sec, hub_fraction)
    key = (id(sec), "al", n_stations, target, tip_loss, hub_loss, hub_fraction)
    if key in _CACHE:
        return _CACHE[key][0]
    if target not in ("thrust", "power"):
        raise ValueError("target must be 'thrust' or 'power'")
    p = _params_sym()
    w = ca.SX.sym("w_mps")
    alpha = ca.SX.sym("alpha_rad", n_stations)
    x_sec = placed_stations(sec, n_stations, hub_fraction)
    st = _design_state(sec, n_stations, w, alpha, p, tip_loss, hub_loss, x_sec)
    achieved = st["thrust"] if target == "thrust" else st["power"]
    res = ca.vertcat(achieved / p["target"] - 1.0, st["cl"] - p["cl_design"])
    eta = st["thrust"] * p["speed_mps"] / st["power"]
    names_in = list(DESIGN_INPUTS) + ["w_mps", "alpha_rad"]
    f = ca.Function(f"adkins_liebeck_{target}", [p[k] for k in DESIGN_INPUTS] + [w, alpha],
                    [res, st["chord"], st["twist"], st["phi"], st["thrust"], st["power"],
                     st["torque"], eta, st["reynolds"], st["mach"], st["gamma"]],
                    names_in, ["residual", "chord_m", "twist_rad", "phi_rad", "thrust_N", "power_W",
                               "torque_Nm", "eta", "reynolds", "mach", "gamma_m2ps"])
    _CACHE[key] = (f, sec)
    return f


def design_guess(sec, p: dict, n_stations: int, target: str = "thrust"):
    """Initial (w, alpha): actuator-disk w, thin-airfoil alpha for the design cl.

    Thrust: ``T = rho A (V + w/2) w``  ->  ``w = -V + sqrt(V^2 + 2 T/(rho A))``;
    power: the same with ``T ~ P / (V + w/2)`` solved by a few fixed-point steps.
    """
    A = math.pi * p["radius_m"] ** 2 * (1.0 - p["hub_fraction"] ** 2)
    V, rho = float(p["speed_mps"]), float(p["rho_kgpm3"])
    if target == "thrust":
        w = -V + math.sqrt(V * V + 2.0 * float(p["target"]) / (rho * A))
    else:
        w = 1.0
        for _ in range(50):
            T = float(p["target"]) / (V + 0.5 * w)
            w = -V + math.sqrt(V * V + 2.0 * T / (rho * A))
    w *= 1.15   # tip/hub losses raise the wake velocity needed for the same thrust
    a0 = float(getattr(sec, "alpha0_rad", 0.0))
    slope = 2.0 * math.pi
    alpha = np.full(n_stations, a0 + float(p["cl_design"]) / slope)
    return w, alpha


def _check_design_inputs(p: dict, target: str):
    for k in ("radius_m", "omega_radps", "rho_kgpm3", "mu_Pas", "a_mps", "cl_design", "target"):
        v = p[k]
        if not (isinstance(v, (int, float, np.floating)) and math.isfinite(v) and v > 0):
            field = {"target": f"design {target}"}.get(k, k)
            raise InputError(field, f"must be a finite number > 0, got {v!r}")
    if not (math.isfinite(p["speed_mps"]) and p["speed_mps"] >= 0):
        raise InputError("design speed", f"must be >= 0 m/s, got {p['speed_mps']!r}")
    if not (0.0 < p["hub_fraction"] < 1.0):
        raise InputError("hub_fraction", f"allowed (0, 1) of the tip radius, got {p['hub_fraction']:g}")
    B = p["blades"]
    if not (float(B).is_integer() and B >= 1):
        raise InputError("blades", f"must be an integer >= 1, got {B!r}")
    if not (0.05 <= p["cl_design"] <= 1.6):
        raise InputError("cl_design", f"allowed [0.05, 1.6], got {p['cl_design']:g}")
    mtip = math.hypot(p["omega_radps"] * p["radius_m"], p["speed_mps"]) / p["a_mps"]
    if mtip >= 1.0:
        raise InputError("tip Mach", f"design helical tip Mach must be < 1, got {mtip:.3f}")


def _design_point(*, radius_m, speed_mps, cl_design, thrust_N, power_W, omega_radps, rpm, tip_mach,
                  hub_fraction, altitude_m, blades) -> tuple[dict, str]:
    """The design point's ``DESIGN_INPUTS`` (checked) and the target ("thrust"/"power")."""
    if (thrust_N is None) == (power_W is None):
        raise InputError("design", "give exactly one of design thrust or design power")
    target = "thrust" if thrust_N is not None else "power"
    try:
        check_altitude(altitude_m, "altitude_m")
    except ValueError as exc:
        raise InputError("altitude", str(exc)) from exc
    a_s = float(speed_of_sound(altitude_m))
    given = [v is not None for v in (omega_radps, rpm, tip_mach)]
    if sum(given) != 1:
        raise InputError("rotor speed", "give exactly one of omega, rpm or tip Mach")
    if rpm is not None:
        omega_radps = rpm * math.pi / 30.0
    elif tip_mach is not None:
        if not (0 < tip_mach < 1):
            raise InputError("tip Mach", f"allowed (0, 1), got {tip_mach!r}")
        omega_radps = tip_mach * a_s / radius_m
    if not (isinstance(radius_m, (int, float)) and math.isfinite(radius_m) and radius_m > 0):
        raise InputError("radius", f"must be > 0 m, got {radius_m!r}")
    p = {"target": float(thrust_N if target == "thrust" else power_W), "speed_mps": float(speed_mps),
         "radius_m": float(radius_m), "omega_radps": float(omega_radps), "cl_design": float(cl_design),
         "rho_kgpm3": float(density(altitude_m)), "mu_Pas": float(dynamic_viscosity(altitude_m)),
         "a_mps": a_s, "hub_fraction": float(hub_fraction), "blades": float(blades)}
    _check_design_inputs(p, target)
    return p, target


def _residual_and_jacobian(sec, n_stations: int, target: str, hub_fraction=None) -> ca.Function:
    """``(DESIGN_INPUTS, z) -> (residual, d residual/dz)`` of the A-L design, cached."""
    hub_fraction = _section_hub(sec, hub_fraction)
    key = (id(sec), "al_jac", n_stations, target, hub_fraction)
    if key not in _CACHE:
        f = adkins_liebeck_function(sec, n_stations, target=target, hub_fraction=hub_fraction)
        z = ca.SX.sym("z", n_stations + 1)
        args = [ca.SX.sym(k) for k in DESIGN_INPUTS]
        res = f(*args, z[0], z[1:])[0]
        _CACHE[key] = (ca.Function("al_newton", args + [z], [res, ca.jacobian(res, z)]), sec)
    return _CACHE[key][0]


def _damped_newton(fj: ca.Function, pargs: list, z: np.ndarray, tol: float, max_iter: int):
    """Newton on the (n+1) A-L residuals with a backtracking line search that keeps
    ``w > 0``, the section angles within +-25 deg and the residual norm decreasing.
    Returns ``(z, residual, iterations)``."""
    def resid(zz):
        r_, J_ = fj(*pargs, zz)
        return np.array(r_).ravel(), np.array(J_)

    r, J = resid(z)
    it = 0
    for it in range(1, max_iter + 1):
        norm = np.linalg.norm(r)
        if not np.all(np.isfinite(r)):
            raise InputError("design", "Adkins-Liebeck design produced non-finite values at the guess; "
                                       "check speed, thrust and rotor speed")
        if norm < tol:
            break
        try:
            dz = np.linalg.solve(J, -r)
        except np.linalg.LinAlgError:
            dz = -np.linalg.lstsq(J, r, rcond=None)[0]
        step = 1.0
        for _ in range(30):
            zn = z + step * dz
            if zn[0] > 0 and np.all(np.abs(zn[1:]) < math.radians(25.0)):
                rn, Jn = resid(zn)
                if np.all(np.isfinite(rn)) and np.linalg.norm(rn) < (1 - 1e-4 * step) * norm:
                    break
            step *= 0.5
        else:
            break
        z, r, J = zn, rn, Jn
    return z, r, it


def _analysis_geometry(res: dict, xi: np.ndarray, radius_m: float, hub_fraction: float, blades: int,
                       sec, name: str) -> RotorGeometry:
    """The designed blade for ``analyze``: the design stations, the hub (the first
    station's chord and angle) and the tip (chord and angle extrapolated linearly)."""
    c, b = res["chord_m"], res["twist_rad"]
    slope = (1 - xi[-1]) / (xi[-1] - xi[-2])
    c_tip = max(c[-1] + (c[-1] - c[-2]) * slope, 1e-3 * radius_m)
    b_tip = b[-1] + (b[-1] - b[-2]) * slope
    return RotorGeometry(radius_m=float(radius_m), blades=int(blades), r_over_R=np.r_[hub_fraction, xi, 1.0],
                         chord_over_R=np.r_[c[0], c, c_tip] / radius_m, beta_rad=np.r_[b[0], b, b_tip],
                         hub_fraction=float(hub_fraction), airfoil=sec, name=name)


def adkins_liebeck(*, blades: int, radius_m: float, speed_mps: float, airfoil="naca4412",
                   cl_design: float = 0.7, thrust_N: float | None = None,
                   power_W: float | None = None, omega_radps: float | None = None,
                   rpm: float | None = None, tip_mach: float | None = None,
                   hub_fraction: float = 0.12, altitude_m: float = 0.0, n_stations: int = 20,
                   tol: float = 1e-12, max_iter: int = 60, name: str = "adkins_liebeck") -> dict:
    """Numeric A-L design (analysis mode).  Give one of ``thrust_N``/``power_W`` and
    one of ``omega_radps``/``rpm``/``tip_mach`` (rotational tip Mach at ``altitude_m``).

    Returns a dict: ``geometry`` (a ``RotorGeometry`` defined at the BEMT stations
    plus the tip, ready for ``analyze``), ``chord_m``, ``twist_rad``, ``phi_rad``,
    ``r_m``, ``w_mps``, ``zeta`` (= w/V), ``thrust_N``, ``power_W``, ``eta``,
    ``residual_max``, ``iterations``, ``omega_radps``, and the inputs.
    """
    p, target = _design_point(radius_m=radius_m, speed_mps=speed_mps, cl_design=cl_design, thrust_N=thrust_N,
                              power_W=power_W, omega_radps=omega_radps, rpm=rpm, tip_mach=tip_mach,
                              hub_fraction=hub_fraction, altitude_m=altitude_m, blades=blades)
    sec = make_section(airfoil)
    f = adkins_liebeck_function(sec, n_stations, target=target, hub_fraction=hub_fraction)
    pargs = [p[k] for k in DESIGN_INPUTS]
    w0, a0 = design_guess(sec, p, n_stations, target)
    z, r, it = _damped_newton(_residual_and_jacobian(sec, n_stations, target, hub_fraction), pargs, np.r_[w0, a0],
                              tol, max_iter)
    if np.linalg.norm(r, np.inf) > 1e-8:
        raise InputError("design", f"Adkins-Liebeck design did not converge (residual "
                                   f"{np.linalg.norm(r, np.inf):.2e}); the design {target} may be "
                                   f"unreachable at cl {cl_design:g} (try a larger radius, rotor speed "
                                   f"or design cl)")
    out = f(*pargs, z[0], z[1:])
    res = {k: np.array(out[i]).ravel() for i, k in enumerate(f.name_out())}
    for k in ("thrust_N", "power_W", "torque_Nm", "eta"):
        res[k] = float(res[k][0])
    xi = station_r_over_R(n_stations, hub_fraction)
    res.update({
        "w_mps": float(z[0]), "zeta": float(z[0] / speed_mps) if speed_mps > 0 else math.inf,
        "alpha_rad": z[1:], "r_m": xi * radius_m, "r_over_R": xi, "residual_max":
        float(np.max(np.abs(res["residual"]))), "iterations": it, "omega_radps": p["omega_radps"],
        "inputs": dict(p), "target": target, "section": sec,
    })
    res["geometry"] = _analysis_geometry(res, xi, radius_m, hub_fraction, blades, sec, name)
    return res


def _symbolic_guess(sec, n: int, p: dict, target: str):
    """``design_guess``'s formulas on symbols (SX or MX): the starting (w, alpha) of the
    unrolled and implicit designs."""
    A = math.pi * p["radius_m"] ** 2 * (1 - p["hub_fraction"] ** 2)
    V = p["speed_mps"]
    if target == "thrust":
        w = -V + ca.sqrt(V * V + 2.0 * p["target"] / (p["rho_kgpm3"] * A))
    else:
        w = 0.0 * V + 1.0
        for _ in range(8):
            T = p["target"] / (V + 0.5 * w)
            w = -V + ca.sqrt(V * V + 2.0 * T / (p["rho_kgpm3"] * A))
    alpha = ca.repmat(float(getattr(sec, "alpha0_rad", 0.0)) + p["cl_design"] / (2 * math.pi), n, 1)
    return 1.15 * w, alpha


def adkins_liebeck_unrolled(sec, n_stations: int = 20, *, n_newton: int = 8, target="thrust",
                            tip_loss=True, hub_loss=True, hub_fraction: float | None = None) -> ca.Function:
    """A-L design as an explicit SX Function: ``n_newton`` full Newton steps on the
    (n+1) residuals from ``design_guess``'s formulas, unrolled.  Inputs
    ``DESIGN_INPUTS``; outputs as ``adkins_liebeck_function`` plus ``w_mps``.
    Differentiable end to end (derivatives of the unrolled map, exact once the
    iteration has converged).  Larger graph than the residual form; kept for
    comparison (``adkins_liebeck_implicit`` is the one the aircraft use)."""
    f = adkins_liebeck_function(sec, n_stations, target=target, tip_loss=tip_loss, hub_loss=hub_loss,
                                hub_fraction=hub_fraction)
    p = _params_sym()
    w, alpha = _symbolic_guess(sec, n_stations, p, target)
    zs = ca.SX.sym("z", n_stations + 1)
    pr = [p[k] for k in DESIGN_INPUTS]
    rz = f(*pr, zs[0], zs[1:])[0]
    fj = ca.Function("al_rj", pr + [zs], [rz, ca.jacobian(rz, zs)])
    z = ca.vertcat(w, alpha)
    for _ in range(n_newton):
        rr, JJ = fj(*pr, z)
        z = z - ca.solve(JJ, rr)
    out = f(*pr, z[0], z[1:])
    names = list(f.name_out()) + ["w_mps"]
    return ca.Function(f"adkins_liebeck_unrolled_{target}", pr, list(out) + [z[0]],
                       list(DESIGN_INPUTS), names)


def adkins_liebeck_implicit(sec, n_stations: int = 20, *, target: str = "thrust", tip_loss=True,
                            hub_loss=True, hub_fraction: float | None = None) -> ca.Function:
    """A-L design as an implicit function of its inputs: an MX Function.

    The (n+1) residuals of ``adkins_liebeck_function`` are solved inside the graph by
    CasADi's Newton ``rootfinder`` (tolerance 1e-12, at most 50 steps), started from
    ``design_guess``'s formulas; first and second derivatives follow from the implicit
    function theorem (``dz/dp = -R_z^-1 R_p``), so the design is exact at every
    evaluation and an NLP needs no blade unknowns.  Measured against the damped
    numeric ``adkins_liebeck`` over the corners of the aircraft's design boxes
    (thrust 0.3-3x, speed 0.6-1.3x (the design-speed box then), radius 0.5-1.6x, cl 0.4-1.0 (the design-cl box then); GA-2P, GA-8P, TTW,
    81 points each): the same blades to 3e-12, and Newton fails only where the
    damped solve fails too (an unreachable design; the evaluation then raises, which
    IPOPT treats as a rejected trial step).  Why: the 17 blade unknowns were dense
    Hessian rows of every mission node (issue 20, ``results/benchmark.md``).

    Inputs ``DESIGN_INPUTS`` (by name); outputs as ``adkins_liebeck_function``
    without ``residual``, plus ``w_mps`` and ``alpha_rad`` [n] (the solved unknowns).
    """
    hub_fraction = _section_hub(sec, hub_fraction)
    key = (id(sec), "al_implicit", n_stations, target, tip_loss, hub_loss, hub_fraction)
    if key in _CACHE:
        return _CACHE[key][0]
    f = adkins_liebeck_function(sec, n_stations, target=target, tip_loss=tip_loss, hub_loss=hub_loss,
                                hub_fraction=hub_fraction)
    z = ca.SX.sym("z", n_stations + 1)
    ps = ca.SX.sym("p", len(DESIGN_INPUTS))
    out = f(**{k: ps[i] for i, k in enumerate(DESIGN_INPUTS)}, w_mps=z[0], alpha_rad=z[1:])
    names = [k for k in f.name_out() if k != "residual"]
    g = ca.Function("al_residual", [z, ps], [out["residual"]] + [out[k] for k in names])
    root = ca.rootfinder(f"adkins_liebeck_root_{target}", "newton", g,
                         {"abstol": 1e-12, "max_iter": 50, "error_on_fail": True})
    pm = {k: ca.MX.sym(k) for k in DESIGN_INPUTS}
    w0, a0 = _symbolic_guess(sec, n_stations, pm, target)
    res = root(ca.vertcat(w0, a0), ca.vertcat(*[pm[k] for k in DESIGN_INPUTS]))
    zs = res[0]
    fn = ca.Function(f"adkins_liebeck_implicit_{target}", [pm[k] for k in DESIGN_INPUTS],
                     list(res[1:]) + [zs[0], zs[1:]], list(DESIGN_INPUTS), names + ["w_mps", "alpha_rad"])
    _CACHE[key] = (fn, sec)
    return fn


def station_clmax(sec, n_stations: int, hub_fraction: float) -> list:
    """cl_max(Re) of the section at each design station (``mdo.airfoil.clmax`` fits over
    Re 3e4-1e7, 2-D: the design point has no blade context); one fit for a section that
    does not vary along the blade."""
    key = (id(sec), "clmax", n_stations, float(hub_fraction))
    if key not in _CACHE:
        xi = station_r_over_R(n_stations, hub_fraction)
        if getattr(sec, "spanwise", False):
            # stations whose section blend is the same (a radial distribution placed at its stations:
            # mostly one section each) share one fit
            blend = (lambda x: tuple(np.round(sec.station_weights(x).ravel(), 12))) \
                if hasattr(sec, "station_weights") else (lambda x: x)
            by_blend = {}
            for x in xi:
                if blend(x) not in by_blend:
                    by_blend[blend(x)] = fit_clmax(lambda a, re, x=x: section_coefficients(sec, a, re, 0.0, x)[0],
                                                   re_range=(3e4, 1e7))
            fits = [by_blend[blend(x)] for x in xi]
        else:
            fits = [fit_clmax(lambda a, re: section_coefficients(sec, a, re, 0.0)[0], re_range=(3e4, 1e7))] * len(xi)
        _CACHE[key] = (fits, sec)
    return _CACHE[key][0]


def design_cl_stall_rows(sec, blade: dict, cl_design, hub_fraction: float, margin: float):
    """The design point below stall: ``cl_design - (cl_max(Re_i) - margin) <= 0`` at every
    station i (an [n x 1] expression), with ``Re_i`` the design point's section Reynolds
    numbers (``blade["reynolds"]``, an output of the A-L design).  Adkins and Liebeck's
    design holds the section cl at ``cl_design`` at every station with attached flow; a
    design cl above the section's cl_max at its Reynolds number is no design at all (the
    implicit solve then fails or lands past stall).  Every station counts, the hub's too:
    there the A-L chord follows Prandtl's hub loss factor towards zero and the Reynolds
    number is lowest (1e4-4e4 on a GA propeller), so the hub station limits first; a limit
    on the loaded stations alone (25-95 % of the radius) was tried and lets the design cl
    rise to where the A-L solve itself fails at the hub (cl 1.2 on a tripped NACA 4412
    GA-2P blade), which IPOPT meets as failed evaluations.  A radial cl distribution in
    the design would lift this (not modelled)."""
    re = blade["reynolds"]
    fits = station_clmax(sec, re.shape[0], hub_fraction)
    clmax = ca.vertcat(*[fits[i](re[i]) for i in range(re.shape[0])])
    return cl_design - (clmax - margin)


def add_adkins_liebeck(problem, name: str, sec, inputs: dict, *, n_stations: int = 20,
                       target: str = "thrust", init: dict | None = None) -> dict:
    """Add one A-L design (unknowns w and alpha_i, residuals) to a duck-typed problem.

    ``inputs`` maps ``DESIGN_INPUTS`` to expressions (design variables or numbers).
    ``init``: a numeric ``adkins_liebeck`` result for the initial guess (recommended).
    Adds variables ``<name>_w`` [m/s] and ``<name>_alpha`` [rad] and the group
    ``<name>_design``; returns the Function's outputs by name (chord_m, twist_rad,
    phi_rad, thrust_N, power_W, ...).
    """
    f = adkins_liebeck_function(sec, n_stations, target=target)
    w_init = init["w_mps"] if init else 20.0
    a_init = init["alpha_rad"] if init else np.full(n_stations, 0.05)
    w = problem.variable(f"{name}_w", 1, unit="m/s", scale=max(abs(w_init), 1.0), lower=1e-3,
                         upper=1e3, init=w_init)
    alpha = problem.variable(f"{name}_alpha", n_stations, unit="rad", scale=0.1,
                             lower=math.radians(-15), upper=math.radians(20), init=a_init)
    out = f(**{k: inputs[k] for k in DESIGN_INPUTS}, w_mps=w, alpha_rad=alpha)
    labels = [f"{name} {target}"] + [f"{name} cl station {i}" for i in range(n_stations)]
    problem.constrain(f"{name}_design", out["residual"], scale=1.0, labels=labels)
    out = dict(out)
    out["w_mps"] = w
    out["alpha_rad"] = alpha
    return out
