"""How a number is shown, defined once: quantity kind -> unit and decimals.

Every headline metric, table column and figure hover text of every page takes its decimals from
:data:`KINDS` (through :func:`text`, :func:`printf`, :func:`pyformat` or :func:`d3`), so the
same quantity reads the same on the Design, Compare, Sensitivity and Optimise pages: a total
mass of 89.1 kg is never 89.14 kg elsewhere. Pure (no Streamlit, no plotly).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class Kind:
    """A kind of quantity: its display unit and the decimals it is shown with."""

    unit: str
    decimals: int


#: Quantity kind -> unit and decimals (the one formatting table of the app).
KINDS: dict[str, Kind] = {
    "mass": Kind("kg", 1),
    "volume": Kind("m³", 1),
    "area": Kind("m²", 1),
    "length": Kind("m", 2),  # hull and fin dimensions, stations along the hull
    "distance": Kind("m", 1),  # blow-by, heights, altitude loss, blow-by limit
    "force": Kind("N", 0),
    "angle": Kind("deg", 1),
    "speed": Kind("m/s", 1),
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


def text(value: Any, quantity: str, *, with_unit: bool = False, thousands: bool = True) -> str:
    """``value`` at the decimals of its quantity, never "-0.0"; "–" for a missing value.

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
    d = k.decimals
    if round(x, d) == 0:
        x = 0.0
    out = f"{x:,.{d}f}" if thousands else f"{x:.{d}f}"
    if with_unit and k.unit != "-":
        out += f" {k.unit}"
    return out


def printf(quantity: str) -> str:
    """printf format of a quantity, for ``st.column_config.NumberColumn(format=...)``."""
    return f"%.{decimals(quantity)}f"


def pyformat(quantity: str) -> str:
    """``str.format`` pattern of a quantity, for pandas stylers."""
    return f"{{:.{decimals(quantity)}f}}"


def d3(quantity: str) -> str:
    """d3 format of a quantity, for plotly hover templates (``%{y:.1f}``)."""
    return f".{decimals(quantity)}f"


def formatter(quantity: str):
    """A cell formatter for pandas stylers: :func:`text` of the quantity (never "-0.0"; "–"
    for a missing value), other cell types unchanged."""

    def fmt(v: Any) -> str:
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            try:
                v = float(v)
            except (TypeError, ValueError):
                return str(v)
        return text(v, quantity)

    return fmt


#: Axis unit -> kind, for figures whose axes carry their unit in brackets ("Height z [m]"):
#: positions along and above the ground are distances (as the blow-by), not hull lengths.
_KIND_OF_AXIS_UNIT = {**_KIND_OF_UNIT, "m": "distance", "s": "time", "kg": "mass"}


def axis_hover(title: str) -> str:
    """d3 hover format of an axis from the unit in its title ("Tension [N]" -> ".0f")."""
    unit_text = title.rsplit("[", 1)[-1].rstrip("]") if "[" in title else "-"
    raw = {"m³": "m3", "m²": "m2"}.get(unit_text, unit_text)
    return d3(_KIND_OF_AXIS_UNIT.get(raw, "ratio"))
