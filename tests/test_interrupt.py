"""Ctrl-C and SIGTERM during a solve keep the IPOPT log and the last iterate (exit 130 / 143);
an interrupt in the baseline stage is reported as an interrupt, not as a failed baseline."""
import json
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

HERE = Path(__file__).parent
PROBLEM = HERE / "problems" / "slow_dense.py"

pytestmark = pytest.mark.skipif(sys.platform.startswith("win"), reason="POSIX signals")


def _start(*args):
    return subprocess.Popen([sys.executable, "-m", "mdo.cli", "run", *map(str, args), "--quiet"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def wait_iterating(out: Path, sub: str = "", timeout: float = 120):
    """Wait until the run into ``out`` (written in its staging sibling) has logged 2 iterations."""
    t0 = time.time()
    while time.time() - t0 < timeout:
        for log in out.parent.glob(f"{out.name}.incomplete-*/{sub}ipopt.log"):
            if len(re.findall(r"(?m)^\s+\d+\s+[-+]?\d\.\d+e", log.read_text(errors="replace"))) >= 2:
                return log
        time.sleep(0.2)
    raise AssertionError("IPOPT did not start iterating")


# SIGTERM during a solve: tests/test_reliability_folders.py::test_lock_refuses_a_second_run_while_one_is_solving
@pytest.mark.parametrize("sig,code,status", [(signal.SIGINT, 130, "Interrupted_By_User")])
def test_signal_keeps_log_and_last_iterate(tmp_path, sig, code, status):
    out = tmp_path / "run"
    proc = _start(PROBLEM, "--out", out)
    wait_iterating(out)
    proc.send_signal(sig)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == code, err
    assert f"interrupted by {signal.Signals(sig).name}" in err
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == status and summary["success"] is False
    assert (out / "solution.json").exists() and (out / "ipopt.log").exists()
    sol = json.loads((out / "solution.json").read_text())
    assert len(sol["variables"][0]["value"]) == 400
    assert not list(tmp_path.glob("run.incomplete-*")) and not (out / "INCOMPLETE.txt").exists()


def test_interrupt_in_the_baseline_stage_says_so(tmp_path):
    # slow_dense with a design variable: `mdo run` first solves the (slow) baseline analysis
    f = tmp_path / "staged.py"
    f.write_text(f"import sys\nsys.path.insert(0, {str(HERE / 'problems')!r})\n"
                 "from slow_dense import build as _build\n\n"
                 "def build(analysis=False):\n    p = _build()\n"
                 "    p.variable('d', lower=0, upper=1, init=0.5, design=True)\n    return p\n")
    out = tmp_path / "run"
    proc = _start(f, "--out", out)
    wait_iterating(out, "analysis/")
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 130, err
    assert "interrupted by SIGINT during stage 1 of 2" in err
    assert "did not converge" not in err and "fix the baseline" not in err
    assert json.loads((out / "analysis" / "summary.json").read_text())["status"] == "Interrupted_By_User"
    assert not (out / "summary.json").exists()   # the optimization never started


@pytest.mark.parametrize("sig,code", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_signal_while_building_leaves_nothing(tmp_path, sig, code):
    f = tmp_path / "slow_build.py"
    started = tmp_path / "building"
    # build() says when it is running, so the signal lands inside it however slow the start
    f.write_text(f"import pathlib, time\n\ndef build():\n    pathlib.Path({str(started)!r}).touch()\n"
                 f"    time.sleep(600)\n")
    out = tmp_path / "new" / "run"
    # a shell's background job inherits SIGINT ignored, and Python keeps it so; the user's
    # terminal run has the default, which this test is about
    proc = subprocess.Popen([sys.executable, "-m", "mdo.cli", "run", str(f), "--out", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    t0 = time.time()
    while not started.exists() and time.time() - t0 < 120:
        time.sleep(0.1)
    assert started.exists(), "build() never started"
    assert list(tmp_path.glob("new/run.incomplete-*")), "the run folder is taken before anything is built"
    time.sleep(0.3)
    proc.send_signal(sig)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == code, err
    assert f"interrupted by {signal.Signals(sig).name}" in err and "no solve was running" in err
    assert "Traceback" not in err and not (tmp_path / "new").exists()


def test_signal_interrupt_names_its_signal_wherever_it_lands():
    """Both handlers (the solve's and the CLI's) raise SignalInterrupt, so the exit code
    follows the signal and not the place it landed (a plain KeyboardInterrupt is SIGINT)."""
    import signal as sig

    from mdo.core.signals import SignalInterrupt, exit_code, interrupt_signal, raise_interrupt
    with pytest.raises(SignalInterrupt) as info:
        raise_interrupt(sig.SIGTERM, None)
    assert isinstance(info.value, KeyboardInterrupt)
    assert exit_code(interrupt_signal(info.value)) == ("SIGTERM", 143)
    assert exit_code(interrupt_signal(KeyboardInterrupt())) == ("SIGINT", 130)
