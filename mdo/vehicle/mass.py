"""Mass build-up that responds to the design variables.

Every term is a smooth closed form that accepts numbers or CasADi expressions, so
that span, taper, rotor radius and the take-off gross weight itself can be NLP
variables.  Structural terms depend on the design gross weight ``W_dg``; the
build-up is therefore an implicit equation ``TOGW = sum(terms(TOGW))``, solved by
fixed-point iteration in analysis (``solve_togw``) and posed as one residual in
the NLP (``togw_residual``).

Sources (statistical regressions; the units of the original correlations are
pounds, feet, square feet, lb/ft^2, horsepower and are converted here at the edges):

* Raymer, *Aircraft Design: A Conceptual Approach*, 6th ed., Sec. 15.3.3, general
  aviation weights (Eqs. 15.46-15.58): wing, horizontal and vertical tail,
  fuselage, main and nose landing gear, flight controls, avionics, electrical,
  furnishings.
* Johnson, *NDARC Theory Manual* (NASA TM 2017-219646?), motor weight for high
  torque electric motors: ``W_lb = 0.3928 Q_ftlb^0.8587`` (p. 213).
* Roskam, *Airplane Design* Part V (General Dynamics propeller method):
  ``W_lb = K_p N_p N_bl^0.391 (D_ft P_shp / (1000 N_p))^0.782``, K_p = 31.92.
* Battery: ``BatteryConfig.mass_kg`` = cells x 48 g (Panasonic 18650 NMC of the paper)
  x the packaging factor (1.42, X-57 module build-up) - the same number the
  electrical pack carries.
* Payload: 4 passengers x 200 lb (FAA AC 120-27F standard summer adult with
  personal items).

Electric-aircraft terms not covered by those references (nacelle structure,
power electronics, the tilt mechanism of a tilt wing) are simple specific-mass
assumptions listed in ``ASSUMPTIONS``; they are small and reported as separate
terms in ``results/<vehicle>/mass.md``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core import units as u
from ..core.errors import InputError
from .config import VehicleConfig, WingConfig, replace
from .wing_structure import G0, bending_material_kg, wing_box_breakdown

__all__ = ["ASSUMPTIONS", "MassDesign", "mass_terms", "total_mass", "solve_togw",
           "togw_residual", "mass_table_markdown"]

ASSUMPTIONS = {
    "nacelle_areal_mass_kgpm2": 3.0,      # composite cowl + frames per wetted m^2 (assumption)
    "esc_specific_power_Wpkg": 15000.0,   # motor controllers, kW/kg class of 2020 inverters (assumption)
    "tilt_mechanism_fraction": 0.08,      # of the tilting mass (wings + rotors + motors) (assumption)
    "wing_fuel_weight_lb": 1.0,           # Raymer's W_fw: no fuel in an electric wing (0 would zero the term)
}


@dataclass
class MassDesign:
    """The design quantities the build-up responds to (numbers or CasADi expressions).

    ``wing_span_m[name]``, ``wing_taper[name]`` per lifting surface (areas are held
    at their configured values, as in Eq. 7), ``rotor_radius_m[group]``,
    ``motor_rated_power_W[group]`` (the sized rating; default the configured one).
    """
    wing_span_m: dict
    wing_taper: dict
    rotor_radius_m: dict
    motor_rated_power_W: dict = None
    motor_rated_speed_radps: dict = None
    # with a WingStructure (VehicleConfig.wing_structure): each wing's 1 g design lift (N; default
    # its area's share of the weight) and the rotors' span positions (fractions of the semispan)
    wing_design_lift_N: dict = None
    rotor_span_eta: dict = None
    # each fin's area over its configured area (Aircraft(fin_sizing=True); aspect ratio held)
    fin_area_scale: dict = None

    @classmethod
    def baseline(cls, cfg: VehicleConfig) -> "MassDesign":
        return cls({w.name: w.span_m for w in cfg.wings}, {w.name: w.taper for w in cfg.wings},
                   {g.name: g.radius_m for g in cfg.rotor_groups})

    def rated_power_W(self, g):
        return (self.motor_rated_power_W or {}).get(g.name, g.motor.rated_power_W)

    def rated_speed_radps(self, g):
        return (self.motor_rated_speed_radps or {}).get(g.name, g.motor_rated_rpm * u.RPM)

    def design_lift_N(self, cfg, w, togw_kg):
        default = G0 * togw_kg * w.area_m2 / sum(x.area_m2 for x in cfg.lifting_wings)
        return (self.wing_design_lift_N or {}).get(w.name, default)

    def span_eta(self, g):
        eta = (self.rotor_span_eta or {}).get(g.name, g.span_eta)
        return [eta[i] for i in range(len(g.span_eta))]


def _q_cruise_psf(cfg: VehicleConfig) -> float:
    from ..core.atmosphere import density
    q = 0.5 * density(cfg.cruise_altitude_m) * cfg.cruise_speed_mps ** 2
    return q / (u.LBF / u.FT ** 2)


def _wing_lb(w: WingConfig, span_m, taper, nz_wdg_lb, q_psf):
    """Raymer Eq. 15.46 (GA wing)."""
    S_ft2 = w.area_m2 / u.FT ** 2
    AR = span_m ** 2 / w.area_m2
    cos_sw = np.cos(np.radians(w.sweep_quarter_chord_deg))
    return (0.036 * S_ft2 ** 0.758 * ASSUMPTIONS["wing_fuel_weight_lb"] ** 0.0035
            * (AR / cos_sw ** 2) ** 0.6 * q_psf ** 0.006 * taper ** 0.04
            * (100 * w.thickness_to_chord / cos_sw) ** -0.3 * nz_wdg_lb ** 0.49)


def _htail_lb(w: WingConfig, nz_wdg_lb, q_psf):
    """Raymer Eq. 15.47."""
    S = w.area_m2 / u.FT ** 2
    cos_sw = np.cos(np.radians(w.sweep_quarter_chord_deg))
    return (0.016 * nz_wdg_lb ** 0.414 * q_psf ** 0.168 * S ** 0.896
            * (100 * w.thickness_to_chord / cos_sw) ** -0.12
            * (w.aspect_ratio / cos_sw ** 2) ** 0.043 * w.taper ** -0.02)


def _vtail_lb(w: WingConfig, nz_wdg_lb, q_psf, t_tail=0.0):
    """Raymer Eq. 15.48 (the fin's ``span_m`` is its height, ``area_m2`` its area)."""
    S = w.area_m2 / u.FT ** 2
    cos_sw = np.cos(np.radians(w.sweep_quarter_chord_deg))
    AR = w.span_m ** 2 / w.area_m2
    return (0.073 * (1 + 0.2 * t_tail) * nz_wdg_lb ** 0.376 * q_psf ** 0.122 * S ** 0.873
            * (100 * w.thickness_to_chord / cos_sw) ** -0.49 * (AR / cos_sw ** 2) ** 0.357
            * w.taper ** 0.039)


def mass_terms(cfg: VehicleConfig, togw_kg, design: MassDesign | None = None) -> dict:
    """All mass terms [kg] for gross weight ``togw_kg`` (number or expression).

    Returns an ordered dict name -> mass; ``total_mass`` sums it.
    """
    d = design or MassDesign.baseline(cfg)
    mi = {"main_gear_length_in": 24.0, "nose_gear_length_in": 20.0, "uninstalled_avionics_lb": 40.0,
          "gear_load_factor": 4.5}
    mi.update(cfg.mass_inputs)
    W_lb = togw_kg / u.LB
    nz_w = cfg.ultimate_load_factor * W_lb
    q = _q_cruise_psf(cfg)
    rotors = _rotor_masses(cfg, d)
    # The calibration scales the regressions.  A wing with a WingStructure is already at the
    # calibrated level (its area-held part, ``_wing_secondary_kg``); its bending material is physics.
    f_cal = mi.get("airframe_calibration", 1.0)
    wings = {}
    for w in cfg.lifting_wings:
        span, taper = d.wing_span_m.get(w.name, w.span_m), d.wing_taper.get(w.name, w.taper)
        if cfg.wing_structure is None:
            wings[f"wing: {w.name}"] = f_cal * _wing_lb(w, span, taper, nz_w, q) * u.LB
        else:
            wings[f"wing: {w.name}"] = _wing_secondary_kg(cfg, w.name) + _wing_bending_kg(
                cfg, w, span, taper, d.design_lift_N(cfg, w, togw_kg), _relief_masses(cfg, d, w, span, rotors))
    terms = {}      # the regressions, before the calibration
    for w in cfg.horizontal_tails:
        terms[f"horizontal tail: {w.name}"] = _htail_lb(w, nz_w, q) * u.LB
    for w in cfg.fins:   # Eq. 15.48 goes as S^0.873 at a held aspect ratio
        s = (d.fin_area_scale or {}).get(w.name, 1.0)
        terms[f"vertical tail: {w.name}"] = _vtail_lb(w, nz_w, q) * s ** 0.873 * u.LB
    f = cfg.fuselage
    S_f = f.wetted_area_m2 / u.FT ** 2
    fineness = f.length_m / np.sqrt(f.width_m * f.height_m)
    terms["fuselage"] = (0.052 * S_f ** 1.086 * nz_w ** 0.177 * (f.tail_arm_m / u.FT) ** -0.051
                         * fineness ** -0.072 * q ** 0.241) * u.LB
    nl_w = mi["gear_load_factor"] * W_lb
    terms["main landing gear"] = 0.095 * nl_w ** 0.768 * (mi["main_gear_length_in"] / 12) ** 0.409 * u.LB
    terms["nose landing gear"] = 0.125 * nl_w ** 0.566 * (mi["nose_gear_length_in"] / 12) ** 0.845 * u.LB
    span_main = d.wing_span_m.get(cfg.main_wing.name, cfg.main_wing.span_m)
    terms["flight controls"] = (0.053 * (f.length_m / u.FT) ** 1.536 * (span_main / u.FT) ** 0.371
                                * (nz_w * 1e-4) ** 0.80) * u.LB
    w_av = 2.117 * mi["uninstalled_avionics_lb"] ** 0.933
    terms["avionics"] = w_av * u.LB
    terms["electrical"] = 12.57 * w_av ** 0.51 * u.LB
    terms["furnishings"] = (0.0582 * W_lb - 65.0) * u.LB
    tilting_mass = 0.0
    for g in cfg.rotor_groups:
        m_motor, m_prop, m_esc, m_nac = rotors[g.name]
        terms[f"motors: {g.name} ({g.count})"] = m_motor
        terms[f"propellers: {g.name} ({g.count})"] = m_prop
        terms[f"motor controllers: {g.name} ({g.count})"] = m_esc
        if g.nacelle_wetted_area_m2:
            terms[f"nacelles: {g.name} ({g.count})"] = m_nac
        if any(cfg.wing(wn).tilting for wn in g.wings):
            tilting_mass = tilting_mass + m_motor + m_prop
    if f_cal != 1.0:
        terms = {k: f_cal * v for k, v in terms.items()}
    terms = {**wings, **terms}
    if cfg.kind == "tilt_wing":   # a fraction of what tilts: the wings and the rotors' motors and propellers
        terms["tilt mechanism"] = ASSUMPTIONS["tilt_mechanism_fraction"] * (
            f_cal * tilting_mass + sum(wings.values()))
    b = cfg.battery
    terms[f"battery ({b.cells_series}s x {b.cells_parallel}p, packaged x {b.packaging_factor:g})"] = b.mass_kg
    terms[f"payload ({cfg.passengers} passengers)"] = cfg.passengers * cfg.passenger_mass_kg
    return terms


def _rotor_masses(cfg: VehicleConfig, d: MassDesign) -> dict:
    """Per group (all its rotors): motors (NDARC), propellers (Roskam), controllers, nacelles [kg]."""
    out = {}
    for g in cfg.rotor_groups:
        R = d.rotor_radius_m.get(g.name, g.radius_m)
        omega = d.rated_speed_radps(g)
        P_r = d.rated_power_W(g)
        # the motor is sized for its largest torque: the short-time rating at rated speed
        torque_ftlb = (g.motor.short_time_power_factor * P_r / omega) / (u.LBF * u.FT)
        m_motor = g.count * 0.3928 * torque_ftlb ** 0.8587 * u.LB
        D_ft = 2 * R / u.FT
        P_shp = g.motor.short_time_power_factor * P_r / u.HP
        m_prop = g.count * 31.92 * g.blades ** 0.391 * (D_ft * P_shp / 1000.0) ** 0.782 * u.LB
        m_esc = g.count * g.motor.short_time_power_factor * P_r / ASSUMPTIONS["esc_specific_power_Wpkg"]
        m_nac = g.count * (g.nacelle_wetted_area_m2 or 0.0) * ASSUMPTIONS["nacelle_areal_mass_kgpm2"]
        out[g.name] = (m_motor, m_prop, m_esc, m_nac)
    return out


def _relief_masses(cfg: VehicleConfig, d: MassDesign, w: WingConfig, span_m, rotors: dict) -> list:
    """(mass, y) of each rotor (motor, propeller, controller, nacelle) on one half of wing ``w``."""
    out = []
    for g in cfg.rotor_groups:
        if w.name not in g.wings:
            continue
        per_rotor = sum(rotors[g.name]) / g.count
        out += [(per_rotor, eta * span_m / 2) for eta in d.span_eta(g)]
    return out


def _wing_bending_kg(cfg, w: WingConfig, span_m, taper, design_lift_N, relief):
    return bending_material_kg(cfg.wing_structure, w.area_m2, span_m, taper, w.thickness_to_chord,
                               cfg.ultimate_load_factor, design_lift_N, relief)


_SECONDARY_CACHE: dict = {}


def _wing_secondary_kg(cfg: VehicleConfig, wing_name: str) -> float:
    """The wing mass that the bending material does not explain (skins beyond the caps' need,
    ribs, leading and trailing edges, controls; it follows the area, which the design holds):
    Raymer's Eq. 15.46 times the airframe calibration, less the bending material, both of the
    baseline design at the baseline gross weight.  The level is the calibrated regression's (the
    baseline wing is what it was); the response to span, taper, thickness and lift share is the
    bending physics' (``mdo.vehicle.wing_structure``), which no calibration scales."""
    key = (repr(cfg), wing_name)
    if key not in _SECONDARY_CACHE:
        raymer = replace(cfg, wing_structure=None)
        d0 = MassDesign.baseline(raymer)
        W0 = solve_togw(raymer, d0)
        w = cfg.wing(wing_name)
        nz_w = cfg.ultimate_load_factor * W0 / u.LB
        m_raymer = float(_wing_lb(w, w.span_m, w.taper, nz_w, _q_cruise_psf(cfg)) * u.LB)
        m_bend = float(_wing_bending_kg(cfg, w, w.span_m, w.taper, d0.design_lift_N(cfg, w, W0),
                                        _relief_masses(cfg, d0, w, w.span_m, _rotor_masses(cfg, d0))))
        m_level = cfg.mass_inputs.get("airframe_calibration", 1.0) * m_raymer
        if m_bend >= m_level:
            raise InputError(f"wing_structure ({wing_name})",
                             f"bending material {m_bend:.1f} kg at the baseline must stay below the "
                             f"(calibrated) Raymer wing {m_level:.1f} kg (a lighter construction, or the "
                             "regression alone)")
        _SECONDARY_CACHE[key] = m_level - m_bend
    return _SECONDARY_CACHE[key]


def total_mass(cfg: VehicleConfig, togw_kg, design: MassDesign | None = None):
    terms = mass_terms(cfg, togw_kg, design)
    total = 0.0
    for v in terms.values():
        total = total + v
    return total


def togw_residual(cfg: VehicleConfig, togw_kg, design: MassDesign | None = None):
    """``TOGW - sum(terms(TOGW))`` [kg]: zero at a consistent gross weight."""
    return togw_kg - total_mass(cfg, togw_kg, design)


def solve_togw(cfg: VehicleConfig, design: MassDesign | None = None, tol_kg: float = 1e-6) -> float:
    """Consistent gross weight by fixed-point iteration (contracts: d(sum)/dW ~ 0.2)."""
    W = cfg.togw_reference_kg or 1500.0
    for _ in range(200):
        W_new = float(total_mass(cfg, W, design))
        if abs(W_new - W) < tol_kg:
            return W_new
        W = W_new
    raise RuntimeError(f"{cfg.name}: gross weight iteration did not converge (last {W:.3f} kg)")


def mass_table_markdown(cfg: VehicleConfig, design: MassDesign | None = None) -> str:
    """The build-up as a markdown table, with the paper's TOGW for comparison."""
    W = solve_togw(cfg, design)
    terms = mass_terms(cfg, W, design)
    f_cal = cfg.mass_inputs.get("airframe_calibration", 1.0)
    raw_cfg = replace(cfg, mass_inputs={**cfg.mass_inputs, "airframe_calibration": 1.0})
    W_raw = solve_togw(raw_cfg, design)
    lines = [f"# {cfg.name}: mass build-up", "",
             "| term | mass (kg) | mass (lb) | fraction |", "|---|---:|---:|---:|"]
    for k, v in terms.items():
        v = float(v)
        lines.append(f"| {k} | {v:.1f} | {v / u.LB:.1f} | {v / W:.3f} |")
    lines.append(f"| **take-off gross weight** | **{W:.1f}** | **{W / u.LB:.1f}** | 1.000 |")
    if cfg.togw_reference_kg:
        ref = cfg.togw_reference_kg
        lines += ["", f"Paper (Table 1): {ref / u.LB:.0f} lb = {ref:.1f} kg; "
                  f"difference {100 * (W - ref) / ref:+.2f} %."]
    lines += ["", f"Airframe calibration factor {f_cal:g} multiplies every regression term (not the battery, "
              "the payload or the wings' bending material, which is physics: a calibrated wing keeps its "
              "baseline mass and responds to the design by its bending material alone). Without it the "
              f"regressions give TOGW = {W_raw:.1f} kg = {W_raw / u.LB:.0f} lb"
              + (f" ({100 * (W_raw - cfg.togw_reference_kg) / cfg.togw_reference_kg:+.1f} % from Table 1)."
                 if cfg.togw_reference_kg else ".")]
    lines += ["", "Sources: Raymer 6th ed. Sec. 15.3.3 (GA structure and systems), NDARC (motors), "
              "Roskam Part V (propellers), cell count x 48 g (battery), 4 x 200 lb (payload). "
              "Assumptions: " + ", ".join(f"{k} = {v}" for k, v in ASSUMPTIONS.items()) + ".",
              "Inputs specific to this vehicle: " + ", ".join(f"{k} = {v}" for k, v in cfg.mass_inputs.items())
              + "."]
    if cfg.wing_structure is not None:
        d = design or MassDesign.baseline(cfg)
        rotors = _rotor_masses(cfg, d)
        lines += ["", "Wings (``mdo.vehicle.wing_structure``): area-held part (Raymer Eq. 15.46 less the "
                  "bending material, both at the baseline) + bending material of the design, sized for "
                  f"n_ult = {cfg.ultimate_load_factor:g} times the wing's design lift:", "",
                  "| wing | AR | design lift (kN) | area-held part (kg) | bending material (kg) | of which for "
                  "stiffness (kg) | limit-load tip deflection of strength-sized caps |", "|---|---:|---:|---:|---:|---:|---:|"]
        ws = cfg.wing_structure
        for w in cfg.lifting_wings:
            span, taper = d.wing_span_m.get(w.name, w.span_m), d.wing_taper.get(w.name, w.taper)
            F = d.design_lift_N(cfg, w, W)
            box = wing_box_breakdown(ws, w.area_m2, span, taper, w.thickness_to_chord, cfg.ultimate_load_factor, F,
                                     _relief_masses(cfg, d, w, span, rotors))
            lines.append(f"| {w.name} | {float(span) ** 2 / w.area_m2:.1f} | {float(F) / 1e3:.2f} | "
                         f"{_wing_secondary_kg(cfg, w.name):.1f} | {float(box['total_kg']):.1f} | "
                         f"{float(box['caps_kg'] - box['strength_caps_kg']):.1f} | "
                         f"{100 * float(box['strength_tip_deflection_fraction']):.0f} % of the semispan |")
        f_max = ws.max_tip_deflection_fraction
        lines += ["", "Stiffness: the caps also hold the limit-load tip deflection to "
                  + ("(no limit)" if f_max is None else f"{100 * f_max:.0f} % of the semispan")
                  + " (S4 of mdo.vehicle.wing_structure); strength-sized caps deflecting more than that are "
                  "thickened where it pays most."]
    if cfg.notes:
        lines += ["", "Notes:"] + [f"- {n}" for n in cfg.notes]
    return "\n".join(lines) + "\n"
