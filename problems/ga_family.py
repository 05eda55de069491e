"""GA-nP: the GA-2P airframe with n = 2, 4, ..., 12 propellers along the span, each layout optimized.

The number of propellers is the paper's future work (Clarke et al., Sec. VII); swept by
``mdo sweep problems/ga_family.py --grid n_props=2,4,6,8,10,12``.  Everything but the
propeller group is GA-8P (``problems/ga8p.py``: the same airframe, battery, objective
Eq. 7, design variables = Adkins-Liebeck inputs + span, taper, twists; positions fixed).
The propeller group for n propellers, k = n/2 per side, is GA-8P's scaled by rules of
ours (stated, not from the paper; n = 8 gives GA-8P's initial design back — initial objective 60.752047 kWh for both at main d8b8071):

* positions equally spaced from inboard to the tip, ``eta_i = i/k`` (i = 1..k), as GA-8P's
  0.25 ... 1.00 (n = 2: one wing-tip propeller a side, NOT GA-2P's eta = 0.23);
* the same total disk area as GA-8P: ``R0 = 0.58 m sqrt(8/n)``, capped at 0.9 R_max, with
  ``R_max = (b/(2k) - c)/2`` the radius at which neighbouring disks touch at the baseline
  span (clearance c = 0.05 m, ``DesignBounds.tip_clearance_m``); the radius bounds are
  GA-8P's (``DesignBounds``), and the disk-clearance constraint keeps the disks apart
  as span and radius move (an extra box at R_max would be a baseline-span copy of it);
* the same total design thrust (8 x 350 N) and initial motor rating (8 x 25.19 kW, the
  optimizer sizes the motors) shared by n;
* design rpm for tip Mach 0.6 at 0.55/0.58 R0 and 138.58 mph (GA-8P's rule, catalog.py);
* nacelle wetted area 1.2 m^2 (P/25.19 kW)^(2/3) each (a nacelle's volume grows with its
  motor's power), disk offset ahead of the leading edge 0.56 m R0/0.58 m.

Options (``-o KEY=VALUE``): ``n_props`` (8; even, 2..12), and those of ``problems/ga8p.py``.
"""
import math
from dataclasses import replace

from mdo.core import units as u
from mdo.core.errors import InputError
from mdo.core.units import FT, MPH, NMI
from mdo.mission.profiles import ga_mission
from mdo.nlp import Problem
from mdo.studies import AIRCRAFT_OPTIONS, minimize_battery_energy
from mdo.wake import DEFAULT_CORE_REL, DEFAULT_STRIP_SAMPLES
from mdo.vehicle.aircraft import Aircraft, DesignBounds
from mdo.vehicle.catalog import design_rpm_for_tip_mach, ga8p

# allowed values of the -o options (mdo.nlp.options; `mdo run problems/ga_family.py --options`)
OPTIONS = {**AIRCRAFT_OPTIONS,
    "n_props": (int, 2, 12),
    "max_span_m": (float, 5.0, 30.0),
    "approach_drag_area_m2": (float, 0.0, 2.0),
}

N_REF, R_REF_M, THRUST_REF_N, POWER_REF_W, NACELLE_REF_M2 = 8, 0.58, 350.0, 25.19e3, 1.2


def family_config(n_props: int, rotation: str = "inboard_up"):
    """(VehicleConfig, R_max) of the GA family member with ``n_props`` propellers."""
    if n_props not in (2, 4, 6, 8, 10, 12):
        raise InputError("n_props", f"one of 2, 4, 6, 8, 10, 12, got {n_props!r}")
    base = ga8p(rotation)
    g, k = base.rotor_groups[0], n_props // 2
    semi = base.main_wing.span_m / 2
    clearance = DesignBounds().tip_clearance_m
    r_max = (semi / k - clearance) / 2 if k > 1 else semi - clearance / 2
    r0 = min(R_REF_M * math.sqrt(N_REF / n_props), 0.9 * r_max)
    share = N_REF / n_props
    group = replace(g, span_eta=tuple((i + 1) / k for i in range(k)), radius_m=r0,
                    design_thrust_N=THRUST_REF_N * share,
                    motor=replace(g.motor, rated_power_W=POWER_REF_W * share),
                    design_rpm=round(design_rpm_for_tip_mach(0.55 / 0.58 * r0, 138.58 * u.MPH, 2500 * u.FT)),
                    x_ahead_of_le_m=0.56 * r0 / R_REF_M, nacelle_wetted_area_m2=NACELLE_REF_M2 * share ** (2 / 3))
    return replace(base, name=f"GA-{n_props}P", rotor_groups=(group,),
                   notes=(f"GA family, {n_props} propellers (problems/ga_family.py)",)), r_max


def build(analysis: bool = False, n_props: int = 8, nodes: int = 6, cruise_distance_nmi: float = 50.0,
          reserve_cruise_distance_nmi: float = 5.0, cruise_altitude_ft: float = 2500.0,
          cruise_speed_mph: float = 175.0, cells_series: int = 120, cells_parallel: int = 80,
          n_stations: int = 16, wing_strips: int = 24, mass_model: str = "buildup", rotation: str = "inboard_up",
          coupling: str = "swirl", swirl_recovery: str = "bounded", limits: bool = True,
          tip_mach_limit: str = "nodes", allow_regeneration: bool = False, max_span_m: float | None = None,
          approach_drag_area_m2: float = 0.40, wake_samples: int = DEFAULT_STRIP_SAMPLES, wake_core_rel: float = DEFAULT_CORE_REL, trim: bool = True, wing_viscous: bool | None = None,
          blown_profile_drag: bool = True, engine_out: str | None = None, fin_sizing: bool = False):
    cfg, _ = family_config(n_props, rotation)
    cfg = replace(cfg, battery=replace(cfg.battery, cells_series=cells_series, cells_parallel=cells_parallel),
                  cruise_speed_mps=cruise_speed_mph * MPH, cruise_altitude_m=cruise_altitude_ft * FT)
    p = Problem("ga_family", f"GA-{n_props}P whole-mission optimization (GA family, Eq. 7)")
    vehicle = Aircraft(cfg, trim=trim, wing_viscous=wing_viscous, blown_profile_drag=blown_profile_drag, free=("rotor", "wing"), n_stations=n_stations, wing_strips=wing_strips,
                       mass_model=mass_model, coupling=coupling, swirl_recovery=swirl_recovery, limits=limits,
                       tip_mach_limit=tip_mach_limit, allow_regeneration=allow_regeneration, max_span_m=max_span_m,
                       design_point_constraints=not analysis, wake_samples=wake_samples, wake_core_rel=wake_core_rel, engine_out=engine_out, fin_sizing=fin_sizing)
    mission = ga_mission(vehicle, nodes=nodes, cruise_distance_m=cruise_distance_nmi * NMI,
                         reserve_cruise_distance_m=reserve_cruise_distance_nmi * NMI,
                         cruise_altitude_m=cruise_altitude_ft * FT, cruise_speed_mps=cruise_speed_mph * MPH,
                         approach_drag_area_m2=approach_drag_area_m2).build(p)
    return minimize_battery_energy(p, vehicle, mission)
