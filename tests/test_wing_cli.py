"""``mdo wing``: output, JSON keys, input checks (exit 2)."""
import json
import math

import pytest

from mdo.cli import main
from mdo.wing.cli import run_wing

BASE = ["wing", "--span", "11.4", "--root-chord", "1.5", "--taper", "0.7", "--alpha", "3", "--nspan", "8"]


def test_text_output(capsys):
    assert main(BASE) == 0
    out = capsys.readouterr().out
    assert "CL  =" in out and "CDi =" in out and "e   =" in out


def test_json_output(capsys):
    assert main(BASE + ["--json", "--airfoil", "naca4412", "--mach", "0.25", "--sweep", "5",
                        "--dihedral", "3", "--twist-root", "2", "--twist-tip", "-1", "--nchord", "3"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert set(d) == {"CL", "CDi", "e", "y", "cl"}
    assert len(d["y"]) == len(d["cl"]) == 8
    assert 0.5 < d["CL"] < 0.9 and 0.9 < d["e"] < 1.0
    assert all(0 < y < 5.7 for y in d["y"])


def test_run_wing_matches_lift_slope():
    a = run_wing(10.0, 1.0, 1.0, 0.0, nspan=12, nchord=2)
    b = run_wing(10.0, 1.0, 1.0, 2.0, nspan=12, nchord=2)
    assert a["CL"] == pytest.approx(0.0, abs=1e-12)
    assert 4.0 < b["CL"] / math.radians(2.0) < 5.0


@pytest.mark.parametrize("args, field", [
    (["--span", "0"], "--span"), (["--span", "-3"], "--span"), (["--root-chord", "0"], "--root-chord"),
    (["--root-chord", "-1"], "--root-chord"), (["--taper", "0"], "--taper"), (["--taper", "-0.5"], "--taper"),
    (["--taper", "2.5"], "--taper"), (["--mach", "1.0"], "--mach"), (["--mach", "1.5"], "--mach"),
    (["--airfoil", "nope"], "--airfoil"), (["--nspan", "0"], "--nspan"), (["--alpha", "60"], "--alpha"),
])
def test_input_errors_exit_2(args, field, capsys):
    argv = ["wing", "--span", "10", "--root-chord", "1", "--taper", "0.5", "--alpha", "2"]
    for k in range(0, len(args), 2):
        if args[k] in argv:
            argv[argv.index(args[k]) + 1] = args[k + 1]
        else:
            argv += args[k:k + 2]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert field in err and err.count("\n") == 1
