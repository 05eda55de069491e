"""The documentation: the API reference builds without warnings, every tutorial runs."""
import importlib.util
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
TUTORIALS = ROOT / "docs" / "tutorials"


def _have_docs_extra() -> bool:
    return all(importlib.util.find_spec(m) is not None for m in ("mkdocs", "mkdocstrings", "mkdocstrings_handlers"))


@pytest.mark.skipif(not _have_docs_extra(), reason="docs extra not installed: pip install -e '.[docs]'")
def test_docs_build_strict(tmp_path):
    t0 = time.perf_counter()
    r = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-f", str(ROOT / "mkdocs.yml"),
                        "-d", str(tmp_path / "site")], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "WARNING" not in r.stderr, r.stderr
    page = (tmp_path / "site" / "api" / "plots" / "index.html").read_text()
    assert "defined_ratio" in page and "write_report_html" in page   # docstrings made it into the reference
    print(f"docs built in {time.perf_counter() - t0:.1f} s")


def _run(script, *args, cwd):
    env = dict(os.environ, MPLBACKEND="Agg")
    r = subprocess.run([sys.executable, str(TUTORIALS / script), *map(str, args)], capture_output=True, text=True,
                       cwd=cwd, env=env, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    return r.stdout


def test_tutorial_run_paper_aircraft(tmp_path):
    out = _run("run_paper_aircraft.py", ROOT / "problems" / "polar_ga_mission.py", tmp_path / "run", cwd=tmp_path)
    assert "Solve_Succeeded" in out
    assert (tmp_path / "run" / "report.html").exists() and (tmp_path / "run" / "mission.csv").exists()


def test_tutorial_read_results(tmp_path):
    out = _run("read_results.py", ROOT / "results" / "ga2p", cwd=tmp_path)
    assert "ga2p (optimization): Solve_Succeeded" in out
    import json
    e = json.loads((ROOT / "results" / "ga2p" / "summary.json").read_text())["battery_energy_kWh"]
    assert f"total {e:.3f}" in out  # the committed GA-2P optimum's energy, kWh
    assert "undefined" in out       # the windmilling nodes are counted, not averaged in


def test_tutorial_block_in_opti(tmp_path):
    out = _run("block_in_opti.py", cwd=tmp_path)
    e = float(out.rsplit("span efficiency e = ", 1)[1].split()[0])
    assert 0.98 < e <= 1.0005, out   # no planar wing beats the elliptic loading


def test_tutorial_my_problem(tmp_path):
    out = _run("my_problem.py", tmp_path / "mine", cwd=tmp_path)
    assert out.startswith("Solve_Succeeded"), out
    area = float(out.split("wing of ", 1)[1].split()[0])
    assert 8.0 <= area < 14.0, out   # the optimizer moved the area off its start, inside its bounds
    r = subprocess.run([sys.executable, "-m", "mdo.cli", "run", str(TUTORIALS / "my_problem.py"), "--out",
                        str(tmp_path / "cli"), "--quiet", "--no-baseline", "-o", "cruise_distance_nmi=20"],
                       capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "cli" / "report.html").exists()


def test_tutorial_sweep(tmp_path):
    out = _run("sweep.py", tmp_path / "sweep", cwd=tmp_path)
    assert out.count("Solve_Succeeded") == 3
    slope = float(out.rsplit("cruise energy ", 1)[1].split()[0])
    assert 0.3 < slope < 2.0, out    # kWh per nmi of a 1.6 t electric airplane at 175 mph


def test_tutorials_all_tested():
    names = {p.name for p in TUTORIALS.glob("*.py")}
    tested = {"run_paper_aircraft.py", "read_results.py", "block_in_opti.py", "my_problem.py", "sweep.py"}
    assert names == tested, f"untested tutorial(s): {sorted(names - tested)}"
    assert shutil.which(sys.executable)
