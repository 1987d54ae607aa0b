"""Payload power: an onboard battery, or conductors in the tether (thesis Table 2.4, issue 13).

Onboard: the battery stores the payload energy over the time between recharges. Through the
tether: a go-and-return pair of copper conductors, sized for a supply voltage and an allowed
resistive loss (with a current-density ceiling), is bundled with the strength member; it adds
mass per metre, diameter (drag) and some strength.

No power or electro-optic tether product with a published mass per metre, diameter and
breaking load was found (docs/methods.md §1.14, S18): the catalogue's power tethers are
:func:`power_tether` applied to the Dyneema 6 mm entry, COMPUTED examples labelled so in
``materials.TETHER_SOURCES``.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from aerostat_core.base import constants as c
from aerostat_core.structures.materials import TetherSpec


def battery_mass(power, hours, energy_density, depth_of_discharge=1.0):
    """Mass of an onboard battery [kg].

    m_b = P t / (e DoD)

    Parameters
    ----------
    power : array_like
        Payload power [W], >= 0.
    hours : array_like
        Time between recharges [h], >= 0.
    energy_density : float
        Pack-level specific energy [Wh/kg], > 0.
    depth_of_discharge : float
        Usable fraction of the rated energy [-], (0, 1].

    Returns
    -------
    ndarray
        [kg]; 0 when the power or the time is 0.

    Notes
    -----
    Valid for any chemistry given its pack-level figure (cells, wiring, case and management).
    Source: definition of specific energy. The default 150 Wh/kg
    (constants.BATTERY_ENERGY_DENSITY) is an engineering choice between two published packs,
    107 Wh/kg (enclosed LiFePO4) and 216 Wh/kg (LiPo drone pack) (docs/methods.md §1.14, S19).

    Examples
    --------
    >>> float(battery_mass(100.0, 24.0, 150.0, 0.8))
    20.0
    """
    return (
        np.asarray(power, float)
        * np.asarray(hours, float)
        / (float(energy_density) * float(depth_of_discharge))
    )


@dataclass(frozen=True)
class Conductors:
    """Conductor pair of a power tether (SI).

    area : copper cross-section of one conductor [m2]; diameter : its bare diameter [m];
    insulated_diameter [m]; current [A]; supply_power : power at the ground [W]; loss : resistive
    loss in the pair [W]; loop_resistance [ohm]; linear_density : added mass per metre, copper +
    insulation of both conductors [kg/m]; strength : added breaking load [N].
    """

    area: float
    diameter: float
    insulated_diameter: float
    current: float
    supply_power: float
    loss: float
    loop_resistance: float
    linear_density: float
    strength: float


def size_conductors(
    power: float,
    length: float,
    voltage: float,
    loss_fraction: float,
    max_current_density: float,
    insulation_thickness: float,
) -> Conductors:
    """Copper conductor pair that delivers ``power`` at the aerostat through ``length`` of tether.

    With supply power P_s = P/(1 - eps) at supply voltage V_s, current I = P_s/V_s, allowed loss
    I^2 R = eps P_s, so the loop resistance is R = eps V_s^2/P_s and one conductor's area is
    A = 2 rho_Cu L / R = 2 rho_Cu L P_s/(eps V_s^2), raised if needed so that I/A <= J_max
    (then the current that delivers P, from P = V_s I - I^2 R, and the loss are smaller).
    Mass per metre 2 (A rho_Cu + A_ins rho_ETFE); strength 2 A sigma_y,Cu (copper at its yield
    when the strength member breaks).

    Parameters
    ----------
    power : float
        Power delivered to the payload [W], >= 0 (0 gives no conductor).
    length : float
        Tether length [m], > 0.
    voltage : float
        Supply voltage at the ground [V] (DC or AC rms with unity power factor), > 0.
    loss_fraction : float
        Allowed loss / supply power eps [-], (0, 1).
    max_current_density : float
        Current-density ceiling J_max [A/m2] (a conductor-temperature limit), > 0.
    insulation_thickness : float
        Insulation wall of each conductor [m], >= 0.

    Returns
    -------
    Conductors

    Notes
    -----
    Resistivity and densities: aerostat_core.base.constants (IEC 60028 copper, ETFE insulation).
    Valid where conductor heating stays within the insulation rating (J_max) and skin effect is
    negligible (DC or mains frequency at these sizes). The delivered voltage is V_s (1 - eps).

    Examples
    --------
    >>> k = size_conductors(1000.0, 300.0, 400.0, 0.1, 5e6, 0.25e-3)
    >>> round(k.area * 1e6, 3), round(k.current, 3)
    (0.718, 2.778)
    """
    if power <= 0.0:
        return Conductors(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, np.inf, 0.0, 0.0)
    p_s = power / (1.0 - loss_fraction)
    i_loss = p_s / voltage
    area = max(
        2.0 * c.COPPER_RESISTIVITY * length * p_s / (loss_fraction * voltage**2),
        i_loss / max_current_density,
    )
    # the current that delivers ``power`` through this area: P = V I - I^2 R (equals i_loss when
    # the loss sets the area, less when the current density does)
    r_loop = 2.0 * c.COPPER_RESISTIVITY * length / area
    # R P from P/A (finite even for a vanishing power), and the cancellation-free root
    # I = 2P/(V + sqrt(V^2 - 4 R P)); the loss I^2 R = I (2 R P)/(V + sqrt(...))
    rp = 2.0 * c.COPPER_RESISTIVITY * length * (power / area)
    root = voltage + np.sqrt(max(voltage**2 - 4.0 * rp, 0.0))
    current = 2.0 * power / root
    p_s = voltage * current
    loss = current * 2.0 * rp / root
    d = float(np.sqrt(4.0 * area / np.pi))
    d_ins = d + 2.0 * insulation_thickness
    a_ins = np.pi / 4.0 * (d_ins**2 - d**2)
    rho_l = 2.0 * (area * c.COPPER_DENSITY + a_ins * c.ETFE_DENSITY)
    return Conductors(
        area=area,
        diameter=d,
        insulated_diameter=d_ins,
        current=float(current),
        supply_power=float(p_s),
        loss=float(loss),
        loop_resistance=r_loop,
        linear_density=float(rho_l),
        strength=2.0 * area * c.COPPER_YIELD_STRENGTH,
    )


def power_tether(base: TetherSpec, k: Conductors) -> TetherSpec:
    """The strength member ``base`` with the conductor pair ``k`` bundled in.

    d = sqrt(d_base^2 + 2 d_ins^2) (a round bundle of the same total cross-section);
    mass per metre and breaking load add; the axial stiffness is the strength member's (copper
    past yield adds little). ``k.area == 0`` returns ``base`` unchanged.
    """
    if k.area <= 0.0:
        return base
    d = float(np.sqrt(base.diameter**2 + 2.0 * k.insulated_diameter**2))
    name = base.name if base.name.endswith(" + power") else base.name[:92] + " + power"
    return replace(
        base,
        name=name,
        linear_density=base.linear_density + k.linear_density,
        diameter=d,
        breaking_strength=base.breaking_strength + k.strength,
    )
