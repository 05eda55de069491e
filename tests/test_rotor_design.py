"""Adkins-Liebeck design: design-point consistency with the BEMT, the hover and
large-inflow-angle cases of the TTW, differentiability, NLP mode, and the
minimum-power comparison against a direct chord/twist optimization."""
import math

import casadi as ca
import numpy as np
import pytest

from mdo.core import InputError, density, dynamic_viscosity, speed_of_sound
from mdo.core.units import FT, MPH
from mdo.rotor import (DESIGN_INPUTS, AnalyticSection, add_adkins_liebeck, add_bemt_nodes,
                       adkins_liebeck, adkins_liebeck_unrolled, analyze, bemt_function)

SEC = AnalyticSection(alpha0_rad=math.radians(-4.0), cd0=0.008, k_drag=0.006)

CASES = {
    # the paper's Table 3 initial designs (tip Mach chosen here: the paper does not give rpm)
    "GA-2P": dict(blades=3, radius_m=0.97, speed_mps=135 * MPH, thrust_N=900.0, tip_mach=0.6,
                  altitude_m=2500 * FT),
    "GA-8P": dict(blades=5, radius_m=0.58, speed_mps=130 * MPH, thrust_N=350.0, tip_mach=0.6,
                  altitude_m=2500 * FT),
    "TTW": dict(blades=3, radius_m=1.2, speed_mps=22.36 * MPH, thrust_N=5395.5, tip_mach=0.55, altitude_m=0.0),
    "hover": dict(blades=3, radius_m=1.2, speed_mps=0.0, thrust_N=5395.5, tip_mach=0.55, altitude_m=0.0),
}


@pytest.mark.parametrize("name", list(CASES))
def test_bemt_of_designed_blade_gives_design_thrust(name):
    case = CASES[name]
    d = adkins_liebeck(airfoil=SEC, cl_design=0.7, **case)
    assert d["residual_max"] < 1e-9
    res = analyze(d["geometry"], omega_radps=d["omega_radps"], v_axial_mps=case["speed_mps"],
                  altitude_m=case["altitude_m"])
    assert res.converged.all()
    err = res["thrust_N"][0] / case["thrust_N"] - 1.0
    assert abs(err) < 1e-3, f"{name}: BEMT thrust {res['thrust_N'][0]:.2f} N vs design {case['thrust_N']} N"
    assert abs(res["power_W"][0] / d["power_W"] - 1.0) < 1e-3
    # the design inflow angles are the BEMT solution
    assert np.max(np.abs(res["phi_rad"][:, 0] - d["phi_rad"])) < 1e-3
    # the designed sections work at the design cl
    np.testing.assert_allclose(res["cl"][:, 0], 0.7, atol=5e-3)
    assert np.all(d["chord_m"] > 0)


def test_ttw_design_is_heavily_loaded():
    """The TTW rotor at 22.36 mph: zeta ~ 4, inflow angles past 40 deg inboard: the
    regime where A-L's quadratic in zeta has no real root (SUAVE clips Tc there)."""
    d = adkins_liebeck(airfoil=SEC, cl_design=0.7, **CASES["TTW"])
    assert d["zeta"] > 3.0
    assert np.degrees(d["phi_rad"].max()) > 40.0
    V = CASES["TTW"]["speed_mps"]
    # A-L's Tc = I1 zeta - I2 zeta^2 peaks at I1^2/(4 I2); the design Tc lies above (light-loading I's):
    Tc = 2 * d["thrust_N"] / (density(0.0) * V ** 2 * math.pi * 1.2 ** 2)
    assert Tc > 10.0


def test_power_target_design():
    case = dict(CASES["GA-2P"])
    thrust_design = adkins_liebeck(airfoil=SEC, cl_design=0.6, **case)
    case.pop("thrust_N")
    d = adkins_liebeck(airfoil=SEC, cl_design=0.6, power_W=thrust_design["power_W"], **case)
    assert abs(d["thrust_N"] / thrust_design["thrust_N"] - 1) < 1e-8
    np.testing.assert_allclose(d["chord_m"], thrust_design["chord_m"], rtol=1e-7)


def _params(case, omega, cl=0.7, h=0.12):
    alt = case["altitude_m"]
    return {"target": case["thrust_N"], "speed_mps": case["speed_mps"], "radius_m": case["radius_m"],
            "omega_radps": omega, "cl_design": cl, "rho_kgpm3": float(density(alt)),
            "mu_Pas": float(dynamic_viscosity(alt)), "a_mps": float(speed_of_sound(alt)),
            "hub_fraction": h, "blades": case["blades"]}


def test_unrolled_design_matches_and_is_differentiable():
    case = CASES["GA-2P"]
    d = adkins_liebeck(airfoil=SEC, cl_design=0.7, **case)
    n = 20
    f = adkins_liebeck_unrolled(SEC, n, n_newton=8)
    p = _params(case, d["omega_radps"])
    out = f(**p)
    np.testing.assert_allclose(np.array(out["chord_m"]).ravel(), d["chord_m"], rtol=1e-9)
    np.testing.assert_allclose(np.array(out["twist_rad"]).ravel(), d["twist_rad"], atol=1e-10)
    # d(chord)/d(thrust, speed, radius) by AD of the unrolled map vs central differences of the solve
    x = ca.SX.sym("x", 3)
    sym = dict(p)
    sym.update(target=x[0], speed_mps=x[1], radius_m=x[2])
    jac = ca.Function("j", [x], [ca.jacobian(f(**sym)["chord_m"], x)])
    J = np.array(jac([p["target"], p["speed_mps"], p["radius_m"]]))
    for k, (key, step) in enumerate((("thrust_N", 1.0), ("speed_mps", 0.05), ("radius_m", 1e-4))):
        hi, lo = dict(case), dict(case)
        hi[key] += step
        lo[key] -= step
        # keep the rotor speed fixed (tip Mach is an input of the numeric helper)
        om = d["omega_radps"]
        for c in (hi, lo):
            c.pop("tip_mach")
        fd = (adkins_liebeck(airfoil=SEC, cl_design=0.7, omega_radps=om, **hi)["chord_m"]
              - adkins_liebeck(airfoil=SEC, cl_design=0.7, omega_radps=om, **lo)["chord_m"]) / (2 * step)
        np.testing.assert_allclose(J[:, k], fd, rtol=2e-4, atol=1e-7 * np.abs(fd).max())


def test_design_and_off_design_nodes_in_one_problem():
    """NLP mode: A-L unknowns + BEMT nodes at two other speeds, against the numeric chain."""
    from mdo.nlp import Problem

    case = CASES["GA-2P"]
    d = adkins_liebeck(airfoil=SEC, cl_design=0.7, **case)
    n = 20
    p = Problem("design_chain")
    params = _params(case, d["omega_radps"])
    design = add_adkins_liebeck(p, "prop", SEC, params, n_stations=n, init=d)
    f = bemt_function(SEC, n)
    speeds = np.array([45.0, 70.0])
    node_inputs = {"radius_m": params["radius_m"], "hub_fraction": 0.12, "blades": 3,
                   "chord_m": design["chord_m"], "twist_rad": design["twist_rad"], "pitch_rad": 0.0,
                   "omega_radps": params["omega_radps"], "v_axial_mps": ca.DM(speeds).T, "v_inplane_mps": 0.0,
                   "rho_kgpm3": params["rho_kgpm3"], "mu_Pas": params["mu_Pas"], "a_mps": params["a_mps"],
                   "spin": 1.0}
    nodes = add_bemt_nodes(p, "prop_nodes", f, node_inputs, n_nodes=2, phi_init=d["phi_rad"])
    sol = p.solve(verbose=False, options={"tol": 1e-12, "acceptable_tol": 1e-12})
    assert sol.success
    ref = analyze(d["geometry"], omega_radps=d["omega_radps"], v_axial_mps=speeds, altitude_m=case["altitude_m"])
    np.testing.assert_allclose(np.asarray(sol.value(nodes["thrust_N"])).ravel(), ref["thrust_N"], rtol=1e-6)


@pytest.mark.parametrize("name,cl", [("GA-2P", 0.7), ("TTW", 0.7)])
def test_direct_blade_optimization_improves_little_on_adkins_liebeck(name, cl):
    """Minimum power at the design thrust over chord and twist at every station."""
    from mdo.nlp import Problem

    case = CASES[name]
    d = adkins_liebeck(airfoil=SEC, cl_design=cl, **case)
    n, R = 20, case["radius_m"]
    alt = case["altitude_m"]
    p = Problem("blade_opt")
    c = p.variable("chord", n, unit="m", scale=0.05 * R, lower=0.002 * R, upper=0.8 * R, init=d["chord_m"])
    tw = p.variable("twist", n, unit="rad", scale=0.3, lower=-0.2, upper=1.5, init=d["twist_rad"])
    inp = {"radius_m": R, "hub_fraction": 0.12, "blades": case["blades"], "chord_m": c, "twist_rad": tw,
           "pitch_rad": 0.0, "omega_radps": d["omega_radps"], "v_axial_mps": case["speed_mps"],
           "v_inplane_mps": 0.0, "rho_kgpm3": float(density(alt)), "mu_Pas": float(dynamic_viscosity(alt)),
           "a_mps": float(speed_of_sound(alt)), "spin": 1.0}
    out = add_bemt_nodes(p, "prop", bemt_function(SEC, n), inp, n_nodes=1, phi_init=d["phi_rad"])
    p.constrain("thrust", out["thrust_N"] - case["thrust_N"], scale=case["thrust_N"])
    p.minimize(out["power_W"], scale=d["power_W"])
    sol = p.solve(verbose=False)
    assert sol.success
    gain = 1.0 - float(sol.value(out["power_W"])) / d["power_W"]
    assert -1e-6 < gain < 0.02, f"{name}: direct optimization saves {100 * gain:.2f} % power"


def test_design_input_errors():
    base = dict(CASES["GA-2P"])
    with pytest.raises(InputError, match="design thrust"):
        adkins_liebeck(airfoil=SEC, **{**base, "thrust_N": -5.0})
    with pytest.raises(InputError, match="tip Mach"):
        adkins_liebeck(airfoil=SEC, **{**base, "tip_mach": 1.2})
    with pytest.raises(InputError, match="cl_design"):
        adkins_liebeck(airfoil=SEC, cl_design=3.0, **base)
    with pytest.raises(InputError, match="hub_fraction"):
        adkins_liebeck(airfoil=SEC, hub_fraction=1.0, **base)
    with pytest.raises(InputError, match="design speed"):
        adkins_liebeck(airfoil=SEC, **{**base, "speed_mps": -1.0})
    with pytest.raises(InputError, match="airfoil"):
        adkins_liebeck(airfoil="no_such_section", **base)
    assert set(DESIGN_INPUTS) >= {"target", "speed_mps", "radius_m", "cl_design"}


def test_design_cl_is_held_by_stall_at_the_design_stations():
    """cl_design <= cl_max(Re_i) - margin at every design station (``design_cl_stall_rows``):
    the cl_max(Re) fit follows the section's scanned maxima, a tripped NACA 4412 blade
    designed at cl 0.7 is inside the limit, and the same blade at cl 1.1 is not (its hub
    station runs at Re 2.6e4, where the fit gives cl_max 1.17)."""
    from mdo.rotor import section
    from mdo.rotor.design import design_cl_stall_rows, station_clmax
    sec = section("naca4412@xtr=0.1")
    fits = station_clmax(sec, 16, 0.12)
    assert fits[0].max_error < 0.08
    a = np.radians(np.linspace(0.0, 25.0, 251))
    for re in (1e5, 1e6):
        scanned = float(np.max(np.asarray(sec.cl(a, re), float)))
        assert float(fits[0](re)) == pytest.approx(scanned, abs=0.08)
    rows = {}
    for cl in (0.7, 1.1):
        b = adkins_liebeck(blades=2, radius_m=0.95, speed_mps=60.0, airfoil=sec, cl_design=cl, thrust_N=1500.0,
                           rpm=2400.0, hub_fraction=0.12, n_stations=16)
        rows[cl] = np.array(design_cl_stall_rows(sec, {"reynolds": ca.DM(b["reynolds"])}, cl, 0.12, 0.1)).ravel()
    assert np.all(rows[0.7] < 0.0)
    assert np.any(rows[1.1] > 0.0)
    assert rows[1.1].max() == pytest.approx(rows[1.1][0])     # the hub station (Re 2.6e4) limits first
