"""``mdo wing``: vortex-lattice analysis of a trapezoidal wing.

    mdo wing --span M --root-chord M --taper L [--sweep DEG] [--dihedral DEG]
             [--twist-root DEG] [--twist-tip DEG] --alpha DEG [--mach M]
             [--nspan N] [--nchord N] [--airfoil NAME] [--json]

Prints CL, CDi (Trefftz plane), the span efficiency and the spanwise section
lift coefficient of the right half; ``--json`` prints one JSON object with keys
``CL``, ``CDi``, ``e``, ``y`` (m, strip centres of the right half) and ``cl``.
Sweep is that of the quarter-chord line; the Prandtl-Glauert stretch is built at
the given Mach number.
"""
from __future__ import annotations

import json
import math

import numpy as np

from ..core.errors import InputError, check_positive, check_range

__all__ = ["register", "run_wing"]


def register(subparsers) -> None:
    p = subparsers.add_parser(
        "wing", help="vortex-lattice analysis of a trapezoidal wing (CL, CDi, e, spanwise cl)",
        description="Vortex-lattice analysis of a mirrored trapezoidal wing: CL, induced drag "
                    "(Trefftz plane), span efficiency and spanwise cl.")
    p.add_argument("--span", type=float, required=True, metavar="M", help="tip-to-tip span, m (> 0)")
    p.add_argument("--root-chord", type=float, required=True, metavar="M", help="root chord, m (> 0)")
    p.add_argument("--taper", type=float, required=True, metavar="L", help="tip/root chord ratio, (0, 2]")
    p.add_argument("--sweep", type=float, default=0.0, metavar="DEG", help="quarter-chord sweep, deg (|.| < 80)")
    p.add_argument("--dihedral", type=float, default=0.0, metavar="DEG", help="dihedral, deg (|.| < 80)")
    p.add_argument("--twist-root", type=float, default=0.0, metavar="DEG", help="root twist, deg, nose up")
    p.add_argument("--twist-tip", type=float, default=0.0, metavar="DEG", help="tip twist, deg, nose up")
    p.add_argument("--alpha", type=float, required=True, metavar="DEG", help="angle of attack, deg (|.| <= 30)")
    p.add_argument("--mach", type=float, default=0.0, metavar="M", help="Mach number, [0, 0.95] (default 0)")
    p.add_argument("--nspan", type=int, default=20, metavar="N", help="panels per semispan, 1..200 (default 20)")
    p.add_argument("--nchord", type=int, default=4, metavar="N", help="chordwise panels, 1..30 (default 4)")
    p.add_argument("--airfoil", default=None, metavar="NAME",
                   help="section camber line (e.g. naca4412, clarky, naca63412, e63; default flat plate)")
    p.add_argument("--json", action="store_true", help="print a JSON object (CL, CDi, e, y, cl)")
    p.set_defaults(func=_handler)


def _check(args) -> None:
    check_positive("--span", args.span, "m")
    check_positive("--root-chord", args.root_chord, "m")
    if not (math.isfinite(args.taper) and 0.0 < args.taper <= 2.0):
        raise InputError("--taper", f"allowed range (0, 2], got {args.taper:g}")
    check_range("--sweep", args.sweep, -80.0, 80.0, "deg", inclusive=False)
    check_range("--dihedral", args.dihedral, -80.0, 80.0, "deg", inclusive=False)
    check_range("--twist-root", args.twist_root, -30.0, 30.0, "deg")
    check_range("--twist-tip", args.twist_tip, -30.0, 30.0, "deg")
    check_range("--alpha", args.alpha, -30.0, 30.0, "deg")
    if not math.isfinite(args.mach) or args.mach < 0.0 or args.mach >= 1.0:
        raise InputError("--mach", f"allowed range [0, 1) (subsonic; Prandtl-Glauert), got {args.mach:g}")
    check_range("--mach", args.mach, 0.0, 0.95)
    if not 1 <= args.nspan <= 200:
        raise InputError("--nspan", f"allowed range [1, 200], got {args.nspan}")
    if not 1 <= args.nchord <= 30:
        raise InputError("--nchord", f"allowed range [1, 30], got {args.nchord}")
    from .camber import camber_line
    try:
        camber_line(args.airfoil)
    except InputError as exc:
        raise InputError("--airfoil", str(exc).split(": ", 1)[-1]) from None


def run_wing(span, root_chord, taper, alpha_deg, *, sweep_deg=0.0, dihedral_deg=0.0, twist_root_deg=0.0,
             twist_tip_deg=0.0, mach=0.0, nspan=20, nchord=4, airfoil=None) -> dict:
    """Analysis behind ``mdo wing``: returns CL, CDi, e, y (m) and cl of the right half."""
    from .camber import camber_line
    from .geometry import trapezoid
    from .vlm import VLM

    camber_line(airfoil)   # unknown section -> InputError before any work
    d = math.radians
    w = trapezoid("wing", span, root_chord, taper, sweep=d(sweep_deg), dihedral=d(dihedral_deg),
                  twist_root=d(twist_root_deg), twist_tip=d(twist_tip_deg), airfoil=airfoil,
                  nspan=nspan, nchord=nchord)
    v = VLM([w], mach_ref=mach)
    r = v.solve(d(alpha_deg), 1.0, rho=1.0, mach=mach)
    g = v.geometry
    y = np.array(g["strip_mid"])[1, :]
    return {"CL": float(r["CL"]), "CDi": float(r["CDi"]), "e": float(r["e"]),
            "y": [float(x) for x in y], "cl": [float(x) for x in np.array(r["cl"]).ravel()]}


def _handler(args) -> int:
    _check(args)
    out = run_wing(args.span, args.root_chord, args.taper, args.alpha, sweep_deg=args.sweep,
                   dihedral_deg=args.dihedral, twist_root_deg=args.twist_root,
                   twist_tip_deg=args.twist_tip, mach=args.mach, nspan=args.nspan,
                   nchord=args.nchord, airfoil=args.airfoil)
    if args.json:
        print(json.dumps(out))
        return 0
    area = args.span * args.root_chord * (1 + args.taper) / 2
    print(f"wing: span {args.span:g} m, root chord {args.root_chord:g} m, taper {args.taper:g}, "
          f"S {area:.4g} m^2, AR {args.span ** 2 / area:.4g}; alpha {args.alpha:g} deg, M {args.mach:g}; "
          f"{args.nspan} x {args.nchord} panels per semispan, section {args.airfoil or 'flat plate'}")
    print(f"CL  = {out['CL']:.5f}")
    print(f"CDi = {out['CDi']:.6f}   (Trefftz plane)")
    print(f"e   = {out['e']:.4f}")
    print("\n   y [m]      cl")
    for yy, cc in zip(out["y"], out["cl"]):
        print(f"{yy:8.4f}  {cc:8.4f}")
    return 0
