"""Design page, Envelope tab: heat map with limit boundaries, flyable time, Monte Carlo and the
report download (AppTest, no browser)."""

from __future__ import annotations

import json

import numpy as np

from aerostat_core import design
from aerostat_core.model.io import inputs_from_dict
from aerostat_core.studies.site_wind import flyable_time
from tests.app.helpers import chart, metric, raw_messages, show_tab, trace, values


def test_envelope_tab_shows_heat_map_flyable_time_and_bands(at):
    show_tab(at, "Envelope")
    assert not at.exception, [e.value for e in at.exception]
    fig = chart(at, "envelope_map")
    heat = fig["data"][0]
    assert heat["type"] == "heatmap"
    z = values(heat, "z")
    assert z.ndim == 2 and z.size >= 200 and np.nanmin(z) < 0 < np.nanmax(z)
    lines = [t["name"] for t in fig["data"] if t["type"] == "contour"]
    assert "Blow-by" in lines  # a limit boundary crosses the map
    assert trace(fig, "design point")["mode"] == "markers"
    d = design(*inputs_from_dict(at.session_state["design_inputs"]))
    pct = flyable_time(d).percent_time_flyable
    assert metric(at, "Time flyable [%]") == f"{pct:.1f}"
    # Monte Carlo on demand
    at.selectbox(key="mc_n").set_value(1000)
    at.button(key="FormSubmitter:mc_form-Run Monte Carlo").click()
    at.run()
    assert not at.exception, [e.value for e in at.exception]
    lo, hi = (float(x) for x in metric(at, "Blow-by 5-95 % [m]").split("–"))
    assert lo < d.design_point["blow_by_m"] < hi
    assert "mc_bands" in [getattr(e, "key", None) for e in at.get("plotly_chart")]
    labels = [b.proto.label for b in at.get("download_button")]
    assert "Design report (HTML)" in labels


def test_bad_wind_csv_gets_a_message_not_a_traceback(at):
    show_tab(at, "Envelope")
    spec = {
        "kind": "csv",
        "shape": 2.0,
        "scale": 6.0,
        "reference_height": 10.0,
        "shear_exponent": 0.14,
        "target": 0.95,
    }
    bad = b"time,speed\n2009-01-01 00:00,**gusty**\n2009-01-01 01:00,3\n"
    at.session_state["envelope_site"] = {"json": json.dumps(spec), "csv": bad}
    at.run()
    assert not at.exception
    # the cell is quoted as plain text, its markdown escaped
    assert any(
        r"row 1: '\*\*gusty\*\*' is not a wind speed" in m for m in raw_messages(at, "error")
    )


def test_site_boxes_read_a_decimal_comma_or_name_the_box(at):
    show_tab(at, "Envelope")
    at.text_input(key="site_c").set_value("6,5")  # 6.5 m/s, never 65
    at.button(key="FormSubmitter:site_form-Compute flyable time").click().run()
    assert not at.exception
    assert json.loads(at.session_state["envelope_site"]["json"])["scale"] == 6.5
    at.text_input(key="site_k").set_value("2,0,1")
    at.button(key="FormSubmitter:site_form-Compute flyable time").click().run()
    errors = raw_messages(at, "error")
    assert any("Weibull k" in e and "ambiguous" in e for e in errors), errors
