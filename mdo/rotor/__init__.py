"""Rotor and propeller aerodynamics: blade geometry, BEMT as a residual in the
inflow angle (Ning 2014), analysis mode with a bracketed solve, and the
Adkins-Liebeck minimum-induced-loss design, all written once in CasADi."""
from .geometry import RotorGeometry, station_layout, read_geometry_csv, write_geometry_csv
from .sections import (AnalyticSection, SpanwiseBlend, SpanwiseSections, RotationalAugmentation, section,
                       available_sections, STALL_DELAY_MODELS)
from .bemt import (
    bemt_function, station_physics, phi_momentum_guess, bemt_unknowns, add_bemt_nodes,
    azimuth_angles, inflow_components, INPUT_NAMES, NLP_OUTPUTS, FULL_OUTPUTS, PHI_MIN_RAD, PHI_MAX_RAD,
)
from .analysis import analyze, analyze_inputs, sweep_J, solve_phi, RotorResult, analysis_function, operating_inputs
from .design import (
    adkins_liebeck, adkins_liebeck_function, adkins_liebeck_implicit, adkins_liebeck_unrolled,
    add_adkins_liebeck,
    DESIGN_INPUTS, design_guess,
)

__all__ = [
    "RotorGeometry", "station_layout", "read_geometry_csv", "write_geometry_csv",
    "AnalyticSection", "SpanwiseBlend", "SpanwiseSections", "RotationalAugmentation", "section",
    "available_sections", "STALL_DELAY_MODELS",
    "bemt_function", "station_physics", "phi_momentum_guess", "bemt_unknowns", "add_bemt_nodes",
    "azimuth_angles", "inflow_components", "INPUT_NAMES", "NLP_OUTPUTS", "FULL_OUTPUTS", "PHI_MIN_RAD", "PHI_MAX_RAD",
    "analyze", "analyze_inputs", "sweep_J", "solve_phi", "RotorResult", "analysis_function", "operating_inputs",
    "adkins_liebeck", "adkins_liebeck_function", "adkins_liebeck_implicit", "adkins_liebeck_unrolled",
    "add_adkins_liebeck",
    "DESIGN_INPUTS", "design_guess",
]
