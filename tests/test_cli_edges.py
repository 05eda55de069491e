"""The command line's edge cases (issue 23 item 5, issue 23 item 1 for `rotor sweep`):
negative numbers in ranges, help for every option without markup, one airfoil-name
resolver, --version, a closed pipe, no overwriting, `mdo run FILE --options`, and an
undefined propeller efficiency shown as blank / "—"."""
import argparse
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from mdo.cli import build_parser, main

ROOT = Path(__file__).resolve().parents[1]
APC = str(ROOT / "mdo" / "rotor" / "data" / "apce_10x7_geometry.csv")
WAKE = ["wake", "velocity", "--radius", "1", "--blades", "3", "--thrust-gamma", "2", "--rpm", "2000",
        "--v-wake", "60"]
SWEEP = ["rotor", "sweep", "--geometry", APC, "--diameter", "0.254", "--blades", "2", "--airfoil", "clarky",
         "--rpm", "5000", "--J", "0.6:1:0.1"]


def _parsers(parser, prog="mdo"):
    yield prog, parser
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from _parsers(sub, f"{prog} {name}")


def test_negative_numbers_in_ranges_and_values(capsys):
    assert main(WAKE + ["--y", "-1:1:0.25", "--x", "-1e-1", "--z", "-.5"]) == 0
    rows = capsys.readouterr().out.strip().splitlines()[1:]
    y = np.array([float(r.split(",")[0]) for r in rows])
    np.testing.assert_allclose(y, np.arange(-1, 1.01, 0.25))
    assert main(SWEEP + ["--pitch-offset", "-2.5e0"]) == 0
    capsys.readouterr()
    assert main(["airfoil", "polar", "clarky", "--re", "1e6", "--alpha", "-1e1", "-5", "5"]) == 0
    assert capsys.readouterr().out.count("\n") == 2 + 2


def test_every_option_has_help_without_markup():
    missing, markup = [], []
    for prog, parser in _parsers(build_parser()):
        texts = [parser.description or ""]
        for a in parser._actions:
            if isinstance(a, (argparse._HelpAction, argparse._SubParsersAction)):
                continue
            if not a.help:
                missing.append(f"{prog} {'/'.join(a.option_strings) or a.dest}")
            texts.append(a.help or "")
        for t in texts:
            if "``" in t or ":math:" in t or ":func:" in t or ":class:" in t:   # RST markup
                markup.append(f"{prog}: {t[:60]}")
    assert not missing, missing
    assert not markup, markup


def test_one_airfoil_resolver(capsys, tmp_path):
    wing = ["wing", "--span", "10", "--root-chord", "1", "--taper", "0.5", "--alpha", "2"]
    bodies = []
    for argv in (wing + ["--airfoil", "naca2412"], ["airfoil", "polar", "naca2412", "--re", "1e6"],
                 SWEEP[:9] + ["naca2412"] + SWEEP[10:], ["airfoil", "check", "naca2412"]):
        assert main(argv) == 2, argv
        err = capsys.readouterr().err.strip()
        assert err.count("\n") == 0
        bodies.append(err.split(": ", 3)[-1])
    assert len(set(bodies)) == 1, bodies
    assert bodies[0] == "unknown airfoil 'naca2412'; available: clarky, e63, naca0015, naca4412, naca63412"
    # and the same spellings are accepted everywhere
    assert main(wing + ["--airfoil", "NACA 4412"]) == 0
    assert main(["airfoil", "polar", "NACA-4412", "--re", "1e6", "--alpha", "0", "1", "1"]) == 0
    assert main(SWEEP[:9] + ["naca_4412"] + SWEEP[10:]) == 0


def test_version():
    from mdo import __version__
    r = subprocess.run([sys.executable, "-m", "mdo.cli", "--version"], capture_output=True, text=True)
    assert r.returncode == 0 and r.stdout.strip() == f"mdo {__version__}"


@pytest.mark.parametrize("argv", [["airfoil", "list"], SWEEP[:-1] + ["0:1:0.001"]])
def test_closed_pipe_is_quiet(argv):
    # the reader is gone before mdo writes (it needs ~1 s to start): the write fails with EPIPE
    p = subprocess.Popen([sys.executable, "-m", "mdo.cli", *argv], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE)
    p.stdout.close()
    err = p.stderr.read().decode()
    assert p.wait(timeout=120) == 141
    assert "Traceback" not in err and "BrokenPipe" not in err and "Exception ignored" not in err, err


@pytest.mark.parametrize("argv", [SWEEP, WAKE + ["--y", "0:1:0.5"], ["battery", "discharge", "--current", "2"],
                                  ["rotor", "design", "--diameter", "1.94", "--blades", "3", "--speed", "60",
                                   "--thrust", "900", "--tip-mach", "0.6"]])
def test_out_never_overwrites_unasked(argv, tmp_path, capsys):
    out = tmp_path / "o.csv"
    out.write_text("keep me\n")
    assert main(argv + ["--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "already exists" in err and "--force" in err and err.count("\n") == 1
    assert out.read_text() == "keep me\n"
    # a symbolic link is never written through, even with --force
    target = tmp_path / "target.csv"
    target.write_text("committed\n")
    link = tmp_path / "link.csv"
    link.symlink_to(target)
    assert main(argv + ["--out", str(link), "--force"]) == 2
    assert "symbolic link" in capsys.readouterr().err and target.read_text() == "committed\n"
    # --force replaces the file, through a temporary sibling (none left behind)
    assert main(argv + ["--out", str(out), "--force"]) == 0
    assert out.read_text() != "keep me\n" and out.read_text().count("\n") > 2
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.csv", "o.csv", "target.csv"]


def test_report_folders_keep_existing_files(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    # battery report: the default is under the current folder, not the repository's results
    args = build_parser().parse_args(["battery", "report"])
    assert args.out == "battery_report" and not Path(args.out).is_absolute()
    (tmp_path / "battery_report").mkdir()
    (tmp_path / "battery_report" / "balance.md").write_text("mine\n")
    assert main(["battery", "report"]) == 2
    assert "balance.md already exists" in capsys.readouterr().err
    assert sorted(os.listdir(tmp_path / "battery_report")) == ["balance.md"]
    # airfoil plot: every figure checked before the first is drawn
    (tmp_path / "figs").mkdir()
    (tmp_path / "figs" / "naca4412.png").write_text("mine\n")
    assert main(["airfoil", "plot", "--all", "--out", "figs"]) == 2
    assert "naca4412.png already exists" in capsys.readouterr().err
    assert os.listdir(tmp_path / "figs") == ["naca4412.png"]


def test_run_options_lists_the_problem_options(capsys):
    assert main(["run", str(ROOT / "problems" / "ga2p.py"), "--options"]) == 0
    out = capsys.readouterr().out
    assert out.startswith(f"{ROOT / 'problems' / 'ga2p.py'}: GA-2P")
    assert "wing_strips (int, default 24): an integer in [8, 60]" in out
    assert "coupling (str, default 'swirl'): one of swirl, local, freestream" in out
    assert "how the wake enters the wing forces" in out          # from the module docstring
    assert "analysis (" not in out                               # set by --analysis, not -o
    assert main(["run", str(ROOT / "problems" / "table3.py"), "--options"]) == 2
    assert "no function build" in capsys.readouterr().err


def test_sweep_efficiency_undefined_where_thrust_or_power_not_positive(capsys, tmp_path):
    from mdo.rotor.cli import sweep_table
    out = tmp_path / "s.csv"
    assert main(SWEEP + ["--out", str(out)]) == 0
    rows = [r.split(",") for r in out.read_text().strip().splitlines()[1:]]
    T = np.array([float(r[4]) for r in rows])
    P = np.array([float(r[5]) for r in rows])
    eta = [r[3] for r in rows]
    assert (T <= 0).any() and (T > 0).any()           # the sweep crosses zero thrust (J ~ 0.8)
    for t, p, e in zip(T, P, eta):
        if t > 0 and p > 0:
            assert 0 < float(e) < 1
        else:
            assert e == ""                              # was 1.74 / -0.12
    res = {"CT": [0.1, -0.1], "CP": [0.05, 0.01], "eta": [0.7, 1.98], "thrust_N": [3.0, -1.0],
           "power_W": [30.0, 5.0], "torque_Nm": [0.06, 0.01]}
    table = sweep_table(np.array([0.5, 0.9]), res, human=True).splitlines()
    assert table[1].split()[3] == "0.7" and table[2].split()[3] == "\u2014"
