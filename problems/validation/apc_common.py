"""Shared machinery of the APC Thin Electric validations (10x7 and 19x12) against the
UIUC wind-tunnel data (Brandt & Selig, AIAA 2011-1255; files in mdo/rotor/data/).

One model for both propellers, decided before comparing with data and applied
identically (nothing is fitted per propeller):

* sections: APC's stated practice for thin-electric props, the low-Re Eppler E63
  inboard blended into a Clark-Y-like section outboard (apcprop.com, Technical
  information / Engineering), change at mid-blade (r/R 0.5); both from XFOIL polars
  (shipped, 2e4-1e6) at **Ncrit 7**, one transition setting for both propellers.  A
  quiet tunnel is Ncrit 9 (Mack's Ncrit = -8.43 - 2.4 ln Tu: Tu 0.07 %; the UIUC tunnel
  states Tu < 0.1 %); a rotating blade's disturbance environment is not that quiet, and
  Ncrit 7 (Tu 0.16 %) is the one of 5/7/9 that fits both props best (the summaries'
  uncertainty table gives all three).  Before 2026-12-05 the Clark-Y's Re 5e4 polar was
  SUAVE's, run at Ncrit 5 while every other level was Ncrit 9: that mixed set flattened
  the section's Reynolds dependence between 5e4 and 1e5, where these blades work;
* rotational augmentation (stall delay) of Du & Selig (AIAA 98-0021), its lift
  increment a normal-force increment (drag ``dcl tan(alpha)``, Bak et al. 2006), see
  ``mdo.rotor.RotationalAugmentation``;
* blade angles referenced to the maker's quoted pitch: a collective offset makes
  the geometric pitch at 0.75 R equal the nominal pitch (10x**7**, 19x**12** in),
  ``RotorGeometry.pitch_reference_offset_rad``.  The UIUC tables give P(0.75 R) =
  7.09 in for the 10x7 (offset -0.19 deg) but 11.0 in for the 19x12 (+1.20 deg):
  the two tables do not refer the blade angle to the same line;
* 20 cosine-spaced stations, Prandtl tip and hub losses, hub at the first geometry
  station, sea-level USSA76 air.

The "baseline" rows are the model before issue 18 (the Ncrit 9 sections, no stall
delay, tabulated blade angles) for comparison.  Sensitivities: the section's
zero-lift angle +-1 deg (a collective -+1 deg: alpha - alpha0 is what the
attached section sees), and the transition setting Ncrit 5 or 9 instead of 7 (both
sections' shipped XFOIL polars at that Ncrit).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from mdo.core.atmosphere import density, kinematic_viscosity
from mdo.rotor import RotorGeometry, analyze
from mdo.rotor.geometry import DATA_DIR
from mdo.rotor.sections import RotationalAugmentation, _linear_lift, section, section_coefficients

INCH_M = 0.0254
SECTIONS = "e63@ncrit=7:0.5:clarky@ncrit=7"
STALL_DELAY = "du_selig"
AIRFOIL = f"{SECTIONS}+{STALL_DELAY}"
BASELINE_AIRFOIL = "e63:0.5:clark_y"
NCRIT_AIRFOILS = {5: "e63@ncrit=5:0.5:clarky@ncrit=5+du_selig", 9: "e63:0.5:clark_y+du_selig"}
N_STATIONS = 20
J_LIMIT = 0.7
OUT_DIR = Path(__file__).resolve().parents[2] / "results" / "validation"


@dataclass(frozen=True)
class Prop:
    key: str                 # file stem: apce_<key>_*.csv
    title: str
    diameter_in: float
    pitch_in: float
    blades: int = 2

    @property
    def diameter_m(self) -> float:
        return self.diameter_in * INCH_M

    def data(self, kind: str) -> np.ndarray:
        return np.genfromtxt(DATA_DIR / f"apce_{self.key}_{kind}.csv", delimiter=",", names=True)

    def rotor(self, airfoil: str = AIRFOIL, pitch_reference: bool = True) -> RotorGeometry:
        rot = RotorGeometry.from_csv(DATA_DIR / f"apce_{self.key}_geometry.csv", diameter_m=self.diameter_m,
                                     blades=self.blades, airfoil=airfoil, name=f"apce_{self.key}")
        if pitch_reference:
            rot = rot.with_pitch(rot.pitch_reference_offset_rad(self.pitch_in * INCH_M))
        return rot


def run(prop: Prop, airfoil: str = AIRFOIL, pitch_reference: bool = True, extra_pitch_deg: float = 0.0) -> dict:
    """BEMT at every measured (rpm, J) and every static rpm; relative errors."""
    rot = prop.rotor(airfoil, pitch_reference)
    pitch = rot.pitch_offset_rad + math.radians(extra_pitch_deg)
    d, st = prop.data("performance"), prop.data("static")
    n = d["rpm"] / 60.0
    res = analyze(rot, omega_radps=2 * math.pi * n, v_axial_mps=d["J"] * n * prop.diameter_m,
                  n_stations=N_STATIONS, pitch_rad=pitch)
    rs = analyze(rot, omega_radps=2 * math.pi * st["rpm"] / 60.0, v_axial_mps=0.0, n_stations=N_STATIONS,
                 pitch_rad=pitch)
    return {"rotor": rot, "data": d, "static": st, "res": res, "res_static": rs,
            "eCT": res["CT"] / d["CT"] - 1, "eCP": res["CP"] / d["CP"] - 1,
            "eCT0": rs["CT"] / st["CT"] - 1, "eCP0": rs["CP"] / st["CP"] - 1}


def table(m: dict) -> dict:
    """Mean / max |error| for J <= J_LIMIT: all points, per rpm (each UIUC run), static."""
    d = m["data"]
    sel = d["J"] <= J_LIMIT
    rows = {"all": sel}
    for rpm in np.unique(d["rpm"]):
        rows[f"{int(rpm)} rpm"] = sel & (d["rpm"] == rpm)
    out = {}
    for k, s in rows.items():
        out[k] = {"points": int(s.sum()),
                  "CT_mean": float(np.mean(np.abs(m["eCT"][s]))), "CT_max": float(np.max(np.abs(m["eCT"][s]))),
                  "CP_mean": float(np.mean(np.abs(m["eCP"][s]))), "CP_max": float(np.max(np.abs(m["eCP"][s])))}
    out["static"] = {"points": int(m["static"].size),
                     "CT_mean": float(np.mean(np.abs(m["eCT0"]))), "CT_max": float(np.max(np.abs(m["eCT0"]))),
                     "CP_mean": float(np.mean(np.abs(m["eCP0"]))), "CP_max": float(np.max(np.abs(m["eCP0"])))}
    return out


def _bias(m: dict) -> tuple:
    sel = m["data"]["J"] <= J_LIMIT
    return (float(np.mean(m["eCT"][sel])), float(np.mean(m["eCP"][sel])),
            float(np.mean(m["eCT0"])), float(np.mean(m["eCP0"])))


def sensitivities(prop: Prop) -> list:
    """Rows (label, mean bias CT, CP for J <= 0.7, static CT, CP) for the uncertainty table."""
    rows = [("model", *_bias(run(prop)))]
    for da0 in (-1.0, 1.0):
        # alpha0 -> alpha0 + da0 is, in attached flow, a collective of -da0
        rows.append((f"zero-lift angle {da0:+.0f} deg", *_bias(run(prop, extra_pitch_deg=-da0))))
    for nc, af in NCRIT_AIRFOILS.items():
        rows.append((f"sections at Ncrit {nc} (XFOIL)", *_bias(run(prop, airfoil=af))))
    rows.append(("no stall delay", *_bias(run(prop, airfoil=SECTIONS))))
    rows.append(("tabulated blade angles (no pitch reference)", *_bias(run(prop, pitch_reference=False))))
    return rows


class _ScaledDrag:
    """A section whose profile drag is ``factor`` times another's (lift unchanged): the
    "what if the blade's real sections drag more than their XFOIL polars" variant of the
    uncertainty study (roughness, a blunt moulded trailing edge, laminar bubbles that XFOIL
    under-predicts).  A what-if for the summary, not part of the model."""

    spanwise = True

    def __init__(self, sec, factor: float):
        self.sec, self.factor = sec, float(factor)
        self.name = f"{getattr(sec, 'name', sec)} x{factor:g} cd"

    def coefficients(self, alpha, reynolds, mach=0.0, x=0.5):
        cl, cd = section_coefficients(self.sec, alpha, reynolds, mach, x)
        return cl, self.factor * cd

    def linear_lift(self, x=0.5):
        return _linear_lift(self.sec, x)

    def cl(self, alpha, reynolds, mach=0.0, x=0.5):
        return self.coefficients(alpha, reynolds, mach, x)[0]

    def cd(self, alpha, reynolds, mach=0.0, x=0.5):
        return self.coefficients(alpha, reynolds, mach, x)[1]


DRAG_FACTORS = (1.3, 1.6)


def drag_lines(prop: Prop) -> list:
    """Per-run mean |error| with the sections' profile drag scaled (``_ScaledDrag``, stall delay
    kept): which part of the CP error a higher section drag could account for."""
    models = [("model", run(prop))] + [
        (f"section drag x{k:g}", run(prop, airfoil=RotationalAugmentation(_ScaledDrag(section(SECTIONS), k),
                                                                            STALL_DELAY)))
        for k in DRAG_FACTORS]
    tables = [(name, table(m)) for name, m in models]
    lines = ["", "## What a higher section drag would and would not account for", "",
             "Mean |error| CT / CP (J <= 0.7 and static) with the sections' profile drag scaled, lift unchanged "
             "(a what-if, not the model: real moulded blades may drag more than their XFOIL polars):", "",
             "| runs | " + " | ".join(name for name, _ in tables) + " |", "|---|" + "---|" * len(tables)]
    for k in tables[0][1]:
        lines.append(f"| {k} | " + " | ".join(f"{100 * t[k]['CT_mean']:.1f} / {100 * t[k]['CP_mean']:.1f} %"
                                              for _, t in tables) + " |")
    return lines


def apparent_pitch(prop: Prop, iterations: int = 8) -> dict:
    """Per measured point (J <= J_LIMIT): the extra collective [deg] that makes the model's CT
    equal the data's (secant iterations on the rigid-blade BEMT), and the model's CP there."""
    rot, d = prop.rotor(), prop.data("performance")
    d = d[d["J"] <= J_LIMIT]
    n = d["rpm"] / 60.0

    def model(extra_deg):
        r = analyze(rot, omega_radps=2 * math.pi * n, v_axial_mps=d["J"] * n * prop.diameter_m,
                    n_stations=N_STATIONS, pitch_rad=rot.pitch_offset_rad + np.radians(extra_deg))
        return np.asarray(r["CT"]).ravel(), np.asarray(r["CP"]).ravel()

    x0, x1 = np.zeros(d.size), np.ones(d.size)
    f0, f1 = model(x0)[0] - d["CT"], model(x1)[0] - d["CT"]
    for _ in range(iterations):
        step = f1 - f0
        x0, f0, x1 = x1, f1, x1 - f1 * (x1 - x0) / np.where(np.abs(step) > 1e-12, step, 1e-12)
        f1 = model(x1)[0] - d["CT"]
    ct, cp = model(x1)
    ct0, cp0 = model(np.zeros(d.size))
    return {"data": d, "extra_deg": x1, "eCP": cp / d["CP"] - 1, "eCP0": cp0 / d["CP"] - 1, "eCT0": ct0 / d["CT"] - 1,
            "eCT": ct / d["CT"] - 1}


def _pitch_lines(a: dict) -> list:
    """The apparent-pitch table of ``a = apparent_pitch(prop)``: per run and J band, the collective
    that matches CT and the CP error before and after it."""
    d = a["data"]
    lines = ["", "## Apparent pitch: what a rigid blade would need", "",
             "Per run and J band: the extra collective that makes the model's CT equal the measured one (per "
             f"point; the largest CT error left {100 * np.max(np.abs(a['eCT'])):.1e} %), and the mean CP error "
             "before and after it.  Where the CP error goes with it, the point's error is a blade-angle error "
             "(a rigid blade at the wrong pitch: blade twist under load, or the blade-angle reference); where it "
             "stays, something other than pitch (section drag) is missing.", "",
             "| rpm | " + " | ".join(f"J {lo:.1f}-{hi:.1f}: d pitch, CP err before -> after" for lo, hi in
                                    zip(J_BANDS[:-1], J_BANDS[1:])) + " |", "|---|" + "---|" * (len(J_BANDS) - 1)]
    for rpm in np.unique(d["rpm"]):
        lines.append(f"| {int(rpm)} | " + _band_cells(d, rpm, lambda s: (
            f"{np.mean(a['extra_deg'][s]):+.2f} deg, "
            f"{100 * np.mean(a['eCP0'][s]):+.0f} -> {100 * np.mean(a['eCP'][s]):+.0f} %")) + " |")
    return lines



def reynolds_75(prop: Prop, rot, J, rpm):
    """Chord Reynolds number at 0.75 R (sea-level air) from the unaccelerated relative speed,
    sqrt((J n D)^2 + (0.75 pi n D)^2); numbers or arrays."""
    n = np.asarray(rpm, float) / 60.0
    c75 = float(np.interp(0.75, rot.r_over_R, rot.chord_over_R)) * rot.radius_m
    w75 = np.hypot(np.asarray(J, float) * n * prop.diameter_m, 0.75 * math.pi * n * prop.diameter_m)
    return w75 * c75 / float(kinematic_viscosity(0.0))


def blade_thrust_N(prop: Prop, d) -> np.ndarray:
    """Thrust of one blade at the measured points (N, sea-level air): rho n^2 D^4 CT / B."""
    n = d["rpm"] / 60.0
    return float(density(0.0)) * n * n * prop.diameter_m ** 4 * d["CT"] / prop.blades


def _line_fit(x, y) -> tuple:
    """Least-squares y = a + b x: (a, b, R^2, rms of the residual)."""
    A = np.c_[np.ones_like(x), x]
    (a, b), *_ = np.linalg.lstsq(A, y, rcond=None)
    r = y - A @ np.array([a, b])
    return float(a), float(b), float(1.0 - r.var() / y.var()), float(r.std())


def load_pitch(prop: Prop, a: dict) -> dict:
    """Does the apparent pitch follow the blade's load?  A blade that twists under its air load
    (nose-up where the load acts ahead of the section's shear centre) gains pitch in proportion
    to that load, a per-propeller property (its torsional stiffness); a section or Reynolds-number
    error is shared by every propeller on those sections.  Fits of the apparent pitch of
    ``a = apparent_pitch(prop)`` against the thrust per blade, the Reynolds number at 0.75 R and
    n^2 (centrifugal loads); and the what-if: the model with the fitted law's pitch at every point,
    fitted on all runs and, as a prediction, on all but the fastest third of the runs."""
    d, y = a["data"], a["extra_deg"]
    n = d["rpm"] / 60.0
    rot = prop.rotor()
    load = blade_thrust_N(prop, d)
    fits = {("thrust per blade", "deg per N"): _line_fit(load, y),
            ("Reynolds number at 0.75 R", "deg per 1e5"):
                _line_fit(reynolds_75(prop, rot, d["J"], d["rpm"]) / 1e5, y),
            ("n^2 (centrifugal load)", "deg per (1000 rpm)^2"): _line_fit((d["rpm"] / 1000.0) ** 2, y)}
    runs = np.unique(d["rpm"])
    fastest = runs[len(runs) - max(1, len(runs) // 3):]      # the fastest third of the runs, held out
    low = ~np.isin(d["rpm"], fastest)
    laws = {"all runs": _line_fit(load, y),
            "the slower runs": _line_fit(load[low], y[low])}
    whatif = {}
    for name, (c0, c1, _, _) in laws.items():
        r = analyze(rot, omega_radps=2 * math.pi * n, v_axial_mps=d["J"] * n * prop.diameter_m,
                    n_stations=N_STATIONS, pitch_rad=rot.pitch_offset_rad + np.radians(c0 + c1 * load))
        whatif[name] = (np.asarray(r["CT"]).ravel() / d["CT"] - 1, np.asarray(r["CP"]).ravel() / d["CP"] - 1)
    return {"data": d, "fits": fits, "laws": laws, "whatif": whatif, "held_out_rpm": fastest}


def load_pitch_lines(prop: Prop, a: dict) -> list:
    """The summary's section on ``load_pitch``."""
    lp = load_pitch(prop, a)
    d = lp["data"]
    lines = ["", "## Apparent pitch against the blade's load", "",
             "A blade that twists under its air load gains pitch in proportion to that load, by its own "
             "torsional stiffness; an error of the sections or of their Reynolds number is shared by every "
             "propeller on them.  Straight-line fits of the apparent pitch above (every point, J <= "
             f"{J_LIMIT}) against:", "", "| against | slope | intercept | R^2 | rms left |", "|---|---:|---:|---:|---:|"]
    for (name, unit), (c0, c1, r2, rms) in lp["fits"].items():
        lines.append(f"| {name} | {c1:.3g} {unit} | {c0:+.2f} deg | {r2:.2f} | {rms:.2f} deg |")
    lines += ["", "What-if, not the model (it would be a per-propeller fit): the rigid-blade model with the "
              "pitch of the thrust law at every point, mean |error| per run.  The second law is fitted without "
              "the fastest third of the runs (" + ", ".join(f"{int(r)}" for r in lp["held_out_rpm"])
              + " rpm) and predicts them:", "",
              "| runs | model CT / CP | " + " | ".join(f"law of {k} CT / CP" for k in lp["whatif"]) + " |",
              "|---|---|" + "---|" * len(lp["whatif"])]
    eCT0, eCP0 = a["eCT0"], a["eCP0"]
    for rpm in np.unique(d["rpm"]):
        s = d["rpm"] == rpm
        cells = [f"{100 * np.mean(np.abs(ct[s])):.1f} / {100 * np.mean(np.abs(cp[s])):.1f} %"
                 for ct, cp in lp["whatif"].values()]
        lines.append(f"| {int(rpm)} rpm | {100 * np.mean(np.abs(eCT0[s])):.1f} / {100 * np.mean(np.abs(eCP0[s])):.1f} % | "
                     + " | ".join(cells) + " |")
    laws = "; ".join(f"{k}: {c0:+.2f} deg {c1:+.3f} deg per N" for k, (c0, c1, _, _) in lp["laws"].items())
    lines += ["", f"Laws: {laws}."]
    return lines

TREND_J = (0.3, 0.45, 0.55, 0.65)


def reynolds_trend(prop: Prop, m: dict) -> list:
    """CT and CP at fixed advance ratios, per UIUC run (data interpolated linearly in J
    within the run's range; the model run at the same J and rpm): rows (J, rpm, Re at
    0.75 R, CT data, CT model, CP data, CP model).  At fixed J the blade sees the same
    angles at every rpm, so what changes along a column is the Reynolds number (and
    the tip Mach number, below 0.25 here): the trend the sections' polars must carry."""
    d, rot = m["data"], m["rotor"]
    rows = []
    for J in TREND_J:
        for rpm in np.unique(d["rpm"]):
            s = d["rpm"] == rpm
            if not d["J"][s].min() <= J <= d["J"][s].max():
                continue
            n = rpm / 60.0
            r = analyze(rot, omega_radps=np.array([2 * math.pi * n]), v_axial_mps=np.array([J * n * prop.diameter_m]),
                        n_stations=N_STATIONS, pitch_rad=rot.pitch_offset_rad)
            rows.append((J, int(rpm), float(reynolds_75(prop, rot, J, rpm)),
                         float(np.interp(J, d["J"][s], d["CT"][s])), float(np.ravel(r["CT"])[0]),
                         float(np.interp(J, d["J"][s], d["CP"][s])), float(np.ravel(r["CP"])[0])))
    return rows


def _trend_lines(rows: list) -> list:
    lines = ["", "## Reynolds trend at fixed advance ratio", "",
             "At a fixed J the blade sees the same angles at every rpm, so along each J the change is the "
             "Reynolds number's (Re at 0.75 R from the unaccelerated relative speed).  Change from the "
             "lowest rpm of that J.  Where the data's change exceeds the model's, the blade's sections gain more "
             "from Reynolds number than the polars they are modelled with (XFOIL, free transition):", "",
             "| J | rpm | Re 0.75R | CT data | CT model | CT data change | CT model change | CP data | CP model |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    first = {}
    for J, rpm, re, ctd, ctm, cpd, cpm in rows:
        f = first.setdefault(J, (ctd, ctm))
        lines.append(f"| {J:.2f} | {rpm} | {re:.2g} | {ctd:.4f} | {ctm:.4f} | {100 * (ctd / f[0] - 1):+.0f} % | "
                     f"{100 * (ctm / f[1] - 1):+.0f} % | {cpd:.4f} | {cpm:.4f} |")
    return lines


J_BANDS = (0.0, 0.3, 0.5, 0.6, 0.7)


def _band_lines(m: dict) -> list:
    """Mean signed CT and CP errors per UIUC run and advance-ratio band (J <= J_LIMIT), with the
    mean CP shortfall in absolute terms: which part of a run's J range carries its error."""
    d = m["data"]
    lines = ["", "## Error by advance ratio", "",
             "Mean signed error per run and J band (points in the band).  The UIUC runs cover different J "
             "ranges, so a run's mean error is also a statement about its J range.  dCP is the model's CP "
             "minus the data's.", "",
             "| rpm | J range | " + " | ".join(f"J {a:.1f}-{b:.1f}: CT, CP, dCP" for a, b in zip(J_BANDS[:-1], J_BANDS[1:]))
             + " |", "|---|---|" + "---|" * (len(J_BANDS) - 1)]
    dcp = np.asarray(m["res"]["CP"]).ravel() - d["CP"]
    for rpm in np.unique(d["rpm"]):
        r = d["J"][d["rpm"] == rpm]
        lines.append(f"| {int(rpm)} | {r.min():.2f}-{r.max():.2f} | " + _band_cells(d, rpm, lambda s: (
            f"{100 * np.mean(m['eCT'][s]):+.0f} %, {100 * np.mean(m['eCP'][s]):+.0f} %, "
            f"{np.mean(dcp[s]):+.4f} ({int(s.sum())})")) + " |")
    return lines


def _band_cells(d, rpm: float, cell) -> str:
    """One run's table cells: ``cell(mask)`` for each J band of ``J_BANDS`` ("-" where the run has
    no point in the band), joined with " | "."""
    out = []
    for lo, hi in zip(J_BANDS[:-1], J_BANDS[1:]):
        s = (d["rpm"] == rpm) & (d["J"] > lo) & (d["J"] <= hi)
        out.append(cell(s) if s.any() else "-")
    return " | ".join(out)


def write_outputs(prop: Prop, out_dir: Path = OUT_DIR, with_sensitivity: bool = True) -> dict:
    """Figure, per-point errors, static table and the markdown summary of one propeller."""
    out_dir.mkdir(parents=True, exist_ok=True)
    main, base = run(prop), run(prop, BASELINE_AIRFOIL, pitch_reference=False)
    t, tb = table(main), table(base)
    d, res, st, rs = main["data"], main["res"], main["static"], main["res_static"]
    assert res.converged.all() and rs.converged.all(), "BEMT residual not converged at some data point"
    stem = f"apc{prop.key}"
    with open(out_dir / f"{stem}_errors.csv", "w") as f:
        f.write("rpm,J,CT_data,CT_model,CT_rel_err,CP_data,CP_model,CP_rel_err,eta_data,eta_model,"
                "CT_baseline,CP_baseline,residual_max\n")
        for i in range(d.size):
            f.write(f"{int(d['rpm'][i])},{d['J'][i]:.4f},{d['CT'][i]:.5f},{res['CT'][i]:.5f},{main['eCT'][i]:.4f},"
                    f"{d['CP'][i]:.5f},{res['CP'][i]:.5f},{main['eCP'][i]:.4f},{d['eta'][i]:.4f},"
                    f"{res['eta'][i]:.4f},{base['res']['CT'][i]:.5f},{base['res']['CP'][i]:.5f},"
                    f"{res.residual_max[i]:.2e}\n")
    with open(out_dir / f"{stem}_static.csv", "w") as f:
        f.write("rpm,CT_data,CT_model,CT_rel_err,CP_data,CP_model,CP_rel_err,FM_model,CT_baseline,CP_baseline\n")
        for i in range(st.size):
            f.write(f"{int(st['rpm'][i])},{st['CT'][i]:.4f},{rs['CT'][i]:.5f},{main['eCT0'][i]:.4f},"
                    f"{st['CP'][i]:.4f},{rs['CP'][i]:.5f},{main['eCP0'][i]:.4f},{rs['FM'][i]:.4f},"
                    f"{base['res_static']['CT'][i]:.5f},{base['res_static']['CP'][i]:.5f}\n")
    _figure(prop, main, t, out_dir / f"{stem}.png")
    rot = main["rotor"]
    lines = [f"# {prop.title}: BEMT vs UIUC wind-tunnel data", "",
             f"Model: sections `{AIRFOIL}` (E63 inboard, Clark-Y outboard, XFOIL at Ncrit 7; Du-Selig stall delay, its lift increment a normal force: dcd = dcl tan(alpha)), blade angles "
             f"referenced to the quoted {prop.pitch_in:g} in pitch at 0.75 R (collective "
             f"{math.degrees(rot.pitch_offset_rad):+.2f} deg on the UIUC table), {N_STATIONS} stations, sea level "
             f"(`problems/validation/apc_common.py`). Relative errors (model - data)/data; J <= {J_LIMIT} "
             "and the static runs.", "",
             "| runs | points | CT mean abs err | CT max | CP mean abs err | CP max | baseline CT mean | baseline CP mean |",
             "|---|---|---|---|---|---|---|---|"]
    for k, v in t.items():
        b = tb[k]
        lines.append(f"| {k} | {v['points']} | {100 * v['CT_mean']:.1f} % | {100 * v['CT_max']:.1f} % | "
                     f"{100 * v['CP_mean']:.1f} % | {100 * v['CP_max']:.1f} % | {100 * b['CT_mean']:.1f} % | "
                     f"{100 * b['CP_mean']:.1f} % |")
    lines += ["", f"Baseline = the model before issue 18 (`{BASELINE_AIRFOIL}`, no stall delay, tabulated blade "
                  "angles), with today's polars (the Clark-Y's Re 5e4 level at Ncrit 9 like the others; until "
                  "2026-12-05 it was SUAVE's Ncrit 5 file).", f"Largest BEMT residual over all points: {res.residual_max.max():.1e}."]
    if with_sensitivity:
        lines += ["", "## Uncertainty: what a section choice is worth", "",
                  "Mean signed error (bias) of the model with one input changed:", "",
                  "| variant | CT bias J<=0.7 | CP bias J<=0.7 | static CT bias | static CP bias |", "|---|---|---|---|---|"]
        for row in sensitivities(prop):
            lines.append(f"| {row[0]} | " + " | ".join(f"{100 * v:+.1f} %" for v in row[1:]) + " |")
    lines += _band_lines(main)
    if with_sensitivity:
        a = apparent_pitch(prop)
        lines += _pitch_lines(a)
        lines += load_pitch_lines(prop, a)
        lines += drag_lines(prop)
    lines += _trend_lines(reynolds_trend(prop, main))
    lines += ["", f"Files: {stem}.png, {stem}_errors.csv (every point), {stem}_static.csv."]
    (out_dir / f"{stem}_summary.md").write_text("\n".join(lines) + "\n")
    return {"table": t, "baseline": tb}


def _figure(prop: Prop, main: dict, t: dict, path: Path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    d, rot = main["data"], main["rotor"]
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
    rpms = np.unique(d["rpm"])
    colors = plt.cm.viridis(np.linspace(0, 0.9, rpms.size))
    Jf = np.linspace(0.0, 0.9, 91)
    for c, rpm in zip(colors, rpms):
        s = d["rpm"] == rpm
        r = analyze(rot, omega_radps=np.full(Jf.size, 2 * math.pi * rpm / 60),
                    v_axial_mps=Jf * rpm / 60 * prop.diameter_m, n_stations=N_STATIONS)
        curves = {"CT": r["CT"], "CP": r["CP"], "eta": np.where((r["CT"] > 0) & (r["CP"] > 0), r["eta"], np.nan)}
        for k, key in enumerate(("CT", "CP", "eta")):
            ax[k].plot(Jf, curves[key], "-", color=c, lw=1.2, label=f"{int(rpm)} rpm" if k == 0 else None)
            ax[k].plot(d["J"][s], d[key][s], "o", color=c, ms=3.5, mfc="none")
    st, rs = main["static"], main["res_static"]
    ax[0].plot(np.zeros(st.size), st["CT"], "k+", ms=6, label="static runs")
    ax[1].plot(np.zeros(st.size), st["CP"], "k+", ms=6)
    ax[0].plot([0.0], [np.mean(rs["CT"])], "kx", ms=7)
    ax[1].plot([0.0], [np.mean(rs["CP"])], "kx", ms=7)
    for k, (key, lab) in enumerate((("CT", "$C_T$"), ("CP", "$C_P$"), ("eta", r"$\eta$"))):
        ax[k].set_xlabel("J")
        ax[k].set_ylabel(lab)
        ax[k].grid(alpha=0.3)
        ax[k].axvline(J_LIMIT, color="0.6", ls=":", lw=1)
    ax[2].set_ylim(0, 0.9)
    ax[0].legend(fontsize=8, title="lines: BEMT, circles: UIUC")
    a, s0 = t["all"], t["static"]
    fig.suptitle(f"{prop.title}, BEMT (E63/Clark-Y, Du-Selig) vs UIUC; J <= {J_LIMIT}: mean |err| CT "
                 f"{100 * a['CT_mean']:.1f} %, CP {100 * a['CP_mean']:.1f} %; static CT {100 * s0['CT_mean']:.1f} %, "
                 f"CP {100 * s0['CP_mean']:.1f} %", fontsize=11)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def print_table(t: dict, tb: dict | None = None):
    for k, v in t.items():
        line = (f"{k:>10}: CT mean {100 * v['CT_mean']:5.1f} % max {100 * v['CT_max']:5.1f} %   "
                f"CP mean {100 * v['CP_mean']:5.1f} % max {100 * v['CP_max']:5.1f} %")
        if tb is not None:
            line += f"   (baseline CT {100 * tb[k]['CT_mean']:5.1f} %, CP {100 * tb[k]['CP_mean']:5.1f} %)"
        print(line)
