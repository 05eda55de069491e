"""Unit conversions, used only at the edges (problem files, CLI, reports).

Inside the package everything is SI.  Each constant is the SI value of one unit:
``speed_mps = 175 * MPH``; ``speed_mph = speed_mps / MPH``.  Exact definitions
(NIST SP 811) where they exist.
"""
from __future__ import annotations

import math

FT = 0.3048                     # m
INCH = 0.0254                   # m
NMI = 1852.0                    # m
MILE = 1609.344                 # m
MPH = 0.44704                   # m/s
KNOT = NMI / 3600.0             # m/s
FT_PER_MIN = FT / 60.0          # m/s
LB = 0.45359237                 # kg (pound mass)
LBF = 4.4482216152605           # N  (pound force)
HP = 745.69987158227022         # W  (mechanical horsepower)
KWH = 3.6e6                     # J
WH = 3600.0                     # J
DEG = math.pi / 180.0           # rad
RPM = 2.0 * math.pi / 60.0      # rad/s
MINUTE = 60.0                   # s
HOUR = 3600.0                   # s
G0 = 9.80665                    # m/s^2, standard gravity


def ft_to_m(x):
    return x * FT


def m_to_ft(x):
    return x / FT


def mph_to_mps(x):
    return x * MPH


def mps_to_mph(x):
    return x / MPH


def kn_to_mps(x):
    return x * KNOT


def mps_to_kn(x):
    return x / KNOT


def lb_to_kg(x):
    return x * LB


def kg_to_lb(x):
    return x / LB


def hp_to_w(x):
    return x * HP


def w_to_hp(x):
    return x / HP


def kwh_to_j(x):
    return x * KWH


def j_to_kwh(x):
    return x / KWH


def fpm_to_mps(x):
    return x * FT_PER_MIN


def mps_to_fpm(x):
    return x / FT_PER_MIN


def deg_to_rad(x):
    return x * DEG


def rad_to_deg(x):
    return x / DEG


def rpm_to_radps(x):
    return x * RPM


def radps_to_rpm(x):
    return x / RPM


def as_read(value, unit: str):
    """``(value, unit)`` as a person reads it: radians in degrees, anything else as is.

    ``value``: a number or (nested) list/array; returns a float array and the unit name.
    The one conversion the summaries, the run report and ``mdo check`` share.
    """
    import numpy as np
    a = np.asarray(np.nan if value is None else value, dtype=float) + 0.0   # + 0.0: no "-0"
    if unit == "rad":
        return np.degrees(a), "deg"
    return a, unit
