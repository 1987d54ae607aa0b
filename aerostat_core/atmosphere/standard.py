"""International Standard Atmosphere (troposphere) with a temperature offset.

Inputs are geometric altitudes above mean sea level, converted to geopotential altitude
H = r0 h/(r0 + h) before the ISA formulas (the difference is 19 m at 11 km). Valid from -500 m to
11 km. The offset shifts temperature at constant
pressure (the usual "ISA + dT" convention), so density falls on a hot day.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from aerostat_core.base import constants as c


def _check_altitude(h: np.ndarray) -> None:
    if np.any(~np.isfinite(h)) or np.any(h < c.ISA_MIN_ALTITUDE) or np.any(h > c.ISA_TROPOPAUSE):
        bad = h[~((h >= c.ISA_MIN_ALTITUDE) & (h <= c.ISA_TROPOPAUSE))]
        raise ValueError(
            f"altitude = {float(bad.flat[0]):g} m is outside the atmosphere model's valid range "
            f"[{c.ISA_MIN_ALTITUDE:g}, {c.ISA_TROPOPAUSE:g}] m"
        )


@dataclass(frozen=True)
class AtmosphereState:
    """Air state: temperature [K], pressure [Pa], density [kg/m3], dynamic viscosity [Pa s]."""

    temperature: np.ndarray
    pressure: np.ndarray
    density: np.ndarray
    viscosity: np.ndarray


def isa(altitude, isa_offset=0.0) -> AtmosphereState:
    """Air state at a geometric altitude.

    H = r0 h/(r0 + h);  T_ISA = T0 - L H;  P = P0 (T_ISA/T0)^(g0/(R L));
    T = T_ISA + dT;  rho = P/(R T);
    mu = beta T^1.5/(T + S) (Sutherland).

    Parameters
    ----------
    altitude : array_like
        Geometric altitude above mean sea level [m], valid [-500, 11000].
    isa_offset : array_like
        Temperature offset dT [K].

    Returns
    -------
    AtmosphereState

    Notes
    -----
    Source: ISO 2533:1975; U.S. Standard Atmosphere 1976 (Sutherland constants).

    Examples
    --------
    >>> round(float(isa(300.0).density), 4)
    1.1901
    """
    h = np.asarray(altitude, dtype=float)
    _check_altitude(np.atleast_1d(h))
    hp = c.ISA_EARTH_RADIUS * h / (c.ISA_EARTH_RADIUS + h)
    t_isa = c.ISA_T0 - c.ISA_LAPSE * hp
    p = c.ISA_P0 * (t_isa / c.ISA_T0) ** (c.G0 / (c.R_AIR * c.ISA_LAPSE))
    t = t_isa + np.asarray(isa_offset, dtype=float)
    rho = p / (c.R_AIR * t)
    mu = c.SUTHERLAND_BETA * t**1.5 / (t + c.SUTHERLAND_S)
    return AtmosphereState(temperature=t, pressure=p, density=rho, viscosity=mu)
