"""Display tables of the Sensitivity and Optimise pages (pandas frames and their column formats),
each quantity at the decimals of :mod:`app_ui.formats`, the fin position in % of the hull length.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd
import streamlit as st
from pandas.io.formats.style import Styler

from aerostat_core.optimize import OptimizationResult, ParetoFront, comparison_rows
from aerostat_core.studies.sensitivity import SensitivityResult

from . import formats
from .optimize_form import DISPLAY, shown, unit, var_label
from .tables import WRAP, export_csv


def comparison_frame(results: Sequence[OptimizationResult]) -> pd.DataFrame:
    """Table 4.12-like comparison: variables, mass, volume, blow-by, evaluations, time."""
    rows = comparison_rows(results)
    return pd.DataFrame(
        [
            {
                "Solver": r["solver"],
                "f [-]": r["fineness_ratio"],
                "ΔS_f [%]": r["area_change_pct"],
                "Δl_f [% of l]": shown("position", r["position"]),
                "Total mass [kg]": r["total_mass_kg"],
                "Volume [m³]": r["volume_m3"],
                "Blow-by [m]": r["blow_by_m"],
                "α_eq [deg]": r["alpha_eq_deg"],
                "Gas cost [USD]": r["gas_cost_USD"],
                "Evaluations": r["evaluations"],
                "Batches": r["batches"],
                "Time [s]": r["time_s"],
                "Status": r["status"],
                "Active constraints / bounds": r["active"],
            }
            for r in rows
        ]
    )


def _number(quantity: str) -> Any:
    """A number column at the decimals of its quantity (:mod:`app_ui.formats`)."""
    return st.column_config.NumberColumn(format=formats.printf(quantity))


#: Column formats of the solver comparison (and of the same columns elsewhere).
COMPARISON_FORMAT = {
    "f [-]": _number("fineness_ratio"),
    "ΔS_f [%]": _number("area_change"),
    "Δl_f [% of l]": _number("position"),
    "Total mass [kg]": _number("total_mass"),
    "Volume [m³]": _number("volume"),
    "Blow-by [m]": _number("blow_by"),
    "α_eq [deg]": _number("alpha_eq"),
    "Gas cost [USD]": _number("gas_cost"),
    "Time [s]": _number("time"),
}


#: Pareto table: each quantity at the precision it has in the solver comparison.
PARETO_FORMAT = {
    "Blow-by limit [m]": _number("blow_by_limit"),
    **{k: v for k, v in COMPARISON_FORMAT.items() if k != "Time [s]"},
}
#: Sweep points and the range summary.
SWEEP_FORMAT = {
    k: v
    for k, v in COMPARISON_FORMAT.items()
    if k in ("Volume [m³]", "Total mass [kg]", "Blow-by [m]", "α_eq [deg]")
} | {"Dynamic lift [N]": _number("dynamic_lift")}
SUMMARY_FORMAT = {
    c: _number("percent")
    for c in (
        "Mass change at low [%]",
        "Mass change at high [%]",
        "Volume change at low [%]",
        "Volume change at high [%]",
    )
}

#: Engine quantity names of the baseline-to-optimum rows shown in other units (the fin
#: position as a fraction of the hull length in the engine, in % here).
_ROW_DISPLAY = {"Fin position": "position"}


def changes_frame(rows: Sequence[Mapping[str, Any]]) -> pd.DataFrame:
    """Baseline-to-optimum changes (quantity, baseline, optimum, change) with units; the fin
    position in % of the hull length."""
    out = []
    for r in rows:
        var = _ROW_DISPLAY.get(r["quantity"])
        u = DISPLAY[var][2].replace("hull length", "l") if var else unit(r["unit"])
        conv = (lambda v, var=var: shown(var, v)) if var else (lambda v: v)
        out.append(
            {
                "Quantity": f"{r['quantity']} [{u}]",
                "Baseline": conv(r["baseline"]),
                "Optimum": conv(r["optimum"]),
                "Change": conv(r["change"]),
            }
        )
    return pd.DataFrame(out)


def changes_styler(
    df: pd.DataFrame, columns: Sequence[str] = ("Baseline", "Optimum", "Change")
) -> Styler:
    """:func:`changes_frame` (or :func:`thesis_frame`) with each row at the decimals of its
    unit, in ``columns``."""
    styler = df.style
    for i, q in zip(df.index, df["Quantity"]):
        u = str(q).rsplit("[", 1)[-1].rstrip("]")
        kind = "percent" if u.startswith("%") else formats.kind_of_unit(_RAW_UNIT.get(u, u))
        if str(q).startswith("Gas"):
            kind = "cost"
        styler = styler.format(formats.formatter(kind), subset=pd.IndexSlice[[i], list(columns)])
    return styler.hide(axis="index")


_RAW_UNIT = {"m³": "m3", "m²": "m2"}


def thesis_frame(rows: Sequence[Mapping[str, Any]]) -> pd.DataFrame:
    """Our baseline-to-optimum changes next to the thesis'."""
    return pd.DataFrame(
        [
            {
                "Quantity": f"{r['quantity']} [{unit(r['unit'])}]",
                "Thesis baseline": r["thesis_baseline"],
                "Thesis optimum": r["thesis_optimum"],
                "Thesis change": r["thesis_change"],
                "Our baseline": r["our_baseline"],
                "Our optimum": r["our_optimum"],
                "Our change": r["our_change"],
            }
            for r in rows
        ]
    )


def pareto_frame(front: ParetoFront) -> pd.DataFrame:
    """Pareto points with units."""
    return pd.DataFrame(
        [
            {
                "Blow-by limit [m]": r["blow_by_limit_m"],
                "Blow-by [m]": r["blow_by_m"],
                "Total mass [kg]": r["total_mass_kg"],
                "Volume [m³]": r["volume_m3"],
                "Gas cost [USD]": r["gas_cost_USD"],
                "f [-]": r["fineness_ratio"],
                "ΔS_f [%]": r["area_change_pct"],
                "Δl_f [% of l]": shown("position", r["position"]),
                "On front": formats.yes_no(r["on_front"]),
                "Why infeasible": r["reason"],
            }
            for r in front.rows()
        ]
    )


def sweep_frame(res: SensitivityResult) -> pd.DataFrame:
    """All sweep points with units."""
    return pd.DataFrame(
        [
            {
                "Variable": var_label(r["variable"]),
                "Value": shown(r["variable"], r["value"])
                if r["variable"] in DISPLAY
                else r["value"],
                "Volume [m³]": r["volume_m3"],
                "Total mass [kg]": r["total_mass_kg"],
                "Blow-by [m]": r["blow_by_m"],
                "α_eq [deg]": r["alpha_eq_deg"],
                "Dynamic lift [N]": r["dynamic_lift_N"],
                "Feasible": formats.yes_no(r["feasible"]),
                "Violations": r["violations"],
            }
            for r in res.rows()
        ]
    )


def summary_frame(res: SensitivityResult) -> pd.DataFrame:
    """Mass and volume change over each sweep range, relative to the baseline [%]."""
    return pd.DataFrame(
        [
            {
                "Variable": var_label(r["variable"]),
                "Baseline": shown(r["variable"], r["baseline"]),
                "Low": shown(r["variable"], r["low"]),
                "High": shown(r["variable"], r["high"]),
                "Mass change at low [%]": r["mass_change_low_pct"],
                "Mass change at high [%]": r["mass_change_high_pct"],
                "Volume change at low [%]": r["volume_change_low_pct"],
                "Volume change at high [%]": r["volume_change_high_pct"],
                "Feasible from": shown(r["variable"], r["feasible_from"]),
                "Feasible to": shown(r["variable"], r["feasible_to"]),
            }
            for r in res.summary_rows()
        ]
    )


def csv_of(rows: list[dict]) -> bytes:
    """CSV bytes of flat rows for download (Sensitivity and Optimise): the SI columns, a row of
    units, and in US customary units a converted column after each SI one
    (:func:`app_ui.tables.export_csv`, the Design page's export)."""
    return export_csv(rows, formats.system())


#: Rows of the transposed range summary: (row label, summary key, shown in the variable's unit).
_SUMMARY_ROWS = (
    ("Baseline", "baseline", True),
    ("Low end of the range", "low", True),
    ("High end of the range", "high", True),
    ("Mass change at the low end [%]", "mass_change_low_pct", False),
    ("Mass change at the high end [%]", "mass_change_high_pct", False),
    ("Volume change at the low end [%]", "volume_change_low_pct", False),
    ("Volume change at the high end [%]", "volume_change_high_pct", False),
    ("Feasible from", "feasible_from", True),
    ("Feasible to", "feasible_to", True),
)
SUMMARY_FIRST_COLUMN = "Over each range"


def summary_table(res: SensitivityResult) -> Styler:
    """The range summary transposed: one row per quantity, one column per design variable (4
    columns instead of 10, so it fits at 1024 px), each cell at the decimals of its quantity."""
    rows = {r["variable"]: r for r in res.summary_rows()}
    names = list(rows)
    df = pd.DataFrame(
        {SUMMARY_FIRST_COLUMN: [label for label, _, _ in _SUMMARY_ROWS]}
        | {
            var_label(n): [
                shown(n, rows[n][key]) if own else rows[n][key] for _, key, own in _SUMMARY_ROWS
            ]
            for n in names
        }
    )
    styler = df.style.hide(axis="index")
    own_rows = [i for i, (_, _, own) in enumerate(_SUMMARY_ROWS) if own]
    pct_rows = [i for i, (_, _, own) in enumerate(_SUMMARY_ROWS) if not own]
    for n in names:
        col = [var_label(n)]
        styler = styler.format(
            formats.formatter(_VAR_KIND[n]), subset=pd.IndexSlice[own_rows, col], na_rep="–"
        )
        styler = styler.format(
            formats.formatter("percent"), subset=pd.IndexSlice[pct_rows, col], na_rep="–"
        )
    return styler


#: Quantity (:mod:`app_ui.formats`) of each design variable in its display unit.
_VAR_KIND = {
    "fineness_ratio": "fineness_ratio",
    "area_change": "area_change",
    "position": "position",
}


#: Quantity (:mod:`app_ui.formats`) of every numeric column of the Optimise tables.
COLUMN_KINDS = {
    "f [-]": "fineness_ratio",
    "ΔS_f [%]": "area_change",
    "Δl_f [% of l]": "position",
    "Total mass [kg]": "total_mass",
    "Volume [m³]": "volume",
    "Blow-by [m]": "blow_by",
    "Blow-by limit [m]": "blow_by_limit",
    "α_eq [deg]": "alpha_eq",
    "Gas cost [USD]": "gas_cost",
    "Time [s]": "time",
    "Evaluations": "count",
    "Batches": "count",
    "Dynamic lift [N]": "dynamic_lift",
}
#: The solver comparison as three static tables (14 columns scrolled sideways at 1024 px).
COMPARISON_TABLES: dict[str, tuple[str, ...]] = {
    "Optimum of each solver": (
        "Solver",
        "Total mass [kg]",
        "Volume [m³]",
        "Blow-by [m]",
        "α_eq [deg]",
        "Gas cost [USD]",
    ),
    "Design variables at the optimum": ("Solver", "f [-]", "ΔS_f [%]", "Δl_f [% of l]"),
    "Cost of the run": (
        "Solver",
        "Evaluations",
        "Batches",
        "Time [s]",
        "Status",
        "Active constraints / bounds",
    ),
}
#: The Pareto table as two static tables.
PARETO_TABLES: dict[str, tuple[str, ...]] = {
    "Along the front": (
        "Blow-by limit [m]",
        "Blow-by [m]",
        "Total mass [kg]",
        "Volume [m³]",
        "Gas cost [USD]",
        "On front",
    ),
    "Design variables along the front": (
        "Blow-by limit [m]",
        "f [-]",
        "ΔS_f [%]",
        "Δl_f [% of l]",
        "Why infeasible",
    ),
}


def styled(df: pd.DataFrame, columns: Sequence[str] | None = None) -> Styler:
    """A static table of ``columns`` of ``df`` (default all), each numeric column at the
    decimals of its quantity, no index."""
    shown_df = df if columns is None else df[list(columns)]
    shown_df, names = formats.frame_in_system(shown_df)  # "Blow-by [ft]" in US customary
    fmt = {names[c]: formats.formatter(k) for c, k in COLUMN_KINDS.items() if c in names}
    return shown_df.style.format(fmt, na_rep="–").set_table_styles(WRAP).hide(axis="index")


def sweep_tables(df: pd.DataFrame) -> list[Styler]:
    """:func:`sweep_frame` as one static table per swept variable (its values as the first
    column, at the variable's decimals): cells wrap, so every column is in sight at 1024 px."""
    out = []
    for label, name in {var_label(n): n for n in _VAR_KIND}.items():
        part = df[df["Variable"] == label].drop(columns="Variable").reset_index(drop=True)
        if len(part):
            part = part.rename(columns={"Value": label})
            out.append(styled(part).format(formats.formatter(_VAR_KIND[name]), subset=[label]))
    return out


def sweep_styler(df: pd.DataFrame) -> Styler:
    """:func:`sweep_frame` as a static table: each variable's values at its own decimals,
    text cells wrapped narrow (9 columns in the 530 px of a page at 1024 px)."""
    narrow = [{"selector": "td > *, th > *", "props": "max-width: 6em; white-space: normal;"}]
    styler = styled(df).set_table_styles(narrow)
    labels = {var_label(n): n for n in _VAR_KIND}
    for label, name in labels.items():
        rows = list(df.index[df["Variable"] == label])
        if rows:
            styler = styler.format(
                formats.formatter(_VAR_KIND[name]), subset=pd.IndexSlice[rows, ["Value"]]
            )
    return styler
