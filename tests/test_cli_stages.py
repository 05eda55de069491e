"""`mdo run` on an optimization: the baseline analysis first, then the optimization
warm-started from it (DESIGN rule 7), in one command."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
POLAR = ROOT / "problems" / "polar_ga_mission.py"


def _mdo(*args):
    return subprocess.run([sys.executable, "-m", "mdo.cli", *map(str, args)], capture_output=True, text=True)


def _summary(folder):
    return json.loads((folder / "summary.json").read_text())


def _run_polar(out, capsys):
    """``mdo run`` of the polar GA problem with its wing area free, into ``out``; asserts exit 0."""
    from mdo import cli

    code = cli.main(["run", str(POLAR), "-o", "design_wing_area=true", "--out", str(out), "--quiet"])
    assert code == 0, capsys.readouterr().err
    return out


def test_optimization_runs_its_baseline_first(tmp_path):
    out = tmp_path / "run"
    r = _mdo("run", POLAR, "-o", "design_wing_area=true", "--out", out, "--quiet")
    assert r.returncode == 0, r.stderr
    assert "stage 1 of 2" in r.stdout and "stage 2 of 2" in r.stdout
    base, opt = _summary(out / "analysis"), _summary(out)
    assert base["status"] == opt["status"] == "Solve_Succeeded"
    # the baseline is the fixed-wing-area mission; the optimum resizes the wing and uses less
    assert opt["battery_energy_kWh"] < base["battery_energy_kWh"] - 1.0
    # the analysis folder is the same as `--analysis` gives
    r2 = _mdo("run", POLAR, "-o", "design_wing_area=true", "--analysis", "--out", tmp_path / "an", "--quiet")
    assert r2.returncode == 0, r2.stderr
    assert abs(_summary(tmp_path / "an")["battery_energy_kWh"] - base["battery_energy_kWh"]) < 1e-6


def test_no_baseline_and_problems_without_design_run_one_stage(tmp_path):
    r = _mdo("run", POLAR, "-o", "design_wing_area=true", "--out", tmp_path / "a", "--quiet", "--no-baseline")
    assert r.returncode == 0, r.stderr
    assert not (tmp_path / "a" / "analysis").exists() and "stage" not in r.stdout
    r = _mdo("run", POLAR, "--out", tmp_path / "b", "--quiet")   # no design variables
    assert r.returncode == 0, r.stderr
    assert not (tmp_path / "b" / "analysis").exists()
    # and it says what it is: an analysis, not an "optimization" (issue 23)
    assert json.loads((tmp_path / "b" / "summary.json").read_text())["mode"] == "analysis"
    assert (tmp_path / "b" / "summary.md").read_text().startswith("# polar_ga_mission: analysis")
    assert json.loads((tmp_path / "a" / "summary.json").read_text())["mode"] == "optimization"


def test_an_earlier_baseline_is_not_overwritten_unasked(tmp_path):
    out = tmp_path / "run"
    (out / "analysis").mkdir(parents=True)
    (out / "analysis" / "summary.json").write_text("{}")
    r = _mdo("run", POLAR, "-o", "design_wing_area=true", "--out", out, "--quiet")
    assert r.returncode == 2
    assert "--force" in r.stderr and "analysis" in r.stderr
    assert (out / "analysis" / "summary.json").read_text() == "{}"
    assert not (out / "summary.json").exists()


def test_a_failed_monotone_optimization_is_retried_with_the_adaptive_barrier(tmp_path, monkeypatch, capsys):
    """DESIGN rule 7's fallback: when the monotone barrier from the baseline ends without an
    optimum, the optimization starts again from the baseline with the adaptive barrier; the
    failed attempt's files are kept in monotone/ and summary.json says so.  The monotone
    attempt is made to fail here by a CPU-time limit added to its options."""
    from mdo import cli
    from mdo.nlp import ipopt

    monkeypatch.setitem(ipopt.FROM_BASELINE_OPTIONS, "max_cpu_time", 1e-6)
    out = _run_polar(tmp_path / "run", capsys)
    opt, failed = _summary(out), _summary(out / "monotone")
    assert failed["status"] == "Maximum_CpuTime_Exceeded" and failed["barrier"]["mu_strategy"] == "monotone"
    assert opt["status"] == "Solve_Succeeded"
    assert opt["barrier"]["mu_strategy"] == "adaptive"
    assert opt["barrier"]["fallback_from"]["status"] == "Maximum_CpuTime_Exceeded"
    assert opt["barrier"]["fallback_from"]["folder"] == "monotone"
    assert "after the monotone barrier ended" in (out / "summary.md").read_text()
    assert (out / "analysis" / "summary.json").exists() and (out / "monotone" / "ipopt.log").exists()
    # the same optimum as the monotone barrier finds when it is not stopped
    monkeypatch.delitem(ipopt.FROM_BASELINE_OPTIONS, "max_cpu_time")
    code = cli.main(["run", str(POLAR), "-o", "design_wing_area=true", "--out", str(tmp_path / "m"), "--quiet"])
    assert code == 0
    mono = _summary(tmp_path / "m")
    assert mono["barrier"] == {"mu_strategy": "monotone", "mu_init": ipopt.FROM_BASELINE_OPTIONS["mu_init"]}
    assert abs(mono["battery_energy_kWh"] - opt["battery_energy_kWh"]) < 1e-4 * mono["battery_energy_kWh"]


def test_a_wandering_monotone_attempt_is_given_up_early(tmp_path, monkeypatch, capsys):
    """The DivergenceWatch stops the monotone attempt (here at once: a watch that any dual
    infeasibility trips) instead of letting it run to its iteration limit; the fallback
    then converges and summary.json says why the first attempt stopped."""
    from mdo.nlp import ipopt, problem as problem_mod

    monkeypatch.setattr(problem_mod, "DivergenceWatch",
                        lambda: ipopt.DivergenceWatch(after_iter=1, inf_du_max=-1.0, run=1))
    out = _run_polar(tmp_path / "run", capsys)
    opt, failed = _summary(out), _summary(out / "monotone")
    assert failed["status"] == "User_Requested_Stop" and failed["iterations"] <= 3
    assert "dual infeasibility above -1" in failed["stopped_because"]
    assert opt["status"] == "Solve_Succeeded" and "stopped_because" not in opt
    assert opt["barrier"]["fallback_from"]["stopped_because"] == failed["stopped_because"]
    assert "dual infeasibility above" in (out / "summary.md").read_text()


def test_a_problem_may_try_the_adaptive_barrier_first(tmp_path, monkeypatch, capsys):
    """Problem.barrier_order = ("adaptive", "monotone") (the TTW's): the adaptive attempt is the
    watched first one; when it fails (here the watch trips at once) its files are kept in
    adaptive/ and the monotone barrier converges from the baseline."""
    from mdo.nlp import ipopt, problem as problem_mod

    first_attempt = problem_mod.Problem.start_from_baseline

    def adaptive_first(self):
        self.barrier_order = ("adaptive", "monotone")
        return first_attempt(self)

    monkeypatch.setattr(problem_mod.Problem, "start_from_baseline", adaptive_first)
    monkeypatch.setattr(problem_mod, "DivergenceWatch",
                        lambda: ipopt.DivergenceWatch(after_iter=1, inf_du_max=-1.0, run=1))
    out = _run_polar(tmp_path / "run", capsys)
    opt, failed = _summary(out), _summary(out / "adaptive")
    assert failed["status"] == "User_Requested_Stop" and failed["barrier"]["mu_strategy"] == "adaptive"
    assert opt["status"] == "Solve_Succeeded"
    assert opt["barrier"]["mu_strategy"] == "monotone"
    assert opt["barrier"]["mu_init"] == ipopt.FROM_BASELINE_OPTIONS["mu_init"]
    assert opt["barrier"]["fallback_from"]["folder"] == "adaptive"
    assert not (out / "monotone").exists()


def test_barrier_order_names_two_different_barriers():
    from mdo.core.errors import InputError
    from mdo.nlp import Problem

    p = Problem("order")
    p.barrier_order = ("adaptive", "adaptive")
    with pytest.raises(InputError, match="barrier_order"):
        p.start_from_baseline()


def test_divergence_watch_reads_the_log_as_written(tmp_path):
    from mdo.nlp.ipopt import Diverging, DivergenceWatch

    log = tmp_path / "ipopt.log"
    head = "iter    objective    inf_pr   inf_du lg(mu)  ||d||  lg(rg) alpha_du alpha_pr  ls\n"
    rows = [f"{i:4d}{'r' if i % 7 == 0 else ' '} 1.0e+00 1.0e-03 {du:.2e}  -2.0 1.0e+00    -  1.0e+00 1.0e+00f  1\n"
            for i, du in enumerate([1.0] * 100 + [1e5] * 9 + [10.0] + [1e6] * 10)]
    w = DivergenceWatch(after_iter=100, inf_du_max=1e4, run=10)
    log.write_text(head + "".join(rows[:110]))
    w.check(log, 110)                       # nine large, then one small: not ten in a row
    log.write_text(head + "".join(rows[:119]))
    w.check(log, 119)                       # nine of the last ten
    log.write_text(head + "".join(rows))
    with pytest.raises(Diverging):
        w.check(log, 120)
    assert "iteration 119" in w.reason
    assert DivergenceWatch().check(tmp_path / "missing.log", 500) is None


def test_divergence_watch_gives_up_a_barrier_stalled_at_its_start(tmp_path):
    """An adaptive barrier still at mu 0.1 (lg -1.0) for 20 iterations after iteration 20 is given
    up (the TTW from a perturbed design, 2026-12-06); one that leaves it, or a monotone barrier at
    mu 1e-4, is not."""
    from mdo.nlp.ipopt import Diverging, DivergenceWatch

    log = tmp_path / "ipopt.log"
    head = "iter    objective    inf_pr   inf_du lg(mu)  ||d||  lg(rg) alpha_du alpha_pr  ls\n"

    def write(lg_mu):
        log.write_text(head + "".join(f"{i:4d}  1.0e+00 1.0e-01 1.00e+02 {m:5.1f} 1.0e+00    -  1.0e+00 1.0e-02h  1\n"
                                      for i, m in enumerate(lg_mu)))

    w = DivergenceWatch()
    write([-1.0] * 40)
    w.check(log, 39)                        # iterations 20-39: not all after iteration 20
    write([-1.0] * 41)
    with pytest.raises(Diverging):
        w.check(log, 40)
    assert "lg(mu) >= -1.2" in w.reason and "iteration 40" in w.reason
    write([-1.0] * 50 + [-1.6] + [-1.0] * 10)  # left it within the last 20
    DivergenceWatch().check(log, 60)
    write([-4.0] * 61)                         # a monotone barrier at mu 1e-4
    DivergenceWatch().check(log, 60)


def test_an_optimization_starts_from_a_given_baseline_folder(tmp_path, capsys):
    """--from-baseline DIR: stage 1 is the user's converged analysis, copied (the original
    untouched); the optimization then equals the one that solved its own baseline."""
    from mdo import cli

    base = tmp_path / "base"
    assert cli.main(["run", str(POLAR), "-o", "design_wing_area=true", "--analysis", "--out", str(base),
                     "--quiet"]) == 0
    before = (base / "solution.json").read_bytes()
    out = tmp_path / "opt"
    code = cli.main(["run", str(POLAR), "-o", "design_wing_area=true", "--from-baseline", str(base),
                     "--out", str(out), "--quiet"])
    assert code == 0, capsys.readouterr().err
    assert (base / "solution.json").read_bytes() == before
    assert (out / "analysis" / "solution.json").read_bytes() == before
    opt = _summary(out)
    assert opt["mode"] == "optimization" and opt["barrier"]["mu_strategy"] == "monotone"
    ref = tmp_path / "ref"
    assert cli.main(["run", str(POLAR), "-o", "design_wing_area=true", "--out", str(ref), "--quiet"]) == 0
    assert abs(opt["battery_energy_kWh"] - _summary(ref)["battery_energy_kWh"]) < 1e-6 * opt["battery_energy_kWh"]
    # bad input: one line, exit 2, nothing created
    for extra, text in ((["--from-baseline", str(out)], "not a converged baseline analysis"),
                        (["--from-baseline", str(tmp_path / "none")], "--from-baseline"),
                        (["--from-baseline", str(base), "--analysis"], "not with --analysis")):
        code = cli.main(["run", str(POLAR), "-o", "design_wing_area=true", "--out", str(tmp_path / "x"),
                         "--quiet", *extra])
        assert code == 2 and text in capsys.readouterr().err
        assert not (tmp_path / "x").exists()


def test_the_baselines_figures_are_drawn_during_stage_2_and_waited_for(tmp_path, monkeypatch):
    """Stage 1's figures are drawn by a forked child while stage 2 runs; the run folder is
    moved into place only after the child ended, with the same files as drawn in process."""
    from mdo import cli
    from mdo.nlp import run as run_mod

    forked = []
    orig = run_mod._fork_figures
    monkeypatch.setattr(run_mod, "_fork_figures", lambda *a: forked.append(orig(*a)) or forked[-1])
    out = tmp_path / "bg"
    assert cli.main(["run", str(POLAR), "-o", "design_wing_area=true", "--out", str(out), "--quiet"]) == 0
    assert forked == [True] and run_mod._BACKGROUND == []          # one child, and it was waited for
    monkeypatch.setenv("MDO_FIGURES_IN_PROCESS", "1")
    ref = tmp_path / "fg"
    assert cli.main(["run", str(POLAR), "-o", "design_wing_area=true", "--out", str(ref), "--quiet"]) == 0
    assert forked == [True, False]
    names = sorted(p.name for p in (ref / "analysis").iterdir())
    assert "report.html" in names and any(n.endswith(".png") for n in names)
    assert sorted(p.name for p in (out / "analysis").iterdir()) == names
    for p in (out / "analysis").iterdir():
        assert p.stat().st_size > 0


def test_solve_into_names_a_wrong_figures_value(tmp_path):
    from mdo.core.errors import InputError
    from mdo.nlp.run import load_problem_file, solve_into
    p = load_problem_file(POLAR, analysis=True)
    with pytest.raises(InputError, match="figures"):
        solve_into(p, tmp_path / "x", figures="later")
    assert not (tmp_path / "x").exists()          # refused before anything is written


def test_divergence_watch_gives_up_a_hessian_held_far_from_convex(tmp_path):
    """Seven iterations in a row with an inertia correction of 1e7 or more are given up (TTW
    attempts that reached their timeouts held it for 8-9, at a minute per iteration); the
    committed converged runs hold it at most 5, and iterations without a correction ("-") or
    with a small one break the run."""
    from mdo.nlp.ipopt import Diverging, DivergenceWatch

    log = tmp_path / "ipopt.log"
    head = "iter    objective    inf_pr   inf_du lg(mu)  ||d||  lg(rg) alpha_du alpha_pr  ls\n"

    def write(lg_rg):
        log.write_text(head + "".join(f"{i:4d}  1.0e+00 1.0e-01 1.00e+02  -4.0 1.0e+00 {rg:>6} 1.0e+00 1.0e-02h  1\n"
                                      for i, rg in enumerate(lg_rg)))

    write(["-"] * 10 + ["8.5"] * 6)
    DivergenceWatch().check(log, 15)                      # six in a row: not yet
    write(["-"] * 10 + ["8.5"] * 3 + ["6.9"] + ["9.7"] * 6)
    DivergenceWatch().check(log, 19)                      # broken by one below 1e7
    write(["-"] * 10 + ["8.5"] * 3 + ["-"] + ["9.7"] * 6)
    DivergenceWatch().check(log, 19)                      # broken by one without a correction
    w = DivergenceWatch()
    write(["-"] * 10 + ["7.0"] * 7)
    with pytest.raises(Diverging):
        w.check(log, 16)
    assert "lg(rg) >= 7" in w.reason and "iteration 16" in w.reason
