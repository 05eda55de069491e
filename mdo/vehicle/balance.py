"""Longitudinal balance: the pitching moment about the centre of gravity, the neutral
point and the static margin.

Axes are the lattice's body axes (``mdo.wing.vlm``): x aft, y starboard, z up; a
moment about +y is nose-up positive.  Every term below is evaluated at every node
(rows 1 x K, numbers or CasADi) about the centre of gravity ``(x_cg, z_cg)``.

**Pitching moment about the CG** (N m), the sum of

* the lattice's forces and moment (both halves, wakes included): ``M_ref + d_z F_x -
  d_x F_z`` with ``d = r_ref - r_cg`` (the moment transferred from the lattice's
  reference point);
* the sections' zero-lift moment when the lattice has one chordwise panel (its load
  then acts at the quarter chord, so the camber's moment is missing):
  ``sum_strips q_loc c^2 w cm0`` with ``cm0`` of each strip's section surrogate at its
  zero-lift angle and Re 1e6 (with more chordwise panels the lattice on the camber line
  carries it itself);
* the fuselage (Raymer, *Aircraft Design*, 6th ed., Eq. 16.25, after Gilruth & White,
  NACA TR 711, 1941): ``dCm/dalpha = K_f W_f^2 L_f / (c S)`` per degree, i.e.
  ``M_fus = q K_f W_f^2 L_f (180/pi) alpha`` - independent of the reference area and
  chord; ``K_f`` is ``FuselageConfig.pitching_moment_factor``;
* the fuselage's viscous crossflow normal force ``N`` (``Aircraft.drag_buildup``), normal to
  the body axis at the planform's centroid, half the body length behind the nose:
  ``M = -(x_c - x_cg) N`` (second order in alpha: it leaves the neutral point alone);
* every rotor's thrust ``T`` and in-plane force ``H`` at its hub: with the thrust axis
  ``a`` above the body x axis pointing forward, ``F_x = -T cos a + H sin a``,
  ``F_z = T sin a + H cos a`` and ``M = d_z F_x - d_x F_z`` with ``d = r_hub - r_cg``.

Left out, stated: the moment of the profile and parasite drag about the CG height,
the rotors' own pitching moments (the normal force of the disk is in ``H``), the
post-stall lift correction of tilt-wing strips, and the hub positions of tilting
rotors (pitch trim of a tilt-wing is refused, :class:`~mdo.vehicle.aircraft.Aircraft`).

**Trim** (``Aircraft(trim=True)``, the default where the vehicle has a trim surface):
the moment about the CG is zero at every node of the segments with ``pitch_trim`` > 0,
with the incidence of each all-moving surface (``WingConfig.trim_incidence_range_deg``:
a stabilator, as on the P2006T and X-57) a control there.  Its incidence enters the
lattice as an upwash ``V delta`` at that surface's control points (as the flaps'
increment does), so the tail's lift, its induced drag and its stall margin follow.

**Neutral point and static margin** (power off, wakes off): the lattice at alpha = +-1 deg
(exact for the linear lattice up to O(1e-4)), plus the fuselage term,

    x_np = x_ref - (dM_ref/dalpha + dM_fus/dalpha + (z_ref - z_cg) dF_x/dalpha) / (dF_z/dalpha)

and the static margin ``(x_np - x_cg) / MAC`` of the main wing (design MAC).  The CG is
a design variable (the battery's position sets it), held by the requirement
``static margin >= VehicleConfig.static_margin_min``.
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from ..core.errors import InputError
from .base import G0, ResidualGroup, Unknown

__all__ = ["section_cm0", "pitching_moment_about_cg", "neutral_point_x", "surface_lift_N",
           "mean_aerodynamic_chord", "add_balance", "trim_unknowns", "trim_upwash", "trim_residuals"]


def section_cm0(vlm) -> np.ndarray:
    """Each strip's section zero-lift moment coefficient about its quarter chord (numbers)."""
    from ..airfoil import Airfoil
    cache: dict = {}
    out = np.zeros(len(vlm.strip_airfoil))
    for i, name in enumerate(vlm.strip_airfoil):
        if name is None or str(name) == "None":
            continue
        key = str(name)
        if key not in cache:
            af = Airfoil.from_name(key)
            a0 = float(af.alpha0_rad)
            cache[key] = float(np.asarray(af.cm(a0, 1e6), float).ravel()[0])
        out[i] = cache[key]
    return out


def _rotor_force_body(T, H, axis):
    """(F_x, F_z) of one rotor in body axes (x aft, z up) for a thrust axis ``axis`` above body x."""
    c, s = ca.cos(axis), ca.sin(axis)
    return -T * c + H * s, T * s + H * c


def pitching_moment_about_cg(vlm, r, rho, V, alpha, x_cg, z_cg, cm0, fuselage, rotors) -> object:
    """Nose-up moment about the CG (N m, 1 x K), module docstring.

    ``r``: a lattice solution of ``vlm`` (``F``, ``M``, ``V_local``); ``cm0``: per strip
    (numbers) or None; ``fuselage``: FuselageConfig; ``rotors``: a list of
    ``(x_hub, z_hub, T, H, axis, n)`` for n identical rotors at that hub station
    (``T``, ``H`` per rotor, 1 x K)."""
    g = vlm.geometry
    r_ref = g["r_ref"]
    F, M = r["F"], r["M"]
    moment = M[1, :] + (r_ref[2] - z_cg) * F[0, :] - (r_ref[0] - x_cg) * F[2, :]
    if cm0 is not None and np.any(cm0):
        c = g["strip_chord"].T
        w = g["strip_width"].T
        K = F.shape[1]
        q_loc = 0.5 * ca.repmat(rho, c.shape[0], 1) * r["V_local"] ** 2
        per_strip = ca.repmat(ca.DM(cm0) * c * c * w, 1, K)
        factor = 2.0 if vlm.symmetric else 1.0
        moment = moment + factor * ca.sum1(per_strip * q_loc)
    q = 0.5 * rho * V * V
    moment = moment + q * fuselage_moment_slope_m3(fuselage) * alpha
    for (x_h, z_h, T, H, axis, n) in rotors:
        Fx, Fz = _rotor_force_body(T, H, axis)
        moment = moment + n * ((z_h - z_cg) * Fx - (x_h - x_cg) * Fz)
    return moment


def fuselage_moment_slope_m3(fuselage) -> float:
    """dM_fus/dalpha / q (m^3 per rad): Raymer Eq. 16.25 times q S c (module docstring)."""
    return fuselage.pitching_moment_factor * fuselage.width_m ** 2 * fuselage.length_m * (180.0 / math.pi)


def neutral_point_x(vlm, fuselage, z_cg, dalpha_rad: float = math.radians(1.0)):
    """Power-off neutral point x (m, body axes; numbers or MX with the design) of the
    lattice ``vlm`` and the fuselage, at the CG height ``z_cg`` (module docstring)."""
    a = ca.DM([[-dalpha_rad, dalpha_rad]])
    r = vlm.solve(a, 1.0, rho=1.0)
    F, M = r["F"], r["M"]
    dF_x = (F[0, 1] - F[0, 0]) / (2 * dalpha_rad)
    dF_z = (F[2, 1] - F[2, 0]) / (2 * dalpha_rad)
    dM = (M[1, 1] - M[1, 0]) / (2 * dalpha_rad) + 0.5 * fuselage_moment_slope_m3(fuselage)
    r_ref = vlm.geometry["r_ref"]
    return r_ref[0] - (dM + (r_ref[2] - z_cg) * dF_x) / dF_z


def surface_lift_N(vlm, r, surface_index: int, rho, V):
    """Lift (N, 1 x K, both halves) of one surface of a lattice solution ``r``."""
    g = vlm.geometry
    idx = [i for i, s in enumerate(vlm.strip_surface) if s == surface_index]
    cw = (g["strip_chord"].T * g["strip_width"].T)[idx]
    q = 0.5 * rho * V * V
    factor = 2.0 if vlm.symmetric else 1.0
    return factor * q * ca.mtimes(ca.reshape(cw, 1, len(idx)), r["cl"][idx, :])


def mean_aerodynamic_chord(area_m2, span, taper):
    """MAC of a straight-tapered wing of constant area (numbers or CasADi)."""
    c_root = 2.0 * area_m2 / (span * (1.0 + taper))
    return 2.0 / 3.0 * c_root * (1 + taper + taper * taper) / (1 + taper)


# ---------------------------------------------------------------- an Aircraft's balance
def add_balance(ac, problem) -> None:
    """The CG's x (a design variable: the battery's position sets it, within
    ``VehicleConfig.cg_x_range_m``), the static margin requirement and the summary outputs
    of an :class:`~mdo.vehicle.aircraft.Aircraft`.  The baseline CG sits 5 % of MAC ahead
    of the required margin, from the baseline's neutral point, or at the end of the range
    nearest it."""
    cfg, main = ac.config, ac.config.main_wing
    c0 = main.mean_aerodynamic_chord_m
    x_np0 = float(neutral_point_x(ac._lattice(ac.wing_surfaces(ac.numeric_design())[0], ac.S_ref),
                                  cfg.fuselage, cfg.cg_z_m))
    if cfg.cg_x_range_m is not None:
        lo, up = (float(x) for x in cfg.cg_x_range_m)
    else:   # the main wing's MAC, 0-50 % (unswept quarter chord: its leading edge at (c_r - c)/4)
        x_le = main.root_le_x_m + 0.25 * (main.root_chord_m - c0)
        lo, up = x_le, x_le + 0.5 * c0
    init = float(np.clip(x_np0 - (cfg.static_margin_min + 0.05) * c0, lo, up))
    if "wing" not in ac.free:
        lo = up = init
    ac.x_cg = problem.variable("cg_x", 1, unit="m", scale=c0, lower=lo, upper=up, init=init, design=True,
                               description="centre of gravity, x (body axes; set by the battery's position)")
    dw = ac.design["wings"][main.name]
    x_np = neutral_point_x(ac.vlm, cfg.fuselage, cfg.cg_z_m)
    margin = (x_np - ac.x_cg) / mean_aerodynamic_chord(main.area_m2, dw["span"], dw["taper"])
    if ac.design_point_constraints:
        problem.constrain("static margin", margin - cfg.static_margin_min, kind=">=", scale=0.05, unit="-",
                          labels=[f"(x_np - x_cg)/MAC - {cfg.static_margin_min:g}"])
    problem.output("cg_x_m", ac.x_cg, unit="m", summary=True)
    problem.output("neutral_point_x_m", x_np, unit="m", summary=True)
    problem.output("static_margin", margin, unit="-", summary=True)
    ac.strip_cm0 = section_cm0(ac.vlm) if ac.nchord == 1 else None


def trim_unknowns(ac) -> list:
    """The incidence of each all-moving surface where the segment trims (``pitch_trim``)."""
    out = []
    for w in ac.trim_surfaces:
        a, b = w.trim_incidence_range_deg
        out.append(Unknown(f"{w.name}.trim_incidence", unit="rad", scale=0.1, lower=math.radians(a),
                           upper=math.radians(b), only_where="pitch_trim",
                           description=f"{w.name} incidence added for pitch trim ({a:g} to {b:g} deg)"))
    return out


def trim_upwash(ac, unknowns, v_cp, V):
    """The trim surfaces' incidence as an upwash ``V delta`` at their control points, added to
    the z component of ``v_cp`` (N x K each)."""
    vlm = ac.vlm
    names = [s_.name for s_ in vlm.surfaces]
    vz = v_cp[2]
    for w in ac.trim_surfaces:
        k = names.index(w.name)
        mask = np.array([1.0 if s == k else 0.0 for s in vlm.strip_surface])
        panel = ca.mtimes(ca.DM(vlm.strip_sum).T, ca.DM(mask.reshape(-1, 1)))   # N x 1
        vz = vz + ca.mtimes(panel, V * unknowns[f"{w.name}.trim_incidence"])
    return (v_cp[0], v_cp[1], vz)


def trim_residuals(ac, nodes, aero, rot, env) -> list:
    """The "pitch trim" group (moment about the CG = 0, N m, scaled by weight x MAC) at the
    nodes with ``pitch_trim`` > 0 of a vehicle with trim surfaces; [] otherwise.  A tilt-wing
    trims only where its wings are level (module docstring)."""
    K = env["K"]
    if not ac.trim_surfaces:
        return []
    on = np.asarray(ca.DM(nodes.parameters.get("pitch_trim", ca.DM.ones(1, K))), float).ravel() * np.ones(K) > 0
    trimmed = np.flatnonzero(on)
    tilted = (np.abs(env["wma_schedule"]) > 1e-9) | env["tilt_nodes"]
    if ac.config.kind == "tilt_wing" and np.any(tilted[trimmed]):
        raise InputError("pitch_trim", "a tilt-wing trims in pitch only where its wings are level (the "
                         "tilted rotors' hub positions and the post-stall strips' moment are not "
                         "modelled): set pitch_trim = 0 in the segments that tilt, as evtol_segments does")
    if not trimmed.size:
        return []
    rotors = []
    for gm in ac.groups:
        o = rot[gm.name]
        axis = ac.rotor_axis_angle(gm, env["wma"])
        rotors += [(x, z, o["T"], o["H"], axis, 2) for (x, _, z) in ac.rotor_centres[gm.name]]
    moment = pitching_moment_about_cg(ac.vlm, aero["vlm"], env["rho"], env["V"], env["alpha"], ac.x_cg,
                                      ac.config.cg_z_m, ac.strip_cm0, ac.config.fuselage, rotors)
    moment = moment - (0.5 * ac.config.fuselage.length_m - ac.x_cg) * aero["body_normal_N"]
    scale = ac.togw_baseline_kg * G0 * ac.config.main_wing.mean_aerodynamic_chord_m
    return [ResidualGroup("pitch trim", moment[:, [int(k) for k in trimmed]], scale=scale, unit="N m",
                          row_labels=["moment about the CG"], columns=trimmed)]
