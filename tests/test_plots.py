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


# ---------------------------------------------------------------- damaged run folders (issue 19 item 6)
import os  # noqa: E402

import pytest  # noqa: E402

MISSION = "time_s,altitude_m,speed_mps,segment\n" + "".join(
    f"{60 * i},{100 * i},{50 + i},{'CL' if i < 5 else 'CR'}\n" for i in range(10))
LOADING = "surface,y_m,cl_props_on,cl_props_off\n" + "".join(
    f"main_wing,{0.5 * i},{0.5 + 0.01 * i},{0.5}\n" for i in range(8))
BLADE = "r_over_R,c_over_R,beta_deg\n0.2,0.1,40\n0.6,0.08,25\n1.0,0.04,12\n"


def _fifo(p):
    os.mkfifo(p)


def _binary(p):
    p.write_bytes(b"\x00\x01\x02\xff" * 1000)


def _huge(p):
    with open(p, "wb") as f:   # sparse: 65 MiB of size, no disk use
        f.truncate(65 * 2 ** 20)


DAMAGE = {
    "fifo log": ("ipopt.log", _fifo, "not a regular file"),
    "folder as log": ("ipopt.log", lambda p: p.mkdir(), "not a regular file"),
    "device as log": ("ipopt.log", lambda p: p.symlink_to("/dev/zero"), "not a regular file"),
    "empty log": ("ipopt.log", lambda p: p.write_text(""), "empty"),
    "log without iterations": ("ipopt.log", lambda p: p.write_text("EXIT: Invalid_Option\n"), "no IPOPT iteration"),
    "binary loading": ("loading.csv", _binary, "binary"),
    "huge loading": ("loading.csv", _huge, "read limit"),
    "loading without columns": ("loading.csv", lambda p: p.write_text("surface,y_m\nmain_wing,1\n"),
                                "column 'cl_props_on' missing"),
    "loading header only": ("loading.csv", lambda p: p.write_text("surface,y_m,cl_props_on,cl_props_off\n"),
                            "no rows"),
    "text in numbers": ("loading.csv", lambda p: p.write_text("surface,y_m,cl_props_on,cl_props_off\nw,a,b,c\n"),
                        "skipped"),
    "not utf-8 blade": ("blade.csv", lambda p: p.write_bytes(b"r_over_R\xe9\xe9\xe9,c\n1,2\n"), "not UTF-8"),
    "truncated blade": ("blade.csv", lambda p: p.write_text("r_over_R,c_over_R\n0.2,0.1\n"),
                        "column 'beta_deg' missing"),
}


@pytest.mark.parametrize("case", sorted(DAMAGE))
def test_plot_damaged_folder_draws_the_rest(case, tmp_path, capsys):
    name, damage, reason = DAMAGE[case]
    run = tmp_path / "run"
    run.mkdir()
    good = {"mission.csv": MISSION, "loading.csv": LOADING, "blade.csv": BLADE}
    for fname, text in good.items():
        if fname != name:
            (run / fname).write_text(text)
    damage(run / name)
    if case == "fifo log":
        # a subprocess with a timeout: a FIFO opened for reading would block for ever
        r = subprocess.run([sys.executable, "-m", "mdo.cli", "plot", str(run)], capture_output=True, text=True,
                           timeout=120)
        code, err = r.returncode, r.stderr
    else:
        from mdo.cli import main
        capsys.readouterr()
        code = main(["plot", str(run)])
        err = capsys.readouterr().err
    assert code == 0, err
    warnings = [line for line in err.splitlines() if line.strip()]
    assert len(warnings) == 1 and "warning" in warnings[0] and reason in warnings[0], err
    assert "Traceback" not in err
    assert (run / "mission.png").stat().st_size > 10_000    # the undamaged figures are drawn
    drawn = {p.name for p in run.glob("*.png")}
    skipped = {"ipopt.log": "convergence.png", "loading.csv": "loading.png", "blade.csv": "rotor.png"}[name]
    assert skipped not in drawn


def test_plot_folder_with_only_damaged_files_exit_2(tmp_path):
    run = tmp_path / "run"
    run.mkdir()
    os.mkfifo(run / "ipopt.log")
    (run / "mission.csv").write_text("")
    r = subprocess.run([sys.executable, "-m", "mdo.cli", "plot", str(run)], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 3 and lines[-1].startswith("mdo: error: RUN_DIR") and "2 figure(s) skipped" in lines[-1]


def test_usable_input_never_opens_a_fifo(tmp_path):
    from mdo.plots.render import usable_input
    os.mkfifo(tmp_path / "f")
    assert "not a regular file" in usable_input(tmp_path / "f")   # returns at once
    assert usable_input(tmp_path / "absent") == "missing"
    (tmp_path / "ok.csv").write_text("a,b\n1,2\n")
    assert usable_input(tmp_path / "ok.csv") is None
