"""Mass build-up: Table 1 gross weights and the response to the design variables."""
from dataclasses import replace

import casadi as ca
import numpy as np
import pytest

from mdo.core import units as u
from mdo.vehicle.catalog import VEHICLES, ga2p, ttw
from mdo.vehicle.mass import MassDesign, mass_table_markdown, mass_terms, solve_togw, togw_residual, total_mass

TABLE1_LB = {"ga2p": 3549.0, "ga8p": 3622.0, "ttw": 4850.0}


@pytest.mark.parametrize("key", sorted(VEHICLES))
def test_togw_within_2_percent_of_table1(key):
    """With the paper's bookkeeping - bare cells (packaging factor 1) and Table 1's motor
    ratings with no take-off overload - the build-up reproduces Table 1; with the packaged battery (1.42, the one
    battery mass the pack also carries) every aircraft is heavier, by the packaging mass
    and its snowball."""
    packaged = VEHICLES[key]()
    if key.startswith("ga"):    # the catalog flies the raw regressions; Table 1 is the paper's 1.16
        packaged = replace(packaged, mass_inputs={**packaged.mass_inputs, "airframe_calibration": 1.16})
    cfg = replace(packaged, battery=replace(packaged.battery, packaging_factor=1.0),
                  rotor_groups=tuple(replace(g, motor=replace(g.motor, short_time_power_factor=1.0))
                                     for g in packaged.rotor_groups))
    W = solve_togw(cfg)
    assert abs(W / u.LB - TABLE1_LB[key]) / TABLE1_LB[key] < 0.02
    packaged = replace(packaged, rotor_groups=cfg.rotor_groups)
    W_pk = solve_togw(packaged)
    extra = packaged.battery.mass_kg - cfg.battery.mass_kg
    assert extra < W_pk - W < 2.0 * extra
    assert abs(float(togw_residual(cfg, W))) < 1e-5
    md = mass_table_markdown(cfg)
    assert "take-off gross weight" in md and "battery" in md and "payload" in md


def test_raw_regressions_weigh_the_x57_mod4_as_nasa_does():
    """The GA family flies the raw regressions (calibration 1.0, issue 17: a calibration only where a
    regression is known to be off).  The evidence: the X-57 Mod IV, an electric P2006T with this
    fuselage, comes out within 5 % of NASA's "approximately 3000 lb" gross weight (1420 kg, +4.3 %;
    its problem file, not the catalog, defines it)."""
    import importlib.util
    from pathlib import Path
    path = Path(__file__).resolve().parents[1] / "problems" / "x57_mod4.py"
    spec = importlib.util.spec_from_file_location("x57_mod4_problem", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    cfg = mod.x57_mod4()
    assert cfg.mass_inputs.get("airframe_calibration", 1.0) == 1.0
    assert ga2p().mass_inputs["airframe_calibration"] == 1.0
    assert abs(solve_togw(cfg) / (3000 * u.LB) - 1.0) < 0.05


def _terms_at(cfg, **kw):
    d = MassDesign.baseline(cfg)
    for k, v in kw.items():
        getattr(d, k).update(v)
    return d


def test_wing_mass_grows_with_span_and_taper_at_constant_area():
    cfg = replace(ga2p(), wing_structure=None)      # Raymer's Eq. 15.46 alone
    W = solve_togw(cfg)
    base = mass_terms(cfg, W)["wing: main_wing"]
    longer = mass_terms(cfg, W, _terms_at(cfg, wing_span_m={"main_wing": 13.0}))["wing: main_wing"]
    tapered = mass_terms(cfg, W, _terms_at(cfg, wing_taper={"main_wing": 1.0}))["wing: main_wing"]
    # Raymer: W ~ AR^0.6 at constant area -> (13/11.4)^1.2 = 1.17
    assert longer / base == pytest.approx((13.0 / 11.4) ** 1.2, rel=1e-9)
    assert tapered > base
    # and the consistent gross weight follows
    assert solve_togw(cfg, _terms_at(cfg, wing_span_m={"main_wing": 13.0})) > W


def test_propeller_mass_grows_with_radius():
    cfg = ga2p()
    W = solve_togw(cfg)
    key = "propellers: propellers (2)"
    m0 = mass_terms(cfg, W)[key]
    m1 = mass_terms(cfg, W, _terms_at(cfg, rotor_radius_m={"propellers": 1.12}))[key]
    assert m1 / m0 == pytest.approx((1.12 / 0.97) ** 0.782, rel=1e-9)


def test_symbolic_build_up_matches_numeric_and_has_gradients():
    cfg = ttw()
    b, lam, R, W = (ca.SX.sym(n) for n in ("b", "lam", "R", "W"))
    d = MassDesign({"main_wing": b, "tandem_wing": 9.6}, {"main_wing": lam, "tandem_wing": 1.0},
                   {"rotors": R})
    m = total_mass(cfg, W, d)
    F = ca.Function("m", [b, lam, R, W], [m, ca.gradient(m, ca.vertcat(b, lam, R, W))])
    W0 = solve_togw(cfg)
    val, grad = F(9.6, 1.0, 1.2, W0)
    assert float(val) == pytest.approx(W0, rel=1e-9)
    g = np.array(grad).ravel()
    assert g[0] > 0 and g[1] > 0 and g[2] > 0 and 0 < g[3] < 0.5  # fixed point contracts
