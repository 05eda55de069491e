"""Analysis mode: numbers in, numbers out, always converging.

The BEMT residual of ``bemt.py`` is solved element by element (blade station x
azimuth station x operating point) by a bracketed root finder written in CasADi
SX, so that a whole J sweep is one mapped call:

1. bracket: the residual is evaluated on ``n_grid`` points from ``phi = 1e-6``
   to ``PHI_MAX_RAD = 3 pi/4`` (the NLP's domain, so analysis and optimization find
   the same root) and the first sign change nearest ``phi = 0`` is taken (Ning 2014,
   section 3; the momentum/propeller region, extended past pi/2 for the hub of a
   steeply pitched blade in fast axial flow, bemt.py docstring).  For ``Vx >= 0`` and
   a blade that lifts at small ``phi`` a sign change in (0, pi/2] is guaranteed;
2. ``n_bisect`` bisection steps shrink the bracket;
3. ``n_newton`` Newton steps, each kept inside the current bracket (a step that
   leaves it is replaced by bisection), polish the root to round-off.

Elements without a sign change in (0, 3 pi/4] (negative pitch at a station,
reversed flow) are retried in Python on the other quadrants in Ning's order:
(-pi/2, 0) searched from 0 downward, (3 pi/4, pi), (-pi, -pi/2).  An element with
no sign change anywhere (e.g. omega = 0 in still air) keeps the ``phi`` of the
smallest |residual| on a fine grid and is reported as not converged: the
analysis never raises for a hard operating point, it reports.

The converged ``phi`` then goes through the same ``bemt_function`` the NLP
uses ("full" outputs), so analysis and optimization share one definition.

Given the rotor's ``hub_fraction`` (a number), a radial distribution of sections is
placed at the stations when the kernels are built, as in ``bemt_function``: the
stations that share one blend share one kernel, which evaluates only the sections
carrying weight there (``geometry.placed_stations``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import casadi as ca
import numpy as np

from ..core.atmosphere import check_altitude, density, dynamic_viscosity, speed_of_sound
from ..core.errors import InputError
from ..core.parallel import default_threads
from .bemt import FULL_OUTPUTS, INPUT_NAMES, PHI_MAX_RAD, _elements, _symbols, bemt_function, station_physics
from .geometry import RotorGeometry, placed_stations
from .sections import section as make_section

__all__ = ["solve_kernel", "point_solver", "solve_phi", "analyze", "analyze_inputs", "RotorResult", "sweep_J",
           "analysis_function", "operating_inputs"]

_EPS_PHI = 1e-6
_CACHE: dict = {}


def _cache_key(sec, *args):
    return (id(sec),) + args


_ELEMENT_PARAMS = ("r", "chord", "theta", "vx", "vy", "rho", "mu", "a", "blades", "r_tip", "r_hub")


def _element_residual(sec, tip_loss, hub_loss, x_station=None):
    """One element's residual and its phi-derivative; ``x_station``: the numeric r/R at
    which a radial distribution of sections is placed (None: at ``r / r_tip``)."""
    key = _cache_key(sec, "eres", tip_loss, hub_loss, x_station)
    if key not in _CACHE:
        phi = ca.SX.sym("phi")
        p = [ca.SX.sym(k) for k in _ELEMENT_PARAMS]
        res = station_physics(phi, *p, sec, tip_loss=tip_loss, hub_loss=hub_loss,
                              x_sections=x_station)["residual"]
        f = ca.Function("bemt_element_residual", [phi] + p, [res, ca.jacobian(res, phi)],
                        ["phi"] + list(_ELEMENT_PARAMS), ["residual", "dres_dphi"])
        _CACHE[key] = (f, sec)  # keep sec alive so id() stays unique
    return _CACHE[key][0]


def _station_groups(sec, n: int, m: int, hub_fraction) -> list:
    """``[(x_station, element indices)]``: the elements (station fastest, n*m) grouped by
    the blend placed at their station (one group with ``x_station = None`` when nothing is
    placed).  Stations with equal section weights share one kernel.  A section with stall
    delay reads r/R itself (its augmentation factor), so it is not grouped: it reads r/R from
    each element, as without a hub; so does a distribution without per-station weights
    (``SpanwiseBlend``)."""
    x = placed_stations(sec, n, hub_fraction)
    if x is None or getattr(sec, "rotational", False) or not hasattr(sec, "station_weights"):
        return [(None, list(range(n * m)))]
    w = sec.station_weights(x)
    groups: dict = {}
    for i in range(n):
        groups.setdefault(tuple(np.round(w[:, i], 14)), []).append(i)
    return [(float(x[st[0]]), [j * n + i for j in range(m) for i in st]) for st in groups.values()]


def solve_kernel(sec, *, n_grid: int = 24, n_bisect: int = 10, n_newton: int = 5,
                 tip_loss: bool = True, hub_loss: bool = True, x_station=None) -> ca.Function:
    """SX Function solving one element's residual on the interval (phi_a -> phi_b).

    Inputs: the element parameters (``r, chord, theta, vx, vy, rho, mu, a, blades,
    r_tip, r_hub``) and the search interval ``phi_a``, ``phi_b`` (grid order: the
    sign change nearest ``phi_a`` is taken).  Outputs ``phi``, ``residual``,
    ``found`` (1 if a bracket was found).  ``x_station``: as ``_element_residual``.
    """
    key = _cache_key(sec, "kernel", n_grid, n_bisect, n_newton, tip_loss, hub_loss, x_station)
    if key in _CACHE:
        return _CACHE[key][0]
    fres = _element_residual(sec, tip_loss, hub_loss, x_station)
    p = [ca.SX.sym(k) for k in _ELEMENT_PARAMS]
    phi_a, phi_b = ca.SX.sym("phi_a"), ca.SX.sym("phi_b")

    def R(ph):
        return fres(ph, *p)[0]

    grid = [phi_a + (phi_b - phi_a) * (k / (n_grid - 1)) for k in range(n_grid)]
    vals = [R(g) for g in grid]
    found = ca.SX(0)
    lo, hi, flo = grid[0], grid[1], vals[0]
    for k in reversed(range(n_grid - 1)):  # the last overwrite is the change nearest phi_a
        sc = vals[k] * vals[k + 1] <= 0
        lo = ca.if_else(sc, grid[k], lo)
        hi = ca.if_else(sc, grid[k + 1], hi)
        flo = ca.if_else(sc, vals[k], flo)
        found = ca.fmax(found, sc)
    for _ in range(n_bisect):
        mid = 0.5 * (lo + hi)
        fm = R(mid)
        same = fm * flo > 0
        lo = ca.if_else(same, mid, lo)
        flo = ca.if_else(same, fm, flo)
        hi = ca.if_else(same, hi, mid)
    x = 0.5 * (lo + hi)
    for _ in range(n_newton):
        fx, dfx = fres(x, *p)
        same = fx * flo > 0
        lo_new = ca.if_else(same, x, lo)
        flo = ca.if_else(same, fx, flo)
        hi = ca.if_else(same, hi, x)
        lo = lo_new
        xn = x - fx / dfx
        inside = (xn - lo) * (xn - hi) <= 0
        x = ca.if_else(inside, xn, 0.5 * (lo + hi))
    fx = R(x)
    f = ca.Function("bemt_solve_element", p + [phi_a, phi_b], [x, fx, found],
                    list(_ELEMENT_PARAMS) + ["phi_a", "phi_b"], ["phi", "residual", "found"])
    _CACHE[key] = (f, sec)
    return f


def point_solver(sec, n_stations: int = 20, n_azimuth: int = 1, *, tip_loss=True, hub_loss=True,
                 hub_fraction=None, **kernel_opts) -> ca.Function:
    """Function: one operating point's inputs (``INPUT_NAMES`` without phi) ->
    ``phi_rad`` [n*m], ``residual`` [n*m], ``found`` [n*m], searching (0, PHI_MAX_RAD].
    An MX wrapper around the SX element kernels, each mapped over its elements;
    ``hub_fraction``: as ``bemt_function`` (the input must then be that number)."""
    key = _cache_key(sec, "point", n_stations, n_azimuth, tip_loss, hub_loss, hub_fraction,
                     tuple(sorted(kernel_opts.items())))
    if key in _CACHE:
        return _CACHE[key][0]
    n, m = n_stations, n_azimuth
    x = _symbols(n, m, ca.MX)   # MX: each element kernel stays one mapped call node (fast build)
    r, dr, e = _elements(x, n, m)
    N = n * m
    ones = ca.DM.ones(N, 1)
    args = [e["r"], e["chord"], e["theta"], x["v_axial_mps"] * ones, e["vy"], x["rho_kgpm3"] * ones,
            x["mu_Pas"] * ones, x["a_mps"] * ones, x["blades"] * ones, x["radius_m"] * ones,
            x["radius_m"] * x["hub_fraction"] * ones, _EPS_PHI * ones, PHI_MAX_RAD * ones]
    parts, order = [], []
    for x_st, idx in _station_groups(sec, n, m, hub_fraction):
        kern = solve_kernel(sec, tip_loss=tip_loss, hub_loss=hub_loss, x_station=x_st, **kernel_opts)
        parts.append(kern.map(len(idx))(*[ca.transpose(a[idx]) for a in args]))
        order += idx
    back = [int(k) for k in np.argsort(order)]          # group order -> element order
    out = [ca.transpose(ca.horzcat(*[pt[j] for pt in parts]))[back] for j in range(3)]
    names_in = [k for k in INPUT_NAMES if k != "phi_rad"]
    f = ca.Function("bemt_point_solver", [x[k] for k in names_in], out, names_in,
                    ["phi_rad", "residual", "found"])
    _CACHE[key] = (f, sec)
    return f


def _element_arrays(inputs: dict, n: int, m: int) -> dict:
    """Numeric per-element parameters, shape (n*m, K), for the fallback search."""
    from .bemt import azimuth_angles
    from .geometry import station_layout

    s, ds = station_layout(n)
    K = inputs["omega_radps"].shape[1]
    R = inputs["radius_m"]
    h = inputs["hub_fraction"]
    r = R * (h + (1 - h) * s[:, None])                      # (n, K)
    r_e = np.tile(r, (m, 1))
    chord = np.tile(inputs["chord_m"], (m, 1))
    theta = np.tile(inputs["twist_rad"], (m, 1)) + inputs["pitch_rad"]
    psi = np.repeat(azimuth_angles(m), n)[:, None]
    vy = inputs["omega_radps"] * r_e
    if m > 1:
        vy = vy + inputs["v_inplane_mps"] * np.sin(psi)
    full = (lambda v: np.broadcast_to(v, (n * m, K)))
    return {"r": full(r_e), "chord": full(chord), "theta": full(theta), "vx": full(inputs["v_axial_mps"]),
            "vy": full(vy), "rho": full(inputs["rho_kgpm3"]), "mu": full(inputs["mu_Pas"]),
            "a": full(inputs["a_mps"]), "blades": full(inputs["blades"]), "r_tip": full(R),
            "r_hub": full(R * h)}


def _broadcast_inputs(inputs: dict, n: int) -> tuple[dict, int]:
    """Inputs as float arrays: scalars -> (1, K); chord/twist -> (n, K)."""
    arr = {}
    K = 1
    for k, v in inputs.items():
        a = np.asarray(v, dtype=float)
        if k in ("chord_m", "twist_rad"):
            a = a.reshape(n, -1)
        else:
            a = a.reshape(1, -1)
        K = max(K, a.shape[1])
        arr[k] = a
    for k, a in arr.items():
        if a.shape[1] not in (1, K):
            raise InputError(k, f"has {a.shape[1]} operating points, others have {K}")
        arr[k] = np.broadcast_to(a, (a.shape[0], K)).copy()
    return arr, K


def solve_phi(sec, inputs: dict, n_stations: int = 20, n_azimuth: int = 1, *, tip_loss=True,
              hub_loss=True, hub_fraction=None) -> dict:
    """Solve the BEMT residual for K operating points at once.

    ``inputs``: ``INPUT_NAMES`` without ``phi_rad``; scalars or arrays with K
    entries (chord/twist: n or (n, K)).  Returns ``phi_rad``, ``residual``
    (n*m, K), ``found`` (bool), ``quadrant`` (1: (0, 3 pi/4], the NLP's domain; 2: (-pi/2, 0);
    3: (3 pi/4, pi); 4: (-pi, -pi/2); 0 if none).  ``hub_fraction``: as ``point_solver``.
    """
    n, m = n_stations, n_azimuth
    arr, K = _broadcast_inputs(inputs, n)
    f = point_solver(sec, n, m, tip_loss=tip_loss, hub_loss=hub_loss, hub_fraction=hub_fraction)
    threads = default_threads()
    if threads > 1 and K > 1:   # the points split over the threads: each point's numbers unchanged
        f = f.map(K, "thread", threads)
    out = f(**{k: arr[k] for k in f.name_in()})
    phi = np.array(out["phi_rad"]).reshape(n * m, K)
    res = np.array(out["residual"]).reshape(n * m, K)
    found = np.array(out["found"]).reshape(n * m, K) > 0.5
    quadrant = np.where(found, 1, 0)
    if not found.all():
        el = _element_arrays(arr, n, m)
        for x_st, rows in _station_groups(sec, n, m, hub_fraction):
            in_group = np.zeros(n * m, bool)
            in_group[rows] = True
            _fallback_quadrants(sec, el, in_group[:, None], phi, res, found, quadrant,
                                tip_loss, hub_loss, x_st)
    return {"phi_rad": phi, "residual": res, "found": found, "quadrant": quadrant}


def _fallback_quadrants(sec, el, in_group, phi, res, found, quadrant, tip_loss, hub_loss, x_st):
    """The elements of one station group without a root in (0, 3 pi/4]: Ning's other
    quadrants, then the smallest |residual| on a fine grid (updates the arrays in place)."""
    kern = solve_kernel(sec, tip_loss=tip_loss, hub_loss=hub_loss, x_station=x_st)
    half = 0.5 * math.pi
    for q, (a, b) in ((2, (-_EPS_PHI, -half)), (3, (PHI_MAX_RAD, math.pi - _EPS_PHI)),
                      (4, (-half, -math.pi + _EPS_PHI))):
        idx = np.nonzero(~found & in_group)
        if idx[0].size == 0:
            return
        p = [el[k][idx][None, :] for k in _ELEMENT_PARAMS]
        o = kern(*p, a, b)
        ok = np.array(o[2]).ravel() > 0.5
        sel = tuple(ix[ok] for ix in idx)
        phi[sel] = np.array(o[0]).ravel()[ok]
        res[sel] = np.array(o[1]).ravel()[ok]
        found[sel] = True
        quadrant[sel] = q
    idx = np.nonzero(~found & in_group)
    if idx[0].size:
        fres = _element_residual(sec, tip_loss, hub_loss, x_st)
        grid = np.linspace(-math.pi + 1e-3, math.pi - 1e-3, 721)
        for i, j in zip(*idx):
            p = [el[k][i, j] for k in _ELEMENT_PARAMS]
            vals = np.abs(np.array(fres(grid[None, :], *p)[0]).ravel())
            vals[~np.isfinite(vals)] = np.inf
            g = int(np.argmin(vals))
            phi[i, j] = grid[g]
            res[i, j] = float(fres(grid[g], *p)[0])


@dataclass
class RotorResult:
    """Analysis results for K operating points (arrays of length K, or (n, K) per station).

    ``converged`` is True where every element found a bracketed root and
    |residual| <= 1e-8; ``residual_max`` is the largest |residual| per point.
    """

    values: dict
    residual_max: np.ndarray
    converged: np.ndarray
    inputs: dict = field(repr=False, default_factory=dict)
    stations: dict = field(repr=False, default_factory=dict)

    def __getitem__(self, key):
        return self.values[key]

    def __getattr__(self, key):
        v = self.__dict__.get("values")
        if v is not None and key in v:
            return v[key]
        raise AttributeError(key)

    def keys(self):
        return self.values.keys()

    def power_budget(self) -> dict:
        """Where the shaft power goes, per operating point (axial flow, from :func:`analyze`): W.

        With ``W cos(phi) = Omega r - v`` and ``W sin(phi) = V + u`` the element's share of
        ``P - T V`` splits exactly into the lift's work on the induced velocities and the drag's::

            P_induced = sum B q c cl (v sin(phi) + u cos(phi)) dr,
            P_profile = sum B q c cd (W + v cos(phi) - u sin(phi)) dr,     q = rho W^2 / 2,

        and ``ideal_induced`` is the actuator disk's induced power at the same thrust on the whole
        disk, ``T V (1/eta_i - 1)``, ``eta_i = 2/(1 + sqrt(1 + T/(q_inf pi R^2)))`` (Froude):
        what no blade can avoid at that disk loading; ``induced - ideal_induced`` is the swirl,
        tip and hub losses and the departure from ideal loading.  Keys: ``shaft``, ``useful``
        (``T V``), ``induced``, ``ideal_induced``, ``profile``, ``disk_loading`` (``T/(q_inf
        pi R^2)``) and ``closure`` (``shaft - useful - induced - profile``: quadrature only)."""
        inp, st = self.inputs, self.stations
        if not st or np.any(np.asarray(inp["v_inplane_mps"], float) > 0):
            raise InputError("power_budget", "needs an axial-flow result of analyze() (no in-plane inflow)")
        V = np.asarray(inp["v_axial_mps"], float)
        rho, B, R = float(inp["rho_kgpm3"]), float(inp["blades"]), float(inp["radius_m"])
        phi, W, u, v = (np.asarray(self.values[k], float) for k in ("phi_rad", "W_mps", "u_mps", "v_mps"))
        qc = 0.5 * rho * W ** 2 * np.asarray(st["chord_m"], float)[:, None] * B * np.asarray(st["dr_m"], float)[:, None]
        induced = np.sum(qc * self.values["cl"] * (v * np.sin(phi) + u * np.cos(phi)), axis=0)
        profile = np.sum(qc * self.values["cd"] * (W + v * np.cos(phi) - u * np.sin(phi)), axis=0)
        T, P = np.asarray(self.values["thrust_N"], float), np.asarray(self.values["power_W"], float)
        useful = T * V
        with np.errstate(divide="ignore", invalid="ignore"):
            tc = T / (0.5 * rho * V ** 2 * math.pi * R ** 2)
            eta_i = 2.0 / (1.0 + np.sqrt(1.0 + tc))
            ideal = np.where(V > 0, useful * (1.0 / eta_i - 1.0), np.nan)
        return {"shaft": P, "useful": useful, "induced": induced, "ideal_induced": ideal, "profile": profile,
                "disk_loading": tc, "closure": P - useful - induced - profile}


def operating_inputs(rotor: RotorGeometry, *, omega_radps, v_axial_mps=0.0, v_inplane_mps=0.0,
                     altitude_m=0.0, pitch_rad=None, rho_kgpm3=None, mu_Pas=None, a_mps=None,
                     n_stations=20) -> tuple[dict, dict]:
    """Numeric BEMT inputs (checked) for a geometry and operating points."""
    st = rotor.stations(n_stations)
    om = np.atleast_1d(np.asarray(omega_radps, dtype=float))
    if not np.all(np.isfinite(om)) or np.any(om <= 0):
        raise InputError("omega", f"rotor speed must be finite and > 0 rad/s, got {om.min():g}")
    for nm, v in (("v_axial_mps", v_axial_mps), ("v_inplane_mps", v_inplane_mps)):
        if not np.all(np.isfinite(np.asarray(v, dtype=float))):
            raise InputError(nm, "must be finite")
    if np.any(np.asarray(v_inplane_mps, dtype=float) < 0):
        raise InputError("v_inplane_mps", "is a magnitude: must be >= 0 m/s")
    if rho_kgpm3 is None or mu_Pas is None or a_mps is None:
        try:
            check_altitude(altitude_m, "altitude_m")
        except ValueError as exc:
            raise InputError("altitude", str(exc)) from exc
    rho = density(np.asarray(altitude_m, dtype=float)) if rho_kgpm3 is None else rho_kgpm3
    mu = dynamic_viscosity(np.asarray(altitude_m, dtype=float)) if mu_Pas is None else mu_Pas
    a = speed_of_sound(np.asarray(altitude_m, dtype=float)) if a_mps is None else a_mps
    for nm, v in (("rho", rho), ("mu", mu), ("speed of sound", a)):
        vv = np.asarray(v, dtype=float)
        if not np.all(np.isfinite(vv)) or np.any(vv <= 0):
            raise InputError(nm, "must be finite and > 0")
    pitch = rotor.pitch_offset_rad if pitch_rad is None else pitch_rad
    vtip = np.sqrt((om * rotor.radius_m) ** 2 + np.asarray(v_axial_mps, dtype=float) ** 2
                   + np.asarray(v_inplane_mps, dtype=float) ** 2)
    mtip = vtip / np.asarray(a, dtype=float)
    if np.any(mtip >= 1.0):
        raise InputError("tip Mach", f"helical tip Mach number must be < 1 (subsonic sections), got "
                                     f"{np.max(mtip):.3f}")
    inputs = {
        "radius_m": rotor.radius_m, "hub_fraction": rotor.hub_fraction, "blades": rotor.blades,
        "chord_m": st["chord_m"], "twist_rad": st["beta_rad"], "pitch_rad": pitch,
        "omega_radps": om, "v_axial_mps": v_axial_mps, "v_inplane_mps": v_inplane_mps,
        "rho_kgpm3": rho, "mu_Pas": mu, "a_mps": a, "spin": float(rotor.rotation),
    }
    return inputs, st


def evaluate(sec, inputs: dict, phi: np.ndarray, n_stations: int, n_azimuth: int, *,
             tip_loss=True, hub_loss=True, hub_fraction=None) -> dict:
    """All ``FULL_OUTPUTS`` of ``bemt_function`` at given ``phi`` (n*m, K)."""
    key = _cache_key(sec, "full", n_stations, n_azimuth, tip_loss, hub_loss, hub_fraction)
    if key not in _CACHE:
        _CACHE[key] = (bemt_function(sec, n_stations, n_azimuth, outputs="full", tip_loss=tip_loss,
                                     hub_loss=hub_loss, name="bemt_full", hub_fraction=hub_fraction), sec)
    f = _CACHE[key][0]
    arr, K = _broadcast_inputs(inputs, n_stations)
    out = f(**{k: arr[k] for k in INPUT_NAMES if k != "phi_rad"}, phi_rad=phi)
    vals = {}
    for k in FULL_OUTPUTS:
        v = np.array(out[k])
        if v.shape[0] == 1:
            v = v.ravel()
        vals[k] = v
    return vals


def analyze(rotor: RotorGeometry, *, omega_radps, v_axial_mps=0.0, v_inplane_mps=0.0,
            altitude_m=0.0, pitch_rad=None, rho_kgpm3=None, mu_Pas=None, a_mps=None,
            n_stations: int = 20, n_azimuth: int | None = None, section=None,
            tip_loss=True, hub_loss=True) -> RotorResult:
    """Rotor performance at one or many operating points (numbers in, numbers out).

    Arguments broadcast over K points: ``omega_radps`` (> 0), ``v_axial_mps``
    (freestream along the thrust axis; negative in descent), ``v_inplane_mps``
    (>= 0), ``altitude_m`` (USSA76; or give rho/mu/a directly), ``pitch_rad``
    (collective; default the geometry's pitch offset).  ``n_azimuth`` defaults to
    1 in axial flow and 12 when any in-plane velocity is given.  Returns a
    ``RotorResult`` with every ``FULL_OUTPUTS`` entry, ``phi_rad`` and the residual.  A radial
    distribution of sections is placed at the stations of this rotor's hub (``analyze_inputs``).
    """
    sec = make_section(rotor.airfoil if section is None else section)
    vin = np.asarray(v_inplane_mps, dtype=float)
    if n_azimuth is None:
        n_azimuth = 12 if np.any(vin > 0) else 1
    if n_azimuth == 1 and np.any(vin > 0):
        raise InputError("n_azimuth", "in-plane inflow needs n_azimuth >= 2 (azimuth averaging)")
    inputs, st = operating_inputs(rotor, omega_radps=omega_radps, v_axial_mps=v_axial_mps,
                                  v_inplane_mps=v_inplane_mps, altitude_m=altitude_m,
                                  pitch_rad=pitch_rad, rho_kgpm3=rho_kgpm3, mu_Pas=mu_Pas,
                                  a_mps=a_mps, n_stations=n_stations)
    out = analyze_inputs(sec, inputs, n_stations, n_azimuth, tip_loss=tip_loss, hub_loss=hub_loss,
                         hub_fraction=rotor.hub_fraction)
    out.stations = st
    return out


def analyze_inputs(sec, inputs: dict, n_stations: int = 20, n_azimuth: int = 1, *, tip_loss=True,
                   hub_loss=True, hub_fraction=None) -> RotorResult:
    """Low-level analysis on raw ``bemt_function`` inputs (no checks): chord and twist
    given at the BEMT stations; scalars or K-vectors for the operating inputs.
    ``hub_fraction`` (a number, equal to the input's): sections placed at the stations, as
    the NLP's rotor Functions built with it (``bemt_function``)."""
    kw = {"tip_loss": tip_loss, "hub_loss": hub_loss, "hub_fraction": hub_fraction}
    sol = solve_phi(sec, inputs, n_stations, n_azimuth, **kw)
    vals = evaluate(sec, inputs, sol["phi_rad"], n_stations, n_azimuth, **kw)
    vals["phi_rad"] = sol["phi_rad"]
    vals["quadrant"] = sol["quadrant"]
    resid = np.abs(np.asarray(vals["residual"]))
    rmax = np.max(resid, axis=0)
    conv = sol["found"].all(axis=0) & (rmax <= 1e-8)
    return RotorResult(vals, rmax, conv, inputs=inputs)


def sweep_J(rotor: RotorGeometry, J, *, rpm: float, altitude_m: float = 0.0, pitch_rad=None,
            n_stations: int = 20, section=None) -> RotorResult:
    """Axial-flow J sweep at constant rpm: ``V = J n D``."""
    J = np.atleast_1d(np.asarray(J, dtype=float))
    if not np.all(np.isfinite(J)):
        raise InputError("J", "advance ratios must be finite")
    if not (math.isfinite(rpm) and rpm > 0):
        raise InputError("rpm", f"must be > 0, got {rpm!r}")
    n_rev = rpm / 60.0
    return analyze(rotor, omega_radps=np.full(J.shape, 2 * math.pi * n_rev),
                   v_axial_mps=J * n_rev * rotor.diameter_m, altitude_m=altitude_m,
                   pitch_rad=pitch_rad, n_stations=n_stations, section=section)


def analysis_function(sec, n_stations: int, n_points: int, n_azimuth: int = 1, *,
                      tip_loss=True, hub_loss=True) -> ca.Function:
    """One CasADi Function for a K-point sweep: inputs as ``bemt_function`` without
    ``phi_rad`` (operating inputs with K columns), outputs ``phi_rad``,
    ``found`` and every "full" output, each with K columns.  Searches (0, PHI_MAX_RAD] only
    (the fallback quadrants are Python; ``analyze`` applies them)."""
    ps = point_solver(sec, n_stations, n_azimuth, tip_loss=tip_loss, hub_loss=hub_loss)
    full = bemt_function(sec, n_stations, n_azimuth, outputs="full", tip_loss=tip_loss,
                         hub_loss=hub_loss)
    x = _symbols(n_stations, n_azimuth, ca.MX)
    names_in = [k for k in INPUT_NAMES if k != "phi_rad"]
    s = ps(**{k: x[k] for k in names_in})
    o = full(**{k: x[k] for k in names_in}, phi_rad=s["phi_rad"])
    point = ca.Function("bemt_point_analysis", [x[k] for k in names_in],
                        [s["phi_rad"], s["found"]] + [o[k] for k in FULL_OUTPUTS],
                        names_in, ["phi_rad", "found"] + list(FULL_OUTPUTS))
    return point.map(n_points)
