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

from aerostat_core.base.fields import UNIT_SYSTEMS, DisplayUnit, unit_in


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
