"""`mdo check RUN_DIR` (#16 item 6) and what limits the design (#16 item 5)."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

from mdo.nlp import Problem, run_problem
from mdo.nlp.check import check_run

HERE = Path(__file__).parent

LIMITED = """
import casadi as ca
from mdo.nlp import Problem

def build(analysis=False):
    # minimize (x - 20)^2 + y0^2 + y1^2 with x <= 10 m (a design bound) and y >= 0.5 rad (a group):
    # d objective / d x_max = 2 (10 - 20) -> 20 m^2 per m; d objective / d y_min = 2 * 0.5 -> 1 m^2 per rad
    p = Problem("limited")
    x = p.variable("x", unit="m", scale=10, lower=0, upper=10, init=5, design=True)
    y = p.variable("y", 3, unit="rad", scale=2, lower=-1, upper=1, init=0, labels=["a", "b", "c"])
    p.constrain("y_floor", y[:2], kind=">=", rhs=0.5, scale=3, unit="rad", labels=["a", "b"])
    p.constrain("cap", x + y[0], kind="<=", rhs=12, scale=0.5, unit="m", labels=["total"])
    p.constrain("pin", y[2] - 0.25, scale=1, unit="rad", labels=["c"])
    p.minimize((x - 20) ** 2 + y[0] ** 2 + y[1] ** 2, unit="m^2", scale=100)
    return p
"""


def _mdo(*args):
    return subprocess.run([sys.executable, "-m", "mdo.cli", *map(str, args)], capture_output=True, text=True)


@pytest.fixture(scope="module")
def good(tmp_path_factory):
    base = tmp_path_factory.mktemp("check")
    f = base / "limited.py"
    f.write_text(LIMITED)
    r = _mdo("run", f, "--out", base / "run", "--quiet", "--no-baseline")
    assert r.returncode == 0, r.stderr
    return base / "run"


def _edit(src, dst, fn):
    import shutil
    shutil.copytree(src, dst)
    data = json.loads((dst / "solution.json").read_text())
    fn(data)
    (dst / "solution.json").write_text(json.dumps(data))
    return dst


def test_active_limits_with_multipliers(good):
    s = json.loads((good / "summary.json").read_text())
    active = {(a["name"], a["where"]): a for a in s["active"]}
    assert set(active) == {("x", "upper bound 10 m"), ("y_floor", "a"), ("y_floor", "b")}
    assert active[("x", "upper bound 10 m")]["multiplier"] == pytest.approx(20.0, rel=1e-4)
    assert active[("x", "upper bound 10 m")]["unit"] == "m^2 per m" and active[("x", "upper bound 10 m")]["kind"] == "bound"
    assert active[("y_floor", "a")]["multiplier"] == pytest.approx(1.0, rel=1e-3)
    assert active[("y_floor", "a")]["unit"] == "m^2 per rad"
    md = (good / "summary.md").read_text()
    assert "## What limits the design" in md and "| x | bound | upper bound 10 m | 20 | m^2 per m |" in md
    sol = json.loads((good / "solution.json").read_text())
    g = {c["name"]: c for c in sol["constraints"]}
    assert g["y_floor"]["kind"] == ">=" and g["y_floor"]["rhs"] == 0.5 and g["cap"]["scale"] == 0.5
    assert g["y_floor"]["labels"] == ["a", "b"] and len(g["y_floor"]["multiplier"]) == 2


def test_a_looser_tolerance_still_reports_what_pushes(good):
    """A solve ended at a loose tolerance leaves an active element a scaled slack of order
    sqrt(mu) (here 0.02 rad / scale 3) with its multiplier; an element as far from its limit
    with a multiplier of mu / slack is not active; a solve that did not converge keeps the
    strict slack rule."""
    from types import SimpleNamespace
    from mdo.nlp.solution import active_limits
    sol = json.loads((good / "solution.json").read_text())
    g = next(c for c in sol["constraints"] if c["name"] == "y_floor")
    g["lhs"] = [0.5 + 0.02 * 3, 0.5 + 0.02 * 3]    # both elements 0.02 (scaled) above their floor
    g["multiplier"] = [-1.0, -1e-4]                 # a: pushes (1 m^2 per rad); b: mu / slack
    def active(success):
        ns = SimpleNamespace(variables=sol["variables"], constraints=sol["constraints"], success=success,
                             objective_unit=sol["objective"]["unit"], objective_scale=sol["objective"]["scale"])
        return {a["where"] for a in active_limits(ns) if a["name"] == "y_floor"}
    assert active(True) == {"a"}
    assert active(False) == set()


def test_angles_read_in_degrees():
    p = Problem("angles")
    a = p.variable("twist", unit="rad", lower=-0.5, upper=0.5, init=0.1, design=True)
    p.minimize((a - 0.2) ** 2)
    md = p.solve(verbose=False).summary_markdown()
    assert "| twist | 11.46 | deg | -28.65 to 28.65 |" in md


def test_good_folder_passes(good):
    r = _mdo("check", good)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "y_floor" in r.stdout and "cap" in r.stdout and "all 5 groups within tolerance" in r.stdout
    assert "tolerance: scaled violation <= 0.0001" in r.stdout


class _R:
    def __init__(self, code, out):
        self.returncode, self.stdout = code, out


def _check(capsys, d):
    from mdo import cli
    code = cli.main(["check", str(d)])
    return _R(code, capsys.readouterr().out)


def test_crafted_violations_exit_1(tmp_path, good, capsys):
    def over_cap(d):   # lhs 12.2 m against rhs 12 m, scale 0.5: scaled violation 0.4
        next(c for c in d["constraints"] if c["name"] == "cap")["lhs"] = [12.2]
    r = _check(capsys, _edit(good, tmp_path / "a", over_cap))
    assert r.returncode == 1 and "EXCEEDED" in r.stdout
    line = next(l for l in r.stdout.splitlines() if l.strip().startswith("cap"))
    assert "-0.2" in line and "total" in line and "EXCEEDED" in line

    def beyond_bound(d):   # x = 10.5 m above its 10 m upper bound
        next(v for v in d["variables"] if v["name"] == "x")["value"] = 10.5
    r = _check(capsys, _edit(good, tmp_path / "b", beyond_bound))
    assert r.returncode == 1
    assert "upper bound" in next(l for l in r.stdout.splitlines() if l.strip().startswith("x "))

    def within_tol(d):     # 0.5 * tolerance beyond: passes, as IPOPT would have accepted it
        next(c for c in d["constraints"] if c["name"] == "cap")["lhs"] = [12 + 0.5 * 1e-4 * 0.5]
    assert _check(capsys, _edit(good, tmp_path / "c", within_tol)).returncode == 0

    def nan_group(d):
        next(c for c in d["constraints"] if c["name"] == "y_floor")["lhs"][1] = None
    assert check_run(_edit(good, tmp_path / "d", nan_group)) == 1


def test_unreadable_folders_exit_2(tmp_path, good, capsys):
    from mdo import cli
    cases = {"missing": None, "empty": {}, "junk": "{nope", "old": json.dumps({"variables": []}),
             "binary": b"\xff\xfe\x00"}
    for name, content in cases.items():
        d = tmp_path / name
        if content is not None:
            d.mkdir()
            if isinstance(content, bytes):
                (d / "solution.json").write_bytes(content)
            elif content:
                (d / "solution.json").write_text(content)
        code = cli.main(["check", str(d)])
        err = capsys.readouterr().err
        assert code == 2, (name, err)
        assert len(err.strip().splitlines()) == 1 and str(d) in err and "Traceback" not in err


def test_run_writes_summary_active_for_a_mission(tmp_path):
    # the fast polar mission with a wing-area design variable: the run folder says what limits it
    from mdo.nlp import load_problem_file
    root = HERE.parent
    sol = run_problem(load_problem_file(root / "problems" / "polar_ga_mission.py",
                                        options={"design_wing_area": True}), tmp_path / "run", verbose=False)
    assert sol.success
    s = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert isinstance(s["active"], list)
    for a in s["active"]:
        assert set(a) == {"name", "kind", "where", "multiplier", "unit"} and a["kind"] in ("bound", "constraint")
        assert a["unit"].startswith("kWh per ")
    assert check_run(tmp_path / "run") == 0
