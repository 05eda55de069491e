"""Electronic speed controller: a constant-efficiency DC-DC stage.

The ESC chops the bus voltage down to the motor voltage (duty cycle = throttle)::

    throttle = V_motor / V_bus              (<= 1 is a constraint of the mission)   (E1)
    P_in = P_out + (1/eta - 1) sqrt(P_out^2 + w^2)                                   (E2)

Eq. E2 is ``P_out / eta`` for motoring (error < (1/eta - 1) w^2 / (2 P_out)) and
``P_out (2 - 1/eta)`` for regeneration, so power never grows through the ESC in
either direction; ``w`` (default 100 W) rounds the corner at zero power (error at
P_out = 0: (1/eta - 1) w = 5.3 W at eta = 0.95).  A smooth form of
``P_out + (1/eta - 1)|P_out|``.  Efficiency 0.95 as in SUAVE's X-57 Mod II model
(``esc.efficiency = 0.95``).
"""
from __future__ import annotations

from ..core.smooth import smooth_abs

__all__ = ["ESC_EFFICIENCY", "ESC_SMOOTHING_W", "esc_input_power_W"]

ESC_EFFICIENCY = 0.95
ESC_SMOOTHING_W = 100.0


def esc_input_power_W(output_power_W, efficiency=ESC_EFFICIENCY, smoothing_W=ESC_SMOOTHING_W):
    """Eq. E2: power drawn from the bus for ``output_power_W`` delivered to the motor."""
    return output_power_W + (1.0 / efficiency - 1.0) * smooth_abs(output_power_W, smoothing_W)
