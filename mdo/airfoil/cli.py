"""``mdo airfoil ...``: list the shipped airfoils, print a polar, plot the surrogate.

    mdo airfoil list
    mdo airfoil polar NACA4412 --re 1e6 [--mach 0.3] [--alpha -10 20 1]
    mdo airfoil plot NACA4412 [--out results/airfoils]      (or: --all)
    mdo airfoil check NACA4412                              (errors at the polar points)

``resolve_airfoil`` is the one name resolver of every command that takes an airfoil
(``mdo wing --airfoil``, ``mdo rotor sweep/design --airfoil``, ``mdo airfoil ...``):
the shipped airfoils of :func:`mdo.airfoil.available`, case, spaces, '-' and '_'
ignored; anything else is refused with the same message listing them.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..core.errors import InputError, parse_float, parse_int

__all__ = ["register", "resolve_airfoil", "RE_RANGE", "ALPHA_RANGE_DEG"]

RE_RANGE = (1e4, 1e8)          # chord Reynolds numbers the polar command accepts (data: 2e4 to 1e7)
ALPHA_RANGE_DEG = (-180.0, 180.0)
MAX_POLAR_POINTS = 10000


def resolve_airfoil(name, field: str = "--airfoil") -> str:
    """The catalogue key of a shipped airfoil (``'NACA 4412'`` -> ``'naca4412'``), or
    ``InputError(field, "unknown airfoil ...; available: ...")``, the same for every command.

    A generated section is asked for explicitly, with its transition setting
    (``"NACA 2412@ncrit=9"``, ``"clarky@xtr=0.1"``, ``"my.dat@ncrit=7"``:
    ``mdo.airfoil.generate``) and passes through unchanged; a bare unknown name is an
    error rather than a silent (slow, NeuralFoil) generation."""
    from .airfoil import available
    from .catalog import normalize

    if "@" in str(name):
        return str(name)
    key = normalize(name)
    if key not in available():
        raise InputError(field, f"unknown airfoil {str(name)!r}; available: {', '.join(available())}")
    return key


def register(subparsers) -> None:
    p = subparsers.add_parser("airfoil", help="section aerodynamics: list, polar, plot, check",
                              description="Shipped airfoil surrogates (cl, cd, cm vs alpha, Re, M).")
    sub = p.add_subparsers(dest="airfoil_command", metavar="ACTION")

    q = sub.add_parser("list", help="shipped airfoils with thickness, data Re range, alpha_0, slope")
    q.set_defaults(func=_cmd_list)

    names = "a shipped airfoil (see 'mdo airfoil list'; case, spaces and '-' ignored)"
    q = sub.add_parser("polar", help="print cl, cd, cm, L/D over an alpha range")
    q.add_argument("name", metavar="NAME", help=names)
    q.add_argument("--re", required=True, metavar="RE",
                   help=f"chord Reynolds number, {RE_RANGE[0]:g} to {RE_RANGE[1]:g}")
    q.add_argument("--mach", default="0", metavar="M", help="Mach number, 0 to 0.95 (default 0)")
    q.add_argument("--alpha", nargs=3, default=["-10", "20", "1"], metavar=("START", "END", "STEP"),
                   help=f"angle of attack range, deg, within -180 to 180, STEP > 0, at most "
                        f"{MAX_POLAR_POINTS} points (default -10 20 1)")
    q.set_defaults(func=_cmd_polar)

    q = sub.add_parser("plot", help="write <name>.png: data over surrogate, incl. post-stall")
    q.add_argument("name", nargs="?", metavar="NAME", help=names)
    q.add_argument("--all", action="store_true", help="every shipped airfoil")
    q.add_argument("--out", default="results/airfoils", metavar="DIR",
                   help="folder (default results/airfoils); existing figures are kept unless --force")
    q.add_argument("--force", action="store_true", help="replace existing <name>.png files")
    q.set_defaults(func=_cmd_plot)

    q = sub.add_parser("check", help="surrogate minus XFOIL data at every polar point")
    q.add_argument("name", metavar="NAME", help=names)
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

    from ..core.errors import check_finite_result

    key = resolve_airfoil(args.name, "NAME")
    re_ = parse_float("--re", args.re, *RE_RANGE)
    mach = parse_float("--mach", args.mach, 0.0, 0.95)
    a0, a1 = (parse_float("--alpha", a, *ALPHA_RANGE_DEG, "deg") for a in args.alpha[:2])
    da = parse_float("--alpha", args.alpha[2], 0.0, 360.0, "deg (STEP)", lower_open=True)
    if a1 < a0 or (a1 - a0) / da > MAX_POLAR_POINTS:
        raise InputError("--alpha", f"expects START <= END and 0 < STEP with at most {MAX_POLAR_POINTS} points")
    af = Airfoil.from_name(key)
    alpha = np.arange(a0, a1 + 0.5 * da, da)
    cl, cd, cm = af.coefficients(np.radians(alpha), re_, mach)
    check_finite_result("--re", cl=cl, cd=cd, cm=cm)
    print(f"{af.title}: Re = {re_:.4g}, M = {mach:g}")
    print(f"{'alpha':>8s} {'cl':>8s} {'cd':>9s} {'cm':>8s} {'L/D':>8s}")
    for row in zip(alpha, cl, cd, cm, cl / cd):
        print("{:8.2f} {:8.4f} {:9.5f} {:8.4f} {:8.2f}".format(*row))
    return 0


def _cmd_plot(args) -> int:
    from . import Airfoil, available
    from .validation import plot_airfoil

    if not args.all and not args.name:
        raise InputError("name", "give an airfoil name or --all")
    from ..core.output import check_new_files

    names = available() if args.all else [resolve_airfoil(args.name, "NAME")]
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise InputError("--out", f"{out} exists and is not a folder")
    if out.is_dir():   # every figure checked before the first is drawn
        check_new_files([out / f"{n}.png" for n in names], args.force)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError("--out", f"cannot create folder {out}: {exc.strerror or exc}") from None
    for name in names:
        af = Airfoil.from_name(name)
        path = plot_airfoil(af, out / f"{af.key}.png")
        print(f"wrote {path}")
    return 0


def _cmd_check(args) -> int:
    from . import Airfoil
    from .validation import CD_TOL, CL_TOL, polar_errors

    af = Airfoil.from_name(resolve_airfoil(args.name, "NAME"))
    errs = polar_errors(af)
    print(f"{af.title}: surrogate - XFOIL at the polar points (M = 0)")
    print(f"{'Re':>9s} {'n':>4s} {'max|dcl|':>8s} {'rms dcl':>8s} {'max dcd/cd':>10s} {'rms':>6s} "
          f"{'n>|' + str(CL_TOL) + '|':>8s} {'n>' + str(int(CD_TOL * 100)) + '%':>6s}")
    for e in errs:
        print(f"{e.reynolds:9.3g} {e.n_points:4d} {e.max_dcl:8.3f} {e.rms_dcl:8.4f} {e.max_rel_dcd:10.3f} "
              f"{e.rms_rel_dcd:6.3f} {e.n_cl_over:8d} {e.n_cd_over:6d}")
    return 0
