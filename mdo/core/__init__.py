"""Numerics every discipline uses: smooth functions, CGL collocation, the US
Standard Atmosphere 1976, unit conversions, and input checks."""
from . import units
from .atmosphere import (
    atmosphere,
    check_altitude,
    density,
    dynamic_viscosity,
    kinematic_viscosity,
    pressure,
    speed_of_sound,
    temperature,
)
from .collocation import Collocation, cgl_nodes, differentiation_matrix, integration_matrix
from .errors import InputError, check_positive, check_range
from .smooth import (
    blend,
    is_symbolic,
    sigmoid,
    smooth_abs,
    smooth_clip,
    smooth_max,
    smooth_min,
    softplus,
    xp,
)

__all__ = [
    "units",
    "atmosphere", "check_altitude", "density", "dynamic_viscosity", "kinematic_viscosity",
    "pressure", "speed_of_sound", "temperature",
    "Collocation", "cgl_nodes", "differentiation_matrix", "integration_matrix",
    "InputError", "check_positive", "check_range",
    "blend", "is_symbolic", "sigmoid", "smooth_abs", "smooth_clip", "smooth_max", "smooth_min",
    "softplus", "xp",
]
