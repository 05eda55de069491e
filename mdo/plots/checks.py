"""Design checks: is the design inside usual practice?  Read from the run folder's files.

An optimizer happily returns a 4 cm blade chord on a 2 m propeller if nothing in the
model penalizes it; these checks flag such a design for the designer (they are not
constraints).  Each range with its basis:

* blade chord at 0.75 R, ``c/R`` in [0.05, 0.30] (``blade.csv``): below 0.05 a blade is
  a strip (4 cm on a 2 m propeller: low chord Reynolds number, no room for a spar);
  above 0.30 it is wider than paddle blades (a range stated by issue #23, not a source).
* solidity at 0.75 R, ``sigma = B c / (pi R)`` in [0.03, 0.25]: helicopter main rotors
  have 0.05-0.12 (Leishman, *Principles of Helicopter Aerodynamics*, 2nd ed., 2006);
  a two-blade propeller at c/R 0.05 has 0.032, a six-blade turboprop at c/R 0.13 has 0.25.
* tip Mach number <= 0.70 over the mission (``mission.csv``): beyond it the tip sections
  of usual propeller airfoils approach their drag-divergence Mach number and the noise
  rises steeply; the paper's design point is bounded at 0.6 (the problems' ``tip_mach_max``).
* the best net propulsive efficiency over the nodes that thrust with shaft power
  (``mission.csv``: the rotors' force along the flight path times the speed over shaft
  power) at most 0.92: the best measured full-scale propellers, two-blade 10-ft
  NACA 16-series blades with Betz loading in the Langley 16-ft high-speed tunnel, reached
  "of the order of 91.5 to 92 percent" (W. Solomon, NACA TN 2881, 1953); production
  constant-speed GA propellers cruise at 0.80-0.85 (Gudmundsson, *General Aviation Aircraft
  Design*, 2014, ch. 14).  Above it an isolated blade's figure is better than any measured
  one: the design is worth a second look (nacelle and spinner blockage, shank losses).
* the propellers' tip clearance to the fuselage at least one inch (``geometry.json``: each disk
  off the symmetry plane against the body's elliptical cross-section in its plane,
  ``mdo.vehicle.config.fuselage_gaps_m``): 14 CFR 23.925(d)(1).  An optimization holds it as a
  constraint (``DesignBounds.fuselage_clearance_m``); the analysis of a given design reports it here.
* the body's pitch attitude over the mission within 15 deg nose-down and 30 deg nose-up
  (``mission.csv``): the pitch-attitude protection of a fly-by-wire passenger airplane (Airbus
  normal law, FCOM DSC-27-20-10-20; 25 deg nose-up at low speed).  A tilt-wing flown on a
  prescribed tilt schedule can meet its thrust direction only by pitching the cabin (the TTW on
  Table 5's schedule: 60-67 deg in its approach and descent transitions).
* the body's pitch rate within the segments, at the nodes, at most 3 deg/s (``mission.csv``
  ``body_pitch_rate_degps``; the limit itself also holds between the nodes): a passenger airplane's take-off rotation, "in most cases should not
  exceed 3 degrees per second" (Boeing, Flight Operations Review, 1986; Airbus SOPs).  The steps at
  segment joins are the prescribed profile's (its acceleration or flight path angle steps) and are
  not in it.
* an optimization's gain over its own baseline (``summary.json`` of the folder and of its
  ``analysis/``) at least 2 %: ours, not a source.  The committed optima gain 7-28 % (GA-2P, GA-8P,
  X-57, TTW); a TTW robustness start ended 1 % below its baseline at a KKT point on a design-speed
  bound, 38 % above the best optimum found
  (``results/robustness/earlier_model/ttw_2026-12-07_twenty-first.md``).  A smaller gain is not
  wrong, but it is where a stationary point near the start hides: try other starts
  (``tests/bench/robustness.py``).
* wing loading ``W/S`` in [50, 2000] N/m^2 (``design.json`` TOGW, ``geometry.json``
  reference area): Raymer, *Aircraft Design: A Conceptual Approach*, Table 5.5 (typical
  take-off wing loadings) runs from 6 lb/ft^2 (290 N/m^2, sailplanes) to 40 lb/ft^2
  (1900 N/m^2, twin turboprops); below 50 N/m^2 are human-powered aircraft.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from ..core.units import G0
from ..mission.profiles import CABIN_ATTITUDE_ENVELOPE_RAD, CABIN_PITCH_RATE_MAX_RADPS
from ..vehicle.config import PROPELLER_STRUCTURE_CLEARANCE_M, fuselage_gaps_m, fuselage_half_axes

__all__ = ["CHECKS", "design_checks", "write_design_checks", "checks_markdown"]

CABIN_ATTITUDE_DEG = tuple(round(math.degrees(a), 9) for a in CABIN_ATTITUDE_ENVELOPE_RAD)
_ATTITUDE_BASIS = (f"Airbus normal-law pitch-attitude protection: {CABIN_ATTITUDE_DEG[0]:+g} to "
                   f"{CABIN_ATTITUDE_DEG[1]:+g} deg (FCOM DSC-27-20-10-20)")

# quantity: (low, high, unit, basis) — see the module docstring for the sources
CHECKS = {
    "blade chord c/R at 0.75 R": (0.05, 0.30, "-", "strip below 0.05, paddle above 0.30"),
    "solidity B c/(pi R) at 0.75 R": (0.03, 0.25, "-", "rotors 0.05-0.12 (Leishman 2006), turboprops to 0.25"),
    "maximum tip Mach number": (0.0, 0.70, "-", "drag divergence and noise of the tip sections"),
    "wing loading W/S": (50.0, 2000.0, "N/m^2", "Raymer Table 5.5: 290 (sailplane) - 1900 (twin turboprop)"),
    "best propulsive efficiency (thrusting nodes)": (0.0, 0.92, "-",
                                                      "best measured full-scale 0.915-0.92 (NACA TN 2881)"),
    "propeller tip clearance to the fuselage": (PROPELLER_STRUCTURE_CLEARANCE_M, math.inf, "m",
                                                "14 CFR 23.925(d)(1): one inch radial to the structure"),
    "most nose-up body attitude": (-90.0, CABIN_ATTITUDE_DEG[1], "deg", _ATTITUDE_BASIS),
    "most nose-down body attitude": (CABIN_ATTITUDE_DEG[0], 90.0, "deg", _ATTITUDE_BASIS),
    "optimization's gain over its baseline": (2.0, 100.0, "%", "ours: a smaller gain may be a stationary point "
                                                             "near the start; try other starts"),
    "fastest body pitch rate within a segment": (0.0, round(math.degrees(CABIN_PITCH_RATE_MAX_RADPS), 9), "deg/s",
                                                 "an airliner's take-off rotation, at most 3 deg/s (Boeing 1986)"),
}


def _json(path: Path):
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        return None


def _values(run: Path) -> dict:
    """The checked quantities the folder's files give (missing files: quantity absent)."""
    from .figures import read_csv
    v = {}
    geom = _json(run / "geometry.json") or {}
    if (run / "blade.csv").exists():
        b = read_csv(run / "blade.csv")
        c75 = float(np.interp(0.75, b["r_over_R"], b["c_over_R"]))
        v["blade chord c/R at 0.75 R"] = c75
        if "blades" in geom:
            v["solidity B c/(pi R) at 0.75 R"] = geom["blades"] * c75 / math.pi
    if (run / "mission.csv").exists():
        m = read_csv(run / "mission.csv")
        if "tip_mach" in m:
            v["maximum tip Mach number"] = float(np.nanmax(m["tip_mach"]))
        if "body_angle_deg" in m:
            v["most nose-up body attitude"] = float(np.nanmax(m["body_angle_deg"]))
            v["most nose-down body attitude"] = float(np.nanmin(m["body_angle_deg"]))
        if "body_pitch_rate_degps" in m:
            v["fastest body pitch rate within a segment"] = float(np.nanmax(np.abs(m["body_pitch_rate_degps"])))
        if {"thrust_power_W", "thrust_N", "shaft_power_W"} <= set(m):
            v.update(_best_propulsive_efficiency(m))
    gap = _fuselage_clearance(geom)
    if gap is not None:
        v["propeller tip clearance to the fuselage"] = gap
    v.update(_gain_over_baseline(run))
    design = _json(run / "design.json") or {}
    if "togw_kg" in design and geom.get("reference_area_m2"):
        v["wing loading W/S"] = design["togw_kg"] * G0 / geom["reference_area_m2"]
    return v


def _gain_over_baseline(run: Path) -> dict:
    """An optimization folder's objective against its ``analysis/`` baseline's, in per cent of the
    baseline (both converged and positive; {} otherwise)."""
    opt, base = _json(run / "summary.json") or {}, _json(run / "analysis" / "summary.json") or {}
    if opt.get("mode") != "optimization" or base.get("mode") != "analysis" or not (opt.get("success") and
                                                                                    base.get("success")):
        return {}
    f, f0 = (float((d.get("objective") or {}).get("value", math.nan)) for d in (opt, base))
    if not (f0 > 0.0 and math.isfinite(f)):
        return {}
    return {"optimization's gain over its baseline": 100.0 * (1.0 - f / f0)}


def _fuselage_clearance(geom: dict):
    """The smallest distance (m) from a rotor disk's rim to the fuselage (``geometry.json``), over the
    disks off the symmetry plane whose plane crosses the body; None when there is none."""
    f, best = geom.get("fuselage"), None
    for r in geom.get("rotors", []) if f else []:
        x, y, z = r["center_m"]
        a, b = fuselage_half_axes(f["length_m"], f["width_m"], f["height_m"], f["nose_x_m"], x)
        if y <= 1e-6 or a <= 0.0:
            continue
        gap = min(fuselage_gaps_m(a, b, f["axis_z_m"], y, z, r["radius_m"]))
        best = gap if best is None else min(best, gap)
    return best


def _best_propulsive_efficiency(m) -> dict:
    """The best net propulsive efficiency ``thrust_power_W / shaft_power_W`` (``mission.csv``:
    the rotors' force along the flight path times the speed, over shaft power) over the nodes
    where thrust, shaft power and thrust power are all positive.  Not the axial figure
    ``propulsive_efficiency`` (thrust times the axial inflow): an inclined rotor that the
    edgewise flow helps to turn (a tilt-wing's descending transition) exceeds 1 on it."""
    T, P, Pt = (np.asarray(m[k], float) for k in ("thrust_N", "shaft_power_W", "thrust_power_W"))
    ok = (T > 0) & (P > 0) & (Pt > 0)
    if not ok.any():
        return {}
    return {"best propulsive efficiency (thrusting nodes)": float(np.max(Pt[ok] / P[ok]))}


def _slack(bound: float) -> float:
    """What a value may pass a range's end by and still be inside: IPOPT holds a bound to about
    1e-8 of its size (``bound_relax_factor``), so a limit that is also a constraint (the cabin's
    30 deg) reads 30.0000001 at an optimum that sits on it."""
    return 1e-6 * max(1.0, abs(bound)) if math.isfinite(bound) else 0.0


def design_checks(run_dir) -> list[dict]:
    """One dict per quantity the folder gives: quantity, value, low, high, unit, basis, ok,
    and a one-line ``message``."""
    out = []
    for q, val in _values(Path(run_dir)).items():
        lo, hi, unit, basis = CHECKS[q]
        ok = bool(lo - _slack(lo) <= val <= hi + _slack(hi))
        where = "inside" if ok else ("below" if val < lo else "above")
        out.append({"quantity": q, "value": val, "low": lo, "high": hi, "unit": unit, "basis": basis, "ok": ok,
                    "message": f"{q} = {val:.4g}{'' if unit == '-' else ' ' + unit} is {where} usual practice "
                               f"[{lo:g}, {hi:g}] ({basis})"})
    return out


def checks_markdown(checks: list[dict]) -> str:
    """The '## Design checks' section of summary.md."""
    lines = ["## Design checks (usual practice; see mdo/plots/checks.py for the sources)", ""]
    if not checks:
        return "\n".join(lines + ["no checkable quantity in this run folder", ""])
    warn = [c for c in checks if not c["ok"]]
    for c in warn:
        lines.append(f"- **warning**: {c['message']}")
    if warn:
        lines.append("")
    lines += ["| quantity | value | usual range | unit | basis |", "|---|---:|---|---|---|"]
    for c in checks:
        flag = "" if c["ok"] else " **(outside)**"
        lines.append(f"| {c['quantity']} | {c['value']:.4g}{flag} | {c['low']:g} - {c['high']:g} | {c['unit']} "
                     f"| {c['basis']} |")
    return "\n".join(lines + [""])


_HEAD = "## Design checks"


def write_design_checks(run_dir) -> list[dict]:
    """Put the checks into ``summary.md`` (replacing an earlier section, so that running it
    twice changes nothing) and ``summary.json`` (``design_checks``, ``design_warnings``)."""
    run = Path(run_dir)
    checks = design_checks(run)
    if not checks:   # nothing to check (a fixed-polar vehicle has no blade, rotor or geometry files)
        return checks
    md = run / "summary.md"
    if md.exists():
        text = md.read_text()
        if _HEAD in text:
            text = text[:text.index(_HEAD)].rstrip() + "\n"
        md.write_text(text.rstrip() + "\n\n" + checks_markdown(checks))
    sj = run / "summary.json"
    s = _json(sj)
    if s is not None:
        s["design_checks"] = checks
        s["design_warnings"] = [c["message"] for c in checks if not c["ok"]]
        sj.write_text(json.dumps(s, indent=1))
    return checks
