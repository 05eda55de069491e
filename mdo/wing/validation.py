"""Validation cases of the vortex lattice, and the script that writes ``results/validation/vlm_*``.

Run ``python -m mdo.wing.validation [OUT_DIR]`` (default ``results/validation``)
to write ``vlm_convergence.png/.csv``, ``vlm_cases.png`` and ``vlm_validation.json``.
The tests (``tests/test_wing_*.py``) call the same case functions at coarser
settings.

References
----------
* Lifting-line theory (elliptic wing): CL_alpha = 2 pi AR / (AR + 2), e = 1.
* Helmbold (1942) / DATCOM: CL_alpha = 2 pi AR / (2 + sqrt(AR^2 + 4)).
* Bertin & Smith, *Aerodynamics for Engineers*, Example 7.2: flat wing AR 5,
  taper 1, quarter-chord sweep 45 deg, four horseshoes per semispan:
  CL_alpha = 0.0601 /deg; Weber & Brebner (1958, ARC R&M 2882) measured
  CL = 0.121, 0.238, 0.350, 0.456, 0.559 at 2.1, 4.2, 6.3, 8.4, 10.5 deg (as quoted
  in FLOWVLM's validation script, byuflowlab/FLOWVLM examples).
* AVL 3.35 (Drela & Youngren) runs of byuflowlab/VortexLattice.jl's test suite:
  wing x_le 0 -> 0.4, y 0 -> 7.5, chord 2.2 -> 1.8, Ainc 2 deg, 12 x 1 uniform
  panels, S 30, c 2, b 15, x_ref 0.5; run 1 (alpha 1 deg): CL 0.24324, CDff 0.00245,
  Cm -0.02252; run 3 (alpha 8 deg): 0.80348, 0.02696, -0.07399; run 4 (tip at
  z = 3.0, dihedral 21.8 deg, alpha 1 deg): 0.24787, 0.00245, -0.02395; run 7 (6
  chordwise panels): 0.24454, 0.00248, -0.02091; run 6 (the dihedral wing 10 m x
  1 -> 0.6 m with a horizontal and a vertical tail 4 m aft, alpha 5 deg, S 9, c 0.9,
  b 10): CL 0.60408, CDff 0.010378, Cm -0.02778.
"""
from __future__ import annotations

import json
import math
import sys
import time
from pathlib import Path

import numpy as np

from .geometry import Section, Surface, trapezoid
from .vlm import VLM

D = math.radians


def lifting_line_elliptic(ar):
    return 2 * math.pi * ar / (ar + 2)


def helmbold(ar):
    return 2 * math.pi * ar / (2 + math.sqrt(ar * ar + 4))


def elliptic_wing(ar: float, nspan: int, nchord: int = 1, span: float = 1.0) -> Surface:
    """Planar elliptic wing with a straight quarter-chord line; sections at the strip edges."""
    area = span * span / ar
    c_root = 4 * area / (math.pi * span)
    eta = np.sin(0.5 * np.pi * np.arange(nspan + 1) / nspan)
    secs = [Section(float(e), float(np.sqrt(max(1 - e * e, 0.0)))) for e in eta]
    return Surface("elliptic", span, c_root, secs, nspan=nspan, nchord=nchord, anchor_sections=False)


def lift_slope(vlm: VLM, alpha=D(2.0)) -> dict:
    """CL_alpha (1/rad, from CL(alpha) - CL(0)) and e at alpha."""
    r = vlm.solve([0.0, alpha], 1.0)
    cl = np.array(r["CL"]).ravel()
    return {"CLa": float((cl[1] - cl[0]) / alpha), "e": float(np.array(r["e"]).ravel()[1]),
            "CL": float(cl[1]), "CDi": float(np.array(r["CDi"]).ravel()[1])}


def case_elliptic(ar=8.0, nspan=32, nchord=1) -> dict:
    w = elliptic_wing(ar, nspan, nchord)
    out = lift_slope(VLM([w], S_ref=1.0 / ar, b_ref=1.0))
    out.update(AR=ar, CLa_lifting_line=lifting_line_elliptic(ar), CLa_helmbold=helmbold(ar))
    return out


def case_rectangular(ar=8.0, nspan=32, nchord=4) -> dict:
    w = trapezoid("rect", ar, 1.0, 1.0, nspan=nspan, nchord=nchord)
    out = lift_slope(VLM([w]))
    out.update(AR=ar, CLa_helmbold=helmbold(ar))
    return out


def case_bertin(nspan=4, nchord=1, spacing="uniform") -> dict:
    """Bertin & Smith Example 7.2 (AR 5, sweep 45 deg); CL_alpha per degree."""
    w = trapezoid("bertin", 5.0, 1.0, 1.0, sweep=D(45.0), nspan=nspan, nchord=nchord, spacing=spacing)
    v = VLM([w])
    r = v.solve(np.radians([2.1, 4.2, 6.3, 8.4, 10.5]), 1.0)
    cl = np.array(r["CL"]).ravel()
    return {"CLa_per_deg": float(cl[1] / 4.2), "CL": cl.tolist(),
            "CL_weber_brebner": [0.121, 0.238, 0.350, 0.456, 0.559], "CLa_bertin_per_deg": 0.0601}


def avl_wing(z_tip=0.0, nchord=1) -> Surface:
    """The AVL test wing of VortexLattice.jl (see module doc); AVL's Ainc about the inclined axis."""
    sweep = math.atan((0.4 + 1.8 / 4 - 2.2 / 4) / 7.5)
    dih = math.atan(z_tip / 7.5)
    tw = math.atan(math.tan(D(2.0)) / math.cos(dih))
    return Surface("wing", 15.0, 2.2, [Section(0, 1.0, tw), Section(1, 1.8 / 2.2, tw)], sweep=sweep,
                   dihedral=dih, nspan=12, nchord=nchord, spacing="uniform")


AVL_RUNS = {  # name: (z_tip, nchord, alpha deg, (CL, CDff, Cm))
    "run1": (0.0, 1, 1.0, (0.24324, 0.00245, -0.02252)),
    "run3": (0.0, 1, 8.0, (0.80348, 0.02696, -0.07399)),
    "run4_dihedral": (3.0, 1, 1.0, (0.24787, 0.00245, -0.02395)),
    "run7_nchord6": (0.0, 6, 1.0, (0.24454, 0.00248, -0.02091)),
}


def case_avl(name: str, near_field=True, trefftz="midpoint") -> dict:
    z, nc, a, ref = AVL_RUNS[name]
    v = VLM([avl_wing(z, nc)], S_ref=30.0, c_ref=2.0, b_ref=15.0, r_ref=(0.5, 0, 0),
            trefftz=trefftz, near_field=near_field)
    r = v.solve(D(a), 1.0)
    return {"CL": float(r["CL"]), "CDff": float(r["CDi_ff"]), "Cm": float(r["Cm"]),
            "AVL": dict(zip(("CL", "CDff", "Cm"), ref))}


def avl_wing_tail() -> list[Surface]:
    def sweep(x_tip, c_tip, c_root, y_tip):
        return math.atan((x_tip + c_tip / 4 - c_root / 4) / y_tip)
    dih = math.atan(1 / 5)
    tw = math.atan(math.tan(D(2.0)) / math.cos(dih))
    wing = Surface("wing", 10.0, 1.0, [Section(0, 1.0, tw), Section(1, 0.6, tw)],
                   sweep=sweep(0.2, 0.6, 1.0, 5.0), dihedral=dih, nspan=12, spacing="uniform")
    ht = Surface("htail", 2.5, 0.7, [Section(0, 1.0), Section(1, 0.6)], sweep=sweep(0.14, 0.42, 0.7, 1.25),
                 origin=(4.0, 0, 0), nspan=6, spacing="uniform")
    vt = Surface("vtail", 1.0, 0.7, [Section(0, 1.0), Section(1, 0.6)], sweep=sweep(0.14, 0.42, 0.7, 1.0),
                 origin=(4.0, 0, 0), nspan=5, spacing="uniform", mirrored=False, vertical=True)
    return [wing, ht, vt]


def case_avl_wing_tail(near_field=True, symmetric=False) -> dict:
    v = VLM(avl_wing_tail(), S_ref=9.0, c_ref=0.9, b_ref=10.0, r_ref=(0.5, 0, 0), trefftz="midpoint",
            near_field=near_field, symmetric=symmetric)
    r = v.solve(D(5.0), 1.0)
    return {"CL": float(r["CL"]), "CDff": float(r["CDi_ff"]), "Cm": float(r["Cm"]), "CY": float(r["CY"]),
            "AVL": {"CL": 0.60408, "CDff": 0.010378, "Cm": -0.02778}}


def ga_wing(nspan=20, nchord=2) -> Surface:
    """GA-2P main wing of the paper (Table 3 initial: span 11.4 m, taper 0.7, twists 3..2 deg, S 14.76)."""
    from .geometry import constant_area
    return constant_area("main", 14.76, 11.4, 0.7, [D(t) for t in (3.0, 2.75, 2.5, 2.25, 2.0)],
                         nspan=nspan, nchord=nchord, airfoil="naca63412", anchor_sections=False)


def convergence(nspans=(4, 6, 8, 12, 16, 24, 32, 48, 64, 96)) -> list[dict]:
    rows = []
    for n in nspans:
        t = time.time()
        ell = case_elliptic(8.0, n, 1)
        rect = case_rectangular(8.0, n, 4)
        v = VLM([ga_wing(n, 2)], S_ref=14.76)
        r = v.solve(D(2.0), 1.0)
        rows.append({"nspan": n, "elliptic_CLa": ell["CLa"], "elliptic_e": ell["e"],
                     "rect_CLa": rect["CLa"], "rect_e": rect["e"],
                     "ga_CL": float(r["CL"]), "ga_CDi": float(r["CDi"]), "ga_e": float(r["e"]),
                     "seconds": time.time() - t})
    return rows


def main(out_dir="results/validation") -> dict:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    rows = convergence()
    keys = list(rows[0])
    with open(out / "vlm_convergence.csv", "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join(f"{r[k]:.6g}" for k in keys) + "\n")
    n = np.array([r["nspan"] for r in rows])
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2))
    ax[0].semilogx(n, [r["elliptic_e"] for r in rows], "o-", label="elliptic AR 8 (linear-Gamma Trefftz)")
    ax[0].semilogx(n, [r["rect_e"] for r in rows], "s-", label="rectangular AR 8")
    ax[0].semilogx(n, [r["ga_e"] for r in rows], "^-", label="GA-2P wing (alpha 2 deg)")
    ax[0].axhspan(0.99, 1.01, color="0.9", label="elliptic target 1 +- 1 %")
    ax[0].set_xlabel("panels per semispan")
    ax[0].set_ylabel("span efficiency e")
    ax[0].legend(fontsize=8)
    ax[1].semilogx(n, [r["elliptic_CLa"] for r in rows], "o-", label="elliptic AR 8")
    ax[1].axhline(lifting_line_elliptic(8), ls="--", color="C0", label="lifting line, elliptic")
    ax[1].semilogx(n, [r["rect_CLa"] for r in rows], "s-", color="C1", label="rectangular AR 8 (4 chordwise)")
    ax[1].axhline(helmbold(8), ls=":", color="k", label="Helmbold AR 8")
    ax[1].set_xlabel("panels per semispan")
    ax[1].set_ylabel("CL_alpha [1/rad]")
    ax[1].legend(fontsize=8)
    ax[2].semilogx(n, [r["ga_CL"] for r in rows], "o-", label="CL")
    ax2 = ax[2].twinx()
    ax2.semilogx(n, [1e4 * r["ga_CDi"] for r in rows], "s-", color="C3", label="CDi x 1e4")
    ax[2].set_xlabel("panels per semispan (2 chordwise)")
    ax[2].set_ylabel("CL")
    ax2.set_ylabel("CDi x 1e4")
    ax[2].set_title("GA-2P wing, alpha 2 deg, NACA 63-412 camber")
    fig.tight_layout()
    fig.savefig(out / "vlm_convergence.png", dpi=120)
    plt.close(fig)

    summary = {
        "elliptic_AR8_n32": case_elliptic(8.0, 32, 1),
        "elliptic_AR20_n48": case_elliptic(20.0, 48, 1),
        "rectangular_AR8_n48_c4": case_rectangular(8.0, 48, 4),
        "bertin_4x1": case_bertin(4, 1),
        "bertin_converged_48x4": case_bertin(48, 4, "cosine"),
        "avl": {k: case_avl(k) for k in AVL_RUNS},
        "avl_run6_wing_tail": case_avl_wing_tail(),
        "convergence": rows,
    }
    (out / "vlm_validation.json").write_text(json.dumps(summary, indent=1))

    # swept (Bertin/Weber-Brebner) and dihedral / wing-tail (AVL) figure
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    a = np.array([2.1, 4.2, 6.3, 8.4, 10.5])
    ax[0].plot(a, summary["bertin_converged_48x4"]["CL"], "o-", label="mdo VLM 48 x 4 cosine")
    ax[0].plot(a, summary["bertin_4x1"]["CL"], "s--", label="mdo VLM 4 x 1 (Bertin's lattice)")
    ax[0].plot(a, 0.0601 * a, "k:", label="Bertin & Smith Ex. 7.2 (0.0601/deg)")
    ax[0].plot(a, summary["bertin_4x1"]["CL_weber_brebner"], "kD", label="Weber & Brebner 1958 (exp.)")
    ax[0].set_xlabel("alpha [deg]")
    ax[0].set_ylabel("CL")
    ax[0].set_title("45 deg swept wing, AR 5")
    ax[0].legend(fontsize=8)
    names = list(summary["avl"]) + ["run6 wing+tails"]
    vals = list(summary["avl"].values()) + [summary["avl_run6_wing_tail"]]
    for i, (k, lab) in enumerate((("CL", "CL"), ("CDff", "CDff"), ("Cm", "Cm"))):
        err = [100 * (v[k] / v["AVL"][k] - 1) for v in vals]
        ax[1].bar(np.arange(len(names)) + 0.27 * (i - 1), err, width=0.27, label=lab)
    ax[1].set_xticks(range(len(names)))
    ax[1].set_xticklabels(names, rotation=20, fontsize=8)
    ax[1].axhline(0, color="k", lw=0.5)
    ax[1].set_ylabel("difference from AVL 3.35 [%]")
    ax[1].set_title("AVL runs (near-field forces, midpoint Trefftz)")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "vlm_cases.png", dpi=120)
    plt.close(fig)
    return summary


if __name__ == "__main__":
    s = main(*sys.argv[1:2])
    print(json.dumps({k: v for k, v in s.items() if k != "convergence"}, indent=1))
