"""Propulsion records of a vehicle configuration: ``MotorConfig`` (rating, short-time/take-off
factor, losses) and ``RotorGroupConfig`` (rotors, their motor, nacelles, what a failed motor
does).  Plain data in SI units, checked when made; re-exported by ``mdo.vehicle.config``,
whose conventions (body axes, spanwise positions, rotation senses) they follow.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.errors import InputError, check_positive, check_range

__all__ = ["MOTOR_MODELS", "MotorConfig", "RotorGroupConfig"]


MOTOR_MODELS = ("pmsm", "dc")


@dataclass(frozen=True)
class MotorConfig:
    """The motors of one rotor group (one per rotor, identical).

    ``rated_power_W`` is the continuous shaft-power rating: the initial value when the
    rating is sized by the optimizer (``sized=True``: a variable of every stage, the
    analysis included, bounded below by the mission's need through the power limit,
    so the motors - and their mass - follow the mission), or a fixed rating
    (``sized=False``).  ``rated_rpm`` defaults to the group's design rpm.
    ``short_time_power_factor`` (>= 1) is a take-off/climb rating as a multiple of the
    continuous one, allowed in the segments ``short_time_segments`` (their names),
    for at most ``short_time_duration_s`` each (checked against the segment
    durations when the mission is built).  ``max_speed_factor``: the highest speed
    as a multiple of the rated speed (bearings, back-emf).
    ``model`` (issue 17 item 3):

    * ``"pmsm"`` (default): the loss-model permanent-magnet synchronous motor and its
      inverter (:mod:`mdo.powertrain.pmsm`: copper I^2 R, iron hysteresis and eddy
      currents, friction and windage; inverter conduction, switching and fixed losses),
      sized from the rating with ``peak_efficiency`` at ``peak_load_fraction`` of the
      rated torque and the inverter's ``inverter_peak_efficiency``.  Aircraft PMSMs
      peak at 0.95-0.97, aircraft inverters at 0.97-0.99 (sources in ``pmsm.py``).
    * ``"dc"``: the paper's DC motor (``mdo.powertrain.motor.size_dc_motor``, Eq. M6,
      ``rated_efficiency`` and ``copper_loss_fraction``) behind an ESC of flat
      ``esc_efficiency``.

    Both are sized at ``rated_voltage_fraction`` of the pack's nominal voltage.
    """
    rated_power_W: float
    rated_rpm: float | None = None
    sized: bool = True
    rated_voltage_fraction: float = 0.9
    rated_efficiency: float = 0.94
    copper_loss_fraction: float = 0.6
    short_time_power_factor: float = 1.0
    short_time_segments: tuple = ()
    short_time_duration_s: float = 300.0
    max_speed_factor: float = 1.2
    esc_efficiency: float = 0.95
    model: str = "pmsm"
    peak_efficiency: float = 0.96
    peak_load_fraction: float = 0.5
    inverter_peak_efficiency: float = 0.985

    def __post_init__(self):
        check_positive("motor.rated_power_W", self.rated_power_W, "W")
        if self.rated_rpm is not None:
            check_positive("motor.rated_rpm", self.rated_rpm, "rpm")
        check_range("motor.rated_voltage_fraction", self.rated_voltage_fraction, 0.5, 1.0)
        check_range("motor.rated_efficiency", self.rated_efficiency, 0.5, 0.99)
        check_range("motor.copper_loss_fraction", self.copper_loss_fraction, 0.05, 0.95)
        check_range("motor.short_time_power_factor", self.short_time_power_factor, 1.0, 3.0)
        check_positive("motor.short_time_duration_s", self.short_time_duration_s, "s")
        check_range("motor.max_speed_factor", self.max_speed_factor, 1.0, 3.0)
        check_range("motor.esc_efficiency", self.esc_efficiency, 0.5, 1.0)
        if self.model not in MOTOR_MODELS:
            raise InputError("motor.model", f"one of {', '.join(map(repr, MOTOR_MODELS))}, got {self.model!r}")
        check_range("motor.peak_efficiency", self.peak_efficiency, 0.80, 0.995)
        check_range("motor.peak_load_fraction", self.peak_load_fraction, 0.1, 1.0)
        check_range("motor.inverter_peak_efficiency", self.inverter_peak_efficiency, 0.90, 0.999)

    @property
    def take_off_power_factor(self) -> float:
        """The motor's take-off power over its continuous rating: the short-time factor when
        a short-time rating is set (``short_time_segments``), else 1."""
        return self.short_time_power_factor if self.short_time_segments else 1.0

    def drive(self, name: str, count: int, rated_power_W, rated_speed_radps, pack):
        """The group's motors as a :class:`mdo.powertrain.MotorGroup` sized at this rating
        (numbers or CasADi expressions) on ``pack``: the one place the motor model is chosen."""
        from ..powertrain import MotorGroup, size_dc_motor, size_inverter, size_pmsm
        v_rated = self.rated_voltage_fraction * pack.nominal_voltage_V
        if self.model == "dc":
            motor = size_dc_motor(rated_power_W, rated_speed_radps, v_rated, rated_efficiency=self.rated_efficiency,
                                  copper_loss_fraction=self.copper_loss_fraction)
            return MotorGroup(name, motor, count, esc_efficiency=self.esc_efficiency)
        v_bus = float(pack.nominal_voltage_V)
        motor = size_pmsm(rated_power_W, rated_speed_radps, v_bus, peak_efficiency=self.peak_efficiency,
                          peak_load_fraction=self.peak_load_fraction, voltage_headroom=self.rated_voltage_fraction,
                          max_torque_factor=self.short_time_power_factor, max_speed_factor=self.max_speed_factor)
        inverter = size_inverter(rated_power_W / self.peak_efficiency, v_bus,
                                 peak_efficiency=self.inverter_peak_efficiency,
                                 voltage_headroom=self.rated_voltage_fraction)
        return MotorGroup(name, motor, count, inverter=inverter)


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
    motor: MotorConfig
    airfoil: str = "NACA_4412"
    hub_fraction: float = 0.12
    x_ahead_of_le_m: float = 0.0     # rotor disk ahead of the local leading edge
    z_below_wing_m: float = 0.0
    rotation: str = "inboard_up"
    tip_mach_max: float = 0.6
    folded_drag_area_m2: float = 0.0   # flat-plate area of one stopped/folded rotor (segments that switch it off)
    # drag of one failed rotor on its disk area (the engine-out limit, mdo.vehicle.engine_out):
    # 0 for a feathered or stopped-and-aligned propeller; a windmilling fixed-pitch one is well above
    inoperative_drag_coefficient: float = 0.0
    # True: a failed motor of this group also stops its mirror (a control system's response, as a
    # distributed-propulsion or wing-tip-motor airplane may have): no yaw for the rudder to hold,
    # the group is left out of the engine-out limit, and the climb on the motors left is not modelled
    failure_stops_mirror: bool = False
    nacelle_wetted_area_m2: float = 0.0  # wetted area of the nacelle of ONE rotor (drag and mass)
    # Raymer sec. 12.5.5: a nacelle mounted on the wing 1.5, within one diameter 1.3, farther 1.0
    nacelle_interference: float = 1.5
    # variable-pitch hub: the collective pitch's stops (deg, added to the blade's twist);
    # None: a fixed-pitch propeller (the segment's pitch_command_rad, 0 by default)
    collective_range_deg: tuple | None = None

    def __post_init__(self):
        check_positive(f"{self.name}.radius_m", self.radius_m, "m")
        if self.collective_range_deg is not None:
            r = tuple(float(x) for x in self.collective_range_deg)
            if len(r) != 2 or not r[0] < r[1]:
                raise InputError(f"{self.name}.collective_range_deg",
                                 f"a pair (fine stop, coarse stop) with fine < coarse, got {self.collective_range_deg!r}")
            check_range(f"{self.name}.collective_range_deg", np.asarray(r), -60.0, 90.0, "deg")
        check_range(f"{self.name}.hub_fraction", self.hub_fraction, 0.0, 0.5, inclusive=False)
        check_range(f"{self.name}.span_eta", np.asarray(self.span_eta, float), 0.0, 1.0)
        check_positive(f"{self.name}.blades", self.blades)
        check_positive(f"{self.name}.design_rpm", self.design_rpm, "rpm")
        if not isinstance(self.motor, MotorConfig):
            raise InputError(f"{self.name}.motor", f"a MotorConfig, got {type(self.motor).__name__}")
        check_range(f"{self.name}.tip_mach_max", self.tip_mach_max, 0.1, 0.95)
        check_range(f"{self.name}.folded_drag_area_m2", self.folded_drag_area_m2, 0.0, 5.0, "m^2")
        check_range(f"{self.name}.inoperative_drag_coefficient", self.inoperative_drag_coefficient, 0.0, 1.5)
        check_range(f"{self.name}.nacelle_wetted_area_m2", self.nacelle_wetted_area_m2, 0.0, 50.0, "m^2")
        check_range(f"{self.name}.nacelle_interference", self.nacelle_interference, 0.8, 2.0)
        if self.rotation not in ("inboard_up", "outboard_up"):
            raise InputError(f"{self.name}.rotation", "must be 'inboard_up' or 'outboard_up'")

    @property
    def count(self) -> int:
        return 2 * len(self.span_eta) * len(self.wings)

    @property
    def variable_pitch(self) -> bool:
        return self.collective_range_deg is not None

    @property
    def motor_rated_rpm(self) -> float:
        return self.motor.rated_rpm if self.motor.rated_rpm is not None else self.design_rpm
