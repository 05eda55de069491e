"""The ailerons still fly at the stall onset (mdo.vehicle.stall_pattern; issue 16 item 4)."""
from dataclasses import replace

import casadi as ca
import numpy as np
import pytest

from mdo.core.smooth import soft_min
from mdo.mission import Mission
from mdo.nlp import Problem
from mdo.vehicle.aircraft import Aircraft
from mdo.vehicle.catalog import TTW_AILERON_SPAN_ETA, ga2p, ttw
from mdo.vehicle.stall_pattern import stall_pattern_rows
from test_operating_limits import SMALL, _initial, _segments


@pytest.fixture(scope="module")
def ga():
    p = Problem("pattern")
    v = Aircraft(ga2p(), **SMALL)
    Mission(v, _segments()).build(p)
    return v


def _excess(v, span, taper, twist_deg):
    """Worst aileron strip's cl - cl_max at the stall onset of a numeric planform."""
    d = v.numeric_design()
    d["wings"]["main_wing"].update(span=span, taper=taper, twist=np.radians(twist_deg))
    surfaces, _ = v.wing_surfaces(d)
    excess, labels, a_s = stall_pattern_rows(v._lattice(surfaces, v.S_ref), v.lifting_wings, v.strip_eta,
                                             v.strip_exposed, v.config.stall_pattern_speed_mps)["main_wing"]
    assert all("at stall onset" in lab for lab in labels)
    return float(np.max(np.asarray(ca.DM(excess)))), float(a_s)


def test_low_taper_stalls_the_ailerons_first_and_washout_or_taper_mends_it(ga):
    """A rectangular wing stalls from the root; taper 0.2 without washout from the aileron span
    (its strips past cl_max at the onset); washout and a larger taper each bring them back."""
    flat = [0.0] * 5
    rect, _ = _excess(ga, 15.0, 1.0, flat)
    tip, _ = _excess(ga, 15.0, 0.2, flat)
    washed, _ = _excess(ga, 15.0, 0.2, [3.0, 2.0, 1.0, 0.0, -1.0])
    mid, _ = _excess(ga, 15.0, 0.45, flat)
    assert rect < -0.1 < tip            # root first / ailerons stalled before the onset
    assert tip > 0.0
    assert washed < tip and mid < tip
    assert rect < min(mid, washed)


def test_the_pattern_is_a_design_constraint_of_an_optimization_and_reported_by_an_analysis(ga):
    p = Problem("pattern")
    v = Aircraft(ga2p(), **SMALL)
    Mission(v, _segments()).build(p)
    g = p.groups["stall pattern"]
    lo, hi = ga2p().main_wing.aileron_span_eta
    n = sum(1 for i, s in enumerate(v.vlm.strip_surface) if s == 0 and lo <= v.strip_eta[i] <= hi)
    assert g.kind == "<=" and g.size == n
    # at the P2006T baseline (taper 0.7, 1 deg of washout) the ailerons keep the 0.1 margin
    assert np.all(_initial(p, g.residual) * g.scale <= 1e-9)
    assert "main_wing.stall_onset_alpha_deg" in p.outputs
    frozen = Problem("analysis")
    va = Aircraft(ga2p(), design_point_constraints=False, **SMALL)
    Mission(va, _segments()).build(frozen)
    assert "stall pattern" not in frozen.groups
    assert "main_wing.aileron_cl_margin_at_stall_onset" in frozen.outputs
    off = Problem("off")
    Mission(Aircraft(ga2p(), limits=False, **SMALL), _segments()).build(off)
    assert "stall pattern" not in off.groups


def test_a_wing_without_ailerons_gets_no_rows():
    # the TTW's ailerons are its catalog's; a fin has none
    assert ttw().main_wing.aileron_span_eta == TTW_AILERON_SPAN_ETA == ttw().wings[1].aileron_span_eta
    assert ttw().wings[2].aileron_span_eta == (0.0, 0.0)
    cfg = ga2p()
    bare = replace(cfg, wings=(replace(cfg.main_wing, aileron_span_eta=(0.0, 0.0)),) + tuple(cfg.wings[1:]))
    p = Problem("bare")
    Mission(Aircraft(bare, **SMALL), _segments()).build(p)
    assert "stall pattern" not in p.groups


def test_soft_min_is_below_the_minimum_by_at_most_w_ln_n():
    x = np.array([0.31, 0.25, 0.27, 0.26])
    w = 0.01
    assert x.min() - w * np.log(len(x)) <= soft_min(x, w) <= x.min()
    s = ca.MX.sym("s", 4)
    f = ca.Function("f", [s], [soft_min(s, w)])
    assert float(f(x)) == pytest.approx(soft_min(x, w), abs=1e-12)
    assert np.isfinite(float(f(np.array([5.0, -3.0, 2.0, 40.0]))))      # no overflow on a wide spread


def test_an_aileron_span_out_of_order_is_refused_naming_the_field():
    from mdo.core.errors import InputError
    with pytest.raises(InputError, match=r"main_wing\.aileron_span_eta.*0 <= start <= end <= 1"):
        replace(ga2p().main_wing, aileron_span_eta=(0.9, 0.5))
    with pytest.raises(InputError, match="stall_pattern_speed_mps"):
        replace(ga2p(), stall_pattern_speed_mps=200.0)


def test_a_slower_stall_speed_brings_the_onset_earlier(ga):
    """The stall speed (``VehicleConfig.stall_pattern_speed_mps``) sets the strips' Reynolds
    number: a slower airplane's sections reach a lower cl_max, so its wing's stall begins at a
    lower angle (here 61 kn against 35 kn)."""
    d = ga.numeric_design()
    surfaces, _ = ga.wing_surfaces(d)
    vlm = ga._lattice(surfaces, ga.S_ref)
    fast, slow = (stall_pattern_rows(vlm, ga.lifting_wings, ga.strip_eta, ga.strip_exposed, v)["main_wing"]
                  for v in (ga.config.stall_pattern_speed_mps, 18.0))
    assert float(slow[2]) < float(fast[2])      # the onset comes earlier at the lower Reynolds number
