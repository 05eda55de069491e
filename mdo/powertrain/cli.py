"""``mdo battery ...`` and ``mdo motor ...``: quick looks at the powertrain models.

* ``mdo battery discharge --current A [--cells-series N --cells-parallel N]
  [--temperature C] [--cutoff V] [--points N] [--out FILE.csv]``: constant-current
  discharge of a pack (one cell by default) from full to the cut-off voltage per
  cell; writes ``capacity_Ah,voltage_V`` (pack values) to FILE or stdout.
* ``mdo battery fit``: the cell model's voltage error table against the measured
  curves; ``mdo battery report [--out DIR] [--force]``: figures and tables, into
  ``./battery_report/`` by default (never into the repository's committed
  ``results/powertrain`` unless asked with ``--out``; existing files are kept unless
  ``--force``).
* ``mdo motor size --power-kw P --rpm N --voltage V [--efficiency E]
  [--copper-loss-fraction F]``: Kv, resistance, no-load current, mass, peak
  efficiency and torque-speed line of a DC motor sized from its rating.

Every number has a finite range (``-h``; the message names it, exit 2); ``--out``
never replaces an existing file without ``--force``.
"""
from __future__ import annotations

import io
import sys

import numpy as np

from ..core import units as u
from ..core.errors import InputError, parse_float, parse_int
from ..core.output import check_new_file, check_new_files, write_new_file

MAX_CELL_CURRENT_A = 12.0   # 1.5 x the largest measured current (8 A)
MAX_CELLS = 10000            # per string / in parallel: far beyond any aircraft pack
MAX_POINTS = 100000
REPORT_FILES = ("discharge_fit.png", "discharge_residuals.png", "fit_errors.md", "motors.png", "balance.md")


def _positive_int(field, value):
    return parse_int(field, value, 1, MAX_CELLS)


def discharge_curve(current_A, cells_series=1, cells_parallel=1, temperature_C=25.0, cutoff_V=2.5,
                    points=101):
    """(capacity_Ah, voltage_V) arrays of a constant-current pack discharge to the cut-off."""
    from .pack import Pack

    cells_series = _positive_int("--cells-series", cells_series)
    cells_parallel = _positive_int("--cells-parallel", cells_parallel)
    current_A = parse_float("--current", current_A, 0.0, MAX_CELL_CURRENT_A * cells_parallel, "A (pack current)",
                            lower_open=True)
    i_cell = current_A / cells_parallel
    if i_cell > MAX_CELL_CURRENT_A:
        raise InputError("--current", f"cell current {i_cell:g} A exceeds {MAX_CELL_CURRENT_A:g} A "
                         f"(1.5x the largest measured); allowed pack current (0, "
                         f"{MAX_CELL_CURRENT_A * cells_parallel:g}] A")
    cutoff_V = parse_float("--cutoff", cutoff_V, 2.0, 4.0, "V")
    temperature_C = parse_float("--temperature", temperature_C, 0.0, 50.0, "deg C")
    points = parse_int("--points", points, 2, MAX_POINTS)
    pack = Pack(cells_series, cells_parallel, temperature_C=temperature_C, min_cell_voltage_V=cutoff_V)
    cell, T = pack.cell, temperature_C
    if cell.voltage(1.0, i_cell, T) <= cutoff_V:
        raise InputError("--current", f"{current_A:g} A gives {cell.voltage(1.0, i_cell, T):.3f} V per cell "
                         f"at full charge, already below the cut-off {cutoff_V:g} V")
    lo, hi = -0.05, 1.0   # U is monotone on [-0.05, 1] (fit constraint)
    if cell.voltage(lo, i_cell, T) > cutoff_V:
        s_end = lo
    else:
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if cell.voltage(mid, i_cell, T) < cutoff_V else (lo, mid)
        s_end = 0.5 * (lo + hi)
    q_cell = np.linspace(0.0, (1.0 - s_end) * cell.usable_capacity_Ah(T), int(points))
    soc = cell.soc_from_charge(q_cell, T)
    return q_cell * cells_parallel, pack.voltage(soc, current_A)


def _cmd_discharge(args) -> int:
    if args.out:
        check_new_file(args.out, args.force)
    q, v = discharge_curve(args.current, args.cells_series, args.cells_parallel, args.temperature,
                           args.cutoff, args.points)
    buf = io.StringIO()
    buf.write("capacity_Ah,voltage_V\n")
    for a, b in zip(q, v):
        buf.write(f"{a:.10g},{b:.10g}\n")
    if args.out:
        write_new_file(args.out, buf.getvalue(), args.force)
        print(f"mdo battery: {len(q)} points, {q[-1]:.4g} Ah to {v[-1]:.4g} V -> {args.out}", file=sys.stderr)
    else:
        sys.stdout.write(buf.getvalue())
    return 0


def _cmd_fit(args) -> int:
    from .cell import nmc18650
    err = nmc18650().fit.get("errors")
    if not err:
        raise InputError("fit", "the cell fit file carries no error table; run python -m mdo.powertrain.cell_fit")
    print("NMC 18650 cell model vs measured discharge curves (0-50 deg C)")
    print("current   RMS all   max all   RMS s>=0.2   max s>=0.2   (mV)")
    for k, e in err["per_current"].items():
        e2 = err["per_current_soc_ge_0.2"][k]
        print(f"{k:>5} A  {e['rms_mV']:8.1f}  {e['max_mV']:8.1f}  {e2['rms_mV']:11.1f}  {e2['max_mV']:11.1f}")
    return 0


def _cmd_report(args) -> int:
    from pathlib import Path

    from .report import write_report
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise InputError("--out", f"{out} exists and is not a folder")
    if out.is_symlink():
        raise InputError("--out", f"{out} is a symbolic link; refusing to write through it")
    if out.is_dir():   # every file checked before the first is written
        check_new_files([out / f for f in REPORT_FILES], args.force)
    # the command's data: the catalog's vehicle definitions (the CLI is the edge that
    # may reach up to them; mdo.powertrain itself knows no vehicle)
    from ..vehicle.catalog import ga2p, ga8p, ttw
    powertrains = {c.name: c.powertrain() for c in (ga2p(), ga8p(), ttw())}
    try:
        files = write_report(out, powertrains)
    except OSError as exc:
        raise InputError("--out", f"cannot write into {out}: {exc.strerror or exc}") from None
    for f in files:
        print(f"mdo battery: wrote {f}")
    return 0


def _cmd_motor_size(args) -> int:
    from .motor import size_dc_motor
    args.power_kw = parse_float("--power-kw", args.power_kw, 0.0, 1e4, "kW", lower_open=True)
    args.rpm = parse_float("--rpm", args.rpm, 0.0, 1e5, "rpm", lower_open=True)
    args.voltage = parse_float("--voltage", args.voltage, 0.0, 1e4, "V", lower_open=True)
    args.efficiency = parse_float("--efficiency", args.efficiency, 0.5, 0.99)
    args.copper_loss_fraction = parse_float("--copper-loss-fraction", args.copper_loss_fraction, 0.05, 0.95)
    m = size_dc_motor(args.power_kw * 1e3, args.rpm * u.RPM, args.voltage, args.efficiency,
                      args.copper_loss_fraction)
    eta, i_pk = m.peak_efficiency(args.voltage)
    print(f"DC motor sized for {args.power_kw:g} kW at {args.rpm:g} rpm, {args.voltage:g} V "
          f"(efficiency {args.efficiency:g} there, copper-loss fraction {args.copper_loss_fraction:g})")
    print(f"  Kv               {m.kv_rpm_per_V:.4f} rpm/V ({m.kv_radps_per_V:.5f} rad/s/V)")
    print(f"  resistance       {m.resistance_ohm * 1e3:.3f} mOhm")
    print(f"  no-load current  {m.no_load_current_A:.3f} A")
    print(f"  rated torque     {m.rated_torque_Nm:.2f} N m")
    print(f"  mass (NDARC)     {m.mass_kg:.2f} kg")
    print(f"  peak efficiency  {eta:.4f} at {i_pk:.1f} A ({i_pk / m.current_A(m.rated_torque_Nm):.2f} x rated current)")
    print(f"  at {args.voltage:g} V: no-load speed {m.no_load_speed_radps(args.voltage) / u.RPM:.1f} rpm, "
          f"stall torque {m.stall_torque_Nm(args.voltage):.1f} N m (line omega = omega_0 - Kv^2 R Q)")
    return 0


def register(subparsers) -> None:
    bat = subparsers.add_parser("battery", help="battery cell/pack model: discharge curves, fit errors",
                                description="Battery models of mdo.powertrain (18650 NMC cell).")
    bsub = bat.add_subparsers(dest="battery_command", metavar="ACTION")
    d = bsub.add_parser("discharge", help="constant-current discharge curve (capacity_Ah,voltage_V)",
                        description="Constant-current discharge of a pack from full to the cut-off voltage.")
    d.add_argument("--current", required=True, metavar="A",
                   help="pack discharge current, A: > 0, at most {MAX_CELL_CURRENT_A:g} A per parallel cell")
    d.add_argument("--cells-series", default="1", metavar="N",
                   help=f"cells in series, an integer in [1, {MAX_CELLS}] (default 1)")
    d.add_argument("--cells-parallel", default="1", metavar="N",
                   help=f"cells in parallel, an integer in [1, {MAX_CELLS}] (default 1)")
    d.add_argument("--temperature", default="25", metavar="C",
                   help="ambient/pack temperature, [0, 50] deg C (default 25)")
    d.add_argument("--cutoff", default="2.5", metavar="V", help="cut-off voltage per cell, [2, 4] V (default 2.5)")
    d.add_argument("--points", default="101", metavar="N",
                   help=f"number of output points, an integer in [2, {MAX_POINTS}] (default 101)")
    d.add_argument("--out", metavar="FILE.csv", help="CSV file (default: stdout); never replaced without --force")
    d.add_argument("--force", action="store_true", help="replace an existing --out file")
    d.set_defaults(func=_cmd_discharge)
    f = bsub.add_parser("fit", help="voltage errors of the cell model against the measured curves")
    f.set_defaults(func=_cmd_fit)
    rp = bsub.add_parser("report", help="figures and tables: model vs measured, motors, network balance",
                         description="Write " + ", ".join(REPORT_FILES) + " into a folder.")
    rp.add_argument("--out", default="battery_report", metavar="DIR",
                    help="folder (default ./battery_report); the committed results/powertrain is written only "
                         "when named here, and existing files only with --force")
    rp.add_argument("--force", action="store_true", help="replace existing report files in --out")
    rp.set_defaults(func=_cmd_report)

    mot = subparsers.add_parser("motor", help="DC motor sizing", description="DC motor models of mdo.powertrain.")
    msub = mot.add_subparsers(dest="motor_command", metavar="ACTION")
    s = msub.add_parser("size", help="size a DC motor from its rating",
                        description="Kv, resistance, no-load current and mass from a rating (mdo.powertrain.motor).")
    s.add_argument("--power-kw", required=True, metavar="P", help="rated shaft power, (0, 1e4] kW")
    s.add_argument("--rpm", required=True, metavar="RPM", help="rated speed, (0, 1e5] rpm")
    s.add_argument("--voltage", required=True, metavar="V", help="terminal voltage at the rated point, (0, 1e4] V")
    s.add_argument("--efficiency", default="0.94", metavar="E",
                   help="efficiency at the rated point, [0.5, 0.99] (default 0.94)")
    s.add_argument("--copper-loss-fraction", default="0.6", metavar="F",
                   help="share of the rated-point losses in the winding, [0.05, 0.95] (default 0.6)")
    s.set_defaults(func=_cmd_motor_size)
