"""The mission as constraints of one NLP: CGL collocation of a chain of segments.

``Mission(vehicle, segments).build(problem)`` writes into ``problem`` (duck-typed:
``variable``, ``constrain``, ``output``; ``set_initial`` and ``opti`` are used for
the initial guess when present):

* per node: the body angle (where the segment does not prescribe it) and the
  vehicle's unknowns (``vehicle.unknowns()``), initial values from
  ``vehicle.initial_guess`` (level-flight angle of attack, momentum power...);
* the vehicle evaluated ONCE for all K nodes of the mission (rows are nodes);
* the point-mass equations of motion in the path frame at every node::

      F_t - m (g sin(gamma) + dV/dt)      = 0     "force_along_path"
      F_n - m (g cos(gamma) + V dgamma/dt) = 0     "force_normal_to_path"

  with the accelerations the segment's kinematics prescribe (closed form);
* the vehicle's residual groups at every node;
* every vehicle state collocated on each segment's CGL nodes.  With T the
  segment duration and D, I the differentiation and integration matrices on
  [0, 1] (``mdo.core.Collocation``), the default defects are

      (D x)_j - T f_j = 0,   j = 1 .. n-1            ("differentiation" form)

  (node 0 is the join, shared with the previous segment, or the initial
  condition), or ``x_j - x_0 - T (I f)_j = 0`` (``state_form="integration"``,
  Clenshaw-Curtis on the last row).  States are one vector over the mission
  in which consecutive segments share their join node, so joins are continuous
  by construction;
* durations: fixed by the kinematics, given, or variables (``free_duration``).

After ``build`` the mission holds expressions for the report: ``rows`` (name ->
1 x K), ``energy_used_J``, ``segment_energy_J``, ``final_states``.

Layout of ``Mission``: kinematics (each segment's speeds, rates, durations), ``build`` and
its named steps in the order it calls them (``_add_durations``, ``_add_body_angle``,
``_add_unknowns``, ``_add_states``, ``_add_equations_of_motion``, ``_add_vehicle_residuals``,
``_add_collocation``, ``_add_energy_and_outputs``), the pieces they share (guesses, defect
matrices), and the results (``report_rows``, ``report``); the unknowns that exist only at some
nodes and the controls' continuity and rate limits are in ``controls.py``.  The free-trajectory envelope lives in ``trajectory.py``, segment kinds in
``segments.py``, Table 5's profiles in ``profiles.py``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..core.collocation import Collocation
from ..core.errors import InputError
from ..core.units import KWH, MINUTE, NMI
from ..vehicle.base import G0, NodeConditions, Output
from .controls import NodeControlsMixin
from .segments import Kinematics, Segment
from .trajectory import Envelope, FreeSpeedRows, trajectory_modes

__all__ = ["Mission", "DEFAULT_NODES", "STANDARD_PARAMETERS"]

#: CGL nodes per segment unless a segment says otherwise.  Chosen by the
#: convergence study (results/mission/convergence.md, tests/bench/mission_convergence.py):
#: the smallest count for which the GA profile's mission energy is within 1e-7 and
#: every segment's energy within 1e-5 of the 32-node solution (polar vehicle,
#: differentiation form: 4.9e-8 and 6.4e-6 at 6 nodes; 5 nodes give 1.4e-6 and 1.6e-4).
DEFAULT_NODES = 6

#: Segment parameters the mission always knows (Table 5's WMA x beta_c); a vehicle
#: may declare more in ``vehicle.parameters``.
STANDARD_PARAMETERS = {"wing_mounted_angle_rad": 0.0, "pitch_command_rad": 0.0,
                       # flap deflection 0-1 and the stall limit's cl margin (negative: no stall
                       # limit, e.g. tilt-wing transitions); a vehicle without these ignores them
                       "flap_deflection": 0.0, "stall_margin_cl": 0.1,
                       # 1 where a tilt-wing may fly its wing-mounted angle as a control
                       "wing_tilt_control": 0.0,
                       # 0 where a vehicle that trims in pitch does not (mdo.vehicle.balance)
                       "pitch_trim": 1.0}


@dataclass
class _Seg:
    segment: Segment
    kin: Kinematics
    n: int
    node0: int          # first node index in the mission rows
    state0: int         # first index in the state vectors
    duration: object    # float or MX
    duration_guess: float


def _row(x) -> ca.DM:
    return ca.DM(np.asarray(x, dtype=float).reshape(1, -1))


class Mission(NodeControlsMixin):
    """A chain of segments flown by one vehicle, transcribed by CGL collocation.

    Parameters
    ----------
    vehicle : a :class:`mdo.vehicle.base.Vehicle`
    segments : list of :mod:`mdo.mission.segments` objects, in flight order
    nodes : default CGL nodes per segment (each segment may override)
    state_form : ``"differentiation"`` (default) or ``"integration"``
    prefix : put in front of every variable, constraint and output name (to
        hold two missions in one problem)
    body_angle_bounds_rad : bounds of the body-angle unknowns
    trajectory : ``"prescribed"`` (default: every segment flies its closed-form
        kinematics), ``"free"`` (every forward-flight segment's speed and duration are
        controls) or ``{segment name: "prescribed" | "speed" | "free"}``
        (:mod:`mdo.mission.trajectory`)
    envelope : the :class:`~mdo.mission.trajectory.Envelope` freed segments respect
    legs : lists of consecutive segment names whose ground distance a free trajectory
        keeps, each on its own (default: the whole mission, one leg)
    max_body_pitch_rate_radps : the body's pitch rate limit (rad/s) at the nodes of the
        segments whose body angle is free and between them (``NodeControlsMixin._limit_body_pitch``);
        None (default): no limit
    """

    def __init__(self, vehicle, segments, *, nodes: int = DEFAULT_NODES, state_form: str = "differentiation",
                 prefix: str = "", body_angle_bounds_rad=(-45.0 * math.pi / 180, 60.0 * math.pi / 180),
                 name: str = "mission", trajectory="prescribed", envelope: Envelope | None = None,
                 legs=None, max_body_pitch_rate_radps: float | None = None):
        if not segments:
            raise InputError("segments", "a mission needs at least one segment")
        if state_form not in ("differentiation", "integration"):
            raise InputError("state_form", f"must be 'differentiation' or 'integration', got {state_form!r}")
        if int(nodes) != nodes or not 3 <= nodes <= 64:
            raise InputError("nodes", f"allowed range [3, 64] CGL nodes per segment, got {nodes!r}")
        names = [s.name for s in segments]
        dup = {n for n in names if names.count(n) > 1}
        if dup:
            raise InputError("segments", f"segment names must be unique; repeated: {sorted(dup)}")
        lo, hi = body_angle_bounds_rad
        if not lo < hi:
            raise InputError("body_angle_bounds_rad", f"need lower < upper, got {body_angle_bounds_rad!r}")
        self.vehicle = vehicle
        self.segments = list(segments)
        self.nodes = int(nodes)
        self.state_form = state_form
        self.prefix = prefix
        self.name = name
        self.body_angle_bounds_rad = (float(lo), float(hi))
        self.parameters = dict(STANDARD_PARAMETERS)
        self.parameters.update(getattr(vehicle, "parameters", {}) or {})
        for seg in self.segments:
            for k in seg.parameters:
                if k not in self.parameters:
                    raise InputError(f"{seg.name}.parameters", f"unknown parameter {k!r}; known: "
                                     f"{sorted(self.parameters)}")
        self._segs: list[_Seg] = []
        self._resolve_kinematics()
        self.modes = trajectory_modes(self._segs, trajectory)
        self.legs = self._check_legs(legs)
        self.envelope = envelope if envelope is not None else Envelope()
        if max_body_pitch_rate_radps is not None and not 0.0 < float(max_body_pitch_rate_radps) <= math.pi:
            raise InputError("max_body_pitch_rate_radps", f"allowed range (0, pi] rad/s, got "
                                                          f"{max_body_pitch_rate_radps!r}")
        self.max_body_pitch_rate_radps = None if max_body_pitch_rate_radps is None else \
            float(max_body_pitch_rate_radps)
        if not isinstance(self.envelope, Envelope):
            raise InputError("envelope", f"an mdo.mission.trajectory.Envelope, got {type(envelope).__name__}")
        self.built = False

    # ------------------------------------------------------------------ kinematics
    def _resolve_kinematics(self):
        h_prev = v_prev = None
        prev_vertical = None
        node0 = state0 = 0
        for i, seg in enumerate(self.segments):
            n = seg.nodes or self.nodes
            kin = seg.kinematics(n, h_prev, v_prev)
            if h_prev is not None and abs(kin.altitude_m[0] - h_prev) > 1e-6 * max(1.0, abs(h_prev)):
                raise InputError(f"{seg.name}.altitude_start_m",
                                 f"{kin.altitude_m[0]:g} m does not continue the previous segment "
                                 f"{self.segments[i - 1].name}, which ends at {h_prev:g} m")
            if v_prev is not None and not (kin.vertical or prev_vertical) and \
                    abs(kin.speed_mps[0] - v_prev) > 1e-6 * max(1.0, v_prev):
                raise InputError(f"{seg.name}.speed_start_mps",
                                 f"{kin.speed_mps[0]:g} m/s does not continue the previous segment "
                                 f"{self.segments[i - 1].name}, which ends at {v_prev:g} m/s")
            if kin.duration_s is not None and not kin.duration_s > 0:
                raise InputError(f"{seg.name}", f"duration {kin.duration_s:g} s must be > 0")
            guess = kin.duration_s if kin.duration_s is not None else kin.free_duration[2]
            self._segs.append(_Seg(seg, kin, n, node0, state0, kin.duration_s, guess))
            node0 += n
            state0 += n - 1
            h_prev, v_prev, prev_vertical = kin.end_altitude_m, kin.end_speed_mps, kin.vertical
        self.K = node0                       # nodes of the mission
        self.N_state = state0 + 1            # state points (joins shared)
        self.labels = [f"{g.segment.name} node {j}" for g in self._segs for j in range(g.n)]
        self.segment_of_node = [g.segment.name for g in self._segs for _ in range(g.n)]
        self.state_index = np.concatenate([g.state0 + np.arange(g.n) for g in self._segs])

    def _check_legs(self, legs):
        names = [g.segment.name for g in self._segs]
        if legs is None:
            return [names]
        out, used = [], set()
        for leg in legs:
            leg = list(leg)
            if not leg or any(n not in names for n in leg) or used & set(leg):
                raise InputError("legs", f"lists of segment names, each used once; segments: {', '.join(names)}")
            i = names.index(leg[0])
            if names[i:i + len(leg)] != leg:
                raise InputError("legs", f"a leg is consecutive segments in flight order, got {leg}")
            used |= set(leg)
            out.append(leg)
        return out

    def leg_nodes(self):
        """(first node, last node) of each leg, mission node indices."""
        by = {g.segment.name: g for g in self._segs}
        return [(by[leg[0]].node0, by[leg[-1]].node0 + by[leg[-1]].n - 1) for leg in self.legs]

    def _numeric_rows(self, durations):
        """Kinematic rows (numpy) with the given segment durations."""
        t, t0 = [], 0.0
        for g, T in zip(self._segs, durations):
            t.append(t0 + T * g.kin.s)
            t0 += T
        cat = lambda attr: np.concatenate([getattr(g.kin, attr) for g in self._segs])  # noqa: E731
        return {"time_s": np.concatenate(t), "altitude_m": cat("altitude_m"), "speed_mps": cat("speed_mps"),
                "flight_path_angle_rad": cat("flight_path_angle_rad"), "acceleration_mps2": cat("acceleration_mps2"),
                "flight_path_angle_rate_radps": cat("flight_path_angle_rate_radps")}

    def parameter_rows(self) -> dict:
        """Segment parameters per node (numpy), defaults where a segment is silent."""
        out = {}
        for k, default in self.parameters.items():
            out[k] = np.concatenate([np.full(g.n, g.segment.parameters.get(k, default)) for g in self._segs])
        return out

    def summary_table(self) -> str:
        """The segment list with kinematics, for humans (markdown)."""
        lines = ["| segment | kind | nodes | h0 -> hf (ft) | V0 -> Vf (mph) | duration (s) |",
                 "|---|---|---|---|---|---|"]
        for g in self._segs:
            k = g.kin
            T = "free" if k.duration_s is None else f"{k.duration_s:.1f}"
            lines.append(f"| {g.segment.name} | {g.segment.kind} | {g.n} | {k.altitude_m[0] / 0.3048:.0f} -> "
                         f"{k.altitude_m[-1] / 0.3048:.0f} | {k.speed_mps[0] / 0.44704:.1f} -> "
                         f"{k.speed_mps[-1] / 0.44704:.1f} | {T} |")
        return "\n".join(lines)

    # ------------------------------------------------------------------ build
    def build(self, problem):
        """Write the mission into ``problem``; returns ``self`` (expressions in ``self.rows``)."""
        if self.built:
            raise RuntimeError("Mission.build: this mission is already built; make a new Mission per problem")
        self.problem = problem
        self.vehicle.setup(problem)
        durations, dur_guess = self._add_durations(problem)
        num = self._numeric_rows(dur_guess)
        params = self.parameter_rows()
        free = FreeSpeedRows(self, problem, self.modes, self.envelope, durations)
        d0 = np.asarray(self._distance_row(dur_guess), float).ravel()
        free.prescribed_leg_m = [d0[b] - d0[a] for a, b in self.leg_nodes()]
        kin = free.rows(num)
        theta, pitch_rate, guess = self._add_body_angle(problem, num, params)
        unknowns = self._add_unknowns(problem, guess, params)
        state_vars, state_rows = self._add_states(problem)
        time_row = self._time_row(durations, num)
        cond = NodeConditions(
            time_s=time_row, altitude_m=_row(num["altitude_m"]), speed_mps=kin["speed_mps"],
            flight_path_angle_rad=kin["flight_path_angle_rad"], acceleration_mps2=kin["acceleration_mps2"],
            flight_path_angle_rate_radps=kin["flight_path_angle_rate_radps"],
            body_angle_rad=theta, pitch_rate_radps=pitch_rate,
            parameters={k: _row(v) for k, v in params.items()}, states=state_rows,
            segment=self.segment_of_node, labels=self.labels)
        ev = self.vehicle.evaluate(cond, unknowns)     # the one vehicle evaluation, all K nodes
        self.cond, self.unknowns, self.theta, self.evaluation = cond, unknowns, theta, ev
        self.states, self.state_rows = state_vars, state_rows
        self._add_equations_of_motion(problem, cond, ev)
        self.duration_s = sum(durations[1:], durations[0]) if len(durations) > 1 else durations[0]
        dist = self._distance_row(durations, cond.speed_mps, cond.flight_path_angle_rad)
        free.constrain(cond, ev.mass_kg, dist, self.duration_s, self.vehicle)   # trip distance, envelope
        self.free = free
        self._add_vehicle_residuals(problem, ev)
        self._add_collocation(problem, ev, state_vars)
        self._add_energy_and_outputs(problem, state_vars, dist, time_row, num, params)
        self.built = True
        # lifted node quantities start at their definitions, before and after the states' guess
        start_defined = getattr(problem, "start_defined", lambda: None)
        start_defined()
        self._initial_states_guess(problem, state_vars, ev, dur_guess)
        start_defined()
        return self

    # ------------------------------------------------------------------ build steps
    def _add_durations(self, problem):
        """Each segment's duration: fixed by its kinematics, or a variable (``free_duration``,
        or a free trajectory's segment); returns (durations, their guesses)."""
        P = self.prefix
        durations, dur_guess = [], []
        for g in self._segs:
            if g.kin.duration_s is None:
                lo, hi, guess = g.kin.free_duration
                T = problem.variable(f"{P}{g.segment.name}.duration", unit="s", scale=max(guess, 1.0), lower=lo,
                                     upper=hi, init=guess, description=f"duration of segment {g.segment.name}")
                g.duration = T
            elif self.modes[g.segment.name] == "free":   # free trajectory: the duration is a control
                T0 = g.kin.duration_s
                lo, hi = self.envelope.duration_range
                t_rate = self.envelope.shortest_duration_s(g.kin.altitude_m, Collocation(g.n).D)
                g.duration = problem.variable(f"{P}{g.segment.name}.duration", unit="s", scale=max(T0, 1.0),
                                              lower=max(lo * T0, t_rate), upper=max(hi * T0, 1.01 * t_rate),
                                              init=max(T0, t_rate),
                                              description=f"duration of segment {g.segment.name} (free trajectory)")
            durations.append(g.duration)
            dur_guess.append(g.duration_guess)
        return durations, dur_guess

    def _add_unknowns(self, problem, guess, params) -> dict:
        """The vehicle's per-node unknowns as variables (``vehicle.unknowns()``)."""
        K, P = self.K, self.prefix
        unknowns = {}
        self.unknown_specs = list(self.vehicle.unknowns())
        for u in self.unknown_specs:
            rows = int(u.rows)
            init = np.asarray(guess.get(u.name, 0.0), float)
            init = np.broadcast_to(init.reshape(rows, -1) if init.size == rows * K else init, (rows, K))
            col = lambda v: np.broadcast_to(np.asarray(v, float).reshape(-1, 1), (rows, 1)) \
                if np.size(v) == rows else np.asarray(v, float)  # noqa: E731
            if u.only_where is not None or u.hold_where_uncollocated:   # a control of some nodes only
                unknowns[u.name] = self._masked_unknown(problem, u, params, init, col)
                if u.replaces is not None or u.max_rate is not None:
                    self._control_continuity_and_rate(problem, u, unknowns[u.name], params)
                continue
            unknowns[u.name] = problem.variable(f"{P}{u.name}", (rows, K), unit=u.unit,
                                                scale=np.broadcast_to(col(u.scale), (rows, K)),
                                                lower=np.broadcast_to(col(u.lower), (rows, K)),
                                                upper=np.broadcast_to(col(u.upper), (rows, K)),
                                                init=init, description=u.description)
        return unknowns

    def _add_states(self, problem):
        """One vector per vehicle state over the mission, joins shared; returns
        (state variables, their 1 x K rows at the nodes)."""
        self.state_specs = list(self.vehicle.states())
        state_vars, state_rows = {}, {}
        idx = [int(i) for i in self.state_index]
        for st in self.state_specs:
            lower = np.full(self.N_state, st.lower, dtype=float)
            upper = np.full(self.N_state, st.upper, dtype=float)
            init0 = st.initial if st.initial is not None else 0.5 * (
                (st.lower if np.isfinite(st.lower) else 0.0) + (st.upper if np.isfinite(st.upper) else 0.0))
            if st.initial is not None:
                lower[0] = upper[0] = st.initial
            x = problem.variable(f"{self.prefix}{st.name}", (1, self.N_state), unit=st.unit, scale=st.scale,
                                 lower=lower.reshape(1, -1), upper=upper.reshape(1, -1),
                                 init=np.full((1, self.N_state), init0), description=st.description)
            state_vars[st.name] = x
            state_rows[st.name] = x[0, idx]
        return state_vars, state_rows

    def _time_row(self, durations, num):
        if not any(isinstance(T, ca.MX) for T in durations):
            return _row(num["time_s"])
        tpieces, t0 = [], 0.0
        for g in self._segs:
            tpieces.append(t0 + g.duration * _row(g.kin.s))
            t0 = t0 + g.duration
        return ca.horzcat(*tpieces)

    def _add_equations_of_motion(self, problem, cond, ev):
        """The point-mass equations in the path frame at every node (module docstring)."""
        P, m = self.prefix, ev.mass_kg
        gam, V = cond.flight_path_angle_rad, cond.speed_mps
        f_scale = float(getattr(ev, "force_scale_N", None) or _force_scale(self.vehicle))
        r_t = ev.force_along_path_N - m * (G0 * ca.sin(gam) + cond.acceleration_mps2)
        r_n = ev.force_normal_N - m * (G0 * ca.cos(gam) + V * cond.flight_path_angle_rate_radps)
        problem.constrain(f"{P}force_along_path", r_t, scale=f_scale, unit="N", labels=self.labels)
        problem.constrain(f"{P}force_normal_to_path", r_n, scale=f_scale, unit="N", labels=self.labels)

    def _add_vehicle_residuals(self, problem, ev):
        K, labels = self.K, self.labels
        for grp in ev.residuals:
            expr = grp.expr
            rows = int(expr.shape[0])
            cols = list(range(K)) if getattr(grp, "columns", None) is None else [int(c) for c in grp.columns]
            if not cols:
                continue
            rl = list(grp.row_labels) if grp.row_labels is not None else (
                [f"row {r}" for r in range(rows)] if rows > 1 else [""])
            lab = [f"{labels[k]} {rl[r]}".rstrip() for k in cols for r in range(rows)]
            defines = None if grp.defines is None else f"{self.prefix}{grp.defines}"
            problem.constrain(f"{self.prefix}{grp.name}", expr, kind=grp.kind, scale=grp.scale, unit=grp.unit,
                              labels=lab, defines=defines)

    def _add_collocation(self, problem, ev, state_vars):
        for st in self.state_specs:
            if st.name not in ev.state_derivatives:
                raise InputError(f"vehicle {self.vehicle.name!r}",
                                 f"declares state {st.name!r} but returns no derivative")
            defect = self._defects(state_vars[st.name], ev.state_derivatives[st.name])
            lab = [f"{g.segment.name} node {j}" for g in self._segs for j in range(1, g.n)]
            problem.constrain(f"{self.prefix}{st.name} collocation", defect, scale=st.scale, unit=st.unit,
                              labels=lab)

    def _add_energy_and_outputs(self, problem, state_vars, dist, time_row, num, params):
        """Energy, end-of-mission limits, the report rows and the summary outputs."""
        P, veh, cond = self.prefix, self.vehicle, self.cond
        self.initial_states = {k: x[0, 0] for k, x in state_vars.items()}
        self.final_states = {k: x[0, self.N_state - 1] for k, x in state_vars.items()}
        self.segment_end_states = [{k: x[0, g.state0 + g.n - 1] for k, x in state_vars.items()} for g in self._segs]
        self.segment_start_states = [{k: x[0, g.state0] for k, x in state_vars.items()} for g in self._segs]
        self.energy_used_J = veh.energy_used_J(self.initial_states, self.final_states)
        for grp in (veh.final_limits(self.final_states) if hasattr(veh, "final_limits") else []):
            problem.constrain(f"{P}{grp.name}", grp.expr, kind=grp.kind, scale=grp.scale, unit=grp.unit,
                              labels=list(grp.row_labels or ["end of mission"]))
        self.segment_energy_J = ca.vertcat(*[veh.energy_used_J(a, b) for a, b in
                                             zip(self.segment_start_states, self.segment_end_states)])
        self.rows = {
            "time_s": (time_row, "s"), "altitude_m": (cond.altitude_m, "m"), "speed_mps": (cond.speed_mps, "m/s"),
            "flight_path_angle_rad": (cond.flight_path_angle_rad, "rad"), "body_angle_rad": (self.theta, "rad"),
            "body_pitch_rate_radps": (cond.pitch_rate_radps, "rad/s"),
            "distance_m": (dist, "m"),
        }
        if self.free.any_free:   # the prescribed profile beside the flown one (mission.csv, mission.png)
            self.rows["profile_time_s"] = (_row(num["time_s"]), "s")
            self.rows["profile_speed_mps"] = (_row(num["speed_mps"]), "m/s")
        for k, row in params.items():
            if np.any(row != 0):
                self.rows[k] = (_row(row), "rad" if k.endswith("_rad") else "-")
        self.range_m = dist[0, self.K - 1]
        problem.output(f"{P}battery_energy_kWh", self.energy_used_J / KWH, unit="kWh", summary=True)
        problem.output(f"{P}mission_time_min", self.duration_s / MINUTE, unit="min", summary=True)
        problem.output(f"{P}mission_range_nmi", self.range_m / NMI, unit="nmi", summary=True)
        problem.output(f"{P}segment_energy_kWh", self.segment_energy_J / KWH, unit="kWh")

    # ------------------------------------------------------------------ pieces
    def _guess(self, num, params, theta_in):
        c = NodeConditions(
            time_s=num["time_s"], altitude_m=num["altitude_m"], speed_mps=num["speed_mps"],
            flight_path_angle_rad=num["flight_path_angle_rad"], acceleration_mps2=num["acceleration_mps2"],
            flight_path_angle_rate_radps=num["flight_path_angle_rate_radps"], body_angle_rad=theta_in.copy(),
            pitch_rate_radps=np.zeros(self.K), parameters=params, states=self._state_guess_rows(),
            segment=self.segment_of_node, labels=self.labels)
        g = dict(self.vehicle.initial_guess(c))
        if "body_angle_rad" not in g:
            g["body_angle_rad"] = np.where(np.isnan(theta_in), 0.0, theta_in)
        return g

    def _state_guess_rows(self):
        """Each state at its initial value (or mid-bounds) at every node, for the vehicle's guess."""
        out = {}
        for st in self.vehicle.states():
            x0 = st.initial if st.initial is not None else 0.5 * (
                (st.lower if np.isfinite(st.lower) else 0.0) + (st.upper if np.isfinite(st.upper) else 0.0))
            out[st.name] = np.full(self.K, float(x0))
        return out

    def _defect_matrices(self):
        """Sparse (N_def x N_state) and (N_def x K) matrices of the state defects."""
        Ndef = self.N_state - 1
        A = np.zeros((Ndef, self.N_state))
        B = np.zeros((Ndef, self.K))
        Tsel = np.zeros((Ndef, len(self._segs)))
        r = 0
        for i, g in enumerate(self._segs):
            c = Collocation(g.n)
            for j in range(1, g.n):
                if self.state_form == "differentiation":
                    A[r, g.state0:g.state0 + g.n] = c.D[j]
                    B[r, g.node0 + j] = 1.0
                else:
                    A[r, g.state0 + j] = 1.0
                    A[r, g.state0] = -1.0
                    B[r, g.node0:g.node0 + g.n] = c.I[j]
                Tsel[r, i] = 1.0
                r += 1
        return ca.sparsify(ca.DM(A)), ca.sparsify(ca.DM(B)), Tsel

    def _defects(self, x, f):
        A, B, Tsel = self._defect_matrices()
        durations = [g.duration for g in self._segs]
        if any(isinstance(T, ca.MX) for T in durations):
            Tcol = ca.mtimes(ca.DM(Tsel), ca.vertcat(*[ca.MX(T) if not isinstance(T, ca.MX) else T
                                                      for T in durations]))
        else:
            Tcol = ca.DM(Tsel @ np.asarray(durations, float))
        return ca.mtimes(A, x.T) - Tcol * ca.mtimes(B, f.T)

    def _distance_row(self, durations, V=None, gam=None):
        """Horizontal distance flown at each node: T (I V cos gamma) per segment, chained;
        the prescribed kinematics unless the rows ``V``, ``gam`` are given (free trajectory)."""
        pieces, d0 = [], 0.0
        for g, T in zip(self._segs, durations):
            if V is None:
                vx = _row(g.kin.speed_mps * np.cos(g.kin.flight_path_angle_rad))
            else:
                vx = V[:, g.node0:g.node0 + g.n] * ca.cos(gam[:, g.node0:g.node0 + g.n])
            if g.kin.vertical:
                vx = ca.DM.zeros(1, g.n)
            local = ca.mtimes(vx, ca.DM(Collocation(g.n).I).T)       # on [0, 1]
            pieces.append(d0 + T * local)
            d0 = d0 + T * local[0, g.n - 1]
        return ca.horzcat(*pieces)

    def _initial_states_guess(self, problem, state_vars, ev, dur_guess):
        """Integrate the state rates at the initial guess (a few Picard sweeps)."""
        opti = getattr(problem, "opti", None)
        if opti is None or not hasattr(problem, "set_initial") or not self.state_specs:
            return
        names = [st.name for st in self.state_specs]
        fexpr = ca.vertcat(*[ev.state_derivatives[k] for k in names])
        for _ in range(3):
            try:
                fval = np.atleast_2d(np.asarray(opti.value(fexpr, opti.initial()), float))
            except Exception:  # noqa: BLE001 - the guess is a convenience; the NLP copes without it
                return
            fval = fval.reshape(len(names), self.K)
            if not np.all(np.isfinite(fval)):
                return
            for si, st in enumerate(self.state_specs):
                x = np.empty(self.N_state)
                x[0] = st.initial if st.initial is not None else float(np.asarray(
                    opti.value(state_vars[st.name][0, 0], opti.initial())))
                for g, T in zip(self._segs, dur_guess):
                    seg_f = fval[si, g.node0:g.node0 + g.n]
                    x[g.state0 + 1:g.state0 + g.n] = x[g.state0] + T * (Collocation(g.n).I @ seg_f)[1:]
                problem.set_initial(f"{self.prefix}{st.name}", x.reshape(1, -1))

    # ------------------------------------------------------------------ results
    def report_rows(self) -> dict:
        """name -> (1 x K expression, unit): kinematics, states, then the vehicle's outputs."""
        if not self.built:
            raise RuntimeError("Mission.report_rows: build the mission first")
        out = dict(self.rows)
        for k, x in self.state_rows.items():
            unit = next(st.unit for st in self.state_specs if st.name == k)
            out[k] = (x, unit)
        for k, o in self.evaluation.outputs.items():
            expr = o.expr if isinstance(o, Output) else o
            unit = o.unit if isinstance(o, Output) else "-"
            if hasattr(expr, "shape") and expr.shape[0] > 1 and expr.shape[1] == self.K:
                for r in range(expr.shape[0]):
                    out[f"{k}[{r}]"] = (expr[r, :], unit)
            else:
                if not hasattr(expr, "shape") or expr.shape == (1, 1):
                    expr = ca.repmat(expr, 1, self.K)
                out[k] = (expr, unit)
        return out

    def report(self, solution, out_dir, figures: bool = True):
        """Write ``mission.csv`` and (with ``figures``) ``mission.png`` into ``out_dir`` (usable with
        ``problem.add_report``; without figures where ``mdo.plots.figure_report`` draws them)."""
        from .report import write_mission_report
        return write_mission_report(self, solution, out_dir, figures=figures)


def _force_scale(vehicle) -> float:
    m = getattr(vehicle, "reference_mass_kg", None)
    if m is None:
        raise InputError(f"vehicle {getattr(vehicle, 'name', '?')!r}",
                         "give NodeEvaluation.force_scale_N or a reference_mass_kg attribute for the force scale")
    return float(m) * G0
