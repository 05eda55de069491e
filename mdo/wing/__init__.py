"""Lifting surfaces: segmented-wing geometry symbolic in the design, a multi-surface vortex
lattice solved for K operating points at once, and the drag build-up.

    >>> from mdo.wing import VLM, trapezoid
    >>> v = VLM([trapezoid("wing", 11.4, 1.5, 0.7, nspan=20)])
    >>> r = v.solve(alpha=0.05, V=60.0)          # r["CL"], r["CDi"], r["cl"], ...

See ``mdo/wing/README.md`` for the model, its conventions and its measured accuracy.
"""
from .buildup import (BodyComponent, CoolingDrag, DragBuildup, SurfaceComponent, Transition,
                      composite_skin_friction)
from .camber import camber_line, known_camber_names
from .drag import Body, body_drag, crossflow_normal_force, profile_drag, section_cd, skin_friction
from .geometry import (Params, Section, Surface, aspect_ratio, constant_area, mean_aerodynamic_chord,
                       planform_area, trapezoid)
from .viscous import lattice_zero_lift_angles, shift_velocity, solve_viscous, viscous_residual
from .vlm import VLM

__all__ = [
    "VLM", "Surface", "Section", "trapezoid", "constant_area", "planform_area",
    "mean_aerodynamic_chord", "aspect_ratio", "Params", "camber_line", "known_camber_names",
    "Body", "body_drag", "crossflow_normal_force", "profile_drag", "section_cd", "skin_friction",
    "DragBuildup", "SurfaceComponent", "BodyComponent", "CoolingDrag", "Transition",
    "composite_skin_friction", "lattice_zero_lift_angles", "shift_velocity", "solve_viscous", "viscous_residual",
]
