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
) -> MassBreakdown:
    """Mass budget of the aerostat.

    m_hull = GSM_h S_h; m_fin from the fin fabric; m_gas = rho_gas V; m_misc = ratio m_hull;
    m_a = m_hull + m_fin + m_gas + m_misc + m_payload; m_total = m_a + m_tether.
    Positions: hull fabric at its surface centroid, gas at the centre of buoyancy, fins at their
    planform centroid (the arrangements are symmetric, so z = 0), payload and miscellaneous items
    at the hull belly below the centre of buoyancy.

    Parameters
    ----------
    hull : HullGeometry
    fins : FinGeometry
    hull_areal_density : float
        Hull fabric [kg/m2].
    gas_density : array_like
        Lifting-gas density in the hull [kg/m3].
    misc_ratio : float
        Miscellaneous mass / hull fabric mass [-] (Table 2.2: 0.30).
    payload_mass : float
        [kg].
    tether_mass : array_like
        [kg].
    battery_mass : float
        Onboard payload battery [kg], carried with the payload (aerostat_core.model.mission).
    ballonet_mass : array_like
        Ballonet fabric [kg], at the hull bottom below the centre of buoyancy (halfway down).
    inertia_integrals : tuple of array_like, optional
        (int ((xi - xi_s)^2 + r^2/2) dS [m4], int ((xi - xi_cb)^2 + r^2/4) dV [m5]) where the
        caller has them (aerostat_core.model.airframe: a scaled unit hull); None: by quadrature.

    Notes
    -----
    Source: docs/methods.md §1.6; Table 2.2 of the thesis for the ratios. The pitch inertia uses the
    hull profile: shell I = sigma int ((xi - xi_s)^2 + r^2/2) dS, gas I = rho int ((xi - xi_cb)^2
    + r^2/4) dV, point masses for the rest, then the parallel-axis theorem.
    """
    m_hull = hull_areal_density * hull.surface_area
    m_gas = np.asarray(gas_density, dtype=float) * hull.volume
    m_misc = misc_ratio * m_hull
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
