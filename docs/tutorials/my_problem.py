"""Tutorial 4: define your own problem file (and your own aircraft).

    mdo run docs/tutorials/my_problem.py -o wing_area_m2=16 --out results/my_problem
    python docs/tutorials/my_problem.py          # the same from Python

A problem file is a Python file with ``build(**options) -> mdo.nlp.Problem``; its
keyword arguments are the ``-o KEY=VALUE`` options.  This one flies an airplane of
your own — a fixed drag polar (``mdo.vehicle.PolarVehicle``) of your chosen mass, wing
and efficiencies — over the GA mission profile, and lets IPOPT choose the wing area
that needs the least battery energy (the mass does not follow the area here: read it
as an aerodynamic trade).  Numbers below are this tutorial's choice, not a paper's.
"""
from mdo.core.units import KWH, NMI
from mdo.mission.profiles import ga_mission
from mdo.nlp import Problem
from mdo.vehicle import PolarVehicle


def build(wing_area_m2: float = 14.0, mass_kg: float = 1500.0, cruise_distance_nmi: float = 30.0,
          nodes: int = 5):
    aircraft = PolarVehicle("my_airplane", mass_kg=mass_kg, wing_area_m2=wing_area_m2, CD0=0.02,
                            aspect_ratio=9.0, oswald_efficiency=0.8, CL_max=2.0, propulsive_efficiency=0.8,
                            chain_efficiency=0.9, battery_capacity_J=120 * KWH,
                            design_wing_area=(8.0, 30.0))   # a design variable; --analysis freezes it
    p = Problem("my_problem", "my airplane over the GA profile, wing area free")
    mission = ga_mission(aircraft, nodes=nodes, cruise_distance_m=cruise_distance_nmi * NMI,
                         reserve_cruise_distance_m=5 * NMI).build(p)
    p.minimize(mission.energy_used_J / KWH, unit="kWh", scale=10.0, name="battery energy used")
    p.add_report(mission.report)      # mission.csv, mission_segments.csv, mission.png
    return p


if __name__ == "__main__":
    import sys
    from pathlib import Path

    from mdo.nlp import run_problem
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("tutorial_runs") / "my_problem"
    sol = run_problem(build(), out, force=True, verbose=False)
    print(f"{sol.status}: {sol.objective:.3f} kWh with a wing of {sol['my_airplane.wing_area']:.2f} m^2 "
          f"(started from 14 m^2); run folder {out}")
