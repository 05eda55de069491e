"""DC motor: sizing from a rating, peak efficiency, torque-speed line, NDARC mass."""
import casadi as ca
import numpy as np
import pytest

from mdo.core import InputError, units as u
from mdo.powertrain import DCMotor, motor_function, motor_mass_ndarc_kg, size_dc_motor
from mdo.vehicle.catalog import ga2p, ga8p, ttw

# the paper's vehicles as data: each definition's first rotor group and battery
VEHICLES = {c.name: c for c in (ga2p(), ga8p(), ttw())}


def paper_powertrain(name):
    return VEHICLES[name].powertrain()


@pytest.mark.parametrize("name", list(VEHICLES))
def test_sizing_reproduces_rating(name):
    m = paper_powertrain(name).motor
    q, w = m.rated_torque_Nm, m.rated_speed_radps
    assert q * w == pytest.approx(VEHICLES[name].rotor_groups[0].motor.rated_power_W)
    assert m.voltage_V(q, w) == pytest.approx(m.rated_voltage_V, rel=1e-12)
    assert m.efficiency(q, w) == pytest.approx(0.94, rel=1e-12)
    # loss split: 60 % copper at the rated point
    p_in = m.power_in_W(q, w)
    assert m.current_A(q) ** 2 * m.resistance_ohm == pytest.approx(0.6 * (p_in - q * w), rel=1e-12)


@pytest.mark.parametrize("name", list(VEHICLES))
def test_peak_efficiency_in_band(name):
    """Scan the torque at the rated voltage: the peak efficiency is 85-95 % and
    equals the closed form (Eq. M5)."""
    m = paper_powertrain(name).motor
    V = m.rated_voltage_V
    q = np.linspace(1e-3, 1.5, 30001) * m.rated_torque_Nm
    w = m.speed_at_voltage_radps(V, q)
    eta = m.efficiency(q, w)
    k = int(np.argmax(eta))
    eta_max, i_star = m.peak_efficiency(V)
    print(f"\n{name}: Kv {m.kv_rpm_per_V:.3f} rpm/V, R {1e3 * m.resistance_ohm:.1f} mOhm, "
          f"I0 {m.no_load_current_A:.2f} A, mass {m.mass_kg:.1f} kg, peak efficiency {eta[k]:.4f} "
          f"at {q[k] / m.rated_torque_Nm:.2f} x rated torque")
    assert 0.85 <= eta[k] <= 0.95
    assert eta[k] == pytest.approx(eta_max, abs=1e-8)
    assert m.current_A(q[k]) == pytest.approx(i_star, rel=1e-3)
    # efficiency falls off on both sides: half load and 1.5x load lower than the peak
    assert eta[0] < 0.5 and eta[-1] < eta[k] - 0.005


@pytest.mark.parametrize("name", list(VEHICLES))
def test_torque_speed_line(name):
    """At fixed voltage the speed falls linearly with torque: slope -Kv^2 R, from the
    no-load speed to zero at the stall torque (Eq. M4); the Function agrees."""
    m = paper_powertrain(name).motor
    V = 0.8 * m.rated_voltage_V
    q = np.linspace(0.0, 2.0, 9) * m.rated_torque_Nm
    w = m.speed_at_voltage_radps(V, q)
    slope = np.diff(w) / np.diff(q)
    assert np.allclose(slope, -m.kv_radps_per_V ** 2 * m.resistance_ohm, rtol=1e-10)
    assert w[0] == pytest.approx(m.no_load_speed_radps(V), rel=1e-14)
    assert m.speed_at_voltage_radps(V, m.stall_torque_Nm(V)) == pytest.approx(0.0, abs=1e-9 * w[0])
    # inverse: the torque at (V, omega) on the line is q; the Function gives voltage V there
    assert np.allclose(m.torque_at_voltage_Nm(V, w), q, rtol=1e-10, atol=1e-9)
    f = m.function()
    out = f.map(len(q))(q[None, :], w[None, :])
    assert np.allclose(np.asarray(out[1]).ravel(), V, rtol=1e-12)
    assert np.allclose(np.asarray(out[3]).ravel(), q * w, rtol=1e-12)


def test_ndarc_mass_regression():
    # W_lb = 0.3928 Q_ftlb^0.8587: 100 ft lbf -> 20.69 lb
    assert motor_mass_ndarc_kg(100 * u.FT * u.LBF) / u.LB == pytest.approx(0.3928 * 100 ** 0.8587)
    masses = {n: paper_powertrain(n).motor.mass_kg for n in VEHICLES}
    # per motor: GA-2P 18.5 kg, GA-8P 5.4 kg, TTW 36.9 kg (lighter per kW at higher rpm)
    assert masses["GA-8P"] < masses["GA-2P"] < masses["TTW"]
    assert 15 < masses["GA-2P"] < 22 and 30 < masses["TTW"] < 45


def test_symbolic_sizing_is_smooth():
    """A motor sized from a symbolic rated speed (e.g. a rotor radius at a tip-Mach
    limit) gives smooth expressions with exact derivatives."""
    w = ca.SX.sym("w")
    m = size_dc_motor(52.7e3, w, 388.8)
    f = ca.Function("f", [w], [m.kv_radps_per_V, m.mass_kg, ca.jacobian(m.mass_kg, w)])
    kv, mass, dm = (float(x) for x in f(170.0))
    ref = size_dc_motor(52.7e3, 170.0, 388.8)
    assert kv == pytest.approx(ref.kv_radps_per_V) and mass == pytest.approx(ref.mass_kg)
    h = 1e-4
    fd = (size_dc_motor(52.7e3, 170.0 + h, 388.8).mass_kg - size_dc_motor(52.7e3, 170.0 - h, 388.8).mass_kg) / (2 * h)
    assert dm == pytest.approx(fd, rel=1e-6)
    g = motor_function()
    assert g.n_in() == 5 and g.name_out()[4] == "efficiency"


@pytest.mark.parametrize("args, field", [((-1.0, 200.0, 400.0), "rated_power_W"),
                                          ((50e3, 0.0, 400.0), "rated_speed_radps"),
                                          ((50e3, 200.0, 400.0, 1.2), "rated_efficiency")])
def test_bad_sizing_inputs(args, field):
    with pytest.raises(InputError, match=field):
        size_dc_motor(*args)


def test_dataclass_with_constants():
    m = DCMotor(0.5, 0.1, 3.0)
    assert m.current_A(10.0) == pytest.approx(8.0)
    assert m.voltage_V(10.0, 100.0) == pytest.approx(200.0 + 0.8)
