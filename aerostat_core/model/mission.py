"""What a mission needs beyond payload mass and altitude (issue 13): payload power, endurance,
ballonet, envelope structure, survival wind, winch.

The mission's demands are Requirement fields (``payload_power``, ``power_via``,
``endurance_days``, ``deployment_days``; all off by default); the technology that meets them is
:class:`MissionSpec` (``Configuration.mission``). Everything that changes a design feeds the
one constraint table (aerostat_core.model.constraints) and the mass breakdown, so sizing and the
optimiser respect it:

* onboard battery -> mass item "battery"; power through the tether -> conductors added to the
  tether (mass, diameter for drag, strength), see :func:`effective_tether`;
* ballonet (``MissionSpec.ballonet`` "auto"/"on") -> mass item "ballonet";
* endurance -> row ``endurance`` (free lift after ``endurance_days`` of permeation);
* envelope -> rows ``envelope_stress`` (design wind) and ``survival_envelope_pressure``.

The winch, top-up gas and the stay-up/reel-in verdict are reported (:func:`mission_report`),
not constrained. This module imports no UI and never imports aerostat_core.model.inputs at import
time (inputs imports :class:`MissionSpec` from here).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from aerostat_core.atmosphere.permeation import (
    days_to_top_up,
    lift_loss_after,
    permeation_time_constant,
    purity_after,
)
from aerostat_core.atmosphere.standard import isa
from aerostat_core.base import constants as c
from aerostat_core.base.fields import choice, integer, number, validate
from aerostat_core.structures.ballonet import ballonet_fabric_mass, ballonet_fraction
from aerostat_core.structures.materials import POWER_TETHER_CONDUCTORS, TetherSpec
from aerostat_core.structures.membrane import allowable_pressure, membrane_loads, required_pressure
from aerostat_core.tether.power import Conductors, battery_mass, power_tether, size_conductors

POWER_ROUTES = ("onboard", "tether")
BALLONET_MODES = ("off", "auto", "on")
#: Largest finite number of days reported (inf is not valid JSON).
DAYS_CAP = 1.0e6


@dataclass(frozen=True)
class MissionSpec:
    """Technology that serves the mission (power, ballonet, envelope, winch).

    Parameters
    ----------
    battery_energy_density : float
        Pack-level specific energy of the onboard battery [Wh/kg], valid [20, 1000]. Default 150
        (constants.BATTERY_ENERGY_DENSITY: between an enclosed LiFePO4 pack's 107 and a LiPo
        drone pack's 216 Wh/kg).
    battery_depth_of_discharge : float
        Usable fraction of the rated energy [-], valid (0, 1]; 0.8 for long cycle life (ASSUMED).
    battery_hours : float or None
        Time between recharges [h], valid (0, 10000]; ``None``: 24 x ``endurance_days`` of the
        requirement, or 24 h when it has no endurance.
    supply_voltage : float
        Ground supply voltage of a power tether [V], valid [12, 20000]; 400 V (ASSUMED).
    power_loss_fraction : float
        Allowed resistive loss / supply power of the tether conductors [-], valid (0, 0.5].
    max_current_density : float
        Conductor current-density ceiling [A/m2], valid [1e5, 5e7] (the conductor-temperature
        limit; 5 A/mm2 for insulated copper in a bundle, ASSUMED).
    insulation_thickness : float
        Insulation wall of each conductor [m], valid [0, 0.005].
    ballonet : {"off", "auto", "on"}
        "off": volume reported, no ballonet built (the thesis design, and today's default);
        "auto": built where the computed volume exceeds the thesis' 500 m rule; "on": built.
    superheat : float
        Day-time gas superheat at the operating altitude [K], valid [0, 40]; 10 K (ASSUMED,
        clear-sky order of magnitude).
    envelope_safety_factor : float
        On the fabric tensile strength [-], valid [1, 20]; 4 (constants.ENVELOPE_SAFETY_FACTOR;
        attributed to Carichner & Nicolai 2013, not verified).
    pressure_dynamic_factor : float
        Required internal pressure / dynamic pressure [-], valid [1, 3]; 1.2
        (constants.PRESSURE_DYNAMIC_FACTOR).
    winch_speed : float
        Reel-in/out speed [m/s], valid (0, 5]; 0.3048 (60 ft/min, thesis §2.2.4).
    winch_efficiency : float
        Motor x drive efficiency [-], valid (0, 1]; 0.75 (ASSUMED: motor 0.85 x gearbox 0.9).
    bend_radius_ratio : float
        Tether minimum bend radius / tether diameter [-], valid [2, 100]; 20
        (constants.TETHER_BEND_RADIUS_RATIO: a cable data sheet's dynamic bend radius).
    drum_layers : int
        Layers of tether on the drum, valid [1, 100]; 10.
    """

    battery_energy_density: float = number(
        c.BATTERY_ENERGY_DENSITY, "Battery specific energy", "Wh/kg", 20, 1000, step=10.0,
        fmt="%.0f", help="Pack level (cells about 250 Wh/kg, packs 150-200).", source="ASSUMED")
    battery_depth_of_discharge: float = number(
        c.BATTERY_DEPTH_OF_DISCHARGE, "Battery depth of discharge", "", 0, 1, lo_open=True,
        step=0.05, fmt="%.2f", help="Usable fraction of the rated energy.", source="ASSUMED")
    battery_hours: float | None = number(
        None, "Hours between recharges", "h", 0, 10000, lo_open=True, empty="endurance",
        step=1.0, fmt="%.0f", help="Empty: 24 h per endurance day, or 24 h without endurance.")
    supply_voltage: float = number(
        c.POWER_TETHER_VOLTAGE, "Power-tether supply voltage", "V", 12, 20000, step=50.0,
        fmt="%.0f", source="ASSUMED")
    power_loss_fraction: float = number(
        c.POWER_TETHER_LOSS_FRACTION, "Allowed conductor loss", "", 0, 0.5, lo_open=True,
        scale=100.0, display_unit="%", step=1.0, fmt="%.1f",
        help="Resistive loss / supply power of the tether conductors.")
    max_current_density: float = number(
        c.MAX_CURRENT_DENSITY, "Conductor current-density limit", "A/m2", 1e5, 5e7, scale=1e-6,
        display_unit="A/mm²", step=0.5, fmt="%.1f",
        help="Conductor-temperature limit (5 A/mm² for insulated copper in a bundle).",
        source="ASSUMED")
    insulation_thickness: float = number(
        0.25e-3, "Conductor insulation wall", "m", 0, 0.005, scale=1000.0, display_unit="mm",
        step=0.05, fmt="%.2f")
    ballonet: str = choice(
        "off", "Ballonet", BALLONET_MODES, source="thesis §2.2.1(c)",
        help="The thesis flies below 500 m without one; a built ballonet adds its fabric to the "
        "mass breakdown.")
    superheat: float = number(
        c.GAS_SUPERHEAT, "Gas superheat (day)", "K", 0, 40, step=1.0, fmt="%.0f",
        help="Day-time gas superheat at the operating altitude.", source="ASSUMED")
    envelope_safety_factor: float = number(
        c.ENVELOPE_SAFETY_FACTOR, "Envelope fabric safety factor", "", 1, 20, step=0.5,
        fmt="%.1f", source="Carichner & Nicolai 2013")
    pressure_dynamic_factor: float = number(
        c.PRESSURE_DYNAMIC_FACTOR, "Internal pressure / dynamic pressure", "", 1, 3, step=0.1,
        fmt="%.2f", source="constants.PRESSURE_DYNAMIC_FACTOR")
    winch_speed: float = number(
        c.THESIS_WINCH_SPEED, "Winch reel speed", "m/s", 0, 5, lo_open=True, step=0.05,
        fmt="%.3f", source="thesis §2.2.4")
    winch_efficiency: float = number(
        c.WINCH_EFFICIENCY, "Winch efficiency", "", 0, 1, lo_open=True, step=0.05, fmt="%.2f",
        source="ASSUMED")
    bend_radius_ratio: float = number(
        c.TETHER_BEND_RADIUS_RATIO, "Tether min bend radius / diameter", "", 2, 100, step=1.0,
        fmt="%.0f", source="ASSUMED")
    drum_layers: int = integer(10, "Tether layers on the drum", 1, 100)

    def __post_init__(self) -> None:
        validate(self)


# --- power -------------------------------------------------------------------------------------
def battery_hours(req, spec: MissionSpec) -> float:
    """Time between battery recharges [h] (see :attr:`MissionSpec.battery_hours`)."""
    if spec.battery_hours is not None:
        return float(spec.battery_hours)
    return c.HOURS_PER_DAY * (float(req.endurance_days) if req.endurance_days > 0 else 1.0)


def onboard_battery_mass(req, cfg) -> float:
    """Battery mass [kg]: 0 unless the payload draws power from an onboard source."""
    if req.payload_power <= 0 or req.power_via != "onboard":
        return 0.0
    m = cfg.mission
    return float(
        battery_mass(
            req.payload_power,
            battery_hours(req, m),
            m.battery_energy_density,
            m.battery_depth_of_discharge,
        )
    )


def tether_conductors(req, cfg) -> tuple[Conductors | None, bool]:
    """Conductors sized for power through the tether, and whether the configured tether's own
    conductors (a catalogue power tether) already carry it. ``(None, False)`` when no power goes
    through the tether."""
    if req.payload_power <= 0 or req.power_via != "tether":
        return None, False
    m = cfg.mission
    k = size_conductors(
        float(req.payload_power),
        float(req.altitude),
        m.supply_voltage,
        m.power_loss_fraction,
        m.max_current_density,
        m.insulation_thickness,
    )
    own = POWER_TETHER_CONDUCTORS.get(cfg.tether.name, 0.0)
    return k, own >= k.area


def effective_tether(req, cfg) -> TetherSpec:
    """The tether as flown: the configured one, with a conductor pair bundled in when the payload
    power goes through it and the tether has no conductors of its own large enough."""
    k, own = tether_conductors(req, cfg)
    if k is None or own:
        return cfg.tether
    t = cfg.tether
    rho_l = t.linear_density + k.linear_density
    d = float(np.sqrt(t.diameter**2 + 2.0 * k.insulated_diameter**2))
    if rho_l > 1.0 or d > 0.05:
        m = cfg.mission
        raise ValueError(
            f"Requirement.payload_power = {req.payload_power:g} W through {req.altitude:g} m of "
            f"tether at MissionSpec.supply_voltage = {m.supply_voltage:g} V with "
            f"power_loss_fraction = {m.power_loss_fraction:g} needs conductors of "
            f"{1000 * k.linear_density:.0f} g/m (tether {1000 * rho_l:.0f} g/m, {1000 * d:.0f} mm);"
            f" the tether model accepts up to 1000 g/m and 50 mm: raise the supply voltage or "
            f"the allowed loss, or carry the power onboard"
        )
    return power_tether(t, k)


# --- ballonet ----------------------------------------------------------------------------------
@dataclass(frozen=True)
class BallonetState:
    """fraction : needed ballonet volume / hull volume [-]; rule_fraction : the same at the
    thesis' 500 m rule altitude (same site and superheat) [-]; needed : fraction > rule_fraction
    (the 500 m rule); built : whether its fabric is in the mass breakdown."""

    fraction: float
    rule_fraction: float
    needed: bool
    built: bool


def ballonet_state(req, cfg) -> BallonetState:
    """Ballonet fraction at the operating altitude against the thesis' 500 m rule."""
    f, f_rule = _ballonet_fractions(
        float(req.site_elevation), float(req.altitude), float(req.isa_offset),
        float(cfg.mission.superheat),
    )
    needed = f > f_rule + 1e-12
    mode = cfg.mission.ballonet
    return BallonetState(f, f_rule, needed, mode == "on" or (mode == "auto" and needed))


@functools.lru_cache(maxsize=256)
def _ballonet_fractions(site_elevation, altitude, isa_offset, superheat):
    """(fraction, rule_fraction) of :func:`ballonet_state` (floats). Cached on its four float
    inputs: three ISA evaluations that every design report repeats for the same site."""
    top = min(site_elevation + c.BALLONET_RULE_ALTITUDE, c.ISA_TROPOPAUSE)
    # site, operating altitude and the 500 m rule altitude in one ISA call
    a = isa(np.array([site_elevation, site_elevation + altitude, top]), isa_offset)
    p, t = a.pressure, a.temperature
    f, f_rule = (float(x) for x in ballonet_fraction(p[0], t[0], p[1:], t[1:], superheat))
    return f, f_rule


def ballonet_mass(req, cfg, hull_volume):
    """Ballonet fabric mass [kg] (hull fabric areal density), 0 where none is built."""
    if cfg.mission.ballonet == "off":  # the default: skip the three ISA calls in the sizing loop
        return np.zeros(np.shape(hull_volume))
    b = ballonet_state(req, cfg)
    if not b.built:
        return np.zeros(np.shape(hull_volume))
    return ballonet_fabric_mass(
        b.fraction * np.asarray(hull_volume, float), cfg.hull_fabric.areal_density
    )


# --- endurance ---------------------------------------------------------------------------------
def _gas_densities(cfg, af):
    """(air, pure lifting gas) densities at hull conditions [kg/m3]."""
    gas = cfg.gas
    if gas.density_model == "fixed":
        return af.air_density, gas.fixed_density_value
    p_hull = af.pressure + gas.superpressure
    molar = c.M_HELIUM if gas.kind == "helium" else c.M_HYDROGEN
    return p_hull / (c.R_AIR * af.temperature), p_hull * molar / (c.R_UNIVERSAL * af.temperature)


def endurance_quantities(req, cfg, af) -> dict:
    """Lift decay by permeation for an airframe batch.

    Returns
    -------
    dict
        tau [day], days_to_top_up [day] (capped at DAYS_CAP), g of the ``endurance`` row
        ((required free lift + lift lost in endurance_days - free lift)/gross lift; -1 when no
        endurance is required), margin [day].
    """
    h = af.hull
    tau = permeation_time_constant(
        h.volume, h.surface_area, cfg.hull_fabric.helium_permeability, af.temperature
    )
    rho_a, rho_p = _gas_densities(cfg, af)
    k0 = cfg.gas.purity
    need = req.free_lift_fraction * af.buoyancy
    days = np.minimum(
        days_to_top_up(af.free_lift - need, h.volume, af.g, rho_a, rho_p, k0, tau), DAYS_CAP
    )
    fb = np.maximum(np.abs(af.buoyancy), 1e-9)
    d_req = float(req.endurance_days)
    if d_req > 0:
        lost = lift_loss_after(h.volume, af.g, rho_a, rho_p, k0, d_req, tau)
        g = (need + lost - af.free_lift) / fb
    else:
        g = -np.ones(np.shape(days))
    return {"tau": tau, "days_to_top_up": days, "g": g, "margin": days - d_req}


# --- envelope structure ------------------------------------------------------------------------
def structure_quantities(req, cfg, ev) -> dict:
    """Envelope pressure and stress at the speeds of an evaluation (design and survival winds).

    Returns
    -------
    dict of arrays (broadcast over designs and speeds)
        pressure_required [Pa] (at the top of the hull: factor q + hydrostatic head, or the gas
        superpressure if higher), moment [N m] (aerodynamic moment of hull + fins about the
        centre of volume, |dM/dalpha alpha|, a linear estimate of the envelope bending moment),
        hoop, longitudinal [N/m], strength_required (SF x the larger load) [N/m], strength
        (fabric) [N/m], pressure_allowable [Pa] (largest pressure the fabric carries with SF
        under that moment).
    """
    af = ev.airframe
    m = cfg.mission
    q = 0.5 * af.air_density * np.asarray(ev.speed, float) ** 2
    p = required_pressure(
        q, af.air_density, af.gas_density, af.g, af.hull.diameter, m.pressure_dynamic_factor
    )
    p = np.maximum(p, cfg.gas.superpressure)
    moment = np.abs(ev.weathervane_slope * ev.equilibrium.alpha)
    r = af.hull.b
    hoop, long = membrane_loads(p, r, moment)
    need = m.envelope_safety_factor * np.maximum(hoop, long)
    strength = float(cfg.hull_fabric.tensile_strength)
    allow = allowable_pressure(strength, m.envelope_safety_factor, r, moment)
    return {
        "pressure_required": p,
        "moment": moment,
        "hoop": hoop,
        "longitudinal": long,
        "strength_required": need,
        "strength": strength,
        "pressure_allowable": allow,
    }


def lift_decay(req, cfg, af, days_max: float, points: int = 31) -> dict:
    """Purity and free lift versus day without top-up, for one (0-d) airframe.

    Returns
    -------
    dict of ndarray
        day [day], purity [-], free_lift_kg [kg] (k(t) and L_f(t) of aerostat_core.atmosphere.permeation),
        required_kg [kg] (the free lift the requirement asks for).
    """
    h = af.hull
    t = np.linspace(0.0, float(days_max), points)
    tau = scalar(
        permeation_time_constant(
            h.volume, h.surface_area, cfg.hull_fabric.helium_permeability, af.temperature
        )
    )
    rho_a, rho_p = _gas_densities(cfg, af)
    k0 = cfg.gas.purity
    fl = scalar(af.free_lift)
    loss = np.asarray(
        lift_loss_after(scalar(h.volume), af.g, scalar(rho_a), scalar(rho_p), k0, t, tau), float
    ).reshape(-1)
    need = req.free_lift_fraction * scalar(af.buoyancy) / af.g
    return {
        "day": t,
        "purity": np.asarray(purity_after(k0, t, tau), float).reshape(-1),
        "free_lift_kg": (fl - loss) / af.g,
        "required_kg": np.full_like(t, need),
    }


def scalar(x) -> float:
    """The first element of ``x`` as a float (0-d and 1-element arrays from the batch code)."""
    return float(np.asarray(x, float).reshape(-1)[0])
