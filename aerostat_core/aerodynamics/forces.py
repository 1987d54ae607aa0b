"""Aerodynamic forces on hull and fins versus angle of attack and dynamic pressure.

Hull: Jones & DeLaurier (1983) component model (docs/methods.md §1.7, sources S1, S6).
Axial drag: Hoerner's volumetric drag law (S10). Fins: Helmbold/DATCOM lift slope with Oswald
induced drag (S11). Forces are in body axes: normal N along body +z (up at alpha = 0), axial A
along +xi (aft, drag-like); moments nose-up positive. Every function broadcasts, so the static
engine, the batch evaluator and the dynamic model all call these same functions.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from aerostat_core.base import constants as c
from aerostat_core.base.constants import MIN_REYNOLDS
from aerostat_core.base.fields import choice, number, validate


def reynolds_number(density, speed, length, viscosity):
    """Length-based Reynolds number Re = rho V l / mu, floored at ``MIN_REYNOLDS``.

    Parameters
    ----------
    density : array_like
        Air density [kg/m3].
    speed : array_like
        Airspeed [m/s].
    length : array_like
        Hull length [m].
    viscosity : array_like
        Dynamic viscosity [Pa s].

    Notes
    -----
    The floor only matters as V -> 0, where the dynamic pressure (and so the drag) is zero.
    """
    re = np.asarray(density) * np.abs(speed) * np.asarray(length) / np.asarray(viscosity)
    return np.maximum(re, MIN_REYNOLDS)


def hoerner_volumetric_drag(fineness_ratio, reynolds):
    """Zero-lift volumetric drag coefficient of a streamlined body (Hoerner).

    C_DV = [0.172 f^(1/3) + 0.252 f^(-1.2) + 1.032 f^(-2.7)] / Re^(1/6), on V^(2/3), Re on length.

    Parameters
    ----------
    fineness_ratio : array_like
        l/d [-], valid about 2-10.
    reynolds : array_like
        Length Reynolds number [-], valid about 1e6-1e9 (turbulent boundary layer).

    Notes
    -----
    Source: Hoerner, *Fluid-Dynamic Drag* (1965) ch. 6; docs/methods.md §1.7 (confirmed in S5).

    Examples
    --------
    >>> round(float(hoerner_volumetric_drag(4.0, 1.72e7)), 4)
    0.0215
    """
    f = np.asarray(fineness_ratio, dtype=float)
    num = 0.172 * f ** (1.0 / 3.0) + 0.252 * f ** (-1.2) + 1.032 * f ** (-2.7)
    return num / np.asarray(reynolds, dtype=float) ** (1.0 / 6.0)


def hull_inviscid(q, alpha, dk, eta_k, i1, i3):
    """Potential-flow (Munk-type) hull terms of Jones & DeLaurier.

    N = q (k3 - k1) eta_k I1 sin 2alpha cos(alpha/2)
    A = -q (k3 - k1) eta_k I1 sin 2alpha sin(alpha/2)
    M = q (k3 - k1) eta_k I3 sin 2alpha cos(alpha/2)       (about the station used for I3)

    Parameters
    ----------
    q : array_like
        Dynamic pressure [Pa].
    alpha : array_like
        Angle of attack [rad], valid |alpha| < 90 deg.
    dk : array_like
        k3 - k1, Lamb transverse minus axial factor [-].
    eta_k : float
        Hull efficiency factor [-].
    i1, i3 : array_like
        Shape integrals [m2], [m3] (:func:`aerostat_core.geometry.hull.shape_integrals`).

    Returns
    -------
    N [N], A [N], M [N m]
    """
    s2 = np.sin(2.0 * alpha)
    base = q * dk * eta_k * s2
    return base * i1 * np.cos(0.5 * alpha), -base * i1 * np.sin(0.5 * alpha), (
        base * i3 * np.cos(0.5 * alpha)
    )


def hull_crossflow(q, alpha, cdc, j1, j2):
    """Viscous cross-flow hull terms of Jones & DeLaurier.

    N = q (C_dc)_h J1 sin alpha |sin alpha|,   M = q (C_dc)_h J2 sin alpha |sin alpha|.

    Parameters
    ----------
    q : array_like
        Dynamic pressure [Pa].
    alpha : array_like
        Angle of attack [rad].
    cdc : float
        Cross-flow drag coefficient [-].
    j1, j2 : array_like
        Planform area [m2] and its first moment about the reference station [m3].
    """
    s = np.sin(alpha)
    k = q * cdc * s * np.abs(s)
    return k * j1, k * j2


def hull_axial(q, alpha, cd0, reference_area):
    """Axial (zero-lift) hull drag A = q C_D0 V^(2/3) cos^2 alpha [N].

    Parameters
    ----------
    q : array_like [Pa]
    alpha : array_like [rad]
    cd0 : array_like
        Volumetric drag coefficient [-] (Hoerner or a given value).
    reference_area : array_like
        V^(2/3) [m2].
    """
    return q * cd0 * reference_area * np.cos(alpha) ** 2


def fin_lift_drag(q, alpha, lift_slope, efficiency, stall_angle, lifting_area, total_area,
                  cd0, aspect_ratio, oswald):
    """Fin lift and drag in wind axes.

    C_L = eta_f C_L_alpha clip(alpha, -alpha_s, alpha_s) (held flat past stall),
    L = q S_lift C_L;  D = q [C_D0 S_total + S_lift C_L^2/(pi e AR)].

    Parameters
    ----------
    q : array_like [Pa]
    alpha : array_like
        Angle of attack at the fins [rad].
    lift_slope : array_like
        3-D C_L_alpha of the fin pair [1/rad].
    efficiency : float
        eta_f [-].
    stall_angle : float
        [rad].
    lifting_area, total_area : array_like
        Horizontal projected planform of the lifting fins and planform of all fins [m2].
    cd0 : float
        Zero-lift drag coefficient on planform [-].
    aspect_ratio, oswald : array_like
        Pair aspect ratio [-] and span efficiency [-].

    Returns
    -------
    L [N] (perpendicular to the relative wind, up for alpha > 0), D [N] (along the wind)

    Notes
    -----
    Sources: DATCOM/Raymer (docs/methods.md §1.7, S11).
    """
    cl = efficiency * lift_slope * np.clip(alpha, -stall_angle, stall_angle)
    lift = q * lifting_area * cl
    drag = q * (cd0 * total_area + lifting_area * cl**2 / (np.pi * oswald * aspect_ratio))
    return lift, drag


def wind_to_body(lift, drag, alpha):
    """Normal and axial body-axis components of a (lift, drag) pair: N = L cos a + D sin a,
    A = D cos a - L sin a."""
    ca, sa = np.cos(alpha), np.sin(alpha)
    return lift * ca + drag * sa, drag * ca - lift * sa


def body_to_wind(normal, axial, alpha):
    """Lift and drag of body-axis (N, A): L = N cos a - A sin a, D = N sin a + A cos a."""
    ca, sa = np.cos(alpha), np.sin(alpha)
    return normal * ca - axial * sa, normal * sa + axial * ca


# --- input spec -----------------------------------------------------------------------------
CUTOFF_MODES = ("fin", "tail")


@dataclass(frozen=True)
class AeroModel:
    """Coefficients of the Jones & DeLaurier hull model and the fin model (docs/methods.md §1.7).

    Parameters
    ----------
    hull_efficiency : float
        eta_k on the inviscid (potential-flow) hull term [-], valid [0, 2].
    hull_crossflow_drag : float
        (C_dc)_h, viscous cross-flow drag coefficient [-], valid [0, 2].
    hull_axial_drag : float or None
        Zero-alpha hull drag on V^(2/3) [-], valid [0, 1]; ``None`` uses Hoerner's C_DV(f, Re).
    cutoff : {"fin", "tail"}
        Station l_h where the potential-flow term is cut off: the fin root leading edge (thesis
        symbol list "l_h: distance of fin from nose") or the tail, where the NPL profile tapers
        fastest (max -dA/dxi); "tail" gives I1 = 0 and the full Munk moment.
    fin_efficiency : float
        eta_f on the 3-D fin lift slope [-], valid [0, 1.5].
    section_lift_slope : float
        Fin section lift slope C_l_alpha [1/rad], valid [1, 7].
    fin_zero_lift_drag : float
        C_D0 of the fins on planform area [-], valid [0, 0.1].
    fin_stall_angle_deg : float
        Fin stall angle [deg], valid [5, 40]; the fin lift is held flat beyond it.
    """

    hull_efficiency: float = number(
        c.HULL_EFFICIENCY, "Hull efficiency η_k", "", 0, 2, step=0.01, fmt="%.2f",
        help="Jones & DeLaurier potential-flow factor (1.19).", source="docs/methods.md §1.7")
    hull_crossflow_drag: float = number(
        c.HULL_CROSSFLOW_DRAG, "Hull cross-flow drag (C_dc)_h", "", 0, 2, step=0.01, fmt="%.2f",
        help="Viscous cross-flow drag coefficient (0.32).", source="docs/methods.md §1.7")
    hull_axial_drag: float | None = number(
        None, "Hull drag C_DV", "", 0, 1, empty="Hoerner", step=0.001, fmt="%.4f",
        help="Zero-α hull drag on V^(2/3); empty uses Hoerner's C_DV(f, Re).")
    cutoff: str = choice(
        "fin", "Potential-flow cut-off station l_h", CUTOFF_MODES,
        help="Station where the Jones & DeLaurier potential-flow term stops.")
    fin_efficiency: float = number(
        c.FIN_EFFICIENCY, "Fin efficiency η_f", "", 0, 1.5, step=0.05, fmt="%.2f",
        help="Factor on the 3-D fin lift slope (1.0).")
    section_lift_slope: float = number(
        c.SECTION_LIFT_SLOPE, "Fin section lift slope", "1/rad", 1, 7, step=0.1, fmt="%.3f",
        help="Thin-aerofoil value 2π = 6.283.")
    fin_zero_lift_drag: float = number(
        c.FIN_ZERO_LIFT_DRAG, "Fin zero-lift drag C_D0", "", 0, 0.1, step=0.001, fmt="%.4f",
        help="On fin planform area (0.003-0.010).")
    fin_stall_angle_deg: float = number(
        c.FIN_STALL_ANGLE_DEG, "Fin stall angle", "deg", 5, 40, step=1.0, fmt="%.1f",
        help="Trim beyond it is flagged.")

    def __post_init__(self) -> None:
        validate(self)
