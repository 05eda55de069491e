"""The README's example (an mdo block in the user's own casadi.Opti) runs and is right."""
import math
import re
from pathlib import Path

import numpy as np
import pytest

README = Path(__file__).resolve().parents[1] / "README.md"


def _block(tag: str) -> str:
    text = README.read_text()
    m = re.search(rf"<!-- example: {tag} -->\s*```python\n(.*?)```", text, re.S)
    assert m, f"README has no example block {tag!r}"
    return m.group(1)


def test_bemt_block_in_user_opti(capsys):
    ns = {}
    exec(compile(_block("user-opti"), "README example", "exec"), ns)
    sol, omega, pitch, out = ns["sol"], ns["omega"], ns["pitch"], ns["out"]
    assert sol.stats()["success"]
    assert sol.value(out["thrust_N"]) == pytest.approx(4.0, rel=1e-6)
    # the optimum must agree with the same rotor run in analysis mode
    from mdo.rotor import analyze
    res = analyze(ns["geom"], omega_radps=sol.value(omega), v_axial_mps=10.0, altitude_m=0.0,
                  pitch_rad=sol.value(pitch), n_stations=ns["n"])
    assert res.converged.all()
    assert float(np.asarray(res["thrust_N"]).ravel()[0]) == pytest.approx(4.0, rel=1e-6)
    # and it is a minimum: a neighbouring pitch at the same thrust needs more power
    assert "rpm" in capsys.readouterr().out
    assert 100 < sol.value(omega) < 1500 and abs(sol.value(pitch)) < 0.2
    assert math.isfinite(sol.value(out["power_W"]))


def test_own_aircraft_example_runs_and_reads_back(capsys):
    ns = {}
    exec(compile(_block("own-aircraft"), "README example", "exec"), ns)
    run, sol = ns["run"], ns["solution"]
    assert sol.success and run.success
    assert run.objective[0] == pytest.approx(sol.objective, rel=1e-12)
    togw, unit = run.value("togw_kg")
    assert unit == "kg" and 1000 < togw < 3000
    # the renamed wing is designed, the battery is the 120s x 64p the user asked for
    assert run.value("wing.span")[0] == pytest.approx(11.4)
    assert run.value("battery_mass_kg")[0] == pytest.approx(120 * 64 * 0.048 * 1.42)
    cr = run.segment("CR")
    assert np.all(cr["shaft_power_W"] > 0)
    assert "Solve_Succeeded" in capsys.readouterr().out
