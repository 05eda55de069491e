"""The mission: segments of Table 4 collocated on CGL nodes, joined end to end, the
vehicle in force balance at every node, its states integrated along the way.

>>> from mdo.mission import Mission, segments
>>> from mdo.mission.profiles import ga_mission
"""
from . import profiles, segments
from .report import write_mission_report
from .segments import (
    SEGMENT_KINDS,
    ConstantAccelerationConstantAltitude,
    ConstantAccelerationConstantAngleLinearClimb,
    ConstantAccelerationConstantPitchrateConstantAltitude,
    ConstantSpeedConstantAltitude,
    Hover,
    Kinematics,
    LinearSpeedConstantRate,
    Segment,
    VerticalAscent,
    VerticalDescent,
)
from .transcription import DEFAULT_NODES, STANDARD_PARAMETERS, Mission

__all__ = [
    "Mission", "DEFAULT_NODES", "STANDARD_PARAMETERS", "write_mission_report", "profiles", "segments",
    "SEGMENT_KINDS", "Segment", "Kinematics",
    "ConstantSpeedConstantAltitude", "LinearSpeedConstantRate", "ConstantAccelerationConstantAngleLinearClimb",
    "ConstantAccelerationConstantPitchrateConstantAltitude", "ConstantAccelerationConstantAltitude",
    "VerticalAscent", "VerticalDescent", "Hover",
]
