"""The wing through stall: the viscous-corrected lattice against a measured wing (issue 17 item 6).

    python problems/validation/graf_wing_stall.py [--out results/validation] [--nspan 20]

Reference: K. Graf et al., "Comparison of full 3D-RANS simulations with 2D-RANS/lifting line
method calculations for the flow analysis of rigid wings for high performance multihulls",
Ocean Engineering (2014): a rectangular NACA 0012 wing (rigid wing sail) of aspect ratio 4.5 on
the wind-tunnel floor, lift and drag measured from 0 to 15 deg (cl_max near 12 deg), and the
authors' 2-D RANS polar of the section (digitized values in ``mdo/wing/data/wings``, see its
SOURCES.md).

Model: ``mdo.wing.VLM`` of the wing and its floor image (span 9 chords, ``nspan`` cosine-spaced
strips per half, one chordwise panel: the aircraft's lattice), with the viscous correction of
``mdo.wing.viscous`` (each strip's angle shift so that its cl is the section's at its effective
angle), the section polar = the authors' 2-D RANS points (made odd in alpha, a cubic B-spline
through them).  Drag: Trefftz-plane induced drag + each strip's section cd at its effective angle.
Alpha is swept upward in 0.25 deg steps, each point starting from the previous one's shifts.
The linear lattice (no correction) is shown beside it.
"""
from __future__ import annotations

import argparse
import csv
import io
import math
from importlib import resources
from pathlib import Path

import sys

import casadi as ca
import numpy as np

from mdo.wing import VLM, trapezoid
from mdo.wing.viscous import solve_viscous

sys.path.insert(0, str(Path(__file__).resolve().parent))   # veldhuis.py, for the PROWIM check

SEMISPAN_C = 4.5     # wing height over chord on the floor (the reflection plane)
V = 8.0              # m/s (the polar is fixed, so only the scale)


def read(name: str) -> dict:
    text = resources.files("mdo.wing").joinpath("data", "wings", name).read_text()
    rows = list(csv.DictReader(io.StringIO(text)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def section_polar():
    """cl(alpha), cd(alpha) of the 2-D RANS points, odd/even in alpha, cubic B-splines (CasADi)."""
    p = read("graf2014_section_rans.csv")
    a = np.radians(np.concatenate([-p["alpha_deg"][:0:-1], p["alpha_deg"]]))
    cl = np.concatenate([-p["cl"][:0:-1], p["cl"]])
    cd = np.concatenate([p["cd"][:0:-1], p["cd"]])
    f_cl = ca.interpolant("cl_rans", "bspline", [a], cl)
    f_cd = ca.interpolant("cd_rans", "bspline", [a], cd)

    def column(f):
        return lambda ae: ca.vertcat(*[f(ae[i]) for i in range(ae.shape[0])])
    return column(f_cl), column(f_cd), p


def run(nspan: int = 20, step_deg: float = 0.25, alpha_max_deg: float = 15.0) -> dict:
    wing = trapezoid("wing", 2 * SEMISPAN_C, 1.0, 1.0, airfoil="naca0012", nspan=nspan, nchord=1)
    vlm = VLM([wing], S_ref=2 * SEMISPAN_C)
    sec_cl, sec_cd, _ = section_polar()
    alphas = np.radians(np.arange(0.0, alpha_max_deg + 1e-9, step_deg))
    pts = solve_viscous(vlm, alphas, sec_cl, V=V)
    g = vlm.geometry
    area = np.array(g["strip_chord"] * g["strip_width"], float).ravel()
    lin = vlm.solve(alphas, V)
    for k, p in enumerate(pts):
        cd = np.array(sec_cd(ca.DM(p["alpha_e"])), float).ravel()
        p["CDp"] = float(cd @ area) / SEMISPAN_C        # half wing: strips' area over the half area
        p["CD"] = p["CDi"] + p["CDp"]
        p["CL_linear"] = float(np.array(lin["CL"]).ravel()[k])
    return {"points": pts, "vlm": vlm}


def table(pts, data) -> list[dict]:
    rows = []
    by_deg = {round(math.degrees(p["alpha"]), 6): p for p in pts}
    for a, CL, CD in zip(data["alpha_deg"], data["CL"], data["CD"]):
        p = by_deg.get(round(float(a), 6))
        if p is None:
            continue
        rows.append({"alpha_deg": float(a), "CL_measured": CL, "CL_model": p["CL"] if p["converged"] else float("nan"),
                     "CL_linear_lattice": p["CL_linear"], "CD_measured": CD,
                     "CD_model": p["CD"] if p["converged"] else float("nan"), "converged": p["converged"],
                     "residual": p["residual"]})
    return rows


def summary(rows, pts) -> str:
    def err(key, sel):
        e = [(r[key] - r["CL_measured"]) / r["CL_measured"] for r in rows if sel(r) and r["CL_measured"] > 0]
        return 100 * float(np.mean(np.abs(e))), 100 * float(np.max(np.abs(e)))
    conv = [p for p in pts if p["converged"]]
    i_max = int(np.argmax([p["CL"] for p in conv]))
    meas_max = max(rows, key=lambda r: r["CL_measured"])
    lin10, visc10 = err("CL_linear_lattice", lambda r: r["alpha_deg"] <= 10), \
        err("CL_model", lambda r: r["alpha_deg"] <= 10)
    failed = [f"{math.degrees(p['alpha']):.2f}" for p in pts if not p["converged"]]
    lines = [
        "| quantity | measured | viscous-corrected lattice | linear lattice |", "|---|---:|---:|---:|",
        f"| CL mean abs error, 1-10 deg | - | {visc10[0]:.1f} % (max {visc10[1]:.1f} %) | "
        f"{lin10[0]:.1f} % (max {lin10[1]:.1f} %) |",
        f"| CL_max (deg) | {meas_max['CL_measured']:.3f} ({meas_max['alpha_deg']:.0f}) | "
        f"{conv[i_max]['CL']:.3f} ({math.degrees(conv[i_max]['alpha']):.2f}) | none (linear) |",
        f"| lift-curve slope 0-6 deg (per deg) | {_slope(rows, 'CL_measured'):.4f} | "
        f"{_slope(rows, 'CL_model'):.4f} | {_slope(rows, 'CL_linear_lattice'):.4f} |",
        f"| angles converged (0.25 deg steps) | - | {len(conv)} of {len(pts)}; not at {', '.join(failed) or '-'} deg | - |",
    ]
    return "\n".join(lines)


def _slope(rows, key):
    sel = [r for r in rows if r["alpha_deg"] <= 6]
    return float(np.polyfit([r["alpha_deg"] for r in sel], [r[key] for r in sel], 1)[0])


def figure(rows, pts, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    a = [math.degrees(p["alpha"]) for p in pts]
    ok = np.array([p["converged"] for p in pts])
    CL = np.where(ok, [p["CL"] for p in pts], np.nan)
    CD = np.where(ok, [p["CD"] for p in pts], np.nan)
    ax[0].plot([r["alpha_deg"] for r in rows], [r["CL_measured"] for r in rows], "ko", label="measured (Graf et al. 2014)")
    ax[0].plot(a, CL, "C0-", label="lattice + viscous correction")
    ax[0].plot(a, [p["CL_linear"] for p in pts], "C1--", label="linear lattice")
    ax[0].set(xlabel="alpha (deg)", ylabel="CL", ylim=(0, 1.3))
    ax[1].plot([r["alpha_deg"] for r in rows], [r["CD_measured"] for r in rows], "ko", label="measured")
    ax[1].plot(a, CD, "C0-", label="model: Trefftz + section cd(alpha_e)")
    ax[1].set(xlabel="alpha (deg)", ylabel="CD")
    for x in ax:
        x.grid(alpha=0.3)
        x.legend(fontsize=8)
    fig.suptitle("NACA 0012 rectangular wing, AR 4.5 on a reflection plane")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def prowim_props_off() -> list[dict]:
    """The PROWIM wing props off (``veldhuis.py``'s lattice, 48 x 6 panels) at alpha 0 and 4 deg,
    linear and viscous-corrected (section: NACA 0015 at the test's Re 8e5 for its 64(2)-015A;
    issue 17's acceptance: the props-off RMS of Cn must stay within today's)."""
    import veldhuis as vd
    from mdo.airfoil import Airfoil
    from mdo.wing.viscous import shift_velocity
    fs, data, vlm = vd.freestream(), vd.measured(), vd.make_vlm()
    af = Airfoil.from_name("naca0015")

    def sec(ae):
        return af.coefficients(ae, 8e5 * ca.MX.ones(ae.shape), vd.MACH * ca.MX.ones(ae.shape))[0]
    out = []
    for a_deg in (0.0, 4.0):
        a = math.radians(a_deg)
        res = solve_viscous(vlm, [a], sec, V=fs["V"], rho=fs["rho"], mach=vd.MACH)[0]
        r = vlm.solve(a, fs["V"], rho=fs["rho"], mach=vd.MACH, v_ext=shift_velocity(vlm, ca.DM(res["shift"]), fs["V"]),
                      v_ext_bound=(ca.DM.zeros(vlm.n_panels, 1),) * 3)
        y, cn = vd.strip_cn(vlm, r)
        y0, cn0 = vd.solve_case(vlm, a, fs)[0]
        d = data[("props_off", a_deg)]
        out.append({"alpha_deg": a_deg, "rms_linear": vd.rms_against(y0, cn0, d), "rms_viscous": vd.rms_against(y, cn, d),
                    "converged": res["converged"]})
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="results/validation")
    ap.add_argument("--nspan", type=int, default=20)
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    data = read("graf2014_wing_measured.csv")
    res = run(args.nspan)
    rows = table(res["points"], data)
    fine = run(2 * args.nspan)
    rows_fine = table(fine["points"], data)
    with open(out / "graf_wing_stall.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    figure(rows, res["points"], out / "graf_wing_stall.png")
    md = ["# The wing through stall: viscous-corrected lattice vs a measured wing (Graf et al. 2014)", "",
          "Generated by `python problems/validation/graf_wing_stall.py` (model and sources in its docstring; data in "
          "`mdo/wing/data/wings`, SOURCES.md there).", "",
          f"Rectangular NACA 0012 wing, aspect ratio 4.5 on the tunnel floor (9 with its image); {args.nspan} strips "
          "per half, one chordwise panel; section polar = the authors' 2-D RANS points.", "",
          summary(rows, res["points"]), "",
          "| alpha (deg) | CL measured | CL model | CL linear lattice | CD measured | CD model |",
          "|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        md.append(f"| {r['alpha_deg']:.0f} | {r['CL_measured']:.3f} | {r['CL_model']:.3f} | "
                  f"{r['CL_linear_lattice']:.3f} | {r['CD_measured']:.4f} | {r['CD_model']:.4f} |")
    md += ["", f"With {2 * args.nspan} strips per half:", "", summary(rows_fine, fine["points"]), "",
           "## PROWIM props off (issue 17: must stay within its RMS)", "",
           "RMS of the spanwise Cn against Veldhuis' props-off data (`veldhuis.py`'s lattice; section NACA 0015 "
           "at Re 8e5 standing in for the 64(2)-015A):", "",
           "| alpha (deg) | linear lattice | viscous-corrected |", "|---:|---:|---:|"]
    md += [f"| {p['alpha_deg']:.0f} | {p['rms_linear']:.4f} | {p['rms_viscous']:.4f} |" for p in prowim_props_off()]
    md += ["",
           "Files: graf_wing_stall.csv (every measured angle), graf_wing_stall.png."]
    (out / "graf_wing_stall.md").write_text("\n".join(md) + "\n")
    print("\n".join(md))


if __name__ == "__main__":
    main()
