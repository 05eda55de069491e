"""Validation: the drag build-up (``mdo.wing.buildup``) of the Tecnam P2006T against its
published performance.

Airframe: the P2006T wing and tails of ``mdo.vehicle.catalog._ga_airframe()`` (wing 14.76 m^2,
span 11.4 m, taper 0.7, t/c 0.12; stabilator 2.54 m^2; fin 2.258 m^2; fuselage 8.28 m x 42 in
x 62 in, 19.35 m^2 wetted) and the catalog's nacelles (2 m long, 42 in equivalent diameter,
4.5 m^2 wetted each, SUAVE's X-57 model).  Engines: 2 x Rotax 912 S3, 73.5 kW (5 min) /
69.0 kW continuous each (P2006T POH / EASA TCDS EASA.A.185, engine section); propellers MT
MTV-21, 1.78 m (same source).

Published performance used for the check (tolerance 10 %):

* Plane & Pilot, "New Light Twin From Italy", 20 Oct 2009 (planeandpilotmag.com pilot report):
  at 7000 ft "cruise with everything against the stops works out to 140 knots or a bit more";
  "1,000 fpm climb at gross" (gross 2,600 lb = 1180 kg) "cleaned up and accelerated to 90 knots".
  Full throttle at 7000 ft is 0.786 of sea-level power (Gagg-Farrar, sigma - (1-sigma)/7.55) of
  the 69 kW continuous rating, i.e. 74 % of 2 x 73.5 kW: this is the "75 % power" cruise.
* The figures quoted in issue 17 (Tecnam: ~145 KTAS at 75 % power, ROC ~1140 ft/min at MTOW
  1230 kg) - not found in a primary source; reported beside, not used as the pass/fail reference.
* The P2006T Aircraft Flight Manual, Section 5 (Performance), as transcribed (numbers only) in the
  public flight-planning repository github.com/AlexandreMoiteiro/briefings-next
  (``src/lib/performance/p2006t-navlog*.ts``, for a fleet including CS-EAQ, MTOW 1180 kg; not
  checked against a copy of the AFM): the cruise tables at 0 / 3000 / 6000 / 9000 ft (ISA
  column: power %, KTAS) and the Enroute Rate of Climb at Vy at 930 / 1080 / 1180 kg (temperature
  columns -25 / 0 / 25 deg C, interpolated to ISA).  The tables do not state the weight of the
  cruise tables (taken as 1180 kg) nor the power of the climb; the AFM's "power %" is read as a
  fraction of the 69 kW continuous rating (at sea level, 2250 rpm and 29.5 inHg, i.e. full throttle
  near the continuous rpm, the table gives 97 %: 67 kW of 69, whereas 97 % of the 73.5 kW take-off
  rating would exceed the continuous power at that rpm), the climb at full throttle and the
  continuous rating (Gagg-Farrar lapse).  Both readings' other choice is in the report.

Models, stated before comparing:

* Drag: the build-up with its metal-GA defaults - transition fixed at 10 % chord on wing and
  tails, turbulent bodies, Raymer interference (nacelles on the wing 1.5, tails 1.05), smooth
  paint roughness, 10 % leakage & protuberance; wing and nacelles inside the slipstream at the
  actuator-disk far-wake velocity ``r = sqrt(1 + T/(q A))``; immersed wing fraction = 2 slipstream
  diameters x the mean chord over the exposed area.
* Cooling drag of the piston engines: heat to the cooling air (coolant radiator + oil + finned
  cylinders) = 1.0 x shaft power (a spark-ignition engine rejects to its coolant and oil about
  as much heat as its brake power; Heywood, *Internal Combustion Engine Fundamentals*, 1988,
  sec. 12.1), Eq. B3 with dT = 30 K, zeta = 0.5.
* Induced drag: CL^2/(pi A e) with Raymer's Oswald factor for straight wings (Eq. 12.48):
  e = 1.78 (1 - 0.045 A^0.68) - 0.64.
* Propeller efficiency: eta = k_p eta_ideal(T) with the actuator-disk ideal efficiency and a
  profile/swirl factor k_p = 0.82, which gives eta = 0.80 in cruise (constant-speed GA
  propellers cruise at 0.80-0.85, Gudmundsson, *General Aviation Aircraft Design*, 2014,
  ch. 14) and the lower figure the higher disk loading of the climb implies.

Run: ``python problems/validation/p2006t_drag.py`` -> ``results/validation/p2006t_drag.md``.
"""
from __future__ import annotations

import csv
import dataclasses
import json
import math
import pathlib
import sys

import numpy as np
from scipy.optimize import brentq, minimize_scalar

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.core.atmosphere import density, dynamic_viscosity, speed_of_sound, temperature  # noqa: E402
from mdo.core import units as u                   # noqa: E402
from mdo.vehicle.catalog import P2006T_LEAKAGE_FRACTION, _ga_airframe  # noqa: E402
from mdo.wing.buildup import INTERFERENCE, BodyComponent, DragBuildup, SurfaceComponent  # noqa: E402

G = u.G0
PROP_DIAMETER_M = 1.78           # MT MTV-21-A-C-F/CF178-05 (POH)
N_ENGINES = 2
P_MAX_W = 73.5e3                 # Rotax 912 S3 take-off (5 min)
P_MCP_W = 69.0e3                 # max continuous
X_MAX_THICKNESS = {"main_wing": 0.35, "horizontal_tail": 0.30, "vertical_tail": 0.30}  # 63-series / 4-digit
K_PROFILE = 0.82
# one-at-a-time perturbations for the sensitivity table (1.0 / 0.0 = the stated model)
SENS = {"k_profile": 0.0, "e_factor": 1.0, "cd0_factor": 1.0}
HEAT_TO_AIR_PER_SHAFT_W = 1.0
RAYMER_CFE_LIGHT_TWIN = 0.0045   # Raymer Table 12.3
# Raymer's trend of the maximum lift-to-drag ratio with the wetted aspect ratio b^2/S_wet,
# (L/D)max = K_LD sqrt(b^2/S_wet) (Raymer, *Aircraft Design: A Conceptual Approach*, sec. 3.4,
# Fig. 3.6): K_LD = 11 for retractable-gear propeller aircraft (the P2006T), 9 for fixed gear
RAYMER_K_LD_RETRACTABLE_PROP = 11.0
RAYMER_K_LD_FIXED_GEAR_PROP = 9.0

# P2006T AFM Section 5 (module docstring): cruise tables at 2250 propeller rpm, ISA column,
# (altitude ft, power %, KTAS), one row per manifold pressure
AFM_CRUISE = (
    (0, 97, 145), (0, 83, 136), (0, 65, 124), (0, 56, 116), (0, 43, 103), (0, 37, 95),
    (3000, 85, 141), (3000, 81, 138), (3000, 68, 129), (3000, 54, 117), (3000, 45, 108),
    (6000, 76, 139), (6000, 65, 130), (6000, 54, 120), (6000, 44, 108),
    (9000, 69, 137), (9000, 62, 131), (9000, 50, 119),
)
AFM_CRUISE_MASS_KG = 1180.0
# Enroute Rate of Climb at Vy: mass kg -> (altitude ft, Vy KIAS, ft/min at -25 / 0 / 25 deg C)
AFM_CLIMB = {
    930.0: ((0, 82, (1873, 1649, 1449)), (4000, 79, (1533, 1317, 1124)),
            (8000, 75, (1196, 987, 800)), (12000, 71, (860, 659, 479))),
    1080.0: ((0, 83, (1560, 1360, 1182)), (4000, 80, (1257, 1064, 892)),
             (8000, 76, (956, 770, 604)), (12000, 72, (657, 478, 318))),
    1180.0: ((0, 84, (1392, 1205, 1038)), (4000, 81, (1108, 927, 766)),
             (8000, 77, (826, 651, 495)), (12000, 73, (545, 377, 227))),
}
AFM_CLIMB_TEMPS_C = (-25.0, 0.0, 25.0)


def build_p2006t(span_m=None, taper=None) -> DragBuildup:
    """The P2006T airframe's build-up; ``span_m`` / ``taper``: another main wing of the same
    area (the GA-2P optimum's, for the L/D trend)."""
    main, htail, vtail, fus = _ga_airframe()
    if span_m is not None or taper is not None:
        main = dataclasses.replace(main, span_m=span_m or main.span_m, taper=taper or main.taper)
    comps = []
    for w in (main, htail, vtail):
        # exposed: the wing minus the fuselage-width strip of root chord; tails taken whole
        # (the stabilator sits on a thin tail cone, the fin area is given above the fuselage)
        q_i = INTERFERENCE["high_wing"] if w.name == "main_wing" else INTERFERENCE["conventional_tail"]
        comps.append(SurfaceComponent.from_trapezoid(
            w.name, w.span_m, w.area_m2, w.taper, w.thickness_to_chord,
            math.radians(w.sweep_quarter_chord_deg), X_MAX_THICKNESS[w.name],
            fus.width_m if w.name == "main_wing" else 0.0, w.vertical, interference=q_i))
    d_eq = math.sqrt(fus.width_m * fus.height_m)
    comps.append(BodyComponent("fuselage", fus.length_m, d_eq, "fuselage", INTERFERENCE["fuselage"],
                               wetted_area_m2=fus.wetted_area_m2))
    comps.append(BodyComponent("nacelles", 2.0, 42 * u.INCH, "nacelle", INTERFERENCE["nacelle_on_wing"],
                               count=N_ENGINES, wetted_area_m2=4.5, slipstream_fraction=1.0))
    return DragBuildup(main.area_m2, tuple(comps))


def oswald_raymer(aspect_ratio):
    """Raymer Eq. 12.48, straight wing."""
    return 1.78 * (1 - 0.045 * aspect_ratio ** 0.68) - 0.64


def prop_efficiency(thrust_N, V, rho):
    """k_p x actuator-disk ideal efficiency per propeller (thrust per propeller)."""
    area = math.pi * PROP_DIAMETER_M ** 2 / 4
    tc = thrust_N / (rho * V * V * area)
    a = 0.5 * (-1 + math.sqrt(1 + 2 * tc))
    return (K_PROFILE + SENS["k_profile"]) / (1 + a), math.sqrt(1 + thrust_N / (0.5 * rho * V * V * area))


def _wing_slipstream_fraction(bu):
    wing = next(c for c in bu.components if c.name == "main_wing")
    return min(1.0, N_ENGINES * PROP_DIAMETER_M * wing.mac_m / wing.exposed_area_m2)


def operating_point(bu, V, altitude_m, mass_kg, shaft_power_W):
    """Drag, thrust power and the terms at speed V with the total shaft power given."""
    rho, mu = float(density(altitude_m)), float(dynamic_viscosity(altitude_m))
    mach = V / float(speed_of_sound(altitude_m))
    main = _ga_airframe()[0]
    ar = main.span_m ** 2 / main.area_m2
    e = SENS["e_factor"] * oswald_raymer(ar)
    q = 0.5 * rho * V * V
    cl = mass_kg * G / (q * bu.s_ref_m2)
    cdi = cl * cl / (math.pi * ar * e)
    thrust_guess = shaft_power_W * 0.8 / V
    for _ in range(30):                      # thrust <-> slipstream <-> efficiency fixed point
        eta, r = prop_efficiency(thrust_guess / N_ENGINES, V, rho)
        f_w = _wing_slipstream_fraction(bu)
        out = bu.evaluate(V, rho, mu, mach, slipstream={"main_wing": (f_w, r), "nacelles": (1.0, r)},
                          heat_loss_W=HEAT_TO_AIR_PER_SHAFT_W * shaft_power_W)
        thrust = eta * shaft_power_W / V
        if abs(thrust - thrust_guess) < 1e-6 * thrust:
            break
        thrust_guess = thrust
    drag = SENS["cd0_factor"] * float(out["D_N"]) + q * bu.s_ref_m2 * cdi
    return {"V": V, "rho": rho, "CL": cl, "CDi": cdi, "e": e, "CD0": SENS["cd0_factor"] * float(out["CD0"]),
            "CD": drag / (q * bu.s_ref_m2), "drag_N": drag, "thrust_N": thrust, "eta_p": eta,
            "r_slip": r, "f_wing": f_w, "terms": out["terms"], "q": q,
            "excess_power_W": eta * shaft_power_W - drag * V}


def cruise_speed(bu, altitude_m, mass_kg, shaft_power_W):
    f = lambda V: operating_point(bu, V, altitude_m, mass_kg, shaft_power_W)["excess_power_W"]
    V = brentq(f, 40.0, 120.0, xtol=1e-6)
    return operating_point(bu, V, altitude_m, mass_kg, shaft_power_W)


def density_ratio(altitude_m):
    """sigma = rho(h) / rho(0), ISA."""
    return float(density(altitude_m) / density(0.0))


def climb_rate_fpm(op, altitude_m, mass_kg):
    """Rate of climb at constant equivalent (indicated) airspeed, as flight manuals state it:
    the specific excess power d(h + V^2/2g)/dt = P_ex/W (the energy-height relation; Anderson,
    *Aircraft Performance and Design*, 1999, ch. 6) with V = V_e/sqrt(sigma) growing as the air
    thins, dV/dh = -(V/2sigma) dsigma/dh: dh/dt = (P_ex/W) / (1 + (V/g) dV/dh)."""
    V, dh = op["V"], 10.0
    dsigma_dh = (density_ratio(altitude_m + dh) - density_ratio(altitude_m - dh)) / (2 * dh)
    sigma = density_ratio(altitude_m)
    accel = 1.0 - V * V / (2 * G * sigma) * dsigma_dh
    return op["excess_power_W"] / (mass_kg * G) / accel / u.FT_PER_MIN


def best_climb(bu, altitude_m, mass_kg, shaft_power_W):
    def rate(V):
        return climb_rate_fpm(operating_point(bu, V, altitude_m, mass_kg, shaft_power_W), altitude_m, mass_kg)
    V = minimize_scalar(lambda V: -rate(V), bounds=(30.0, 70.0), method="bounded", options={"xatol": 1e-4}).x
    return climb_at(bu, V, altitude_m, mass_kg, shaft_power_W)


def climb_at(bu, V, altitude_m, mass_kg, shaft_power_W):
    op = operating_point(bu, V, altitude_m, mass_kg, shaft_power_W)
    op["roc_fpm"] = climb_rate_fpm(op, altitude_m, mass_kg)
    return op


def gagg_farrar(altitude_m):
    sigma = density_ratio(altitude_m)
    return sigma - (1 - sigma) / 7.55


def afm_cruise_checks(bu, power_basis_W=P_MCP_W):
    """Model cruise speed at each AFM cruise-table point's power (per engine: % x
    ``power_basis_W``): rows (altitude ft, power %, AFM KTAS, model KTAS, error, eta_p, CD0 that
    makes the AFM speed with the model's eta_p and e)."""
    rows = []
    for h_ft, pct, ktas in AFM_CRUISE:
        p = N_ENGINES * pct / 100 * power_basis_W
        op = cruise_speed(bu, h_ft * u.FT, AFM_CRUISE_MASS_KG, p)
        at_afm = operating_point(bu, ktas * u.KNOT, h_ft * u.FT, AFM_CRUISE_MASS_KG, p)
        cd0_afm = at_afm["CD0"] + at_afm["excess_power_W"] / (ktas * u.KNOT * at_afm["q"] * bu.s_ref_m2)
        rows.append((h_ft, pct, ktas, op["V"] / u.KNOT, op["V"] / u.KNOT / ktas - 1, op["eta_p"], op["CD0"], cd0_afm))
    return rows


def afm_climb_checks(bu, power_W=P_MCP_W):
    """Model rate of climb (full throttle at ``power_W`` per engine, Gagg-Farrar lapse) at
    each AFM climb-table point, flown at the table's Vy (KIAS read as EAS: 70-85 kt at
    most 12 000 ft): rows (mass, altitude ft, AFM Vy KIAS, AFM ft/min at ISA, model ft/min at
    that Vy, error, model best ft/min, model Vy KIAS)."""
    rows = []
    for mass, table in AFM_CLIMB.items():
        for h_ft, vy, rates in table:
            h = h_ft * u.FT
            sqrt_sigma = math.sqrt(density_ratio(h))
            afm = float(np.interp(float(temperature(h)) - 273.15, AFM_CLIMB_TEMPS_C, rates))
            power = N_ENGINES * power_W * gagg_farrar(h)
            at_vy = climb_at(bu, vy * u.KNOT / sqrt_sigma, h, mass, power)
            best = best_climb(bu, h, mass, power)
            rows.append((mass, h_ft, vy, afm, at_vy["roc_fpm"], at_vy["roc_fpm"] / afm - 1,
                         best["roc_fpm"], best["V"] / u.KNOT * sqrt_sigma))
    return rows


def total_wetted_area(bu):
    s = 0.0
    for c in bu.components:
        s += c.count * c.s_wet()
    return s


def wetted_aspect_ratio(bu, span_m):
    """b^2 / S_wet with the build-up's wetted area."""
    return span_m ** 2 / total_wetted_area(bu)


def raymer_ld_max(bu, span_m, k_ld=RAYMER_K_LD_RETRACTABLE_PROP):
    """Raymer's class trend (L/D)max = K_LD sqrt(b^2 / S_wet) for the build-up's wetted area."""
    return k_ld * math.sqrt(wetted_aspect_ratio(bu, span_m))


def model_ld_max(op, span_m, s_ref_m2):
    """(L/D)max = 0.5 sqrt(pi A e / CD0) of an operating point's polar (CD0 held at its value there)."""
    return 0.5 * math.sqrt(math.pi * span_m ** 2 / s_ref_m2 * op["e"] / op["CD0"])


def mission_cruise_polar(run_dir, s_ref_m2):
    """The mean cruise (CR) node of a committed run folder: CL, CD, L/D and the parabolic polar
    through it (CD0 = CD - CDi, e from the lattice's CDi and the wing's span), or None."""
    path = pathlib.Path(run_dir)
    if not (path / "mission.csv").exists():
        return None
    rows = [r for r in csv.DictReader((path / "mission.csv").open()) if r["segment"] == "CR"]
    span = json.loads((path / "design.json").read_text())["wings"]["main_wing"]["span_m"]
    mean = lambda k: sum(float(r[k]) for r in rows) / len(rows)
    cl, cd, cdi = mean("CL"), mean("CD"), mean("CDi")
    e = cl * cl / (math.pi * span ** 2 / s_ref_m2 * cdi)
    return {"span_m": span, "CL": cl, "CD": cd, "L/D": cl / cd, "e": e, "CD0": cd - cdi,
            "ld_max": model_ld_max({"e": e, "CD0": cd - cdi}, span, s_ref_m2)}


def ld_against_class(bu, res):
    """Rows (label, span m, S_wet/S_ref, b^2/S_wet, Raymer (L/D)max at K_LD 11 and 9, the model's (L/D)max,
    its Oswald e, the model's L/D at its cruise point): the P2006T build-up as stated and calibrated, and the
    GA-2P baseline and optimum of the committed run folders (their wing on this airframe)."""
    main = _ga_airframe()[0]
    cal = calibrated_p2006t(bu)
    c_cal = cruise_speed(cal, 7000 * u.FT, 1180.0, res["p_full_7000"])
    rows = []
    for label, op, b in (("P2006T build-up, 7000 ft full throttle (stated 10 % leakage)", res["cruise_pp"], bu),
                         ("the same with the catalog's calibration", c_cal, cal)):
        rows.append((label, main.span_m, total_wetted_area(b) / b.s_ref_m2, wetted_aspect_ratio(b, main.span_m),
                     raymer_ld_max(b, main.span_m),
                     raymer_ld_max(b, main.span_m, RAYMER_K_LD_FIXED_GEAR_PROP),
                     model_ld_max(op, main.span_m, b.s_ref_m2), op["e"], op["CL"] / op["CD"]))
    for label, run_dir in (("GA-2P baseline, cruise (mission nodes)", ROOT / "results/ga2p/analysis"),
                           ("GA-2P optimum, cruise (mission nodes)", ROOT / "results/ga2p")):
        m = mission_cruise_polar(run_dir, bu.s_ref_m2)
        if m is None:
            continue
        taper = json.loads((run_dir / "design.json").read_text())["wings"]["main_wing"]["taper"]
        b = build_p2006t(m["span_m"], taper)
        rows.append((label, m["span_m"], total_wetted_area(b) / b.s_ref_m2, wetted_aspect_ratio(b, m["span_m"]),
                     raymer_ld_max(b, m["span_m"]),
                     raymer_ld_max(b, m["span_m"], RAYMER_K_LD_FIXED_GEAR_PROP), m["ld_max"], m["e"], m["L/D"]))
    return rows


def run():
    bu = build_p2006t()
    h7 = 7000 * u.FT
    p_full_7000 = N_ENGINES * P_MCP_W * gagg_farrar(h7)
    res = {
        "cruise_pp": cruise_speed(bu, h7, 1180.0, p_full_7000),
        "cruise_75_7000": cruise_speed(bu, h7, 1230.0, 0.75 * N_ENGINES * P_MAX_W),
        "cruise_75_9000": cruise_speed(bu, 9000 * u.FT, 1230.0, 0.75 * N_ENGINES * P_MAX_W),
        "climb_90kt_1180": climb_at(bu, 90 * u.KNOT, 0.0, 1180.0, N_ENGINES * P_MAX_W),
        "climb_best_1180": best_climb(bu, 0.0, 1180.0, N_ENGINES * P_MAX_W),
        "climb_best_1230": best_climb(bu, 0.0, 1230.0, N_ENGINES * P_MAX_W),
        "climb_mcp_1180": climb_at(bu, 90 * u.KNOT, 0.0, 1180.0, N_ENGINES * P_MCP_W),
    }
    s_wet = total_wetted_area(bu)
    res["raymer_cfe_CD0"] = RAYMER_CFE_LIGHT_TWIN * s_wet / bu.s_ref_m2
    res["s_wet"] = s_wet
    res["p_full_7000"] = p_full_7000
    res["sensitivity"] = sensitivity(bu)
    res["afm_cruise"] = afm_cruise_checks(bu, P_MCP_W)
    res["afm_cruise_to"] = afm_cruise_checks(bu, P_MAX_W)
    res["afm_climb"] = afm_climb_checks(bu, P_MCP_W)
    res["afm_climb_to"] = afm_climb_checks(bu, P_MAX_W)
    res["afm_leakage"] = afm_leakage_fraction(bu)
    cal = calibrated_p2006t(bu)
    res["afm_cruise_cal"] = afm_cruise_checks(cal, P_MCP_W)
    res["afm_climb_leak"] = afm_climb_checks(cal, P_MCP_W)
    res["climb_90kt_cal"] = {p: climb_at(cal, 90 * u.KNOT, 0.0, 1180.0, N_ENGINES * p) for p in (P_MAX_W, P_MCP_W)}
    res["ld_class"] = ld_against_class(bu, res)
    return bu, res


def with_leakage(bu, fraction):
    """The same build-up with another leakage & protuberance allowance."""
    return DragBuildup(bu.s_ref_m2, bu.components, excrescence_fraction=fraction, cooling=bu.cooling)


def calibrated_p2006t(bu):
    """The build-up with the catalog's P2006T calibration (``mdo.vehicle.catalog.P2006T_LEAKAGE_FRACTION``,
    the allowance GA-2P and GA-8P fly with) instead of Raymer's 10 %."""
    return with_leakage(bu, P2006T_LEAKAGE_FRACTION)


def afm_leakage_fraction(bu):
    """The leakage & protuberance fraction at which the mean AFM cruise-speed error is zero
    (everything else as stated): the allowance the flight manual implies, for what-if runs
    (``-o leakage_fraction=``)."""
    def mean_err(x):
        return sum(r[4] for r in afm_cruise_checks(with_leakage(bu, x))) / len(AFM_CRUISE)
    return brentq(mean_err, bu.excrescence_fraction, 0.5, xtol=1e-4)


def sensitivity(bu):
    """Cruise speed (P&P case) and 90-KIAS climb rate with each assumption moved alone."""
    h7 = 7000 * u.FT
    p7 = N_ENGINES * P_MCP_W * gagg_farrar(h7)
    cases = [("stated model", {}), ("CD0 x 1.10", {"cd0_factor": 1.10}), ("CD0 x 0.90", {"cd0_factor": 0.90}),
             ("eta_p - 0.05 (k_p 0.77)", {"k_profile": -0.05}), ("e x 0.9", {"e_factor": 0.9})]
    rows = []
    for label, change in cases:
        saved = dict(SENS)
        SENS.update(change)
        try:
            c = cruise_speed(bu, h7, 1180.0, p7)
            cl = climb_at(bu, 90 * u.KNOT, 0.0, 1180.0, N_ENGINES * P_MAX_W)
        finally:
            SENS.clear()
            SENS.update(saved)
        rows.append((label, c["V"] / u.KNOT, cl["roc_fpm"]))
    leak = with_leakage(bu, 0.05)
    rows.append(("leakage 5 % instead of 10 %", cruise_speed(leak, h7, 1180.0, p7)["V"] / u.KNOT,
                 climb_at(leak, 90 * u.KNOT, 0.0, 1180.0, N_ENGINES * P_MAX_W)["roc_fpm"]))
    return rows


def _terms_table(op, s_ref):
    lines = ["| term | D (N) | ΔCD (on S_ref) | share |", "|---|---:|---:|---:|"]
    tot = sum(float(t["D_N"]) for t in op["terms"].values()) + op["q"] * s_ref * op["CDi"]
    for name, t in op["terms"].items():
        lines.append(f"| {name} | {float(t['D_N']):.1f} | {float(t['dCD']):.5f} | {float(t['D_N']) / tot:.1%} |")
    lines.append(f"| induced (e = {op['e']:.3f}) | {op['q'] * s_ref * op['CDi']:.1f} | {op['CDi']:.5f} | "
                 f"{op['q'] * s_ref * op['CDi'] / tot:.1%} |")
    lines.append(f"| **total** | **{tot:.1f}** | **{op['CD']:.5f}** | |")
    return "\n".join(lines)


def _pct(model, ref):
    return f"{(model / ref - 1) * 100:+.1f} %"


def write_report(bu, res, path):
    c, c7, c9 = res["cruise_pp"], res["cruise_75_7000"], res["cruise_75_9000"]
    cl90, clb, clb2, clm = res["climb_90kt_1180"], res["climb_best_1180"], res["climb_best_1230"], res["climb_mcp_1180"]
    cal90 = res["climb_90kt_cal"]
    comp = "\n".join(f"| {x.name} | {x.count} | {x.count * x.s_wet():.2f} | {x.form_factor(c['V'] / 330):.3f} | "
                     f"{x.interference:.2f} | {x.transition.mode} {x.transition.x_tr:.2f} | {x.slipstream_fraction:.2f} |"
                     for x in bu.components)
    sens = "\n".join(f"| {a} | {b:.1f} | {c_:.0f} |" for a, b, c_ in res["sensitivity"])
    kt = lambda op: op["V"] / u.KNOT
    ok = lambda m, r: "PASS" if abs(m / r - 1) <= 0.10 else "MISS"
    text = f"""# P2006T drag build-up vs published performance

Generated by `python problems/validation/p2006t_drag.py` (models and sources in its docstring
and in `mdo/wing/buildup.py`).  Tolerance: 10 %.

## Components

| component | count | S_wet total (m²) | FF | Q | transition x_tr/c | default f_slip (wing: per node, below) |
|---|---:|---:|---:|---:|---|---:|
{comp}

Total wetted area {res['s_wet']:.2f} m², S_wet/S_ref = {res['s_wet'] / bu.s_ref_m2:.2f};
leakage & protuberances {bu.excrescence_fraction:.0%} of the component parasite drag (Raymer 12.5.9);
cooling: heat to air = {HEAT_TO_AIR_PER_SHAFT_W:.1f} × shaft power, ΔT = {bu.cooling.delta_T_K:.0f} K, ζ = {bu.cooling.zeta:.2f}.

## Cruise, 7000 ft ISA, 1180 kg, full throttle ({res['p_full_7000'] / 1e3:.1f} kW = {res['p_full_7000'] / (2 * P_MAX_W):.1%} of 2 × 73.5 kW)

V = {kt(c):.1f} KTAS, CL = {c['CL']:.3f}, η_p = {c['eta_p']:.3f}, slipstream r = {c['r_slip']:.3f} (wing fraction {c['f_wing']:.2f}),
Re(wing MAC) = {c['rho'] * c['V'] * bu.components[0].mac_m / float(dynamic_viscosity(7000 * u.FT)):.3g}.

{_terms_table(c, bu.s_ref_m2)}

CD0 = {c['CD0']:.4f}, L/D = {c['CL'] / c['CD']:.1f} at this speed; (L/D)max = 0.5 sqrt(pi A e / CD0) = {0.5 * math.sqrt(math.pi * 8.804 * c['e'] / c['CD0']):.1f}.

## Checks

| quantity | model | published | error | check |
|---|---:|---:|---:|---|
| cruise speed, 7000 ft full throttle (≈74 %), 1180 kg | {kt(c):.1f} KTAS | 140 KTAS "or a bit more" (Plane & Pilot 2009) | {_pct(kt(c), 140)} | {ok(kt(c), 140)} |
| climb rate, SL, 90 KIAS, 1180 kg, 2 × 73.5 kW | {cl90['roc_fpm']:.0f} ft/min | 1000 ft/min at gross (Plane & Pilot 2009) | {_pct(cl90['roc_fpm'], 1000)} | {ok(cl90['roc_fpm'], 1000)} |
| climb rate, SL, 90 KIAS, 1180 kg, 2 × 69 kW (MCP) | {clm['roc_fpm']:.0f} ft/min | 1000 ft/min | {_pct(clm['roc_fpm'], 1000)} | {ok(clm['roc_fpm'], 1000)} |
| cruise 75 % (110 kW), 7000 ft, 1230 kg | {kt(c7):.1f} KTAS | ~145 KTAS (issue 17, unverified) | {_pct(kt(c7), 145)} | {ok(kt(c7), 145)} |
| cruise 75 % (110 kW), 9000 ft, 1230 kg | {kt(c9):.1f} KTAS | ~145 KTAS (issue 17, unverified) | {_pct(kt(c9), 145)} | {ok(kt(c9), 145)} |
| best climb rate, SL, 1230 kg, 2 × 73.5 kW | {clb2['roc_fpm']:.0f} ft/min at {kt(clb2):.0f} KTAS | ~1140 ft/min (issue 17, unverified) | {_pct(clb2['roc_fpm'], 1140)} | {ok(clb2['roc_fpm'], 1140)} |
| best climb rate, SL, 1180 kg, 2 × 73.5 kW | {clb['roc_fpm']:.0f} ft/min at {kt(clb):.0f} KTAS | — | | |
| climb rate, SL, 90 KIAS, 1180 kg, 2 × 73.5 kW, with the calibration below | {cal90[P_MAX_W]['roc_fpm']:.0f} ft/min | 1000 ft/min | {_pct(cal90[P_MAX_W]['roc_fpm'], 1000)} | {ok(cal90[P_MAX_W]['roc_fpm'], 1000)} |
| the same at 2 × 69 kW (MCP) | {cal90[P_MCP_W]['roc_fpm']:.0f} ft/min | 1000 ft/min | {_pct(cal90[P_MCP_W]['roc_fpm'], 1000)} | {ok(cal90[P_MCP_W]['roc_fpm'], 1000)} |

Climb at 90 KIAS: η_p = {cl90['eta_p']:.3f}, slipstream r = {cl90['r_slip']:.3f}, CL = {cl90['CL']:.3f}, CD0 = {cl90['CD0']:.4f}
(cooling {float(cl90['terms']['cooling']['dCD']):.4f}), L/D = {cl90['CL'] / cl90['CD']:.1f}.

{_afm_section(res)}

## Sensitivity (one assumption at a time)

| change | cruise, 7000 ft (KTAS; published 140+) | climb, SL 90 KIAS 2 × 73.5 kW (ft/min; published 1000) |
|---|---:|---:|
{sens}

## CD0 against class methods

| method | CD0 |
|---|---:|
| this build-up, cruise 7000 ft | {c['CD0']:.4f} |
| this build-up without cooling drag | {c['CD0'] - float(c['terms']['cooling']['dCD']):.4f} |
| Raymer equivalent skin friction, Cfe = 0.0045 (light twin, Table 12.3) × S_wet/S_ref | {res['raymer_cfe_CD0']:.4f} |
| implied by 140 KTAS at 108.5 kW, η_p 0.80, this e (issue 17's estimate: 0.024–0.026) | {_implied_cd0(c):.4f} |
| implied by the AFM cruise tables (18 points, mean; section above) | {sum(r[7] for r in res['afm_cruise']) / len(res['afm_cruise']):.4f} |
| light piston twins, Roskam / Gudmundsson class range (as quoted in issue 17, not re-checked) | 0.020–0.035 |

{_ld_section(res)}

## Reading

The flight manual's tables are the reference now (section above): every cruise point passes at
+6 to +9 %, but by the same sign everywhere, so the build-up's CD0 is about a fifth low (the
pilot-report figures below say the same), and GA-2P and GA-8P fly with the calibration the tables give.  The cruise-speed check passes but is weak on drag: speed goes as CD0^(-1/3), so the CD0 that makes
exactly 140 KTAS with these e and η_p ({_implied_cd0(c):.4f}) is {(_implied_cd0(c) / c['CD0'] - 1) * 100:+.0f} % from the
build-up's {c['CD0']:.4f}.  The build-up sits {(c['CD0'] / res['raymer_cfe_CD0'] - 1) * 100:+.0f} % from Raymer's
equivalent-skin-friction estimate.  Not modelled as components (inside the leakage allowance only): the
main-gear sponsons, the partly open wheel wells, winglets, flap-track fairings, trim drag.  The climb
rate at 90 KIAS is the weaker check: it depends mostly on the climb propeller efficiency
(η_p = {cl90['eta_p']:.3f} from the stated model) and on the power actually delivered (take-off vs
continuous rating), see the sensitivity table.
"""
    pathlib.Path(path).parent.mkdir(parents=True, exist_ok=True)
    pathlib.Path(path).write_text(text)
    return text


def _stats(errs):
    return sum(errs) / len(errs), min(errs), max(errs)


def afm_summary(res):
    """{key: (mean, min, max) relative error} of the four AFM comparisons."""
    return {"cruise": _stats([r[4] for r in res["afm_cruise"]]),
            "cruise_to": _stats([r[4] for r in res["afm_cruise_to"]]),
            "climb": _stats([r[5] for r in res["afm_climb"]]),
            "climb_to": _stats([r[5] for r in res["afm_climb_to"]]),
            "cruise_cal": _stats([r[4] for r in res["afm_cruise_cal"]]),
            "climb_leak": _stats([r[5] for r in res["afm_climb_leak"]])}


def _afm_section(res):
    st = afm_summary(res)
    f = lambda t: f"mean {t[0]:+.1%}, {t[1]:+.1%} to {t[2]:+.1%}"
    ok = lambda t: "PASS" if max(abs(t[1]), abs(t[2])) <= 0.10 else "MISS"
    cru = "\n".join(f"| {h} | {pc} | {k} | {m:.1f} | {e:+.1%} | {eta:.3f} | {c0:.4f} | {c0a:.4f} |"
                     for h, pc, k, m, e, eta, c0, c0a in res["afm_cruise"])
    clb = "\n".join(f"| {ms:.0f} | {h} | {vy} | {a:.0f} | {m:.0f} | {e:+.1%} | {mb:.0f} | {vk:.0f} |"
                     for ms, h, vy, a, m, e, mb, vk in res["afm_climb"])
    cd0_afm = sum(r[7] for r in res["afm_cruise"]) / len(res["afm_cruise"])
    cd0_mod = sum(r[6] for r in res["afm_cruise"]) / len(res["afm_cruise"])
    return f"""## Against the flight manual's tables (P2006T AFM Section 5; source in the script's docstring)

| comparison | points | error | check (every point within 10 %) |
|---|---:|---|---|
| cruise speed, 2250 rpm rows, 0-9000 ft, {AFM_CRUISE_MASS_KG:.0f} kg, power % of 69 kW | {len(res['afm_cruise'])} | {f(st['cruise'])} | {ok(st['cruise'])} |
| the same, power % of 73.5 kW (the other reading) | {len(res['afm_cruise_to'])} | {f(st['cruise_to'])} | {ok(st['cruise_to'])} |
| rate of climb at the AFM's Vy, 930/1080/1180 kg, 0-12000 ft, full throttle at 69 kW | {len(res['afm_climb'])} | {f(st['climb'])} | {ok(st['climb'])} |
| the same at 73.5 kW | {len(res['afm_climb_to'])} | {f(st['climb_to'])} | {ok(st['climb_to'])} |
| cruise with the catalog's P2006T calibration (leakage {P2006T_LEAKAGE_FRACTION:.0%}, what GA-2P and GA-8P fly with) | {len(res['afm_cruise_cal'])} | {f(st['cruise_cal'])} | {ok(st['cruise_cal'])} |
| climb at 69 kW with that calibration | {len(res['afm_climb_leak'])} | {f(st['climb_leak'])} | {ok(st['climb_leak'])} |

The model is fast at every cruise point by a near-constant fraction: its drag is low, not its
shape.  The CD0 that makes each AFM speed with the model's own η_p and e averages
**{cd0_afm:.4f}** against the build-up's {cd0_mod:.4f} ({(cd0_afm / cd0_mod - 1) * 100:+.0f} %); the items
the build-up leaves to its leakage allowance (gear sponsons, wheel wells, winglets, flap tracks,
trim) are where that difference would sit: the leakage & protuberance allowance that makes the
mean cruise error zero is **{res['afm_leakage']:.1%}** of the component parasite drag (stated model 10 %).
Since 2026-12-06 (tenth session) the P2006T airframe of GA-2P and GA-8P flies with that calibration,
rounded: `mdo.vehicle.catalog.P2006T_LEAKAGE_FRACTION` = {P2006T_LEAKAGE_FRACTION:.2f} (rows above).  The climb's error is a near-constant 40-95 ft/min
of excess rate at every altitude (so its percentage grows as the climb rate falls): the same
drag deficit.  With the allowance the cruise implies, the climb falls to the last row of the
table: one drag correction accounts for both (what remains is largest at 12 000 ft).  The
climbs are flown at the AFM's Vy at constant indicated speed (the acceleration as the air
thins takes 1 % of the excess power; until 2026-12-06 the model's own best rate was compared,
without it: +0.4 % to +11.2 % with the calibration).  The AFM does not say whether it climbs at full
throttle (the model: Gagg-Farrar's lapse of the continuous rating).

Cruise (power % of 69 kW):

| ft | power % | AFM KTAS | model KTAS | error | η_p | CD0 build-up | CD0 for the AFM speed |
|---:|---:|---:|---:|---:|---:|---:|---:|
{cru}

Climb at Vy (ISA, full throttle at the 69 kW continuous rating; the model flies the AFM's Vy
at constant indicated speed, so part of the excess power accelerates it as the air thins,
`climb_rate_fpm`; beside, the model's own best rate and speed):

| kg | ft | AFM Vy KIAS | AFM ft/min | model ft/min at AFM Vy | error | model best ft/min | model Vy KIAS |
|---:|---:|---:|---:|---:|---:|---:|---:|
{clb}"""


def _ld_section(res):
    rows = "\n".join(f"| {lab} | {b:.2f} | {sw:.2f} | {aw:.2f} | {r11:.1f} | {r9:.1f} | {m:.1f} "
                     f"({m / r11 - 1:+.0%}) | {e:.3f} | {c:.1f} ({c / r11:.0%}) |"
                     for lab, b, sw, aw, r11, r9, m, e, c in res["ld_class"])
    return f"""## L/D against the class

Raymer's trend of (L/D)max with the wetted aspect ratio b²/S_wet (*Aircraft Design: A
Conceptual Approach*, sec. 3.4, Fig. 3.6): (L/D)max = K_LD sqrt(b²/S_wet), K_LD = {RAYMER_K_LD_RETRACTABLE_PROP:g} for
retractable-gear propeller aircraft like the P2006T ({RAYMER_K_LD_FIXED_GEAR_PROP:g} with fixed gear).  The wetted area is
this build-up's, with the run's own wing (same area) for GA-2P.  The model's (L/D)max is the
parabolic polar through its cruise point, 0.5 sqrt(pi A e / CD0): for the build-up with
Raymer's Oswald factor (Eq. 12.48, which carries the lift-dependent profile drag); for GA-2P
with CD0 = CD - CDi and e from the lattice's CDi at the mean cruise node (about 1: the
lattice's induced drag, the slipstream's swirl included), which leaves the lift-dependent profile drag in CD0, so its (L/D)max is an upper bound.  A
propeller aircraft's best range is flown at (L/D)max (Raymer sec. 3.4); the missions cruise
faster than that (78 m/s), so their cruise L/D sits below it (in brackets: the fraction of
the K_LD 11 trend).

| case | span (m) | S_wet/S_ref | A_wet | Raymer (L/D)max, K_LD 11 | K_LD 9 | model (L/D)max (vs K_LD 11) | e | model cruise L/D |
|---|---:|---:|---:|---:|---:|---:|---:|---:|
{rows}"""


def _implied_cd0(op):
    """CD0 that makes 140 KTAS at the cruise op's power with eta_p = 0.80 (the cross-check)."""
    V = 140 * u.KNOT
    q = 0.5 * op["rho"] * V * V
    s = 14.76
    cl = op["CL"] * op["q"] / q
    d = 0.80 * 2 * P_MCP_W * gagg_farrar(7000 * u.FT) / V
    return d / (q * s) - cl * cl / (math.pi * 8.804 * op["e"])


if __name__ == "__main__":
    bu, res = run()
    print(write_report(bu, res, ROOT / "results/validation/p2006t_drag.md"))
