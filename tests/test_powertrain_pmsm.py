"""Loss-model PMSM and inverter (mdo.powertrain.pmsm): energy conservation, the stated peak
efficiencies at the stated loads, efficiency < 1 and smooth down to zero torque/speed,
CasADi gradients (also with a symbolic rating), limits and the efficiency map."""
import casadi as ca
import numpy as np
import pytest

from mdo.core.errors import InputError
from mdo.core.units import RPM
from mdo.powertrain.pmsm import (DRIVE_OUTPUTS, drive_function, drive_node, efficiency_map,
                                 plot_efficiency_map, size_inverter, size_pmsm)

P_R, W_R, V_BUS = 52.7e3, 1665 * RPM, 432.0     # GA-2P rating (catalog), pack nominal voltage


@pytest.fixture(scope="module")
def drive():
    return size_pmsm(P_R, W_R, V_BUS), size_inverter(P_R / 0.96, V_BUS)


def test_energy_conservation(drive):
    m, inv = drive
    W, Q = np.meshgrid(np.linspace(-50, 1.2 * W_R, 23), np.linspace(-100, 300, 19))
    out = drive_node(m, inv, Q, W, V_BUS)
    motor_losses = sum(out[f"motor_{k}"] for k in ("copper_W", "hysteresis_W", "eddy_W", "friction_W", "windage_W"))
    np.testing.assert_allclose(out["motor_power_in_W"], Q * W + motor_losses, rtol=1e-10, atol=1e-7)
    inv_losses = sum(out[f"inverter_{k}"] for k in ("fixed_W", "conduction_W", "switching_W"))
    np.testing.assert_allclose(out["bus_power_W"], out["motor_power_in_W"] + inv_losses, rtol=1e-12, atol=1e-9)
    assert np.all(motor_losses > 0) and np.all(inv_losses > 0)       # each loss >= 0, any sign


def test_peak_efficiency_at_stated_load(drive):
    m, inv = drive
    q = np.linspace(0.01, 1.0, 4001) * m.rated_torque_Nm
    out = drive_node(m, inv, q, np.full_like(q, W_R), V_BUS)
    k = np.argmax(out["motor_efficiency"])
    assert out["motor_efficiency"][k] == pytest.approx(0.96, abs=1e-5)
    assert q[k] / m.rated_torque_Nm == pytest.approx(0.5, abs=2e-3)
    k = np.argmax(out["inverter_efficiency"])
    assert 0.97 <= out["inverter_efficiency"][k] <= 0.99
    assert out["inverter_efficiency"][k] == pytest.approx(0.985, abs=1e-3)
    # whole map (up to the speed and voltage limits): the peak stays in the PMSM class band
    _, _, eta_m, eta_d, vr = efficiency_map(m, inv)
    assert 0.95 <= np.max(eta_m[vr <= 1]) <= 0.97
    assert np.max(eta_d[vr <= 1]) < np.max(eta_m[vr <= 1])


def test_rated_point_voltage_and_limits(drive):
    m, inv = drive
    out = drive_node(m, inv, m.rated_torque_Nm, W_R, V_BUS)
    assert out["voltage_ratio"] == pytest.approx(0.9, rel=1e-9)
    assert out["torque_ratio"] == pytest.approx(1.0) and out["power_ratio"] == pytest.approx(1.0)
    assert out["speed_ratio"] == pytest.approx(1 / 1.2)
    assert 0.93 < out["motor_efficiency"] < 0.96
    assert m.mass_kg == pytest.approx(P_R / 5e3)


def test_efficiency_below_one_and_smooth_near_zero(drive):
    m, inv = drive
    q = np.concatenate([np.geomspace(1e-6, 1.0, 40), np.linspace(1.0, 300, 60)])
    for w in (0.1, 1.0, 50.0, W_R, 1.2 * W_R):
        out = drive_node(m, inv, q, np.full_like(q, w), V_BUS)
        for key in ("motor_efficiency", "inverter_efficiency", "drive_efficiency"):
            assert np.all(out[key] < 1.0) and np.all(out[key] > 0.0)
        assert out["motor_efficiency"][0] < 1e-4                         # -> 0 with the torque
    # second derivatives of the drive efficiency exist and are finite at and around zero torque
    Q, W = ca.SX.sym("Q"), ca.SX.sym("W")
    eta = drive_node(m, inv, Q, W, V_BUS)["drive_efficiency"]
    h = ca.Function("h", [Q, W], [ca.hessian(eta, ca.vertcat(Q, W))[0]])
    for qq, ww in ((0.0, 1.0), (1e-3, 0.5), (-1.0, W_R), (150.0, W_R)):
        assert np.all(np.isfinite(np.array(h(qq, ww))))


@pytest.mark.parametrize("kind", [ca.SX, ca.MX])
def test_casadi_gradients_and_symbolic_rating(kind, drive):
    w_r = kind.sym("w_r")
    q, w = kind.sym("q"), kind.sym("w")
    m = size_pmsm(P_R, w_r, V_BUS)
    inv = size_inverter(P_R / 0.96, V_BUS)
    out = drive_node(m, inv, q, w, V_BUS)
    x = ca.vertcat(q, w, w_r)
    f = ca.Function("f", [x], [out["bus_power_W"], ca.jacobian(out["bus_power_W"], x),
                               ca.jacobian(out["motor_efficiency"], x)])
    p, j1, j2 = f([120.0, 170.0, W_R])
    assert np.all(np.isfinite(np.array(j1))) and np.all(np.isfinite(np.array(j2)))
    num = drive_node(*drive, 120.0, 170.0, V_BUS)["bus_power_W"]
    assert float(p) == pytest.approx(num, rel=1e-10)


def test_drive_function_matches_node(drive):
    m, inv = drive
    f = drive_function(m, inv)
    res = f(torque_Nm=100.0, omega_radps=150.0, bus_voltage_V=400.0)
    ref = drive_node(m, inv, 100.0, 150.0, 400.0)
    for k in DRIVE_OUTPUTS:
        assert float(res[k]) == pytest.approx(ref[k], rel=1e-12)


def test_bad_inputs_name_the_field():
    with pytest.raises(InputError, match="peak_efficiency"):
        size_pmsm(P_R, W_R, V_BUS, peak_efficiency=1.2)
    with pytest.raises(InputError, match="rated_speed_radps"):
        size_pmsm(P_R, -1.0, V_BUS)
    with pytest.raises(InputError, match="linear_fraction"):
        size_inverter(P_R, V_BUS, linear_fraction=1.5)


def test_efficiency_map_figure(tmp_path, drive):
    path = plot_efficiency_map(*drive, tmp_path / "map.png", points={"cruise": (1665, 110.0)})
    assert path.exists() and path.stat().st_size > 10_000
