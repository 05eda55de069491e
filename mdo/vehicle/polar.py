"""A point-mass vehicle with a fixed drag polar and fixed efficiencies.

For quick mission studies, for sizing intuition before the full models are set
up, and as the exact oracle of the mission's tests.  Everything is closed form:

Aerodynamics (wing at angle of attack ``alpha_w = theta + i_w [+ WMA] - gamma``)::

    CL     = CL0 + CL_alpha alpha_w                          (CL_max None: the exact linear polar)
    CL_lin = CL0 + CL_alpha sin(2 alpha_w)/2,                (CL_max given: a stall model for
    CL     = CL_lin / (1 + (CL_lin/CL_max)^8)^(1/8)           tilt-wings; sin(2a)/2 = a within 0.5 %
                                                             below 5 deg, 2 % at 10 deg, and gives
                                                             no lift at 90 and 180 deg; the
                                                             saturation is smooth: -0.7 % at
                                                             0.7 CL_max, -1e-5 below 0.25 CL_max)
    CD     = CD0 + k CL^2 + CD_90 sin^2(alpha_w)             (k = 1/(pi e AR); CD_90 a flat-plate
                                                             term for a tilted wing, default 0)
    L = q S CL,  D = q S CD,  q = rho V^2 / 2

Propulsion: a thrust ``T`` (the per-node unknown) along a line inclined at
``phi = theta + i_T + WMA [+ free tilt]`` above the horizon, at ``eps = phi - gamma``
to the velocity.  The ideal power is the momentum-theory power with the
Glauert inflow (``disk_area_m2`` given; v_i a per-node unknown)::

    v_i sqrt((V_a + v_i)^2 + V_e^2) = T / (2 rho A),   V_a = V cos(eps), V_e = V sin(eps)
    P_ideal = T (V_a + v_i)

(hover: P_ideal = T^1.5 / sqrt(2 rho A)), or without a disk area simply
``P_ideal = T V_a`` (a propeller of fixed propulsive efficiency, which cannot hover).
Then ``P_shaft = P_ideal / eta_p`` (eta_p: propulsive efficiency, or figure of
merit with a disk area) and ``P_battery = P_shaft / eta_chain + P_aux`` (eta_chain:
motor x ESC x battery).  Where ``min_thrust_N < 0`` allows a braking (windmilling)
thrust, the ideal power turns negative; the shaft then receives
``eta_p |P_ideal|`` and the battery ``regeneration_efficiency eta_chain`` of that
(0 by default: the motor freewheels).  The switch is a softplus of width
``w_P = 1e-3 m g (1 m/s)`` (error <= w_P ln 2 at zero power, none elsewhere).  The collocated state is the energy drawn from the battery,
``dE/dt = P_battery``; with ``battery_capacity_J`` the state of charge is
``1 - E / capacity``.

Momentum theory: Glauert, *Airplane Propellers*, in Durand (ed.), Aerodynamic
Theory IV, 1935; Leishman, *Principles of Helicopter Aerodynamics*, 2nd ed., 2006,
Eqs. 2.15 and 5.13 (forward-flight induced velocity).
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from ..core.atmosphere import density
from ..core.errors import InputError, check_positive, check_range
from ..core.smooth import softplus
from .base import G0, NodeEvaluation, Output, ResidualGroup, State, Unknown

__all__ = ["PolarVehicle"]


class PolarVehicle:
    """A point-mass aircraft with a parabolic drag polar and fixed efficiencies.

    Parameters (SI)
    ---------------
    mass_kg, wing_area_m2, CD0 : mass, reference area, zero-lift drag coefficient
    induced_drag_factor : k in CD = CD0 + k CL^2; or give ``aspect_ratio`` and
        ``oswald_efficiency`` (k = 1/(pi e AR))
    CL0, CL_alpha_per_rad : linear lift curve (default slope 2 pi AR/(AR + 2),
        Helmbold's low-aspect-ratio approximation)
    CL_max : smooth stall model (None: the exact linear fixed polar)
    wing_incidence_rad, thrust_incidence_rad : wing and thrust line relative to
        the body x axis
    wing_tilts : the wing tilts with the wing-mounted angle (a tilt-wing)
    flat_plate_drag_coefficient : CD_90 of the sin^2 term (0: pure polar)
    propulsive_efficiency : thrust power / shaft power (with a disk area: ideal
        momentum power / shaft power, a figure of merit)
    chain_efficiency : shaft power / battery power (motor x ESC x battery)
    disk_area_m2 : total rotor disk area (enables momentum-theory power and hover)
    auxiliary_power_W : avionics and payload power drawn from the battery
    battery_capacity_J : for the state of charge output
    max_thrust_N, min_thrust_N : bounds of the thrust unknown (``min_thrust_N < 0``
        allows a braking, windmilling thrust)
    regeneration_efficiency : fraction of the windmilling shaft power times
        ``chain_efficiency`` returned to the battery (0: none)
    free_tilt : the thrust-line tilt is a per-node unknown (a tilt-rotor whose
        nacelle angle the mission chooses), bounded by ``tilt_bounds_rad``
    design_wing_area : ``(lower, upper)`` m^2 makes the wing area a design
        variable (a quick wing-loading study); the mass does not change with it
    """

    parameters = {"wing_mounted_angle_rad": 0.0, "pitch_command_rad": 0.0}

    def __init__(self, name: str = "polar", *, mass_kg: float, wing_area_m2: float, CD0: float,
                 induced_drag_factor: float | None = None, aspect_ratio: float | None = None,
                 oswald_efficiency: float | None = None, CL0: float = 0.0, CL_alpha_per_rad: float | None = None,
                 CL_max: float | None = None, wing_incidence_rad: float = 0.0, thrust_incidence_rad: float = 0.0,
                 wing_tilts: bool = False, flat_plate_drag_coefficient: float = 0.0,
                 propulsive_efficiency: float = 0.8, chain_efficiency: float = 0.9,
                 disk_area_m2: float | None = None, auxiliary_power_W: float = 0.0,
                 battery_capacity_J: float | None = None, max_thrust_N: float | None = None,
                 min_thrust_N: float = 0.0, regeneration_efficiency: float = 0.0, free_tilt: bool = False, tilt_bounds_rad=(-10 * math.pi / 180, 100 * math.pi / 180),
                 design_wing_area=None):
        self.name = name
        check_positive("mass_kg", mass_kg, "kg")
        check_positive("wing_area_m2", wing_area_m2, "m^2")
        check_range("CD0", CD0, 0.0, 1.0)
        if induced_drag_factor is None:
            if aspect_ratio is None or oswald_efficiency is None:
                raise InputError("induced_drag_factor", "give it, or aspect_ratio and oswald_efficiency")
            check_positive("aspect_ratio", aspect_ratio)
            check_range("oswald_efficiency", oswald_efficiency, 0.3, 1.0)
            induced_drag_factor = 1.0 / (math.pi * oswald_efficiency * aspect_ratio)
        check_range("induced_drag_factor", induced_drag_factor, 0.0, 1.0)
        if CL_alpha_per_rad is None:
            if aspect_ratio is None:
                raise InputError("CL_alpha_per_rad", "give it, or aspect_ratio for 2 pi AR/(AR + 2)")
            CL_alpha_per_rad = 2.0 * math.pi * aspect_ratio / (aspect_ratio + 2.0)
        check_range("CL_alpha_per_rad", CL_alpha_per_rad, 0.5, 2 * math.pi)
        if CL_max is not None:
            check_range("CL_max", CL_max, 0.3, 6.0)
        check_range("propulsive_efficiency", propulsive_efficiency, 0.05, 1.0)
        check_range("chain_efficiency", chain_efficiency, 0.05, 1.0)
        check_range("flat_plate_drag_coefficient", flat_plate_drag_coefficient, 0.0, 3.0)
        check_range("auxiliary_power_W", auxiliary_power_W, 0.0, 1e7, "W")
        if disk_area_m2 is not None:
            check_positive("disk_area_m2", disk_area_m2, "m^2")
        if battery_capacity_J is not None:
            check_positive("battery_capacity_J", battery_capacity_J, "J")
        if max_thrust_N is not None:
            check_positive("max_thrust_N", max_thrust_N, "N")
        check_range("min_thrust_N", min_thrust_N, -10 * mass_kg * G0, 0.0, "N")
        check_range("regeneration_efficiency", regeneration_efficiency, 0.0, 1.0)
        if design_wing_area is not None:
            lo, hi = (float(x) for x in design_wing_area)
            if not 0 < lo <= wing_area_m2 <= hi:
                raise InputError("design_wing_area", f"need 0 < lower <= wing_area_m2 = {wing_area_m2:g} <= upper")
            design_wing_area = (lo, hi)
        self.mass_kg = float(mass_kg)
        self.reference_mass_kg = self.mass_kg
        self.wing_area_m2 = float(wing_area_m2)
        self.CD0 = float(CD0)
        self.k = float(induced_drag_factor)
        self.CL0 = float(CL0)
        self.CL_alpha = float(CL_alpha_per_rad)
        self.CL_max = None if CL_max is None else float(CL_max)
        self.wing_incidence_rad = float(wing_incidence_rad)
        self.thrust_incidence_rad = float(thrust_incidence_rad)
        self.wing_tilts = bool(wing_tilts)
        self.CD90 = float(flat_plate_drag_coefficient)
        self.eta_p = float(propulsive_efficiency)
        self.eta_chain = float(chain_efficiency)
        self.disk_area_m2 = None if disk_area_m2 is None else float(disk_area_m2)
        self.aux_W = float(auxiliary_power_W)
        self.capacity_J = None if battery_capacity_J is None else float(battery_capacity_J)
        self.max_thrust_N = None if max_thrust_N is None else float(max_thrust_N)
        self.min_thrust_N = float(min_thrust_N)
        self.regen = float(regeneration_efficiency)
        self.power_width_W = 1e-3 * self.mass_kg * G0 * 1.0
        self.free_tilt = bool(free_tilt)
        self.tilt_bounds_rad = tuple(float(x) for x in tilt_bounds_rad)
        self.design_wing_area = design_wing_area
        self._S = self.wing_area_m2       # expression after setup (design variable)
        self._problem_id = None

    # ------------------------------------------------------------------ protocol
    @property
    def weight_N(self) -> float:
        return self.mass_kg * G0

    def setup(self, problem) -> None:
        if self._problem_id == id(problem):
            return
        self._problem_id = id(problem)
        self._S = self.wing_area_m2
        if self.design_wing_area is not None:
            lo, hi = self.design_wing_area
            self._S = problem.variable(f"{self.name}.wing_area", unit="m^2", scale=self.wing_area_m2, lower=lo,
                                       upper=hi, init=self.wing_area_m2, design=True,
                                       description="reference wing area")

    def unknowns(self) -> list:
        W = self.weight_N
        out = [Unknown("thrust", unit="N", scale=0.25 * W, lower=self.min_thrust_N,
                       upper=self.max_thrust_N if self.max_thrust_N is not None else np.inf,
                       description="total thrust along the thrust line")]
        if self.disk_area_m2 is not None:
            out.append(Unknown("induced_velocity", unit="m/s", scale=self._v_hover(1.225),
                               lower=0.0 if self.min_thrust_N >= 0 else -np.inf,
                               description="momentum-theory induced velocity at the disk (Glauert)"))
        if self.free_tilt:
            lo, hi = self.tilt_bounds_rad
            out.append(Unknown("thrust_tilt", unit="rad", scale=0.5, lower=lo, upper=hi,
                               description="thrust-line tilt chosen by the mission (added to the WMA)"))
        return out

    def states(self) -> list:
        scale = self.capacity_J if self.capacity_J is not None else 1e8
        # a battery of given capacity cannot deliver more than it holds
        upper = self.capacity_J if self.capacity_J is not None else np.inf
        return [State("energy_drawn", unit="J", scale=scale, initial=0.0, upper=upper,
                      description="energy drawn from the battery since the start of the mission")]

    def energy_used_J(self, initial: dict, final: dict):
        return final["energy_drawn"] - initial["energy_drawn"]

    def stall_reference(self):
        """(reference area m^2, CL_max) for the free trajectory's stall-speed margin
        (:mod:`mdo.mission.trajectory`); None without a ``CL_max``."""
        return None if self.CL_max is None else (self._S, self.CL_max)

    # ------------------------------------------------------------------ physics
    def _v_hover(self, rho):
        return math.sqrt(self.weight_N / (2.0 * rho * self.disk_area_m2))

    def _aero(self, lib, S, rho, V, theta, gamma, wma):
        alpha_w = theta + self.wing_incidence_rad - gamma
        if self.wing_tilts:
            alpha_w = alpha_w + wma
        if self.CL_max is None:
            CL = self.CL0 + self.CL_alpha * alpha_w
        else:
            CL = self.CL0 + self.CL_alpha * 0.5 * lib.sin(2.0 * alpha_w)
            CL = CL / (1.0 + (CL / self.CL_max) ** 8) ** 0.125
        CD = self.CD0 + self.k * CL ** 2 + self.CD90 * lib.sin(alpha_w) ** 2
        q = 0.5 * rho * V ** 2
        return alpha_w, CL, CD, q * S * CL, q * S * CD

    def evaluate(self, nodes, unknowns) -> NodeEvaluation:
        rho = density(nodes.altitude_m)
        V, gamma, theta = nodes.speed_mps, nodes.flight_path_angle_rad, nodes.body_angle_rad
        wma = nodes.parameters.get("wing_mounted_angle_rad", 0.0)
        T = unknowns["thrust"]
        tilt = wma + self.thrust_incidence_rad
        if self.free_tilt:
            tilt = tilt + unknowns["thrust_tilt"]
        alpha_w, CL, CD, L, D = self._aero(ca, self._S, rho, V, theta, gamma, wma)
        eps = theta + tilt - gamma
        Va, Ve = V * ca.cos(eps), V * ca.sin(eps)
        residuals = []
        outputs = {}
        if self.disk_area_m2 is not None:
            vi = unknowns["induced_velocity"]
            vh2 = T / (2.0 * rho * self.disk_area_m2)
            # Glauert's forward-flight inflow (Leishman Eq. 5.13) times the total velocity at the disk
            residuals.append(ResidualGroup("induced_velocity_momentum",
                                           vi * ca.sqrt((Va + vi) ** 2 + Ve ** 2) - vh2,
                                           scale=self._v_hover(1.225) ** 2, unit="m^2/s^2"))
            P_ideal = T * (Va + vi)
            outputs["induced_velocity_mps"] = Output(vi, "m/s", "momentum-theory induced velocity")
        else:
            P_ideal = T * Va
        if self.min_thrust_N < 0:
            w = self.power_width_W
            P_shaft = softplus(P_ideal, w) / self.eta_p - self.eta_p * softplus(-P_ideal, w)
            P_batt = softplus(P_shaft, w) / self.eta_chain - self.regen * self.eta_chain * softplus(-P_shaft, w) \
                + self.aux_W
        else:
            P_shaft = P_ideal / self.eta_p
            P_batt = P_shaft / self.eta_chain + self.aux_W
        outputs.update({
            "CL": Output(CL, "-", "lift coefficient"),
            "CD": Output(CD, "-", "drag coefficient"),
            "angle_of_attack_rad": Output(alpha_w, "rad", "wing angle of attack"),
            "lift_N": Output(L, "N"), "drag_N": Output(D, "N"),
            "thrust_N": Output(T, "N", "thrust"),
            "shaft_power_W": Output(P_shaft, "W", "shaft power"),
            "battery_power_W": Output(P_batt, "W", "power drawn from the battery"),
        })
        if self.free_tilt:
            outputs["thrust_tilt_rad"] = Output(unknowns["thrust_tilt"], "rad")
        E = nodes.states["energy_drawn"]
        if self.capacity_J is not None:
            outputs["state_of_charge"] = Output(1.0 - E / self.capacity_J, "-", "state of charge")
        return NodeEvaluation(mass_kg=self.mass_kg,
                              force_along_path_N=T * ca.cos(eps) - D,
                              force_normal_N=T * ca.sin(eps) + L,
                              residuals=residuals, force_scale_N=self.weight_N,
                              state_derivatives={"energy_drawn": P_batt}, outputs=outputs)

    # ------------------------------------------------------------------ initial guess
    def induced_velocity(self, T, rho, Va, Ve):
        """Glauert inflow (numpy): solve v sqrt((Va + v)^2 + Ve^2) = T/(2 rho A) by Newton."""
        vh2 = T / (2.0 * rho * self.disk_area_m2)
        # start on the branch of the root: hover-like sqrt(|vh2|) plus the descent speed, or T/(2 rho A V)
        v = np.where(vh2 >= 0, np.sqrt(np.abs(vh2)) + np.maximum(-Va, 0.0),
                     vh2 / np.maximum(np.hypot(Va, Ve), 1.0))
        for _ in range(60):
            w = np.sqrt((Va + v) ** 2 + Ve ** 2)
            F = v * w - vh2
            dF = w + v * (Va + v) / np.maximum(w, 1e-9)
            step = F / np.where(np.abs(dF) > 1e-9, dF, 1e-9)
            v = v - np.clip(step, -0.5 * np.abs(v) - 1.0, 0.5 * np.abs(v) + 1.0)
        return v

    def initial_guess(self, nodes) -> dict:
        """Level-flight angle of attack and the thrust of the force balance, solved per node.

        A damped Newton iteration on the two path-frame force equations for
        (body angle, thrust) - or (tilt, thrust) where the segment prescribes the
        body angle and the tilt is free - started from the level-flight angle of
        attack (wing-borne nodes) or a vertical thrust line (hover-like nodes).
        """
        h = np.asarray(nodes.altitude_m, float)
        V = np.asarray(nodes.speed_mps, float)
        gam = np.asarray(nodes.flight_path_angle_rad, float)
        acc = np.asarray(nodes.acceleration_mps2, float)
        gdot = np.asarray(nodes.flight_path_angle_rate_radps, float)
        wma = np.asarray(nodes.parameters.get("wing_mounted_angle_rad", np.zeros_like(h)), float)
        fixed_theta = np.asarray(nodes.body_angle_rad, float)
        free_theta = np.isnan(fixed_theta)
        K = h.size
        rho = np.asarray(density(h), float)
        S = self.wing_area_m2
        m, W = self.mass_kg, self.weight_N
        q = 0.5 * rho * V ** 2
        base_tilt = wma + self.thrust_incidence_rad
        need_t = m * (G0 * np.sin(gam) + acc)
        need_n = m * (G0 * np.cos(gam) + V * gdot)
        # wing-borne where the wing at (about) its maximum lift carries most of the normal load
        cl_cap = min(self.CL_max if self.CL_max is not None else np.inf, 0.3 * self.CL_alpha)
        wing_borne = q * S * cl_cap > 0.6 * np.abs(need_n)
        # start: level-flight alpha where the wing can carry the weight, vertical thrust line otherwise
        extra = wma if self.wing_tilts else 0.0
        alpha0 = np.clip((need_n / np.maximum(q * S, 1e-9) - self.CL0) / self.CL_alpha, -0.1, 0.3)
        theta_offset = gam - self.wing_incidence_rad - extra            # theta = alpha_w + offset
        theta = np.where(wing_borne, alpha0 + theta_offset, 0.5 * math.pi - base_tilt)
        theta = np.where(free_theta, np.clip(theta, -0.7, 1.0), fixed_theta)
        tilt = np.zeros(K)
        T = np.maximum(np.hypot(need_t, need_n - 0.0), 0.05 * W) * np.where(wing_borne, 0.2, 1.0)

        def resid(th, tl, T):
            _, _, _, L, D = self._aero(np, S, rho, V, th, gam, wma)
            eps = th + base_tilt + tl - gam
            return T * np.cos(eps) - D - need_t, T * np.sin(eps) + L - need_n

        second = np.where(free_theta, 0, 1 if self.free_tilt else 2)   # 0: theta, 1: tilt, 2: none
        for _ in range(40):
            r1, r2 = resid(theta, tilt, T)
            dT = 1e-3 * W
            a1, a2 = resid(theta, tilt, T + dT)
            j11, j21 = (a1 - r1) / dT, (a2 - r2) / dT
            dx = 1e-6
            b1, b2 = resid(theta + dx * (second == 0), tilt + dx * (second == 1), T)
            j12, j22 = (b1 - r1) / dx, (b2 - r2) / dx
            det = j11 * j22 - j12 * j21
            ok = (second != 2) & (np.abs(det) > 1e-12)
            dTn = np.where(ok, (-r1 * j22 + r2 * j12) / np.where(ok, det, 1.0), -r1 / np.where(
                np.abs(j11) > 1e-12, j11, 1.0))
            dXn = np.where(ok, (-r2 * j11 + r1 * j21) / np.where(ok, det, 1.0), 0.0)
            dXn = np.clip(dXn, -0.1, 0.1)
            dTn = np.clip(dTn, -0.5 * W, 0.5 * W)
            T = np.maximum(T + dTn, self.min_thrust_N)
            # wing-borne nodes stay on the attached-flow branch (alpha_w in [-0.3, 0.45] rad)
            theta_new = np.where(wing_borne, np.clip(theta + dXn, theta_offset - 0.3, theta_offset + 0.45),
                                 theta + dXn)
            theta = np.where(second == 0, np.clip(theta_new, -0.75, 1.2), theta)
            tilt = np.where(second == 1, np.clip(tilt + dXn, *self.tilt_bounds_rad), tilt)
        out = {"body_angle_rad": theta, "thrust": T.reshape(1, -1)}
        eps = theta + base_tilt + tilt - gam
        if self.disk_area_m2 is not None:
            out["induced_velocity"] = self.induced_velocity(T, rho, V * np.cos(eps), V * np.sin(eps)).reshape(1, -1)
        if self.free_tilt:
            out["thrust_tilt"] = tilt.reshape(1, -1)
        return out
