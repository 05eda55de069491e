"""US Standard Atmosphere 1976, 0 to 20 km, smooth and symbolic.

Input is the *geometric* altitude above mean sea level (what an aircraft's
altitude means); it is converted to geopotential altitude
``H = r0 h / (r0 + h)`` with r0 = 6 356 766 m (USSA76, Eq. 18).  Layers:

* troposphere, H < 11 km:  T = T0 - L H,  p = p0 (T/T0)^(g0/(R L))
* tropopause layer, 11-20 km: T = 216.65 K, p = p11 exp(-g0 (H - 11000)/(R T11))

The temperature has a corner at H = 11 km; it is rounded with
``smooth_max`` over 0.05 K (error <= 0.025 K, 0.01 %).  The two pressure laws agree
in value and slope at 11 km (dp/dH = -rho g0 is continuous), so they are blended
with a logistic weight of 30 m width: the error of the blend is second order.
The tropopause itself (H = 11 000 m) lies at geometric altitude 11 019 m, where
rho = 0.3639 kg/m^3; at geometric 11 000 m rho = 0.3648 kg/m^3.

Viscosity by Sutherland's law (USSA76, Eq. 51): mu = beta T^1.5 / (T + S),
beta = 1.458e-6 kg/(m s K^0.5), S = 110.4 K.
"""
from __future__ import annotations

import numpy as np

from .smooth import sigmoid, smooth_max, xp

__all__ = [
    "ALTITUDE_MIN_M",
    "ALTITUDE_MAX_M",
    "geopotential_altitude",
    "temperature",
    "pressure",
    "density",
    "speed_of_sound",
    "dynamic_viscosity",
    "kinematic_viscosity",
    "atmosphere",
    "check_altitude",
]

R_AIR = 287.05287      # J/(kg K), USSA76 R*/M0
GAMMA = 1.4
G0 = 9.80665           # m/s^2
R_EARTH = 6356766.0    # m, USSA76 r0
T0 = 288.15            # K
P0 = 101325.0          # Pa
LAPSE = 0.0065         # K/m
H_TROPOPAUSE = 11000.0  # m geopotential
T11 = T0 - LAPSE * H_TROPOPAUSE          # 216.65 K
P11 = P0 * (T11 / T0) ** (G0 / (R_AIR * LAPSE))  # 22632.06 Pa
SUTHERLAND_BETA = 1.458e-6
SUTHERLAND_S = 110.4

ALTITUDE_MIN_M = 0.0
ALTITUDE_MAX_M = 20000.0
_T_WIDTH_K = 0.05
_P_WIDTH_M = 30.0


def check_altitude(altitude_m, field: str = "altitude_m") -> None:
    """Raise ``ValueError`` naming ``field`` if a numeric altitude is outside 0-20 km."""
    a = np.atleast_1d(np.asarray(altitude_m, dtype=float))
    if not np.all(np.isfinite(a)) or a.min() < ALTITUDE_MIN_M - 1e-9 or a.max() > ALTITUDE_MAX_M + 1e-9:
        raise ValueError(
            f"{field} = {a.min() if a.min() < 0 else a.max():g} m is outside the atmosphere model: "
            f"allowed {ALTITUDE_MIN_M:g} to {ALTITUDE_MAX_M:g} m (US Standard Atmosphere 1976)"
        )


def geopotential_altitude(altitude_m):
    return R_EARTH * altitude_m / (R_EARTH + altitude_m)


def temperature(altitude_m):
    """Static temperature [K]."""
    H = geopotential_altitude(altitude_m)
    return smooth_max(T0 - LAPSE * H, T11, _T_WIDTH_K)


def pressure(altitude_m):
    """Static pressure [Pa]."""
    lib = xp(altitude_m)
    H = geopotential_altitude(altitude_m)
    p_trop = P0 * ((T0 - LAPSE * H) / T0) ** (G0 / (R_AIR * LAPSE))
    p_strat = P11 * lib.exp(-G0 * (H - H_TROPOPAUSE) / (R_AIR * T11))
    s = sigmoid(H - H_TROPOPAUSE, _P_WIDTH_M)
    return (1.0 - s) * p_trop + s * p_strat


def density(altitude_m):
    """Density [kg/m^3]."""
    return pressure(altitude_m) / (R_AIR * temperature(altitude_m))


def speed_of_sound(altitude_m):
    """Speed of sound [m/s]."""
    return xp(altitude_m).sqrt(GAMMA * R_AIR * temperature(altitude_m))


def dynamic_viscosity(altitude_m):
    """Dynamic viscosity [Pa s] (Sutherland)."""
    T = temperature(altitude_m)
    return SUTHERLAND_BETA * T ** 1.5 / (T + SUTHERLAND_S)


def kinematic_viscosity(altitude_m):
    """Kinematic viscosity [m^2/s]."""
    return dynamic_viscosity(altitude_m) / density(altitude_m)


def atmosphere(altitude_m):
    """All properties at once: dict with temperature_K, pressure_Pa, density_kgpm3,
    speed_of_sound_mps, dynamic_viscosity_Pas."""
    T = temperature(altitude_m)
    p = pressure(altitude_m)
    return {
        "temperature_K": T,
        "pressure_Pa": p,
        "density_kgpm3": p / (R_AIR * T),
        "speed_of_sound_mps": xp(altitude_m).sqrt(GAMMA * R_AIR * T),
        "dynamic_viscosity_Pas": SUTHERLAND_BETA * T ** 1.5 / (T + SUTHERLAND_S),
    }
