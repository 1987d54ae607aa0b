"""Ballonet sizing (thesis §2.2.1(c)): the air bag that keeps the hull full and pressurised as
the gas expands and contracts between launch and operating altitude and between night and day.
"""

from __future__ import annotations

import numpy as np


def ballonet_fraction(p_launch, t_launch, p_op, t_op, superheat=0.0):
    r"""Ballonet volume / hull volume needed [-].

    The helium fills the whole hull at the operating altitude on a hot day (gas temperature
    T_op + superheat); at launch on a cold night (gas at ambient T_launch) the same helium
    takes V p_op T_launch/(p_launch (T_op + dT_sh)), and the ballonet holds the rest:

    .. math::

        f_b = \max\left(0,\; 1 - \frac{p_{op} T_{launch}}{p_{launch} (T_{op} + \Delta T_{sh})}\right)

    Parameters
    ----------
    p_launch, t_launch : array_like
        Ambient pressure [Pa] and temperature [K] at the launch site.
    p_op, t_op : array_like
        Ambient pressure [Pa] and temperature [K] at the operating altitude.
    superheat : float
        Day-time gas superheat over ambient at the operating altitude [K], valid
        {range:MissionSpec.superheat}.

    Returns
    -------
    ndarray [-]

    Notes
    -----
    Ideal gas, same helium mass, hull superpressure small against ambient (a few hundred Pa in
    100 kPa). Valid in the troposphere. Launch at the operating altitude with no superheat gives
    0 (no ballonet). Source: ideal-gas law; thesis §2.2.1(c) for the ballonet's role;
    docs/methods.md §1.14.

    Examples
    --------
    Sea level to 500 m ISA (95461 Pa, 284.9 K): 1 - 95461.3 x 288.15/(101325 x 284.9) = 0.0471
    (by hand):

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
    r"""Surface area of a sphere of a given volume [m2].

    .. math::

        S = \left(36 \pi V^2\right)^{1/3}

    Parameters
    ----------
    volume : array_like
        Volume V [m3], valid >= 0.

    Returns
    -------
    ndarray [m2]

    Notes
    -----
    Source: geometry of the sphere (S = 4 pi r^2, V = 4 pi r^3/3); docs/methods.md §1.14.

    Examples
    --------
    The unit sphere, V = 4 pi/3, has S = 4 pi = 12.566 m2:

    >>> round(float(sphere_area(4 * np.pi / 3)), 3)
    12.566
    """
    return (36.0 * np.pi * np.asarray(volume, float) ** 2) ** (1.0 / 3.0)


def ballonet_fabric_mass(ballonet_volume, areal_density):
    r"""Fabric mass of a ballonet [kg], sized as a sphere of the ballonet's volume (an internal bag;
    a catenary diaphragm of the same volume has a similar area).

    .. math::

        m = \sigma\, \left(36 \pi V_b^2\right)^{1/3}

    Parameters
    ----------
    ballonet_volume : array_like
        V_b [m3], valid >= 0.
    areal_density : float
        Ballonet fabric sigma [kg/m2], valid {range:Fabric.areal_density}.

    Returns
    -------
    ndarray [kg]

    Notes
    -----
    Source: :func:`sphere_area`; docs/methods.md §1.14.

    Examples
    --------
    The unit sphere in 200 g/m2 fabric: 0.2 x 4 pi = 2.513 kg:

    >>> round(float(ballonet_fabric_mass(4 * np.pi / 3, 0.2)), 3)
    2.513
    """
    return float(areal_density) * sphere_area(ballonet_volume)
