"""DC motor (the paper's motor model: constant speed constant, winding resistance and
no-load current, as SUAVE's ``Motor`` component) and its sizing.

With ``Kv`` the speed constant in rad/s per volt (torque constant ``1/Kv`` in N m/A),
``R`` the winding resistance and ``I0`` the no-load current, at shaft torque ``Q``
and speed ``omega``::

    I = I0 + Kv Q                      current drawn                              (M1)
    V = omega / Kv + I R               terminal voltage (back-emf + resistive drop)   (M2)
    eta = Q omega / (V I)              efficiency                                  (M3)

All explicit in (Q, omega): the mission gets current, voltage and power at every
node with no unknown.  At a fixed terminal voltage the torque-speed line is

    omega = Kv (V - I0 R) - Kv^2 R Q                                              (M4)

and the efficiency at voltage V peaks at ``I* = sqrt(I0 V / R)`` with

    eta_max = (1 - sqrt(I0 R / V))^2.                                             (M5)

Sizing from a rating (``size_dc_motor``): rated shaft power ``P_r`` at rated speed
``omega_r`` (from the propeller: its design rpm) and rated terminal voltage
``V_r`` with efficiency ``eta_r`` there, a fraction ``f_cu`` of the losses being
copper (I^2 R) and the rest no-load (I0 x back-emf)::

    P_in = P_r/eta_r,  I_r = P_in/V_r,  L = P_in - P_r,
    R = f_cu L / I_r^2,  E_r = V_r - I_r R,  Kv = omega_r / E_r,  I0 = (1 - f_cu) L / E_r   (M6)

closed form and smooth, so the rated speed may be a design expression (a rotor
radius at a tip-Mach limit).  Defaults eta_r = 0.94 and f_cu = 0.6 place the peak
efficiency (M5) at 0.941, at 83 % of the rated current - inside the 85-95 % band of
electric aircraft motors of this size; SUAVE's X-57 model sizes its motors for
0.95 at the design point (``size_optimal_motor``).

Mass: NDARC's regression for high power-to-weight electric motors,
``W_lb = 0.3928 Q_max^0.8587`` with ``Q_max`` in ft lbf (Johnson, *NDARC - NASA
Design and Analysis of Rotorcraft, Theory*, Release 1.11, NASA 2017, p. 213, as
implemented in SUAVE's ``nasa_motor``), with ``Q_max = P_r / omega_r``.
"""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from ..core import units as u
from ..core.errors import check_positive, check_range
from ..core.smooth import xp

__all__ = ["DCMotor", "size_dc_motor", "motor_mass_ndarc_kg", "motor_current", "motor_voltage",
           "motor_function"]

NDARC_MOTOR_K_LB = 0.3928
NDARC_MOTOR_EXPONENT = 0.8587


def _symbolic(x) -> bool:
    return isinstance(x, (ca.SX, ca.MX))


def motor_mass_ndarc_kg(max_torque_Nm):
    """NDARC high-torque electric motor mass, kg, from the maximum torque in N m."""
    q_ftlb = max_torque_Nm / (u.FT * u.LBF)
    return NDARC_MOTOR_K_LB * q_ftlb ** NDARC_MOTOR_EXPONENT * u.LB


def motor_current(torque_Nm, kv_radps_per_V, no_load_current_A):
    """Eq. M1, A."""
    return no_load_current_A + kv_radps_per_V * torque_Nm


def motor_voltage(torque_Nm, omega_radps, kv_radps_per_V, resistance_ohm, no_load_current_A):
    """Eq. M2, V."""
    return omega_radps / kv_radps_per_V + motor_current(torque_Nm, kv_radps_per_V, no_load_current_A) * resistance_ohm


@dataclass(frozen=True)
class DCMotor:
    """A DC motor: ``kv_radps_per_V`` (rad/s/V), ``resistance_ohm``, ``no_load_current_A``;
    optional rating (``rated_power_W``, ``rated_speed_radps``, ``rated_voltage_V``) and
    ``mass_kg``.  Fields may be numbers or CasADi expressions (a sized motor whose
    rated speed is a design variable)."""

    kv_radps_per_V: object
    resistance_ohm: object
    no_load_current_A: object
    rated_power_W: object = None
    rated_speed_radps: object = None
    rated_voltage_V: object = None
    mass_kg: object = None

    @property
    def kv_rpm_per_V(self):
        return self.kv_radps_per_V / u.RPM

    @property
    def rated_torque_Nm(self):
        return self.rated_power_W / self.rated_speed_radps

    # ---------------------------------------------------------------- performance
    def current_A(self, torque_Nm):
        return motor_current(torque_Nm, self.kv_radps_per_V, self.no_load_current_A)

    def voltage_V(self, torque_Nm, omega_radps):
        return motor_voltage(torque_Nm, omega_radps, self.kv_radps_per_V, self.resistance_ohm,
                             self.no_load_current_A)

    def power_in_W(self, torque_Nm, omega_radps):
        return self.voltage_V(torque_Nm, omega_radps) * self.current_A(torque_Nm)

    def efficiency(self, torque_Nm, omega_radps):
        """Eq. M3 (for motoring: Q, omega > 0)."""
        return torque_Nm * omega_radps / self.power_in_W(torque_Nm, omega_radps)

    def torque_at_voltage_Nm(self, voltage_V, omega_radps):
        """Shaft torque at terminal voltage and speed (M1-M2 inverted): ((V - omega/Kv)/R - I0)/Kv."""
        i = (voltage_V - omega_radps / self.kv_radps_per_V) / self.resistance_ohm
        return (i - self.no_load_current_A) / self.kv_radps_per_V

    def speed_at_voltage_radps(self, voltage_V, torque_Nm):
        """Torque-speed line at fixed voltage (Eq. M4)."""
        return self.kv_radps_per_V * (voltage_V - self.current_A(torque_Nm) * self.resistance_ohm)

    def no_load_speed_radps(self, voltage_V):
        return self.kv_radps_per_V * (voltage_V - self.no_load_current_A * self.resistance_ohm)

    def stall_torque_Nm(self, voltage_V):
        return (voltage_V / self.resistance_ohm - self.no_load_current_A) / self.kv_radps_per_V

    def peak_efficiency(self, voltage_V):
        """(eta_max, current at eta_max) at terminal voltage ``voltage_V`` (Eq. M5)."""
        lib = xp(voltage_V, self.resistance_ohm, self.no_load_current_A)
        root = lib.sqrt(self.no_load_current_A * self.resistance_ohm / voltage_V)
        return (1.0 - root) ** 2, lib.sqrt(self.no_load_current_A * voltage_V / self.resistance_ohm)

    def function(self, name: str = "motor") -> ca.Function:
        """SX ``Function`` (torque_Nm, omega_radps) -> (current_A, voltage_V, power_in_W,
        shaft_power_W, efficiency) with this motor's constants (numbers) embedded."""
        return motor_function(name, self)


def motor_function(name: str = "motor", motor: DCMotor | None = None) -> ca.Function:
    """SX ``Function`` of Eqs. M1-M3.  With ``motor=None`` the constants are inputs
    (kv_radps_per_V, resistance_ohm, no_load_current_A) after torque and speed."""
    q, w = ca.SX.sym("torque_Nm"), ca.SX.sym("omega_radps")
    if motor is None:
        kv, r, i0 = ca.SX.sym("kv_radps_per_V"), ca.SX.sym("resistance_ohm"), ca.SX.sym("no_load_current_A")
        ins, names = [q, w, kv, r, i0], ["torque_Nm", "omega_radps", "kv_radps_per_V", "resistance_ohm",
                                           "no_load_current_A"]
    else:
        kv, r, i0 = motor.kv_radps_per_V, motor.resistance_ohm, motor.no_load_current_A
        ins, names = [q, w], ["torque_Nm", "omega_radps"]
    i = motor_current(q, kv, i0)
    v = w / kv + i * r
    return ca.Function(name, ins, [i, v, v * i, q * w, q * w / (v * i)], names,
                       ["current_A", "voltage_V", "power_in_W", "shaft_power_W", "efficiency"])


def size_dc_motor(rated_power_W, rated_speed_radps, rated_voltage_V, rated_efficiency=0.94,
                  copper_loss_fraction=0.6) -> DCMotor:
    """Size a DC motor from its rating (Eq. M6) and its mass (NDARC regression).

    Numbers are checked (``InputError`` naming the field); CasADi expressions pass
    through so that the rating can depend on design variables.
    """
    for name, value, unit in (("rated_power_W", rated_power_W, "W"),
                              ("rated_speed_radps", rated_speed_radps, "rad/s"),
                              ("rated_voltage_V", rated_voltage_V, "V")):
        if not _symbolic(value):
            check_positive(name, value, unit)
    if not _symbolic(rated_efficiency):
        check_range("rated_efficiency", rated_efficiency, 0.5, 0.99)
    if not _symbolic(copper_loss_fraction):
        check_range("copper_loss_fraction", copper_loss_fraction, 0.05, 0.95)
    p_in = rated_power_W / rated_efficiency
    i_r = p_in / rated_voltage_V
    loss = p_in - rated_power_W
    r = copper_loss_fraction * loss / i_r ** 2
    emf = rated_voltage_V - i_r * r
    kv = rated_speed_radps / emf
    i0 = (1.0 - copper_loss_fraction) * loss / emf
    return DCMotor(kv, r, i0, rated_power_W, rated_speed_radps, rated_voltage_V,
                   motor_mass_ndarc_kg(rated_power_W / rated_speed_radps))
