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


def system() -> str:
    """The unit system values are shown in ("SI" or "US")."""
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
