"""One precision per quantity (issue 9 item 9): the formatting table of app_ui.formats is what the
Design metrics, the Design tables, the Optimise tables and the figures' hover texts show."""

from __future__ import annotations

import re

import pytest

from app_ui import formats, tables
from tests.app.helpers import chart, goto, messages, metric, show_tab, shown_table, table

OPT_PAGE = "pages/4_Optimise.py"


def _decimals(text: str) -> int:
    """Decimals of a shown number ("1,234.5" -> 1, "12" -> 0)."""
    m = re.search(r"-?[\d,]+(?:\.(\d+))?", text)
    assert m, text
    return len(m.group(1) or "")


def _styled_cells(styler, column: str) -> list[str]:
    """The shown texts of one column of a pandas styler."""
    ctx = styler._translate(False, False)
    col = list(styler.data.columns).index(column)
    return [row[col + 1]["display_value"] for row in ctx["body"]]


def test_the_table_is_the_brief_one():
    assert {k: (v.unit, v.decimals) for k, v in formats.KINDS.items() if k in (
        "mass", "volume", "force", "angle", "speed", "percent"
    )} == {
        "mass": ("kg", 1), "volume": ("m³", 1), "force": ("N", 0), "angle": ("deg", 1),
        "speed": ("m/s", 1), "percent": ("%", 1),
    }  # fmt: skip
    assert formats.text(-0.04, "blow_by") == "0.0"  # never "-0.0"
    assert formats.text(12345.678, "tension") == "12,346"


def test_same_quantity_same_decimals_on_design_optimise_and_in_the_tables(thesis_at):
    at = thesis_at
    shown = {
        "total_mass": metric(at, "Total mass [kg]"),
        "volume": metric(at, "Volume [m³]"),
        "blow_by": metric(at, "Blow-by [m]"),
        "alpha_eq": metric(at, "α_eq [deg]"),
        "tension": metric(at, "Tension [N]"),
    }
    for q, text in shown.items():
        assert _decimals(text) == formats.decimals(q), (q, text)
    # the Design tables: the mass table's column, the geometry's volume row, the sweep's blow-by
    show_tab(at, "Mass")
    masses = shown_table(at, "Item")  # the mass table as the page shows it
    assert all(_decimals(v) == formats.decimals("total_mass") for v in masses["Mass [kg]"])
    total = masses.loc[masses["Item"] == "total", "Mass [kg]"].item()
    assert total == shown["total_mass"]  # the same text as the headline metric
    show_tab(at, "Performance")
    where = table(at, "Wind [m/s]")  # "Where it flies", as the page shows it
    assert all(_decimals(v) == formats.decimals("blow_by") for v in where["Blow-by [m]"])
    assert not any(v.startswith("-0.0") or v == "-0" for v in where["Altitude loss [m]"])
    from aerostat_core import design, thesis_baseline
    from aerostat_core.output.report import design_report

    rep = design_report(design(*thesis_baseline()))
    df = tables.performance_frame(rep.performance_rows)
    forces = tables.PERF_TABLES["Forces and stability"]
    for cell in _styled_cells(tables.performance_styler(df, forces), "α_eq [deg]"):
        assert _decimals(cell) == formats.decimals("alpha_eq"), cell
    volume_row = [r for r in rep.geometry_rows].index(
        next(r for r in rep.geometry_rows if r["quantity"] == "Hull volume")
    )
    page = tables.geometry_html(tables.geometry_frame(rep.geometry_rows))  # what the page shows
    cells = re.findall(r'<td class="num">([^<]*)</td>', page)
    assert cells[volume_row] == shown["volume"]
    # the hover text of a Design figure (the interactive charts: a toggle on the tab)
    at.toggle(key="perf_interactive").set_value(True).run()
    blow = chart(at, "perf_blow_by")["data"][0]["hovertemplate"]
    assert f"%{{y:.{formats.decimals('blow_by')}f}}" in blow

    # Optimise: the solver comparison and the Pareto table give the same decimals
    goto(at, OPT_PAGE)
    at.radio(key="opt_level").set_value("Quick")
    at.multiselect(key="opt_solvers").set_value(["slsqp", "pso"])
    at.button(key="opt_run").click().run()
    assert not at.exception, [e.value for e in at.exception]
    best = shown_table(at, "Solver")  # "Optimum of each solver", as the page shows it
    for col, q in (("Total mass [kg]", "total_mass"), ("Volume [m³]", "volume"),
                   ("Blow-by [m]", "blow_by"), ("α_eq [deg]", "alpha_eq")):  # fmt: skip
        assert all(_decimals(v) == formats.decimals(q) for v in best[col]), (col, list(best[col]))
    front = shown_table(at, "Blow-by limit [m]")
    assert all(_decimals(v) == formats.decimals("total_mass") for v in front["Total mass [kg]"])
    spread = next(m for m in messages(at, "success") if "Spread" in m)
    best = re.search(r"best ([\d.,]+) kg", spread).group(1)
    assert _decimals(best) == formats.decimals("total_mass")
    conv = chart(at, "opt_convergence")["data"][0]["hovertemplate"]
    assert "%{y:.1f} kg" in conv


@pytest.mark.parametrize("q", sorted(formats.QUANTITIES))
def test_every_quantity_has_a_kind(q):
    assert formats.kind_of(q) in formats.KINDS


def test_compare_results_use_the_formatting_tables_decimals():
    """The same quantity shows the same decimals on Compare as on the Design page."""
    from aerostat_core import Requirement, design
    from aerostat_core.model.presets import practice_configuration
    from aerostat_core.output.report import comparison_rows
    from app_ui import formats
    from app_ui.tables import comparison_frame

    d = design(Requirement(), practice_configuration())
    df = comparison_frame(comparison_rows({"a": d, "b": d}), ["a", "b"])
    row = dict(zip(df["Quantity"], df["a"]))
    s = d.summary()
    assert row["Total mass [kg]"] == formats.text(s["total_mass_kg"], "total_mass")
    assert row["Blow-by at the design wind [m]"] == formats.text(
        s["blow_by_at_design_wind_m"], "blow_by"
    )
    assert row["Hull volume [m³]"] == formats.text(s["volume_m3"], "volume")
