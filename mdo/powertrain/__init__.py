"""Powertrain: battery cell and pack, DC motors, ESCs and the network that ties them
to the rotors (the energy side of Clarke, Erhard & Alonso, Sec. II).

Public surface:

* :func:`nmc18650` / :class:`CellModel` - the fitted 18650 NMC cell
  ``V = U(s) - I R(s,T) - A(s,T) asinh(I/1A)`` (``cell.py``).
* :class:`Pack` - N_s x N_p cells: terminal voltage, state-of-charge rate, chemical
  energy used ``energy_used_J`` (E_EOF), mass (``pack.py``).
* :class:`DCMotor`, :func:`size_dc_motor`, :func:`motor_mass_ndarc_kg` (``motor.py``).
* :func:`esc_input_power_W` (``esc.py``).
* :class:`PMSM`, :class:`Inverter`, :func:`size_pmsm`, :func:`size_inverter`, :func:`drive_node`
  - loss-model PMSM and inverter (``pmsm.py``).
* :class:`Powertrain` - the network at mission nodes: ``node_function`` (SX kernel),
  ``evaluate`` (mapped over nodes), ``limits``, ``add_to_problem`` (NLP mode),
  ``analyze`` / ``balance`` (numeric) (``network.py``); a vehicle's own network is
  ``VehicleConfig.bus()`` / ``VehicleConfig.powertrain()`` (``mdo.vehicle.config``).
"""
from .cell import CellModel, load_discharge_data, nmc18650
from .esc import ESC_EFFICIENCY, esc_input_power_W
from .motor import DCMotor, motor_function, motor_mass_ndarc_kg, size_dc_motor
from .network import Bus, MotorGroup, NODE_INPUTS, NODE_OUTPUTS, Powertrain, propeller_torque_law
from .pmsm import (PMSM, Inverter, drive_function, drive_node, plot_efficiency_map, size_inverter,
                   size_pmsm)
from .pack import PACKAGING_FACTOR_X57, Pack

__all__ = [
    "CellModel", "nmc18650", "load_discharge_data",
    "Pack", "PACKAGING_FACTOR_X57",
    "DCMotor", "size_dc_motor", "motor_mass_ndarc_kg", "motor_function",
    "ESC_EFFICIENCY", "esc_input_power_W",
    "Bus", "MotorGroup", "Powertrain", "propeller_torque_law",
    "NODE_INPUTS", "NODE_OUTPUTS",
    "PMSM", "Inverter", "size_pmsm", "size_inverter", "drive_node", "drive_function",
    "plot_efficiency_map",
]
