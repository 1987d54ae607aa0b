"""What the user asks for (:class:`Requirement`) and the design choices (:class:`Configuration`).

All inputs are frozen dataclasses validated on construction: a bad value raises ``ValueError``
naming the field, the value and the valid range. SI units throughout (angles in degrees only
where the field name says ``_deg``).
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace

from . import constants as c
from .fields import check, choice, field_spec, integer, number, part, validate
from .materials import Fabric, TetherSpec
from .mission import POWER_ROUTES, MissionSpec
from .rules import DEFAULT_RULES, RULE_NAMES, RuleSet, get_rules
from .shapes import SHAPE_INFO, SHAPES
from .validation import InputError

GAS_KINDS = ("helium", "hydrogen")
DENSITY_MODELS = ("ideal", "fixed")
FIN_ARRANGEMENTS = ("+", "x", "inverted-y")
WIND_PROFILES = ("uniform", "power", "log")
CUTOFF_MODES = ("fin", "tail")
#: Widest fineness-ratio range over the shapes (each shape narrows it, ``SHAPE_INFO``).
_FINENESS_LO = min(s.fineness_range[0] for s in SHAPE_INFO.values())
_FINENESS_HI = max(s.fineness_range[1] for s in SHAPE_INFO.values())
_FINENESS_RANGES = ", ".join(
    f"{s.label} {lo:g}" + (f"-{hi:g}" if hi > lo else "")
    for s in SHAPE_INFO.values() for lo, hi in [s.fineness_range])


#: Requirement fields that a rule set fills in when left as ``None`` (aerostat_core.rules).
RULE_FIELDS = (
    "design_wind", "survival_wind", "blow_by_limit", "altitude_loss_limit",
    "free_lift_fraction", "min_tether_safety_factor", "survival_safety_factor",
    "max_tether_angle_deg", "weathervane_margin", "top_up_interval_days",
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
    top_up_interval_days : float or None
        Days between helium top-ups [day], valid [0, 365]: the free-lift margin must still hold
        at the end of one (practice 7, thesis 0: at the fill); the endurance row checks the
        longer of this and ``endurance_days``.
    confidence : float or None
        Robust sizing [-], valid [0.5, 0.999]: size the smallest hull whose probability of
        meeting the operating limits under the Monte Carlo spreads is at least this
        (:func:`aerostat_core.verdict.robust_size`); ``None`` (the default) sizes to the
        design margins alone.
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
        "stability are checked (practice 10 m/s, thesis 15 m/s).", source="aerostat_core.rules")
    survival_wind: float | None = number(
        None, "Survival wind", "m/s", 0, 60, empty="rule set", step=1.0, fmt="%.1f",
        help="Wind the tether must survive aloft (practice 20 m/s, the tactical class); at "
        "least the design wind.", source="aerostat_core.rules")
    blow_by_limit: float | None = number(
        None, "Blow-by limit at the design wind", "m", 0, 3000, lo_open=True,
        hi_field="altitude", empty="rule set", step=5.0, fmt="%.1f",
        help="Largest acceptable downwind offset of the confluence point from the winch "
        "(practice 0.5 x altitude, thesis 0.178 x altitude); at most the altitude.",
        source="aerostat_core.rules")
    altitude_loss_limit: float | None = number(
        None, "Permissible altitude loss", "m", 0, 3000, lo_open=True, empty="rule set",
        step=5.0, fmt="%.1f", help="Largest acceptable loss of height at the design wind "
        "(practice 0.15 x altitude, thesis: off).", source="aerostat_core.rules")
    free_lift_fraction: float | None = number(
        None, "Free lift, share of gross lift", "", 0, 0.8, scale=100.0, display_unit="%",
        empty="rule set", step=1.0, fmt="%.1f",
        help="Free lift at rest the hull must keep (practice 15 %, thesis 1 %).",
        source="aerostat_core.rules")
    min_tether_safety_factor: float | None = number(
        None, "Tether safety factor at the design wind", "", 1, 20, empty="rule set",
        step=0.5, fmt="%.2f", help="Breaking strength / largest tether tension must reach this "
        "(3 in both rule sets).", source="aerostat_core.rules")
    survival_safety_factor: float | None = number(
        None, "Tether safety factor at the survival wind", "", 1, 20, empty="rule set",
        step=0.1, fmt="%.2f", help="Practice 1.5.", source="aerostat_core.rules")
    max_tether_angle_deg: float | None = number(
        None, "Largest tether angle from the vertical", "deg", 0, 90, lo_open=True,
        empty="rule set", step=5.0, fmt="%.0f",
        help="At the design wind (practice 60 deg, thesis 45 deg).", source="aerostat_core.rules")
    weathervane_margin: float | None = number(
        None, "Weathervane stability margin", "1/rad", 0, 1, empty="rule set", step=0.01,
        fmt="%.3f", help="C_m_alpha about the centre of volume must be at most minus this "
        "(practice 0.02, thesis 0).", source="aerostat_core.rules")
    rules: str = choice(
        DEFAULT_RULES, "Rule set", RULE_NAMES, source="aerostat_core.rules",
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
    top_up_interval_days: float | None = number(
        None, "Top-up interval", "day", 0, 365, empty="rule set", step=1.0, fmt="%.1f",
        help="Days between helium top-ups; the free-lift margin must still hold at the end of "
        "one (practice 7 days, thesis 0).", source="aerostat_core.rules")
    confidence: float | None = number(
        None, "Sizing confidence", "", 0.5, 0.999, empty="design margins only", step=0.01,
        fmt="%.3f", help="Size the smallest hull that meets the operating limits with at least "
        "this probability under the model's uncertainties (e.g. 0.95). Empty: size to the "
        "design margins.", source="aerostat_core.verdict")

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
    def days_without_top_up(self) -> float:
        """Days the free-lift margin must last [day]: the longer of ``endurance_days`` and the
        top-up interval (the rule set's when left open)."""
        t = self.top_up_interval_days
        if t is None:
            t = self.rule_set.top_up_interval_days
        return max(float(self.endurance_days), float(t))

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
            "top_up_interval_days": r.top_up_interval_days,
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

    kind: str = choice(
        "helium", "Lifting gas", GAS_KINDS, help="Hydrogen lifts about 8 % more but burns.")
    purity: float = number(
        0.98, "Gas purity", "", 0, 1, lo_open=True, scale=100.0, display_unit="% by volume",
        step=0.5, fmt="%.1f", help="The rest is air. Helium is supplied at about 98 %.")
    superpressure: float = number(
        0.0, "Hull superpressure", "Pa", 0, 5000, step=50.0, fmt="%.0f",
        help="Pressure above ambient (250-400 Pa typical).")
    density_model: str = choice(
        "ideal", "Gas density model", DENSITY_MODELS,
        help="Ideal: gas density from pressure, temperature, purity and superpressure. Fixed: "
        "the thesis' 0.169 kg/m³ for helium.")
    fixed_density: float | None = number(
        None, "Fixed gas density", "kg/m3", 0, 1, lo_open=True, empty="thesis value",
        step=0.001, fmt="%.3f",
        help="Used by the 'fixed' model only: thesis 0.169 (He), 0.085 (H₂).",
        source="thesis §2.2")

    def __post_init__(self) -> None:
        validate(self)

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

    fineness_ratio: float | None = number(
        None, "Fineness ratio l/d", "", _FINENESS_LO, _FINENESS_HI, checked=False, step=0.1,
        fmt="%.2f", help="Design variable 1: hull length / maximum diameter (NPL standard 4.0, "
        "tactical aerostats 2.9-3.1). The valid range depends on the shape: "
        + _FINENESS_RANGES + ".", source="aerostat_core.shapes.SHAPE_INFO")
    nose_fraction: float = number(
        0.432, "Max-diameter station a1/l", "", 0.2, 0.8, step=0.01, fmt="%.3f",
        help="Where the two ellipsoids meet; NPL standard 0.432.")
    volume: float | None = number(
        None, "Hull volume", "m3", 1.0, 1e5, empty="sized", step=10.0, fmt="%.1f",
        help="The thesis baseline is 170 m³; empty sizes the smallest hull that meets every "
        "constraint.")
    shape: str = choice(
        "npl", "Hull shape", SHAPES, source="aerostat_core.shapes",
        help="Envelope profile (Shapes page). Changing it resets l/d to the shape's standard "
        "value; sphere, oblate and Helikite hulls carry no fins.")

    def __post_init__(self) -> None:
        validate(self)  # the shape first: the fineness ratio's range depends on it
        if self.fineness_ratio is None:
            object.__setattr__(self, "fineness_ratio", SHAPE_INFO[self.shape].default_fineness)
        lo, hi = SHAPE_INFO[self.shape].fineness_range
        check(self, "fineness_ratio", lo=lo, hi=hi, reason_suffix=f" for shape {self.shape!r}")


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

    kind: str = choice(
        "uniform", "Wind profile along the tether", WIND_PROFILES,
        help="The sweep speed is the wind at the aerostat; the profile scales it down along "
        "the tether.")
    exponent: float = number(
        1.0 / 7.0, "Power-law exponent", "", 0, 0.6, step=0.01, fmt="%.3f",
        help="Used by the power-law profile (1/7 open land).")
    roughness_length: float = number(
        0.03, "Log-law roughness length", "m", 1e-5, 2, step=0.01, fmt="%.3f",
        help="Used by the log-law profile (0.03 m open land).")

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
        Battery, power-tether, ballonet, envelope and winch technology (aerostat_core.mission).
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
