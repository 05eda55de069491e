"""Validation: APC 10x7 Thin Electric propeller against the UIUC wind-tunnel data.

The paper (Clarke et al., section IV.A, Fig. 3a) compares its BEMT with Brandt &
Selig's UIUC measurements of this propeller and reports under 10 % error up to
J = 0.7.  Here the BEMT of ``mdo.rotor`` is run at every rpm and every measured
advance ratio of ``mdo/rotor/data/apce_10x7_performance.csv`` (7 runs, 4007 to
6531 rpm), plus the static (J = 0) runs of ``apce_10x7_static.csv``.

Sections, chosen on physical grounds before comparing with the data: APC states
that its thin-electric propellers "blend the low Reynolds number Eppler E63
airfoil (inboard) with a Clark-Y similar airfoil (outboard)" (apcprop.com,
Technical information / Engineering).  The blend position is not published; the
model puts it at mid-blade (r/R = 0.5, logistic width 0.05).  The same run with
Clark-Y everywhere (the section SUAVE's regression script uses for this
propeller) is reported as a sensitivity.  Nothing else is adjusted: 20 cosine-
spaced stations, hub at the first geometry station (r/R = 0.15), Prandtl tip
and hub losses, sea-level USSA76 air.

Two ways to run it:

* ``python problems/validation/apc10x7.py`` -- analysis mode (bracketed solve);
  writes ``results/validation/apc10x7.png`` (CT, CP, eta vs J, model over data),
  ``apc10x7_errors.csv`` (every data point), ``apc10x7_static.csv`` and
  ``apc10x7_summary.md`` (mean and max |error| of CT and CP for J <= 0.7).
* ``mdo run problems/validation/apc10x7.py --out results/validation/apc10x7_nlp``
  -- the same operating points as ONE NLP: the inflow angles of every station at
  every data point are IPOPT variables and the BEMT residuals its constraints
  (``add_bemt_nodes``), i.e. the mission's NLP mode on the validation case; the
  report compares it with the analysis.
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from mdo.rotor import RotorGeometry, add_bemt_nodes, analyze, bemt_function, section
from mdo.rotor.analysis import operating_inputs
from mdo.rotor.geometry import DATA_DIR

DIAMETER_M = 10 * 0.0254
BLADES = 2
AIRFOIL = "e63:0.5:clark_y"         # APC: E63 inboard, Clark-Y-like outboard
SENSITIVITY_AIRFOIL = "clark_y"      # SUAVE's choice for this propeller
N_STATIONS = 20
J_LIMIT = 0.7
OUT_DIR = Path(__file__).resolve().parents[2] / "results" / "validation"


def rotor(airfoil: str = AIRFOIL) -> RotorGeometry:
    return RotorGeometry.from_csv(DATA_DIR / "apce_10x7_geometry.csv", diameter_m=DIAMETER_M, blades=BLADES,
                                  airfoil=airfoil, name="apce_10x7")


def performance_data() -> np.ndarray:
    return np.genfromtxt(DATA_DIR / "apce_10x7_performance.csv", delimiter=",", names=True)


def static_data() -> np.ndarray:
    return np.genfromtxt(DATA_DIR / "apce_10x7_static.csv", delimiter=",", names=True)


def _operating_points(d):
    n = d["rpm"] / 60.0
    return 2 * math.pi * n, d["J"] * n * DIAMETER_M


def model_at_data(airfoil: str = AIRFOIL) -> dict:
    """BEMT at every measured (rpm, J): one analysis call for all 123 points."""
    d = performance_data()
    om, v = _operating_points(d)
    res = analyze(rotor(airfoil), omega_radps=om, v_axial_mps=v, n_stations=N_STATIONS)
    return {"data": d, "res": res}


def error_table(m: dict) -> dict:
    d, res = m["data"], m["res"]
    eCT = (res["CT"] - d["CT"]) / d["CT"]
    eCP = (res["CP"] - d["CP"]) / d["CP"]
    sel = d["J"] <= J_LIMIT
    rows = {"all": sel}
    for rpm in np.unique(d["rpm"]):
        rows[f"{int(rpm)} rpm"] = sel & (d["rpm"] == rpm)
    table = {}
    for k, s in rows.items():
        table[k] = {"points": int(s.sum()),
                    "CT_mean": float(np.mean(np.abs(eCT[s]))), "CT_max": float(np.max(np.abs(eCT[s]))),
                    "CP_mean": float(np.mean(np.abs(eCP[s]))), "CP_max": float(np.max(np.abs(eCP[s])))}
    return {"eCT": eCT, "eCP": eCP, "table": table}


def write_outputs(out_dir: Path = OUT_DIR) -> dict:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out_dir.mkdir(parents=True, exist_ok=True)
    main = model_at_data(AIRFOIL)
    sens = model_at_data(SENSITIVITY_AIRFOIL)
    err = error_table(main)
    err_s = error_table(sens)
    d, res = main["data"], main["res"]
    assert res.converged.all(), "BEMT residual not converged at some data point"

    with open(out_dir / "apc10x7_errors.csv", "w") as f:
        f.write("rpm,J,CT_data,CT_model,CT_rel_err,CP_data,CP_model,CP_rel_err,eta_data,eta_model,"
                "CT_model_clarky,CP_model_clarky,residual_max\n")
        for i in range(d.size):
            f.write(f"{int(d['rpm'][i])},{d['J'][i]:.4f},{d['CT'][i]:.5f},{res['CT'][i]:.5f},{err['eCT'][i]:.4f},"
                    f"{d['CP'][i]:.5f},{res['CP'][i]:.5f},{err['eCP'][i]:.4f},{d['eta'][i]:.4f},"
                    f"{res['eta'][i]:.4f},{sens['res']['CT'][i]:.5f},{sens['res']['CP'][i]:.5f},"
                    f"{res.residual_max[i]:.2e}\n")

    st = static_data()
    rs = analyze(rotor(AIRFOIL), omega_radps=2 * math.pi * st["rpm"] / 60.0, v_axial_mps=0.0,
                 n_stations=N_STATIONS)
    with open(out_dir / "apc10x7_static.csv", "w") as f:
        f.write("rpm,CT_data,CT_model,CT_rel_err,CP_data,CP_model,CP_rel_err,FM_model\n")
        for i in range(st.size):
            f.write(f"{int(st['rpm'][i])},{st['CT'][i]:.4f},{rs['CT'][i]:.5f},{rs['CT'][i] / st['CT'][i] - 1:.4f},"
                    f"{st['CP'][i]:.4f},{rs['CP'][i]:.5f},{rs['CP'][i] / st['CP'][i] - 1:.4f},{rs['FM'][i]:.4f}\n")
    eCT0 = np.abs(rs["CT"] / st["CT"] - 1)
    eCP0 = np.abs(rs["CP"] / st["CP"] - 1)

    # curves on a fine J grid, one per rpm
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
    rpms = np.unique(d["rpm"])
    colors = plt.cm.viridis(np.linspace(0, 0.9, rpms.size))
    Jf = np.linspace(0.0, 0.9, 91)
    for c, rpm in zip(colors, rpms):
        s = d["rpm"] == rpm
        r = analyze(rotor(AIRFOIL), omega_radps=np.full(Jf.size, 2 * math.pi * rpm / 60),
                    v_axial_mps=Jf * rpm / 60 * DIAMETER_M, n_stations=N_STATIONS)
        curves = {"CT": r["CT"], "CP": r["CP"],
                  "eta": np.where((r["CT"] > 0) & (r["CP"] > 0), r["eta"], np.nan)}  # eta: thrusting only
        for k, key in enumerate(("CT", "CP", "eta")):
            ax[k].plot(Jf, curves[key], "-", color=c, lw=1.2, label=f"{int(rpm)} rpm" if k == 0 else None)
            ax[k].plot(d["J"][s], d[key][s], "o", color=c, ms=3.5, mfc="none")
    for k, (key, lab) in enumerate((("CT", "$C_T$"), ("CP", "$C_P$"), ("eta", r"$\eta$"))):
        ax[k].set_xlabel("J")
        ax[k].set_ylabel(lab)
        ax[k].grid(alpha=0.3)
        ax[k].axvline(J_LIMIT, color="0.6", ls=":", lw=1)
    ax[2].set_ylim(0, 0.9)
    ax[0].legend(fontsize=8, title="lines: BEMT, circles: UIUC")
    t = err["table"]["all"]
    fig.suptitle(f"APC 10x7 Thin Electric, BEMT (E63 inboard / Clark-Y outboard) vs UIUC data; J <= {J_LIMIT}: "
                 f"mean |err| CT {100 * t['CT_mean']:.1f} %, CP {100 * t['CP_mean']:.1f} %", fontsize=11)
    fig.tight_layout()
    fig.savefig(out_dir / "apc10x7.png", dpi=130)
    plt.close(fig)

    lines = ["# APC 10x7 Thin Electric: BEMT vs UIUC wind-tunnel data", "",
             f"Sections: {AIRFOIL} (E63 inboard of r/R 0.5, Clark-Y outboard; APC's stated practice). "
             f"{N_STATIONS} stations, sea level. Relative errors (model - data)/data for J <= {J_LIMIT}.", "",
             "| runs | points | CT mean abs err | CT max abs err | CP mean abs err | CP max abs err |",
             "|---|---|---|---|---|---|"]
    for k, v in err["table"].items():
        lines.append(f"| {k} | {v['points']} | {100 * v['CT_mean']:.1f} % | {100 * v['CT_max']:.1f} % | "
                     f"{100 * v['CP_mean']:.1f} % | {100 * v['CP_max']:.1f} % |")
    ts = err_s["table"]["all"]
    lines += ["", f"Sensitivity, Clark-Y at every station (SUAVE's choice): CT mean {100 * ts['CT_mean']:.1f} % "
                  f"(max {100 * ts['CT_max']:.1f} %), CP mean {100 * ts['CP_mean']:.1f} % (max {100 * ts['CP_max']:.1f} %).",
              f"Static runs (J = 0, {st.size} rpm from {int(st['rpm'].min())} to {int(st['rpm'].max())}): "
              f"CT mean {100 * eCT0.mean():.1f} % (max {100 * eCT0.max():.1f} %), "
              f"CP mean {100 * eCP0.mean():.1f} % (max {100 * eCP0.max():.1f} %).",
              f"Largest BEMT residual over all points: {res.residual_max.max():.1e}.",
              "", "Files: apc10x7.png, apc10x7_errors.csv (every point), apc10x7_static.csv."]
    (out_dir / "apc10x7_summary.md").write_text("\n".join(lines) + "\n")
    return {"table": err["table"], "sensitivity": err_s["table"], "static_CT": eCT0, "static_CP": eCP0}


# allowed values of the -o options (mdo.nlp.options)
OPTIONS = {"n_stations": (int, 6, 60)}


def build(airfoil: str = AIRFOIL, n_stations: int = N_STATIONS, **_):
    """The validation as one NLP: inflow angles of all stations x data points as
    variables, BEMT residuals as constraints, no objective (a feasibility solve)."""
    from mdo.nlp import Problem

    d = performance_data()
    om, v = _operating_points(d)
    rot = rotor(airfoil)
    sec = section(airfoil)
    inputs, _ = operating_inputs(rot, omega_radps=om, v_axial_mps=v, n_stations=n_stations)
    K = d.size
    ref = analyze(rot, omega_radps=om, v_axial_mps=v, n_stations=n_stations)
    start = np.full((n_stations, K), 0.3)     # a flat start, not the answer: IPOPT must find it
    from mdo.rotor import phi_momentum_guess
    st = rot.stations(n_stations)
    for k in range(K):
        start[:, k] = phi_momentum_guess(st["r_m"], st["chord_m"], st["beta_rad"], v[k], om[k] * st["r_m"], BLADES,
                                         alpha0=math.radians(-4.0))
    p = Problem("apc10x7_nlp", "APC 10x7 validation points as one NLP (BEMT residuals as constraints)")
    row = (lambda x: np.asarray(x, dtype=float).reshape(1, -1))
    nlp_inputs = dict(inputs)
    nlp_inputs["omega_radps"] = row(om)
    nlp_inputs["v_axial_mps"] = row(v)
    out = add_bemt_nodes(p, "apc", bemt_function(sec, n_stations), nlp_inputs, n_nodes=K, phi_init=start)
    n_rev = om / (2 * math.pi)
    rho = float(np.asarray(inputs["rho_kgpm3"]).ravel()[0])
    p.output("CT", out["thrust_N"] / (rho * row(n_rev) ** 2 * DIAMETER_M ** 4))
    p.output("CP", out["power_W"] / (rho * row(n_rev) ** 3 * DIAMETER_M ** 5))

    def report(solution, out_dir):
        ct = np.asarray(solution.outputs["CT"]["value"], dtype=float).ravel()
        cp = np.asarray(solution.outputs["CP"]["value"], dtype=float).ravel()
        lines = ["# APC 10x7 validation points solved as one NLP", "",
                 f"{K} operating points x {n_stations} stations = {K * n_stations} inflow angles.",
                 f"Max |CT_nlp - CT_analysis| = {np.max(np.abs(ct - ref['CT'])):.2e}, "
                 f"max |CP_nlp - CP_analysis| = {np.max(np.abs(cp - ref['CP'])):.2e}.",
                 f"Mean |CT err| vs data (J <= {J_LIMIT}): "
                 f"{100 * np.mean(np.abs(ct / d['CT'] - 1)[d['J'] <= J_LIMIT]):.2f} %, CP: "
                 f"{100 * np.mean(np.abs(cp / d['CP'] - 1)[d['J'] <= J_LIMIT]):.2f} %."]
        Path(out_dir, "apc10x7_nlp_check.md").write_text("\n".join(lines) + "\n")

    p.add_report(report)
    return p


if __name__ == "__main__":
    out = write_outputs(Path(sys.argv[1]) if len(sys.argv) > 1 else OUT_DIR)
    for k, v in out["table"].items():
        print(f"{k:>10}: CT mean {100 * v['CT_mean']:5.1f} % max {100 * v['CT_max']:5.1f} %   "
              f"CP mean {100 * v['CP_mean']:5.1f} % max {100 * v['CP_max']:5.1f} %")
    s = out["sensitivity"]["all"]
    print(f"Clark-Y only: CT mean {100 * s['CT_mean']:.1f} %, CP mean {100 * s['CP_mean']:.1f} %")
