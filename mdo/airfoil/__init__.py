"""Section aerodynamics: smooth cl, cd, cm of shipped airfoils over the full circle
of angle of attack, any Reynolds number and subsonic Mach number, for NumPy and
CasADi alike.

    >>> from mdo.airfoil import Airfoil, available
    >>> af = Airfoil.from_name("NACA 4412")
    >>> cl, cd, cm = af.coefficients(alpha_rad, reynolds, mach)

See ``mdo/airfoil/README.md`` for the model, its data and its measured accuracy.
"""
from .airfoil import Airfoil, available
from .model import ModelSettings, post_stall_maxima

__all__ = ["Airfoil", "available", "ModelSettings", "post_stall_maxima"]
