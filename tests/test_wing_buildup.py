"""Drag build-up (mdo.wing.buildup): flat-plate limits, transition modes, slipstream scrubbing,
cooling and excrescence terms, CasADi, and the P2006T CD0 / cruise speed against its class."""
import importlib.util
import math
import pathlib

import casadi as ca
import numpy as np
import pytest

from mdo.core.errors import InputError
from mdo.wing.buildup import (BodyComponent, CoolingDrag, DragBuildup, SurfaceComponent, Transition,
                              composite_skin_friction)

RE = np.logspace(6, 8, 9)


def _blasius(re):
    return 1.328 / np.sqrt(re)


def _turb(re):
    return 0.455 / np.log10(re) ** 2.58


def test_flat_plate_limits():
    # (rtol 1e-4: the smooth floor sqrt(Re^2 + 1e4^2) of mdo.wing.drag shifts Re by 5e-5 at 1e6)
    # fully turbulent = the Schlichting fit; transition at the trailing edge = Blasius
    np.testing.assert_allclose(composite_skin_friction(RE, 0.0, Transition.turbulent()), _turb(RE), rtol=1e-4)
    np.testing.assert_allclose(composite_skin_friction(RE, 0.0, Transition.fixed(1.0)), _blasius(RE), rtol=1e-4)
    np.testing.assert_allclose(composite_skin_friction(RE, 0.0, Transition.fixed(0.0)), _turb(RE), rtol=1e-4)


def test_prandtl_schlichting_composite():
    # Schlichting's 0.455/(log Re)^2.58 - 1700/Re for Re_tr = 5e5 (free transition, no cap)
    cf = composite_skin_friction(RE, 0.0, Transition.free(x_max=1.0, re_crit=5e5))
    # Eq. B2 gives 1614/Re with this turbulent fit (Schlichting's 1700 comes from the 0.074 Re^-0.2
    # law): 3.1 % at Re = 1e6, < 1 % above 3e6
    ref = _turb(RE) - 1700.0 / RE
    np.testing.assert_allclose(cf, ref, rtol=0.035)
    np.testing.assert_allclose(cf, _turb(RE) - 1614.0 / RE, rtol=2e-3)


def test_transition_modes_order_and_free_location():
    re = 6e6
    cfs = [composite_skin_friction(re, 0.2, t) for t in
           (Transition.turbulent(), Transition.fixed(0.1), Transition.fixed(0.3), Transition.fixed(1.0))]
    assert all(a > b for a, b in zip(cfs, cfs[1:]))
    free = Transition.free(x_max=0.4, re_crit=5e5)
    assert free.location(5e7) == pytest.approx(0.01, abs=1e-3)       # Re criterion governs
    assert free.location(2e5) == pytest.approx(0.4, abs=0.011)       # capped at the pressure minimum
    assert free.location(2e6) == pytest.approx(0.25, abs=1e-3)
    with pytest.raises(InputError, match="transition.mode"):
        Transition("laminar")


def test_roughness_cutoff_caps_reynolds():
    cf_smooth = composite_skin_friction(1e9, 0.0, Transition.turbulent())
    cf_rough = composite_skin_friction(1e9, 0.0, Transition.turbulent(), length_m=10.0)
    assert cf_rough > 1.2 * cf_smooth


def _plate_buildup(f_s=0.0):
    wing = SurfaceComponent("wing", 10.0, 1.0, 0.12, 0.3, transition=Transition.turbulent(),
                            slipstream_fraction=f_s)
    return DragBuildup(10.0, (wing,), excrescence_fraction=0.0)


def test_slipstream_scrubbing_dynamic_pressure_ratio():
    V, rho, mu = 60.0, 1.0, 1.8e-5
    base = _plate_buildup().evaluate(V, rho, mu, 0.0)["D_N"]
    for r in (1.1, 1.3, 1.6):
        full = _plate_buildup().evaluate(V, rho, mu, 0.0, slipstream={"wing": (1.0, r)})["D_N"]
        re = rho * V / mu
        cf_ratio = _turb(r * re) / _turb(re)
        assert full / base == pytest.approx(r * r * cf_ratio, rel=2e-3)
        assert 0.9 * r * r < full / base < r * r                # q ratio, less the Re gain
        half = _plate_buildup().evaluate(V, rho, mu, 0.0, slipstream={"wing": (0.5, r)})["D_N"]
        assert half - base == pytest.approx(0.5 * (full - base), rel=1e-9)
    with pytest.raises(InputError, match="slipstream"):
        _plate_buildup().evaluate(V, rho, mu, slipstream={"tail": (1.0, 1.2)})


def test_cooling_and_excrescence_terms():
    fus = BodyComponent("fuselage", 8.0, 1.2)
    bu = DragBuildup(15.0, (fus,), excrescence_fraction=0.1, cooling=CoolingDrag(30.0, 0.5))
    V, p_loss = 70.0, 5e3
    out = bu.evaluate(V, 1.0, 1.8e-5, 0.2, heat_loss_W=p_loss)
    t = out["terms"]
    assert t["cooling"]["D_N"] * V == pytest.approx(0.5 * V * V / (1005.0 * 30.0) * p_loss, rel=1e-9)
    assert t["excrescence"]["D_N"] == pytest.approx(0.1 * t["fuselage"]["D_N"], rel=1e-12)
    assert out["D_N"] == pytest.approx(sum(x["D_N"] for x in t.values()), rel=1e-9)
    assert out["CD0"] == pytest.approx(sum(x["dCD"] for x in t.values()), rel=1e-6)


@pytest.mark.parametrize("kind", [ca.SX, ca.MX])
def test_casadi_matches_numbers_and_gradients_finite(kind):
    bu = DragBuildup(14.0, (SurfaceComponent("wing", 12.0, 1.3, transition=Transition.free(0.4)),
                            BodyComponent("nacelle", 2.0, 0.7, "nacelle", 1.5, count=2)))
    V = kind.sym("V", 1, 3)
    r = kind.sym("r", 1, 3)
    out = bu.evaluate(V, 1.1, 1.8e-5, V / 340.0, slipstream={"nacelle": (1.0, r)}, heat_loss_W=4e3)
    f = ca.Function("f", [V, r], [out["D_N"], ca.jacobian(out["D_N"], ca.vertcat(V.T, r.T))])
    vals = np.array([[0.0, 30.0, 70.0]])
    d, jac = f(vals, np.array([[1.0, 1.2, 1.05]]))
    assert np.all(np.isfinite(np.array(jac)))
    num = bu.evaluate(70.0, 1.1, 1.8e-5, 70.0 / 340.0, slipstream={"nacelle": (1.0, 1.05)},
                      heat_loss_W=4e3)["D_N"]
    assert float(d[0, 2]) == pytest.approx(num, rel=1e-10)
    assert float(d[0, 0]) == pytest.approx(0.0, abs=1e-9)


def _p2006t_module():
    path = pathlib.Path(__file__).resolve().parents[1] / "problems/validation/p2006t_drag.py"
    spec = importlib.util.spec_from_file_location("p2006t_drag", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_p2006t_cd0_and_cruise_speed_in_class():
    mod = _p2006t_module()
    bu = mod.build_p2006t()
    op = mod.cruise_speed(bu, 7000 * 0.3048, 1180.0, 2 * 69.0e3 * mod.gagg_farrar(7000 * 0.3048))
    # CD0 between Raymer's equivalent skin friction for a light twin (0.0198 on this S_wet)
    # and the 0.030 top of the class; cruise speed within 10 % of the published 140 KTAS
    assert 0.019 <= op["CD0"] <= 0.030
    assert op["V"] / (1852 / 3600) == pytest.approx(140.0, rel=0.10)
    assert 0.78 <= op["eta_p"] <= 0.82


def test_p2006t_against_the_flight_manual_tables():
    """The build-up against the P2006T AFM's cruise and climb tables (issue 17 item 1): every
    cruise-table point within 10 % in speed (power % read of the 69 kW continuous rating), the
    sea-level best rate of climb within 10 % at every tabulated mass."""
    mod = _p2006t_module()
    bu = mod.build_p2006t()
    cruise = mod.afm_cruise_checks(bu)
    assert len(cruise) == len(mod.AFM_CRUISE) == 18
    assert max(abs(r[4]) for r in cruise) <= 0.10
    sea_level = [r for r in mod.afm_climb_checks(bu) if r[1] == 0]
    assert len(sea_level) == 3
    assert max(abs(r[5]) for r in sea_level) <= 0.10


def test_the_catalogs_p2006t_drag_calibration_is_the_flight_manuals():
    """GA-2P and GA-8P fly the P2006T airframe with ``P2006T_LEAKAGE_FRACTION``: it must stay the
    allowance at which the build-up's mean cruise-speed error against the AFM tables is zero
    (within 0.02), and with it every cruise-table point within 3 %."""
    from mdo.vehicle.catalog import P2006T_LEAKAGE_FRACTION, ga2p, ga8p
    mod = _p2006t_module()
    bu = mod.build_p2006t()
    assert mod.afm_leakage_fraction(bu) == pytest.approx(P2006T_LEAKAGE_FRACTION, abs=0.02)
    assert max(abs(r[4]) for r in mod.afm_cruise_checks(mod.calibrated_p2006t(bu))) <= 0.03
    for cfg in (ga2p(), ga8p()):
        assert cfg.drag.leakage_protuberance_fraction == P2006T_LEAKAGE_FRACTION


def test_p2006t_climb_table_within_10_percent_with_the_calibration():
    """Issue 17's P2006T check on the AFM's 12 climb points (3 masses, 0-12 000 ft), flown at
    the AFM's Vy at constant indicated speed with the calibration the cruise tables give: every
    point within 10 %.  The constant-speed climb gives up 0.5-2 % of its rate to the
    acceleration as the air thins (energy height)."""
    mod = _p2006t_module()
    bu = mod.calibrated_p2006t(mod.build_p2006t())
    rows = mod.afm_climb_checks(bu)
    assert len(rows) == 12 and max(abs(r[5]) for r in rows) <= 0.10
    h = 12000 * 0.3048
    op = mod.operating_point(bu, 45.0, h, 1180.0, 2 * 69e3 * mod.gagg_farrar(h))
    steady = op["excess_power_W"] / (1180.0 * mod.G) / (0.3048 / 60)
    assert 0.005 < 1 - mod.climb_rate_fpm(op, h, 1180.0) / steady < 0.02


def test_p2006t_ld_max_on_raymers_class_trend():
    """Issue 17's L/D against its class: the P2006T build-up's (L/D)max, as stated and with the
    catalog's calibration, within 10 % of Raymer's trend for retractable-gear propeller aircraft,
    K_LD sqrt(b^2/S_wet) with K_LD = 11 (15.6 on this wetted area), and above the fixed-gear
    trend's K_LD = 9; a wider wing of the same area raises the trend as sqrt(b^2/S_wet)."""
    mod = _p2006t_module()
    bu = mod.build_p2006t()
    h = 7000 * 0.3048
    power = 2 * 69.0e3 * mod.gagg_farrar(h)
    trend = mod.raymer_ld_max(bu, 11.4)
    assert trend == pytest.approx(15.6, abs=0.1)
    for b in (bu, mod.calibrated_p2006t(bu)):
        ld = mod.model_ld_max(mod.cruise_speed(b, h, 1180.0, power), 11.4, b.s_ref_m2)
        assert ld == pytest.approx(trend, rel=0.10)
        assert ld > mod.raymer_ld_max(b, 11.4, mod.RAYMER_K_LD_FIXED_GEAR_PROP)
    wide = mod.build_p2006t(14.87, 0.66)
    ratio = mod.raymer_ld_max(wide, 14.87) / trend
    assert ratio == pytest.approx(14.87 / 11.4 * math.sqrt(mod.total_wetted_area(bu) / mod.total_wetted_area(wide)))
