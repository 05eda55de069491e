"""The infeasibility report names causes (#19 item 5): a battery too small for the
mission shows as the battery's energy pinned at its capacity, beside the force residual."""
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).parent


def test_small_battery_report_names_the_pinned_state(tmp_path):
    r = subprocess.run([sys.executable, "-m", "mdo.cli", "run", str(HERE / "problems" / "small_battery.py"),
                        "--out", str(tmp_path / "run"), "--quiet"], capture_output=True, text=True)
    assert r.returncode == 1, r.stderr
    err = r.stderr
    assert "worst-violated constraint groups" in err and "force_along_path" in err
    assert "variables pinned at a bound" in err
    # 10 kWh = 3.6e7 J: the energy drawn reaches the pack's capacity
    assert "energy_drawn at its upper bound 3.6e+07 J" in err
    md = (tmp_path / "run" / "summary.md").read_text()
    assert "energy_drawn at its upper bound" in md


def test_feasible_run_reports_no_pinned_causes(tmp_path):
    r = subprocess.run([sys.executable, "-m", "mdo.cli", "run", str(HERE / "problems" / "small_battery.py"),
                        "-o", "battery_kWh=80", "--out", str(tmp_path / "run"), "--quiet"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert "pinned" not in r.stderr and "pinned" not in (tmp_path / "run" / "summary.md").read_text()


def test_ipopt_abort_before_the_first_iterate_is_exit_1(tmp_path):
    # an unavailable linear solver: IPOPT stops with Invalid_Option before iterating (CasADi
    # crashes destroying such a solver; the CLI must still exit 1 with its report and files)
    f = tmp_path / "bad_option.py"
    f.write_text("from mdo.nlp import Problem\n\ndef build():\n    p = Problem('bad_option')\n"
                 "    x = p.variable('x', lower=0, upper=2, init=1)\n    p.minimize((x - 3) ** 2)\n"
                 "    p.ipopt_options['linear_solver'] = 'ma97'\n    return p\n")
    r = subprocess.run([sys.executable, "-m", "mdo.cli", "run", str(f), "--out", str(tmp_path / "run"), "--quiet"],
                       capture_output=True, text=True)
    assert r.returncode == 1, r.stderr
    assert "Invalid_Option" in r.stderr and "Traceback" not in r.stderr
    assert (tmp_path / "run" / "summary.json").exists()


def test_a_limiting_inequality_is_named_beside_the_residual():
    """When the cause is a constraint, not a bound (the aircraft's state-of-charge reserve
    is one), the report names it: here an energy budget e <= 1 against a need e = 2 x."""
    from mdo.nlp import Problem
    p = Problem("budget")
    x = p.variable("x", lower=1.0, upper=10.0, init=2.0)
    e = p.variable("e", lower=0.0, upper=100.0, init=1.0)
    p.constrain("energy need", e - 2.0 * x, kind="==", scale=1.0)
    p.constrain("energy budget", e, kind="<=", rhs=1.0, scale=1.0, unit="kWh", labels=["end of mission"])
    p.minimize(e)
    sol = p.solve(verbose=False, max_iter=100)
    assert not sol.success
    report = sol.violation_report()
    assert "inequality constraints at their limit" in report and "energy budget at end of mission" in report
