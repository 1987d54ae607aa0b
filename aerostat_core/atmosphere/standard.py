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
from aerostat_core.base.validation import InputError


def _check_altitude(h: np.ndarray) -> None:
    if np.any(~np.isfinite(h)) or np.any(h < c.ISA_MIN_ALTITUDE) or np.any(h > c.ISA_TROPOPAUSE):
        bad = h[~((h >= c.ISA_MIN_ALTITUDE) & (h <= c.ISA_TROPOPAUSE))]
        reason = (f"is outside the atmosphere model's valid range "
                  f"[{c.ISA_MIN_ALTITUDE:g}, {c.ISA_TROPOPAUSE:g}] m")
        raise InputError(
            f"altitude = {float(bad.flat[0]):g} m {reason}", owner="isa", field="altitude",
            value=float(bad.flat[0]), lo=c.ISA_MIN_ALTITUDE, hi=c.ISA_TROPOPAUSE, unit="m",
            reason=reason,
        )


@dataclass(frozen=True)
class AtmosphereState:
    """Air state: temperature [K], pressure [Pa], density [kg/m3], dynamic viscosity [Pa s]."""

    temperature: np.ndarray
    pressure: np.ndarray
    density: np.ndarray
    viscosity: np.ndarray


def isa(altitude, isa_offset=0.0) -> AtmosphereState:
    r"""Air state at a geometric altitude (ISA troposphere with a temperature offset).

    .. math::

        H = \frac{r_0 h}{r_0 + h}, \quad T_{ISA} = T_0 - L H, \quad
        P = P_0 \left(\frac{T_{ISA}}{T_0}\right)^{g_0/(R L)},

        T = T_{ISA} + \Delta T, \quad \rho = \frac{P}{R T}, \quad
        \mu = \frac{\beta T^{3/2}}{T + S}

    Parameters
    ----------
    altitude : array_like
        Geometric altitude above mean sea level h [m], valid [-500, 11000] (the troposphere;
        raises ``ValueError`` outside).
    isa_offset : array_like
        Temperature offset dT [K] at constant pressure; the input field is
        {range:Requirement.isa_offset}.

    Returns
    -------
    AtmosphereState

    Notes
    -----
    Valid in the troposphere, dry air. Source: ISO 2533:1975; U.S. Standard Atmosphere 1976
    (Sutherland constants); docs/methods.md §1.2.

    Examples
    --------
    The ISA table gives 1.1901 kg/m3 at 300 m and 1.2250 at sea level:

    >>> round(float(isa(300.0).density), 4)
    1.1901
    >>> round(float(isa(0.0).density), 4)
    1.225
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
