"""Directional control with one motor failed: the rudder must hold the yaw of the
motor still running opposite the failed one, at every wing-borne node.

Why: the optimizer moves propellers outboard (the slipstream relieves the wing's
bending and cuts induced drag), and nothing else in the model pushes back.  A real
multi-engine airplane must stay controllable when its outboard motor fails at
take-off power at the lowest speed it flies (14 CFR 23.149 / CS-23.149, the minimum
control speed V_MC).  This is the first limit an outboard motor meets.

For each rotor position ``i`` of each group (the starboard motor fails; its port
mirror runs at take-off power), at each node where the segment is wing-borne (its
stall margin on) and the group runs::

    y_i (T_TO(V, rho, R) + D_dead)  <=  N_rudder = eta_v q S_v a_v tau delta_max l_v      (E1)

* ``T_TO``: the thrust of one rotor at the motor's take-off power (``P_rated`` times the
  short-time factor when the group has a short-time rating), from momentum theory,
  ``P = T (V + v_i)`` with ``v_i = -V/2 + sqrt(V^2/4 + T/(2 rho A))`` (fixed-point, eight
  passes from ``T = P/V``; ``v_i << V`` at wing-borne speeds), times the propeller's
  efficiency relative to the ideal disk, ``ENGINE_OUT_IDEAL_FRACTION`` = 0.85 (profile
  and swirl losses of 10-20 % at climb speeds: McCormick, *Aerodynamics, Aeronautics and
  Flight Mechanics*, 2nd ed., ch. 6).
* ``D_dead``: the failed rotor's drag, ``q C_D A`` with the group's
  ``inoperative_drag_coefficient`` on the disk area (0 by default: a feathered or
  stopped-and-aligned propeller; a windmilling fixed-pitch propeller is well above).
* ``a_v``: the fin's lift slope (Helmbold/DATCOM, Eq. E2) at its effective aspect ratio,
  1.55 times the geometric ``b_v^2/S_v`` for the end-plate effect of the fuselage and
  horizontal tail (Raymer, *Aircraft Design*, 6th ed., sec. 16.4).
* ``tau``: the rudder's effectiveness, thin-airfoil theory for a plain flap of chord
  fraction ``c_f/c`` (Eq. E3: ``tau = 1 - (theta_f - sin theta_f)/pi``,
  ``cos theta_f = 2 c_f/c - 1``; Abbott & von Doenhoff, *Theory of Wing Sections*,
  sec. 8.5), times ``rudder_effectiveness_factor`` for the lost effectiveness at large
  deflections (about 0.7 at 25 deg: Roskam, *Airplane Design* Part VI, Fig. 8.13).
* ``eta_v`` = 0.9, the fin's dynamic-pressure ratio (Raymer sec. 16.3: 0.9 for a tail
  out of the slipstream); ``l_v``: from the centre of gravity (a design variable when the
  vehicle trims; else the main wing's quarter MAC) to the fin's quarter MAC.

Left out, all on the conservative side but the last: the 5 deg bank toward the live
motor that the rule allows (its side force relieves the fin), the fin's sidewash, the
rudder pedal force limit, and the failed motor's mirror being throttled back by a
control system (a distributed-propulsion airplane may do that: a group with
``failure_stops_mirror=True`` is left out, and the climb on the motors left, which that
response then needs, is not modelled; ``Aircraft(engine_out="off")`` leaves out every group).  The check is at each node's own speed:
a certification V_MC at 1.2 V_S1 can be below the slowest speed a mission flies.
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from ..core.errors import InputError
from .base import ResidualGroup

__all__ = ["fin_lift_slope_per_rad", "rudder_effectiveness", "fin_yaw_moment_per_q_m3",
           "ideal_thrust_N", "minimum_control_speed_mps", "engine_out_moments", "engine_out_moments_once",
           "engine_out_rows",
           "engine_out_option", "add_fin_design", "default_x_cg_m", "FIN_AREA_SCALE_MAX", "ENGINE_OUT_IDEAL_FRACTION", "FIN_EFFECTIVE_AR_FACTOR",
           "FIN_DYNAMIC_PRESSURE_RATIO"]

ENGINE_OUT_IDEAL_FRACTION = 0.85     # propeller thrust / ideal actuator-disk thrust at equal power
FIN_EFFECTIVE_AR_FACTOR = 1.55       # Raymer 16.4: end-plate effect of fuselage and horizontal tail
FIN_DYNAMIC_PRESSURE_RATIO = 0.9     # Raymer 16.3
SECTION_SLOPE_FRACTION = 0.95        # section lift slope / 2 pi (DATCOM's kappa)


def fin_lift_slope_per_rad(fin) -> float:
    """Lift slope of a fin (1/rad on its area), Helmbold/DATCOM (Eq. E2)::

        a = 2 pi A / (2 + sqrt(4 + A^2 (1 + tan^2 L_c2) / kappa^2))

    with the effective aspect ratio ``A = 1.55 b^2/S`` and the half-chord sweep from the
    quarter-chord sweep of the fin mirrored into a wing of aspect ratio ``2 b^2/S``."""
    A_geo = fin.span_m ** 2 / fin.area_m2
    A = FIN_EFFECTIVE_AR_FACTOR * A_geo
    lam = fin.taper
    tan_c2 = math.tan(math.radians(fin.sweep_quarter_chord_deg)) - 4.0 / (2 * A_geo) * 0.25 * (1 - lam) / (1 + lam)
    k = SECTION_SLOPE_FRACTION
    return 2 * math.pi * A / (2 + math.sqrt(4 + A * A * (1 + tan_c2 ** 2) / (k * k)))


def rudder_effectiveness(chord_fraction: float) -> float:
    """Thin-airfoil flap effectiveness d(alpha_0)/d(delta) of a plain flap (Eq. E3)."""
    theta = math.acos(2 * chord_fraction - 1)
    return 1 - (theta - math.sin(theta)) / math.pi


def _fin_quarter_mac_x(fin) -> float:
    """x of a fin's quarter MAC: its LE sweep from the quarter-chord sweep and taper."""
    b, lam, c_r = fin.span_m, fin.taper, fin.root_chord_m
    tan_le = math.tan(math.radians(fin.sweep_quarter_chord_deg)) + 0.25 * (c_r - lam * c_r) / b
    z_mac = b / 3 * (1 + 2 * lam) / (1 + lam)
    return fin.root_le_x_m + z_mac * tan_le + 0.25 * fin.mean_aerodynamic_chord_m


def fin_yaw_moment_per_q_m3(fins, x_cg, area_scale: dict | None = None):
    """The fins' largest rudder yawing moment over the freestream dynamic pressure, m^3
    (the right side of Eq. E1 without ``q``); ``x_cg`` a number or CasADi expression;
    ``area_scale[fin]`` a sized fin's area over its configured one (aspect ratio held:
    the lift slope is the configured fin's; the arm is held too)."""
    total = 0.0
    for f in fins:
        s = (area_scale or {}).get(f.name, 1.0)
        dCL = (fin_lift_slope_per_rad(f) * rudder_effectiveness(f.rudder_chord_fraction)
               * f.rudder_effectiveness_factor * math.radians(f.rudder_max_deflection_deg))
        total = total + FIN_DYNAMIC_PRESSURE_RATIO * f.area_m2 * s * dCL * (_fin_quarter_mac_x(f) - x_cg)
    return total


def ideal_thrust_N(power_W, V, rho, disk_area_m2, passes: int = 8):
    """Thrust of an ideal actuator disk absorbing ``power_W`` at axial speed ``V``
    (momentum theory, ``P = T (V + v_i)``), by fixed-point passes from ``T = P/V``."""
    T = power_W / V
    for _ in range(passes):
        v_i = -0.5 * V + ca.sqrt(0.25 * V * V + T / (2 * rho * disk_area_m2))
        T = power_W / (V + v_i)
    return T


def minimum_control_speed_mps(yaw_per_q_m3: float, arm_m: float, take_off_power_W: float, radius_m: float,
                              inoperative_drag_coefficient: float = 0.0, rho: float = 1.225) -> float:
    """The speed (m/s, at density ``rho``) above which the rudder holds a failed motor at
    ``arm_m`` with its mirror at ``take_off_power_W`` (Eq. E1 with equality): the design's
    V_MC in this model.  Numbers; bisection (the demand falls with speed, the rudder's moment
    grows as q).  0 if it holds at any speed above 1 m/s, inf if at none below 300 m/s."""
    area = math.pi * radius_m ** 2

    def excess(V):
        q = 0.5 * rho * V * V
        T = ENGINE_OUT_IDEAL_FRACTION * float(ideal_thrust_N(take_off_power_W, V, rho, area))
        return arm_m * (T + q * inoperative_drag_coefficient * area) - yaw_per_q_m3 * q

    lo, hi = 1.0, 300.0
    if excess(lo) <= 0.0:
        return 0.0
    if excess(hi) > 0.0:
        return math.inf
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if excess(mid) > 0.0 else (lo, mid)
    return 0.5 * (lo + hi)


def engine_out_moments(ac, env) -> tuple:
    """The rudder's largest yawing moment and, per rotor group, each position's yawing
    moment with its motor failed (Eq. E1's two sides), N m, 1 x K at every node:
    ``(N_rudder, {group: [demand of position i]})``."""
    cfg = ac.config
    x_cg = getattr(ac, "x_cg", None)
    x_cg = default_x_cg_m(cfg) if x_cg is None else x_cg
    V, rho = env["V"], env["rho"]
    q = 0.5 * rho * V * V
    N_rudder = fin_yaw_moment_per_q_m3(cfg.fins, x_cg, getattr(ac, "fin_area_scale", None)) * q
    demand = {}
    for gm in ac.groups:
        g, d = gm.config, gm.design
        area = math.pi * d["R"] ** 2
        P_to = d["P_rated"] * g.motor.take_off_power_factor
        T_to = ENGINE_OUT_IDEAL_FRACTION * ideal_thrust_N(P_to, V, rho, area)
        D_dead = q * g.inoperative_drag_coefficient * area
        # the arm of each position: the starboard rotor's y
        demand[gm.name] = [p[1] * (T_to + D_dead) for p in ac.rotor_centres[gm.name]]
    return N_rudder, demand


def engine_out_moments_once(ac, env) -> tuple:
    """:func:`engine_out_moments`, built once per evaluation and kept in ``env``: the limit
    and the ``mission.csv`` outputs read the same expressions."""
    if "engine_out" not in env:
        env["engine_out"] = engine_out_moments(ac, env)
    return env["engine_out"]


def engine_out_rows(ac, nodes, rot, env, wing_borne: np.ndarray) -> list:
    """Eq. E1 as one ``ResidualGroup`` per rotor group (a row per rotor position), at the
    wing-borne nodes where the group runs.  Scaled by the rudder's moment at the baseline
    cruise speed.  The moments are built once per evaluation (``env["engine_out"]``, which
    the ``mission.csv`` outputs read too)."""
    N_rudder, demand = engine_out_moments_once(ac, env)
    scale = _reference_moment(ac.config)
    out = []
    for gm in ac.groups:
        if gm.config.failure_stops_mirror:
            continue
        cols = np.intersect1d(np.flatnonzero(wing_borne), rot[gm.name]["on"])
        if cols.size == 0:
            continue
        c = list(cols)
        rows = ca.vertcat(*[n[:, c] - N_rudder[:, c] for n in demand[gm.name]])
        out.append(ResidualGroup(f"{gm.config.name} engine-out yaw", rows, kind="<=", scale=scale, unit="N m",
                                 row_labels=[f"position {i}: y (T_TO + D_dead) - N_rudder"
                                             for i in range(len(demand[gm.name]))], columns=cols))
    return out


def _reference_moment(cfg) -> float:
    """The rudder's moment at the baseline cruise speed and altitude, N m (a scale)."""
    from ..core.atmosphere import atmosphere
    rho = float(np.asarray(atmosphere(np.array([cfg.cruise_altitude_m]))["density_kgpm3"]).ravel()[0])
    return float(fin_yaw_moment_per_q_m3(cfg.fins, default_x_cg_m(cfg))) * 0.5 * rho * cfg.cruise_speed_mps ** 2


def default_x_cg_m(cfg) -> float:
    """The CG's x when the vehicle does not place it (no pitch trim): the main wing's root
    quarter chord (its quarter chord is unswept)."""
    main = cfg.main_wing
    return main.root_le_x_m + 0.25 * main.root_chord_m


#: the largest fin a fin-sizing optimization may reach, times the configured fin's area
FIN_AREA_SCALE_MAX = 3.0


def engine_out_option(config, engine_out) -> str:
    """``Aircraft(engine_out=...)`` checked: None is "rudder" for an airplane, "off" for a
    tilt-wing (its rotor failure is a hover and transition case of the remaining rotors,
    not modelled); "rudder" needs a fin unless every group's failure stops its mirror."""
    if engine_out is None:
        engine_out = "rudder" if config.kind == "airplane" else "off"
    if engine_out not in ("rudder", "off"):
        raise InputError("engine_out", f"one of 'rudder', 'off', got {engine_out!r}")
    held = [g for g in config.rotor_groups if not g.failure_stops_mirror]
    if engine_out == "rudder" and held and not config.fins:
        raise InputError("engine_out", "'rudder' needs a fin (a wing with role 'fin') to hold the yaw of a "
                         "failed motor; add one or set engine_out='off' and say how the yaw is held")
    return engine_out


def add_fin_design(ac, problem) -> dict:
    """Each fin's area over its configured area: a design variable with ``ac.fin_sizing``
    (free with the wing, 1 to ``FIN_AREA_SCALE_MAX``), else 1."""
    if not ac.fin_sizing:
        return {f.name: 1.0 for f in ac.config.fins}
    free = "wing" in ac.free
    out = {}
    for f in ac.config.fins:
        out[f.name] = problem.variable(f"{f.name}.area_scale", 1, unit="-", scale=1.0, lower=1.0,
                                       upper=FIN_AREA_SCALE_MAX if free else 1.0, init=1.0, design=True,
                                       description=f"{f.name} area / its configured {f.area_m2:g} m^2 "
                                                   "(aspect ratio held)")
        problem.output(f"{f.name}.area_m2", f.area_m2 * out[f.name], unit="m^2", summary=True)
    return out
