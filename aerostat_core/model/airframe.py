"""Assemble the evaluated aerostat: hull, fins, masses, buoyancy and confluence point.

:func:`build_airframe` broadcasts over arrays of the design variables, so the same code serves a
single design, a wind sweep and a batch of thousands of designs (optimisation, Monte Carlo).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, fields, replace

import numpy as np

from aerostat_core.aerodynamics.helikite import KiteGeometry, kite_geometry
from aerostat_core.atmosphere.gas import gas_density, gross_buoyancy
from aerostat_core.atmosphere.standard import isa
from aerostat_core.base import constants as c
from aerostat_core.geometry.fins import FinGeometry, fin_geometry
from aerostat_core.geometry.hull import (
    HullGeometry,
    hull_geometry,
    profile_quadrature,
    shape_integrals,
)
from aerostat_core.geometry.shapes import check_fineness, shape_info
from aerostat_core.model.inputs import Configuration, Requirement
from aerostat_core.model.mission import ballonet_mass, effective_tether, onboard_battery_mass
from aerostat_core.structures.mass import MassBreakdown, mass_breakdown
from aerostat_core.structures.materials import TetherSpec


@dataclass(frozen=True)
class Airframe:
    """Everything the statics and the dynamics need about one (or a batch of) aerostat(s).

    Attributes (SI): hull, fins, mass; air_density [kg/m3], viscosity [Pa s], pressure [Pa],
    temperature [K] at the operating altitude; gas_density [kg/m3]; buoyancy (gross) [N];
    aerostat_weight (all but tether) [N]; total_weight [N]; free_lift = buoyancy - total_weight
    [N]; xi_c, z_c (confluence point, body frame) [m]; J&D integrals i1 [m2], i3 [m3], j1 [m2],
    j2 [m3] about xi_m [m] (= centre of buoyancy); cutoff_station [m]; tether_length [m];

    """

    hull: HullGeometry
    fins: FinGeometry
    mass: MassBreakdown
    air_density: np.ndarray
    viscosity: np.ndarray
    pressure: np.ndarray
    temperature: np.ndarray
    gas_density: np.ndarray
    buoyancy: np.ndarray
    aerostat_weight: np.ndarray
    total_weight: np.ndarray
    free_lift: np.ndarray
    xi_c: np.ndarray
    z_c: np.ndarray
    xi_m: np.ndarray
    cutoff_station: np.ndarray
    i1: np.ndarray
    i3: np.ndarray
    j1: np.ndarray
    j2: np.ndarray
    tether_length: float
    tether_weight_per_length: float
    g: float
    kite: KiteGeometry | None = None
    tether: TetherSpec | None = None


def _without_fins(fins: FinGeometry, hull: HullGeometry, kite: KiteGeometry | None) -> FinGeometry:
    """Fins of a bluff hull (sphere, oblate, Helikite): none. Zero areas and mass, so no fin
    force or mass; for the Helikite the kite (sail, spars, keel) is booked here, at the centre
    of buoyancy (the sail is centred on the balloon)."""
    zero = np.zeros_like(hull.length)
    mass = zero if kite is None else kite.mass * np.ones_like(zero)
    return replace(
        fins, root_chord=zero, tip_chord=zero, span=zero, area_one=zero, area_total=zero,
        lifting_area=zero, xi_root_le=hull.xi_cb, xi_root_te=hull.xi_cb, xi_ac=hull.xi_cb,
        xi_centroid=hull.xi_cb, y_mac=zero, z_fins=tuple(zero for _ in fins.z_fins),
        lift_slope=zero, fabric_area=zero, mass=mass,
    )


# Power of length of each geometry field (0: dimensionless). With a scalar fineness ratio,
# nose fraction and fin variables every hull of a batch of volumes is one shape scaled by
# lambda = V^(1/3), so its geometry is the unit-volume one times lambda^p (_scaled_geometry).
_HULL_POWERS = {
    "volume": 3, "fineness_ratio": 0, "length": 1, "diameter": 1, "a1": 1, "a2": 1, "b": 1,
    "surface_area": 2, "xi_cb": 1, "xi_surface": 1, "planform_area": 2,
    "planform_centroid": 1, "reference_area": 2, "k1": 0, "k2": 0, "k_rot": 0,
}
_FIN_POWERS = {
    "root_chord": 1, "tip_chord": 1, "span": 1, "sweep_le": 0, "area_one": 2, "area_total": 2,
    "lifting_area": 2, "aspect_ratio": 0, "mac": 1, "xi_root_le": 1, "xi_root_te": 1,
    "xi_ac": 1, "xi_centroid": 1, "y_mac": 1, "lift_slope": 0, "oswald": 0, "fabric_area": 2,
    "mass": 2,
}
assert set(_HULL_POWERS) | {"shape"} == {f.name for f in fields(HullGeometry)}
assert set(_FIN_POWERS) | {"count", "z_fins"} == {f.name for f in fields(FinGeometry)}


@functools.lru_cache(maxsize=256)
def _unit_geometry(shape, fineness_ratio, nose_fraction, fin_spec, fin_areal_density,
                   area_change, position, section_lift_slope, cutoff):
    """Hull, fins, J&D integrals (i1, i3, j1, j2) and pitch-inertia integrals (shell [m4], gas
    [m5], see :func:`aerostat_core.structures.mass.mass_breakdown`) of the hull of unit volume (1 m3),
    packed for :func:`_scaled_geometry`: (shape, fin count, groups), each group (p, the
    fields' (kind, name), their unit values as a read-only column) of one power p of length.

    Cached on these (hashable, scalar) inputs: sizing builds the airframe of 24-32 volumes of
    one shape twice per design, and the quadratures (profile, surface moment, inertia) depend
    on the shape's proportions only."""
    hull = hull_geometry(1.0, fineness_ratio, nose_fraction, shape)
    fins = fin_geometry(hull, fin_spec, fin_areal_density, area_change, position,
                        section_lift_slope)
    lh = fins.xi_root_le if cutoff == "fin" else hull.length
    integrals = shape_integrals(hull, lh, hull.xi_cb)
    xi, r, ws, wv = profile_quadrature(hull)
    shell = np.sum(ws * ((xi - hull.xi_surface) ** 2 + 0.5 * r**2))
    gas = np.sum(wv * ((xi - hull.xi_cb) ** 2 + 0.25 * r**2))
    entries = [("h", k, getattr(hull, k), p) for k, p in _HULL_POWERS.items()
               if k not in ("volume", "reference_area")]
    entries += [("f", k, getattr(fins, k), p) for k, p in _FIN_POWERS.items()]
    entries += [("z", i, z, 1) for i, z in enumerate(fins.z_fins)]
    entries += [("i", i, x, p) for i, (x, p) in enumerate(zip(integrals, (2, 3, 2, 3)))]
    entries += [("m", 0, shell, 4), ("m", 1, gas, 5)]
    groups = []
    for p in sorted({e[3] for e in entries}):
        group = [e for e in entries if e[3] == p]
        column = np.array([float(e[2]) for e in group]).reshape(-1, 1)
        column.flags.writeable = False
        groups.append((p, tuple(e[:2] for e in group), column))
    return hull.shape, fins.count, tuple(groups)


def _unit_key(cfg, shape, f, area_change, position):
    """The :func:`_unit_geometry` arguments when every input of the unit geometry is one scalar
    (a batch of volumes of one shape); None when any is an array (batch overrides, or the
    uncertainty study's sampled configurations): those take the direct computation."""
    dsf = cfg.fins.area_change if area_change is None else area_change
    pos = cfg.fins.position if position is None else position
    values = (f, cfg.hull.nose_fraction, cfg.fin_fabric.areal_density, dsf, pos,
              cfg.aero.section_lift_slope)
    if any(np.ndim(v) != 0 for v in values):
        return None
    try:
        hash(cfg.fins)  # a spec with array fields is not a cache key
    except TypeError:
        return None
    f, nose, density, dsf, pos, slope = (float(v) for v in values)
    return (shape, 1.0 if shape == "sphere" else f, nose, cfg.fins, density, dsf, pos, slope,
            cfg.aero.cutoff)


def _scaled_geometry(volume, unit):
    """The unit-volume geometry of :func:`_unit_geometry` scaled to hull volumes ``volume``
    [m3]: each field times lambda^p, lambda = V^(1/3), one product per power p (the volume
    and V^(2/3) as :func:`aerostat_core.geometry.hull.hull_geometry` computes them). The same
    numbers as the direct computation to rounding. Returns (hull, fins, (i1, i3, j1, j2),
    (shell, gas) inertia integrals)."""
    shape, count, groups = unit
    v = np.asarray(volume, dtype=float)
    lam = np.cbrt(v)
    one = np.ones_like(lam)
    lam2 = lam * lam
    lam4 = lam2 * lam2
    power = (one, lam, lam2, lam2 * lam, lam4, lam4 * lam)
    out = {"h": {}, "f": {}, "z": {}, "i": {}, "m": {}}
    lead = (-1,) + (1,) * lam.ndim
    for p, keys, column in groups:
        for (kind, key), row in zip(keys, column.reshape(lead) * power[p]):
            out[kind][key] = row
    h, z, i, m = out["h"], out["z"], out["i"], out["m"]
    h["volume"] = v * one
    h["reference_area"] = h["volume"] ** (2.0 / 3.0)
    return (
        HullGeometry(shape=shape, **h),
        FinGeometry(count=count, z_fins=tuple(z[k] for k in range(len(z))), **out["f"]),
        (i[0], i[1], i[2], i[3]),
        (m[0], m[1]),
    )


def build_airframe(
    req: Requirement,
    cfg: Configuration,
    volume,
    fineness_ratio=None,
    area_change=None,
    position=None,
    g: float = c.G0,
) -> Airframe:
    """Evaluate geometry, mass, buoyancy and confluence point.

    Parameters
    ----------
    req : Requirement
    cfg : Configuration
    volume : array_like
        Hull volume [m3].
    fineness_ratio, area_change, position : array_like or None
        Design variables f [-], Delta S_f [%], Delta l_f [-]; ``None`` takes them from ``cfg``.
    g : float
        Gravity [m/s2].

    Notes
    -----
    Air properties are taken at the operating altitude (site + altitude); the few metres of
    altitude loss in wind change density by < 0.1 %, which is neglected. The confluence point is
    placed below the centre of net static lift (docs/methods.md §1.8, G9), so the hull flies level in
    calm air: xi_C = (F_B xi_CB - W_a xi_CG)/(F_B - W_a) + offset * l, z_C = -(b + drop * d).
    Where F_B <= W_a there is no net lift at the confluence point and xi_C falls back to xi_CB.

    Bluff hulls (sphere, oblate, Helikite; ``ShapeInfo.streamlined`` False) carry no fins, and
    their tether force is taken at the centre of buoyancy (z_C = 0): a bluff hull's drag passes
    through its centre and its pitch attitude has no aerodynamic meaning, so it trims level. The
    Helikite adds its kite (:mod:`aerostat_core.aerodynamics.helikite`). A fineness ratio outside the
    shape's valid range raises ``ValueError`` naming the value, the shape and the range.
    """
    shape = getattr(cfg.hull, "shape", "npl")
    info = shape_info(shape)
    f = cfg.hull.fineness_ratio if fineness_ratio is None else np.asarray(fineness_ratio, float)
    check_fineness(shape, f)  # batch overrides too: a shape is only valid over its l/d range
    integrals = inertia = None
    key = _unit_key(cfg, shape, f, area_change, position)
    if key is not None:
        hull, fins, integrals, inertia = _scaled_geometry(volume, _unit_geometry(*key))
    else:
        hull = hull_geometry(volume, f, cfg.hull.nose_fraction, shape)
        fins = fin_geometry(
            hull, cfg.fins, cfg.fin_fabric.areal_density, area_change, position,
            cfg.aero.section_lift_slope,
        )
    atm = isa(req.site_elevation + req.altitude, req.isa_offset)
    rho_gas = gas_density(cfg.gas, atm.pressure, atm.temperature)
    kite = kite_geometry(hull.volume) if info.kite else None
    if not info.streamlined:
        fins = _without_fins(fins, hull, kite)
    t = effective_tether(req, cfg)
    tether_length = float(req.altitude)
    mass = mass_breakdown(
        hull, fins, cfg.hull_fabric.areal_density, rho_gas, cfg.misc_mass_ratio,
        req.payload_mass, t.linear_density * tether_length,
        onboard_battery_mass(req, cfg), ballonet_mass(req, cfg, hull.volume),
        inertia_integrals=inertia,
    )
    fb = gross_buoyancy(atm.density, hull.volume, g)
    w_a = mass.aerostat * g
    w_t = mass.total * g
    net = fb - w_a
    safe = np.where(net > 1e-9 * fb, net, 1.0)
    xi_c = np.where(net > 1e-9 * fb, (fb * hull.xi_cb - w_a * mass.xi_cg) / safe, hull.xi_cb)
    xi_c = xi_c + cfg.confluence.xi_offset * hull.length
    z_c = -(hull.b + cfg.confluence.drop_ratio * hull.diameter)
    xi_m = hull.xi_cb
    lh = fins.xi_root_le if cfg.aero.cutoff == "fin" else hull.length
    i1, i3, j1, j2 = shape_integrals(hull, lh, xi_m) if integrals is None else integrals
    if not info.streamlined:  # drag-only hull (statics.aero_loads), tether at the centre
        z_c = np.zeros_like(hull.length)
        i1, i3, j1, j2 = (np.zeros_like(hull.length) for _ in range(4))
    area_t = np.pi * t.diameter**2 / 4.0
    w_line = (t.linear_density - float(atm.density) * area_t) * g
    return Airframe(
        hull=hull, fins=fins, mass=mass,
        air_density=atm.density, viscosity=atm.viscosity, pressure=atm.pressure,
        temperature=atm.temperature, gas_density=rho_gas,
        buoyancy=fb, aerostat_weight=w_a, total_weight=w_t, free_lift=fb - w_t,
        xi_c=xi_c, z_c=z_c, xi_m=xi_m, cutoff_station=lh * np.ones_like(hull.length),
        i1=i1, i3=i3, j1=j1, j2=j2,
        tether_length=tether_length, tether_weight_per_length=w_line, g=g, kite=kite, tether=t,
    )
