"""Mean wind profiles for the static engine (docs/methods.md §1.2; docs/dynamics.md §2.1)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from aerostat_core.base.fields import choice, number, validate

#: Heights below this are clipped when evaluating sheared profiles [m].
MIN_PROFILE_HEIGHT = 1.0


def profile_speed(profile: WindProfile, z, top_speed, top_height):
    """Wind speed at height ``z`` for a profile that gives ``top_speed`` at ``top_height``.

    uniform: U = U_top;  power: U = U_top (z/z_top)^p;
    log: U = U_top ln(z/z0)/ln(z_top/z0) (z0 = roughness length).

    Parameters
    ----------
    profile : WindProfile
    z : array_like
        Height above the winch [m] (clipped to >= 1 m).
    top_speed : array_like
        Wind at the aerostat [m/s].
    top_height : array_like
        Aerostat height above the winch [m].

    Notes
    -----
    Sources: Hellmann power law (exponent 1/7 for open terrain); logarithmic law of the neutral
    surface layer (e.g. Stull, *An Introduction to Boundary Layer Meteorology*, 1988).

    Examples
    --------
    >>> from aerostat_core.model.inputs import WindProfile
    >>> round(float(profile_speed(WindProfile("power"), 150.0, 10.0, 300.0)), 3)
    9.057
    """
    u = np.asarray(top_speed, float)
    if profile.kind == "uniform":
        return u * np.ones_like(np.asarray(z, float))
    zc = np.maximum(np.asarray(z, float), MIN_PROFILE_HEIGHT)
    ht = np.maximum(np.asarray(top_height, float), MIN_PROFILE_HEIGHT)
    if profile.kind == "power":
        return u * (zc / ht) ** profile.exponent
    z0 = profile.roughness_length
    return u * np.log(np.maximum(zc, 2 * z0) / z0) / np.log(np.maximum(ht, 2 * z0) / z0)


# --- input spec -----------------------------------------------------------------------------
WIND_PROFILES = ("uniform", "power", "log")


@dataclass(frozen=True)
class WindProfile:
    """Mean wind versus height along the tether.

    The sweep's wind speed is the wind at the aerostat's flying height; the profile scales it down
    to the tether below: power law U(z) = U_top (z/z_top)^p,
    log law U = U_top ln(z/z0)/ln(z_top/z0).

    Parameters
    ----------
    kind : {"uniform", "power", "log"}
    exponent : float
        Power-law exponent p [-], valid [0, 0.6] (1/7 open terrain).
    roughness_length : float
        Log-law roughness z0 [m], valid [1e-5, 2].
    """

    kind: str = choice(
        "uniform", "Wind profile along the tether", WIND_PROFILES,
        help="The sweep speed is the wind at the aerostat; the profile scales it down along "
        "the tether.")
    exponent: float = number(
        1.0 / 7.0, "Power-law exponent", "", 0, 0.6, step=0.01, fmt="%.3f",
        help="Used by the power-law profile (1/7 open land).")
    roughness_length: float = number(
        0.03, "Log-law roughness length", "m", 1e-5, 2, step=0.01, fmt="%.3f",
        help="Used by the log-law profile (0.03 m open land).")

    def __post_init__(self) -> None:
        validate(self)
