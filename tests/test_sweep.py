"""mdo sweep: grid parsing and checks, resume and fault rules, the table, and the acceptance
test — a sweep on a local Dask cluster of 2 workers equals the same points run alone by
``mdo run`` (objective to 1e-8 relative)."""
import json
from pathlib import Path

import pytest

from mdo.cli import main
from mdo.core.errors import InputError
from mdo.sweep.grid import check_keys, expand, parse_grid, point_name, structural_keys
from mdo.sweep.point import finished, point_status
from mdo.sweep.runner import nearest_neighbour
from mdo.sweep.table import read_table

ROOT = Path(__file__).resolve().parents[1]
BRACH = ROOT / "tests" / "problems" / "brachistochrone.py"


# ---------------------------------------------------------------- grid
def test_parse_grid_and_expand_in_build_order():
    grid = parse_grid(["final_y=4.0,5.5", "nodes=8,12"])
    assert grid == {"final_y": [4.0, 5.5], "nodes": [8, 12]}
    pts = expand(grid, ["nodes", "analysis", "final_y"])
    assert [point_name(p) for p in pts] == ["nodes=8,final_y=4.0", "nodes=8,final_y=5.5",
                                            "nodes=12,final_y=4.0", "nodes=12,final_y=5.5"]
    assert structural_keys(grid) == ["nodes"]          # ints may change the NLP's size
    assert parse_grid(["mode=a,b"]) == {"mode": ["a", "b"]}


@pytest.mark.parametrize("items, text", [
    ([], "empty grid"), (["nodes"], "KEY=V1"), (["nodes="], "empty value"), (["nodes=1,,2"], "empty value"),
    (["nodes=1,1"], "repeated"), (["nodes=1", "nodes=2"], "twice"), (["a b=1"], "identifier"),
    (["mode=a/b"], "plain word")])
def test_parse_grid_rejects(items, text):
    with pytest.raises(InputError, match=text):
        parse_grid(items)


def test_check_keys_against_build_signature():
    check_keys({"nodes": [1]}, ["analysis", "nodes", "final_y"], {"final_y": 5.0})
    with pytest.raises(InputError, match="unknown key 'span'.*nodes, final_y"):
        check_keys({"span": [1]}, ["analysis", "nodes", "final_y"])
    with pytest.raises(InputError, match="analysis"):
        check_keys({"analysis": [True]}, ["analysis", "nodes"])
    with pytest.raises(InputError, match="also a --grid key"):
        check_keys({"nodes": [1]}, ["nodes"], {"nodes": 2})
    check_keys({"anything": [1]}, ["**"])                 # build(**options) takes any key


def test_nearest_neighbour_keeps_structural_keys():
    grid = {"nodes": [8, 12], "final_y": [4.0, 5.0, 6.0]}
    done = [{"point": {"nodes": 12, "final_y": 6.0}}, {"point": {"nodes": 8, "final_y": 4.0}}]
    assert nearest_neighbour({"nodes": 12, "final_y": 4.0}, done, grid) is done[0]
    assert nearest_neighbour({"nodes": 8, "final_y": 6.0}, done, grid) is done[1]
    assert nearest_neighbour({"nodes": 8, "final_y": 6.0}, done[:1], grid) is None


# ---------------------------------------------------------------- bad input: exit 2, nothing started
@pytest.mark.parametrize("argv, text", [
    (["--grid", "span=1,2"], "unknown key 'span'"),
    ([], "empty grid"),
    (["--grid", "final_y=4.0", "--scheduler", "tcp://127.0.0.1:9", "--scheduler-timeout", "1"],
     "no Dask scheduler reachable"),
    (["--grid", "final_y=4.0", "--point-timeout", "0"], "--point-timeout: must be > 0 seconds"),
])
def test_bad_input_one_line_exit_2(tmp_path, capsys, argv, text):
    out = tmp_path / "sw"
    assert main(["sweep", str(BRACH), "--out", str(out), *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and text in err[0]
    assert not out.exists()                               # nothing started


# ---------------------------------------------------------------- resume and faults
def test_finished_needs_a_complete_summary(tmp_path):
    d = tmp_path / "p"
    (d / "analysis").mkdir(parents=True)
    (d / "analysis" / "summary.json").write_text(json.dumps({"status": "Solve_Succeeded", "objective": {}}))
    assert not finished(d)                                # killed during the optimization stage
    (d / "summary.json").write_text('{"status": "Solve_Succ')
    assert not finished(d) and point_status(d) == "not run"   # killed while writing
    (d / "summary.json").write_text(json.dumps({"status": "Solve_Succeeded", "objective": {"value": 1}}))
    assert finished(d)
    e = tmp_path / "q"
    (tmp_path / ".points").mkdir()
    (tmp_path / ".points" / "q.json").write_text(json.dumps({"returncode": -9}))
    assert not finished(e) and point_status(e) == "crashed (exit -9)"   # lost: run again
    (tmp_path / ".points" / "q.json").write_text(json.dumps({"returncode": 2}))
    assert finished(e) and point_status(e) == "input error"             # ended by itself: kept


def test_failed_point_does_not_stop_the_others_and_resume_skips(tmp_path, capsys):
    out = tmp_path / "sw"
    # nodes=1 cannot be collocated: that point fails in build(), the other runs
    code = main(["sweep", str(BRACH), "--grid", "nodes=1,8", "--out", str(out), "--workers", "0"])
    assert code == 1
    rows = {r["point"]: r for r in read_table(out / "sweep.csv")}
    assert rows["nodes=8"]["status"] == "Solve_Succeeded" and rows["nodes=8"]["success"] is True
    assert rows["nodes=1"]["status"] == "input error" and rows["nodes=1"]["success"] is False
    assert "nodes=1: input error" in capsys.readouterr().out
    stamp = (out / ".points" / "nodes=8.json").stat().st_mtime_ns
    assert main(["sweep", str(BRACH), "--grid", "nodes=1,8", "--out", str(out), "--workers", "0"]) == 1
    assert "2 already finished, 0 to run" in capsys.readouterr().out
    assert (out / ".points" / "nodes=8.json").stat().st_mtime_ns == stamp


def test_a_point_past_its_time_budget_is_stopped_kept_and_not_rerun(tmp_path, capsys):
    """--point-timeout: a point still running when its budget is spent is killed and recorded as
    stopped, with its log; the sweep goes on, and a resume does not run it again."""
    out = tmp_path / "sw"
    argv = ["sweep", str(BRACH), "--grid", "final_y=4.0", "--out", str(out), "--workers", "0",
            "--point-timeout", "0.2"]                      # an `mdo run` needs seconds to import
    assert main(argv) == 1
    row = read_table(out / "sweep.csv")[0]
    assert row["status"] == "stopped after 0.2 s (--point-timeout)" and row["success"] is False
    assert "stopped after 0.2 s" in (out / ".points" / "final_y=4.0.log").read_text()
    capsys.readouterr()
    assert main(argv) == 1
    assert "1 already finished, 0 to run" in capsys.readouterr().out


# ---------------------------------------------------------------- acceptance
def test_sweep_on_two_workers_equals_mdo_run_alone(tmp_path, capsys):
    out = tmp_path / "sw"
    values = [4.0, 5.0, 6.0]
    code = main(["sweep", str(BRACH), "--grid", "final_y=" + ",".join(map(str, values)), "-o", "nodes=12",
                 "--out", str(out), "--workers", "2"])
    assert code == 0, capsys.readouterr()
    rows = {r["final_y"]: r for r in read_table(out / "sweep.csv")}
    assert sorted(rows) == values
    for y in values:
        alone = tmp_path / f"alone_{y}"
        assert main(["run", str(BRACH), "--out", str(alone), "--quiet", "-o", "nodes=12", "-o", f"final_y={y}"]) == 0
        ref = json.loads((alone / "summary.json").read_text())
        got = json.loads((out / f"final_y={y}" / "summary.json").read_text())
        assert got["objective"]["value"] == pytest.approx(ref["objective"]["value"], rel=1e-8)
        assert rows[y]["objective"] == pytest.approx(ref["objective"]["value"], rel=1e-8)
        assert rows[y]["iterations"] == ref["iterations"]
        assert rows[y]["final_time"] == pytest.approx(ref["final_time_s"], rel=1e-8)   # design variable column
    # the minimum time grows with the drop shortened: 4 m -> 6 m end height
    assert rows[4.0]["objective"] < rows[5.0]["objective"] < rows[6.0]["objective"]
    png = out / "objective_vs_final_y.png"
    assert main(["sweep", "plot", str(out), "--x", "final_y"]) == 0 and png.stat().st_size > 1000


def test_carpet_and_line_plots_from_a_table(tmp_path):
    """Plots read only sweep.csv and sweep.json: a table of 2 x 3 points, one not converged."""
    from mdo.sweep.plot import carpet_plot, line_plot
    grid = {"distance": [50.0, 100.0], "cells": [60, 80, 100]}
    (tmp_path / "sweep.json").write_text(json.dumps({"problem": "x.py", "grid": grid}))
    lines = ["point,distance,cells,status,success,objective,objective_name,objective_unit,togw_kg"]
    for d in grid["distance"]:
        for c in grid["cells"]:
            ok = not (d == 100.0 and c == 60)
            lines.append(f'"distance={d},cells={c}",{d},{c},{"Solve_Succeeded" if ok else "Infeasible"},'
                         f"{ok},{d * 0.4 + c * 0.01 if ok else ''},energy,kWh,{1500 + 5 * c}")
    (tmp_path / "sweep.csv").write_text("\n".join(lines) + "\n")
    assert carpet_plot(tmp_path, "distance", "cells").stat().st_size > 1000
    assert line_plot(tmp_path, "cells", "togw_kg").stat().st_size > 1000
    with pytest.raises(InputError, match="no column 'mass'"):
        line_plot(tmp_path, "cells", "mass")
    with pytest.raises(InputError, match="not a grid key"):
        carpet_plot(tmp_path, "distance", "speed")


# ---------------------------------------------------------------- threads per point
@pytest.mark.parametrize("argv, expected", [
    (["--workers", "0"], None),                   # serial: mdo run's own default
    (["--workers", "2"], "1"),                    # one core per Dask worker
    (["--workers", "2", "--threads", "2"], "2"),  # the user's choice wins
])
def test_points_on_dask_workers_use_one_thread(tmp_path, monkeypatch, argv, expected):
    import mdo.sweep.cli as sweep_cli
    import mdo.sweep.runner as runner
    seen = {}
    monkeypatch.setattr(runner, "connect", lambda *a, **k: None)   # no cluster for this check
    monkeypatch.setattr(sweep_cli, "_run", lambda args, grid, points, out, fixed, run_args, client:
                        seen.setdefault("run_args", list(run_args)) and 0)
    main(["sweep", str(BRACH), "--out", str(tmp_path / "sw"), "--grid", "final_y=4.0", *argv])
    ra = seen["run_args"]
    assert (ra[ra.index("--threads") + 1] if "--threads" in ra else None) == expected
