"""Warm starts check what they load (#19 item 3) and a converged point re-converges in
at most 2 iterations with its multipliers (#23 item 4)."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

from mdo.nlp import load_problem_file, run_problem
from mdo.nlp.problem import WarmStartError

HERE = Path(__file__).parent
ROOT = HERE.parent
BRACH = HERE / "problems" / "brachistochrone.py"
POLAR = ROOT / "problems" / "polar_ga_mission.py"


def _mdo(*args):
    return subprocess.run([sys.executable, "-m", "mdo.cli", *map(str, args)], capture_output=True, text=True)


@pytest.fixture(scope="module")
def brach_solution(tmp_path_factory):
    out = tmp_path_factory.mktemp("ws") / "brach"
    sol = run_problem(load_problem_file(BRACH), out, verbose=False)
    assert sol.success
    return out / "solution.json", sol


def _refused(r, tmp_path, *needles):
    assert r.returncode == 2, r.stderr
    line = r.stderr.strip()
    assert len(line.splitlines()) == 1 and "Traceback" not in line, r.stderr
    for n in needles:
        assert n in line, line
    assert not (tmp_path / "new").exists()   # nothing created before the file was validated


def test_other_problem_refused(tmp_path, brach_solution):
    r = _mdo("run", HERE / "problems" / "small_battery.py", "--warm-start", brach_solution[0],
             "--out", tmp_path / "new" / "run", "--quiet")
    _refused(r, tmp_path, "written by problem 'brachistochrone', this is 'small_battery'", "0 of ")


def test_size_mismatch_refused_unless_partial(tmp_path, brach_solution):
    r = _mdo("run", BRACH, "-o", "nodes=10", "--warm-start", brach_solution[0], "--out", tmp_path / "new" / "run",
             "--quiet")
    _refused(r, tmp_path, "1 of 5 variables match", "'x' has 20 values, expected 10", "partial")
    r = _mdo("run", BRACH, "-o", "nodes=10", "--warm-start", brach_solution[0], "--warm-start-partial",
             "--out", tmp_path / "part", "--quiet")
    assert r.returncode == 0, r.stderr
    assert "1 of 5 variables match" in r.stdout and "multipliers" not in r.stdout


def test_non_finite_and_unreadable_files_refused(tmp_path, brach_solution):
    data = json.loads(brach_solution[0].read_text())
    data["variables"][1]["value"][3] = [float("nan")]
    bad = tmp_path / "nan.json"
    bad.write_text(json.dumps(data))
    r = _mdo("run", BRACH, "--warm-start", bad, "--out", tmp_path / "new" / "run", "--quiet")
    _refused(r, tmp_path, "non-finite", "4 of 5 variables match")
    for name, text, needle in (("junk.json", "{not json", "invalid JSON"), ("list.json", "[1, 2]", "no 'variables'"),
                               ("missing.json", None, "cannot read")):
        f = tmp_path / name
        if text is not None:
            f.write_text(text)
        r = _mdo("run", BRACH, "--warm-start", f, "--out", tmp_path / "new" / "run", "--quiet")
        _refused(r, tmp_path, needle, str(f))


def test_api_refuses_and_reports(brach_solution):
    p = load_problem_file(BRACH, options={"nodes": 12})
    with pytest.raises(WarmStartError, match="1 of 5 variables match"):
        p.warm_start(brach_solution[0])
    ws = p.warm_start(brach_solution[0], partial=True)
    assert len(ws) == 1 and ws.total == 5 and not ws.complete and not ws.multipliers


def test_warm_start_from_a_converged_point_takes_at_most_2_iterations(tmp_path, brach_solution):
    path, cold = brach_solution
    r = _mdo("run", BRACH, "--warm-start", path, "--out", tmp_path / "warm", "--quiet")
    assert r.returncode == 0, r.stderr
    assert "5 of 5 variables match; multipliers loaded" in r.stdout
    warm = json.loads((tmp_path / "warm" / "summary.json").read_text())
    assert warm["status"] == "Solve_Succeeded" and warm["iterations"] <= 2 < cold.iterations
    assert warm["objective"]["value"] == pytest.approx(cold.objective, rel=1e-7)


def test_polar_mission_warm_start_at_most_2_iterations(tmp_path):
    opts = {"design_wing_area": True}
    cold = run_problem(load_problem_file(POLAR, options=opts), tmp_path / "cold", verbose=False)
    assert cold.success
    p = load_problem_file(POLAR, options=opts)
    warm = run_problem(p, tmp_path / "warm", verbose=False, warm_start=tmp_path / "cold" / "solution.json")
    assert warm.success and warm.iterations <= 2 < cold.iterations
    assert warm["battery_energy_kWh"] == pytest.approx(cold["battery_energy_kWh"], rel=1e-6)
