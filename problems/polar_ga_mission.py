"""The GA profile of Table 5 flown by an X-57-like airplane with a fixed drag polar.

A quick full-profile run of the mission machinery (CGL collocation of every GA
segment, force balance at each node, battery energy integrated) before the real
GA-2P exists: ``mdo run problems/polar_ga_mission.py``.  It writes the usual run
folder plus ``mission.csv``, ``mission_segments.csv`` and ``mission.png``.

The vehicle is NOT the paper's GA-2P model; its numbers are chosen, not validated:

* mass 3549 lb (Table 1 TOGW of GA-2P), wing 14.76 m^2 and 11.4 m span (Table 1);
* Oswald efficiency 0.8 (assumed), lift slope 2 pi AR/(AR + 2), CL_max 2.0 with
  approach flaps (the smooth stall model of ``PolarVehicle``);
* CD0 = 0.0175, chosen so that the 175 mph cruise at 2500 ft needs about
  2 x 53 kW of shaft power, the rating of Table 1's two motors;
* propulsive efficiency 0.82, chain efficiency 0.90 (motor 0.95 x ESC 0.98 x
  battery 0.97), battery 120s x 80p of 3.55 Ah, 3.6 V cells = 122.7 kWh (Table 1).

Options (``-o KEY=VALUE``): ``nodes`` per segment, ``cruise_distance_nmi`` (50),
``reserve_cruise_distance_nmi`` (5), ``design_wing_area`` (false: analysis of the
fixed vehicle; true: the wing area becomes a design variable in [10, 25] m^2 -
the mass does not follow it, so read the result as an aerodynamic trade only),
``state_form`` ("differentiation" or "integration").
"""
from mdo.core.units import KWH, LB, NMI
from mdo.mission.profiles import ga_mission
from mdo.nlp import Problem
from mdo.vehicle import PolarVehicle

SPAN_M = 11.4
AREA_M2 = 14.76
CELLS = 120 * 80
CELL_WH = 3.55 * 3.6


def vehicle(design_wing_area: bool = False) -> PolarVehicle:
    return PolarVehicle(
        "ga_polar", mass_kg=3549 * LB, wing_area_m2=AREA_M2, CD0=0.0175, aspect_ratio=SPAN_M ** 2 / AREA_M2,
        oswald_efficiency=0.8, CL_max=2.0, propulsive_efficiency=0.82, chain_efficiency=0.90,
        battery_capacity_J=CELLS * CELL_WH * 3600.0,
        design_wing_area=(10.0, 25.0) if design_wing_area else None)


# allowed values of the -o options (mdo.nlp.options; `mdo run problems/polar_ga_mission.py --options`)
OPTIONS = {
    "nodes": (int, 3, 30),
    "cruise_distance_nmi": (float, 1.0, 300.0),
    "reserve_cruise_distance_nmi": (float, 1.0, 100.0),
    "design_wing_area": (bool,),
    "state_form": (str, "differentiation", "integration"),
}


def build(nodes: int = 6, cruise_distance_nmi: float = 50.0, reserve_cruise_distance_nmi: float = 5.0,
          design_wing_area: bool = False, state_form: str = "differentiation", analysis: bool = False):
    p = Problem("polar_ga_mission", "GA profile of Table 5 with an X-57-like fixed-polar airplane")
    mission = ga_mission(vehicle(design_wing_area), nodes=nodes, state_form=state_form,
                         cruise_distance_m=cruise_distance_nmi * NMI,
                         reserve_cruise_distance_m=reserve_cruise_distance_nmi * NMI).build(p)
    p.minimize(mission.energy_used_J / KWH, unit="kWh", scale=10.0, name="battery energy used")
    p.add_report(mission.report)
    p.meta["segments"] = mission.summary_table()
    return p
