"""Exact derivatives of the symbolic lattice against central finite differences."""
import math

import casadi as ca
import numpy as np
import pytest

from mdo.wing import VLM, constant_area, profile_drag

D = math.radians


def _ga_symbolic(prop_breaks=False, K=2):
    b = ca.MX.sym("span")
    lam = ca.MX.sym("taper")
    tw = ca.MX.sym("twist", 5)
    yp = ca.MX.sym("y_prop")
    kw = {}
    if prop_breaks:   # slipstream edges of a 0.97 m propeller as moving strip boundaries
        R = 0.97
        kw = dict(breaks=[(yp - R) / (b / 2), (yp + R) / (b / 2)],
                  break_nominal=[(2.6 - R) / 5.7, (2.6 + R) / 5.7], anchor_sections=False,
                  nspan=[3, 4, 5])
    else:
        kw = dict(nspan=8)
    w = constant_area("main", 14.76, b, lam, [tw[i] for i in range(5)], nchord=2, airfoil="naca63412", **kw)
    v = VLM([w], S_ref=14.76)
    al = ca.MX.sym("alpha", 1, K)
    V = ca.MX.sym("V", 1, K)
    r = v.solve(al, V, rho=1.0, mach=0.2)
    x = ca.vertcat(b, lam, tw, yp, al.T, V.T)
    x0 = np.concatenate([[11.4, 0.7], np.radians([3, 2.75, 2.5, 2.25, 2.0]), [2.6],
                         np.radians(np.linspace(1, 4, K)), np.linspace(50, 70, K)])
    return v, r, x, x0


def _fd_check(f_out, x, x0, rel=1e-6):
    f = ca.Function("f", [x], [f_out])
    J = np.array(ca.Function("J", [x], [ca.jacobian(f_out, x)])(x0))
    Jf = np.zeros_like(J)
    for i in range(len(x0)):
        h = 1e-6 * max(1.0, abs(x0[i]))
        xp, xm = x0.copy(), x0.copy()
        xp[i] += h
        xm[i] -= h
        Jf[:, i] = (np.array(f(xp)) - np.array(f(xm))).ravel() / (2 * h)
    scale = np.abs(J).max(axis=1, keepdims=True)
    assert np.all(np.abs(J - Jf) <= rel * scale + 1e-12), np.abs(J - Jf).max()
    return J


def test_cl_cdi_gradients_wrt_span_taper_twist():
    v, r, x, x0 = _ga_symbolic()
    out = ca.vertcat(r["CL"].T, r["CDi"].T, r["Cm"].T)
    J = _fd_check(out, x, x0)
    # physics of the signs: more twist -> more lift; longer span at fixed area -> less CDi
    assert np.all(J[0, 2:7] > 0)
    assert J[2, 0] < 0


def test_gradients_with_moving_slipstream_edges():
    v, r, x, x0 = _ga_symbolic(prop_breaks=True, K=1)
    out = ca.vertcat(r["CL"], r["CDi"], r["cl"][:, 0])
    J = _fd_check(out, x, x0)
    assert np.all(np.isfinite(J))


def test_profile_drag_gradients_and_hessian_finite():
    v, r, x, x0 = _ga_symbolic(K=1)
    pd = profile_drag(v, r, 1.0, 1.8e-5)
    out = ca.vertcat(pd["CD_p"], r["CDi"])
    _fd_check(out, x, x0, rel=1e-5)
    H = ca.Function("H", [x], [ca.hessian(pd["CD_p"] + r["CDi"], x)[0]])(x0)
    H = np.array(H)
    assert np.all(np.isfinite(H)) and np.allclose(H, H.T, atol=1e-9 * np.abs(H).max())
