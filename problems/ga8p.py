"""GA-8P: the GA-2P airframe with eight 5-bladed propellers, optimized over the GA profile (Eq. 7).

As ``problems/ga2p.py``, but the propellers' span positions are held fixed and equally
spaced (as in the paper); the design variables are the propellers' Adkins-Liebeck
inputs and the wing's span, taper and section twists, with every operating limit at
every node.  The initial design violates the tip-Mach constraint (Table 3's footnote),
so ``--analysis`` flies it as given (the limit reported, not enforced) and the
optimization starts infeasible.

Options (``-o KEY=VALUE``): as ``problems/ga2p.py``, the airframe what-ifs included.
"""
from dataclasses import replace

from mdo.core.units import FT, MPH, NMI
from mdo.mission.profiles import ga_mission
from mdo.nlp import Problem
from mdo.studies import (AIRCRAFT_OPTIONS, AIRFRAME_OPTIONS, TRAJECTORY_OPTIONS, airframe_variant,
                         minimize_battery_energy, trajectory_envelope)
from mdo.wake import DEFAULT_CORE_REL, DEFAULT_STRIP_SAMPLES
from mdo.vehicle.aircraft import Aircraft
from mdo.vehicle.catalog import ga8p


# allowed values of the -o options (mdo.nlp.options; `mdo run problems/ga8p.py --options`)
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
    p = Problem("ga8p", "GA-8P whole-mission optimization (Clarke et al. Eq. 7)")
    cfg = ga8p(rotation)
    cfg = replace(cfg, battery=replace(cfg.battery, cells_series=cells_series, cells_parallel=cells_parallel),
                  cruise_speed_mps=cruise_speed_mph * MPH, cruise_altitude_m=cruise_altitude_ft * FT)
    cfg = airframe_variant(cfg, motor_model, sections, leakage_fraction, nacelle_slipstream, cooling_drag,
                           airframe_calibration, wing_mass, max_tip_deflection_pct)
    vehicle = Aircraft(cfg, trim=trim, wing_viscous=wing_viscous, blown_profile_drag=blown_profile_drag, free=("rotor", "wing"), n_stations=n_stations, wing_strips=wing_strips,
                       mass_model=mass_model, coupling=coupling, swirl_recovery=swirl_recovery, limits=limits,
                       tip_mach_limit=tip_mach_limit, allow_regeneration=allow_regeneration, max_span_m=max_span_m,
                       design_point_constraints=not analysis, wake_samples=wake_samples, wake_core_rel=wake_core_rel, engine_out=engine_out, fin_sizing=fin_sizing)
    mission = ga_mission(vehicle, nodes=nodes, cruise_distance_m=cruise_distance_nmi * NMI,
                         reserve_cruise_distance_m=reserve_cruise_distance_nmi * NMI,
                         cruise_altitude_m=cruise_altitude_ft * FT, cruise_speed_mps=cruise_speed_mph * MPH,
                         approach_drag_area_m2=approach_drag_area_m2, trajectory=trajectory,
                         envelope=trajectory_envelope(max_block_time_min, min_climb_gradient_pct)).build(p)
    return minimize_battery_energy(p, vehicle, mission)
