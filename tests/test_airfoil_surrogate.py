"""Airfoil surrogate: interface, accuracy against the XFOIL polars, post-stall,
compressibility, Reynolds extrapolation (issue 3)."""
import casadi as ca
import numpy as np
import pytest

from mdo.airfoil import Airfoil, available
from mdo.airfoil.fit import natural_spline_weights
from mdo.airfoil.model import splines_of
from mdo.airfoil.validation import CD_TOL, CL_TOL, jump_mask, polar_errors
from mdo.core import InputError

NAMES = ["clarky", "e63", "naca0015", "naca4412", "naca63412"]

# Achieved accuracy (fraction of polar points inside |dcl| <= 0.03 and |dcd|/cd <= 5 %),
# stated per airfoil with a small margin below the measured value.  The points that
# miss sit at XFOIL's discontinuities (laminar-bubble bursts and negative stall,
# where cl jumps by up to 0.6 and cd by 2-7x between two 0.25 deg points); see
# mdo/airfoil/README.md for the numbers.  Clark-Y at Re 5e4 and NACA 63-412 at 5e4-1e6 are
# Ncrit 9 since 2026-12-05 (SUAVE's files there were Ncrit 5): bumpier laminar-bubble polars,
# measured 0.950 (63-412 cl), 0.959 (63-412 cd) and 0.939 (Clark-Y cd).
MIN_FRACTION_CL = {"clarky": 0.96, "e63": 0.95, "naca0015": 0.97, "naca4412": 0.97, "naca63412": 0.94}
MIN_FRACTION_CD = {"clarky": 0.93, "e63": 0.93, "naca0015": 0.98, "naca4412": 0.95, "naca63412": 0.95}


@pytest.fixture(scope="module", params=NAMES)
def airfoil(request):
    return Airfoil.from_name(request.param)


def test_available_and_names():
    assert set(NAMES) <= set(available())
    a = Airfoil.from_name("NACA 4412")
    assert Airfoil.from_name("naca_4412") is a
    assert Airfoil.from_name("NACA 63-412").title == "NACA 63-412"
    assert Airfoil.from_name("Clark-Y").key == "clarky"
    with pytest.raises(InputError, match="airfoil"):
        Airfoil.from_name("NACA 9999")


def test_geometry_numbers():
    assert Airfoil.from_name("naca4412").thickness_to_chord == pytest.approx(0.12, abs=0.003)
    assert Airfoil.from_name("naca0015").thickness_to_chord == pytest.approx(0.15, abs=0.003)
    assert Airfoil.from_name("e63").thickness_to_chord == pytest.approx(0.0425, abs=0.002)
    assert Airfoil.from_name("naca0015").max_camber == pytest.approx(0.0, abs=1e-3)
    assert Airfoil.from_name("naca4412").max_camber == pytest.approx(0.04, abs=0.002)


def test_zero_lift_angle_and_slope():
    # thin-airfoil theory: alpha_0 = -4.15 deg for NACA 4412 (Abbott & von Doenhoff
    # measured -4.0 deg at Re 6e6); symmetric section: 0
    a0 = np.degrees(Airfoil.from_name("naca4412").alpha0_rad)
    assert -4.8 < a0 < -3.5
    assert abs(np.degrees(Airfoil.from_name("naca0015").alpha0_rad)) < 0.1
    for name in NAMES:
        slope = Airfoil.from_name(name).lift_slope_per_rad
        if name == "e63":
            # XFOIL's thin E63 comes out of lower-surface nose separation just above
            # alpha_0 with a steep rise (cl -0.01 -> 0.99 from -4.5 to 1.5 deg at 1e6)
            assert 8.0 < slope < 11.0, slope
        else:
            assert 5.5 < slope < 7.3, (name, slope)


def test_accuracy_at_polar_points(airfoil):
    errs = polar_errors(airfoil)
    n = sum(e.n_points for e in errs)
    ok_cl = 1.0 - sum(e.n_cl_over for e in errs) / n
    ok_cd = 1.0 - sum(e.n_cd_over for e in errs) / n
    assert ok_cl >= MIN_FRACTION_CL[airfoil.key], (ok_cl, CL_TOL)
    assert ok_cd >= MIN_FRACTION_CD[airfoil.key], (ok_cd, CD_TOL)
    # and the bulk is well inside the tolerance
    dcl, rcd = [], []
    for p in airfoil.polars:
        cl, cd, _ = airfoil.coefficients(np.radians(p.alpha_deg), p.reynolds)
        dcl.append(np.abs(cl - p.cl))
        rcd.append(np.abs(cd / p.cd - 1))
    assert np.median(np.concatenate(dcl)) < 0.01
    assert np.median(np.concatenate(rcd)) < 0.02


def test_accuracy_away_from_xfoil_jumps(airfoil):
    """Every polar point more than 1 deg away from an XFOIL discontinuity meets
    |dcl| <= 0.03 and |dcd|/cd <= 5 % (a few named exceptions at most)."""
    misses = 0
    total = 0
    for p in airfoil.polars:
        cl, cd, _ = airfoil.coefficients(np.radians(p.alpha_deg), p.reynolds)
        near = jump_mask(p)
        bad = (np.abs(cl - p.cl) > CL_TOL) | (np.abs(cd / p.cd - 1) > CD_TOL)
        misses += int(np.sum(bad & ~near))
        total += int(np.sum(~near))
    assert misses <= 0.02 * total, (misses, total)


def test_post_stall_values(airfoil):
    for re_ in (5e4, 3e5, 1e6, 5e6):
        for m in (0.0, 0.3):
            cl45 = airfoil.cl(np.radians(45.0), re_, m)
            cd90 = airfoil.cd(np.radians(90.0), re_, m)
            assert 0.9 <= cl45 <= 1.25, (re_, m, cl45)
            assert 1.7 <= cd90 <= 2.1, (re_, m, cd90)
            assert -1.25 <= airfoil.cl(np.radians(-45.0), re_, m) <= -0.9
            assert 1.7 <= airfoil.cd(np.radians(-90.0), re_, m) <= 2.1
    # reverse flow: small lift and drag near 180 deg; value wraps continuously
    cl_p, cd_p, _ = airfoil.coefficients(np.pi, 1e6)
    cl_m, cd_m, _ = airfoil.coefficients(-np.pi, 1e6)
    assert abs(cl_p) < 0.01 and 0.01 < cd_p < 0.1
    assert cl_p == pytest.approx(cl_m, abs=1e-9) and cd_p == pytest.approx(cd_m, abs=1e-9)


def test_attached_lift_slope_compressibility():
    af = Airfoil.from_name("naca4412")
    a = np.radians([-1.0, 3.0])
    for m in (0.3, 0.5, 0.6):
        slope0 = np.diff(af.cl(a, 1e6, 0.0))[0]
        slope = np.diff(af.cl(a, 1e6, m))[0]
        assert slope / slope0 == pytest.approx(1.0 / np.sqrt(1.0 - m * m), rel=0.01)
    # smoothly capped: finite and bounded at and beyond the cap
    ratio = [af.cl(np.radians(2.0), 1e6, m) / af.cl(np.radians(2.0), 1e6, 0.0) for m in (0.7, 0.8, 0.95)]
    assert all(1.3 < r < 1.45 for r in ratio), ratio
    assert ratio[0] <= ratio[1] <= ratio[2]


def test_drag_compressibility():
    af = Airfoil.from_name("naca4412")
    a = np.radians(2.0)
    cd0 = af.cd(a, 1e6, 0.0)
    # skin-friction ratio (1 + 0.144 M^2)^-0.65 at M 0.3 (no wave drag yet)
    assert af.cd(a, 1e6, 0.3) / cd0 == pytest.approx((1 + 0.144 * 0.09) ** -0.65, rel=2e-3)
    # drag rise past the Korn critical Mach number (M_dd ~ 0.87 - 0.12 - cl/10)
    assert af.cd(a, 1e6, 0.75) > 1.5 * af.cd(a, 1e6, 0.6)
    assert np.isfinite(af.cd(a, 1e6, 0.9))


def test_reynolds_extrapolation():
    for name in NAMES:
        af = Airfoil.from_name(name)
        lo, hi = af.reynolds_range
        a = np.radians(np.linspace(-4.0, 8.0, 13))
        # drag keeps falling with Re beyond the data (power laws), lift stays bounded
        assert np.all(af.cd(a, lo / 3, 0) > af.cd(a, lo, 0))
        assert np.all(af.cd(a, hi * 5, 0) < af.cd(a, hi, 0))
        # cl follows the lowest levels' trend 0.15 further in ln Re, then freezes
        # (XFOIL's cl changes fast between Re 2e4 and 5e4); above the data it freezes
        assert np.all(np.abs(af.cl(a, lo / 3, 0) - af.cl(a, lo, 0)) < 0.2)
        assert np.all(np.abs(af.cl(a, lo / 10, 0) - af.cl(a, lo / 3, 0)) < 1e-3)
        assert np.all(np.abs(af.cl(a, hi * 5, 0) - af.cl(a, hi, 0)) < 0.05)
    af = Airfoil.from_name("naca4412")
    r = af.cd(np.radians(2.0), 4e5, 0) / af.cd(np.radians(2.0), 4e5 * 1.1, 0)
    assert 1.0 < r < 1.1  # smooth between levels


def test_numpy_sx_mx_agree():
    af = Airfoil.from_name("naca63412")
    rng = np.random.default_rng(3)
    a = np.radians(rng.uniform(-180, 180, 50))
    re_ = 10 ** rng.uniform(4.3, 7.0, 50)
    m = rng.uniform(0, 0.8, 50)
    ref = np.array(af.coefficients(a, re_, m))
    # SX vectors, inlined
    x = ca.SX.sym("x", 50)
    f_sx = ca.Function("f", [x], [ca.horzcat(*af.coefficients(x, re_, m))])
    assert np.allclose(np.array(f_sx(a)).T, ref, atol=1e-12, rtol=1e-12)
    # MX column, through the mapped SX function
    y = ca.MX.sym("y", 50)
    f_mx = ca.Function("g", [y], [ca.horzcat(*af.coefficients(y, re_, m))])
    assert np.allclose(np.array(f_mx(a)).T, ref, atol=1e-12, rtol=1e-12)
    # scalar SX function mapped over stations
    fm = af.casadi_function().map(50)
    assert np.allclose(np.vstack([np.array(o) for o in fm(a[None], re_[None], m[None])]), ref,
                       atol=1e-12, rtol=1e-12)
    # floats give floats, arrays broadcast
    cl, cd, cm = af.coefficients(0.05, 1e6)
    assert all(isinstance(v, float) for v in (cl, cd, cm))
    assert af.cl(np.zeros((2, 3)), 1e6).shape == (2, 3)
    # DM in, DM out
    assert isinstance(af.cl(ca.DM([0.1, 0.2]), 1e6), ca.DM)


def test_bad_numeric_input():
    af = Airfoil.from_name("naca4412")
    with pytest.raises(InputError, match="reynolds"):
        af.cl(0.1, -1e5)
    with pytest.raises(InputError, match="mach"):
        af.cl(0.1, 1e5, 1.2)
    with pytest.raises(InputError, match="alpha"):
        af.cl(np.nan, 1e5)


def test_spline_representations_agree():
    """The shipped tensor B-spline equals the per-level P-splines combined with the
    natural-spline weights in ln Re (the construction documented in fit.py)."""
    from scipy.interpolate import BSpline

    af = Airfoil.from_name("naca4412")
    tab = af.tables
    spl = splines_of(tab)
    rng = np.random.default_rng(0)
    a = rng.uniform(tab.alpha_clip[0], tab.alpha_clip[1], 200)
    r = rng.uniform(tab.log_re[0] - 0.5, tab.log_re[-1] + 0.5, 200)
    cl, lncd, cm = spl.surface(np, a, r, 200)
    wa, wb, we = natural_spline_weights(tab.log_re)
    w = wa + r[:, None] * wb + (np.fmax(r[:, None] - tab.log_re, 0.0) ** 3) @ we
    for q, got in (("cl", cl), ("logcd", lncd), ("cm", cm)):
        t, c = tab.bspline[q]
        per_level = np.stack([BSpline(t, c[:, j], 3)(a) for j in range(c.shape[1])], axis=-1)
        assert np.allclose((per_level * w).sum(-1), got, atol=1e-9)
    # and the CasADi call node evaluates the same spline
    fm = spl.ca_surface.map(200)
    assert np.allclose(np.array(fm(np.vstack([a, r]))), np.vstack([cl, lncd, cm]), atol=1e-12)
