"""mdo: whole-mission design optimization of propeller-driven aircraft.

Disciplines (each a subpackage, depending downward only):
``mission`` -> ``vehicle`` -> ``rotor`` / ``wake`` / ``wing`` / ``powertrain`` ->
``airfoil`` / ``core``; ``nlp`` (the problem builder) and ``cli`` sit on top.
See ``mdo/README.md`` for the architecture.
"""
__version__ = "0.1.0"
