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
