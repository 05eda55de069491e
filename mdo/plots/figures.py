"""Figures from the files of a run folder (so that ``mdo plot`` can redo them):
mission profile (``mission.csv``), spanwise loading (``loading.csv``, with a baseline
``analysis/loading.csv`` overlaid when present) and rotor (``blade.csv`` + ``mission.csv``).

Every figure takes ``units="si"|"aviation"`` (:mod:`mdo.plots.units`): one unit system
per figure, stated on every axis.  Titles name the problem (``summary.json``), not the
folder.  Efficiencies are drawn only where they are defined (thrust and shaft power > 0).
"""
from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np

from .units import defined_ratio, equivalent_airspeed, unit_system

__all__ = ["read_csv", "plot_mission", "plot_loading", "plot_rotor", "run_title", "propulsive_efficiency"]


def read_csv(path) -> dict:
    """Columns of a CSV file: numbers as float arrays, text as lists."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise ValueError(f"{path}: no rows")
    out = {}
    for key in rows[0]:
        vals = [r[key] for r in rows]
        try:
            out[key] = np.array([float(v) for v in vals])
        except ValueError:
            out[key] = vals
    return out


def run_title(run_dir, what: str) -> str:
    """'what: PROBLEM optimum' or 'what: PROBLEM baseline (analysis)' from ``summary.json``;
    the folder name only when the folder has no readable summary."""
    run = Path(run_dir)
    try:
        s = json.loads((run / "summary.json").read_text())
        name = s.get("problem") or run.name
        mode = s.get("mode", "")
    except (OSError, ValueError):
        return f"{what}: run folder {run.name}"
    if mode == "analysis":
        return f"{what}: {name}, baseline design (analysis)"
    return f"{what}: {name}, optimum" if mode == "optimization" else f"{what}: {name}"


def _plt():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _segments(ax, d):
    seg = d.get("segment")
    if seg is None:
        return
    t = d["time_s"] / 60.0
    for i in range(1, len(seg)):
        if seg[i] != seg[i - 1]:
            ax.axvline(t[i], color="0.85", lw=0.6, zorder=0)


def _segment_labels(ax, d, fontsize=7):
    """Segment names above the axes, in as many rows as needed so that none overlaps
    (greedy: each name goes to the lowest row whose last name ends before it starts)."""
    seg = d.get("segment")
    if seg is None:
        return
    t = d["time_s"] / 60.0
    starts = [i for i in range(len(seg)) if i == 0 or seg[i] != seg[i - 1]]
    lo, hi = ax.get_xlim()
    fig = ax.figure
    width_pt = ax.get_position().width * fig.get_figwidth() * 72.0
    per_pt = (hi - lo) / width_pt
    row_end = []
    for i in starts:
        x = t[i]
        w = (len(seg[i]) + 1) * 0.62 * fontsize * per_pt
        row = next((r for r, e in enumerate(row_end) if e < x), len(row_end))
        if row == len(row_end):
            row_end.append(0.0)
        row_end[row] = x + w
        ax.annotate(seg[i], (x, 1.0), xycoords=("data", "axes fraction"), xytext=(1, 2 + 8.5 * row),
                    textcoords="offset points", fontsize=fontsize, va="bottom", ha="left", color="0.25")
        ax.axvline(x, color="0.6", lw=0.5, zorder=0)


def propulsive_efficiency(d: dict):
    """Propulsive efficiency per node from ``mission.csv`` columns, ``nan`` where undefined:
    thrust power / shaft power needs thrust, thrust power and shaft power > 0."""
    if "thrust_power_W" in d and "shaft_power_W" in d:
        eta = defined_ratio(d["thrust_power_W"], d["shaft_power_W"])
        if "propulsive_efficiency" in d:   # the vehicle's own (axial) definition, on the same mask
            eta = np.where(np.isfinite(eta) & (d["propulsive_efficiency"] > 0), d["propulsive_efficiency"], np.nan)
        if "thrust_N" in d:
            eta = np.where(d["thrust_N"] > 0, eta, np.nan)
        return eta
    if "propulsive_efficiency" in d:
        return np.where(d["propulsive_efficiency"] > 0, d["propulsive_efficiency"], np.nan)
    return None


def _mission_title(run: Path, minutes: float) -> str:
    title = run_title(run, "mission profile")
    seg = run / "mission_segments.csv"
    if seg.exists():
        e = read_csv(seg).get("energy_kWh")
        if e is not None:
            title += f"; battery energy {float(np.sum(e)):.3f} kWh"
    return title + f", {minutes:.1f} min"


def plot_mission(mission_csv, out_png, title=None, units="si"):
    """Altitude, airspeed (TAS and EAS), power and state of charge vs time, segments named."""
    plt = _plt()
    us = unit_system(units)
    d = read_csv(mission_csv)
    t = d["time_s"] / 60.0
    fig, ax = plt.subplots(2, 2, figsize=(12, 7.5), sharex=True)
    ax[0, 0].plot(t, us.conv("altitude", d["altitude_m"]), ".-", ms=3)
    ax[0, 0].set_ylabel(us.label("altitude", "altitude"))
    ax[0, 1].plot(t, us.conv("speed", d["speed_mps"]), ".-", ms=3, label="true airspeed (TAS)")
    ax[0, 1].plot(t, us.conv("speed", equivalent_airspeed(d["speed_mps"], d["altitude_m"])), "--", lw=1,
                  label="equivalent airspeed (EAS, ISA)")
    if "profile_time_s" in d:   # a free trajectory: the prescribed profile it departs from
        tp = d["profile_time_s"] / 60.0
        ax[0, 0].plot(tp, us.conv("altitude", d["altitude_m"]), ":", color="0.4", lw=1.2, label="prescribed profile")
        ax[0, 1].plot(tp, us.conv("speed", d["profile_speed_mps"]), ":", color="0.4", lw=1.2,
                      label="prescribed profile (TAS)")
        ax[0, 0].legend(fontsize=8)
    ax[0, 1].set_ylabel(us.label("airspeed", "speed"))
    ax[0, 1].legend(fontsize=8)
    for key, lab in (("battery_power_W", "battery (chemical)"), ("shaft_power_W", "shaft, all motors")):
        if key in d:
            ax[1, 0].plot(t, us.conv("power", d[key]), ".-", ms=3, label=lab)
    ax[1, 0].set_ylabel(us.label("power", "power"))
    ax[1, 0].legend(fontsize=8)
    if "state_of_charge" in d:
        ax[1, 1].plot(t, d["state_of_charge"], ".-", ms=3)
        ax[1, 1].set_ylabel("state of charge (-)")
    else:
        e = next((k for k in d if k.endswith("energy_J") or k.endswith("_energy_used_J")), None)
        if e is not None:
            ax[1, 1].plot(t, d[e] / 3.6e6, ".-", ms=3)
            ax[1, 1].set_ylabel(f"{e[:-2]} (kWh)")
    for a in ax.ravel():
        _segments(a, d)
        a.grid(True, alpha=0.3)
    for a in ax[1]:
        a.set_xlabel("time (min)")
    fig.suptitle(title or _mission_title(Path(mission_csv).parent, t[-1]))
    fig.tight_layout(rect=(0, 0, 1, 0.93))
    for a in ax[0]:
        _segment_labels(a, d)
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png


def _rotor_spans(run: Path):
    """(surface or None, y centre, R) of every rotor on the right half: from geometry.json
    (which knows each rotor's surface), else design.json (surface unknown)."""
    g = run / "geometry.json"
    if g.exists():
        from .geometry import rotor_surfaces
        return rotor_surfaces(json.loads(g.read_text()))
    dj = run / "design.json"
    if dj.exists():
        d = json.loads(dj.read_text())
        R = d.get("tip_radius_m")
        return [(None, c[1], R) for c in d.get("rotor_centers_m", []) if R and c[1] > 0]
    return []


def _loading_line(ax, d, name, us, style, label):
    m = np.array([s == name for s in d["surface"]])
    order = np.argsort(d["y_m"][m])
    y = us.conv("length", d["y_m"][m][order])
    if "ccl_over_cref" in d:
        ax.plot(y, d["ccl_over_cref"][m][order], style, ms=3, lw=1.2, label=label)
    return y, m, order


def plot_loading(loading_csv, out_png, baseline=None, title=None, units="si"):
    """Spanwise loading c·cl/c_ref (props on and off) on every surface, the propeller disks
    shaded, the baseline design overlaid."""
    plt = _plt()
    us = unit_system(units)
    run = Path(loading_csv).parent
    d = read_csv(loading_csv)
    ok = np.abs(d["ccl_over_cref"]) > 1e-9   # c_ref: the file's own c cl / (c cl / c_ref)
    c_ref = float(np.median(d["chord_m"][ok] * d["cl_props_on"][ok] / d["ccl_over_cref"][ok]))
    surfaces = list(dict.fromkeys(d["surface"]))
    fig, axes = plt.subplots(len(surfaces), 1, figsize=(8.5, 3.4 * len(surfaces)), squeeze=False)
    base = read_csv(baseline) if baseline is not None and Path(baseline).exists() else None
    rotors = _rotor_spans(run)
    for ax, name in zip(axes[:, 0], surfaces):
        y, m, order = _loading_line(ax, d, name, us, "b.-", "with propeller wakes")
        ax.plot(y, (d["chord_m"] * d["cl_props_off"])[m][order] / c_ref, "k--", lw=1, label="propellers off")
        if base is not None and "ccl_over_cref" in base:
            _loading_line(ax, base, name, us, "-", "baseline design, with wakes")
            ax.lines[-1].set_color("tab:orange")
        first = True
        for surf, yc, R in rotors:
            if surf not in (None, name):
                continue
            ax.axvspan(us.conv("length", yc - R), us.conv("length", yc + R), color="tab:green", alpha=0.12,
                       label="propeller disk (optimum)" if first else None)
            ax.axvline(us.conv("length", yc), color="tab:green", lw=0.8, ls=":")
            first = False
        ax.set_ylabel(f"c·cl / c_ref  ({name})")
        ax.set_xlim(left=0)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    axes[-1, 0].set_xlabel(us.label("spanwise position y, right half", "length"))
    fig.suptitle(title or run_title(run, f"spanwise loading at mid-cruise (c_ref = {c_ref:.3f} m)"))
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png


def plot_rotor(run_dir, out_png, title=None, units="si"):
    """Blade chord and twist (blade.csv) and the rotor along the mission (mission.csv):
    propulsive efficiency (where defined), tip Mach, thrust, rotor speed, one quantity
    per axis."""
    plt = _plt()
    us = unit_system(units)
    run = Path(run_dir)
    fig, ax = plt.subplots(3, 2, figsize=(11, 9.5))
    if (run / "blade.csv").exists():
        b = read_csv(run / "blade.csv")
        ax[0, 0].plot(b["r_over_R"], b["c_over_R"], "k.-")
        ax[0, 0].set_ylabel("blade chord c/R (-)")
        ax[0, 1].plot(b["r_over_R"], b["beta_deg"], "k.-")
        ax[0, 1].set_ylabel("blade angle β (deg)")
        for a in ax[0]:
            a.set_xlabel("radial position r/R (-)")
    if (run / "mission.csv").exists():
        d = read_csv(run / "mission.csv")
        t = d["time_s"] / 60.0
        eta = propulsive_efficiency(d)
        panels = [(ax[1, 0], eta, "propulsive efficiency (-)\n(blank: thrust or power ≤ 0)"),
                  (ax[1, 1], d.get("tip_mach"), "tip Mach number (-)"),
                  (ax[2, 0], us.conv("force", d["thrust_N"]) if "thrust_N" in d else None,
                   us.label("total thrust", "force")),
                  (ax[2, 1], d.get("rotor_speed_rpm"), "rotor speed (rpm)")]
        for a, y, lab in panels:
            if y is not None:
                a.plot(t, y, ".-", ms=3)
            a.set_ylabel(lab)
            a.set_xlabel("time (min)")
            _segments(a, d)
    for a in ax.ravel():
        a.grid(True, alpha=0.3)
    fig.suptitle(title or run_title(run, "rotor"))
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png
