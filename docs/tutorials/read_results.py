"""Tutorial 2: read a run folder's results in Python.

    python docs/tutorials/read_results.py [RUN_DIR]

Every number a run writes is in plain files (SI units): ``summary.json`` (status,
objective, summary outputs, design checks), ``solution.json`` (every variable),
``mission.csv`` (one row per collocation node), ``mission_segments.csv``,
``convergence.csv`` (the iteration lines of ``ipopt.log``).  The default folder is the
committed GA-2P optimum, ``results/ga2p``.
"""
import json
import sys
from pathlib import Path

import numpy as np

from mdo.plots import read_csv
from mdo.plots.figures import propulsive_efficiency
from mdo.plots.units import unit_system

REPO = Path(__file__).resolve().parents[2]
run = Path(sys.argv[1]) if len(sys.argv) > 1 else REPO / "results" / "ga2p"

summary = json.loads((run / "summary.json").read_text())
obj = summary["objective"]
print(f"{summary['problem']} ({summary['mode']}): {summary['status']}, {obj['name']} {obj['value']:.3f} {obj['unit']}")

# design variables (name, value in model units, unit)
for v in json.loads((run / "solution.json").read_text())["variables"]:
    if v["design"]:
        print(f"  {v['name']:<28s} {np.round(np.asarray(v['value'], float).ravel(), 4)} {v['unit']}")

# the mission time history: columns by name, SI
m = read_csv(run / "mission.csv")
kt = unit_system("aviation")
cruise = np.array([s == "CR" for s in m["segment"]])
if cruise.any():
    print(f"  cruise: {kt.conv('speed', m['speed_mps'][cruise]).mean():.1f} kt TAS at "
          f"{kt.conv('altitude', m['altitude_m'][cruise]).mean():.0f} ft")
eta = propulsive_efficiency(m)          # nan where thrust or power <= 0 (undefined)
if eta is not None:
    print(f"  propulsive efficiency: {np.nanmin(eta):.3f} to {np.nanmax(eta):.3f} "
          f"({int(np.isnan(eta).sum())} nodes where it is undefined)")

# energy per segment
seg = read_csv(run / "mission_segments.csv")
for name, e in zip(seg["segment"], seg["energy_kWh"]):
    print(f"  {name:<4s} {e:8.3f} kWh")
print(f"  total {np.sum(seg['energy_kWh']):.3f} kWh")
