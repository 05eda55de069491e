"""Component drag build-up of a whole airframe: every term in N and as Delta CD on S_ref.

The parasite drag of each component (wing, tails, fuselage, nacelles, booms) is Raymer's
component build-up (Raymer, *Aircraft Design: A Conceptual Approach*, 6th ed., sec. 12.5)::

    D_c = q FF_c Q_c S_wet,c [(1 - f_s) Cf(Re_c) + f_s r^2 Cf(r Re_c)]            (B1)

``FF`` form factor, ``Q`` interference factor, ``S_wet`` wetted area; ``f_s`` is the fraction
of the component's wetted area inside a propeller slipstream and ``r = V_slip / V`` the
slipstream axial velocity ratio there (per node): the immersed part is scrubbed at the
slipstream's dynamic pressure ``r^2 q`` and Reynolds number ``r Re``.  With ``f_s = 0`` (B1) is
Raymer's Eq. 12.24 term by term.

Skin friction with transition at ``x_tr`` (fraction of the reference length), the
Prandtl-Schlichting composite flat plate (Schlichting, *Boundary-Layer Theory*, 7th ed.,
ch. XXI, Eq. 21.16 generalised to any transition Reynolds number): the laminar run is
Blasius, the turbulent part is counted as if it had started at the leading edge minus the
turbulent friction of the laminar run::

    Cf = Cf_t(Re) - x_tr [Cf_t(x_tr Re) - Cf_l(x_tr Re)]                             (B2)
    Cf_l = 1.328 / sqrt(Re)                           (Blasius)
    Cf_t = 0.455 / ((log10 Re)^2.58 (1 + 0.144 M^2)^0.65)   (Schlichting fit, Raymer 12.27)

With x_tr Re = 5e5 this is Schlichting's ``0.455/(log Re)^2.58 - 1700/Re`` (the bracket is
1614/Re at 5e5 with the fit above; 1700 with the 0.074 Re^-0.2 law).  ``Re`` is capped by
Raymer's roughness cut-off ``38.21 (l/k)^1.053`` (a smooth minimum, 5 % width).

Transition (configuration, never a variable: the expression is the same smooth form in
every mode):

* ``Transition.turbulent()`` - x_tr = 0 (Raymer: fuselages and nacelles of metal aircraft).
* ``Transition.fixed(x)``    - x_tr = x (tripped, or a stated class figure).
* ``Transition.free(x_max, re_crit)`` - a Reynolds-number criterion: the boundary layer stays
  laminar up to ``Re_x = re_crit`` (default 5e5, the flat-plate value, Schlichting ch. XVI)
  but not past the section's pressure minimum ``x_max`` (adverse gradient),
  ``x_tr = smooth_min(re_crit/Re, x_max)`` with width 0.02.
  The section-polar alternative (XFOIL free transition per strip) stays
  :func:`mdo.wing.drag.profile_drag`.

Default for a metal GA airframe (``Transition.METAL_GA_SURFACE``): fixed at 10 % chord on
wing and tails, fully turbulent bodies.  Raymer sec. 12.5.3: riveted metal production
surfaces keep little laminar flow (laminar runs of 50 % need smooth composite); 10 % is the
front of the nose where the pressure gradient is strongly favourable.

Form factors (Raymer Eqs. 12.30-12.32, implemented in :mod:`mdo.wing.drag`)::

    FF_surface  = (1 + 0.6/(x/c)_m t/c + 100 (t/c)^4) 1.34 M^0.18 cos(L_m)^0.28
    FF_fuselage = 1 + 60/f^3 + f/400,    FF_nacelle/boom = 1 + 0.35/f,   f = l/d

Interference factors (Raymer sec. 12.5.5), the class defaults of this module:
nacelle mounted on the wing 1.5, within a diameter 1.3, farther 1.0; high/mid wing 1.0;
conventional tail 1.04-1.05 (here 1.05), V-tail 1.03, H-tail 1.08; boom 1.0.

Wetted area of a lifting surface (Raymer Eq. 7.10): ``S_wet = S_exposed (1.977 + 0.52 t/c)``.

Fuselage upsweep (Raymer Eq. 12.36): ``D/q = 3.83 u^2.5 A_max`` (u in rad), optional.

Motor / engine cooling drag, from the momentum deficit of the cooling air: the heat
``P_loss`` is carried off by ``m = P_loss / (cp dT)`` of air heated by ``dT``; the duct returns
it with a fraction ``zeta`` of its momentum lost (inlet spillage, heat-exchanger pressure
drop; Meredith's thrust recovery would make zeta smaller)::

    D_cool = zeta m V = zeta V P_loss / (cp dT)        i.e.  D_cool V = k P_loss,  k = zeta V^2/(cp dT)   (B3)

Defaults ``dT = 30 K``, ``zeta = 0.5`` (our stated assumption for a ram-air ducted cooler;
Meredith, ARC R&M 1683, 1935, for the momentum balance; Brelje et al., AIAA 2019, OpenConcept
duct model, which at cruise gives net drags of the same order).  At V = 70 m/s, k = 0.08.

Leakage and protuberances (Raymer sec. 12.5.9): a stated fraction of the component parasite
drag; propeller-driven GA 5-10 %.  Default ``EXCRESCENCE_METAL_GA = 0.10`` (the upper end:
riveted sheet metal, slotted flaps with external hinges, antennas, gear doors).

Smooth where IPOPT looks: every term is a product of smooth factors of (V, rho, mu, M, f_s,
r, P_loss), any of which may be CasADi SX/MX rows (one column per node) or NumPy arrays.

API::

    wing = SurfaceComponent.from_trapezoid("main_wing", 11.4, 14.76, 0.7, 0.12, body_width_m=1.07)
    bu = DragBuildup(s_ref_m2, components=(wing, BodyComponent(...), ...),
                     excrescence_fraction=0.10, cooling=CoolingDrag())
    out = bu.evaluate(V_mps, rho, mu, mach, slipstream={"main_wing": (f_s, r)},
                      heat_loss_W=P_loss)
    out["terms"][name] -> {"D_N", "dCD", "drag_area_m2"};  out["D_N"], out["CD0"]
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..core.errors import InputError, check_positive, check_range
from ..core.smooth import smooth_min, xp
from .drag import (ROUGHNESS_M, _smooth_re, body_wetted_area, cutoff_reynolds, form_factor_body,
                   form_factor_nacelle, form_factor_wing, skin_friction)

__all__ = [
    "Transition", "composite_skin_friction", "SurfaceComponent", "BodyComponent", "CoolingDrag",
    "DragBuildup", "surface_wetted_area", "upsweep_drag_area", "EXCRESCENCE_METAL_GA",
    "INTERFERENCE", "RE_CRIT_FLAT_PLATE",
]

RE_CRIT_FLAT_PLATE = 5e5       # Schlichting ch. XVI: flat-plate transition Re_x, 3.5e5-1e6
EXCRESCENCE_METAL_GA = 0.10    # Raymer sec. 12.5.9: propeller GA 5-10 % of parasite drag
CP_AIR = 1005.0                # J/(kg K)
X_TR_WIDTH = 0.02              # smooth-min width of the free-transition criterion (x/c)

# Raymer sec. 12.5.5 interference factors (class values).
INTERFERENCE = {
    "nacelle_on_wing": 1.5, "nacelle_within_diameter": 1.3, "nacelle_clear": 1.0,
    "high_wing": 1.0, "conventional_tail": 1.05, "v_tail": 1.03, "h_tail": 1.08,
    "fuselage": 1.0, "boom": 1.0,
}


# --- transition and skin friction ----------------------------------------------------------------
@dataclass(frozen=True)
class Transition:
    """Where the boundary layer turns turbulent (configuration; see module doc).

    mode 'turbulent' | 'fixed' | 'free'; ``x_tr`` fixed location or, for 'free', the
    upper limit (pressure minimum); ``re_crit`` the free-transition Re_x.
    """
    mode: str = "turbulent"
    x_tr: float = 0.0
    re_crit: float = RE_CRIT_FLAT_PLATE

    def __post_init__(self):
        if self.mode not in ("turbulent", "fixed", "free"):
            raise InputError("transition.mode", f"'turbulent', 'fixed' or 'free', got {self.mode!r}")
        check_range("transition.x_tr", self.x_tr, 0.0, 1.0)
        check_positive("transition.re_crit", self.re_crit)

    @classmethod
    def turbulent(cls):
        return cls("turbulent", 0.0)

    @classmethod
    def fixed(cls, x_tr):
        return cls("fixed", x_tr)

    @classmethod
    def free(cls, x_max=0.4, re_crit=RE_CRIT_FLAT_PLATE):
        return cls("free", x_max, re_crit)

    def location(self, reynolds):
        """x_tr as a fraction of the reference length at Reynolds number ``reynolds``."""
        if self.mode == "turbulent":
            return 0.0
        if self.mode == "fixed":
            return self.x_tr
        return smooth_min(self.re_crit / _smooth_re(reynolds), self.x_tr, X_TR_WIDTH)


Transition.METAL_GA_SURFACE = Transition.fixed(0.10)
Transition.METAL_GA_BODY = Transition.turbulent()


def composite_skin_friction(reynolds, mach=0.0, transition=Transition.METAL_GA_BODY,
                            length_m=None, roughness_m=ROUGHNESS_M):
    """Eq. B2: flat-plate Cf with laminar run to ``transition.location(Re)`` (any array kind).

    With ``length_m`` the Reynolds number is capped at Raymer's roughness cut-off.
    """
    re = _smooth_re(reynolds)
    if length_m is not None:
        re_c = cutoff_reynolds(length_m, roughness_m)
        re = smooth_min(re, re_c, 0.05 * re_c)
    cf = skin_friction(re, mach, 0.0)
    if transition.mode == "turbulent":
        return cf
    x = transition.location(re)
    re_x = x * re
    return cf - x * (skin_friction(re_x, mach, 0.0) - skin_friction(re_x, mach, 1.0))


# --- components ---------------------------------------------------------------------------------
def surface_wetted_area(exposed_area_m2, thickness_to_chord):
    """Raymer Eq. 7.10: S_wet = S_exposed (1.977 + 0.52 t/c), m^2."""
    return exposed_area_m2 * (1.977 + 0.52 * thickness_to_chord)


def upsweep_drag_area(upsweep_rad, max_area_m2):
    """Raymer Eq. 12.36: fuselage upsweep drag area D/q = 3.83 u^2.5 A_max, m^2."""
    return 3.83 * upsweep_rad ** 2.5 * max_area_m2


@dataclass(frozen=True)
class SurfaceComponent:
    """A lifting surface: wing, tail, fin, strut.

    exposed_area_m2 (outside the fuselage, both sides), mac_m (Reynolds length), t/c,
    x_max_thickness (x/c of max thickness), sweep of the max-thickness line (rad),
    interference Q, transition, count, optional wetted_area_m2 (else Eq. 7.10),
    slipstream_fraction (default f_s, overridable per node in ``evaluate``).
    """
    name: str
    exposed_area_m2: float
    mac_m: float
    thickness_to_chord: float = 0.12
    x_max_thickness: float = 0.3
    sweep_max_thickness_rad: float = 0.0
    interference: float = 1.0
    transition: Transition = Transition.METAL_GA_SURFACE
    count: int = 1
    wetted_area_m2: float | None = None
    slipstream_fraction: float = 0.0

    def __post_init__(self):
        check_positive(f"{self.name}.exposed_area_m2", self.exposed_area_m2, "m^2")
        check_positive(f"{self.name}.mac_m", self.mac_m, "m")
        check_range(f"{self.name}.thickness_to_chord", self.thickness_to_chord, 0.01, 0.4)
        check_range(f"{self.name}.x_max_thickness", self.x_max_thickness, 0.1, 0.7)
        check_range(f"{self.name}.interference", self.interference, 0.8, 2.0)
        check_range(f"{self.name}.slipstream_fraction", self.slipstream_fraction, 0.0, 1.0)

    @property
    def length_m(self):
        return self.mac_m

    @classmethod
    def from_trapezoid(cls, name, span_m, area_m2, taper, thickness_to_chord=0.12,
                       sweep_quarter_chord_rad=0.0, x_max_thickness=0.3, body_width_m=0.0,
                       vertical=False, **kw):
        """A trapezoidal surface: span (full span; a fin's height), area (a fin: one side),
        taper; exposed area = area - root chord x ``body_width_m`` (the body-covered strip);
        MAC and the sweep of the max-thickness line from the planform."""
        c_root = 2 * area_m2 / (span_m * (1 + taper))
        mac = 2 / 3 * c_root * (1 + taper + taper * taper) / (1 + taper)
        ar = 2 * span_m ** 2 / area_m2 if vertical else span_m ** 2 / area_m2   # a fin is half a wing
        tan_m = math.tan(sweep_quarter_chord_rad) - 4 / ar * (x_max_thickness - 0.25) * (1 - taper) / (1 + taper)
        return cls(name, area_m2 - c_root * body_width_m, mac, thickness_to_chord, x_max_thickness,
                   math.atan(tan_m), **kw)


    def s_wet(self):
        return self.wetted_area_m2 if self.wetted_area_m2 is not None else \
            surface_wetted_area(self.exposed_area_m2, self.thickness_to_chord)

    def form_factor(self, mach):
        return form_factor_wing(self.thickness_to_chord, self.x_max_thickness, mach,
                                self.sweep_max_thickness_rad)

    def fixed_drag_area_m2(self):
        return 0.0


@dataclass(frozen=True)
class BodyComponent:
    """A body: kind 'fuselage' (Raymer FF 12.31, Torenbeek S_wet) or 'nacelle' / 'boom'
    (FF 12.32, cylinder S_wet); diameter_m the equivalent diameter; optional upsweep."""
    name: str
    length_m: float
    diameter_m: float
    kind: str = "fuselage"
    interference: float = 1.0
    transition: Transition = Transition.METAL_GA_BODY
    count: int = 1
    wetted_area_m2: float | None = None
    slipstream_fraction: float = 0.0
    upsweep_rad: float = 0.0

    def __post_init__(self):
        check_positive(f"{self.name}.length_m", self.length_m, "m")
        check_positive(f"{self.name}.diameter_m", self.diameter_m, "m")
        if self.kind not in ("fuselage", "nacelle", "boom"):
            raise InputError(f"{self.name}.kind", f"'fuselage', 'nacelle' or 'boom', got {self.kind!r}")
        if self.kind == "fuselage" and self.length_m / self.diameter_m <= 2:
            raise InputError(f"{self.name}.length_m", "fuselage fineness l/d must exceed 2")
        check_range(f"{self.name}.interference", self.interference, 0.8, 2.0)
        check_range(f"{self.name}.slipstream_fraction", self.slipstream_fraction, 0.0, 1.0)
        check_range(f"{self.name}.upsweep_rad", self.upsweep_rad, 0.0, 0.5)

    def s_wet(self):
        return self.wetted_area_m2 if self.wetted_area_m2 is not None else \
            body_wetted_area(self.length_m, self.diameter_m, self.kind)

    def form_factor(self, mach):
        f = self.length_m / self.diameter_m
        return form_factor_body(f) if self.kind == "fuselage" else form_factor_nacelle(f)

    def fixed_drag_area_m2(self):
        return upsweep_drag_area(self.upsweep_rad, math.pi * self.diameter_m ** 2 / 4)


@dataclass(frozen=True)
class CoolingDrag:
    """Eq. B3: cooling-air temperature rise ``delta_T_K`` and momentum-loss fraction ``zeta``."""
    delta_T_K: float = 30.0
    zeta: float = 0.5

    def __post_init__(self):
        check_range("cooling.delta_T_K", self.delta_T_K, 5.0, 200.0, "K")
        check_range("cooling.zeta", self.zeta, 0.0, 1.0)

    def drag_N(self, V_mps, heat_loss_W):
        return self.zeta * V_mps * heat_loss_W / (CP_AIR * self.delta_T_K)


# --- the build-up -------------------------------------------------------------------------------
@dataclass(frozen=True)
class DragBuildup:
    """All parasite drag of an airframe on reference area ``s_ref_m2`` (see module doc)."""
    s_ref_m2: float
    components: tuple = ()
    excrescence_fraction: float = EXCRESCENCE_METAL_GA
    cooling: CoolingDrag = field(default_factory=CoolingDrag)
    roughness_m: float = ROUGHNESS_M

    def __post_init__(self):
        check_positive("s_ref_m2", self.s_ref_m2, "m^2")
        check_range("excrescence_fraction", self.excrescence_fraction, 0.0, 0.5)
        names = [c.name for c in self.components]
        if len(set(names)) != len(names):
            raise InputError("components", f"names must be unique, got {names}")

    def component_drag_area_m2(self, comp, V_mps, rho, mu, mach=0.0, f_s=None, r=1.0):
        """Eq. B1 divided by the freestream q: the component's drag area D/q, m^2."""
        f_s = comp.slipstream_fraction if f_s is None else f_s
        re = rho * V_mps * comp.length_m / mu
        cf0 = composite_skin_friction(re, mach, comp.transition, comp.length_m, self.roughness_m)
        if isinstance(f_s, (int, float)) and f_s == 0:
            scrub = cf0                      # nothing immersed: keep the expression graph small
        else:
            cf_s = composite_skin_friction(r * re, r * mach, comp.transition, comp.length_m, self.roughness_m)
            scrub = (1 - f_s) * cf0 + f_s * r * r * cf_s
        return comp.count * (comp.form_factor(mach) * comp.interference * comp.s_wet() * scrub
                             + comp.fixed_drag_area_m2())

    def evaluate(self, V_mps, rho, mu, mach=0.0, slipstream=None, heat_loss_W=0.0):
        """Every drag term at the nodes (any array kind, elementwise).

        slipstream: {component name: (f_s, r)} per-node overrides of the immersed fraction and
        the velocity ratio V_slip/V; heat_loss_W: heat the cooling air carries (all motors).
        Returns {"terms": {name: {"D_N", "dCD", "drag_area_m2"}}, "D_N", "CD0", "q_Pa",
        "drag_area_m2"} with terms for every component, "excrescence" and "cooling".
        """
        slipstream = slipstream or {}
        unknown = set(slipstream) - {c.name for c in self.components}
        if unknown:
            raise InputError("slipstream", f"unknown components {sorted(unknown)}")
        q = 0.5 * rho * V_mps * V_mps
        areas, parasite = {}, 0.0
        for c in self.components:
            f_s, r = slipstream.get(c.name, (None, 1.0))
            a = self.component_drag_area_m2(c, V_mps, rho, mu, mach, f_s, r)
            parasite = parasite + a
            areas[c.name] = a
        areas["excrescence"] = self.excrescence_fraction * parasite
        drag = {name: q * a for name, a in areas.items()}
        drag["cooling"] = self.cooling.drag_N(V_mps, heat_loss_W)
        areas["cooling"] = drag["cooling"] / _safe_q(q)
        total_N = q * (parasite + areas["excrescence"]) + drag["cooling"]
        total_area = parasite + areas["excrescence"] + areas["cooling"]
        out = {name: {"drag_area_m2": areas[name], "D_N": drag[name],
                      "dCD": areas[name] / self.s_ref_m2} for name in areas}
        return {"terms": out, "drag_area_m2": total_area, "D_N": total_N,
                "CD0": total_area / self.s_ref_m2, "q_Pa": q}


def _safe_q(q):
    """q with a floor of 1e-3 Pa (smooth): cooling drag area stays finite in hover, where its
    drag D = q * area -> zeta V P/(cp dT) -> 0 anyway."""
    return xp(q).sqrt(q * q + 1e-6)
