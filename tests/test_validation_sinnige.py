"""Wing drag, wingtip-mounted vs conventional propeller, against Sinnige et al. (J. Aircraft 56(1),
2019, DOI 10.2514/1.C034978): about 15 % less drag at CL = 0.5, Tc = 0.12 with the tip-mounted,
inboard-up propeller (problems/validation/sinnige_tip.py; its docstring lists the assumptions)."""
import importlib.util
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def sinnige():
    spec = importlib.util.spec_from_file_location("sinnige_tip", ROOT / "problems" / "validation" / "sinnige_tip.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules["sinnige_tip"] = mod
    spec.loader.exec_module(mod)
    res = mod.compare(40, 4, (mod.CL_TARGET,))
    return mod, res


def test_trimmed_to_the_published_point(sinnige):
    mod, res = sinnige
    for name, r in res.items():
        assert abs(r["CL"][0] - mod.CL_TARGET) < 1e-6, name
        if name != "props_off":
            assert abs(r["prop"]["Tc"][0] - mod.TC_TARGET) < 1e-4, name


@pytest.mark.xfail(strict=True, reason="model misses: tip-vs-conventional drag reduction 4.9 % at CL 0.5, Tc 0.12 "
                                       "(measured ~15 %, tolerance +/- 7 points; results/validation/sinnige_tip.md)")
def test_tip_vs_conventional_drag_reduction(sinnige):
    mod, res = sinnige
    red = mod.reduction(res)
    assert abs(red - mod.MEASURED_REDUCTION) <= mod.TOLERANCE, red


def test_tip_beats_conventional_and_inboard_up_beats_outboard_up(sinnige):
    """The signs the paper reports: tip inboard-up has the least wing drag of the three layouts;
    at the tip inboard-up beats outboard-up (swirl recovery vs swirl loss)."""
    _, res = sinnige
    tip, conv, out = (res[n]["CD"][0] for n in ("tip_inboard_up", "conventional_inboard_up", "tip_outboard_up"))
    assert tip < conv and tip < out
    assert res["tip_inboard_up"]["e"][0] > res["conventional_inboard_up"]["e"][0]   # the paper's mechanism


def test_the_near_field_swirl_credit_is_the_trefftz_plane_interaction(sinnige):
    """Issue 16 item 3: the lattice's near-field force in the swirl against the Trefftz-plane
    interaction term computed from the BEMT circulation on an independent path (analytic far-wake
    swirl, 25 points per strip): the same within 5 % in every layout (near minus Trefftz, measured: +1.4 % tip
    inboard-up, -3.5 % conventional, -1.0 % tip outboard-up); and the net benefit against props off
    stays below the swirl power the slipstreams carry."""
    mod, res = sinnige
    for name, near, tref, _, net_W, avail_W in mod.trefftz_table(res):
        assert near == pytest.approx(tref, rel=0.05), name
        assert net_W < avail_W, name
