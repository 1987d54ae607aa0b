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
    """Time constant of the purity decay tau [day].

    dk/dt = -kappa S k (T/T_0)/V, so k(t) = k_0 exp(-t/tau), tau = V T_0/(kappa S T).

    Parameters
    ----------
    volume : array_like
        Hull volume V [m3].
    area : array_like
        Envelope area S [m2].
    permeability : float
        Helium permeability kappa [L/(m2 day atm)] at standard conditions (0 degC, 1 atm),
        >= 0; 0 gives tau = inf.
    temperature : array_like
        Gas temperature in the hull [K].

    Notes
    -----
    The flux kappa S (k P_hull/1 atm) is a standard volume per day; at hull pressure and
    temperature it is kappa S k (T/T_0) (the hull pressure cancels). Valid while the outside
    helium partial pressure is nil and the fabric's permeability does not change with age
    (Lv et al. 2022 measure it falling by a factor 3-4 over 18 months of weathering).
    """
    kappa = float(permeability) * 1e-3  # m3/(m2 day atm)
    rate = kappa * np.asarray(area, float) * np.asarray(temperature, float) / c.STANDARD_TEMPERATURE
    flows = rate > 0  # elsewhere the divisor is 1: no division by zero
    return np.where(flows, np.asarray(volume, float) / np.where(flows, rate, 1.0), np.inf)


def purity_after(purity0, days, tau):
    """Helium purity after ``days`` [day] without top-up: k = k_0 exp(-t/tau) [-]."""
    return np.asarray(purity0, float) * np.exp(-np.asarray(days, float) / np.asarray(tau, float))


def lift_loss_after(volume, g, rho_air, rho_helium, purity0, days, tau):
    """Loss of free lift after ``days`` without top-up [N].

    Delta L = V g (rho_air - rho_He) (k_0 - k(t)): each volume of helium replaced by air adds
    (rho_air - rho_He) of gas mass; the displaced volume (gross buoyancy) is unchanged.

    Parameters
    ----------
    volume [m3]; g [m/s2]; rho_air, rho_helium : density of air and of pure helium at hull
    conditions [kg/m3]; purity0 [-]; days [day]; tau [day] (:func:`permeation_time_constant`).
    """
    k = purity_after(purity0, days, tau)
    return (
        np.asarray(volume, float)
        * g
        * (np.asarray(rho_air) - np.asarray(rho_helium))
        * (np.asarray(purity0, float) - k)
    )


def days_to_top_up(excess_lift, volume, g, rho_air, rho_helium, purity0, tau):
    """Days until the free lift falls to the required margin [day].

    Solves Delta L(t) = excess: k_0 - k(t) = x = excess/(V g (rho_air - rho_He)), so
    t = -tau ln(1 - x/k_0); 0 when there is no excess, inf when the purity could fall to 0 (or
    nothing permeates) before the excess is used up.

    Parameters
    ----------
    excess_lift : array_like
        Free lift now minus the required free lift [N].
    volume, g, rho_air, rho_helium, purity0, tau : see :func:`lift_loss_after`.

    Examples
    --------
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
    """Helium to add over a deployment of ``days`` to replace what permeates [m3 at 0 degC, 1 atm].

    V_top = kappa S k (P_hull/1 atm) t, with the purity held at k by the top-ups.

    Parameters
    ----------
    area [m2]; permeability kappa [L/(m2 day atm)]; purity k [-]; hull_pressure [Pa];
    days [day].

    Examples
    --------
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
