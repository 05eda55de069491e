"""GA-2P: the X-57 Mod II airframe with two propellers, optimized over the GA profile (Eq. 7).

``mdo run problems/ga2p.py`` minimizes the battery energy used over the GA profile of
Table 5 with respect to the Adkins-Liebeck inputs of the propellers (design thrust,
design speed, tip radius, design cl), the main wing's span, taper and five section
twists at constant reference area, and the propellers' span position, subject to the
mission and every operating limit at every node (motor power, torque and speed with
the motors sized, throttle, tip Mach <= 0.6, cell current and voltage, no battery
charging, the wing's stall margin with flaps on take-off and approach, 20 % state of
charge left at the end), in one IPOPT solve.  ``--analysis`` freezes the design at
Table 3's initial values (the motors are still sized; the tip-Mach limit is reported
but not enforced: the frozen blade violates it in the climb).

Options (``-o KEY=VALUE``): ``nodes`` per segment (6), ``wing_viscous`` (true: every lattice strip on its
section polar, mdo.vehicle.viscous_wing; false: the linear lattice), ``trim`` (true: pitch trim with the
stabilator, the CG held by the static margin; mdo.vehicle.balance), ``cruise_distance_nmi`` (50),
``reserve_cruise_distance_nmi`` (5), ``cruise_altitude_ft`` (2500), ``cruise_speed_mph``
(175), ``cells_series`` (120) and ``cells_parallel`` (80) of the battery, ``n_stations``
(16), ``wing_strips`` (24), ``mass_model`` ("buildup" or "fixed"), ``rotation``
("inboard_up"), ``coupling`` ("swirl", "local" or "freestream": how the wake enters the
wing forces, see mdo/wake/README.md), ``swirl_recovery`` ("bounded": the swirl credit
never exceeds the swirl power the slipstreams carry; "unbounded"), ``limits`` (true),
``tip_mach_limit`` ("nodes", "design_point" or "off"), ``fin_sizing`` (false; true: the fin's area a design variable, x1 to x3, its rudder moment, drag and mass following it), ``allow_regeneration`` (false),
``max_span_m`` (none: a hangar/gate limit), ``engine_out`` ("rudder": the fin's rudder holds a
failed propeller's mirror at take-off power at every wing-borne node, ``mdo.vehicle.engine_out``;
"off"), ``approach_drag_area_m2`` (0.40 m^2, ``GA_APPROACH_DRAG_AREA_M2``:
gear and flap drag the pilot may add on BL and FA, a control per node; without it and
without battery charging the clean airframe cannot slow down on the base leg), ``wake_samples`` (7),
``wake_core_rel`` (0.1: the width of the slipstream's edge, mdo.wake.DEFAULT_CORE_REL),
``trajectory`` ("prescribed": Table 5's speeds and rates; "free": every segment's speeds and
duration are controls within the envelope of ``mdo.mission.trajectory``, the altitudes and the
trip's ground distance kept), ``min_climb_gradient_pct`` (8.3: 14 CFR 23.65's take-off climb
gradient on the freed climbs; a powered-lift vehicle's designer may state another rule), ``max_block_time_min`` (none; with a
free trajectory, the mission duration limit).
``motor_model`` ("pmsm", or "dc": the paper's DC motor behind a 0.95 ESC), ``sections``
("as_defined": the catalog's tripped sections; "free_transition": the XFOIL polars), ``leakage_fraction``
(0.10), ``nacelle_slipstream`` (true), ``cooling_drag`` (true), ``airframe_calibration`` (the
catalog's mass calibration; 1.0 = the raw regressions), ``wing_mass`` ("bending", default: the
wing's bending and stiffness material, so that its mass responds to span, taper and the wing's own
lift share, ``mdo.vehicle.wing_structure``; "raymer": Eq. 15.46 alone), ``max_tip_deflection_pct`` (20: the
wing's limit-load tip deflection, percent of the semispan, that its caps are sized to hold): what-ifs on the airframe and
motor models (``mdo.studies.airframe_variant``; results/table3_reconciliation.md).
"""
from dataclasses import replace

from mdo.core.units import FT, MPH, NMI
from mdo.mission.profiles import ga_mission
from mdo.nlp import Problem
from mdo.studies import (AIRCRAFT_OPTIONS, AIRFRAME_OPTIONS, TRAJECTORY_OPTIONS, airframe_variant,
                         minimize_battery_energy, trajectory_envelope)
from mdo.wake import DEFAULT_CORE_REL, DEFAULT_STRIP_SAMPLES
from mdo.vehicle.aircraft import Aircraft
from mdo.vehicle.catalog import ga2p


# allowed values of the -o options (mdo.nlp.options; `mdo run problems/ga2p.py --options`)
OPTIONS = {**AIRCRAFT_OPTIONS, **AIRFRAME_OPTIONS, **TRAJECTORY_OPTIONS,
    "max_span_m": (float, 5.0, 30.0),
    "approach_drag_area_m2": (float, 0.0, 2.0),
}


def build(analysis: bool = False, nodes: int = 6, cruise_distance_nmi: float = 50.0,
          reserve_cruise_distance_nmi: float = 5.0, cruise_altitude_ft: float = 2500.0,
          cruise_speed_mph: float = 175.0, cells_series: int = 120, cells_parallel: int = 80,
          n_stations: int = 16, wing_strips: int = 24, mass_model: str = "buildup", rotation: str = "inboard_up",
          coupling: str = "swirl", swirl_recovery: str = "bounded", limits: bool = True,
          tip_mach_limit: str = "nodes", allow_regeneration: bool = False, max_span_m: float | None = None,
          approach_drag_area_m2: float = 0.40, wake_samples: int = DEFAULT_STRIP_SAMPLES, wake_core_rel: float = DEFAULT_CORE_REL, trajectory: str = "prescribed",
          max_block_time_min: float | None = None, min_climb_gradient_pct: float | None = None,
          motor_model: str = "pmsm", sections: str = "as_defined", leakage_fraction: float | None = None,
          nacelle_slipstream: bool = True, cooling_drag: bool = True, airframe_calibration: float | None = None,
          wing_mass: str = "bending", max_tip_deflection_pct: float | None = None,
          trim: bool = True, wing_viscous: bool | None = None,
          blown_profile_drag: bool = True, engine_out: str | None = None, fin_sizing: bool = False):
    p = Problem("ga2p", "GA-2P whole-mission optimization (Clarke et al. Eq. 7)")
    cfg = ga2p(rotation)
    cfg = replace(cfg, battery=replace(cfg.battery, cells_series=cells_series, cells_parallel=cells_parallel),
                  cruise_speed_mps=cruise_speed_mph * MPH, cruise_altitude_m=cruise_altitude_ft * FT)
    cfg = airframe_variant(cfg, motor_model, sections, leakage_fraction, nacelle_slipstream, cooling_drag,
                           airframe_calibration, wing_mass, max_tip_deflection_pct)
    vehicle = Aircraft(cfg, trim=trim, wing_viscous=wing_viscous, blown_profile_drag=blown_profile_drag, n_stations=n_stations, wing_strips=wing_strips, mass_model=mass_model,
                       coupling=coupling, swirl_recovery=swirl_recovery, limits=limits,
                       tip_mach_limit=tip_mach_limit, allow_regeneration=allow_regeneration, max_span_m=max_span_m,
                       design_point_constraints=not analysis, wake_samples=wake_samples, wake_core_rel=wake_core_rel, engine_out=engine_out, fin_sizing=fin_sizing)
    mission = ga_mission(vehicle, nodes=nodes, cruise_distance_m=cruise_distance_nmi * NMI,
                         reserve_cruise_distance_m=reserve_cruise_distance_nmi * NMI,
                         cruise_altitude_m=cruise_altitude_ft * FT, cruise_speed_mps=cruise_speed_mph * MPH,
                         approach_drag_area_m2=approach_drag_area_m2, trajectory=trajectory,
                         envelope=trajectory_envelope(max_block_time_min, min_climb_gradient_pct)).build(p)
    return minimize_battery_energy(p, vehicle, mission)
