"""BEMT residual, analysis solve and NLP mode on analytic sections (no polar data).

Checks: the solved state satisfies annulus momentum and blade-element loads;
the actuator-disk limits (lightly loaded rotor in axial flow, ideal-twist hover
with FM -> 1 when losses are switched off, FM < 1 with them); rotation-sense
symmetry in non-axial flow; hover, climb, descent and windmilling do not break
the solve; the NLP (IPOPT on the residual) lands on the analysis solution.
"""
import math

import casadi as ca
import numpy as np
import pytest

from mdo.rotor import (AnalyticSection, RotorGeometry, analyze, analyze_inputs, bemt_function,
                       add_bemt_nodes, phi_momentum_guess, station_layout)

RHO, MU, A = 1.225, 1.789e-5, 340.3


def _inputs(n, chord, twist, *, R=1.0, h=0.15, B=3, omega=100.0, vx=0.0, vp=0.0, pitch=0.0, spin=1.0):
    return {"radius_m": R, "hub_fraction": h, "blades": B, "chord_m": np.broadcast_to(chord, (n,)),
            "twist_rad": np.broadcast_to(twist, (n,)), "pitch_rad": pitch, "omega_radps": omega,
            "v_axial_mps": vx, "v_inplane_mps": vp, "rho_kgpm3": RHO, "mu_Pas": MU, "a_mps": A,
            "spin": spin}


def _stations(n, R=1.0, h=0.15):
    s, ds = station_layout(n)
    return R * (h + (1 - h) * s), R * (1 - h) * ds


def test_solution_satisfies_momentum_and_blade_element():
    sec = AnalyticSection(alpha0_rad=math.radians(-3))
    n = 16
    r, dr = _stations(n)
    inp = _inputs(n, 0.08, np.radians(30) * 0.3 / (r / 1.0) ** 0.5, vx=[0.0, 10.0, 30.0], omega=120.0)
    res = analyze_inputs(sec, inp, n)
    assert res.converged.all() and res.residual_max.max() < 1e-10
    for k, vx in enumerate([0.0, 10.0, 30.0]):
        u, v, F = res["u_mps"][:, k], res["v_mps"][:, k], res["F"][:, k]
        dTdr = res["dTdr_Npm"][:, k]
        dQdr = res["dQdr_N"][:, k]
        # annulus momentum with Prandtl's F (Glauert): dT = 4 pi r rho F (V + u) u dr
        np.testing.assert_allclose(dTdr, 4 * math.pi * r * RHO * F * (vx + u) * u, rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(dQdr, 4 * math.pi * r ** 3 * RHO * F * (vx + u) * (v / r), rtol=1e-9,
                                   atol=1e-9)
        assert np.isclose(res["thrust_N"][k], np.dot(dTdr, dr))
        # the annulus-mean square swirl of Prandtl's picture, F v^2 (the slipstream's swirl
        # energy, Aircraft's bound on the swirl credit): between the uniform annulus of the
        # same angular momentum, (F v)^2, and the factor-free v^2 it replaced
        msq = res["vt_msq_F_m2ps2"][:, k]
        np.testing.assert_allclose(msq, F * v * v, rtol=1e-12, atol=1e-15)
        assert np.all((F * v) ** 2 <= msq + 1e-15) and np.all(msq <= v * v + 1e-15)
        assert np.any(msq < 0.5 * v * v)                   # the hub and tip stations, F < 1/2


def test_lightly_loaded_rotor_tends_to_actuator_disk():
    """No losses: disk-averaged induced velocity -> T/(2 rho A V) as the loading -> 0."""
    sec = AnalyticSection(cd0=0.0, k_drag=0.0, alpha_stall_rad=1.0)
    n, R, h = 24, 1.0, 0.2
    r, dr = _stations(n, R, h)
    V, omega = 40.0, 150.0
    phi_geo = np.arctan(V / (omega * r))
    errs = []
    for dth in (0.04, 0.02, 0.01, 0.005):
        inp = _inputs(n, 0.06, phi_geo + dth, R=R, h=h, omega=omega, vx=V)
        res = analyze_inputs(sec, inp, n, tip_loss=False, hub_loss=False)
        T = res["thrust_N"][0]
        A_ann = math.pi * R ** 2 * (1 - h * h)
        u_mean = np.dot(res["va_mps"][:, 0], 2 * math.pi * r * dr) / A_ann
        assert np.isclose(u_mean, res["va_mean_mps"][0])
        u_ad = -V / 2 + math.sqrt(V * V / 4 + T / (2 * RHO * A_ann))   # actuator disk, same T
        errs.append(abs(u_mean / (T / (2 * RHO * A_ann * V)) - 1.0))
        assert abs(u_mean / u_ad - 1.0) < 0.05
    # the linear (light-loading) limit is approached in proportion to the loading
    assert errs[-1] < 0.01 and errs[-1] < errs[0] / 4


def test_ideal_twist_hover_gives_uniform_inflow_and_unit_figure_of_merit():
    """theta = theta_t R/r, constant chord, no losses, no drag: uniform inflow
    u = sqrt(T / (2 rho A)) and FM -> 1 (up to swirl and large-angle terms)."""
    sec = AnalyticSection(cd0=0.0, k_drag=0.0, alpha_stall_rad=1.0, mach_correction=False)
    n, R, h = 30, 1.0, 0.2
    r, dr = _stations(n, R, h)
    inp = _inputs(n, 0.1, 0.06 * R / r, R=R, h=h, B=3, omega=120.0)
    res = analyze_inputs(sec, inp, n, tip_loss=False, hub_loss=False)
    assert res.converged.all()
    u = res["va_mps"][:, 0]
    A_ann = math.pi * R ** 2 * (1 - h * h)
    T, P = res["thrust_N"][0], res["power_W"][0]
    u_ideal = math.sqrt(T / (2 * RHO * A_ann))
    w = 2 * math.pi * r * dr / A_ann
    assert np.sqrt(np.dot(w, (u / u_ideal - 1) ** 2)) < 0.02       # uniform to 2 % (rms)
    fm = T * u_ideal / P
    assert 0.97 < fm < 1.0


def test_hover_figure_of_merit_below_one_with_losses():
    sec = AnalyticSection(alpha0_rad=math.radians(-3), cd0=0.011, k_drag=0.008)
    rotor = RotorGeometry(radius_m=1.2, blades=3, r_over_R=[0.12, 0.5, 1.0], chord_over_R=[0.08, 0.08, 0.06],
                          beta_rad=np.radians([22.0, 12.0, 6.0]), airfoil=sec)
    res = analyze(rotor, omega_radps=np.linspace(80, 160, 5), v_axial_mps=0.0)
    assert res.converged.all()
    fm = res["FM"]
    assert np.all(fm < 1.0) and np.all(fm > 0.4)
    # the no-loss, no-drag rotor has a higher figure of merit than the real one
    ideal = analyze(rotor, omega_radps=120.0, section=AnalyticSection(alpha0_rad=math.radians(-3), cd0=0.0,
                                                                       k_drag=0.0), tip_loss=False,
                    hub_loss=False)
    assert ideal["FM"][0] > fm[2] + 0.1


@pytest.mark.parametrize("vx,pitch_deg", [(0.0, 0.0), (15.0, 0.0), (-3.0, 0.0), (-25.0, 0.0), (60.0, -15.0),
                                          (120.0, -25.0), (0.0, -20.0)])
def test_hover_climb_descent_windmill_do_not_break(vx, pitch_deg):
    sec = AnalyticSection(alpha0_rad=math.radians(-3))
    rotor = RotorGeometry(radius_m=1.0, blades=3, r_over_R=[0.15, 0.5, 1.0], chord_over_R=[0.09, 0.08, 0.05],
                          beta_rad=np.radians([35.0, 20.0, 12.0]), airfoil=sec)
    res = analyze(rotor, omega_radps=150.0, v_axial_mps=vx, pitch_rad=math.radians(pitch_deg))
    for k in ("thrust_N", "torque_Nm", "power_W"):
        assert np.all(np.isfinite(res[k]))
    assert np.all(np.isfinite(res["phi_rad"]))
    assert res.residual_max[0] < 1e-8, f"residual {res.residual_max[0]:.2e} (quadrants {np.unique(res['quadrant'])})"
    if (vx, pitch_deg) == (60.0, -15.0):
        assert res["thrust_N"][0] < 0 and res["power_W"][0] < 0     # windmilling: drives the shaft


def test_rotation_sense_symmetry_in_nonaxial_flow():
    sec = AnalyticSection(alpha0_rad=math.radians(-3))
    n, m = 12, 8
    r, _ = _stations(n)
    out = {}
    for spin in (1.0, -1.0):
        inp = _inputs(n, 0.08, np.radians(25) * 0.4 / r, omega=120.0, vx=12.0, vp=20.0, spin=spin)
        res = analyze_inputs(sec, inp, n, m)
        assert res.converged.all()
        out[spin] = res
    a, b = out[1.0], out[-1.0]
    np.testing.assert_allclose(a["phi_rad"], b["phi_rad"], atol=1e-12)
    for k in ("thrust_N", "torque_Nm", "power_W", "hforce_N", "ms_hub_Nm", "yforce_N"):
        np.testing.assert_allclose(a[k], b[k], rtol=1e-12, atol=1e-9)
    # the advancing side carries more thrust: a rolling hub moment whose sign follows the spin
    np.testing.assert_allclose(a["mp_hub_Nm"], -b["mp_hub_Nm"], rtol=1e-12)
    assert a["mp_hub_Nm"][0] > 1.0
    assert a["hforce_N"][0] > 0                          # H acts downstream (drag-like)
    # without a skewed-wake model the loads are fore-aft symmetric: no side force, no pitch moment
    assert abs(a["yforce_N"][0]) < 1e-9 * a["thrust_N"][0] and abs(a["ms_hub_Nm"][0]) < 1e-9 * a["thrust_N"][0]
    # the swirl left in the wake turns with the blades (positive in the rotation sense for both)
    assert np.all(a["vt_mps"] > 0) and np.all(b["vt_mps"] > 0)


def test_zero_inplane_flow_with_azimuths_equals_axial():
    sec = AnalyticSection(alpha0_rad=math.radians(-3))
    n = 10
    r, _ = _stations(n)
    inp = _inputs(n, 0.08, np.radians(20) * 0.5 / r, omega=120.0, vx=8.0)
    ax = analyze_inputs(sec, inp, n, 1)
    az = analyze_inputs(sec, inp, n, 6)
    for k in ("thrust_N", "torque_Nm", "va_mean_mps"):
        np.testing.assert_allclose(ax[k], az[k], rtol=1e-12)
    assert abs(az["hforce_N"][0]) < 1e-9 and abs(az["yforce_N"][0]) < 1e-9


def test_momentum_guess_is_close_for_light_loading():
    sec = AnalyticSection()
    n = 12
    r, _ = _stations(n)
    theta = np.arctan(20.0 / (150.0 * r)) + 0.03
    inp = _inputs(n, 0.05, theta, omega=150.0, vx=20.0)
    res = analyze_inputs(sec, inp, n, tip_loss=False, hub_loss=False)
    guess = phi_momentum_guess(r, 0.05, theta, 20.0, 150.0 * r, 3)
    err = np.abs(guess - res["phi_rad"][:, 0])
    outer = r > 0.6
    assert np.max(err[outer]) < math.radians(0.2)     # small-angle formula: exact in the limit
    assert np.max(err) < math.radians(2.0)            # still a good start at 40 deg inflow


def test_nlp_mode_reproduces_analysis():
    """Three operating points as mapped BEMT nodes in an IPOPT feasibility problem."""
    from mdo.nlp import Problem

    sec = AnalyticSection(alpha0_rad=math.radians(-3))
    n, K = 12, 3
    r, _ = _stations(n, 1.2, 0.12)
    chord = np.full(n, 0.1)
    twist = np.radians(28.0) * 0.35 / (r / 1.2)
    vx = np.array([0.0, 10.0, 40.0])
    om = np.array([110.0, 120.0, 140.0])
    inp = _inputs(n, chord, twist, R=1.2, h=0.12, omega=om, vx=vx)
    ref = analyze_inputs(sec, inp, n)
    p = Problem("bemt_nodes")
    f = bemt_function(sec, n)
    mx_inputs = dict(inp)
    mx_inputs["omega_radps"] = ca.DM(om).T
    mx_inputs["v_axial_mps"] = ca.DM(vx).T
    mx_inputs["chord_m"] = ca.DM(chord)
    mx_inputs["twist_rad"] = ca.DM(twist)
    guess = np.stack([phi_momentum_guess(r, chord, twist, vx[k], om[k] * r, 3) for k in range(K)], axis=1)
    out = add_bemt_nodes(p, "rotor", f, mx_inputs, n_nodes=K, phi_init=guess)
    sol = p.solve(verbose=False, options={"tol": 1e-12, "acceptable_tol": 1e-12})
    assert sol.success
    phi = np.asarray(sol.value(out["phi_rad"]))
    np.testing.assert_allclose(phi, ref["phi_rad"], atol=1e-7)
    np.testing.assert_allclose(np.asarray(sol.value(out["thrust_N"])).ravel(), ref["thrust_N"], rtol=1e-6)


@pytest.mark.parametrize("wma_deg", [45.0, 15.0])
def test_tilt_wing_transition_incidence_converges_in_azimuth(wma_deg):
    """TTW-like rotor in transition (rotor axis at 45 and 15 deg to the flight path)."""
    from mdo.rotor import inflow_components

    sec = AnalyticSection(alpha0_rad=math.radians(-4), cd0=0.009, k_drag=0.007)
    rotor = RotorGeometry(radius_m=1.2, blades=3, r_over_R=[0.12, 0.4, 0.7, 1.0],
                          chord_over_R=[0.12, 0.16, 0.11, 0.06], beta_rad=np.radians([45.0, 25.0, 15.0, 11.0]),
                          airfoil=sec)
    V = 25.0 if wma_deg == 45.0 else 45.0
    vx, vp = inflow_components(V, math.radians(90.0 - wma_deg))
    T = {}
    for m in (8, 16, 32):
        res = analyze(rotor, omega_radps=140.0, v_axial_mps=vx, v_inplane_mps=vp, n_azimuth=m)
        assert res.converged.all()
        T[m] = (res["thrust_N"][0], res["hforce_N"][0], res["power_W"][0])
    for k in range(3):
        assert abs(T[8][k] / T[32][k] - 1) < 5e-3 and abs(T[16][k] / T[32][k] - 1) < 1e-3
    assert T[32][1] > 0
    axial = analyze(rotor, omega_radps=140.0, v_axial_mps=vx)
    # in-plane flow raises the mean dynamic pressure: more thrust and power than the axial part alone
    assert T[32][0] > axial["thrust_N"][0] and T[32][2] > axial["power_W"][0]


def test_hub_of_a_steeply_pitched_blade_has_its_root_past_pi_over_2():
    """The TTW's cruise (2026-12-05): a hover-twisted blade (hub 44 deg) at a 45-50 deg
    collective, 630 rpm and 78 m/s.  The hub station's root lies just past pi/2; the NLP's
    bounds must contain it (with pi/2 as the bound the hub station held the cruise
    collective) and the analysis must find the same root, and the loads must be regular
    at exactly pi/2 (no 1/cos(phi))."""
    from mdo.rotor import PHI_MAX_RAD
    from mdo.rotor.analysis import solve_phi
    from mdo.rotor.bemt import station_physics
    sec = AnalyticSection(alpha0_rad=math.radians(-4))
    n, R, h = 16, 1.16, 0.12
    r, _ = _stations(n, R, h)
    twist = np.radians(44.0) * r[0] / r
    for pitch_deg in (45.0, 50.0):
        inp = _inputs(n, 0.1, twist, R=R, h=h, omega=65.7, vx=78.0, pitch=math.radians(pitch_deg))
        sol = solve_phi(sec, inp, n)
        phi_hub = sol["phi_rad"][0, 0]
        assert sol["found"].all() and np.abs(sol["residual"]).max() < 1e-10
        assert 0.5 * math.pi < phi_hub < PHI_MAX_RAD, math.degrees(phi_hub)
        assert np.all(sol["phi_rad"][1:, 0] < 0.5 * math.pi)      # the other stations as before
        # the NLP reproduces it from the analysis' neighbourhood, inside its bounds
        fn = bemt_function(sec, n, 1, outputs="full")
        out = fn(**inp, phi_rad=sol["phi_rad"][:, 0])
        assert np.all(np.isfinite(np.array(out["thrust_N"])))
    ph = np.array([0.5 * math.pi - 1e-3, 0.5 * math.pi, 0.5 * math.pi + 1e-3])
    st = station_physics(ph, r[0], 0.1, twist[0] + math.radians(45), 78.0, 65.7 * r[0], RHO, MU, A, 3, R, h * R, sec)
    assert np.all(np.isfinite(st["W"])) and np.all(np.isfinite(st["v"]))
    assert abs(st["W"][1] - 0.5 * (st["W"][0] + st["W"][2])) < 1e-3 * st["W"][1]   # smooth through pi/2


def test_power_budget_closes_and_induced_exceeds_the_actuator_disk():
    # an APC-like blade in axial flow at three advance ratios: the lift's and the drag's work
    # add up to the shaft power beyond T V, and no blade does better than Froude's disk
    from mdo.rotor.geometry import DATA_DIR
    rot = RotorGeometry.from_csv(DATA_DIR / "apce_10x7_geometry.csv", diameter_m=0.254, blades=2,
                                 airfoil="e63:0.5:clark_y")
    n = 5000.0 / 60.0
    J = np.array([0.3, 0.5, 0.6])
    res = analyze(rot, omega_radps=2 * math.pi * n, v_axial_mps=J * n * 0.254, n_stations=20)
    b = res.power_budget()
    assert np.all(np.abs(b["closure"]) < 1e-9 * b["shaft"])
    assert b["useful"] / b["shaft"] == pytest.approx(np.asarray(res["eta"]), rel=1e-9)
    assert np.all(b["induced"] > b["ideal_induced"]) and np.all(b["ideal_induced"] > 0)
    assert np.all(b["profile"] > 0)
    with pytest.raises(Exception, match="power_budget"):
        analyze(rot, omega_radps=500.0, v_axial_mps=5.0, v_inplane_mps=3.0, n_stations=8).power_budget()
