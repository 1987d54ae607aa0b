"""Design page (AppTest): inputs -> metrics, tables and plotted data; errors next to their group;
save case; file import through the page's handler; state kept across page switches."""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest

from aerostat_core import FABRICS, Requirement, design, thesis_baseline
from aerostat_core.model.io import design_to_json, inputs_from_dict, inputs_to_dict
from app_ui import formats, state
from app_ui.form_model import FIELD_BY_KEY
from tests.app.helpers import (
    COMPARE_PAGE,
    DESIGN_PAGE,
    chart,
    chart_keys,
    field_value,
    goto,
    mass_bars,
    messages,
    metric,
    metric_float,
    perf_charts,
    show_tab,
    side_view,
    submit,
    svg_limit_lines,
    svg_limit_points,
    svg_series,
    table,
    trace,
    values,
)

SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture
def at(thesis_at):
    """These tests check the page against the thesis' numbers: start from the thesis baseline
    (the app itself opens on the practice default)."""
    return thesis_at


def _baseline():
    return design(*thesis_baseline())


def test_opens_on_the_practice_default():
    """A new user sees design(Requirement()): the practice rules, hull sized, limits empty (taken
    from the rule set), the rule set and the binding constraint named, every margin listed."""
    from streamlit.testing.v1 import AppTest

    from tests.app.conftest import APP_PATH, TIMEOUT_S

    app = AppTest.from_file(str(APP_PATH), default_timeout=TIMEOUT_S)
    app.run()
    assert not app.exception
    d = design(Requirement())
    assert app.session_state["design_inputs"] == state.baseline_inputs()
    assert metric_float(app, "Volume [m³]") == pytest.approx(d.volume, abs=0.05)
    assert metric_float(app, "Total mass [kg]") == pytest.approx(d.total_mass, abs=0.05)
    assert app.selectbox(key="in_rules").value == "practice"
    assert app.radio(key="in_volume_mode").value == "sized"
    assert any("Rule set: **practice**" in c.value for c in app.caption)  # title in its help
    # the design placed in its class of thesis Table 2.3, with that class' fielded figures
    # (shown as plain text: markdown characters escaped)
    assert any(c.value.startswith("Class") and "tactical" in c.value and "TCOM 12M" in c.value
               for c in app.caption)
    app.session_state["design_constraints"] = True  # the table is drawn once opened
    app.run()
    rows = table(app, "Constraint")
    assert list(rows["Met"]) == ["yes"] * len(d.constraint_rows())
    assert d.feasible


def test_opens_on_the_thesis_baseline(at):
    d = _baseline()
    assert at.session_state["design_inputs"] == inputs_to_dict(*thesis_baseline())
    assert at.session_state["cases"] == {}
    assert at.title[0].value == "Aerostat design"
    assert metric(at, "Volume [m³]") == "170.0"
    assert metric_float(at, "Total mass [kg]") == pytest.approx(d.total_mass, abs=0.05)
    assert metric_float(at, "Free lift [kg]") == pytest.approx(d.free_lift_kg, abs=0.05)
    assert metric_float(at, "Blow-by [m]") == pytest.approx(d.design_point["blow_by_m"], abs=0.05)
    assert metric_float(at, "Safety factor [-]") == pytest.approx(
        d.design_point["safety_factor"], abs=0.005
    )
    assert metric_float(at, "Gas cost [USD]") == pytest.approx(d.gas_cost, abs=0.5)
    # the baseline meets every requirement (51.3 m blow-by under the 53.4 m limit): no error
    assert d.feasible
    assert not any("Requirements not met" in e for e in messages(at, "error"))
    # every input widget shows the baseline
    assert field_value(at, "in_payload") == 10.0
    assert field_value(at, "in_fin_pos") == pytest.approx(68.0)
    assert field_value(at, "in_hull_gsm") == pytest.approx(130.0)
    assert at.radio(key="in_volume_mode").value == "given"


def test_payload_change_updates_mass_and_lift(at):
    before_mass = metric_float(at, "Total mass [kg]")
    before_lift = metric_float(at, "Free lift [kg]")
    submit(at, in_payload=30.0)
    assert not at.exception
    assert at.session_state["design_inputs"]["requirement"]["payload_mass"] == 30.0
    # the volume is given, so 20 kg more payload is 20 kg more mass and 20 kg less free lift
    assert metric_float(at, "Total mass [kg]") - before_mass == pytest.approx(20.0, abs=0.11)
    assert before_lift - metric_float(at, "Free lift [kg]") == pytest.approx(20.0, abs=0.11)
    show_tab(at, "Mass")
    masses = table(at, "Item")
    assert masses.loc[masses["Item"] == "payload", "Mass [kg]"].item() == pytest.approx(30.0)


def test_sized_volume_follows_the_payload(at):
    submit(at, in_volume_mode="sized", in_payload=30.0)
    req, cfg = thesis_baseline()
    expected = design(replace(req, payload_mass=30.0), cfg.with_design_variables(volume=None))
    assert at.session_state["design_inputs"]["configuration"]["hull"]["volume"] is None
    assert metric_float(at, "Volume [m³]") == pytest.approx(expected.volume, abs=0.05)
    assert metric(at, "Volume [m³]") != "170.0"
    geo = table(at, "Quantity")
    row = geo.loc[geo["Quantity"] == "Hull length l"]
    assert float(row["Value"].item()) == pytest.approx(
        float(expected.airframe.hull.length), abs=0.005  # shown to the centimetre
    )
    side = side_view(at)  # the first tab's static drawing, to scale
    assert side["hull_length"] == pytest.approx(float(expected.airframe.hull.length), rel=1e-3)
    # the 3-D view is the same hull: its mesh spans the new length (fins stay on the hull)
    show_tab(at, "3-D view")
    data = chart(at, "hull_3d")["data"]
    assert len(data) == 1  # one mesh: hull, fins, points and lines (software WebGL cost)
    mesh = next(t for t in data if t["type"] == "mesh3d")
    assert values(mesh, "x").max() == pytest.approx(float(expected.airframe.hull.length))
    assert values(mesh, "x").min() == pytest.approx(0.0, abs=1e-9)


def test_performance_plots_show_the_engine_curves(at):
    """The Performance tab's static charts draw the engine's numbers (SI here; US customary in
    test_units), the requirement lines at their values and the trim point on the C_m curve."""
    d = _baseline()
    p = d.performance
    show_tab(at, "Performance")
    charts = perf_charts(at)
    assert list(charts) == ["perf_blow_by", "perf_alpha", "perf_lift", "perf_tension", "perf_cm"]
    for key, field in (("perf_blow_by", "blow_by"), ("perf_alpha", "alpha_eq"),
                       ("perf_lift", "dynamic_lift")):  # fmt: skip
        x, y = svg_series(charts[key], field)
        np.testing.assert_allclose(x, p.wind_speed, rtol=1e-8)
        np.testing.assert_allclose(y, getattr(p, field), rtol=1e-8, atol=1e-12)
        assert svg_limit_lines(charts[key])["design_wind"] == d.requirement.design_wind
    assert svg_limit_lines(charts["perf_blow_by"])["blow_by_limit"] == pytest.approx(
        d.requirement.blow_by_limit
    )
    assert svg_limit_lines(charts["perf_alpha"])["stall_deg"] == pytest.approx(
        d.configuration.aero.fin_stall_angle_deg
    )
    tension = charts["perf_tension"]
    np.testing.assert_allclose(svg_series(tension, "tension_top")[1], p.tension_top, rtol=1e-8)
    np.testing.assert_allclose(svg_series(tension, "tension_winch")[1], p.tension_winch, rtol=1e-8)
    np.testing.assert_allclose(svg_series(tension, "safety_factor")[1], p.safety_factor, rtol=1e-8)
    sf = next(g for g in tension.iter(f"{SVG}g") if g.get("data-series") == "safety_factor")
    assert sf.get("data-axis") == "y2"  # the right-hand axis, with the required factor on it
    assert svg_limit_lines(tension)["min_safety_factor"] == d.requirement.min_tether_safety_factor
    cm = charts["perf_cm"]
    a, c = svg_series(cm, "cm")
    np.testing.assert_allclose(a, d.cm_alpha_deg, rtol=1e-8)
    np.testing.assert_allclose(c, d.cm, rtol=1e-8, atol=1e-12)
    trim = next(g for g in cm.iter(f"{SVG}g") if g.get("data-trim"))
    a_eq = float(d.design_point["alpha_eq_deg"])
    assert float(trim.get("data-x")) == pytest.approx(a_eq, abs=1e-6)
    assert float(trim.get("data-y")) == pytest.approx(np.interp(a_eq, d.cm_alpha_deg, d.cm))
    perf = table(at, "Wind [m/s]")  # the table as shown: each value at its decimals
    assert len(perf) == d.performance.wind_speed.size
    assert list(perf["Blow-by [m]"]) == [formats.text(v, "blow_by") for v in p.blow_by]
    np.testing.assert_allclose(perf["Blow-by [m]"].astype(float), p.blow_by, atol=0.05)


def test_interactive_charts_are_the_plotly_figures(at):
    """The toggle swaps the drawings for the plotly figures (zoom, hover): the same curves."""
    d = _baseline()
    show_tab(at, "Performance")
    assert chart_keys(at) == []
    at.toggle(key="perf_interactive").set_value(True).run()
    assert not at.exception
    assert perf_charts(at) == {}  # the drawings make way for the figures
    blow = chart(at, "perf_blow_by")
    main = blow["data"][0]
    np.testing.assert_allclose(values(main, "x"), d.performance.wind_speed)
    np.testing.assert_allclose(values(main, "y"), d.performance.blow_by, rtol=1e-9)
    limit_lines = [s for s in blow["layout"]["shapes"] if s["y0"] == s["y1"]]
    assert any(s["y0"] == d.requirement.blow_by_limit for s in limit_lines)
    alpha = chart(at, "perf_alpha")
    np.testing.assert_allclose(values(alpha["data"][0], "y"), d.performance.alpha_eq, rtol=1e-9)
    lift = chart(at, "perf_lift")
    np.testing.assert_allclose(values(lift["data"][0], "y"), d.performance.dynamic_lift, rtol=1e-9)
    tension = chart(at, "perf_tension")
    np.testing.assert_allclose(
        values(trace(tension, "tension at the confluence point [N]"), "y"),
        d.performance.tension_top,
        rtol=1e-9,
    )
    sf = trace(tension, "safety factor [-]")
    assert sf["yaxis"] == "y2"
    np.testing.assert_allclose(values(sf, "y"), d.performance.safety_factor, rtol=1e-9)
    cm = chart(at, "perf_cm")
    np.testing.assert_allclose(values(cm["data"][0], "x"), d.cm_alpha_deg)
    np.testing.assert_allclose(values(cm["data"][0], "y"), d.cm, rtol=1e-9)
    # the lateral block stays on the tab either way
    assert any("C_nβ" in m.value for m in at.markdown)
    at.toggle(key="perf_interactive").set_value(False).run()
    assert chart_keys(at) == [] and len(perf_charts(at)) == 5


def test_rows_over_a_limit_stand_out(at):
    submit(at, in_min_sf=15.0)  # the baseline's safety factor drops below 15 above 13 m/s
    req, cfg = thesis_baseline()
    d = design(replace(req, min_tether_safety_factor=15.0), cfg)
    show_tab(at, "Performance")
    limited = np.asarray(d.performance.limited, bool)
    assert limited.any() and not limited.all()
    speeds = d.performance.wind_speed[limited]
    charts = perf_charts(at)
    for key in ("perf_blow_by", "perf_alpha", "perf_lift", "perf_tension"):
        np.testing.assert_allclose(svg_limit_points(charts[key]), speeds)
        marks = [
            c.get("data-limited")
            for c in charts[key].iter(f"{SVG}circle")
            if c.get("data-limited") is not None
        ]
        assert marks == [str(int(f)) for f in limited]  # every marker says whether it is over
    at.toggle(key="perf_interactive").set_value(True).run()
    for key in ("perf_blow_by", "perf_alpha", "perf_lift", "perf_tension"):
        marks = trace(chart(at, key), "operating limit exceeded")
        np.testing.assert_allclose(values(marks, "x"), speeds)
        assert marks["marker"]["symbol"] == "x"
    perf = table(at, "Wind [m/s]")
    flagged = perf["Limits exceeded"].str.contains("safety factor").to_numpy()
    np.testing.assert_array_equal(flagged, limited)
    warnings = messages(at, "warning")
    assert any("Operating limits exceeded" in w and f"{speeds[0]:g}" in w for w in warnings)
    assert any("safety factor" in e for e in messages(at, "error"))


def test_tether_profiles_are_to_scale_with_winch_and_aerostat(at):
    d = _baseline()
    show_tab(at, "Tether profiles")
    fig = chart(at, "tether_plot")
    assert fig["layout"]["yaxis"]["scaleanchor"] == "x"
    assert fig["layout"]["yaxis"].get("scaleratio", 1) == 1
    winch = trace(fig, "winch")
    assert values(winch, "x").tolist() == [0.0] and values(winch, "y").tolist() == [0.0]
    tops = trace(fig, "aerostat (confluence point)")
    shown = [float(t["name"].split()[0]) for t in fig["data"] if t["name"].endswith(" m/s")]
    assert len(shown) >= 4 and max(shown) == d.requirement.wind_max
    idx = [int(np.argmin(np.abs(d.performance.wind_speed - s))) for s in shown]
    np.testing.assert_allclose(values(tops, "x"), d.performance.blow_by[idx], rtol=1e-6)
    # choose other speeds: the plot follows (fragment rerun)
    at.multiselect(key="tether_speeds").set_value([5.0, 15.0]).run()
    fig = chart(at, "tether_plot")
    names = [t["name"] for t in fig["data"] if t["name"].endswith(" m/s")]
    assert names == ["5 m/s", "15 m/s"]
    profile = trace(fig, "15 m/s")
    np.testing.assert_allclose(values(profile, "x"), d.tether_x[:, 15])
    np.testing.assert_allclose(values(profile, "y"), d.tether_z[:, 15])


def test_geometry_and_mass_tables_have_units_and_match(at):
    d = _baseline()
    geo = table(at, "Quantity")
    assert list(geo.columns) == ["Quantity", "Value", "Unit"]
    expect = {r["quantity"]: r["value"] for r in d.geometry_rows()}
    # the table shows each value at the decimals of its kind (a Markdown table: its texts)
    decimals = {"Hull volume": 1, "Fin leading-edge sweep": 1}
    for q in (
        "Hull volume",
        "Nose semi-axis a1",
        "Tail semi-axis a2",
        "Max radius b",
        "Fin root chord",
        "Fin tip chord",
        "Fin span (exposed, one fin)",
        "Fin leading-edge sweep",
        "Fin root leading edge (from nose)",
    ):
        shown = geo.loc[geo["Quantity"] == q, "Value"].item()
        assert shown == f"{expect[q]:.{decimals.get(q, 2)}f}", q
    assert geo.loc[geo["Quantity"] == "Hull volume", "Unit"].item() == "m³"
    show_tab(at, "Mass")
    mass = table(at, "Item")
    assert list(mass.columns) == ["Item", "Mass [kg]", "Share [%]"]
    parts = mass[mass["Item"] != "total"]
    total = mass.loc[mass["Item"] == "total", "Mass [kg]"].item()
    assert parts["Mass [kg]"].sum() == pytest.approx(total)
    assert total == pytest.approx(d.total_mass)
    bars = mass_bars(at)  # the static bar chart: one bar per item, as in the table
    assert list(bars) == list(parts["Item"])
    assert list(bars.values()) == pytest.approx(list(parts["Mass [kg]"]))


def test_side_view_marks_buoyancy_gravity_and_confluence(at):
    d = _baseline()
    af = d.airframe
    # the first tab: a static drawing to scale (no plotly.js before the first result)
    side = side_view(at)
    assert side["points"]["cb"][0] == pytest.approx(float(af.hull.xi_cb))
    assert side["points"]["cg"][0] == pytest.approx(float(af.mass.xi_cg))
    assert side["points"]["c"] == pytest.approx((float(af.xi_c), float(af.z_c)))
    assert side["hull_length"] == pytest.approx(float(af.hull.length), rel=1e-3)
    assert side["parts"].count("confluence line") >= 2 and "fin" in side["parts"]
    # the interactive side view, in a section drawn once opened: the same points
    assert "side_view" not in chart_keys(at)
    at.session_state["side_view_interactive"] = True
    at.run()
    fig = chart(at, "side_view")
    cb = trace(fig, "centre of buoyancy (CB)")
    cg = trace(fig, "centre of gravity (CG)")
    c = trace(fig, "confluence point (C)")
    assert values(cb, "x")[0] == pytest.approx(float(af.hull.xi_cb))
    assert values(cg, "x")[0] == pytest.approx(float(af.mass.xi_cg))
    assert values(c, "x")[0] == pytest.approx(float(af.xi_c))
    assert values(c, "y")[0] == pytest.approx(float(af.z_c))
    lines = [t for t in fig["data"] if t.get("legendgroup") == "cl"]
    assert len(lines) >= 2
    for ln in lines:  # every confluence line starts at the confluence point
        assert values(ln, "x")[0] == pytest.approx(float(af.xi_c))
    assert fig["layout"]["yaxis"]["scaleanchor"] == "x"


def test_rejected_input_shows_next_to_its_group_and_changes_nothing(at):
    before = json.dumps(at.session_state["design_inputs"], sort_keys=True)
    volume_before = metric(at, "Volume [m³]")
    submit(at, in_blow_by=400.0, in_payload=25.0)  # limit above the 300 m altitude
    assert not at.exception
    errors = messages(at, "error")
    assert any("Blow-by limit at the design wind [m]" in e and "Not applied" in e for e in errors)
    warnings = messages(at, "warning")
    assert any("Wind and operating limits" in w for w in warnings)
    assert json.dumps(at.session_state["design_inputs"], sort_keys=True) == before
    assert metric(at, "Volume [m³]") == volume_before
    assert at.session_state["input_error"]["group"] == "wind"
    # the user's values stay in the form to be fixed; fixing them applies both changes
    assert field_value(at, "in_blow_by") == 400.0
    submit(at, in_blow_by=40.0)
    assert "input_error" not in at.session_state
    assert at.session_state["design_inputs"]["requirement"]["blow_by_limit"] == 40.0
    assert at.session_state["design_inputs"]["requirement"]["payload_mass"] == 25.0


@pytest.mark.parametrize(
    "widgets, group, key",
    [
        ({"in_payload": 20000.0}, "requirement", "in_payload"),
        ({"in_altitude": 5.0}, "requirement", "in_altitude"),
        ({"in_wind_max": 65.0}, "wind", "in_wind_max"),
        ({"in_purity": 120.0}, "gas", "in_purity"),
        ({"in_hull_fabric": "Custom", "in_hull_gsm": 0.0}, "materials", "in_hull_gsm"),
        ({"in_fineness": 9.0}, "configuration", "in_fineness"),
        ({"in_fin_pos": 99.0}, "configuration", "in_fin_pos"),
        ({"in_fin_ar": 9.0}, "advanced", "in_fin_ar"),
        ({"in_segments": 5}, "advanced", "in_segments"),
        ({"in_payload": ""}, "requirement", "in_payload"),
        ({"in_altitude": "3,5,0"}, "requirement", "in_altitude"),
    ],
)
def test_each_rejected_input_is_reported_in_its_group(at, widgets, group, key):
    before = json.dumps(at.session_state["design_inputs"], sort_keys=True)
    submit(at, **widgets)
    assert not at.exception
    err = at.session_state["input_error"]
    assert err["group"] == group and err["key"] == key
    label = FIELD_BY_KEY[key].label
    assert err["text"].startswith(f"{label}: ")  # the form's label and unit, not Class.field
    assert "." not in err["text"].split(":")[0].replace("Δl_f", "")
    assert any(e.startswith(f"Not applied: {label}") for e in messages(at, "error"))
    assert json.dumps(at.session_state["design_inputs"], sort_keys=True) == before


def test_an_emptied_box_says_required_not_zero(at):
    submit(at, in_payload="")
    assert at.session_state["input_error"]["text"] == "Payload mass [kg]: required; enter a value."
    assert at.session_state["design_inputs"]["requirement"]["payload_mass"] == 10.0


def test_a_decimal_comma_is_read_as_a_point(at):
    submit(at, in_payload="12,5")
    assert "input_error" not in at.session_state
    assert at.session_state["design_inputs"]["requirement"]["payload_mass"] == 12.5
    assert field_value(at, "in_payload") == 12.5


def test_after_a_rejected_submit_the_results_say_they_are_the_last_valid_inputs(at):
    assert any("Meets every requirement" in m for m in messages(at, "success"))
    submit(at, in_payload=20000.0)
    warnings = messages(at, "warning")
    assert any("last valid inputs" in w for w in warnings)
    assert not any(m.startswith("Meets every requirement") for m in messages(at, "success"))
    submit(at, in_payload=10.0)
    assert not any("last valid inputs" in w for w in messages(at, "warning"))


def test_custom_fabric_and_catalogue_tether(at):
    d0 = _baseline()
    submit(at, in_hull_fabric="Custom", in_hull_gsm=260.0)
    hull_fabric = at.session_state["design_inputs"]["configuration"]["hull_fabric"]
    assert hull_fabric["areal_density"] == pytest.approx(0.260)
    show_tab(at, "Mass")
    mass = table(at, "Item")
    hull = mass.loc[mass["Item"] == "hull", "Mass [kg]"].item()
    assert hull == pytest.approx(2 * float(d0.airframe.mass.items["hull"]))
    name = "Dyneema 4 mm (9 g/m)"
    submit(at, in_tether=name)
    tether = at.session_state["design_inputs"]["configuration"]["tether"]
    assert tether["name"] == name and tether["linear_density"] == pytest.approx(0.009)
    # the custom boxes now show the catalogue tether's values
    assert field_value(at, "in_tether_lin") == pytest.approx(9.0)
    assert at.selectbox(key="in_hull_fabric").value == "Custom"
    assert "Heavy laminate (300 g/m2)" in FABRICS


def test_load_thesis_baseline_resets_inputs_and_form(at):
    submit(at, in_payload=42.0, in_volume_mode="sized")
    assert at.session_state["design_inputs"]["requirement"]["payload_mass"] == 42.0
    at.button[0].click().run()  # "Load thesis baseline"
    assert at.button[0].label == "Load thesis baseline"
    assert at.session_state["design_inputs"] == inputs_to_dict(*thesis_baseline())
    assert field_value(at, "in_payload") == 10.0
    assert at.radio(key="in_volume_mode").value == "given"
    assert metric(at, "Volume [m³]") == "170.0"


def test_save_case_with_default_and_given_names(at):
    save = [b for b in at.button if b.label == "Save case"][0]
    save.click().run()
    cases = at.session_state["cases"]
    assert list(cases) == ["Case 1: 10 kg at 300 m"]
    assert cases["Case 1: 10 kg at 300 m"] == at.session_state["design_inputs"]
    assert any("Saved case" in s for s in messages(at, "success"))
    submit(at, in_payload=30.0)
    at.text_input(key="case_name").set_value("heavy payload")
    [b for b in at.button if b.label == "Save case"][0].click().run()
    assert list(at.session_state["cases"]) == ["Case 1: 10 kg at 300 m", "heavy payload"]
    saved = inputs_from_dict(at.session_state["cases"]["heavy payload"])
    assert saved[0].payload_mass == 30.0


def test_inputs_and_cases_survive_page_switches(at):
    submit(at, in_payload=17.0, in_fineness=3.2)
    [b for b in at.button if b.label == "Save case"][0].click().run()
    goto(at, COMPARE_PAGE)
    assert not at.exception
    goto(at, DESIGN_PAGE)
    assert not at.exception
    assert field_value(at, "in_payload") == 17.0
    assert field_value(at, "in_fineness") == pytest.approx(3.2)
    assert at.session_state["design_inputs"]["requirement"]["payload_mass"] == 17.0
    assert len(at.session_state["cases"]) == 1
    assert metric_float(at, "Length [m]") != pytest.approx(_baseline().summary().length_m)


def test_importing_a_design_file_restores_inputs(at):
    req, cfg = thesis_baseline()
    text = design_to_json(
        replace(req, payload_mass=22.0, altitude=400.0),
        cfg.with_design_variables(fineness_ratio=3.5),
    )
    level, msg = state.handle_upload(text.encode(), "design", at.session_state)
    assert level == "success"
    at.run()
    assert not at.exception
    assert field_value(at, "in_payload") == 22.0
    assert field_value(at, "in_altitude") == 400.0
    assert field_value(at, "in_fineness") == 3.5
    assert any("Loaded the design inputs" in s for s in messages(at, "success"))


@pytest.mark.parametrize(
    "payload, fragment",
    [
        (b'{"requirement": {"payload_mass": "heavy"}}', "payload_mass"),
        (b'{"requirement": {"payload_mass": -3}}', "payload_mass"),
        (b'{"requirement": {"altitude": 300}, "oops": 1}', "unknown field"),
        (b'{"configuration": {"tether_segments": 1e400}}', "tether_segments"),
        (b"not json at all", "not valid JSON"),
        (b"[" * 50_000 + b"]" * 50_000, "nested too deeply"),
        (b" " * 1_000_001, "limit"),
    ],
)
def test_a_bad_design_file_shows_a_message_and_changes_nothing(at, payload, fragment):
    before = json.dumps(at.session_state["design_inputs"], sort_keys=True)
    level, msg = state.handle_upload(payload, "design", at.session_state)
    assert level == "error" and fragment in msg
    at.run()
    assert not at.exception
    errors = messages(at, "error")
    assert any("Could not import" in e and "Nothing was changed" in e for e in errors)
    assert json.dumps(at.session_state["design_inputs"], sort_keys=True) == before
    assert field_value(at, "in_payload") == 10.0
    assert at.session_state["cases"] == {}


def test_corrupt_state_falls_back_to_the_baseline(at):
    at.session_state["design_inputs"] = {"requirement": {"payload_mass": "x"}}
    at.run()
    assert not at.exception
    # the corrupt inputs are replaced by the app's default (practice rules, hull sized)
    assert at.session_state["design_inputs"] == state.baseline_inputs()
    assert metric_float(at, "Volume [m³]") == pytest.approx(design(Requirement()).volume, abs=0.05)


def test_downloads_are_offered_in_every_tab(at):
    def labels():
        return [b.proto.label for b in at.get("download_button")]

    assert "Geometry table (CSV)" in labels()
    # the design file's section is drawn once opened (its uploader's code is not on the way
    # to a fresh browser's first result)
    assert "Download design inputs (JSON)" not in labels()
    assert not at.get("file_uploader")
    at.session_state["design_file"] = True
    at.run()
    assert "Download design inputs (JSON)" in labels()
    assert [u.proto.label for u in at.get("file_uploader")] == [
        "Upload a design or cases file (JSON)"
    ]
    for tab, label in (
        ("Mass", "Mass table (CSV)"),
        ("Performance", "Performance table (CSV)"),
        ("Tether profiles", "Tether profiles (CSV)"),
    ):
        show_tab(at, tab)
        assert label in labels(), tab


def test_only_the_open_tab_is_computed(at):
    assert chart_keys(at) == []  # the first tab draws no chart: its side view is static
    show_tab(at, "3-D view")
    assert chart_keys(at) == ["hull_3d"]
    show_tab(at, "Performance")
    assert chart_keys(at) == []  # static drawings; the plotly figures behind a toggle
    assert list(perf_charts(at)) == [
        "perf_blow_by", "perf_alpha", "perf_lift", "perf_tension", "perf_cm"
    ]
    submit(at, in_payload=12.0)  # the open tab stays open after a change
    assert "perf_blow_by" in perf_charts(at)
