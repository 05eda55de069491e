"""Rotation-direction studies of the paper (§V, Figs. 8–10) with the wake coupling.

    /work/venv/bin/python problems/validation/wake_rotation.py [--out results/rotation]
                                                               [--model mean|full] [--lift-velocity freestream|local]

GA-2P (all inboard-up, all outboard-up), GA-8P (four cases) and the TTW (four
cases) at α = 3°, J = 1 (GA-8P: J = 1.5), 175 mph at 2500 ft.  Writes per vehicle
a figure of the spanwise sectional lift coefficient of each case (main wing and
tail / front wing) with CL, CDi, CDp and L/D in the legend, a CSV of the curves and
``summary.csv`` with the integrated coefficients and the checks of the paper's
findings.

Vehicle definitions (local to this study until mdo.vehicle provides them; numbers
from the paper's Table 1 and Table 3 "Initial", and SUAVE's X-57 Mod II model
``regression/scripts/Vehicles/X57_Maxwell_Mod2.py`` @ suavecode/SUAVE 0210617):

* GA wing: span 11.4 m, S = 14.76 m², taper 0.7 (trapezoid, c_root 1.523 m), five
  sections at η = 0, 0.25, 0.5, 0.75, 1 with twists 3.0, 2.75, 2.5, 2.25, 2.0 deg
  (Table 3), NACA 63-412; horizontal tail 3.3 m × 0.769 m, 4.77 m behind and 0.76 m
  below the wing root leading edge (SUAVE X-57); propeller disks 0.93 m ahead of and
  0.226 m below the wing root leading edge (SUAVE X-57).
* GA-2P: two 3-bladed propellers, R = 0.97 m, at 23 % semispan.
* GA-8P: eight 5-bladed propellers, R = 0.58 m, four per side equally spaced from
  the tip inwards, Δy = 1.45 m (η = 1.0, 0.746, 0.491, 0.237).
* TTW: two unswept, untapered wings of span 9.6 m, S = 10.85 m² each (21.7 m²
  together), twists 4, 3, 2, 1, 0 deg, NACA 63-412; front wing root LE at
  (0.8, 0, 0.4) m, main wing at (4.4, 0, 1.4) m (length 6.1 m, "vertically offset";
  the offsets are assumptions); four 3-bladed rotors, R = 1.2 m, per wing at
  η = 0.38 and 1.0, disks 0.6 m ahead of the leading edge on the wing plane.

Rotors: Adkins–Liebeck designs (mdo.rotor) at the Table 3 initial design thrust,
speed and radius with design cl 0.7, NACA 4412 sections, hub 12 % R, at the rotor
speed of the study (J) — except the TTW rotor, designed at a 0.55 rotational tip
Mach number (a hover rotor); in the study each rotor's collective pitch is trimmed
so that it delivers its share of a cruise drag D = q S · 0.03 (an assumed cruise
CD; the paper does not give the thrust of these cases): 772 N per GA-2P propeller,
193 N per GA-8P propeller, 284 N per TTW rotor.  The TTW rotor is a hover design;
at J = 1 and 284 N its inner blade windmills (negative circulation inboard of
0.55 R), which reverses the swirl of the inner slipstream.  "TTW beta_c=20" repeats
the TTW cases at the cruise pitch command of Table 5 (β_c = +20°: circulation
positive along the blade, 14 kN per rotor — far above the cruise drag, but the
loading sense of the paper's Fig. 10).  The BEMT runs at the rotor's
incidence (azimuth-averaged); its blade circulation feeds the wake (averaged table
by default, ``--model full`` for the helical fixed wake of the paper).
"""
from __future__ import annotations

import argparse
import csv
import math
import time
from dataclasses import dataclass, field
from pathlib import Path

import casadi as ca
import numpy as np

import mdo.wake as wake
from mdo.core.atmosphere import density, dynamic_viscosity, speed_of_sound
from mdo.core.units import FT, MPH
from mdo.rotor import adkins_liebeck, analyze
from mdo.wing.drag import profile_drag
from mdo.wing.geometry import Section, Surface
from mdo.wing.vlm import VLM

REPO = Path(__file__).resolve().parents[2]
ALT_M = 2500 * FT
V_MPS = 175 * MPH
ALPHA_DEG = 3.0
CD_CRUISE = 0.03
N_STATIONS = 20


def atmos():
    return dict(rho=float(density(ALT_M)), mu=float(dynamic_viscosity(ALT_M)), a=float(speed_of_sound(ALT_M)))


@dataclass
class Vehicle:
    name: str
    surfaces: list
    S_ref: float
    rotor_y: list                  # starboard rotor centres y (m); mirrored to port
    rotor_x: list
    rotor_z: list
    surface_of_rotor: list         # which surface each starboard rotor sits on (for plots)
    radius: float
    blades: int
    J: float
    design: dict
    cases: dict = field(default_factory=dict)   # name -> list of senses per starboard rotor


def ga_surfaces(nspan=40, nchord=4, tail=True, breaks=()):
    span, S, taper = 11.4, 14.76, 0.7
    c_root = 2 * S / (span * (1 + taper))
    etas = (0.0, 0.25, 0.5, 0.75, 1.0)
    tw = (3.0, 2.75, 2.5, 2.25, 2.0)
    secs = [Section(e, 1 + (taper - 1) * e, math.radians(t)) for e, t in zip(etas, tw)]
    wing = Surface("main_wing", span=span, root_chord=c_root, sections=secs, airfoil="naca63412",
                   nspan=nspan, nchord=nchord, breaks=tuple(breaks))
    out = [wing]
    if tail:
        out.append(Surface("horizontal_tail", span=3.3, root_chord=0.769, origin=(4.77, 0.0, -0.76),
                           nspan=max(8, nspan // 3), nchord=max(2, nchord // 2), airfoil=None))
    return out


def _edges_eta(ys, radius, semispan):
    out = []
    for y in ys:
        for e in (y - radius, y + radius):
            if 0.0 < e / semispan < 1.0:
                out.append(round(e / semispan, 6))
    return sorted(set(out))


def ga2p(nspan=40, nchord=4):
    y = [0.23 * 5.7]
    return Vehicle("GA-2P", ga_surfaces(nspan, nchord, breaks=_edges_eta(y, 0.97, 5.7)), 14.76, y, [-0.93],
                   [-0.226], [0], 0.97, 3, 1.0,
                   dict(thrust_N=900.0, speed_mps=135 * MPH, cl_design=0.7),
                   {"Case 1: all inboard-up": ["inboard_up"], "Case 2: all outboard-up": ["outboard_up"]})


def ga8p(nspan=48, nchord=4):
    y = [5.7 - 1.45 * i for i in range(4)]   # tip inwards
    iu, ou = "inboard_up", "outboard_up"
    return Vehicle("GA-8P", ga_surfaces(nspan, nchord, breaks=_edges_eta(y, 0.58, 5.7)), 14.76, y,
                   [-0.93] * 4, [-0.226] * 4, [0] * 4, 0.58, 5, 1.5,
                   dict(thrust_N=350.0, speed_mps=130 * MPH, cl_design=0.7),
                   {"Case 1: all inboard-up": [iu] * 4, "Case 2: all outboard-up": [ou] * 4,
                    "Case 3: alternating, tip inboard-up": [iu, ou, iu, ou],
                    "Case 4: alternating, tip outboard-up": [ou, iu, ou, iu]})


def ttw(nspan=36, nchord=4):
    span, S = 9.6, 21.7 / 2
    chord = S / span
    y = [0.38 * 4.8, 4.8]
    br = _edges_eta(y, 1.2, 4.8)
    tw = (4.0, 3.0, 2.0, 1.0, 0.0)
    secs = [Section(e, 1.0, math.radians(t)) for e, t in zip((0, 0.25, 0.5, 0.75, 1.0), tw)]
    front = Surface("front_wing", span=span, root_chord=chord, sections=secs, origin=(0.8, 0.0, 0.4),
                    airfoil="naca63412", nspan=nspan, nchord=nchord, breaks=tuple(br))
    main = Surface("main_wing", span=span, root_chord=chord, sections=secs, origin=(4.4, 0.0, 1.4),
                   airfoil="naca63412", nspan=nspan, nchord=nchord, breaks=tuple(br))
    iu, ou = "inboard_up", "outboard_up"
    # starboard rotors: (front inner, front tip, main inner, main tip)
    return Vehicle("TTW", [main, front], 21.7, y + y, [0.8 - 0.6] * 2 + [4.4 - 0.6] * 2, [0.4] * 2 + [1.4] * 2,
                   [1, 1, 0, 0], 1.2, 3, 1.0,
                   dict(thrust_N=5395.5, speed_mps=22.36 * MPH, cl_design=0.7, tip_mach=0.55),
                   {"Case 1: all inboard-up": [iu] * 4, "Case 2: all outboard-up": [ou] * 4,
                    "Case 3: inner inboard-up, tip outboard-up": [iu, ou, iu, ou],
                    "Case 4: inner outboard-up, tip inboard-up": [ou, iu, ou, iu]})


def ttw_pitch20(nspan=36, nchord=4):
    """The TTW with its rotors at the cruise pitch command of Table 5 (beta_c = +20 deg)
    instead of trimmed to the cruise drag."""
    v = ttw(nspan, nchord)
    v.name = "TTW beta_c=20"
    v.design = dict(v.design, pitch_deg=20.0)
    return v


def design_rotor(veh: Vehicle, at):
    n_rps = V_MPS / (veh.J * 2 * veh.radius)
    kw = dict(blades=veh.blades, radius_m=veh.radius, speed_mps=veh.design["speed_mps"], airfoil="naca4412",
              cl_design=veh.design["cl_design"], thrust_N=veh.design["thrust_N"], hub_fraction=0.12,
              altitude_m=ALT_M, n_stations=N_STATIONS)
    if "tip_mach" in veh.design:
        kw["tip_mach"] = veh.design["tip_mach"]
    else:
        kw["rpm"] = 60 * n_rps
    d = adkins_liebeck(**kw)
    return d["geometry"], 2 * math.pi * n_rps


def trimmed_state(geom, omega, alpha_rad, thrust_target, at, pitch_deg=None):
    """BEMT at the study's operating point with the collective pitch that gives
    ``thrust_target`` (or at the given ``pitch_deg``)."""
    v_ax, v_ip = V_MPS * math.cos(alpha_rad), V_MPS * abs(math.sin(alpha_rad))

    def run(pitch):
        return analyze(geom, omega_radps=omega, v_axial_mps=v_ax, v_inplane_mps=v_ip, rho_kgpm3=at["rho"],
                       mu_Pas=at["mu"], a_mps=at["a"], pitch_rad=pitch, n_stations=N_STATIONS,
                       n_azimuth=12 if v_ip > 0 else 1)

    if pitch_deg is not None:
        return _state(run(math.radians(pitch_deg)), omega, v_ax, pitch_deg)

    grid = np.radians(np.arange(-10.0, 40.01, 2.5))
    res = run(grid)
    T = np.asarray(res["thrust_N"]).ravel()
    ok = np.asarray(res.converged).ravel()
    k = np.where(ok[:-1] & ok[1:] & (T[:-1] <= thrust_target) & (T[1:] > thrust_target))[0]
    if k.size == 0:
        raise RuntimeError(f"no pitch in [-10, 40] deg gives {thrust_target:.0f} N")
    lo, hi = grid[k[0]], grid[k[0] + 1]
    for _ in range(30):    # bisection on a monotone bracket
        mid = 0.5 * (lo + hi)
        if float(np.ravel(run(mid)["thrust_N"])[0]) > thrust_target:
            hi = mid
        else:
            lo = mid
    return _state(run(0.5 * (lo + hi)), omega, v_ax, math.degrees(0.5 * (lo + hi)))


def _state(r, omega, v_ax, pitch_deg):
    if not bool(np.all(r.converged)):
        raise RuntimeError("BEMT did not converge")
    va = float(np.ravel(r["va_mean_mps"])[0])
    return dict(gamma=np.asarray(r["gamma_m2ps"]).ravel(), omega=omega,
                v_wake=wake.wake_convection_speed(v_ax, va), pitch_deg=pitch_deg,
                thrust_N=float(np.ravel(r["thrust_N"])[0]), CT=float(np.ravel(r["CT"])[0]),
                power_W=float(np.ravel(r["power_W"])[0]))


def wake_rotors(veh: Vehicle, geom, senses):
    edges = wake.WakeRotor.from_geometry(geom, (0.0, 0.0, 0.0), n_stations=N_STATIONS).s_edges
    out = []
    for i, y in enumerate(veh.rotor_y):
        for side in (1, -1):
            yy = side * y
            out.append(wake.WakeRotor(center=(veh.rotor_x[i], yy, veh.rotor_z[i]), axis=(1.0, 0.0, 0.0),
                                      radius_m=veh.radius, s_edges=edges, blades=veh.blades,
                                      spin=wake.spin_for(yy, senses[i]), name=f"rotor{i}{'R' if side > 0 else 'L'}"))
    return out


COUPLINGS = wake.COUPLINGS   # "swirl" (default), "freestream" (the paper's code), "local"


def solve(vlm, rotors, state, at, model="mean", phases=8, coupling="swirl"):
    a = math.radians(ALPHA_DEG)
    kw = {}
    if rotors:
        k = len(rotors)
        opts = dict(phases=phases) if model == "full" else {}
        kw = wake.vlm_wake_inputs(vlm, rotors, [state["gamma"]] * k, [state["omega"]] * k,
                                  [state["v_wake"]] * k, coupling=coupling, model=model, **opts)
    out = vlm.solve(a, V_MPS, rho=at["rho"], mach=V_MPS / at["a"], **kw)
    pdrag = profile_drag(vlm, out, at["rho"], at["mu"], V_MPS / at["a"])
    return out, float(np.ravel(np.array(pdrag["CD_p"]))[0])


def strip_curves(vlm, out):
    g = vlm.geometry
    y = np.array(g["strip_mid"])[1, :]
    cl = np.array(out["cl"])[:, 0]
    surf = np.asarray(vlm.strip_surface)
    return y, cl, surf


def run_vehicle(veh: Vehicle, out_dir: Path, model="mean", coupling="swirl", phases=8, plots=True):
    at = atmos()
    vlm = VLM(veh.surfaces, mach_ref=V_MPS / at["a"], lift_velocity=COUPLINGS[coupling][0], S_ref=veh.S_ref)
    geom, omega = design_rotor(veh, at)
    q = 0.5 * at["rho"] * V_MPS**2
    n_rot = 2 * len(veh.rotor_y)
    t_target = q * veh.S_ref * CD_CRUISE / n_rot
    st = trimmed_state(geom, omega, math.radians(ALPHA_DEG), t_target, at, veh.design.get("pitch_deg"))
    print(f"{veh.name}: {n_rot} rotors, thrust {st['thrust_N']:.0f} N each (CT {st['CT']:.4f}, pitch "
          f"{st['pitch_deg']:+.2f} deg), {veh.J=}, omega {omega:.1f} rad/s")
    rows, curves = [], {}
    out0, cdp0 = solve(vlm, [], st, at)
    cases = {"Propellers off": None, **veh.cases}
    for name, senses in cases.items():
        if senses is None:
            out, cdp = out0, cdp0
        else:
            out, cdp = solve(vlm, wake_rotors(veh, geom, senses), st, at, model, phases, coupling)
        CL = float(np.ravel(np.array(out["CL"]))[0])
        CDi = float(np.ravel(np.array(out["CDi"]))[0])
        ld = CL / (CDi + cdp) if np.isfinite(cdp) else float("nan")
        rows.append(dict(vehicle=veh.name, case=name, CL=CL, CDi=CDi, CDp=cdp, L_over_D=ld,
                         L_over_Di=CL / CDi))
        curves[name] = strip_curves(vlm, out)
        print(f"  {name:42s} CL {CL:.4f}  CDi {CDi:.5f}  CDp {cdp:.5f}  L/D {ld:6.2f}  L/Di {CL / CDi:6.2f}")
    tag = veh.name.lower().replace("-", "").replace(" ", "_").replace(",", "").replace("=", "")
    with open(out_dir / f"{tag}_spanwise_cl.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "surface", "y_m", "cl"])
        for name, (y, cl, surf) in curves.items():
            for yi, ci, si in zip(y, cl, surf):
                w.writerow([name, veh.surfaces[si].name, f"{yi:.4f}", f"{ci:.5f}"])
    if plots:
        _plot(out_dir / f"{tag}_spanwise_cl.png", veh, curves, rows, st)
    return rows, curves


def _plot(path, veh, curves, rows, st):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = [c for c in curves if c != "Propellers off"]
    n = len(cases)
    fig, axs = plt.subplots(1 if n <= 2 else 2, 2, figsize=(11, 4.2 if n <= 2 else 7.6), squeeze=False)
    by = {r["case"]: r for r in rows}
    y0, cl0, s0 = curves["Propellers off"]
    for ax, name in zip(axs.ravel(), cases):
        y, cl, surf = curves[name]
        for si, surf_obj in enumerate(veh.surfaces):
            m = surf == si
            o = np.argsort(y[m])
            m0 = s0 == si
            o0 = np.argsort(y0[m0])
            col = "C0" if si == 0 else "C3"
            ax.plot(y0[m0][o0], cl0[m0][o0], color=col, ls=":", lw=1.0)
            ax.plot(y[m][o], cl[m][o], color=col, lw=1.5, label=surf_obj.name.replace("_", " "))
            ax.plot(-y[m][o], cl[m][o], color=col, lw=1.5)
            ax.plot(-y0[m0][o0], cl0[m0][o0], color=col, ls=":", lw=1.0)
        for i, yy in enumerate(veh.rotor_y):
            for s in (1, -1):
                ax.axvline(s * yy, color="0.75", lw=0.8, zorder=0)
        r = by[name]
        ax.set_title(f"{name}\nCL {r['CL']:.3f}, CDi {r['CDi']:.4f}, L/D {r['L_over_D']:.1f} "
                     f"(L/Di {r['L_over_Di']:.1f})", fontsize=9)
        ax.set_xlabel("y (m)")
        ax.set_ylabel("c_l")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="lower center")
    for ax in axs.ravel()[n:]:
        ax.axis("off")
    fig.suptitle(f"{veh.name}: alpha {ALPHA_DEG:g} deg, J = {veh.J:g}, {V_MPS / MPH:.0f} mph at 2500 ft, "
                 f"thrust {st['thrust_N']:.0f} N per rotor (dotted: propellers off)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def checks(all_rows, all_curves):
    """The paper's findings, as numbers."""
    out = []
    # 1. GA-2P: inboard-up lifts the wing inboard of the nacelle
    y, cl1, s = all_curves["GA-2P"]["Case 1: all inboard-up"]
    _, cl2, _ = all_curves["GA-2P"]["Case 2: all outboard-up"]
    yp = 0.23 * 5.7
    m = (s == 0) & (y > yp - 0.97) & (y < yp)
    mo = (s == 0) & (y > yp) & (y < yp + 0.97)
    d_in = float(np.mean(cl1[m] - cl2[m]))
    d_out = float(np.mean(cl1[mo] - cl2[mo]))
    out.append(("GA-2P inboard of nacelle: mean cl(inboard-up) - cl(outboard-up)", d_in, d_in > 0))
    out.append(("GA-2P outboard of nacelle: mean cl(inboard-up) - cl(outboard-up)", d_out, d_out < 0))
    # 2. GA-8P: all-inboard-up has the highest L/D
    ga8 = [r for r in all_rows if r["vehicle"] == "GA-8P" and r["case"] != "Propellers off"]
    key = "L_over_D" if all(np.isfinite(r["L_over_D"]) for r in ga8) else "L_over_Di"
    best = max(ga8, key=lambda r: r[key])
    out.append((f"GA-8P case with the highest {key}: {best['case']}", best[key],
                best["case"].startswith("Case 1")))
    # 3. TTW: tip rotors inboard-up (cases 1, 4) raise cl near the wingtips (outer 15 % of the span)
    for veh in ("TTW", "TTW beta_c=20"):
        if veh not in all_curves:
            continue
        c = all_curves[veh]
        tip = {}
        for name, (y, cl, s) in c.items():
            m = (s == 0) & (y > 0.85 * 4.8)
            tip[name[:6]] = float(np.mean(cl[m]))
        d = min(tip["Case 1"], tip["Case 4"]) - max(tip["Case 2"], tip["Case 3"])
        out.append((f"{veh}: min tip cl of cases 1,4 - max of cases 2,3 (main wing, y > 0.85 b/2)", d, d > 0))
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(REPO / "results" / "rotation"))
    ap.add_argument("--model", default="mean", choices=("mean", "full"))
    ap.add_argument("--coupling", default="swirl", choices=tuple(COUPLINGS))
    ap.add_argument("--phases", type=int, default=8)
    ap.add_argument("--vehicles", default="ga2p,ga8p,ttw,ttw20")
    args = ap.parse_args(argv)
    out_dir = Path(args.out)
    out_dir.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    all_rows, all_curves = [], {}
    for key in args.vehicles.split(","):
        veh = {"ga2p": ga2p, "ga8p": ga8p, "ttw": ttw, "ttw20": ttw_pitch20}[key]()
        rows, curves = run_vehicle(veh, out_dir, args.model, args.coupling, args.phases)
        all_rows += rows
        all_curves[veh.name] = curves
    with open(out_dir / "summary.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["vehicle", "case", "CL", "CDi", "CDp", "L_over_D", "L_over_Di", "wake_model", "coupling"])
        for r in all_rows:
            w.writerow([r["vehicle"], r["case"], f"{r['CL']:.5f}", f"{r['CDi']:.6f}", f"{r['CDp']:.6f}",
                        f"{r['L_over_D']:.3f}", f"{r['L_over_Di']:.3f}", args.model, args.coupling])
    if "GA-2P" in all_curves and "GA-8P" in all_curves:
        with open(out_dir / "checks.csv", "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["check", "value", "agrees_with_paper"])
            for name, val, ok in checks(all_rows, all_curves):
                w.writerow([name, f"{val:.5f}", ok])
                print(f"check: {name}: {val:.4f} -> {'agrees' if ok else 'DISAGREES'} with the paper")
    print(f"done in {time.perf_counter() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
