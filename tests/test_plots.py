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
LOADING = "surface,y_m,cl_props_on,cl_props_off,ccl_over_cref,chord_m\n" + "".join(
    f"main_wing,{0.5 * i},{0.5 + 0.01 * i},{0.5},{0.5},{1.5}\n" for i in range(8))
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
                                "column 'ccl_over_cref' missing"),
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


# ---------------------------------------------------------------- issue 23: what a designer sees
import json  # noqa: E402
import shutil  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
import pytest  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def _capture(monkeypatch):
    """Record every figure's axes labels, titles and x ticks when it is saved."""
    import matplotlib.figure
    seen = []
    orig = matplotlib.figure.Figure.savefig

    def save(fig, *a, **k):
        fig.canvas.draw()
        seen.append({"ylabels": [ax.get_ylabel() for ax in fig.axes], "xlabels": [ax.get_xlabel() for ax in fig.axes],
                     "title": fig._suptitle.get_text() if fig._suptitle else fig.axes[0].get_title(),
                     "xticks": [list(ax.get_xticks()) for ax in fig.axes],
                     "lines": [[ln.get_ydata() for ln in ax.get_lines()] for ax in fig.axes]})
        return orig(fig, *a, **k)
    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", save)
    return seen


def test_convergence_csv_is_the_log(tmp_path):
    """One source: convergence.csv holds the numbers of ipopt.log's iteration lines (GA-2P: 8.17e-04
    at iteration 1, where the intermediate callback said 0.00715)."""
    from mdo.plots.convergence import write_convergence_csv
    from mdo.plots.figures import read_csv
    log = ROOT / "results" / "ga2p" / "ipopt.log"
    n = write_convergence_csv(log, tmp_path / "c.csv")
    c = read_csv(tmp_path / "c.csv")
    h = parse_ipopt_log(log)
    iters = json.loads((ROOT / "results" / "ga2p" / "summary.json").read_text())["iterations"]
    assert n == iters + 1 and c["iter"].tolist() == list(range(iters + 1))
    assert np.array_equal(c["inf_pr"], h["inf_pr"]) and np.array_equal(c["objective"], h["objective"])
    sol = run_problem(load_problem_file(BRACH), tmp_path / "run", verbose=False)
    h = parse_ipopt_log(tmp_path / "run" / "ipopt.log")
    c = read_csv(tmp_path / "run" / "convergence.csv")
    assert c["iter"].size == sol.iterations + 1
    assert np.array_equal(c["inf_pr"], h["inf_pr"]) and np.array_equal(c["inf_du"], h["inf_du"])


def test_undefined_ratios_are_nan():
    from mdo.plots.units import defined_ratio
    r = defined_ratio([0.9, -0.165, 0.2, 0.0, 1.0], [1.0, -0.128, -0.1, 1.0, 0.0])
    assert r[0] == pytest.approx(0.9) and np.isnan(r[1:]).all()


def test_propulsive_efficiency_blank_when_windmilling():
    from mdo.plots.figures import propulsive_efficiency, read_csv
    d = read_csv(ROOT / "results" / "ga2p" / "mission.csv")
    eta = propulsive_efficiency(d)
    bl = np.array([s == "BL" for s in d["segment"]])
    assert np.isnan(eta[bl & (d["thrust_N"] < 0)]).all() and (bl & (d["thrust_N"] < 0)).any()
    assert (np.nanmax(eta) <= 1.0) and (np.nanmin(eta) > 0.0)   # 1.43 in the old figure
    assert np.isfinite(eta[[s == "CR" for s in d["segment"]]]).all()


def test_energy_table_efficiency_cells():
    from mdo.vehicle.reports import _efficiency
    assert _efficiency(-0.128, -0.085) == "—"     # GA-2P base leg: printed 1.510 before
    assert _efficiency(-0.165, -0.128) == "—"
    assert _efficiency(-0.05, 0.06) == "—"        # -0.850 with the approach drag device
    assert _efficiency(0.12, 0.10) == "—"         # > 1: a segment mixing forward and backward flow
    assert _efficiency(0.166, 0.215) == "0.772"


@pytest.mark.parametrize("units,length,speed,force", [("si", "(m)", "(m/s)", "(kN)"),
                                                      ("aviation", "(ft)", "(kt)", "(lbf)")])
def test_unit_option_labels_every_axis(monkeypatch, tmp_path, units, length, speed, force):
    from mdo.plots.figures import plot_loading, plot_mission, plot_rotor
    from mdo.plots.geometry import plot_geometry, plot_planform
    run = ROOT / "results" / "ga2p"
    seen = _capture(monkeypatch)
    plot_mission(run / "mission.csv", tmp_path / "m.png", units=units)
    plot_rotor(run, tmp_path / "r.png", units=units)
    plot_loading(run / "loading.csv", tmp_path / "l.png", baseline=run / "analysis" / "loading.csv", units=units)
    plot_geometry(run / "geometry.json", tmp_path / "g.png", units=units)
    plot_planform(run / "geometry.json", tmp_path / "p.png", baseline=run / "analysis" / "geometry.json",
                  units=units)
    mission, rotor, loading, geometry, planform = seen
    assert mission["ylabels"][:2] == [f"altitude {length}", f"airspeed {speed}"]
    assert mission["ylabels"][2] == "power (kW)"
    assert any(force in y for y in rotor["ylabels"]) and "rotor speed (rpm)" in rotor["ylabels"]
    other = ("(m)", "(ft)", "(m/s)", "(kt)", "(kN)", "(lbf)", "(mph)")
    for fig in seen:
        labels = [x for x in fig["ylabels"] + fig["xlabels"]]
        assert all(lab for lab in fig["ylabels"]), fig   # every axis labelled
        assert not any(u in lab for lab in labels for u in other if u not in (length, speed, force)), labels
    assert "ga2p, optimum" in mission["title"] and "(ga2p)" not in mission["title"]
    assert all(lab.startswith("c·cl / c_ref") for lab in loading["ylabels"])


def test_bad_units_is_a_clear_error(tmp_path):
    from mdo.core.errors import InputError
    from mdo.plots.units import unit_system
    with pytest.raises(InputError, match="units: got 'imperial'; allowed: si, aviation"):
        unit_system("imperial")
    r = subprocess.run([sys.executable, "-m", "mdo.cli", "plot", str(ROOT / "results" / "ga2p"), "--units",
                        "imperial"], capture_output=True, text=True)
    assert r.returncode == 2 and "--units" in r.stderr


def test_integer_ticks_and_problem_title(monkeypatch, tmp_path):
    from mdo.plots.convergence import plot_convergence
    run = tmp_path / "analysis"
    shutil.copytree(ROOT / "results" / "ga2p" / "analysis", run)
    seen = _capture(monkeypatch)
    plot_convergence(run / "ipopt.log", tmp_path / "c.png")   # 3 iterations
    ticks = [t for t in seen[0]["xticks"][1] if 0 <= t <= 3]
    assert ticks and all(float(t).is_integer() for t in ticks)
    assert seen[0]["title"] == "IPOPT convergence: ga2p, baseline design (analysis)"


def test_loading_marks_propellers_on_their_wing():
    from mdo.plots.geometry import read_geometry, rotor_surfaces
    for name, wing in (("ga2p", "main_wing"), ("ttw/analysis", None)):
        g = read_geometry(ROOT / "results" / name / "geometry.json")
        rs = rotor_surfaces(g)
        assert rs and all(s is not None for s, _, _ in rs)
        if wing:
            assert {s for s, _, _ in rs} == {wing}
    ttw = rotor_surfaces(read_geometry(ROOT / "results" / "ttw" / "analysis" / "geometry.json"))
    assert {s for s, _, _ in ttw} == {"main_wing", "tandem_wing"}   # two rotors on each tandem wing half


def test_design_checks_flag_thin_blade(tmp_path):
    from mdo.plots.checks import design_checks, write_design_checks
    run = tmp_path / "ga2p"
    shutil.copytree(ROOT / "results" / "ga2p", run)
    # a slender blade: the committed blade with its chords scaled to c/R 0.03 at 0.75 R
    rows = (run / "blade.csv").read_text().splitlines()
    head, data = rows[0], [r.split(",") for r in rows[1:]]
    r_R = np.array([float(d[0]) for d in data])
    c_R = np.array([float(d[1]) for d in data])
    c_R *= 0.03 / np.interp(0.75, r_R, c_R)
    (run / "blade.csv").write_text("\n".join([head] + [f"{d[0]},{c:.5f},{d[2]}" for d, c in zip(data, c_R)]) + "\n")
    checks = {c["quantity"]: c for c in design_checks(run)}
    c = checks["blade chord c/R at 0.75 R"]
    assert not c["ok"] and c["value"] == pytest.approx(0.03, rel=1e-3)
    W = json.loads((run / "summary.json").read_text())["togw_kg"] * 9.80665 / 14.76
    assert checks["wing loading W/S"]["ok"] and checks["wing loading W/S"]["value"] == pytest.approx(W, rel=1e-3)
    write_design_checks(run)
    once = (run / "summary.md").read_text()
    write_design_checks(run)
    assert (run / "summary.md").read_text() == once and once.count("## Design checks") == 1
    s = json.loads((run / "summary.json").read_text())
    assert any("blade chord" in w for w in s["design_warnings"])
    # a blade inside usual practice is not flagged
    b = (run / "blade.csv").read_text().splitlines()
    rows = [b[0]] + [f"{r.split(',')[0]},0.12,{r.split(',')[2]}" for r in b[1:]]
    (run / "blade.csv").write_text("\n".join(rows) + "\n")
    assert {c["quantity"]: c for c in design_checks(run)}["blade chord c/R at 0.75 R"]["ok"]


def test_design_checks_flag_a_propeller_better_than_any_measured():
    """The best net propulsive efficiency (rotor force along the path x speed / shaft power) is
    checked against the best measured full-scale propellers (0.92, NACA TN 2881): GA-2P's
    optimum cruises at 0.924 and is flagged, its baseline (0.909) is not; the windmilling nodes
    of its descent (thrust and shaft power both negative: ratios above 2) do not count."""
    from mdo.plots.checks import design_checks
    from mdo.plots.figures import read_csv
    key = "best propulsive efficiency (thrusting nodes)"
    opt = {c["quantity"]: c for c in design_checks(ROOT / "results" / "ga2p")}[key]
    base = {c["quantity"]: c for c in design_checks(ROOT / "results" / "ga2p" / "analysis")}[key]
    assert not opt["ok"] and opt["value"] == pytest.approx(0.924, abs=1e-3)
    assert base["ok"] and base["value"] == pytest.approx(0.909, abs=1e-3)
    m = read_csv(ROOT / "results" / "ga2p" / "mission.csv")
    windmilling = (m["thrust_N"] < 0) & (m["shaft_power_W"] < 0)
    assert windmilling.any() and np.max(m["thrust_power_W"][windmilling] / m["shaft_power_W"][windmilling]) > 1


def test_mdo_plot_redraws_geometry_and_planform(tmp_path):
    run = tmp_path / "ga2p"
    shutil.copytree(ROOT / "results" / "ga2p", run)
    for f in ("geometry.png", "planform.png", "report.html", "convergence.csv"):
        (run / f).unlink(missing_ok=True)
    r = subprocess.run([sys.executable, "-m", "mdo.cli", "plot", str(run), "--units", "aviation"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    for f in ("geometry.png", "planform.png", "report.html", "convergence.csv", "mission.png", "loading.png",
              "rotor.png"):
        assert (run / f).exists() and (run / f).stat().st_size > (500 if f.endswith(".csv") else 5_000), f


def test_design_checks_flag_a_cabin_pitched_beyond_a_passenger_airplanes_envelope():
    """The body's attitude over the mission against 15 deg nose-down / 30 deg nose-up (Airbus
    normal-law pitch-attitude protection): the TTW on Table 5's tilt schedule pitched its cabin to
    67 deg in the descent transition and is flagged; with its tilt a control (the default) it is
    not; GA-2P's climbs stay far inside."""
    from mdo.plots.checks import design_checks
    up, down = "most nose-up body attitude", "most nose-down body attitude"
    sched = {c["quantity"]: c for c in design_checks(ROOT / "results" / "ttw" / "tilt_schedule")}
    assert not sched[up]["ok"] and sched[up]["value"] == pytest.approx(67.2, abs=0.1) and sched[up]["high"] == 30
    ttw = {c["quantity"]: c for c in design_checks(ROOT / "results" / "ttw")}
    assert ttw[up]["ok"] and ttw[down]["ok"] and ttw[down]["low"] == -15
    ga = {c["quantity"]: c for c in design_checks(ROOT / "results" / "ga2p")}
    assert ga[up]["ok"] and ga[up]["value"] < 15 and ga[down]["ok"]


def test_design_checks_flag_a_cabin_pitching_faster_than_a_take_off_rotation(tmp_path):
    """The fastest body pitch rate within a segment (``mission.csv`` ``body_pitch_rate_degps``)
    against 3 deg/s, an airliner's take-off rotation; a folder without the column is not checked."""
    from mdo.plots.checks import design_checks
    q = "fastest body pitch rate within a segment"
    (tmp_path / "mission.csv").write_text("segment,node,body_angle_deg,body_pitch_rate_degps\n"
                                          "DT,0,29.5,-0.4\nDT,1,20.0,-6.2\n")
    c = {c["quantity"]: c for c in design_checks(tmp_path)}[q]
    assert not c["ok"] and c["value"] == pytest.approx(6.2) and c["high"] == pytest.approx(3.0)
    (tmp_path / "mission.csv").write_text("segment,node,body_angle_deg\nDT,0,29.5\n")
    assert q not in {c["quantity"] for c in design_checks(tmp_path)}


def test_design_checks_flag_an_optimum_that_hardly_left_its_baseline(tmp_path):
    """An optimization folder's gain over its ``analysis/`` baseline below 2 %: the TTW robustness
    start that stopped 1 % below its baseline (158.06 against 159.64 kWh) is flagged, the committed
    TTW optimum (28 %) is not."""
    from mdo.plots.checks import design_checks
    q = "optimization's gain over its baseline"
    (tmp_path / "analysis").mkdir()
    for d, mode, f in ((tmp_path, "optimization", 158.06), (tmp_path / "analysis", "analysis", 159.64)):
        (d / "summary.json").write_text(json.dumps({"mode": mode, "success": True,
                                                    "objective": {"value": f, "unit": "kWh"}}))
    c = {c["quantity"]: c for c in design_checks(tmp_path)}[q]
    assert not c["ok"] and c["value"] == pytest.approx(100 * (1 - 158.06 / 159.64))
    ttw = {c["quantity"]: c for c in design_checks(ROOT / "results" / "ttw")}[q]
    assert ttw["ok"] and ttw["value"] > 20
