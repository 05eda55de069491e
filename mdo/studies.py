"""Glue shared by the aircraft problem files: the paper's objective and the run-folder
reports.  Sits on top of the disciplines (like ``cli``); problem files call it after
building their vehicle and mission."""
from __future__ import annotations

import re

from .core.units import KWH
from .plots import figure_report
from .vehicle.reports import add_vehicle_reports
from .wake.mean import table_core_rels

__all__ = ["minimize_battery_energy", "AIRCRAFT_OPTIONS", "AIRFRAME_OPTIONS", "airframe_variant"]

#: allowed values of the ``-o`` options every whole-mission aircraft problem shares
#: (``mdo.nlp.options``): a problem file writes ``OPTIONS = {**AIRCRAFT_OPTIONS, ...its own}``
AIRCRAFT_OPTIONS = {
    "nodes": (int, 3, 30),
    "cruise_distance_nmi": (float, 1.0, 300.0),
    "reserve_cruise_distance_nmi": (float, 1.0, 100.0),
    "cruise_altitude_ft": (float, 0.0, 25000.0),
    "cruise_speed_mph": (float, 60.0, 300.0),
    "cells_series": (int, 10, 400),
    "cells_parallel": (int, 1, 400),
    "n_stations": (int, 6, 40),
    "wing_strips": (int, 8, 60),
    "mass_model": (str, "buildup", "fixed"),
    "rotation": (str, "inboard_up", "outboard_up"),
    "coupling": (str, "swirl", "local", "freestream"),
    "swirl_recovery": (str, "bounded", "unbounded"),
    "limits": (bool,),
    "tip_mach_limit": (str, "nodes", "design_point", "off"),
    "allow_regeneration": (bool,),
    "wake_samples": (int, 1, 15),
    "wake_core_rel": (float, min(table_core_rels()), max(table_core_rels())),   # the shipped tables' range
    "trim": (bool,),
    "wing_viscous": (bool,),
    "blown_profile_drag": (bool,),
    "engine_out": (str, "rudder", "off"),
    "fin_sizing": (bool,),
}

#: the free-trajectory options of a problem that offers them (problems/ga2p.py, ga8p.py)
TRAJECTORY_OPTIONS = {
    "trajectory": (str, "prescribed", "free"),
    "max_block_time_min": (float, 1.0, 1000.0),
    "min_climb_gradient_pct": (float, 0.0, 50.0),
}


#: what-if options on the airframe and motor models (problems/ga2p.py, ga8p.py, ttw.py): the
#: term-by-term reconciliation with the paper's assumptions (results/table3_reconciliation.md)
AIRFRAME_OPTIONS = {
    "motor_model": (str, "pmsm", "dc"),
    "sections": (str, "as_defined", "free_transition"),
    "leakage_fraction": (float, 0.0, 0.5),
    "nacelle_slipstream": (bool,),
    "cooling_drag": (bool,),
    "airframe_calibration": (float, 0.5, 1.5),
    "wing_mass": (str, "bending", "raymer"),
    "max_tip_deflection_pct": (float, 1.0, 100.0),
}


def airframe_variant(cfg, motor_model: str = "pmsm", sections: str = "as_defined", leakage_fraction=None,
                     nacelle_slipstream: bool = True, cooling_drag: bool = True, airframe_calibration=None,
                     wing_mass: str = "bending", max_tip_deflection_pct=None):
    """``cfg`` with the what-ifs of ``AIRFRAME_OPTIONS``: every motor group's ``model``;
    ``sections="free_transition"`` drops the transition setting of every wing's and rotor's
    airfoil (``"NACA_63_412@xtr=0.1"`` -> the free-transition XFOIL polar ``"NACA_63_412"``);
    the leakage fraction, nacelles in the slipstream, cooling drag on/off
    (``VehicleConfig.drag``); ``airframe_calibration`` replaces the mass build-up's one factor
    on the non-battery terms (``mass_inputs``; 1.0: the raw regressions); ``wing_mass="raymer"``
    drops the lifting wings' ``WingStructure`` (their mass is Raymer's Eq. 15.46 alone, the
    regression outside its data beyond AR ~12); ``"bending"`` (default) keeps ``cfg``'s, or
    gives the aluminium defaults where it has none (``mdo.vehicle.wing_structure``);
    ``max_tip_deflection_pct`` replaces its stiffness criterion (limit-load tip deflection, percent
    of the semispan; 100: in effect strength alone).  The defaults return ``cfg``'s own models."""
    from dataclasses import replace
    free = sections == "free_transition"
    # every section's transition setting, also in a radial distribution ("A@xtr=0.1:0.35:B@xtr=0.1")
    strip = (lambda name: re.sub(r"@[^:;+]*", "", name)) if free else (lambda name: name)
    groups = tuple(replace(g, airfoil=strip(g.airfoil), motor=replace(g.motor, model=motor_model))
                   for g in cfg.rotor_groups)
    wings = tuple(replace(w, airfoil=strip(w.airfoil)) for w in cfg.wings)
    d = cfg.drag
    drag = replace(d, leakage_protuberance_fraction=d.leakage_protuberance_fraction if leakage_fraction is None
                   else float(leakage_fraction), nacelles_in_slipstream=bool(nacelle_slipstream),
                   cooling_momentum_loss=d.cooling_momentum_loss if cooling_drag else 0.0)
    mass_inputs = cfg.mass_inputs if airframe_calibration is None else \
        {**cfg.mass_inputs, "airframe_calibration": float(airframe_calibration)}
    structure = cfg.wing_structure
    if wing_mass == "raymer":
        structure = None
    elif structure is None:
        from .vehicle.wing_structure import WingStructure
        structure = WingStructure()
    if structure is not None and max_tip_deflection_pct is not None:
        structure = replace(structure, max_tip_deflection_fraction=float(max_tip_deflection_pct) / 100.0)
    return replace(cfg, rotor_groups=groups, wings=wings, drag=drag, mass_inputs=mass_inputs,
                   wing_structure=structure)


def trajectory_envelope(max_block_time_min=None, min_climb_gradient_pct=None):
    """The default free-trajectory ``Envelope`` with the problem's block-time option (min) and
    climb-gradient rule (percent; default ``Envelope.min_climb_gradient``, 14 CFR 23.65's 8.3 %)."""
    from .mission.trajectory import Envelope
    extra = {} if min_climb_gradient_pct is None else {"min_climb_gradient": min_climb_gradient_pct / 100.0}
    return Envelope(max_block_time_s=None if max_block_time_min is None else max_block_time_min * 60.0, **extra)


def minimize_battery_energy(problem, vehicle, mission, *, max_iter: int = 500):
    """Objective E_EOF of Eq. 7 (kWh, scaled by 10 kWh) and every report: mission.csv and
    mission.png, mass, energy breakdown, loading, blade, design, geometry, and the
    figures of ``mdo plot``."""
    problem.minimize(mission.energy_used_J / KWH, unit="kWh", scale=10.0, name="battery energy used")
    problem.ipopt_options["max_iter"] = int(max_iter)

    def mission_report(solution, out_dir):   # the data; figure_report draws every figure once
        return mission.report(solution, out_dir, figures=False)

    problem.add_report(mission_report)
    add_vehicle_reports(problem, vehicle, mission, figures=False)
    problem.add_report(figure_report)
    return problem
