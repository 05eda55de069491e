"""US Standard Atmosphere 1976 against its tables (NOAA-S/T 76-1562, Table I, geometric altitude)."""
import casadi as ca
import numpy as np
import pytest

from mdo.core import atmosphere, check_altitude, density, dynamic_viscosity, pressure, speed_of_sound, temperature
from mdo.core.atmosphere import geopotential_altitude

# geometric altitude m: (T K, p Pa, rho kg/m^3, a m/s, mu Pa s)   -- USSA76 Table I
TABLE = {
    0.0: (288.150, 1.01325e5, 1.2250, 340.29, 1.7894e-5),
    1000.0: (281.651, 8.98763e4, 1.1117, 336.43, 1.7579e-5),
    2000.0: (275.154, 7.95014e4, 1.0066, 332.53, 1.7260e-5),
    5000.0: (255.676, 5.40482e4, 0.73643, 320.55, 1.6282e-5),
    10000.0: (223.252, 2.64999e4, 0.41351, 299.53, 1.4577e-5),
    11000.0: (216.774, 2.26999e4, 0.36480, 295.15, 1.4223e-5),
    15000.0: (216.650, 1.21118e4, 0.19476, 295.07, 1.4216e-5),
    20000.0: (216.650, 5.52930e3, 0.088910, 295.07, 1.4216e-5),
}


@pytest.mark.parametrize("h", sorted(TABLE))
def test_against_table(h):
    T, p, rho, a, mu = TABLE[h]
    assert temperature(h) == pytest.approx(T, abs=0.03)
    assert pressure(h) == pytest.approx(p, rel=2e-4)
    assert density(h) == pytest.approx(rho, rel=3e-4)
    assert speed_of_sound(h) == pytest.approx(a, abs=0.02)
    assert dynamic_viscosity(h) == pytest.approx(mu, rel=3e-4)


def test_issue_reference_densities():
    # rho = 1.2250, 1.1117, 0.7364 at 0, 1000, 5000 m; 0.3639 at the tropopause, which is
    # geopotential 11 000 m = geometric 11 019 m.
    for h, rho in [(0, 1.2250), (1000, 1.1117), (5000, 0.7364)]:
        assert round(density(h), 4) == rho
    h_trop = 11000.0 * 6356766.0 / (6356766.0 - 11000.0)
    assert geopotential_altitude(h_trop) == pytest.approx(11000.0)
    assert round(density(h_trop), 4) == 0.3639


def test_symbolic_smooth_through_tropopause():
    h = ca.SX.sym("h")
    rho = density(h)
    F = ca.Function("f", [h], [rho, ca.jacobian(rho, h), ca.hessian(rho, h)[0]])
    hs = np.linspace(10500, 11500, 201)
    vals = np.array([[float(v) for v in F(x)] for x in hs])
    assert np.all(np.isfinite(vals))
    # first derivative continuous: between 5 m samples it moves by < 10 % of its size
    assert np.max(np.abs(np.diff(vals[:, 1]))) < 0.1 * np.min(np.abs(vals[:, 1]))
    assert vals[:, 0] == pytest.approx(np.array([density(x) for x in hs]), rel=1e-12)
    d = atmosphere(3000.0)
    assert d["density_kgpm3"] == pytest.approx(density(3000.0))


@pytest.mark.parametrize("bad", [-10.0, 20001.0, float("nan")])
def test_altitude_outside_model_is_an_error(bad):
    with pytest.raises(ValueError, match="0 to 20000 m"):
        check_altitude(bad)
