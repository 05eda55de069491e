"""Generate ``cylinder_table_core010.npz``: the induced velocity of a unit semi-infinite
cylindrical vortex sheet, smeared radially by the wake's vortex core.

Run once (data generation, needs scipy >= 1.8 for Carlson's R_J):

    /work/venv/bin/python mdo/wake/data/generate_cylinder_table.py [--core 0.1]

What is tabulated
-----------------
A cylinder of radius 1 from x = 0 to +inf carrying azimuthal vorticity of unit
strength per unit length (right-handed about +x, so that the flow inside is
accelerated along +x, as in a propeller slipstream).  Its induced velocity at axial
station xi and radius eta has the closed form of Branlard & Gaunaa (2015),
"Cylindrical vortex wake model: right cylinder", Wind Energy 18:1973, Eqs. for
u_r and u_z (complete elliptic integrals K, E, Pi):

    u_r = -(1/2pi) sqrt(1/eta) [ (2 - k^2)/k K(k^2) - (2/k) E(k^2) ]
    u_x = 1/2 [ (1 - eta + |1 - eta|)/(2|1 - eta|)
                + xi k/(2pi sqrt(eta)) (K(k^2) + (1 - eta)/(1 + eta) Pi(k0^2, k^2)) ]
    k^2 = 4 eta/((1 + eta)^2 + xi^2),  k0^2 = 4 eta/(1 + eta)^2

checked below against the numerical integral of vortex-ring fields (to 1e-9).

The wake's filaments carry a Scully core of radius delta (mdo.wake.biot_savart);
averaged over the blade passage, a row of such filaments is a sheet whose axial
velocity jumps as 1/2 (1 + h/sqrt(h^2 + delta^2)) across it, i.e. a sheet smeared over
the radius with density f(s) = delta^2 / (2 ((s - 1)^2 + delta^2)^(3/2)).  The table
holds that smeared field,

    K_delta(xi, eta) = int f(s) K(xi/s, eta/s) ds   (velocity is scale-free: a cylinder
                                                      of radius s at (xi, eta) equals the
                                                      unit one at (xi/s, eta/s)),

computed with Gauss-Legendre quadrature in s = 1 + delta tan(theta), split at s = eta
where the unsmeared field jumps.  Tabulated are ``u_x`` and ``g = u_r/eta`` (both even
in eta; g is finite on the axis).  Stored: the data grids ``xi``, ``eta`` (eta >= 0),
``core_rel``, and the interpolating cubic spline of each field over (xi, +-eta):
``knots_xi``, ``knots_eta``, ``coef_ux``, ``coef_g`` (float32).
"""
from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from scipy import integrate, special


def ellippi(n, m):
    """Complete elliptic integral of the third kind Pi(n | m) via Carlson's forms."""
    return special.elliprf(0.0, 1.0 - m, 1.0) + n / 3.0 * special.elliprj(0.0, 1.0 - m, 1.0, 1.0 - n)


def cylinder(xi, eta):
    """(u_x, g = u_r/eta) of the unit semi-infinite cylinder (no core). eta > 0."""
    xi, eta = np.broadcast_arrays(np.asarray(xi, float), np.asarray(eta, float))
    k2 = 4 * eta / ((1 + eta) ** 2 + xi**2)
    k = np.sqrt(k2)
    k02 = 4 * eta / (1 + eta) ** 2
    kk, ee = special.ellipk(k2), special.ellipe(k2)
    ur = -1 / (2 * np.pi) * np.sqrt(1 / eta) * ((2 - k2) / k * kk - 2 / k * ee)
    d = 1 - eta
    step = np.where(d > 0, 1.0, 0.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        pi3 = np.where(np.abs(d) > 0, d / (1 + eta) * ellippi(k02, k2), 0.0)
    ux = 0.5 * (step + xi * k / (2 * np.pi * np.sqrt(eta)) * (kk + pi3))
    return ux, ur / eta


def cylinder_axis(xi):
    """Limits on the axis: u_x = (1 + xi/sqrt(1 + xi^2))/2, g = -(1/2) d u_x/d xi."""
    return 0.5 * (1 + xi / np.sqrt(1 + xi**2)), -0.25 / (1 + xi**2) ** 1.5


def ring(xi, eta, a=1.0):
    """(u_x, u_r) of a unit-circulation vortex ring of radius a (elliptic closed form)."""
    d2 = (a + eta) ** 2 + xi**2
    m = 4 * a * eta / d2
    kk, ee = special.ellipk(m), special.ellipe(m)
    q = (a - eta) ** 2 + xi**2
    ux = 1 / (2 * np.pi * np.sqrt(d2)) * (kk + (a * a - eta * eta - xi * xi) / q * ee)
    ur = xi / (2 * np.pi * eta * np.sqrt(d2)) * (-kk + (a * a + eta * eta + xi * xi) / q * ee)
    return ux, ur


def check_closed_form():
    worst = 0.0
    for xi, eta in [(0.5, 0.3), (2, 0.5), (-1, 0.7), (0.3, 1.5), (-0.5, 2.0), (3, 0.2), (0.1, 0.95)]:
        qx = integrate.quad(lambda s: ring(xi - s, eta)[0], 0, np.inf, limit=500)[0]
        qr = integrate.quad(lambda s: ring(xi - s, eta)[1], 0, np.inf, limit=500)[0]
        ux, g = cylinder(xi, eta)
        worst = max(worst, abs(ux - qx), abs(g * eta - qr))
    assert worst < 1e-8, worst
    return worst


def smeared(xi, eta, core, n=160):
    """K_delta at arrays xi, eta (same shape) by split Gauss-Legendre in theta."""
    th0 = np.arctan(-1.0 / core)          # s = 0
    th1 = np.pi / 2 * (1 - 1e-9)           # s -> inf (weight -> 0)
    mass = 0.5 * (np.sin(th1) - np.sin(th0))
    x_gl, w_gl = np.polynomial.legendre.leggauss(n)
    thj = np.clip(np.arctan((eta - 1.0) / core), th0, th1)  # where s = eta
    ux = np.zeros_like(xi)
    g = np.zeros_like(xi)
    for lo, hi in ((np.full_like(xi, th0), thj), (thj, np.full_like(xi, th1))):
        half = 0.5 * (hi - lo)
        mid = 0.5 * (hi + lo)
        for xg, wg in zip(x_gl, w_gl):
            th = mid + half * xg
            s = 1 + core * np.tan(th)
            w = wg * half * 0.5 * np.cos(th)
            if np.all(eta == 0):
                a, b = cylinder_axis(xi / s)
            else:
                a, b = cylinder(xi / s, eta / s)
            ux += w * a
            g += w * b / s  # u_r/eta = (g(xi/s, eta/s) * eta/s)/eta
    return ux / mass, g / mass


def grids(core):
    fine = core / 5
    eta = np.concatenate([
        np.arange(0.0, 0.6, 0.05),
        np.arange(0.6, 1.4, fine),
        np.arange(1.4, 3.0, 0.05),
        3.0 * 1.15 ** np.arange(0, 100),
    ])
    eta = eta[eta <= 400.0]
    pos = np.concatenate([
        np.arange(0.0, 0.3, fine / 2),   # the disk edge, where u_r peaks
        np.arange(0.3, 0.5, fine),
        np.arange(0.5, 4.0, 0.05),
        4.0 * 1.15 ** np.arange(0, 100),
    ])
    pos = pos[pos <= 400.0]
    xi = np.concatenate([-pos[:0:-1], pos])
    return np.unique(np.round(xi, 10)), np.unique(np.round(eta, 10))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--core", type=float, default=0.1, help="core radius / sheet radius")
    ap.add_argument("--out", default=None)
    args = ap.parse_args(argv)
    print("closed form vs ring quadrature, worst |diff| =", check_closed_form())
    xi, eta = grids(args.core)
    X, E = np.meshgrid(xi, eta, indexing="ij")
    ux = np.zeros_like(X)
    g = np.zeros_like(X)
    ax = eta == 0
    ux[:, ax], g[:, ax] = smeared(X[:, ax], E[:, ax], args.core)
    ux[:, ~ax], g[:, ~ax] = smeared(X[:, ~ax], E[:, ~ax], args.core)
    out = Path(args.out or Path(__file__).with_name(f"cylinder_table_core{round(args.core * 100):03d}.npz"))
    # Interpolating tensor-product cubic spline (not-a-knot ends, as FITPACK's s = 0),
    # over eta mirrored to negative values so that both fields are even in eta and the
    # spline's eta-derivative vanishes on the axis.  The knots and coefficients are
    # stored so that the run time builds casadi.Function.bspline without a solve.
    from scipy.interpolate import RectBivariateSpline
    eta_m = np.concatenate([-eta[:0:-1], eta])
    coef = []
    for field in (ux, g):
        fm = np.concatenate([field[:, :0:-1], field], axis=1)
        spl = RectBivariateSpline(xi, eta_m, fm, kx=3, ky=3, s=0)
        tx, ty, c = spl.tck
        coef.append(c.reshape(len(tx) - 4, len(ty) - 4))
    # float32 coefficients: 1e-7 relative, far below the table's interpolation error
    np.savez_compressed(out, xi=xi, eta=eta, core_rel=args.core,
                        knots_xi=tx, knots_eta=ty, coef_ux=coef[0].astype(np.float32),
                        coef_g=coef[1].astype(np.float32),
                        note="unit semi-infinite vortex cylinder, radially smeared by a Scully core; "
                             "see generate_cylinder_table.py")
    print(f"wrote {out}: {xi.size} x {eta.size} points; ux in [{ux.min():.3f}, {ux.max():.3f}], "
          f"g in [{g.min():.3f}, {g.max():.3f}]")


if __name__ == "__main__":
    main()
