"""The 18650 NMC cell: open-circuit voltage, overpotential and usable capacity.

A quasi-static equivalent circuit, smooth in every argument, written once for
floats, NumPy arrays and CasADi expressions::

    V(s, I, T) = U(s) - I R(s, T) - A(s, T) asinh(I / I_k)                      (C1)

* ``s`` state of charge, ``s = 1 - q / Q_u(T)``, ``q`` the charge drawn (Ah) and
  ``Q_u(T)`` the usable capacity to the 2.5 V cut-off at the pack temperature
  ``T``; ``I`` the cell current (A, discharge > 0); ``T`` the ambient (pack)
  temperature in deg C, a parameter of a problem (0..50 deg C, the measured range).
* ``U(s)`` the open-circuit voltage: a degree-7 Chebyshev series in ``2s - 1``
  (increasing in s; the collapse near empty is carried by the ``exp(-s/0.15)``
  terms of the overpotential, whose amplitude grows at low temperature).        (C2)
* ``I R`` an ohmic drop and ``A asinh(I/I_k)`` (I_k = 1 A) a Butler-Volmer-type
  kinetic overpotential (symmetric Butler-Volmer gives exactly this form,
  Newman & Thomas-Alyea, *Electrochemical Systems*, 3rd ed., Eq. 8.6); both
  coefficients are smooth surfaces ``sum_jk c_jk phi_j(s) psi_k(tau)`` with
  ``phi = [1, 1-s, (1-s)^2, exp(-s/0.15)]``, ``psi = [1, tau, tau^2]``,
  ``tau = (T - 25)/25``.                                                         (C3)
* ``Q_u(T) = Q_nom exp(c0 + c1 tau + c2 tau^2)``, fitted to the measured cut-off
  capacities (3.07 Ah at 0 deg C .. 3.40 Ah at 50 deg C; Q_nom = 3.55 Ah).       (C4)

Physics the form guarantees: ``V = U`` at zero current; ``-dV/dI = R + A /
sqrt(I^2 + I_k^2) > 0`` because the fit constrains ``R >= 5 mOhm`` and ``A >= 0``
on a grid covering s in [-0.05, 1] and T in [0, 50] deg C (a unique current for
each power below the maximum); the loaded voltage increases with ``s`` for every
current 0..12 A on that grid (no spurious rise past the knee).
The self-heating of the measured cells (they warm by up to 30 K at 8 A) is inside
the fitted surfaces: the model reproduces a discharge *in the thermal environment
of the test* starting at ambient ``T``; a pack with other cooling runs warmer or
cooler.  Coefficients and the error table are in ``data/nmc18650_fit.json``
(produced by :mod:`mdo.powertrain.cell_fit`).

Energy bookkeeping.  The chemical energy a cell holds above empty is a function of
the state of charge alone::

    E(s) = Q_u(T) * integral_0^s U(sigma) d sigma          (J with Q_u in coulombs)  (C5)

so ``E(s0) - E(s1)`` is the energy drawn from the chemistry between two states:
the energy delivered at the terminals plus the internal losses
``I (U - V)`` - closed form, no quadrature, exact for any current history.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import casadi as ca
import numpy as np
from numpy.polynomial import chebyshev as C

from ..core.errors import check_range
from ..core.smooth import xp

__all__ = ["CellModel", "nmc18650", "load_discharge_data", "DATA_DIR", "FIT_FILE", "RAW_FILE"]

DATA_DIR = Path(__file__).parent / "data"
FIT_FILE = DATA_DIR / "nmc18650_fit.json"
RAW_FILE = DATA_DIR / "nmc18650_discharge.json"

AH = 3600.0  # coulombs per ampere-hour

# Structure of the fit (also used by cell_fit.py; change both together).
OCV_DEGREE = 7
SOC_BASIS_WIDTH = 0.15
TEMP_REF_C = 25.0
TEMP_SPAN_C = 25.0
CURRENT_REF_A = 1.0


def _clenshaw(coeffs, x):
    """Chebyshev series sum c_k T_k(x) by Clenshaw's recurrence (numpy or casadi)."""
    b1 = 0.0 * x
    b2 = 0.0 * x
    for c in coeffs[:0:-1]:
        b1, b2 = c + 2.0 * x * b1 - b2, b1
    return coeffs[0] + x * b1 - b2


def soc_basis(soc):
    """phi(s) of Eq. C3 as a list: [1, 1-s, (1-s)^2, exp(-s/0.15)]."""
    lib = xp(soc)
    y = 1.0 - soc
    return [1.0 + 0.0 * soc, y, y * y, lib.exp(-soc / SOC_BASIS_WIDTH)]


def temperature_basis(tau):
    """psi(tau) of Eq. C3: [1, tau, tau^2]."""
    return [1.0 + 0.0 * tau, tau, tau * tau]


def _surface(coeffs, soc, tau):
    """sum_jk c[j][k] phi_j(s) psi_k(tau)."""
    phi = soc_basis(soc)
    psi = temperature_basis(tau)
    out = 0.0
    for j, pj in enumerate(phi):
        row = coeffs[j]
        out = out + pj * (row[0] * psi[0] + row[1] * psi[1] + row[2] * psi[2])
    return out


@dataclass(frozen=True)
class CellModel:
    """A fitted cell (Eqs. C1-C5).  All methods take numbers, arrays or CasADi objects.

    Units: state of charge ``soc`` (-), current ``current_A`` (A per cell, discharge
    > 0), temperature ``temperature_C`` (deg C, 0..50), voltages in V, capacities in
    Ah, energies in J.
    """

    name: str
    capacity_nominal_Ah: float
    voltage_nominal_V: float
    voltage_max_V: float
    voltage_cutoff_V: float
    mass_kg: float
    capacity_log_coeffs: tuple        # c0, c1, c2 of Eq. C4
    ocv_chebyshev: tuple              # u_0..u_7 of Eq. C2
    resistance_coeffs: tuple          # 4 x 3, ohm
    kinetic_coeffs: tuple             # 4 x 3, V
    temperature_range_C: tuple = (0.0, 50.0)
    current_range_A: tuple = (2.0, 8.0)      # measured currents
    fit: dict = field(default_factory=dict, compare=False, repr=False)

    # -------------------------------------------------------------- capacity
    def tau(self, temperature_C):
        return (temperature_C - TEMP_REF_C) / TEMP_SPAN_C

    def usable_capacity_Ah(self, temperature_C=TEMP_REF_C):
        """Q_u(T) (Eq. C4): charge from full to the 2.5 V cut-off at low rate, Ah."""
        t = self.tau(temperature_C)
        c0, c1, c2 = self.capacity_log_coeffs
        return self.capacity_nominal_Ah * xp(t).exp(c0 + c1 * t + c2 * t * t)

    def soc_from_charge(self, charge_Ah, temperature_C=TEMP_REF_C):
        """State of charge after drawing ``charge_Ah`` from a full cell."""
        return 1.0 - charge_Ah / self.usable_capacity_Ah(temperature_C)

    # -------------------------------------------------------------- voltages
    def ocv(self, soc):
        """Open-circuit voltage U(s) (Eq. C2), V."""
        return _clenshaw(self.ocv_chebyshev, 2.0 * soc - 1.0)

    @property
    def _ocv_integral_coeffs(self):
        return _ocv_integral_cheb(self.ocv_chebyshev)

    def ocv_integral(self, soc):
        """integral_0^s U(sigma) d sigma, V (closed form: the Chebyshev integral)."""
        return _clenshaw(self._ocv_integral_coeffs, 2.0 * soc - 1.0)

    def resistance_ohm(self, soc, temperature_C=TEMP_REF_C):
        """Ohmic coefficient R(s, T) of Eq. C3."""
        return _surface(self.resistance_coeffs, soc, self.tau(temperature_C))

    def kinetic_V(self, soc, temperature_C=TEMP_REF_C):
        """Kinetic coefficient A(s, T) of Eq. C3 (V multiplying asinh(I/1 A))."""
        return _surface(self.kinetic_coeffs, soc, self.tau(temperature_C))

    def overpotential_V(self, soc, current_A, temperature_C=TEMP_REF_C):
        """U - V = I R + A asinh(I/I_k) (>= 0 for discharge)."""
        lib = xp(soc, current_A, temperature_C)
        return (current_A * self.resistance_ohm(soc, temperature_C)
                + self.kinetic_V(soc, temperature_C) * lib.arcsinh(current_A / CURRENT_REF_A))

    def voltage(self, soc, current_A, temperature_C=TEMP_REF_C):
        """Terminal voltage under load, V (Eq. C1)."""
        return self.ocv(soc) - self.overpotential_V(soc, current_A, temperature_C)

    def dvoltage_dcurrent(self, soc, current_A, temperature_C=TEMP_REF_C):
        """dV/dI = -(R + A / sqrt(I^2 + I_k^2)), ohm (< 0)."""
        lib = xp(soc, current_A, temperature_C)
        return -(self.resistance_ohm(soc, temperature_C) + self.kinetic_V(soc, temperature_C)
                 / lib.sqrt(current_A * current_A + CURRENT_REF_A ** 2))

    # -------------------------------------------------------------- energy
    def energy_J(self, soc, temperature_C=TEMP_REF_C):
        """Chemical energy above empty, E(s) = Q_u * int_0^s U (Eq. C5), J."""
        return self.usable_capacity_Ah(temperature_C) * AH * self.ocv_integral(soc)

    def soc_rate(self, current_A, temperature_C=TEMP_REF_C):
        """ds/dt = -I / Q_u(T), 1/s."""
        return -current_A / (self.usable_capacity_Ah(temperature_C) * AH)

    # -------------------------------------------------------------- casadi
    def function(self, name: str = "cell") -> ca.Function:
        """SX ``Function`` (soc, current_A, temperature_C) -> (voltage_V, ocv_V,
        overpotential_V, dvoltage_dcurrent_ohm, soc_rate_per_s); scalar, ``map`` it."""
        s, i, t = ca.SX.sym("soc"), ca.SX.sym("current_A"), ca.SX.sym("temperature_C")
        return ca.Function(
            name, [s, i, t],
            [self.voltage(s, i, t), self.ocv(s), self.overpotential_V(s, i, t),
             self.dvoltage_dcurrent(s, i, t), self.soc_rate(i, t)],
            ["soc", "current_A", "temperature_C"],
            ["voltage_V", "ocv_V", "overpotential_V", "dvoltage_dcurrent_ohm", "soc_rate_per_s"])

    def check_temperature(self, temperature_C, field_name="temperature_C"):
        lo, hi = self.temperature_range_C
        check_range(field_name, temperature_C, lo, hi, "deg C")

    # -------------------------------------------------------------- I/O
    @classmethod
    def from_json(cls, path=FIT_FILE) -> "CellModel":
        d = json.loads(Path(path).read_text())
        m = d["model"]
        return cls(
            name=d["name"],
            capacity_nominal_Ah=m["capacity_nominal_Ah"], voltage_nominal_V=m["voltage_nominal_V"],
            voltage_max_V=m["voltage_max_V"], voltage_cutoff_V=m["voltage_cutoff_V"],
            mass_kg=m["mass_kg"], capacity_log_coeffs=tuple(m["capacity_log_coeffs"]),
            ocv_chebyshev=tuple(m["ocv_chebyshev"]),
            resistance_coeffs=tuple(tuple(r) for r in m["resistance_coeffs"]),
            kinetic_coeffs=tuple(tuple(r) for r in m["kinetic_coeffs"]),
            temperature_range_C=tuple(m["temperature_range_C"]),
            current_range_A=tuple(m["current_range_A"]),
            fit=d.get("fit", {}))


@lru_cache(maxsize=16)
def _ocv_integral_cheb(cheb: tuple) -> tuple:
    # d sigma = dx/2 with x = 2 sigma - 1; lower bound sigma = 0 <-> x = -1.
    return tuple(C.chebint(np.asarray(cheb, float), lbnd=-1.0, scl=0.5))


@lru_cache(maxsize=1)
def nmc18650() -> CellModel:
    """The Panasonic NCR18650G-type NMC cell of the paper (3.55 Ah, 48 g), fitted."""
    return CellModel.from_json(FIT_FILE)


def load_discharge_data(path=RAW_FILE):
    """The measured curves as a list of dicts (duplicate ``Amps_0`` dropped).

    Each dict: ``current_A``, ``ambient_C``, ``capacity_Ah`` (array),
    ``voltage_V`` (array), ``cell_temperature_C`` (array, interpolated from the
    temperature trace at the voltage points).
    """
    raw = json.loads(Path(path).read_text())
    curves = []
    for akey, by_temp in raw["Voltage"].items():
        amps = float(akey.split("_")[1])
        if amps == 0.0:
            continue  # a copy of Amps_2 (see data/SOURCES.md)
        for tkey, pts in by_temp.items():
            v = np.asarray(pts, float)
            tr = np.asarray(raw["Temperature"][akey][tkey], float)
            q = v[:, 0] / 1000.0
            curves.append({
                "current_A": amps, "ambient_C": float(tkey.split("_")[1]),
                "capacity_Ah": q, "voltage_V": v[:, 1],
                "cell_temperature_C": np.interp(v[:, 0], tr[:, 0], tr[:, 1]),
            })
    curves.sort(key=lambda c: (c["current_A"], c["ambient_C"]))
    return curves
