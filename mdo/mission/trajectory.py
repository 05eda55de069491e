"""Free trajectory: a segment's speed (and duration) as controls, within an envelope.

A prescribed segment (Table 5) fixes altitude h(s), airspeed V(s), path angle and the
duration T in closed form.  A freed segment keeps its **altitude profile** h(s) on
s in [0, 1] (so its end altitudes, and the atmosphere at each node, are those of the
profile) and frees

* ``"speed"``: its airspeed (the duration, hence the rate of climb h'(s)/T, stays
  prescribed);
* ``"free"``: its airspeed and its duration T (bounded by ``Envelope.duration_range``
  times the prescribed one, and by the climb/descent rates): speed and climb rate free.

A freed segment keeps its kind's speed form: linear in s from its start speed (the
previous segment's end) to its end speed, which is a variable where the next segment
is freed too (``FreeSpeedRows.rows``); constant-speed kinds keep one speed.  Speeds
per node would be a polynomial the quadrature cannot integrate exactly against
V dV/dt: measured on a polar cruise, the optimizer then oscillates the node speeds
and gains energy from the aliasing (a spuriously lower optimum with more nodes).  With the
speed linear in time the kinetic-energy term is integrated exactly.  The kinematics
follow from V(s), T and the prescribed h(s) (D the CGL differentiation matrix on
[0, 1]; exact, h is a polynomial in s)::

    hdot  = (D h) / T,  hddot = (D^2 h) / T^2        climb rate and its rate
    gamma = asin(hdot / V),  dV/dt = (Vf - V0) / T
    dgamma/dt = (hddot V - hdot dV/dt) / (V^2 cos gamma)

Speed is continuous at every forward join by construction and the mission starts and
ends at the profile's speeds (a free start speed would be kinetic energy from
nowhere); the **ground distance of each leg** (``Mission(legs=...)``: the whole mission
by default; the GA and eVTOL profiles hold the trip and the reserve apart) is held at
the profile's ("ground distance"): a free trajectory flies the same trip, its own way.
Without a block-time limit nothing charges for time, so the energy optimum flies
slowly and descends early (measured on GA-2P; ``max_block_time_s``).
The distance is Clenshaw-Curtis of V cos(gamma) over each segment's nodes, exact for
the linear speed of a level segment.

The envelope (``Envelope``), on every node of a freed segment, each a named group:

* "stall speed margin": V >= k_s V_stall, V_stall = sqrt(2 m g cos(gamma) / (rho S
  CL_max)) for a vehicle that states ``stall_reference()`` (S, CL_max); k_s = 1.2
  (the 1.2 V_S1 of take-off climb, 14 CFR 23.2120 and its means of compliance; final
  approach uses 1.3 V_S0, a larger margin: set ``stall_speed_factor``).  The Aircraft
  also holds each strip's section cl below its cl_max (issue 16 item 2) in every
  airplane-mode segment, the local form of the same limit.
* V <= V_MO: the speed variable's upper bound (``max_speed_mps``; the profile's top
  speed x 1.3 unless the user gives the airframe's V_MO/V_NE - a placeholder, said so).
* "climb gradient": sin(gamma) >= 0.083 in segments that climb (14 CFR 23.65(a)(1),
  the pre-Amendment-64 take-off climb gradient of a normal-category landplane; applied
  to the flown gradient, a conservative reading).
* "climb rate" / "descent rate": hdot within [-max_descent_rate, max_climb_rate];
  defaults 1500 ft/min each (passenger comfort in an unpressurized cabin, a choice
  the designer may tighten).
* "normal load factor": n = cos(gamma) + V gamma'/g within 1 +- 0.3 (passenger ride
  comfort; a choice).
* "longitudinal acceleration": |dV/dt| <= 0.3 g (the same comfort figure; without it
  a short free transition brakes or accelerates without limit wherever the vehicle
  model lets it, e.g. a polar without CL_max at extreme angles of attack).
* "block time": the mission duration <= ``max_block_time_s`` when given.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..core.collocation import Collocation
from ..core.errors import InputError
from ..core.units import FT, MINUTE

__all__ = ["Envelope", "TRAJECTORY_MODES", "trajectory_modes", "FreeSpeedRows"]

TRAJECTORY_MODES = ("prescribed", "speed", "free")
_G0 = 9.80665


@dataclass(frozen=True)
class Envelope:
    """The flight envelope a freed segment must respect (module docstring; SI)."""

    stall_speed_factor: float = 1.2
    max_speed_mps: float | None = None
    min_climb_gradient: float = 0.083
    max_climb_rate_mps: float = 1500 * FT / MINUTE
    max_descent_rate_mps: float = 1500 * FT / MINUTE
    load_factor_increment: float = 0.3
    max_acceleration_mps2: float = 0.3 * 9.80665
    max_block_time_s: float | None = None
    duration_range: tuple = (0.01, 10.0)   # a free duration within these factors of the prescribed one

    def __post_init__(self):
        def rng(name, v, lo, hi):
            if v is None:
                return
            if not (isinstance(v, (int, float)) and math.isfinite(v) and lo <= v <= hi):
                raise InputError(f"envelope.{name}", f"allowed range [{lo:g}, {hi:g}], got {v!r}")
        rng("stall_speed_factor", self.stall_speed_factor, 1.0, 2.0)
        rng("max_speed_mps", self.max_speed_mps, 1.0, 340.0)
        rng("min_climb_gradient", self.min_climb_gradient, 0.0, 0.5)
        rng("max_climb_rate_mps", self.max_climb_rate_mps, 0.1, 100.0)
        rng("max_descent_rate_mps", self.max_descent_rate_mps, 0.1, 100.0)
        rng("load_factor_increment", self.load_factor_increment, 0.01, 3.0)
        rng("max_acceleration_mps2", self.max_acceleration_mps2, 0.01, 30.0)
        rng("max_block_time_s", self.max_block_time_s, 1.0, 1e6)
        lo, hi = self.duration_range
        if not 0.01 <= lo < 1.0 < hi <= 100.0:
            raise InputError("envelope.duration_range", f"need 0.01 <= lower < 1 < upper <= 100, got {self.duration_range!r}")

    def shortest_duration_s(self, altitude_m, D) -> float:
        """The least duration at which the segment's altitude profile h(s) stays within the
        climb and descent rates: max over nodes of h'(s)/rate - a bound on a free duration,
        so that no trial point of IPOPT has |hdot| > V (asin(hdot/V) undefined)."""
        dh_ds = np.asarray(D, float) @ np.asarray(altitude_m, float)
        return float(max(np.max(dh_ds) / self.max_climb_rate_mps, np.max(-dh_ds) / self.max_descent_rate_mps, 0.0))


def trajectory_modes(segs, trajectory) -> dict:
    """Segment name -> mode from the ``trajectory`` choice: ``"prescribed"``, ``"free"``
    (every segment that may be freed: forward flight, not vertical) or a dict
    ``{segment name: mode}`` (others prescribed).  Bad names and modes are InputErrors."""
    names = [g.segment.name for g in segs]
    eligible = {g.segment.name for g in segs if not g.kin.vertical and np.all(g.kin.speed_mps > 0)}
    if isinstance(trajectory, str):
        if trajectory not in ("prescribed", "free"):
            raise InputError("trajectory", f"'prescribed', 'free' or a dict segment -> mode, got {trajectory!r}")
        return {n: ("free" if trajectory == "free" and n in eligible else "prescribed") for n in names}
    if not isinstance(trajectory, dict):
        raise InputError("trajectory", f"'prescribed', 'free' or a dict segment -> mode, got {trajectory!r}")
    modes = {n: "prescribed" for n in names}
    for name, mode in trajectory.items():
        if name not in modes:
            raise InputError("trajectory", f"no segment {name!r}; segments: {', '.join(names)}")
        if mode not in TRAJECTORY_MODES:
            raise InputError(f"trajectory[{name!r}]", f"one of {', '.join(TRAJECTORY_MODES)}, got {mode!r}")
        if mode != "prescribed" and name not in eligible:
            raise InputError(f"trajectory[{name!r}]", "a vertical or hovering segment has no forward speed to free")
        modes[name] = mode
    return modes


class FreeSpeedRows:
    """The kinematic rows of a mission with freed segments (module docstring)."""

    def __init__(self, mission, problem, modes: dict, envelope: Envelope, durations: list):
        self.m, self.p, self.modes, self.env = mission, problem, modes, envelope
        self.durations = durations
        self.speed_vars = {}
        top = max(float(np.max(g.kin.speed_mps)) for g in mission._segs)
        self.v_max = envelope.max_speed_mps or 1.3 * top

    @property
    def any_free(self) -> bool:
        return any(m != "prescribed" for m in self.modes.values())

    def rows(self, num: dict) -> dict:
        """speed, path angle, dV/dt, dgamma/dt as 1 x K rows (DM where prescribed).

        A freed segment keeps its kind's speed form, linear in s from the start speed (the
        previous segment's end) to its end speed; the end speed is a variable when the
        next segment is freed too and flies forward, else the profile's (so a prescribed
        neighbour, a vertical segment or the mission's end fix it), and a constant-speed
        kind (cruise) ends at its start speed.  Speed is therefore continuous at every
        forward join by construction, and the speed at mission start and end is the
        profile's (a free start speed would be kinetic energy from nowhere)."""
        P, segs = self.m.prefix, self.m._segs
        pieces = {k: [] for k in ("speed_mps", "flight_path_angle_rad", "acceleration_mps2",
                                  "flight_path_angle_rate_radps")}
        v_end = None
        for i, (g, T) in enumerate(zip(segs, self.durations)):
            a, b = g.node0, g.node0 + g.n
            kin, name = g.kin, g.segment.name
            forward_join = i > 0 and not (kin.vertical or segs[i - 1].kin.vertical)
            if self.modes[name] == "prescribed":
                for k in pieces:
                    pieces[k].append(ca.DM(np.asarray(num[k][a:b], float).reshape(1, -1)))
                v_end = float(kin.speed_mps[-1])
                continue
            V0 = v_end if forward_join else float(kin.speed_mps[0])
            nxt = segs[i + 1] if i + 1 < len(segs) else None
            if np.allclose(kin.speed_mps, kin.speed_mps[0]):
                Vf = V0                                   # constant-speed kind
            elif nxt is not None and self.modes[nxt.segment.name] != "prescribed" and not nxt.kin.vertical:
                Vp = float(kin.speed_mps[-1])
                v_lo = max(0.3 * Vp, 1.05 * max(self.env.max_climb_rate_mps, self.env.max_descent_rate_mps))
                Vf = self.p.variable(f"{P}{name}.speed_end", unit="m/s", scale=Vp, lower=v_lo,
                                     upper=self.v_max, init=Vp,
                                     description=f"airspeed at the end of segment {name} (free trajectory)")
                self.speed_vars[name] = Vf
            else:
                Vf = float(nxt.kin.speed_mps[0]) if nxt is not None and not nxt.kin.vertical \
                    else float(kin.speed_mps[-1])
            s_row = ca.DM(np.asarray(kin.s, float).reshape(1, -1))
            V = V0 + (Vf - V0) * s_row
            c = Collocation(g.n)
            h = ca.DM(np.asarray(kin.altitude_m, float).reshape(1, -1))
            hdot = ca.mtimes(h, ca.DM(c.D).T) / T                 # exact: h(s) is a polynomial
            hddot = ca.mtimes(h, ca.DM(c.D @ c.D).T) / T ** 2
            Vdot = (Vf - V0) / T * ca.DM.ones(1, g.n)
            gam = ca.asin(hdot / V)
            pieces["speed_mps"].append(V)
            pieces["flight_path_angle_rad"].append(gam)
            pieces["acceleration_mps2"].append(Vdot)
            # d/dt asin(hdot/V) = (hddot V - hdot Vdot) / (V^2 cos gamma)
            pieces["flight_path_angle_rate_radps"].append((hddot * V - hdot * Vdot) / (V ** 2 * ca.cos(gam)))
            v_end = Vf
        return {k: ca.horzcat(*v) for k, v in pieces.items()}

    def constrain(self, cond, mass_kg, distance_row, duration_s, vehicle):
        """The trip's ground distance and the envelope (module docstring)."""
        if not self.any_free:
            return
        P, m = self.m.prefix, self.m
        r, lab = [], []
        for first, last in m.leg_nodes():
            r.append(distance_row[0, last] - distance_row[0, first])
            lab.append(f"{m.labels[first].split(' node ')[0]}..{m.labels[last].split(' node ')[0]}")
        self.p.constrain(f"{P}ground distance", ca.vertcat(*r) - ca.DM(self.prescribed_leg_m), scale=1e4,
                         unit="m", labels=lab)
        self._envelope(cond, mass_kg, vehicle, duration_s)

    def _free_columns(self, climbing=False):
        cols = []
        for g in self.m._segs:
            if self.modes[g.segment.name] == "prescribed":
                continue
            if climbing and not g.kin.altitude_m[-1] > g.kin.altitude_m[0]:
                continue
            cols += list(range(g.node0, g.node0 + g.n))
        return cols

    def _envelope(self, cond, mass_kg, vehicle, duration_s):
        P, p, env, labels = self.m.prefix, self.p, self.env, self.m.labels
        cols = self._free_columns()
        V, gam = cond.speed_mps[:, cols], cond.flight_path_angle_rad[:, cols]
        lab = [labels[k] for k in cols]
        ref = getattr(vehicle, "stall_reference", None)
        ref = ref() if callable(ref) else None
        if ref is not None:
            area_m2, cl_max = ref
            from ..core.atmosphere import density
            rho = ca.DM(np.asarray(density(np.asarray(cond.altitude_m, float).ravel()[cols]), float).reshape(1, -1))
            v_stall = ca.sqrt(2 * mass_kg * _G0 * ca.cos(gam) / (rho * area_m2 * cl_max))
            p.constrain(f"{P}stall speed margin", V - env.stall_speed_factor * v_stall, kind=">=", scale=10.0,
                        unit="m/s", labels=lab)
        hdot = V * ca.sin(gam)
        p.constrain(f"{P}climb rate", hdot, kind="<=", rhs=env.max_climb_rate_mps, scale=1.0, unit="m/s", labels=lab)
        p.constrain(f"{P}descent rate", hdot, kind=">=", rhs=-env.max_descent_rate_mps, scale=1.0, unit="m/s",
                    labels=lab)
        climb = self._free_columns(climbing=True)
        if climb and env.min_climb_gradient > 0:
            p.constrain(f"{P}climb gradient", ca.sin(cond.flight_path_angle_rad[:, climb]), kind=">=",
                        rhs=env.min_climb_gradient, scale=0.01, unit="-", labels=[labels[k] for k in climb])
        n_z = ca.cos(gam) + V * cond.flight_path_angle_rate_radps[:, cols] / _G0
        p.constrain(f"{P}normal load factor", n_z, kind="<=", rhs=1 + env.load_factor_increment, scale=0.1,
                    unit="g", labels=lab)
        p.constrain(f"{P}normal load factor (low)", n_z, kind=">=", rhs=1 - env.load_factor_increment, scale=0.1,
                    unit="g", labels=lab)
        acc = cond.acceleration_mps2[:, cols]
        p.constrain(f"{P}longitudinal acceleration", acc, kind="<=", rhs=env.max_acceleration_mps2, scale=1.0,
                    unit="m/s^2", labels=lab)
        p.constrain(f"{P}longitudinal deceleration", acc, kind=">=", rhs=-env.max_acceleration_mps2, scale=1.0,
                    unit="m/s^2", labels=lab)
        if env.max_block_time_s is not None:
            p.constrain(f"{P}block time", duration_s, kind="<=", rhs=env.max_block_time_s, scale=60.0, unit="s",
                        labels=["mission"])
