"""Per-node unknowns that exist only where a segment allows them, the body angle, and controls that
take over a segment parameter (continuity at the joins, rate limits): a mixin of
:class:`mdo.mission.transcription.Mission` (it reads the mission's node layout, ``self._segs``,
``self.K``, ``self.labels``, ``self.prefix``, ``self.state_form``, ``self._guess``, the body angle's
bounds and pitch-rate limit).
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..core.collocation import Collocation
from ..core.errors import InputError

__all__ = ["NodeControlsMixin"]


class NodeControlsMixin:
    """Masked unknowns, the body angle and control continuity/rate of
    :class:`~mdo.mission.transcription.Mission`."""

    def _add_body_angle(self, problem, num, params):
        """Free nodes' body angle as unknowns, prescribed nodes on their schedule; returns
        (theta row, pitch-rate row, the vehicle's initial guess)."""
        K, P, labels = self.K, self.prefix, self.labels
        free_mask = np.ones(K, dtype=bool)
        for g in self._segs:
            if g.kin.body_angle is not None:
                free_mask[g.node0:g.node0 + g.n] = False
        theta_guess_in = np.full(K, np.nan)
        for g in self._segs:   # numeric schedules for the guess (continuity ones filled after the first guess)
            if g.kin.body_angle is not None and g.kin.body_angle[0] is not None:
                th0, thf = g.kin.body_angle
                theta_guess_in[g.node0:g.node0 + g.n] = th0 + (thf - th0) * g.kin.s
        guess = self._guess(num, params, theta_guess_in)
        theta_g = np.asarray(guess["body_angle_rad"], float).ravel()
        for g in self._segs:
            if g.kin.body_angle is not None and g.kin.body_angle[0] is None:
                th0 = theta_g[g.node0 - 1] if g.node0 > 0 else 0.0
                thf = g.kin.body_angle[1]
                theta_guess_in[g.node0:g.node0 + g.n] = th0 + (thf - th0) * g.kin.s
        if np.any(~free_mask):
            guess = self._guess(num, params, theta_guess_in)
            theta_g = np.where(free_mask, np.asarray(guess["body_angle_rad"], float).ravel(), theta_guess_in)
        lo_th, hi_th = self.body_angle_bounds_rad
        n_free = int(free_mask.sum())
        theta_var = None
        if n_free:
            theta_var = problem.variable(f"{P}body_angle", (1, n_free), unit="rad", scale=0.1, lower=lo_th,
                                         upper=hi_th, init=np.clip(theta_g[free_mask], lo_th, hi_th).reshape(1, -1),
                                         description="body (pitch) angle at the nodes",
                                         labels=[l for l, f in zip(labels, free_mask) if f])
        pieces, rate_pieces = [], []
        ifree = 0
        for g in self._segs:
            if g.kin.body_angle is None:
                th = theta_var[0, ifree:ifree + g.n]
                ifree += g.n
                D = ca.DM(Collocation(g.n).D)
                rate = ca.mtimes(th, D.T) / g.duration
            else:
                th0, thf = g.kin.body_angle
                if th0 is None:
                    th0 = pieces[-1][0, -1] if pieces else 0.0
                th = th0 + (thf - th0) * ca.DM(np.asarray(g.kin.s, float).reshape(1, -1))
                rate = (thf - th0) / g.duration * ca.DM.ones(1, g.n)
            pieces.append(th)
            rate_pieces.append(rate)
        if self.max_body_pitch_rate_radps is not None:
            self._limit_body_pitch(pieces)
        return ca.horzcat(*pieces), ca.horzcat(*rate_pieces), guess

    def _masked_unknown(self, problem, u, params, init, col):
        """An unknown that exists only at some nodes: where the segment parameter
        ``u.only_where`` is > 0 (zeros elsewhere: a free variable with no effect would
        leave the NLP singular), and, for ``u.hold_where_uncollocated``, not at a node
        whose derivative the collocation ignores (it takes the next node's value there)."""
        K, rows = self.K, int(u.rows)
        if u.only_where is not None and u.only_where not in params:
            raise InputError(f"unknown {u.name!r}.only_where", f"a segment parameter of the vehicle, got "
                                                               f"{u.only_where!r}")
        on = np.ones(K, bool) if u.only_where is None else \
            np.asarray(params[u.only_where], float).ravel() * np.ones(K) > 0.0
        owner = np.arange(K)            # the node whose variable each node reads
        if u.hold_where_uncollocated:   # a segment has >= 2 nodes: node0 + 1 is in the same one
            for k in self._uncollocated_nodes():
                if on[k + 1]:
                    owner[k] = k + 1
        active = np.flatnonzero(on)
        own = [int(k) for k in active if owner[k] == k]
        if not own:
            return ca.DM.zeros(rows, K)
        n = len(own)
        var = problem.variable(f"{self.prefix}{u.name}", (rows, n), unit=u.unit,
                               scale=np.broadcast_to(col(u.scale), (rows, n)),
                               lower=np.broadcast_to(col(u.lower), (rows, n)),
                               upper=np.broadcast_to(col(u.upper), (rows, n)),
                               init=init[:, own], description=u.description,
                               labels=[self.labels[k] for k in own])
        index = {k: i for i, k in enumerate(own)}
        cols = [int(k) for k in active]
        spread = ca.DM.triplet([index[int(owner[k])] for k in cols], cols, ca.DM.ones(len(cols)), n, K)
        return ca.densify(ca.mtimes(var, spread))

    def _control_continuity_and_rate(self, problem, u, row, params):
        """A control that takes over the segment parameter ``u.replaces`` where
        ``u.only_where`` > 0: equal values at every segment join (the last node of a
        segment and the first of the next are one instant), against the parameter where a
        neighbour keeps it prescribed; and |d(control)/dt| <= ``u.max_rate`` at every node
        of its segments and between them, ``+-(E u)_k / T - max_rate <= 0`` (``_rate_between_nodes``,
        T the segment's duration)."""
        if u.only_where is None or int(u.rows) != 1:
            raise InputError(f"unknown {u.name!r}", "replaces/max_rate need only_where and one row")
        if u.replaces is not None and u.replaces not in params:
            raise InputError(f"unknown {u.name!r}.replaces", f"a segment parameter of the vehicle, got "
                                                             f"{u.replaces!r}")
        on = np.asarray(params[u.only_where], float).ravel() * np.ones(self.K) > 0.0
        seg_on = [bool(on[g.node0]) for g in self._segs]
        if u.replaces is not None:
            fixed = np.asarray(params[u.replaces], float).ravel() * np.ones(self.K)
            value = lambda k: row[0, k] if on[k] else float(fixed[k])  # noqa: E731
            gaps, labels = [], []
            for i, (a, b) in enumerate(zip(self._segs[:-1], self._segs[1:])):
                if seg_on[i] or seg_on[i + 1]:
                    gaps.append(value(b.node0) - value(a.node0 + a.n - 1))
                    labels.append(f"{a.segment.name}/{b.segment.name}")
            if gaps:
                problem.constrain(f"{u.name} continuity", ca.vertcat(*gaps), scale=float(np.max(u.scale)),
                                  unit=u.unit, labels=labels)
        if u.max_rate is not None:
            self._rate_limit(f"{u.name} rate", [(g, row[0, g.node0:g.node0 + g.n]) for g, is_on in
                                                zip(self._segs, seg_on) if is_on],
                             float(u.max_rate), f"{u.unit}/s", ("rising", "falling"))

    def _uncollocated_nodes(self) -> list:
        """Nodes whose state derivative enters no defect: the first node of each segment
        in the differentiation form (its rows of D start at j = 1); none in the integration form."""
        return [g.node0 for g in self._segs] if self.state_form == "differentiation" else []

    def _rate_between_nodes(self, g, row):
        """The rate of a segment's row of node values (1 x n) at its nodes and between them
        (``Collocation.between_nodes``): ``(E row)_k / T`` with ``E`` the interpolant's derivative
        matrix there and T the duration; returns (1 x m rate, m labels)."""
        col, per = Collocation(g.n), 3
        s = col.between_nodes(per)
        rate = ca.mtimes(row, ca.DM(col.derivative_at(s)).T) / g.duration
        where = [self.labels[g.node0 + k // (per + 1)] if k % (per + 1) == 0 else f"{g.segment.name} s={x:.3f}"
                 for k, x in enumerate(s)]
        return rate, where

    def _rate_limit(self, name, rows, max_rate, unit, signs):
        """``+-(E row)_k / T - max_rate <= 0`` at the nodes of each ``(segment, 1 x n row)`` of
        ``rows`` and between them (``_rate_between_nodes``), as the group ``name``; ``signs`` name
        the two directions in the labels."""
        pieces, labels = [], []
        for g, row in rows:
            rate, where = self._rate_between_nodes(g, row)
            pieces += [rate - max_rate, -rate - max_rate]
            labels += [f"{w} {sign}" for sign in signs for w in where]
        if pieces:
            self.problem.constrain(name, ca.horzcat(*pieces), kind="<=", scale=max_rate, unit=unit,
                                   labels=labels)

    def _limit_body_pitch(self, theta_pieces):
        """The body's pitch rate limit (``Mission(max_body_pitch_rate_radps=...)``) at every node of
        the segments whose body angle is free and between them ("body pitch rate", ``_rate_limit``;
        ``theta_pieces``: per segment the body angle, 1 x n).  Within segments only: at a join the
        prescribed profile's acceleration or flight path angle steps (hover to the transition's
        0.2 g, a climb to level flight), and the point-mass mission turns the force there by
        stepping the attitude - a manoeuvre shorter than its nodes resolve; with the attitude and a
        tilt both held continuous the join node would have one force control for two equations."""
        rows = [(g, th) for g, th in zip(self._segs, theta_pieces) if g.kin.body_angle is None]
        self._rate_limit(f"{self.prefix}body pitch rate", rows, self.max_body_pitch_rate_radps, "rad/s",
                         ("nose-up", "nose-down"))
