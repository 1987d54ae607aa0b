"""Helikite-style kite balloon: a spheroidal hull with a kite sail and keel (thesis §2.2.1).

The hull is the ``helikite`` shape of :mod:`aerostat_core.geometry.shapes` (a prolate spheroid, l/d 1.24
by default: Table 2.2's 6.2 m x 5 m). The kite is a flat low-aspect-ratio sail bridled to fly at a
fixed incidence to the wind (the keel "aids in aligning the entire system in the wind
direction": IIT Bombay DIC Helikite page, diciitb.wordpress.com/helikite), so its coefficients
do not depend on the hull's pitch:

    C_L = C_L_alpha(AR) * alpha_k  (Helmbold/DATCOM lift slope, alpha_k <= stall),
    C_D = C_L^2 / (pi e AR)  (Oswald e from Raymer's fit; the hull carries the profile drag),
    L = q S_k C_L,  D = q S_k C_D,  q = rho U^2 / 2.

Reference parameters (thesis Table 2.2, Allsopp Helikites Ltd "Aerostar" via the thesis):
100 m3, kite 11.38 kg, dynamic lift 48 kg at 15 m/s at 300 m (ISA). The sail area S_k is
CALIBRATED to that lift and scales with V^(2/3) (geometric similarity); the kite mass scales with
S_k. Limits (Table 2.1): wind <= 25 m/s, payload < 30 kg, altitude about 2 km;
:func:`helikite_limits` lists those a requirement breaks. The aspect ratio (1.5) and bridle
incidence (15 deg) are ASSUMED (constants.py); only their product with S_k is pinned by Table 2.2.

Sources: the one published Helikite performance figure held is the thesis' Table 2.2 (48 kg of
dynamic lift at 15 m/s, kite 11.38 kg, after the Allsopp Helikites "Aerostar" web page, which
was not read here) and its Table 2.1 limits. No published lift or drag coefficient of a
Helikite sail was found (docs/methods.md S18), so C_L and C_D follow from the Helmbold slope
and Oswald's induced drag at the assumed AR and incidence, and only the lift is pinned by the
thesis; the kite's drag is a prediction of that model, not a calibrated number.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from aerostat_core.atmosphere.standard import isa
from aerostat_core.base import constants as c
from aerostat_core.geometry.fins import helmbold_lift_slope, oswald_efficiency


def kite_coefficients(
    aspect_ratio: float = c.HELIKITE_KITE_ASPECT_RATIO,
    incidence_deg: float = c.HELIKITE_KITE_INCIDENCE_DEG,
):
    """Kite lift and induced-drag coefficients (C_L, C_D) on sail area [-].

    C_L = C_L_alpha alpha_k with Helmbold's slope for an unswept sail of aspect ratio AR and
    section slope 2 pi; C_D = C_L^2/(pi e AR). Valid for alpha_k below stall (about 20 deg for
    AR 1-2, docs/methods.md §1.7).

    Examples
    --------
    >>> [round(float(x), 3) for x in kite_coefficients()]
    [0.548, 0.07]
    """
    cla = helmbold_lift_slope(aspect_ratio, 0.0, 2.0 * np.pi)
    cl = cla * np.radians(incidence_deg)
    e = oswald_efficiency(aspect_ratio, 0.0)
    return float(cl), float(cl**2 / (np.pi * e * aspect_ratio))


def reference_sail_ratio() -> float:
    """Sail area / V^(2/3) [-] that gives Table 2.2's 48 kg of dynamic lift at 15 m/s, 300 m.

    S_k = m_L g / (q_ref C_L), q_ref = rho_ISA(300 m) 15^2 / 2, over V_ref^(2/3) (100 m3).
    """
    cl, _ = kite_coefficients()
    q = 0.5 * float(isa(c.HELIKITE_REF_ALTITUDE).density) * c.HELIKITE_REF_WIND**2
    s_k = c.HELIKITE_REF_DYNAMIC_LIFT_KG * c.G0 / (q * cl)
    return s_k / c.HELIKITE_REF_VOLUME ** (2.0 / 3.0)


@dataclass(frozen=True)
class KiteGeometry:
    """The kite of a Helikite (arrays over a batch): sail area [m2], lift and drag coefficients
    on it [-], mass (sail, spars, keel) [kg]."""

    area: np.ndarray
    lift_coefficient: float
    drag_coefficient: float
    mass: np.ndarray


def kite_geometry(volume) -> KiteGeometry:
    """Kite of a Helikite of hull volume ``volume`` [m3]: S_k = ratio V^(2/3),
    m_k = 11.38 kg (S_k / S_k,ref) (Table 2.2 reference, scaled by sail area)."""
    ratio = reference_sail_ratio()
    area = ratio * np.asarray(volume, dtype=float) ** (2.0 / 3.0)
    ref_area = ratio * c.HELIKITE_REF_VOLUME ** (2.0 / 3.0)
    cl, cd = kite_coefficients()
    return KiteGeometry(
        area=area,
        lift_coefficient=cl,
        drag_coefficient=cd,
        mass=c.HELIKITE_REF_KITE_MASS * area / ref_area,
    )


def kite_lift_drag(q, kite: KiteGeometry):
    """Kite lift (up, perpendicular to the wind) and drag (along it) [N] at dynamic pressure
    ``q`` [Pa]: L = q S_k C_L, D = q S_k C_D."""
    q = np.asarray(q, dtype=float)
    return q * kite.area * kite.lift_coefficient, q * kite.area * kite.drag_coefficient


def helikite_limits(payload_mass: float, altitude: float, wind: float) -> list[str]:
    """Plain-language list of the Table 2.1 Helikite limits a requirement exceeds
    (payload [kg], altitude [m], wind [m/s]); empty when within them."""
    out = []
    if payload_mass >= c.HELIKITE_MAX_PAYLOAD:
        out.append(
            f"payload {payload_mass:g} kg is not below the Helikite limit "
            f"{c.HELIKITE_MAX_PAYLOAD:g} kg (thesis Table 2.1)"
        )
    if altitude > c.HELIKITE_MAX_ALTITUDE:
        out.append(
            f"altitude {altitude:g} m is above the Helikite's ~"
            f"{c.HELIKITE_MAX_ALTITUDE:g} m (thesis Table 2.1)"
        )
    if wind > c.HELIKITE_MAX_WIND:
        out.append(
            f"wind {wind:g} m/s is above the Helikite limit {c.HELIKITE_MAX_WIND:g} m/s "
            "(thesis Table 2.1)"
        )
    return out
