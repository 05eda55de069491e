"""``mdo rotor ...``: propeller sweeps and Adkins-Liebeck designs from the command line.

    mdo rotor sweep --geometry FILE.csv --diameter D_M --blades B --airfoil NAME
                    [--hub-fraction F] [--pitch-offset DEG] --rpm RPM --J START:STOP:STEP
                    [--altitude M] [--stations N] [--out FILE.csv]
    mdo rotor design --diameter D_M --blades B --speed V_MPS (--thrust N | --power W)
                     (--rpm RPM | --tip-mach M) [--cl CL] [--airfoil NAME]
                     [--hub-fraction F] [--altitude M] [--stations N] [--out FILE.csv]

``sweep`` writes ``J,CT,CP,eta,T_N,P_W,Q_Nm`` (stdout without ``--out``);
``design`` writes a geometry CSV ``r_over_R,c_over_R,beta_deg`` that ``sweep``
reads back.  Bad input raises ``InputError`` (one line, exit 2).
"""
from __future__ import annotations

import io
import math
import sys

import numpy as np

from ..core.errors import InputError

__all__ = ["register", "parse_range"]


def parse_range(text: str, field: str = "--J") -> np.ndarray:
    """``START:STOP:STEP`` (STOP included when it falls on the grid) -> array."""
    parts = str(text).split(":")
    if len(parts) != 3:
        raise InputError(field, f"expected START:STOP:STEP, got {text!r}")
    try:
        start, stop, step = (float(p) for p in parts)
    except ValueError as exc:
        raise InputError(field, f"expected numbers START:STOP:STEP, got {text!r}") from exc
    if not all(math.isfinite(v) for v in (start, stop, step)):
        raise InputError(field, f"values must be finite, got {text!r}")
    if step <= 0:
        raise InputError(field, f"STEP must be > 0, got {step:g}")
    if stop < start:
        raise InputError(field, f"STOP must be >= START, got {start:g}:{stop:g}")
    count = int(math.floor((stop - start) / step + 1e-9)) + 1
    if count > 100000:
        raise InputError(field, f"{count} points is too many (max 100000)")
    return start + step * np.arange(count)


def _positive(field: str, value, unit=""):
    if value is None or not math.isfinite(value) or value <= 0:
        raise InputError(field, f"must be a finite number > 0{(' ' + unit) if unit else ''}, got {value!r}")


def _cmd_sweep(args) -> int:
    from .analysis import sweep_J
    from .geometry import RotorGeometry
    from .sections import section

    _positive("--diameter", args.diameter, "m")
    _positive("--rpm", args.rpm, "rpm")
    if args.blades < 1:
        raise InputError("--blades", f"must be an integer >= 1, got {args.blades}")
    if args.stations < 4 or args.stations > 200:
        raise InputError("--stations", f"allowed 4..200, got {args.stations}")
    J = parse_range(args.J)
    sec = section(args.airfoil)
    rotor = RotorGeometry.from_csv(args.geometry, diameter_m=args.diameter, blades=args.blades,
                                   airfoil=sec, hub_fraction=args.hub_fraction,
                                   pitch_offset_rad=math.radians(args.pitch_offset))
    res = sweep_J(rotor, J, rpm=args.rpm, altitude_m=args.altitude, n_stations=args.stations)
    buf = io.StringIO()
    buf.write("J,CT,CP,eta,T_N,P_W,Q_Nm\n")
    for i in range(J.size):
        buf.write(",".join(f"{v:.6g}" for v in (J[i], res["CT"][i], res["CP"][i], res["eta"][i],
                                                  res["thrust_N"][i], res["power_W"][i],
                                                  res["torque_Nm"][i])) + "\n")
    _emit(buf.getvalue(), args.out)
    bad = ~res.converged
    if bad.any():
        print(f"mdo rotor sweep: warning: BEMT residual not converged at J = "
              f"{', '.join(f'{j:g}' for j in J[bad])} (max |residual| {res.residual_max.max():.2e})",
              file=sys.stderr)
    return 0


def _cmd_design(args) -> int:
    from .design import adkins_liebeck
    from .geometry import write_geometry_csv

    _positive("--diameter", args.diameter, "m")
    if args.blades < 1:
        raise InputError("--blades", f"must be an integer >= 1, got {args.blades}")
    if args.speed is None or not math.isfinite(args.speed) or args.speed < 0:
        raise InputError("--speed", f"must be >= 0 m/s, got {args.speed!r}")
    if args.thrust is not None:
        _positive("--thrust", args.thrust, "N")
    if args.power is not None:
        _positive("--power", args.power, "W")
    if args.rpm is not None:
        _positive("--rpm", args.rpm)
    if args.stations < 4 or args.stations > 200:
        raise InputError("--stations", f"allowed 4..200, got {args.stations}")
    d = adkins_liebeck(blades=args.blades, radius_m=0.5 * args.diameter, speed_mps=args.speed,
                       airfoil=args.airfoil, cl_design=args.cl, thrust_N=args.thrust,
                       power_W=args.power, rpm=args.rpm, tip_mach=args.tip_mach,
                       hub_fraction=args.hub_fraction, altitude_m=args.altitude,
                       n_stations=args.stations)
    g = d["geometry"]
    text = write_geometry_csv(None, g.r_over_R, g.chord_over_R, np.degrees(g.beta_rad))
    _emit(text, args.out)
    rpm = d["omega_radps"] * 30.0 / math.pi
    print(f"mdo rotor design: {args.blades} blades, D {args.diameter:g} m, {rpm:.1f} rpm, V {args.speed:g} m/s: "
          f"T {d['thrust_N']:.2f} N, P {d['power_W']:.1f} W, eta {d['eta']:.4f}, "
          f"w {d['w_mps']:.3f} m/s (zeta {d['zeta']:.4g}); Newton residual {d['residual_max']:.1e}",
          file=sys.stderr)
    return 0


def _emit(text: str, out):
    if out:
        try:
            with open(out, "w") as f:
                f.write(text)
        except OSError as exc:
            raise InputError("--out", f"cannot write {out}: {exc}") from exc
    else:
        sys.stdout.write(text)


def register(subparsers) -> None:
    rotor = subparsers.add_parser("rotor", help="propeller/rotor analysis (BEMT) and design (Adkins-Liebeck)",
                                  description="Propeller and rotor analysis and design.")
    sub = rotor.add_subparsers(dest="rotor_command", metavar="ROTOR_COMMAND")

    sw = sub.add_parser("sweep", help="CT, CP, eta vs J at constant rpm (BEMT)",
                        description="Advance-ratio sweep of a blade geometry at constant rpm.")
    sw.add_argument("--geometry", required=True, metavar="FILE.csv",
                    help="columns r_over_R,c_over_R,beta_deg (hub to tip)")
    sw.add_argument("--diameter", required=True, type=float, metavar="D_M", help="tip diameter [m]")
    sw.add_argument("--blades", required=True, type=int, metavar="B")
    sw.add_argument("--airfoil", required=True, metavar="NAME", help="section name (mdo.airfoil), or 'analytic'")
    sw.add_argument("--hub-fraction", type=float, default=None, metavar="F",
                    help="hub radius / tip radius (default: first geometry station)")
    sw.add_argument("--pitch-offset", type=float, default=0.0, metavar="DEG", help="collective added to beta")
    sw.add_argument("--rpm", required=True, type=float)
    sw.add_argument("--J", required=True, metavar="START:STOP:STEP", help="advance ratios")
    sw.add_argument("--altitude", type=float, default=0.0, metavar="M", help="USSA76 altitude [m]")
    sw.add_argument("--stations", type=int, default=20, metavar="N", help="BEMT stations (default 20)")
    sw.add_argument("--out", metavar="FILE.csv", help="output file (default stdout)")
    sw.set_defaults(func=_cmd_sweep)

    de = sub.add_parser("design", help="Adkins-Liebeck minimum-induced-loss blade -> geometry CSV",
                        description="Adkins-Liebeck design; writes r_over_R,c_over_R,beta_deg.")
    de.add_argument("--diameter", required=True, type=float, metavar="D_M")
    de.add_argument("--blades", required=True, type=int, metavar="B")
    de.add_argument("--speed", required=True, type=float, metavar="V_MPS", help="design speed [m/s] (0: hover)")
    g = de.add_mutually_exclusive_group(required=True)
    g.add_argument("--thrust", type=float, metavar="N", help="design thrust [N]")
    g.add_argument("--power", type=float, metavar="W", help="design shaft power [W]")
    s = de.add_mutually_exclusive_group(required=True)
    s.add_argument("--rpm", type=float)
    s.add_argument("--tip-mach", type=float, metavar="M", help="rotational tip Mach number")
    de.add_argument("--cl", type=float, default=0.7, help="design section lift coefficient (default 0.7)")
    de.add_argument("--airfoil", default="naca4412", metavar="NAME")
    de.add_argument("--hub-fraction", type=float, default=0.12, metavar="F", help="default 0.12 (the paper)")
    de.add_argument("--altitude", type=float, default=0.0, metavar="M")
    de.add_argument("--stations", type=int, default=20, metavar="N")
    de.add_argument("--out", metavar="FILE.csv")
    de.set_defaults(func=_cmd_design)

    def _help(args, _p=rotor):
        _p.print_help()
        return 2
    rotor.set_defaults(func=_help)
