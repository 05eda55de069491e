"""Pack scaling, energy bookkeeping, and a CGL-collocated constant-power discharge."""
import casadi as ca
import numpy as np
import pytest

from mdo.core import Collocation, InputError
from mdo.powertrain import Pack, nmc18650


def test_pack_scaling_and_mass():
    p = Pack(120, 80)
    c = p.cell
    assert p.cells == 9600
    assert p.mass_kg == pytest.approx(9600 * 0.048 * 1.42)            # 654.3 kg
    assert p.nominal_energy_J / 3.6e6 == pytest.approx(122.688)         # 9600 x 3.55 Ah x 3.6 V
    for s, i in [(0.9, 200.0), (0.4, 640.0)]:
        assert p.voltage(s, i) == pytest.approx(120 * c.voltage(s, i / 80, 25.0), rel=1e-14)
        assert p.soc_rate(i) == pytest.approx(-i / 80 / (c.usable_capacity_Ah(25.0) * 3600))
    assert p.c_rate(284.0) == pytest.approx(1.0)
    assert p.energy_used_J(1.0, 0.5) == pytest.approx(9600 * (c.energy_J(1.0) - c.energy_J(0.5)))
    f = p.function()
    out = f(0.7, 300.0)
    assert float(out[0]) == pytest.approx(p.voltage(0.7, 300.0), rel=1e-14)
    assert float(out[6]) == pytest.approx((p.ocv(0.7) - p.voltage(0.7, 300.0)) * 300.0, rel=1e-12)


def test_current_for_power_round_trip():
    p = Pack(150, 120)
    P = np.array([-40e3, 0.0, 1e3, 150e3, 450e3, 700e3])
    for s in (1.0, 0.6, 0.15):
        i = p.current_for_power(P, s)
        assert np.allclose(p.voltage(s, i) * i, P, rtol=1e-12, atol=1e-6)
    pmax, imax = p.max_power_W(0.5)
    with pytest.raises(InputError, match="power_W"):
        p.current_for_power(1.01 * pmax, 0.5)


@pytest.mark.parametrize("kw, field", [({"n_series": 0, "n_parallel": 10}, "n_series"),
                                        ({"n_series": 10, "n_parallel": 2.5}, "n_parallel"),
                                        ({"n_series": 10, "n_parallel": 2, "temperature_C": 70}, "temperature_C")])
def test_bad_pack_inputs(kw, field):
    with pytest.raises(InputError, match=field):
        Pack(**kw)


def _collocated_discharge(cell, power_W, duration_s, n, temperature_C=25.0):
    """soc and current at the n CGL nodes of a constant-terminal-power discharge:
    D s = T ds/dt(I), V(s, I) I = P, s(0) = 1, solved by Newton."""
    col = Collocation(n)
    s = ca.SX.sym("s", n - 1)
    i = ca.SX.sym("i", n)
    soc = ca.vertcat(1.0, s)
    rate = cell.soc_rate(i, temperature_C)
    r1 = ca.mtimes(ca.DM(col.D[1:, :]), soc) - duration_s * rate[1:]
    r2 = (cell.voltage(soc, i, temperature_C) * i - power_W) / power_W
    x = ca.vertcat(s, i)
    rf = ca.rootfinder("rf", "newton", ca.Function("g", [x], [ca.vertcat(r1, r2)]), {"abstol": 1e-14})
    x0 = np.concatenate([1.0 - np.linspace(0.0, 0.5, n)[1:], np.full(n, power_W / 3.7)])
    xs = np.asarray(rf(x0)).ravel()
    return col, np.concatenate([[1.0], xs[:n - 1]]), xs[n - 1:]


def _reference_discharge(cell, power_W, duration_s, temperature_C=25.0):
    """The same discharge by a DAE integrator (IDAS, tolerances 1e-12): s, E_chem drawn, E_terminal."""
    x = ca.SX.sym("x", 3)                  # soc, chemical energy drawn, terminal energy
    z = ca.SX.sym("z")                     # current
    s = x[0]
    ode = ca.vertcat(cell.soc_rate(z, temperature_C), cell.ocv(s) * z, cell.voltage(s, z, temperature_C) * z)
    alg = cell.voltage(s, z, temperature_C) * z - power_W
    F = ca.integrator("F", "idas", {"x": x, "z": z, "ode": ode, "alg": alg}, 0.0, duration_s,
                      {"abstol": 1e-13, "reltol": 1e-13})
    r = F(x0=[1.0, 0.0, 0.0], z0=power_W / 4.0)
    return np.asarray(r["xf"]).ravel()


@pytest.mark.parametrize("power_W, duration_s, temperature_C", [(12.0, 2400.0, 25.0), (25.0, 1000.0, 10.0)])
def test_constant_power_discharge_by_collocation(power_W, duration_s, temperature_C):
    """A constant-power discharge integrated by CGL collocation: the terminal energy
    integrated at the nodes is int P dt, the state-of-charge drop gives the chemical
    energy in closed form, and both match a tight DAE integration to 1e-6."""
    cell = nmc18650()
    col, soc, cur = _collocated_discharge(cell, power_W, duration_s, 24, temperature_C)
    s_ref, e_chem_ref, e_term_ref = _reference_discharge(cell, power_W, duration_s, temperature_C)
    w = col.weights * duration_s
    v = cell.voltage(soc, cur, temperature_C)
    # terminal energy by the collocation quadrature = int P dt = P T
    e_term = float(w @ (v * cur))
    assert e_term == pytest.approx(power_W * duration_s, rel=1e-9)
    assert e_term_ref == pytest.approx(power_W * duration_s, rel=1e-9)
    # chemical energy from the collocated state (closed form, Eq. C5) vs the DAE reference
    e_chem = float(cell.energy_J(1.0, temperature_C) - cell.energy_J(soc[-1], temperature_C))
    assert soc[-1] == pytest.approx(s_ref, rel=1e-8)
    assert e_chem == pytest.approx(e_chem_ref, rel=1e-6)
    # and equals int (P + losses) dt by the node quadrature
    e_chem_quad = float(w @ (cell.ocv(soc) * cur))
    assert e_chem_quad == pytest.approx(e_chem, rel=1e-6)
    # internal losses: positive, 6 % (3.3 A, 25 C) to 16 % (7.5 A, 10 C) of the energy
    assert 0.005 < (e_chem - e_term) / e_term < 0.25
    print(f"\nP = {power_W} W, T = {duration_s} s: s_end {soc[-1]:.6f} (ref {s_ref:.6f}), "
          f"E_chem {e_chem:.3f} J (ref {e_chem_ref:.3f}), rel diff {abs(e_chem / e_chem_ref - 1):.2e}, "
          f"losses {100 * (e_chem - e_term) / e_term:.2f} %")
