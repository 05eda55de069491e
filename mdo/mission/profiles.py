"""The flight profiles of Table 5 (Clarke, Erhard & Alonso 2021, appendix B) as segment lists.

``ga_segments(**options)`` / ``ga_mission(vehicle, **options)``: the GA-2P/GA-8P
profile, DER through FA including the reserve climb, cruise and descent.  Takeoff,
landing and reverse thrust are not modeled (as in the paper: Table 4 marks them
"Not Modeled"), so they carry no energy.

``evtol_segments(**options)`` / ``evtol_mission(vehicle, **options)``: the TTW
profile VC through VD, each segment with its wing-mounted angle x pitch command
(Table 5's "WMA x beta_c") as the segment parameters ``wing_mounted_angle_rad``
and ``pitch_command_rad``.

Table 5 as printed, and how its gaps and inconsistencies are resolved here (every
choice is an option of the builders):

* **No cruise distances** are given.  Default 50 nmi for the main cruise (the
  public X-57 Mod II mission of SUAVE's successor RCAIDE flies the same GA segment
  list with a 50 nmi cruise and uses about 63 kWh at 1230 kg, the size of the
  paper's 61 kWh for GA-2P) and 5 nmi for the reserve cruise (the paper's group
  sizes reserve cruises at about 10 % of the cruise in its SUAVE eVTOL scripts).
  The same 50 / 5 nmi are the eVTOL defaults.
* **GA D -> DL speed "50 mph"**: the descent is printed 175 -> 50 mph and the
  downleg 50 -> 100 mph.  50 mph is far below the X-57's stall speed (58 kn =
  67 mph) and would make the downleg accelerate after the descent decelerated
  through the stall; every neighbouring speed fits a dropped leading digit, so
  the descent ends and the downleg starts at **150 mph**, and the downleg
  decelerates 150 -> 100 mph (option ``descent_end_speed_mps``).
* **GA RD -> BL altitude**: RD ends at 1000 ft but BL is printed from 1500 ft.
  Altitude must be continuous; BL flies **1000 -> 500 ft** (the reserve
  descent's end, and the baseleg of SUAVE's X-57 missions).
* **Downleg acceleration** is not given: default -0.2 m/s^2 (150 -> 100 mph in
  112 s, 6.3 km), gentle enough that drag alone never asks for reverse thrust.
* **Base leg and final approach need drag.**  BL decelerates 135 -> 90 mph while
  descending at 300 ft/min; drag alone does not supply that deceleration for a
  clean airframe, so without a drag device the propellers must windmill, and how
  much braking thrust a propeller design can give becomes a hidden constraint of
  the design (it was active at the GA-2P optimum).  A pilot lowers the gear and
  some flap here: option ``approach_drag_area_m2`` (default 0, none) gives BL and
  FA the segment parameter ``drag_device_area_m2``, the largest extra flat-plate
  drag area a vehicle may deploy there (a control per node, ``mdo.vehicle``).
* **Transition accelerations** (TTW VT, CT No. 2, DT) are not given: defaults
  g/5 = 1.96 m/s^2 for the vertical transition and the level climb transition,
  -0.5 m/s^2 for the descent transition (the values of the SUAVE tilt-wing
  mission scripts by the paper's first author).
* **TTW DT climb rate "*"**: the segment is Constant-Acceleration-Constant-
  Pitchrate-Constant-Altitude (Table 4), so its rate is 0.
* **TTW VC speed "0 -> 3.4 mph"**: a vertical ascent at the constant 300 ft/min
  (= 3.41 mph) of the table; the 0 is the standstill before it.
* **Constant-Angle climbs** (TTW CT No. 1, AT): the printed rate is taken as the
  segment's *mean* rate of climb, which fixes the path angle
  (sin(gamma) = 2 rate / (V0 + Vf)); CT No. 2 (100 -> 100 ft) is a level
  acceleration of the same kind.
* **TTW DT attitude**: decelerating to 3.4 mph with the wings and rotors at
  WMA = 25 deg, the rotors must carry the weight at the end, so the thrust line
  must be near vertical and the body pitches to about 65-70 deg nose-up (the wing
  gives nothing at hover speed).  Table 5 implies it; the eVTOL mission's
  default body-angle bounds are therefore (-60, 85) deg instead of the
  mission's (-45, 60) deg.  A vehicle that wants a sane attitude needs a
  different WMA schedule (option of the vehicle's problem file).
* **Pitch-rate segments** (VT, DT) leave the body angle to the optimizer at every
  node, as SUAVE's body-angle unknown does for this segment kind; pass
  ``transition_pitch=(initial, final)`` to prescribe a linear pitch schedule
  (then the vehicle needs a second force control).
"""
from __future__ import annotations

from ..core.errors import InputError
from ..core.units import DEG, FT, FT_PER_MIN, MPH, NMI
from .segments import (
    ConstantAccelerationConstantAltitude,
    ConstantAccelerationConstantAngleLinearClimb,
    ConstantAccelerationConstantPitchrateConstantAltitude,
    ConstantSpeedConstantAltitude,
    LinearSpeedConstantRate,
    VerticalAscent,
    VerticalDescent,
)
from .transcription import DEFAULT_NODES, Mission

# A passenger cabin's pitch-attitude envelope (rad), nose-down to nose-up: the pitch-attitude
# protection of a fly-by-wire passenger airplane, 15 deg nose-down to 30 deg nose-up (Airbus normal
# law, FCOM DSC-27-20-10-20; 25 deg nose-up at low speed).  The eVTOL profile's body-angle box
# (-60/+85 deg) is wider: a tilt-wing on a prescribed tilt schedule points its thrust by pitching
# the cabin.  Read by the TTW problem (its default bounds) and the design checks.
CABIN_ATTITUDE_ENVELOPE_RAD = (-15.0 * DEG, 30.0 * DEG)

# A passenger cabin's pitch rate (rad/s): the fastest pitch change a passenger airplane's normal
# operation puts its cabin through, the take-off rotation, "typically 2-3 degrees per second and in
# most cases should not exceed 3 degrees per second" (Boeing, Flight Operations Review, "The
# importance of proper rotation technique", 14 March 1986; Airbus flies the same 3 deg/s by its
# SOPs, Safety First, "A focus on the takeoff rotation").  A rotation rate is a tail-clearance rule,
# not a comfort study: the figure is what passengers routinely accept, not a measured threshold.
# Read by the TTW problem (``Mission(max_body_pitch_rate_radps=...)``) and the design checks.
CABIN_PITCH_RATE_MAX_RADPS = 3.0 * DEG

__all__ = ["CABIN_ATTITUDE_ENVELOPE_RAD", "CABIN_PITCH_RATE_MAX_RADPS", "TABLE5_GA", "TABLE5_EVTOL", "ga_segments", "ga_mission", "evtol_segments", "evtol_mission"]

# Table 5 as printed: (symbol, h0 ft, hf ft, V0 mph, Vf mph, rate ft/min, WMA deg, beta_c deg)
TABLE5_GA = [
    ("TO", 0, 0, 0, 91, 0, None, None),
    ("DER", 0, 50, 91, 100, 600, None, None),
    ("ICA", 50, 500, 100, 110, 600, None, None),
    ("CL", 500, 2500, 110, 175, 500, None, None),
    ("CR", 2500, 2500, 175, 175, 0, None, None),
    ("D", 2500, 1000, 175, 50, -300, None, None),
    ("DL", 1000, 1000, 50, 100, 0, None, None),
    ("RCL", 1000, 1500, 100, 150, 500, None, None),
    ("RCR", 1500, 1500, 150, 150, 0, None, None),
    ("RD", 1500, 1000, 150, 135, -300, None, None),
    ("BL", 1500, 500, 135, 90, -300, None, None),
    ("FA", 500, 0, 90, 78, -300, None, None),
    ("L", 0, 0, 78, 50, 0, None, None),
    ("RT", 0, 0, 50, 0, 0, None, None),
]
TABLE5_EVTOL = [
    ("VC", 0, 40, 0, 3.4, 300, 90, -5),
    ("VT", 40, 40, 3.4, 55, 0, 45, 3),
    ("CT1", 40, 100, 55, 85, 500, 15, 5),
    ("CT2", 100, 100, 85, 125, 0, 15, 5),
    ("CL", 100, 2500, 125, 175, 500, 0, 16),
    ("CR", 2500, 2500, 175, 175, 0, 0, 20),
    ("D", 2500, 100, 175, 125, -300, 0, 16),
    ("RCL", 100, 1000, 125, 150, 500, 0, 16),
    ("RCR", 1000, 1000, 150, 150, 0, 0, 20),
    ("RD", 1000, 100, 150, 125, -300, 0, 16),
    ("AT", 100, 40, 125, 55, -200, 0, 16),
    ("DT", 40, 40, 55, 3.4, None, 25, 10),
    ("VD", 40, 0, 3.4, 3.4, -300, 90, -5),
]


def _nodes(nodes, name):
    if isinstance(nodes, dict):
        return nodes.get(name)
    return nodes


def _check_cruise(altitude_m, speed_mps, floor_what: str, climb_start_mps: float):
    """Cruise above 1000 ft (``floor_what``) and below 20 km, faster than the climb starts."""
    if not (1000 * FT < altitude_m <= 20000.0):
        raise InputError("cruise_altitude_m", f"above 1000 ft ({floor_what}) and <= 20000 m, got {altitude_m!r}")
    if not (climb_start_mps < speed_mps < 250.0):
        raise InputError("cruise_speed_mps", f"above the climb's start speed {climb_start_mps / MPH:.0f} mph "
                         f"({climb_start_mps:.1f} m/s) and below 250 m/s, got {speed_mps!r}")


def ga_segments(*, cruise_distance_m: float = 50 * NMI, reserve_cruise_distance_m: float = 5 * NMI,
                cruise_altitude_m: float = 2500 * FT, cruise_speed_mps: float = 175 * MPH,
                descent_end_speed_mps: float = 150 * MPH, downleg_acceleration_mps2: float = -0.2,
                approach_drag_area_m2: float = 0.0, takeoff_flap: float = 0.5, landing_flap: float = 1.0,
                extra: dict | None = None, nodes=None) -> list:
    """The GA profile of Table 5 (DER ... FA), resolved as described in the module docstring.

    ``cruise_altitude_m``, ``cruise_speed_mps``: the climb ends and the cruise flies
    there (Table 5: 2500 ft, 175 mph); ``cruise_distance_m``, ``reserve_cruise_distance_m``.
    ``nodes`` is None (the mission default), a number for every segment, or a
    dict segment symbol -> number.  ``approach_drag_area_m2`` > 0 lets the vehicle
    deploy up to that much flat-plate drag area (gear, flap) on BL and FA.
    ``takeoff_flap`` (DER, ICA) and ``landing_flap`` (BL half of it, FA): the flap
    deflection (0-1) the segments fly with; it raises the stall limit of flapped strips
    (``mdo.vehicle.stall``).  ``extra``: more segment parameters per segment symbol,
    e.g. ``{"CR": {"highlift.active": 0.0}}`` (a vehicle's own parameters).
    """
    ft, mph, fpm = FT, MPH, FT_PER_MIN
    n = lambda s: _nodes(nodes, s)  # noqa: E731
    if not (approach_drag_area_m2 >= 0.0 and approach_drag_area_m2 < 10.0):
        raise InputError("approach_drag_area_m2", f"must be in [0, 10) m^2, got {approach_drag_area_m2!r}")
    _check_cruise(cruise_altitude_m, cruise_speed_mps, "the downleg altitude", 110 * mph)
    for name, v in (("takeoff_flap", takeoff_flap), ("landing_flap", landing_flap)):
        if not 0.0 <= v <= 1.0:
            raise InputError(name, f"a flap deflection in [0, 1], got {v!r}")
    ex = dict(extra or {})

    def par(sym, **kw):
        out = {k: float(v) for k, v in kw.items() if v}
        out.update(ex.get(sym, {}))
        return out or None
    dev = {"drag_device_area_m2": float(approach_drag_area_m2)} if approach_drag_area_m2 > 0 else {}
    return [
        LinearSpeedConstantRate("DER", altitude_start_m=0.0, altitude_end_m=50 * ft, speed_start_mps=91 * mph,
                                speed_end_mps=100 * mph, climb_rate_mps=600 * fpm, nodes=n("DER"),
                                parameters=par("DER", flap_deflection=takeoff_flap),
                                description="departure end of runway"),
        LinearSpeedConstantRate("ICA", altitude_end_m=500 * ft, speed_end_mps=110 * mph, climb_rate_mps=600 * fpm,
                                nodes=n("ICA"), parameters=par("ICA", flap_deflection=takeoff_flap),
                                description="initial climb area"),
        LinearSpeedConstantRate("CL", altitude_end_m=cruise_altitude_m, speed_end_mps=cruise_speed_mps,
                                climb_rate_mps=500 * fpm, nodes=n("CL"), parameters=par("CL"), description="climb"),
        ConstantSpeedConstantAltitude("CR", distance_m=cruise_distance_m, nodes=n("CR"), parameters=par("CR"),
                                      description="cruise"),
        LinearSpeedConstantRate("D", altitude_end_m=1000 * ft, speed_end_mps=descent_end_speed_mps,
                                climb_rate_mps=-300 * fpm, nodes=n("D"), parameters=par("D"), description="descent"),
        ConstantAccelerationConstantAltitude("DL", speed_end_mps=100 * mph,
                                             acceleration_mps2=downleg_acceleration_mps2, nodes=n("DL"), parameters=par("DL"),
                                             description="downleg"),
        LinearSpeedConstantRate("RCL", altitude_end_m=1500 * ft, speed_end_mps=150 * mph, climb_rate_mps=500 * fpm,
                                nodes=n("RCL"), parameters=par("RCL"), description="reserve climb"),
        ConstantSpeedConstantAltitude("RCR", distance_m=reserve_cruise_distance_m, nodes=n("RCR"), parameters=par("RCR"),
                                      description="reserve cruise"),
        LinearSpeedConstantRate("RD", altitude_end_m=1000 * ft, speed_end_mps=135 * mph, climb_rate_mps=-300 * fpm,
                                nodes=n("RD"), parameters=par("RD"), description="reserve descent"),
        LinearSpeedConstantRate("BL", altitude_end_m=500 * ft, speed_end_mps=90 * mph, climb_rate_mps=-300 * fpm,
                                nodes=n("BL"), parameters=par("BL", flap_deflection=0.5 * landing_flap, **dev),
                                description="baseleg"),
        LinearSpeedConstantRate("FA", altitude_end_m=0.0, speed_end_mps=78 * mph, climb_rate_mps=-300 * fpm,
                                nodes=n("FA"), parameters=par("FA", flap_deflection=landing_flap, **dev),
                                description="final approach"),
    ]


def ga_mission(vehicle, *, nodes: int = DEFAULT_NODES, state_form: str = "differentiation", prefix: str = "",
               trajectory="prescribed", envelope=None, **options) -> Mission:
    """A :class:`Mission` of ``vehicle`` over the GA profile (options as :func:`ga_segments`;
    ``trajectory`` and ``envelope`` as :class:`Mission`)."""
    segs = ga_segments(**options)
    return Mission(vehicle, segs, nodes=nodes, state_form=state_form, prefix=prefix,
                   name="GA profile (Table 5)", trajectory=trajectory, envelope=envelope,
                   legs=_trip_and_reserve(segs, "RCL"))


def evtol_segments(*, cruise_distance_m: float = 50 * NMI, reserve_cruise_distance_m: float = 5 * NMI,
                   cruise_altitude_m: float = 2500 * FT, cruise_speed_mps: float = 175 * MPH,
                   vertical_transition_acceleration_mps2: float = 9.80665 / 5,
                   climb_transition_acceleration_mps2: float = 9.80665 / 5,
                   descent_transition_acceleration_mps2: float = -0.5,
                   transition_pitch=None, nodes=None) -> list:
    """The eVTOL (TTW) profile of Table 5 (VC ... VD) with WMA x beta_c per segment.

    ``transition_pitch``: None (body angle free in VT and DT) or a dict
    ``{"VT": (initial_rad or None, final_rad), "DT": (...)}`` prescribing a
    linear pitch schedule.  ``cruise_altitude_m``/``cruise_speed_mps``: where CL ends
    and CR flies (Table 5: 2500 ft, 175 mph).  The transition segments (VC, VT,
    CT1, CT2, AT, DT, VD) keep the wing's post-stall model and carry no stall limit
    (``stall_margin_cl`` = -1) and are not trimmed in pitch (``pitch_trim`` = 0: the
    tilted rotors' hub positions and the post-stall strips' moment are not modelled);
    the wing-borne segments carry both.  VT, CT1, CT2, AT and DT
    set ``wing_tilt_control`` = 1: with ``Aircraft(tilt="control")`` their wing-mounted
    angle is a control (Table 5's WMA is then the initial guess only).
    """
    ft, mph, fpm = FT, MPH, FT_PER_MIN
    n = lambda s: _nodes(nodes, s)  # noqa: E731
    tp = transition_pitch or {}
    _check_cruise(cruise_altitude_m, cruise_speed_mps, "the reserve altitude", 125 * mph)

    def p(wma, bc, transition=False, tilt=False):
        out = {"wing_mounted_angle_rad": wma * DEG, "pitch_command_rad": bc * DEG}
        if transition:   # post-stall strips, no stall limit; not trimmed in pitch (mdo.vehicle.balance)
            out["stall_margin_cl"] = -1.0
            out["pitch_trim"] = 0.0
        if tilt:   # where Aircraft(tilt="control") flies the wing-mounted angle as a control
            out["wing_tilt_control"] = 1.0
        return out

    def pitch(sym):
        if sym in tp:
            return {"pitch_initial_rad": tp[sym][0], "pitch_final_rad": tp[sym][1]}
        return {}

    return [
        VerticalAscent("VC", altitude_start_m=0.0, altitude_end_m=40 * ft, climb_rate_mps=300 * fpm,
                       parameters=p(90, -5, True), nodes=n("VC"), description="vertical climb"),
        ConstantAccelerationConstantPitchrateConstantAltitude(
            "VT", speed_start_mps=300 * fpm, speed_end_mps=55 * mph,
            acceleration_mps2=vertical_transition_acceleration_mps2, parameters=p(45, 3, True, True), nodes=n("VT"),
            description="vertical transition", **pitch("VT")),
        ConstantAccelerationConstantAngleLinearClimb("CT1", altitude_end_m=100 * ft, speed_end_mps=85 * mph,
                                                     climb_rate_mps=500 * fpm, parameters=p(15, 5, True, True), nodes=n("CT1"),
                                                     description="climb transition no. 1"),
        ConstantAccelerationConstantAngleLinearClimb("CT2", altitude_end_m=100 * ft, speed_end_mps=125 * mph,
                                                     acceleration_mps2=climb_transition_acceleration_mps2,
                                                     parameters=p(15, 5, True, True), nodes=n("CT2"),
                                                     description="climb transition no. 2"),
        LinearSpeedConstantRate("CL", altitude_end_m=cruise_altitude_m, speed_end_mps=cruise_speed_mps,
                                climb_rate_mps=500 * fpm, parameters=p(0, 16), nodes=n("CL"), description="climb"),
        ConstantSpeedConstantAltitude("CR", distance_m=cruise_distance_m, parameters=p(0, 20), nodes=n("CR"),
                                      description="cruise"),
        LinearSpeedConstantRate("D", altitude_end_m=100 * ft, speed_end_mps=125 * mph, climb_rate_mps=-300 * fpm,
                                parameters=p(0, 16), nodes=n("D"), description="descent"),
        LinearSpeedConstantRate("RCL", altitude_end_m=1000 * ft, speed_end_mps=150 * mph, climb_rate_mps=500 * fpm,
                                parameters=p(0, 16), nodes=n("RCL"), description="reserve climb"),
        ConstantSpeedConstantAltitude("RCR", distance_m=reserve_cruise_distance_m, parameters=p(0, 20),
                                      nodes=n("RCR"), description="reserve cruise"),
        LinearSpeedConstantRate("RD", altitude_end_m=100 * ft, speed_end_mps=125 * mph, climb_rate_mps=-300 * fpm,
                                parameters=p(0, 16), nodes=n("RD"), description="reserve descent"),
        ConstantAccelerationConstantAngleLinearClimb("AT", altitude_end_m=40 * ft, speed_end_mps=55 * mph,
                                                     climb_rate_mps=-200 * fpm, parameters=p(0, 16, True, True), nodes=n("AT"),
                                                     description="approach transition"),
        ConstantAccelerationConstantPitchrateConstantAltitude(
            "DT", speed_end_mps=300 * fpm, acceleration_mps2=descent_transition_acceleration_mps2,
            parameters=p(25, 10, True, True), nodes=n("DT"), description="descent transition", **pitch("DT")),
        VerticalDescent("VD", altitude_end_m=0.0, descent_rate_mps=300 * fpm, parameters=p(90, -5, True), nodes=n("VD"),
                        description="vertical descent"),
    ]


def evtol_mission(vehicle, *, nodes: int = DEFAULT_NODES, state_form: str = "differentiation", prefix: str = "",
                  body_angle_bounds_rad=(-60 * DEG, 85 * DEG), trajectory="prescribed", envelope=None,
                  max_body_pitch_rate_radps=None, **options) -> Mission:
    """A :class:`Mission` of ``vehicle`` over the eVTOL profile (options as :func:`evtol_segments`;
    ``trajectory``, ``envelope`` and ``max_body_pitch_rate_radps`` as :class:`Mission`)."""
    segs = evtol_segments(**options)
    return Mission(vehicle, segs, nodes=nodes, state_form=state_form, prefix=prefix,
                   body_angle_bounds_rad=body_angle_bounds_rad, name="eVTOL profile (Table 5)",
                   trajectory=trajectory, envelope=envelope, legs=_trip_and_reserve(segs, "RCL"),
                   max_body_pitch_rate_radps=max_body_pitch_rate_radps)


def _trip_and_reserve(segs, reserve_start):
    """The trip (to the reserve climb) and the reserve as the two legs whose ground
    distances a free trajectory keeps."""
    names = [s.name for s in segs]
    if reserve_start not in names:
        return None
    i = names.index(reserve_start)
    return [names[:i], names[i:]]
