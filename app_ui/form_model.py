"""The design-input form as data: which inputs it shows, in which group, and the conversions
between widget values and the inputs. No Streamlit import (rendering: :mod:`app_ui.form`).

Every fact about an input (label, unit, display scale, step, format, help, valid range) comes
from the core's field registry (:mod:`aerostat_core.fields`); this module only says which
widget key shows which input path, and where.

* :data:`FIELDS` - every numeric widget (key, path, group; the rest from the registry);
* :func:`widget_values` - inputs dict -> widget values (display units);
* :func:`build_inputs` - widget values + the current inputs -> (Requirement, Configuration), or
  :class:`InputError` naming the widget and group the problem belongs to;
* :func:`form_error` - an engine :class:`aerostat_core.validation.InputError` in the form's
  words, placed by its ``owner`` and ``field`` (no message parsing).

Inputs the form does not show (e.g. the tether's axial stiffness) are carried over unchanged from
the current inputs, so a JSON file's values are never lost by submitting the form.
"""

from __future__ import annotations

import copy
import math
import re
from collections.abc import Mapping, MutableMapping
from dataclasses import dataclass, fields
from functools import cached_property
from typing import Any

from aerostat_core import FABRICS, TETHERS, Configuration, Requirement, budget
from aerostat_core import validation as _validation
from aerostat_core.fields import PathSpec, paths_for, spec_for_path
from aerostat_core.io import inputs_from_dict
from aerostat_core.rules import RULE_SETS
from aerostat_core.shapes import SHAPE_INFO

from .text import clean, format_value, short

CUSTOM = "Custom"
#: Where the last rejected submit's message goes: {"group": str, "text": str, "key": str}.
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
    """One numeric widget: its key, the input path it shows and its group. Label, unit,
    display scale (``display = SI value * scale``), step, format and help come from the field
    registry; ``note`` replaces the registry's "(empty = ...)" hint where the form has its own
    way to leave the value open (the volume's Given/Sized choice)."""

    key: str
    path: str
    group: str
    note: str | None = None

    @cached_property
    def entry(self) -> PathSpec:
        return spec_for_path(self.path)

    @property
    def unit(self) -> str:
        return self.entry.spec.shown_unit

    @property
    def label(self) -> str:
        s = self.entry.spec
        note = self.note if self.note is not None else (f"empty = {s.empty}" if s.empty else "")
        return f"{self.entry.label} [{self.unit}]" + (f" ({note})" if note else "")

    @property
    def scale(self) -> float:
        return float(self.entry.spec.scale)

    @property
    def step(self) -> float:
        return self.entry.spec.step or 1.0

    @property
    def fmt(self) -> str:
        return self.entry.spec.fmt

    @property
    def optional(self) -> bool:
        return self.entry.spec.optional and self.note is None

    @property
    def integer(self) -> bool:
        return self.entry.spec.integer

    @property
    def help(self) -> str:
        """The registry's help, plus the valid range in display units (not for a range that
        depends on another field: the help says it)."""
        s = self.entry.spec
        rng = s.range_text() if s.checked and not s.hi_field else ""
        return f"{s.help} Valid {rng}.".strip() if rng else s.help


#: Numeric widgets: group -> (key, input path) in display order. Selects and the fabric/tether
#: choices are handled separately (:data:`CHOICES`, :data:`LAYOUT`).
_NUMBERS: dict[str, tuple[tuple[str, str], ...]] = {
    "requirement": (
        ("in_payload", "requirement.payload_mass"),
        ("in_altitude", "requirement.altitude"),
        ("in_site", "requirement.site_elevation"),
        ("in_isa", "requirement.isa_offset"),
        ("in_site_temp", "requirement.site_temperature"),
    ),
    "wind": (
        ("in_wind_max", "requirement.wind_max"),
        ("in_wind_step", "requirement.wind_step"),
        ("in_design_wind", "requirement.design_wind"),
        ("in_survival_wind", "requirement.survival_wind"),
        ("in_blow_by", "requirement.blow_by_limit"),
        ("in_loss_limit", "requirement.altitude_loss_limit"),
        ("in_free_lift", "requirement.free_lift_fraction"),
        ("in_min_sf", "requirement.min_tether_safety_factor"),
        ("in_survival_sf", "requirement.survival_safety_factor"),
        ("in_max_angle", "requirement.max_tether_angle_deg"),
        ("in_wv_margin", "requirement.weathervane_margin"),
    ),
    "gas": (
        ("in_purity", "configuration.gas.purity"),
        ("in_superpressure", "configuration.gas.superpressure"),
        ("in_fixed_density", "configuration.gas.fixed_density"),
        ("in_gas_price", "configuration.gas_price"),
    ),
    "materials": (
        ("in_hull_gsm", "configuration.hull_fabric.areal_density"),
        ("in_fin_gsm", "configuration.fin_fabric.areal_density"),
        ("in_tether_lin", "configuration.tether.linear_density"),
        ("in_tether_dia", "configuration.tether.diameter"),
        ("in_tether_mbl", "configuration.tether.breaking_strength"),
        ("in_tether_cd", "configuration.tether.normal_drag_coefficient"),
    ),
    "configuration": (
        ("in_volume", "configuration.hull.volume"),
        ("in_fineness", "configuration.hull.fineness_ratio"),
        ("in_fin_area", "configuration.fins.area_change"),
        ("in_fin_pos", "configuration.fins.position"),
        ("in_nose", "configuration.hull.nose_fraction"),
    ),
    "advanced": (
        ("in_fin_ratio", "configuration.fins.area_ratio"),
        ("in_fin_ar", "configuration.fins.aspect_ratio"),
        ("in_fin_taper", "configuration.fins.taper_ratio"),
        ("in_fin_fabric_factor", "configuration.fins.fabric_factor"),
        ("in_misc", "configuration.misc_mass_ratio"),
        ("in_eta_k", "configuration.aero.hull_efficiency"),
        ("in_cdc", "configuration.aero.hull_crossflow_drag"),
        ("in_cdv", "configuration.aero.hull_axial_drag"),
        ("in_eta_f", "configuration.aero.fin_efficiency"),
        ("in_cla", "configuration.aero.section_lift_slope"),
        ("in_cd0_fin", "configuration.aero.fin_zero_lift_drag"),
        ("in_stall", "configuration.aero.fin_stall_angle_deg"),
        ("in_drop", "configuration.confluence.drop_ratio"),
        ("in_xi_off", "configuration.confluence.xi_offset"),
        ("in_wind_exp", "configuration.wind_profile.exponent"),
        ("in_z0", "configuration.wind_profile.roughness_length"),
        ("in_segments", "configuration.tether_segments"),
    ),
}
#: Form-only notes on a label (the form leaves these open another way).
_NOTES = {"in_volume": "when given"}

FIELDS: tuple[Field, ...] = tuple(
    Field(key, path, group, _NOTES.get(key))
    for group, rows in _NUMBERS.items()
    for key, path in rows
)
FIELD_BY_KEY = {f.key: f for f in FIELDS}


@dataclass(frozen=True)
class Choice:
    """One select or radio widget: key, input path, group and the text shown for each option;
    the label and help come from the field registry."""

    key: str
    path: str
    group: str
    options: Mapping[str, str]

    @property
    def label(self) -> str:
        return spec_for_path(self.path).label

    @property
    def help(self) -> str:
        return spec_for_path(self.path).spec.help


CHOICES: dict[str, Choice] = {
    c.key: c
    for c in (
        Choice(
            "in_rules",
            "requirement.rules",
            "requirement",
            {name: r.title for name, r in RULE_SETS.items()},
        ),
        Choice(
            "in_shape",
            "configuration.hull.shape",
            "configuration",
            {k: v.label for k, v in SHAPE_INFO.items()},
        ),
        Choice(
            "in_gas_kind",
            "configuration.gas.kind",
            "gas",
            {"helium": "Helium", "hydrogen": "Hydrogen"},
        ),
        Choice(
            "in_density_model",
            "configuration.gas.density_model",
            "gas",
            {
                "ideal": "Ideal gas at altitude (physics)",
                "fixed": "Fixed density (thesis constants)",
            },
        ),
        Choice(
            "in_arrangement",
            "configuration.fins.arrangement",
            "configuration",
            {"+": "4 fins, + (cross)", "x": "4 fins, x", "inverted-y": "3 fins, inverted Y"},
        ),
        Choice(
            "in_cutoff",
            "configuration.aero.cutoff",
            "advanced",
            {"fin": "At the fin root (thesis symbol list)", "tail": "At the tail"},
        ),
        Choice(
            "in_wind_kind",
            "configuration.wind_profile.kind",
            "advanced",
            {"uniform": "Uniform (thesis plots)", "power": "Power law", "log": "Log law"},
        ),
    )
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


def _keys(group: str) -> tuple[str, ...]:
    return tuple(key for key, _path in _NUMBERS[group])


#: Form layout: group -> widgets in order (field keys, choice keys, or the special keys).
LAYOUT: dict[str, tuple[str, ...]] = {
    "requirement": ("in_rules", *_keys("requirement")),
    "wind": (*_keys("wind")[2:], *_keys("wind")[:2]),  # the limits first, the sweep last
    "configuration": (
        "in_shape",
        VOLUME_MODE_KEY,
        *_keys("configuration")[:4],
        "in_arrangement",
        *_keys("configuration")[4:],
    ),
    "gas": ("in_gas_kind", "in_density_model", *_keys("gas")),
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
    "advanced": ("in_cutoff", "in_wind_kind", *_keys("advanced")),
}


# --- errors: placed by the engine's owner and field -------------------------------------------

#: Inputs set by another widget: the fin count follows the arrangement.
_SET_BY = {"configuration.fins.count": "in_arrangement"}
_WIDGET_OF_PATH: dict[str, tuple[str, str]] = {
    **{f.path: (f.key, f.group) for f in FIELDS},
    **{c.path: (c.key, c.group) for c in CHOICES.values()},
}


def widget_for(
    owner: str, field: str, value: Any = None, values: Mapping[str, Any] | None = None
) -> tuple[str | None, str]:
    """(widget key or ``None``, group) of an engine input ``owner.field`` (an
    ``InputError``'s attributes). A class used in two places (``Fabric``: hull and fin) picks
    the widget whose box shows the rejected ``value`` in the widget ``values``, else the
    first. An input without a widget goes to the group of its siblings (``"general"`` if
    none)."""
    paths = paths_for(owner, field)
    for path in paths:
        if path in _SET_BY:
            key = _SET_BY[path]
            return key, _WIDGET_OF_PATH[CHOICES[key].path][1]
    shown = [_WIDGET_OF_PATH[p] for p in paths if p in _WIDGET_OF_PATH]
    if len(shown) > 1 and values is not None and isinstance(value, (int, float)):
        for key, group in shown:
            f = FIELD_BY_KEY.get(key)
            if f is not None and _same_text(values.get(key), format_value(value * f.scale)):
                return key, group
    if shown:
        return shown[0]
    for path in paths:
        parent = path.rsplit(".", 1)[0] + "."
        sibling = next((g for p, (_k, g) in _WIDGET_OF_PATH.items() if p.startswith(parent)), None)
        if sibling:
            return None, sibling
    return None, "general"


def _range_words(lo: float, hi: float, lo_open: bool, hi_open: bool) -> str:
    lo_t, hi_t = format_value(lo), format_value(hi)
    if lo_open and hi_open:
        return f"more than {lo_t} and less than {hi_t}"
    if lo_open:
        return f"more than {lo_t} and at most {hi_t}"
    if hi_open:
        return f"at least {lo_t} and less than {hi_t}"
    return f"between {lo_t} and {hi_t}"


def form_error(exc: _validation.InputError, values: Mapping[str, Any] | None = None) -> InputError:
    """An engine :class:`aerostat_core.validation.InputError` in the form's words: its label and
    display unit (e.g. % of hull length for the fin position), the value as typed, the range.
    The widget is found by the error's ``owner`` and ``field``; ``values`` (the widget values)
    tell the hull fabric from the fin fabric.

    >>> from aerostat_core import Requirement
    >>> try:
    ...     Requirement(payload_mass=-5)
    ... except ValueError as e:
    ...     print(form_error(e))
    Payload mass [kg]: -5 is not allowed; it must be more than 0 and at most 500.
    """
    key, group = widget_for(exc.owner, exc.field, exc.value, values)
    f = FIELD_BY_KEY.get(key or "")
    if f is None:
        label = CHOICES[key].label if key in CHOICES else exc.label
        return InputError(group, f"{label}: {exc.reason}.", key)
    if exc.lo is not None and exc.hi is not None and isinstance(exc.value, (int, float)):
        value = format_value(float(exc.value) * f.scale, f.integer)
        rng = _range_words(exc.lo * f.scale, exc.hi * f.scale, exc.lo_open, exc.hi_open)
        if exc.too_small:
            return InputError(f.group, f"{f.label}: {value} is too small to compute with.", f.key)
        return InputError(
            f.group, f"{f.label}: {value} is not allowed; it must be {rng}{exc.context}.", f.key
        )
    return InputError(f.group, f"{f.label}: {exc.reason}.", f.key)


# --- pure conversions ---------------------------------------------------------------------------

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


def inputs_to_dict_part(obj: Any) -> dict[str, Any]:
    """A catalogue item (Fabric/TetherSpec) as the plain dict used in inputs dicts."""
    out = {}
    for f in fields(obj):
        v = getattr(obj, f.name)
        out[f.name] = "inf" if isinstance(v, float) and v == float("inf") else v
    return out


def _catalogue_name(current: Mapping[str, Any] | None, catalogue: Mapping[str, Any]) -> str:
    """The catalogue entry equal to ``current`` (an inputs sub-dict), else "Custom"."""
    if isinstance(current, Mapping):
        name = current.get("name")
        if name in catalogue:
            entry = inputs_to_dict_part(catalogue[name])
            if all(current.get(k) == v for k, v in entry.items()):
                return str(name)
    return CUSTOM


def _same_text(a: Any, b: Any) -> bool:
    """Whether two box values show the same thing ("68" and 68.0 do)."""
    if isinstance(a, str) and isinstance(b, str):
        return a.strip() == b.strip()
    try:
        return float(a) == float(b)
    except (TypeError, ValueError):
        return a == b


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
    for key, c in CHOICES.items():
        v = _get(inputs, c.path)
        out[key] = v if v in c.options else next(iter(c.options))
    vol = _get(inputs, "configuration.hull.volume")
    out[VOLUME_MODE_KEY] = "sized" if vol is None else "given"
    cfg = inputs.get("configuration", {}) if isinstance(inputs, Mapping) else {}
    out[HULL_FABRIC_KEY] = _catalogue_name(cfg.get("hull_fabric"), FABRICS)
    out[FIN_FABRIC_KEY] = _catalogue_name(cfg.get("fin_fabric"), FABRICS)
    out[TETHER_KEY] = _catalogue_name(cfg.get("tether"), TETHERS)
    return out


def _materials(d: dict, values: Mapping[str, Any], shown: Mapping[str, Any]) -> None:
    """Set the fabrics and the tether in ``d`` from the catalogue choices or the custom boxes."""
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
        f = FIELD_BY_KEY[gsm_key]
        shown_value = parse_number(values.get(gsm_key), f)
        old = _get(d, f"configuration.{part}") or {}
        areal = clean(float(shown_value) / f.scale)
        name = (
            old.get("name")
            if (old.get("areal_density") == areal and old.get("name") not in FABRICS)
            else f"Custom {shown_value:g} g/m2"
        )
        _set(d, f"configuration.{part}", {"name": name, "areal_density": areal})
    choice = values.get(TETHER_KEY)
    if choice is None:
        return
    if choice != CUSTOM:
        if choice not in TETHERS:
            raise InputError("materials", f"Unknown tether {choice!r}.")
        _set(d, "configuration.tether", inputs_to_dict_part(TETHERS[choice]))
        return
    old = dict(_get(d, "configuration.tether") or {})
    new = dict(old)
    for key in ("in_tether_lin", "in_tether_dia", "in_tether_mbl", "in_tether_cd"):
        f = FIELD_BY_KEY[key]
        name = f.path.rsplit(".", 1)[1]
        if _same_text(values.get(key), shown.get(key)) and old.get(name) is not None:
            continue
        new[name] = clean(parse_number(values.get(key), f) / f.scale)
    if new != old or old.get("name") in TETHERS or not old.get("name"):
        new["name"] = f"Custom tether {new['linear_density'] * 1000:g} g/m"
    _set(d, "configuration.tether", new)


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
        if f.group == "materials" or f.key == "in_volume":
            continue  # handled with the material choice and the volume mode below
        x = parse_number(v, f)
        if x is None:
            _set(d, f.path, None)
            continue
        _set(d, f.path, x if f.integer else clean(x / f.scale))
    for key, c in CHOICES.items():
        if key in values:
            _set(d, c.path, values[key])
    if _get(d, "configuration.hull.shape") != (
        _get(base, "configuration.hull.shape") or "npl"
    ) and values.get("in_fineness") == shown.get("in_fineness"):
        _set(d, "configuration.hull.fineness_ratio", None)  # the new shape's standard l/d
    arrangement = _get(d, "configuration.fins.arrangement")
    _set(d, "configuration.fins.count", 3 if arrangement == "inverted-y" else 4)
    # volume
    if values.get(VOLUME_MODE_KEY, "given") == "sized":
        _set(d, "configuration.hull.volume", None)
    elif "in_volume" in values:
        f = FIELD_BY_KEY["in_volume"]
        v = values["in_volume"]
        if v is None or (isinstance(v, str) and not v.strip()):
            raise InputError(
                f.group, f"{f.label}: required; enter a value or choose 'Sized'.", f.key
            )
        if (
            not _same_text(v, shown.get("in_volume"))
            or _get(base, "configuration.hull.volume") is None
        ):
            _set(d, f.path, clean(parse_number(v, f) / f.scale))
    _materials(d, values, shown)
    try:
        req, cfg = inputs_from_dict(d)
    except _validation.InputError as exc:
        raise form_error(exc, values) from None
    except ValueError as exc:  # not about one input (a malformed file): shown as it is
        raise InputError("general", str(exc)) from None
    try:
        budget.check_design(req, cfg)
    except budget.BudgetError as exc:
        raise InputError("advanced", str(exc), "in_segments") from None
    return req, cfg
