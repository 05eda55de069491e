"""Battery pack of ``n_series`` x ``n_parallel`` identical cells.

All cells carry the same current and state of charge (a balanced pack; no
interconnect resistance)::

    I_cell = I / N_p,   V_pack = N_s V_cell(s, I_cell, T),   ds/dt = -I_cell / Q_u(T)     (P1)

The **state** the mission collocates is the state of charge ``s`` (dimensionless,
O(1), bounds [0, 1]): the cell voltage is a function of the charge drawn, so the
charge is the natural state; its rate is linear in the current and needs no
energy-to-charge conversion (SUAVE integrates energy and divides by E_max to get a
state of charge, which mixes the energy and charge bases).

**Battery energy used** ``E_EOF`` (the objective of the paper's Eq. 7) is defined
here as the *chemical* energy drawn from the pack: the energy delivered at the
terminals **plus** the internal losses ``I (U - V)``.  It is a closed-form function
of the initial and final states (Eq. C5 of ``cell.py``)::

    E_used = N_s N_p [E_cell(s_0) - E_cell(s_f)],   E_cell(s) = Q_u(T) int_0^s U      (P2)

exact for any current history (no quadrature), smooth, and equal to
``int (V_pack I + losses) dt``; this is what SUAVE's battery integrates
(``P_bat - P_loss``).  The terminal energy ``int V_pack I dt`` is available per node
as ``battery_power_W`` for a quadrature if wanted.

Mass: cells x 48 g x 1.42, the module build-up factor of SUAVE
(``initialize_from_circuit_configuration``, module_weight_factor = 1.42: casing,
wiring, thermal and battery management, computed from the X-57 Maxwell battery of
Chin et al., "Battery Performance Modeling on Maxwell X-57", AIAA SciTech 2019).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import casadi as ca
import numpy as np

from ..core.errors import InputError, check_positive, check_range
from .cell import AH, CellModel, nmc18650

__all__ = ["Pack", "PACKAGING_FACTOR_X57"]

PACKAGING_FACTOR_X57 = 1.42


@dataclass(frozen=True)
class Pack:
    """A pack of identical cells in ``n_series`` x ``n_parallel``.

    ``temperature_C``: ambient/pack temperature of the cell model (0..50 deg C).
    ``max_cell_current_A``: the cell-current limit offered as a constraint
    (default 8 A, the largest measured current; the model extrapolates beyond).
    ``min_cell_voltage_V``: the loaded-voltage floor offered as a constraint
    (default 2.5 V, the cut-off of the measured curves).
    ``max_charge_current_A``: the charge-current limit offered as a constraint where
    windmilling may charge the pack (default 1.7 A, the standard charge current of the
    Panasonic NCR18650GA data sheet, about 0.5 C).
    """

    n_series: float
    n_parallel: float
    cell: CellModel = field(default_factory=nmc18650)
    temperature_C: float = 25.0
    packaging_factor: float = PACKAGING_FACTOR_X57
    max_cell_current_A: float = 8.0
    min_cell_voltage_V: float = 2.5
    max_charge_current_A: float = 1.7

    def __post_init__(self):
        for name in ("n_series", "n_parallel"):
            v = getattr(self, name)
            if isinstance(v, (int, float)):
                check_positive(name, v)
                if float(v) != round(float(v)):
                    raise InputError(name, f"must be a whole number of cells, got {v}")
        self.cell.check_temperature(self.temperature_C, "temperature_C")
        check_range("packaging_factor", self.packaging_factor, 1.0, 3.0)
        check_positive("max_cell_current_A", self.max_cell_current_A, "A")
        check_range("min_cell_voltage_V", self.min_cell_voltage_V, 2.0, 4.0, "V")
        check_positive("max_charge_current_A", self.max_charge_current_A, "A")

    # ------------------------------------------------------------ size
    @property
    def cells(self):
        return self.n_series * self.n_parallel

    @property
    def mass_kg(self):
        """Cells x cell mass x packaging factor (SUAVE/X-57 1.42)."""
        return self.cells * self.cell.mass_kg * self.packaging_factor

    @property
    def capacity_Ah(self):
        """Usable pack capacity at ``temperature_C`` (to the cut-off at low rate)."""
        return self.n_parallel * self.cell.usable_capacity_Ah(self.temperature_C)

    @property
    def nominal_voltage_V(self):
        return self.n_series * self.cell.voltage_nominal_V

    @property
    def nominal_energy_J(self):
        """Rating: cells x 3.55 Ah x 3.6 V (what Table 1 capacities imply)."""
        return self.cells * self.cell.capacity_nominal_Ah * self.cell.voltage_nominal_V * AH

    @property
    def max_current_A(self):
        return self.n_parallel * self.max_cell_current_A

    # ------------------------------------------------------------ physics (numbers or casadi)
    def cell_current_A(self, current_A):
        return current_A / self.n_parallel

    def c_rate(self, current_A):
        """Cell current / rated capacity (3.55 Ah), 1/h."""
        return current_A / self.n_parallel / self.cell.capacity_nominal_Ah

    def voltage(self, soc, current_A):
        """Terminal voltage under load, V (Eq. P1)."""
        return self.n_series * self.cell.voltage(soc, current_A / self.n_parallel, self.temperature_C)

    def ocv(self, soc):
        return self.n_series * self.cell.ocv(soc)

    def soc_rate(self, current_A):
        """ds/dt for pack current ``current_A`` (A, discharge > 0), 1/s."""
        return self.cell.soc_rate(current_A / self.n_parallel, self.temperature_C)

    def energy_J(self, soc):
        """Chemical energy above empty, J (Eq. P2)."""
        return self.cells * self.cell.energy_J(soc, self.temperature_C)

    def energy_used_J(self, soc_initial, soc_final):
        """E_EOF: chemical energy drawn between two states, J (Eq. P2).  kWh = J / 3.6e6."""
        return self.energy_J(soc_initial) - self.energy_J(soc_final)

    def max_power_W(self, soc):
        """Largest terminal power and its current (numeric, vectorized): the maximum
        over I of V(s, I) I, found by bisection on d(V I)/dI = V + I dV/dI = 0."""
        s = np.asarray(soc, float)
        lo = np.zeros(s.shape)
        hi = np.full(s.shape, 200.0 * float(self.n_parallel))
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            ic = mid / self.n_parallel
            d = (self.cell.voltage(s, ic, self.temperature_C)
                 + ic * self.cell.dvoltage_dcurrent(s, ic, self.temperature_C))
            lo, hi = np.where(d > 0, mid, lo), np.where(d > 0, hi, mid)
        i = 0.5 * (lo + hi)
        return self.voltage(s, i) * i, i

    def current_for_power(self, power_W, soc):
        """Pack current that delivers terminal ``power_W`` at ``soc`` (numeric, bracketed).

        The root of V(s, I) I = P on the rising branch [I(P<0 side), I_maxpower],
        by bisection to round-off (vectorized); raises ``InputError`` if P exceeds
        the pack's maximum power at that state.  Negative P (charging) is allowed.
        """
        P, s = np.broadcast_arrays(np.asarray(power_W, float), np.asarray(soc, float))
        pmax, imax = self.max_power_W(s)
        if np.any(P > pmax):
            k = np.unravel_index(np.argmax(P - pmax), P.shape)
            raise InputError("power_W", f"{P[k]:.6g} W exceeds the pack's maximum power "
                             f"{pmax[k]:.6g} W at soc {s[k]:.3f}")
        u = self.ocv(s)
        lo = np.minimum(0.0, 2.0 * P / u)       # V > U/2 for any charging current of interest
        hi = imax.copy()
        for _ in range(120):
            mid = 0.5 * (lo + hi)
            over = self.voltage(s, mid) * mid > P
            lo, hi = np.where(over, lo, mid), np.where(over, mid, hi)
        i = 0.5 * (lo + hi)
        return i if i.shape else float(i)

    # ------------------------------------------------------------ casadi
    def function(self, name: str = "pack") -> ca.Function:
        """SX ``Function`` (soc, current_A) -> (voltage_V, ocv_V, cell_voltage_V,
        cell_current_A, c_rate, power_W, loss_W, soc_rate_per_s); scalar, ``map`` it."""
        s, i = ca.SX.sym("soc"), ca.SX.sym("current_A")
        v = self.voltage(s, i)
        u = self.ocv(s)
        return ca.Function(
            name, [s, i],
            [v, u, v / self.n_series, i / self.n_parallel, self.c_rate(i), v * i, (u - v) * i,
             self.soc_rate(i)],
            ["soc", "current_A"],
            ["voltage_V", "ocv_V", "cell_voltage_V", "cell_current_A", "c_rate", "power_W",
             "loss_W", "soc_rate_per_s"])
