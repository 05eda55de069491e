"""The contract between a mission and a vehicle: what the vehicle does at the nodes.

The mission (``mdo.mission``) owns the *transcription*: segments, their prescribed
kinematics, CGL nodes, state collocation, joins and the point-mass equations of
motion.  The vehicle owns the *physics*: the forces it produces at a flight
condition, the implicit models it needs solved there (BEMT inflow, motor-rotor
torque match, ...), and the rates of its own states (battery).  This split is the
one Dymos makes between a transcription and an ODE system.

A vehicle is any object with the attributes and methods of :class:`Vehicle`
(duck-typed; nothing here needs subclassing):

``setup(problem)``
    Add the vehicle's design variables to ``problem`` (anything with ``variable()``
    and ``constrain()`` like ``mdo.nlp.Problem``) and keep their expressions.
    Called by the mission before anything else; must be idempotent for a given
    problem (two missions may share one vehicle).
``parameters`` -> ``dict[str, float]``
    Per-segment settings the vehicle understands, with defaults (SI), e.g.
    ``{"wing_mounted_angle_rad": 0.0, "pitch_command_rad": 0.0}``.  A segment
    sets them (Table 5's WMA x beta_c); the mission hands them over per node.
``unknowns()`` -> ``list[Unknown]``
    Per-node unknowns besides the body angle (rotor speed per rotor group, BEMT
    inflow angles per station and group, thrust, ...), each ``rows`` x K.
``states()`` -> ``list[State]``
    States the mission must collocate (battery energy drawn or state of charge).
``energy_used_J(initial, final)``
    Battery energy used between two state dicts (the objective E_EOF of Eq. 7).
``initial_guess(nodes)`` -> ``dict``
    Physics-based guesses (numpy, rows x K) for each unknown and for
    ``"body_angle_rad"`` from the *numeric* node conditions (momentum-theory
    power, level-flight angle of attack).
``final_limits(final_states)`` -> ``list[ResidualGroup]`` (optional)
    Scalar inequalities on the states at the end of the mission (e.g. the state of
    charge that must remain after the reserve); the mission constrains them.
``evaluate(nodes, unknowns)`` -> :class:`NodeEvaluation`
    The physics at ALL K nodes of the mission at once (rows are nodes): forces
    in the path frame, residual groups, state derivatives, outputs.  Evaluating
    every node in one call lets a vehicle batch its work - one factorization
    ``A(d)[G_1 ... G_K] = [b_1 ... b_K]`` for the wing, a BEMT ``Function``
    mapped over nodes - so the graph grows linearly with the node count.

Frames and signs (2-D point mass in the vertical plane, x forward, z up):
the flight-path angle ``gamma`` is the angle of the velocity above the horizon
(+90 deg for a vertical ascent, -90 deg for a vertical descent, set by the
segment even at zero speed, so hover has a frame); the body angle ``theta`` is the
pitch attitude of the fuselage x axis above the horizon; the angle of attack of
the body is ``alpha = theta - gamma``.  The path frame has the unit vectors
``e_t = (cos gamma, sin gamma)`` (along the velocity) and
``e_n = (-sin gamma, cos gamma)`` (normal, "up" for level flight).  The vehicle
returns the resultant of every force except gravity in that frame:
``force_along_path_N`` (thrust minus drag, ...) and ``force_normal_N`` (lift plus
the normal component of thrust, ...).  The mission closes Newton's law::

    m dV/dt       = F_t - m g sin(gamma)
    m V dgamma/dt = F_n - m g cos(gamma)
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Protocol, Sequence, runtime_checkable

import casadi as ca
import numpy as np

__all__ = [
    "G0",
    "Unknown",
    "State",
    "ResidualGroup",
    "Output",
    "NodeConditions",
    "NodeEvaluation",
    "Vehicle",
    "path_components",
    "rotate_to_path",
]

G0 = 9.80665  # m/s^2, standard gravity (the mission's weight uses it too)


@dataclass(frozen=True)
class Unknown:
    """A per-node unknown the mission makes a variable of shape ``rows`` x K.

    ``scale`` is a typical magnitude (IPOPT sees value/scale); ``lower``/``upper``
    are bounds in ``unit``; each may be a number or a sequence of ``rows``
    numbers.  ``row_labels`` name the rows (e.g. ``["front", "rear"]``).
    ``only_where``: the name of a segment parameter; the unknown is then a variable
    only at the nodes where that parameter is > 0 (a control some segments allow,
    e.g. a drag device on approach) and the vehicle sees zeros elsewhere.
    ``replaces`` and ``max_rate`` (with ``only_where``): a control that takes over a
    segment parameter, continuous across segment joins and rate-limited
    (:meth:`mdo.mission.Mission` adds the groups "<name> continuity" and "<name> rate").
    """

    name: str
    unit: str = "-"
    scale: float | Sequence[float] = 1.0
    lower: float | Sequence[float] = -np.inf
    upper: float | Sequence[float] = np.inf
    rows: int = 1
    description: str = ""
    row_labels: Sequence[str] | None = None
    only_where: str | None = None
    #: a control that acts on the mission only through the state derivatives (a blade
    #: pitch, not a rotor speed that a force balance fixes): where the collocation does not
    #: look at the derivative (the first node of each segment in the differentiation
    #: form) it would be undetermined, so there it holds the next node's value
    hold_where_uncollocated: bool = False
    #: the segment parameter this control takes over where it is a variable (e.g. a
    #: tilt-wing's ``wing_mounted_angle_rad``): the mission then holds the control
    #: continuous at every segment join, against the parameter's value where the
    #: neighbouring segment keeps it prescribed (a wing cannot jump)
    replaces: str | None = None
    #: the largest rate of change of the control, ``unit`` per second, at every node of
    #: the segments where it is a variable (an actuator's rate; None: unlimited)
    max_rate: float | None = None


@dataclass(frozen=True)
class State:
    """A state the mission collocates: ``dx/dt = f`` from ``NodeEvaluation.state_derivatives``.

    ``initial`` is the value at the start of the mission (``None``: free, e.g. an
    initial state of charge the optimizer may choose).  States are continuous
    across segment joins.
    """

    name: str
    unit: str = "-"
    scale: float = 1.0
    initial: float | None = 0.0
    lower: float = -np.inf
    upper: float = np.inf
    description: str = ""


@dataclass
class ResidualGroup:
    """Residuals the mission constrains to zero: ``expr`` is rows x K (K = nodes).

    ``scale`` is a typical magnitude of the residual's terms in ``unit``
    (the constraint IPOPT sees is expr/scale).  ``kind`` may be ``'<='`` or
    ``'>='`` for limits (e.g. a cell current), compared with zero.
    ``columns``: the node indices of the columns of ``expr`` when it covers only
    some nodes (rows x len(columns)); None = all K nodes.
    ``defines``: the name of an :class:`Unknown` this equality defines, ``expr =
    unknown - definition`` (the unknown with coefficient one, in its own unit): a
    quantity computed at the nodes that the NLP carries as a variable (a *lifted*
    intermediate, Albersmeyer & Diehl, SIAM J. Optim. 20(3), 2010), which makes the
    Hessian sparser; the problem starts it at its definition's value
    (``mdo.nlp.Problem.constrain(defines=...)``), so the vehicle guesses nothing for it.
    """

    name: str
    expr: Any
    scale: float = 1.0
    unit: str = "-"
    kind: str = "=="
    row_labels: Sequence[str] | None = None
    columns: Sequence[int] | None = None
    defines: str | None = None


@dataclass
class Output:
    """A quantity at the nodes (rows x K, usually 1 x K) for reports and objectives."""

    expr: Any
    unit: str = "-"
    description: str = ""


@dataclass
class NodeConditions:
    """The flight condition at every node of the mission, as 1 x K rows.

    In :meth:`Vehicle.evaluate` the rows are CasADi objects (``DM`` for what the
    kinematics fix, ``MX`` for what is unknown: body angle, pitch rate, states,
    time if a duration is free).  In :meth:`Vehicle.initial_guess` they are 1-D
    numpy arrays and ``body_angle_rad`` holds the prescribed values where a
    segment prescribes the attitude and NaN where the vehicle should guess it.
    """

    time_s: Any
    altitude_m: Any
    speed_mps: Any                   # airspeed magnitude (no wind)
    flight_path_angle_rad: Any
    acceleration_mps2: Any           # dV/dt along the path
    flight_path_angle_rate_radps: Any
    body_angle_rad: Any
    pitch_rate_radps: Any
    parameters: dict = field(default_factory=dict)   # name -> row (segment settings)
    states: dict = field(default_factory=dict)       # name -> row
    segment: Sequence[str] = ()       # segment name per node
    labels: Sequence[str] = ()        # "CR node 3" per node

    @property
    def size(self) -> int:
        return len(self.labels)


@dataclass
class NodeEvaluation:
    """What the vehicle returns for all K nodes.

    ``mass_kg`` is a scalar or 1 x K; ``force_along_path_N``/``force_normal_N`` are
    1 x K (every force but gravity, in the path frame); ``residuals`` are the
    vehicle's own implicit equations; ``state_derivatives`` maps each declared
    state to its 1 x K rate; ``outputs`` maps names to :class:`Output` (the
    mission's report looks for ``CL``, ``thrust_N``, ``rotor_speed_rpm``,
    ``shaft_power_W``, ``battery_power_W``, ``state_of_charge`` and writes every
    1 x K output it is given).  ``distributions`` are quantities along a span or a
    blade at every node (rows x K: section cl per lattice strip, ...), for reports;
    they are not columns of the mission table.
    """

    mass_kg: Any
    force_along_path_N: Any
    force_normal_N: Any
    residuals: list = field(default_factory=list)
    force_scale_N: float | None = None          # typical force (weight) for scaling the force balance
    state_derivatives: dict = field(default_factory=dict)
    outputs: dict = field(default_factory=dict)
    distributions: dict = field(default_factory=dict)   # name -> Output, rows x K (spanwise, radial)


@runtime_checkable
class Vehicle(Protocol):
    """What the mission needs of a vehicle (see the module docstring)."""

    name: str
    parameters: dict

    def setup(self, problem) -> None: ...

    def unknowns(self) -> list: ...

    def states(self) -> list: ...

    def energy_used_J(self, initial: dict, final: dict): ...

    def initial_guess(self, nodes: NodeConditions) -> dict: ...

    def evaluate(self, nodes: NodeConditions, unknowns: dict) -> NodeEvaluation: ...


def path_components(fx, fz, gamma):
    """Inertial (horizontal ``fx``, vertical ``fz``) force -> (along-path, normal) components."""
    lib = ca if isinstance(gamma, (ca.SX, ca.MX, ca.DM)) or isinstance(fx, (ca.SX, ca.MX, ca.DM)) \
        or isinstance(fz, (ca.SX, ca.MX, ca.DM)) else np
    c, s = lib.cos(gamma), lib.sin(gamma)
    return fx * c + fz * s, -fx * s + fz * c


def rotate_to_path(magnitude, angle_to_path):
    """A force of ``magnitude`` at ``angle_to_path`` above the velocity -> (along, normal).

    For a thrust line inclined at ``phi`` above the horizon, ``angle_to_path =
    phi - gamma``; for a rotor with wing-mounted angle ``WMA`` on a body at
    ``theta``, ``phi = theta + incidence + WMA``.
    """
    lib = ca if any(isinstance(a, (ca.SX, ca.MX, ca.DM)) for a in (magnitude, angle_to_path)) else np
    return magnitude * lib.cos(angle_to_path), magnitude * lib.sin(angle_to_path)
