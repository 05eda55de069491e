"""mdo plot: figures from a run folder, clear errors otherwise."""
import subprocess
import sys

from mdo.nlp import load_problem_file, run_problem
from mdo.plots import parse_ipopt_log

from test_nlp_harness import BRACH


def test_plot_convergence_from_run_folder(tmp_path):
    sol = run_problem(load_problem_file(BRACH), tmp_path / "run", verbose=False)
    h = parse_ipopt_log(tmp_path / "run" / "ipopt.log")
    assert h["iter"].size == sol.iterations + 1
    assert h["inf_pr"][-1] < 1e-6
    r = subprocess.run([sys.executable, "-m", "mdo.cli", "plot", str(tmp_path / "run")],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    png = tmp_path / "run" / "convergence.png"
    assert png.exists() and png.stat().st_size > 10_000


def test_plot_bad_folder_exit_2(tmp_path):
    r = subprocess.run([sys.executable, "-m", "mdo.cli", "plot", str(tmp_path / "nope")],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "RUN_DIR" in r.stderr
    r = subprocess.run([sys.executable, "-m", "mdo.cli", "plot", str(tmp_path)], capture_output=True, text=True)
    assert r.returncode == 2 and "no data to plot" in r.stderr
