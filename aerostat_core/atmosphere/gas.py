"""Lifting-gas density, buoyancy and free lift (docs/methods.md §1.3)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from aerostat_core.base import constants as c
from aerostat_core.base.fields import choice, number, validate


def gas_density(gas: LiftingGas, pressure, temperature):
    r"""Density of the (impure) lifting gas in the hull [kg/m3].

    Ideal model: the pure gas at hull pressure and ambient temperature, mixed by volume with air
    at the same state:

    .. math::

        \rho_{pure} = \frac{(P + \Delta P)\, M_{gas}}{R_u T}, \qquad
        \rho = k\, \rho_{pure} + (1 - k) \frac{P + \Delta P}{R_{air} T}

    with the purity k = ``gas.purity``, valid {range:LiftingGas.purity}, and the superpressure
    dP = ``gas.superpressure``, valid {range:LiftingGas.superpressure}. Fixed model: the constant
    ``gas.fixed_density_value`` (thesis: 0.169 kg/m3 for helium).

    Parameters
    ----------
    gas : LiftingGas
        Kind, purity, superpressure and density model.
    pressure : array_like
        Ambient pressure P [Pa], > 0.
    temperature : array_like
        Ambient (and gas) temperature T [K], > 0; no superheat.

    Returns
    -------
    ndarray [kg/m3]

    Notes
    -----
    Valid for an ideal gas (pressures near atmospheric, far from condensation) with the gas at
    ambient temperature. Source: ideal-gas law; PADS (docs/methods.md §1.3, S3) for purity and
    off-standard density.

    Examples
    --------
    Pure helium at ISA sea level, P M_He/(R_u T) = 101325 x 0.0040026/(8.31446 x 288.15) =
    0.1693 kg/m3 (by hand; the thesis rounds it to 0.169):

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
    r"""Archimedes buoyancy of a displaced volume [N].

    .. math::

        F_B = \rho_{air}\, g\, V

    Parameters
    ----------
    air_density : array_like
        Ambient air density [kg/m3], > 0.
    volume : array_like
        Displaced volume V [m3], >= 0.
    g : float
        Gravitational acceleration [m/s2] (standard gravity by default).

    Returns
    -------
    ndarray [N]

    Notes
    -----
    Valid for a body wholly immersed in air of uniform density (the density change over the
    height of a hull, about 0.1 % per 10 m, is neglected). Source: Archimedes' principle;
    docs/methods.md §1.3.

    Examples
    --------
    100 m3 at the ISA sea-level density 1.225 kg/m3: 1.225 x 9.80665 x 100 = 1201.3 N (by hand):

    >>> round(float(gross_buoyancy(1.225, 100.0)), 1)
    1201.3
    """
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
        Volume (mole) fraction of the lifting gas; the rest is air [-], valid {range:LiftingGas.purity}.
    superpressure : float
        Hull pressure above ambient [Pa], valid {range:LiftingGas.superpressure}.
    density_model : {"ideal", "fixed"}
        ``"ideal"``: ideal-gas density at ambient temperature and hull pressure, mixed with air by
        purity. ``"fixed"``: a constant density (the thesis uses 0.169 kg/m3 for helium).
    fixed_density : float or None
        Density for ``"fixed"`` [kg/m3], valid {range:LiftingGas.fixed_density}; ``None`` takes the thesis value of the gas.
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
