"""Ballonet sizing (thesis §2.2.1(c)): the air bag that keeps the hull full and pressurised as
the gas expands and contracts between launch and operating altitude and between night and day.
"""

from __future__ import annotations

import numpy as np


def ballonet_fraction(p_launch, t_launch, p_op, t_op, superheat=0.0):
    """Ballonet volume / hull volume needed [-].

    The helium fills the whole hull at the operating altitude on a hot day (gas temperature
    T_op + superheat); at launch on a cold night (gas at ambient T_launch) the same helium
    takes V p_op T_launch/(p_launch (T_op + dT_sh)), and the ballonet holds the rest:

    f_b = 1 - (p_op T_launch)/(p_launch (T_op + dT_sh)), clipped at 0.

    Parameters
    ----------
    p_launch, t_launch : array_like
        Ambient pressure [Pa] and temperature [K] at the launch site.
    p_op, t_op : array_like
        Ambient pressure [Pa] and temperature [K] at the operating altitude.
    superheat : float
        Day-time gas superheat over ambient at the operating altitude [K], >= 0.

    Notes
    -----
    Ideal gas, same helium mass, hull superpressure small against ambient (a few hundred Pa in
    100 kPa). Valid in the troposphere. Launch at the operating altitude with no superheat gives
    0 (no ballonet). Source: ideal-gas law; thesis §2.2.1(c) for the ballonet's role.

    Examples
    --------
    >>> round(float(ballonet_fraction(101325.0, 288.15, 95461.3, 284.9, 0.0)), 4)
    0.0471
    """
    ratio = (
        np.asarray(p_op, float)
        * np.asarray(t_launch, float)
        / (np.asarray(p_launch, float) * (np.asarray(t_op, float) + superheat))
    )
    return np.clip(1.0 - ratio, 0.0, 1.0)


def sphere_area(volume):
    """Surface area of a sphere of ``volume`` [m3]: S = (36 pi V^2)^(1/3) [m2]."""
    return (36.0 * np.pi * np.asarray(volume, float) ** 2) ** (1.0 / 3.0)


def ballonet_fabric_mass(ballonet_volume, areal_density):
    """Fabric mass of a ballonet [kg]: m = sigma S, S the area of a sphere of the ballonet's
    volume (an internal bag; a catenary diaphragm of the same volume has a similar area).

    Parameters
    ----------
    ballonet_volume : array_like
        [m3], >= 0.
    areal_density : float
        Ballonet fabric [kg/m2].
    """
    return float(areal_density) * sphere_area(ballonet_volume)
