"""Bad input at the edges: one line naming the field and the allowed range, exit 2,
nothing written; failures that explain themselves (issue 11)."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
APC = ROOT / "mdo" / "rotor" / "data" / "apce_10x7_geometry.csv"
PROBLEMS = Path(__file__).parent / "problems"


def mdo(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "mdo.cli", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd)


def sweep(*extra, geometry=APC):
    base = ["rotor", "sweep", "--geometry", geometry, "--diameter", "0.254", "--blades", "2",
            "--airfoil", "clarky", "--rpm", "5000", "--J", "0:0.5:0.1"]
    args = list(base)
    for k, v in zip(extra[::2], extra[1::2]):
        if k in args:
            args[args.index(k) + 1] = v
        else:
            args += [k, v]
    return args


def _csv(tmp_path, text):
    f = tmp_path / "blade.csv"
    f.write_text(text)
    return f


CASES = {
    "negative chord": (lambda t: sweep(geometry=_csv(t, "r_over_R,c_over_R,beta_deg\n0.2,-0.1,30\n0.6,0.1,20\n1.0,0.05,10\n")),
                       ["c_over_R", "> 0"]),
    "zero diameter": (lambda t: sweep("--diameter", "0"), ["--diameter", "(0, 100] m"]),
    "negative span": (lambda t: ["wing", "--span", "-3", "--root-chord", "1", "--taper", "0.5", "--alpha", "2"],
                      ["--span", "[0.01, 1000] m"]),
    "zero chord (wing)": (lambda t: ["wing", "--span", "10", "--root-chord", "0", "--taper", "0.5", "--alpha", "2"],
                          ["--root-chord", "[0.001, 100] m"]),
    "hub >= tip": (lambda t: sweep("--hub-fraction", "1.2"), ["hub", "(0, 1)"]),
    "tip Mach >= 1": (lambda t: sweep("--rpm", "90000"), ["tip Mach", "< 1"]),
    "altitude above the model": (lambda t: sweep("--altitude", "30000"), ["altitude", "[0, 20000] m"]),
    "altitude below the model": (lambda t: sweep("--altitude", "-100"), ["altitude", "[0, 20000] m"]),
    "unknown airfoil": (lambda t: sweep("--airfoil", "nosuchfoil"), ["airfoil", "available"]),
    "malformed CSV": (lambda t: sweep(geometry=_csv(t, "a,b\n1,2\n")), ["--geometry", "r_over_R,c_over_R,beta_deg"]),
    "not a CSV of numbers": (lambda t: sweep(geometry=_csv(t, "r_over_R,c_over_R,beta_deg\n0.2,x,30\n")),
                             ["--geometry"]),
    "overlapping rotors": (lambda t: ["run", PROBLEMS / "overlapping_rotors.py"], ["span_eta", "overlap", "R1 + R2"]),
    "negative current": (lambda t: ["battery", "discharge", "--current", "-3"], ["--current", "(0, 12] A"]),
    "wing Mach >= 1": (lambda t: ["wing", "--span", "10", "--root-chord", "1", "--taper", "0.5", "--alpha", "2",
                                  "--mach", "1.2"], ["mach"]),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_bad_input_one_line_exit_2_nothing_written(tmp_path, case):
    make_args, needles = CASES[case]
    out = tmp_path / "out.csv"
    args = list(make_args(tmp_path))
    if args[0] == "rotor":
        args += ["--out", out]
    elif args[0] == "run":
        args += ["--out", tmp_path / "run"]
    r = mdo(*args, cwd=tmp_path)
    assert r.returncode == 2, (case, r.stdout, r.stderr)
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("mdo: error:"), r.stderr
    for n in needles:
        assert n.lower() in lines[0].lower(), (case, lines[0])
    assert not out.exists() and not (tmp_path / "run" / "summary.json").exists()


def test_infeasible_mission_explains_itself(tmp_path):
    out = tmp_path / "run"
    r = mdo("run", PROBLEMS / "small_battery.py", "--out", out, "--quiet", "--max-iter", "150")
    assert r.returncode == 1, r.stderr
    assert "did not converge" in r.stderr and "worst-violated constraint groups" in r.stderr
    # the report names groups and the node/segment where they are violated
    assert " node " in r.stderr
    assert (out / "ipopt.log").exists() and (out / "solution.json").exists()
    summary = json.loads((out / "summary.json").read_text())
    assert summary["success"] is False and summary["worst_violations"][0]["scaled"] > 1e-4


def test_nan_names_the_block(tmp_path):
    r = mdo("run", PROBLEMS / "nan_model.py", "--out", tmp_path / "run", "--quiet")
    assert r.returncode == 1
    assert "NaN/Inf" in r.stderr and "rotor model" in r.stderr and "CR node 3" in r.stderr
