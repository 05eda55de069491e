"""Vehicle configuration records: the numbers that define an aircraft.

These are plain data (SI units).  The design variables of the optimization
(Eq. 7 of Clarke et al.) are the *initial values* stored here; the vehicle
assembly turns them into symbolic expressions.  Conventions:

* body axes: x aft from the fuselage nose, y to starboard, z up;
* a rotor's spanwise position is a fraction of the wing *semispan*
  (``y = eta * b/2``): the paper's Table 3 puts the TTW's outer rotors at 1.00,
  the wing tip, and bounds the GA propellers' positions "up to the wingtip";
* rotation senses are 'inboard_up' or 'outboard_up' per rotor (the paper's
  Case 1 is all inboard-up);
* wing sections are given at semispan fractions with twist and chord as a
  fraction of the root chord (Fig. 12): at fixed reference area a change of span
  or taper rescales the whole planform.

The records, in file order: ``WingConfig`` (a lifting surface, tail or fin; its flaps and
ailerons; a fin's rudder), ``FuselageConfig``,
``BatteryConfig``, ``AirframeDragConfig`` and ``VehicleConfig`` (the whole aircraft: payload,
load factor, cruise reference, CG and static margin, the stall pattern's stall speed, mass
inputs, wing structure; and its consistency checks: roles, references, disk overlaps).
``MotorConfig`` (rating, short-time/take-off factor, losses) and ``RotorGroupConfig`` (rotors, their
motor, nacelles, what a failed motor does) are in ``propulsion_config.py``, re-exported here.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from ..core.errors import InputError, check_positive, check_range
from ..core.units import KNOT
from .propulsion_config import MOTOR_MODELS, MotorConfig, RotorGroupConfig  # noqa: F401 (re-exported)
from .wing_structure import WingStructure

__all__ = ["WingConfig", "RotorGroupConfig", "MotorConfig", "FuselageConfig", "BatteryConfig",
           "AirframeDragConfig", "VehicleConfig", "replace", "WING_ROLES", "LIFTING_ROLES"]

#: What a wing is for; every discipline reads this, never the wing's name.
#: ``main`` and ``tandem`` wings carry the lift and are designed (span, taper, twists);
#: a ``horizontal_tail`` is analysed in the lattice but not designed; a ``fin`` is a
#: single vertical surface (drag and mass only).
WING_ROLES = ("main", "tandem", "horizontal_tail", "fin")
LIFTING_ROLES = ("main", "tandem")


@dataclass(frozen=True)
class WingConfig:
    """A lifting surface mirrored about the symmetry plane (or a single vertical fin).

    ``section_eta`` are the semispan fractions of the twist sections (the design
    variables θ of Eq. 7); the chord follows linear taper from root to tip,
    ``c(eta) = c_root (1 - (1 - taper) eta)``, with ``c_root = 2 S / (b (1 + taper))``.
    """
    name: str
    span_m: float
    area_m2: float
    taper: float
    section_eta: tuple
    twist_deg: tuple
    airfoil: str
    role: str = "main"             # one of WING_ROLES
    thickness_to_chord: float = 0.12
    sweep_quarter_chord_deg: float = 0.0
    dihedral_deg: float = 0.0
    incidence_deg: float = 0.0
    root_le_x_m: float = 0.0
    root_z_m: float = 0.0
    tilting: bool = False          # TTW: the wing and its rotors tilt by the wing-mounted angle
    flap_span_eta: tuple = (0.0, 0.0)   # flapped part of the semispan (fractions), for the stall margin
    flap_clmax_increment: float = 0.0   # section cl_max gain of the fully deflected flap (mdo.vehicle.stall)
    aileron_span_eta: tuple = (0.0, 0.0)  # ailerons' part of the semispan: kept unstalled at stall onset
    #                                       (mdo.vehicle.stall_pattern); (0, 0): no ailerons, no check
    pivot_x_m: float | None = None  # tilt axis position (defaults to the quarter chord)
    # the tilt mechanism, used where the wing-mounted angle is a control (Aircraft(tilt="control")):
    # its stops, and its largest rate.  10 deg/s: the Canadair CL-84 tilt-wing went from
    # hover to 100 kt in 8 s, some 11 deg/s of wing tilt on average (Wikipedia, "Tiltwing",
    # retrieved 2026-12); a placeholder to replace by the actuator of the design at hand
    tilt_range_deg: tuple = (0.0, 90.0)
    max_tilt_rate_degps: float = 10.0
    # an all-moving surface (a stabilator): its incidence, added to ``incidence_deg``, is the
    # pitch-trim control at every trimmed node, within these stops (deg); None: fixed
    trim_incidence_range_deg: tuple | None = None
    # a fin's rudder (read by the engine-out limit, mdo.vehicle.engine_out): its chord over the
    # fin's, its largest deflection, and the loss of effectiveness at that deflection.  Rudders
    # span 25-50 % of the tail chord and deflect 25-30 deg (Raymer, Aircraft Design 6th ed.,
    # sec. 6.6); 0.7 at 25 deg for a plain flap (Roskam, Airplane Design VI, Fig. 8.13)
    rudder_chord_fraction: float = 0.3
    rudder_max_deflection_deg: float = 25.0
    rudder_effectiveness_factor: float = 0.7

    def __post_init__(self):
        check_range(f"{self.name}.rudder_chord_fraction", self.rudder_chord_fraction, 0.05, 0.8)
        check_range(f"{self.name}.rudder_max_deflection_deg", self.rudder_max_deflection_deg, 0.0, 40.0, "deg")
        check_range(f"{self.name}.rudder_effectiveness_factor", self.rudder_effectiveness_factor, 0.0, 1.0)
        if self.role not in WING_ROLES:
            raise InputError(f"{self.name}.role", f"one of {', '.join(WING_ROLES)}, got {self.role!r}")
        for field_name in ("flap_span_eta", "aileron_span_eta"):
            lo, hi = (float(x) for x in getattr(self, field_name))
            if not (0.0 <= lo <= hi <= 1.0):
                raise InputError(f"{self.name}.{field_name}",
                                 f"0 <= start <= end <= 1, got {getattr(self, field_name)!r}")
        check_range(f"{self.name}.flap_clmax_increment", self.flap_clmax_increment, 0.0, 2.5)
        lo, hi = (float(x) for x in self.tilt_range_deg)
        if not (-30.0 <= lo < hi <= 120.0):
            raise InputError(f"{self.name}.tilt_range_deg", f"a pair (lower, upper) with -30 <= lower < upper "
                             f"<= 120 deg, got {self.tilt_range_deg!r}")
        check_range(f"{self.name}.max_tilt_rate_degps", self.max_tilt_rate_degps, 0.1, 180.0, "deg/s")
        if self.trim_incidence_range_deg is not None:
            r = tuple(float(x) for x in self.trim_incidence_range_deg)
            if len(r) != 2 or not (-30.0 <= r[0] < 0.0 < r[1] <= 30.0):
                raise InputError(f"{self.name}.trim_incidence_range_deg", f"a pair (lower, upper) with "
                                 f"-30 <= lower < 0 < upper <= 30 deg, got {self.trim_incidence_range_deg!r}")
            if self.role == "fin":
                raise InputError(f"{self.name}.trim_incidence_range_deg", "a fin cannot trim in pitch")
        if self.tilting and self.role not in LIFTING_ROLES:
            raise InputError(f"{self.name}.tilting", f"only a main or tandem wing may tilt, this one is "
                             f"a {self.role}")
        check_positive(f"{self.name}.span_m", self.span_m, "m")
        check_positive(f"{self.name}.area_m2", self.area_m2, "m^2")
        check_range(f"{self.name}.taper", self.taper, 0.05, 2.0)
        if len(self.section_eta) != len(self.twist_deg):
            raise InputError(f"{self.name}.twist_deg", f"{len(self.twist_deg)} twists for "
                             f"{len(self.section_eta)} sections")
        eta = np.asarray(self.section_eta, float)
        if eta[0] != 0.0 or eta[-1] != 1.0 or np.any(np.diff(eta) <= 0):
            raise InputError(f"{self.name}.section_eta", "must increase from 0 (root) to 1 (tip)")

    @property
    def vertical(self) -> bool:
        """A fin: one vertical surface, not mirrored."""
        return self.role == "fin"

    @property
    def lifting(self) -> bool:
        """A main or tandem wing: carries the lift and is designed."""
        return self.role in LIFTING_ROLES

    @property
    def aspect_ratio(self) -> float:
        return self.span_m ** 2 / self.area_m2

    @property
    def root_chord_m(self) -> float:
        return 2.0 * self.area_m2 / (self.span_m * (1.0 + self.taper))

    @property
    def mean_aerodynamic_chord_m(self) -> float:
        t = self.taper
        return 2.0 / 3.0 * self.root_chord_m * (1 + t + t * t) / (1 + t)


def fuselage_section_scale(s):
    """The fuselage's cross-section size over its largest, at ``s`` = (x - nose x)/length in [0, 1]
    (NumPy; 0 outside): an elliptical nose (a quarter ellipse over the first 20 % of the length),
    the full section to mid-length, a straight tail cone down to 12 % at the end.  A layout
    estimate of a light aircraft's body, the one shape the propellers' clearance
    (:meth:`FuselageConfig.section_half_axes`) and the drawings (``mdo.plots.geometry``) read; the
    drag build-up uses the wetted area and fineness instead."""
    s = np.asarray(s, float)
    nose = np.sqrt(np.clip(1.0 - (1.0 - s / 0.2) ** 2, 0.0, 1.0))
    tail = 1.0 - 0.88 * np.clip((s - 0.5) / 0.5, 0.0, 1.0)
    return np.where((s < 0.0) | (s > 1.0), 0.0, np.where(s < 0.2, nose, tail))


# 14 CFR 23.925(d)(1) (Part 23 before amendment 23-64; 25.925(c)(1) the same): "at least one
# inch radial clearance between the blade tips and the airplane structure, plus any additional
# radial clearance necessary to prevent harmful vibration"
PROPELLER_STRUCTURE_CLEARANCE_M = 0.0254
# points on the side of the body's elliptical cross-section toward a disk (fuselage_gaps_m); the
# polygon through them lies inside the ellipse by at most (pi b / 2(n-1))^2 / (8 rho_min), under
# 2 mm for the GA body (b = 0.79 m, rho_min = a^2/b = 0.36 m)
FUSELAGE_SECTION_POINTS = 33


def fuselage_gaps_m(half_width, half_height, axis_z, y, z, radius):
    """Distance (m) from the rim of a rotor disk (centre at lateral ``y`` and height ``z``,
    ``radius``, its plane a body cross-section) to each of ``FUSELAGE_SECTION_POINTS`` points of
    the fuselage's elliptical cross-section in that plane (half axes ``half_width``,
    ``half_height``, centre at ``axis_z``), on the side toward y > 0: a list, negative where the
    disk cuts into the body.  ``y``, ``z``, ``radius`` may be numbers or CasADi symbols."""
    t = np.linspace(-0.5 * math.pi, 0.5 * math.pi, FUSELAGE_SECTION_POINTS)
    return [((y - half_width * math.cos(tk)) ** 2 + (z - axis_z - half_height * math.sin(tk)) ** 2) ** 0.5 - radius
            for tk in t]


def fuselage_half_axes(length_m, width_m, height_m, nose_x_m, x_m) -> tuple:
    """Half width and half height (m) of the body's elliptical cross-section at body station ``x_m``
    (both 0 ahead of the nose and behind the tail): :func:`fuselage_section_scale` of the largest."""
    k = float(fuselage_section_scale((x_m - nose_x_m) / length_m))
    return 0.5 * width_m * k, 0.5 * height_m * k


@dataclass(frozen=True)
class FuselageConfig:
    length_m: float
    width_m: float
    height_m: float
    wetted_area_m2: float
    tail_arm_m: float               # wing quarter chord to horizontal tail quarter chord
    # K_f of the fuselage's destabilizing moment, dCm/dalpha = K_f W_f^2 L_f / (c S) per deg
    # (Raymer, Aircraft Design 6th ed., Eq. 16.25 and Fig. 16.14, after Gilruth & White, NACA
    # TR 711): about 0.01 with the wing's root quarter chord near 30-35 % of the body length,
    # rising to 0.02-0.03 near 50 %; 0.012 is read off that chart for the GA layouts, an estimate
    pitching_moment_factor: float = 0.012
    # the body at an angle of attack: the viscous crossflow's normal force (Allen & Perkins,
    # NACA TR 1048, 1951; mdo.wing.drag.crossflow_normal_force), N = q eta c_dc S_p sin(a)|sin(a)|
    # with c_dc 1.2, the crossflow drag coefficient of a circular cylinder below the critical
    # crossflow Reynolds number, eta 0.6, the finite-length factor for fineness ratios 4-6
    # (Jorgensen, NASA TR R-474, 1977, Fig. 3: rising to about 0.7 near 10), and the planform
    # area S_p (default pi/4 L W, an ellipse: between a cylinder's L W and a cone's L W/2)
    crossflow_drag_coefficient: float = 1.2
    crossflow_eta: float = 0.6
    planform_area_m2: float | None = None
    # where the body sits (body axes, m): its nose's x, and the height of its axis; None puts
    # its top at the highest lifting wing's root, a high wing like the P2006T's
    # (VehicleConfig.fuselage_axis_z_m).  Read by the propellers' clearance to the fuselage.
    nose_x_m: float = 0.0
    axis_z_m: float | None = None

    def __post_init__(self):
        check_range("fuselage.nose_x_m", self.nose_x_m, -50.0, 100.0, "m")
        if self.axis_z_m is not None:
            check_range("fuselage.axis_z_m", self.axis_z_m, -20.0, 20.0, "m")
        for k in ("length_m", "width_m", "height_m", "wetted_area_m2", "tail_arm_m"):
            check_positive(f"fuselage.{k}", getattr(self, k), "m" if k != "wetted_area_m2" else "m^2")
        check_range("fuselage.pitching_moment_factor", self.pitching_moment_factor, 0.0, 0.1)
        check_range("fuselage.crossflow_drag_coefficient", self.crossflow_drag_coefficient, 0.0, 2.5)
        check_range("fuselage.crossflow_eta", self.crossflow_eta, 0.0, 1.0)
        if self.planform_area_m2 is not None:
            check_range("fuselage.planform_area_m2", self.planform_area_m2, 1e-3, self.length_m * self.width_m,
                        "m^2")

    def section_half_axes(self, x_m: float) -> tuple:
        """Half width and half height (m) of the cross-section at body station ``x_m``
        (:func:`fuselage_half_axes`)."""
        return fuselage_half_axes(self.length_m, self.width_m, self.height_m, self.nose_x_m, x_m)

    @property
    def planform_area(self) -> float:
        """The body's planform area (m^2): as given, or an ellipse of its length and width."""
        return self.planform_area_m2 if self.planform_area_m2 is not None else \
            0.25 * math.pi * self.length_m * self.width_m


@dataclass(frozen=True)
class BatteryConfig:
    """The battery: ``cells_series`` x ``cells_parallel`` cells of the 18650 NMC model
    (``mdo.powertrain.cell.nmc18650``: the paper's Panasonic cell, 48 g, 3.55 Ah).

    The ONE place the pack is defined: the mass build-up and the electrical pack
    (``mdo.powertrain.Pack``) both read it.  ``packaging_factor`` multiplies the cell
    mass for casing, wiring, thermal management and BMS: 1.42, the module factor
    SUAVE derives from the X-57 Maxwell battery (Chin et al., AIAA SciTech 2019).
    ``max_cell_current_A`` (10 A, the continuous rating of the Panasonic NCR18650GA
    class of 3.4-3.5 Ah NMC cells, Panasonic data sheet; the measured curves the cell
    model is fitted to reach 8 A, so 8-10 A is an extrapolation of the model) and
    ``min_cell_voltage_V`` (2.5 V, the measured cut-off) are the cell's operating
    limits, with ``max_charge_current_A`` (1.7 A, the data sheet's standard charge
    current, about 0.5 C) where the problem lets windmilling charge the pack; ``reserve_soc``: the state of charge that must remain at the end of the
    mission (after the reserve segments).
    """
    cells_series: int
    cells_parallel: int
    cell_mass_kg: float = 0.048     # Panasonic 18650 NMC, 48 g (shared/data/battery SOURCES)
    cell_capacity_Ah: float = 3.55
    cell_nominal_V: float = 3.6
    packaging_factor: float = 1.42
    max_cell_current_A: float = 10.0
    min_cell_voltage_V: float = 2.5
    max_charge_current_A: float = 1.7
    reserve_soc: float = 0.2
    temperature_C: float = 25.0

    def __post_init__(self):
        for name in ("cells_series", "cells_parallel"):
            v = getattr(self, name)
            if not isinstance(v, (int, np.integer)) or v < 1:
                raise InputError(f"battery.{name}", f"a whole number of cells >= 1, got {v!r}")
        check_positive("battery.cell_mass_kg", self.cell_mass_kg, "kg")
        check_range("battery.packaging_factor", self.packaging_factor, 1.0, 3.0)
        check_positive("battery.max_cell_current_A", self.max_cell_current_A, "A")
        check_range("battery.min_cell_voltage_V", self.min_cell_voltage_V, 2.0, 4.0, "V")
        check_positive("battery.max_charge_current_A", self.max_charge_current_A, "A")
        check_range("battery.reserve_soc", self.reserve_soc, 0.0, 0.9)

    @property
    def cells(self) -> int:
        return self.cells_series * self.cells_parallel

    @property
    def mass_kg(self) -> float:
        """Packaged battery mass, kg (cells x cell mass x packaging factor)."""
        return self.cells * self.cell_mass_kg * self.packaging_factor

    def pack(self):
        """The electrical pack of this battery (``mdo.powertrain.Pack``)."""
        from ..powertrain import Pack
        return Pack(self.cells_series, self.cells_parallel, temperature_C=self.temperature_C,
                    packaging_factor=self.packaging_factor, max_cell_current_A=self.max_cell_current_A,
                    min_cell_voltage_V=self.min_cell_voltage_V, max_charge_current_A=self.max_charge_current_A)

    @property
    def energy_nominal_kWh(self) -> float:
        return self.cells * self.cell_capacity_Ah * self.cell_nominal_V / 1000.0


VEHICLE_KINDS = ("airplane", "tilt_wing")

#: Disks of two rotor groups whose planes are this far apart along x (m) may overlap in
#: span (staggered, like the X-57's wing-tip cruise propellers ahead of its high-lift ones).
STAGGER_CLEARANCE_M = 0.3


def disks_in_one_plane(group_a: str, x_ahead_a: float, group_b: str, x_ahead_b: float) -> bool:
    """Whether two disks can collide: same group, or planes closer than STAGGER_CLEARANCE_M."""
    return group_a == group_b or abs(x_ahead_a - x_ahead_b) < STAGGER_CLEARANCE_M


@dataclass(frozen=True)
class AirframeDragConfig:
    """What the airframe's parasite drag adds beyond its components (``Aircraft.drag_buildup``).

    The components themselves are read where they are defined: each lifting surface's
    section polar (its airfoil, with the transition setting in the airfoil name, e.g.
    ``"NACA_63_412@xtr=0.1"``), the fuselage, each rotor group's nacelles (with their
    ``nacelle_interference``, scrubbed by the slipstream when ``nacelles_in_slipstream``)
    and the fins.

    * ``leakage_protuberance_fraction``: leakage and protuberances as a fraction of the
      component parasite drag; Raymer, *Aircraft Design*, 6th ed., sec. 12.5.9: 5-10 %
      for propeller aircraft.  Default 0.10, the upper end (riveted sheet metal, slotted
      flaps with external hinges, antennas).
    * ``cooling_delta_T_K``, ``cooling_momentum_loss``: the motor and inverter heat is
      carried off by ram air heated by ``delta_T`` and returned with a fraction of its
      momentum lost (Eq. B3 of :mod:`mdo.wing.buildup`, Meredith, ARC R&M 1683, 1935);
      ``cooling_momentum_loss = 0`` switches cooling drag off.
    """
    leakage_protuberance_fraction: float = 0.10
    cooling_delta_T_K: float = 30.0
    cooling_momentum_loss: float = 0.5
    nacelles_in_slipstream: bool = True

    def __post_init__(self):
        check_range("drag.leakage_protuberance_fraction", self.leakage_protuberance_fraction, 0.0, 0.5)
        check_range("drag.cooling_delta_T_K", self.cooling_delta_T_K, 5.0, 200.0, "K")
        check_range("drag.cooling_momentum_loss", self.cooling_momentum_loss, 0.0, 1.0)


@dataclass
class DesignBounds:
    """Bounds of the design variables, as factors of the baseline (or absolute where noted).

    These are ranges of validity of the models, not results: no bound is taken from a
    published optimum.  Span is held by what it costs (the default ``WingStructure``: the
    bending material grows with AR^1.5 and the wing's own lift share, and beyond the
    limit-load tip deflection the stiffness material with AR^2; Raymer's Eq. 15.46 alone,
    ``wing_structure=None``, grows with AR^0.6) and by ``Aircraft(max_span_m=...)`` when the
    user has a hangar or gate limit; the box 0.6-3.0 x the baseline span is far outside
    every committed optimum.  Taper by the
    stall pattern of a wing with ailerons (``mdo.vehicle.stall_pattern``: the aileron span
    still attached at the stall onset, which low taper without washout loses) and the stall
    margin of the tip strips (cl_max falls with the tip chord's Reynolds number) - the box
    0.2-1.0 keeps the planform a trapezoid with a tip chord the lattice and the section data
    can carry; a wing without an aileron span (the TTW's, as defined) can sit on it.
    Design speeds 0.05-2.0 x the baseline: the Adkins-Liebeck design is valid down to
    V = 0 (hover), so the box only keeps its scale (``problems/ttw.py``: to the cruise speed); the design cl of
    the blade sections by the design point's stall limit at each station's Reynolds
    number (``design_cl_stall_rows``, the vehicle's stall margin) - the box 0.2-1.5
    is the range of the Adkins-Liebeck design.
    """
    design_thrust: tuple = (0.3, 3.0)
    design_speed: tuple = (0.05, 2.0)
    tip_radius: tuple = (0.5, 1.6)
    design_cl: tuple = (0.2, 1.5)          # absolute; held by stall at the design stations' Re
    span: tuple = (0.6, 3.0)
    taper: tuple = (0.2, 1.0)              # absolute
    twist_deg: tuple = (-8.0, 8.0)         # absolute
    span_eta: tuple = (0.0, 1.0)           # absolute (fraction of the semispan)
    tip_clearance_m: float = 0.05          # between neighbouring disks, and disk to symmetry plane
    # each wing's innermost disk to the fuselage's side (14 CFR 23.925(d)(1), 1 in); None: unchecked
    fuselage_clearance_m: float | None = PROPELLER_STRUCTURE_CLEARANCE_M


@dataclass(frozen=True)
class VehicleConfig:
    """A whole aircraft: the single source of truth every discipline reads.

    ``kind``: 'airplane' or 'tilt_wing' (lifting wings with ``tilting=True`` and
    their rotors turn by the segment's wing-mounted angle).  ``wings``: WingConfig
    with explicit roles (exactly one 'main').  ``name`` is a label only: nothing
    depends on it, nor on the names of wings and groups beyond cross-references.
    """
    name: str
    kind: str                       # 'airplane' or 'tilt_wing'
    wings: tuple                    # WingConfig, exactly one with role 'main'
    rotor_groups: tuple
    fuselage: FuselageConfig
    battery: BatteryConfig
    passengers: int = 4
    passenger_mass_kg: float = 90.7  # 200 lb with personal items (FAA AC 120-27F summer adult + bag)
    avionics_power_W: float = 20.0
    payload_power_W: float = 10.0
    ultimate_load_factor: float = 5.7  # 1.5 x 3.8 (14 CFR 23 normal category; SUAVE X-57 model)
    cruise_speed_mps: float = 78.232   # 175 mph
    cruise_altitude_m: float = 762.0   # 2500 ft
    togw_reference_kg: float = 0.0     # Table 1 of the paper, for comparison only
    # the centre of gravity's height (body z, m; its x is a design variable placed by the
    # battery, mdo.vehicle.balance) and the smallest static margin allowed, a fraction of
    # the main wing's MAC: 5 %, a usual minimum for a statically stable airplane (Raymer,
    # Aircraft Design 6th ed., ch. 16) - a requirement the designer sets
    cg_z_m: float = 0.0
    static_margin_min: float = 0.05
    # the stall speed the wing's stall pattern is checked at (its strips' Reynolds numbers,
    # sea level; mdo.vehicle.stall_pattern): 61 kn, CS-23's stall-speed limit for the class
    stall_pattern_speed_mps: float = 61.0 * KNOT
    # where the layout can put the CG (x, m; the battery moves it within this range): None is
    # the main wing's mean aerodynamic chord from 0 to 50 % (an airplane balances on its wing;
    # light aircraft fly between about 15 and 35 % MAC); a tandem or canard states its own
    cg_x_range_m: tuple | None = None
    drag: AirframeDragConfig = field(default_factory=AirframeDragConfig)
    mass_inputs: dict = field(default_factory=dict)
    # the lifting wings' mass: a WingStructure (default: aluminium, strength and a limit-load
    # tip deflection of 20 % of the semispan) gives the bending material's response to span,
    # taper, thickness and the wing's own lift share on top of the area-held rest of Raymer's
    # Eq. 15.46 (mdo.vehicle.wing_structure); None is Eq. 15.46 alone (each wing sized for the
    # whole N_z W, AR^0.6: fitted below AR ~12, it lets an optimizer stretch a wing to AR 18-36)
    wing_structure: object = field(default_factory=WingStructure)
    notes: tuple = ()

    def __post_init__(self):
        if self.kind not in VEHICLE_KINDS:
            raise InputError("kind", f"one of {', '.join(VEHICLE_KINDS)}, got {self.kind!r}")
        for what, items in (("wings", self.wings), ("rotor_groups", self.rotor_groups)):
            seen = [x.name for x in items]
            dup = sorted({n for n in seen if seen.count(n) > 1})
            if dup:
                raise InputError(what, f"names must be unique, {', '.join(dup)} repeated")
        mains = [w.name for w in self.wings if w.role == "main"]
        if len(mains) != 1:
            raise InputError("wings", f"exactly one wing with role 'main', got {len(mains)} ({', '.join(mains)})")
        if not self.rotor_groups:
            raise InputError("rotor_groups", "at least one rotor group")
        if not isinstance(self.battery, BatteryConfig):
            raise InputError("battery", f"a BatteryConfig, got {type(self.battery).__name__}")
        if not isinstance(self.drag, AirframeDragConfig):
            raise InputError("drag", f"an AirframeDragConfig, got {type(self.drag).__name__}")
        check_positive("cruise_speed_mps", self.cruise_speed_mps, "m/s")
        check_range("cruise_altitude_m", self.cruise_altitude_m, 0.0, 20000.0, "m")
        check_range("static_margin_min", self.static_margin_min, -0.5, 0.5)
        check_range("stall_pattern_speed_mps", self.stall_pattern_speed_mps, 5.0, 100.0, "m/s")
        check_range("cg_z_m", self.cg_z_m, -20.0, 20.0, "m")
        if self.cg_x_range_m is not None:
            r = tuple(float(x) for x in self.cg_x_range_m)
            if len(r) != 2 or not (-50.0 <= r[0] < r[1] <= 100.0):
                raise InputError("cg_x_range_m", f"a pair (forward, aft) in m with forward < aft, got "
                                 f"{self.cg_x_range_m!r}")
        names = {w.name for w in self.wings}
        disks = {}
        for g in self.rotor_groups:
            for wn in g.wings:
                if wn not in names:
                    raise InputError(f"{g.name}.wings", f"no wing named {wn!r}; have {', '.join(sorted(names))}")
                if not self.wing(wn).lifting:
                    raise InputError(f"{g.name}.wings", f"rotors must sit on a main or tandem wing; {wn} is a "
                                     f"{self.wing(wn).role}")
                semi = self.wing(wn).span_m / 2
                for e in g.span_eta:
                    disks.setdefault(wn, []).append((float(e) * semi, g.radius_m, g.name, g.x_ahead_of_le_m))
        for wn, ds in disks.items():
            ds.sort()
            if ds[0][0] < ds[0][1]:
                y, R, gn, _ = ds[0]
                raise InputError(f"{gn}.span_eta",
                                 f"the inner disk on {wn} (y = {y:.3f} m) crosses the symmetry plane and "
                                 f"overlaps its mirror image: allowed y >= R = {R:.3f} m, i.e. "
                                 f"span_eta >= {R / (self.wing(wn).span_m / 2):.3f}")
            for (ya, Ra, ga, xa), (yb, Rb, gb, xb) in zip(ds[:-1], ds[1:]):
                if not disks_in_one_plane(ga, xa, gb, xb):
                    continue
                if yb - ya < Ra + Rb:
                    raise InputError(f"{gb}.span_eta",
                                     f"rotors at y = {ya:.3f} m ({ga}) and {yb:.3f} m ({gb}) on {wn} overlap: "
                                     f"allowed spacing >= R1 + R2 = {Ra + Rb:.3f} m, got {yb - ya:.3f} m")

    @property
    def fuselage_axis_z_m(self) -> float:
        """Height of the fuselage's axis (body z, m): ``fuselage.axis_z_m``, or with None the
        body's top at the highest lifting wing's root (a high wing)."""
        f = self.fuselage
        if f.axis_z_m is not None:
            return float(f.axis_z_m)
        return max(w.root_z_m for w in self.lifting_wings) - 0.5 * f.height_m

    def wing(self, name: str) -> WingConfig:
        for w in self.wings:
            if w.name == name:
                return w
        raise InputError("wing", f"no wing named {name!r} in {self.name}; have "
                         f"{', '.join(w.name for w in self.wings)}")

    @property
    def main_wing(self) -> WingConfig:
        """The wing with role 'main' (reference chord and span)."""
        return next(w for w in self.wings if w.role == "main")

    @property
    def lifting_wings(self) -> list:
        """Main and tandem wings, in definition order (designed, carry the lift)."""
        return [w for w in self.wings if w.lifting]

    @property
    def horizontal_tails(self) -> list:
        return [w for w in self.wings if w.role == "horizontal_tail"]

    @property
    def trim_surfaces(self) -> list:
        """The all-moving surfaces (``trim_incidence_range_deg`` set): the pitch-trim controls."""
        return [w for w in self.wings if w.trim_incidence_range_deg is not None]

    @property
    def fins(self) -> list:
        return [w for w in self.wings if w.role == "fin"]

    @property
    def aux_power_W(self) -> float:
        """Avionics and payload power drawn from the bus, W."""
        return self.avionics_power_W + self.payload_power_W

    @property
    def rotors(self) -> int:
        return sum(g.count for g in self.rotor_groups)

    def _motor(self, group: RotorGroupConfig, pack):
        """A group's DC motor at its configured rating (Eq. M6 at the rated voltage): the
        paper's motor model, which :meth:`powertrain` uses whatever ``motor.model`` says."""
        from ..core import units as u
        from ..powertrain import size_dc_motor
        m = group.motor
        return size_dc_motor(m.rated_power_W, group.motor_rated_rpm * u.RPM,
                             m.rated_voltage_fraction * pack.nominal_voltage_V, rated_efficiency=m.rated_efficiency,
                             copper_loss_fraction=m.copper_loss_fraction)

    def bus(self):
        """The electrical network with every motor at its configured rating, as numbers
        (``mdo.powertrain.Bus``: this battery's pack, one motor group per rotor group,
        the avionics and payload load)."""
        from ..core import units as u
        from ..powertrain import Bus
        pack = self.battery.pack()
        groups = [g.motor.drive(g.name, g.count, g.motor.rated_power_W, g.motor_rated_rpm * u.RPM, pack)
                  for g in self.rotor_groups]
        return Bus(pack, groups, aux_power_W=self.aux_power_W)

    def powertrain(self, group: str | None = None):
        """This battery and one rotor group's motors (default the first group) as a
        ``mdo.powertrain.Powertrain``: the single-group network of ``mdo battery report``
        (efficiency maps, balance over throttle).  It flies the paper's DC motor model
        (Eqs. M1-M6) at this group's rating whatever ``motor.model`` is; the mission's
        network is :meth:`bus`, which follows ``motor.model``."""
        g = self.rotor_groups[0] if group is None else next(
            (x for x in self.rotor_groups if x.name == group), None)
        if g is None:
            raise InputError("group", f"one of {', '.join(x.name for x in self.rotor_groups)}, got {group!r}")
        from ..powertrain import Powertrain
        pack = self.battery.pack()
        return Powertrain(pack, self._motor(g, pack), g.count, esc_efficiency=g.motor.esc_efficiency,
                          aux_power_W=self.aux_power_W, name=self.name)
