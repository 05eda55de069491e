"""Blade element momentum theory as a residual in the inflow angle (Ning 2014).

One unknown per blade station (and azimuth station): the inflow angle ``phi``
between the local relative velocity and the rotor plane.  Everything else is an
explicit function of ``phi``, so the residual is cheap, smooth and, on
``phi in (0, pi/2]``, bracketed (Ning, "A simple solution method for the blade
element momentum equations with guaranteed convergence", Wind Energy 17, 2014;
propeller form as in Ning, Struct. Multidisc. Optim. 64, 2021).

Propeller convention (all at one station, rotor frame)
------------------------------------------------------
``Vx``  freestream component along the thrust axis, into the disk (> 0 in climb /
forward flight, 0 in hover, < 0 in descent);
``Vy``  tangential velocity of the air relative to the blade, ``Omega r`` plus the
in-plane freestream component at that azimuth;
velocities at the blade: ``W sin(phi) = Vx + u``, ``W cos(phi) = Vy - v`` with
``u`` the induced axial and ``v`` the induced swirl velocity (in the direction of
rotation).  Angle of attack ``alpha = theta - phi`` with ``theta`` the blade angle
plus the collective pitch.  Section coefficients at ``Re = rho W0 c / mu`` and
``M = W0 / a`` with ``W0 = sqrt(Vx^2 + Vy^2)`` (induction left out of Re and M, a
minor error that keeps the residual explicit -- Ning 2021, Eq. 12 ff.).

    cn = cl cos(phi) - cd sin(phi)           (thrust direction)
    ct = cl sin(phi) + cd cos(phi)           (against rotation)
    sigma' = B c / (2 pi r)
    F = F_tip F_hub,  F_tip = 2/pi acos(exp(-B (R - r) / (2 r |sin phi|)))
                      F_hub = 2/pi acos(exp(-B (r - R_hub) / (2 R_hub |sin phi|)))
    k  = sigma' cn / (4 F sin(phi) |sin(phi)|)       [= a / (1 + a),  u = a Vx]
    k' = sigma' ct / (4 F |sin(phi)| cos(phi))        [= a'/(1 - a'), v = a' Vy]

Annulus momentum with Prandtl's F (dT = 4 pi r rho F (Vx + u) u dr,
dQ = 4 pi r^3 rho F (Vx + u) (v / r) dr) equated to the blade-element loads gives
``k`` and ``k'`` above; the velocity triangle then closes when

    R(phi) = [Vy (sin phi - sigma' cn/(4 F |sin phi|))
              - Vx (cos phi + sigma' ct/(4 F |sin phi|))] / W0 = 0,

which is Ning's ``sin(phi)/(1 + a) - Vx/Vy cos(phi)/(1 - a')`` multiplied by
``(1 - k)(1 + k') Vy / W0``: the same roots, but with no division by ``Vx``, so
hover (Vx = 0, where the root has k = 1) and descent (Vx < 0) are the same
formula as climb.  For ``Vx >= 0``, ``Vy > 0`` and a blade that lifts at small
``phi`` (cn(0+) > 0), ``R(0+) = -inf`` and

    R(pi/2) = [Vy (1 + sigma' cd/(4F)) - Vx sigma' cl/(4F)] / W0,

with cl, cd at ``alpha = theta - pi/2``: positive, so a root lies in (0, pi/2], unless
the section still lifts with its chord turned past the axis, ``cl(theta - pi/2) >
4 F Vy/(Vx sigma') + cd Vy/Vx``.  That happens at the hub of a steeply twisted blade
at a large collective in fast axial flow (small Vy/Vx, small hub F): the TTW rotors'
hub station (blade angle 44 deg) at the cruise collective of 45 deg and 630 rpm
(J = 3.2).  The root then lies just past pi/2 (swirl v > Vy, ``W cos(phi) < 0``; at
the TTW's hub 92-101 deg for collectives 45-55 deg, alpha -3..+1 deg, a lightly loaded
element) - the root the numeric analysis finds in its third quadrant.  The NLP's bounds
are therefore ``phi in [phi_min, 3 pi/4]``: with the bracket's end at pi/2 instead,
the hub station pinned there held the TTW's cruise collective (bound multipliers up to
1.1 kWh per rad, 2026-12-05).  A scan of the TTW blade (400-2000 rpm, 0-100 m/s axial,
collective -10..60 deg, every station) found no case with roots on both sides of pi/2,
so widening the bounds adds no second root.  On (0, 3 pi/4] ``|sin phi| = sin phi >=
0.7`` near the end and the residual is smooth; the loads are written without
``1/cos(phi)`` or ``1/A`` (below), so that ``phi = pi/2`` is an ordinary point and no
iterate meets a pole.
The |sin phi| factors carry Ning's sign conventions into the other quadrants (used
only by the analysis fallback).

At the root the induced velocities and loads follow without dividing by ``Vx``:

    with A = cos(phi) + q ct, B = sin(phi) - q cn, q = sigma'/(4 F |sin phi|):
    swirl momentum gives W A = Vy (v = Vy k'/(1 + k')), axial momentum W B = Vx, and R = 0
    is their compatibility; W = (Vy A + Vx B)/(A^2 + B^2) (both at the root, no pole
    off it), v = Vy - W cos(phi), u = W sin(phi) - Vx
    N' = 1/2 rho W^2 c cn,  T' = 1/2 rho W^2 c ct   (per blade, per unit span)
    Gamma = 1/2 W c cl                                (bound circulation)

Non-axial inflow is handled by azimuth averaging: ``n_azimuth`` blade positions
``psi_j = 2 pi (j + 1/2)/n_azimuth`` (psi = 0 pointing downstream of the in-plane
flow, psi = 90 deg the advancing blade), each an independent BEMT with
``Vy = Omega r + V_inplane sin(psi)`` (held above ``Omega r / 4`` where the retreating
blade would see reverse flow); loads are averaged over the positions.
In-plane force (H, along the in-plane flow) and side force (Y, along
``n x e_p``, n the thrust axis) and hub moments follow from the tangential and
normal loads resolved at each azimuth (see ``_rotor_totals``).  No skewed-wake
correction is applied (as in the paper's BEMT); the momentum balance uses the
axial mass flow only, which over-predicts induced power in edgewise flight.
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from ..core.smooth import softplus
from .geometry import placed_stations, station_layout
from .sections import section_coefficients

__all__ = [
    "station_physics",
    "bemt_function",
    "INPUT_NAMES",
    "NLP_OUTPUTS",
    "FULL_OUTPUTS",
    "PHI_MIN_RAD",
    "PHI_MAX_RAD",
    "azimuth_angles",
    "inflow_components",
    "phi_momentum_guess",
    "bemt_unknowns",
    "add_bemt_nodes",
]

PHI_MIN_RAD = math.radians(0.1)   # NLP lower bound: keeps |sin phi| = sin phi (smooth)
PHI_MAX_RAD = 0.75 * math.pi      # NLP upper bound: past pi/2 for the hub of a steeply pitched blade (docstring)

INPUT_NAMES = (
    "radius_m", "hub_fraction", "blades", "chord_m", "twist_rad", "pitch_rad",
    "omega_radps", "v_axial_mps", "v_inplane_mps", "rho_kgpm3", "mu_Pas", "a_mps",
    "spin", "phi_rad",
)

NLP_OUTPUTS = (
    "residual", "thrust_N", "torque_Nm", "power_W", "hforce_N", "yforce_N",
    "gamma_m2ps", "va_mps", "vt_mps", "dTdr_Npm", "dQdr_N", "va_mean_mps", "vt_msq_F_m2ps2",
)

FULL_OUTPUTS = NLP_OUTPUTS + (
    "CT", "CP", "CQ", "eta", "FM", "J", "mp_hub_Nm", "ms_hub_Nm",
    "alpha_rad", "cl", "cd", "W_mps", "reynolds", "mach", "F", "u_mps", "v_mps",
    "dTdr_elem_Npm", "dQdr_elem_N",
)


def azimuth_angles(n_azimuth: int) -> np.ndarray:
    """Blade positions psi_j = 2 pi (j + 1/2)/n [rad] (0 = downstream of the in-plane flow)."""
    return 2.0 * np.pi * (np.arange(n_azimuth) + 0.5) / n_azimuth


def inflow_components(speed_mps, incidence_rad):
    """Freestream in the rotor frame: ``(v_axial, v_inplane) = (V cos i, V sin i)``.

    ``incidence_rad`` is the angle between the freestream velocity and the thrust
    axis (0: axial flow into the disk, pi/2: edgewise).  For a tilt-wing rotor with
    wing-mounted angle WMA and body angle of attack alpha in level flight,
    ``i = WMA + alpha`` measured from the flight direction.  A negative in-plane
    value means flow along ``-e_p``; H then changes sign with it.  Works on numbers
    and CasADi expressions.
    """
    lib = ca if isinstance(speed_mps, (ca.SX, ca.MX, ca.DM)) or isinstance(incidence_rad, (ca.SX, ca.MX, ca.DM)) \
        else np
    return speed_mps * lib.cos(incidence_rad), speed_mps * lib.sin(incidence_rad)


def station_physics(phi, r, chord, theta, vx, vy, rho, mu, a_sound, blades, r_tip, r_hub, sec,
                    tip_loss=True, hub_loss=True, x_sections=None):
    """Residual and loads at blade elements, elementwise (CasADi or NumPy).

    Arguments are broadcast elementwise: ``phi`` inflow angle [rad], ``r`` radius
    [m], ``chord`` [m], ``theta`` blade angle incl. pitch [rad], ``vx`` axial and
    ``vy`` tangential inflow [m/s], ``rho`` [kg/m^3], ``mu`` [Pa s], ``a_sound``
    [m/s], ``blades``, ``r_tip``/``r_hub`` [m], ``sec`` the section object;
    ``x_sections``: numeric r/R of the elements where a radial distribution of
    sections is read (None: ``r / r_tip``, as an expression).
    Returns a dict (module docstring for the equations).
    """
    lib = ca if any(isinstance(x, (ca.SX, ca.MX, ca.DM)) for x in
                    (phi, r, chord, theta, vx, vy, rho, mu, a_sound, blades, r_tip, r_hub)) else np
    sphi, cphi = lib.sin(phi), lib.cos(phi)
    asphi = lib.fabs(sphi) if lib is ca else np.abs(sphi)
    sigma = blades * chord / (2.0 * math.pi * r)
    alpha = theta - phi
    w0 = lib.sqrt(vx * vx + vy * vy)
    reynolds = rho * w0 * chord / mu
    mach = w0 / a_sound
    x = r / r_tip if x_sections is None else x_sections
    if getattr(sec, "rotational", False):     # stall delay needs c/r and Omega R / |V_tip|
        vtip = vy * r_tip / r
        cl, cd = section_coefficients(sec, alpha, reynolds, mach, x, chord / r,
                                      vtip / lib.sqrt(vx * vx + vtip * vtip))
    else:
        cl, cd = section_coefficients(sec, alpha, reynolds, mach, x)
    cn = cl * cphi - cd * sphi
    ct = cl * sphi + cd * cphi
    acos = ca.acos if lib is ca else np.arccos
    F = 1.0
    if tip_loss:
        F = F * (2.0 / math.pi) * acos(lib.exp(-0.5 * blades * (r_tip - r) / (r * asphi)))
    if hub_loss:
        F = F * (2.0 / math.pi) * acos(lib.exp(-0.5 * blades * (r - r_hub) / (r_hub * asphi)))
    q = sigma / (4.0 * F * asphi)          # sigma'/(4 F |sin phi|)
    A = cphi + q * ct
    B = sphi - q * cn
    residual = (vy * B - vx * A) / w0
    # Momentum gives W A = Vy (swirl: W cos(phi) = Vy - v, v = Vy k'/(1 + k')) and W B = Vx
    # (axial: W sin(phi) = Vx + u); the residual is their compatibility Vy B = Vx A.  W is
    # their least-squares combination: equal to both at the root, and with no pole where
    # A or B alone vanishes (A = 0 just past phi = pi/2 on a lightly loaded station, B = 0
    # in hover away from the root), so every iterate in (0, 3 pi/4] has finite loads.
    W = (vy * A + vx * B) / (A * A + B * B)
    v = vy - W * cphi
    u = W * sphi - vx
    dyn = 0.5 * rho * W * W * chord
    return {
        "residual": residual, "alpha": alpha, "cl": cl, "cd": cd, "cn": cn, "ct": ct,
        "F": F, "W": W, "u": u, "v": v, "reynolds": reynolds, "mach": mach,
        "Np": dyn * cn, "Tp": dyn * ct, "gamma": 0.5 * W * chord * cl,
    }


def _symbols(n: int, n_azimuth: int, kind=ca.SX) -> dict:
    sym = kind.sym
    return {
        "radius_m": sym("radius_m"),
        "hub_fraction": sym("hub_fraction"),
        "blades": sym("blades"),
        "chord_m": sym("chord_m", n),
        "twist_rad": sym("twist_rad", n),
        "pitch_rad": sym("pitch_rad"),
        "omega_radps": sym("omega_radps"),
        "v_axial_mps": sym("v_axial_mps"),
        "v_inplane_mps": sym("v_inplane_mps"),
        "rho_kgpm3": sym("rho_kgpm3"),
        "mu_Pas": sym("mu_Pas"),
        "a_mps": sym("a_mps"),
        "spin": sym("spin"),
        "phi_rad": sym("phi_rad", n * n_azimuth),
    }


def _elements(x: dict, n: int, n_azimuth: int):
    """Per-element (station x azimuth, station index fastest) geometry and inflow."""
    s, ds = station_layout(n)
    R, h = x["radius_m"], x["hub_fraction"]
    r = R * (h + (1.0 - h) * ca.DM(s))
    dr = R * (1.0 - h) * ca.DM(ds)
    psi = np.repeat(azimuth_angles(n_azimuth), n)
    rep = (lambda v: ca.repmat(v, n_azimuth, 1))
    e = {
        "r": rep(r), "dr": rep(dr), "chord": rep(x["chord_m"]),
        "theta": rep(x["twist_rad"]) + x["pitch_rad"],
        "psi": psi,
    }
    vy = x["omega_radps"] * e["r"]
    if n_azimuth > 1:
        # Reverse flow (the retreating blade's root in strongly edgewise flight, e.g. the
        # tilt-wing's descent transition) has no root of the phi-residual in (0, pi/2]:
        # the tangential velocity is held above a quarter of the rotational one
        # (a softplus ramp of width 2 % of Omega r: exact to round-off where there is no
        # reverse flow).  The reverse-flow region carries little load; this treats it
        # as a lightly loaded forward-flow element.
        vrot = vy
        floor = 0.25 * vrot
        vy = floor + softplus(vrot + x["v_inplane_mps"] * ca.DM(np.sin(psi)) - floor, 0.02 * vrot)
    e["vy"] = vy
    return r, dr, e


def _rotor_totals(x, r, dr, e, ph, n, n_azimuth):
    """Azimuth-averaged totals.

    Rotor frame: n = thrust axis, e_p = in-plane flow direction, e_s = n x e_p.
    A blade at azimuth psi lies along e_r = cos(psi) e_p + spin sin(psi) e_s and
    moves along e_t = spin (n x e_r); the element force on the rotor is
    ``N' n - T' e_t``.  Averaging over psi (B blades):
        H = B <T' sin psi>,  Y = -spin B <T' cos psi>        (in-plane force)
        M_p = spin B <N' r sin psi>,  M_s = -B <N' r cos psi> (hub moments)
    """
    B = x["blades"]
    avg = (lambda v: ca.sum2(ca.reshape(v, n, n_azimuth)) / n_azimuth)
    dTdr = B * avg(ph["Np"])
    dQdr = B * avg(ph["Tp"] * e["r"])
    T = ca.dot(dTdr, dr)
    Q = ca.dot(dQdr, dr)
    spsi = ca.DM(np.sin(e["psi"]))
    cpsi = ca.DM(np.cos(e["psi"]))
    edr = e["dr"]
    H = B * ca.sum1(ph["Tp"] * edr * spsi) / n_azimuth
    Y = -x["spin"] * B * ca.sum1(ph["Tp"] * edr * cpsi) / n_azimuth
    Mp = x["spin"] * B * ca.sum1(ph["Np"] * e["r"] * edr * spsi) / n_azimuth
    Ms = -B * ca.sum1(ph["Np"] * e["r"] * edr * cpsi) / n_azimuth
    va = avg(ph["u"])
    ring = r * dr
    va_mean = ca.dot(va, ring) / ca.sum1(ring)
    return {
        "thrust_N": T, "torque_Nm": Q, "power_W": Q * x["omega_radps"],
        "hforce_N": H, "yforce_N": Y, "mp_hub_Nm": Mp, "ms_hub_Nm": Ms,
        "gamma_m2ps": avg(ph["gamma"]), "va_mps": va, "vt_mps": avg(ph["v"]),
        "dTdr_Npm": dTdr, "dQdr_N": dQdr, "va_mean_mps": va_mean,
        # F v^2: the annulus-mean square swirl of Prandtl's sheet picture (swirl_power_W)
        "vt_msq_F_m2ps2": avg(ph["F"] * ph["v"] * ph["v"]),
    }


def bemt_function(sec, n_stations: int = 20, n_azimuth: int = 1, *, outputs: str | tuple = "nlp",
                  tip_loss: bool = True, hub_loss: bool = True, name: str = "bemt",
                  hub_fraction: float | None = None) -> ca.Function:
    """The BEMT of one rotor at one operating point as an SX ``casadi.Function``.

    Inputs (``INPUT_NAMES``; shapes in brackets, n = n_stations, m = n_azimuth):
        radius_m [1] tip radius; hub_fraction [1] R_hub/R; blades [1];
        chord_m [n], twist_rad [n] at the BEMT stations (``geometry.station_layout``);
        pitch_rad [1] collective added to twist; omega_radps [1] rotor speed (> 0);
        v_axial_mps [1] freestream along the thrust axis, into the disk;
        v_inplane_mps [1] freestream in the rotor plane (used only if m > 1);
        rho_kgpm3, mu_Pas, a_mps [1] air density, viscosity, speed of sound;
        spin [1] rotation sense +1/-1 (``RotorGeometry.rotation``);
        phi_rad [n*m] inflow angles, station index fastest (column j*n..j*n+n-1 is
        azimuth j).
    Outputs ``outputs="nlp"`` (``NLP_OUTPUTS``):
        residual [n*m]; thrust_N, torque_Nm, power_W; hforce_N (in-plane force along
        the in-plane flow, H), yforce_N (along n x e_p); gamma_m2ps [n] bound
        circulation, va_mps [n] induced axial, vt_mps [n] induced swirl (in the
        rotation direction), dTdr_Npm [n], dQdr_N [n] (all blades, azimuth
        averaged); va_mean_mps [1] area-averaged induced axial velocity;
        vt_msq_F_m2ps2 [n] the azimuth average of F v_t^2 (the Prandtl factor F times
        the square of the induced swirl at the blade: the annulus-mean square swirl).
    ``outputs="full"`` adds (``FULL_OUTPUTS``) CT, CP, CQ, eta = T Vx/P, FM =
    T^1.5/(P sqrt(2 rho pi R^2)), J = Vx/(n D), hub moments, and per element
    [n x m] alpha, cl, cd, W, Re, Mach, F, u, v and the element dT/dr, dQ/dr.
    A tuple of names selects outputs.  The per-element quantities of "full" use
    |.| (not for the NLP).

    The Function is pure SX (section calls included), meant to be mapped over
    mission nodes: ``f.map(K)`` with ``phi_rad`` as an (n*m, K) matrix.

    ``hub_fraction`` (a number): the rotors this Function serves have that hub, so a
    radial distribution of sections is placed at the stations' r/R when the graph is
    built and each section evaluated only where it carries weight (one section call
    per element instead of one per section).  The ``hub_fraction`` input must then be
    that number; None: sections placed at ``r/R`` as an expression of the input.
    """
    n, m = int(n_stations), int(n_azimuth)
    if m < 1:
        raise ValueError("n_azimuth must be >= 1")
    x = _symbols(n, m)
    r, dr, e = _elements(x, n, m)
    R = x["radius_m"]
    x_sec = placed_stations(sec, n, hub_fraction)
    x_sec = None if x_sec is None else np.tile(x_sec, m)
    ph = station_physics(x["phi_rad"], e["r"], e["chord"], e["theta"], x["v_axial_mps"], e["vy"],
                         x["rho_kgpm3"], x["mu_Pas"], x["a_mps"], x["blades"], R,
                         R * x["hub_fraction"], sec, tip_loss=tip_loss, hub_loss=hub_loss, x_sections=x_sec)
    out = _rotor_totals(x, r, dr, e, ph, n, m)
    out["residual"] = ph["residual"]
    if outputs == "nlp":
        names = NLP_OUTPUTS
    elif outputs == "full":
        names = FULL_OUTPUTS
    else:
        names = tuple(outputs)
    if any(nm not in NLP_OUTPUTS for nm in names):
        nrev = x["omega_radps"] / (2.0 * math.pi)
        D = 2.0 * R
        rho = x["rho_kgpm3"]
        T, Q, P = out["thrust_N"], out["torque_Nm"], out["power_W"]
        out["CT"] = T / (rho * nrev ** 2 * D ** 4)
        out["CP"] = P / (rho * nrev ** 3 * D ** 5)
        out["CQ"] = Q / (rho * nrev ** 2 * D ** 5)
        out["eta"] = T * x["v_axial_mps"] / P
        out["FM"] = T * ca.sqrt(ca.fabs(T)) / (P * ca.sqrt(2.0 * rho * math.pi * R * R))
        out["J"] = x["v_axial_mps"] / (nrev * D)
        shape = (lambda v: ca.reshape(v, n, m))
        for k_out, k_ph in (("alpha_rad", "alpha"), ("cl", "cl"), ("cd", "cd"), ("W_mps", "W"),
                            ("reynolds", "reynolds"), ("mach", "mach"), ("F", "F"), ("u_mps", "u"),
                            ("v_mps", "v")):
            out[k_out] = shape(ph[k_ph] + 0 * x["phi_rad"])
        out["dTdr_elem_Npm"] = shape(x["blades"] * ph["Np"])
        out["dQdr_elem_N"] = shape(x["blades"] * ph["Tp"] * e["r"])
    unknown = [nm for nm in names if nm not in out]
    if unknown:
        raise ValueError(f"unknown BEMT outputs {unknown}; choose from {FULL_OUTPUTS}")
    return ca.Function(name, [x[k] for k in INPUT_NAMES], [out[k] for k in names],
                       list(INPUT_NAMES), list(names))


def phi_momentum_guess(r, chord, theta, vx, vy, blades, lift_slope=2 * math.pi, alpha0=0.0):
    """Inflow angle from small-angle blade-element momentum with linear lift, no losses.

    Annulus momentum ``4 pi r (Vx + u) u = (B c/2) a0 Vy^2 (theta - alpha0 - phi)``
    with ``phi = (Vx + u)/Vy`` gives ``x = Vx + u`` from
    ``x^2 + (b - Vx) x - b Vy (theta - alpha0) = 0``, ``b = sigma' a0 Vy / 4``
    (the classic hover/climb inflow formula, e.g. Leishman, Principles of
    Helicopter Aerodynamics, Eq. 3.59).  Returns ``atan2(x, Vy)`` limited to
    [PHI_MIN_RAD, 80 deg].  NumPy in, NumPy out.
    """
    r, chord, theta, vx, vy = (np.asarray(v, dtype=float) for v in (r, chord, theta, vx, vy))
    b = blades * chord / (2 * np.pi * r) * lift_slope * vy / 4.0
    disc = np.maximum((b - vx) ** 2 + 4.0 * b * vy * (theta - alpha0), 0.0)
    xax = 0.5 * (-(b - vx) + np.sqrt(disc))
    xax = np.maximum(xax, 0.5 * np.maximum(vx, 0.0))
    return np.clip(np.arctan2(xax, vy), PHI_MIN_RAD, math.radians(80.0))


def bemt_unknowns(n_stations: int, n_azimuth: int = 1, init=None, *, n_nodes: int | None = None) -> dict:
    """Spec of the BEMT unknowns for an NLP: name, shape, unit, bounds, scale, init.

    Bounds [PHI_MIN_RAD, 3 pi/4] hold the root for climb, hover, mild descent,
    windmilling and the hub of a steeply pitched blade in fast axial flow (module
    docstring); the scale 0.3 rad is a typical inflow angle.
    ``init`` (rad) may be a full array (e.g. from ``analysis.solve_phi``) or a number.
    """
    shape = (n_stations * n_azimuth,) if n_nodes is None else (n_stations * n_azimuth, n_nodes)
    if init is None:
        init = 0.3
    init = np.asarray(init, dtype=float)
    if init.ndim == 1 and len(shape) == 2 and init.size == shape[0]:
        init = init[:, None]            # one column shared by every node
    init = np.broadcast_to(init, shape).copy()
    return {
        "name": "phi", "shape": shape, "unit": "rad", "lower": PHI_MIN_RAD, "upper": PHI_MAX_RAD,
        "scale": 0.3, "init": np.clip(init, PHI_MIN_RAD, PHI_MAX_RAD),
        "residual_scale": 1.0,
    }


def add_bemt_nodes(problem, name: str, fn: ca.Function, inputs: dict, *, n_nodes: int,
                   phi_init=None, labels_prefix: str | None = None) -> dict:
    """Add one rotor's BEMT at ``n_nodes`` operating points to a duck-typed problem.

    ``problem`` needs ``variable(name, shape, unit=, scale=, lower=, upper=, init=)``
    and ``constrain(name, expr, scale=, labels=)`` (``mdo.nlp.Problem`` has them).
    ``fn`` is a ``bemt_function``; ``inputs`` maps its input names (except
    ``phi_rad``) to expressions that are scalars/columns (shared by every node)
    or have ``n_nodes`` columns (one per node).  Adds the variable
    ``<name>_phi`` [n*m x n_nodes] and the constraint group ``<name>_bemt``; returns
    the outputs of ``fn.map(n_nodes)`` by name (each with n_nodes columns).
    """
    n_phi = fn.size1_in("phi_rad")
    spec = bemt_unknowns(n_phi, 1, phi_init, n_nodes=n_nodes)
    phi = problem.variable(f"{name}_phi", spec["shape"], unit="rad", scale=spec["scale"],
                           lower=spec["lower"], upper=spec["upper"], init=spec["init"])
    fmap = fn.map(n_nodes)
    args = {}
    for k in fn.name_in():
        if k == "phi_rad":
            args[k] = phi
        elif k in inputs:
            args[k] = inputs[k]
        else:
            raise KeyError(f"add_bemt_nodes: input {k!r} missing")
    res = fmap(**args)
    pre = labels_prefix or name
    labels = [f"{pre} node {j} element {i}" for j in range(n_nodes) for i in range(n_phi)]
    problem.constrain(f"{name}_bemt", res["residual"], scale=spec["residual_scale"], labels=labels)
    res = dict(res)
    res["phi_rad"] = phi
    return res
