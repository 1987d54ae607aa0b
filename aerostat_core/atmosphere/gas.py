"""Lifting-gas density, buoyancy and free lift (docs/methods.md §1.3)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from aerostat_core.base import constants as c
from aerostat_core.base.fields import choice, number, validate


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
    >>> from aerostat_core.model.inputs import LiftingGas
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


# --- input spec -----------------------------------------------------------------------------
GAS_KINDS = ("helium", "hydrogen")
DENSITY_MODELS = ("ideal", "fixed")


@dataclass(frozen=True)
class LiftingGas:
    """Lifting gas and its state in the hull.

    Parameters
    ----------
    kind : {"helium", "hydrogen"}
    purity : float
        Volume (mole) fraction of the lifting gas; the rest is air [-], valid (0, 1].
    superpressure : float
        Hull pressure above ambient [Pa], valid [0, 5000].
    density_model : {"ideal", "fixed"}
        ``"ideal"``: ideal-gas density at ambient temperature and hull pressure, mixed with air by
        purity. ``"fixed"``: a constant density (the thesis uses 0.169 kg/m3 for helium).
    fixed_density : float or None
        Density for ``"fixed"`` [kg/m3], valid (0, 1]; ``None`` takes the thesis value of the gas.
    """

    kind: str = choice(
        "helium", "Lifting gas", GAS_KINDS, help="Hydrogen lifts about 8 % more but burns.")
    purity: float = number(
        0.98, "Gas purity", "", 0, 1, lo_open=True, scale=100.0, display_unit="% by volume",
        step=0.5, fmt="%.1f", help="The rest is air. Helium is supplied at about 98 %.")
    superpressure: float = number(
        0.0, "Hull superpressure", "Pa", 0, 5000, step=50.0, fmt="%.0f",
        help="Pressure above ambient (250-400 Pa typical).")
    density_model: str = choice(
        "ideal", "Gas density model", DENSITY_MODELS,
        help="Ideal: gas density from pressure, temperature, purity and superpressure. Fixed: "
        "the thesis' 0.169 kg/m³ for helium.")
    fixed_density: float | None = number(
        None, "Fixed gas density", "kg/m3", 0, 1, lo_open=True, empty="thesis value",
        step=0.001, fmt="%.3f",
        help="Used by the 'fixed' model only: thesis 0.169 (He), 0.085 (H₂).",
        source="thesis §2.2")

    def __post_init__(self) -> None:
        validate(self)

    @property
    def fixed_density_value(self) -> float:
        """Density used by the ``"fixed"`` model [kg/m3]."""
        if self.fixed_density is not None:
            return float(self.fixed_density)
        return c.THESIS_HELIUM_DENSITY if self.kind == "helium" else c.THESIS_HYDROGEN_DENSITY
