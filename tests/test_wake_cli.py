"""``mdo wake velocity``."""
import numpy as np

from mdo.cli import main


def test_wake_velocity_cli_writes_csv(tmp_path, capsys):
    out = tmp_path / "v.csv"
    rc = main(["wake", "velocity", "--radius", "0.97", "--blades", "3", "--thrust-gamma", "2", "--rpm", "2400",
               "--v-wake", "80", "--y", "0:2:0.25", "--out", str(out)])
    assert rc == 0
    d = np.loadtxt(out, delimiter=",", skiprows=1)
    assert d.shape == (9, 4)
    inside = d[:, 0] == 0.5
    # inside the slipstream: accelerated, swirl upwards at +y for spin +1 about +x
    assert d[inside, 1][0] > 1.0 and d[inside, 3][0] > 1.0


def test_wake_velocity_cli_bad_input_is_one_line(capsys):
    rc = main(["wake", "velocity", "--radius", "-1", "--blades", "3", "--thrust-gamma", "2", "--rpm", "2400",
               "--v-wake", "80"])
    assert rc == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--radius" in err[0]
