"""Mass budget, centre of gravity and pitch inertia (docs/methods.md §1.6, thesis §3.1.3(c))."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from aerostat_core.geometry.fins import FinGeometry
from aerostat_core.geometry.hull import HullGeometry, profile_quadrature

#: Order of the breakdown items (also the CSV/table order).
ITEM_NAMES = ("hull", "fins", "lifting gas", "miscellaneous", "payload", "tether", "battery",
              "ballonet")


@dataclass(frozen=True)
class MassBreakdown:
    """Masses [kg] and their body positions (xi from the nose aft, z up) [m].

    ``items`` maps each name of ``ITEM_NAMES`` to its mass. ``aerostat`` is everything the hull
    carries (all but the tether); ``total`` adds the tether. ``xi_cg``/``z_cg`` locate the CG of
    the aerostat (tether excluded); ``pitch_inertia`` is I_yy about that CG [kg m2], including
    the lifting gas (it moves with the hull) but not the added mass of the outside air.
    """

    items: dict
    positions: dict
    aerostat: np.ndarray
    total: np.ndarray
    xi_cg: np.ndarray
    z_cg: np.ndarray
    pitch_inertia: np.ndarray


def mass_breakdown(
    hull: HullGeometry,
    fins: FinGeometry,
    hull_areal_density: float,
    gas_density,
    misc_ratio: float,
    payload_mass: float,
    tether_mass,
    battery_mass: float = 0.0,
    ballonet_mass=0.0,
    inertia_integrals=None,
    systems_mass=0.0,
) -> MassBreakdown:
    r"""Mass budget of the aerostat.

    .. math::

        m_{hull} = \sigma_h S_h, \quad m_{gas} = \rho_{gas} V, \quad
        m_{misc} = k_{misc} m_{hull}, \quad
        m_a = m_{hull} + m_{fin} + m_{gas} + m_{misc} + m_{payload} + m_{battery}
        + m_{ballonet},

        m_{total} = m_a + m_{tether}, \qquad
        \xi_{cg} = \frac{\sum_i m_i \xi_i}{m_a}, \qquad
        I_{yy} = \sum_i \left(I_i + m_i \left[(\xi_i - \xi_{cg})^2
        + (z_i - z_{cg})^2\right]\right)

    Positions: hull fabric at its surface centroid, gas at the centre of buoyancy, fins at their
    planform centroid (the arrangements are symmetric, so z = 0), payload and miscellaneous items
    at the hull belly below the centre of buoyancy.

    Parameters
    ----------
    hull : HullGeometry
        The hull.
    fins : FinGeometry
        The fins (their mass and centroid).
    hull_areal_density : float
        Hull fabric sigma_h [kg/m2], valid {range:Fabric.areal_density}.
    gas_density : array_like
        Lifting-gas density in the hull [kg/m3].
    misc_ratio : float
        Miscellaneous mass / hull fabric mass k_misc [-], valid
        {range:Configuration.misc_mass_ratio} (Table 2.2: 0.30).
    payload_mass : float
        [kg], valid {range:Requirement.payload_mass}.
    tether_mass : array_like
        [kg].
    battery_mass : float
        Onboard payload battery [kg], carried with the payload (aerostat_core.model.mission).
    ballonet_mass : array_like
        Ballonet fabric [kg], at the hull bottom below the centre of buoyancy (halfway down).
    systems_mass : array_like
        Hull systems that scale with the hull volume (pressure control, avionics, lighting,
        rigging, fin structure) [kg], :func:`systems_mass`; booked with the miscellaneous items.
    inertia_integrals : tuple of array_like, optional
        (int ((xi - xi_s)^2 + r^2/2) dS [m4], int ((xi - xi_cb)^2 + r^2/4) dV [m5]) where the
        caller has them (aerostat_core.model.airframe: a scaled unit hull); None: by quadrature.

    Returns
    -------
    MassBreakdown

    Notes
    -----
    Valid for a thin uniform envelope and point masses for the rest. The pitch inertia uses the
    hull profile: shell I = sigma int ((xi - xi_s)^2 + r^2/2) dS, gas I = rho int ((xi - xi_cb)^2
    + r^2/4) dV, point masses for the rest, then the parallel-axis theorem.
    Source: docs/methods.md §1.6; Table 2.2 of the thesis for the ratios.

    Examples
    --------
    100 m3 of gas at 0.17 kg/m3 weighs 17 kg; the miscellaneous items are 0.3 of the hull
    fabric; the tether is outside the aerostat's mass (by hand):

    >>> import aerostat_core
    >>> from aerostat_core.geometry.fins import fin_geometry
    >>> from aerostat_core.geometry.hull import hull_geometry
    >>> h = hull_geometry(100.0, 4.0)
    >>> m = mass_breakdown(h, fin_geometry(h, aerostat_core.FinSpec(), 0.1), 0.13, 0.17, 0.3,
    ...                    10.0, 6.0)
    >>> float(m.items["lifting gas"]), round(float(m.items["miscellaneous"] / m.items["hull"]), 12)
    (17.0, 0.3)
    >>> round(float(m.total - m.aerostat), 12)
    6.0
    """
    m_hull = hull_areal_density * hull.surface_area
    m_gas = np.asarray(gas_density, dtype=float) * hull.volume
    m_misc = misc_ratio * m_hull + np.asarray(systems_mass, dtype=float)
    m_pay = np.full_like(m_hull, float(payload_mass))
    m_teth = np.asarray(tether_mass, dtype=float) * np.ones_like(m_hull)
    items = {
        "hull": m_hull,
        "fins": fins.mass * np.ones_like(m_hull),
        "lifting gas": m_gas * np.ones_like(m_hull),
        "miscellaneous": m_misc,
        "payload": m_pay,
        "tether": m_teth,
        "battery": np.full_like(m_hull, float(battery_mass)),
        "ballonet": np.asarray(ballonet_mass, dtype=float) * np.ones_like(m_hull),
    }
    zero = np.zeros_like(m_hull)
    positions = {
        "hull": (hull.xi_surface, zero),
        "fins": (fins.xi_centroid * np.ones_like(m_hull), zero),
        "lifting gas": (hull.xi_cb, zero),
        "miscellaneous": (hull.xi_cb, -hull.b),
        "payload": (hull.xi_cb, -hull.b),
        "battery": (hull.xi_cb, -hull.b),
        "ballonet": (hull.xi_cb, -0.5 * hull.b),
    }
    carried = [k for k in ITEM_NAMES if k != "tether"]
    m_a = sum(items[k] for k in carried)
    xi_cg = sum(items[k] * positions[k][0] for k in carried) / m_a
    z_cg = sum(items[k] * positions[k][1] for k in carried) / m_a

    sigma = hull_areal_density
    if inertia_integrals is None:
        xi, r, ws, wv = profile_quadrature(hull)
        shell = np.sum(ws * ((xi - hull.xi_surface[..., None]) ** 2 + 0.5 * r**2), axis=-1)
        i_shell = sigma * shell
        rho_g = np.asarray(gas_density, dtype=float)[..., None]
        i_gas = np.sum(rho_g * wv * ((xi - hull.xi_cb[..., None]) ** 2 + 0.25 * r**2), axis=-1)
    else:
        shell, gas = inertia_integrals
        i_shell = sigma * shell
        i_gas = np.asarray(gas_density, dtype=float) * gas
    # parallel axis to the aerostat CG
    inertia = i_shell + m_hull * ((hull.xi_surface - xi_cg) ** 2 + z_cg**2)
    inertia = inertia + i_gas + m_gas * ((hull.xi_cb - xi_cg) ** 2 + z_cg**2)
    m_one_fin = fins.mass / fins.count
    for zf in fins.z_fins:
        inertia = inertia + m_one_fin * ((fins.xi_centroid - xi_cg) ** 2 + (zf - z_cg) ** 2)
    for k in ("miscellaneous", "payload", "battery", "ballonet"):
        xk, zk = positions[k]
        inertia = inertia + items[k] * ((xk - xi_cg) ** 2 + (zk - z_cg) ** 2)
    return MassBreakdown(
        items=items,
        positions=positions,
        aerostat=m_a,
        total=m_a + m_teth,
        xi_cg=xi_cg,
        z_cg=z_cg,
        pitch_inertia=inertia,
    )


#: Reference hull volume of the systems-mass law [m3] (the operational class, thesis §2.3.2).
SYSTEMS_REFERENCE_VOLUME = 1000.0


def systems_mass(volume, per_volume: float, exponent: float = 0.0):
    """Mass of the hull systems that grow with the hull [kg].

    .. math::

        m_{sys} = k\\, V \\left(V / V_{ref}\\right)^{c}

    The items a fabric-and-payload budget leaves out and that scale with the hull volume: the
    pressure-control system (blowers and valves, sized by the air flow that fills the ballonet,
    itself a share of V as the aerostat climbs and the day warms: aerostat_core.structures.ballonet), the
    avionics, lighting and lightning protection, the rigging (confluence lines and patches) and
    the fins' inflation structure. Their sum is taken proportional to V, with one coefficient
    k_sys [kg/m3] (presets.PRACTICE_SYSTEMS_MASS_PER_VOLUME, FITTED on the declared fit set of
    aerostat_core.studies.fielded; the thesis preset has 0: Table 2.2 books only fabric, gas, fins and
    0.30 x hull of miscellaneous items).

    Parameters
    ----------
    volume : array_like
        Hull volume [m3].
    per_volume : float
        k_sys, the mass per m3 of a hull of V_ref = 1000 m3 [kg/m3], valid
        {range:Configuration.systems_mass_per_volume}.
    exponent : float
        c [-], valid {range:Configuration.systems_mass_exponent}: how much faster than V the
        systems grow (0: in proportion).

    Notes
    -----
    Valid over the classes of thesis Table 2.3 (30-25,000 m3). Why linear in V: the blower flow
    and the ballonet scale with V; the rigging's mass is small (SF T l / (sigma/rho): 3 x 100 kN
    x 24 m / 2.2e6 m is 3 kg on a strategic hull, docs/methods.md §1.15) and is inside k_sys.
    Source: docs/methods.md §1.15 (the law), docs/validation.md (the fit).

    Examples
    --------
    >>> float(systems_mass(1000.0, 0.25)), round(float(systems_mass(8000.0, 0.25, 1 / 3)), 6)
    (250.0, 4000.0)
    """
    v = np.asarray(volume, dtype=float)
    if exponent == 0.0:
        return float(per_volume) * v
    return float(per_volume) * v * (v / SYSTEMS_REFERENCE_VOLUME) ** float(exponent)
