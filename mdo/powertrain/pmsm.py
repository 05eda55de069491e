"""Permanent-magnet synchronous motor (PMSM) and its inverter, from their losses.

Same node-level role as :class:`mdo.powertrain.motor.DCMotor`: given the shaft torque ``Q``
(N m) and speed ``omega`` (rad/s) of one rotor (and the bus voltage), everything is explicit.
The machine is written in DC-bus-equivalent quantities (field-oriented control, q-axis
current only, torque constant ``Kt`` N m/A = back-emf constant V s/rad)::

    Q_loss = (k_h + k_f) tanh(omega/w) + k_e omega + k_w omega sqrt(omega^2 + w^2)    (P1)
    Q_em   = Q + Q_loss                   electromagnetic torque                     (P2)
    I      = Q_em / Kt                    current                                   (P3)
    V_m    = Kt omega + I R               terminal voltage                          (P4)
    P_in   = V_m I = Q omega + P_fe + P_fw + P_cu                                   (P5)

with the losses, each >= 0 for any sign of omega (w = 1 rad/s rounds the sign at rest):

* copper ``P_cu = I^2 R``;
* iron (Steinmetz-type loss separation, Bertotti, IEEE Trans. Magn. 24(1), 1988): hysteresis
  ``P_h = k_h omega`` (per cycle loss constant, frequency ~ omega) and eddy current
  ``P_e = k_e omega^2``;
* friction (bearings, ~ omega) ``P_f = k_f omega`` and windage ``P_w = k_w omega^3``.

Eq. P5 is exact energy conservation: ``P_in - Q omega`` is the sum of the four losses.

Sizing (``size_pmsm``) from the rating ``P_r`` at ``omega_r`` and the bus voltage ``V_r``,
placing the peak efficiency ``eta_pk`` at torque ``Q* = lambda Q_r`` on the rated-speed line.
At fixed speed with speed losses ``P0 = Q0 omega_r`` and ``c = R/Kt^2`` the efficiency
``Q omega/(Q omega + P0 + c (Q + Q0)^2)`` is stationary where ``P0 = c (Q^2 - Q0^2)``; with
the total loss ``L = (1/eta_pk - 1) Q* omega_r`` there, closed form::

    P0 = (L/2) / (1 + L/(2 Q* omega_r)),   Q0 = P0/omega_r,   c = L / (2 Q* (Q* + Q0))     (P6)
    Kt = h V_r / (omega_r + c Q_em,r),    R = c Kt^2                                      (P7)

``h`` (default 0.9) is the voltage headroom at the rated point (V_m = h V_r, as the DC motor
of ``motor.py``).  ``P0`` is split into iron (fraction ``iron_fraction``, default 0.75;
high-pole-count aircraft machines are iron-loss dominated at speed) and friction + windage,
each halved between its two speed laws at the rated speed (stated assumptions).
Defaults ``eta_pk = 0.96`` at ``lambda = 0.5``: aircraft PMSMs peak at 0.95-0.97 - SUAVE's
X-57 model sizes its cruise motors for 0.95 at the design point; the X-57's Joby cruise
motor is reported at about 96 % at cruise and Siemens' SP260D at 95 %+ (figures quoted in
issue 17, not re-checked against a primary source here).  Propeller motors are rated for
take-off and climb and cruise at 40-60 % of that torque, where designers put the peak.

Mass: specific power of the class, default 5 kW/kg (Siemens SP260D: 260 kW continuous,
50 kg, i.e. 5.2 kW/kg; Siemens press release on the Extra 330LE first flight, 2016,
as reported by tradeflights.com).

Inverter (``Inverter``, ``size_inverter``): bus current ``I`` equal to the motor current
in this DC-equivalent model; losses

    P_inv = P_0 + v_0 |I| + r_on I^2 + k_sw V_bus |I|                                   (P8)

gate-drive / control (P_0), conduction (threshold v_0 and on-resistance r_on, ~ I and I^2)
and switching (~ V I f_sw, lumped into k_sw).  At fixed bus voltage the efficiency peaks at
``I* = sqrt(P_0/r_on)``; ``size_inverter`` puts it at ``lambda_inv`` of the rated current
with ``eta_inv,pk`` (default 0.985), the linear terms (conduction threshold + switching,
split ``switching_share``) taking ``linear_fraction`` (0.6) of the loss there.  Inverters
for aircraft reach 0.97-0.99: the X-57's SiC cruise motor controllers 98 % at take-off
and cruise (NASA, reported by gkseries.com, 2023).  |I| is ``sqrt(I^2 + w_I^2)`` with
``w_I`` = 0.5 % of the rated current (error P_0-scale watts at zero current).
Inverter mass: 10 kW/kg (our assumption for an air-cooled SiC unit of 50-100 kW).

Limits at a node (``drive_node``): torque ratio ``Q/Q_max``, speed ratio ``omega/omega_max``,
power ratio ``Q omega/P_r`` and the voltage ratio ``V_m/V_bus`` (the throttle), each <= 1.

API::

    m = size_pmsm(52.7e3, 1665 * RPM, 432.0)           # PMSM, numbers or CasADi ratings
    inv = size_inverter(52.7e3 / 0.96, 432.0)
    out = drive_node(m, inv, Q, omega, V_bus)          # dict of node quantities (any kind)
    f = drive_function(m, inv)                          # SX Function (Q, omega, V_bus) -> ...
    plot_efficiency_map(m, inv, "results/powertrain/pmsm_map.png")
"""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..core.errors import check_positive, check_range
from ..core.smooth import xp

__all__ = ["PMSM", "Inverter", "size_pmsm", "size_inverter", "drive_node", "drive_function",
           "efficiency_map", "plot_efficiency_map", "DRIVE_OUTPUTS",
           "MOTOR_SPECIFIC_POWER_W_PER_KG", "INVERTER_SPECIFIC_POWER_W_PER_KG"]

MOTOR_SPECIFIC_POWER_W_PER_KG = 5.0e3     # Siemens SP260D class (5.2 kW/kg)
INVERTER_SPECIFIC_POWER_W_PER_KG = 10.0e3  # assumption, air-cooled SiC
SPEED_WIDTH_RADPS = 1.0                    # w in Eq. P1


def _sym(x) -> bool:
    return isinstance(x, (ca.SX, ca.MX))


@dataclass(frozen=True)
class PMSM:
    """Loss-model PMSM (Eqs. P1-P5).  Fields may be numbers or CasADi expressions.

    kt_Nm_per_A, resistance_ohm; loss coefficients hysteresis_Nm (k_h, W per rad/s),
    eddy_Nms (k_e, W/(rad/s)^2), friction_Nm (k_f), windage_Nms2 (k_w, W/(rad/s)^3);
    rating and limits: rated_power_W, rated_speed_radps, rated_voltage_V, max_torque_Nm,
    max_speed_radps; mass_kg.
    """
    kt_Nm_per_A: object
    resistance_ohm: object
    hysteresis_Nm: object
    eddy_Nms: object
    friction_Nm: object
    windage_Nms2: object
    rated_power_W: object = None
    rated_speed_radps: object = None
    rated_voltage_V: object = None
    max_torque_Nm: object = None
    max_speed_radps: object = None
    mass_kg: object = None

    @property
    def rated_torque_Nm(self):
        return self.rated_power_W / self.rated_speed_radps

    def loss_torque_Nm(self, omega):
        """Eq. P1: the drag torque of iron, friction and windage losses."""
        lib = xp(omega)
        w = SPEED_WIDTH_RADPS
        return (self.hysteresis_Nm + self.friction_Nm) * lib.tanh(omega / w) + self.eddy_Nms * omega \
            + self.windage_Nms2 * omega * lib.sqrt(omega * omega + w * w)

    def current_A(self, torque_Nm, omega):
        return (torque_Nm + self.loss_torque_Nm(omega)) / self.kt_Nm_per_A

    def voltage_V(self, torque_Nm, omega):
        return self.kt_Nm_per_A * omega + self.current_A(torque_Nm, omega) * self.resistance_ohm

    def losses_W(self, torque_Nm, omega):
        """Each loss (W): copper, hysteresis, eddy, friction, windage."""
        lib = xp(omega)
        w = SPEED_WIDTH_RADPS
        i = self.current_A(torque_Nm, omega)
        sgn_w = omega * lib.tanh(omega / w)         # smooth |omega|
        return {"copper_W": i * i * self.resistance_ohm,
                "hysteresis_W": self.hysteresis_Nm * sgn_w,
                "eddy_W": self.eddy_Nms * omega * omega,
                "friction_W": self.friction_Nm * sgn_w,
                "windage_W": self.windage_Nms2 * omega * omega * lib.sqrt(omega * omega + w * w)}

    def power_in_W(self, torque_Nm, omega):
        return self.voltage_V(torque_Nm, omega) * self.current_A(torque_Nm, omega)

    def efficiency(self, torque_Nm, omega):
        """Q omega / P_in: < 1 wherever the losses are > 0, -> 0 as Q -> 0 (motoring)."""
        return torque_Nm * omega / self.power_in_W(torque_Nm, omega)


@dataclass(frozen=True)
class Inverter:
    """Loss-model inverter (Eq. P8): fixed_W, v0_V, r_on_ohm, k_sw (W per V A), current width."""
    fixed_W: object
    v0_V: object
    r_on_ohm: object
    k_sw: object
    current_width_A: object = 1.0
    rated_power_W: object = None
    rated_voltage_V: object = None
    mass_kg: object = None

    def losses_W(self, current_A, bus_voltage_V):
        i_abs = xp(current_A).sqrt(current_A * current_A + self.current_width_A ** 2)
        return {"fixed_W": self.fixed_W + 0 * current_A, "conduction_W": self.v0_V * i_abs
                + self.r_on_ohm * current_A * current_A,
                "switching_W": self.k_sw * bus_voltage_V * i_abs}

    def power_in_W(self, power_out_W, current_A, bus_voltage_V):
        lo = self.losses_W(current_A, bus_voltage_V)
        return power_out_W + lo["fixed_W"] + lo["conduction_W"] + lo["switching_W"]


def _check_rating(**kw):
    for name, (value, unit) in kw.items():
        if not _sym(value):
            check_positive(name, value, unit)


def size_pmsm(rated_power_W, rated_speed_radps, rated_voltage_V, peak_efficiency=0.96,
              peak_load_fraction=0.5, iron_fraction=0.75, voltage_headroom=0.9,
              max_torque_factor=1.0, max_speed_factor=1.2,
              specific_power_W_per_kg=MOTOR_SPECIFIC_POWER_W_PER_KG) -> PMSM:
    """Size a PMSM from its rating (Eqs. P6-P7); see the module doc for every default."""
    _check_rating(rated_power_W=(rated_power_W, "W"), rated_speed_radps=(rated_speed_radps, "rad/s"),
                  rated_voltage_V=(rated_voltage_V, "V"))
    check_range("peak_efficiency", peak_efficiency, 0.80, 0.995)
    check_range("peak_load_fraction", peak_load_fraction, 0.1, 1.0)
    check_range("iron_fraction", iron_fraction, 0.0, 1.0)
    check_range("voltage_headroom", voltage_headroom, 0.5, 1.0)
    check_range("max_torque_factor", max_torque_factor, 1.0, 3.0)
    check_range("max_speed_factor", max_speed_factor, 1.0, 3.0)
    w_r = rated_speed_radps
    q_r = rated_power_W / w_r
    q_pk = peak_load_fraction * q_r
    loss = (1.0 / peak_efficiency - 1.0) * q_pk * w_r
    p0 = 0.5 * loss / (1.0 + loss / (2.0 * q_pk * w_r))            # Eq. P6
    q0 = p0 / w_r
    c = loss / (2.0 * q_pk * (q_pk + q0))
    kt = voltage_headroom * rated_voltage_V / (w_r + c * (q_r + q0))  # Eq. P7
    p_fe, p_fw = iron_fraction * p0, (1.0 - iron_fraction) * p0
    return PMSM(kt, c * kt * kt, 0.5 * p_fe / w_r, 0.5 * p_fe / w_r ** 2, 0.5 * p_fw / w_r,
                0.5 * p_fw / w_r ** 3, rated_power_W, w_r, rated_voltage_V,
                max_torque_factor * q_r, max_speed_factor * w_r,
                rated_power_W / specific_power_W_per_kg)


def size_inverter(rated_power_W, rated_voltage_V, peak_efficiency=0.985, peak_load_fraction=0.5,
                  linear_fraction=0.6, switching_share=0.5, voltage_headroom=0.9,
                  specific_power_W_per_kg=INVERTER_SPECIFIC_POWER_W_PER_KG) -> Inverter:
    """Size the inverter (Eq. P8) for output ``rated_power_W`` at bus ``rated_voltage_V``:
    efficiency ``peak_efficiency`` at ``peak_load_fraction`` of the rated current, the
    output (motor) voltage being ``voltage_headroom`` of the bus as in ``size_pmsm``."""
    _check_rating(rated_power_W=(rated_power_W, "W"), rated_voltage_V=(rated_voltage_V, "V"))
    check_range("peak_efficiency", peak_efficiency, 0.90, 0.999)
    check_range("peak_load_fraction", peak_load_fraction, 0.1, 1.0)
    check_range("linear_fraction", linear_fraction, 0.0, 0.95)
    check_range("switching_share", switching_share, 0.0, 1.0)
    check_range("voltage_headroom", voltage_headroom, 0.5, 1.0)
    v_out = voltage_headroom * rated_voltage_V
    i_r = rated_power_W / v_out
    i_pk = peak_load_fraction * i_r
    loss = (1.0 / peak_efficiency - 1.0) * v_out * i_pk
    lin = linear_fraction * loss / i_pk           # v0 + k_sw V_bus, volts
    p_fixed = 0.5 * (1.0 - linear_fraction) * loss  # = r_on I*^2 at the peak
    return Inverter(p_fixed, (1.0 - switching_share) * lin, p_fixed / i_pk ** 2,
                    switching_share * lin / rated_voltage_V, 0.005 * i_r, rated_power_W,
                    rated_voltage_V, rated_power_W / specific_power_W_per_kg)


DRIVE_OUTPUTS = ("motor_current_A", "motor_voltage_V", "shaft_power_W", "motor_power_in_W",
                 "bus_power_W", "motor_loss_W", "inverter_loss_W", "motor_efficiency",
                 "inverter_efficiency", "drive_efficiency", "torque_ratio", "speed_ratio",
                 "power_ratio", "voltage_ratio")


def drive_node(motor: PMSM, inverter: Inverter, torque_Nm, omega_radps, bus_voltage_V=None) -> dict:
    """Motor + inverter at nodes (elementwise, any array kind); keys ``DRIVE_OUTPUTS`` plus
    each loss.  ``bus_voltage_V`` defaults to the motor's rated voltage."""
    v_bus = motor.rated_voltage_V if bus_voltage_V is None else bus_voltage_V
    i = motor.current_A(torque_Nm, omega_radps)
    v_m = motor.voltage_V(torque_Nm, omega_radps)
    p_shaft = torque_Nm * omega_radps
    p_m = v_m * i
    inv = inverter.losses_W(i, v_bus)
    p_bus = p_m + inv["fixed_W"] + inv["conduction_W"] + inv["switching_W"]
    out = {"motor_current_A": i, "motor_voltage_V": v_m, "shaft_power_W": p_shaft,
           "motor_power_in_W": p_m, "bus_power_W": p_bus, "motor_loss_W": p_m - p_shaft,
           "inverter_loss_W": p_bus - p_m, "motor_efficiency": p_shaft / p_m,
           "inverter_efficiency": p_m / p_bus, "drive_efficiency": p_shaft / p_bus,
           "torque_ratio": torque_Nm / motor.max_torque_Nm,
           "speed_ratio": omega_radps / motor.max_speed_radps,
           "power_ratio": p_shaft / motor.rated_power_W, "voltage_ratio": v_m / v_bus}
    out.update({f"motor_{k}": v for k, v in motor.losses_W(torque_Nm, omega_radps).items()})
    out.update({f"inverter_{k}": v for k, v in inv.items()})
    return out


def drive_function(motor: PMSM, inverter: Inverter, name: str = "pmsm_drive") -> ca.Function:
    """SX ``Function`` (torque_Nm, omega_radps, bus_voltage_V) -> ``DRIVE_OUTPUTS``."""
    q, w, v = ca.SX.sym("torque_Nm"), ca.SX.sym("omega_radps"), ca.SX.sym("bus_voltage_V")
    out = drive_node(motor, inverter, q, w, v)
    return ca.Function(name, [q, w, v], [out[k] for k in DRIVE_OUTPUTS],
                       ["torque_Nm", "omega_radps", "bus_voltage_V"], list(DRIVE_OUTPUTS))


def efficiency_map(motor: PMSM, inverter: Inverter, n_speed=61, n_torque=61, bus_voltage_V=None):
    """(rpm grid, torque grid N m, motor eta, drive eta, voltage ratio) on 5-100 % of the
    speed and torque limits; points above the voltage limit are kept (mask with the ratio)."""
    w = np.linspace(0.05, 1.0, n_speed) * float(motor.max_speed_radps)
    q = np.linspace(0.02, 1.0, n_torque) * float(motor.max_torque_Nm)
    W, Q = np.meshgrid(w, q)
    out = drive_node(motor, inverter, Q, W, bus_voltage_V)
    return W * 60 / (2 * np.pi), Q, out["motor_efficiency"], out["drive_efficiency"], out["voltage_ratio"]


def plot_efficiency_map(motor: PMSM, inverter: Inverter, path, title="PMSM + inverter", points=None):
    """Write the efficiency map (motor and motor+inverter over torque-speed) to ``path``.

    ``points``: optional {label: (rpm, torque_Nm)} operating points to mark.  Returns path.
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rpm, q, eta_m, eta_d, vr = efficiency_map(motor, inverter)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4), sharey=True)
    levels = [0.70, 0.80, 0.85, 0.88, 0.90, 0.92, 0.93, 0.94, 0.95, 0.96, 0.97]
    for ax, eta, lab in ((axes[0], eta_m, "motor"), (axes[1], eta_d, "motor + inverter")):
        shown = np.where(vr <= 1.0, eta, np.nan)
        cf = ax.contourf(rpm, q, shown, levels=[0.5] + levels + [1.0], cmap="viridis")
        cs = ax.contour(rpm, q, shown, levels=levels, colors="k", linewidths=0.5)
        ax.clabel(cs, fmt="%.2f", fontsize=7)
        k = np.nanargmax(shown)
        ax.plot(rpm.flat[k], q.flat[k], "r*", ms=10, label=f"peak {np.nanmax(shown):.3f}")
        ax.plot(float(motor.rated_speed_radps) * 60 / (2 * np.pi), float(motor.rated_torque_Nm), "wo",
                mec="k", label="rated point")
        for name, (r, t) in (points or {}).items():
            ax.plot(r, t, "s", mfc="none", mec="w", ms=8)
            ax.annotate(name, (r, t), color="w", fontsize=8, xytext=(4, 4), textcoords="offset points")
        ax.set_title(f"{lab} efficiency")
        ax.set_xlabel("speed (rpm)")
        ax.legend(loc="lower right", fontsize=8)
    axes[0].set_ylabel("shaft torque (N m)")
    fig.suptitle(title)
    fig.colorbar(cf, ax=axes, shrink=0.9, label="efficiency")
    fig.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(fig)
    return path


def _ga2p_map(path="results/powertrain/pmsm_map.png"):
    """The GA-2P motor's map (rating from the catalog: 52.7 kW at the propeller design rpm,
    on the pack's nominal voltage).  ``python -m mdo.powertrain.pmsm``."""
    from ..vehicle.catalog import ga2p
    cfg = ga2p()
    g = cfg.rotor_groups[0]
    w_r = g.design_rpm * 2 * np.pi / 60
    v_bus = float(cfg.battery.pack().nominal_voltage_V)
    m = size_pmsm(g.motor_rated_power_W, w_r, v_bus)
    inv = size_inverter(g.motor_rated_power_W / 0.96, v_bus)
    q_r = float(m.rated_torque_Nm)
    pts = {"36 % load": (g.design_rpm, 0.36 * q_r)}
    plot_efficiency_map(m, inv, path, title=f"GA-2P {g.motor_rated_power_W / 1e3:.1f} kW", points=pts)
    return path, m, inv


if __name__ == "__main__":
    print(_ga2p_map()[0])
