"""Where the wing stalls first: the ailerons must still fly when the wing stalls.

A wing whose tips stall first rolls off at the stall, and its ailerons, in separated flow,
cannot pick it up.  The certification basis asks that a wings-level stall can be held within
15 deg of roll by normal use of the controls (14 CFR 23.201(b) before Amendment 23-64; CS-23
Amdt 4, 23.201), and design practice is a wing that stalls from the root, its aileron span
attached (Raymer, *Aircraft Design*, 6th ed., sec. 4.3 on taper, twist and tip stall;
Gudmundsson, *General Aviation Aircraft Design*, 2014, sec. 9.5 on stall progression).  A
taper below about 0.4 loads the tips and brings their stall inboard of the root's unless the
wing is washed out; the mission's stall margin alone does not see this, for the mission flies
well below cl_max.  This is the limit that holds taper (issue 16 item 4), a property of the
design:

* The clean lattice of the design (flaps up, no slipstreams: the power-off stall) is linear
  in the angle of attack, so each strip's section cl is ``c0_i + c1_i alpha``, from two
  solves of the lattice (alpha 0 and 0.1 rad).  Strip i reaches its section's cl_max at

      alpha_i = (cl_max_i - c0_i) / c1_i                                          (P1)

  with cl_max at the strip's Reynolds number for a sea-level stall at the vehicle's
  ``VehicleConfig.stall_pattern_speed_mps`` (default 61 kn = 31.4 m/s, CS-23's stall-speed
  limit for the class; a small UAV states its own).
* The stall onset is the smooth minimum of (P1) over the exposed strips inboard of the
  ailerons, ``alpha_s = soft_min(alpha_i, w)``, w = 0.1 deg (below the true minimum by at
  most w ln n, 0.3 deg for 20 strips: conservative).
* At the onset every aileron strip keeps the vehicle's stall margin (0.1 in cl):

      c0_k + c1_k alpha_s <= cl_max_k - margin        for every strip k of the aileron span (P2)

The lattice is the attached (linear) one; the viscous correction of the mission's nodes
(``mdo.vehicle.viscous_wing``) is not applied here.  Its main effect, each section's own
zero-lift angle and slope against the lattice's, shifts every strip of one section alike and
so moves the onset but not which strips stall first; its bend of each strip's lift curve near
cl_max delays no strip's stall.  A wing without ailerons
(``WingConfig.aileron_span_eta`` = (0, 0)) gets no rows.
"""
from __future__ import annotations

import math

import casadi as ca

from ..core.atmosphere import atmosphere
from ..core.smooth import soft_min
from ..core.units import DEG
from .stall import clmax_of_re

__all__ = ["ONSET_WIDTH_RAD", "stall_pattern_rows", "add_stall_pattern"]

ONSET_WIDTH_RAD = math.radians(0.1)
_ALPHA1 = 0.1                              # rad, the second lattice solve


def stall_pattern_rows(vlm, wings, strip_eta, exposed, speed_mps) -> dict:
    """Per wing of ``wings`` (WingConfig) with an aileron span: ``{name: (excess, labels,
    alpha_s)}`` for a stall at ``speed_mps`` (sea level), ``excess`` the column
    ``c0_k + c1_k alpha_s - cl_max_k`` of its aileron strips
    (P2 asks ``excess + margin <= 0``) and ``alpha_s`` its stall onset (rad, P1)."""
    atm = atmosphere(0.0)
    re_per_chord = float(atm["density_kgpm3"]) * speed_mps / float(atm["dynamic_viscosity_Pas"])
    r = vlm.solve(ca.DM([[0.0, _ALPHA1]]), 1.0, rho=1.0)
    cl = r["cl_local"]
    c0, c1 = cl[:, 0], (cl[:, 1] - cl[:, 0]) / _ALPHA1
    chord = vlm.geometry["strip_chord"].T
    names = [s.name for s in vlm.surfaces]
    out = {}
    for w in wings:
        lo, hi = (float(x) for x in w.aileron_span_eta)
        mine = [i for i, si in enumerate(vlm.strip_surface) if names[si] == w.name and exposed[i]]
        inboard = [i for i in mine if strip_eta[i] < lo]
        aileron = [i for i in mine if lo <= strip_eta[i] <= hi]
        if hi <= lo or not inboard or not aileron:
            continue
        cmax = {i: clmax_of_re(str(vlm.strip_airfoil[i]), re_per_chord * chord[i]) for i in inboard + aileron}
        a_s = soft_min(ca.vertcat(*[(cmax[i] - c0[i]) / c1[i] for i in inboard]), ONSET_WIDTH_RAD)   # (P1)
        excess = ca.vertcat(*[c0[k] + c1[k] * a_s - cmax[k] for k in aileron])                     # (P2)
        out[w.name] = (excess, [f"{w.name} eta {float(strip_eta[k]):.2f} at stall onset" for k in aileron], a_s)
    return out


def add_stall_pattern(ac, problem) -> None:
    """(P2) on the design's lattice as the constraint group "stall pattern" (a design
    optimization, ``ac.design_point_constraints``, with its limits on; an analysis reports it),
    and per wing its stall onset angle (deg) and the aileron strips' smallest margin to
    cl_max there (outputs)."""
    margin = float(ac.stall_margin_cl)
    per_wing = stall_pattern_rows(ac.vlm, ac.lifting_wings, ac.strip_eta, ac.strip_exposed,
                                  ac.config.stall_pattern_speed_mps)
    for name, (excess, _, a_s) in per_wing.items():
        problem.output(f"{name}.stall_onset_alpha_deg", a_s / DEG, unit="deg", summary=True)
        problem.output(f"{name}.aileron_cl_margin_at_stall_onset", -ca.mmax(excess), unit="-", summary=True)
    if per_wing and ac.design_point_constraints and ac.limits_on and margin >= 0.0:
        rows = ca.vertcat(*[e for e, _, _ in per_wing.values()]) + margin
        labels = [lab for _, labs, _ in per_wing.values() for lab in labs]
        problem.constrain("stall pattern", rows, kind="<=", rhs=0.0, scale=0.1, unit="-", labels=labels)
