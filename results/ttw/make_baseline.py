"""The committed TTW baseline (``results/ttw/analysis``), from Table 5's-schedule baseline.

    python results/ttw/make_baseline.py [--out results/ttw/analysis] [--force]

``problems/ttw.py`` flies the transitions' wing tilt as a control with the cabin inside a passenger
airplane's attitude envelope (default since 2026-12-07).  Its baseline is started from the baseline
flown on Table 5's tilt schedule (``results/ttw/tilt_schedule/analysis``, the cabin pitched to 64 deg)
with the attitude beyond the envelope moved into the wing tilt (``attitude_into_tilt`` of the problem
file, the same step its relaxed start takes), then solved by ``mdo run --analysis``.  The optimization
is then ``mdo run problems/ttw.py --from-baseline results/ttw/analysis --max-iter 600``.
"""
import argparse
import importlib.util
import json
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("--out", default=str(ROOT / "results" / "ttw" / "analysis"))
ap.add_argument("--force", action="store_true")
args = ap.parse_args()

spec = importlib.util.spec_from_file_location("ttw_problem_file", ROOT / "problems" / "ttw.py")
ttw = importlib.util.module_from_spec(spec)
spec.loader.exec_module(ttw)
schedule = ROOT / "results" / "ttw" / "tilt_schedule" / "analysis"
start = json.loads((schedule / "solution.json").read_text())
ttw.attitude_into_tilt(schedule, start, ttw.cabin_attitude_bounds_rad("control", None))
with tempfile.TemporaryDirectory() as tmp:
    ws = Path(tmp) / "solution.json"
    ws.write_text(json.dumps(start))
    cmd = [sys.executable, "-m", "mdo.cli", "run", str(ROOT / "problems" / "ttw.py"), "--analysis",
           "--warm-start", str(ws), "--warm-start-partial", "--max-iter", "300", "--out", args.out]
    sys.exit(subprocess.run(cmd + (["--force"] if args.force else [])).returncode)
