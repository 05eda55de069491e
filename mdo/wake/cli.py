"""``mdo wake velocity``: the slipstream of one rotor along a line, from the command line.

    mdo wake velocity --radius R_M --blades B --thrust-gamma G_M2PS | --gamma G1,G2,...
                      --rpm RPM --v-wake V_MPS [--hub-fraction F] [--spin +1|-1]
                      [--x X_M] [--z Z_M] [--y START:STOP:STEP] [--model mean|full]
                      [--phases N] [--rotations N] [--core-rel C] [--out FILE.csv]

The rotor sits at the origin with its wake along +x; the line runs along y at
(x, z).  Blade circulation: ``--gamma`` per blade element (equal-width elements
from the hub to the tip) or ``--thrust-gamma`` for a uniform value.  Writes
``y_m,u_mps,v_mps,w_mps`` (stdout without ``--out``; an existing file is replaced
only with ``--force``).  ``--model mean`` is the blade-passage-averaged wake of the
NLP; ``full`` the helical fixed wake, whose size (points x filament segments) is
bounded.  Every number has a finite range (``-h``); bad input raises ``InputError``
(one line, exit 2).
"""
from __future__ import annotations

import math
import sys

import numpy as np

from ..core.errors import InputError, check_finite_result, parse_choice, parse_float, parse_grid, parse_int
from ..core.output import check_new_file, write_new_file
from .rotor import DEFAULT_CORE_REL

__all__ = ["register"]


Y_RANGE_M = (-1000.0, 1000.0)
MAX_POINTS = 20000
MAX_ELEMENTS = 50
# the full wake's cost is points x filament segments (each Biot-Savart pair a few
# dozen flops, held in memory at build); 2e7 is some 20 s and a few hundred MB
MAX_FULL_WAKE_PAIRS = 2e7


def _gamma(args):
    if (args.gamma is None) == (args.thrust_gamma is None):
        raise InputError("--gamma", "give exactly one of --gamma G1,G2,... or --thrust-gamma G")
    if args.thrust_gamma is not None:
        return np.array([parse_float("--thrust-gamma", args.thrust_gamma, -1e4, 1e4, "m^2/s")])
    parts = args.gamma.split(",")
    if not 1 <= len(parts) <= MAX_ELEMENTS:
        raise InputError("--gamma", f"1 to {MAX_ELEMENTS} comma-separated values, got {len(parts)}")
    return np.array([parse_float("--gamma", v, -1e4, 1e4, "m^2/s") for v in parts])


def _full_wake_options(args, n_points, n_elements) -> dict:
    phases = parse_int("--phases", args.phases, 1, 36)
    rotations = parse_float("--rotations", args.rotations, 0.0, 100.0, lower_open=True)
    from .helical import DEFAULT_STEPS_PER_ROTATION
    segments = phases * args.blades * (n_elements + 1) * math.ceil(rotations * DEFAULT_STEPS_PER_ROTATION)
    if segments * n_points > MAX_FULL_WAKE_PAIRS:
        raise InputError("--rotations", f"the full wake would need {n_points} points x {segments} filament segments "
                                        f"= {segments * n_points:.3g} > {MAX_FULL_WAKE_PAIRS:.0e}; lower --rotations, "
                                        f"--phases, the number of --gamma elements or of --y points")
    return dict(phases=phases, n_rotations=rotations)


def _cmd_velocity(args) -> int:
    from . import WakeRotor, external_velocity

    radius = parse_float("--radius", args.radius, 0.0, 100.0, "m", lower_open=True)
    args.blades = parse_int("--blades", args.blades, 1, 20)
    rpm = parse_float("--rpm", args.rpm, 0.0, 1e5, "rpm", lower_open=True)
    v_wake = parse_float("--v-wake", args.v_wake, 0.0, 1000.0, "m/s", lower_open=True)
    hub = parse_float("--hub-fraction", args.hub_fraction, 0.0, 0.9, lower_open=True, upper_open=True)
    spin = int(parse_choice("--spin", str(args.spin).lstrip("+"), ("1", "-1")))
    x = parse_float("--x", args.x, -1000.0, 1000.0, "m")
    z = parse_float("--z", args.z, -1000.0, 1000.0, "m")
    g = _gamma(args)
    model = parse_choice("--model", args.model, ("mean", "full"))
    if model == "mean":
        from .mean import table_core_rels
        core = float(parse_choice("--core-rel", f"{parse_float('--core-rel', args.core_rel, 0, 1):g}",
                                  tuple(f"{c:g}" for c in table_core_rels())))
    else:
        core = parse_float("--core-rel", args.core_rel, 0.0, 1.0, lower_open=True)
    y = parse_grid("--y", args.y, *Y_RANGE_M, MAX_POINTS, "m")
    kw = dict(model=model)
    if model == "full":
        kw.update(_full_wake_options(args, y.size, g.size))
    if args.out:
        check_new_file(args.out, args.force)
    rot = WakeRotor(center=(0.0, 0.0, 0.0), axis=(1.0, 0.0, 0.0), radius_m=radius,
                    s_edges=np.linspace(hub, 1.0, g.size + 1), blades=args.blades, spin=spin, core_rel=core)
    pts = np.vstack([np.full_like(y, x), y, np.full_like(y, z)])
    om = rpm * math.pi / 30.0
    u, v, w = external_velocity(pts, [rot], [g], [om], [v_wake], **kw)
    check_finite_result("--radius", u=u, v=v, w=w)
    lines = ["y_m,u_mps,v_mps,w_mps"] + [f"{yi:.6g},{a:.6g},{b:.6g},{c:.6g}"
                                         for yi, a, b, c in zip(y, u[:, 0], v[:, 0], w[:, 0])]
    text = "\n".join(lines) + "\n"
    if args.out:
        write_new_file(args.out, text, args.force)
    else:
        sys.stdout.write(text)
    return 0


def register(subparsers) -> None:
    p = subparsers.add_parser("wake", help="propeller wake: induced velocity of a rotor's slipstream",
                              description="The slipstream of one rotor along a line, from the command line.")
    sub = p.add_subparsers(dest="wake_command", metavar="WAKE_COMMAND")
    v = sub.add_parser("velocity", help="induced velocity along a spanwise line behind a rotor",
                       description="Induced velocity (u, v, w) of one rotor's wake along a line parallel to y. "
                                   "The rotor sits at the origin with its wake along +x.")
    v.add_argument("--radius", required=True, metavar="R_M", help="tip radius, (0, 100] m")
    v.add_argument("--blades", required=True, metavar="B", help="number of blades, an integer in [1, 20]")
    v.add_argument("--gamma", metavar="G1,G2,...",
                   help=f"blade circulation per element (equal-width elements, hub to tip), each in "
                        f"[-1e4, 1e4] m^2/s, 1 to {MAX_ELEMENTS} values")
    v.add_argument("--thrust-gamma", metavar="G", help="uniform blade circulation, [-1e4, 1e4] m^2/s")
    v.add_argument("--rpm", required=True, metavar="RPM", help="rotor speed, (0, 1e+05] rpm")
    v.add_argument("--v-wake", required=True, metavar="V_MPS",
                   help="wake convection speed along the axis, (0, 1000] m/s")
    v.add_argument("--hub-fraction", default="0.15", metavar="F", help="hub radius / tip radius, (0, 0.9) (default 0.15)")
    v.add_argument("--spin", default="1", metavar="+1|-1",
                   help="sense of rotation about the wake axis (+x): +1 or -1 (default +1)")
    v.add_argument("--x", default="1", metavar="X_M", help="axial station of the line, [-1000, 1000] m (default 1)")
    v.add_argument("--z", default="0", metavar="Z_M", help="height of the line, [-1000, 1000] m (default 0)")
    v.add_argument("--y", default="-2:2:0.1", metavar="START:STOP:STEP",
                   help=f"stations along y, within [-1000, 1000] m, at most {MAX_POINTS} points (default -2:2:0.1)")
    v.add_argument("--model", default="mean", metavar="mean|full",
                   help="mean: the blade-passage-averaged wake of the NLP (default); full: the helical fixed wake")
    v.add_argument("--phases", default="1", metavar="N",
                   help="full model: blade positions averaged, an integer in [1, 36] (default 1)")
    v.add_argument("--rotations", default="5", metavar="N",
                   help="full model: wake length in rotor revolutions, (0, 100] (default 5)")
    v.add_argument("--core-rel", default=f"{DEFAULT_CORE_REL:g}", metavar="C",
                   help="vortex core radius / tip radius: 0.05 or 0.1 for the mean model (its tables), "
                        f"(0, 1] for the full one (default {DEFAULT_CORE_REL:g}, the aircraft's)")
    v.add_argument("--out", metavar="FILE.csv", help="output file (default stdout); never replaced without --force")
    v.add_argument("--force", action="store_true", help="replace an existing --out file")
    v.set_defaults(func=_cmd_velocity)
    p.set_defaults(func=lambda args: (p.print_help(), 2)[1])
