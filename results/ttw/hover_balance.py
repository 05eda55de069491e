"""The TTW's pitch balance in hover, which the mission does not trim (an estimate, not a model).

    python results/ttw/hover_balance.py [RUN_DIR ...]   (default: results/ttw)

The tandem tilt-wing hovers on one rotor group spread over both wings, all rotors at one speed and
collective, so the hover and transition nodes are not trimmed in pitch (``problems/ttw.py``).  A real
tandem tilt-wing trims its hover by thrusting more on one wing than on the other.  This script asks
what that would take at the run's hover nodes (wing-mounted angle 90 deg): the rotors' thrust is
vertical, the hubs sit above the wings' tilt pivot, and the front wing's share of the thrust that
puts the moment about the CG at zero is

    s_front = (x_rear - x_cg) / (x_rear - x_front)

with x_front and x_rear the mean pivot positions of the front and rear rotors.  The pivot is not in
the vehicle definition: it is taken at the leading edge and at 30 % of the chord, the two ends of
where a tilt-wing's spar-mounted pivot sits (ours), so each figure is given as a range.  What a split
costs, by momentum theory at a fixed total thrust (ideal induced power ~ T^1.5 per rotor):

* hover power: (s^1.5 + (1 - s)^1.5) / (2 * 0.5^1.5) - 1 of the even split's;
* the more loaded wing's motors: (2 s)^1.5 - 1 more power than at the even split.

Writes ``hover_balance.md`` into each run folder.
"""
import csv
import json
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
PIVOT_CHORD_FRACTIONS = (0.0, 0.3)


def _pivots_x(geometry: dict, x_ahead_of_le_m: float, chord_fraction: float) -> list[tuple[float, float]]:
    """(pivot x, wing-borne hub z) of every rotor: its leading edge plus ``chord_fraction`` of the chord at
    its span station, on the lifting surface whose leading edge is nearest its hub."""
    out = []
    wings = [s for s in geometry["surfaces"] if not s.get("vertical") and not s.get("image")]
    for r in geometry["rotors"]:
        x, y, z = r["center_m"]
        x_le = x + x_ahead_of_le_m
        wing = min(wings, key=lambda s: min(abs(np.asarray(s["le"][0]) - x_le)))
        le, te = np.asarray(wing["le"]), np.asarray(wing["te"])
        chord = float(np.interp(abs(y), le[1], te[0] - le[0]))
        out.append((float(np.interp(abs(y), le[1], le[0])) + chord_fraction * chord, z))
    return out


def hover_balance(run: Path) -> str:
    sys.path.insert(0, str(ROOT))
    from mdo.vehicle.catalog import ttw
    geometry = json.loads((run / "geometry.json").read_text())
    summary = json.loads((run / "summary.json").read_text())
    x_cg = float(summary["cg_x_m"])
    rows = list(csv.DictReader(open(run / "mission.csv")))
    hover = [r for r in rows if abs(float(r["wing_mounted_angle_deg"]) - 90.0) < 1e-6]
    x_ahead = ttw().rotor_groups[0].x_ahead_of_le_m
    lines = [f"# Pitch balance in hover (estimate): `{run.relative_to(ROOT) if run.is_relative_to(ROOT) else run}`",
             "", "Made by `results/ttw/hover_balance.py` (its docstring gives the method).  CG at x = "
             f"{x_cg:.3f} m; {len(hover)} hover nodes (wing-mounted angle 90 deg), body angle "
             f"{min(float(r['body_angle_deg']) for r in hover):+.2f} to "
             f"{max(float(r['body_angle_deg']) for r in hover):+.2f} deg.", "",
             "| pivot | front rotors' pivot x | rear rotors' pivot x | untrimmed moment at even thrust, per kN "
             "of total thrust | front wing's share to trim | hover power | the loaded wing's motors |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for f in PIVOT_CHORD_FRACTIONS:
        piv = _pivots_x(geometry, x_ahead, f)
        z_mid = 0.5 * (min(z for _, z in piv) + max(z for _, z in piv))
        front = np.mean([x for x, z in piv if z < z_mid])
        rear = np.mean([x for x, z in piv if z >= z_mid])
        moment = 1000.0 * (x_cg - 0.5 * (front + rear))      # nose-up N m per kN, thrust evenly shared
        s = (rear - x_cg) / (rear - front)
        power = (s ** 1.5 + (1 - s) ** 1.5) / (2 * 0.5 ** 1.5) - 1
        motors = (2 * max(s, 1 - s)) ** 1.5 - 1
        lines.append(f"| leading edge + {f:.0%} chord | {front:.3f} m | {rear:.3f} m | {moment:+.0f} N m | "
                     f"{s:.1%} | {power:+.2%} | {motors:+.1%} |")
    lines += ["", "Front = the rotors on the forward wing.  A positive moment is nose-up.  The split's cost to "
              "the mission's energy is the hover power's share times the hover and transition energy; the "
              "motors' figure matters where hover sizes them.", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    runs = [Path(a).resolve() for a in sys.argv[1:]] or [ROOT / "results" / "ttw"]
    for run in runs:
        text = hover_balance(run)
        (run / "hover_balance.md").write_text(text)
        print(text)
