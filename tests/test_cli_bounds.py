"""Bounded inputs everywhere (issue 19 item 4): every number a command or a problem option
takes has a type and a finite range; a bad one is one line naming the field and the
range, exit 2, nothing written; results that are not finite are never printed."""
import math
from pathlib import Path

import numpy as np
import pytest

from mdo.cli import main
from mdo.core.errors import InputError, check_finite_result, parse_float, parse_grid, parse_int

ROOT = Path(__file__).resolve().parents[1]
APC = ROOT / "mdo" / "rotor" / "data" / "apce_10x7_geometry.csv"
GA2P = ROOT / "problems" / "ga2p.py"
POLAR = ROOT / "problems" / "polar_ga_mission.py"
WAKE = ["wake", "velocity", "--radius", "1", "--blades", "3", "--thrust-gamma", "2", "--rpm", "2000",
        "--v-wake", "60"]
SWEEP = ["rotor", "sweep", "--geometry", str(APC), "--diameter", "0.254", "--blades", "2", "--airfoil", "clarky",
         "--rpm", "5000", "--J", "0:0.5:0.1"]
WING = ["wing", "--span", "10", "--root-chord", "1", "--taper", "0.5", "--alpha", "2"]


def _huge_chord(tmp_path):
    f = tmp_path / "g.csv"
    f.write_text("r_over_R,c_over_R,beta_deg\n0.2,1e300,30\n0.6,0.1,20\n1.0,0.05,10\n")
    return str(f)


# argv (a function of tmp_path), then what the one error line must contain
CASES = {
    "wake rotations 1e9": (lambda t: WAKE + ["--model", "full", "--rotations", "1e9"],
                           ["--rotations: a number in (0, 100], got '1e9'"]),
    "wake full too big": (lambda t: WAKE + ["--model", "full", "--rotations", "100", "--phases", "36",
                                            "--y", "-2:2:0.001"], ["--rotations", "filament segments", "2e+07"]),
    "wake phases 2.5": (lambda t: WAKE + ["--model", "full", "--phases", "2.5"], ["--phases: an integer in [1, 36]"]),
    "wake y too many": (lambda t: WAKE + ["--y", "0:1:1e-9"], ["--y", "at most 20000"]),
    "wake spin 2": (lambda t: WAKE + ["--spin", "2"], ["--spin: one of 1, -1"]),
    "wake model": (lambda t: WAKE + ["--model", "exact"], ["--model: one of mean, full"]),
    "wake core": (lambda t: WAKE + ["--core-rel", "0.07"], ["--core-rel: one of 0.05, 0.1"]),
    "wake gamma nan": (lambda t: ["wake", "velocity", "--radius", "1", "--blades", "3", "--gamma", "1,nan",
                                  "--rpm", "2000", "--v-wake", "60"], ["--gamma: a number in [-10000, 10000] m^2/s"]),
    "battery points 1e12": (lambda t: ["battery", "discharge", "--current", "2", "--points", "1e12"],
                            ["--points: an integer in [2, 100000], got '1e12'"]),
    "battery cells 1e9": (lambda t: ["battery", "discharge", "--current", "2", "--cells-series", "1000000000"],
                          ["--cells-series: an integer in [1, 10000]"]),
    "battery current inf": (lambda t: ["battery", "discharge", "--current", "inf"], ["--current: a number in (0, 12]"]),
    "motor power nan": (lambda t: ["motor", "size", "--power-kw", "nan", "--rpm", "2000", "--voltage", "400"],
                        ["--power-kw: a number in (0, 10000] kW"]),
    "rotor chord 1e300": (lambda t: SWEEP[:3] + [_huge_chord(t)] + SWEEP[4:], ["c_over_R", "(0, 1]"]),
    "rotor J huge": (lambda t: SWEEP[:-1] + ["0:1e300:1e299"], ["--J", "[0, 10]"]),
    "rotor blades 2.5": (lambda t: SWEEP[:7] + ["2.5"] + SWEEP[8:], ["--blades: an integer in [1, 20]"]),
    "rotor rpm text": (lambda t: SWEEP[:11] + ["fast"] + SWEEP[12:], ["--rpm: a number in (0, 1e+06] rpm, got 'fast'"]),
    "rotor design cl": (lambda t: ["rotor", "design", "--diameter", "2", "--blades", "3", "--speed", "50",
                                   "--thrust", "900", "--tip-mach", "0.6", "--cl", "5"], ["--cl: a number in [0.05, 2]"]),
    "wing span 1e300": (lambda t: ["wing", "--span", "1e300", "--root-chord", "1", "--taper", "0.5", "--alpha", "2",
                                   "--json"], ["--span: a number in [0.01, 1000] m, got '1e300'"]),
    "wing nspan 2.5": (lambda t: WING + ["--nspan", "2.5"], ["--nspan: an integer in [1, 200]"]),
    "wing sweep nan": (lambda t: WING + ["--sweep", "nan"], ["--sweep: a number in (-80, 80) deg"]),
    "run max-iter": (lambda t: ["run", str(GA2P), "--max-iter", "1e12", "--out", str(t / "run")],
                     ["--max-iter: an integer in [0, 100000], got '1e12'"]),
    "airfoil re 1e300": (lambda t: ["airfoil", "polar", "clarky", "--re", "1e300"],
                         ["--re: a number in [10000, 1e+08], got '1e300'"]),
    "airfoil alpha step 0": (lambda t: ["airfoil", "polar", "clarky", "--re", "1e6", "--alpha", "0", "10", "0"],
                             ["--alpha", "(0, 360] deg"]),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_bad_number_one_line_exit_2(case, tmp_path, capsys):
    argv, needles = CASES[case]
    argv = list(argv(tmp_path))
    out = tmp_path / "out.csv"
    if argv[0] in ("rotor", "wake") or argv[:2] == ["battery", "discharge"]:
        argv += ["--out", str(out)]
    assert main(argv) == 2, case
    cap = capsys.readouterr()
    lines = cap.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("mdo: error: "), cap.err
    for n in needles:
        assert n in lines[0], (case, lines[0])
    assert cap.out == "" and not out.exists()


# problem options: each class of bad -o value, checked before anything is built
OPTION_CASES = {
    "nodes=abc": (GA2P, "nodes: an integer in [3, 30], got 'abc'"),
    "wing_strips=100000": (GA2P, "wing_strips: an integer in [8, 60], got 100000"),
    "wake_samples=2.5": (GA2P, "wake_samples: an integer in [1, 15], got 2.5"),
    "wake_core_rel=0.3": (GA2P, "wake_core_rel: a number in [0.05, 0.1], got 0.3"),
    "wake_core_rel=0.07": (GA2P, "wake_core_rel: one of 0.05, 0.1 (the mean-wake tables that ship), got 0.07"),
    "cruise_distance_nmi=NaN": (GA2P, "cruise_distance_nmi: a number in [1, 300], got 'NaN'"),
    "cruise_distance_nmi=1e300": (GA2P, "cruise_distance_nmi: a number in [1, 300], got 1e+300"),
    "coupling=wakeless": (GA2P, "coupling: one of swirl, local, freestream, got 'wakeless'"),
    "engine_out=differential": (GA2P, "engine_out: one of rudder, off, got 'differential'"),
    "wing_strip=30": (GA2P, "wing_strip: unknown option of ga2p.py; allowed: nodes, cruise_distance_nmi"),
    "design_wing_area=3": (POLAR, "design_wing_area: true or false, got 3"),
    "state_form=1": (POLAR, "state_form: one of differentiation, integration, got 1"),
}


@pytest.mark.parametrize("option", sorted(OPTION_CASES))
def test_bad_problem_option_one_line_exit_2(option, tmp_path, capsys):
    problem, needle = OPTION_CASES[option]
    out = tmp_path / "run"
    assert main(["run", str(problem), "-o", option, "--out", str(out), "--quiet"]) == 2
    cap = capsys.readouterr()
    lines = cap.err.strip().splitlines()
    assert len(lines) == 1 and needle in lines[0], cap.err
    assert not (out / "summary.json").exists()


def _problem(tmp_path, body: str) -> Path:
    f = tmp_path / "p.py"
    f.write_text(body)
    return f


@pytest.mark.parametrize("body, needle", [
    ("import sys\nsys.exit(0)\n", "called sys.exit(0) while being imported"),
    ("import sys\ndef build():\n    sys.exit(0)\n", "build() called sys.exit(0)"),
    ("def build():\n    pass\n", "build() returned nothing (None)"),
    ("OPTIONS = {'n': (int, 5, 1)}\ndef build(n: int = 3):\n    pass\n", "OPTIONS['n']"),
    ("OPTIONS = {'n': (float, 0, 1)}\ndef build(n: int = 3):\n    pass\n", "OPTIONS['n']"),
    ("OPTIONS = {'m': (int, 0, 1)}\ndef build(n: int = 3):\n    pass\n", "does not take"),
])
def test_problem_file_that_exits_or_returns_nothing(body, needle, tmp_path, capsys):
    f = _problem(tmp_path, body)
    assert main(["run", str(f), "--out", str(tmp_path / "run"), "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and needle in err[0], err


def test_declared_options_are_converted_and_passed(tmp_path):
    from mdo.nlp.run import load_problem_file
    f = _problem(tmp_path, "OPTIONS = {'n': (int, 1, 9), 'x': (float, 0, 2)}\n"
                           "SEEN = {}\n"
                           "def build(n: int = 3, x: float = 1.0, flag=False):\n"
                           "    SEEN.update(n=n, x=x, flag=flag)\n")
    with pytest.raises(Exception, match="returned nothing"):
        load_problem_file(f, options={"n": 4, "x": 1, "flag": True})
    import sys
    seen = [m for k, m in sys.modules.items() if k.startswith("mdo_problem_p")][-1].SEEN
    assert seen == {"n": 4, "x": 1.0, "flag": True} and isinstance(seen["x"], float)
    with pytest.raises(InputError, match=r"x: a number in \[0, 2\], got 3"):
        load_problem_file(f, options={"x": 3})


def test_parsers_name_field_and_range():
    assert parse_int("--n", "7", 1, 9) == 7 and parse_int("--n", 7.0, 1, 9) == 7
    for bad in ("2.5", "1e3", "x", True, 2.5, "10"):
        with pytest.raises(InputError, match=r"^--n: an integer in \[1, 9\], got"):
            parse_int("--n", bad, 1, 9)
    assert parse_float("--v", "-1.5e0", -2, 2, "m/s") == -1.5
    for bad in ("nan", "inf", "-inf", "1e400", "3", "", None):
        with pytest.raises(InputError, match=r"^--v: a number in \[-2, 2\] m/s, got"):
            parse_float("--v", bad, -2, 2, "m/s")
    with pytest.raises(InputError, match=r"\(0, 1\)"):
        parse_float("--f", "0", 0, 1, lower_open=True, upper_open=True)
    y = parse_grid("--y", "-1:1:0.25", -10, 10, 100)
    assert y.size == 9 and y[0] == -1.0 and math.isclose(y[-1], 1.0)
    with pytest.raises(InputError, match=r"1001 points is too many \(at most 100\)"):
        parse_grid("--y", "0:1:0.001", -10, 10, 100)


def test_non_finite_results_are_refused():
    check_finite_result("--x", a=[1.0, 2.0])
    with pytest.raises(InputError, match="non-finite b"):
        check_finite_result("--x", a=[1.0], b=np.array([1.0, np.nan]))
