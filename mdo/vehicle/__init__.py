"""Vehicles: the physics a mission evaluates at its nodes.

``base`` defines the contract between a mission and a vehicle (unknowns, states,
residual groups, the batched node evaluation); ``polar`` is a simple vehicle with
a fixed drag polar and fixed efficiencies, for quick studies and tests.
"""
from . import base, polar
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
from .polar import PolarVehicle

__all__ = [
    "base", "polar",
    "G0", "NodeConditions", "NodeEvaluation", "Output", "ResidualGroup", "State", "Unknown", "Vehicle",
    "path_components", "rotate_to_path",
    "PolarVehicle",
]
