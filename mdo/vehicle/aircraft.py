"""The paper's aircraft as a mission vehicle: every discipline at every node.

``Aircraft(config)`` implements the vehicle protocol of ``mdo.vehicle.base`` for a
:class:`~mdo.vehicle.config.VehicleConfig` (GA-2P, GA-8P, TTW).  At setup it adds
the design variables of Eq. 7 (Adkins-Liebeck inputs per rotor group, wing span,
taper and section twists at constant reference area, rotor span positions) and
the gross weight, and builds the design-dependent parts once:

* the blades: Adkins-Liebeck as residuals (design-level unknowns ``w``, ``alpha_i``),
  giving chord and twist at the BEMT stations (``mdo.rotor``);
* the lifting surfaces: a symmetric vortex lattice whose influence matrix depends
  on span, taper, twists and slipstream edges only (``mdo.wing``);
* the propeller wakes: the blade-passage-averaged wake's influence at the wing's
  control points, per rotor (``mdo.wake``);
* the mass build-up residual ``TOGW = sum(terms(TOGW, design))`` (``mass.py``).

At the mission's K nodes (``evaluate``), with the body angle, rotor speed, BEMT
inflow angles and pack current as unknowns:

1. atmosphere at the node altitude; rotor inflow from speed, angle of attack and
   the wing-mounted angle (axial ``V cos(a)``, in-plane ``V sin(a)``, ``a = alpha + WMA``);
2. BEMT residuals and loads (one SX Function mapped over the nodes);
3. wake velocity at the wing = sum over rotors of influence x (Gamma, Omega/V_w);
4. one vortex-lattice solve for all nodes: ``A(d) [G_1..G_K] = [b_1..b_K]``, with the
   wake in the flow tangency and the "swirl" force coupling (``mdo.wake`` README);
5. drag build-up: strip profile drag, fuselage, nacelles, fin;
6. powertrain: motor, ESC, pack current balance, state-of-charge rate;
7. forces in the path frame: lift, drag, thrust and in-plane rotor force along the
   tilted rotor axis.

Frames: the mission's path frame (x forward, z up); the wing and wake use body
axes with x aft, y starboard, z up (``mdo.wing``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..core import units as u
from ..core.atmosphere import atmosphere
from ..core.errors import InputError
from ..core.smooth import smooth_max, smooth_min
from ..powertrain import paper_powertrain
from ..rotor import (PHI_MAX_RAD, PHI_MIN_RAD, adkins_liebeck, add_adkins_liebeck,
                     bemt_function, section)
from ..wake import WakeRotor, influence_sum_parts, spin_for, wake_influences
from ..wing import VLM, Body, body_drag, constant_area, profile_drag, trapezoid
from ..wing.drag import form_factor_wing, skin_friction
from .base import G0, NodeEvaluation, Output, ResidualGroup, State, Unknown
from .config import VehicleConfig, WingConfig
from .mass import MassDesign, solve_togw, total_mass

__all__ = ["Aircraft", "DesignBounds"]


@dataclass
class DesignBounds:
    """Bounds of the design variables, as factors of the baseline (or absolute where noted).

    The paper gives no bounds.  Its GA-2P optimum has a span of exactly 13.00 m, which we
    read as the upper bound (1.14 x 11.4 m) and apply as the same factor to every wing;
    the others are ordinary engineering ranges (a tapered wing between 0.35 and
    rectangular; design speeds within -40 %/+30 % of the baseline, as Table 3's
    optima move at most 18 %; design cl of NACA 4412 sections 0.4-1.0, below stall).
    """
    design_thrust: tuple = (0.5, 2.0)
    design_speed: tuple = (0.6, 1.3)
    tip_radius: tuple = (0.6, 1.6)
    design_cl: tuple = (0.4, 1.0)          # absolute
    span: tuple = (0.8, 13.0 / 11.4)
    taper: tuple = (0.35, 1.0)             # absolute
    twist_deg: tuple = (-5.0, 8.0)         # absolute
    span_eta: tuple = (0.0, 1.0)           # absolute (fraction of the semispan)
    tip_clearance_m: float = 0.05          # between neighbouring disks, and disk to symmetry plane


def _row(x, K=None) -> ca.DM:
    a = np.asarray(x, dtype=float).reshape(1, -1)
    if K is not None and a.size == 1:
        a = np.repeat(a, K, axis=1)
    return ca.DM(a)


def _num(x) -> np.ndarray:
    return np.asarray(ca.DM(x), dtype=float)


def _cols(v, idx, K):
    """Columns ``idx`` of a 1 x K row (or a scalar)."""
    if isinstance(v, (ca.MX, ca.SX, ca.DM)) and v.shape[1] == K and K > 1:
        return v[:, list(idx)]
    return v


class Aircraft:
    """A configuration of ``mdo.vehicle.catalog`` flying a mission (see module docstring).

    Parameters
    ----------
    config : VehicleConfig
    free : which design variables the optimizer may move: any of ``"rotor"`` (the
        Adkins-Liebeck inputs), ``"wing"`` (span, taper, twists of every lifting
        wing), ``"positions"`` (rotor span positions).  All are created as design
        variables either way (``--analysis`` freezes them); the others are fixed.
    n_stations : BEMT stations per blade.  ``n_azimuth``: azimuth positions (1 for
        axial flow; the tilt-wing uses 4 for its transitions).
    wing_strips, tail_strips, nchord : lattice size (strips per semispan, chordwise panels).
    coupling : ``"swirl"`` (default; see mdo/wake/README.md), ``"freestream"`` or ``"local"``.
    mass_model : ``"buildup"`` (gross weight follows the design) or ``"fixed"``
        (the baseline build-up's gross weight, as the paper's optimization keeps it).
    powertrain_limits : add throttle <= 1, cell current and cell voltage limits.
    wake_samples : points across each lattice strip over which the propeller wake is
        averaged (default 5; 1 = at the control point, which makes the energy ripple
        with the rotor position, see mdo/README.md).
    Segments may set ``drag_device_area_m2`` (gear/flap drag on approach, a control).
    """

    def __init__(self, config: VehicleConfig, *, free=("rotor", "wing", "positions"), n_stations: int = 16,
                 n_azimuth: int | None = None, wing_strips: int = 20, tail_strips: int = 6, nchord: int = 1,
                 coupling: str = "swirl", mass_model: str = "buildup", powertrain_limits: bool = False,
                 misc_drag_fraction: float = 0.05, bounds: DesignBounds | None = None,
                 positions_free: bool | None = None, design_point_constraints: bool = True,
                 wing_stall: bool | None = None, slipstream_breaks: bool = False, wake_samples: int = 5):
        """See the class docstring; ``design_point_constraints=False`` leaves out the
        tip-Mach and disk-clearance constraints (analysis of a violating design)."""
        if coupling not in ("swirl", "freestream", "local"):
            raise InputError("coupling", f"'swirl', 'freestream' or 'local', got {coupling!r}")
        if mass_model not in ("buildup", "fixed"):
            raise InputError("mass_model", f"'buildup' or 'fixed', got {mass_model!r}")
        unknown_free = set(free) - {"rotor", "wing", "positions"}
        if unknown_free:
            raise InputError("free", f"unknown design groups {sorted(unknown_free)}; allowed rotor, wing, positions")
        if len(config.rotor_groups) != 1:
            raise InputError("rotor_groups", "this vehicle model supports one rotor group (all motors identical)")
        self.config = config
        self.name = config.name
        self.free = set(free)
        self.n_stations = int(n_stations)
        self.n_azimuth = int(n_azimuth or (4 if config.kind == "tilt_wing" else 1))
        self.wing_strips = int(wing_strips)
        self.tail_strips = int(tail_strips)
        self.nchord = int(nchord)
        self.coupling = coupling
        self.mass_model = mass_model
        self.powertrain_limits = bool(powertrain_limits)
        # post-stall strips (tilt-wing transitions); the linear lattice elsewhere
        self.wing_stall = (config.kind == "tilt_wing") if wing_stall is None else bool(wing_stall)
        # Strip boundaries at the slipstream edges move with the rotors, but the strip
        # counts between them are fixed by the baseline: when a rotor moves far (GA-2P's
        # optimum moves it from 0.23 to 0.8 of the semispan) an interval keeps one strip.
        # The default is a fixed cosine lattice; the averaged wake is smooth (cored
        # sheets), so lift and drag stay smooth in the rotor position.
        self.slipstream_breaks = bool(slipstream_breaks)
        # wake velocity averaged over this many points across each strip (1: at the
        # control point).  At the control point alone the mission energy ripples by
        # +-0.35 kWh (GA-2P) as a rotor's slipstream edge crosses the strips, and the
        # optimizer parks the rotor in a ripple trough; 5 samples leave +-0.01 kWh
        # (tests/bench/position_sweep.py; mdo.wake.mean.strip_averaged_influence)
        if int(wake_samples) < 1:
            raise InputError("wake_samples", f"must be >= 1, got {wake_samples}")
        self.wake_samples = int(wake_samples)
        # tip Mach and disk clearance; off for the analysis of a design that violates them (GA-8P)
        self.design_point_constraints = bool(design_point_constraints)
        self.misc_drag_fraction = float(misc_drag_fraction)
        self.bounds = bounds or DesignBounds()
        # drag_device_area_m2: the most flat-plate area (gear, flap) the pilot may add at a
        # node (segment parameter; 0 = none); its deployment is a control of those nodes
        self.parameters = {"wing_mounted_angle_rad": 0.0, "pitch_command_rad": 0.0, "drag_device_area_m2": 0.0}
        self.group = config.rotor_groups[0]
        self.section = section(self.group.airfoil.lower().replace("_", ""))
        self.powertrain = paper_powertrain(config.name, rated_rpm=self.group.design_rpm)
        self.omega_design = self.group.design_rpm * u.RPM
        self.bemt = bemt_function(self.section, self.n_stations, self.n_azimuth, outputs="nlp")
        self._problem = None
        self.togw_baseline_kg = solve_togw(config)
        # rotor positions free unless the config says they are fixed (GA-8P: equally spaced)
        self.positions_free = ("positions" in self.free) if positions_free is None else bool(positions_free)
        self._baseline_blade = None

    # ------------------------------------------------------------------ design
    @property
    def lifting_wings(self) -> list[WingConfig]:
        """Wings whose span/taper/twist are design variables (main and tandem wings)."""
        return [w for w in self.config.wings if not w.vertical and (w.name == "main_wing" or w.tilting
                                                                    or w.name.startswith("tandem"))]

    @property
    def tails(self) -> list[WingConfig]:
        return [w for w in self.config.wings if not w.vertical and w not in self.lifting_wings]

    def baseline_blade(self) -> dict:
        """The numeric Adkins-Liebeck blade at the configured design point."""
        if self._baseline_blade is None:
            g = self.group
            self._baseline_blade = adkins_liebeck(
                blades=g.blades, radius_m=g.radius_m, speed_mps=g.design_speed_mps, airfoil=self.section,
                cl_design=g.design_cl, thrust_N=g.design_thrust_N, omega_radps=self.omega_design,
                hub_fraction=g.hub_fraction, altitude_m=g.design_altitude_m, n_stations=self.n_stations)
        return self._baseline_blade

    def setup(self, problem) -> None:
        if self._problem is problem:
            return
        self._problem = problem
        cfg, g, b = self.config, self.group, self.bounds
        var = problem.variable
        d = {}
        # --- rotor design (Eq. 7: c, beta = f(V_design, R_tip, T_design, cl_design))
        rotor_free = "rotor" in self.free

        def dv(name, init, lo, hi, unit, scale, desc, free=True, shape=1):
            if not free:
                lo, hi = init, init
            return var(name, shape, unit=unit, scale=scale, lower=lo, upper=hi, init=init, design=True,
                       description=desc)

        p = g.name
        d["T_design"] = dv(f"{p}.design_thrust", g.design_thrust_N, b.design_thrust[0] * g.design_thrust_N,
                           b.design_thrust[1] * g.design_thrust_N, "N", g.design_thrust_N,
                           "Adkins-Liebeck design thrust", rotor_free)
        d["V_design"] = dv(f"{p}.design_speed", g.design_speed_mps, b.design_speed[0] * g.design_speed_mps,
                           b.design_speed[1] * g.design_speed_mps, "m/s", max(g.design_speed_mps, 5.0),
                           "Adkins-Liebeck design speed", rotor_free)
        d["R"] = dv(f"{p}.tip_radius", g.radius_m, b.tip_radius[0] * g.radius_m, b.tip_radius[1] * g.radius_m,
                    "m", g.radius_m, "propeller/rotor tip radius", rotor_free)
        d["cl_design"] = dv(f"{p}.design_cl", g.design_cl, b.design_cl[0], b.design_cl[1], "-", 1.0,
                            "Adkins-Liebeck design lift coefficient", rotor_free)
        # --- wings: span, taper, section twists at constant area (Fig. 12)
        wing_free = "wing" in self.free
        d["wings"] = {}
        for w in self.lifting_wings:
            span = dv(f"{w.name}.span", w.span_m, b.span[0] * w.span_m, b.span[1] * w.span_m, "m", w.span_m,
                      f"{w.name} span (area held at {w.area_m2} m^2)", wing_free)
            taper = dv(f"{w.name}.taper", w.taper, b.taper[0], b.taper[1], "-", 1.0, f"{w.name} taper ratio",
                       wing_free)
            tw0 = np.radians(np.asarray(w.twist_deg, float))
            twist = dv(f"{w.name}.twist", tw0, np.radians(b.twist_deg[0]), np.radians(b.twist_deg[1]), "rad",
                       0.05, f"{w.name} section twists at eta {list(w.section_eta)}", wing_free,
                       shape=len(tw0))
            d["wings"][w.name] = {"span": span, "taper": taper, "twist": twist}
        # --- rotor span positions (fraction of the semispan of their wing)
        eta0 = np.asarray(g.span_eta, float)
        d["eta"] = dv(f"{p}.span_eta", eta0, b.span_eta[0], b.span_eta[1], "-", 1.0,
                      "rotor span positions, fraction of the semispan", self.positions_free, shape=len(eta0))
        self.design = d

        # --- blade: Adkins-Liebeck as residuals, design-level unknowns
        atm_d = atmosphere(g.design_altitude_m)
        blade0 = self.baseline_blade()
        al_inputs = {"target": d["T_design"], "speed_mps": d["V_design"], "radius_m": d["R"],
                     "omega_radps": self.omega_design, "cl_design": d["cl_design"],
                     "rho_kgpm3": float(atm_d["density_kgpm3"]), "mu_Pas": float(atm_d["dynamic_viscosity_Pas"]),
                     "a_mps": float(atm_d["speed_of_sound_mps"]), "hub_fraction": g.hub_fraction,
                     "blades": g.blades}
        self.blade = add_adkins_liebeck(problem, f"{p}.blade", self.section, al_inputs,
                                        n_stations=self.n_stations, init=blade0)
        # tip Mach at the design point (Eq. 7: M_tip <= M_max), design rpm fixed per vehicle
        a_d = float(atm_d["speed_of_sound_mps"])
        tip2 = (self.omega_design * d["R"]) ** 2 + d["V_design"] ** 2
        if self.design_point_constraints:
            problem.constrain(f"{p} tip Mach", tip2 / (g.tip_mach_max * a_d) ** 2, kind="<=", rhs=1.0,
                              scale=1.0, unit="-", labels=[f"{p} design point"])
        self.tip_mach_design = ca.sqrt(tip2) / a_d
        problem.output(f"{p}.tip_mach_design", self.tip_mach_design, unit="-", summary=True)

        # --- geometry: wings, rotor placements, lattice, wakes
        self._build_geometry(problem, d)
        if self.design_point_constraints:
            self._no_overlap(problem, d)
        # --- gross weight
        md = MassDesign({w: v["span"] for w, v in d["wings"].items()},
                        {w: v["taper"] for w, v in d["wings"].items()}, {p: d["R"]})
        self.mass_design = md
        if self.mass_model == "buildup":
            togw = var("togw", 1, unit="kg", scale=self.togw_baseline_kg, lower=0.3 * self.togw_baseline_kg,
                       upper=3.0 * self.togw_baseline_kg, init=self.togw_baseline_kg,
                       description="take-off gross weight (mass build-up)")
            problem.constrain("mass build-up", togw - total_mass(cfg, togw, md), scale=self.togw_baseline_kg,
                              unit="kg", labels=["TOGW"])
            self.togw = togw
        else:
            self.togw = self.togw_baseline_kg
        problem.output("togw_kg", self.togw, unit="kg", summary=True)

    def _wing_surfaces(self, d, numeric: bool):
        """VLM surfaces from the design dict ``d`` (MX) or from the baseline (numeric)."""
        g = self.group
        surfaces, rotor_pos = [], []
        eta_r = d["eta"]
        R = d["R"]
        for w in self.lifting_wings:
            dw = d["wings"][w.name]
            span, taper, twist = dw["span"], dw["taper"], dw["twist"]
            semispan = span / 2
            breaks, nominal = [], []
            if w.name in g.wings and self.slipstream_breaks:
                for i in range(len(g.span_eta)):
                    e = eta_r[i]
                    lo = (e * semispan - R) / semispan
                    hi = (e * semispan + R) / semispan
                    e0 = float(g.span_eta[i])
                    lo0 = e0 - g.radius_m / (w.span_m / 2)
                    hi0 = e0 + g.radius_m / (w.span_m / 2)
                    # keep the moving slipstream edges inside the wing (smooth, width 0.01 semispan)
                    if lo0 > 0.02:
                        breaks.append(smooth_max(lo, 0.02, 0.01))
                        nominal.append(lo0)
                    if hi0 < 0.98:
                        breaks.append(smooth_min(hi, 0.98, 0.01))
                        nominal.append(hi0)
            twists = [twist[k] for k in range(len(w.twist_deg))]
            surf = constant_area(w.name, w.area_m2, span, taper, twists, eta=list(w.section_eta),
                                 airfoil=w.airfoil.lower().replace("_", ""), nspan=self.wing_strips,
                                 nchord=self.nchord, anchor_sections=False, breaks=breaks,
                                 break_nominal=nominal if nominal else None,
                                 origin=(w.root_le_x_m, 0.0, w.root_z_m), incidence=math.radians(w.incidence_deg),
                                 thickness_to_chord=w.thickness_to_chord)
            surfaces.append(surf)
            if w.name in g.wings:
                c_r = surf.root_chord
                for i in range(len(g.span_eta)):
                    e = eta_r[i]
                    # unswept quarter chord: the leading edge moves aft by (c_r - c(y))/4
                    x_le = w.root_le_x_m + 0.25 * c_r * (1 - taper) * e
                    y = e * semispan
                    rotor_pos.append((x_le - g.x_ahead_of_le_m, y, w.root_z_m - g.z_below_wing_m))
        for t in self.tails:
            surfaces.append(trapezoid(t.name, t.span_m, t.root_chord_m, t.taper,
                                      airfoil=t.airfoil.lower().replace("_", ""), nspan=self.tail_strips,
                                      nchord=self.nchord, origin=(t.root_le_x_m, 0.0, t.root_z_m),
                                      incidence=math.radians(t.incidence_deg),
                                      thickness_to_chord=t.thickness_to_chord))
        return surfaces, rotor_pos

    def _rotors(self, rotor_pos, R):
        g = self.group
        edges = WakeRotor.from_geometry(self.baseline_blade()["geometry"], (0.0, 0.0, 0.0),
                                        n_stations=self.n_stations).s_edges
        rotors = []
        for (x, y, z) in rotor_pos:
            for s in (1.0, -1.0):   # starboard, port
                ys = s * y
                center = ca.vertcat(x, ys, z) if any(isinstance(c, ca.MX) for c in (x, ys, z)) else (x, ys, z)
                rotors.append(WakeRotor(center, (1.0, 0.0, 0.0), R, edges, g.blades, spin_for(s, g.rotation)))
        return rotors

    def _build_geometry(self, problem, d):
        cfg = self.config
        S_ref = sum(w.area_m2 for w in self.lifting_wings)
        main = cfg.main_wing
        lift_velocity = "freestream" if self.coupling == "freestream" else "local"
        surfaces, rotor_pos = self._wing_surfaces(d, numeric=False)
        self.vlm = VLM(surfaces, S_ref=S_ref, c_ref=main.mean_aerodynamic_chord_m, b_ref=main.span_m,
                       r_ref=(main.root_le_x_m + 0.25 * main.mean_aerodynamic_chord_m, 0.0, main.root_z_m),
                       mach_ref=0.2, lift_velocity=lift_velocity)
        self.rotors = self._rotors(rotor_pos, d["R"])
        self.rotor_positions = rotor_pos
        self.influences = wake_influences(self.vlm.geometry["cp"], self.rotors, spans=self.vlm.geometry["lb"],
                                          samples=self.wake_samples)
        self.S_ref = S_ref
        # non-lifting bodies (Raymer build-up) and the fin
        f = cfg.fuselage
        d_eff = math.sqrt(f.width_m * f.height_m)
        self.bodies = [Body("fuselage", f.length_m, d_eff, "fuselage", 1.0, wetted_area=f.wetted_area_m2)]
        nac_area = cfg.mass_inputs.get("nacelle_wetted_area_m2", 0.0)
        if nac_area:
            # nacelle as a body of fineness 3 with the configured wetted area: pi d l = A, l = 3 d
            dn = math.sqrt(nac_area / (3 * math.pi))
            self.bodies.append(Body("nacelle", 3 * dn, dn, "nacelle", 1.3, count=self.group.count,
                                    wetted_area=nac_area))
        self.fins = [w for w in cfg.wings if w.vertical]
        problem.output("wing_aspect_ratio", d["wings"][main.name]["span"] ** 2 / main.area_m2, unit="-",
                       summary=True)

    def _no_overlap(self, problem, d):
        """Disks must not overlap each other or cross the symmetry plane (R <= R_max, Eq. 7)."""
        g, cl = self.group, self.bounds.tip_clearance_m
        for w in g.wings:
            span = d["wings"][w]["span"]
            y = [d["eta"][i] * span / 2 for i in range(len(g.span_eta))]
            gaps = [y[0] - d["R"] - 0.5 * cl]
            gaps += [y[i + 1] - y[i] - 2 * d["R"] - cl for i in range(len(y) - 1)]
            problem.constrain(f"{g.name} disk clearance ({w})", ca.vertcat(*gaps), kind=">=", scale=0.1,
                              unit="m", labels=[f"{w} inner disk to symmetry plane"]
                              + [f"{w} disks {i}-{i + 1}" for i in range(len(y) - 1)])

    # ------------------------------------------------------------------ protocol
    def unknowns(self):
        g, n, m = self.group, self.n_stations, self.n_azimuth
        pt = self.powertrain
        spec = pt.battery_current_unknown()
        return [
            Unknown(f"{g.name}.omega", unit="rad/s", scale=self.omega_design, lower=0.05 * self.omega_design,
                    upper=3.0 * self.omega_design, description="rotor speed (all rotors, equally throttled)"),
            Unknown(f"{g.name}.phi", unit="rad", scale=0.3, lower=PHI_MIN_RAD, upper=PHI_MAX_RAD, rows=n * m,
                    description="BEMT inflow angles (station fastest, then azimuth)"),
            Unknown(spec["name"], unit=spec["unit"], scale=spec["scale"], lower=spec["lower"], upper=spec["upper"],
                    description=spec["description"]),
        ]

    def states(self):
        return [State(**self.powertrain.soc_state())]

    def energy_used_J(self, initial, final):
        return self.powertrain.energy_used_J(initial["state_of_charge"], final["state_of_charge"])

    def rotor_axis_angle(self, wma):
        """Angle of the thrust axis above the body x axis: the wing-mounted angle (TTW) or 0."""
        tilting = any(self.config.wing(w).tilting for w in self.group.wings)
        return wma if tilting else 0.0 * wma

    def evaluate(self, nodes, unknowns) -> NodeEvaluation:
        if self._problem is None:
            raise RuntimeError("Aircraft.evaluate before setup(problem)")
        d, g = self.design, self.group
        K = nodes.size
        h = _num(nodes.altitude_m).ravel()
        atm = atmosphere(h)
        rho, mu, a_s = (_row(atm[k]) for k in ("density_kgpm3", "dynamic_viscosity_Pas", "speed_of_sound_mps"))
        V = nodes.speed_mps
        gam = nodes.flight_path_angle_rad
        theta = nodes.body_angle_rad
        alpha = theta - gam
        wma = nodes.parameters.get("wing_mounted_angle_rad", _row(0.0, K))
        pitch = nodes.parameters.get("pitch_command_rad", _row(0.0, K))
        a_rot = alpha + self.rotor_axis_angle(wma)
        v_ax = V * ca.cos(a_rot)
        v_ip = V * ca.sin(a_rot)
        omega = unknowns[f"{g.name}.omega"]
        phi = unknowns[f"{g.name}.phi"]
        ib = unknowns["battery_current_A"]
        # --- rotors (one BEMT, all rotors of the group alike)
        bm, extra_res = self._bemt_nodes(K, _num(wma).ravel(), d, pitch, omega, v_ax, v_ip, rho, mu, a_s, phi)
        n_rot = g.count
        T1, Q1, H1 = bm["thrust_N"], bm["torque_Nm"], bm["hforce_N"]
        # --- wake at the wing and the lattice
        v_w = v_ax + bm["va_mean_mps"]
        gam_r = [bm["gamma_m2ps"]] * len(self.rotors)
        om_r = [omega] * len(self.rotors)
        vw_r = [v_w] * len(self.rotors)
        # the whole wake in the flow tangency; without its axial part in the forces ("swirl")
        v_axial, v_rest = influence_sum_parts(self.influences, gam_r, om_r, vw_r)
        v_cp = tuple(a + r for a, r in zip(v_axial, v_rest))
        v_b = v_rest if self.coupling == "swirl" else None
        mach = V / a_s
        wing_alpha = alpha + wma if self.config.kind == "tilt_wing" else alpha
        r = self.vlm.solve(wing_alpha, V, rho=rho, mach=mach, v_ext=v_cp, v_ext_bound=v_b)
        # --- drag build-up
        pd = profile_drag(self.vlm, r, rho, mu, mach)
        L_stall, D_stall = self.stall_correction(self.vlm, r, pd, rho, V) if self.wing_stall else (0.0, 0.0)
        D_bodies, _ = body_drag(self.bodies, V, rho, mu, mach)
        D_fin = 0.0
        q = 0.5 * rho * V * V
        for f in self.fins:
            re = rho * V * f.mean_aerodynamic_chord_m / mu
            cf = skin_friction(ca.sqrt(re * re + 1e8), mach)
            ff = form_factor_wing(f.thickness_to_chord, mach=ca.sqrt(mach * mach + 1e-4),
                                  sweep_max_thickness=math.radians(f.sweep_quarter_chord_deg))
            D_fin = D_fin + q * cf * ff * 2.04 * f.area_m2
        D_device, deploy = self._drag_device(nodes, q)
        D_parasite = (pd["D_p"] + D_stall + D_bodies + D_fin) * (1.0 + self.misc_drag_fraction) + D_device
        D = r["D_i"] + D_parasite
        L = r["L"] + L_stall
        # --- forces in the path frame (x along the velocity, z normal)
        ca_r, sa_r = ca.cos(a_rot), ca.sin(a_rot)
        F_t = -D + n_rot * (T1 * ca_r - H1 * sa_r)
        F_n = L + n_rot * (T1 * sa_r + H1 * ca_r)
        # --- powertrain
        soc = nodes.states["state_of_charge"]
        pt = self.powertrain
        po = pt.evaluate(Q1, omega, soc, ib)
        residuals = [ResidualGroup("power balance", po["power_balance_W"], scale=pt.power_scale_W, unit="W")]
        if extra_res is None:
            residuals.insert(0, ResidualGroup(
                f"{g.name} BEMT", bm["residual"], scale=1.0, unit="-",
                row_labels=[f"r{i} psi{j}" for j in range(self.n_azimuth) for i in range(self.n_stations)]))
        else:   # azimuth-averaged and axial nodes have different row counts: added directly, own labels
            for name, expr, cols, rows in extra_res:
                labels = [f"{nodes.labels[k]} {r}" for k in cols for r in rows]
                self._problem.constrain(f"{g.name} {name}", expr, scale=1.0, unit="-", labels=labels)
        if self.powertrain_limits:
            for lim in pt.limits(po):
                residuals.append(ResidualGroup(lim["name"], lim["expr"] - lim["rhs"], scale=lim["scale"],
                                               unit=lim["unit"], kind=lim["kind"]))
        tip_mach = ca.sqrt((omega * d["R"]) ** 2 + V * V) / a_s
        P_shaft = n_rot * Q1 * omega
        out = {
            "CL": Output(r["CL"], "-", "lift coefficient on S_ref"),
            "CD": Output(D / (q * self.S_ref + 1e-9), "-", "drag coefficient on S_ref"),
            "CDi": Output(r["CDi"], "-", "induced drag coefficient (Trefftz plane)"),
            "lift_N": Output(L, "N"), "drag_N": Output(D, "N"),
            "induced_drag_N": Output(r["D_i"], "N"), "parasite_drag_N": Output(D_parasite, "N"),
            "drag_device_drag_N": Output(D_device, "N", "gear/flap drag deployed on approach (in parasite)"),
            "drag_device_deployment": Output(deploy, "-", "fraction of the segment's drag_device_area_m2"),
            "angle_of_attack_deg": Output(alpha / u.DEG, "deg"),
            "thrust_N": Output(n_rot * T1, "N", "total thrust"),
            "thrust_power_W": Output(n_rot * (T1 * ca_r - H1 * sa_r) * V, "W",
                                     "rotor force along the path times speed (useful propulsive power)"),
            "rotor_speed_rpm": Output(omega / u.RPM, "rpm"),
            "tip_mach": Output(tip_mach, "-"),
            "shaft_power_W": Output(P_shaft, "W", "total shaft power"),
            "propulsive_efficiency": Output(n_rot * T1 * v_ax / (P_shaft + 1e-9), "-"),
            "battery_power_W": Output(po["chemical_power_W"], "W", "chemical power drawn from the cells"),
            "terminal_power_W": Output(po["battery_power_W"], "W"),
            "state_of_charge": Output(soc, "-"),
            "throttle": Output(po["throttle"], "-"),
            "cell_current_A": Output(po["cell_current_A"], "A"),
            "motor_efficiency": Output(po["motor_efficiency"], "-"),
        }
        self._last = {"vlm": r, "bemt": bm, "powertrain": po}
        return NodeEvaluation(mass_kg=self.togw, force_along_path_N=F_t, force_normal_N=F_n, residuals=residuals,
                              force_scale_N=self.togw_baseline_kg * G0,
                              state_derivatives={"state_of_charge": po["soc_rate_per_s"]}, outputs=out)

    def _drag_device(self, nodes, q):
        """Gear/flap drag where the segment allows it (``drag_device_area_m2`` > 0):
        ``D = q A_max delta`` with the deployment ``delta`` in [0, 1] a control of those
        nodes only (elsewhere it would be a free variable with no effect).  Its lift
        change is neglected.  Returns (drag row, deployment row)."""
        K = nodes.size
        area = _num(nodes.parameters.get("drag_device_area_m2", _row(0.0, K))).ravel()
        active = np.flatnonzero(area > 0.0)
        if active.size == 0:
            return 0.0 * q, ca.DM.zeros(1, K)
        delta = self._problem.variable(
            "drag_device_deployment", (1, active.size), unit="-", scale=1.0, lower=0.0, upper=1.0, init=0.0,
            description="gear/flap deployment on approach (fraction of drag_device_area_m2)",
            labels=[nodes.labels[k] for k in active])
        spread = ca.DM.triplet(list(range(active.size)), [int(k) for k in active], ca.DM.ones(active.size),
                               active.size, K)
        deploy = ca.densify(ca.mtimes(delta, spread))
        return q * _row(area) * deploy, deploy

    def stall_limits(self, airfoil: str) -> tuple:
        """(alpha0, lift slope, cl_min, cl_max) of a section at Re 1e6 (numbers, cached)."""
        cache = self.__dict__.setdefault("_stall_cache", {})
        if airfoil not in cache:
            from ..airfoil import Airfoil
            af = Airfoil.from_name(airfoil)
            a = np.radians(np.linspace(-30.0, 30.0, 601))
            cl = np.asarray(af.cl(a, 1e6), float).ravel()
            cache[airfoil] = (af, float(af.alpha0_rad), float(af.lift_slope_per_rad), float(cl[a < 0].min()),
                              float(cl[a > 0].max()))
        return cache[airfoil]

    def stall_correction(self, vlm, r, pd, rho, V, width: float = 0.1):
        """Lift and drag corrections (N, 1 x K) of strips past stall.

        The lattice is linear: a strip at sectional cl beyond the section's cl_max
        (or below cl_min) is read as a section at the equivalent attached angle
        ``alpha_e = alpha_0 + cl/a`` (a: the section's lift slope) and given the
        full-circle section coefficients there (``mdo.airfoil``: AERODAS/flat-plate
        post-stall).  The switch is a logistic weight of width 0.1 in cl, so the
        lattice is untouched below stall; in transition (the tilt-wing at 45 deg)
        the wing then loses lift and gains pressure drag as a real wing does, instead
        of the lattice's unbounded linear lift.
        """
        g = vlm.geometry
        cl_loc = r["cl_local"]
        K = cl_loc.shape[1]
        Vl = r["V_local"]
        c = g["strip_chord"].T
        w = g["strip_width"].T
        dL = 0.0
        dD = 0.0
        names = [str(a) for a in vlm.strip_airfoil]
        for name in sorted(set(names)):
            if name == "None":
                continue
            idx = [i for i, a in enumerate(names) if a == name]
            af, a0, slope, cl_min, cl_max = self.stall_limits(name)
            cl_i = cl_loc[idx, :]
            alpha_e = a0 + cl_i / slope
            cl_af, cd_af, _ = af.coefficients(alpha_e, pd["Re"][idx, :])
            wgt = 0.5 * (1 + ca.tanh(0.5 * (cl_i - cl_max) / width)) + 0.5 * (1 + ca.tanh(0.5 * (cl_min - cl_i) / width))
            q_loc = 0.5 * ca.repmat(rho, len(idx), 1) * Vl[idx, :] ** 2
            area = ca.repmat(c[idx] * w[idx], 1, K)
            dL = dL + ca.mtimes(ca.DM.ones(1, len(idx)), wgt * (cl_af - cl_i) * q_loc * area)
            dD = dD + ca.mtimes(ca.DM.ones(1, len(idx)), wgt * (cd_af - pd["cd"][idx, :]) * q_loc * area)
        factor = 2.0 if vlm.symmetric else 1.0
        return factor * dL, factor * dD

    def transition_nodes(self, wma) -> np.ndarray:
        """Nodes whose rotors see in-plane flow worth azimuth averaging: a tilted wing
        between cruise (0) and hover (90 deg).  Elsewhere the inflow is axial."""
        wma = np.asarray(wma, float).ravel()
        if self.n_azimuth == 1:
            return np.zeros(wma.size, bool)
        tilt_deg = np.degrees(wma)
        return (np.abs(tilt_deg) > 1.0) & (np.abs(tilt_deg - 90.0) > 1.0)

    def _bemt_nodes(self, K, wma, d, pitch, omega, v_ax, v_ip, rho, mu, a_s, phi):
        """BEMT outputs at all K nodes: azimuth-averaged where the rotors are tilted in
        forward flight, axial elsewhere (the unused azimuth rows of phi then copy the
        axial ones, so that every unknown has an equation)."""
        g, n, m = self.group, self.n_stations, self.n_azimuth
        common = dict(radius_m=d["R"], hub_fraction=g.hub_fraction, blades=g.blades,
                      chord_m=self.blade["chord_m"], twist_rad=self.blade["twist_rad"], spin=1.0)
        per = dict(pitch_rad=pitch, omega_radps=omega, v_axial_mps=v_ax, v_inplane_mps=v_ip, rho_kgpm3=rho,
                   mu_Pas=mu, a_mps=a_s)
        mask = self.transition_nodes(wma)
        if m == 1 or mask.all():
            return self.bemt.map(K)(**common, **per, phi_rad=phi), None
        it, ia = np.flatnonzero(mask), np.flatnonzero(~mask)
        axial = bemt_function(self.section, n, 1, outputs="nlp")
        pieces = []
        if it.size:
            pieces.append((it, self.bemt.map(it.size)(**common, **{k: _cols(v, it, K) for k, v in per.items()},
                                                         phi_rad=phi[:, list(it)])))
        pa = phi[:n, list(ia)]
        pieces.append((ia, axial.map(ia.size)(**common, **{k: _cols(v, ia, K) for k, v in per.items()},
                                             phi_rad=pa)))
        order = np.concatenate([p[0] for p in pieces])
        # column j of the stacked blocks is node order[j]: perm[j, order[j]] = 1 puts it back
        perm = ca.DM.triplet(list(range(K)), [int(o) for o in order], ca.DM.ones(K), K, K)
        out = {}
        for key in pieces[0][1].keys():
            if key == "residual":
                continue
            out[key] = ca.mtimes(ca.horzcat(*[p[1][key] for p in pieces]), perm)
        rows_m = [f"r{i} psi{j}" for j in range(m) for i in range(n)]
        groups = []
        if it.size:
            groups.append(("BEMT (azimuth-averaged)", pieces[0][1]["residual"], it, rows_m))
        groups.append(("BEMT (axial)", pieces[-1][1]["residual"], ia, rows_m[:n]))
        # unused azimuth rows at the axial nodes follow the axial solution
        groups.append(("BEMT azimuth copies", phi[n:, list(ia)] - ca.repmat(pa, m - 1, 1), ia, rows_m[n:]))
        return out, groups

    # ------------------------------------------------------------------ guesses
    def initial_guess(self, nodes) -> dict:
        """Physics-based guesses at the baseline design (:mod:`mdo.vehicle.guess`)."""
        from .guess import initial_guess
        return initial_guess(self, nodes)
