"""``mdo wake velocity``: the slipstream of one rotor along a line, from the command line.

    mdo wake velocity --radius R_M --blades B --thrust-gamma G_M2PS | --gamma G1,G2,...
                      --rpm RPM --v-wake V_MPS [--hub-fraction F] [--spin +1|-1]
                      [--x X_M] [--z Z_M] [--y START:STOP:STEP] [--model mean|full]
                      [--phases N] [--rotations N] [--core-rel C] [--out FILE.csv]

The rotor sits at the origin with its wake along +x; the line runs along y at
(x, z).  Blade circulation: ``--gamma`` per blade element (equal-width elements
from the hub to the tip) or ``--thrust-gamma`` for a uniform value.  Writes
``y_m,u_mps,v_mps,w_mps`` (stdout without ``--out``).  ``--model mean`` is the
blade-passage-averaged wake of the NLP; ``full`` the helical fixed wake.
Bad input raises ``InputError`` (one line, exit 2).
"""
from __future__ import annotations

import math
import sys

import numpy as np

from ..core.errors import InputError

__all__ = ["register"]


def _range(text, field):
    parts = str(text).split(":")
    try:
        a, b, s = (float(p) for p in parts)
    except ValueError as exc:
        raise InputError(field, f"expected START:STOP:STEP, got {text!r}") from exc
    if s <= 0 or b < a or not all(math.isfinite(v) for v in (a, b, s)):
        raise InputError(field, f"need finite START <= STOP and STEP > 0, got {text!r}")
    n = int(math.floor((b - a) / s + 1e-9)) + 1
    if n > 20000:
        raise InputError(field, f"{n} points is too many (max 20000)")
    return a + s * np.arange(n)


def _positive(field, v, unit=""):
    if v is None or not math.isfinite(v) or v <= 0:
        raise InputError(field, f"must be a finite number > 0{(' ' + unit) if unit else ''}, got {v!r}")


def _cmd_velocity(args) -> int:
    from . import WakeRotor, external_velocity

    _positive("--radius", args.radius, "m")
    _positive("--rpm", args.rpm, "rpm")
    _positive("--v-wake", args.v_wake, "m/s")
    if args.blades < 1:
        raise InputError("--blades", f"must be >= 1, got {args.blades}")
    if not (0.0 < args.hub_fraction < 0.9):
        raise InputError("--hub-fraction", f"allowed range (0, 0.9), got {args.hub_fraction:g}")
    if args.spin not in (1, -1):
        raise InputError("--spin", f"must be +1 or -1, got {args.spin}")
    if (args.gamma is None) == (args.thrust_gamma is None):
        raise InputError("--gamma", "give exactly one of --gamma G1,G2,... or --thrust-gamma G")
    if args.gamma is not None:
        try:
            g = np.array([float(v) for v in args.gamma.split(",")])
        except ValueError as exc:
            raise InputError("--gamma", f"expected comma-separated numbers, got {args.gamma!r}") from exc
        if g.size < 1 or not np.all(np.isfinite(g)):
            raise InputError("--gamma", "needs at least one finite value")
    else:
        if not math.isfinite(args.thrust_gamma):
            raise InputError("--thrust-gamma", "must be finite")
        g = np.array([args.thrust_gamma])
    if args.model not in ("mean", "full"):
        raise InputError("--model", f"'mean' or 'full', got {args.model!r}")
    if args.core_rel not in (0.05, 0.1) and args.model == "mean":
        raise InputError("--core-rel", "the mean-wake tables exist for 0.05 and 0.1")
    y = _range(args.y, "--y")
    rot = WakeRotor(center=(0.0, 0.0, 0.0), axis=(1.0, 0.0, 0.0), radius_m=args.radius,
                    s_edges=np.linspace(args.hub_fraction, 1.0, g.size + 1), blades=args.blades,
                    spin=args.spin, core_rel=args.core_rel)
    pts = np.vstack([np.full_like(y, args.x), y, np.full_like(y, args.z)])
    om = args.rpm * math.pi / 30.0
    kw = dict(model=args.model)
    if args.model == "full":
        if args.phases < 1 or args.rotations <= 0:
            raise InputError("--phases", "phases >= 1 and rotations > 0 required")
        kw.update(phases=args.phases, n_rotations=args.rotations)
    u, v, w = external_velocity(pts, [rot], [g], [om], [args.v_wake], **kw)
    lines = ["y_m,u_mps,v_mps,w_mps"] + [f"{yi:.6g},{a:.6g},{b:.6g},{c:.6g}"
                                         for yi, a, b, c in zip(y, u[:, 0], v[:, 0], w[:, 0])]
    text = "\n".join(lines) + "\n"
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


def register(subparsers) -> None:
    p = subparsers.add_parser("wake", help="propeller wake: induced velocity of a rotor's slipstream",
                              description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="wake_command", metavar="WAKE_COMMAND")
    v = sub.add_parser("velocity", help="induced velocity along a spanwise line behind a rotor")
    v.add_argument("--radius", type=float, required=True, help="tip radius, m")
    v.add_argument("--blades", type=int, required=True)
    v.add_argument("--gamma", help="blade circulation per element, m^2/s, hub to tip (comma-separated)")
    v.add_argument("--thrust-gamma", type=float, help="uniform blade circulation, m^2/s")
    v.add_argument("--rpm", type=float, required=True)
    v.add_argument("--v-wake", type=float, required=True, help="wake convection speed along the axis, m/s")
    v.add_argument("--hub-fraction", type=float, default=0.15)
    v.add_argument("--spin", type=int, default=1, help="+1/-1: sense of rotation about the wake axis (+x)")
    v.add_argument("--x", type=float, default=1.0, help="axial station of the line, m")
    v.add_argument("--z", type=float, default=0.0, help="height of the line, m")
    v.add_argument("--y", default="-2:2:0.1", help="START:STOP:STEP along y, m")
    v.add_argument("--model", default="mean")
    v.add_argument("--phases", type=int, default=1)
    v.add_argument("--rotations", type=float, default=5.0)
    v.add_argument("--core-rel", type=float, default=0.05)
    v.add_argument("--out")
    v.set_defaults(func=_cmd_velocity)
    p.set_defaults(func=lambda args: (p.print_help(), 2)[1])
