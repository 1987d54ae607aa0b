"""How a number is shown, defined once: quantity kind -> unit and decimals.

Every headline metric, table column and figure hover text of every page takes its decimals from
:data:`KINDS` (through :func:`text`, :func:`printf`, :func:`pyformat` or :func:`d3`), so the
same quantity reads the same on the Design, Compare, Sensitivity and Optimise pages: a total
mass of 89.1 kg is never 89.14 kg elsewhere. Pure (no Streamlit, no plotly).

Unit system: values are SI everywhere in the program; :func:`use_system` (called once per script
run by ``app.py`` from the sidebar's choice) makes :func:`text`, :func:`formatter`,
:func:`unit_of` and :func:`label` show them in SI or US customary units, from the field
registry's display units (:data:`aerostat_core.base.fields.US_CUSTOMARY`). The choice is a context
variable: every session's script thread has its own.

Missing values say why in words (:func:`missing`), never "nan", "None" or a bare dash.
"""

from __future__ import annotations

import contextvars
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from aerostat_core.base.fields import UNIT_SYSTEMS, DisplayUnit, FieldSpec, spec_display, unit_in

from .text import clean, format_value


@dataclass(frozen=True)
class Kind:
    """A kind of quantity: its display unit and the decimals it is shown with."""

    unit: str
    decimals: int
    #: SI unit token of the value ("m3"); "" when no unit system changes it.
    si: str = ""


#: Quantity kind -> unit and decimals (the one formatting table of the app).
KINDS: dict[str, Kind] = {
    "mass": Kind("kg", 1, "kg"),
    "volume": Kind("m³", 1, "m3"),
    "area": Kind("m²", 1, "m2"),
    "length": Kind("m", 2, "m"),  # hull and fin dimensions, stations along the hull
    "distance": Kind("m", 1, "m"),  # blow-by, heights, altitude loss, blow-by limit
    "force": Kind("N", 0, "N"),
    "angle": Kind("deg", 1),
    "speed": Kind("m/s", 1, "m/s"),
    "percent": Kind("%", 1),
    "ratio": Kind("-", 2),  # fineness ratio, safety factor, aspect ratio
    "coefficient": Kind("1/rad", 3),  # moment and lift slopes
    "cost": Kind("USD", 0),
    "power": Kind("W", 0),
    "time": Kind("s", 2),
    "count": Kind("-", 0),
}

#: Quantities shown on several pages -> their kind (names as the core's keys, unit suffix off).
QUANTITIES: dict[str, str] = {
    "volume": "volume",
    "total_mass": "mass",
    "free_lift": "mass",
    "length": "length",
    "diameter": "length",
    "blow_by": "distance",
    "blow_by_limit": "distance",
    "flying_height": "distance",
    "altitude_loss": "distance",
    "alpha_eq": "angle",
    "tether_angle": "angle",
    "dynamic_lift": "force",
    "drag": "force",
    "tension": "force",
    "safety_factor": "ratio",
    "fineness_ratio": "ratio",
    "area_change": "percent",
    "position": "percent",  # fin position, % of the hull length
    "gas_cost": "cost",
    "wind": "speed",
    "cm_alpha": "coefficient",
    "time": "time",
    "share": "percent",
}

#: Units as the core spells them -> as shown (m3 -> m³).
_UNIT_TEXT = {"m3": "m³", "m2": "m²"}
#: Shown SI units -> the core's token (m³ -> m3, °C -> degC).
_TOKEN_OF_TEXT = {"m³": "m3", "m²": "m2", "°C": "degC", "kg/m³": "kg/m3"}
#: Unit -> kind, for tables whose rows carry their unit (geometry).
_KIND_OF_UNIT = {
    "m3": "volume",
    "m2": "area",
    "m": "length",
    "deg": "angle",
    "kg": "mass",
    "N": "force",
    "m/s": "speed",
    "%": "percent",
    "1/rad": "coefficient",
    "-": "ratio",
}


def unit(u: str) -> str:
    """Display form of a unit string.

    >>> unit("m3"), unit("m/s")
    ('m³', 'm/s')
    """
    return _UNIT_TEXT.get(u, u)


def kind_of(quantity: str) -> str:
    """The kind of a quantity name of :data:`QUANTITIES`, or a kind name itself."""
    if quantity in KINDS:
        return quantity
    return QUANTITIES[quantity]


def kind_of_unit(u: str, quantity: str = "") -> str:
    """The kind of a table row from its unit (counts, named "Number of ...", as counts)."""
    if quantity.startswith("Number"):
        return "count"
    return _KIND_OF_UNIT.get(u, "ratio")


def decimals(quantity: str) -> int:
    """Decimals of a quantity (or kind)."""
    return KINDS[kind_of(quantity)].decimals


_SYSTEM: contextvars.ContextVar[str] = contextvars.ContextVar("unit_system", default="SI")


def use_system(name: str) -> None:
    """Show values in unit system ``name`` ("SI" or "US") from now on in this context (the
    session's script run)."""
    if name not in UNIT_SYSTEMS:
        raise ValueError(f"unit system {name!r}: use one of {', '.join(UNIT_SYSTEMS)}")
    _SYSTEM.set(name)


#: Where the session's choice is read from while a script runs (set by :mod:`app_ui.show`, which
#: knows the session; this module stays free of Streamlit): a page, a fragment or a callback then
#: follows the choice even where no :func:`use_system` ran before it.
_SESSION_CHOICE: Callable[[], str | None] | None = None


def read_choice_with(resolver: Callable[[], str | None] | None) -> None:
    """Read the unit system from ``resolver`` (``None`` outside a session) before the context's
    :func:`use_system` value."""
    global _SESSION_CHOICE
    _SESSION_CHOICE = resolver


def system() -> str:
    """The unit system values are shown in ("SI" or "US"): the session's choice while a script
    runs, else the one :func:`use_system` set (SI by default)."""
    if _SESSION_CHOICE is not None:
        chosen = _SESSION_CHOICE()
        if chosen in UNIT_SYSTEMS:
            return chosen
    return _SYSTEM.get()


def display(quantity: str) -> DisplayUnit:
    """The display unit of a quantity (or kind) in the current system.

    >>> display("blow_by").unit
    'm'
    """
    k = KINDS[kind_of(quantity)]
    if not k.si:
        return DisplayUnit(k.unit)
    return unit_in(k.si, system())


def unit_token(u: str) -> str:
    """The SI token of a displayed SI unit ("m³" -> "m3"), as :func:`unit_in` takes it."""
    return _TOKEN_OF_TEXT.get(u, u)


def unit_of(quantity: str) -> str:
    """The unit a quantity is shown in, in the current system ("m³", or "ft³" in US)."""
    return display(quantity).unit


def label(name: str, quantity: str) -> str:
    """A column or metric label with the quantity's unit in brackets ("Volume [m³]"); no
    brackets for a dimensionless quantity."""
    u = unit_of(quantity)
    return name if u in ("-", "") else f"{name} [{u}]"


def convert(value: Any, quantity: str) -> float:
    """An SI value of a quantity in the current system's unit."""
    return display(quantity).show(float(value))


def missing(why: str) -> str:
    """The text of a value that is not there, with the reason ("not computed: ...")."""
    return f"not computed: {why}"


def yes_no(flag: Any) -> str:
    """A flag as a word for a table cell ("yes"/"no"), never True/False."""
    return "yes" if bool(flag) else "no"


def cell_unit(u: str) -> str:
    """A unit for a table cell: "-" (dimensionless) as "–", which Markdown does not turn into a
    bullet (a static table rendered "-" as an empty list item)."""
    shown = unit(u)
    return "–" if shown.strip() in ("-", "") else shown


def text(
    value: Any,
    quantity: str,
    *,
    with_unit: bool = False,
    thousands: bool = True,
    in_system: bool = False,
) -> str:
    """``value`` (SI) at the decimals of its quantity, never "-0.0"; "–" for a missing value.
    ``in_system``: in the current unit system (:func:`use_system`; see :func:`shown`), else SI.

    >>> text(89.1426, "total_mass"), text(1234.5, "tension"), text(-0.04, "blow_by")
    ('89.1', '1,234', '0.0')
    >>> text(17.319, "length", with_unit=True)
    '17.32 m'
    """
    if value is None:
        return "–"
    x = float(value)
    if not math.isfinite(x):
        return "–"
    k = KINDS[kind_of(quantity)]
    du = display(quantity) if in_system else DisplayUnit(k.unit)
    x = du.show(x)
    d = k.decimals
    if round(x, d) == 0:
        x = 0.0
    out = f"{x:,.{d}f}" if thousands else f"{x:.{d}f}"
    if with_unit and du.unit != "-":
        out += f" {du.unit}"
    return out


def shown(value: Any, quantity: str, *, with_unit: bool = False) -> str:
    """``value`` (SI) as :func:`text` in the current unit system; its header or label must come
    from :func:`label` (or :func:`relabel`), so the unit shown is the unit of the number.

    >>> use_system("US"); shown(170.0, "volume", with_unit=True); use_system("SI")
    '6,003.5 ft³'
    """
    return text(value, quantity, with_unit=with_unit, in_system=True)


def shown_formatter(quantity: str):
    """:func:`formatter` in the current unit system (pair it with :func:`relabel`)."""
    return formatter(quantity, in_system=True)


#: Bracketed SI units of table headers -> their unit token (what :func:`relabel` swaps).
_HEADER_UNIT = {"m": "m", "m³": "m3", "m²": "m2", "kg": "kg", "N": "N", "m/s": "m/s"}


def relabel(header: str) -> str:
    """A header "Name [SI unit]" with the unit of the current system ("Blow-by [m]" ->
    "Blow-by [ft]" in US customary); other headers unchanged.

    >>> relabel("Blow-by [m]"), relabel("Share [%]")
    ('Blow-by [m]', 'Share [%]')
    """
    h = str(header)
    if not h.endswith("]") or "[" not in h:
        return h
    name, u = h[:-1].rsplit("[", 1)
    token = _HEADER_UNIT.get(u)
    if token is None:
        return h
    return f"{name}[{unit_in(token, system()).unit}]"


def printf(quantity: str) -> str:
    """printf format of a quantity, for ``st.column_config.NumberColumn(format=...)``."""
    return f"%.{decimals(quantity)}f"


def pyformat(quantity: str) -> str:
    """``str.format`` pattern of a quantity, for pandas stylers."""
    return f"{{:.{decimals(quantity)}f}}"


def d3(quantity: str) -> str:
    """d3 format of a quantity, for plotly hover templates (``%{y:.1f}``)."""
    return f".{decimals(quantity)}f"


def formatter(quantity: str, *, in_system: bool = False):
    """A cell formatter for pandas stylers: :func:`text` of the quantity (never "-0.0"; "–"
    for a missing value), other cell types unchanged; ``in_system`` as in :func:`text`."""

    def fmt(v: Any) -> str:
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            try:
                v = float(v)
            except (TypeError, ValueError):
                return str(v)
        return text(v, quantity, in_system=in_system)

    return fmt


#: Axis unit -> kind, for figures whose axes carry their unit in brackets ("Height z [m]"):
#: positions along and above the ground are distances (as the blow-by), not hull lengths.
_KIND_OF_AXIS_UNIT = {**_KIND_OF_UNIT, "m": "distance", "s": "time", "kg": "mass"}


def axis_hover(title: str) -> str:
    """d3 hover format of an axis from the unit in its title ("Tension [N]" -> ".0f")."""
    unit_text = title.rsplit("[", 1)[-1].rstrip("]") if "[" in title else "-"
    raw = {"m³": "m3", "m²": "m2"}.get(unit_text, unit_text)
    return d3(_KIND_OF_AXIS_UNIT.get(raw, "ratio"))


# --- registry-built input boxes in the chosen unit system ---------------------------------------
#
# Every number box built from a field of the registry (the Design form, the Mission tab, the
# Envelope site, the Dynamics request) shows its value, unit, range and step in the session's
# unit system through these functions, and reads the typed number back to SI through them: a
# US user types 1000 ft, 22 lb or 30 kt and the engine receives 304.8 m, 9.979 kg, 15.43 m/s.

#: Significant digits of a box's text in a converted unit (984.252 ft for 300 m): enough that a
#: value typed back gives the same SI value to 6 digits; an untouched box keeps its exact SI
#: value (the form compares the text with what it showed).
BOX_DIGITS = 6


def field_unit(spec: FieldSpec, system_name: str | None = None) -> DisplayUnit:
    """The display unit of a registry field in ``system_name`` (default: the current system)."""
    return spec_display(spec, system_name or system())


def _converted(du: DisplayUnit, spec: FieldSpec) -> bool:
    return du.scale != float(spec.scale) or du.offset != 0.0


def box_text(
    si: Any, spec: FieldSpec, system_name: str | None = None, *, integer: bool | None = None
) -> str:
    """An SI value of a registry field as the text of its box in ``system_name``: as
    :func:`app_ui.text.format_value` in the field's own display unit, at :data:`BOX_DIGITS`
    significant digits in a converted one; "" for ``None``.

    >>> from aerostat_core.base.fields import field_spec
    >>> from aerostat_core.model.inputs import Requirement
    >>> s = field_spec(Requirement, "altitude")
    >>> box_text(300.0, s, "SI"), box_text(300.0, s, "US")
    ('300', '984.252')
    """
    integer = spec.integer if integer is None else integer
    if si is None:
        return ""
    if integer:
        return format_value(si, True)
    du = field_unit(spec, system_name)
    x = du.show(float(si))
    if _converted(du, spec):
        x = float(f"{x:.{BOX_DIGITS}g}")
    return format_value(x)


def box_to_si(x: float, spec: FieldSpec, system_name: str | None = None) -> float:
    """A number typed in a registry field's box (in ``system_name``'s unit) in SI, rounded to 12
    significant digits (:func:`app_ui.text.clean`) so that 1000 ft is 304.8 m exactly.

    >>> from aerostat_core.base.fields import field_spec
    >>> from aerostat_core.model.inputs import Requirement
    >>> box_to_si(1000, field_spec(Requirement, "altitude"), "US")
    304.8
    """
    return clean(field_unit(spec, system_name).to_si(float(x)))


def box_unit(spec: FieldSpec, system_name: str | None = None) -> str:
    """The unit shown in a registry field's label ("ft", "%", "-")."""
    return field_unit(spec, system_name).unit


def box_label(label: str, spec: FieldSpec, system_name: str | None = None) -> str:
    """A box label with the field's unit in ``system_name`` in brackets ("Altitude [ft]")."""
    u = box_unit(spec, system_name)
    return f"{label} [{u}]" if u else label


def box_bounds(
    spec: FieldSpec, system_name: str | None = None
) -> tuple[float | None, float | None, float | None]:
    """(min, max, step) of a registry field's box in ``system_name``'s unit: the registry range
    converted (``None`` for an open or missing bound: the engine checks it and says why), the
    step converted at 2 significant digits (10 m -> 33 ft) so a spin box stays readable."""
    du = field_unit(spec, system_name)
    lo = None if spec.lo is None or spec.lo_open else clean(du.show(spec.lo))
    hi = None if spec.hi is None or spec.hi_open else clean(du.show(spec.hi))
    step = None
    if spec.step:
        # the registry's step is in the field's own display unit (scale), an SI step underneath
        raw = du.scale * float(spec.step) / float(spec.scale)
        step = float(f"{raw:.2g}") if _converted(du, spec) else float(spec.step)
    return lo, hi, step


# --- figures in the chosen unit system ----------------------------------------------------------
#
# The figure builders draw in SI (their axis titles carry the unit in brackets: "Blow-by [m]");
# :func:`figure_in_system` turns a finished figure into the session's unit system by those
# brackets: every trace on an axis whose unit converts is converted, with the axis' title, range
# and ticks, the reference lines and notes on it, the colour bar's values, the hover texts' units
# and the numbers with a unit in titles, names and notes ("blow-by limit 150 m" -> "492.1 ft").
# One definition of each factor: :data:`aerostat_core.base.fields.US_CUSTOMARY`.

import re as _re  # noqa: E402 - kept with the figure helpers

#: Units as shown in figures -> their SI token, for the units whose display converts a value in
#: that very unit (not "kN" or "mm", whose US entries apply to the value in N or m).
_FIGURE_UNITS = {"m/s": "m/s", "m³": "m3", "m²": "m2", "m": "m", "N": "N", "kg": "kg", "°C": "degC"}
_UNIT_ALT = "|".join(_re.escape(u) for u in sorted(_FIGURE_UNITS, key=len, reverse=True))
_BRACKET = _re.compile(r"\[(" + _UNIT_ALT + r")\]")
_NUMBER_UNIT = _re.compile(r"(?<![\w.])(-?\d[\d,]*(?:\.\d+)?)( ?)(" + _UNIT_ALT + r")(?![\w/³²])")
_PLACEHOLDER_UNIT = _re.compile(r"(%\{(x|y|z)(?::[^}]*)?\})(\s*)(" + _UNIT_ALT + r")(?![\w/³²])")
_AXIS_KEY = _re.compile(r"^(x|y)axis(\d*)$")


def _fig_unit(text: str, system_name: str) -> DisplayUnit | None:
    """The display unit of the last bracketed unit of an axis or colour-bar title, when it
    converts in ``system_name``."""
    found = _BRACKET.findall(text or "")
    if not found:
        return None
    du = unit_in(_FIGURE_UNITS[found[-1]], system_name)
    return du if (du.scale != 1.0 or du.offset != 0.0) else None


def _relabel_text(text: str, system_name: str) -> str:
    """Bracketed units and "number unit" pairs of a text in ``system_name``."""

    def bracket(m: _re.Match) -> str:
        return f"[{unit_in(_FIGURE_UNITS[m.group(1)], system_name).unit}]"

    def number(m: _re.Match) -> str:
        raw = m.group(1).replace(",", "")
        du = unit_in(_FIGURE_UNITS[m.group(3)], system_name)
        if du.scale == 1.0 and du.offset == 0.0:
            return m.group(0)
        x = du.show(float(raw))
        d = len(raw.split(".")[1]) if "." in raw else 0
        if not d:  # an integer: three significant digits, never an exponent
            d = max(0, 2 - math.floor(math.log10(abs(x)))) if x else 0
        out = f"{x:.{d}f}"
        return f"{out}{m.group(2)}{du.unit}"

    return _BRACKET.sub(bracket, _NUMBER_UNIT.sub(number, text))


def text_in_system(text: str, system_name: str | None = None) -> str:
    """A sentence with SI numbers and units ("payload 10 kg at 300 m") in the current unit
    system ("payload 22.0 lb at 984 ft"): bracketed units and "number unit" pairs converted.

    >>> text_in_system("blow-by limit 150 m at 15 m/s [m]", "US")
    'blow-by limit 492 ft at 29.2 kt [ft]'
    """
    system_name = system_name or system()
    return text if system_name == "SI" else _relabel_text(text, system_name)


def unit_shown(u: str, system_name: str | None = None) -> DisplayUnit | None:
    """How a value in the SI unit ``u`` (as a table's Unit column or a header's brackets show
    it: "m", "m/s", "N", "kg", "m³") is shown in the current system, when it converts; ``None``
    when the number stays as it is (SI, or a unit no system changes: deg, s, %)."""
    token = _FIGURE_UNITS.get(str(u).strip())
    if token is None:
        return None
    du = unit_in(token, system_name or system())
    return du if (du.scale != 1.0 or du.offset != 0.0) else None


def frame_in_system(df: Any, system_name: str | None = None) -> tuple[Any, dict[str, str]]:
    """A table (pandas frame) whose headers carry SI units in brackets ("Blow-by [m]") in the
    current unit system: numeric cells of those columns converted, headers relabelled; returns
    the frame and {old header: new header} (every header), so formats keyed by the old names
    follow."""
    system_name = system_name or system()
    names = {c: c for c in df.columns}
    if system_name == "SI":
        return df, names
    out = df.copy()
    for c in df.columns:
        found = _BRACKET.findall(str(c))
        du = unit_shown(found[-1], system_name) if found else None
        if du is None:
            continue
        out[c] = [
            du.show(float(v))
            if isinstance(v, (int, float)) and not isinstance(v, bool) and v == v
            else v
            for v in df[c]
        ]
        names[c] = _relabel_text(str(c), system_name)
    return out.rename(columns=names), names


def _convert_values(v: Any, du: DisplayUnit, *, delta: bool = False) -> Any:
    """Values (a number, a list with ``None`` gaps, nested lists, a numpy array) in ``du``;
    ``delta``: a difference (a step), scaled only."""
    import numpy as np

    def one(x: Any) -> Any:
        if x is None or isinstance(x, (bool, str)):
            return x
        return float(x) * du.scale if delta else du.show(float(x))

    if isinstance(v, np.ndarray):
        if v.dtype.kind in "fiu":
            return v * du.scale if delta else v * du.scale + du.offset
        return np.array([_convert_values(x, du, delta=delta) for x in v], dtype=object)
    if isinstance(v, (list, tuple)):
        return [_convert_values(x, du, delta=delta) for x in v]
    if isinstance(v, dict):
        return v  # a typed-array encoding is not expected in a figure being built
    return one(v)


def _title_text(obj: dict) -> str:
    t = obj.get("title")
    if isinstance(t, dict):
        return str(t.get("text") or "")
    return str(t or "")


def _set_title(obj: dict, text: str) -> None:
    t = obj.get("title")
    if isinstance(t, dict):
        t["text"] = text
    else:
        obj["title"] = {"text": text}


def _convert_axis(ax: dict, system_name: str) -> DisplayUnit | None:
    du = _fig_unit(_title_text(ax), system_name)
    if _title_text(ax):
        _set_title(ax, _relabel_text(_title_text(ax), system_name))
    if du is None:
        return None
    for k in ("range", "tickvals"):
        if ax.get(k) is not None:
            ax[k] = _convert_values(ax[k], du)
    if ax.get("dtick") is not None and isinstance(ax["dtick"], (int, float)):
        ax["dtick"] = ax["dtick"] * du.scale
    return du


def _hover_units(template: str, units: dict[str, DisplayUnit | None]) -> str:
    def sub(m: _re.Match) -> str:
        du = units.get(m.group(2))
        return m.group(0) if du is None else f"{m.group(1)}{m.group(3)}{du.unit}"

    return _PLACEHOLDER_UNIT.sub(sub, template)


def figure_dict_in_system(fig: dict, system_name: str | None = None) -> dict:
    """A plotly figure as a dict (``{"data": [...], "layout": {...}}``, SI values, units in the
    axis titles' brackets) in unit system ``system_name`` (default: the current one), converted
    in place and returned. Pure: no plotly import.

    >>> f = {"data": [{"type": "scatter", "x": [10.0], "y": [150.0],
    ...                "hovertemplate": "%{x:.1f} m/s: %{y:.0f} m"}],
    ...      "layout": {"xaxis": {"title": {"text": "Wind [m/s]"}},
    ...                 "yaxis": {"title": {"text": "Blow-by [m]"}},
    ...                 "shapes": [{"xref": "paper", "yref": "y", "y0": 150.0, "y1": 150.0}],
    ...                 "annotations": [{"text": "blow-by limit 150 m", "xref": "paper",
    ...                                  "yref": "y", "y": 150.0}]}}
    >>> g = figure_dict_in_system(f, "US")
    >>> g["layout"]["yaxis"]["title"]["text"], round(g["data"][0]["y"][0], 1)
    ('Blow-by [ft]', 492.1)
    >>> g["data"][0]["hovertemplate"], g["layout"]["annotations"][0]["text"]
    ('%{x:.1f} kt: %{y:.0f} ft', 'blow-by limit 492 ft')
    """
    system_name = system_name or system()
    if system_name == "SI":
        return fig
    lay = fig.setdefault("layout", {})
    axes: dict[str, DisplayUnit | None] = {}
    for key in list(lay):
        m = _AXIS_KEY.match(key)
        if m and isinstance(lay[key], dict):
            axes[f"{m.group(1)}{m.group(2)}"] = _convert_axis(lay[key], system_name)
        elif key.startswith("scene") and isinstance(lay[key], dict):
            for a in ("x", "y", "z"):
                ax = lay[key].get(f"{a}axis")
                if isinstance(ax, dict):
                    axes[f"{key}.{a}"] = _convert_axis(ax, system_name)
    if _title_text(lay):
        _set_title(lay, _relabel_text(_title_text(lay), system_name))
    for tr in fig.get("data", []):
        if tr.get("type") in ("scatter3d", "mesh3d", "surface", "cone"):
            scene = tr.get("scene") or "scene"
            units = {a: axes.get(f"{scene}.{a}") for a in ("x", "y", "z")}
        else:
            units = {
                "x": axes.get(tr.get("xaxis") or "x"),
                "y": axes.get(tr.get("yaxis") or "y"),
                "z": None,
            }
            bar = tr.get("colorbar") or (tr.get("marker") or {}).get("colorbar") or {}
            units["z"] = _fig_unit(_title_text(bar), system_name) if bar else None
            if bar and _title_text(bar):
                _set_title(bar, _relabel_text(_title_text(bar), system_name))
        for a, du in units.items():
            if du is None:
                continue
            if tr.get(a) is not None:
                tr[a] = _convert_values(tr[a], du)
            if a == "z" and tr.get("type") not in ("scatter3d", "mesh3d", "surface"):
                c = tr.get("contours") or {}
                for k in ("start", "end"):
                    if c.get(k) is not None:
                        c[k] = _convert_values(c[k], du)
                if c.get("size") is not None:
                    c["size"] = _convert_values(c["size"], du, delta=True)
                marker = tr.get("marker") or {}
                if tr.get("type") == "scatter" and marker.get("color") is not None:
                    marker["color"] = _convert_values(marker["color"], du)
        if isinstance(tr.get("hovertemplate"), str):
            tr["hovertemplate"] = _hover_units(tr["hovertemplate"], units)
        if isinstance(tr.get("name"), str):
            tr["name"] = _relabel_text(tr["name"], system_name)
        text = tr.get("text")
        if isinstance(text, str):
            tr["text"] = _relabel_text(text, system_name)
        elif isinstance(text, (list, tuple)):
            tr["text"] = [_relabel_text(t, system_name) if isinstance(t, str) else t for t in text]
    for shape in lay.get("shapes") or []:
        for a in ("x", "y"):
            du = axes.get(shape.get(f"{a}ref") or a)
            if du is not None:
                for k in (f"{a}0", f"{a}1"):
                    if shape.get(k) is not None:
                        shape[k] = du.show(float(shape[k]))
    for note in lay.get("annotations") or []:
        for a in ("x", "y"):
            du = axes.get(note.get(f"{a}ref") or a)
            if du is not None and isinstance(note.get(a), (int, float)):
                note[a] = du.show(float(note[a]))
        if isinstance(note.get("text"), str):
            note["text"] = _relabel_text(note["text"], system_name)
    return fig


def figure_in_system(fig: Any, system_name: str | None = None) -> Any:
    """A plotly figure (``go.Figure``) in the current unit system (:func:`figure_dict_in_system`);
    the same object in SI, a new figure of the same type otherwise."""
    system_name = system_name or system()
    if system_name == "SI":
        return fig
    d = fig.to_dict() if hasattr(fig, "to_dict") else fig
    out = figure_dict_in_system(d, system_name)
    return type(fig)(out) if hasattr(fig, "to_dict") else out
