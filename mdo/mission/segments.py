"""Mission segments: the kinds of Table 4 of Clarke et al. and their prescribed kinematics.

Each segment prescribes the vehicle's motion in closed form on its CGL nodes:
altitude h, airspeed V, flight-path angle gamma and their rates dV/dt and
dgamma/dt, and the duration T wherever the kinematics fix it.  What is left for the
NLP at each node is the body angle (unless the segment prescribes it) and the
vehicle's own unknowns; the force balance closes the system.

Kinds (Table 4 names; formulas with s in [0, 1], t = T s):

========================================================  ==========================================
kind                                                      kinematics
========================================================  ==========================================
Constant-Speed-Constant-Altitude  (cruise)                h = h0, V = V0; T = distance/V0 or given
Linear-Speed-Constant-Rate  (climb/descent)               h = h0 + hdot t, V = V0 + (Vf-V0) s,
                                                          gamma = asin(hdot/V); T = (hf-h0)/hdot
Constant-Acceleration-Constant-Angle-Linear-Climb         gamma fixed, V = V0 + a t,
                                                          h = h0 + sin(gamma)(V0 t + a t^2/2);
                                                          path length L = (hf-h0)/sin(gamma),
                                                          T = 2L/(V0+Vf), a = (Vf-V0)/T
Constant-Acceleration-Constant-Pitchrate-Constant-Altitude h = h0, V = V0 + a t, T = (Vf-V0)/a;
                                                          body angle free, or linear in t
Constant-Acceleration-Constant-Altitude                   h = h0, V = V0 + a t, T = (Vf-V0)/a
Vertical Ascent / Vertical Descent                        gamma = +-90 deg, V = rate, T = |dh|/rate
Hover (vertical ascent at zero rate)                      V = 0, gamma = 90 deg, T given or free
========================================================  ==========================================

The rates follow analytically: for the linear-speed climb
``dgamma/dt = -hdot dV/dt / (V^2 cos gamma)`` (from gamma = asin(hdot/V)).

A segment's start values default to the end of the previous segment (altitude,
speed); the mission checks that altitude is continuous at every join, and speed
where both segments fly forward (vertical segments have a constant vertical speed
by definition, so speed jumps at their ends as in SUAVE's vertical segments).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..core.errors import InputError

__all__ = [
    "Kinematics",
    "Segment",
    "ConstantSpeedConstantAltitude",
    "LinearSpeedConstantRate",
    "ConstantAccelerationConstantAngleLinearClimb",
    "ConstantAccelerationConstantPitchrateConstantAltitude",
    "ConstantAccelerationConstantAltitude",
    "VerticalAscent",
    "VerticalDescent",
    "Hover",
    "SEGMENT_KINDS",
]

_HALF_PI = 0.5 * math.pi


@dataclass
class Kinematics:
    """The prescribed motion of one segment at its nodes ``s`` (CGL on [0, 1]).

    ``duration_s`` is None when the duration is a variable (``free_duration``
    holds its bounds and initial guess).  ``body_angle`` is None when the body
    angle is an unknown; otherwise ``(initial, final)`` of a linear schedule, with
    ``initial = None`` meaning "the previous segment's final body angle".
    """

    s: np.ndarray
    duration_s: float | None
    altitude_m: np.ndarray
    speed_mps: np.ndarray
    flight_path_angle_rad: np.ndarray
    acceleration_mps2: np.ndarray
    flight_path_angle_rate_radps: np.ndarray
    vertical: bool = False
    body_angle: tuple | None = None
    free_duration: tuple | None = None     # (lower_s, upper_s, guess_s)

    @property
    def end_altitude_m(self) -> float:
        return float(self.altitude_m[-1])

    @property
    def end_speed_mps(self) -> float:
        return float(self.speed_mps[-1])


def _num(field_name: str, value, *, positive=False, nonzero=False, allow_none=False):
    if value is None:
        if allow_none:
            return None
        raise InputError(field_name, "is required")
    try:
        x = float(value)
    except (TypeError, ValueError) as exc:
        raise InputError(field_name, f"must be a number, got {value!r}") from exc
    if not math.isfinite(x):
        raise InputError(field_name, f"must be finite, got {x}")
    if positive and x <= 0:
        raise InputError(field_name, f"must be > 0, got {x:g}")
    if nonzero and x == 0:
        raise InputError(field_name, "must be nonzero")
    return x


def _altitude(field_name, value):
    x = _num(field_name, value)
    if x < 0.0 or x > 20000.0:
        raise InputError(field_name, f"allowed range [0, 20000] m (US Standard Atmosphere 1976), got {x:g} m")
    return x


def _speed(field_name, value, *, allow_zero=False):
    x = _num(field_name, value)
    if x < 0 or (x == 0 and not allow_zero):
        raise InputError(field_name, f"must be > 0 m/s, got {x:g} m/s")
    if x > 340.0:
        raise InputError(field_name, f"allowed range (0, 340] m/s (subsonic point mass), got {x:g} m/s")
    return x


class Segment:
    """Base class of the segment kinds.

    ``name`` labels the segment in constraints and reports ("CR node 3");
    ``nodes`` overrides the mission's default node count; ``parameters`` are the
    per-segment vehicle settings (SI), e.g. ``{"wing_mounted_angle_rad": ...,
    "pitch_command_rad": ...}`` for the TTW's WMA x beta_c of Table 5.
    """

    kind: str = "segment"
    symbol: str = ""

    def __init__(self, name: str, *, nodes: int | None = None, parameters: dict | None = None,
                 description: str = ""):
        if not isinstance(name, str) or not name or any(c in name for c in " \t\n/\\"):
            raise InputError("segment name", f"must be a non-empty word without spaces, got {name!r}")
        self.name = name
        if nodes is not None:
            if int(nodes) != nodes or nodes < 3 or nodes > 64:
                raise InputError(f"{name}.nodes", f"allowed range [3, 64] CGL nodes, got {nodes!r}")
            nodes = int(nodes)
        self.nodes = nodes
        self.parameters = {}
        for k, v in (parameters or {}).items():
            self.parameters[k] = _num(f"{name}.parameters[{k!r}]", v)
        self.description = description

    # -- to be provided by each kind
    def kinematics(self, n: int, start_altitude_m: float | None, start_speed_mps: float | None) -> Kinematics:
        raise NotImplementedError

    def _start(self, what, given, previous, field_name):
        if given is None:
            if previous is None:
                raise InputError(f"{self.name}.{field_name}", f"is required for the first segment ({what})")
            return previous
        return given

    def __repr__(self):
        return f"{type(self).__name__}({self.name!r})"


def _rows(n, s, T, h, V, gamma, Vdot, gdot, **kw):
    ones = np.ones(n)
    return Kinematics(s=s, duration_s=T, altitude_m=np.asarray(h, float) * ones,
                      speed_mps=np.asarray(V, float) * ones,
                      flight_path_angle_rad=np.asarray(gamma, float) * ones,
                      acceleration_mps2=np.asarray(Vdot, float) * ones,
                      flight_path_angle_rate_radps=np.asarray(gdot, float) * ones, **kw)


def _cgl01(n):
    from ..core.collocation import cgl_nodes
    return cgl_nodes(n, 0.0, 1.0)


def _free_duration(name, free_duration):
    if free_duration is None:
        return None
    try:
        lo, hi, guess = (float(x) for x in free_duration)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name}.free_duration", "must be (lower_s, upper_s, guess_s)") from exc
    if not (0 < lo <= guess <= hi < math.inf):
        raise InputError(f"{name}.free_duration", f"need 0 < lower <= guess <= upper < inf s, got {free_duration!r}")
    return (lo, hi, guess)


class ConstantSpeedConstantAltitude(Segment):
    """Cruise: constant airspeed and altitude for a ``distance_m``, a ``duration_s``,
    or a ``free_duration=(lower_s, upper_s, guess_s)`` left to the optimizer."""

    kind = "Constant-Speed-Constant-Altitude"

    def __init__(self, name, *, speed_mps=None, altitude_m=None, distance_m=None, duration_s=None,
                 free_duration=None, **kw):
        super().__init__(name, **kw)
        given = [x is not None for x in (distance_m, duration_s, free_duration)]
        if sum(given) != 1:
            raise InputError(f"{name}", "give exactly one of distance_m, duration_s, free_duration")
        self.speed_mps = None if speed_mps is None else _speed(f"{name}.speed_mps", speed_mps)
        self.altitude_m = None if altitude_m is None else _altitude(f"{name}.altitude_m", altitude_m)
        self.distance_m = _num(f"{name}.distance_m", distance_m, positive=True, allow_none=True)
        self.duration_s = _num(f"{name}.duration_s", duration_s, positive=True, allow_none=True)
        self.free_duration = _free_duration(name, free_duration)

    def kinematics(self, n, h_prev, v_prev):
        h = self._start("altitude", self.altitude_m, h_prev, "altitude_m")
        V = self._start("speed", self.speed_mps, v_prev, "speed_mps")
        if V <= 0:
            raise InputError(f"{self.name}.speed_mps", "must be > 0 m/s (use Hover for zero speed)")
        T = self.duration_s if self.duration_s is not None else (
            self.distance_m / V if self.distance_m is not None else None)
        return _rows(n, _cgl01(n), T, h, V, 0.0, 0.0, 0.0, free_duration=self.free_duration)


class LinearSpeedConstantRate(Segment):
    """Climb or descent at a constant rate of climb ``climb_rate_mps`` (negative
    to descend) between two altitudes, the airspeed linear in time."""

    kind = "Linear-Speed-Constant-Rate"

    def __init__(self, name, *, altitude_end_m, climb_rate_mps, speed_end_mps, altitude_start_m=None,
                 speed_start_mps=None, **kw):
        super().__init__(name, **kw)
        self.altitude_start_m = None if altitude_start_m is None else _altitude(f"{name}.altitude_start_m",
                                                                                   altitude_start_m)
        self.altitude_end_m = _altitude(f"{name}.altitude_end_m", altitude_end_m)
        self.climb_rate_mps = _num(f"{name}.climb_rate_mps", climb_rate_mps, nonzero=True)
        self.speed_start_mps = None if speed_start_mps is None else _speed(f"{name}.speed_start_mps",
                                                                              speed_start_mps)
        self.speed_end_mps = _speed(f"{name}.speed_end_mps", speed_end_mps)

    def kinematics(self, n, h_prev, v_prev):
        h0 = self._start("altitude", self.altitude_start_m, h_prev, "altitude_start_m")
        V0 = self._start("speed", self.speed_start_mps, v_prev, "speed_start_mps")
        hf, Vf, rate = self.altitude_end_m, self.speed_end_mps, self.climb_rate_mps
        dh = hf - h0
        if dh == 0 or np.sign(dh) != np.sign(rate):
            raise InputError(f"{self.name}.climb_rate_mps",
                             f"must have the sign of altitude_end - altitude_start = {dh:g} m (nonzero), "
                             f"got {rate:g} m/s")
        if abs(rate) >= min(V0, Vf):
            raise InputError(f"{self.name}.climb_rate_mps",
                             f"|rate| must be below the airspeed {min(V0, Vf):g} m/s, got {rate:g} m/s")
        T = dh / rate
        s = _cgl01(n)
        V = V0 + (Vf - V0) * s
        Vdot = (Vf - V0) / T
        gamma = np.arcsin(rate / V)
        gdot = -rate * Vdot / (V ** 2 * np.cos(gamma))
        return _rows(n, s, T, h0 + dh * s, V, gamma, Vdot, gdot)


class ConstantAccelerationConstantAngleLinearClimb(Segment):
    """Straight path at a constant flight-path angle with constant acceleration.

    Give the angle (``climb_angle_rad``) or the *mean* rate of climb
    (``climb_rate_mps``; sin(gamma) = 2 rate / (V0 + Vf), since the rate itself
    varies with speed along a straight path).  With ``altitude_end_m`` equal to
    the start (a level acceleration, e.g. Table 5's TTW CT No. 2) give
    ``acceleration_mps2`` instead.
    """

    kind = "Constant-Acceleration-Constant-Angle-Linear-Climb"

    def __init__(self, name, *, altitude_end_m, speed_end_mps, climb_angle_rad=None, climb_rate_mps=None,
                 acceleration_mps2=None, altitude_start_m=None, speed_start_mps=None, **kw):
        super().__init__(name, **kw)
        self.altitude_start_m = None if altitude_start_m is None else _altitude(f"{name}.altitude_start_m",
                                                                                   altitude_start_m)
        self.altitude_end_m = _altitude(f"{name}.altitude_end_m", altitude_end_m)
        self.speed_start_mps = None if speed_start_mps is None else _speed(f"{name}.speed_start_mps",
                                                                              speed_start_mps)
        self.speed_end_mps = _speed(f"{name}.speed_end_mps", speed_end_mps)
        self.climb_angle_rad = _num(f"{name}.climb_angle_rad", climb_angle_rad, allow_none=True)
        self.climb_rate_mps = _num(f"{name}.climb_rate_mps", climb_rate_mps, allow_none=True)
        self.acceleration_mps2 = _num(f"{name}.acceleration_mps2", acceleration_mps2, allow_none=True,
                                      nonzero=True)
        if self.climb_angle_rad is not None and abs(self.climb_angle_rad) >= _HALF_PI:
            raise InputError(f"{name}.climb_angle_rad", "allowed range (-pi/2, pi/2)")

    def kinematics(self, n, h_prev, v_prev):
        name = self.name
        h0 = self._start("altitude", self.altitude_start_m, h_prev, "altitude_start_m")
        V0 = self._start("speed", self.speed_start_mps, v_prev, "speed_start_mps")
        hf, Vf = self.altitude_end_m, self.speed_end_mps
        dh = hf - h0
        s = _cgl01(n)
        if dh == 0:
            if (self.climb_angle_rad or 0.0) != 0.0 or (self.climb_rate_mps or 0.0) != 0.0:
                raise InputError(f"{name}.climb_angle_rad", "must be 0 when altitude_end equals altitude_start")
            a = self.acceleration_mps2
            if a is None or Vf == V0 or np.sign(a) != np.sign(Vf - V0):
                raise InputError(f"{name}.acceleration_mps2",
                                 f"a level segment needs an acceleration with the sign of Vf - V0 = {Vf - V0:g} m/s")
            gamma = 0.0
            T = (Vf - V0) / a
        else:
            if (self.climb_angle_rad is None) == (self.climb_rate_mps is None):
                raise InputError(name, "give exactly one of climb_angle_rad, climb_rate_mps (mean rate)")
            if self.acceleration_mps2 is not None:
                raise InputError(f"{name}.acceleration_mps2",
                                 "is fixed by the speeds and the path length; do not give it")
            if self.climb_angle_rad is not None:
                gamma = self.climb_angle_rad
            else:
                sg = 2.0 * self.climb_rate_mps / (V0 + Vf)
                if abs(sg) >= 1:
                    raise InputError(f"{name}.climb_rate_mps", f"mean rate exceeds the mean speed {(V0 + Vf) / 2:g} m/s")
                gamma = math.asin(sg)
            if gamma == 0 or np.sign(gamma) != np.sign(dh):
                raise InputError(f"{name}.climb_angle_rad", f"must have the sign of the altitude change {dh:g} m")
            path = dh / math.sin(gamma)
            T = 2.0 * path / (V0 + Vf)
            a = (Vf - V0) / T
        t = T * s
        V = V0 + a * t
        h = h0 + math.sin(gamma) * (V0 * t + 0.5 * a * t ** 2)
        return _rows(n, s, T, h, V, gamma, a, 0.0)


class ConstantAccelerationConstantPitchrateConstantAltitude(Segment):
    """Level acceleration or deceleration (a transition) with a pitch schedule.

    With ``pitch_final_rad`` given, the body angle is prescribed linear in time
    from ``pitch_initial_rad`` (default: the previous segment's final body angle,
    so the attitude is continuous) to ``pitch_final_rad`` - a constant pitch rate;
    the vehicle then needs two independent controls for the two force equations
    (e.g. two rotor groups at different tilt, or a free tilt).  Without it the
    body angle is an unknown at every node, which is what SUAVE's segment of this
    name effectively solves (its body-angle unknown overrides the schedule).
    """

    kind = "Constant-Acceleration-Constant-Pitchrate-Constant-Altitude"

    def __init__(self, name, *, speed_end_mps, acceleration_mps2, altitude_m=None, speed_start_mps=None,
                 pitch_initial_rad=None, pitch_final_rad=None, **kw):
        super().__init__(name, **kw)
        self.altitude_m = None if altitude_m is None else _altitude(f"{name}.altitude_m", altitude_m)
        self.speed_start_mps = None if speed_start_mps is None else _speed(f"{name}.speed_start_mps",
                                                                              speed_start_mps)
        self.speed_end_mps = _speed(f"{name}.speed_end_mps", speed_end_mps)
        self.acceleration_mps2 = _num(f"{name}.acceleration_mps2", acceleration_mps2, nonzero=True)
        self.pitch_initial_rad = _num(f"{name}.pitch_initial_rad", pitch_initial_rad, allow_none=True)
        self.pitch_final_rad = _num(f"{name}.pitch_final_rad", pitch_final_rad, allow_none=True)
        if self.pitch_final_rad is None and self.pitch_initial_rad is not None:
            raise InputError(f"{name}.pitch_final_rad", "is required when pitch_initial_rad is given")
        for k in ("pitch_initial_rad", "pitch_final_rad"):
            v = getattr(self, k)
            if v is not None and abs(v) >= _HALF_PI:
                raise InputError(f"{name}.{k}", "allowed range (-pi/2, pi/2)")

    def kinematics(self, n, h_prev, v_prev):
        h = self._start("altitude", self.altitude_m, h_prev, "altitude_m")
        V0 = self._start("speed", self.speed_start_mps, v_prev, "speed_start_mps")
        Vf, a = self.speed_end_mps, self.acceleration_mps2
        if Vf == V0 or np.sign(a) != np.sign(Vf - V0):
            raise InputError(f"{self.name}.acceleration_mps2",
                             f"must have the sign of speed_end - speed_start = {Vf - V0:g} m/s (nonzero)")
        T = (Vf - V0) / a
        s = _cgl01(n)
        body = None if self.pitch_final_rad is None else (self.pitch_initial_rad, self.pitch_final_rad)
        return _rows(n, s, T, h, V0 + (Vf - V0) * s, 0.0, a, 0.0, body_angle=body)


class ConstantAccelerationConstantAltitude(Segment):
    """Level acceleration or deceleration from the start speed to ``speed_end_mps``;
    give exactly one of ``acceleration_mps2``, ``distance_m``, ``duration_s``."""

    kind = "Constant-Acceleration-Constant-Altitude"

    def __init__(self, name, *, speed_end_mps, acceleration_mps2=None, distance_m=None, duration_s=None,
                 altitude_m=None, speed_start_mps=None, **kw):
        super().__init__(name, **kw)
        if sum(x is not None for x in (acceleration_mps2, distance_m, duration_s)) != 1:
            raise InputError(name, "give exactly one of acceleration_mps2, distance_m, duration_s")
        self.altitude_m = None if altitude_m is None else _altitude(f"{name}.altitude_m", altitude_m)
        self.speed_start_mps = None if speed_start_mps is None else _speed(f"{name}.speed_start_mps",
                                                                              speed_start_mps)
        self.speed_end_mps = _speed(f"{name}.speed_end_mps", speed_end_mps)
        self.acceleration_mps2 = _num(f"{name}.acceleration_mps2", acceleration_mps2, allow_none=True,
                                      nonzero=True)
        self.distance_m = _num(f"{name}.distance_m", distance_m, positive=True, allow_none=True)
        self.duration_s = _num(f"{name}.duration_s", duration_s, positive=True, allow_none=True)

    def kinematics(self, n, h_prev, v_prev):
        h = self._start("altitude", self.altitude_m, h_prev, "altitude_m")
        V0 = self._start("speed", self.speed_start_mps, v_prev, "speed_start_mps")
        Vf = self.speed_end_mps
        if self.acceleration_mps2 is not None:
            a = self.acceleration_mps2
            if Vf == V0 or np.sign(a) != np.sign(Vf - V0):
                raise InputError(f"{self.name}.acceleration_mps2",
                                 f"must have the sign of speed_end - speed_start = {Vf - V0:g} m/s (nonzero)")
            T = (Vf - V0) / a
        elif self.distance_m is not None:
            T = 2.0 * self.distance_m / (V0 + Vf)
            a = (Vf - V0) / T
        else:
            T = self.duration_s
            a = (Vf - V0) / T
        s = _cgl01(n)
        return _rows(n, s, T, h, V0 + (Vf - V0) * s, 0.0, a, 0.0)


class _Vertical(Segment):
    direction = 1.0

    def __init__(self, name, *, altitude_end_m, rate_mps, altitude_start_m=None, **kw):
        super().__init__(name, **kw)
        self.altitude_start_m = None if altitude_start_m is None else _altitude(f"{name}.altitude_start_m",
                                                                                   altitude_start_m)
        self.altitude_end_m = _altitude(f"{name}.altitude_end_m", altitude_end_m)
        self.rate_mps = _num(f"{name}.rate", rate_mps, positive=True)

    def kinematics(self, n, h_prev, v_prev):
        h0 = self._start("altitude", self.altitude_start_m, h_prev, "altitude_start_m")
        dh = self.altitude_end_m - h0
        if dh * self.direction <= 0:
            raise InputError(f"{self.name}.altitude_end_m",
                             f"must be {'above' if self.direction > 0 else 'below'} the start altitude {h0:g} m")
        T = abs(dh) / self.rate_mps
        s = _cgl01(n)
        return _rows(n, s, T, h0 + dh * s, self.rate_mps, self.direction * _HALF_PI, 0.0, 0.0, vertical=True)


class VerticalAscent(_Vertical):
    """Vertical climb at a constant rate (Table 5's VC: 0 to 40 ft at 300 ft/min)."""

    kind = "Vertical Ascent"

    def __init__(self, name, *, altitude_end_m, climb_rate_mps, altitude_start_m=None, **kw):
        super().__init__(name, altitude_end_m=altitude_end_m, rate_mps=climb_rate_mps,
                         altitude_start_m=altitude_start_m, **kw)


class VerticalDescent(_Vertical):
    """Vertical descent at a constant rate (Table 5's VD: 40 to 0 ft at 300 ft/min)."""

    kind = "Vertical Descent"
    direction = -1.0

    def __init__(self, name, *, altitude_end_m, descent_rate_mps, altitude_start_m=None, **kw):
        super().__init__(name, altitude_end_m=altitude_end_m, rate_mps=descent_rate_mps,
                         altitude_start_m=altitude_start_m, **kw)


class Hover(Segment):
    """Hover: the vertical ascent at zero rate, for ``duration_s`` or a ``free_duration``."""

    kind = "Vertical Ascent (hover)"

    def __init__(self, name, *, duration_s=None, free_duration=None, altitude_m=None, **kw):
        super().__init__(name, **kw)
        if (duration_s is None) == (free_duration is None):
            raise InputError(name, "give exactly one of duration_s, free_duration")
        self.duration_s = _num(f"{name}.duration_s", duration_s, positive=True, allow_none=True)
        self.free_duration = _free_duration(name, free_duration)
        self.altitude_m = None if altitude_m is None else _altitude(f"{name}.altitude_m", altitude_m)

    def kinematics(self, n, h_prev, v_prev):
        h = self._start("altitude", self.altitude_m, h_prev, "altitude_m")
        return _rows(n, _cgl01(n), self.duration_s, h, 0.0, _HALF_PI, 0.0, 0.0, vertical=True,
                     free_duration=self.free_duration)


SEGMENT_KINDS = {
    cls.kind: cls for cls in (
        ConstantSpeedConstantAltitude, LinearSpeedConstantRate, ConstantAccelerationConstantAngleLinearClimb,
        ConstantAccelerationConstantPitchrateConstantAltitude, ConstantAccelerationConstantAltitude,
        VerticalAscent, VerticalDescent, Hover)
}
