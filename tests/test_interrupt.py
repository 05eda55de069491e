"""Ctrl-C during a solve keeps the IPOPT log and the last iterate (exit 130)."""
import json
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

PROBLEM = Path(__file__).parent / "problems" / "slow_dense.py"


@pytest.mark.skipif(sys.platform.startswith("win"), reason="POSIX signals")
def test_ctrl_c_keeps_log_and_last_iterate(tmp_path):
    out = tmp_path / "run"
    proc = subprocess.Popen([sys.executable, "-m", "mdo.cli", "run", str(PROBLEM), "--out", str(out), "--quiet"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    log = out / "ipopt.log"
    t0 = time.time()
    while time.time() - t0 < 120:          # wait until IPOPT is iterating
        if log.exists() and len(re.findall(r"(?m)^\s+\d+\s+[-+]?\d\.\d+e", log.read_text(errors="replace"))) >= 2:
            break
        time.sleep(0.2)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 130, err
    assert "interrupted" in err
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "Interrupted_By_User" and summary["success"] is False
    assert (out / "solution.json").exists() and log.exists()
    sol = json.loads((out / "solution.json").read_text())
    assert len(sol["variables"][0]["value"]) == 400
