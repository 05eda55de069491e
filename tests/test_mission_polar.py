"""The mission with the fixed-polar vehicle against closed-form answers (issue 8 acceptance).

* level cruise energy = P t, with P from the force balance solved independently;
* a steady climb's extra energy = m g dh / (eta_p eta_chain);
* spectral convergence of the mission energy with the node count;
* joins continuous; every segment kind of Table 4 solved (hover power = momentum theory).
"""
import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import fsolve

from mdo.core import density
from mdo.core.units import FT, FT_PER_MIN, KWH, MPH, NMI
from mdo.mission import Mission
from mdo.mission import segments as S
from mdo.nlp import Problem
from mdo.vehicle import G0, PolarVehicle

GA = dict(mass_kg=1610.0, wing_area_m2=14.76, CD0=0.0175, induced_drag_factor=0.045, CL_alpha_per_rad=5.1,
          propulsive_efficiency=0.82, chain_efficiency=0.9)


def solve(vehicle, segments, nodes=8, tol=1e-12, **kw):
    p = Problem("t")
    m = Mission(vehicle, segments, nodes=nodes, **kw).build(p)
    sol = p.solve(verbose=False, options={"tol": tol})
    assert sol.success, sol.status + "\n" + sol.violation_report()
    return m, sol


def test_level_cruise_energy_is_power_times_time():
    veh = PolarVehicle(**GA)
    h, V, dist = 2500 * FT, 175 * MPH, 50 * NMI
    m, sol = solve(veh, [S.ConstantSpeedConstantAltitude("CR", speed_mps=V, altitude_m=h, distance_m=dist)],
                   nodes=5)
    # oracle: the two force equations solved on their own (thrust along the body axis, theta = alpha)
    q, W = 0.5 * float(density(h)) * V ** 2, GA["mass_kg"] * G0

    def eqs(x):
        a, T = x
        CL = GA["CL_alpha_per_rad"] * a
        return [T * math.cos(a) - q * GA["wing_area_m2"] * (GA["CD0"] + GA["induced_drag_factor"] * CL ** 2),
                T * math.sin(a) + q * GA["wing_area_m2"] * CL - W]

    a, T = fsolve(eqs, [0.05, 1000.0], xtol=1e-14)
    P = T * V * math.cos(a) / (GA["propulsive_efficiency"] * GA["chain_efficiency"])
    E = sol.value(m.energy_used_J)
    assert E == pytest.approx(P * dist / V, rel=1e-10)
    np.testing.assert_allclose(sol.value(m.theta), a, rtol=1e-9)
    assert sol["mission_range_nmi"] == pytest.approx(50.0, rel=1e-12)


def test_steady_climb_extra_energy_is_weight_times_height_over_efficiency():
    # k = 0: the drag does not depend on lift, so thrust power = (D(h) + W sin gamma) V exactly
    veh = PolarVehicle(**{**GA, "induced_drag_factor": 0.0})
    V, rate, h0, h1 = 60.0, 600 * FT_PER_MIN, 500 * FT, 4500 * FT
    m, sol = solve(veh, [S.LinearSpeedConstantRate("CL", altitude_start_m=h0, altitude_end_m=h1, speed_start_mps=V,
                                                   speed_end_mps=V, climb_rate_mps=rate)], nodes=12)
    eta = GA["propulsive_efficiency"] * GA["chain_efficiency"]
    T = (h1 - h0) / rate
    drag_energy, _ = quad(lambda t: 0.5 * float(density(h0 + rate * t)) * V ** 3 * GA["wing_area_m2"] * GA["CD0"],
                          0.0, T, epsabs=0, epsrel=1e-13)
    extra = sol.value(m.energy_used_J) - drag_energy / eta
    assert extra == pytest.approx(GA["mass_kg"] * G0 * (h1 - h0) / eta, rel=1e-9)


def _climb_energy(n, form="differentiation"):
    veh = PolarVehicle(**GA)
    seg = S.LinearSpeedConstantRate("CL", altitude_start_m=500 * FT, altitude_end_m=2500 * FT,
                                    speed_start_mps=110 * MPH, speed_end_mps=175 * MPH, climb_rate_mps=500 * FT_PER_MIN)
    m, sol = solve(veh, [seg], nodes=n, state_form=form)
    return sol.value(m.energy_used_J)


def test_spectral_convergence_of_mission_energy():
    ref = _climb_energy(32)
    err = {n: abs(_climb_energy(n) / ref - 1) for n in (4, 6, 8, 10, 12)}
    for a, b in ((4, 6), (6, 8), (8, 10), (10, 12)):
        assert err[b] < err[a] / 10, err          # at least a decade per two nodes: exponential
    assert err[12] < 1e-10, err
    # the integration-matrix form converges to the same energy
    assert _climb_energy(12, "integration") == pytest.approx(ref, rel=1e-11)


def test_joins_are_continuous_and_states_integrate(tmp_path):
    from mdo.mission.profiles import ga_mission
    veh = PolarVehicle(**GA, battery_capacity_J=120 * KWH)
    p = Problem("ga")
    m = ga_mission(veh, nodes=10).build(p)
    p.add_report(m.report)
    sol = p.solve(verbose=False)
    assert sol.success
    m.report(sol, tmp_path)
    import csv
    rows = list(csv.DictReader(open(tmp_path / "mission.csv")))
    assert len(rows) == m.K
    for col in ("time_s", "altitude_m", "speed_mps", "body_angle_deg", "CL", "thrust_N", "shaft_power_W",
                "battery_power_W", "state_of_charge", "distance_m"):
        assert col in rows[0], col
    f = lambda r, k: float(r[k])  # noqa: E731
    joins = 0
    for a, b in zip(rows[:-1], rows[1:]):
        if a["segment"] != b["segment"]:
            joins += 1
            for k in ("time_s", "altitude_m", "speed_mps", "energy_drawn", "state_of_charge", "distance_m"):
                assert f(b, k) == pytest.approx(f(a, k), rel=1e-12, abs=1e-9), (a["segment"], b["segment"], k)
    assert joins == len(m.segments) - 1
    t = np.array([f(r, "time_s") for r in rows])
    assert np.all(np.diff(t) >= 0)
    # the energy state is the integral of the battery power, segment by segment (Clenshaw-Curtis check)
    from mdo.core import Collocation
    P = np.array([f(r, "battery_power_W") for r in rows])
    E = np.array([f(r, "energy_drawn") for r in rows])
    for g in m._segs:
        sl = slice(g.node0, g.node0 + g.n)
        cc = g.kin.duration_s * Collocation(g.n).weights @ P[sl]
        assert E[sl][-1] - E[sl][0] == pytest.approx(cc, rel=1e-7)
    assert (tmp_path / "mission.png").stat().st_size > 10000
    assert sol["battery_energy_kWh"] == pytest.approx(E[-1] / KWH, rel=1e-9)


def _evtol(**kw):
    kw.setdefault("wing_tilts", True)
    return PolarVehicle("evtol", mass_kg=2200.0, wing_area_m2=21.7, CD0=0.03, induced_drag_factor=0.047,
                        CL_alpha_per_rad=4.9, propulsive_efficiency=0.75, chain_efficiency=0.9,
                        disk_area_m2=8 * math.pi * 1.2 ** 2, **kw)


def test_every_segment_kind_solves_and_hover_matches_momentum_theory():
    veh = _evtol(CL_max=1.5, flat_plate_drag_coefficient=1.2)
    up, fwd = {"wing_mounted_angle_rad": math.pi / 2}, {"wing_mounted_angle_rad": 0.0}
    segs = [
        S.VerticalAscent("VC", altitude_start_m=0.0, altitude_end_m=15.0, climb_rate_mps=1.5, parameters=up),
        S.Hover("HOV", duration_s=20.0, parameters=up),
        S.ConstantAccelerationConstantPitchrateConstantAltitude(
            "VT", speed_start_mps=1.0, speed_end_mps=20.0, acceleration_mps2=1.5,
            parameters={"wing_mounted_angle_rad": math.radians(45)}),
        S.ConstantAccelerationConstantAngleLinearClimb("CT", altitude_end_m=40.0, speed_end_mps=35.0,
                                                       climb_rate_mps=2.5,
                                                       parameters={"wing_mounted_angle_rad": math.radians(15)}),
        S.ConstantAccelerationConstantAltitude("ACC", speed_end_mps=50.0, acceleration_mps2=1.0, parameters=fwd),
        S.LinearSpeedConstantRate("CL", altitude_end_m=500.0, speed_end_mps=60.0, climb_rate_mps=2.5,
                                  parameters=fwd),
        S.ConstantSpeedConstantAltitude("CR", distance_m=20e3, parameters=fwd),
        S.LinearSpeedConstantRate("D", altitude_end_m=40.0, speed_end_mps=15.0, climb_rate_mps=-1.5, parameters=fwd),
        S.ConstantAccelerationConstantPitchrateConstantAltitude(
            "DT", speed_end_mps=1.5, acceleration_mps2=-0.5, parameters={"wing_mounted_angle_rad": math.radians(75)}),
        S.VerticalDescent("VD", altitude_end_m=0.0, descent_rate_mps=1.5, parameters=up),
    ]
    m, sol = solve(veh, segs, nodes=8, tol=1e-10, body_angle_bounds_rad=(-1.4, 1.5))
    kinds = {s.kind for s in segs}
    assert len(kinds) == 8                         # the seven kinds of Table 4 and hover
    assert all(v["scaled"] < 1e-8 for v in sol.violations)
    P = sol.value(m.evaluation.outputs["battery_power_W"].expr)
    th = sol.value(m.theta)
    rho0 = float(density(15.0))
    W, A, eta = 2200.0 * G0, 8 * math.pi * 1.2 ** 2, 0.75 * 0.9
    hov = [k for k, s in enumerate(m.segment_of_node) if s == "HOV"]
    np.testing.assert_allclose(th[hov], 0.0, atol=1e-9)                    # thrust vertical
    np.testing.assert_allclose(P[hov], W ** 1.5 / math.sqrt(2 * rho0 * A) / eta, rtol=1e-9)
    # vertical climb: T = W + D (wing edge-on, CL = 0), P = T (V + v_i) with the climb inflow of momentum theory
    vc = [k for k, s in enumerate(m.segment_of_node) if s == "VC"]
    h = np.array([float(x) for x in sol.value(m.cond.altitude_m)])[vc]
    rho = np.array([float(density(x)) for x in h])
    T = W + 0.5 * rho * 1.5 ** 2 * 21.7 * 0.03
    vi = -0.75 + np.sqrt(0.75 ** 2 + T / (2 * rho * A))
    np.testing.assert_allclose(P[vc], T * (1.5 + vi) / eta, rtol=1e-9)


def test_prescribed_pitch_schedule_with_a_free_tilt():
    # a tilt-rotor: the wing stays, the thrust line tilts (a per-node unknown) on top of a 60 deg WMA
    veh = _evtol(free_tilt=True, wing_tilts=False)
    segs = [S.ConstantAccelerationConstantPitchrateConstantAltitude(
        "VT", altitude_m=20.0, speed_start_mps=2.0, speed_end_mps=30.0, acceleration_mps2=1.0,
        pitch_initial_rad=0.10, pitch_final_rad=0.02, parameters={"wing_mounted_angle_rad": math.radians(60)}),
        S.ConstantAccelerationConstantPitchrateConstantAltitude(
            "VT2", speed_end_mps=40.0, acceleration_mps2=1.0, pitch_final_rad=0.05)]
    m, sol = solve(veh, segs, nodes=7, tol=1e-10)
    th = sol.value(m.theta)
    s = np.concatenate([g.kin.s for g in m._segs])
    np.testing.assert_allclose(th[:7], 0.10 + (0.02 - 0.10) * s[:7], atol=1e-14)
    np.testing.assert_allclose(th[7:], 0.02 + (0.05 - 0.02) * s[7:], atol=1e-14)   # continuous attitude
    tilt = sol.value(m.unknowns["thrust_tilt"])
    assert np.ptp(tilt) > 0.05                      # the mission used the second control


def test_free_duration_cruise_spends_an_energy_budget():
    veh = PolarVehicle(**GA)
    h, V = 2500 * FT, 175 * MPH
    p = Problem("range")
    m = Mission(veh, [S.ConstantSpeedConstantAltitude("CR", speed_mps=V, altitude_m=h,
                                                      free_duration=(60, 20000, 1000))], nodes=5).build(p)
    p.constrain("budget", m.energy_used_J - 30 * KWH, scale=KWH, unit="J")
    p.minimize(-m.range_m / 1e5, unit="-")
    sol = p.solve(verbose=False, options={"tol": 1e-12})
    assert sol.success
    ref, ref_sol = solve(veh, [S.ConstantSpeedConstantAltitude("CR", speed_mps=V, altitude_m=h, duration_s=100.0)],
                         nodes=5)
    P = ref_sol.value(ref.energy_used_J) / 100.0
    assert sol["CR.duration"] == pytest.approx(30 * KWH / P, rel=1e-9)
    assert sol.value(m.range_m) == pytest.approx(V * 30 * KWH / P, rel=1e-9)


def test_wing_area_design_variable_finds_the_analytic_optimum():
    # cruise only: minimum drag where the zero-lift and induced drag are equal, S* = W/(q sqrt(CD0/k))
    veh = PolarVehicle(**{**GA, "CL_alpha_per_rad": 2 * math.pi}, design_wing_area=(5.0, 40.0))
    h, V = 2500 * FT, 175 * MPH
    p = Problem("wing")
    m = Mission(veh, [S.ConstantSpeedConstantAltitude("CR", speed_mps=V, altitude_m=h, distance_m=50 * NMI)],
                nodes=4).build(p)
    p.minimize(m.energy_used_J / KWH, unit="kWh")
    sol = p.solve(verbose=False, options={"tol": 1e-12})
    assert sol.success
    q, W = 0.5 * float(density(h)) * V ** 2, GA["mass_kg"] * G0
    S_drag = W / (q * math.sqrt(GA["CD0"] / GA["induced_drag_factor"]))   # minimum drag: CD0 = k CL^2
    k, cla = GA["induced_drag_factor"], 2 * math.pi

    def thrust_power(area):   # the force balance with the thrust on the body axis, solved on its own
        a, T = fsolve(lambda x: [x[1] * math.cos(x[0]) - q * area * (GA["CD0"] + k * (cla * x[0]) ** 2),
                                 x[1] * math.sin(x[0]) + q * area * cla * x[0] - W], [0.05, 1000.0], xtol=1e-12)
        return T * V * math.cos(a)

    from scipy.optimize import minimize_scalar
    S_star = minimize_scalar(thrust_power, bracket=(5, 7, 10), tol=1e-10).x
    assert sol["polar.wing_area"] == pytest.approx(S_star, rel=1e-5)
    assert S_star == pytest.approx(S_drag, rel=0.02)        # near the textbook minimum-drag wing
