"""Run-folder reports of an :class:`~mdo.vehicle.aircraft.Aircraft` mission.

Written after a solve by ``add_vehicle_reports``:

``mass.md``      the mass build-up at the solution (terms, TOGW, Table 1 comparison)
``loading.csv``  spanwise loading at mid-cruise, with and without the propeller wakes
``blade.csv``    the Adkins-Liebeck blade at the solution (``r_over_R,c_over_R,beta_deg``,
                 the geometry format ``mdo rotor sweep --geometry`` reads)
``design.json``  every design variable and the derived geometry (span, chords, rotor positions)
``energy.md``    where the energy goes per segment: battery, shaft, propulsive, drag, climb
``geometry.json`` surfaces, fuselage, rotors and wake pitch as numbers, drawn by
                 :mod:`mdo.plots.geometry` into ``geometry.png`` (3-D view)
and the design checks (:mod:`mdo.plots.checks`) appended to ``summary.md``/``summary.json``.  The
figures made from these files (loading, rotor, mission, convergence) belong to
``mdo.plots`` (``mdo plot RUN_DIR``), which problem files register after this report.
"""
from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import casadi as ca
import numpy as np

from ..core import units as u
from ..rotor.geometry import station_layout
from .mass import MassDesign, mass_table_markdown

__all__ = ["add_vehicle_reports", "cruise_node", "write_geometry", "energy_breakdown"]


def cruise_node(mission) -> int:
    """Index of the middle node of the cruise segment (the first segment named CR)."""
    idx = [k for k, lab in enumerate(mission.labels) if lab.split(" node ")[0] == "CR"]
    if not idx:
        V = np.concatenate([g.kin.speed_mps for g in mission._segs])   # the profile's speeds
        return int(np.argmax(V))
    return idx[len(idx) // 2]


def _val(solution, expr):
    return np.asarray(solution.value(expr), float) if isinstance(expr, (ca.MX, ca.SX)) else np.asarray(expr, float)


def _design_numbers(vehicle, solution) -> dict:
    d = vehicle.design
    out = {"tip_radius_m": float(_val(solution, d["R"])), "span_eta": _val(solution, d["eta"]).ravel().tolist(),
           "design_thrust_N": float(_val(solution, d["T_design"])),
           "design_speed_mps": float(_val(solution, d["V_design"])),
           "design_cl": float(_val(solution, d["cl_design"])), "wings": {}}
    for name, w in d["wings"].items():
        out["wings"][name] = {"span_m": float(_val(solution, w["span"])), "taper": float(_val(solution, w["taper"])),
                              "twist_deg": np.degrees(_val(solution, w["twist"]).ravel()).tolist()}
        if name in getattr(vehicle, "wing_design_lift", {}):
            out["wings"][name]["design_lift_N"] = float(_val(solution, vehicle.wing_design_lift[name]))
    out["rotor_centers_m"] = [[float(_val(solution, c)) for c in p] for p in vehicle.rotor_positions]
    out["fins"] = {f.name: {"area_m2": f.area_m2 * float(_val(solution, vehicle.fin_area_scale[f.name]))}
                   for f in vehicle.config.fins}
    out["engine_out"] = _engine_out_numbers(vehicle, solution, out)
    out["togw_kg"] = float(_val(solution, vehicle.togw))
    out["battery_mass_kg"] = float(vehicle.config.battery.mass_kg)
    out["rotor_groups"] = {}
    for gm in vehicle.groups:
        gd = gm.design
        out["rotor_groups"][gm.name] = {
            "count": gm.config.count, "tip_radius_m": float(_val(solution, gd["R"])),
            "span_eta": _val(solution, gd["eta"]).ravel().tolist(),
            "design_thrust_N": float(_val(solution, gd["T_design"])),
            "design_speed_mps": float(_val(solution, gd["V_design"])),
            "design_cl": float(_val(solution, gd["cl_design"])),
            "motor_rated_power_W": float(_val(solution, gd["P_rated"])),
            "motor_rated_rpm": float(_val(solution, gd["omega_rated"])) * 60 / (2 * math.pi)}
    return out


def _engine_out_numbers(vehicle, solution, design: dict) -> dict:
    """The rudder's moment per unit q and, per rotor group, its outermost arm and the design's
    minimum control speed at sea level with that motor failed and its mirror at take-off power
    (``mdo.vehicle.engine_out``; whether or not the limit is enforced)."""
    from .engine_out import default_x_cg_m, fin_yaw_moment_per_q_m3, minimum_control_speed_mps
    cfg = vehicle.config
    if not cfg.fins:
        return {}
    x_cg = getattr(vehicle, "x_cg", None)
    x_cg = default_x_cg_m(cfg) if x_cg is None else float(_val(solution, x_cg))
    scale = {f.name: design["fins"][f.name]["area_m2"] / f.area_m2 for f in cfg.fins}
    Nq = float(fin_yaw_moment_per_q_m3(cfg.fins, x_cg, scale))
    out = {"mode": vehicle.engine_out, "rudder_yaw_moment_per_q_m3": Nq, "groups": {}}
    for gm in vehicle.groups:
        g = gm.config
        arm = max(abs(float(_val(solution, p[1]))) for p in vehicle.rotor_centres[g.name])
        P_to = float(_val(solution, gm.design["P_rated"])) * g.motor.take_off_power_factor
        v_mc = minimum_control_speed_mps(Nq, arm, P_to, float(_val(solution, gm.design["R"])),
                                         g.inoperative_drag_coefficient)
        finite = math.isfinite(v_mc)   # (inf: beyond the rudder at any speed; JSON has no inf)
        out["groups"][g.name] = {"arm_m": arm, "take_off_power_W": P_to, "failure_stops_mirror": g.failure_stops_mirror,
                                 "minimum_control_speed_sea_level_mps": v_mc if finite else None,
                                 "minimum_control_speed_sea_level_kn": v_mc / u.KNOT if finite else None}
    return out


def _loading(vehicle, mission, solution, k):
    """Strip y, chord and cl with and without the wakes at node k (numbers)."""
    vlm = vehicle.vlm
    g = vlm.geometry
    y = _val(solution, g["strip_mid"])[1, :]
    chord = _val(solution, g["strip_chord"]).ravel()
    cl_on = _val(solution, mission.evaluation.distributions["strip_cl"].expr)[:, k]
    cond = mission.cond
    alpha = cond.body_angle_rad[:, k] - cond.flight_path_angle_rad[:, k]
    if vehicle.config.kind == "tilt_wing":
        alpha = alpha + vehicle.wing_mounted_angle(cond.parameters, mission.unknowns, cond.size)[:, k]
    V = cond.speed_mps[:, k]
    r_off = vlm.solve(alpha, V)
    cl_off = _val(solution, r_off["cl"]).ravel()
    surf = [vlm.surfaces[i].name for i in vlm.strip_surface]
    dist = mission.evaluation.distributions
    shift = (_val(solution, dist["strip_viscous_shift"].expr)[:, k] if "strip_viscous_shift" in dist else None)
    return y, chord, cl_on, cl_off, surf, shift


def _write_loading(vehicle, mission, solution, out: Path):
    k = cruise_node(mission)
    y, chord, cl_on, cl_off, surf, shift = _loading(vehicle, mission, solution, k)
    b = {n: float(_val(solution, w["span"])) for n, w in vehicle.design["wings"].items()}
    c_ref = vehicle.config.main_wing.mean_aerodynamic_chord_m
    with open(out / "loading.csv", "w", newline="") as f:
        wr = csv.writer(f)
        wr.writerow(["surface", "y_m", "y_over_semispan", "chord_m", "cl_props_on", "cl_props_off", "ccl_over_cref"]
                    + (["viscous_shift_deg"] if shift is not None else []))
        for i in range(y.size):
            semi = b.get(surf[i], 2 * max(abs(y[j]) for j in range(y.size) if surf[j] == surf[i])) / 2
            wr.writerow([surf[i], f"{y[i]:.5f}", f"{y[i] / semi:.5f}", f"{chord[i]:.5f}", f"{cl_on[i]:.6f}",
                         f"{cl_off[i]:.6f}", f"{chord[i] * cl_on[i] / c_ref:.6f}"]
                        + ([f"{math.degrees(shift[i]):.4f}"] if shift is not None else []))
    return k


def _write_blade(vehicle, solution, out: Path):
    """``blade.csv`` for the first rotor group, ``blade_<group>.csv`` for the others."""
    for i, gm in enumerate(vehicle.groups):
        R = _write_group_blade(gm, solution, out / ("blade.csv" if i == 0 else f"blade_{gm.name}.csv"))
        if i == 0:
            R0 = R
    return R0


def _write_group_blade(gm, solution, path: Path):
    n = gm.n_stations
    g = gm.config
    s, _ = station_layout(n)
    h = g.hub_fraction
    R = float(_val(solution, gm.design["R"]))
    r_over_R = h + (1 - h) * np.asarray(s, float)
    chord = _val(solution, gm.blade["chord_m"]).ravel()
    twist = _val(solution, gm.blade["twist_rad"]).ravel()
    with open(path, "w", newline="") as f:
        wr = csv.writer(f)
        wr.writerow(["r_over_R", "c_over_R", "beta_deg"])
        for i in range(n):
            wr.writerow([f"{r_over_R[i]:.5f}", f"{chord[i] / R:.5f}", f"{math.degrees(twist[i]):.4f}"])
    return R


def _fin_outline(w) -> dict:
    """Leading and trailing edge (root, tip) of a vertical fin: linear taper, quarter-chord sweep."""
    cr = w.root_chord_m
    ct = cr * w.taper
    x_le_tip = w.root_le_x_m + 0.25 * cr + w.span_m * math.tan(math.radians(w.sweep_quarter_chord_deg)) - 0.25 * ct
    z = [w.root_z_m, w.root_z_m + w.span_m]
    return {"name": w.name, "image": False, "vertical": True,
            "le": [[w.root_le_x_m, x_le_tip], [0.0, 0.0], z], "te": [[w.root_le_x_m + cr, x_le_tip + ct], [0.0, 0.0], z]}


def _geometry_numbers(vehicle, mission, solution, k: int) -> dict:
    """Everything ``geometry.png`` and ``planform.png`` need, as numbers (SI), so that
    ``mdo plot`` redraws them from the run folder alone (format: :mod:`mdo.plots.geometry`)."""
    surfaces = [{"name": h["surface"], "image": bool(h["image"]), "le": _val(solution, h["le"]).tolist(),
                 "te": _val(solution, h["te"]).tolist()} for h in vehicle.vlm.outline()]
    surfaces += [_fin_outline(w) for w in vehicle.config.wings if w.vertical]   # not in the lattice
    f = vehicle.config.fuselage
    V = float(_val(solution, mission.cond.speed_mps).ravel()[k])
    rotors, pitch0 = [], None
    for gm in vehicle.groups:
        R = float(_val(solution, gm.design["R"]))
        om = float(_val(solution, mission.unknowns[f"{gm.name}.omega"]).ravel()[k])
        va = float(_val(solution, mission.evaluation.outputs[f"{gm.name}.induced_axial_velocity_mps"].expr)
                   .ravel()[k])
        # helix pitch of the fixed wake: (V + mean induced axial velocity) per revolution
        pitch = 2 * math.pi * (V + va) / max(om, 1e-6)
        pitch0 = pitch if pitch0 is None else pitch0
        for rot in vehicle.group_rotors[gm.name]:
            c = rot.center if isinstance(rot.center, tuple) else [rot.center[i] for i in range(3)]
            rotors.append({"group": gm.name, "center_m": [float(_val(solution, x)) for x in c], "radius_m": R,
                           "spin": float(rot.spin), "blades": int(gm.config.blades), "pitch_m": pitch,
                           "axis": [float(a) for a in np.asarray(rot.axis, float).ravel()]})
    return {"name": vehicle.name, "surfaces": surfaces,
            "fuselage": {"length_m": f.length_m, "width_m": f.width_m, "height_m": f.height_m, "nose_x_m": f.nose_x_m,
                         "axis_z_m": vehicle.config.fuselage_axis_z_m},
            "rotors": rotors, "blades": int(vehicle.groups[0].config.blades),   # the group of blade.csv
            "wake": {"pitch_m": pitch0, "node": int(k), "speed_mps": V},
            "reference_area_m2": float(_val(solution, vehicle.S_ref)),
            "reference_chord_m": vehicle.config.main_wing.mean_aerodynamic_chord_m}


def write_geometry(vehicle, mission, solution, out: Path, k: int | None = None, figure: bool = True) -> Path:
    """``geometry.json`` at node ``k`` (mid-cruise by default) and (with ``figure``) ``geometry.png`` from it."""
    k = cruise_node(mission) if k is None else k
    path = Path(out) / "geometry.json"
    path.write_text(json.dumps(_geometry_numbers(vehicle, mission, solution, k), indent=1))
    if figure:
        from ..plots.figures import run_title
        from ..plots.geometry import plot_geometry
        plot_geometry(path, Path(out) / "geometry.png", title=run_title(out, f"{vehicle.name} geometry"))
    return path


def _efficiency(out_kwh: float, in_kwh: float) -> str:
    """out/in to 3 decimals, or "—" where it is no efficiency: energy flowing backwards
    (windmilling, regeneration: out or in <= 0; 1 Wh threshold for quadrature noise), or
    a ratio above 1, which only a segment that mixes forward and backward flow gives."""
    from ..plots.units import DASH
    ok = out_kwh > 1e-3 and in_kwh > 1e-3 and out_kwh <= in_kwh
    return f"{out_kwh / in_kwh:.3f}" if ok else DASH


def energy_breakdown(vehicle, mission, solution) -> str:
    """Where the battery energy goes, per segment: battery -> shaft (motors, ESCs, pack
    losses) -> propulsive work (propeller efficiency) -> drag work (induced, parasite)
    + potential + kinetic energy.  Integrals by each segment's Clenshaw-Curtis weights."""
    from ..core.collocation import Collocation
    from ..plots.units import DASH
    ev = mission.evaluation.outputs
    rows = {k: np.asarray(solution.value(ev[k].expr), float).ravel()
            for k in ("battery_power_W", "shaft_power_W", "thrust_power_W", "drag_N", "induced_drag_N",
                      "parasite_drag_N")}
    V = _val(solution, mission.cond.speed_mps).ravel()
    h = np.asarray(mission.cond.altitude_m, float).ravel()
    m = float(_val(solution, vehicle.togw))
    g0 = 9.80665
    lines = [f"# {vehicle.name}: energy breakdown by segment", "",
             "kWh; battery = chemical energy drawn; shaft = motor output; propulsive = rotor force along the "
             "path x speed; drag = (induced + parasite) x speed; potential m g dh; kinetic m dV^2/2.", "",
             "| segment | time (s) | battery | shaft | propulsive | drag: induced | drag: parasite | potential "
             "| kinetic | chain eff. | prop. eff. |", "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    tot = np.zeros(7)
    for sg in mission._segs:
        idx = slice(sg.node0, sg.node0 + sg.n)
        T = float(_val(solution, sg.duration))
        w = Collocation(sg.n).weights * T
        e = np.array([w @ rows["battery_power_W"][idx], w @ rows["shaft_power_W"][idx],
                      w @ rows["thrust_power_W"][idx], w @ (rows["induced_drag_N"][idx] * V[idx]),
                      w @ (rows["parasite_drag_N"][idx] * V[idx]),
                      m * g0 * (h[idx][-1] - h[idx][0]), 0.5 * m * (V[idx][-1] ** 2 - V[idx][0] ** 2)]) / u.KWH
        tot += e
        lines.append(f"| {sg.segment.name} | {T:.0f} | " + " | ".join(f"{x:.3f}" for x in e)
                     + f" | {_efficiency(e[1], e[0])} | {_efficiency(e[2], e[1])} |")
    lines.append("| **total** | | " + " | ".join(f"**{x:.3f}**" for x in tot)
                 + f" | {_efficiency(tot[1], tot[0])} | {_efficiency(tot[2], tot[1])} |")
    lines += ["", f"Check: propulsive = drag + potential + kinetic to "
              f"{abs(tot[2] - tot[3] - tot[4] - tot[5] - tot[6]) / max(abs(tot[2]), 1e-9) * 100:.2f} % "
              "(the rest is the in-plane rotor force and quadrature).",
              f"Efficiencies are {DASH} where energy flows backwards (shaft or battery energy <= 0: "
              "windmilling or regeneration) or the ratio exceeds 1 (a segment mixing both), where it is no "
              "efficiency.", ""]
    return "\n".join(lines)


def _write_motor_maps(vehicle, mission, solution, design, out: Path) -> None:
    """``motor_map_<group>.png``: the efficiency map of each group's PMSM + inverter at the
    solution's rating, with every segment's operating points (rpm, torque per motor)."""
    from ..powertrain.pmsm import plot_efficiency_map
    ev = mission.evaluation.outputs
    for gm in vehicle.groups:
        if gm.motor.inverter is None:
            continue
        g, rd = gm.config, design["rotor_groups"][gm.name]
        mg = g.motor.drive(g.name, g.count, rd["motor_rated_power_W"], rd["motor_rated_rpm"] * u.RPM, vehicle.pack)
        rpm = np.asarray(solution.value(ev[f"{g.name}.rotor_speed_rpm"].expr), float).ravel()
        shaft = np.asarray(solution.value(ev[f"{g.name}.shaft_power_W"].expr), float).ravel() / g.count
        torque = shaft / np.maximum(rpm * u.RPM, 1e-6)
        points = {}
        for sg in mission._segs:
            k = sg.node0 + sg.n // 2
            if torque[k] > 0:
                points[sg.segment.name] = (rpm[k], torque[k])
        plot_efficiency_map(mg.motor, mg.inverter, out / f"motor_map_{_file_safe(g.name)}.png",
                            title=f"{vehicle.name} {g.name} {rd['motor_rated_power_W'] / 1e3:.0f} kW", points=points)


def _file_safe(name: str) -> str:
    return "".join(ch if ch.isalnum() or ch in "-_" else "_" for ch in name)


def add_vehicle_reports(problem, vehicle, mission, figures: bool = True):
    """Register the vehicle's reports (mass, loading, blade, design, figures) on ``problem``;
    ``figures=False`` leaves geometry.png and the design checks to ``mdo.plots.figure_report``
    (registered after it: each figure is then drawn once)."""

    def vehicle_report(solution, out_dir):
        out = Path(out_dir)
        design = _design_numbers(vehicle, solution)
        rg = design["rotor_groups"]
        md = MassDesign({n: w["span_m"] for n, w in design["wings"].items()},
                        {n: w["taper"] for n, w in design["wings"].items()},
                        {n: g["tip_radius_m"] for n, g in rg.items()},
                        {n: g["motor_rated_power_W"] for n, g in rg.items()},
                        {n: g["motor_rated_rpm"] * 2 * math.pi / 60 for n, g in rg.items()},
                        wing_design_lift_N={n: w["design_lift_N"] for n, w in design["wings"].items()
                                            if "design_lift_N" in w},
                        rotor_span_eta={n: g["span_eta"] for n, g in rg.items()},
                        fin_area_scale={f.name: design["fins"][f.name]["area_m2"] / f.area_m2
                                        for f in vehicle.config.fins})
        (out / "mass.md").write_text(mass_table_markdown(vehicle.config, md))
        (out / "design.json").write_text(json.dumps(design, indent=1))
        (out / "energy.md").write_text(energy_breakdown(vehicle, mission, solution))
        k = _write_loading(vehicle, mission, solution, out)
        _write_blade(vehicle, solution, out)
        write_geometry(vehicle, mission, solution, out, k, figure=figures)
        _write_motor_maps(vehicle, mission, solution, design, out)
        if figures:
            from ..plots.checks import write_design_checks
            write_design_checks(out)

    vehicle_report.vehicle, vehicle_report.mission = vehicle, mission   # for tools that redo one file
    problem.add_report(vehicle_report)
