"""Run-folder integrity (#19 items 1-2): lock, staging sibling, --force moves the old run
aside, symlinks refused, every file-system error one line with exit 2 (1 after a solve)."""
import errno
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from mdo import cli
from mdo.nlp import run as nlp_run

HERE = Path(__file__).parent
BRACH = HERE / "problems" / "brachistochrone.py"
SLOW = HERE / "problems" / "slow_dense.py"
sys.path.insert(0, str(HERE))
from test_interrupt import wait_iterating  # noqa: E402


def _mdo(*args):
    return subprocess.run([sys.executable, "-m", "mdo.cli", *map(str, args)], capture_output=True, text=True)


def _main(capsys, *args):
    code = cli.main([*map(str, args)])
    cap = capsys.readouterr()
    return code, cap.out, cap.err


def _one_line(err):
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    return lines[0]


@pytest.fixture(scope="module")
def brach_run(tmp_path_factory):
    """A finished brachistochrone run folder (copied by the tests that change it)."""
    out = tmp_path_factory.mktemp("done") / "run"
    r = _mdo("run", BRACH, "--out", out, "--quiet", "--no-baseline")
    assert r.returncode == 0, r.stderr
    return out


def _copy(src, dst):
    import shutil
    shutil.copytree(src, dst, symlinks=True)
    return dst


def test_concurrent_runs_one_refused(tmp_path):
    out = tmp_path / "run"
    procs = [subprocess.Popen([sys.executable, "-m", "mdo.cli", "run", str(BRACH), "--out", str(out), "--quiet",
                               "--no-baseline"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for _ in range(2)]
    res = [(p.wait(timeout=120), p.stderr.read()) for p in procs]
    assert sorted(c for c, _ in res) == [0, 2], res
    err = [e for c, e in res if c == 2][0]
    assert "another mdo run" in err or "already holds a run" in err
    assert json.loads((out / "summary.json").read_text())["status"] == "Solve_Succeeded"
    assert not list(tmp_path.glob("run.*")) and not list(tmp_path.glob(".run.lock"))


def test_lock_refuses_a_second_run_while_one_is_solving(tmp_path):
    out = tmp_path / "run"
    a = subprocess.Popen([sys.executable, "-m", "mdo.cli", "run", str(SLOW), "--out", str(out), "--quiet"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        wait_iterating(out)
        r = _mdo("run", BRACH, "--out", out, "--quiet", "--force")
        assert r.returncode == 2 and "another mdo run is writing it" in _one_line(r.stderr)
    finally:
        a.send_signal(signal.SIGTERM)   # handled like Ctrl-C: last iterate and log kept, exit 143
        _, err = a.communicate(timeout=120)
    assert a.returncode == 143 and "interrupted by SIGTERM" in err
    summary = json.loads((out / "summary.json").read_text())
    assert summary["problem"] == "slow_dense" and summary["status"] == "Terminated_By_Signal"
    assert (out / "ipopt.log").exists()
    assert len(json.loads((out / "solution.json").read_text())["variables"][0]["value"]) == 400


def test_kill_9_leaves_the_earlier_run_intact(tmp_path, brach_run):
    out = _copy(brach_run, tmp_path / "run")
    before = {f: (out / f).read_bytes() for f in ("summary.json", "solution.json", "ipopt.log")}
    p = subprocess.Popen([sys.executable, "-m", "mdo.cli", "run", str(SLOW), "--out", str(out), "--quiet",
                          "--force"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    wait_iterating(out)
    p.send_signal(signal.SIGKILL)
    p.wait(timeout=60)
    assert {f: (out / f).read_bytes() for f in before} == before
    partial = list(tmp_path.glob("run.incomplete-*"))
    assert len(partial) == 1 and (partial[0] / "INCOMPLETE.txt").exists()
    # the lock died with the process: the next run goes ahead
    r = _mdo("run", BRACH, "--out", out, "--quiet", "--force", "--no-baseline")
    assert r.returncode == 0, r.stderr


def test_force_moves_the_old_run_aside_and_keeps_none_of_its_files(tmp_path, brach_run):
    out = _copy(brach_run, tmp_path / "run")
    (out / "blade.csv").write_text("another problem's file\n")
    (out / "analysis").mkdir()
    (out / "analysis" / "summary.json").write_text("{}")
    r = _mdo("run", BRACH, "--out", out, "--quiet", "--force", "--no-baseline")
    assert r.returncode == 0, r.stderr
    assert not (out / "blade.csv").exists() and not (out / "analysis").exists()
    old = list(tmp_path.glob("run.old-*"))
    assert len(old) == 1 and (old[0] / "blade.csv").exists() and "moved to" in r.stdout


def test_failed_force_run_keeps_the_earlier_run_in_place(tmp_path, brach_run):
    out = _copy(brach_run, tmp_path / "run")
    before = (out / "summary.json").read_text()
    r = _mdo("run", BRACH, "--out", out, "--quiet", "--force", "--max-iter", "3", "--no-baseline")
    assert r.returncode == 1 and "did not converge" in r.stderr
    assert (out / "summary.json").read_text() == before
    failed = list(tmp_path.glob("run.failed-*"))
    assert len(failed) == 1
    assert json.loads((failed[0] / "summary.json").read_text())["status"] == "Maximum_Iterations_Exceeded"
    assert str(failed[0]) in r.stderr


def test_symlinks_refused(tmp_path, brach_run, capsys):
    out = _copy(brach_run, tmp_path / "run")
    target = tmp_path / "precious.txt"
    target.write_text("keep me")
    (out / "summary.md").unlink()
    (out / "summary.md").symlink_to(target)
    code, _, err = _main(capsys, "run", BRACH, "--out", out, "--quiet", "--force")
    assert code == 2 and "symbolic link" in _one_line(err) and "summary.md" in err
    assert target.read_text() == "keep me"
    link = tmp_path / "link"
    link.symlink_to(tmp_path / "elsewhere", target_is_directory=True)
    code, _, err = _main(capsys, "run", BRACH, "--out", link, "--quiet")
    assert code == 2 and "symbolic link" in _one_line(err)
    assert not (tmp_path / "elsewhere").exists()


def test_not_a_directory_and_existing_file(tmp_path, capsys):
    f = tmp_path / "file"
    f.write_text("x")
    for out in (f, f / "sub" / "run"):
        code, outp, err = _main(capsys, "run", BRACH, "--out", out, "--quiet")
        assert code == 2 and str(f) in _one_line(err), err
        assert "building" not in outp
    assert f.read_text() == "x"


def test_a_folder_of_other_files_is_refused(tmp_path, capsys):
    (tmp_path / "notes.txt").write_text("mine")
    code, _, err = _main(capsys, "run", BRACH, "--out", tmp_path, "--quiet", "--force")
    assert code == 2 and "not an mdo run" in _one_line(err)
    assert (tmp_path / "notes.txt").read_text() == "mine"


def test_over_long_names(tmp_path, capsys):
    out = tmp_path / ("x" * 300)
    code, _, err = _main(capsys, "run", BRACH, "--out", out, "--quiet")
    assert code == 2 and "name too long" in _one_line(err) and "xxxx" in err
    code, _, err = _main(capsys, "run", tmp_path / ("p" * 300 + ".py"), "--out", tmp_path / "o")
    assert code == 2 and "problem file" in _one_line(err)
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("err_no", [errno.EROFS, errno.EACCES, errno.ENOSPC])
def test_unwritable_output_refused_before_the_build(tmp_path, capsys, monkeypatch, err_no):
    # root ignores permission bits, so the file system's answer is simulated where mdo asks it
    def refuse(*a, **k):
        raise OSError(err_no, os.strerror(err_no), str(tmp_path / "run.incomplete-x"))
    monkeypatch.setattr(nlp_run.tempfile, "mkdtemp", refuse)
    built = []
    monkeypatch.setattr(nlp_run, "load_problem_file", lambda *a, **k: built.append(1))
    code, outp, err = _main(capsys, "run", BRACH, "--out", tmp_path / "new" / "run", "--quiet")
    line = _one_line(err)
    assert code == 2 and "--out" in line and str(tmp_path / "new" / "run") in line
    assert {errno.EROFS: "not writable", errno.EACCES: "not writable", errno.ENOSPC: "no space"}[err_no] in line
    assert not built and not (tmp_path / "new").exists()   # nothing built, the parents made are removed


def test_full_disk_after_the_solve_is_exit_1_and_keeps_the_earlier_run(tmp_path, brach_run, capsys,
                                                                       monkeypatch):
    from mdo.nlp import solution as nlp_solution   # Solution.save writes through it
    out = _copy(brach_run, tmp_path / "run")
    before = (out / "summary.json").read_text()

    def full(path, text):
        raise OSError(errno.ENOSPC, "No space left on device")
    monkeypatch.setattr(nlp_solution, "write_atomic", full)
    code, _, err = _main(capsys, "run", BRACH, "--out", out, "--quiet", "--force", "--no-baseline")
    line = _one_line(err)
    assert code == 1 and "no space left" in line and "incomplete" in line and "Solve_Succeeded" in line
    assert (out / "summary.json").read_text() == before
    partial = list(tmp_path.glob("run.incomplete-*"))
    assert len(partial) == 1 and (partial[0] / "INCOMPLETE.txt").exists() and (partial[0] / "ipopt.log").exists()


def test_problem_file_that_exits_or_returns_nothing(tmp_path, capsys):
    for body, needle in (("import sys\nsys.exit(0)\n", "sys.exit(0)"),
                         ("def build():\n    import sys\n    sys.exit(0)\n", "sys.exit(0)"),
                         ("def build():\n    pass\n", "returned nothing")):
        f = tmp_path / "p.py"
        f.write_text(body)
        code, _, err = _main(capsys, "run", f, "--out", tmp_path / "out")
        assert code == 2 and needle in _one_line(err)
        assert not (tmp_path / "out").exists()


def test_relaxed_start_solves_first_and_hands_on(tmp_path):
    """A problem file's RELAXED_OPTIONS: the relaxed analysis is solved into relaxed/ and
    the baseline starts from it (through the file's relaxed_start)."""
    prob = HERE / "problems" / "relaxed_brachistochrone.py"
    out = tmp_path / "run"
    r = _mdo("run", prob, "--out", out, "--quiet")
    assert r.returncode == 0, r.stderr
    relaxed = json.loads((out / "analysis" / "relaxed" / "summary.json").read_text())
    assert relaxed["status"] == "Solve_Succeeded"
    assert (out / "analysis" / "relaxed" / "relaxed_start_called.txt").exists()
    assert json.loads((out / "summary.json").read_text())["status"] == "Solve_Succeeded"
    ana = tmp_path / "ana"
    r = _mdo("run", prob, "--analysis", "--out", ana, "--quiet")
    assert r.returncode == 0, r.stderr
    assert (ana / "relaxed" / "summary.json").exists() and (ana / "summary.json").exists()


def test_relaxed_start_in_steps_hands_each_on_with_the_next_solves_options(tmp_path):
    """RELAXED_OPTIONS as a list: each step is solved in turn (relaxed/, relaxed_2/), the hook sees
    after each the options of the solve it starts (the next step's, then the run's own) and, in the
    step's summary.json, the build() options the step was flown with (defaults included)."""
    prob = HERE / "problems" / "relaxed_steps_brachistochrone.py"
    out = tmp_path / "run"
    r = _mdo("run", prob, "--out", out, "--quiet", "-o", "nodes=12")
    assert r.returncode == 0, r.stderr
    first = json.loads((out / "analysis" / "relaxed" / "relaxed_start_called.json").read_text())
    second = json.loads((out / "analysis" / "relaxed_2" / "relaxed_start_called.json").read_text())
    assert first["flown"] == {"nodes": 12, "analysis": True, "final_y": 6.0}
    assert first["next"] == {"nodes": 12, "analysis": True, "final_y": 5.5}
    assert second["flown"]["final_y"] == 5.5 and second["next"] == {"nodes": 12, "analysis": True, "final_y": 5.0}
    assert json.loads((out / "analysis" / "summary.json").read_text())["options"]["final_y"] == 5.0
    assert json.loads((out / "summary.json").read_text())["options"] == {"nodes": 12, "analysis": False,
                                                                         "final_y": 5.0}
