"""Any propeller-driven aircraft as a mission vehicle: every discipline at every node.

``Aircraft(config)`` implements the vehicle protocol of ``mdo.vehicle.base`` for a
:class:`~mdo.vehicle.config.VehicleConfig` - the paper's GA-2P, GA-8P and TTW are
data like any other.  Everything is read from the definition (wing roles, rotor
groups with their motors, battery, fuselage, nacelles); nothing depends on a name.
At setup it adds the design variables of Eq. 7 (Adkins-Liebeck inputs and span
positions per rotor group, wing span, taper and section twists at constant
reference area), the motor ratings (sized) and the gross weight, and builds the
design-dependent parts once:

* the blades: Adkins-Liebeck solved inside the graph (``adkins_liebeck_implicit``: a
  Newton rootfinder with implicit-function derivatives, no blade unknowns), giving chord
  and twist at the BEMT stations (``mdo.rotor``);
* the lifting surfaces: a symmetric vortex lattice whose influence matrix depends
  on span, taper, twists and slipstream edges only (``mdo.wing``);
* the propeller wakes: the blade-passage-averaged wake's influence at the wing's
  control points, per rotor (``mdo.wake``);
* the mass build-up residual ``TOGW = sum(terms(TOGW, design))`` (``mass.py``), each lifting
  wing's spar caps and webs sized for strength and stiffness (``wing_structure.py``).

At the mission's K nodes (``evaluate``), with the body angle, rotor speed, BEMT
inflow angles and pack current as unknowns:

1. atmosphere at the node altitude; rotor inflow from speed, angle of attack and
   the wing-mounted angle (axial ``V cos(a)``, in-plane ``V sin(a)``, ``a = alpha + WMA``);
2. BEMT residuals and loads (one SX Function mapped over the nodes); the loads (thrust,
   torque, in-plane force, circulation, mean induced velocity, swirl power) are lifted:
   node variables with an equality to their BEMT sums, so the Hessian stays sparse;
3. wake velocity at the wing = sum over rotors of influence x (Gamma, Omega/V_w);
4. one vortex-lattice solve for all nodes: ``A(d) [G_1..G_K] = [b_1..b_K]``, with the
   wake in the flow tangency and the "swirl" force coupling (``mdo.wake`` README);
5. drag build-up: strip profile drag, fuselage, nacelles, fin;
6. powertrain (``mdo.powertrain.Bus``): each group's motors and ESCs on one pack,
   the pack current balance, state-of-charge rate;
7. forces in the path frame: lift, drag, thrust and in-plane rotor force along the
   tilted rotor axis;
8. the operating limits (``aircraft_nodes.operating_limits``), each a named
   inequality group at every node (on by
   default): motor power, torque and speed, throttle, tip Mach (``rotor_group``),
   cell current and voltage, no battery charging unless allowed, the wing's stall
   margin (``stall``), an airplane's rudder against a failed motor's yaw (``engine_out``),
   and the state of charge left at the end (``final_limits``).

Swirl recovery: with the "swirl" coupling the wing's bound vortices see the
slipstreams' swirl, and the Kutta-Joukowski force along the flight path is a
thrust (negative near-field drag).  That credit is bounded by the rotational
kinetic-energy flux the slipstreams carry (``RotorGroupModel.swirl_power_W``):
the credited power is ``smooth_min(P_recovered, P_available)`` (width 2 % of the
available power + 10 W), so no node gains more from the swirl than is there; both
are outputs (``swirl_recovered_power_W``, ``swirl_available_power_W``).  The bound holds
in every coupling: with "local" (slipstream dynamic pressure in the wing forces) the
near-field thrust of the blown strips is the same kind of credit and, unbounded, an
optimizer windmills the rotors to harvest it (X-57 Mod IV: 77 kW "recovered" on final
approach from slipstreams carrying 0.2 kW of swirl).

Frames: the mission's path frame (x forward, z up); the wing and wake use body
axes with x aft, y starboard, z up (``mdo.wing``).

Layout: this file holds ``Aircraft`` (its ``DesignBounds`` are in ``config.py``) in sections - design (the design
variables, mass, wing design lifts), protocol (unknowns, states, ``evaluate`` and its rotor
and aerodynamic parts), guesses.
Beside it: ``aircraft_geometry.py`` (lattice surfaces, rotors, wakes, strip layout, bodies,
disk and fuselage clearance), ``viscous_wing.py`` (the strips on their section polars),
``aircraft_tilt.py`` (a tilt-wing's wing-mounted angle: schedule or control),
``aircraft_nodes.py`` (the operating limits and ``mission.csv`` outputs at the
nodes), ``aircraft_drag.py`` (the parasite drag build-up, flaps, drag device),
``rotor_group.py`` (one rotor group's design and BEMT), ``balance.py`` (pitch trim),
``guess.py`` (initial guesses), ``mass.py`` and ``wing_structure.py`` (the mass build-up).
"""
from __future__ import annotations


import casadi as ca
import numpy as np

from ..core.atmosphere import atmosphere
from ..core.errors import InputError
from ..core.smooth import smooth_min
from ..powertrain import Bus
from ..wake import DEFAULT_CORE_REL, DEFAULT_STRIP_SAMPLES, influence_sum_parts
from ..wake.mean import checked_table_core
from .aircraft_drag import AirframeDragMixin
from .aircraft_geometry import AircraftGeometryMixin
from .aircraft_tilt import WingTiltMixin
from .aircraft_nodes import _num, _row, node_outputs, operating_limits, wing_design_lift_rows
from .balance import add_balance, trim_residuals, trim_unknowns, trim_upwash
from .base import G0, NodeEvaluation, Output, ResidualGroup, State, Unknown
from .config import DesignBounds, VehicleConfig, WingConfig  # noqa: F401 (DesignBounds re-exported)
from .engine_out import add_fin_design, engine_out_option
from .mass import MassDesign, solve_togw, total_mass
from .rotor_group import RotorGroupModel
from .stall_pattern import add_stall_pattern
from .viscous_wing import viscous_rows, viscous_unknowns, viscous_upwash

__all__ = ["Aircraft", "DesignBounds"]


class Aircraft(AircraftGeometryMixin, AirframeDragMixin, WingTiltMixin):
    """A :class:`VehicleConfig` flying a mission (see the module docstring).

    Parameters
    ----------
    config : VehicleConfig
    free : which design variables the optimizer may move: any of ``"rotor"`` (the
        Adkins-Liebeck inputs), ``"wing"`` (span, taper, twists of every lifting
        wing), ``"positions"`` (rotor span positions).  All are created as design
        variables either way (``--analysis`` freezes them); the others are fixed.
        Motor ratings are sized in every stage (``MotorConfig.sized``).
    n_stations : BEMT stations per blade.  ``n_azimuth``: azimuth positions for the
        rotors of tilting wings in transition (default 4 for a tilt-wing).
    wing_strips, tail_strips, nchord : lattice size (strips per semispan, chordwise panels).
    coupling : ``"swirl"`` (default; see mdo/wake/README.md), ``"freestream"`` or ``"local"``.
    mass_model : ``"buildup"`` (gross weight follows the design) or ``"fixed"``.
    limits : the operating limits at every node (module docstring); on by default.
    tip_mach_limit : ``"nodes"`` (every node, default), ``"design_point"`` (the
        Adkins-Liebeck point only) or ``"off"``; with ``design_point_constraints=False``
        (the analysis of a frozen design that violates them) only reported.
    stall_margin_cl : the default cl margin of the stall limit (S1 of ``stall``); a
        segment parameter ``stall_margin_cl`` overrides it (negative: off there).
    allow_regeneration : let windmilling charge the battery (default off: pack current >= 0).
    swirl_recovery : ``"bounded"`` (default) or ``"unbounded"`` (the near-field credit as is).
    max_span_m : a hangar/gate limit on every lifting wing's span (None: none).
    wake_samples : points across each lattice strip over which the propeller wake is
        averaged (``mdo.wake.DEFAULT_STRIP_SAMPLES``, 7; 1 = at the control point, which
        makes the energy ripple with the rotor position, see mdo/README.md).
    wake_core_rel : the wake filaments' core radius / the radius of their helix
        (``mdo.wake.DEFAULT_CORE_REL``, 0.1; tables ship for 0.05 and 0.1): the width over
        which the averaged slipstream's edge rises.  It must exceed the spacing of the wake
        samples across a strip, or the energy ripples with the rotor position (mdo/README.md).
    pitch : ``"control"`` (variable-pitch groups fly their collective as a control) or
        ``"schedule"`` (the segments' ``pitch_command_rad``).
    tilt : ``"schedule"`` (default: the segments' ``wing_mounted_angle_rad``, Table 5) or
        ``"control"``: a tilt-wing's wing-mounted angle is a control (``wing_tilt``) at
        every node of the segments with ``wing_tilt_control`` > 0 (the eVTOL profile's
        transitions), within the tilting wings' ``tilt_range_deg``, at most their
        ``max_tilt_rate_degps``, continuous with the prescribed angle of the neighbouring
        segments; its rotors there are azimuth-averaged whatever the angle.
    trim : pitch trim about the centre of gravity at every node of the segments with
        ``pitch_trim`` > 0 (default all), the incidence of each all-moving surface
        (``WingConfig.trim_incidence_range_deg``) a control there, the CG a design variable
        held by the static margin (:mod:`mdo.vehicle.balance`); on by default, and inert
        for a vehicle without such a surface (reported as untrimmed).
    wing_viscous : every lattice strip's lift on its section polar at every node
        (:mod:`mdo.vehicle.viscous_wing`: an angle shift per strip and node, solved with the
        mission), so the stall margin reads the section's cl_max; default on for airplanes, off
        for a tilt-wing.  With ``wing_stall`` as well (a tilt-wing asked for it), the one-pass
        post-stall strips apply at the nodes of segments that are not wing-borne (negative
        ``stall_margin_cl``: the transitions) and the correction at every other node.
    fin_sizing : each fin's area a design variable (``<fin>.area_scale``, 1 to 3 times its
        configured area, aspect ratio, taper and sweep held; free with the wing), its rudder's
        moment (``engine_out``), skin-friction drag and mass (Raymer Eq. 15.48) following it.
        The configured fin is the floor: directional stability is not modelled.  Default off.
    engine_out : ``"rudder"`` (default for airplanes): at every wing-borne node the fins' rudder
        holds the yaw of each outboard motor's mirror at take-off power with that motor failed
        (:mod:`mdo.vehicle.engine_out`); ``"off"`` (default for a tilt-wing).  A property of the
        design: with ``design_point_constraints=False`` (the analysis of a frozen design) it is
        reported in ``mission.csv``, not enforced (a baseline beyond the rudder still flies).
    blown_profile_drag : the strips' profile drag at the dynamic pressure of the whole wake at
        their control points (the slipstream's axial part included: a blown strip is scrubbed at
        the slipstream's speed); on by default.  Off, the strips read the lattice's local velocity,
        which with the "swirl" coupling leaves the axial part out (about freestream q).
    Segments may set ``drag_device_area_m2`` (gear/flap drag on approach, a control),
    ``flap_deflection`` (0-1, raises the stall limit of flapped strips) and
    ``<group>.active`` (0: that rotor group stopped/folded there).
    """

    def __init__(self, config: VehicleConfig, *, free=("rotor", "wing", "positions"), n_stations: int = 16,
                 n_azimuth: int | None = None, wing_strips: int = 20, tail_strips: int = 6, nchord: int = 1,
                 coupling: str = "swirl", mass_model: str = "buildup", limits: bool = True,
                 tip_mach_limit: str = "nodes", stall_margin_cl: float = 0.1, allow_regeneration: bool = False,
                 swirl_recovery: str = "bounded", max_span_m: float | None = None,
                 bounds: DesignBounds | None = None,
                 positions_free: bool | None = None, design_point_constraints: bool = True,
                 wing_stall: bool | None = None, slipstream_breaks: bool = False, wake_samples: int = DEFAULT_STRIP_SAMPLES,
                 wake_core_rel: float = DEFAULT_CORE_REL,
                 pitch: str = "control", tilt: str = "schedule", trim: bool = True, wing_viscous: bool | None = None,
                 blown_profile_drag: bool = True, engine_out: str | None = None, fin_sizing: bool = False):
        self._check_options(config, free, coupling, mass_model, tip_mach_limit, swirl_recovery, wake_samples,
                            stall_margin_cl, max_span_m, pitch, tilt, trim)
        self.engine_out = engine_out_option(config, engine_out)
        # each fin's area a design variable (x1 to x3 of its own, aspect ratio and sweep held): its
        # rudder's moment, drag and mass follow it; the baseline fin's directional stability is the floor
        self.fin_sizing = bool(fin_sizing)
        self.config = config
        self.name = config.name
        self.free = set(free)
        self.n_stations = int(n_stations)
        self.n_azimuth = int(n_azimuth or (4 if config.kind == "tilt_wing" else 1))
        self.wing_strips, self.tail_strips, self.nchord = int(wing_strips), int(tail_strips), int(nchord)
        self.coupling = coupling
        self.mass_model = mass_model
        self.limits_on = bool(limits)
        self.tip_mach_limit = tip_mach_limit
        self.stall_margin_cl = float(stall_margin_cl)
        self.allow_regeneration = bool(allow_regeneration)
        self.swirl_recovery = swirl_recovery
        self.max_span_m = None if max_span_m is None else float(max_span_m)
        # strips on their section polars (mdo.vehicle.viscous_wing), or the linear lattice with the
        # one-pass post-stall strips of a tilt-wing's transitions
        # on by default for airplanes; a tilt-wing's transitions keep the one-pass post-stall strips
        # (their wing flies far past stall, where the correction's equations have several roots)
        if wing_viscous is None:
            wing_viscous = config.kind != "tilt_wing" and not wing_stall
        self.wing_viscous = bool(wing_viscous)
        # the strips' profile drag at the local dynamic pressure with the slipstream's axial part too
        # (with the "swirl" coupling the lattice's local velocity leaves it out; that stays for the lift)
        self.blown_profile_drag = bool(blown_profile_drag)
        # with both, the post-stall strips apply where the segment is not wing-borne (a negative
        # stall margin: a tilt-wing's transitions) and the viscous correction everywhere else
        self.wing_stall = (config.kind == "tilt_wing") if wing_stall is None else bool(wing_stall)
        self.slipstream_breaks = bool(slipstream_breaks)
        # wake velocity averaged over this many points across each strip (1: at the
        # control point; see the class docstring and tests/bench/position_sweep.py)
        self.wake_samples = int(wake_samples)
        self.wake_core_rel = checked_table_core(wake_core_rel, "wake_core_rel")
        # design-point tip Mach and disk clearance; off for the analysis of a design that violates them (GA-8P)
        self.design_point_constraints = bool(design_point_constraints)
        self.bounds = bounds or DesignBounds()
        # variable-pitch groups fly their collective as a control at every node ("control"),
        # or the segments' pitch_command_rad (the paper's Table 5 schedule, "schedule")
        self.pitch = pitch
        self.tilt = tilt
        self.groups = [RotorGroupModel(g, config.kind, any(config.wing(w).tilting for w in g.wings),
                                       n_stations=self.n_stations, n_azimuth=self.n_azimuth,
                                       pitch_control=(pitch == "control"))
                       for g in config.rotor_groups]
        self.parameters = {"wing_mounted_angle_rad": 0.0, "pitch_command_rad": 0.0, "drag_device_area_m2": 0.0,
                           "stall_margin_cl": self.stall_margin_cl, "flap_deflection": 0.0,
                           "wing_tilt_control": 0.0, "pitch_trim": 1.0}
        self.parameters.update({f"{g.name}.active": 1.0 for g in self.groups})
        # pitch trim about the CG with the all-moving surfaces as controls (mdo.vehicle.balance)
        self.trim_surfaces = list(config.trim_surfaces) if trim else []
        self.pack = config.battery.pack()
        self._problem = None
        self.togw_baseline_kg = solve_togw(config)
        self.positions_free = ("positions" in self.free) if positions_free is None else bool(positions_free)

    @staticmethod
    def _check_options(config, free, coupling, mass_model, tip_mach_limit, swirl_recovery, wake_samples,
                       stall_margin_cl, max_span_m, pitch="control", tilt="schedule", trim=True):
        if not isinstance(config, VehicleConfig):
            raise InputError("config", f"a VehicleConfig, got {type(config).__name__}")
        choices = {"coupling": (coupling, ("swirl", "freestream", "local")),
                   "mass_model": (mass_model, ("buildup", "fixed")),
                   "tip_mach_limit": (tip_mach_limit, ("nodes", "design_point", "off")),
                   "swirl_recovery": (swirl_recovery, ("bounded", "unbounded")),
                   "pitch": (pitch, ("control", "schedule")),
                   "tilt": (tilt, ("schedule", "control"))}
        for field_name, (value, allowed) in choices.items():
            if value not in allowed:
                raise InputError(field_name, f"one of {', '.join(map(repr, allowed))}, got {value!r}")
        unknown_free = set(free) - {"rotor", "wing", "positions"}
        if unknown_free:
            raise InputError("free", f"unknown design groups {sorted(unknown_free)}; allowed rotor, wing, positions")
        if int(wake_samples) != wake_samples or int(wake_samples) < 1:
            raise InputError("wake_samples", f"an integer >= 1, got {wake_samples!r}")
        if not (-1.0 <= float(stall_margin_cl) <= 1.0):
            raise InputError("stall_margin_cl", f"in [-1, 1], got {stall_margin_cl!r}")
        if max_span_m is not None and not (0.5 <= float(max_span_m) <= 100.0):
            raise InputError("max_span_m", f"in [0.5, 100] m, got {max_span_m!r}")
        if tilt == "control" and not any(w.tilting for w in config.wings):
            raise InputError("tilt", "'control' needs a wing with tilting=True (a tilt-wing)")

    # ------------------------------------------------------------------ compatibility views
    @property
    def group(self):
        """The first rotor group's definition (single-group vehicles)."""
        return self.config.rotor_groups[0]

    @property
    def lifting_wings(self) -> list[WingConfig]:
        return self.config.lifting_wings

    @property
    def tails(self) -> list[WingConfig]:
        return self.config.horizontal_tails

    @property
    def omega_design(self) -> float:
        return self.groups[0].omega_design

    @property
    def section(self):
        return self.groups[0].section

    def baseline_blade(self) -> dict:
        return self.groups[0].baseline_blade()

    def transition_nodes(self, wma) -> np.ndarray:
        return self.groups[0].transition_nodes(wma)

    # ------------------------------------------------------------------ design
    def setup(self, problem) -> None:
        if self._problem is problem:
            return
        self._problem = problem
        b = self.bounds
        dtp = self.design_point_constraints and self.tip_mach_limit != "off"
        for gm in self.groups:
            gm.add_design(problem, b, rotor_free="rotor" in self.free, positions_free=self.positions_free,
                          design_point_constraint=dtp, stall_margin_cl=self.stall_margin_cl)
        self.design = {"wings": self._wing_design(problem)}
        self.fin_area_scale = add_fin_design(self, problem)
        first = self.groups[0].design
        self.design.update({k: first[k] for k in ("T_design", "V_design", "R", "cl_design", "eta", "P_rated")})
        self.blade = self.groups[0].blade
        self.tip_mach_design = self.groups[0].tip_mach_design
        self._build_geometry(problem)
        if self.design_point_constraints:
            self._no_overlap(problem)
        add_stall_pattern(self, problem)     # the ailerons fly at stall onset (holds taper)
        if self.trim_surfaces:
            add_balance(self, problem)
        self.bus = Bus(self.pack, [gm.motor_group(self.pack) for gm in self.groups],
                       aux_power_W=self.config.aux_power_W)
        self.powertrain = self.bus
        self._add_mass(problem)

    def _wing_design(self, problem) -> dict:
        """Span, taper, section twists at constant area (Fig. 12) per lifting wing."""
        b, free = self.bounds, "wing" in self.free
        out = {}
        for w in self.lifting_wings:
            hi = b.span[1] * w.span_m if self.max_span_m is None else min(b.span[1] * w.span_m, self.max_span_m)
            if hi < w.span_m:
                raise InputError("max_span_m", f"{self.max_span_m} m is below {w.name}'s baseline span {w.span_m} m")

            def dv(name, init, lo, up, unit, scale, desc, shape=1):
                lo, up = (lo, up) if free else (init, init)
                return problem.variable(name, shape, unit=unit, scale=scale, lower=lo, upper=up, init=init,
                                        design=True, description=desc)
            tw0 = np.radians(np.asarray(w.twist_deg, float))
            out[w.name] = {
                "span": dv(f"{w.name}.span", w.span_m, b.span[0] * w.span_m, hi, "m", w.span_m,
                           f"{w.name} span (area held at {w.area_m2} m^2)"),
                "taper": dv(f"{w.name}.taper", w.taper, b.taper[0], b.taper[1], "-", 1.0, f"{w.name} taper ratio"),
                "twist": dv(f"{w.name}.twist", tw0, np.radians(b.twist_deg[0]), np.radians(b.twist_deg[1]), "rad",
                            0.05, f"{w.name} section twists at eta {list(w.section_eta)}", shape=len(tw0))}
        return out

    def _add_mass(self, problem):
        d = self.design
        md = MassDesign({w: v["span"] for w, v in d["wings"].items()},
                        {w: v["taper"] for w, v in d["wings"].items()},
                        {gm.name: gm.design["R"] for gm in self.groups},
                        {gm.name: gm.design["P_rated"] for gm in self.groups},
                        {gm.name: gm.design["omega_rated"] for gm in self.groups},
                        wing_design_lift_N=self._wing_design_lifts(problem),
                        rotor_span_eta={gm.name: gm.design["eta"] for gm in self.groups},
                        fin_area_scale=self.fin_area_scale)
        self.mass_design = md
        if self.mass_model == "buildup":
            W0 = self.togw_baseline_kg
            togw = problem.variable("togw", 1, unit="kg", scale=W0, lower=0.3 * W0, upper=3.0 * W0, init=W0,
                                    description="take-off gross weight (mass build-up)")
            problem.constrain("mass build-up", togw - total_mass(self.config, togw, md), scale=W0, unit="kg",
                              labels=["TOGW"])
            self.togw = togw
        else:
            self.togw = self.togw_baseline_kg
        problem.output("togw_kg", self.togw, unit="kg", summary=True)
        problem.output("battery_mass_kg", self.config.battery.mass_kg, unit="kg", summary=True)

    def _wing_design_lifts(self, problem) -> dict | None:
        """With a ``WingStructure``: each lifting wing's 1 g design lift (N), sized in every
        stage like the motor ratings - at least the wing's lift at every node ("<wing> design
        lift"); its bending material follows it (``mdo.vehicle.wing_structure``)."""
        if self.config.wing_structure is None or self.mass_model != "buildup":
            self.wing_design_lift = {}
            return None
        W0 = self.togw_baseline_kg * G0
        S = sum(w.area_m2 for w in self.lifting_wings)
        self.wing_design_lift = {
            w.name: problem.variable(f"{w.name}.design_lift", 1, unit="N", scale=W0, lower=0.02 * W0,
                                     upper=3.0 * W0, init=W0 * w.area_m2 / S, design=False,
                                     description=f"{w.name}: 1 g lift its structure is sized for (sized)")
            for w in self.lifting_wings}
        for name, F in self.wing_design_lift.items():
            problem.output(f"{name}.design_lift_kN", F / 1000.0, unit="kN", summary=True)
        return self.wing_design_lift

    # ------------------------------------------------------------------ protocol
    def unknowns(self):
        spec = self.bus.battery_current_unknown()
        out = [u_ for gm in self.groups for u_ in gm.unknowns()]
        out.append(Unknown(spec["name"], unit=spec["unit"], scale=spec["scale"], lower=spec["lower"],
                           upper=spec["upper"], description=spec["description"]))
        if self.tilt == "control":   # the wing-mounted angle where a segment lets it be a control
            out.append(self._tilt_unknown())
        out += trim_unknowns(self)
        out += viscous_unknowns(self)
        # gear/flap deployment: a control only where a segment allows a drag device
        out.append(Unknown("drag_device_deployment", unit="-", scale=1.0, lower=0.0, upper=1.0,
                           description="gear/flap deployment on approach (fraction of drag_device_area_m2)",
                           only_where="drag_device_area_m2", hold_where_uncollocated=True))
        return out

    def states(self):
        return [State("state_of_charge", unit="-", scale=1.0, initial=1.0, lower=0.0, upper=1.0,
                      description="battery state of charge s = 1 - q/Q_u(T); ds/dt = soc_rate_per_s")]

    def energy_used_J(self, initial, final):
        return self.pack.energy_used_J(initial["state_of_charge"], final["state_of_charge"])

    def final_limits(self, final_states):
        """State of charge left after the whole mission (reserves included) >= BatteryConfig.reserve_soc."""
        if not self.limits_on:
            return []
        r = self.config.battery.reserve_soc
        return [ResidualGroup("state of charge reserve", final_states["state_of_charge"] - r, kind=">=",
                              scale=0.1, unit="-", row_labels=[f"end of mission (reserve {r:g})"])]

    def evaluate(self, nodes, unknowns) -> NodeEvaluation:
        if self._problem is None:
            raise RuntimeError("Aircraft.evaluate before setup(problem)")
        K = nodes.size
        atm = atmosphere(_num(nodes.altitude_m).ravel())
        rho, mu, a_s = (_row(atm[k]) for k in ("density_kgpm3", "dynamic_viscosity_Pas", "speed_of_sound_mps"))
        V, gam, theta = nodes.speed_mps, nodes.flight_path_angle_rad, nodes.body_angle_rad
        alpha = theta - gam
        wma = self.wing_mounted_angle(nodes.parameters, unknowns, K)
        pitch = nodes.parameters.get("pitch_command_rad", _row(0.0, K))
        env = dict(K=K, rho=rho, mu=mu, a_s=a_s, V=V, alpha=alpha, wma=wma, pitch=pitch,
                   wma_schedule=self.scheduled_wing_angle(nodes.parameters, K),
                   tilt_nodes=self.tilt_control_nodes(nodes.parameters, K))
        rot = {gm.name: self._rotor_nodes(gm, nodes, unknowns, env) for gm in self.groups}
        soc = nodes.states["state_of_charge"]
        ib = unknowns["battery_current_A"]
        po = self.bus.evaluate([rot[gm.name]["Q"] for gm in self.groups],
                               [rot[gm.name]["omega"] for gm in self.groups], soc, ib)
        # motor and inverter heat, carried off by the cooling air (its drag in the build-up)
        heat_W = sum(gm.config.count * (po["groups"][gm.name]["esc_power_in_W"]
                                        - rot[gm.name]["Q"] * rot[gm.name]["omega"]) for gm in self.groups)
        aero = self._aerodynamics(nodes, unknowns, rot, env, heat_W)
        F_t, F_n = -aero["D"], aero["L"]
        for gm in self.groups:
            o = rot[gm.name]
            n = gm.config.count
            F_t = F_t + n * (o["T"] * o["cos"] - o["H"] * o["sin"])
            F_n = F_n + n * (o["T"] * o["sin"] + o["H"] * o["cos"])
        residuals = [r_ for gm in self.groups for r_ in rot[gm.name]["residuals"]]
        residuals.append(ResidualGroup("power balance", po["power_balance_W"], scale=self.bus.power_scale_W,
                                       unit="W"))
        residuals += trim_residuals(self, nodes, aero, rot, env)
        if self.limits_on:
            residuals += operating_limits(self, nodes, rot, po, aero, env)
        residuals += wing_design_lift_rows(self, nodes, aero, env)
        post = self.post_stall_nodes(nodes, K)
        residuals += viscous_rows(self, aero["vlm"], unknowns, rho, mu, V, V / a_s,
                                  _num(nodes.parameters.get("flap_deflection", _row(0.0, K))).ravel(),
                                  on=None if post is None else ~post)
        out = node_outputs(self, nodes, rot, aero, po, env)
        dist = {"strip_cl": Output(aero["vlm"]["cl"], "-", "section lift coefficient of each lattice strip "
                                                         "(with the wakes)")}
        if self.wing_viscous:
            dist["strip_viscous_shift"] = Output(unknowns["wing_viscous_shift"], "rad",
                                                 "each strip's angle shift of the viscous correction")
        return NodeEvaluation(mass_kg=self.togw, force_along_path_N=F_t, force_normal_N=F_n, residuals=residuals,
                              force_scale_N=self.togw_baseline_kg * G0,
                              state_derivatives={"state_of_charge": po["soc_rate_per_s"]}, outputs=out,
                              distributions=dist)

    def _rotor_nodes(self, gm, nodes, unknowns, env) -> dict:
        """One group's BEMT at every node, masked where the segment stops it."""
        K, V, alpha, wma = env["K"], env["V"], env["alpha"], env["wma"]
        g = gm.config
        a_rot = alpha + self.rotor_axis_angle(gm, wma)
        v_ax, v_ip = V * ca.cos(a_rot), V * ca.sin(a_rot)
        omega, phi = unknowns[f"{g.name}.omega"], unknowns[f"{g.name}.phi"]
        act = _num(nodes.parameters.get(f"{g.name}.active", _row(1.0, K))).ravel() * np.ones(K)
        pitch = env["pitch"]
        if gm.pitch_control:   # the collective where the rotor runs (a control), the schedule's where stopped
            pitch = unknowns[f"{g.name}.collective_pitch"] + _row(1.0 - (act > 0.5)) * pitch
        bm, residuals = gm.bemt_nodes(K, env["wma_schedule"], pitch, omega, v_ax, v_ip, env["rho"],
                                      env["mu"], env["a_s"], phi, azimuth_nodes=env["tilt_nodes"])
        loads, lifted = gm.lifted_loads(bm, unknowns, v_ax, env["rho"])
        residuals = residuals + lifted
        on = np.flatnonzero(act > 0.5)
        off = np.flatnonzero(act <= 0.5)
        if off.size:   # stopped: hold the speed so the unused BEMT unknowns stay determined
            residuals = residuals + [ResidualGroup(f"{g.name} stopped", omega[:, list(off)] - gm.omega_design,
                                                   scale=gm.omega_design, unit="rad/s", columns=off)]
        a = _row(act)
        return {"T": a * loads["thrust_N"], "Q": a * loads["torque_Nm"], "H": a * loads["hforce_N"], "omega": omega,
                "gamma": ca.repmat(a, self.n_stations, 1) * loads["gamma_m2ps"], "v_wake": v_ax + loads["va_mean_mps"],
                "v_ax": v_ax, "cos": ca.cos(a_rot), "sin": ca.sin(a_rot), "bemt": bm, "residuals": residuals,
                "pitch": pitch * _row(1.0, K),
                "active": act, "on": on, "off": off,
                "swirl_W": a * loads["swirl_W"] * g.count}

    def _aerodynamics(self, nodes, unknowns, rot, env, heat_W=None) -> dict:
        """Wake at the wing, the lattice, the bounded swirl credit and the drag build-up."""
        K, V, rho, mu, a_s, alpha, wma = (env[k] for k in ("K", "V", "rho", "mu", "a_s", "alpha", "wma"))
        gam_r, om_r, vw_r = [], [], []
        for gm in self.groups:
            o = rot[gm.name]
            n_r = len(self.group_rotors[gm.name])
            gam_r += [o["gamma"]] * n_r
            om_r += [o["omega"]] * n_r
            vw_r += [o["v_wake"]] * n_r
        # the whole wake in the flow tangency; without its axial part in the forces ("swirl")
        v_axial, v_rest = influence_sum_parts(self.influences, gam_r, om_r, vw_r)
        v_cp = tuple(x + y for x, y in zip(v_axial, v_rest))
        v_cp = self._flap_upwash(nodes, v_cp, V)
        if self.trim_surfaces:
            v_cp = trim_upwash(self, unknowns, v_cp, V)
        v_b = v_rest if self.coupling == "swirl" else None
        if self.wing_viscous:   # the strips' angle shifts: in the tangency only, not in the forces
            v_b = v_cp if v_b is None else v_b
            v_cp = viscous_upwash(self, unknowns, v_cp, V)
        mach = V / a_s
        wing_alpha = alpha + wma if self.config.kind == "tilt_wing" else alpha
        r = self.vlm.solve(wing_alpha, V, rho=rho, mach=mach, v_ext=v_cp, v_ext_bound=v_b)
        q = 0.5 * rho * V * V
        # swirl: the near-field force along the path is the power recovered from the slipstreams
        recovered = -r["CDi_near"] * q * self.S_ref * V
        available = sum(rot[gm.name]["swirl_W"] for gm in self.groups)
        # bounded in every coupling: "local" tilts the slipstream's lift forward just the same
        if self.swirl_recovery == "bounded":
            credit = smooth_min(recovered, available, 0.02 * available + 10.0)
            D_i = r["D_i"] + (recovered - credit) / ca.sqrt(V * V + 1.0)
        else:
            credit, D_i = recovered, r["D_i"]
        stopped = {gm.name: _row(1.0 - rot[gm.name]["active"]) for gm in self.groups if rot[gm.name]["off"].size}
        r_blown = self._blown_strips(r, v_axial, v_rest, V, wing_alpha) if self.blown_profile_drag else None
        b = self.drag_buildup(self.vlm, r, rho, mu, V, mach, stopped, r_profile=r_blown,
                              fin_area_scale=self.fin_area_scale,
                              thrust={gm.name: rot[gm.name]["T"] for gm in self.groups}, heat_W=heat_W,
                              alpha_body=alpha, post_stall_nodes=self.post_stall_nodes(nodes, K))
        pd, L_stall, L_body, D_folded = b["pd"], b["L_stall"], b["L_body"], b["D_folded"]
        D_device, deploy = self._drag_device(nodes, unknowns, q)
        D_parasite = b["D_parasite"] + D_device
        trim = {w.name: unknowns[f"{w.name}.trim_incidence"] for w in self.trim_surfaces}
        return {"vlm": r, "pd": pd, "D": D_i + D_parasite, "trim_incidence": trim, "L": r["L"] + L_stall + L_body, "D_i": D_i,
                "D_parasite": D_parasite, "D_device": D_device, "deploy": deploy, "q": q, "D_folded": D_folded,
                "drag_terms": b["terms"], "body_normal_N": b["N_body"],
                "swirl_recovered_W": recovered, "swirl_available_W": available, "swirl_credit_W": credit}

    # ------------------------------------------------------------------ guesses
    def guess_motor_rating(self, gm, power_W: float, speed_radps: float) -> None:
        """Start a sized group's motor rating (its design variables) at these values,
        clipped to their bounds; the initial guess calls it (:mod:`mdo.vehicle.guess`)."""
        if self._problem is None or not gm.config.motor.sized:
            return
        for name, value in ((f"{gm.name}.motor_rated_power", power_W), (f"{gm.name}.motor_rated_speed", speed_radps)):
            var = self._problem.variables[name]
            self._problem.set_initial(name, float(np.clip(value, np.min(var.lower), np.max(var.upper))))

    def initial_guess(self, nodes) -> dict:
        """Physics-based guesses at the baseline design (:mod:`mdo.vehicle.guess`)."""
        from .guess import initial_guess
        out = initial_guess(self, nodes)
        if self.tilt == "control":
            # the guess flies the schedule's wing and thrust angles (body + tilt) with the
            # cabin level where the tilt's range allows: the forces of the guess are unchanged
            K = nodes.size
            wma = self.scheduled_wing_angle(nodes.parameters, K)
            spec = self._tilt_unknown()
            on = self.tilt_control_nodes(nodes.parameters, K)
            theta = np.asarray(out["body_angle_rad"], float).ravel() * np.ones(K)
            tilt = np.where(on, np.clip(wma + theta, spec.lower, spec.upper), wma)
            out["wing_tilt"] = tilt
            out["body_angle_rad"] = theta - (tilt - wma)
        return out

