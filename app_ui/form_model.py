"""The design-input form as data: the conversions between widget values and the inputs, and
the engine's errors in the form's words. No Streamlit import (rendering: :mod:`app_ui.form`).

Every fact about an input (label, unit, display scale, step, format, help, valid range) comes
from the core's field registry (:mod:`aerostat_core.base.fields`); :mod:`app_ui.form_fields` only
says which widget key shows which input path, and where (re-exported here).

* :data:`FIELDS` - every numeric widget (key, path, group; the rest from the registry);
* :func:`widget_values` - inputs dict -> widget values (display units of a unit system);
* :func:`texts_in_system` - the boxes' texts after a switch of the unit system;
* :func:`build_inputs` - widget values + the current inputs -> (Requirement, Configuration), or
  :class:`InputError` naming the widget and group the problem belongs to;
* :func:`form_error` - an engine :class:`aerostat_core.base.validation.InputError` in the form's
  words, placed by its ``owner`` and ``field`` (no message parsing).

Inputs the form does not show (e.g. the tether's axial stiffness) are carried over unchanged from
the current inputs, so a JSON file's values are never lost by submitting the form.
"""

from __future__ import annotations

import copy
import math
import re
from collections.abc import Mapping, MutableMapping
from dataclasses import fields
from typing import Any

from aerostat_core import FABRICS, TETHERS, Configuration, Requirement
from aerostat_core.base import validation as _validation
from aerostat_core.model import budget
from aerostat_core.model.input_paths import paths_for
from aerostat_core.model.io import inputs_from_dict

from .form_fields import (  # noqa: F401 - re-exported: the form model's vocabulary
    CHOICES,
    CUSTOM,
    ERROR_KEY,
    FIELD_BY_KEY,
    FIELDS,
    FIN_FABRIC_KEY,
    GROUPS,
    HULL_FABRIC_KEY,
    LAYOUT,
    OPEN_GROUPS,
    RULE_SETS,
    SRC_KEY,
    SUBMIT_KEY,
    TETHER_KEY,
    VOLUME_MODE_KEY,
    VOLUME_MODES,
    WIDGET_KEYS,
    Choice,
    Field,
    InputError,
    group_key,
)
from .text import format_value, short

# --- errors: placed by the engine's owner and field -------------------------------------------

#: Inputs set by another widget: the fin count follows the arrangement.
_SET_BY = {"configuration.fins.count": "in_arrangement"}
_WIDGET_OF_PATH: dict[str, tuple[str, str]] = {
    **{f.path: (f.key, f.group) for f in FIELDS},
    **{c.path: (c.key, c.group) for c in CHOICES.values()},
}


def widget_for(
    owner: str,
    field: str,
    value: Any = None,
    values: Mapping[str, Any] | None = None,
    system: str = "SI",
) -> tuple[str | None, str]:
    """(widget key or ``None``, group) of an engine input ``owner.field`` (an
    ``InputError``'s attributes). A class used in two places (``Fabric``: hull and fin) picks
    the widget whose box shows the rejected ``value`` in the widget ``values`` (in unit system
    ``system``), else the first. An input without a widget goes to the group of its siblings (``"general"`` if
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
            if f is not None and _same_text(values.get(key), f.text_of(value, system)):
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


def form_error(
    exc: _validation.InputError, values: Mapping[str, Any] | None = None, system: str = "SI"
) -> InputError:
    """An engine :class:`aerostat_core.base.validation.InputError` in the form's words: its label and
    display unit in unit system ``system`` (e.g. % of hull length for the fin position, ft for
    the altitude in US customary units), the value as typed, the range. The widget is found by
    the error's ``owner`` and ``field``; ``values`` (the widget values) tell the hull fabric
    from the fin fabric.

    >>> from aerostat_core import Requirement
    >>> try:
    ...     Requirement(payload_mass=-5)
    ... except ValueError as e:
    ...     print(form_error(e)); print(form_error(e, system="US"))
    Payload mass [kg]: -5 is not allowed; it must be more than 0 and at most 10000.
    Payload mass [lb]: -11.0231 is not allowed; it must be more than 0 and at most 22046.2.
    """
    key, group = widget_for(exc.owner, exc.field, exc.value, values, system)
    f = FIELD_BY_KEY.get(key or "")
    if f is None:
        label = CHOICES[key].label if key in CHOICES else exc.label
        return InputError(group, f"{label}: {exc.reason}.", key)
    label = f.label_in(system)
    if exc.lo is not None and exc.hi is not None and isinstance(exc.value, (int, float)):
        value = f.text_of(exc.value, system) if not f.integer else format_value(exc.value, True)
        lo, hi = (float(f.text_of(b, system)) for b in (exc.lo, exc.hi))
        rng = _range_words(lo, hi, exc.lo_open, exc.hi_open)
        if exc.too_small:
            return InputError(f.group, f"{label}: {value} is too small to compute with.", f.key)
        return InputError(
            f.group, f"{label}: {value} is not allowed; it must be {rng}{exc.context}.", f.key
        )
    return InputError(f.group, f"{label}: {exc.reason}.", f.key)


# --- pure conversions ---------------------------------------------------------------------------

_NUMBER_RE = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def parse_number(text: Any, f: Field, label: str | None = None) -> float | int | None:
    """The number typed in the box of field ``f``, or ``None`` for an empty optional box;
    ``label`` (default ``f.label``) names the box in messages (its label in the unit system).

    A decimal comma is read as a decimal point ("12,5" is 12.5, never 125); text with both a
    comma and a point, or several commas, is refused as ambiguous (no thousands separators).
    Raises :class:`InputError` with the field's label; an empty required box says "required".
    """
    label = f.label if label is None else label
    if isinstance(text, (int, float)) and not isinstance(text, bool):
        value = float(text)  # a number set programmatically (tests, older session state)
        raw = format_value(value)
    else:
        raw = "" if text is None else str(text).strip().replace("\u2212", "-")
        if not raw:
            if f.optional:
                return None
            raise InputError(f.group, f"{label}: required; enter a value.", f.key)
        shown = short(raw, 30)
        if raw.count(",") > 1 or ("," in raw and "." in raw):
            raise InputError(
                f.group,
                f"{label}: “{shown}” is ambiguous. Use one decimal point or one decimal comma, "
                "without thousands separators.",
                f.key,
            )
        candidate = raw.replace(",", ".")
        if not _NUMBER_RE.match(candidate):
            raise InputError(f.group, f"{label}: “{shown}” is not a number.", f.key)
        value = float(candidate)
    if not math.isfinite(value):
        raise InputError(f.group, f"{label}: “{short(raw, 30)}” is too large.", f.key)
    if f.integer:
        if value != int(value):
            raise InputError(f.group, f"{label}: {raw} is not a whole number.", f.key)
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
    inputs: Mapping[str, Any], previous: Mapping[str, Any] | None = None, system: str = "SI"
) -> dict[str, Any]:
    """Widget values (the text of each box, in the display units of unit system ``system``)
    that show ``inputs``; ``previous`` widget values fill the boxes the inputs leave open (the
    given-volume box while the volume is sized)."""
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
                else (f.text_of(170.0, system) if f.key == "in_volume" else "")
            )
            continue
        out[f.key] = f.text_of(int(v) if f.integer else float(v), system)
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


def texts_in_system(
    values: Mapping[str, Any], inputs: Mapping[str, Any], old: str, new: str
) -> dict[str, str]:
    """The number boxes' texts of ``values`` (typed in unit system ``old``) in unit system
    ``new``: a box showing ``inputs`` shows them in the new unit (so applying it keeps the exact
    SI value), a box with an edit not yet applied keeps that edit, converted (1000 ft -> 304.8
    m); text that is not a number stays as typed (its message comes on applying).

    >>> from aerostat_core import thesis_baseline
    >>> from aerostat_core.model.io import inputs_to_dict
    >>> d = inputs_to_dict(*thesis_baseline())
    >>> si = widget_values(d)
    >>> us = texts_in_system({**si, "in_payload": "10"}, d, "SI", "US")
    >>> us["in_altitude"], us["in_payload"]
    ('984.252', '22.0462')
    """
    shown_old = widget_values(inputs, values, old)
    shown_new = widget_values(inputs, values, new)
    out: dict[str, str] = {}
    for f in FIELDS:
        if f.key not in values:
            continue
        text = values[f.key]
        if _get(inputs, f.path) is not None and _same_text(text, shown_old.get(f.key)):
            out[f.key] = shown_new[f.key]
            continue
        try:
            x = parse_number(text, f)
        except InputError:
            out[f.key] = text
            continue
        if x is None or f.integer:
            out[f.key] = text if x is None else format_value(x, True)
            continue
        out[f.key] = f.text_of(f.to_si(x, old), new)
    return out


def _materials(
    d: dict, values: Mapping[str, Any], shown: Mapping[str, Any], system: str = "SI"
) -> None:
    """Set the fabrics and the tether in ``d`` from the catalogue choices or the custom boxes
    (typed in unit system ``system``)."""
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
        shown_value = parse_number(values.get(gsm_key), f, f.label_in(system))
        old = _get(d, f"configuration.{part}") or {}
        areal = f.to_si(float(shown_value), system)
        name = (
            old.get("name")
            if (old.get("areal_density") == areal and old.get("name") not in FABRICS)
            else f"Custom {f.shown(areal, 'SI'):g} g/m2"
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
        new[name] = f.to_si(parse_number(values.get(key), f, f.label_in(system)), system)
    if new != old or old.get("name") in TETHERS or not old.get("name"):
        new["name"] = f"Custom tether {new['linear_density'] * 1000:g} g/m"
    _set(d, "configuration.tether", new)


def build_inputs(
    values: Mapping[str, Any], base: Mapping[str, Any], system: str = "SI"
) -> tuple[Requirement, Configuration]:
    """Validated (Requirement, Configuration) from widget ``values``, typed in the display units
    of unit system ``system`` ("SI" or "US": 1000 in the altitude box is 304.8 m in "US"),
    converted to SI here, once; anything the widgets do not cover is taken from ``base`` (the
    current inputs dict). A box whose text is what the form showed for ``base`` keeps its exact
    SI value, so switching units and applying changes nothing. Raises :class:`InputError`."""
    d = copy.deepcopy(dict(base))
    d.pop("name", None)
    shown = widget_values(base, system=system)
    for f in FIELDS:
        if f.key not in values:
            continue
        v = values[f.key]
        if _same_text(v, shown.get(f.key)) and _get(base, f.path) is not None:
            continue  # untouched: keep the exact value (no rounding drift through the display)
        if f.group == "materials" or f.key == "in_volume":
            continue  # handled with the material choice and the volume mode below
        x = parse_number(v, f, f.label_in(system))
        if x is None:
            _set(d, f.path, None)
            continue
        _set(d, f.path, x if f.integer else f.to_si(x, system))
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
                f.group, f"{f.label_in(system)}: required; enter a value or choose 'Sized'.", f.key
            )
        if (
            not _same_text(v, shown.get("in_volume"))
            or _get(base, "configuration.hull.volume") is None
        ):
            _set(d, f.path, f.to_si(parse_number(v, f, f.label_in(system)), system))
    _materials(d, values, shown, system)
    try:
        req, cfg = inputs_from_dict(d)
    except _validation.InputError as exc:
        raise form_error(exc, values, system) from None
    except ValueError as exc:  # not about one input (a malformed file): shown as it is
        raise InputError("general", str(exc)) from None
    try:
        budget.check_design(req, cfg)
    except budget.BudgetError as exc:
        raise InputError("advanced", str(exc), "in_segments") from None
    return req, cfg
