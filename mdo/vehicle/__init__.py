"""Vehicles: the physics a mission evaluates at its nodes.

``base`` defines the contract between a mission and a vehicle (unknowns, states,
residual groups, the batched node evaluation); ``polar`` is a simple vehicle with
a fixed drag polar and fixed efficiencies, for quick studies and tests;
``config``/``catalog`` hold the numbers of the paper's aircraft (GA-2P, GA-8P,
TTW) and ``mass`` the mass build-up that responds to the design variables;
``balance`` the pitching moment about the CG, the neutral point and pitch trim.
"""
from . import balance, base, catalog, config, mass, polar
from .base import (
    G0,
    NodeConditions,
    NodeEvaluation,
    Output,
    ResidualGroup,
    State,
    Unknown,
    Vehicle,
    path_components,
    rotate_to_path,
)
from .catalog import VEHICLES, ga2p, ga8p, ttw
from .config import BatteryConfig, FuselageConfig, RotorGroupConfig, VehicleConfig, WingConfig
from .mass import MassDesign, mass_table_markdown, mass_terms, solve_togw, togw_residual, total_mass
from .polar import PolarVehicle

__all__ = [
    "balance", "base", "polar",
    "G0", "NodeConditions", "NodeEvaluation", "Output", "ResidualGroup", "State", "Unknown", "Vehicle",
    "path_components", "rotate_to_path",
    "PolarVehicle",
    "catalog", "config", "mass", "VEHICLES", "ga2p", "ga8p", "ttw",
    "BatteryConfig", "FuselageConfig", "RotorGroupConfig", "VehicleConfig", "WingConfig",
    "MassDesign", "mass_table_markdown", "mass_terms", "solve_togw", "togw_residual", "total_mass",
]
