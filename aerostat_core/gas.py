"""Lifting-gas density, buoyancy and free lift (docs/methods.md §1.3)."""

from __future__ import annotations

import numpy as np

from . import constants as c
from .inputs import LiftingGas


def gas_density(gas: LiftingGas, pressure, temperature):
    """Density of the (impure) lifting gas in the hull [kg/m3].

    Ideal model: rho_pure = (P + dP) M_gas/(R_u T); rho = k rho_pure + (1 - k) (P + dP)/(R_air T)
    (purity k as a volume fraction; the impurity is air at hull pressure).
    Fixed model: the constant of ``gas.fixed_density_value`` (thesis: 0.169 kg/m3 for helium).

    Parameters
    ----------
    gas : LiftingGas
    pressure : array_like
        Ambient pressure [Pa].
    temperature : array_like
        Ambient (and gas) temperature [K]; no superheat.

    Returns
    -------
    ndarray [kg/m3]

    Notes
    -----
    Sources: ideal-gas law; PADS (docs/methods.md S3) for purity and off-standard density.

    Examples
    --------
    >>> from aerostat_core.inputs import LiftingGas
    >>> round(float(gas_density(LiftingGas(purity=1.0), 101325.0, 288.15)), 4)
    0.1693
    """
    p = np.asarray(pressure, dtype=float)
    t = np.asarray(temperature, dtype=float)
    if gas.density_model == "fixed":
        return np.full(np.broadcast(p, t).shape, gas.fixed_density_value)[()]
    molar = c.M_HELIUM if gas.kind == "helium" else c.M_HYDROGEN
    p_hull = p + gas.superpressure
    pure = p_hull * molar / (c.R_UNIVERSAL * t)
    air = p_hull / (c.R_AIR * t)
    return gas.purity * pure + (1.0 - gas.purity) * air


def gross_buoyancy(air_density, volume, g=c.G0):
    """Archimedes buoyancy F_B = rho_air g V [N] (air density [kg/m3], displaced volume [m3])."""
    return np.asarray(air_density) * g * np.asarray(volume)
