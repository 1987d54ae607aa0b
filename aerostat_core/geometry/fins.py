"""Tail-fin planform from statistical ratios, fin mass and the 3-D fin lift slope.

Broadcasts over a batch of hulls. A fin is a trapezoid with an unswept trailing edge; an
opposite pair is treated as one wing of span 2 S_p and area 2 S_1 (exposed-panel definition).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from aerostat_core.base.fields import choice, field_spec, integer, number, validate
from aerostat_core.base.validation import InputError
from aerostat_core.geometry.hull import HullGeometry

#: Fin angles from the horizontal [deg] for each arrangement (thesis fin count not found: G2).
ARRANGEMENT_ANGLES_DEG = {
    "+": (0.0, 90.0, 180.0, 270.0),
    "x": (45.0, 135.0, 225.0, 315.0),
    "inverted-y": (90.0, 210.0, 330.0),
}


def helmbold_lift_slope(aspect_ratio, sweep_half_chord, section_lift_slope=2.0 * np.pi):
    """3-D lift-curve slope of a low-aspect-ratio wing, DATCOM/Helmbold form (incompressible).

    C_L_alpha = 2 pi AR / (2 + sqrt((AR^2/kappa^2)(1 + tan^2 Lambda_c/2) + 4)),
    kappa = C_l_alpha/(2 pi).

    Parameters
    ----------
    aspect_ratio : array_like
        Wing aspect ratio b^2/S [-], 0.5-6.
    sweep_half_chord : array_like
        Half-chord sweep angle [rad].
    section_lift_slope : float
        Section C_l_alpha [1/rad].

    Returns
    -------
    ndarray
        C_L_alpha [1/rad].

    Notes
    -----
    Source: USAF DATCOM §4.1.3.2; Raymer, *Aircraft Design*, eq. 12.6 (Mach 0).

    Examples
    --------
    >>> round(float(helmbold_lift_slope(2.0, 0.0)), 3)
    2.603
    """
    ar = np.asarray(aspect_ratio, dtype=float)
    kappa = section_lift_slope / (2.0 * np.pi)
    t = np.tan(sweep_half_chord)
    return 2.0 * np.pi * ar / (2.0 + np.sqrt(ar**2 / kappa**2 * (1.0 + t**2) + 4.0))


def oswald_efficiency(aspect_ratio, sweep_le):
    """Oswald span efficiency, Raymer's fits, clamped to [0.7, 0.95].

    Straight wing: e = 1.78 (1 - 0.045 AR^0.68) - 0.64;
    swept (Lambda_LE > 30 deg): e = 4.61 (1 - 0.045 AR^0.68) (cos Lambda_LE)^0.15 - 3.1.
    The fits exceed 1 for AR < 2, hence the clamp (docs/methods.md §1.7). Source: Raymer eq. 12.48-12.49.

    Parameters
    ----------
    aspect_ratio : array_like [-]
    sweep_le : array_like
        Leading-edge sweep [rad].
    """
    ar = np.asarray(aspect_ratio, dtype=float)
    straight = 1.78 * (1.0 - 0.045 * ar**0.68) - 0.64
    swept = 4.61 * (1.0 - 0.045 * ar**0.68) * np.cos(sweep_le) ** 0.15 - 3.1
    e = np.where(sweep_le > np.radians(30.0), swept, straight)
    return np.clip(e, 0.7, 0.95)


@dataclass(frozen=True)
class FinGeometry:
    """Fin planform and derived data (arrays over a batch).

    Attributes: count [-]; root_chord, tip_chord, span (exposed, one fin) [m]; sweep_le [rad];
    area_one (one fin's planform) [m2]; area_total [m2]; lifting_area (planform projected on the
    horizontal, sum S_1 cos^2 phi) [m2]; aspect_ratio (pair) [-]; mac [m]; xi_root_le,
    xi_root_te, xi_ac (aerodynamic centre, quarter MAC), xi_centroid (half MAC) [m];
    y_mac (spanwise station of the MAC from the root) [m]; z_fins (vertical offsets of each fin's
    centroid from the axis) [m]; lift_slope (C_L_alpha of the pair) [1/rad]; oswald [-];
    fabric_area [m2]; mass [kg].
    """

    count: int
    root_chord: np.ndarray
    tip_chord: np.ndarray
    span: np.ndarray
    sweep_le: np.ndarray
    area_one: np.ndarray
    area_total: np.ndarray
    lifting_area: np.ndarray
    aspect_ratio: np.ndarray
    mac: np.ndarray
    xi_root_le: np.ndarray
    xi_root_te: np.ndarray
    xi_ac: np.ndarray
    xi_centroid: np.ndarray
    y_mac: np.ndarray
    z_fins: tuple
    lift_slope: np.ndarray
    oswald: np.ndarray
    fabric_area: np.ndarray
    mass: np.ndarray


def fin_geometry(
    hull: HullGeometry,
    spec: FinSpec,
    fin_areal_density: float,
    area_change=None,
    position=None,
    section_lift_slope: float = 2.0 * np.pi,
) -> FinGeometry:
    """Size the fins from the statistical ratios and the two fin design variables.

    S_total = area_ratio * S_hull * (1 + Delta S_f/100); S_1 = S_total/n;
    S_p = sqrt(AR S_1/2); RC = 2 S_1/((1 + lambda) S_p); TC = lambda RC;
    tan Lambda_LE = (RC - TC)/S_p; MAC = (2/3) RC (1 + lambda + lambda^2)/(1 + lambda);
    y_mac = (S_p/3)(1 + 2 lambda)/(1 + lambda); xi_ac = l_f + y_mac tan Lambda_LE + MAC/4,
    l_f = Delta l_f * l; mass = n * GSM_f * fabric_factor * S_1.

    Parameters
    ----------
    hull : HullGeometry
    spec : FinSpec
        Ratios and defaults for the design variables.
    fin_areal_density : float
        Fin fabric mass per area [kg/m2].
    area_change, position : array_like or None
        Override Delta S_f [%] and Delta l_f [-] (batch evaluation); ``None`` uses ``spec``.
    section_lift_slope : float
        Section C_l_alpha [1/rad] for the Helmbold slope.

    Notes
    -----
    Sources: docs/methods.md §1.5; planform relations are textbook (Raymer ch. 7); the area ratio
    0.227 is calibrated so that thesis Table 2.2's 100 m3 hull has 7.8 kg of fins (presets.py).
    """
    dsf = spec.area_change if area_change is None else np.asarray(area_change, dtype=float)
    pos = spec.position if position is None else np.asarray(position, dtype=float)
    n = spec.count
    lam = spec.taper_ratio
    s_total = spec.area_ratio * hull.surface_area * (1.0 + dsf / 100.0)
    s1 = s_total / n
    span = np.sqrt(spec.aspect_ratio * s1 / 2.0)
    rc = 2.0 * s1 / ((1.0 + lam) * span)
    tc = lam * rc
    tan_le = (rc - tc) / span
    sweep_le = np.arctan(tan_le)
    ar = 2.0 * span**2 / s1
    mac = (2.0 / 3.0) * rc * (1.0 + lam + lam**2) / (1.0 + lam)
    y_mac = span / 3.0 * (1.0 + 2.0 * lam) / (1.0 + lam)
    xi_le = pos * hull.length
    xi_le_mac = xi_le + y_mac * tan_le
    angles = np.radians(ARRANGEMENT_ANGLES_DEG[spec.arrangement])
    lifting = s1 * float(np.sum(np.cos(angles) ** 2))
    tan_c2 = tan_le - (2.0 / ar) * (1.0 - lam) / (1.0 + lam)
    cla = helmbold_lift_slope(ar, np.arctan(tan_c2), section_lift_slope)
    r_root = hull.radius_at(xi_le + 0.5 * rc)
    z_fins = tuple((r_root + y_mac) * np.sin(a) for a in angles)
    fabric = spec.fabric_factor * s1 * n
    return FinGeometry(
        count=n,
        root_chord=rc,
        tip_chord=tc,
        span=span,
        sweep_le=sweep_le,
        area_one=s1,
        area_total=s_total,
        lifting_area=lifting,
        aspect_ratio=ar,
        mac=mac,
        xi_root_le=xi_le * np.ones_like(rc),
        xi_root_te=xi_le + rc,
        xi_ac=xi_le_mac + 0.25 * mac,
        xi_centroid=xi_le_mac + 0.5 * mac,
        y_mac=y_mac,
        z_fins=z_fins,
        lift_slope=cla,
        oswald=oswald_efficiency(ar, sweep_le),
        fabric_area=fabric,
        mass=fin_areal_density * fabric,
    )


# --- input spec -----------------------------------------------------------------------------
FIN_ARRANGEMENTS = ("+", "x", "inverted-y")


@dataclass(frozen=True)
class FinSpec:
    """Tail fins: statistical sizing ratios plus the two fin design variables.

    Parameters
    ----------
    count : int
        Number of fins, 3 or 4.
    arrangement : {"+", "x", "inverted-y"}
        ``"+"``/``"x"`` need 4 fins, ``"inverted-y"`` 3 fins (one on top, two 30 deg below the
        horizontal).
    area_change : float
        Fin-area change Delta S_f from the statistical size [%], valid [-50, 200] (design
        variable 2). Lengths scale with sqrt(1 + Delta S_f/100) at constant aspect ratio and taper.
    position : float
        Root leading-edge station / hull length, Delta l_f [-], valid [0.4, 0.95] (design
        variable 3). The trailing edge must stay on the hull (checked by the engine).
    area_ratio : float
        Statistical total fin planform area / hull surface area [-], valid (0, 1].
    aspect_ratio : float
        Aspect ratio of an opposite fin pair taken as one wing, 2 S_p^2 / S_1 [-], valid [0.5, 6].
    taper_ratio : float
        Tip chord / root chord [-], valid [0.1, 1].
    fabric_factor : float
        Fabric area of one fin / its planform area [-], valid [1, 4] (two faces plus ribs/seams).
    """

    count: int = integer(4, "Number of fins", 3, 4)
    arrangement: str = choice(
        "+", "Fin arrangement", FIN_ARRANGEMENTS, help="Number and layout of the tail fins.")
    area_change: float = number(
        0.0, "Fin area change ΔS_f", "%", -50, 200, step=5.0, fmt="%.1f",
        help="Design variable 2: change of the fin area from the statistical size.")
    position: float = number(
        0.68, "Fin position Δl_f", "", 0.4, 0.95, scale=100.0, display_unit="% of hull length",
        csv_unit="fraction_of_length", step=1.0, fmt="%.1f",
        help="Design variable 3: station of the fin root leading edge from the nose; the "
        "trailing edge must stay on the hull.")
    area_ratio: float = number(
        0.227, "Fin area / hull area", "", 0, 1, lo_open=True, step=0.01, fmt="%.3f",
        help="Statistical fin size (thesis preset 0.227, calibrated).")
    aspect_ratio: float = number(
        2.0, "Fin pair aspect ratio", "", 0.5, 6, step=0.1, fmt="%.2f",
        help="Opposite pair as one wing: 2 S_p²/S_1.")
    taper_ratio: float = number(
        0.5, "Fin taper ratio", "", 0.1, 1, step=0.05, fmt="%.2f", help="Tip chord / root chord.")
    fabric_factor: float = number(
        2.2, "Fin fabric / planform area", "", 1, 4, step=0.1, fmt="%.2f",
        help="Two faces plus ribs and seams.")

    def __post_init__(self) -> None:
        validate(self)
        need = 3 if self.arrangement == "inverted-y" else 4
        if self.count != need:
            reason = f"does not fit arrangement {self.arrangement!r}, which needs {need} fins"
            raise InputError(
                f"FinSpec.count = {self.count} {reason}", owner="FinSpec", field="count",
                value=self.count, reason=reason, label=field_spec(self, "count").label,
            )
