"""Endurance: helium permeation through the envelope, purity and lift decay, top-up gas.

Model (issue 13 item 2): the hull volume is held constant by the pressure system, so every litre
of helium that permeates out is replaced by air; helium leaves at a rate proportional to its
partial-pressure difference across the fabric (the permeability figure is per atmosphere of
helium), so the purity k decays exponentially and the free lift falls with it. Seams, valves
and damage leak more than the fabric (measured leaks of whole aerostats exceed the fabric
figure); use a higher effective permeability to cover them. With hydrogen the fabric's figure
is applied as given (hydrogen permeates faster than helium through most films: enter its own
figure).

Permeability figures (docs/methods.md §1.14): the measured ones are Lv et al. 2022 (S15), 0.8818
and 0.6360 L/(m2 day atm) on new 3216LV and FV1175 laminates, about 0.2 after 18 months of
coastal ageing. The default 2.5 L/m2/day "ADRDE" figure was seen only second-hand (S8); its
primary source was not found (S18). Model: Fick's-law flux proportional to the helium partial
pressure difference, the definition of a permeability quoted per atmosphere.
"""

from __future__ import annotations

import numpy as np

from aerostat_core.base import constants as c


def permeation_time_constant(volume, area, permeability, temperature):
    r"""Time constant of the purity decay tau [day].

    .. math::

        \frac{dk}{dt} = -\frac{\kappa S k}{V} \frac{T}{T_0}
        \quad\Rightarrow\quad k(t) = k_0 e^{-t/\tau}, \qquad
        \tau = \frac{V T_0}{\kappa S T}

    Parameters
    ----------
    volume : array_like
        Hull volume V [m3], > 0.
    area : array_like
        Envelope area S [m2], >= 0.
    permeability : float
        Helium permeability kappa [L/(m2 day atm)] at standard conditions (0 degC, 1 atm),
        >= 0 (the input field Fabric.helium_permeability bounds it further); 0 gives tau = inf.
    temperature : array_like
        Gas temperature in the hull T [K], > 0.

    Returns
    -------
    ndarray [day]

    Notes
    -----
    The flux kappa S (k P_hull/1 atm) is a standard volume per day; at hull pressure and
    temperature it is kappa S k (T/T_0) (the hull pressure cancels). Valid while the outside
    helium partial pressure is nil and the fabric's permeability does not change with age
    (Lv et al. 2022 measure it falling by a factor 3-4 over 18 months of weathering).
    Source: Fick's law with the permeability per atmosphere of partial pressure;
    docs/methods.md §1.14, S15.

    Examples
    --------
    100 m3 in 100 m2 of 2.5 L/(m2 day atm) fabric at 0 degC: tau = 100/(0.0025 x 100) = 400 days
    (by hand):

    >>> float(permeation_time_constant(100.0, 100.0, 2.5, 273.15))
    400.0
    """
    kappa = float(permeability) * 1e-3  # m3/(m2 day atm)
    rate = kappa * np.asarray(area, float) * np.asarray(temperature, float) / c.STANDARD_TEMPERATURE
    flows = rate > 0  # elsewhere the divisor is 1: no division by zero
    return np.where(flows, np.asarray(volume, float) / np.where(flows, rate, 1.0), np.inf)


def purity_after(purity0, days, tau):
    r"""Helium purity after ``days`` without top-up [-].

    .. math::

        k(t) = k_0\, e^{-t/\tau}

    Parameters
    ----------
    purity0 : array_like
        Purity at the start k_0 [-], valid {range:LiftingGas.purity}.
    days : array_like
        Time since the last top-up t [day], >= 0.
    tau : array_like
        Time constant [day] (:func:`permeation_time_constant`), > 0 or inf.

    Returns
    -------
    ndarray [-]

    Notes
    -----
    Valid under the assumptions of :func:`permeation_time_constant`. Source: the solution of its
    decay equation; docs/methods.md §1.14.

    Examples
    --------
    One time constant from 98 %: 0.98/e = 0.3605 (by hand):

    >>> round(float(purity_after(0.98, 400.0, 400.0)), 4)
    0.3605
    """
    return np.asarray(purity0, float) * np.exp(-np.asarray(days, float) / np.asarray(tau, float))


def lift_loss_after(volume, g, rho_air, rho_helium, purity0, days, tau):
    r"""Loss of free lift after ``days`` without top-up [N].

    Each volume of helium replaced by air adds (rho_air - rho_He) of gas mass; the displaced volume
    (gross buoyancy) is unchanged:

    .. math::

        \Delta L = V g (\rho_{air} - \rho_{He}) \left(k_0 - k(t)\right)

    Parameters
    ----------
    volume : array_like
        Hull volume V [m3], > 0.
    g : float
        Gravitational acceleration [m/s2].
    rho_air, rho_helium : array_like
        Density of air and of pure helium at hull conditions [kg/m3].
    purity0 : array_like
        Purity at the start k_0 [-], valid {range:LiftingGas.purity}.
    days : array_like
        Time since the last top-up [day], >= 0.
    tau : array_like
        Time constant [day] (:func:`permeation_time_constant`).

    Returns
    -------
    ndarray [N]

    Notes
    -----
    Valid under the assumptions of :func:`permeation_time_constant`, with the hull volume held by
    the pressure system. Source: docs/methods.md §1.14 (issue 13 item 2).

    Examples
    --------
    Pure helium, half gone after tau ln 2; with a density difference of 1 kg/m3 the loss is
    100 x 9.80665 x 1 x 0.5 = 490.33 N (by hand):

    >>> round(float(lift_loss_after(100.0, 9.80665, 1.17, 0.17, 1.0, 400.0 * np.log(2.0), 400.0)), 2)
    490.33
    """
    k = purity_after(purity0, days, tau)
    return (
        np.asarray(volume, float)
        * g
        * (np.asarray(rho_air) - np.asarray(rho_helium))
        * (np.asarray(purity0, float) - k)
    )


def days_to_top_up(excess_lift, volume, g, rho_air, rho_helium, purity0, tau):
    r"""Days until the free lift falls to the required margin [day].

    Solves Delta L(t) = excess for t:

    .. math::

        x = \frac{L_{excess}}{V g (\rho_{air} - \rho_{He})}, \qquad
        t = -\tau \ln\left(1 - \frac{x}{k_0}\right)

    0 when there is no excess, inf when the purity could fall to 0 (or nothing permeates) before
    the excess is used up.

    Parameters
    ----------
    excess_lift : array_like
        Free lift now minus the required free lift [N].
    volume : array_like
        Hull volume [m3], > 0.
    g : float
        Gravitational acceleration [m/s2].
    rho_air, rho_helium : array_like
        Density of air and of pure helium at hull conditions [kg/m3].
    purity0 : array_like
        Purity now [-], valid {range:LiftingGas.purity}.
    tau : array_like
        Time constant [day] (:func:`permeation_time_constant`).

    Returns
    -------
    ndarray [day]

    Notes
    -----
    Valid under the assumptions of :func:`lift_loss_after`. Source: docs/methods.md §1.14.

    Examples
    --------
    1 kgf of excess on 100 m3 (Delta rho = 1.03 kg/m3, 98 % pure, tau = 500 days):
    x = 1/103 = 0.009709, t = -500 ln(1 - 0.009709/0.98) = 4.978 days (by hand):

    >>> round(float(days_to_top_up(9.80665, 100.0, 9.80665, 1.2, 0.17, 0.98, 500.0)), 2)
    4.98
    """
    dl = np.asarray(volume, float) * g * (np.asarray(rho_air) - np.asarray(rho_helium))
    x = np.asarray(excess_lift, float) / np.maximum(dl, 1e-12)
    frac = np.minimum(np.maximum(x / np.asarray(purity0, float), 0.0), 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -np.asarray(tau, float) * np.log1p(-frac)
    # frac = 1: the purity could fall to 0 first; NaN (tau = inf: nothing permeates): never
    t = np.where((frac >= 1.0) | np.isnan(t), np.inf, t)
    return np.where(np.asarray(excess_lift) <= 0.0, 0.0, t)


def helium_top_up(area, permeability, purity, hull_pressure, days):
    r"""Helium to add over a deployment of ``days`` to replace what permeates [m3 at 0 degC, 1 atm].

    With the purity held at k by the top-ups:

    .. math::

        V_{top} = \kappa\, S\, k \frac{P_{hull}}{1\,\mathrm{atm}}\, t

    Parameters
    ----------
    area : array_like
        Envelope area S [m2], >= 0.
    permeability : float
        Helium permeability kappa [L/(m2 day atm)], >= 0.
    purity : array_like
        Purity held by the top-ups k [-], valid {range:LiftingGas.purity}.
    hull_pressure : array_like
        Absolute gas pressure in the hull [Pa].
    days : float
        Deployment t [day], >= 0.

    Returns
    -------
    ndarray [m3] at standard conditions.

    Notes
    -----
    Valid under the assumptions of :func:`permeation_time_constant`. Source: Fick's law as
    there; docs/methods.md §1.14.

    Examples
    --------
    100 m2 at 2.5 L/(m2 day atm) for 30 days at 1 atm: 0.0025 x 100 x 30 = 7.5 m3 (by hand):

    >>> round(float(helium_top_up(100.0, 2.5, 1.0, 101325.0, 30.0)), 3)
    7.5
    """
    return (
        float(permeability)
        * 1e-3
        * np.asarray(area, float)
        * np.asarray(purity, float)
        * np.asarray(hull_pressure, float)
        / c.STANDARD_PRESSURE
        * float(days)
    )
