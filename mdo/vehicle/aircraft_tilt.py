"""A tilt-wing's wing-mounted angle at the mission nodes: the segments' schedule (Table 5) or,
with ``Aircraft(tilt="control")``, the ``wing_tilt`` control within the tilting wings' range and
rate.  A mixin of :class:`mdo.vehicle.aircraft.Aircraft` (it reads ``self.config`` and
``self.tilt``)."""
from __future__ import annotations

import math

import numpy as np

from ..core.errors import InputError
from .aircraft_nodes import _num, _row
from .base import Unknown

__all__ = ["WingTiltMixin"]


class WingTiltMixin:
    """The wing-mounted angle of :class:`~mdo.vehicle.aircraft.Aircraft` (module docstring)."""

    def _tilt_unknown(self):
        """The ``wing_tilt`` control: the tilting wings' common range and slowest rate."""
        tilting = [w for w in self.config.wings if w.tilting]
        lo = max(w.tilt_range_deg[0] for w in tilting)
        hi = min(w.tilt_range_deg[1] for w in tilting)
        if not lo < hi:
            raise InputError("tilt_range_deg", f"the tilting wings' ranges do not overlap ({lo:g} >= {hi:g} deg)")
        return Unknown("wing_tilt", unit="rad", scale=0.5, lower=math.radians(lo), upper=math.radians(hi),
                       only_where="wing_tilt_control", replaces="wing_mounted_angle_rad",
                       max_rate=math.radians(min(w.max_tilt_rate_degps for w in tilting)),
                       description=f"wing-mounted angle of the tilting wings ({lo:g} to {hi:g} deg)")

    @staticmethod
    def scheduled_wing_angle(parameters, K) -> np.ndarray:
        """The segments' wing-mounted angle at every node (rad, numbers, K)."""
        return _num(parameters.get("wing_mounted_angle_rad", _row(0.0, K))).ravel() * np.ones(K)

    def tilt_control_nodes(self, parameters, K) -> np.ndarray:
        """Nodes where the wing-mounted angle is the ``wing_tilt`` control (bool, K)."""
        if self.tilt != "control":
            return np.zeros(K, bool)
        return _num(parameters.get("wing_tilt_control", _row(0.0, K))).ravel() * np.ones(K) > 0.0

    def wing_mounted_angle(self, parameters, unknowns, K):
        """The wing-mounted angle at every node (rad, 1 x K): the segments' schedule, or the
        ``wing_tilt`` control at the nodes of ``tilt_control_nodes``."""
        wma = parameters.get("wing_mounted_angle_rad", _row(0.0, K))
        on = self.tilt_control_nodes(parameters, K)
        if not on.any():
            return wma
        return unknowns["wing_tilt"] + _row(1.0 - on) * wma

    def rotor_axis_angle(self, gm, wma):
        """Angle of a group's thrust axis above the body x axis: the wing-mounted angle if its wing tilts."""
        return wma if gm.tilting else 0.0 * wma

