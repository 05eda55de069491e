"""Figures and tables of the powertrain models (``mdo battery report --out DIR``).

Writes into DIR: ``discharge_fit.png`` (model vs measured curves, 0-50 deg C, 2-8 A),
``discharge_residuals.png``, ``fit_errors.md`` (RMS/max voltage error per current and
per curve, cut-off capacities), ``motors.png`` (efficiency vs torque and the
torque-speed lines of the paper's three motors) and ``balance.md`` (network balance
over throttle 0.1-1 for GA-2P, GA-8P, TTW).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..core import units as u

__all__ = ["write_report"]

_COLORS = {2.0: "tab:blue", 4.0: "tab:orange", 6.0: "tab:green", 8.0: "tab:red"}


def _model_curve(cell, current_A, ambient_C, v_end):
    s = np.linspace(1.0, -0.05, 400)
    v = cell.voltage(s, current_A, ambient_C)
    keep = v >= v_end - 1e-9
    s, v = s[keep], v[keep]
    return (1.0 - s) * cell.usable_capacity_Ah(ambient_C), v


def plot_discharge_fit(path, cell=None, curves=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from .cell import load_discharge_data, nmc18650
    cell = cell or nmc18650()
    curves = curves or load_discharge_data()
    temps = sorted({c["ambient_C"] for c in curves})
    fig, axes = plt.subplots(2, 3, figsize=(14, 8), sharex=True, sharey=True)
    for ax, T in zip(axes.flat, temps):
        for c in (c for c in curves if c["ambient_C"] == T):
            I = c["current_A"]
            ax.plot(c["capacity_Ah"], c["voltage_V"], "o", ms=3.5, color=_COLORS[I], label=f"{I:g} A measured")
            q, v = _model_curve(cell, I, T, c["voltage_V"][-1])
            ax.plot(q, v, "-", lw=1.4, color=_COLORS[I], label=f"{I:g} A model")
        ax.set_title(f"ambient {T:g} deg C")
        ax.grid(alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("discharged capacity (Ah)")
    for ax in axes[:, 0]:
        ax.set_ylabel("cell voltage (V)")
    axes.flat[0].legend(fontsize=7, ncol=2)
    fig.suptitle("18650 NMC cell: model V = U(s) - I R(s,T) - A(s,T) asinh(I/1A) vs measured discharge "
                 "(Panasonic NCR18650G data via SUAVE)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_residuals(path, cell=None, curves=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from .cell import load_discharge_data, nmc18650
    cell = cell or nmc18650()
    curves = curves or load_discharge_data()
    temps = sorted({c["ambient_C"] for c in curves})
    fig, axes = plt.subplots(2, 3, figsize=(14, 7), sharex=True, sharey=True)
    for ax, T in zip(axes.flat, temps):
        for c in (c for c in curves if c["ambient_C"] == T):
            s = cell.soc_from_charge(c["capacity_Ah"], T)
            e = 1e3 * (cell.voltage(s, c["current_A"], T) - c["voltage_V"])
            ax.plot(s, e, "o-", ms=3, lw=0.8, color=_COLORS[c["current_A"]], label=f"{c['current_A']:g} A")
        ax.axvline(0.2, color="k", lw=0.6, ls=":")
        ax.set_title(f"ambient {T:g} deg C")
        ax.grid(alpha=0.3)
        ax.invert_xaxis()
    for ax in axes[-1]:
        ax.set_xlabel("state of charge s")
    for ax in axes[:, 0]:
        ax.set_ylabel("model - measured (mV)")
    axes.flat[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def fit_errors_markdown(cell=None) -> str:
    from .cell import nmc18650
    from .cell_fit import error_table
    cell = cell or nmc18650()
    err = error_table(cell)
    lines = ["# NMC 18650 cell model: voltage error against the measured discharge curves", "",
             "Model `V = U(s) - I R(s,T) - A(s,T) asinh(I/1 A)` (mdo/powertrain/cell.py), 32 coefficients, "
             "fitted once to all 24 curves (2, 4, 6, 8 A x 0..50 deg C ambient; the file's `Amps_0` "
             "curves are copies of `Amps_2` and are not used). Errors are model minus measured.", "",
             "| current | RMS, all points (mV) | max (mV) | RMS, s >= 0.2 (mV) | max, s >= 0.2 (mV) | points |",
             "|---|---|---|---|---|---|"]
    for k, e in err["per_current"].items():
        e2 = err["per_current_soc_ge_0.2"][k]
        lines.append(f"| {k} A | {e['rms_mV']:.1f} | {e['max_mV']:.0f} | {e2['rms_mV']:.1f} | {e2['max_mV']:.0f} | {e['points']} |")
    a, a2 = err["all"], err["all_soc_ge_0.2"]
    lines.append(f"| all | {a['rms_mV']:.1f} | {a['max_mV']:.0f} | {a2['rms_mV']:.1f} | {a2['max_mV']:.0f} | {a['points']} |")
    lines += ["", "Per curve (capacity at the last measured voltage: measured vs model; a model value "
              "of 1.05 Q_u means the model does not reach that voltage above s = -0.05):", "",
              "| current | ambient | RMS (mV) | max (mV) | cut-off capacity measured (Ah) | model (Ah) |",
              "|---|---|---|---|---|---|"]
    for c in err["per_curve"]:
        lines.append(f"| {c['current_A']:g} A | {c['ambient_C']:g} C | {c['rms_mV']:.1f} | {c['max_mV']:.0f} | "
                     f"{c['cutoff_capacity_measured_Ah']:.3f} | {c['cutoff_capacity_model_Ah']:.3f} |")
    return "\n".join(lines) + "\n"


def plot_motors(path, powertrains: dict):
    """Efficiency and torque-speed lines of each powertrain's motor (name -> Powertrain)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from .network import propeller_torque_law
    n = len(powertrains)
    fig, axes = plt.subplots(2, n, figsize=(5 * n, 8), squeeze=False)
    for col, (name, pt) in enumerate(powertrains.items()):
        m = pt.motor
        law = propeller_torque_law(m.rated_torque_Nm, m.rated_speed_radps)
        q = np.linspace(0.005, 1.6, 400) * m.rated_torque_Nm
        for frac in (1.0, 0.75, 0.5):
            V = frac * m.rated_voltage_V
            w = m.speed_at_voltage_radps(V, q)
            ok = w > 0
            axes[0, col].plot(q[ok], m.efficiency(q[ok], w[ok]), label=f"{V:.0f} V")
            axes[1, col].plot(q, w / u.RPM, label=f"{V:.0f} V")
            eta_max, i_star = m.peak_efficiency(V)
            q_star = (i_star - m.no_load_current_A) / m.kv_radps_per_V
            axes[0, col].plot([q_star], [eta_max], "k.", ms=6)
        wl = np.linspace(0.0, 1.1, 100) * m.rated_speed_radps
        axes[1, col].plot(law(wl), wl / u.RPM, "k:", label="propeller load Q ~ omega^2")
        axes[1, col].plot([m.rated_torque_Nm], [m.rated_speed_radps / u.RPM], "ks", ms=5, label="rated point")
        axes[0, col].axhspan(0.85, 0.95, color="0.92", zorder=0)
        axes[0, col].set_ylim(0.6, 1.0)
        axes[0, col].set_title(f"{name}: {m.rated_power_W / 1e3:g} kW, Kv {m.kv_rpm_per_V:.2f} rpm/V, "
                               f"R {1e3 * m.resistance_ohm:.0f} mOhm, I0 {m.no_load_current_A:.1f} A, "
                               f"{m.mass_kg:.1f} kg", fontsize=9)
        axes[0, col].set_ylabel("efficiency")
        axes[1, col].set_ylabel("speed (rpm)")
        axes[1, col].set_xlabel("shaft torque (N m)")
        axes[1, col].set_ylim(0, None)
        for ax in axes[:, col]:
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7)
    fig.suptitle("DC motors at the vehicle definitions' ratings (efficiency 0.94, 60 % copper losses at the rated point; rated "
                 "voltage 0.9 x pack nominal). Dots: peak efficiency (Eq. M5); bottom: torque-speed lines (Eq. M4)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def balance_markdown(powertrains: dict) -> str:
    """The network balance over throttle of each powertrain (name -> Powertrain)."""
    from .network import propeller_torque_law
    th = np.linspace(0.1, 1.0, 10)
    lines = ["# Network balance over throttle (propeller load Q = Q_r (omega/omega_r)^2, s = 0.9, 25 deg C)", "",
             "Solved by nested bisection; Newton from a cold start (omega = half no-load speed, I_b = 0) "
             "converges to the same point (tests/test_powertrain_network.py).", ""]
    for name, pt in powertrains.items():
        m = pt.motor
        b = pt.balance(th, propeller_torque_law(m.rated_torque_Nm, m.rated_speed_radps), soc=0.9)
        n = pt.balance(th, propeller_torque_law(m.rated_torque_Nm, m.rated_speed_radps), soc=0.9, method="newton")
        lines += [f"## {name}: {pt.n_motors} x {m.rated_power_W / 1e3:g} kW, Kv {m.kv_rpm_per_V:.3f} rpm/V, "
                  f"R {1e3 * m.resistance_ohm:.1f} mOhm, I0 {m.no_load_current_A:.2f} A, motor {m.mass_kg:.1f} kg; "
                  f"pack {pt.pack.n_series:g}s x {pt.pack.n_parallel:g}p, {pt.pack.mass_kg:.0f} kg", "",
                  "| throttle | rpm | shaft kW/motor | motor eta | bus kW | pack V | pack A | cell A | Newton iter |",
                  "|---|---|---|---|---|---|---|---|---|"]
        for k, t in enumerate(th):
            lines.append(f"| {t:.1f} | {b['omega_radps'][k] / u.RPM:.0f} | {b['shaft_power_W'][k] / 1e3:.2f} | "
                         f"{b['motor_efficiency'][k]:.3f} | {b['bus_power_W'][k] / 1e3:.1f} | "
                         f"{b['pack_voltage_V'][k]:.1f} | {b['battery_current_A'][k]:.1f} | "
                         f"{b['cell_current_A'][k]:.2f} | {int(n['iterations'][k])} |")
        lines.append("")
    return "\n".join(lines)


def write_report(out_dir, powertrains: dict) -> list:
    """The cell fit against the measured curves, and the motors and network balance of
    ``powertrains`` (name -> :class:`~mdo.powertrain.Powertrain`, e.g. a vehicle
    definition's ``VehicleConfig.powertrain()``)."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    files = [out / "discharge_fit.png", out / "discharge_residuals.png", out / "fit_errors.md",
             out / "motors.png", out / "balance.md"]
    plot_discharge_fit(files[0])
    plot_residuals(files[1])
    files[2].write_text(fit_errors_markdown())
    plot_motors(files[3], powertrains)
    files[4].write_text(balance_markdown(powertrains))
    return files
