"""Mission time history and figure after a solve: ``mission.csv``, ``mission.png``,
``mission_segments.csv``.

Used as ``problem.add_report(mission.report)``; ``mdo run`` then calls it with the
solution and the run folder.  Columns are SI except angles (degrees, ``*_deg``);
the vehicle supplies what it has (CL, thrust, rotor speed, shaft and battery
power, state of charge ...): every 1 x K output of its node evaluation is written.
"""
from __future__ import annotations

import csv
from pathlib import Path

import casadi as ca
import numpy as np

from ..core.units import KWH

__all__ = ["write_mission_report", "mission_table"]

_FIRST = ["time_s", "altitude_m", "speed_mps", "flight_path_angle_rad", "body_angle_rad", "CL", "thrust_N",
          "rotor_speed_rpm", "shaft_power_W", "battery_power_W", "state_of_charge"]


def mission_table(mission, solution) -> tuple[list[str], np.ndarray, list[str]]:
    """(column names, K x C values, segment name per row) at ``solution``."""
    rows = mission.report_rows()
    order = [k for k in _FIRST if k in rows] + [k for k in rows if k not in _FIRST]
    stacked = ca.vertcat(*[ca.MX(rows[k][0]) if isinstance(rows[k][0], ca.DM) else rows[k][0] for k in order])
    vals = np.asarray(solution.value(stacked), dtype=float).reshape(len(order), mission.K)
    names = []
    for i, k in enumerate(order):
        if rows[k][1] == "rad":
            vals[i] = np.degrees(vals[i])
            names.append(k[:-4] + "_deg" if k.endswith("_rad") else k + "_deg")
        elif rows[k][1] == "rad/s":
            vals[i] = np.degrees(vals[i])
            names.append(k[:-6] + "_degps" if k.endswith("_radps") else k + "_degps")
        else:
            names.append(k)
    return names, vals.T, list(mission.segment_of_node)


def write_mission_report(mission, solution, out_dir, figures: bool = True):
    """Write mission.csv, mission_segments.csv and (with ``figures``) mission.png; returns the csv path."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    names, vals, seg = mission_table(mission, solution)
    node = [lab.rsplit(" ", 1)[-1] for lab in mission.labels]
    path = out / "mission.csv"
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["segment", "node"] + names)
        for k in range(mission.K):
            w.writerow([seg[k], node[k]] + [f"{v:.10g}" for v in vals[k]])
    # per-segment summary
    e_seg = np.atleast_1d(np.asarray(solution.value(mission.segment_energy_J), float)).ravel()
    t = vals[:, names.index("time_s")]
    v = vals[:, names.index("speed_mps")]      # the solved speeds (free where the trajectory is)
    with open(out / "mission_segments.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["segment", "kind", "nodes", "start_s", "duration_s", "altitude_start_m", "altitude_end_m",
                    "speed_start_mps", "speed_end_mps", "energy_kWh"])
        for i, g in enumerate(mission._segs):
            a, b = g.node0, g.node0 + g.n - 1
            w.writerow([g.segment.name, g.segment.kind, g.n, f"{t[a]:.6g}", f"{t[b] - t[a]:.6g}",
                        f"{g.kin.altitude_m[0]:.6g}", f"{g.kin.altitude_m[-1]:.6g}", f"{v[a]:.6g}",
                        f"{v[b]:.6g}", f"{e_seg[i] / KWH:.12g}"])
    if figures:
        from ..plots.figures import plot_mission   # the figure is drawn from the file, as by ``mdo plot``
        plot_mission(path, out / "mission.png")
    return path
