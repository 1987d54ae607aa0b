"""What the user asks for (:class:`Requirement`) and the design choices (:class:`Configuration`).

All inputs are frozen dataclasses validated on construction: a bad value raises ``ValueError``
naming the field, the value and the valid range. SI units throughout (angles in degrees only
where the field name says ``_deg``).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields, replace

from . import constants as c
from .materials import Fabric, TetherSpec
from .mission import POWER_ROUTES, MissionSpec
from .rules import DEFAULT_RULES, RULE_NAMES, RuleSet, get_rules
from .shapes import SHAPE_INFO, SHAPES
from .validation import InputError, check_choice, check_int, check_number

GAS_KINDS = ("helium", "hydrogen")
DENSITY_MODELS = ("ideal", "fixed")
FIN_ARRANGEMENTS = ("+", "x", "inverted-y")
WIND_PROFILES = ("uniform", "power", "log")
CUTOFF_MODES = ("fin", "tail")


#: Requirement fields that a rule set fills in when left as ``None`` (aerostat_core.rules).
RULE_FIELDS = (
    "design_wind", "survival_wind", "blow_by_limit", "altitude_loss_limit",
    "free_lift_fraction", "min_tether_safety_factor", "survival_safety_factor",
    "max_tether_angle_deg", "weathervane_margin",
)


@dataclass(frozen=True)
class Requirement:
    """The mission, in the language of thesis Table 2.4 and of vendor spec sheets.

    Any limit left as ``None`` takes the value of the rule set ``rules`` (see
    :mod:`aerostat_core.rules`, where each default has its source); :meth:`resolved` returns the
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
        power supply (thesis Table 2.4 "power requirement"; aerostat_core.mission).
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

    payload_mass: float = 10.0
    altitude: float = 300.0
    site_elevation: float = 0.0
    isa_offset: float = 0.0
    site_temperature: float | None = None
    wind_max: float = 20.0
    wind_step: float = 1.0
    design_wind: float | None = None
    survival_wind: float | None = None
    blow_by_limit: float | None = None
    altitude_loss_limit: float | None = None
    free_lift_fraction: float | None = None
    min_tether_safety_factor: float | None = None
    survival_safety_factor: float | None = None
    max_tether_angle_deg: float | None = None
    weathervane_margin: float | None = None
    rules: str = DEFAULT_RULES
    payload_power: float = 0.0
    power_via: str = "onboard"
    endurance_days: float = 0.0
    deployment_days: float = 30.0

    def __post_init__(self) -> None:
        o = "Requirement"
        check_choice(o, "rules", self.rules, RULE_NAMES)
        check_number(o, "payload_power", self.payload_power, 0, 1e5, "W")
        check_choice(o, "power_via", self.power_via, POWER_ROUTES)
        check_number(o, "endurance_days", self.endurance_days, 0, 365, "day")
        check_number(o, "deployment_days", self.deployment_days, 0, 3650, "day")
        check_number(o, "payload_mass", self.payload_mass, 0, 500, "kg", lo_open=True)
        check_number(o, "altitude", self.altitude, 10, 3000, "m")
        check_number(o, "site_elevation", self.site_elevation, -400, 5000, "m")
        check_number(o, "isa_offset", self.isa_offset, -40, 40, "K")
        if self.site_temperature is not None:
            check_number(o, "site_temperature", self.site_temperature, -60, 60, "degC")
        check_number(o, "wind_max", self.wind_max, 0, 60, "m/s", lo_open=True)
        check_number(o, "wind_step", self.wind_step, 0.1, 10, "m/s")
        opt = (
            ("design_wind", 0, 40, "m/s", False),
            ("survival_wind", 0, 60, "m/s", False),
            ("blow_by_limit", 0, self.altitude, "m", True),
            ("altitude_loss_limit", 0, 3000, "m", True),
            ("free_lift_fraction", 0, 0.8, "", False),
            ("min_tether_safety_factor", 1, 20, "", False),
            ("survival_safety_factor", 1, 20, "", False),
            ("max_tether_angle_deg", 0, 90, "deg", True),
            ("weathervane_margin", 0, 1, "1/rad", False),
        )
        for name, lo, hi, unit, lo_open in opt:
            v = getattr(self, name)
            if v is not None:
                check_number(o, name, v, lo, hi, unit, lo_open=lo_open)
        if (self.design_wind is not None and self.survival_wind is not None
                and self.survival_wind < self.design_wind):
            raise ValueError(
                f"Requirement.survival_wind = {self.survival_wind:g} m/s is below the design "
                f"wind {self.design_wind:g} m/s; valid range [{self.design_wind:g}, 60] m/s"
            )
        top = self.site_elevation + self.altitude
        if top > c.ISA_TROPOPAUSE:
            raise ValueError(
                f"Requirement.altitude = {self.altitude:g} m with site_elevation = "
                f"{self.site_elevation:g} m puts the aerostat at {top:g} m above sea level, beyond "
                f"the atmosphere model's valid range "
                f"[{c.ISA_MIN_ALTITUDE:g}, {c.ISA_TROPOPAUSE:g}] m"
            )

    @property
    def rule_set(self) -> RuleSet:
        """The :class:`~aerostat_core.rules.RuleSet` named by ``rules``."""
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
class LiftingGas:
    """Lifting gas and its state in the hull.

    Parameters
    ----------
    kind : {"helium", "hydrogen"}
    purity : float
        Volume (mole) fraction of the lifting gas; the rest is air [-], valid (0, 1].
    superpressure : float
        Hull pressure above ambient [Pa], valid [0, 5000].
    density_model : {"ideal", "fixed"}
        ``"ideal"``: ideal-gas density at ambient temperature and hull pressure, mixed with air by
        purity. ``"fixed"``: a constant density (the thesis uses 0.169 kg/m3 for helium).
    fixed_density : float or None
        Density for ``"fixed"`` [kg/m3], valid (0, 1]; ``None`` takes the thesis value of the gas.
    """

    kind: str = "helium"
    purity: float = 0.98
    superpressure: float = 0.0
    density_model: str = "ideal"
    fixed_density: float | None = None

    def __post_init__(self) -> None:
        o = "LiftingGas"
        check_choice(o, "kind", self.kind, GAS_KINDS)
        check_number(o, "purity", self.purity, 0, 1, lo_open=True)
        check_number(o, "superpressure", self.superpressure, 0, 5000, "Pa")
        check_choice(o, "density_model", self.density_model, DENSITY_MODELS)
        if self.fixed_density is not None:
            check_number(o, "fixed_density", self.fixed_density, 0, 1, "kg/m3", lo_open=True)

    @property
    def fixed_density_value(self) -> float:
        """Density used by the ``"fixed"`` model [kg/m3]."""
        if self.fixed_density is not None:
            return float(self.fixed_density)
        return c.THESIS_HELIUM_DENSITY if self.kind == "helium" else c.THESIS_HYDROGEN_DENSITY


@dataclass(frozen=True)
class HullSpec:
    """The hull: its shape, fineness ratio and (optionally) volume.

    Parameters
    ----------
    fineness_ratio : float or None
        Length / maximum diameter f [-] (design variable 1), valid in the shape's range
        (``aerostat_core.shapes.SHAPE_INFO``: NPL [1.5, 8], Gertler shapes [2, 6], sphere 1,
        oblate [0.5, 0.95], Helikite [1, 1.6]); ``None`` takes the shape's standard value
        (4.0 for NPL).
    nose_fraction : float
        Station of maximum diameter / length, a1/l [-], valid [0.2, 0.8]; NPL standard 0.432
        (NPL only; the other profiles fix their own).
    volume : float or None
        Hull volume [m3], valid [1, 1e5]; ``None`` sizes the smallest hull that meets the blow-by
        limit at the design wind with positive free lift.
    shape : str
        Hull shape, one of ``aerostat_core.shapes.SHAPES``: "npl" (default), "gnvr", "wang",
        "zhiyuan-1", "lotte", "sphere", "oblate", "helikite".
    """

    fineness_ratio: float | None = None
    nose_fraction: float = 0.432
    volume: float | None = None
    shape: str = "npl"

    def __post_init__(self) -> None:
        o = "HullSpec"
        check_choice(o, "shape", self.shape, SHAPES)
        if self.fineness_ratio is None:
            object.__setattr__(self, "fineness_ratio", SHAPE_INFO[self.shape].default_fineness)
        lo, hi = SHAPE_INFO[self.shape].fineness_range
        try:
            check_number(o, "fineness_ratio", self.fineness_ratio, lo, hi)
        except InputError as exc:
            raise InputError(
                f"{exc} for shape {self.shape!r}", owner=o, field="fineness_ratio",
                value=exc.value, lo=lo, hi=hi, unit="", reason=f"{exc.reason} for shape "
                f"{self.shape!r}") from None
        check_number(o, "nose_fraction", self.nose_fraction, 0.2, 0.8)
        if self.volume is not None:
            check_number(o, "volume", self.volume, 1.0, 1e5, "m3")


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

    count: int = 4
    arrangement: str = "+"
    area_change: float = 0.0
    position: float = 0.68
    area_ratio: float = 0.227
    aspect_ratio: float = 2.0
    taper_ratio: float = 0.5
    fabric_factor: float = 2.2

    def __post_init__(self) -> None:
        o = "FinSpec"
        object.__setattr__(self, "count", check_int(o, "count", self.count, 3, 4))
        check_choice(o, "arrangement", self.arrangement, FIN_ARRANGEMENTS)
        need = 3 if self.arrangement == "inverted-y" else 4
        if self.count != need:
            raise ValueError(
                f"FinSpec.count = {self.count} does not fit arrangement {self.arrangement!r}, "
                f"which needs {need} fins"
            )
        check_number(o, "area_change", self.area_change, -50, 200, "%")
        check_number(o, "position", self.position, 0.4, 0.95)
        check_number(o, "area_ratio", self.area_ratio, 0, 1, lo_open=True)
        check_number(o, "aspect_ratio", self.aspect_ratio, 0.5, 6)
        check_number(o, "taper_ratio", self.taper_ratio, 0.1, 1)
        check_number(o, "fabric_factor", self.fabric_factor, 1, 4)


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

    hull_efficiency: float = c.HULL_EFFICIENCY
    hull_crossflow_drag: float = c.HULL_CROSSFLOW_DRAG
    hull_axial_drag: float | None = None
    cutoff: str = "fin"
    fin_efficiency: float = c.FIN_EFFICIENCY
    section_lift_slope: float = c.SECTION_LIFT_SLOPE
    fin_zero_lift_drag: float = c.FIN_ZERO_LIFT_DRAG
    fin_stall_angle_deg: float = c.FIN_STALL_ANGLE_DEG

    def __post_init__(self) -> None:
        o = "AeroModel"
        check_number(o, "hull_efficiency", self.hull_efficiency, 0, 2)
        check_number(o, "hull_crossflow_drag", self.hull_crossflow_drag, 0, 2)
        if self.hull_axial_drag is not None:
            check_number(o, "hull_axial_drag", self.hull_axial_drag, 0, 1)
        check_choice(o, "cutoff", self.cutoff, CUTOFF_MODES)
        check_number(o, "fin_efficiency", self.fin_efficiency, 0, 1.5)
        check_number(o, "section_lift_slope", self.section_lift_slope, 1, 7, "1/rad")
        check_number(o, "fin_zero_lift_drag", self.fin_zero_lift_drag, 0, 0.1)
        check_number(o, "fin_stall_angle_deg", self.fin_stall_angle_deg, 5, 40, "deg")


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

    drop_ratio: float = 0.6
    xi_offset: float = 0.0

    def __post_init__(self) -> None:
        check_number("ConfluenceSpec", "drop_ratio", self.drop_ratio, 0.05, 3)
        check_number("ConfluenceSpec", "xi_offset", self.xi_offset, -0.2, 0.2)


@dataclass(frozen=True)
class WindProfile:
    """Mean wind versus height along the tether.

    The sweep's wind speed is the wind at the aerostat's flying height; the profile scales it down
    to the tether below: power law U(z) = U_top (z/z_top)^p,
    log law U = U_top ln(z/z0)/ln(z_top/z0).

    Parameters
    ----------
    kind : {"uniform", "power", "log"}
    exponent : float
        Power-law exponent p [-], valid [0, 0.6] (1/7 open terrain).
    roughness_length : float
        Log-law roughness z0 [m], valid [1e-5, 2].
    """

    kind: str = "uniform"
    exponent: float = 1.0 / 7.0
    roughness_length: float = 0.03

    def __post_init__(self) -> None:
        check_choice("WindProfile", "kind", self.kind, WIND_PROFILES)
        check_number("WindProfile", "exponent", self.exponent, 0, 0.6)
        check_number("WindProfile", "roughness_length", self.roughness_length, 1e-5, 2, "m")


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
        Battery, power-tether, ballonet, envelope and winch technology (aerostat_core.mission).
    """

    gas: LiftingGas = field(default_factory=LiftingGas)
    hull_fabric: Fabric = field(default_factory=Fabric)
    fin_fabric: Fabric = field(default_factory=Fabric)
    tether: TetherSpec = field(default_factory=TetherSpec)
    hull: HullSpec = field(default_factory=HullSpec)
    fins: FinSpec = field(default_factory=FinSpec)
    aero: AeroModel = field(default_factory=AeroModel)
    confluence: ConfluenceSpec = field(default_factory=ConfluenceSpec)
    wind_profile: WindProfile = field(default_factory=WindProfile)
    misc_mass_ratio: float = 0.30
    gas_price: float | None = None
    tether_segments: int = 50
    mission: MissionSpec = field(default_factory=MissionSpec)

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
        check_number(o, "misc_mass_ratio", self.misc_mass_ratio, 0, 2)
        if self.gas_price is not None:
            check_number(o, "gas_price", self.gas_price, 0, 1000, "USD/m3")
        object.__setattr__(
            self, "tether_segments", check_int(o, "tether_segments", self.tether_segments, 10, 5000)
        )

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
