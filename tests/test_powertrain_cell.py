"""The NMC cell model against the measured discharge curves, and its physical form."""
import json

import casadi as ca
import numpy as np
import pytest
from scipy.integrate import quad

from mdo.powertrain import load_discharge_data, nmc18650
from mdo.powertrain.cell import FIT_FILE, RAW_FILE
from mdo.powertrain.cell_fit import error_table, fit

KINK_OPS = {ca.OP_FMAX, ca.OP_FMIN, ca.OP_FABS, ca.OP_IF_ELSE_ZERO, ca.OP_SIGN, ca.OP_FLOOR,
            ca.OP_CEIL, ca.OP_FMOD, ca.OP_LT, ca.OP_LE, ca.OP_EQ, ca.OP_NOT, ca.OP_AND, ca.OP_OR,
            ca.OP_COPYSIGN}

# Voltage error budget (mV): all points of a curve, and the operating range s >= 0.2
# (below it the knee is steep and the digitized curves disagree with each other by
# ~0.1 Ah in cut-off capacity at equal temperature).
RMS_ALL_MV = 34.0
RMS_SOC02_MV = 18.0


def _ops(f):
    return {f.instruction_id(k) for k in range(f.n_instructions())}


def test_raw_data_structure_and_duplicate():
    raw = json.loads(RAW_FILE.read_text())
    assert set(raw) == {"Voltage", "Temperature"}
    assert sorted(raw["Voltage"]) == ["Amps_0", "Amps_2", "Amps_4", "Amps_6", "Amps_8"]
    # 'Amps_0' is a copy of 'Amps_2' (why the fit has no 0 A / 1 A curve)
    for t in ("Deg_0", "Deg_10", "Deg_20", "Deg_30"):
        assert raw["Voltage"]["Amps_0"][t] == raw["Voltage"]["Amps_2"][t]
    curves = load_discharge_data()
    assert len(curves) == 24
    assert sorted({c["current_A"] for c in curves}) == [2.0, 4.0, 6.0, 8.0]
    assert sorted({c["ambient_C"] for c in curves}) == [0, 10, 20, 30, 40, 50]


def test_voltage_sag_against_measured_curves():
    """RMS voltage error per current, model evaluated through its CasADi Function."""
    cell = nmc18650()
    f = cell.function()
    rows = []
    for I in (2.0, 4.0, 6.0, 8.0):
        err_all, err_op = [], []
        for c in (c for c in load_discharge_data() if c["current_A"] == I):
            soc = cell.soc_from_charge(c["capacity_Ah"], c["ambient_C"])
            v = np.asarray(f.map(len(soc))(soc[None, :], I, c["ambient_C"])[0]).ravel()
            e = v - c["voltage_V"]
            err_all.append(e)
            err_op.append(e[soc >= 0.2])
        e_all, e_op = np.concatenate(err_all), np.concatenate(err_op)
        rows.append((I, 1e3 * np.sqrt(np.mean(e_all ** 2)), 1e3 * np.sqrt(np.mean(e_op ** 2)),
                     1e3 * np.abs(e_op).max()))
    print("\ncurrent  RMS all (mV)  RMS s>=0.2 (mV)  max s>=0.2 (mV)")
    for I, a, b, m in rows:
        print(f"{I:5.0f} A  {a:12.1f}  {b:15.1f}  {m:15.1f}")
    for I, a, b, m in rows:
        assert a < RMS_ALL_MV, (I, a)
        assert b < RMS_SOC02_MV, (I, b)
    # the committed error table is what this model gives
    table = error_table(cell)
    for I, a, b, _ in rows:
        assert table["per_current"][f"{I:g}"]["rms_mV"] == pytest.approx(a, rel=1e-9)


def test_cutoff_capacity_within_measured_spread():
    """Capacity at the measured end voltage: model vs measured, 2-8 A, 10-40 deg C."""
    table = error_table(nmc18650())
    for c in table["per_curve"]:
        if 10 <= c["ambient_C"] <= 40:
            assert abs(c["cutoff_capacity_model_Ah"] - c["cutoff_capacity_measured_Ah"]) < 0.12, c


def test_physical_form():
    cell = nmc18650()
    s = np.linspace(0.0, 1.0, 101)
    # zero current: terminal voltage is the open-circuit voltage
    assert np.allclose(cell.voltage(s, 0.0, 25.0), cell.ocv(s), atol=1e-15)
    # OCV increases with s; full and empty values of an NMC cell charged to 4.2 V
    assert np.all(np.diff(cell.ocv(np.linspace(-0.05, 1, 211))) > 0)
    assert 4.10 < cell.ocv(1.0) < 4.22
    assert cell.ocv(0.0) < 3.0
    # voltage falls with current everywhere (0..15 A, 0..50 deg C): unique current root
    S, I, T = np.meshgrid(s, np.linspace(0, 15, 31), np.linspace(0, 50, 11))
    assert cell.dvoltage_dcurrent(S, I, T).max() < -0.005
    v1 = cell.voltage(S, I, T)
    v2 = cell.voltage(S, I + 1e-4, T)
    assert np.all(v2 < v1)
    # loaded voltage increases with the state of charge at every current, also past the knee
    S2, I2, T2 = np.meshgrid(np.linspace(-0.05, 1.0, 421), np.linspace(0, 12, 25), np.linspace(0, 50, 21))
    assert np.all(np.diff(cell.voltage(S2, I2, T2), axis=1) > 0)
    # colder cell: lower loaded voltage (2-8 A, mid charge)
    for i in (2.0, 8.0):
        assert cell.voltage(0.5, i, 0.0) < cell.voltage(0.5, i, 25.0) < cell.voltage(0.5, i, 50.0) + 0.03
    # usable capacity grows with temperature, below the 3.55 Ah rating
    caps = cell.usable_capacity_Ah(np.array([0.0, 25.0, 50.0]))
    assert np.all(np.diff(caps) > 0) and caps[-1] < 3.55 and caps[0] > 3.0


def test_function_is_smooth_and_matches_numpy():
    cell = nmc18650()
    f = cell.function()
    assert not (_ops(f) & KINK_OPS)
    for s, i, t in [(0.9, 3.0, 20.0), (0.3, 7.5, 45.0), (0.05, 0.5, 5.0)]:
        out = f(s, i, t)
        assert float(out[0]) == pytest.approx(cell.voltage(s, i, t), rel=1e-14)
        assert float(out[3]) == pytest.approx(cell.dvoltage_dcurrent(s, i, t), rel=1e-12)
    # the analytic dV/dI is the derivative of the Function
    s_, i_ = ca.SX.sym("s"), ca.SX.sym("i")
    j = ca.Function("j", [s_, i_], [ca.jacobian(cell.voltage(s_, i_, 30.0), i_)])
    assert float(j(0.6, 4.0)) == pytest.approx(cell.dvoltage_dcurrent(0.6, 4.0, 30.0), rel=1e-12)


def test_chemical_energy_closed_form():
    cell = nmc18650()
    for T in (0.0, 25.0, 50.0):
        for s in (1.0, 0.55, 0.1):
            ref = quad(lambda x: cell.ocv(x), 0.0, s, epsabs=1e-13, epsrel=1e-13)[0]
            ref *= cell.usable_capacity_Ah(T) * 3600.0
            assert cell.energy_J(s, T) == pytest.approx(ref, rel=1e-11)
    # about 12.3 Wh per cell at 25 deg C (rating 3.55 Ah x 3.6 V = 12.8 Wh)
    assert 12.0 < cell.energy_J(1.0, 25.0) / 3600.0 < 12.8


def test_committed_fit_is_reproducible():
    committed = json.loads(FIT_FILE.read_text())["model"]
    m = fit()
    assert np.allclose(m.ocv_chebyshev, committed["ocv_chebyshev"], atol=1e-6)
    assert np.allclose(m.resistance_coeffs, committed["resistance_coeffs"], atol=1e-6)
    assert np.allclose(m.kinetic_coeffs, committed["kinetic_coeffs"], atol=1e-6)
    assert np.allclose(m.capacity_log_coeffs, committed["capacity_log_coeffs"], atol=1e-12)
