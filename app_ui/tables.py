"""Display tables of the Design and Compare pages: pure functions from the plain rows of
:func:`aerostat_core.output.report.design_report` to pandas frames and stylers (no Streamlit; tested
directly). Units sit in every column name; decimals come from :mod:`app_ui.formats`.

The performance sweep has 15 columns, too many for one table at 1024 px (the result column is
under 400 px wide there): it is shown as three static tables by theme (:data:`PERF_TABLES`:
where the aerostat flies, the tether, the forces and stability), each starting with the wind
speed, whose headers wrap, so no table scrolls sideways.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd
from pandas.io.formats.style import Styler

from aerostat_core.output.report import SUMMARY_FIELDS

from . import formats

#: Performance-row keys -> display column names (units in brackets).
PERF_COLUMNS: dict[str, str] = {
    "wind_speed_m_s": "Wind [m/s]",
    "alpha_eq_deg": "α_eq [deg]",
    "dynamic_lift_N": "Dynamic lift [N]",
    "drag_N": "Drag [N]",
    "blow_by_m": "Blow-by [m]",
    "flying_height_m": "Flying height [m]",
    "altitude_loss_m": "Altitude loss [m]",
    "tension_top_N": "Tension at top [N]",
    "tension_winch_N": "Tension at winch [N]",
    "tether_angle_top_deg": "Tether angle at top [deg]",
    "tether_angle_winch_deg": "Tether angle at winch [deg]",
    "safety_factor": "Safety factor [-]",
    "cm_alpha_per_rad": "C_mα [1/rad]",
    "cm_alpha_aero_cv_per_rad": "C_mα,CV [1/rad]",
    "flags": "Limits exceeded",
}
#: Longer explanations of the short column names (the tables' column help).
PERF_HELP: dict[str, str] = {
    "Tether angle at top [deg]": "Tether angle at the confluence point, from the vertical.",
    "Tether angle at winch [deg]": "Tether angle at the winch, from the vertical.",
    "C_mα [1/rad]": "Pitching-moment slope about the confluence point (negative: stable).",
    "C_mα,CV [1/rad]": "Weathervane stability: pitching-moment slope of hull + fins about the "
    "centre of volume (negative: stable).",
    "Altitude loss [m]": "The altitude asked for minus the flying height (negative: flies higher).",
}
#: Quantity of each performance column (its decimals and unit, :mod:`app_ui.formats`).
PERF_KINDS: dict[str, str] = {
    "Wind [m/s]": "wind",
    "α_eq [deg]": "alpha_eq",
    "Dynamic lift [N]": "dynamic_lift",
    "Drag [N]": "drag",
    "Blow-by [m]": "blow_by",
    "Flying height [m]": "flying_height",
    "Altitude loss [m]": "altitude_loss",
    "Tension at top [N]": "tension",
    "Tension at winch [N]": "tension",
    "Tether angle at top [deg]": "tether_angle",
    "Tether angle at winch [deg]": "tether_angle",
    "Safety factor [-]": "safety_factor",
    "C_mα [1/rad]": "cm_alpha",
    "C_mα,CV [1/rad]": "cm_alpha",
}
#: The sweep's tables by theme: title -> columns (each with the wind speed; the limit flags in
#: the first). Six columns at most: the result column is under 400 px wide at 1024 px.
PERF_TABLES: dict[str, tuple[str, ...]] = {
    "Where it flies": (
        "Wind [m/s]",
        "Blow-by [m]",
        "Flying height [m]",
        "Altitude loss [m]",
        "Limits exceeded",
    ),
    "Tether": (
        "Wind [m/s]",
        "Tension at top [N]",
        "Tension at winch [N]",
        "Tether angle at top [deg]",
        "Tether angle at winch [deg]",
        "Safety factor [-]",
    ),
    "Forces and stability": (
        "Wind [m/s]",
        "α_eq [deg]",
        "Dynamic lift [N]",
        "Drag [N]",
        "C_mα [1/rad]",
        "C_mα,CV [1/rad]",
    ),
}
LIMIT_ROW_STYLE = "background-color: #fde2e2"
#: Table styles of a static table whose text cells wrap: Streamlit lets a cell grow to a wide
#: maximum before it wraps, which made the geometry table scroll at 1024 px.
WRAP = [{"selector": "td > *, th > *", "props": "max-width: 14em; white-space: normal;"}]
DIFF_ROW_STYLE = "background-color: #fff3c4"


def geometry_frame(rows: Sequence[Mapping[str, Any]]) -> pd.DataFrame:
    """Geometry rows as a frame: Quantity, Value, Unit."""
    return pd.DataFrame(
        {
            "Quantity": [r["quantity"] for r in rows],
            "Value": [float(r["value"]) for r in rows],
            "Unit": [formats.cell_unit(r["unit"]) for r in rows],
        }
    )


_SHOWN_UNIT = {formats.unit(u): u for u in ("m3", "m2")}


def _geometry_kinds(df: pd.DataFrame) -> tuple[list[str], list[str]]:
    """The kind (decimals, conversion) of each geometry row and its unit in the chosen system."""
    kinds = [
        formats.kind_of_unit(_SHOWN_UNIT.get(str(u), str(u)), str(q))
        for q, u in zip(df["Quantity"], df["Unit"])
    ]
    units = [
        formats.cell_unit(formats.unit_of(k)) if formats.KINDS[k].si else u
        for k, u in zip(kinds, df["Unit"])
    ]
    return kinds, units


#: The look of :func:`geometry_html`'s table (Streamlit's own static tables: thin row rules,
#: the theme's font; numbers right-aligned).
_HTML_TABLE_CSS = (
    "<style>.aerostat-table{border-collapse:collapse;font-size:0.875rem;margin:0 0 1rem 0}"
    ".aerostat-table th,.aerostat-table td{padding:0.25rem 0.75rem 0.25rem 0.375rem;"
    "border-bottom:1px solid rgba(49,51,63,0.1);text-align:left;vertical-align:top}"
    ".aerostat-table th{font-weight:600}.aerostat-table td.num{text-align:right}</style>"
)


def geometry_html(df: pd.DataFrame) -> str:
    """The geometry table as one HTML table: each value at the decimals of its kind (counts as
    integers, "4" not "4.000"; the hull volume as the headline metric; lengths as the metrics),
    in the chosen unit system, with its unit (ft for m, ...), every cell HTML-escaped.

    Why HTML: it is the first tab a fresh browser shows, and a static ``st.table`` there made
    the browser load about 1 MB of table code (Arrow) before the first result appeared; as
    Markdown, the table was parsed again in the browser on every rerun. ``st.html`` sets it
    as it is (sanitised), with code the page has already loaded for the app's style sheet.
    """
    from html import escape

    kinds, units = _geometry_kinds(df)
    rows = "".join(
        f"<tr><td>{escape(str(q))}</td><td class=\"num\">"
        f"{escape(formats.shown_formatter(kind)(v))}</td><td>{escape(str(u))}</td></tr>"
        for q, v, kind, u in zip(df["Quantity"], df["Value"], kinds, units)
    )
    return (
        f"{_HTML_TABLE_CSS}<table class=\"aerostat-table\" data-testid=\"geometry-table\">"
        f"<thead><tr><th>Quantity</th><th>Value</th><th>Unit</th></tr></thead>"
        f"<tbody>{rows}</tbody></table>"
    )


def constraint_styler(df: pd.DataFrame) -> Styler:
    """The constraint table as a static table that fits at 1024 px: the unit joined to the
    value, limit and margin, where it is checked joined to the constraint (two columns less),
    text cells that wrap, no index."""
    if "Unit" in df:
        unit = df["Unit"].map(lambda u: "" if u in ("-", "", None) else f" {formats.unit(u)}")
        for col in ("Value", "Limit", "Margin"):
            if col in df:
                df = df.assign(**{col: df[col].astype(str) + unit})
        df = df.drop(columns=["Unit"])
    if "Checked at" in df and "Constraint" in df:  # "Blow-by, at 15 m/s": one column less
        at = df["Checked at"].astype(str).map(lambda t: f", at {t}" if t.strip() else "")
        df = df.assign(Constraint=df["Constraint"].astype(str) + at).drop(columns=["Checked at"])
    wrap = [{"selector": "td > *, th > *", "props": "max-width: 7em; white-space: normal;"}]
    return df.style.set_table_styles(wrap).hide(axis="index")


def mass_frame(rows: Sequence[Mapping[str, Any]]) -> pd.DataFrame:
    """Mass rows as a frame: Item, Mass [kg], Share [%]."""
    return pd.DataFrame(
        {
            "Item": [r["item"] for r in rows],
            "Mass [kg]": [float(r["mass_kg"]) for r in rows],
            "Share [%]": [float(r["share_pct"]) for r in rows],
        }
    )


def mass_styler(df: pd.DataFrame) -> Styler:
    """:func:`mass_frame` as a static table: masses and shares at their decimals, no index."""
    df = df.rename(columns=formats.relabel)  # "Mass [lb]" in US customary units
    fmt = {formats.relabel("Mass [kg]"): formats.shown_formatter("mass")}
    fmt["Share [%]"] = formats.formatter("share")
    return df.style.format(fmt).hide(axis="index")


def performance_frame(rows: Sequence[Mapping[str, Any]]) -> pd.DataFrame:
    """Performance rows with display column names; ``limit_exceeded`` kept as the last column
    (the styler hides it)."""
    df = pd.DataFrame([{PERF_COLUMNS.get(k, k): v for k, v in r.items()} for r in rows])
    for col in df.columns:
        if df[col].dtype.kind == "f":
            df[col] = df[col].round(9) + 0.0  # no "-0.0" for values that are zero
    return df


def _performance_shown(
    df: pd.DataFrame, columns: Sequence[str] | None
) -> tuple[pd.DataFrame, np.ndarray, dict[str, Any]]:
    """The columns shown (``columns``, default all), which rows break an operating limit, and
    each column's formatter in the chosen unit system, keyed by its relabelled header."""
    limited = df["limit_exceeded"].to_numpy(bool) if "limit_exceeded" in df else np.zeros(len(df))
    shown = df.drop(columns=["limit_exceeded"], errors="ignore")
    if columns is not None:
        shown = shown[[c for c in columns if c in shown.columns]]
    # values and headers in the chosen unit system ("Blow-by [ft]")
    fmt = {
        formats.relabel(c): formats.shown_formatter(PERF_KINDS[c])
        for c in shown.columns
        if c in PERF_KINDS
    }
    return shown.rename(columns=formats.relabel), limited, fmt


def performance_styler(df: pd.DataFrame, columns: Sequence[str] | None = None) -> Styler:
    """Red background on rows that break an operating limit; each column at the decimals of
    its quantity; only ``columns`` (default: all) are shown."""
    shown, limited, fmt = _performance_shown(df, columns)

    def rowstyle(row: pd.Series) -> list[str]:
        return [LIMIT_ROW_STYLE if limited[row.name] else ""] * len(row)

    return shown.style.apply(rowstyle, axis=1).format(fmt).hide(axis="index")


#: The look of :func:`performance_html` on top of :data:`_HTML_TABLE_CSS`: a limited row's red
#: background, a header with an explanation underlined (it shows on hover), a title per table
#: and the note under them as Streamlit's own bold text and caption.
_PERF_HTML_CSS = (
    f".aerostat-table tr.limit td{{{LIMIT_ROW_STYLE}}}"
    ".aerostat-table th[title]{text-decoration:underline dotted;cursor:help}"
    ".aerostat-perf p{margin:0 0 0.5rem 0}.aerostat-perf p.note{font-size:0.875rem;"
    "color:rgba(49,51,63,0.6)}"
)


def performance_html(
    df: pd.DataFrame, groups: Mapping[str, Sequence[str]] | None = None
) -> str:
    """The performance sweep as one HTML block: a titled table per theme (``groups``, default
    :data:`PERF_TABLES`), each value as :func:`performance_styler` shows it (the decimals of
    its quantity, in the chosen unit system), the rows that break an operating limit on a red
    background, a short header's explanation (:data:`PERF_HELP`) on hover, every cell
    HTML-escaped; and the note saying what the red rows are.

    Why HTML: three ``st.table`` of a styler were about 0.3 s of a switch to the Performance
    tab in a browser without a GPU (benchmarks/bench_app.py), their rendering in the browser
    more than the five charts' once those were static drawings; ``st.html`` sets one block
    as it is (sanitised).
    """
    from html import escape

    parts = []
    for title, columns in (groups or PERF_TABLES).items():
        shown, limited, fmt = _performance_shown(df, columns)
        helps = {formats.relabel(c): PERF_HELP.get(c) for c in columns}
        head = "".join(
            f'<th title="{escape(helps[h])}">{escape(h)}</th>' if helps.get(h) else
            f"<th>{escape(h)}</th>"
            for h in shown.columns
        )
        body = []
        for i, row in enumerate(shown.itertuples(index=False)):
            cells = "".join(
                f'<td class="num">{escape(fmt[h](v))}</td>' if h in fmt else
                f"<td>{escape(str(v))}</td>"
                for h, v in zip(shown.columns, row)
            )
            body.append(f'<tr class="limit">{cells}</tr>' if limited[i] else f"<tr>{cells}</tr>")
        parts.append(
            f"<p><strong>{escape(title)}</strong></p><table class=\"aerostat-table\">"
            f"<thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>"
        )
    note = (
        '<p class="note">Rows with a red background break an operating limit (last column of '
        "the first table says which).</p>"
    )
    return (
        _HTML_TABLE_CSS.replace("</style>", _PERF_HTML_CSS + "</style>")
        + f'<div class="aerostat-perf" data-testid="performance-tables">{"".join(parts)}{note}</div>'
    )


def format_value(v: Any) -> str:
    """A table cell as text: 4 significant digits (thousands separated above 1000), booleans as
    yes/no, None as auto.

    >>> [format_value(x) for x in (372.96, 12.345, 10.0, 0.6789, 0.0123, 12000.0, True, None, "+")]
    ['373', '12.35', '10', '0.6789', '0.0123', '12,000', 'yes', 'auto', '+']
    """
    if isinstance(v, (bool, np.bool_)):
        return "yes" if v else "no"
    if v is None:
        return "auto"
    if isinstance(v, (int, float, np.floating, np.integer)):
        x = float(v)
        if abs(x) >= 1000:
            return f"{x:,.0f}"
        return f"{x:.4g}"
    return str(v)


#: Design-summary key -> its quantity kind in :mod:`app_ui.formats`.
_SUMMARY_KINDS = {
    "volume_m3": "volume",
    "length_m": "length",
    "diameter_m": "diameter",
    "total_mass_kg": "total_mass",
    "gross_buoyancy_N": "force",
    "free_lift_kg": "free_lift",
    "percent_static_lift": "percent",
    "blow_by_at_design_wind_m": "blow_by",
    "alpha_at_design_wind_deg": "alpha_eq",
    "tension_top_at_design_wind_N": "tension",
    "safety_factor_at_design_wind": "safety_factor",
    "gas_cost_USD": "gas_cost",
}
#: The comparison's result rows (their labels, from report.SUMMARY_FIELDS) -> quantity kind.
_RESULT_KINDS = {
    f"{label} [{u}]" if u else label: _SUMMARY_KINDS[key]
    for key, label, u in SUMMARY_FIELDS
    if key in _SUMMARY_KINDS
}


def comparison_frame(
    rows: Sequence[Mapping[str, Any]], names: Sequence[str], only_differences: bool = False
) -> pd.DataFrame:
    """Side-by-side table (one column per case, values as text) from
    :func:`aerostat_core.output.report.comparison_rows`; ``Differs`` says where the cases disagree."""
    keep = [r for r in rows if r["differs"] or not only_differences]
    data: dict[str, list] = {
        "Section": [r["section"] for r in keep],
        "Quantity": [r["quantity"] for r in keep],
    }

    def cell(r: Mapping[str, Any], n: str) -> str:
        # results at the formatting table's decimals (as on the Design page); inputs as typed
        kind = _RESULT_KINDS.get(r["quantity"]) if r["section"] == "result" else None
        v = r.get(n)
        if kind and isinstance(v, (int, float, np.floating)) and not isinstance(v, bool):
            return formats.shown(v, kind)  # in the chosen unit system, as its label says
        return format_value(v)

    for n in names:
        data[n] = [cell(r, n) for r in keep]
    data["Quantity"] = [
        formats.relabel(q) if r["section"] == "result" and q in _RESULT_KINDS else q
        for r, q in zip(keep, data["Quantity"])
    ]
    data["Differs"] = [formats.yes_no(r["differs"]) for r in keep]  # words, never True/False
    return pd.DataFrame(data)


def comparison_styler(df: pd.DataFrame) -> Styler:
    """Yellow background on the rows where the cases differ."""
    differs = (df["Differs"] == formats.yes_no(True)).to_numpy(bool)

    def rowstyle(row: pd.Series) -> list[str]:
        return [DIFF_ROW_STYLE if differs[row.name] else ""] * len(row)

    return df.style.apply(rowstyle, axis=1)


def labelled_table(
    rows: Sequence[Mapping[str, Any]],
    columns: Mapping[str, tuple[str, str | None] | tuple[str, str | None, str]],
) -> pd.DataFrame:
    """Rows as the text of a static table (cells wrap, so every column is in sight at 1024 px):
    the ``columns`` {key: (header, format[, missing])} in order, numbers by ``format``
    ("{:.3f}", never "-0.000"), booleans as yes/no, a missing or non-finite number as
    ``missing`` (default "not computed: no value"); a "Unit" column's "-" as "–" (Markdown made
    it a bullet); keys absent from the rows are left out.

    >>> labelled_table([{"a": -0.0001, "u": "-", "t": None}],
    ...                {"a": ("A", "{:.3f}"), "u": ("Unit", None), "t": ("T", None, "never")}
    ...                ).iloc[0].tolist()
    ['0.000', '–', 'never']
    """

    def cell(v: Any, spec: tuple, du: Any = None) -> Any:
        header, fmt = spec[0], spec[1]
        if isinstance(v, (bool, np.bool_)):
            return "yes" if v else "no"
        if v is None or (isinstance(v, (float, np.floating)) and not np.isfinite(v)):
            return spec[2] if len(spec) > 2 else formats.missing("no value")
        if header == "Unit" and isinstance(v, str):
            return formats.cell_unit(du.unit if du is not None else v)
        if fmt and isinstance(v, (int, float, np.integer, np.floating)):
            if du is not None and "[" not in header:  # in the row's unit: the chosen system's
                v = du.show(float(v))
            return _no_negative_zero(fmt.format(v))
        return v

    keys = [k for k in columns if any(k in r for r in rows)]
    # a table with a Unit column: each row's numbers without a unit of their own in the header
    # are in that row's unit, shown in the session's unit system (ft, kt, lbf in US customary)
    unit_key = next((k for k in keys if columns[k][0] == "Unit"), None)
    units = [
        formats.unit_shown(r.get(unit_key)) if unit_key and isinstance(r.get(unit_key), str)
        else None
        for r in rows
    ]
    return pd.DataFrame(
        {columns[k][0]: [cell(r.get(k), columns[k], du) for r, du in zip(rows, units)] for k in keys}
    )


def _no_negative_zero(text: str) -> str:
    """ "-0.000" -> "0.000": a value that rounds to zero has no sign."""
    if text.startswith("-") and not any(ch in "123456789" for ch in text):
        return text[1:]
    return text


#: CSV column-name suffixes (the SI unit in the key, "blow_by_m") -> unit token; two-part
#: suffixes first ("m_s" before "s").
_SUFFIX_UNIT = {
    "m_s": "m/s",
    "per_rad": "1/rad",
    "m3": "m3",
    "m2": "m2",
    "m": "m",
    "kg": "kg",
    "N": "N",
    "deg": "deg",
    "pct": "%",
    "USD": "USD",
    "W": "W",
    "s": "s",
}
#: US unit -> its CSV suffix ("ft³" -> "ft3").
_US_SUFFIX = {"ft": "ft", "ft²": "ft2", "ft³": "ft3", "lb": "lb", "lbf": "lbf", "kt": "kt"}


def column_unit(name: str) -> str:
    """The SI unit of a CSV column from its name's suffix ("blow_by_m" -> "m", "wind_speed_m_s"
    -> "m/s", "safety_factor" -> "").

    >>> column_unit("blow_by_m"), column_unit("wind_speed_m_s"), column_unit("safety_factor")
    ('m', 'm/s', '')
    """
    parts = str(name).split("_")
    for n in (2, 1):
        if len(parts) > n and "_".join(parts[-n:]) in _SUFFIX_UNIT:
            return _SUFFIX_UNIT["_".join(parts[-n:])]
    return ""


def export_csv(rows: Sequence[Mapping[str, Any]], system: str = "SI") -> bytes:
    """UTF-8 CSV of result rows for download: the SI columns as always (their names end in the
    unit), a second row giving each column's unit, and in US customary units one more column
    after each converted one ("blow_by_ft" after "blow_by_m"). Text cells are protected against
    formula injection as in :func:`aerostat_core.model.io.rows_to_csv`.

    >>> print(export_csv([{"blow_by_m": 30.48, "flags": ""}], "US").decode(), end="")
    blow_by_m,blow_by_ft,flags
    m,ft,
    30.48,100.0,
    """
    import csv
    import io

    from aerostat_core.base.fields import unit_in
    from aerostat_core.model.io import csv_safe

    if not rows:
        return b""
    names = list(rows[0].keys())
    cols: list[tuple[str, str, Any]] = []  # (name, unit, converter)
    for n in names:
        u = column_unit(n)
        cols.append((n, u, None))
        du = unit_in(_RAW.get(u, u), system) if u else None
        if system != "SI" and du is not None and du.unit in _US_SUFFIX:
            base = n[: -len(u.replace("/", "_"))].rstrip("_") if u != "m/s" else n[:-4]
            cols.append((f"{base}_{_US_SUFFIX[du.unit]}", du.unit, du.show))
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow([csv_safe(c[0]) for c in cols])
    w.writerow([c[1] for c in cols])
    for r in rows:
        out = []
        for n, _u, conv in cols:
            if conv is None:
                out.append(csv_safe(r.get(n, "")))
            else:
                v = r.get(_source(cols, n))
                ok = isinstance(v, (int, float)) and not isinstance(v, bool)
                out.append(round(conv(float(v)), 12) if ok else "")
        w.writerow(out)
    return buf.getvalue().encode("utf-8")


_RAW = {"m³": "m3", "m²": "m2"}


def _source(cols: list[tuple[str, str, Any]], name: str) -> str:
    """The SI column a converted column follows."""
    i = [c[0] for c in cols].index(name)
    return cols[i - 1][0]
