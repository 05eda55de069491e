"""The GA profile with the fixed-polar airplane and a battery too small to fly it:
an infeasible mission for the failure report (exit 1, named groups and nodes)."""
from mdo.core.units import KWH, LB, NMI
from mdo.mission.profiles import ga_mission
from mdo.nlp import Problem
from mdo.vehicle import PolarVehicle


def build(battery_kWh: float = 10.0, analysis: bool = False):
    p = Problem("small_battery", "a mission the battery cannot fly")
    v = PolarVehicle("ga_polar", mass_kg=3549 * LB, wing_area_m2=14.76, CD0=0.0175, aspect_ratio=8.8,
                     oswald_efficiency=0.8, CL_max=2.0, propulsive_efficiency=0.82, chain_efficiency=0.90,
                     battery_capacity_J=battery_kWh * KWH)
    mission = ga_mission(v, cruise_distance_m=50 * NMI).build(p)
    p.minimize(mission.energy_used_J / KWH, unit="kWh", scale=10.0)
    return p
