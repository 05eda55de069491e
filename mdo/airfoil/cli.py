"""``mdo airfoil ...``: list the shipped airfoils, print a polar, plot the surrogate.

    mdo airfoil list
    mdo airfoil polar NACA4412 --re 1e6 [--mach 0.3] [--alpha -10 20 1]
    mdo airfoil plot NACA4412 [--out results/airfoils]      (or: --all)
    mdo airfoil check NACA4412                              (errors at the polar points)
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..core.errors import InputError, check_positive, check_range


def register(subparsers) -> None:
    p = subparsers.add_parser("airfoil", help="section aerodynamics: list, polar, plot, check",
                              description="Shipped airfoil surrogates (cl, cd, cm vs alpha, Re, M).")
    sub = p.add_subparsers(dest="airfoil_command", metavar="ACTION")

    q = sub.add_parser("list", help="shipped airfoils with thickness, data Re range, alpha_0, slope")
    q.set_defaults(func=_cmd_list)

    q = sub.add_parser("polar", help="print cl, cd, cm, L/D over an alpha range")
    q.add_argument("name")
    q.add_argument("--re", type=float, required=True, help="chord Reynolds number")
    q.add_argument("--mach", type=float, default=0.0)
    q.add_argument("--alpha", type=float, nargs=3, default=[-10.0, 20.0, 1.0],
                   metavar=("START", "END", "STEP"), help="degrees (default -10 20 1)")
    q.set_defaults(func=_cmd_polar)

    q = sub.add_parser("plot", help="write <name>.png: data over surrogate, incl. post-stall")
    q.add_argument("name", nargs="?")
    q.add_argument("--all", action="store_true", help="every shipped airfoil")
    q.add_argument("--out", default="results/airfoils", help="folder (default results/airfoils)")
    q.set_defaults(func=_cmd_plot)

    q = sub.add_parser("check", help="surrogate minus XFOIL data at every polar point")
    q.add_argument("name")
    q.set_defaults(func=_cmd_check)

    p.set_defaults(func=lambda args: (p.print_help(), 2)[1])


def _cmd_list(args) -> int:
    from . import Airfoil, available

    print(f"{'name':10s} {'title':12s} {'t/c':>6s} {'Re data':>17s} {'alpha0 deg':>10s} "
          f"{'cl_a /rad':>9s}  used for")
    for name in available():
        af = Airfoil.from_name(name)
        lo, hi = af.reynolds_range
        from .catalog import CATALOG
        print(f"{name:10s} {af.title:12s} {af.thickness_to_chord:6.3f} {lo:8.2g}-{hi:8.2g} "
              f"{np.degrees(af.alpha0_rad):10.2f} {af.lift_slope_per_rad:9.2f}  {CATALOG[name].used_for}")
    return 0


def _cmd_polar(args) -> int:
    from . import Airfoil

    check_positive("--re", args.re)
    check_range("--mach", args.mach, 0.0, 0.95)
    a0, a1, da = args.alpha
    if da <= 0 or a1 < a0 or (a1 - a0) / da > 10000:
        raise InputError("--alpha", "expects START <= END and 0 < STEP with at most 10000 points")
    af = Airfoil.from_name(args.name)
    alpha = np.arange(a0, a1 + 0.5 * da, da)
    cl, cd, cm = af.coefficients(np.radians(alpha), args.re, args.mach)
    print(f"{af.title}: Re = {args.re:.4g}, M = {args.mach:g}")
    print(f"{'alpha':>8s} {'cl':>8s} {'cd':>9s} {'cm':>8s} {'L/D':>8s}")
    for row in zip(alpha, cl, cd, cm, cl / cd):
        print("{:8.2f} {:8.4f} {:9.5f} {:8.4f} {:8.2f}".format(*row))
    return 0


def _cmd_plot(args) -> int:
    from . import Airfoil, available
    from .validation import plot_airfoil

    if not args.all and not args.name:
        raise InputError("name", "give an airfoil name or --all")
    names = available() if args.all else [args.name]
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for name in names:
        af = Airfoil.from_name(name)
        path = plot_airfoil(af, out / f"{af.key}.png")
        print(f"wrote {path}")
    return 0


def _cmd_check(args) -> int:
    from . import Airfoil
    from .validation import CD_TOL, CL_TOL, polar_errors

    af = Airfoil.from_name(args.name)
    errs = polar_errors(af)
    print(f"{af.title}: surrogate - XFOIL at the polar points (M = 0)")
    print(f"{'Re':>9s} {'n':>4s} {'max|dcl|':>8s} {'rms dcl':>8s} {'max dcd/cd':>10s} {'rms':>6s} "
          f"{'n>|' + str(CL_TOL) + '|':>8s} {'n>' + str(int(CD_TOL * 100)) + '%':>6s}")
    for e in errs:
        print(f"{e.reynolds:9.3g} {e.n_points:4d} {e.max_dcl:8.3f} {e.rms_dcl:8.4f} {e.max_rel_dcd:10.3f} "
              f"{e.rms_rel_dcd:6.3f} {e.n_cl_over:8d} {e.n_cd_over:6d}")
    return 0
