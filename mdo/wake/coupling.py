"""Coupling of the propeller wakes into the wing (paper Eqs. 5–6).

The wake's induced velocity at the wing's control points is added to the onset
flow in the VLM's flow-tangency condition (Eq. 5: v_tot = v_wing + v_wake, with
v_wake = Σ C_{r,t} Γ_r, Eq. 6b); mdo.wing.VLM takes it as ``v_ext``.  With
``lift_velocity='local'`` the VLM also uses it in Kutta–Joukowski, so a blown strip
feels the slipstream's dynamic pressure (the paper's code used the freestream one;
see README for the choice).

One function serves analysis and the mission NLP:

    vx, vy, vz = external_velocity(points, rotors, gamma, omega_radps, v_wake_mps)

``points`` 3×M (numbers or MX, e.g. the VLM's symbolic control points), ``rotors`` a
list of :class:`WakeRotor` (placement, axis, sense, radius; may hold MX), and per
rotor its blade circulation ``gamma`` (N×K, one column per operating point), rotor
speed and wake convection speed (K,).  Returns three M×K matrices.

With ``model="mean"`` (default) the blade-passage-averaged wake is evaluated in
factored form, M×N influence matrices (axial, radial, swirl) of the geometry times
Γ Ω/V_w or Γ: the B-spline table is evaluated once per design (M·(N+1) look-ups per
rotor), and each operating point costs three matrix–vector products — the form for
the mission NLP.  ``model="full"`` evaluates the
helical fixed wake (Biot–Savart over every filament) at every operating point:
the paper's model, for analysis and checks.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..core.errors import InputError
from .helical import DEFAULT_ROTATIONS, DEFAULT_STEPS_PER_ROTATION, full_wake_velocity
from .frames import rotor_frame
from .mean import influence, influence_parts, strip_averaged_influence

__all__ = ["wake_influences", "external_velocity", "apply_influences", "influence_sum_parts",
           "wake_convection_speed"]


def wake_convection_speed(v_axial_mps, va_mean_mps):
    """Convection speed of the fixed wake along its axis: the freestream component
    along the axis plus the BEMT's disk-averaged induced axial velocity (paper §III.B)."""
    return v_axial_mps + va_mean_mps


def wake_influences(points, rotors, spans=None, samples: int = 1):
    """Per rotor, the averaged wake's factored influence at ``points`` (3×M): see
    mean.influence_function.  Evaluate once per design; reuse for every node.
    With ``spans`` (3×M, each strip's spanwise extent through its point) and
    ``samples`` > 1, the velocity is averaged across each strip
    (:func:`mdo.wake.mean.strip_averaged_influence`)."""
    if spans is not None and samples > 1:
        return [strip_averaged_influence(points, spans, r, samples) for r in rotors]
    return [influence(points, r) for r in rotors]


def _is_sym(*xs):
    return any(isinstance(x, (ca.MX, ca.SX)) for x in xs)


def _as_nk(g, n, name):
    if isinstance(g, (ca.MX, ca.SX, ca.DM)):
        if g.shape[0] != n:
            if g.shape[1] == n:
                return g.T
            raise InputError(name, f"must have {n} rows (stations), got {g.shape}")
        return g
    a = np.asarray(g, dtype=float)
    if a.ndim == 1:
        a = a.reshape(-1, 1)
    if a.shape[0] != n:
        raise InputError(name, f"must have {n} rows (stations), got {a.shape}")
    return ca.DM(a)


def _as_row(v, k, name):
    if isinstance(v, (ca.MX, ca.SX, ca.DM)):
        v = ca.reshape(v, 1, v.numel())
        return ca.repmat(v, 1, k) if v.numel() == 1 and k > 1 else v
    a = np.atleast_1d(np.asarray(v, dtype=float)).reshape(1, -1)
    if a.size == 1 and k > 1:
        a = np.repeat(a, k, axis=1)
    if a.size != k:
        raise InputError(name, f"must have one value per operating point ({k}), got {a.size}")
    return ca.DM(a)


def apply_influences(influences, gamma, omega_radps, v_wake_mps, axial_factor=1.0):
    """Σ over rotors of the averaged-wake velocity: (vx, vy, vz), each M×K, from the
    per-rotor factored influences and per-rotor Γ (N×K), Ω and V_w (K values);
    ``axial_factor`` scales each rotor's velocity component along its own axis."""
    axial, rest = influence_sum_parts(influences, gamma, omega_radps, v_wake_mps)
    return tuple(axial_factor * a + r for a, r in zip(axial, rest))


def influence_sum_parts(influences, gamma, omega_radps, v_wake_mps):
    """As :func:`apply_influences`, in two parts summed over the rotors: the velocity
    along each rotor's axis and the rest (radial, swirl), each (vx, vy, vz) M×K."""
    axial = rest = None
    for infl, g, om, vw in zip(influences, gamma, omega_radps, v_wake_mps):
        n = (infl["Bx"] if isinstance(infl, dict) else infl[0]).shape[1]
        g = _as_nk(g, n, "gamma")
        k = g.shape[1]
        ratio = _as_row(om, k, "omega_radps") / _as_row(vw, k, "v_wake_mps")
        a, r = influence_parts(infl, g * ca.repmat(ratio, n, 1), g)
        axial = a if axial is None else tuple(x + y for x, y in zip(axial, a))
        rest = r if rest is None else tuple(x + y for x, y in zip(rest, r))
    return axial, rest


def external_velocity(points, rotors, gamma, omega_radps, v_wake_mps, *, model: str = "mean",
                      influences=None, phases: int = 1, n_rotations=DEFAULT_ROTATIONS,
                      steps_per_rotation=DEFAULT_STEPS_PER_ROTATION, phase_rad=0.0, axial_factor=1.0):
    """Wake-induced velocity of all ``rotors`` at ``points`` for K operating points.

    points: 3×M (numbers or MX).  rotors: list of WakeRotor.  gamma: per rotor N×K
    blade circulation (m²/s).  omega_radps, v_wake_mps: per rotor K values.
    model: "mean" (averaged wake, NLP form; ``influences`` may be passed to reuse
    the per-design factors of :func:`wake_influences`) or "full" (helical fixed wake; ``phases`` snapshots
    averaged, each ``n_rotations`` × ``steps_per_rotation`` rings per blade and
    element, blade 0 at ``phase_rad``).
    axial_factor: scales each rotor's velocity component along its axis (1: the wake
    as it is; 0: swirl and radial parts only — e.g. for the Kutta–Joukowski velocity
    at the bound vortices when the slipstream's extra dynamic pressure is to be left
    out of the forces, see README "Coupling").
    Returns (vx, vy, vz), each M×K (NumPy for numeric input, MX otherwise).
    """
    if len(gamma) != len(rotors) or len(omega_radps) != len(rotors) or len(v_wake_mps) != len(rotors):
        raise InputError("gamma", "give one entry per rotor in gamma, omega_radps and v_wake_mps")
    pts = points if isinstance(points, (ca.MX, ca.SX, ca.DM)) else ca.DM(np.asarray(points, float).reshape(3, -1))
    m = pts.shape[1]
    if model == "mean":
        infl = influences if influences is not None else wake_influences(pts, rotors)
        vx, vy, vz = apply_influences(infl, gamma, omega_radps, v_wake_mps, axial_factor)
        if isinstance(vx, ca.DM):
            return np.array(vx), np.array(vy), np.array(vz)
        return vx, vy, vz
    elif model == "full":
        cols = None
        for r, g, om, vw in zip(rotors, gamma, omega_radps, v_wake_mps):
            g = _as_nk(g, r.n_stations, "gamma")
            k = g.shape[1]
            om = _as_row(om, k, "omega_radps")
            vw = _as_row(vw, k, "v_wake_mps")
            cr = []
            for j in range(k):
                v = full_wake_velocity(pts, r, g[:, j], om[j], vw[j], phases=phases, n_rotations=n_rotations,
                                       steps_per_rotation=steps_per_rotation, phase_rad=phase_rad)
                v = v if isinstance(v, (ca.MX, ca.SX)) else ca.DM(v)
                if not (isinstance(axial_factor, (int, float)) and axial_factor == 1.0):
                    e_a = rotor_frame(r.axis if isinstance(r.axis, (ca.MX, ca.SX)) else ca.DM(np.asarray(r.axis, float)))[0]
                    e_a = ca.DM(e_a) if not isinstance(e_a, (ca.MX, ca.SX)) else e_a
                    v = v - (1 - axial_factor) * ca.mtimes(e_a, ca.mtimes(e_a.T, v))
                cr.append(ca.reshape(v, 3 * m, 1))
            cr = ca.horzcat(*cr)
            cols = cr if cols is None else cols + cr
        u = cols
    else:
        raise InputError("model", f"'mean' or 'full', got {model!r}")
    vx, vy, vz = u[0::3, :], u[1::3, :], u[2::3, :]
    if isinstance(u, ca.DM):
        return np.array(vx), np.array(vy), np.array(vz)
    return vx, vy, vz


# Force couplings measured on PROWIM and the rotation studies (README "Coupling"):
# name -> (the VLM's lift_velocity, axial factor of the wake velocity at the bound vortices)
COUPLINGS = {
    "swirl": ("local", 0.0),            # forces ⊥ V∞ + swirl/radial wake velocity, freestream q (default)
    "freestream": ("freestream", 1.0),  # the paper's code: forces with V∞ only
    "local": ("local", 1.0),            # forces with the full local velocity (slipstream q)
}


def vlm_wake_inputs(vlm, rotors, gamma, omega_radps, v_wake_mps, *, coupling: str = "swirl",
                    model: str = "mean", bound_points: str = "rb", influences=None, **full_options):
    """Keyword arguments ``v_ext`` and ``v_ext_bound`` for ``vlm.solve`` (duck-typed: any
    object whose ``geometry`` dict has control points ``cp`` and bound midpoints ``rb``).

    ``coupling`` picks the force model (``COUPLINGS``; build the VLM with
    ``lift_velocity=COUPLINGS[coupling][0]``).  ``bound_points="rb"`` evaluates the wake
    at the bound-vortex midpoints; ``"cp"`` reuses the control-point influence (half the
    table look-ups in an NLP; the points are half a panel chord apart).
    ``influences``: optional (cp_influences, rb_influences) from :func:`wake_influences`
    to reuse per-design factors (model "mean").  ``full_options`` go to the full wake.
    """
    if coupling not in COUPLINGS:
        raise InputError("coupling", f"one of {tuple(COUPLINGS)}, got {coupling!r}")
    if bound_points not in ("rb", "cp"):
        raise InputError("bound_points", f"'rb' or 'cp', got {bound_points!r}")
    lv, k_ax = COUPLINGS[coupling]
    if getattr(vlm, "lift_velocity", lv) != lv:
        raise InputError("coupling", f"coupling {coupling!r} needs VLM(lift_velocity={lv!r}), "
                                     f"the VLM has {vlm.lift_velocity!r}")
    g = vlm.geometry
    cp = g["cp"]
    rb = g["rb"] if bound_points == "rb" else cp
    infl_cp, infl_rb = (influences if influences is not None else (None, None))
    if model == "mean" and infl_cp is None:
        infl_cp = wake_influences(cp, rotors)
        infl_rb = infl_cp if bound_points == "cp" else wake_influences(rb, rotors)
    args = (rotors, gamma, omega_radps, v_wake_mps)
    v_cp = external_velocity(cp, *args, model=model, influences=infl_cp, **full_options)
    v_rb = external_velocity(rb, *args, model=model, influences=infl_rb, axial_factor=k_ax, **full_options)
    return {"v_ext": v_cp, "v_ext_bound": v_rb}
