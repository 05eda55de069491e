"""The NLP harness end to end on a genuine small problem with a known answer."""
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from mdo.nlp import Problem, SolveError, load_problem_file, run_problem
from mdo.nlp.run import RunError

HERE = Path(__file__).parent
BRACH = HERE / "problems" / "brachistochrone.py"


def _mdo(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "mdo.cli", *map(str, args)], capture_output=True,
                          text=True, cwd=cwd)


def test_brachistochrone_minimum_time(tmp_path):
    prob = load_problem_file(BRACH)
    sol = run_problem(prob, tmp_path / "run", verbose=False)
    assert sol.success, sol.status
    assert sol["final_time"] == pytest.approx(1.8016, abs=2e-4)
    for f in ("ipopt.log", "solution.json", "summary.json", "summary.md", "convergence.csv"):
        assert (tmp_path / "run" / f).exists(), f
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert summary["status"] == "Solve_Succeeded"
    assert summary["objective"]["unit"] == "s"
    assert summary["iterations"] == sol.iterations > 0
    assert summary["nlp_size"]["variables"] == 1 + 4 * 20
    assert summary["nlp_size"]["jacobian_nnz"] > 0
    assert "Ipopt" in (tmp_path / "run" / "ipopt.log").read_text()
    # bounds and single-variable boundary conditions went to IPOPT as variable bounds
    assert summary["nlp_size"]["constraints_ipopt"] == 3 * 20
    names = {v["name"]: v for v in json.loads((tmp_path / "run" / "solution.json").read_text())["variables"]}
    assert names["x"]["unit"] == "m" and len(names["x"]["value"]) == 20


def test_warm_start_converges_faster(tmp_path):
    sol = run_problem(load_problem_file(BRACH), tmp_path / "a", verbose=False)
    prob = load_problem_file(BRACH)
    sol2 = run_problem(prob, tmp_path / "b", verbose=False, warm_start=tmp_path / "a" / "solution.json")
    assert sol2.success and sol2.iterations < sol.iterations
    assert sol2["final_time"] == pytest.approx(sol["final_time"], rel=1e-6)


def test_analysis_freezes_design(tmp_path):
    prob = load_problem_file(BRACH, analysis=True)
    sol = prob.solve(verbose=False)
    assert sol.analysis
    assert sol["final_time"] == pytest.approx(2.0)  # held at its initial value


def test_infeasible_reports_groups(tmp_path):
    # the bead cannot rise above its start height with zero initial speed
    prob = load_problem_file(BRACH, options={"final_y": 12.0})
    with pytest.raises(SolveError) as err:
        prob.solve(verbose=False, max_iter=200, raise_on_failure=True)
    sol = err.value.solution
    assert not sol.success
    worst = sol.violations[0]
    assert worst["scaled"] > 1e-3
    assert worst["group"] in ("end", "y_dynamics", "v_dynamics", "x_dynamics", "start")
    assert "worst-violated" in sol.violation_report()


def test_variable_bounds_and_names_checked():
    p = Problem("t")
    p.variable("a", lower=0, upper=1)
    with pytest.raises(ValueError, match="already defined"):
        p.variable("a")
    with pytest.raises(ValueError, match="lower 2 > upper 1"):
        p.variable("b", lower=2, upper=1)
    with pytest.raises(ValueError, match="scale"):
        p.variable("c", scale=0)


def test_cli_run_writes_results_and_refuses_overwrite(tmp_path):
    out = tmp_path / "brach"
    r = _mdo("run", BRACH, "--out", out, "--quiet")
    assert r.returncode == 0, r.stderr
    assert "Solve_Succeeded" in r.stdout
    s = json.loads((out / "summary.json").read_text())
    assert s["final_time_s"] == pytest.approx(1.8016, abs=2e-4)
    before = (out / "summary.json").read_text()
    r = _mdo("run", BRACH, "--out", out, "--quiet")
    assert r.returncode == 2 and "--force" in r.stderr
    assert (out / "summary.json").read_text() == before
    r = _mdo("run", BRACH, "--out", out, "--quiet", "--force", "--max-iter", "3")
    assert r.returncode == 1
    assert "did not converge" in r.stderr and "worst-violated" in r.stderr
    assert (out / "ipopt.log").exists()


@pytest.mark.parametrize("content,needle", [
    (None, "does not exist"),
    ("import nonexistent_module_xyz\n", "failed to import"),
    ("x = 1\n", "no function build"),
    ("def build(**o):\n    return 42\n", "returned int"),
    ("def build():\n    raise ValueError('boom')\n", "build() failed"),
])
def test_cli_bad_problem_file_exit_2(tmp_path, content, needle):
    f = tmp_path / "p.py"
    if content is not None:
        f.write_text(content)
    r = _mdo("run", f, "--out", tmp_path / "out")
    assert r.returncode == 2
    assert needle in r.stderr
    assert "Traceback" not in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "out" / "summary.json").exists()


def test_cli_debug_shows_traceback(tmp_path):
    f = tmp_path / "p.py"
    f.write_text("x = 1\n")
    r = _mdo("--debug", "run", f, "--out", tmp_path / "out")
    assert r.returncode == 2 and "Traceback" in r.stderr


def test_design_level_limit_binds_an_optimization_and_is_lifted_for_a_frozen_design():
    # min (x - 1)^2 + y^2 with a design-level limit x >= 2 and a node-like limit y >= 0.5
    def build():
        p = Problem("design_level")
        x = p.variable("x", init=1.0, lower=-10, upper=10, design=True)
        y = p.variable("y", init=1.0, lower=-10, upper=10)
        p.constrain("clearance", x, kind=">=", rhs=2.0, design_level=True)
        p.constrain("y limit", y, kind=">=", rhs=0.5)
        p.minimize((x - 1.0) ** 2 + y ** 2)
        return p, x, y
    p, x, _ = build()
    opt = p.solve(verbose=False)
    assert opt.success and float(opt.value(x)) == pytest.approx(2.0, abs=1e-6)
    frozen, x, y = build()
    frozen.freeze_design()
    sol = frozen.solve(verbose=False)
    # the given design flies as it is (x stays 1); its violation of the limit is reported, the other limit holds
    assert sol.success and float(sol.value(x)) == pytest.approx(1.0) and float(sol.value(y)) == pytest.approx(0.5, abs=1e-6)
    worst = {v["group"]: v for v in sol.violations}
    assert worst["clearance"]["max_violation"] == pytest.approx(1.0, abs=1e-6)
    assert worst["y limit"]["max_violation"] < 1e-6
    with pytest.raises(Exception, match="design_level"):
        build()[0].constrain("bad", x, kind="==", design_level=True)
