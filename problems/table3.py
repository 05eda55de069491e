"""Write results/table3.md: the paper's Table 3 beside our optimizations.

    python problems/table3.py

Reads ``results/<problem>/summary.json`` and ``design.json`` of the optimization
runs and of their baseline analyses (``results/<problem>/analysis/``) for GA-2P,
GA-8P and TTW.  Not a problem file (no ``build``): a report over committed results.
"""
from __future__ import annotations

import json
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MPH = 0.44704

# Clarke, Erhard & Alonso, Table 3 (initial, optimized)
PAPER = {
    "ga2p": {"energy": (61.01, 57.96), "reduction": 5.00, "T": (900.00, 1059.59), "V": (135.00, 119.04),
             "R": (0.97, 1.12), "eta": [(0.23, 0.34)], "wings": {"main_wing": {
                 "span": (11.40, 13.00), "taper": (0.70, 0.54),
                 "twist": [(3.00, 3.16), (2.75, 2.59), (2.50, 2.41), (2.25, 1.84), (2.00, 1.16)]}}},
    "ga8p": {"energy": (40.51, 37.57), "reduction": 7.25, "T": (350.00, 376.82), "V": (130.00, 138.58),
             "R": (0.58, 0.55), "eta": None, "wings": {"main_wing": {
                 "span": (11.40, 12.30), "taper": (0.70, 0.85),
                 "twist": [(3.00, 2.98), (2.75, 2.73), (2.50, 2.26), (2.25, 2.85), (2.00, 1.01)]}}},
    "ttw": {"energy": (114.77, 103.84), "reduction": 9.52, "T": (5395.50, 5573.87), "V": (22.36, 18.253),
            "R": (1.20, 1.38), "eta": [(0.38, 0.27), (1.00, 0.82)], "wings": {
                "main_wing": {"span": (9.60, 10.52), "taper": (1.00, 0.82),
                              "twist": [(4.00, 3.82), (3.00, 3.18), (2.00, 1.82), (1.00, 1.18), (0.00, -0.18)]},
                "tandem_wing": {"span": (9.60, 10.4), "taper": (1.00, 0.82),
                                "twist": [(4.00, 4.18), (3.00, 2.82), (2.00, 2.18), (1.00, 0.82), (0.00, 0.18)]}}},
}
NAMES = {"ga2p": "GA-2P", "ga8p": "GA-8P", "ttw": "TTW"}


def _load(problem):
    run = ROOT / "results" / problem
    try:
        s_opt = json.loads((run / "summary.json").read_text())
        d_opt = json.loads((run / "design.json").read_text())
        s_an = json.loads((run / "analysis" / "summary.json").read_text())
        d_an = json.loads((run / "analysis" / "design.json").read_text())
    except FileNotFoundError:
        return None
    return s_an, d_an, s_opt, d_opt


def main():
    lines = ["# Table 3: the paper's optimizations and ours", "",
             "Paper: Clarke, Erhard & Alonso, Table 3 (SUAVE, sequential optimizer, mission re-solved at every "
             "design).  Ours: `mdo run problems/<p>.py`, which solves the baseline analysis with the design "
             "frozen (initial, `results/<p>/analysis/`) and then the optimization warm-started from it "
             "(optimized, `results/<p>/`) — design and mission in one IPOPT solve.  Status and iterations "
             "are IPOPT's.", ""]
    for p, ref in PAPER.items():
        got = _load(p)
        lines += [f"## {NAMES[p]}", ""]
        if got is None:
            lines += ["(no committed results yet)", ""]
            continue
        s_an, d_an, s_opt, d_opt = got
        e0, e1 = s_an["battery_energy_kWh"], s_opt["battery_energy_kWh"]
        red = 100 * (e0 - e1) / e0
        rows = [("Battery energy (kWh)", ref["energy"], (e0, e1), "{:.2f}"),
                ("Percent reduction", (None, ref["reduction"]), (None, red), "{:.2f}"),
                ("Propeller design thrust (N)", ref["T"], (d_an["design_thrust_N"], d_opt["design_thrust_N"]), "{:.2f}"),
                ("Propeller design speed (mph)", ref["V"],
                 (d_an["design_speed_mps"] / MPH, d_opt["design_speed_mps"] / MPH), "{:.2f}"),
                ("Propeller tip radius (m)", ref["R"], (d_an["tip_radius_m"], d_opt["tip_radius_m"]), "{:.3f}"),
                ("Propeller design cl (not in the paper's table)", (None, None),
                 (d_an["design_cl"], d_opt["design_cl"]), "{:.3f}")]
        if ref["eta"]:
            for i, pe in enumerate(ref["eta"]):
                rows.append((f"Propeller span location {i + 1} (fraction of semispan)", pe,
                             (d_an["span_eta"][i], d_opt["span_eta"][i]), "{:.3f}"))
        else:
            rows.append(("Propeller span locations", (None, None), (None, None), "fixed"))
        for w, wr in ref["wings"].items():
            tag = "M.W." if w == "main_wing" else "T.W."
            rows.append((f"{tag} span (m)", wr["span"], (d_an["wings"][w]["span_m"], d_opt["wings"][w]["span_m"]),
                         "{:.2f}"))
            rows.append((f"{tag} taper", wr["taper"], (d_an["wings"][w]["taper"], d_opt["wings"][w]["taper"]),
                         "{:.2f}"))
            for i, tw in enumerate(wr["twist"]):
                rows.append((f"{tag} section {i + 1} twist (deg)", tw,
                             (d_an["wings"][w]["twist_deg"][i], d_opt["wings"][w]["twist_deg"][i]), "{:.2f}"))
        rows.append(("Take-off gross weight (kg; paper: fixed)", (None, None), (d_an["togw_kg"], d_opt["togw_kg"]),
                     "{:.1f}"))

        def f(x, fmt):
            if fmt == "fixed":
                return "fixed"
            return "-" if x is None else fmt.format(x)
        lines += ["| | paper initial | paper optimized | ours initial | ours optimized |", "|---|---:|---:|---:|---:|"]
        for name, (pa, pb), (oa, ob), fmt in rows:
            lines.append(f"| {name} | {f(pa, fmt)} | {f(pb, fmt)} | {f(oa, fmt)} | {f(ob, fmt)} |")
        lines += ["", f"IPOPT: baseline {s_an['status']} in {s_an['iterations']} iterations "
                      f"({s_an['wall_time_s']:.0f} s); optimization {s_opt['status']} in {s_opt['iterations']} "
                      f"iterations ({s_opt['wall_time_s']:.0f} s).", ""]
    disc = ROOT / "results" / "table3_discussion.md"
    if disc.exists():
        lines += [disc.read_text()]
    (ROOT / "results" / "table3.md").write_text("\n".join(lines) + "\n")
    print("wrote results/table3.md")


if __name__ == "__main__":
    main()
