"""``mdo rotor ...``: propeller sweeps and Adkins-Liebeck designs from the command line.

    mdo rotor sweep --geometry FILE.csv --diameter D_M --blades B --airfoil NAME
                    [--hub-fraction F] [--pitch-offset DEG] --rpm RPM --J START:STOP:STEP
                    [--altitude M] [--stations N] [--out FILE.csv]
    mdo rotor design --diameter D_M --blades B --speed V_MPS (--thrust N | --power W)
                     (--rpm RPM | --tip-mach M) [--cl CL] [--airfoil NAME]
                     [--hub-fraction F] [--altitude M] [--stations N] [--out FILE.csv]

``sweep`` writes ``J,CT,CP,eta,T_N,P_W,Q_Nm`` (stdout without ``--out``; on a
terminal as aligned columns); eta = T V / P is undefined where T <= 0 or P <= 0
(windmilling, braking) and is left blank in the CSV, "—" on the terminal.
``design`` writes a geometry CSV ``r_over_R,c_over_R,beta_deg`` that ``sweep``
reads back.  ``--out`` never replaces an existing file without ``--force``.
Every number has a finite range (``-h``); bad input raises ``InputError`` (one
line, exit 2), and non-finite results are refused rather than printed.
"""
from __future__ import annotations

import io
import math
import sys

import numpy as np

from ..core.errors import InputError, check_finite_result, parse_float, parse_grid, parse_int
from ..core.output import check_new_file, write_new_file

__all__ = ["register", "parse_range", "sweep_table", "efficiency_or_none"]


J_RANGE = (0.0, 10.0)          # advance ratios the sweep accepts
MAX_SWEEP_POINTS = 100000
MAX_GEOMETRY_BYTES = 10 * 2 ** 20


def parse_range(text: str, field: str = "--J") -> np.ndarray:
    """``START:STOP:STEP`` (STOP included when it falls on the grid) -> array of advance ratios."""
    return parse_grid(field, text, *J_RANGE, MAX_SWEEP_POINTS)


def _common(args) -> None:
    """Numbers both sub-commands take, parsed in place against their ranges."""
    args.diameter = parse_float("--diameter", args.diameter, 0.0, 100.0, "m", lower_open=True)
    args.blades = parse_int("--blades", args.blades, 1, 20)
    args.altitude = parse_float("--altitude", args.altitude, 0.0, 20000.0, "m")
    args.stations = parse_int("--stations", args.stations, 4, 200)


def _airfoil(text):
    """The rotor's section spec: every airfoil name in it ('analytic', a shipped airfoil;
    blends NAME:R_OVER_R:NAME[:R_OVER_R:NAME...][;width=W], an optional +MODEL suffix) through the one
    resolver; the rest is checked by ``mdo.rotor.sections.section``."""
    from ..airfoil.cli import resolve_airfoil

    base, plus, suffix = str(text).partition("+")
    base, semi, option = base.partition(";")       # a distribution's ";width=W"
    parts = base.split(":")
    for i in range(0, len(parts), 2):
        if parts[i].strip().lower() != "analytic":
            parts[i] = resolve_airfoil(parts[i], "--airfoil")
    return ":".join(parts) + semi + option + plus + suffix


def efficiency_or_none(eta, thrust_N, power_W) -> np.ndarray:
    """Propulsive efficiency where it is defined (thrust > 0 and power > 0), NaN elsewhere:
    T V / P is meaningless for a windmilling or braking rotor (issue 23 item 1)."""
    eta = np.asarray(eta, float)
    ok = (np.asarray(thrust_N, float) > 0) & (np.asarray(power_W, float) > 0)
    return np.where(ok, eta, np.nan)


def sweep_table(J, res, human: bool) -> str:
    """The sweep as CSV (undefined efficiency blank) or, for a terminal, aligned columns
    with "—" for it."""
    eta = efficiency_or_none(res["eta"], res["thrust_N"], res["power_W"])
    cols = (J, res["CT"], res["CP"], eta, res["thrust_N"], res["power_W"], res["torque_Nm"])
    head = ("J", "CT", "CP", "eta", "T_N", "P_W", "Q_Nm")
    buf = io.StringIO()
    if human:
        buf.write(" ".join(f"{h:>11s}" for h in head) + "\n")
    else:
        buf.write(",".join(head) + "\n")
    for i in range(len(J)):
        vals = [("\u2014" if human else "") if not math.isfinite(float(c[i])) else f"{float(c[i]):.6g}"
                for c in cols]
        buf.write((" ".join(f"{v:>11s}" for v in vals) if human else ",".join(vals)) + "\n")
    return buf.getvalue()


def _load_geometry(args, sec):
    from .geometry import RotorGeometry

    from pathlib import Path
    p = Path(args.geometry)
    if p.is_file() and p.stat().st_size > MAX_GEOMETRY_BYTES:
        raise InputError("--geometry", f"{p} is larger than {MAX_GEOMETRY_BYTES // 2 ** 20} MiB; "
                                       f"not a blade geometry CSV")
    hub = None if args.hub_fraction is None else parse_float("--hub-fraction", args.hub_fraction, 0.0, 1.0,
                                                              lower_open=True, upper_open=True)
    pitch = parse_float("--pitch-offset", args.pitch_offset, -90.0, 90.0, "deg")
    rotor = RotorGeometry.from_csv(args.geometry, diameter_m=args.diameter, blades=args.blades,
                                   airfoil=sec, hub_fraction=hub, pitch_offset_rad=math.radians(pitch))
    c = np.asarray(rotor.chord_over_R, float)
    if np.any(c > 1.0):   # the model's own check is c > 0; a chord beyond the radius is not a blade
        raise InputError("c_over_R", f"blade chord / tip radius must lie in (0, 1], got {c.max():g} "
                                     f"in {args.geometry}")
    return rotor


def _cmd_sweep(args) -> int:
    from .analysis import sweep_J
    from .sections import section

    _common(args)
    args.rpm = parse_float("--rpm", args.rpm, 0.0, 1e6, "rpm", lower_open=True)
    J = parse_range(args.J)
    sec = section(_airfoil(args.airfoil))
    if args.out:
        check_new_file(args.out, args.force)
    rotor = _load_geometry(args, sec)
    res = sweep_J(rotor, J, rpm=args.rpm, altitude_m=args.altitude, n_stations=args.stations)
    check_finite_result("--geometry", CT=res["CT"], CP=res["CP"], thrust=res["thrust_N"], power=res["power_W"])
    human = not args.out and sys.stdout.isatty()
    _emit(sweep_table(J, res, human), args.out, args.force)
    bad = ~res.converged
    if bad.any():
        print(f"mdo rotor sweep: warning: BEMT residual not converged at J = "
              f"{', '.join(f'{j:g}' for j in J[bad])} (max |residual| {res.residual_max.max():.2e})",
              file=sys.stderr)
    return 0


def _cmd_design(args) -> int:
    from .design import adkins_liebeck
    from .geometry import write_geometry_csv

    _common(args)
    speed = parse_float("--speed", args.speed, 0.0, 400.0, "m/s")
    thrust = None if args.thrust is None else parse_float("--thrust", args.thrust, 0.0, 1e7, "N", lower_open=True)
    power = None if args.power is None else parse_float("--power", args.power, 0.0, 1e9, "W", lower_open=True)
    rpm = None if args.rpm is None else parse_float("--rpm", args.rpm, 0.0, 1e6, "rpm", lower_open=True)
    tip_mach = None if args.tip_mach is None else parse_float("--tip-mach", args.tip_mach, 0.0, 1.0,
                                                              lower_open=True, upper_open=True)
    cl = parse_float("--cl", args.cl, 0.05, 2.0)
    hub = parse_float("--hub-fraction", args.hub_fraction, 0.0, 0.9, lower_open=True, upper_open=True)
    airfoil = _airfoil(args.airfoil)
    if args.out:
        check_new_file(args.out, args.force)
    d = adkins_liebeck(blades=args.blades, radius_m=0.5 * args.diameter, speed_mps=speed,
                       airfoil=airfoil, cl_design=cl, thrust_N=thrust, power_W=power, rpm=rpm,
                       tip_mach=tip_mach, hub_fraction=hub, altitude_m=args.altitude,
                       n_stations=args.stations)
    g = d["geometry"]
    check_finite_result("--thrust/--power", chord=g.chord_over_R, beta=g.beta_rad, eta=d["eta"])
    text = write_geometry_csv(None, g.r_over_R, g.chord_over_R, np.degrees(g.beta_rad))
    _emit(text, args.out, args.force)
    rpm = d["omega_radps"] * 30.0 / math.pi
    print(f"mdo rotor design: {args.blades} blades, D {args.diameter:g} m, {rpm:.1f} rpm, V {speed:g} m/s: "
          f"T {d['thrust_N']:.2f} N, P {d['power_W']:.1f} W, eta {d['eta']:.4f}, "
          f"w {d['w_mps']:.3f} m/s (zeta {d['zeta']:.4g}); Newton residual {d['residual_max']:.1e}",
          file=sys.stderr)
    return 0


def _emit(text: str, out, force: bool = False):
    if out:
        write_new_file(out, text, force)
    else:
        sys.stdout.write(text)


def register(subparsers) -> None:
    rotor = subparsers.add_parser("rotor", help="propeller/rotor analysis (BEMT) and design (Adkins-Liebeck)",
                                  description="Propeller and rotor analysis and design.")
    sub = rotor.add_subparsers(dest="rotor_command", metavar="ROTOR_COMMAND")

    airfoil_help = ("section: a shipped airfoil (see 'mdo airfoil list'), 'analytic', a generated one ('NACA 23012', "
                    "'naca4412@xtr=0.1'), or a radial distribution A:R_OVER_R:B[:R_OVER_R:C...] with an optional "
                    "';width=W' (r/R over which one section turns into the next, default 0.05) and '+snel' or "
                    "'+du_selig' (stall delay)")

    def common(p, hub_default, hub_help):
        p.add_argument("--diameter", required=True, metavar="D_M", help="tip diameter, (0, 100] m")
        p.add_argument("--blades", required=True, metavar="B", help="number of blades, an integer in [1, 20]")
        p.add_argument("--hub-fraction", default=hub_default, metavar="F", help=hub_help)
        p.add_argument("--altitude", default="0", metavar="M", help="USSA76 altitude, [0, 20000] m (default 0)")
        p.add_argument("--stations", default="20", metavar="N",
                       help="BEMT stations, an integer in [4, 200] (default 20)")
        p.add_argument("--force", action="store_true", help="replace an existing --out file")

    sw = sub.add_parser("sweep", help="CT, CP, eta vs J at constant rpm (BEMT)",
                        description="Advance-ratio sweep of a blade geometry at constant rpm.  Efficiency is "
                                    "left blank (CSV) or printed as \u2014 (terminal) where thrust or power <= 0.")
    sw.add_argument("--geometry", required=True, metavar="FILE.csv",
                    help="columns r_over_R,c_over_R,beta_deg (hub to tip), c_over_R in (0, 1]")
    common(sw, None, "hub radius / tip radius, (0, 1) (default: first geometry station)")
    sw.add_argument("--airfoil", required=True, metavar="NAME", help=airfoil_help)
    sw.add_argument("--pitch-offset", default="0", metavar="DEG",
                    help="collective added to beta, [-90, 90] deg (default 0)")
    sw.add_argument("--rpm", required=True, metavar="RPM", help="rotor speed, (0, 1e+06] rpm (tip Mach < 1)")
    sw.add_argument("--J", required=True, metavar="START:STOP:STEP",
                    help=f"advance ratios V/(n D), within [{J_RANGE[0]:g}, {J_RANGE[1]:g}], "
                         f"at most {MAX_SWEEP_POINTS} points")
    sw.add_argument("--out", metavar="FILE.csv", help="output file (default stdout); never replaced without --force")
    sw.set_defaults(func=_cmd_sweep)

    de = sub.add_parser("design", help="Adkins-Liebeck minimum-induced-loss blade -> geometry CSV",
                        description="Adkins-Liebeck design; writes r_over_R,c_over_R,beta_deg.")
    common(de, "0.12", "hub radius / tip radius, (0, 0.9) (default 0.12, the paper)")
    de.add_argument("--speed", required=True, metavar="V_MPS", help="design speed, [0, 400] m/s (0: hover)")
    g = de.add_mutually_exclusive_group(required=True)
    g.add_argument("--thrust", metavar="N", help="design thrust, (0, 1e+07] N")
    g.add_argument("--power", metavar="W", help="design shaft power, (0, 1e+09] W")
    s = de.add_mutually_exclusive_group(required=True)
    s.add_argument("--rpm", metavar="RPM", help="rotor speed, (0, 1e+06] rpm")
    s.add_argument("--tip-mach", metavar="M", help="rotational tip Mach number, (0, 1)")
    de.add_argument("--cl", default="0.7", help="design section lift coefficient, [0.05, 2] (default 0.7)")
    de.add_argument("--airfoil", default="naca4412", metavar="NAME", help=airfoil_help + " (default naca4412)")
    de.add_argument("--out", metavar="FILE.csv", help="output file (default stdout); never replaced without --force")
    de.set_defaults(func=_cmd_design)

    def _help(args, _p=rotor):
        _p.print_help()
        return 2
    rotor.set_defaults(func=_help)
