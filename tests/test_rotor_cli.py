"""``mdo rotor sweep`` / ``mdo rotor design`` and the geometry input checks."""
import math

import numpy as np
import pytest

from mdo.cli import main
from mdo.core import InputError
from mdo.rotor import RotorGeometry
from mdo.rotor.cli import parse_range
from mdo.rotor.geometry import DATA_DIR

APC = str(DATA_DIR / "apce_10x7_geometry.csv")
SWEEP = ["rotor", "sweep", "--geometry", APC, "--diameter", "0.254", "--blades", "2", "--airfoil", "analytic",
         "--rpm", "5000", "--J", "0:0.8:0.2"]


def _run(argv, capsys):
    code = main(argv)
    out = capsys.readouterr()
    return code, out.out, out.err


def test_sweep_writes_the_columns(capsys, tmp_path):
    code, out, err = _run(SWEEP, capsys)
    assert code == 0, err
    lines = out.strip().splitlines()
    assert lines[0] == "J,CT,CP,eta,T_N,P_W,Q_Nm"
    data = np.array([[float(v) if v else np.nan for v in line.split(",")] for line in lines[1:]])
    np.testing.assert_allclose(data[:, 0], [0, 0.2, 0.4, 0.6, 0.8])
    # efficiency blank exactly where thrust or power <= 0 (issue 23), a number in [0, 1) elsewhere
    undefined = (data[:, 4] <= 0) | (data[:, 5] <= 0)
    assert np.array_equal(np.isnan(data[:, 3]), undefined)
    assert np.all((data[~undefined, 3] >= 0) & (data[~undefined, 3] < 1))
    n = 5000 / 60
    rho = 1.225
    # CT, CP consistent with T, P in SI
    np.testing.assert_allclose(data[:, 1], data[:, 4] / (rho * n ** 2 * 0.254 ** 4), rtol=1e-3)
    np.testing.assert_allclose(data[:, 2], data[:, 5] / (rho * n ** 3 * 0.254 ** 5), rtol=1e-3)
    np.testing.assert_allclose(data[:, 5], data[:, 6] * 2 * math.pi * n, rtol=1e-4)
    out_file = tmp_path / "s.csv"
    code, _, _ = _run(SWEEP + ["--out", str(out_file)], capsys)
    assert code == 0 and out_file.read_text().splitlines()[0] == "J,CT,CP,eta,T_N,P_W,Q_Nm"


def test_design_then_sweep_round_trip(capsys, tmp_path):
    geo = tmp_path / "prop.csv"
    code, _, err = _run(["rotor", "design", "--diameter", "1.94", "--blades", "3", "--speed", "60.35",
                         "--thrust", "900", "--tip-mach", "0.6", "--airfoil", "analytic", "--altitude", "762",
                         "--out", str(geo)], capsys)
    assert code == 0, err
    assert geo.read_text().splitlines()[0] == "r_over_R,c_over_R,beta_deg"
    g = RotorGeometry.from_csv(geo, diameter_m=1.94, blades=3, hub_fraction=0.12, airfoil="analytic")
    from mdo.core import speed_of_sound
    rpm = 0.6 * float(speed_of_sound(762.0)) * 30 / (math.pi * 0.97)   # tip Mach 0.6 at 762 m
    J = 60.35 / (rpm / 60 * 1.94)
    code, out, err = _run(["rotor", "sweep", "--geometry", str(geo), "--diameter", "1.94", "--blades", "3",
                           "--airfoil", "analytic", "--hub-fraction", "0.12", "--rpm", f"{rpm:.6f}",
                           "--J", f"{J:.6f}:{J:.6f}:0.1", "--altitude", "762"], capsys)
    assert code == 0, err
    T = float(out.splitlines()[1].split(",")[4])
    assert abs(T / 900.0 - 1) < 0.01            # design thrust recovered through the CSV round trip


@pytest.mark.parametrize("extra,field", [
    (["--diameter", "0"], "--diameter"),
    (["--diameter", "-0.3"], "--diameter"),
    (["--hub-fraction", "1.0"], "--hub-fraction: a number in (0, 1)"),
    (["--hub-fraction", "0"], "--hub-fraction: a number in (0, 1)"),
    (["--airfoil", "no_such_airfoil"], "airfoil"),
    (["--rpm", "60000"], "tip Mach"),
    (["--rpm", "-5"], "--rpm"),
    (["--J", "0.5:0.1:0.1"], "--J"),
    (["--J", "0:1:0"], "--J"),
    (["--J", "a:b:c"], "--J"),
    (["--blades", "0"], "--blades"),
])
def test_sweep_bad_input_exits_2(extra, field, capsys):
    code, out, err = _run(SWEEP + extra, capsys)
    assert code == 2
    assert field in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("text,field", [
    ("r_over_R,c_over_R,beta_deg\n0.2,0.1,30\n0.6,0.0,20\n1.0,0.05,10\n", "c_over_R"),
    ("r_over_R,c_over_R,beta_deg\n0.2,0.1,30\n0.6,-0.1,20\n1.0,0.05,10\n", "c_over_R"),
    ("r_over_R,chord\n0.2,0.1\n1.0,0.1\n", "--geometry"),
    ("r_over_R,c_over_R,beta_deg\n0.2,0.1,abc\n1.0,0.05,10\n", "--geometry"),
    ("r_over_R,c_over_R,beta_deg\n0.2,0.1\n1.0,0.05,10\n", "--geometry"),
    ("r_over_R,c_over_R,beta_deg\n0.6,0.1,30\n0.3,0.05,10\n1.0,0.05,10\n", "r_over_R"),
    ("", "--geometry"),
])
def test_malformed_geometry_csv(text, field, tmp_path, capsys):
    f = tmp_path / "g.csv"
    f.write_text(text)
    argv = list(SWEEP)
    argv[argv.index(APC)] = str(f)
    code, _, err = _run(argv, capsys)
    assert code == 2 and field in err


def test_geometry_checks_in_python():
    kw = dict(radius_m=1.0, blades=3, r_over_R=[0.2, 0.6, 1.0], chord_over_R=[0.1, 0.1, 0.05],
              beta_rad=np.radians([30, 20, 10]))
    RotorGeometry(**kw)
    with pytest.raises(InputError, match="radius_m"):
        RotorGeometry(**{**kw, "radius_m": 0.0})
    with pytest.raises(InputError, match="blades"):
        RotorGeometry(**{**kw, "blades": 2.5})
    with pytest.raises(InputError, match="hub_fraction"):
        RotorGeometry(**kw, hub_fraction=1.0)
    with pytest.raises(InputError, match="rotation"):
        RotorGeometry(**kw, rotation=2)
    with pytest.raises(InputError, match="beta"):
        RotorGeometry(**{**kw, "beta_rad": np.radians([95, 20, 10])})


def test_parse_range_includes_stop():
    np.testing.assert_allclose(parse_range("0:2:0.05")[[0, -1]], [0.0, 2.0])
    assert parse_range("0.3:0.3:0.1").size == 1


def test_sweep_accepts_a_radial_distribution_and_stall_delay(capsys):
    i = SWEEP.index("--airfoil")
    argv = SWEEP[:i + 1] + ["naca4412:0.4:clark_y:0.8:e63+du_selig"] + SWEEP[i + 2:]
    code, out, err = _run(argv, capsys)
    assert code == 0, err
    assert len(out.strip().splitlines()) == 6


def test_sweep_unknown_section_in_distribution_exits_2(capsys):
    i = SWEEP.index("--airfoil")
    code, out, err = _run(SWEEP[:i + 1] + ["naca4412:0.4:nosuch"] + SWEEP[i + 2:], capsys)
    assert code == 2 and "airfoil" in err


def test_sweep_accepts_a_distribution_width(capsys):
    i = SWEEP.index("--airfoil")
    code, out, err = _run(SWEEP[:i + 1] + ["naca4412:0.4:clark_y:0.8:e63;width=0.01"] + SWEEP[i + 2:], capsys)
    assert code == 0, err
    assert len(out.strip().splitlines()) == 6
    code, out, err = _run(SWEEP[:i + 1] + ["naca4412:0.4:clark_y;width=-1"] + SWEEP[i + 2:], capsys)
    assert code == 2 and "width" in err
