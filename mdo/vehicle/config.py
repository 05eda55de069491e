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
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Sequence

import numpy as np

from ..core.errors import InputError, check_positive, check_range

__all__ = ["WingConfig", "RotorGroupConfig", "FuselageConfig", "BatteryConfig",
           "VehicleConfig", "replace"]


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
    thickness_to_chord: float = 0.12
    sweep_quarter_chord_deg: float = 0.0
    dihedral_deg: float = 0.0
    incidence_deg: float = 0.0
    root_le_x_m: float = 0.0
    root_z_m: float = 0.0
    vertical: bool = False
    tilting: bool = False          # TTW: the wing and its rotors tilt by the wing-mounted angle
    pivot_x_m: float | None = None  # tilt axis position (defaults to the quarter chord)

    def __post_init__(self):
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
    def aspect_ratio(self) -> float:
        return self.span_m ** 2 / self.area_m2

    @property
    def root_chord_m(self) -> float:
        return 2.0 * self.area_m2 / (self.span_m * (1.0 + self.taper))

    @property
    def mean_aerodynamic_chord_m(self) -> float:
        t = self.taper
        return 2.0 / 3.0 * self.root_chord_m * (1 + t + t * t) / (1 + t)


@dataclass(frozen=True)
class RotorGroupConfig:
    """Identical rotors, identically throttled, mirrored in pairs about the symmetry plane.

    ``span_eta`` lists the semispan fractions of the rotors on ONE side of ONE
    wing; the group has ``2 * len(span_eta) * len(wings)`` rotors.  The Adkins-Liebeck design point
    (design thrust, speed, lift coefficient, rpm, altitude) defines the blade.
    """
    name: str
    wings: tuple                    # the wing(s) carrying the rotors (TTW: both)
    span_eta: tuple
    blades: int
    radius_m: float
    design_thrust_N: float
    design_speed_mps: float
    design_cl: float
    design_rpm: float
    design_altitude_m: float
    motor_rated_power_W: float
    airfoil: str = "NACA_4412"
    hub_fraction: float = 0.12
    x_ahead_of_le_m: float = 0.0     # rotor disk ahead of the local leading edge
    z_below_wing_m: float = 0.0
    rotation: str = "inboard_up"
    tip_mach_max: float = 0.6

    def __post_init__(self):
        check_positive(f"{self.name}.radius_m", self.radius_m, "m")
        check_range(f"{self.name}.hub_fraction", self.hub_fraction, 0.0, 0.5, inclusive=False)
        check_range(f"{self.name}.span_eta", np.asarray(self.span_eta, float), 0.0, 1.0)
        check_positive(f"{self.name}.blades", self.blades)
        check_positive(f"{self.name}.design_rpm", self.design_rpm, "rpm")
        check_positive(f"{self.name}.motor_rated_power_W", self.motor_rated_power_W, "W")
        if self.rotation not in ("inboard_up", "outboard_up"):
            raise InputError(f"{self.name}.rotation", "must be 'inboard_up' or 'outboard_up'")

    @property
    def count(self) -> int:
        return 2 * len(self.span_eta) * len(self.wings)


@dataclass(frozen=True)
class FuselageConfig:
    length_m: float
    width_m: float
    height_m: float
    wetted_area_m2: float
    tail_arm_m: float               # wing quarter chord to horizontal tail quarter chord


@dataclass(frozen=True)
class BatteryConfig:
    cells_series: int
    cells_parallel: int
    cell_mass_kg: float = 0.048     # Panasonic 18650 NMC, 48 g (shared/data/battery SOURCES)
    cell_capacity_Ah: float = 3.55
    cell_nominal_V: float = 3.6
    packaging_fraction: float = 0.0  # pack structure/BMS mass as a fraction of cell mass

    @property
    def cells(self) -> int:
        return self.cells_series * self.cells_parallel

    @property
    def energy_nominal_kWh(self) -> float:
        return self.cells * self.cell_capacity_Ah * self.cell_nominal_V / 1000.0


@dataclass(frozen=True)
class VehicleConfig:
    name: str
    kind: str                       # 'airplane' or 'tilt_wing'
    wings: tuple                    # WingConfig, the first is the main wing
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
    mass_inputs: dict = field(default_factory=dict)
    notes: tuple = ()

    def __post_init__(self):
        names = {w.name for w in self.wings}
        for g in self.rotor_groups:
            for wn in g.wings:
                if wn not in names:
                    raise InputError(f"{g.name}.wings", f"no wing named {wn!r}; have {', '.join(sorted(names))}")
                semi = self.wing(wn).span_m / 2
                y = sorted(float(e) * semi for e in g.span_eta)
                if y[0] < g.radius_m:
                    raise InputError(f"{g.name}.span_eta",
                                     f"the inner disk on {wn} (y = {y[0]:.3f} m) crosses the symmetry plane and "
                                     f"overlaps its mirror image: allowed y >= R = {g.radius_m:.3f} m, i.e. "
                                     f"span_eta >= {g.radius_m / semi:.3f}")
                for a, b in zip(y[:-1], y[1:]):
                    if b - a < 2 * g.radius_m:
                        raise InputError(f"{g.name}.span_eta",
                                         f"rotors at y = {a:.3f} m and {b:.3f} m on {wn} overlap: allowed spacing "
                                         f">= 2 R = {2 * g.radius_m:.3f} m, got {b - a:.3f} m")

    def wing(self, name: str) -> WingConfig:
        for w in self.wings:
            if w.name == name:
                return w
        raise InputError("wing", f"no wing named {name!r} in {self.name}; have "
                         f"{', '.join(w.name for w in self.wings)}")

    @property
    def main_wing(self) -> WingConfig:
        return self.wings[0]

    @property
    def rotors(self) -> int:
        return sum(g.count for g in self.rotor_groups)
