"""The electric network: battery pack -> ESCs -> identical DC motors -> rotors.

All motors of a rotor group are identical, wired in parallel on the bus and equally
throttled (the paper, Sec. II).  At one mission node, for the shaft torque ``Q`` and
speed ``omega`` of one rotor (from the BEMT), everything is explicit except the
battery current::

    I_m, V_m                 = motor(Q, omega)                 Eqs. M1-M2 (explicit)
    P_esc                    = esc_in(V_m I_m)                 Eq. E2     (explicit)
    P_bus                    = n_motors P_esc + P_aux          avionics + payload
    V_pack(s, I_b) I_b - P_bus = 0                             the ONE unknown I_b   (N1)
    throttle = V_m / V_pack(s, I_b) <= 1                       Eq. E1
    ds/dt    = -I_b / (N_p Q_u(T))                             the collocated state  (N2)

Why the battery current is the unknown: the terminal voltage depends on the current
(Eq. C1), so the current that delivers a power is the root of Eq. N1 - implicit.
Making ``I_b`` an NLP variable per node (scale ``current_scale_A``, residual scale
``power_scale_W``) keeps every expression explicit and the Jacobian sparse (one
node's residual depends on that node's Q, omega, s and I_b only).  In analysis the
same root is bracketed on [0, I at maximum power] (``Pack.current_for_power``).

Equivalently the mission may pick the throttle and leave the rotor speed unknown
(SUAVE's formulation): ``balance()`` solves that pair (omega, I_b) for a rotor
torque law, by nested bisection (always converges) or by Newton.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import re

import casadi as ca
import numpy as np

from ..core.errors import InputError, check_positive, check_range
from .esc import ESC_EFFICIENCY, ESC_SMOOTHING_W, esc_input_power_W
from .motor import DCMotor, motor_current
from .pack import Pack
from .pmsm import drive_node

__all__ = ["Bus", "MotorGroup", "Powertrain", "NODE_INPUTS", "NODE_OUTPUTS",
           "propeller_torque_law"]

NODE_INPUTS = ("torque_Nm", "omega_radps", "soc", "battery_current_A", "aux_power_W",
               "kv_radps_per_V", "resistance_ohm", "no_load_current_A")
NODE_OUTPUTS = (
    "motor_current_A", "motor_voltage_V", "motor_power_in_W", "shaft_power_W", "motor_efficiency",
    "esc_power_in_W", "esc_current_in_A", "bus_power_W",
    "pack_voltage_V", "pack_ocv_V", "cell_voltage_V", "cell_current_A", "c_rate",
    "battery_power_W", "chemical_power_W", "loss_power_W",
    "throttle", "voltage_margin_V", "power_balance_W", "soc_rate_per_s",
)
_MOTOR_PARAMS = ("kv_radps_per_V", "resistance_ohm", "no_load_current_A")


def _is_numeric(x):
    if isinstance(x, (ca.SX, ca.MX)):
        return False
    if isinstance(x, ca.DM):
        return True
    try:
        np.asarray(x, dtype=float)
        return True
    except (TypeError, ValueError):
        return False


@dataclass
class Powertrain:
    """Pack + ``n_motors`` identical motors with ESCs + auxiliary loads.

    ``aux_power_W``: avionics and payload power drawn from the bus (W), a default
    for nodes where the caller gives none.
    """

    pack: Pack
    motor: DCMotor
    n_motors: int
    esc_efficiency: float = ESC_EFFICIENCY
    esc_smoothing_W: float = ESC_SMOOTHING_W
    aux_power_W: float = 0.0
    name: str = "powertrain"
    _fn: ca.Function | None = field(default=None, init=False, repr=False)
    _maps: dict = field(default_factory=dict, init=False, repr=False)

    def __post_init__(self):
        check_positive("n_motors", self.n_motors)
        check_range("esc_efficiency", self.esc_efficiency, 0.5, 1.0)
        check_positive("esc_smoothing_W", self.esc_smoothing_W, "W")
        check_range("aux_power_W", self.aux_power_W, 0.0, np.inf, "W")

    # ------------------------------------------------------------------ scales
    @property
    def power_scale_W(self) -> float:
        """Typical bus power: n_motors x rated power (the residual scale of Eq. N1)."""
        if self.motor.rated_power_W is not None and _is_numeric(self.motor.rated_power_W):
            return float(self.n_motors * self.motor.rated_power_W)
        return float(self.pack.nominal_voltage_V * self.pack.max_current_A * 0.5)

    @property
    def current_scale_A(self) -> float:
        return self.power_scale_W / float(self.pack.nominal_voltage_V)

    @property
    def voltage_scale_V(self) -> float:
        return float(self.pack.nominal_voltage_V)

    def soc_state(self, initial=1.0, lower=0.0, upper=1.0) -> dict:
        """Spec of the collocated state (for ``mdo.vehicle.State(**spec)``)."""
        return {"name": "state_of_charge", "unit": "-", "scale": 1.0, "initial": initial,
                "lower": lower, "upper": upper,
                "description": "battery state of charge s = 1 - q/Q_u(T); ds/dt = soc_rate_per_s"}

    @property
    def soc_rate_scale_per_s(self) -> float:
        """|ds/dt| at the current scale (for scaling D s = T ds/dt by duration x this)."""
        return float(self.current_scale_A / self.pack.capacity_Ah / 3600.0)

    def battery_current_unknown(self) -> dict:
        """Spec of the per-node unknown I_b (for ``mdo.vehicle.Unknown(**spec)``).

        Bounds are wide safety bounds (charging to -1x, discharging to 3x the
        cell-current limit); the limit itself is a named constraint (``limits``)."""
        imax = float(self.pack.max_current_A)
        return {"name": "battery_current_A", "unit": "A", "scale": self.current_scale_A,
                "lower": -imax, "upper": 3.0 * imax,
                "description": "pack current, root of V_pack(s, I) I = P_bus (Eq. N1)"}

    def motor_parameters(self) -> dict:
        return {k: getattr(self.motor, k) for k in _MOTOR_PARAMS}

    # ------------------------------------------------------------------ kernel
    def node_function(self) -> ca.Function:
        """SX ``Function`` of one node: inputs ``NODE_INPUTS``, outputs ``NODE_OUTPUTS``.

        Torque and speed are per motor (= per rotor); the pack constants
        (N_s, N_p, T) are embedded, the motor constants are inputs so that a motor
        sized from design variables can be passed as expressions.  Scalar in,
        scalar out: ``map`` it over nodes (``evaluate`` does).
        """
        if self._fn is not None:
            return self._fn
        sym = {k: ca.SX.sym(k) for k in NODE_INPUTS}
        q, w, s, ib, paux = (sym[k] for k in NODE_INPUTS[:5])
        kv, r, i0 = (sym[k] for k in _MOTOR_PARAMS)
        pk = self.pack
        i_m = i0 + kv * q                                   # M1
        v_m = w / kv + i_m * r                              # M2
        p_m = v_m * i_m
        p_esc = esc_input_power_W(p_m, self.esc_efficiency, self.esc_smoothing_W)   # E2
        p_bus = self.n_motors * p_esc + paux
        i_cell = ib / pk.n_parallel
        v_cell = pk.cell.voltage(s, i_cell, pk.temperature_C)
        u_cell = pk.cell.ocv(s)
        v_pack = pk.n_series * v_cell
        u_pack = pk.n_series * u_cell
        out = {
            "motor_current_A": i_m, "motor_voltage_V": v_m, "motor_power_in_W": p_m,
            "shaft_power_W": q * w, "motor_efficiency": q * w / p_m,
            "esc_power_in_W": p_esc, "esc_current_in_A": p_esc / v_pack, "bus_power_W": p_bus,
            "pack_voltage_V": v_pack, "pack_ocv_V": u_pack, "cell_voltage_V": v_cell,
            "cell_current_A": i_cell, "c_rate": i_cell / pk.cell.capacity_nominal_Ah,
            "battery_power_W": v_pack * ib, "chemical_power_W": u_pack * ib,
            "loss_power_W": (u_pack - v_pack) * ib,
            "throttle": v_m / v_pack, "voltage_margin_V": v_pack - v_m,
            "power_balance_W": v_pack * ib - p_bus,                                  # N1
            "soc_rate_per_s": pk.cell.soc_rate(i_cell, pk.temperature_C),            # N2
        }
        # CasADi names: a letter, then letters, digits and single underscores
        ident = "_".join(filter(None, re.split(r"[^A-Za-z0-9]+", self.name))) or "powertrain"
        self._fn = ca.Function(f"pt_{ident}_node", [sym[k] for k in NODE_INPUTS],
                               [out[k] for k in NODE_OUTPUTS], list(NODE_INPUTS), list(NODE_OUTPUTS))
        return self._fn

    def _mapped(self, n: int) -> ca.Function:
        if n not in self._maps:
            self._maps[n] = self.node_function().map(n)
        return self._maps[n]

    def evaluate(self, torque_Nm, omega_radps, soc, battery_current_A, aux_power_W=None,
                 motor: DCMotor | None = None) -> dict:
        """Every output of ``NODE_OUTPUTS`` at N nodes.

        Inputs are scalars or length-N vectors (rows, columns or 1-D), numbers or
        CasADi expressions; outputs are 1 x N CasADi rows (the vehicle contract's
        orientation), or 1-D numpy arrays when every input is numeric.
        """
        aux = self.aux_power_W if aux_power_W is None else aux_power_W
        m = motor or self.motor
        node = [torque_Nm, omega_radps, soc, battery_current_A, aux]
        params = [getattr(m, k) for k in _MOTOR_PARAMS]
        numeric = all(_is_numeric(x) for x in node + params)
        sizes = [int(np.prod(x.shape)) if hasattr(x, "shape") else 1 for x in node]
        n = max(sizes)
        if any(k not in (1, n) for k in sizes):
            raise InputError("powertrain.evaluate", f"node inputs must be scalars or length {n}, got sizes {sizes}")
        args = []
        for x, k in zip(node, sizes):
            if not isinstance(x, (ca.SX, ca.MX)):
                x = ca.DM(np.asarray(x, float).reshape(1, -1))
            elif k > 1:
                x = ca.reshape(x, 1, n)
            args.append(x)
        res = self._mapped(n)(*args, *params)
        if numeric:
            return {k: np.asarray(v, float).ravel() for k, v in zip(NODE_OUTPUTS, res)}
        return dict(zip(NODE_OUTPUTS, res))

    # ------------------------------------------------------------------ mission helpers
    def energy_used_J(self, soc_initial, soc_final):
        """E_EOF between two states of charge, J (chemical energy, Eq. P2)."""
        return self.pack.energy_used_J(soc_initial, soc_final)

    def limits(self, out: dict) -> list[dict]:
        """The mission's inequality groups from ``evaluate`` outputs, each a dict
        (name, expr, kind, rhs, scale, unit): throttle <= 1 as a voltage margin,
        cell current <= limit, loaded cell voltage >= floor."""
        pk = self.pack
        return [
            {"name": "throttle", "expr": out["voltage_margin_V"], "kind": ">=", "rhs": 0.0,
             "scale": self.voltage_scale_V, "unit": "V"},
            {"name": "cell current", "expr": out["cell_current_A"], "kind": "<=",
             "rhs": float(pk.max_cell_current_A), "scale": float(pk.max_cell_current_A), "unit": "A"},
            {"name": "cell voltage", "expr": out["cell_voltage_V"], "kind": ">=",
             "rhs": float(pk.min_cell_voltage_V), "scale": 1.0, "unit": "V"},
        ]

    def add_to_problem(self, problem, torque_Nm, omega_radps, soc, *, prefix: str = "powertrain",
                       aux_power_W=None, init_battery_current_A=None, labels=None, limits: bool = True):
        """NLP mode (duck-typed ``problem`` with ``variable``/``constrain``).

        Adds the per-node battery current variable and the power balance (Eq. N1)
        and, with ``limits``, the throttle, cell-current and cell-voltage groups.
        Returns ``(outputs, battery_current)``; the caller collocates
        ``outputs["soc_rate_per_s"]`` for the state ``soc`` and uses
        ``energy_used_J`` for the objective.
        """
        n = max(int(np.prod(x.shape)) if hasattr(x, "shape") else 1 for x in (torque_Nm, omega_radps, soc))
        spec = self.battery_current_unknown()
        init = 0.5 * self.current_scale_A if init_battery_current_A is None else init_battery_current_A
        ib = problem.variable(f"{prefix}_battery_current", n, unit="A", scale=spec["scale"],
                              lower=spec["lower"], upper=spec["upper"], init=init,
                              description=spec["description"], labels=labels)
        out = self.evaluate(torque_Nm, omega_radps, soc, ib, aux_power_W)
        problem.constrain(f"{prefix} power balance", out["power_balance_W"], kind="==",
                          scale=self.power_scale_W, unit="W", labels=labels)
        if limits:
            for g in self.limits(out):
                problem.constrain(f"{prefix} {g['name']}", g["expr"], kind=g["kind"], rhs=g["rhs"],
                                  scale=g["scale"], unit=g["unit"], labels=labels)
        return out, ib

    # ------------------------------------------------------------------ analysis
    def bus_power_W(self, torque_Nm, omega_radps, aux_power_W=None):
        """Explicit bus power (numbers) for rotor torque/speed."""
        m = self.motor
        p_m = m.power_in_W(np.asarray(torque_Nm, float), np.asarray(omega_radps, float))
        aux = self.aux_power_W if aux_power_W is None else aux_power_W
        return self.n_motors * esc_input_power_W(p_m, self.esc_efficiency, self.esc_smoothing_W) + aux

    def analyze(self, torque_Nm, omega_radps, soc, aux_power_W=None) -> dict:
        """Numeric node analysis: explicit motor/ESC, bracketed battery current (Eq. N1).
        Returns the ``NODE_OUTPUTS`` and ``battery_current_A`` as 1-D arrays."""
        tq, om, s = np.broadcast_arrays(*(np.atleast_1d(np.asarray(x, float)) for x in (torque_Nm, omega_radps, soc)))
        p_bus = self.bus_power_W(tq, om, aux_power_W)
        ib = self.pack.current_for_power(p_bus, s)
        out = self.evaluate(tq, om, s, ib, aux_power_W)
        out["battery_current_A"] = np.atleast_1d(ib)
        return out

    def balance(self, throttle, rotor_torque, soc=1.0, aux_power_W=None, method: str = "bracket",
                omega0=None, current0=None, tol=1e-12) -> dict:
        """Motor-rotor-battery balance at a given throttle (SUAVE's formulation).

        Unknowns: rotor speed omega and pack current I_b, with
        ``motor torque(throttle V_pack(s, I_b), omega) = rotor_torque(omega)`` and
        Eq. N1.  ``rotor_torque`` maps speed (rad/s) to the torque one rotor
        absorbs (N m), increasing in speed; a callable on numpy arrays (and on
        CasADi SX for ``method="newton"``).

        ``method="bracket"``: nested bisection - omega on [0, no-load speed] for a
        fixed bus voltage, I_b on [0, I at maximum power] - converges from any state.
        ``method="newton"``: CasADi's Newton rootfinder on the scaled pair from a
        cold start (omega0 = half the no-load speed at the nominal voltage,
        I_b = 0 unless given); returns ``converged`` and the iteration count.
        """
        th = np.atleast_1d(np.asarray(throttle, float))
        check_range("throttle", th, 0.0, 1.5)
        s = float(soc)
        m = self.motor
        aux = self.aux_power_W if aux_power_W is None else aux_power_W
        if method == "bracket":
            omegas, currents = np.empty_like(th), np.empty_like(th)
            for k, t in enumerate(th):
                def omega_for(ib):
                    vm = t * float(self.pack.voltage(s, ib))
                    lo, hi = 0.0, float(m.no_load_speed_radps(vm))
                    for _ in range(200):
                        mid = 0.5 * (lo + hi)
                        if m.torque_at_voltage_Nm(vm, mid) > rotor_torque(mid):
                            lo = mid
                        else:
                            hi = mid
                        if hi - lo <= 1e-15 * hi:
                            break
                    return 0.5 * (lo + hi)
                _, imax = self.pack.max_power_W(s)
                lo, hi = 0.0, float(imax)
                for _ in range(200):
                    mid = 0.5 * (lo + hi)
                    w = omega_for(mid)
                    g = float(self.pack.voltage(s, mid)) * mid - float(self.bus_power_W(rotor_torque(w), w, aux))
                    lo, hi = (lo, mid) if g > 0 else (mid, hi)
                    if hi - lo <= 1e-14 * hi:
                        break
                currents[k] = 0.5 * (lo + hi)
                omegas[k] = omega_for(currents[k])
            out = self.evaluate(rotor_torque(omegas), omegas, s, currents, aux)
            out.update(omega_radps=omegas, battery_current_A=currents, converged=np.ones(th.shape, bool))
            return out
        if method != "newton":
            raise InputError("method", f"'bracket' or 'newton', got {method!r}")
        # Newton on x = (omega / w_ref, I_b / I_ref)
        w_ref = float(m.no_load_speed_radps(self.pack.nominal_voltage_V))
        i_ref = self.current_scale_A
        x = ca.SX.sym("x", 2)
        tsym = ca.SX.sym("throttle")
        w, ib = x[0] * w_ref, x[1] * i_ref
        v_pack = self.pack.voltage(s, ib)
        qm = m.torque_at_voltage_Nm(tsym * v_pack, w)
        qr = rotor_torque(w)
        p_bus = self.n_motors * esc_input_power_W(m.power_in_W(qr, w), self.esc_efficiency,
                                                  self.esc_smoothing_W) + aux
        q_ref = float(m.rated_torque_Nm) if m.rated_power_W is not None else 1.0
        g = ca.vertcat((qm - qr) / q_ref, (v_pack * ib - p_bus) / self.power_scale_W)
        rf = ca.rootfinder("balance", "newton", ca.Function("g", [x, tsym], [g]),
                           {"abstol": tol, "max_iter": 100, "error_on_fail": False})
        omegas, currents, ok, iters = (np.empty_like(th) for _ in range(4))
        x0 = np.array([0.5 if omega0 is None else omega0 / w_ref, 0.0 if current0 is None else current0 / i_ref])
        for k, t in enumerate(th):
            xs = np.asarray(rf(x0, t)).ravel()
            st = rf.stats()
            omegas[k], currents[k] = xs[0] * w_ref, xs[1] * i_ref
            ok[k], iters[k] = bool(st["success"]), st.get("iter_count", np.nan) if isinstance(st, dict) else np.nan
        out = self.evaluate(rotor_torque(omegas), omegas, s, currents, aux)
        out.update(omega_radps=omegas, battery_current_A=currents, converged=ok.astype(bool), iterations=iters)
        return out


def propeller_torque_law(rated_torque_Nm, rated_speed_radps):
    """A fixed-pitch propeller at constant advance ratio: Q = Q_r (omega / omega_r)^2
    (constant C_Q); a stand-in rotor for network tests and the CLI."""
    k = rated_torque_Nm / rated_speed_radps ** 2
    return lambda omega: k * omega * omega


@dataclass
class MotorGroup:
    """``n_motors`` identical motors driving one rotor group: a :class:`DCMotor` behind an
    ESC of flat ``esc_efficiency`` (the paper's model), or a :class:`~mdo.powertrain.pmsm.PMSM`
    with its loss-model ``inverter`` (then ``esc_efficiency`` is not used)."""

    name: str
    motor: object
    n_motors: int
    esc_efficiency: float = ESC_EFFICIENCY
    inverter: object = None


@dataclass
class Bus:
    """One pack feeding several motor groups and the auxiliary loads (the general network).

    At the nodes, for each group's per-motor torque ``Q_g`` and speed ``omega_g``
    (rows 1 x K; numbers or CasADi), and the pack current ``I_b`` (the one
    unknown, Eq. N1)::

        I_g = I0 + Kv Q_g,  V_g = omega_g / Kv + I_g R         (M1, M2)
        P_bus = sum_g n_g esc_in(V_g I_g) + P_aux              (E2)
        V_pack(s, I_b) I_b - P_bus = 0                         (N1)
        throttle_g = V_g / V_pack <= 1                          (E1)

    The expressions are elementwise, so rows of K nodes are evaluated in one call.
    """

    pack: Pack
    groups: list
    aux_power_W: float = 0.0
    esc_smoothing_W: float = ESC_SMOOTHING_W

    @property
    def power_scale_W(self) -> float:
        total = 0.0
        for g in self.groups:
            p = g.motor.rated_power_W
            total += g.n_motors * (float(p) if _is_numeric(p) else 0.0)
        return total if total > 0 else float(self.pack.nominal_voltage_V * self.pack.max_current_A * 0.5)

    @property
    def current_scale_A(self) -> float:
        return self.power_scale_W / float(self.pack.nominal_voltage_V)

    def battery_current_unknown(self) -> dict:
        imax = float(self.pack.max_current_A)
        return {"name": "battery_current_A", "unit": "A", "scale": self.current_scale_A,
                "lower": -imax, "upper": 3.0 * imax,
                "description": "pack current, root of V_pack(s, I) I = P_bus (Eq. N1)"}

    def motor_outputs(self, group: MotorGroup, torque_Nm, omega_radps, bus_voltage_V=None) -> dict:
        """One motor of ``group`` at (Q, omega): its current, voltage, electrical input and
        the power it draws from the bus (``esc_power_in_W``: behind the ESC or inverter).
        ``bus_voltage_V`` (the pack's terminal voltage) sets an inverter's switching loss;
        default the pack's nominal voltage."""
        m = group.motor
        if group.inverter is not None:     # PMSM + inverter (mdo.powertrain.pmsm, Eqs. P1-P8)
            v_bus = float(self.pack.nominal_voltage_V) if bus_voltage_V is None else bus_voltage_V
            d = drive_node(m, group.inverter, torque_Nm, omega_radps, v_bus)
            return {"motor_current_A": d["motor_current_A"], "motor_voltage_V": d["motor_voltage_V"],
                    "motor_power_in_W": d["motor_power_in_W"], "shaft_power_W": d["shaft_power_W"],
                    "esc_power_in_W": d["bus_power_W"]}
        i_m = motor_current(torque_Nm, m.kv_radps_per_V, m.no_load_current_A)
        v_m = omega_radps / m.kv_radps_per_V + i_m * m.resistance_ohm
        p_m = v_m * i_m
        p_esc = esc_input_power_W(p_m, group.esc_efficiency, self.esc_smoothing_W)
        return {"motor_current_A": i_m, "motor_voltage_V": v_m, "motor_power_in_W": p_m,
                "shaft_power_W": torque_Nm * omega_radps, "esc_power_in_W": p_esc}

    def evaluate(self, torques, omegas, soc, battery_current_A) -> dict:
        """Per group (``out["groups"][name]``) and pack outputs, as in ``NODE_OUTPUTS``."""
        pk = self.pack
        ib = battery_current_A
        i_cell = ib / pk.n_parallel
        v_cell = pk.cell.voltage(soc, i_cell, pk.temperature_C)
        u_cell = pk.cell.ocv(soc)
        v_pack = pk.n_series * v_cell
        u_pack = pk.n_series * u_cell
        per = {g.name: self.motor_outputs(g, q, w, v_pack) for g, q, w in zip(self.groups, torques, omegas)}
        p_bus = self.aux_power_W
        for g in self.groups:
            p_bus = p_bus + g.n_motors * per[g.name]["esc_power_in_W"]
        for g in self.groups:
            o = per[g.name]
            o["throttle"] = o["motor_voltage_V"] / v_pack
            o["voltage_margin_V"] = v_pack - o["motor_voltage_V"]
        return {"groups": per, "bus_power_W": p_bus, "pack_voltage_V": v_pack, "pack_ocv_V": u_pack,
                "cell_voltage_V": v_cell, "cell_current_A": i_cell,
                "c_rate": i_cell / pk.cell.capacity_nominal_Ah,
                "battery_power_W": v_pack * ib, "chemical_power_W": u_pack * ib,
                "loss_power_W": (u_pack - v_pack) * ib, "power_balance_W": v_pack * ib - p_bus,
                "soc_rate_per_s": pk.cell.soc_rate(i_cell, pk.temperature_C)}

    def analyze(self, torques, omegas, soc, *, within_pack: bool = False) -> dict:
        """Numbers: explicit motors, bracketed pack current (Eq. N1); adds ``battery_current_A``.
        ``within_pack``: a bus power above the pack's maximum draws the maximum-power current
        instead of raising (an initial guess, which the NLP then corrects)."""
        s = np.atleast_1d(np.asarray(soc, float))
        v_bus = None
        for _ in range(3):   # an inverter's loss depends on the bus voltage, which the current sets
            p_bus = self.aux_power_W
            for g, q, w in zip(self.groups, torques, omegas):
                p_bus = p_bus + g.n_motors * np.asarray(self.motor_outputs(g, np.asarray(q, float),
                                                                           np.asarray(w, float), v_bus)["esc_power_in_W"])
            p_bus, s = np.broadcast_arrays(np.atleast_1d(p_bus), s)
            if within_pack:
                p_bus = np.minimum(p_bus, self.pack.max_power_W(s)[0])
            ib = np.atleast_1d(self.pack.current_for_power(p_bus, s))
            if not any(g.inverter is not None for g in self.groups):
                break
            pk = self.pack
            v_bus = pk.n_series * np.asarray(pk.cell.voltage(s, ib / pk.n_parallel, pk.temperature_C), float)
        out = self.evaluate([np.asarray(q, float) for q in torques], [np.asarray(w, float) for w in omegas], s, ib)
        out["battery_current_A"] = ib
        return out

    def energy_used_J(self, soc_initial, soc_final):
        return self.pack.energy_used_J(soc_initial, soc_final)
