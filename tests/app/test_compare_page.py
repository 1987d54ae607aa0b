"""Compare page (AppTest): saved cases side by side with differences highlighted, overlaid curves
and tether profiles, thesis GUI test cases, rename/delete/load, cases-file import."""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest

from aerostat_core import design, thesis_baseline
from aerostat_core.model.io import cases_to_json, inputs_from_dict, inputs_to_dict
from aerostat_core.output.report import thesis_gui_cases
from app_ui import state
from tests.app.helpers import (
    COMPARE_PAGE,
    DESIGN_PAGE,
    chart,
    field_value,
    goto,
    messages,
    raw_messages,
    show_tab,
    submit,
    table,
    trace,
    values,
)

GUI = list(thesis_gui_cases())


@pytest.fixture
def at(thesis_at):
    """These tests check the page against the thesis' numbers: start from the thesis baseline
    (the app itself opens on the practice default)."""
    return thesis_at


def _button(at, label):
    return next(b for b in at.button if b.label == label)


@pytest.fixture
def compare(at):
    goto(at, COMPARE_PAGE)
    assert not at.exception
    return at


@pytest.fixture
def with_gui_cases(compare):
    _button(compare, "Load the thesis' GUI test cases").click().run()
    assert not compare.exception
    return compare


def test_empty_page_explains_how_to_get_cases(compare):
    assert compare.title[0].value == "Compare saved cases"
    assert any("No saved cases yet" in i for i in messages(compare, "info"))
    assert compare.get("plotly_chart") == [] or len(compare.get("plotly_chart")) == 0


def test_gui_test_cases_side_by_side(with_gui_cases):
    at = with_gui_cases
    assert list(at.session_state["cases"]) == GUI
    df = table(at, "Section")
    assert list(df.columns) == ["Section", "Quantity", *GUI, "Differs"]
    payload = df[df["Quantity"] == "Payload mass [kg]"].iloc[0]
    assert [payload[n] for n in GUI] == ["10", "30", "10", "10"]
    assert payload["Differs"] == "yes"
    fineness = df[df["Quantity"] == "Fineness ratio l/d [-]"].iloc[0]
    assert fineness["Differs"] == "no"
    designs = {n: design(*inputs_from_dict(c)) for n, c in thesis_gui_cases().items()}
    vol = df[df["Quantity"] == "Hull volume [m³]"].iloc[0]
    for n in GUI:
        assert float(vol[n].replace(",", "")) == pytest.approx(designs[n].volume, abs=0.06)
    assert any("rows differ" in c.value for c in at.caption)


def test_only_differences_toggle(with_gui_cases):
    at = with_gui_cases
    n_all = len(table(at, "Section"))
    at.toggle(key="compare_only_diff").set_value(True).run()
    df = table(at, "Section")
    assert 0 < len(df) < n_all
    assert (df["Differs"] == "yes").all()
    assert "Payload mass [kg]" in set(df["Quantity"])
    assert "Fineness ratio l/d [-]" not in set(df["Quantity"])


def tab(at, label):
    return show_tab(at, label, key="compare_tab")


def test_overlaid_curves_one_line_per_case(with_gui_cases):
    at = with_gui_cases
    tab(at, "Performance")
    designs = {n: design(*inputs_from_dict(c)) for n, c in thesis_gui_cases().items()}
    for key, attr in (
        ("cmp_blow_by", "blow_by"),
        ("cmp_alpha", "alpha_eq"),
        ("cmp_lift", "dynamic_lift"),
        ("cmp_tension", "tension_top"),
    ):
        fig = chart(at, key)
        for n in GUI:
            tr = trace(fig, n)
            np.testing.assert_allclose(values(tr, "x"), designs[n].performance.wind_speed)
            np.testing.assert_allclose(
                values(tr, "y"), getattr(designs[n].performance, attr), rtol=1e-9
            )


def test_overlaid_tether_profiles_to_scale(with_gui_cases):
    at = with_gui_cases
    tab(at, "Tether profiles")
    fig = chart(at, "cmp_tether")
    assert fig["layout"]["yaxis"]["scaleanchor"] == "x"
    names = [t["name"] for t in fig["data"] if t.get("showlegend", True) and t["name"] != "winch"]
    designs = {n: design(*inputs_from_dict(c)) for n, c in thesis_gui_cases().items()}
    # the design wind of every case (the practice rules: 10 m/s)
    assert names == [f"{n} ({designs[n].requirement.design_wind:g} m/s)" for n in GUI]
    tops = {n: values(trace(fig, f"{n}: aerostat"), "y")[0] for n in GUI}
    # the 500 m case flies highest, the 100 m case lowest
    assert (
        tops["GUI test: altitude 500 m, 10 kg"]
        > tops[GUI[0]]
        > tops["GUI test: altitude 100 m, 10 kg"]
    )
    u = designs[GUI[1]].requirement.design_wind
    xu = values(trace(fig, f"{GUI[1]} ({u:g} m/s)"), "x")
    np.testing.assert_allclose(xu, designs[GUI[1]].tether_x[:, int(u)])
    at.select_slider(key="compare_wind").set_value(5.0).run()
    fig = chart(at, "cmp_tether")
    assert fig["layout"]["title"]["text"].replace("<br>", " ").startswith("Tether profiles at 5 m/s")


def test_two_saved_designs_compared(at):
    submit(at, in_payload=10.0)
    at.text_input(key="case_name").set_value("light")
    _button(at, "Save case").click().run()
    submit(at, in_payload=30.0, in_volume_mode="sized")
    at.text_input(key="case_name").set_value("heavy")
    _button(at, "Save case").click().run()
    goto(at, COMPARE_PAGE)
    assert not at.exception
    df = table(at, "Section")
    assert list(df.columns) == ["Section", "Quantity", "light", "heavy", "Differs"]
    diff = df[df["Differs"] == "yes"]
    assert {"Payload mass [kg]", "Hull volume [m³]", "Total mass [kg]"} <= set(diff["Quantity"])
    tab(at, "Performance")
    fig = chart(at, "cmp_blow_by")
    assert [t["name"] for t in fig["data"] if t.get("showlegend", True)] == ["light", "heavy"]


def test_deselecting_a_case_drops_its_column(with_gui_cases):
    at = with_gui_cases
    at.multiselect(key="compare_selected").set_value(GUI[:2]).run()
    df = table(at, "Section")
    assert list(df.columns) == ["Section", "Quantity", *GUI[:2], "Differs"]
    tab(at, "Performance")
    fig = chart(at, "cmp_blow_by")
    assert {t["name"] for t in fig["data"] if t.get("showlegend", True)} == set(GUI[:2])


def test_rename_and_refuse_duplicates(with_gui_cases):
    at = with_gui_cases
    tab(at, "Manage cases")
    at.selectbox(key="rename_from").set_value(GUI[1])
    at.text_input(key="rename_to").set_value("thirty kilos")
    _button(at, "Rename").click().run()
    assert list(at.session_state["cases"]) == [GUI[0], "thirty kilos", *GUI[2:]]
    assert any("Renamed" in s for s in messages(at, "success"))
    tab(at, "Side by side")
    assert "thirty kilos" in table(at, "Section").columns
    tab(at, "Manage cases")
    at.selectbox(key="rename_from").set_value("thirty kilos")
    at.text_input(key="rename_to").set_value(GUI[0])
    _button(at, "Rename").click().run()
    assert any("exists already" in e for e in messages(at, "error"))
    assert "thirty kilos" in at.session_state["cases"]


def test_a_rename_updates_the_pickers_and_a_second_rename_works(with_gui_cases):
    at = with_gui_cases
    tab(at, "Manage cases")
    at.selectbox(key="rename_from").set_value(GUI[1])
    at.text_input(key="rename_to").set_value("first rename")
    _button(at, "Rename").click().run()
    assert at.selectbox(key="rename_from").value == "first rename"
    assert "first rename" in at.multiselect(key="compare_selected").value
    assert GUI[1] not in at.selectbox(key="rename_from").options
    at.text_input(key="rename_to").set_value("second rename")  # the picker already shows it
    _button(at, "Rename").click().run()
    assert not at.exception
    assert list(at.session_state["cases"])[1] == "second rename"
    assert at.selectbox(key="rename_from").value == "second rename"
    assert any("Renamed “first rename” to “second rename”" in m for m in messages(at, "success"))


def test_loading_the_gui_cases_twice_adds_nothing(with_gui_cases):
    at = with_gui_cases
    _button(at, "Load the thesis' GUI test cases").click().run()
    assert not at.exception
    assert len(at.session_state["cases"]) == 4
    assert any("saved already" in m for m in messages(at, "info"))


def test_import_can_replace_the_saved_cases(with_gui_cases):
    at = with_gui_cases
    assert at.radio(key="import_mode").value == "add"
    one = {GUI[0]: at.session_state["cases"][GUI[0]]}
    level, msg = state.handle_upload(
        cases_to_json(one).encode(), "compare", at.session_state, mode="replace"
    )
    assert level == "success" and "Replaced" in msg
    at.run()
    assert list(at.session_state["cases"]) == [GUI[0]]


def test_a_comparison_over_the_compute_budget_is_a_message(compare):
    at = compare
    req, cfg = thesis_baseline()
    big = inputs_to_dict(req, replace(cfg, tether_segments=2000))
    state.add_cases({f"big {i}": big for i in range(12)}, at.session_state)
    at.run()
    assert not at.exception
    assert any("units of work" in e and "fewer cases" in e for e in messages(at, "error"))


def test_hostile_case_names_show_as_plain_text(compare):
    at = compare
    name = "![i](http://example.invalid/x.png) *bold* <b>b</b>"
    state.save_case(name, *thesis_baseline(), at.session_state)
    at.run()
    assert not at.exception
    tab(at, "Performance")
    fig = chart(at, "cmp_blow_by")
    assert (
        fig["data"][0]["name"] == "![i](http://example.invalid/x.png) *bold* &lt;b&gt;b&lt;/b&gt;"
    )
    raw = [m for m in raw_messages(at, "success") + raw_messages(at, "error") if "example" in m]
    assert all("\\!\\[i\\]" in m for m in raw)


def test_delete_cases(with_gui_cases):
    at = with_gui_cases
    tab(at, "Manage cases")
    at.multiselect(key="delete_names").set_value(GUI[2:])
    _button(at, "Delete").click().run()
    assert not at.exception
    assert list(at.session_state["cases"]) == GUI[:2]
    tab(at, "Side by side")
    assert list(table(at, "Section").columns) == ["Section", "Quantity", *GUI[:2], "Differs"]
    tab(at, "Manage cases")
    at.multiselect(key="delete_names").set_value(GUI[:2])
    _button(at, "Delete").click().run()
    assert at.session_state["cases"] == {}
    assert any("No saved cases yet" in i for i in messages(at, "info"))


def test_open_a_case_on_the_design_page(with_gui_cases):
    at = with_gui_cases
    tab(at, "Manage cases")
    at.selectbox(key="load_name").set_value(GUI[1])
    _button(at, "Make it the current design").click().run()
    assert at.session_state["design_inputs"] == at.session_state["cases"][GUI[1]]
    goto(at, DESIGN_PAGE)
    assert not at.exception
    assert field_value(at, "in_payload") == 30.0
    assert at.radio(key="in_volume_mode").value == "sized"


def test_import_cases_file_adds_with_unique_names(with_gui_cases):
    at = with_gui_cases
    text = cases_to_json(thesis_gui_cases())
    level, msg = state.handle_upload(text.encode(), "compare", at.session_state)
    assert level == "info" and "nothing was added" in msg  # re-importing duplicates nothing
    at.run()
    assert any("nothing was added" in s for s in messages(at, "info"))
    at.run()  # the message is shown once, not left next to the next file's
    assert not any("nothing was added" in s for s in messages(at, "info"))
    changed = json.loads(text)
    for case in changed["cases"].values():
        case["requirement"]["payload_mass"] = 12.5
    up = state.handle_upload(json.dumps(changed).encode(), "compare", at.session_state)
    assert up[0] == "success" and "Added 4 case(s)" in up[1]
    at.run()
    assert not at.exception
    names = list(at.session_state["cases"])
    assert len(names) == 8 and f"{GUI[0]} (2)" in names
    assert any("Added 4 case(s)" in s for s in messages(at, "success"))


def test_bad_cases_file_changes_nothing(with_gui_cases):
    at = with_gui_cases
    good = json.loads(cases_to_json(thesis_gui_cases()))
    good["cases"]["broken"] = {"requirement": {"altitude": "high"}}
    before = dict(at.session_state["cases"])
    level, msg = state.handle_upload(json.dumps(good).encode(), "compare", at.session_state)
    assert level == "error" and "broken" in msg and "altitude" in msg
    at.run()
    assert not at.exception
    assert any("Could not import" in e for e in messages(at, "error"))
    assert at.session_state["cases"] == before


def test_only_the_open_tab_is_computed(with_gui_cases):
    at = with_gui_cases
    assert at.get("plotly_chart") == [] or len(at.get("plotly_chart")) == 0
    tab(at, "Performance")
    assert len(at.get("plotly_chart")) == 4
    assert len(at.dataframe) == 0


def test_exports_are_offered(with_gui_cases):
    labels = [b.proto.label for b in with_gui_cases.get("download_button")]
    for label in (
        "Download all cases (JSON)",
        "Download all cases (CSV)",
        "Comparison table (CSV)",
    ):
        assert label in labels


def test_case_limit_is_a_message_not_a_traceback(compare):
    from aerostat_core.model.io import MAX_CASES

    at = compare
    one = thesis_gui_cases()[GUI[0]]
    state.add_cases({f"c{i}": one for i in range(MAX_CASES - 2)}, at.session_state)  # saved
    at.run()
    _button(at, "Load the thesis' GUI test cases").click().run()
    assert not at.exception
    assert any("at most" in e for e in messages(at, "error"))
    assert len(at.session_state["cases"]) == MAX_CASES - 2
