"""The wing's bending material: how the wing mass responds to span, taper, thickness and
the share of the lift the wing carries.

Raymer's Eq. 15.46 is a regression over single-wing light aircraft: it sizes every wing
for the whole ``N_z W`` and grows with ``AR^0.6``.  A tandem whose front wing carries
84 % of the lift, or a long wing that the optimizer stretches, needs the physics the
regression stands for (Torenbeek, *Synthesis of Subsonic Airplane Design*, 1982, Sec. 8.4
and App. C: the material that resists the root bending moment is the design-sensitive
part of a wing's weight):

* **Load.**  The wing's design lift ``F`` (N, 1 g; sized: at least the wing's lift at every
  wing-borne node, ``aircraft_nodes.wing_design_lift_rows``), times the ultimate load factor
  (the maneuver and gust envelope of the class), spread elliptically over the span
  (the ideal loading the weight estimates assume).  Per half wing, with ``u = y/s`` and
  ``l0 = 4 (n F / 2) / (pi s)``::

      V(u) = l0 s [pi/4 - (u sqrt(1-u^2) + asin u)/2]                        (S1)
      M(u) = l0 s^2 [(1-u^2)^1.5 / 3 - u (pi/4 - (u sqrt(1-u^2) + asin u)/2)] (S2)

* **Inertia relief.**  Motors, propellers and nacelles on the wing, at ``y_i``, accelerated at
  the same ``n``: ``M -= n g m_i (y_i - y)`` inboard of each, written with a softplus of
  width ``relief_width_fraction * s`` (smooth in the rotor positions, which are design
  variables).
* **Material.**  Two spar caps at the box depth ``h = k_box (t/c) c(y)`` carry ``M/h`` each
  at the allowable stress ``sigma``; the webs carry ``V`` at ``tau``::

      m = 2 rho s int_0^1 [2 |M| / (sigma h) + |V| / tau] du                    (S3)

  (both halves; ``|x|`` as ``sqrt(x^2 + eps^2)``, eps 1e-6 of the root value), by
  Gauss-Legendre quadrature in ``u``, times a non-optimum factor (joints, fasteners,
  cut-outs, minimum gauges on the ideal material).

At constant area the caps grow like ``b^3 n F / ((t/c) S)``: ``AR^1.5`` and linear in the
lift share, against Raymer's ``AR^0.6`` at the whole weight.  The rest of the wing (skins
beyond the caps' need, ribs, leading and trailing edges, control surfaces) depends on the
area, which the design holds: ``mdo.vehicle.mass`` takes it as the Raymer wing of the
baseline less this model's bending material at the baseline (the regression's level, the
bending physics' slopes).

* **Stiffness.**  Caps sized for strength alone bend the tip of a long wing far: their
  curvature at limit load is ``2 sigma / (E h FS)`` whatever the load, so the tip deflection
  at limit load is ``delta_s = s^2 int (1-u) 2 sigma / (FS E h) du`` (FS the factor of safety
  between limit and ultimate load, 1.5, 14 CFR 23.2230(a)(2) / CS 23.305) and grows like
  ``s^2 / h``: 13 % of the semispan for the P2006T's wing (AR 8.8), 42 % for an aluminium
  AR-30 wing.  The wing must also meet ``delta <= f s`` at limit load.  The caps of least
  mass that meet the deflection alone are ``A = lambda g``, ``g = sqrt((1-u) M_lim) / h``
  (the Lagrange condition of min int A du at int (1-u) 2 M_lim / (E A h^2) du = f / s), so
  ``lambda = 2 s G / (E f)`` with ``G = int g du``.  Each station's cap is the larger of the
  two (smooth maximum, width 1 % of their sum): feasible for both criteria, and at most the
  stiffness material above the strength-only optimum::

      m_caps = 2 rho s int 2 max(|M| / (sigma h), lambda g) du                   (S4)

  Why a deflection limit: the lattice is a rigid planar wing, the beam linear; at
  ``f = 0.2`` (default) the 1 g deflection is ``0.2 / 3.8``, 5 % of the semispan, where the
  projected span the rigid lattice assumes is still within 0.5 %.  It is also about what a
  strength-sized aluminium wing of AR 15 (the X-57 Mod IV's) deflects (21 %), so no wing
  the class flies is held by it; wings beyond AR ~15 pay for their stiffness.  Wing-mounted
  rotors add whirl-flutter stiffness needs this model does not have (``f`` is a field: a
  stiffer criterion for them).  ``max_tip_deflection_fraction=None``: strength only.

Material defaults: aluminium 2024-T3 (MMPDS-01: density 2780 kg/m^3, F_tu 483 MPa,
F_su 283 MPa, E 72.4 GPa), with a cap allowable of 345 MPa (compression caps, stiffened-panel
crippling below F_tu) and 200 MPa in the webs; ``k_box`` 0.85 (caps inside the section's
depth); non-optimum factor 1.5.  These are assumptions of the class, stated, and fields
of :class:`WingStructure` a user replaces for another construction (a composite wing).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..core.errors import InputError, check_range
from ..core.smooth import sigmoid, smooth_abs, smooth_max, softplus

__all__ = ["WingStructure", "bending_material_kg", "wing_box_breakdown", "strength_sized_tip_deflection",
           "elliptic_shear_moment"]

G0 = 9.80665


@dataclass(frozen=True)
class WingStructure:
    """The construction of a cantilever wing box (see the module docstring)."""
    density_kgpm3: float = 2780.0
    cap_stress_Pa: float = 345e6
    web_stress_Pa: float = 200e6
    box_depth_fraction: float = 0.85
    non_optimum_factor: float = 1.5
    quadrature_points: int = 12
    relief_width_fraction: float = 0.01
    youngs_modulus_Pa: float = 72.4e9
    max_tip_deflection_fraction: float | None = 0.2    # at limit load, of the semispan (S4)
    factor_of_safety: float = 1.5                      # ultimate / limit load

    def __post_init__(self):
        for name, (lo, hi) in {"density_kgpm3": (100.0, 20000.0), "cap_stress_Pa": (1e6, 5e9),
                               "web_stress_Pa": (1e6, 5e9), "box_depth_fraction": (0.1, 1.0),
                               "non_optimum_factor": (1.0, 5.0), "relief_width_fraction": (0.002, 0.2),
                               "quadrature_points": (4, 64), "youngs_modulus_Pa": (1e8, 1e12),
                               "factor_of_safety": (1.0, 3.0)}.items():
            check_range(f"wing_structure.{name}", getattr(self, name), lo, hi)
        if self.max_tip_deflection_fraction is not None:
            check_range("wing_structure.max_tip_deflection_fraction", self.max_tip_deflection_fraction, 0.01, 1.0)
        if not isinstance(self.quadrature_points, int):
            raise InputError("wing_structure.quadrature_points", f"an integer, got {self.quadrature_points!r}")


def elliptic_shear_moment(u, half_lift, semispan):
    """Shear force and bending moment (S1, S2) at ``u = y/s`` of a half wing carrying
    ``half_lift`` (N) elliptically over ``semispan`` (m)."""
    l0 = 4.0 * half_lift / (math.pi * semispan)
    root = np.sqrt(1.0 - u * u)
    tail = math.pi / 4 - (u * root + np.arcsin(u)) / 2     # int_u^1 sqrt(1-t^2) dt
    return l0 * semispan * tail, l0 * semispan ** 2 * (root ** 3 / 3.0 - u * tail)


def bending_material_kg(ws: WingStructure, area_m2, span_m, taper, thickness_to_chord, load_factor,
                        design_lift_N, point_masses=()):
    """Bending and shear material of the whole wing (S3, S4, times the non-optimum factor), kg.

    ``point_masses``: ``(mass_kg, y_m)`` per half wing (numbers or CasADi), the masses
    that relieve the bending.  Every other input is a number or a CasADi expression."""
    return wing_box_breakdown(ws, area_m2, span_m, taper, thickness_to_chord, load_factor, design_lift_N,
                              point_masses)["total_kg"]


def _stations(ws: WingStructure):
    """Gauss-Legendre stations ``u = y/s`` in (0, 1) and their weights."""
    x, w = np.polynomial.legendre.leggauss(ws.quadrature_points)
    return 0.5 * (x + 1.0), 0.5 * w


def _box_depth(ws: WingStructure, area_m2, span_m, taper, thickness_to_chord, u):
    """Depth h (m) of the box at ``u``: ``k_box (t/c) c(u)`` on the trapezoid of ``area_m2``."""
    c_root = 2.0 * area_m2 / (span_m * (1.0 + taper))
    return ws.box_depth_fraction * thickness_to_chord * c_root * (1.0 - (1.0 - taper) * u)


def strength_sized_tip_deflection(ws: WingStructure, area_m2, span_m, taper, thickness_to_chord):
    """Limit-load tip deflection over the semispan of caps sized for strength alone:
    ``s int_0^1 (1-u) 2 sigma / (FS E h) du`` (S4's curvature; geometry only, no load)."""
    u_all, w_all = _stations(ws)
    total = 0.0
    for u, wq in zip(u_all, w_all):
        h = _box_depth(ws, area_m2, span_m, taper, thickness_to_chord, u)
        total = total + wq * (1.0 - u) * 2.0 * ws.cap_stress_Pa / (ws.factor_of_safety * ws.youngs_modulus_Pa * h)
    return 0.5 * span_m * total


def wing_box_breakdown(ws: WingStructure, area_m2, span_m, taper, thickness_to_chord, load_factor,
                       design_lift_N, point_masses=()) -> dict:
    """The wing box of :func:`bending_material_kg` term by term (kg, non-optimum factor in):
    ``caps_kg`` (S4), ``strength_caps_kg`` (S3's caps alone), ``webs_kg``, ``total_kg``, and
    ``strength_tip_deflection_fraction`` (:func:`strength_sized_tip_deflection`, what S4's
    stiffness criterion compares with its limit)."""
    s = span_m / 2.0
    u_all, w_all = _stations(ws)
    V_root, M_root = elliptic_shear_moment(0.0, 0.5 * load_factor * design_lift_N, s)
    width = ws.relief_width_fraction * s
    strength, g, webs = [], [], 0.0
    for u, wq in zip(u_all, w_all):
        V, M = elliptic_shear_moment(u, 0.5 * load_factor * design_lift_N, s)
        for m_i, y_i in point_masses:
            # softplus -> max(0, y_i - y) (the relieving moment's arm); sigmoid -> the shear's step
            M = M - load_factor * G0 * m_i * softplus(y_i - u * s, width)
            V = V - load_factor * G0 * m_i * sigmoid(y_i - u * s, width)
        h = _box_depth(ws, area_m2, span_m, taper, thickness_to_chord, u)
        M_abs = smooth_abs(M, 1e-6 * M_root)
        strength.append(M_abs / (ws.cap_stress_Pa * h))                    # one cap's area, S3
        g.append(((1.0 - u) * M_abs / ws.factor_of_safety) ** 0.5 / h)   # S4's g at limit load
        webs = webs + wq * smooth_abs(V, 1e-6 * V_root) / ws.web_stress_Pa
    strength_caps = sum(wq * a_s for wq, a_s in zip(w_all, strength))
    if ws.max_tip_deflection_fraction is None:
        caps = strength_caps
    else:   # S4: lambda = 2 s G / (E f), each station's cap the larger of the two (smooth, 1 % of their sum)
        G = sum(wq * gi for wq, gi in zip(w_all, g))
        lam = 2.0 * s * G / (ws.youngs_modulus_Pa * ws.max_tip_deflection_fraction)
        caps = sum(wq * smooth_max(a_s, lam * gi, 0.01 * (a_s + lam * gi)) for wq, a_s, gi in zip(w_all, strength, g))
    k = ws.non_optimum_factor * 2.0 * ws.density_kgpm3 * s
    return {"caps_kg": k * 2.0 * caps, "strength_caps_kg": k * 2.0 * strength_caps, "webs_kg": k * webs,
            "total_kg": k * (2.0 * caps + webs),
            "strength_tip_deflection_fraction": strength_sized_tip_deflection(ws, area_m2, span_m, taper,
                                                                              thickness_to_chord)}
