"""NASA X-57 Maxwell Mod IV: wing-tip cruise propellers plus twelve folding high-lift
propellers, defined here from published figures and optimized over the GA profile.

Not one of the paper's aircraft: everything is in this file (no change to ``mdo/``).
Two rotor groups on one high-aspect-ratio wing: the cruise propellers (3 blades, 1.52 m,
at the wing tips) fly the whole mission; the high-lift propellers (5 blades, 0.58 m, six
per side) run only in the take-off and approach segments (DER, ICA, BL, FA) and are
folded elsewhere (``highlift.active = 0``: no thrust, no wake, a small folded-blade drag).

Published figures (NASA X-57 fact sheet FS-2017-07-008-AFRC; Borer et al., "Design and
Performance of the NASA SCEPTOR Distributed Electric Propulsion Flight Demonstrator",
AIAA 2016-3920; the Mod 4 geometry of SUAVE's regression vehicle ``X57_Mod4.py``, R.
Erhard 2021): wing 6.144 m^2, span 31.6 ft (9.63 m), root/tip chord 2.48/1.74 ft; cruise
propellers D = 1.523 m, 3 blades, designed at 174 mph and 8000 ft, 2250 rpm, design cl
0.75, 60 kW cruise motors; high-lift propellers D = 0.58 m, 5 blades, 4000 rpm, designed
at 64 mph, spaced 0.6 m from y = 1.05 m, 10.5 kW motors; battery 128s x 40p 18650 cells
(460 V; 5120 cells in 16 modules), about 3000 lb gross; cruise 172 mph at 8000 ft.
The X-57's cells (Samsung 18650-30Q, Chin et al., "Battery Performance Modeling on
Maxwell X-57", AIAA SciTech 2019) are rated 15 A continuous: that is the cell-current
limit here, beyond the 8 A of the measured curves the cell model is fitted to (an
extrapolation of the cell model, stated).  The mass build-up (Raymer GA regressions, no
calibration) gives 1348 kg = 2972 lb against NASA's "approximately 3000 lb".
The P2006T fuselage and tails are kept (the X-57 is a modified P2006T).  The wing's
section is not published in those sources: NACA 63-412 stands in.  Its ailerons run from
the flaps' end (0.75 of the semispan) to the cruise nacelle (0.96), an estimate from the
published renderings; at the clean wing's stall onset they keep the stall margin
(``mdo.vehicle.stall_pattern``).  The high-lift
propellers' blown lift is captured with the "local" coupling (slipstream dynamic
pressure in the wing forces), which over-predicts PROWIM's blown-lift rise (see
mdo/wake/README.md) - stated, and an option.

Options (``-o KEY=VALUE``): ``nodes`` (6), ``cruise_distance_nmi`` (12.5, the sizing profile), ``approach_speed_kn`` (75.4),
``reserve_cruise_distance_nmi`` (5), ``cruise_altitude_ft`` (8000), ``cruise_speed_mph``
(172), ``cells_parallel`` (40), ``coupling`` ("local"), ``wing_strips`` (20), ``n_stations`` (12),
``wake_core_rel`` (0.1), ``engine_out`` ("rudder": the P2006T fin's rudder holds the yaw of a failed
wing-tip cruise motor's mirror at take-off power, or of a high-lift motor's where they run; "off"),
``leakage_fraction`` (the airframe's leakage & protuberance allowance, ``AirframeDragConfig``; 0.35 is what the
P2006T flight manual implies, ``results/validation/p2006t_drag.md``).
"""
from mdo.core.units import FT, INCH, KNOT, MPH, NMI
from mdo.mission import Mission
from mdo.mission.profiles import ga_segments
from mdo.nlp import Problem
from mdo.studies import AIRCRAFT_OPTIONS, AIRFRAME_OPTIONS, airframe_variant, minimize_battery_energy
from mdo.wake import DEFAULT_CORE_REL
from mdo.vehicle.aircraft import Aircraft
from mdo.vehicle.catalog import GA_CG_Z_M, GA_STABILATOR_RANGE_DEG
from mdo.vehicle.config import (BatteryConfig, FuselageConfig, MotorConfig, RotorGroupConfig, VehicleConfig,
                                WingConfig)

SEMISPAN_M = 31.6 * FT / 2
# The X-57 battery-sizing flight profile (Chin et al., as tabulated in M. Clarke's thesis
# repository, missionTable.tex; shared/data/vehicles/x57_battery_mission_profile.csv):
# cruise climb 540 s (1500 -> 8000 ft here from 500 ft: ~850 ft/min), 300 s of cruise
# (12.5 nmi at 172 mph), descent 450 s to 1500 ft (~900 ft/min), final approach 180 s
# on the high-lift motors.  Table 5's 500 ft/min climb to 8000 ft (15 min, 26 kWh) and
# 50 nmi cruise need more than the X-57's 69 kWh pack holds above its 20 % reserve.
CLIMB_RATE_MPS = 850 * FT / 60
DESCENT_RATE_MPS = 900 * FT / 60
APPROACH_SPEED_MPS = 1.3 * 58 * KNOT    # 1.3 x the published 58 kn stall speed (NASA fact sheet)
# A failed wing-tip cruise motor stops the other one too (the control system's response; our
# assumption, not a published X-57 procedure).  By the rudder alone the P2006T fin cannot hold
# it: at the 75 kn approach, the running tip motor at its 72 kW take-off rating yaws the
# airplane by 6.3 kN m against the rudder's 4.6 kN m (mdo.vehicle.engine_out; the baseline
# analysis is infeasible with it).  The high-lift motors (0.9 kN m) stay on the rudder's check.
CRUISE_FAILURE_STOPS_MIRROR = True


def x57_mod4(cells_parallel: int = 40, cruise_speed_mps: float = 172 * MPH,
             cruise_altitude_m: float = 8000 * FT) -> VehicleConfig:
    wing = WingConfig("wing", span_m=31.6 * FT, area_m2=6.144, taper=1.74 / 2.48, section_eta=(0.0, 0.5, 1.0),
                      twist_deg=(3.0, 1.5, 0.0), airfoil="NACA_63_412", role="main", root_le_x_m=2.93,
                      root_z_m=1.01, flap_span_eta=(0.09, 0.75), flap_clmax_increment=1.3,
                      aileron_span_eta=(0.75, 0.96))
    htail = WingConfig("stabilator", span_m=3.454, area_m2=3.74, taper=0.762 / 1.397, section_eta=(0.0, 1.0),
                       twist_deg=(0.0, 0.0), airfoil="NACA_0015", role="horizontal_tail", root_le_x_m=7.7,
                       root_z_m=0.25, trim_incidence_range_deg=GA_STABILATOR_RANGE_DEG)
    fin = WingConfig("fin", span_m=1.854, area_m2=2.258, taper=0.6858 / 1.6764, section_eta=(0.0, 1.0),
                     twist_deg=(0.0, 0.0), airfoil="NACA_0015", role="fin", sweep_quarter_chord_deg=25.0,
                     root_le_x_m=6.75, root_z_m=0.623)
    cruise = RotorGroupConfig(
        "cruise", wings=("wing",), span_eta=(1.0,), blades=3, radius_m=1.523 / 2, design_thrust_N=900.0,
        design_speed_mps=174 * MPH, design_cl=0.75, design_rpm=2250.0, design_altitude_m=8000 * FT,
        motor=MotorConfig(60e3, short_time_power_factor=1.2, short_time_segments=("DER", "ICA", "RCL")),
        x_ahead_of_le_m=1.0, nacelle_wetted_area_m2=1.5, failure_stops_mirror=CRUISE_FAILURE_STOPS_MIRROR)
    highlift = RotorGroupConfig(
        "highlift", wings=("wing",), span_eta=tuple((1.05 + 0.6 * i) / SEMISPAN_M for i in range(6)), blades=5,
        radius_m=0.29, design_thrust_N=250.0, design_speed_mps=64 * MPH, design_cl=0.75, design_rpm=4000.0,
        design_altitude_m=1000 * FT, motor=MotorConfig(10.5e3, short_time_power_factor=1.2,
                                                       short_time_segments=("DER", "ICA")),
        x_ahead_of_le_m=0.4, folded_drag_area_m2=0.003, nacelle_wetted_area_m2=0.25)
    fuselage = FuselageConfig(length_m=332.2 * INCH, width_m=42 * INCH, height_m=62 * INCH,
                              wetted_area_m2=30000 * INCH ** 2, tail_arm_m=4.66)
    return VehicleConfig(
        "X-57 Mod IV", "airplane", wings=(wing, htail, fin), rotor_groups=(cruise, highlift), fuselage=fuselage,
        battery=BatteryConfig(128, cells_parallel, max_cell_current_A=15.0), cruise_speed_mps=cruise_speed_mps,
        cruise_altitude_m=cruise_altitude_m, togw_reference_kg=3000 * 0.45359237, cg_z_m=GA_CG_Z_M,
        mass_inputs={"airframe_calibration": 1.0, "main_gear_length_in": 24.0, "nose_gear_length_in": 20.0,
                     "uninstalled_avionics_lb": 40.0})

# allowed values of the -o options (mdo.nlp.options; `mdo run problems/x57_mod4.py --options`)
OPTIONS = {
    "nodes": (int, 3, 30),
    "trim": (bool,),
    "cruise_distance_nmi": (float, 1.0, 300.0),
    "reserve_cruise_distance_nmi": (float, 1.0, 100.0),
    "cruise_altitude_ft": (float, 0.0, 25000.0),
    "cruise_speed_mph": (float, 60.0, 300.0),
    "cells_parallel": (int, 1, 400),
    "coupling": (str, "swirl", "local", "freestream"),
    "wing_strips": (int, 8, 60),
    "n_stations": (int, 6, 40),
    "approach_speed_kn": (float, 60.0, 120.0),
    "wake_core_rel": AIRCRAFT_OPTIONS["wake_core_rel"],
    "engine_out": AIRCRAFT_OPTIONS["engine_out"],
    "fin_sizing": AIRCRAFT_OPTIONS["fin_sizing"],
    "leakage_fraction": AIRFRAME_OPTIONS["leakage_fraction"],
}


def build(analysis: bool = False, nodes: int = 6, cruise_distance_nmi: float = 12.5,
          reserve_cruise_distance_nmi: float = 5.0, cruise_altitude_ft: float = 8000.0,
          cruise_speed_mph: float = 172.0, cells_parallel: int = 40, coupling: str = "local",
          wing_strips: int = 20, n_stations: int = 12, approach_speed_kn: float = APPROACH_SPEED_MPS / KNOT,
          trim: bool = True, wing_viscous: bool | None = None,
          blown_profile_drag: bool = True, engine_out: str | None = None, fin_sizing: bool = False, wake_core_rel: float = DEFAULT_CORE_REL,
          leakage_fraction: float | None = None):
    p = Problem("x57_mod4", "X-57 Maxwell Mod IV whole-mission optimization (two rotor groups)")
    cfg = x57_mod4(cells_parallel, cruise_speed_mph * MPH, cruise_altitude_ft * FT)
    cfg = airframe_variant(cfg, leakage_fraction=leakage_fraction)   # the defaults return cfg itself
    vehicle = Aircraft(cfg, trim=trim, wing_viscous=wing_viscous, blown_profile_drag=blown_profile_drag, free=("rotor", "wing"), n_stations=n_stations, wing_strips=wing_strips,
                       coupling=coupling, design_point_constraints=not analysis, wake_core_rel=wake_core_rel, engine_out=engine_out, fin_sizing=fin_sizing)
    folded = {s: {"highlift.active": 0.0} for s in ("CL", "CR", "D", "DL", "RCL", "RCR", "RD")}
    segs = ga_segments(cruise_distance_m=cruise_distance_nmi * NMI,
                       reserve_cruise_distance_m=reserve_cruise_distance_nmi * NMI,
                       cruise_altitude_m=cruise_altitude_ft * FT, cruise_speed_mps=cruise_speed_mph * MPH,
                       approach_drag_area_m2=0.40, extra=folded)
    # the X-57's own battery-sizing profile (SIZING_PROFILE): climb and descend at its rates
    by_name = {s.name: s for s in segs}
    by_name["CL"].climb_rate_mps = CLIMB_RATE_MPS
    by_name["D"].climb_rate_mps = -DESCENT_RATE_MPS
    # the X-57's own approach: final at 1.3 x its 58 kn stall speed (75 kn), not Table 5's 78 mph
    segs[-2].speed_end_mps = (approach_speed_kn + 10) * KNOT    # base leg
    segs[-1].speed_end_mps = approach_speed_kn * KNOT           # final approach
    mission = Mission(vehicle, segs, nodes=nodes, name="GA profile (Table 5), X-57 approach speeds").build(p)
    return minimize_battery_energy(p, vehicle, mission)
