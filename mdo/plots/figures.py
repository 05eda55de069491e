"""Figures from the files of a run folder (so that ``mdo plot`` can redo them):
mission profile (``mission.csv``), spanwise loading (``loading.csv``, with a baseline
``analysis/loading.csv`` overlaid when present) and rotor (``blade.csv`` + ``mission.csv``)."""
from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

__all__ = ["read_csv", "plot_mission", "plot_loading", "plot_rotor"]


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


def plot_mission(mission_csv, out_png, title=None):
    """Altitude, speed, power and state of charge vs time, segments marked."""
    plt = _plt()
    d = read_csv(mission_csv)
    t = d["time_s"] / 60.0
    fig, ax = plt.subplots(2, 2, figsize=(12, 7), sharex=True)
    ax[0, 0].plot(t, d["altitude_m"] / 0.3048, ".-", ms=3)
    ax[0, 0].set_ylabel("altitude (ft)")
    ax[0, 1].plot(t, d["speed_mps"] / 0.44704, ".-", ms=3)
    ax[0, 1].set_ylabel("airspeed (mph)")
    for key, lab in (("battery_power_W", "battery"), ("shaft_power_W", "shaft")):
        if key in d:
            ax[1, 0].plot(t, d[key] / 1e3, ".-", ms=3, label=lab)
    ax[1, 0].set_ylabel("power (kW)")
    ax[1, 0].legend(fontsize=8)
    if "state_of_charge" in d:
        ax[1, 1].plot(t, d["state_of_charge"], ".-", ms=3)
    ax[1, 1].set_ylabel("state of charge (-)")
    seg = d.get("segment", [])
    starts = [i for i in range(len(seg)) if i == 0 or seg[i] != seg[i - 1]]
    for a in ax.ravel():
        _segments(a, d)
        a.grid(True, alpha=0.3)
    for i in starts:
        ax[0, 0].annotate(seg[i], (t[i], d["altitude_m"][i] / 0.3048), fontsize=7, rotation=90,
                          xytext=(2, 4), textcoords="offset points")
    for a in ax[1]:
        a.set_xlabel("time (min)")
    fig.suptitle(title or f"mission profile ({Path(mission_csv).parent.name})")
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png


def plot_loading(loading_csv, out_png, baseline=None, title=None):
    """Sectional cl vs span (props on and off) for every surface, baseline overlaid."""
    plt = _plt()
    d = read_csv(loading_csv)
    surfaces = list(dict.fromkeys(d["surface"]))
    fig, axes = plt.subplots(len(surfaces), 1, figsize=(8, 3.2 * len(surfaces)), squeeze=False)
    base = read_csv(baseline) if baseline is not None and Path(baseline).exists() else None
    for ax, name in zip(axes[:, 0], surfaces):
        m = np.array([s == name for s in d["surface"]])
        order = np.argsort(d["y_m"][m])
        y = d["y_m"][m][order]
        ax.plot(y, d["cl_props_on"][m][order], "b.-", ms=3, label="with propeller wakes")
        ax.plot(y, d["cl_props_off"][m][order], "k--", lw=1, label="propellers off")
        if base is not None:
            mb = np.array([s == name for s in base["surface"]])
            ob = np.argsort(base["y_m"][mb])
            ax.plot(base["y_m"][mb][ob], base["cl_props_on"][mb][ob], "-", color="tab:orange", lw=1,
                    label="baseline design, with wakes")
        ax.set_ylabel(f"cl  ({name})")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    axes[-1, 0].set_xlabel("y (m), right half")
    fig.suptitle(title or f"spanwise loading ({Path(loading_csv).parent.name})")
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png


def plot_rotor(run_dir, out_png, title=None):
    """Blade chord and twist (blade.csv) and the rotor along the mission (mission.csv)."""
    plt = _plt()
    run = Path(run_dir)
    fig, ax = plt.subplots(2, 2, figsize=(11, 7))
    if (run / "blade.csv").exists():
        b = read_csv(run / "blade.csv")
        ax[0, 0].plot(b["r_over_R"], b["c_over_R"], "k.-")
        ax[0, 0].set_xlabel("r/R")
        ax[0, 0].set_ylabel("c/R")
        ax[0, 1].plot(b["r_over_R"], b["beta_deg"], "k.-")
        ax[0, 1].set_xlabel("r/R")
        ax[0, 1].set_ylabel("blade angle (deg)")
    if (run / "mission.csv").exists():
        d = read_csv(run / "mission.csv")
        t = d["time_s"] / 60.0
        if "propulsive_efficiency" in d:
            eta = np.where(np.abs(d["propulsive_efficiency"]) < 1.5, d["propulsive_efficiency"], np.nan)
            ax[1, 0].plot(t, eta, ".-", ms=3, label="propulsive efficiency")
        if "tip_mach" in d:
            ax[1, 0].plot(t, d["tip_mach"], ".-", ms=3, label="tip Mach")
        ax[1, 0].set_xlabel("time (min)")
        ax[1, 0].legend(fontsize=8)
        if "thrust_N" in d:
            ax[1, 1].plot(t, d["thrust_N"] / 1e3, ".-", ms=3, label="thrust (kN)")
        if "rotor_speed_rpm" in d:
            ax[1, 1].plot(t, d["rotor_speed_rpm"] / 1e3, ".-", ms=3, label="rotor speed (1000 rpm)")
        ax[1, 1].set_xlabel("time (min)")
        ax[1, 1].legend(fontsize=8)
        for a in ax[1]:
            _segments(a, d)
    for a in ax.ravel():
        a.grid(True, alpha=0.3)
    fig.suptitle(title or f"rotor ({run.name})")
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png
