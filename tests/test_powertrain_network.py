"""The network at mission nodes: explicit outputs, the battery-current residual, the
throttle balance from cold starts, and NLP mode with a collocated state of charge."""
import casadi as ca
import numpy as np
import pytest

from mdo.core import Collocation, InputError
from mdo.nlp import Problem
from mdo.powertrain import NODE_OUTPUTS, propeller_torque_law
from mdo.vehicle.catalog import ga2p, ga8p, ttw

# the paper's vehicles as data: each definition's first rotor group and battery
VEHICLES = {c.name: c for c in (ga2p(), ga8p(), ttw())}


def paper_powertrain(name):
    return VEHICLES[name].powertrain()

KINK_OPS = {ca.OP_FMAX, ca.OP_FMIN, ca.OP_FABS, ca.OP_IF_ELSE_ZERO, ca.OP_SIGN, ca.OP_FLOOR,
            ca.OP_CEIL, ca.OP_FMOD, ca.OP_LT, ca.OP_LE, ca.OP_EQ, ca.OP_NOT, ca.OP_AND, ca.OP_OR,
            ca.OP_COPYSIGN}
THROTTLES = np.linspace(0.1, 1.0, 10)


@pytest.mark.parametrize("name", list(VEHICLES))
def test_balance_converges_from_cold_starts(name):
    """Throttle 0.1..1 with a propeller load Q ~ omega^2 (rated torque at rated speed):
    nested bisection and Newton from a cold start (omega = half no-load speed, I_b = 0)
    both converge, to the same point, with residuals at round-off."""
    pt = paper_powertrain(name)
    m = pt.motor
    law = propeller_torque_law(m.rated_torque_Nm, m.rated_speed_radps)
    for soc in (1.0, 0.3):
        b = pt.balance(THROTTLES, law, soc=soc, method="bracket")
        n = pt.balance(THROTTLES, law, soc=soc, method="newton")
        assert n["converged"].all(), (name, soc, n["iterations"])
        assert np.all(n["iterations"] <= 10)
        for out in (b, n):
            assert np.allclose(out["throttle"], THROTTLES, rtol=1e-10)
            assert np.all(np.abs(out["power_balance_W"]) < 1e-9 * pt.power_scale_W)
            q_motor = m.torque_at_voltage_Nm(out["motor_voltage_V"], out["omega_radps"])
            assert np.allclose(q_motor, law(out["omega_radps"]), rtol=1e-9)
        assert np.allclose(n["omega_radps"], b["omega_radps"], rtol=1e-9)
        assert np.allclose(n["battery_current_A"], b["battery_current_A"], rtol=1e-8, atol=1e-9)
        # more throttle: faster rotor, more current
        assert np.all(np.diff(b["omega_radps"]) > 0) and np.all(np.diff(b["battery_current_A"]) > 0)


def test_node_function_smooth_and_consistent():
    pt = paper_powertrain("GA-2P")
    f = pt.node_function()
    assert not ({f.instruction_id(k) for k in range(f.n_instructions())} & KINK_OPS)
    assert f.n_instructions() < 400
    m = pt.motor
    K = 100
    q = np.linspace(0.2, 1.1, K) * m.rated_torque_Nm
    w = np.linspace(0.7, 1.05, K) * m.rated_speed_radps
    soc = np.linspace(1.0, 0.3, K)
    a = pt.analyze(q, w, soc)
    assert set(NODE_OUTPUTS) < set(a) and a["throttle"].shape == (K,)
    # Eq. N1 holds; energy flows add up
    assert np.all(np.abs(a["power_balance_W"]) < 1e-9 * pt.power_scale_W)
    assert np.allclose(a["chemical_power_W"], a["battery_power_W"] + a["loss_power_W"], rtol=1e-12)
    assert np.allclose(a["bus_power_W"], 2 * a["esc_power_in_W"] + pt.aux_power_W, rtol=1e-12)
    assert np.allclose(a["esc_power_in_W"], a["motor_power_in_W"] / 0.95, rtol=1e-5)  # E2 smoothing
    assert np.allclose(a["shaft_power_W"], q * w)
    assert np.all((a["motor_efficiency"] > 0.85) & (a["motor_efficiency"] < 0.95))
    # the same Function called from MX on column vectors gives the same numbers
    Q, W, S, I = (ca.MX.sym(k, K) for k in "QWSI")
    out = pt.evaluate(Q, W, S, I)
    assert out["throttle"].shape == (1, K)
    g = ca.Function("g", [Q, W, S, I], [out["throttle"], out["soc_rate_per_s"]])
    th, rate = g(q, w, soc, a["battery_current_A"])
    assert np.allclose(np.asarray(th).ravel(), a["throttle"], rtol=1e-13)
    assert np.allclose(np.asarray(rate).ravel(), a["soc_rate_per_s"], rtol=1e-13)
    # the Jacobian of the power balance is diagonal in the nodes (sparse NLP)
    J = ca.jacobian(out["power_balance_W"], ca.vertcat(Q, W, S, I))
    assert J.nnz() == 4 * K


def test_regeneration_conserves_energy():
    """Windmilling (negative torque): power flows back through the ESC with a loss."""
    pt = paper_powertrain("GA-8P")
    m = pt.motor
    a = pt.analyze(-0.2 * m.rated_torque_Nm, m.rated_speed_radps, 0.5, aux_power_W=0.0)
    assert a["shaft_power_W"][0] < 0 and a["bus_power_W"][0] < 0
    assert abs(a["bus_power_W"][0]) < abs(pt.n_motors * a["shaft_power_W"][0])
    assert a["battery_current_A"][0] < 0
    assert a["chemical_power_W"][0] > a["battery_power_W"][0]       # losses also when charging


def test_bad_balance_input():
    pt = paper_powertrain("TTW")
    with pytest.raises(InputError, match="throttle"):
        pt.balance(-0.1, propeller_torque_law(1000.0, 150.0))
    with pytest.raises(InputError, match="group"):
        VEHICLES["TTW"].powertrain(group="no such group")


def test_nlp_mode_collocated_state_of_charge():
    """The mission's use: rotor torque/speed profile at CGL nodes, the battery current a
    variable per node, the state of charge collocated with D; IPOPT finds the same
    currents as the node-by-node analysis and E_EOF (closed form) equals the
    quadrature of the chemical power."""
    pt = paper_powertrain("GA-2P")
    m = pt.motor
    n, T = 16, 900.0
    col = Collocation(n)
    tau = col.s
    q = m.rated_torque_Nm * (0.9 - 0.4 * tau)            # climb then cruise-like torque
    w = m.rated_speed_radps * (1.0 - 0.1 * tau)
    p = Problem("powertrain_nlp")
    spec = pt.soc_state()
    soc = p.variable("soc", n, scale=spec["scale"], lower=spec["lower"], upper=spec["upper"], init=0.9)
    out, ib = pt.add_to_problem(p, q, w, soc, init_battery_current_A=200.0,
                                labels=[f"node {k}" for k in range(n)])
    p.constrain("soc start", soc[0], rhs=1.0)
    p.constrain("soc dynamics", ca.mtimes(ca.DM(col.D[1:]), soc) - T * out["soc_rate_per_s"][1:].T,
                scale=T * pt.soc_rate_scale_per_s)
    e_used = pt.energy_used_J(soc[0], soc[-1])
    p.minimize(e_used, unit="J", scale=1e7)
    sol = p.solve(verbose=False)
    assert sol.success, sol.status
    s_val = np.asarray(sol.value(soc)).ravel()
    i_val = np.asarray(sol.value(ib)).ravel()
    ref = pt.analyze(q, w, s_val)
    assert np.allclose(i_val, ref["battery_current_A"], rtol=1e-7)
    chem = pt.evaluate(q, w, s_val, i_val)["chemical_power_W"]
    e_quad = float(col.weights @ chem) * T
    e_closed = float(sol.value(e_used))
    assert e_closed == pytest.approx(e_quad, rel=1e-6)
    print(f"\nGA-2P, 900 s at 0.9-0.5 rated torque: E_used {e_closed / 3.6e6:.3f} kWh, "
          f"s_end {s_val[-1]:.4f}, throttle max {ref['throttle'].max():.3f}, IPOPT iterations {sol.iterations}")
