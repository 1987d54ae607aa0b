"""Shapes page and the shape choice on the Design / Sensitivity pages (AppTest, issue 12)."""

from __future__ import annotations

import pandas as pd
import pytest

from aerostat_core.studies.shape_comparison import thesis_shape_comparison
from tests.app.helpers import (
    DESIGN_PAGE,
    chart,
    goto,
    messages,
    side_view,
    submit,
    trace,
    values,
)

SHAPES_PAGE = "pages/7_Shapes.py"


def test_shapes_page_shows_table_2_2_and_figure_2_5(at):
    goto(at, SHAPES_PAGE)
    assert not at.exception, [e.value for e in at.exception]
    fig = chart(at, "shape_fig_thesis")
    ref = {r["key"]: r for r in thesis_shape_comparison().rows}
    bb = {
        name: values(trace(fig, name), "y")[-1]
        for name in ("Helikite", "Spherical", "Streamlined (NPL, f = 2.7)")
    }
    assert bb["Streamlined (NPL, f = 2.7)"] < bb["Helikite"] < bb["Spherical"]
    assert bb["Spherical"] == pytest.approx(ref["sphere"]["blow_by_at_design_wind_m"])
    assert "shape_fig_full" in [getattr(e, "key", None) for e in at.get("plotly_chart")]
    # static tables (every cell in sight at 1024 px): library, thesis vs this model, full model
    assert len(at.table) >= 3
    lib = pd.concat([t.value for t in at.table if "C_p [-]" in t.value.index], axis=1)
    assert len(lib.columns) == 8 and "GNVR" in lib.columns
    assert {"l/d [-]", "C_p [-]", "Area / V^(2/3) [-]"} <= set(lib.index)
    assert any("GNVR: Ellipse + circular arc + parabola" in str(c.value) for c in at.caption)
    versus = [t.value for t in at.table if "Hull [kg]" in t.value.index][0]
    assert float(versus.loc["Hull [kg]", ("Spherical", "thesis")]) == 13.54
    hull = float(versus.loc["Hull [kg]", ("Spherical", "this model")])
    assert hull == pytest.approx(13.54, rel=0.02)
    assert any("same blow-by ranking" in str(m.value) for m in at.markdown)


def test_shapes_page_optimises_every_shape(at):
    goto(at, SHAPES_PAGE)
    at.button(key="shape_opt_run").click()
    at.run()
    assert not at.exception, [e.value for e in at.exception]
    assert any("Best shape" in m for m in messages(at, "success"))
    t = [df.value for df in [*at.dataframe, *at.table] if "Best" in df.value.columns][0]
    assert len(t) == 8 and t["Best"].sum() == 1
    pos = t["Δl_f [% of l]"].dropna()  # the fin position in % of the hull length, as elsewhere
    assert len(pos) and ((pos >= 40) & (pos <= 95)).all()


def test_design_page_shape_selector_resets_fineness_and_redraws(at):
    assert at.selectbox(key="in_shape").value == "npl"
    submit(at, in_shape="sphere")
    assert not at.exception, [e.value for e in at.exception]
    hull = at.session_state["design_inputs"]["configuration"]["hull"]
    assert hull["shape"] == "sphere" and hull["fineness_ratio"] == 1.0
    assert not any("not applied" in m for m in messages(at, "warning"))
    side = side_view(at)
    assert side["hull_length"] == pytest.approx(side["hull_height"], rel=1e-2)  # a circle, to scale
    assert "Hull and fins (STL)" not in [b.label for b in at.get("download_button")]  # lazy
    at.session_state["design_exports"] = True  # open "Build it"
    at.run()
    names = [b.label for b in at.get("download_button")]
    exports = {"STL: hull and fins", "DXF: gore patterns", "SVG: gore patterns"}
    assert exports | {"CSV: gore half-widths"} <= set(names)
    # no two export buttons share their first 14 characters (what a narrow button shows
    # before its ellipsis: "Gore patterns (..." was both the DXF and the SVG button)
    assert len({n[:14] for n in exports}) == len(exports)


def test_design_page_rejects_fineness_outside_the_shape_range(at):
    submit(at, in_shape="gnvr")
    submit(at, in_fineness=7.0)
    assert any("for shape 'gnvr'" in m for m in messages(at, "error"))


def test_sensitivity_page_has_a_per_shape_sweep(at):
    goto(at, "pages/3_Sensitivity.py")
    assert not at.exception, [e.value for e in at.exception]
    at.button(key="sens_shapes_run").click()
    at.run()
    assert not at.exception, [e.value for e in at.exception]
    fig = chart(at, "sens_shapes")
    assert len(fig["data"]) == 8
    goto(at, DESIGN_PAGE)
