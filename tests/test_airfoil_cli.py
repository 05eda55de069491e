"""``mdo airfoil ...`` sub-commands."""
from mdo.cli import main


def test_list_and_polar(capsys):
    assert main(["airfoil", "list"]) == 0
    out = capsys.readouterr().out
    assert "naca4412" in out and "e63" in out
    assert main(["airfoil", "polar", "NACA 4412", "--re", "1e6", "--alpha", "0", "4", "2"]) == 0
    lines = capsys.readouterr().out.strip().splitlines()
    assert len(lines) == 2 + 3
    alpha, cl = (float(v) for v in lines[-1].split()[:2])
    assert alpha == 4.0 and 0.8 < cl < 1.1


def test_bad_input_exit_code(capsys):
    assert main(["airfoil", "polar", "nosuch", "--re", "1e6"]) == 2
    assert "available" in capsys.readouterr().err
    assert main(["airfoil", "polar", "clarky", "--re", "-5"]) == 2
    assert main(["airfoil", "polar", "clarky", "--re", "1e6", "--mach", "2"]) == 2


def test_plot_and_check(tmp_path, capsys):
    assert main(["airfoil", "plot", "naca63412", "--out", str(tmp_path)]) == 0
    assert (tmp_path / "naca63412.png").stat().st_size > 10_000
    assert main(["airfoil", "check", "naca63412"]) == 0
    assert "max|dcl|" in capsys.readouterr().out
