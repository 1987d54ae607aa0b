"""What the user asks for (:class:`Requirement`) and the design choices (:class:`Configuration`).

All inputs are frozen dataclasses validated on construction: a bad value raises ``ValueError``
naming the field, the value and the valid range. SI units throughout (angles in degrees only
where the field name says ``_deg``).
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace

from aerostat_core.aerodynamics.forces import AeroModel
from aerostat_core.atmosphere.gas import LiftingGas
from aerostat_core.atmosphere.wind import WindProfile
from aerostat_core.base import constants as c
from aerostat_core.base.fields import choice, field_spec, integer, number, part, validate
from aerostat_core.base.validation import InputError
from aerostat_core.geometry.fins import FinSpec
from aerostat_core.geometry.shapes import HullSpec
from aerostat_core.model.mission import POWER_ROUTES, MissionSpec
from aerostat_core.model.rules import DEFAULT_RULES, RULE_NAMES, RuleSet, get_rules
from aerostat_core.structures.materials import Fabric, TetherSpec

#: Requirement fields that a rule set fills in when left as ``None`` (aerostat_core.model.rules).
RULE_FIELDS = (
    "design_wind", "survival_wind", "blow_by_limit", "altitude_loss_limit",
    "free_lift_fraction", "min_tether_safety_factor", "survival_safety_factor",
    "max_tether_angle_deg", "weathervane_margin",
)


@dataclass(frozen=True)
class Requirement:
    """The mission, in the language of thesis Table 2.4 and of vendor spec sheets.

    Any limit left as ``None`` takes the value of the rule set ``rules`` (see
    :mod:`aerostat_core.model.rules`, where each default has its source); :meth:`resolved` returns the
    requirement with every limit filled in, and every engine entry point resolves first.

    Parameters
    ----------
    payload_mass : float
        Payload carried below the hull [kg], valid (0, 500].
    altitude : float
        Floating (operating) altitude above the launch site [m], valid [10, 3000]. The tether
        length is set equal to it (thesis practice); the table reports the altitude loss in wind.
    site_elevation : float
        Base-station elevation above mean sea level [m], valid [-400, 5000]; site + altitude must
        stay within the ISA troposphere (<= 11 km).
    isa_offset : float
        Temperature offset from ISA [K], valid [-40, 40] (hot tropical day about +15 K). Ignored
        when ``site_temperature`` is given.
    site_temperature : float or None
        Air temperature at the launch site [degC], valid [-60, 60]; sets the ISA offset so that
        the ISA lapse rate runs through it (thesis Table 2.4 "temperature at launch site").
    wind_max : float
        Largest wind speed of the performance sweep [m/s], valid (0, 60].
    wind_step : float
        Step of the sweep [m/s], valid [0.1, 10].
    design_wind : float or None
        Operational wind at the aerostat [m/s], valid [0, 40], at which blow-by, altitude loss,
        tether angle, stall and stability are checked.
    survival_wind : float or None
        Survival wind at the aerostat [m/s], valid [0, 60] and >= ``design_wind``, at which the
        tether safety factor must still be ``survival_safety_factor``.
    blow_by_limit : float or None
        Largest acceptable horizontal offset of the confluence point from the winch at the design
        wind [m], valid (0, altitude].
    altitude_loss_limit : float or None
        Permissible reduction in altitude at the design wind [m], valid (0, 3000] (a limit above
        the altitude never binds).
    free_lift_fraction : float or None
        Required free lift at rest / gross lift [-], valid [0, 0.8].
    min_tether_safety_factor : float or None
        Breaking strength / largest tether tension at the design wind [-], valid [1, 20].
    survival_safety_factor : float or None
        Breaking strength / largest tether tension at the survival wind [-], valid [1, 20].
    max_tether_angle_deg : float or None
        Largest tether angle from the vertical at the design wind [deg], valid (0, 90].
    weathervane_margin : float or None
        Required aerodynamic stability margin, C_m_alpha about the centre of volume <= -margin
        [1/rad], valid [0, 1].
    rules : {"practice", "thesis"}
        Rule set for the limits left as ``None``.
    payload_power : float
        Electrical power the payload draws [W], valid [0, 100000]; 0 (the default) models no
        power supply (thesis Table 2.4 "power requirement"; aerostat_core.model.mission).
    power_via : {"onboard", "tether"}
        Where the power comes from: an onboard battery, or the ground through conductors in the
        tether (a "live" tether, thesis §2.2.3).
    endurance_days : float
        Days the aerostat must stay up without a helium top-up, keeping the required free lift
        [day], valid [0, 365]; 0 (the default) sets no endurance requirement (thesis §2.3:
        tactical systems 5-7 days, operational ones weeks "on helium gas addition").
    deployment_days : float
        Deployment length over which the helium top-up gas and its cost are reported [day],
        valid [0, 3650].
    """

    payload_mass: float = number(
        10.0, "Payload mass", "kg", 0, 500, lo_open=True, step=1.0, fmt="%.1f",
        help="Mass hung below the hull (camera, radio...).")
    altitude: float = number(
        300.0, "Operating altitude", "m", 10, 3000, step=10.0, fmt="%.0f",
        help="Height above the launch site; the tether length equals it.")
    site_elevation: float = number(
        0.0, "Site elevation", "m", -400, 5000, display_unit="m above sea level", step=50.0,
        fmt="%.0f", help="Launch-site elevation; air density is taken at site + altitude.")
    isa_offset: float = number(
        0.0, "Temperature offset from ISA", "K", -40, 40, step=1.0, fmt="%.1f",
        help="Hot tropical day about +15 K. Ignored when the site temperature is given.")
    site_temperature: float | None = number(
        None, "Temperature at the launch site", "degC", -60, 60, empty="ISA + offset",
        step=1.0, fmt="%.1f",
        help="Sets the ISA offset so that the standard lapse rate runs through it.",
        source="thesis Table 2.4")
    wind_max: float = number(
        20.0, "Maximum wind of the sweep", "m/s", 0, 60, lo_open=True, step=1.0, fmt="%.1f",
        help="Performance is computed from 0 to this speed.")
    wind_step: float = number(
        1.0, "Wind step of the sweep", "m/s", 0.1, 10, step=0.5, fmt="%.1f",
        help="Spacing of the wind sweep.")
    design_wind: float | None = number(
        None, "Operational (design) wind", "m/s", 0, 40, empty="rule set", step=1.0,
        fmt="%.1f", help="Wind at which blow-by, altitude loss, tether angle, stall and "
        "stability are checked (practice 10 m/s, thesis 15 m/s).", source="aerostat_core.model.rules")
    survival_wind: float | None = number(
        None, "Survival wind", "m/s", 0, 60, empty="rule set", step=1.0, fmt="%.1f",
        help="Wind the tether must survive aloft (practice 20 m/s, the tactical class); at "
        "least the design wind.", source="aerostat_core.model.rules")
    blow_by_limit: float | None = number(
        None, "Blow-by limit at the design wind", "m", 0, 3000, lo_open=True,
        hi_field="altitude", empty="rule set", step=5.0, fmt="%.1f",
        help="Largest acceptable downwind offset of the confluence point from the winch "
        "(practice 0.5 x altitude, thesis 0.178 x altitude); at most the altitude.",
        source="aerostat_core.model.rules")
    altitude_loss_limit: float | None = number(
        None, "Permissible altitude loss", "m", 0, 3000, lo_open=True, empty="rule set",
        step=5.0, fmt="%.1f", help="Largest acceptable loss of height at the design wind "
        "(practice 0.15 x altitude, thesis: off).", source="aerostat_core.model.rules")
    free_lift_fraction: float | None = number(
        None, "Free lift, share of gross lift", "", 0, 0.8, scale=100.0, display_unit="%",
        empty="rule set", step=1.0, fmt="%.1f",
        help="Free lift at rest the hull must keep (practice 15 %, thesis 1 %).",
        source="aerostat_core.model.rules")
    min_tether_safety_factor: float | None = number(
        None, "Tether safety factor at the design wind", "", 1, 20, empty="rule set",
        step=0.5, fmt="%.2f", help="Breaking strength / largest tether tension must reach this "
        "(3 in both rule sets).", source="aerostat_core.model.rules")
    survival_safety_factor: float | None = number(
        None, "Tether safety factor at the survival wind", "", 1, 20, empty="rule set",
        step=0.1, fmt="%.2f", help="Practice 1.5.", source="aerostat_core.model.rules")
    max_tether_angle_deg: float | None = number(
        None, "Largest tether angle from the vertical", "deg", 0, 90, lo_open=True,
        empty="rule set", step=5.0, fmt="%.0f",
        help="At the design wind (practice 60 deg, thesis 45 deg).", source="aerostat_core.model.rules")
    weathervane_margin: float | None = number(
        None, "Weathervane stability margin", "1/rad", 0, 1, empty="rule set", step=0.01,
        fmt="%.3f", help="C_m_alpha about the centre of volume must be at most minus this "
        "(practice 0.02, thesis 0).", source="aerostat_core.model.rules")
    rules: str = choice(
        DEFAULT_RULES, "Rule set", RULE_NAMES, source="aerostat_core.model.rules",
        help="Where the limits left empty come from: 'practice' for real missions (free lift "
        "15 % of gross lift, limits scaled to the tether length), 'thesis' for the calibrated "
        "preset of Mahmood (2020). Method page: sources of every value.")
    payload_power: float = number(
        0.0, "Payload power", "W", 0, 1e5, step=10.0, fmt="%.0f",
        help="Electrical power the payload draws; 0 models no power supply.",
        source="thesis Table 2.4")
    power_via: str = choice(
        "onboard", "Payload power from", POWER_ROUTES, source="thesis §2.2.3",
        help="An onboard battery adds its mass; through the tether adds copper conductors.")
    endurance_days: float = number(
        0.0, "Endurance without top-up", "day", 0, 365, step=1.0, fmt="%.1f",
        help="Days the free-lift margin must last while helium permeates out (tactical "
        "5-7 days). 0: no requirement.", source="thesis §2.3")
    deployment_days: float = number(
        30.0, "Deployment length (top-up gas)", "day", 0, 3650, step=1.0, fmt="%.0f",
        help="Period over which the helium top-up gas and its cost are reported.")

    def __post_init__(self) -> None:
        validate(self)
        if (self.design_wind is not None and self.survival_wind is not None
                and self.survival_wind < self.design_wind):
            hi = field_spec(self, "survival_wind").hi
            reason = (f"is below the design wind {self.design_wind:g} m/s; valid range "
                      f"[{self.design_wind:g}, {hi:g}] m/s")
            raise InputError(
                f"Requirement.survival_wind = {self.survival_wind:g} m/s {reason}",
                owner="Requirement", field="survival_wind", value=self.survival_wind,
                lo=self.design_wind, hi=hi, unit="m/s", reason=reason,
                label=field_spec(self, "survival_wind").label,
            )
        top = self.site_elevation + self.altitude
        if top > c.ISA_TROPOPAUSE:
            reason = (
                f"with a site elevation of {self.site_elevation:g} m puts the aerostat at {top:g} m "
                f"above sea level, beyond the atmosphere model's valid range "
                f"[{c.ISA_MIN_ALTITUDE:g}, {c.ISA_TROPOPAUSE:g}] m"
            )
            raise InputError(
                f"Requirement.altitude = {self.altitude:g} m {reason}", owner="Requirement",
                field="altitude", value=self.altitude, unit="m", reason=reason,
                label=field_spec(self, "altitude").label,
            )

    @property
    def rule_set(self) -> RuleSet:
        """The :class:`~aerostat_core.model.rules.RuleSet` named by ``rules``."""
        return get_rules(self.rules)

    @property
    def is_resolved(self) -> bool:
        """True when no limit is left to the rule set."""
        return all(getattr(self, k) is not None for k in RULE_FIELDS)

    def resolved(self) -> Requirement:
        """This requirement with every ``None`` limit filled in from its rule set.

        Fractions of the tether length become lengths (tether length = ``altitude``); a rule set
        without a survival wind checks the survival safety factor at the design wind; one without
        an altitude-loss limit sets it to the whole altitude (never binding). A given
        ``site_temperature`` sets ``isa_offset`` = T_site - T_ISA(site_elevation).
        """
        changes = {}
        if self.site_temperature is not None:
            t_isa = c.ISA_T0 - c.ISA_LAPSE * (
                c.ISA_EARTH_RADIUS * self.site_elevation / (c.ISA_EARTH_RADIUS + self.site_elevation))
            off = float(self.site_temperature) + 273.15 - t_isa
            if abs(off - self.isa_offset) > 1e-12:
                changes["isa_offset"] = off
        if self.is_resolved and not changes:
            return self
        r = self.rule_set
        h = float(self.altitude)
        design_wind = r.design_wind if self.design_wind is None else self.design_wind
        survival = self.survival_wind
        if survival is None:
            survival = max(r.survival_wind or design_wind, design_wind)
        defaults = {
            "design_wind": design_wind,
            "survival_wind": survival,
            "blow_by_limit": r.blow_by_fraction * h,
            "altitude_loss_limit": (h if r.altitude_loss_fraction is None
                                    else r.altitude_loss_fraction * h),
            "free_lift_fraction": r.free_lift_fraction,
            "min_tether_safety_factor": r.min_tether_safety_factor,
            "survival_safety_factor": r.survival_safety_factor,
            "max_tether_angle_deg": r.max_tether_angle_deg,
            "weathervane_margin": r.weathervane_margin,
        }
        for k, v in defaults.items():
            if getattr(self, k) is None:
                changes[k] = v
        return replace(self, **changes)


@dataclass(frozen=True)
class ConfluenceSpec:
    """Where the confluence lines meet the tether.

    Parameters
    ----------
    drop_ratio : float
        Distance of the confluence point below the hull bottom / hull diameter [-], valid
        [0.05, 3]. Not found in the thesis; 0.6 is an engineering guess (docs/methods.md G9).
    xi_offset : float
        Station shift from the point below the centre of net static lift / hull length [-], valid
        [-0.2, 0.2]; positive moves it aft and trims the nose up in calm air.
    """

    drop_ratio: float = number(
        0.6, "Confluence drop / hull diameter", "", 0.05, 3, step=0.05, fmt="%.2f",
        help="Confluence point below the hull bottom; not given in the thesis, 0.6 is an "
        "engineering guess.", source="docs/methods.md G9")
    xi_offset: float = number(
        0.0, "Confluence station offset / hull length", "", -0.2, 0.2, step=0.01, fmt="%.3f",
        help="Shift aft (+) from below the centre of net static lift.")

    def __post_init__(self) -> None:
        validate(self)


@dataclass(frozen=True)
class Configuration:
    """Every design choice that is not part of the requirement.

    Parameters
    ----------
    gas, hull_fabric, fin_fabric, tether, hull, fins, aero, confluence, wind_profile
        See the component classes.
    misc_mass_ratio : float
        Miscellaneous mass (confluence lines, patches, valves, nose cone) / hull fabric mass [-],
        valid [0, 2]. Thesis Table 2.2: 4.7 / 15.57 = 0.30 (INFERRED).
    gas_price : float or None
        Lifting-gas price [USD/m3], valid [0, 1000]; ``None`` takes the default of the gas kind.
    tether_segments : int
        Segments of the static tether march, valid [10, 5000]. Heun's method with 50 segments is
        within 1 mm of a 2000-segment solution for a 300 m tether (tests/core/test_tether.py).
    mission : MissionSpec
        Battery, power-tether, ballonet, envelope and winch technology (aerostat_core.model.mission).
    """

    gas: LiftingGas = part(LiftingGas, "Lifting gas")
    hull_fabric: Fabric = part(Fabric, "Hull fabric", prefix=True)
    fin_fabric: Fabric = part(Fabric, "Fin fabric", prefix=True)
    tether: TetherSpec = part(TetherSpec, "Tether", prefix=True)
    hull: HullSpec = part(HullSpec, "Hull")
    fins: FinSpec = part(FinSpec, "Fins")
    aero: AeroModel = part(AeroModel, "Aerodynamic model")
    confluence: ConfluenceSpec = part(ConfluenceSpec, "Confluence point")
    wind_profile: WindProfile = part(WindProfile, "Wind profile")
    misc_mass_ratio: float = number(
        0.30, "Miscellaneous mass / hull mass", "", 0, 2, step=0.05, fmt="%.2f",
        help="Confluence lines, patches, valves (thesis Table 2.2: 0.30).",
        source="thesis Table 2.2")
    gas_price: float | None = number(
        None, "Gas price", "USD/m3", 0, 1000, empty="default", step=1.0, fmt="%.2f",
        help="Fill cost per cubic metre. Default helium 38.5 USD/m³ (thesis App. H).")
    tether_segments: int = integer(
        50, "Tether segments", 10, 5000, step=10,
        help="Segments of the static tether march (50 is within 1 mm of 2000).")
    mission: MissionSpec = part(MissionSpec, "Mission technology")

    def __post_init__(self) -> None:
        o = "Configuration"
        for f, cls in (
            ("gas", LiftingGas),
            ("hull_fabric", Fabric),
            ("fin_fabric", Fabric),
            ("tether", TetherSpec),
            ("hull", HullSpec),
            ("fins", FinSpec),
            ("aero", AeroModel),
            ("confluence", ConfluenceSpec),
            ("wind_profile", WindProfile),
            ("mission", MissionSpec),
        ):
            if not isinstance(getattr(self, f), cls):
                raise ValueError(f"{o}.{f} must be a {cls.__name__}")
        validate(self)

    @property
    def gas_price_value(self) -> float:
        """Lifting-gas price used for the fill cost [USD/m3]."""
        if self.gas_price is not None:
            return float(self.gas_price)
        if self.gas.kind == "helium":
            return c.HELIUM_PRICE_USD_PER_M3
        return c.HYDROGEN_PRICE_USD_PER_M3

    def with_design_variables(
        self,
        fineness_ratio: float | None = None,
        area_change: float | None = None,
        position: float | None = None,
        volume: float | None | str = "keep",
    ) -> Configuration:
        """Return a copy with the thesis' design variables (and optionally the volume) changed."""
        hull = self.hull
        if fineness_ratio is not None:
            hull = replace(hull, fineness_ratio=fineness_ratio)
        if volume != "keep":
            hull = replace(hull, volume=volume)
        fins = self.fins
        if area_change is not None:
            fins = replace(fins, area_change=area_change)
        if position is not None:
            fins = replace(fins, position=position)
        return replace(self, hull=hull, fins=fins)


def field_names(cls: type) -> tuple[str, ...]:
    """Names of a dataclass' fields, in order (used by the I/O layer)."""
    return tuple(f.name for f in fields(cls))
