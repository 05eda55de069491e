"""``mdo wing``: vortex-lattice analysis of a trapezoidal wing.

    mdo wing --span M --root-chord M --taper L [--sweep DEG] [--dihedral DEG]
             [--twist-root DEG] [--twist-tip DEG] --alpha DEG [--mach M]
             [--nspan N] [--nchord N] [--airfoil NAME] [--json]

Prints CL, CDi (Trefftz plane), the span efficiency and the spanwise section
lift coefficient of the right half; ``--json`` prints one JSON object with keys
``CL``, ``CDi``, ``e``, ``y`` (m, strip centres of the right half) and ``cl``.
Sweep is that of the quarter-chord line; the Prandtl-Glauert stretch is built at
the given Mach number.  Every number has a finite range (``mdo wing -h``); the
section names are those of ``mdo airfoil list`` (one resolver for every command).
"""
from __future__ import annotations

import json
import math

import numpy as np

from ..core.errors import check_finite_result, parse_float, parse_int

__all__ = ["register", "run_wing"]


# (field, attribute, lower, upper, unit, lower open, upper open, help): every number is
# checked against a finite range (issue 19 item 4); the help text prints the same range
_NUMBERS = (
    ("--span", "span", 0.01, 1000.0, "m", False, False, "tip-to-tip span"),
    ("--root-chord", "root_chord", 0.001, 100.0, "m", False, False, "root chord"),
    ("--taper", "taper", 0.0, 2.0, "", True, False, "tip/root chord ratio"),
    ("--sweep", "sweep", -80.0, 80.0, "deg", True, True, "quarter-chord sweep"),
    ("--dihedral", "dihedral", -80.0, 80.0, "deg", True, True, "dihedral"),
    ("--twist-root", "twist_root", -30.0, 30.0, "deg", False, False, "root twist, nose up"),
    ("--twist-tip", "twist_tip", -30.0, 30.0, "deg", False, False, "tip twist, nose up"),
    ("--alpha", "alpha", -30.0, 30.0, "deg", False, False, "angle of attack"),
    ("--mach", "mach", 0.0, 0.95, "", False, False, "Mach number (subsonic; Prandtl-Glauert)"),
)
_INTEGERS = (("--nspan", "nspan", 1, 200, "panels per semispan"), ("--nchord", "nchord", 1, 30, "chordwise panels"))
_DEFAULTS = {"sweep": "0", "dihedral": "0", "twist_root": "0", "twist_tip": "0", "mach": "0",
             "nspan": "20", "nchord": "4"}
_REQUIRED = ("span", "root_chord", "taper", "alpha")


def register(subparsers) -> None:
    from ..core.errors import range_text

    p = subparsers.add_parser(
        "wing", help="vortex-lattice analysis of a trapezoidal wing (CL, CDi, e, spanwise cl)",
        description="Vortex-lattice analysis of a mirrored trapezoidal wing: CL, induced drag "
                    "(Trefftz plane), span efficiency and spanwise cl.")
    for flag, dest, lo, hi, unit, lo_open, hi_open, what in _NUMBERS:
        default = _DEFAULTS.get(dest)
        tail = f" (default {default})" if default is not None else ""
        p.add_argument(flag, dest=dest, required=dest in _REQUIRED, default=default, metavar=unit.upper() or "X",
                       help=f"{what}, {range_text(lo, hi, unit, lo_open, hi_open)}{tail}")
    for flag, dest, lo, hi, what in _INTEGERS:
        p.add_argument(flag, dest=dest, default=_DEFAULTS[dest], metavar="N",
                       help=f"{what}, an integer in [{lo}, {hi}] (default {_DEFAULTS[dest]})")
    p.add_argument("--airfoil", default=None, metavar="NAME",
                   help="section whose camber line the lattice follows: a shipped airfoil "
                        "(see 'mdo airfoil list'); default flat plate")
    p.add_argument("--json", action="store_true", help="print a JSON object (CL, CDi, e, y, cl)")
    p.set_defaults(func=_handler)


def _check(args) -> None:
    """Parse every number of ``args`` in place (InputError names the flag and its range)."""
    for flag, dest, lo, hi, unit, lo_open, hi_open, _ in _NUMBERS:
        setattr(args, dest, parse_float(flag, getattr(args, dest), lo, hi, unit,
                                        lower_open=lo_open, upper_open=hi_open))
    for flag, dest, lo, hi, _ in _INTEGERS:
        setattr(args, dest, parse_int(flag, getattr(args, dest), lo, hi))
    if args.airfoil is not None:
        from ..airfoil.cli import resolve_airfoil
        args.airfoil = resolve_airfoil(args.airfoil, "--airfoil")


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
    check_finite_result("--span", CL=out["CL"], CDi=out["CDi"], e=out["e"], cl=out["cl"])
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
