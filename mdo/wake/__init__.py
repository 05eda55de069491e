"""Propeller wake: the helical fixed wake of the paper (Eqs. 2, 4, 6b), its
blade-passage-averaged form for the mission NLP, and the coupling into the wing.

Public surface
--------------
WakeRotor, element_edges           the rotor as the wake sees it (rotor.py)
rotor_frame, spin_for              frames and rotation sense (frames.py)
filament_velocity, ring_velocity   Biot–Savart kernels, Eqs. 2 and 4 (biot_savart.py)
full_wake_velocity                 the helical fixed wake, symbolic (helical.py)
mean_wake_velocity, influence      the averaged wake from the shipped table (mean.py)
external_velocity, vlm_wake_inputs the coupling into the wing's VLM (coupling.py)
"""
from .biot_savart import filament_kernel, filament_velocity, ring_kernel, ring_velocity
from .frames import rotor_frame, spin_for
from .helical import full_wake_function, full_wake_velocity, wake_segments_function
from .mean import (DEFAULT_STRIP_SAMPLES, apply_influence, influence, influence_function, jump_matrix,
                   mean_wake_velocity, unit_cylinder)
from .rotor import DEFAULT_CORE_REL, WakeRotor, element_edges

__all__ = [
    "WakeRotor", "element_edges", "DEFAULT_CORE_REL", "DEFAULT_STRIP_SAMPLES",
    "rotor_frame", "spin_for",
    "filament_kernel", "filament_velocity", "ring_kernel", "ring_velocity",
    "full_wake_function", "full_wake_velocity", "wake_segments_function",
    "apply_influence", "influence", "influence_function", "jump_matrix", "mean_wake_velocity", "unit_cylinder",
]
from .coupling import (COUPLINGS, apply_influences, external_velocity, influence_sum_parts, vlm_wake_inputs,
                       wake_convection_speed, wake_influences)

__all__ += ["COUPLINGS", "apply_influences", "external_velocity", "influence_sum_parts", "vlm_wake_inputs",
            "wake_convection_speed", "wake_influences"]
