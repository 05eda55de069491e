"""The propellers' clearance to the fuselage (14 CFR 23.925(d)(1)): the geometry, the design
check of a run folder, and the body's placement every reader shares."""
import json
import math

import numpy as np
import pytest

from mdo.plots.checks import design_checks
from mdo.vehicle.catalog import ga2p
from mdo.vehicle.config import (FUSELAGE_SECTION_POINTS, PROPELLER_STRUCTURE_CLEARANCE_M, fuselage_gaps_m,
                                fuselage_section_scale)


def _exact_rim_distance(a, b, zc, y, z, R, n=200001):
    t = np.linspace(-math.pi, math.pi, n)
    return float(np.min(np.hypot(y - a * np.cos(t), z - zc - b * np.sin(t)))) - R


def test_gaps_of_a_circular_body_are_exact():
    # body of radius 0.5 centred at z = 0.2, disk of radius 0.9 level with it at y = 1.5: 0.1 m
    gaps = fuselage_gaps_m(0.5, 0.5, 0.2, 1.5, 0.2, 0.9)
    assert len(gaps) == FUSELAGE_SECTION_POINTS
    assert min(gaps) == pytest.approx(0.1, abs=1e-12)


@pytest.mark.parametrize("y, z, R", [(1.311, 0.784, 0.97), (1.518, 0.784, 1.073), (0.9, -0.3, 0.3)])
def test_gaps_of_the_ga_body_within_two_millimetres(y, z, R):
    # the GA body (42 x 62 in) below a high wing: the sampled section against a dense one
    cfg = ga2p()
    a, b = cfg.fuselage.section_half_axes(2.02)
    zc = cfg.fuselage_axis_z_m
    exact = _exact_rim_distance(a, b, zc, y, z, R)
    sampled = min(fuselage_gaps_m(a, b, zc, y, z, R))
    assert sampled >= exact - 1e-12          # the polygon lies inside the ellipse
    assert sampled - exact < 2e-3


def test_body_shape_and_placement():
    cfg = ga2p()
    f = cfg.fuselage
    # the top of the body at the wing root (a high wing), unless the config places it
    assert cfg.fuselage_axis_z_m + 0.5 * f.height_m == pytest.approx(max(w.root_z_m for w in cfg.lifting_wings))
    assert fuselage_section_scale([-0.1, 0.0, 0.2, 0.5, 1.0, 1.1]).tolist() == pytest.approx([0, 0, 1, 1, 0.12, 0])
    assert f.section_half_axes(f.nose_x_m + 0.3 * f.length_m) == pytest.approx((0.5 * f.width_m, 0.5 * f.height_m))
    assert f.section_half_axes(f.nose_x_m - 1.0) == (0.0, 0.0)


def _geometry(cfg, y, R):
    f = cfg.fuselage
    return {"fuselage": {"length_m": f.length_m, "width_m": f.width_m, "height_m": f.height_m,
                         "nose_x_m": f.nose_x_m, "axis_z_m": cfg.fuselage_axis_z_m},
            "rotors": [{"center_m": [2.02, s * y, 0.784], "radius_m": R} for s in (1, -1)]}


def test_design_check_flags_the_papers_twin_cutting_into_the_fuselage(tmp_path):
    # Table 3's GA-2P baseline: R 0.97 m at 23 % of the 5.7 m semispan cuts 11 cm into the
    # P2006T body; moved out to 1.8 m it clears
    cfg = ga2p()
    a, b = cfg.fuselage.section_half_axes(2.02)
    for y, R, inside in ((1.311, 0.97, False), (1.8, 0.97, True)):
        (tmp_path / "geometry.json").write_text(json.dumps(_geometry(cfg, y, R)))
        c = {c["quantity"]: c for c in design_checks(tmp_path)}["propeller tip clearance to the fuselage"]
        assert c["ok"] is inside
        assert c["low"] == PROPELLER_STRUCTURE_CLEARANCE_M
        assert c["value"] == pytest.approx(_exact_rim_distance(a, b, cfg.fuselage_axis_z_m, y, 0.784, R), abs=2e-3)
        if not inside:
            assert c["value"] == pytest.approx(-0.11, abs=0.01)
