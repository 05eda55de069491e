"""The eVTOL profile of Table 5 flown by a tilt-wing fixed-polar vehicle; writes
results/mission/evtol_polar/ (mission.csv, mission_segments.csv, mission.png, summary).

The vehicle is a stand-in until the TTW exists (numbers chosen, not validated):
Table 1's 4850 lb and 21.7 m^2 (two 9.6 m wings), Oswald 0.8, CD0 0.03, CL_max 1.5
with a flat-plate drag of 1.2 sin^2(alpha) for the tilted wing, eight 2.4 m rotors
(momentum theory, figure of merit 0.8), chain efficiency 0.9, braking thrust allowed
down to -W/2 (Table 5's approach transition decelerates at 0.18 g).
Run: ``python tests/bench/mission_evtol_polar.py``.
"""
import math
import sys
import time
from pathlib import Path

from mdo.core.units import KWH, LB
from mdo.mission.profiles import evtol_mission
from mdo.nlp import Problem
from mdo.vehicle import G0, PolarVehicle

OUT = Path(__file__).resolve().parents[2] / "results" / "mission" / "evtol_polar"


def vehicle():
    m = 4850 * LB
    return PolarVehicle("ttw_polar", mass_kg=m, wing_area_m2=21.7, CD0=0.03, aspect_ratio=9.6 ** 2 / (21.7 / 2),
                        oswald_efficiency=0.8, CL_max=1.5, flat_plate_drag_coefficient=1.2, wing_tilts=True,
                        propulsive_efficiency=0.8, chain_efficiency=0.9, disk_area_m2=8 * math.pi * 1.2 ** 2,
                        min_thrust_N=-0.5 * m * G0, battery_capacity_J=150 * 120 * 3.55 * 3.6 * 3600)


def main():
    p = Problem("evtol_polar")
    m = evtol_mission(vehicle()).build(p)
    p.minimize(m.energy_used_J / KWH, unit="kWh", name="battery energy used")
    t0 = time.perf_counter()
    sol = p.solve(verbose=False, log_path=OUT / "ipopt.log")
    print(f"{sol.status} in {sol.iterations} iterations, {time.perf_counter() - t0:.3f} s; "
          f"battery energy {sol['battery_energy_kWh']:.3f} kWh, {sol['mission_time_min']:.1f} min, "
          f"{sol['mission_range_nmi']:.1f} nmi")
    sol.save(OUT)
    m.report(sol, OUT)
    (OUT / "segments.md").write_text(m.summary_table() + "\n")
    return 0 if sol.success else 1


if __name__ == "__main__":
    sys.exit(main())
