"""report.html: one self-contained page per run folder, checked in headless Chromium."""
import base64
import io
import json
import math
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from mdo.plots.report_html import markdown_to_html, report_html

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")


@pytest.fixture(scope="module")
def ga2p_run(tmp_path_factory):
    """A copy of the committed GA-2P optimum (with its baseline) rendered afresh by mdo plot's code."""
    from mdo.plots import render_run
    run = tmp_path_factory.mktemp("report") / "ga2p"
    shutil.copytree(ROOT / "results" / "ga2p", run)
    made = render_run(run)
    assert run / "report.html" in made
    return run


def _imgs(page: str):
    return re.findall(r"<img\b[^>]*>", page)


def test_report_is_self_contained(ga2p_run):
    page = (ga2p_run / "report.html").read_text()
    imgs = _imgs(page)
    pngs = {p.name for p in ga2p_run.glob("*.png")}
    assert len(imgs) == len(pngs) >= 6          # every figure of the folder, planform and geometry included
    import matplotlib.image as mpimg
    for tag in imgs:
        src = re.search(r"src='([^']*)'", tag).group(1)
        assert src.startswith("data:image/png;base64,"), tag[:80]
        img = mpimg.imread(io.BytesIO(base64.b64decode(src.split(",", 1)[1])), format="png")
        assert img.shape[0] > 100 and img.shape[1] > 100
    assert not re.search(r"(src|href)=['\"](?!data:|#)", page)   # nothing outside the file
    assert "<script" not in page
    energy = f'{json.loads((ga2p_run / "summary.json").read_text())["objective"]["value"]:.6g}'
    for text in ("Solve_Succeeded", "battery energy used", energy, "Design variables", "main_wing.span",
                 "Energy breakdown", "Mass build-up", "Design checks", "Active constraints"):
        assert text in page, text
    base = json.loads((ga2p_run / "analysis" / "summary.json").read_text())["objective"]["value"]
    assert "baseline (analysis/)" in page and f"{base:.6g}" in page   # the baseline's energy beside the optimum


def test_active_constraints_rendered_or_not_available(tmp_path, ga2p_run):
    run = tmp_path / "run"
    shutil.copytree(ga2p_run, run)
    s = json.loads((run / "summary.json").read_text())
    s.pop("active", None)
    (run / "summary.json").write_text(json.dumps(s))
    assert "not available" in report_html(run)
    s["active"] = [{"name": "propellers tip Mach", "kind": "<=", "where": "propellers design point",
                    "multiplier": 1.234e-2, "unit": "-"},
                   {"name": "main_wing.span", "kind": "upper bound", "where": "", "multiplier": -5.5e-3, "unit": "m"}]
    (run / "summary.json").write_text(json.dumps(s))
    page = report_html(run)
    assert "not available" not in page
    assert "propellers tip Mach" in page and "0.01234" in page and "-0.0055" in page


@pytest.fixture(scope="module")
def windmilling_run(tmp_path_factory):
    """A committed GA-2P optimum whose base leg windmills: the what-if with Raymer's 10 % leakage
    allowance (`results/ga2p/raymer_leakage`; with the P2006T calibration the default's base leg
    keeps drawing power), rendered afresh."""
    from mdo.plots import render_run
    run = tmp_path_factory.mktemp("report_windmilling") / "ga2p"
    shutil.copytree(ROOT / "results" / "ga2p" / "raymer_leakage", run)
    render_run(run)
    return run


def test_undefined_efficiencies_are_dashes(windmilling_run):
    page = (windmilling_run / "report.html").read_text()
    rows = {m.group(1): m.group(0) for m in re.finditer(r"<tr><td>(\w+)</td>.*?</tr>", page)}
    # where energy flows backwards (windmilling: shaft or battery energy <= 0; a propulsive
    # energy <= 0) the efficiency is a dash, never a number; the base leg's propellers windmill
    dashes = checked = 0
    for seg, row in rows.items():
        cells = re.findall(r"<td[^>]*>([^<]*)</td>", row)
        if len(cells) != 11 or not all(re.fullmatch(r"-?\d+\.\d+", c) for c in cells[2:5]):
            continue                     # a row of another table
        battery, shaft, propulsive = (float(c) for c in cells[2:5])
        chain, prop = cells[-2:]
        checked += 1
        if battery <= 0 or shaft <= 0:
            assert chain == "—", (seg, cells)
        if shaft <= 0 or propulsive <= 0:
            assert prop == "—", (seg, cells)
        dashes += (chain == "—") + (prop == "—")
    assert checked >= 10 and dashes and float(re.findall(r"<td[^>]*>([^<]*)</td>", rows["BL"])[4]) < 0
    effs = [float(c) for r in rows.values() for c in re.findall(r"<td[^>]*>([^<]*)</td>", r)[-2:]
            if re.fullmatch(r"0\.\d+|1\.0+", c)]
    assert effs and all(0 < e <= 1 for e in effs)


def test_markdown_tables_and_escaping():
    h = markdown_to_html("# T\n\n| a | b |\n|---|---:|\n| x<y | 1.5 |\n\n- **bold** item\n")
    assert "<h2>T</h2>" in h and "<th>a</th>" in h and "x&lt;y" in h and "<b>bold</b>" in h
    assert "|---" not in h


@pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (apt-get install chromium); "
                                             ".ci/run installs it so CI runs this test")
def test_report_in_headless_chromium(ga2p_run, tmp_path):
    url = (ga2p_run / "report.html").resolve().as_uri()
    base = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
            "--disable-component-update", "--disable-sync", "--no-first-run", "--enable-logging=stderr", "--v=0"]
    shot = tmp_path / "report.png"
    r = subprocess.run(base + [f"--user-data-dir={tmp_path / 'profile1'}", f"--screenshot={shot}",
                               "--window-size=1280,2000", url], capture_output=True, text=True, timeout=120)
    assert shot.exists() and shot.stat().st_size > 20_000, r.stderr[-2000:]
    import matplotlib.image as mpimg
    img = mpimg.imread(shot)
    assert img.shape[:2] == (2000, 1280)
    assert float(np.std(img[..., :3])) > 0.05      # not a blank page
    for bad in ("Uncaught", "SyntaxError", "ReferenceError", "Failed to load resource", "net::ERR"):
        assert bad not in r.stderr, bad
    d = subprocess.run(base + [f"--user-data-dir={tmp_path / 'profile2'}", "--dump-dom", url],
                       capture_output=True, text=True, timeout=120)
    dom = d.stdout
    assert "ga2p: optimization" in dom and "Solve_Succeeded" in dom
    srcs = re.findall(r"<img\b[^>]*\bsrc=\"([^\"]*)\"", dom)
    assert len(srcs) >= 6 and all(s.startswith("data:image/png;base64,") for s in srcs)
    for bad in ("Uncaught", "SyntaxError", "ReferenceError"):
        assert bad not in d.stderr, bad


def test_run_problem_writes_report(tmp_path):
    from mdo.nlp import load_problem_file, run_problem
    run_problem(load_problem_file(ROOT / "problems" / "polar_ga_mission.py"), tmp_path / "run", verbose=False)
    assert (tmp_path / "run" / "report.html").exists()          # written by the run itself
    page = (tmp_path / "run" / "report.html").read_text()
    assert page == report_html(tmp_path / "run")                 # and from the folder's files alone
    assert "polar_ga_mission" in page and len(_imgs(page)) >= 1


def test_design_angles_in_degrees(ga2p_run):
    """solution.json keeps radians; the report shows the twists in degrees."""
    sol = json.loads((ga2p_run / "solution.json").read_text())
    twist = next(v for v in sol["variables"] if v["name"] == "main_wing.twist")
    assert twist["unit"] == "rad"
    page = report_html(ga2p_run)
    row = page.split("<td>main_wing.twist</td>", 1)[1].split("</tr>", 1)[0]
    assert "<td>deg</td>" in row and "rad" not in row.split("<td>", 3)[2]
    first = float(row.split("[", 1)[1].split(",", 1)[0])
    assert abs(first - math.degrees(np.ravel(twist["value"])[0])) < 1e-3 * max(1.0, abs(first))
