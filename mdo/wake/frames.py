"""Rotor frames and rotation sense.

Coordinates are those of the wing geometry (x aft, y to starboard, z up, metres).
A rotor is placed by its disk centre and its *wake axis* e_a: the unit vector
along which its slipstream convects, i.e. opposite to the thrust (for a tractor
propeller in cruise e_a ≈ +x; tilted with the wing or the nacelle it rotates about
y: e_a = (cos t, 0, −sin t) for a tilt t that points the thrust up).

Rotation sense ``spin`` is the sign of the rotor's angular velocity about e_a:
ω = spin · Ω · e_a.  Seen from behind (from downstream, looking forward along −e_a)
spin = +1 turns counter-clockwise.  ``spin_for(y_center_m, "inboard_up")`` gives the
sign from the usual description; for a rotor with e_a ≈ +x:

* starboard (y > 0): inboard-up ⇔ spin = −1, outboard-up ⇔ spin = +1;
* port (y < 0): inboard-up ⇔ spin = +1, outboard-up ⇔ spin = −1.

The sense is fixed to the rotor, so a rotor tilting about y (the TTW) keeps its spin.
The slipstream swirls in the same sense as the blades turn (the wake's swirl is
spin · BΓ/(2πρ) about e_a), hence inboard-up raises the upwash inboard of the
nacelle (paper §V).
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..core.errors import InputError

__all__ = ["rotor_frame", "spin_for", "SENSES"]

SENSES = ("inboard_up", "outboard_up")


def rotor_frame(axis, reference=(0.0, 1.0, 0.0)):
    """Orthonormal rotor frame (e_a, e_1, e_2) from the wake axis.

    e_a = axis/|axis|; e_1 = (reference × e_a)/|·| is the zero of blade azimuth;
    e_2 = e_a × e_1.  With the default reference (the wing's y axis) the frame is
    defined for every tilt about y, including hover (e_a = −z).  Works on numbers
    and CasADi expressions.
    """
    sym = isinstance(axis, (ca.SX, ca.MX))
    lib = ca if sym else np
    a = axis if sym else np.asarray(axis, dtype=float).reshape(3)
    ref = ca.DM(reference) if sym else np.asarray(reference, dtype=float)
    e_a = a / lib.sqrt(lib.dot(a, a)) if sym else a / np.linalg.norm(a)
    c = ca.cross(ref, e_a) if sym else np.cross(ref, e_a)
    e_1 = c / lib.sqrt(lib.dot(c, c)) if sym else c / np.linalg.norm(c)
    e_2 = ca.cross(e_a, e_1) if sym else np.cross(e_a, e_1)
    return e_a, e_1, e_2


def spin_for(y_center_m: float, sense: str, axis=(1.0, 0.0, 0.0)) -> int:
    """Spin sign (±1 about the wake axis) for a rotation ``sense`` at lateral position
    ``y_center_m``: "inboard_up" (blade rises on the side nearer the symmetry plane)
    or "outboard_up".  ``axis`` is the wake axis at zero tilt (default +x)."""
    if sense not in SENSES:
        raise InputError("sense", f"must be one of {SENSES}, got {sense!r}")
    y = float(y_center_m)
    if y == 0.0:
        raise InputError("y_center_m", "a rotor on the symmetry plane has no inboard side; give spin directly")
    e_a = np.asarray(axis, dtype=float)
    e_a = e_a / np.linalg.norm(e_a)
    e_in = np.array([0.0, -np.sign(y), 0.0])
    # blade velocity at the inboard tip is spin·Ω·(e_a × e_in); its z part must be > 0
    up = float(np.cross(e_a, e_in)[2])
    if abs(up) < 1e-9:
        raise InputError("axis", "inboard/outboard-up is undefined for an axis along y or z")
    s = 1 if up > 0 else -1
    return s if sense == "inboard_up" else -s
