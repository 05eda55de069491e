"""Geometry figures from ``geometry.json`` (written by the vehicle's reports):
``geometry.png``  a 3-D view of the lifting surfaces, fuselage, rotor disks and the
                  fixed (prescribed-pitch) propeller wakes at mid-cruise;
``planform.png``  a three-view (top, front, side) of the optimum drawn over the
                  baseline design (``analysis/geometry.json`` of an optimization run).

``geometry.json`` holds numbers only (SI): ``surfaces`` (one entry per half, ``le`` and
``te`` as 3 x E point lists), ``fuselage`` (length, width, height, nose x, axis z),
``rotors`` (centre, radius, spin, axis), ``blades``, ``wake`` (helix pitch at mid-cruise)
and ``reference_area_m2``.  The fuselage is drawn as the body of elliptical cross-section
that the propellers' clearance reads (``mdo.vehicle.config.fuselage_section_scale``: an
elliptical nose over the first 20 % of its length, a straight tail cone over the last 50 %
down to 12 % of the maximum section), not the drag model's body.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from ..vehicle.config import fuselage_section_scale as fuselage_profile  # the one body shape
from .units import unit_system

__all__ = ["read_geometry", "rotor_surfaces", "fuselage_profile", "plot_geometry", "plot_planform"]


def read_geometry(path) -> dict:
    """``geometry.json`` as a dict with numpy arrays for every surface's ``le``/``te``."""
    g = json.loads(Path(path).read_text())
    for s in g.get("surfaces", []):
        s["le"] = np.asarray(s["le"], float)
        s["te"] = np.asarray(s["te"], float)
    return g


def rotor_surfaces(g: dict) -> list:
    """(surface name, y centre, radius) of every rotor on the right half (y > 0); the
    surface is the non-vertical one whose leading edge at that y is nearest the disk centre."""
    out = []
    surfaces = [dict(s, le=np.asarray(s["le"], float)) for s in g.get("surfaces", [])]
    for r in g.get("rotors", []):
        c = np.asarray(r["center_m"], float)
        if c[1] <= 0:
            continue
        best, dist = None, math.inf
        for s in surfaces:
            le = s["le"]
            if s.get("image") or s.get("vertical") or np.ptp(le[1]) < 1e-6 or not (le[1].min() <= c[1] <= le[1].max()):
                continue
            o = np.argsort(le[1])
            x = np.interp(c[1], le[1][o], le[0][o])
            z = np.interp(c[1], le[1][o], le[2][o])
            dd = math.hypot(x - c[0], z - c[2])
            if dd < dist:
                best, dist = s["name"], dd
        out.append((best, float(c[1]), float(r["radius_m"])))
    return out


def _plt():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _fuselage_mesh(f: dict, n=40, m=24):
    x = f["nose_x_m"] + np.linspace(0.0, 1.0, n) * f["length_m"]
    p = fuselage_profile(np.linspace(0.0, 1.0, n))
    th = np.linspace(0.0, 2 * math.pi, m)
    X = np.repeat(x[:, None], m, 1)
    Y = 0.5 * f["width_m"] * p[:, None] * np.cos(th)[None, :]
    Z = f["axis_z_m"] + 0.5 * f["height_m"] * p[:, None] * np.sin(th)[None, :]
    return X, Y, Z


def _disk(r: dict, n=60):
    """Points of a rotor disk rim (3 x n), in the plane normal to its axis."""
    c = np.asarray(r["center_m"], float)
    a = np.asarray(r.get("axis", [1.0, 0.0, 0.0]), float)
    a = a / np.linalg.norm(a)
    e1 = np.cross(a, [0.0, 0.0, 1.0]) if abs(a[2]) < 0.9 else np.cross(a, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(a, e1)
    t = np.linspace(0, 2 * math.pi, n)
    return c[:, None] + r["radius_m"] * (np.outer(e1, np.cos(t)) + np.outer(e2, np.sin(t)))


def plot_geometry(geometry_json, out_png, title=None, units="si", turns: float = 2.0):
    """3-D view: surfaces (filled), fuselage, rotor disks and each rotor's wake helix
    (``turns`` turns of every blade's tip path downstream, one colour per rotor)."""
    plt = _plt()
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    us = unit_system(units)
    g = read_geometry(geometry_json)
    k = 1.0 / us.length
    fig = plt.figure(figsize=(10, 7))
    ax = fig.add_subplot(111, projection="3d")
    pts = np.hstack([s["le"] for s in g["surfaces"]] + [s["te"] for s in g["surfaces"]]
                    + [_disk(r) for r in g.get("rotors", [])]) * k
    lo, hi = pts.min(axis=1), pts.max(axis=1)
    if "fuselage" in g:
        f = g["fuselage"]
        lo[0] = min(lo[0], f["nose_x_m"] * k)
        hi[0] = max(hi[0], (f["nose_x_m"] + f["length_m"]) * k)
    span = hi - lo
    mid = 0.5 * (hi + lo)
    half = 0.5 * np.maximum(span, 0.25 * span.max()) * 1.05
    for setter, j in ((ax.set_xlim, 0), (ax.set_ylim, 1), (ax.set_zlim, 2)):
        setter(mid[j] - half[j], mid[j] + half[j])
    for s in g["surfaces"]:
        poly = np.hstack([s["le"], s["te"][:, ::-1]]).T * k
        ax.add_collection3d(Poly3DCollection([poly], facecolor="0.82", edgecolor="k", lw=0.6, alpha=0.9))
    if "fuselage" in g:
        X, Y, Z = _fuselage_mesh(g["fuselage"])
        ax.plot_surface(X * k, Y * k, Z * k, color="tan", alpha=0.45, lw=0, shade=True)
    pitch = g.get("wake", {}).get("pitch_m", 0.0)
    B = int(g.get("blades", 1))
    for i, r in enumerate(g.get("rotors", [])):
        rim = _disk(r) * k
        col = f"C{(i + 3) % 10}"
        ax.plot(*rim, "-", color="tab:blue", lw=1.2)
        c = np.asarray(r["center_m"], float)
        p_r, B_r = r.get("pitch_m", pitch), int(r.get("blades", B))   # per rotor group when given
        tw = np.linspace(0, turns * 2 * math.pi, int(120 * turns))
        if p_r > 0:   # the wake inside the drawing box (it would spill over the axes)
            tw = tw[(c[0] + p_r * tw / (2 * math.pi)) * k <= mid[0] + half[0]]
        for blade in range(B_r):
            ph = tw * r.get("spin", 1.0) + 2 * math.pi * blade / B_r
            ax.plot((c[0] + p_r * tw / (2 * math.pi)) * k, (c[1] + r["radius_m"] * np.cos(ph)) * k,
                    (c[2] + r["radius_m"] * np.sin(ph)) * k, color=col, lw=0.5, alpha=0.55)
    ax.set_box_aspect(tuple(half))
    ax.set_xlabel(us.label("x, aft from nose", "length"))
    ax.set_ylabel(us.label("y, spanwise", "length"))
    ax.set_zlabel(us.label("z, up", "length"))
    ax.view_init(elev=28, azim=-58)
    sub = (f"lifting surfaces, fuselage (sketch), rotor disks and fixed wakes (up to {turns:g} turns per blade, "
           f"pitch {us.conv('length', pitch):.2f} {us.length_unit}, at mid-cruise)" if pitch
           else "lifting surfaces, fuselage (sketch), rotor disks")
    ax.set_title(f"{title or g.get('name', '')}\n{sub}", fontsize=10)
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png


def _views(ax3, g, k, style):
    """Draw one design on the top (x-y), front (y-z) and side (x-z) axes."""
    top, front, side = ax3
    for s in g["surfaces"]:
        p = np.hstack([s["le"], s["te"][:, ::-1], s["le"][:, :1]]) * k
        top.plot(p[1], p[0], **style)
        front.plot(p[1], p[2], **style)
        side.plot(p[0], p[2], **style)
    f = g.get("fuselage")
    if f:
        s = np.linspace(0, 1, 60)
        x = (f["nose_x_m"] + s * f["length_m"]) * k
        w = 0.5 * f["width_m"] * fuselage_profile(s) * k
        h = 0.5 * f["height_m"] * fuselage_profile(s) * k
        top.plot(np.r_[w, -w[::-1]], np.r_[x, x[::-1]], **style)
        side.plot(np.r_[x, x[::-1]], np.r_[f["axis_z_m"] * k + h, f["axis_z_m"] * k - h[::-1]], **style)
        th = np.linspace(0, 2 * math.pi, 60)
        front.plot(0.5 * f["width_m"] * k * np.cos(th), (f["axis_z_m"] + 0.5 * f["height_m"] * np.sin(th)) * k,
                   **style)
    for r in g.get("rotors", []):
        rim = _disk(r) * k
        top.plot(rim[1], rim[0], **style)
        front.plot(rim[1], rim[2], **style)
        side.plot(rim[0], rim[2], **style)


def plot_planform(geometry_json, out_png, baseline=None, title=None, units="si"):
    """Three-view of the design in ``geometry_json`` (solid) over ``baseline`` (dashed)."""
    plt = _plt()
    us = unit_system(units)
    k = 1.0 / us.length
    g = read_geometry(geometry_json)
    b = read_geometry(baseline) if baseline is not None and Path(baseline).exists() else None
    fig = plt.figure(figsize=(12, 8.5))
    gs = fig.add_gridspec(2, 2, height_ratios=[1.6, 1.0])
    top = fig.add_subplot(gs[0, 0])
    front = fig.add_subplot(gs[0, 1])
    side = fig.add_subplot(gs[1, :])
    if b is not None:
        _views((top, front, side), b, k, dict(color="tab:orange", ls="--", lw=1.0))
    _views((top, front, side), g, k, dict(color="k", ls="-", lw=1.1))
    L = us.length_unit
    top.set_title("top view (nose up)", fontsize=9)
    top.set_xlabel(f"y, spanwise ({L})")
    top.set_ylabel(f"x, aft from nose ({L})")
    top.invert_yaxis()
    front.set_title("front view", fontsize=9)
    front.set_xlabel(f"y, spanwise ({L})")
    front.set_ylabel(f"z, up ({L})")
    side.set_title("side view", fontsize=9)
    side.set_xlabel(f"x, aft from nose ({L})")
    side.set_ylabel(f"z, up ({L})")
    for a in (top, front, side):
        a.set_aspect("equal", adjustable="datalim")
        a.grid(True, alpha=0.3)
    handles = [plt.Line2D([], [], color="k", lw=1.1, label="optimum" if b is not None else "design")]
    if b is not None:
        handles.append(plt.Line2D([], [], color="tab:orange", ls="--", lw=1.0, label="baseline (analysis/)"))
    top.legend(handles=handles, fontsize=8, loc="lower left")
    fig.suptitle(title or f"{g.get('name', '')}: three-view" + (" of the optimum over the baseline" if b else ""))
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png
