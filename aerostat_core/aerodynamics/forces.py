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
    r"""Length-based Reynolds number, floored at ``MIN_REYNOLDS``.

    .. math::

        Re = \max\left(\frac{\rho |V| l}{\mu}, Re_{min}\right)

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

    Returns
    -------
    ndarray [-]

    Notes
    -----
    Valid for any speed; the floor only matters as V -> 0, where the dynamic pressure (and so the
    drag) is zero. Source: definition (e.g. Hoerner 1965 ch. 1); docs/methods.md §1.7.

    Examples
    --------
    10 m at 10 m/s in ISA sea-level air (mu = 1.7894e-5 Pa s): 1.225 x 100/1.7894e-5 = 6.846e6
    (by hand):

    >>> round(float(reynolds_number(1.225, 10.0, 10.0, 1.7894e-5)) / 1e6, 3)
    6.846
    """
    re = np.asarray(density) * np.abs(speed) * np.asarray(length) / np.asarray(viscosity)
    return np.maximum(re, MIN_REYNOLDS)


def hoerner_volumetric_drag(fineness_ratio, reynolds):
    r"""Zero-lift volumetric drag coefficient of a streamlined body (Hoerner), on V^(2/3).

    .. math::

        C_{DV} = \frac{0.172 f^{1/3} + 0.252 f^{-1.2} + 1.032 f^{-2.7}}{Re_l^{1/6}}

    Parameters
    ----------
    fineness_ratio : array_like
        l/d [-], valid about 2-10.
    reynolds : array_like
        Length Reynolds number [-], valid about 1e6-1e9 (turbulent boundary layer).

    Returns
    -------
    ndarray [-]

    Notes
    -----
    Source: Hoerner, *Fluid-Dynamic Drag* (1965) ch. 6; docs/methods.md §1.7 (confirmed in S5).

    Examples
    --------
    l/d 4 at Re 1.72e7: (0.2730 + 0.0477 + 0.0245)/16.07 = 0.0215 (by hand):

    >>> round(float(hoerner_volumetric_drag(4.0, 1.72e7)), 4)
    0.0215
    """
    f = np.asarray(fineness_ratio, dtype=float)
    num = 0.172 * f ** (1.0 / 3.0) + 0.252 * f ** (-1.2) + 1.032 * f ** (-2.7)
    return num / np.asarray(reynolds, dtype=float) ** (1.0 / 6.0)


def hull_inviscid(q, alpha, dk, eta_k, i1, i3):
    r"""Potential-flow (Munk-type) hull terms of Jones & DeLaurier.

    .. math::

        N = q (k_3 - k_1) \eta_k I_1 \sin 2\alpha \cos\frac{\alpha}{2}, \quad
        A = -q (k_3 - k_1) \eta_k I_1 \sin 2\alpha \sin\frac{\alpha}{2}, \quad
        M = q (k_3 - k_1) \eta_k I_3 \sin 2\alpha \cos\frac{\alpha}{2}

    (the moment about the station used for I3).

    Parameters
    ----------
    q : array_like
        Dynamic pressure [Pa].
    alpha : array_like
        Angle of attack [rad], valid |alpha| < 90 deg.
    dk : array_like
        k3 - k1, Lamb transverse minus axial factor [-].
    eta_k : float
        Hull efficiency factor [-], valid {range:AeroModel.hull_efficiency}.
    i1, i3 : array_like
        Shape integrals [m2], [m3] (:func:`aerostat_core.geometry.hull.shape_integrals`).

    Returns
    -------
    N [N], A [N], M [N m]

    Notes
    -----
    Source: Jones & DeLaurier (1983), docs/methods.md §1.7 (S1, S6).

    Examples
    --------
    At 45 deg, sin 2 alpha = 1: N = 100 x 0.8 x 2 cos(22.5 deg) = 147.82 N (by hand):

    >>> n, a, m = hull_inviscid(100.0, np.radians(45.0), 0.8, 1.0, 2.0, 3.0)
    >>> round(float(n), 2), round(float(m), 2)
    (147.82, 221.73)
    """
    s2 = np.sin(2.0 * alpha)
    base = q * dk * eta_k * s2
    return base * i1 * np.cos(0.5 * alpha), -base * i1 * np.sin(0.5 * alpha), (
        base * i3 * np.cos(0.5 * alpha)
    )


def hull_crossflow(q, alpha, cdc, j1, j2):
    r"""Viscous cross-flow hull terms of Jones & DeLaurier.

    .. math::

        N = q\, (C_{dc})_h J_1 \sin\alpha |\sin\alpha|, \qquad
        M = q\, (C_{dc})_h J_2 \sin\alpha |\sin\alpha|

    Parameters
    ----------
    q : array_like
        Dynamic pressure [Pa].
    alpha : array_like
        Angle of attack [rad], valid |alpha| <= 90 deg.
    cdc : float
        Cross-flow drag coefficient [-], valid {range:AeroModel.hull_crossflow_drag}.
    j1, j2 : array_like
        Planform area [m2] and its first moment about the reference station [m3].

    Returns
    -------
    N [N], M [N m]

    Notes
    -----
    Source: Jones & DeLaurier (1983), docs/methods.md §1.7 (S1).

    Examples
    --------
    Broadside (alpha = 90 deg) the hull is a plate of drag C_dc J1: 100 x 0.32 x 10 = 320 N:

    >>> [float(v) for v in hull_crossflow(100.0, np.pi / 2, 0.32, 10.0, 5.0)]
    [320.0, 160.0]
    """
    s = np.sin(alpha)
    k = q * cdc * s * np.abs(s)
    return k * j1, k * j2


def hull_axial(q, alpha, cd0, reference_area):
    r"""Axial (zero-lift) hull drag [N].

    .. math::

        A = q\, C_{D0} V^{2/3} \cos^2\alpha

    Parameters
    ----------
    q : array_like
        Dynamic pressure [Pa].
    alpha : array_like
        Angle of attack [rad], valid |alpha| <= 90 deg.
    cd0 : array_like
        Volumetric drag coefficient [-] (Hoerner or a given value, valid
        {range:AeroModel.hull_axial_drag}).
    reference_area : array_like
        V^(2/3) [m2].

    Returns
    -------
    ndarray [N]

    Notes
    -----
    Source: Jones & DeLaurier (1983) axial term, docs/methods.md §1.7 (S1).

    Examples
    --------
    At 60 deg, cos^2 = 1/4: 100 x 0.02 x 20/4 = 10 N (by hand):

    >>> round(float(hull_axial(100.0, np.pi / 3, 0.02, 20.0)), 9)
    10.0
    """
    return q * cd0 * reference_area * np.cos(alpha) ** 2


def fin_lift_drag(q, alpha, lift_slope, efficiency, stall_angle, lifting_area, total_area,
                  cd0, aspect_ratio, oswald):
    r"""Fin lift and drag in wind axes.

    .. math::

        C_L = \eta_f C_{L_\alpha} \operatorname{clip}(\alpha, -\alpha_s, \alpha_s), \qquad
        L = q S_{lift} C_L, \qquad
        D = q \left[C_{D0} S_{total} + S_{lift} \frac{C_L^2}{\pi e A}\right]

    (the lift held flat past stall).

    Parameters
    ----------
    q : array_like
        Dynamic pressure [Pa].
    alpha : array_like
        Angle of attack at the fins [rad].
    lift_slope : array_like
        3-D C_L_alpha of the fin pair [1/rad].
    efficiency : float
        eta_f [-], valid {range:AeroModel.fin_efficiency}.
    stall_angle : float
        alpha_s [rad].
    lifting_area, total_area : array_like
        Horizontal projected planform of the lifting fins and planform of all fins [m2].
    cd0 : float
        Zero-lift drag coefficient on planform [-], valid {range:AeroModel.fin_zero_lift_drag}.
    aspect_ratio : array_like
        Pair aspect ratio A [-].
    oswald : array_like
        Span efficiency e [-].

    Returns
    -------
    L [N] (perpendicular to the relative wind, up for alpha > 0), D [N] (along the wind)

    Notes
    -----
    Valid below stall (above it, the lift is only held). Sources: DATCOM/Raymer
    (docs/methods.md §1.7, S11).

    Examples
    --------
    C_L = 2.6 x 0.1 = 0.26: L = 100 x 2 x 0.26 = 52 N,
    D = 100 (0.005 x 4 + 2 x 0.26^2/(pi 0.9 x 2)) = 4.391 N (by hand):

    >>> [round(float(v), 3) for v in fin_lift_drag(100.0, 0.1, 2.6, 1.0, 0.3, 2.0, 4.0, 0.005, 2.0, 0.9)]
    [52.0, 4.391]
    """
    cl = efficiency * lift_slope * np.clip(alpha, -stall_angle, stall_angle)
    lift = q * lifting_area * cl
    drag = q * (cd0 * total_area + lifting_area * cl**2 / (np.pi * oswald * aspect_ratio))
    return lift, drag


def wind_to_body(lift, drag, alpha):
    r"""Normal and axial body-axis components of a (lift, drag) pair.

    .. math::

        N = L \cos\alpha + D \sin\alpha, \qquad A = D \cos\alpha - L \sin\alpha

    Parameters
    ----------
    lift, drag : array_like
        Lift and drag [N].
    alpha : array_like
        Angle of attack [rad].

    Returns
    -------
    N, A : ndarray [N]

    Notes
    -----
    Valid for any alpha (a rotation). Source: docs/methods.md §1 (frames and sign conventions).

    Examples
    --------
    At 90 deg the lift is axial, forwards:

    >>> [round(float(v), 12) for v in wind_to_body(1.0, 0.0, np.pi / 2)]
    [0.0, -1.0]
    """
    ca, sa = np.cos(alpha), np.sin(alpha)
    return lift * ca + drag * sa, drag * ca - lift * sa


def body_to_wind(normal, axial, alpha):
    r"""Lift and drag of body-axis (N, A), the inverse of :func:`wind_to_body`.

    .. math::

        L = N \cos\alpha - A \sin\alpha, \qquad D = N \sin\alpha + A \cos\alpha

    Parameters
    ----------
    normal, axial : array_like
        Normal and axial force [N].
    alpha : array_like
        Angle of attack [rad].

    Returns
    -------
    L, D : ndarray [N]

    Notes
    -----
    Valid for any alpha (a rotation). Source: docs/methods.md §1 (frames and sign conventions).

    Examples
    --------
    The round trip returns the pair:

    >>> [round(float(v), 12) for v in body_to_wind(*wind_to_body(3.0, 4.0, 0.3), 0.3)]
    [3.0, 4.0]
    """
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
        eta_k on the inviscid (potential-flow) hull term [-], valid {range:AeroModel.hull_efficiency}.
    hull_crossflow_drag : float
        (C_dc)_h, viscous cross-flow drag coefficient [-], valid {range:AeroModel.hull_crossflow_drag}.
    hull_axial_drag : float or None
        Zero-alpha hull drag on V^(2/3) [-], valid {range:AeroModel.hull_axial_drag}; ``None`` uses Hoerner's C_DV(f, Re).
    cutoff : {"fin", "tail"}
        Station l_h where the potential-flow term is cut off: the fin root leading edge (thesis
        symbol list "l_h: distance of fin from nose") or the tail, where the NPL profile tapers
        fastest (max -dA/dxi); "tail" gives I1 = 0 and the full Munk moment.
    fin_efficiency : float
        eta_f on the 3-D fin lift slope [-], valid {range:AeroModel.fin_efficiency}.
    section_lift_slope : float
        Fin section lift slope C_l_alpha [1/rad], valid {range:AeroModel.section_lift_slope}.
    fin_zero_lift_drag : float
        C_D0 of the fins on planform area [-], valid {range:AeroModel.fin_zero_lift_drag}.
    fin_stall_angle_deg : float
        Fin stall angle [deg], valid {range:AeroModel.fin_stall_angle_deg}; the fin lift is held flat beyond it.
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
