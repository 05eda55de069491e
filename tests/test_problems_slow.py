"""Full problems of the paper (slow: minutes each; `python -m pytest -m slow`)."""
import csv
import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow

PAPER_BASELINE_KWH = {"ga2p": 61.01, "ga8p": 40.51, "ttw": 114.77}
PAPER_REDUCTION = {"ga2p": 5.00, "ga8p": 7.25, "ttw": 9.52}


def _run(*args):
    return subprocess.run([sys.executable, "-m", "mdo.cli", "run", *map(str, args), "--quiet"],
                          capture_output=True, text=True, cwd=ROOT)


# The TTW runs about 35 minutes (its relaxed start in two steps, the baseline, the optimization:
# 2026-12-07, twenty-second session, with the cabin's pitch-rate limit, 32 min 28 s with another solve on
# the second core: 160.076 -> 114.548 kWh, results/ttw/from_nothing; twenty-first: 114.429).  With a one-step relaxed start (twentieth session) it ended in
# the hover-designed blade's local optimum, 125.847 kWh; until then it was an expected failure: from the
# problem's own guess the baseline had not converged (2026-12-06).
@pytest.mark.parametrize("problem", ["ga2p", "ga8p", "ttw"])
def test_baseline_analysis_and_optimization(tmp_path, problem):
    """One `mdo run`: the baseline analysis (design frozen) into OUT/analysis, then the
    optimization warm-started from it into OUT."""
    op = tmp_path / "opt"
    r = _run(f"problems/{problem}.py", "--out", op)
    assert r.returncode == 0, r.stderr
    an = op / "analysis"
    s_an = json.loads((an / "summary.json").read_text())
    assert s_an["status"] == "Solve_Succeeded"
    # same order of magnitude as the paper's baseline (differences explained in results/table3.md and
    # results/table3_reconciliation.md).  The band was 0.5-2.0 until the P2006T airframe's drag was
    # calibrated to its flight manual (2026-12-06, tenth session): GA-8P's baseline is now 2.17 x the
    # paper's 40.51 kWh, which sits 34 % below the paper's own GA-2P (ours: +6 %).
    assert 0.5 < s_an["battery_energy_kWh"] / PAPER_BASELINE_KWH[problem] < 2.5
    for f in ("mass.md", "energy.md", "loading.csv", "blade.csv", "design.json", "mission.csv", "geometry.png"):
        assert (an / f).exists(), f
    s = json.loads((op / "summary.json").read_text())
    assert s["status"] == "Solve_Succeeded"
    reduction = 100 * (s_an["battery_energy_kWh"] - s["battery_energy_kWh"]) / s_an["battery_energy_kWh"]
    assert reduction >= PAPER_REDUCTION[problem]
    if problem == "ttw":   # the cruise-designed blade's basin, not the hover blade's (10 % above)
        committed = json.loads((ROOT / "results" / "ttw" / "summary.json").read_text())["battery_energy_kWh"]
        assert s["battery_energy_kWh"] < 1.005 * committed
    if problem != "ttw":   # an airplane's optimum is controllable with a motor out at every speed it flies
        eo = json.loads((op / "design.json").read_text())["engine_out"]
        with open(op / "mission.csv") as fh:
            v_min = min(float(r["speed_mps"]) for r in csv.DictReader(fh))
        for name, g in eo["groups"].items():
            # V_MC at sea level, where the rudder is strongest: at most the slowest node's speed
            assert g["minimum_control_speed_sea_level_mps"] <= v_min * (1 + 1e-3), name
