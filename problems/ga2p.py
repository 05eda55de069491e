"""GA-2P: the X-57 Mod II airframe with two propellers, optimized over the GA profile (Eq. 7).

``mdo run problems/ga2p.py`` minimizes the battery energy used over the GA profile of
Table 5 with respect to the Adkins-Liebeck inputs of the propellers (design thrust,
design speed, tip radius, design cl), the main wing's span, taper and five section
twists at constant reference area, and the propellers' span position, subject to the
design-point tip Mach <= 0.6, disk clearance and the mission itself, in one IPOPT
solve.  ``--analysis`` freezes the design at Table 3's initial values.

Options (``-o KEY=VALUE``): ``nodes`` per segment (6), ``cruise_distance_nmi`` (50),
``reserve_cruise_distance_nmi`` (5), ``n_stations`` (16), ``wing_strips`` (24),
``mass_model`` ("buildup" or "fixed"), ``rotation`` ("inboard_up"), ``coupling`` ("swirl",
"local" or "freestream": how the wake enters the wing forces, see mdo/wake/README.md),
``approach_drag_area_m2`` (0: the propellers windmill for all the braking the base leg and
final approach need, as in the paper; ``mdo.vehicle.catalog.GA_APPROACH_DRAG_AREA_M2`` =
0.40 m^2 lets the pilot add gear and flap drag there, a control per node), ``wake_samples``
(5: points across each lattice strip at which the propeller wake is averaged; 1 = at the
control point only, which makes the energy ripple with the rotor position).
"""
from mdo.core.units import NMI
from mdo.mission.profiles import ga_mission
from mdo.nlp import Problem
from mdo.studies import minimize_battery_energy
from mdo.vehicle.aircraft import Aircraft
from mdo.vehicle.catalog import ga2p


# allowed values of the -o options (mdo.nlp.options; `mdo run problems/ga2p.py --options`)
OPTIONS = {
    "nodes": (int, 3, 30),
    "cruise_distance_nmi": (float, 1.0, 300.0),
    "reserve_cruise_distance_nmi": (float, 1.0, 100.0),
    "n_stations": (int, 6, 40),
    "wing_strips": (int, 8, 60),
    "approach_drag_area_m2": (float, 0.0, 2.0),
    "mass_model": (str, "buildup", "fixed"),
    "rotation": (str, "inboard_up", "outboard_up"),
    "coupling": (str, "swirl", "local", "freestream"),
    "wake_samples": (int, 1, 15),
}


def build(analysis: bool = False, nodes: int = 6, cruise_distance_nmi: float = 50.0,
          reserve_cruise_distance_nmi: float = 5.0, n_stations: int = 16, wing_strips: int = 24,
          mass_model: str = "buildup", rotation: str = "inboard_up", coupling: str = "swirl",
          approach_drag_area_m2: float = 0.0, wake_samples: int = 5):
    p = Problem("ga2p", "GA-2P whole-mission optimization (Clarke et al. Eq. 7)")
    vehicle = Aircraft(ga2p(rotation), n_stations=n_stations, wing_strips=wing_strips, mass_model=mass_model,
                       coupling=coupling, design_point_constraints=not analysis,
                       wake_samples=wake_samples)
    mission = ga_mission(vehicle, nodes=nodes, cruise_distance_m=cruise_distance_nmi * NMI,
                         reserve_cruise_distance_m=reserve_cruise_distance_nmi * NMI,
                         approach_drag_area_m2=approach_drag_area_m2).build(p)
    return minimize_battery_energy(p, vehicle, mission)
