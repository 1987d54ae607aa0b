"""The design-input form: grouped, labelled widgets with units, one submit per change set.

Pure parts (testable without a running app):

* :data:`FIELDS` - every numeric widget: key, input path, label with unit, display scale, help;
* :func:`widget_values` - inputs dict -> widget values (display units);
* :func:`build_inputs` - widget values + the current inputs -> (Requirement, Configuration), or
  :class:`InputError` naming the group of widgets the problem belongs to;
* :func:`error_group` - which group an engine ``ValueError`` message concerns.

Streamlit parts: :func:`sync_widgets` (before the form renders) and :func:`input_form`.
Inputs the form does not show (e.g. the tether's axial stiffness) are carried over unchanged from
the current inputs, so a JSON file's values are never lost by submitting the form.
"""

from __future__ import annotations

import copy
import math
import re
from collections.abc import Mapping, MutableMapping
from dataclasses import dataclass
from typing import Any

import streamlit as st

from aerostat_core import FABRICS, TETHERS, Configuration, Requirement, budget
from aerostat_core import validation as _validation
from aerostat_core.io import inputs_from_dict
from aerostat_core.rules import RULE_SETS
from aerostat_core.shapes import SHAPE_INFO
from aerostat_core.validation import short

from .state import DESIGN_KEY, init_state, set_current_inputs

CUSTOM = "Custom"
#: Where the last rejected submit's message goes: {"group": str, "text": str}.
ERROR_KEY = "input_error"
#: The inputs dict the widgets were last filled from.
SRC_KEY = "_widgets_src"

GROUPS = {
    "requirement": "Requirement",
    "wind": "Wind and operating limits",
    "gas": "Lifting gas",
    "materials": "Materials",
    "configuration": "Configuration (design variables)",
    "advanced": "Advanced model parameters",
}


class InputError(ValueError):
    """A rejected form input; ``group`` is a key of :data:`GROUPS`, ``key`` the widget's key
    when the problem is one box. The message uses the form's label and unit."""

    def __init__(self, group: str, message: str, key: str | None = None) -> None:
        super().__init__(short(message))
        self.group = group
        self.key = key


@dataclass(frozen=True)
class Field:
    """One numeric widget. ``display = SI value * scale``; ``optional`` allows an empty box
    (``None``: the engine's automatic value)."""

    key: str
    path: str
    label: str
    group: str
    scale: float = 1.0
    step: float = 1.0
    fmt: str = "%.2f"
    help: str = ""
    optional: bool = False
    integer: bool = False


def _F(key, path, label, group, **kw) -> Field:  # noqa: N802 - table constructor
    return Field(key, path, label, group, **kw)


#: Numeric widgets in display order (selects and fabric/tether choices are handled separately).
FIELDS: tuple[Field, ...] = (
    # requirement
    _F(
        "in_payload",
        "requirement.payload_mass",
        "Payload mass [kg]",
        "requirement",
        step=1.0,
        fmt="%.1f",
        help="Mass hung below the hull (camera, radio...). Valid (0, 500] kg.",
    ),
    _F(
        "in_altitude",
        "requirement.altitude",
        "Operating altitude [m]",
        "requirement",
        step=10.0,
        fmt="%.0f",
        help="Height above the launch site; the tether length equals it. Valid 10-3000 m.",
    ),
    _F(
        "in_site",
        "requirement.site_elevation",
        "Site elevation [m above sea level]",
        "requirement",
        step=50.0,
        fmt="%.0f",
        help="Launch-site elevation; air density is taken at site + altitude. Valid -400-5000 m.",
    ),
    _F(
        "in_isa",
        "requirement.isa_offset",
        "Temperature offset from ISA [K]",
        "requirement",
        step=1.0,
        fmt="%.1f",
        help="Hot tropical day about +15 K. Valid -40 to +40 K. Ignored when the site "
        "temperature is given.",
    ),
    _F(
        "in_site_temp",
        "requirement.site_temperature",
        "Temperature at the launch site [°C] (empty = ISA + offset)",
        "requirement",
        step=1.0,
        fmt="%.1f",
        optional=True,
        help="Sets the ISA offset so that the standard lapse rate runs through it. "
        "Valid -60 to 60 °C.",
    ),
    # wind and limits
    _F(
        "in_wind_max",
        "requirement.wind_max",
        "Maximum wind of the sweep [m/s]",
        "wind",
        step=1.0,
        fmt="%.1f",
        help="Performance is computed from 0 to this speed. Valid (0, 40].",
    ),
    _F(
        "in_wind_step",
        "requirement.wind_step",
        "Wind step of the sweep [m/s]",
        "wind",
        step=0.5,
        fmt="%.1f",
        help="Spacing of the wind sweep. Valid 0.1-10 m/s.",
    ),
    _F(
        "in_design_wind",
        "requirement.design_wind",
        "Operational (design) wind [m/s] (empty = rule set)",
        "wind",
        step=1.0,
        fmt="%.1f",
        optional=True,
        help="Wind at which blow-by, altitude loss, tether angle, stall and stability are checked "
        "(practice 10 m/s, thesis 15 m/s). Valid 0-40 m/s.",
    ),
    _F(
        "in_survival_wind",
        "requirement.survival_wind",
        "Survival wind [m/s] (empty = rule set)",
        "wind",
        step=1.0,
        fmt="%.1f",
        optional=True,
        help="Wind the tether must survive aloft (practice 20 m/s, the tactical class). "
        "At least the design wind, at most 60 m/s.",
    ),
    _F(
        "in_blow_by",
        "requirement.blow_by_limit",
        "Blow-by limit at the design wind [m] (empty = rule set)",
        "wind",
        step=5.0,
        fmt="%.1f",
        optional=True,
        help="Largest acceptable downwind offset of the confluence point from the winch "
        "(practice 0.5 x altitude, thesis 0.178 x altitude); must not exceed the altitude.",
    ),
    _F(
        "in_loss_limit",
        "requirement.altitude_loss_limit",
        "Permissible altitude loss [m] (empty = rule set)",
        "wind",
        step=5.0,
        fmt="%.1f",
        optional=True,
        help="Largest acceptable loss of height at the design wind (practice 0.15 x altitude, "
        "thesis: off).",
    ),
    _F(
        "in_free_lift",
        "requirement.free_lift_fraction",
        "Free lift, share of gross lift [%] (empty = rule set)",
        "wind",
        scale=100.0,
        step=1.0,
        fmt="%.1f",
        optional=True,
        help="Free lift at rest the hull must keep (practice 15 %, thesis 1 %). Valid 0-80 %.",
    ),
    _F(
        "in_min_sf",
        "requirement.min_tether_safety_factor",
        "Tether safety factor at the design wind [-] (empty = rule set)",
        "wind",
        step=0.5,
        fmt="%.2f",
        optional=True,
        help="Breaking strength / largest tether tension must reach this (3 in both rule sets). "
        "Valid 1-20.",
    ),
    _F(
        "in_survival_sf",
        "requirement.survival_safety_factor",
        "Tether safety factor at the survival wind [-] (empty = rule set)",
        "wind",
        step=0.1,
        fmt="%.2f",
        optional=True,
        help="Practice 1.5. Valid 1-20.",
    ),
    _F(
        "in_max_angle",
        "requirement.max_tether_angle_deg",
        "Largest tether angle from the vertical [deg] (empty = rule set)",
        "wind",
        step=5.0,
        fmt="%.0f",
        optional=True,
        help="At the design wind (practice 60 deg, thesis 45 deg). Valid (0, 90].",
    ),
    _F(
        "in_wv_margin",
        "requirement.weathervane_margin",
        "Weathervane stability margin [1/rad] (empty = rule set)",
        "wind",
        step=0.01,
        fmt="%.3f",
        optional=True,
        help="C_m_alpha about the centre of volume must be at most minus this (practice 0.02, "
        "thesis 0). Valid 0-1.",
    ),
    # gas
    _F(
        "in_purity",
        "configuration.gas.purity",
        "Gas purity [% by volume]",
        "gas",
        scale=100.0,
        step=0.5,
        fmt="%.1f",
        help="The rest is air. Helium is supplied at about 98 %.",
    ),
    _F(
        "in_superpressure",
        "configuration.gas.superpressure",
        "Hull superpressure [Pa]",
        "gas",
        step=50.0,
        fmt="%.0f",
        help="Pressure above ambient (250-400 Pa typical). Valid 0-5000.",
    ),
    _F(
        "in_fixed_density",
        "configuration.gas.fixed_density",
        "Fixed gas density [kg/m³] (empty = thesis value)",
        "gas",
        step=0.001,
        fmt="%.3f",
        optional=True,
        help="Used by the 'fixed' model only: thesis 0.169 (He), 0.085 (H₂).",
    ),
    _F(
        "in_gas_price",
        "configuration.gas_price",
        "Gas price [USD/m³] (empty = default)",
        "gas",
        step=1.0,
        fmt="%.2f",
        optional=True,
        help="Fill cost per cubic metre. Default helium 38.5 USD/m³ (thesis App. H).",
    ),
    # materials (custom values; used when 'Custom' is chosen)
    _F(
        "in_hull_gsm",
        "configuration.hull_fabric.areal_density",
        "Custom hull fabric [g/m²]",
        "materials",
        scale=1000.0,
        step=10.0,
        fmt="%.0f",
        help="Used when the hull fabric is 'Custom'. Thesis fabric 130 g/m².",
    ),
    _F(
        "in_fin_gsm",
        "configuration.fin_fabric.areal_density",
        "Custom fin fabric [g/m²]",
        "materials",
        scale=1000.0,
        step=10.0,
        fmt="%.0f",
        help="Used when the fin fabric is 'Custom'.",
    ),
    _F(
        "in_tether_lin",
        "configuration.tether.linear_density",
        "Custom tether linear density [g/m]",
        "materials",
        scale=1000.0,
        step=1.0,
        fmt="%.1f",
        help="Used when the tether is 'Custom'. Thesis 20 g/m (6 kg per 300 m).",
    ),
    _F(
        "in_tether_dia",
        "configuration.tether.diameter",
        "Custom tether diameter [mm]",
        "materials",
        scale=1000.0,
        step=0.5,
        fmt="%.1f",
        help="Used when the tether is 'Custom'; sets the tether drag.",
    ),
    _F(
        "in_tether_mbl",
        "configuration.tether.breaking_strength",
        "Custom tether breaking strength [kN]",
        "materials",
        scale=1e-3,
        step=1.0,
        fmt="%.2f",
        help="Used when the tether is 'Custom'.",
    ),
    _F(
        "in_tether_cd",
        "configuration.tether.normal_drag_coefficient",
        "Custom tether drag coefficient [-]",
        "materials",
        step=0.1,
        fmt="%.2f",
        help="Cross-flow drag coefficient of the cable (round cable 1.0-1.2).",
    ),
    # configuration
    _F(
        "in_volume",
        "configuration.hull.volume",
        "Hull volume [m³] (when given)",
        "configuration",
        step=10.0,
        fmt="%.1f",
        help="Used when the volume is 'Given'; the thesis baseline is 170 m³.",
    ),
    _F(
        "in_fineness",
        "configuration.hull.fineness_ratio",
        "Fineness ratio l/d [-]",
        "configuration",
        step=0.1,
        fmt="%.2f",
        help="Design variable 1: hull length / maximum diameter (NPL standard 4.0, tactical "
        "aerostats 2.9-3.1). Valid range per shape: NPL 1.5-8, GNVR/Wang/Zhiyuan-1/Lotte 2-6, "
        "sphere 1, oblate 0.5-0.95, Helikite 1-1.6.",
    ),
    _F(
        "in_fin_area",
        "configuration.fins.area_change",
        "Fin area change ΔS_f [%]",
        "configuration",
        step=5.0,
        fmt="%.1f",
        help="Design variable 2: change of the fin area from the statistical size. "
        "Valid -50 to +200 %.",
    ),
    _F(
        "in_fin_pos",
        "configuration.fins.position",
        "Fin position Δl_f [% of hull length]",
        "configuration",
        scale=100.0,
        step=1.0,
        fmt="%.1f",
        help="Design variable 3: station of the fin root leading edge from the nose. "
        "Valid 40-95 %; the trailing edge must stay on the hull.",
    ),
    _F(
        "in_nose",
        "configuration.hull.nose_fraction",
        "Max-diameter station a1/l [-]",
        "configuration",
        step=0.01,
        fmt="%.3f",
        help="Where the two ellipsoids meet; NPL standard 0.432. Valid 0.2-0.8.",
    ),
    # advanced
    _F(
        "in_fin_ratio",
        "configuration.fins.area_ratio",
        "Fin area / hull area [-]",
        "advanced",
        step=0.01,
        fmt="%.3f",
        help="Statistical fin size (thesis preset 0.227, calibrated).",
    ),
    _F(
        "in_fin_ar",
        "configuration.fins.aspect_ratio",
        "Fin pair aspect ratio [-]",
        "advanced",
        step=0.1,
        fmt="%.2f",
        help="Opposite pair as one wing: 2 S_p²/S_1. Valid 0.5-6.",
    ),
    _F(
        "in_fin_taper",
        "configuration.fins.taper_ratio",
        "Fin taper ratio [-]",
        "advanced",
        step=0.05,
        fmt="%.2f",
        help="Tip chord / root chord. Valid 0.1-1.",
    ),
    _F(
        "in_fin_fabric_factor",
        "configuration.fins.fabric_factor",
        "Fin fabric / planform area [-]",
        "advanced",
        step=0.1,
        fmt="%.2f",
        help="Two faces plus ribs and seams. Valid 1-4.",
    ),
    _F(
        "in_misc",
        "configuration.misc_mass_ratio",
        "Miscellaneous mass / hull mass [-]",
        "advanced",
        step=0.05,
        fmt="%.2f",
        help="Confluence lines, patches, valves (thesis Table 2.2: 0.30). Valid 0-2.",
    ),
    _F(
        "in_eta_k",
        "configuration.aero.hull_efficiency",
        "Hull efficiency η_k [-]",
        "advanced",
        step=0.01,
        fmt="%.2f",
        help="Jones & DeLaurier potential-flow factor (1.19).",
    ),
    _F(
        "in_cdc",
        "configuration.aero.hull_crossflow_drag",
        "Hull cross-flow drag (C_dc)_h [-]",
        "advanced",
        step=0.01,
        fmt="%.2f",
        help="Viscous cross-flow drag coefficient (0.32).",
    ),
    _F(
        "in_cdv",
        "configuration.aero.hull_axial_drag",
        "Hull drag C_DV [-] (empty = Hoerner)",
        "advanced",
        step=0.001,
        fmt="%.4f",
        optional=True,
        help="Zero-α hull drag on V^(2/3); empty uses Hoerner's C_DV(f, Re).",
    ),
    _F(
        "in_eta_f",
        "configuration.aero.fin_efficiency",
        "Fin efficiency η_f [-]",
        "advanced",
        step=0.05,
        fmt="%.2f",
        help="Factor on the 3-D fin lift slope (1.0). Valid 0-1.5.",
    ),
    _F(
        "in_cla",
        "configuration.aero.section_lift_slope",
        "Fin section lift slope [1/rad]",
        "advanced",
        step=0.1,
        fmt="%.3f",
        help="Thin-aerofoil value 2π = 6.283.",
    ),
    _F(
        "in_cd0_fin",
        "configuration.aero.fin_zero_lift_drag",
        "Fin zero-lift drag C_D0 [-]",
        "advanced",
        step=0.001,
        fmt="%.4f",
        help="On fin planform area (0.003-0.010).",
    ),
    _F(
        "in_stall",
        "configuration.aero.fin_stall_angle_deg",
        "Fin stall angle [deg]",
        "advanced",
        step=1.0,
        fmt="%.1f",
        help="Trim beyond it is flagged. Valid 5-40 deg.",
    ),
    _F(
        "in_drop",
        "configuration.confluence.drop_ratio",
        "Confluence point below hull / diameter [-]",
        "advanced",
        step=0.05,
        fmt="%.2f",
        help="Not given in the thesis; 0.6 is an engineering guess. Valid 0.05-3.",
    ),
    _F(
        "in_xi_off",
        "configuration.confluence.xi_offset",
        "Confluence station offset / length [-]",
        "advanced",
        step=0.01,
        fmt="%.3f",
        help="Shift aft (+) from below the centre of net static lift. Valid -0.2 to 0.2.",
    ),
    _F(
        "in_wind_exp",
        "configuration.wind_profile.exponent",
        "Power-law exponent [-]",
        "advanced",
        step=0.01,
        fmt="%.3f",
        help="Used by the power-law profile (1/7 open land).",
    ),
    _F(
        "in_z0",
        "configuration.wind_profile.roughness_length",
        "Log-law roughness length [m]",
        "advanced",
        step=0.01,
        fmt="%.3f",
        help="Used by the log-law profile (0.03 m open land).",
    ),
    _F(
        "in_segments",
        "configuration.tether_segments",
        "Tether segments [-]",
        "advanced",
        step=10,
        fmt="%d",
        integer=True,
        help="Segments of the static tether march (50 is within 1 mm of 2000). Valid 10-5000.",
    ),
)

FIELD_BY_KEY = {f.key: f for f in FIELDS}

#: Choice widgets: key -> (path, label, options {value: shown text}, group, help).
CHOICES: dict[str, tuple[str, str, dict[str, str], str, str]] = {
    "in_rules": (
        "requirement.rules",
        "Rule set",
        {name: r.title for name, r in RULE_SETS.items()},
        "requirement",
        "Where the limits left empty come from: 'practice' for real missions (free lift 15 % "
        "of gross lift, limits scaled to the tether length), 'thesis' for the calibrated preset "
        "of Mahmood (2020). Method page: sources of every value.",
    ),
    "in_shape": (
        "configuration.hull.shape",
        "Hull shape",
        {k: v.label for k, v in SHAPE_INFO.items()},
        "configuration",
        "Envelope profile (Shapes page). Changing it resets l/d to the shape's standard value; "
        "sphere, oblate and Helikite hulls carry no fins.",
    ),
    "in_gas_kind": (
        "configuration.gas.kind",
        "Lifting gas",
        {"helium": "Helium", "hydrogen": "Hydrogen"},
        "gas",
        "Hydrogen lifts about 8 % more but burns.",
    ),
    "in_density_model": (
        "configuration.gas.density_model",
        "Gas density model",
        {"ideal": "Ideal gas at altitude (physics)", "fixed": "Fixed density (thesis constants)"},
        "gas",
        "Ideal: gas density from pressure, temperature, purity and "
        "superpressure. Fixed: the thesis' 0.169 kg/m³ for helium.",
    ),
    "in_arrangement": (
        "configuration.fins.arrangement",
        "Fin arrangement",
        {"+": "4 fins, + (cross)", "x": "4 fins, x", "inverted-y": "3 fins, inverted Y"},
        "configuration",
        "Number and layout of the tail fins.",
    ),
    "in_cutoff": (
        "configuration.aero.cutoff",
        "Potential-flow cut-off station l_h",
        {"fin": "At the fin root (thesis symbol list)", "tail": "At the tail"},
        "advanced",
        "Station where the Jones & DeLaurier potential-flow term stops.",
    ),
    "in_wind_kind": (
        "configuration.wind_profile.kind",
        "Wind profile along the tether",
        {"uniform": "Uniform (thesis plots)", "power": "Power law", "log": "Log law"},
        "advanced",
        "The sweep speed is the wind at the aerostat; the profile scales it down along the tether.",
    ),
}

VOLUME_MODE_KEY = "in_volume_mode"
VOLUME_MODES = {"given": "Given", "sized": "Sized: smallest hull meeting every constraint"}
HULL_FABRIC_KEY, FIN_FABRIC_KEY, TETHER_KEY = "in_hull_fabric", "in_fin_fabric", "in_tether"
SUBMIT_KEY = "in_submit"

WIDGET_KEYS: tuple[str, ...] = (
    *FIELD_BY_KEY,
    *CHOICES,
    VOLUME_MODE_KEY,
    HULL_FABRIC_KEY,
    FIN_FABRIC_KEY,
    TETHER_KEY,
)

#: Engine class (and optional field) -> widget group, for placing an error message.
_CLASS_GROUP = {
    "LiftingGas": "gas",
    "Fabric": "materials",
    "TetherSpec": "materials",
    "HullSpec": "configuration",
    "AeroModel": "advanced",
    "ConfluenceSpec": "advanced",
    "WindProfile": "advanced",
}
_FIELD_GROUP = {
    "Requirement.payload_mass": "requirement",
    "Requirement.altitude": "requirement",
    "Requirement.site_elevation": "requirement",
    "Requirement.isa_offset": "requirement",
    "Requirement.site_temperature": "requirement",
    "Requirement.rules": "requirement",
    "Configuration.gas_price": "gas",
    "Configuration.misc_mass_ratio": "advanced",
    "Configuration.tether_segments": "advanced",
    "FinSpec.count": "configuration",
    "FinSpec.arrangement": "configuration",
    "FinSpec.area_change": "configuration",
    "FinSpec.position": "configuration",
}
_ERR_RE = re.compile(r"([A-Za-z]+)\.([a-z_]+)")


def error_group(message: str) -> str:
    """The widget group an engine message concerns ("Requirement.altitude = ..." ->
    "requirement"); "general" when it names no known field.

    >>> error_group("Requirement.blow_by_limit = 400 m is outside the valid range (0, 300] m")
    'wind'
    >>> error_group("FinSpec.aspect_ratio = 9 is outside the valid range [0.5, 6]")
    'advanced'
    >>> error_group("something else")
    'general'
    """
    m = _ERR_RE.search(message)
    if not m:
        return "general"
    cls, field = m.group(1), m.group(2)
    if f"{cls}.{field}" in _FIELD_GROUP:
        return _FIELD_GROUP[f"{cls}.{field}"]
    if cls == "Requirement":
        return "wind"
    if cls == "FinSpec":
        return "advanced"
    return _CLASS_GROUP.get(cls, "general")


# --- pure conversions ---------------------------------------------------------------------------


def _clean(x: float) -> float:
    """Round to 12 significant digits so that 0.68 -> 68 % -> 0.68 round-trips exactly."""
    return float(f"{x:.12g}")


def format_value(x: Any, integer: bool = False) -> str:
    """A number as the text of its box: integers without a decimal point, floats with up to 12
    significant digits and no trailing zeros; ``None`` as an empty box.

    >>> format_value(68.0), format_value(0.432), format_value(50, integer=True), format_value(None)
    ('68', '0.432', '50', '')
    """
    if x is None:
        return ""
    if integer:
        return str(int(x))
    text = f"{_clean(float(x)):.12g}"
    return "0" if text == "-0" else text


_NUMBER_RE = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def parse_number(text: Any, f: Field) -> float | int | None:
    """The number typed in the box of field ``f``, or ``None`` for an empty optional box.

    A decimal comma is read as a decimal point ("12,5" is 12.5, never 125); text with both a
    comma and a point, or several commas, is refused as ambiguous (no thousands separators).
    Raises :class:`InputError` with the field's label; an empty required box says "required".
    """
    if isinstance(text, (int, float)) and not isinstance(text, bool):
        value = float(text)  # a number set programmatically (tests, older session state)
        raw = format_value(value)
    else:
        raw = "" if text is None else str(text).strip().replace("\u2212", "-")
        if not raw:
            if f.optional:
                return None
            raise InputError(f.group, f"{f.label}: required; enter a value.", f.key)
        shown = short(raw, 30)
        if raw.count(",") > 1 or ("," in raw and "." in raw):
            raise InputError(
                f.group,
                f"{f.label}: “{shown}” is ambiguous. Use one decimal point or one decimal comma, "
                "without thousands separators.",
                f.key,
            )
        candidate = raw.replace(",", ".")
        if not _NUMBER_RE.match(candidate):
            raise InputError(f.group, f"{f.label}: “{shown}” is not a number.", f.key)
        value = float(candidate)
    if not math.isfinite(value):
        raise InputError(f.group, f"{f.label}: “{short(raw, 30)}” is too large.", f.key)
    if f.integer:
        if value != int(value):
            raise InputError(f.group, f"{f.label}: {raw} is not a whole number.", f.key)
        return int(value)
    return value


def _get(d: Mapping[str, Any], path: str) -> Any:
    obj: Any = d
    for part in path.split("."):
        if not isinstance(obj, Mapping) or part not in obj:
            return None
        obj = obj[part]
    return obj


def _set(d: MutableMapping[str, Any], path: str, value: Any) -> None:
    parts = path.split(".")
    obj = d
    for part in parts[:-1]:
        obj = obj.setdefault(part, {})
    obj[parts[-1]] = value


def _catalogue_name(current: Mapping[str, Any] | None, catalogue: Mapping[str, Any]) -> str:
    """The catalogue entry equal to ``current`` (an inputs sub-dict), else "Custom"."""
    if isinstance(current, Mapping):
        name = current.get("name")
        if name in catalogue:
            entry = inputs_to_dict_part(catalogue[name])
            if all(current.get(k) == v for k, v in entry.items()):
                return str(name)
    return CUSTOM


def inputs_to_dict_part(obj: Any) -> dict[str, Any]:
    """A catalogue item (Fabric/TetherSpec) as the plain dict used in inputs dicts."""
    from dataclasses import fields

    out = {}
    for f in fields(obj):
        v = getattr(obj, f.name)
        out[f.name] = "inf" if isinstance(v, float) and v == float("inf") else v
    return out


def widget_values(
    inputs: Mapping[str, Any], previous: Mapping[str, Any] | None = None
) -> dict[str, Any]:
    """Widget values (the text of each box, in display units) that show ``inputs``;
    ``previous`` widget values fill the boxes the inputs leave open (the given-volume box while
    the volume is sized)."""
    previous = previous or {}
    out: dict[str, Any] = {}
    for f in FIELDS:
        v = _get(inputs, f.path)
        if v is None or isinstance(v, str):
            if f.optional:
                out[f.key] = ""
                continue
            prev = previous.get(f.key)
            out[f.key] = (
                prev
                if isinstance(prev, str) and prev.strip()
                else ("170" if f.key == "in_volume" else "")
            )
            continue
        out[f.key] = format_value(int(v) if f.integer else float(v) * f.scale, f.integer)
    for key, (path, _label, options, _g, _h) in CHOICES.items():
        v = _get(inputs, path)
        out[key] = v if v in options else next(iter(options))
    vol = _get(inputs, "configuration.hull.volume")
    out[VOLUME_MODE_KEY] = "sized" if vol is None else "given"
    cfg = inputs.get("configuration", {}) if isinstance(inputs, Mapping) else {}
    out[HULL_FABRIC_KEY] = _catalogue_name(cfg.get("hull_fabric"), FABRICS)
    out[FIN_FABRIC_KEY] = _catalogue_name(cfg.get("fin_fabric"), FABRICS)
    out[TETHER_KEY] = _catalogue_name(cfg.get("tether"), TETHERS)
    return out


def build_inputs(
    values: Mapping[str, Any], base: Mapping[str, Any]
) -> tuple[Requirement, Configuration]:
    """Validated (Requirement, Configuration) from widget ``values``; anything the widgets do not
    cover is taken from ``base`` (the current inputs dict). Raises :class:`InputError`."""
    d = copy.deepcopy(dict(base))
    d.pop("name", None)
    shown = widget_values(base)
    for f in FIELDS:
        if f.key not in values:
            continue
        v = values[f.key]
        if _same_text(v, shown.get(f.key)) and _get(base, f.path) is not None:
            continue  # untouched: keep the exact value (no rounding drift through the display)
        if f.key == "in_volume":
            continue  # handled with the volume mode below
        if f.key in ("in_hull_gsm", "in_fin_gsm") or f.key.startswith("in_tether_"):
            continue  # handled with the material choice below
        x = parse_number(v, f)
        if x is None:
            _set(d, f.path, None)
            continue
        _set(d, f.path, x if f.integer else _clean(x / f.scale))
    for key, (path, _label, _options, _g, _h) in CHOICES.items():
        if key in values:
            _set(d, path, values[key])
    if _get(d, "configuration.hull.shape") != (_get(base, "configuration.hull.shape") or "npl") \
            and values.get("in_fineness") == shown.get("in_fineness"):
        _set(d, "configuration.hull.fineness_ratio", None)  # the new shape's standard l/d
    arrangement = _get(d, "configuration.fins.arrangement")
    _set(d, "configuration.fins.count", 3 if arrangement == "inverted-y" else 4)
    # volume
    if values.get(VOLUME_MODE_KEY, "given") == "sized":
        _set(d, "configuration.hull.volume", None)
    elif "in_volume" in values:
        v = values["in_volume"]
        if v is None or (isinstance(v, str) and not v.strip()):
            raise InputError(
                "configuration",
                "Hull volume [m³] (when given): required; enter a value or choose 'Sized'.",
                "in_volume",
            )
        if (
            not _same_text(v, shown.get("in_volume"))
            or _get(base, "configuration.hull.volume") is None
        ):
            _set(d, "configuration.hull.volume", _clean(parse_number(v, FIELD_BY_KEY["in_volume"])))
    # materials
    for sel_key, gsm_key, part in (
        (HULL_FABRIC_KEY, "in_hull_gsm", "hull_fabric"),
        (FIN_FABRIC_KEY, "in_fin_gsm", "fin_fabric"),
    ):
        choice = values.get(sel_key)
        if choice is None:
            continue
        if choice != CUSTOM:
            if choice not in FABRICS:
                raise InputError("materials", f"Unknown fabric {choice!r}.")
            _set(d, f"configuration.{part}", inputs_to_dict_part(FABRICS[choice]))
            continue
        gsm = parse_number(values.get(gsm_key), FIELD_BY_KEY[gsm_key])
        old = _get(d, f"configuration.{part}") or {}
        areal = _clean(float(gsm) / 1000.0)
        name = (
            old.get("name")
            if (old.get("areal_density") == areal and old.get("name") not in FABRICS)
            else f"Custom {gsm:g} g/m2"
        )
        _set(d, f"configuration.{part}", {"name": name, "areal_density": areal})
    choice = values.get(TETHER_KEY)
    if choice is not None:
        if choice != CUSTOM:
            if choice not in TETHERS:
                raise InputError("materials", f"Unknown tether {choice!r}.")
            _set(d, "configuration.tether", inputs_to_dict_part(TETHERS[choice]))
        else:
            old = dict(_get(d, "configuration.tether") or {})
            new = dict(old)
            for key in ("in_tether_lin", "in_tether_dia", "in_tether_mbl", "in_tether_cd"):
                f = FIELD_BY_KEY[key]
                if (
                    _same_text(values.get(key), shown.get(key))
                    and old.get(f.path.rsplit(".", 1)[1]) is not None
                ):
                    continue
                new[f.path.rsplit(".", 1)[1]] = _clean(parse_number(values.get(key), f) / f.scale)
            if new != old or old.get("name") in TETHERS or not old.get("name"):
                new["name"] = f"Custom tether {new['linear_density'] * 1000:g} g/m"
            _set(d, "configuration.tether", new)
    try:
        req, cfg = inputs_from_dict(d)
    except _validation.InputError as exc:
        raise form_error(exc) from None
    except ValueError as exc:
        msg = str(exc)
        raise InputError(error_group(msg), humanise(msg)) from None
    try:
        budget.check_design(req, cfg)
    except budget.BudgetError as exc:
        raise InputError("advanced", str(exc), "in_segments") from None
    return req, cfg


def _same_text(a: Any, b: Any) -> bool:
    """Whether two box values show the same thing ("68" and 68.0 do)."""
    if isinstance(a, str) and isinstance(b, str):
        return a.strip() == b.strip()
    try:
        return float(a) == float(b)
    except (TypeError, ValueError):
        return a == b


#: Path prefix of each engine class in an inputs dict (for mapping its errors to form fields).
_OWNER_PATH = {
    "Requirement": "requirement",
    "Configuration": "configuration",
    "LiftingGas": "configuration.gas",
    "HullSpec": "configuration.hull",
    "FinSpec": "configuration.fins",
    "AeroModel": "configuration.aero",
    "ConfluenceSpec": "configuration.confluence",
    "WindProfile": "configuration.wind_profile",
    "TetherSpec": "configuration.tether",
    "Fabric": "configuration.hull_fabric",
}


def _field_for(owner: str, field: str) -> Field | None:
    prefix = _OWNER_PATH.get(owner)
    if prefix is None:
        return None
    path = f"{prefix}.{field}"
    return next((f for f in FIELDS if f.path == path), None)


def _range_words(lo: float, hi: float, lo_open: bool, hi_open: bool) -> str:
    lo_t, hi_t = format_value(lo), format_value(hi)
    if lo_open and hi_open:
        return f"more than {lo_t} and less than {hi_t}"
    if lo_open:
        return f"more than {lo_t} and at most {hi_t}"
    if hi_open:
        return f"at least {lo_t} and less than {hi_t}"
    return f"between {lo_t} and {hi_t}"


def form_error(exc: _validation.InputError) -> InputError:
    """An engine :class:`aerostat_core.validation.InputError` in the form's words: its label and
    display unit (e.g. % of hull length for the fin position), the value as typed, the range.

    >>> from aerostat_core import Requirement
    >>> try:
    ...     Requirement(payload_mass=-5)
    ... except ValueError as e:
    ...     print(form_error(e))
    Payload mass [kg]: -5 is not allowed; it must be more than 0 and at most 500.
    """
    f = _field_for(exc.owner, exc.field)
    if f is None:
        msg = humanise(str(exc))
        return InputError(error_group(str(exc)), msg)
    if exc.lo is not None and exc.hi is not None and isinstance(exc.value, (int, float)):
        value = format_value(float(exc.value) * f.scale, f.integer)
        rng = _range_words(exc.lo * f.scale, exc.hi * f.scale, exc.lo_open, exc.hi_open)
        if "too small" in exc.reason:
            return InputError(f.group, f"{f.label}: {value} is too small to compute with.", f.key)
        where = exc.reason[exc.reason.find(" for shape"):] if " for shape" in exc.reason else ""
        return InputError(
            f.group, f"{f.label}: {value} is not allowed; it must be {rng}{where}.", f.key
        )
    return InputError(f.group, f"{f.label}: {humanise(exc.reason)}.", f.key)


_NAME_RE = re.compile(r"\b([A-Z][A-Za-z]+)\.([a-z_]+)\b")


def humanise(message: str) -> str:
    """Replace the engine's internal ``Class.field`` names in a message by the form's labels.

    >>> humanise("Requirement.altitude = 4000 m with site_elevation = 8000 m puts ...")
    'Operating altitude [m] = 4000 m with site_elevation = 8000 m puts ...'
    """

    def label(m: re.Match) -> str:
        f = _field_for(m.group(1), m.group(2))
        return f.label if f is not None else m.group(0)

    return short(_NAME_RE.sub(label, message))


# --- Streamlit side -----------------------------------------------------------------------------

_MD_SPECIAL = re.compile(r"([!-/:-@\[-`{-~])")


def plain(text: Any) -> str:
    """User text (case and file names, messages quoting them) for Streamlit's Markdown
    elements, shown exactly as typed: every ASCII punctuation character is backslash-escaped
    (CommonMark), so ``![i](http://...)`` is text, not an image the browser would fetch, and
    ``:red[x]`` or ``$x$`` are not directives.
    """
    return _MD_SPECIAL.sub(r"\\\1", str(text))


def signed(x: float, digits: int = 1) -> str:
    """``x`` with its sign, rounded, never "-0.0" (a delta that rounds to zero is "0.0").

    >>> signed(-0.04), signed(2.345, 2), signed(-3.0), signed(0.0)
    ('0.0', '+2.35', '-3.0', '0.0')
    """
    r = round(float(x), digits)
    if r == 0:
        return f"{0:.{digits}f}"
    return f"{r:+.{digits}f}"


def speed_ranges(speeds: Any, step: float | None = None) -> str:
    """Wind speeds as ranges: consecutive sweep points (``step`` apart, or the smallest gap)
    collapse into "a–b".

    >>> speed_ranges([0, 1, 2, 3, 7, 8, 9, 12])
    '0–3, 7–9, 12'
    >>> speed_ranges([0.5, 1.0, 1.5, 4.0], 0.5)
    '0.5–1.5, 4'
    """
    v = sorted({float(s) for s in speeds})
    if not v:
        return ""
    if step is None:
        gaps = [b - a for a, b in zip(v, v[1:])]
        step = min(gaps) if gaps else 1.0
    parts, start, prev = [], v[0], v[0]
    for s in v[1:]:
        if s - prev > 1.5 * step:
            parts.append(f"{start:g}" if start == prev else f"{start:g}–{prev:g}")
            start = s
        prev = s
    parts.append(f"{start:g}" if start == prev else f"{start:g}–{prev:g}")
    return ", ".join(parts)


class _MetricSlot:
    """One place in a :func:`metric_row`: ``.metric(...)`` sized to its content."""

    def __init__(self, row: Any) -> None:
        self._row = row

    def metric(self, *args: Any, **kwargs: Any) -> Any:
        kwargs.setdefault("width", "content")
        return self._row.metric(*args, **kwargs)


def metric_row(n: int) -> list[_MetricSlot]:
    """``n`` places for headline numbers, used like ``st.columns(n)``: a wrapping horizontal
    row whose metrics take the width of their label and value, so a narrow window moves a
    metric to the next line instead of cutting it to "1…" (fixed columns did at 1024 px)."""
    row = st.container(horizontal=True, wrap=True, gap="large")
    return [_MetricSlot(row)] * n


def feedback(level: str, text: str) -> None:
    """Show a message (level "success", "info", "warning" or anything else for an error) as
    plain text (see :func:`plain`)."""
    show = {"success": st.success, "info": st.info, "warning": st.warning}.get(level, st.error)
    show(plain(text))


def sync_widgets(state: MutableMapping[str, Any] | None = None, *, force: bool = False) -> None:
    """Fill the form's widgets from the current inputs when those changed elsewhere (baseline
    button, file import, another page) or when a widget value is missing. Call before the form
    renders, or from a callback."""
    s = st.session_state if state is None else state
    init_state(s)
    inputs = s[DESIGN_KEY]
    missing = any(k not in s for k in WIDGET_KEYS)
    if force or missing or s.get(SRC_KEY) != inputs:
        previous = {k: s[k] for k in WIDGET_KEYS if k in s}
        for k, v in widget_values(inputs, previous).items():
            s[k] = v
        s[SRC_KEY] = copy.deepcopy(inputs)


def _on_submit() -> None:
    s = st.session_state
    values = {k: s[k] for k in WIDGET_KEYS if k in s}
    try:
        req, cfg = build_inputs(values, s[DESIGN_KEY])
    except InputError as exc:
        s[ERROR_KEY] = {"group": exc.group, "text": str(exc), "key": exc.key}
        return
    s.pop(ERROR_KEY, None)
    set_current_inputs(req, cfg, s)  # written through to the workspace store
    sync_widgets(s, force=True)  # show the canonical values (catalogue materials, rounding)


def _group_error(group: str) -> None:
    err = st.session_state.get(ERROR_KEY)
    if err and err.get("group") == group:
        st.error(plain(f"Not applied: {err['text']}"), icon=":material/error:")


def _number(f: Field) -> None:
    # A text box, parsed by parse_number: the browser's number box read "12,5" as 125 and showed
    # an emptied box as 0.
    st.text_input(
        f.label,
        key=f.key,
        help=f.help,
        placeholder="auto" if f.optional else "required",
        persist_state="session",
    )


def _choice(key: str, horizontal: bool = False) -> None:
    path, label, options, _g, help_ = CHOICES[key]
    if len(options) <= 3 and horizontal:
        st.radio(
            label,
            list(options),
            format_func=options.get,
            key=key,
            help=help_,
            horizontal=True,
            persist_state="session",
        )
    else:
        st.selectbox(
            label,
            list(options),
            format_func=options.get,
            key=key,
            help=help_,
            persist_state="session",
        )


#: Form layout: group -> widgets in order (field keys, choice keys, or the special keys).
LAYOUT: dict[str, tuple[str, ...]] = {
    "requirement": ("in_rules", "in_payload", "in_altitude", "in_site", "in_isa", "in_site_temp"),
    "wind": (
        "in_design_wind",
        "in_survival_wind",
        "in_blow_by",
        "in_loss_limit",
        "in_free_lift",
        "in_min_sf",
        "in_survival_sf",
        "in_max_angle",
        "in_wv_margin",
        "in_wind_max",
        "in_wind_step",
    ),
    "configuration": (
        "in_shape",
        VOLUME_MODE_KEY,
        "in_volume",
        "in_fineness",
        "in_fin_area",
        "in_fin_pos",
        "in_arrangement",
        "in_nose",
    ),
    "gas": (
        "in_gas_kind",
        "in_density_model",
        "in_purity",
        "in_superpressure",
        "in_fixed_density",
        "in_gas_price",
    ),
    "materials": (
        HULL_FABRIC_KEY,
        "in_hull_gsm",
        FIN_FABRIC_KEY,
        "in_fin_gsm",
        TETHER_KEY,
        "in_tether_lin",
        "in_tether_dia",
        "in_tether_mbl",
        "in_tether_cd",
    ),
    "advanced": ("in_cutoff", "in_wind_kind", *(f.key for f in FIELDS if f.group == "advanced")),
}
_GROUP_ICONS = {
    "requirement": ":material/flag:",
    "wind": ":material/air:",
    "configuration": ":material/tune:",
    "gas": ":material/bubble_chart:",
    "materials": ":material/layers:",
    "advanced": ":material/science:",
}
_EXPANDED = {"requirement", "wind", "configuration"}


def _widget(key: str) -> None:
    if key in FIELD_BY_KEY:
        _number(FIELD_BY_KEY[key])
    elif key in CHOICES:
        _choice(key)
    elif key == VOLUME_MODE_KEY:
        st.radio(
            "Hull volume",
            list(VOLUME_MODES),
            format_func=VOLUME_MODES.get,
            key=VOLUME_MODE_KEY,
            persist_state="session",
            help="Given: use the volume below. Sized: the smallest hull that meets the "
            "blow-by limit at the design wind with positive free lift.",
        )
    elif key in (HULL_FABRIC_KEY, FIN_FABRIC_KEY):
        what = "Hull" if key == HULL_FABRIC_KEY else "Fin"
        st.selectbox(
            f"{what} fabric",
            [*FABRICS, CUSTOM],
            key=key,
            persist_state="session",
            help="Catalogue fabric (areal density in the name), or 'Custom' to use "
            "the value below.",
        )
    elif key == TETHER_KEY:
        st.selectbox(
            "Tether",
            [*TETHERS, CUSTOM],
            key=TETHER_KEY,
            persist_state="session",
            help="Catalogue tether, or 'Custom' to use the values below.",
        )


def _submit_button(key: str) -> None:
    st.form_submit_button(
        "Update design",
        type="primary",
        on_click=_on_submit,
        key=key,
        icon=":material/refresh:",
        width="stretch",
    )


def input_form() -> None:
    """The grouped design-input form (one rerun per submit); an input the engine rejects is
    reported inside its group and nothing is applied. The submit button comes first, so it is
    in sight without scrolling, and again after the last group."""
    sync_widgets()
    err = st.session_state.get(ERROR_KEY)
    with st.form("design_inputs_form", border=False, enter_to_submit=False):
        _submit_button(SUBMIT_KEY)
        with st.container():  # always present: the groups below keep their place
            if err and err.get("group") == "general":
                st.error(plain(f"Not applied: {err['text']}"), icon=":material/error:")
            elif err:
                st.warning(
                    plain(f"Inputs not applied: see {GROUPS.get(err['group'], '')} below."),
                    icon=":material/warning:",
                )
        for group, keys in LAYOUT.items():
            has_error = bool(err and err.get("group") == group)
            with st.expander(
                GROUPS[group], expanded=group in _EXPANDED or has_error, icon=_GROUP_ICONS[group]
            ):
                with st.container():
                    _group_error(group)
                if group == "advanced":
                    st.caption("Model coefficients with documented defaults (Method page).")
                if group == "materials":
                    st.caption("The custom values are used when 'Custom' is chosen above them.")
                for key in keys:
                    _widget(key)
        _submit_button(SUBMIT_KEY + "_bottom")


def constraint_table_rows(rows: list[dict]) -> list[dict]:
    """Display rows of the constraint table (aerostat_core.constraints via the design report):
    label, where checked, value, limit and margin with the unit (4 significant digits; an
    unbounded margin shows as a dash), and met."""

    def fmt(x: float) -> str:
        if x != x or abs(x) == float("inf"):
            return "–"
        text = f"{x:.4g}"
        return "0" if text == "-0" else text

    return [
        {
            "Constraint": r["label"],
            "Checked at": r["checked_at"],
            "Value": fmt(r["value"]),
            "Limit": fmt(r["limit"]),
            "Margin": fmt(r["margin"]),
            "Unit": r["unit"],
            "Met": "yes" if r["met"] else "NO",
        }
        for r in rows
    ]
