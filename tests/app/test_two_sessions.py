"""Two sessions of the app on one workspace (AppTest, the pages' own buttons and callbacks), on
SQLite and on PostgreSQL: import, save, rename, delete and replace in one tab never lose or
overwrite what the other tab saved (issue 20's repros)."""

from __future__ import annotations

from dataclasses import replace

import pytest
from streamlit.testing.v1 import AppTest

from aerostat_core import thesis_baseline
from aerostat_core.model.io import cases_to_json, inputs_to_dict
from aerostat_core.output.report import thesis_gui_cases
from app_ui import store
from tests.app.conftest import APP_PATH, TIMEOUT_S
from tests.app.helpers import COMPARE_PAGE, goto, messages, show_tab
from tests.app.test_store import PG_URL, _require_pg

GUI = list(thesis_gui_cases())


@pytest.fixture(params=["sqlite", "postgresql"])
def backend(request, monkeypatch, tmp_path):
    """The app's store: a fresh SQLite folder, or the PostgreSQL test server."""
    if request.param == "postgresql":
        _require_pg()
        monkeypatch.setenv("AEROSTAT_DATABASE_URL", PG_URL)
    else:
        monkeypatch.setenv("AEROSTAT_DATA_DIR", str(tmp_path / "data"))
    yield store.get_store()


def _session(token: str | None = None, page: str | None = None, payload: float | None = None):
    at = AppTest.from_file(str(APP_PATH), default_timeout=TIMEOUT_S)
    if token:
        at.query_params["ws"] = token
    if payload is not None:
        req, cfg = thesis_baseline()
        at.session_state["design_inputs"] = inputs_to_dict(replace(req, payload_mass=payload), cfg)
    at.run()
    assert not at.exception, [e.value for e in at.exception]
    if page:
        goto(at, page)
        assert not at.exception, [e.value for e in at.exception]
    return at


def _token(at) -> str:
    return at.session_state["_workspace"]


def _button(at, label: str):
    return next(b for b in at.button if b.label == label)


def _save(at, name: str) -> None:
    at.text_input(key="case_name").set_value(name)
    _button(at, "Save case").click().run()
    assert not at.exception, [e.value for e in at.exception]


def _payload(inputs: dict) -> float:
    return inputs["requirement"]["payload_mass"]


def test_import_in_one_tab_keeps_the_case_the_other_tab_saved(backend):
    a = _session(page=COMPARE_PAGE)  # tab A on /Compare?ws=W
    b = _session(_token(a))  # tab B on /?ws=W
    _save(b, "B-case")
    _button(a, "Load the thesis' GUI test cases").click().run()  # A's page is stale
    assert not a.exception
    saved = backend.load(_token(a))[1]
    assert list(saved) == ["B-case", *GUI]
    assert a.multiselect(key="compare_selected").options == ["B-case", *GUI]


def test_a_stale_tab_asks_before_replacing_a_same_named_case(backend):
    a = _session(payload=10.0)
    b = _session(_token(a), payload=77.0)
    _save(b, "Same")
    _save(a, "Same")  # A never saw B's "Same"
    assert any("exists already" in m for m in messages(a, "warning"))
    assert not any("Saved case" in m for m in messages(a, "success"))
    assert _payload(backend.load(_token(a))[1]["Same"]) == 77.0
    _button(a, "Keep both").click().run()
    saved = backend.load(_token(a))[1]
    assert _payload(saved["Same"]) == 77.0 and _payload(saved["Same (2)"]) == 10.0
    assert any("Saved case “Same (2)”" in m for m in messages(a, "success"))
    # asked again, "Replace it" replaces the version it was told about
    _save(a, "Same")
    _button(a, "Replace it").click().run()
    assert _payload(backend.load(_token(a))[1]["Same"]) == 10.0
    # B is now stale: its replace is refused, and it offers keep both or reload
    _save(b, "Same")
    _button(b, "Replace it").click().run()
    assert not b.exception
    assert _payload(backend.load(_token(a))[1]["Same"]) == 10.0
    assert any("changed in another tab" in m for m in messages(b, "warning"))
    _button(b, "Reload").click().run()
    assert _payload(backend.load(_token(a))[1]["Same"]) == 10.0
    assert not any("changed in another tab" in m for m in messages(b, "warning"))


def test_rename_delete_and_replace_in_a_stale_tab(backend):
    a = _session(page=COMPARE_PAGE)
    _button(a, "Load the thesis' GUI test cases").click().run()
    b = _session(_token(a), page=COMPARE_PAGE)
    # B (up to date) saves a new case while A's page still shows only the four
    from app_ui import state

    state.save_case("B-case", *thesis_baseline(), b.session_state)
    b.run()
    # rename, in A, to the name B just took: "exists already", not "unavailable"
    show_tab(a, "Manage cases", key="compare_tab")
    a.selectbox(key="rename_from").set_value(GUI[0])
    a.text_input(key="rename_to").set_value("B-case")
    _button(a, "Rename").click().run()
    assert any("exists already" in m for m in messages(a, "error"))
    assert not any("unavailable" in m for m in messages(a, "error"))
    # delete in A: only what A chose goes
    show_tab(a, "Manage cases", key="compare_tab")
    a.multiselect(key="delete_names").set_value([GUI[1]])
    _button(a, "Delete").click().run()
    assert list(backend.load(_token(a))[1]) == [GUI[0], GUI[2], GUI[3], "B-case"]
    # replace (asks first) in A while B adds another: B's cases stay
    seen_before = list(a.session_state["cases"])
    a.radio(key="import_mode").set_value("replace").run()
    state.save_case("B-late", *thesis_baseline(), b.session_state)
    one = {"From file": thesis_gui_cases()[GUI[0]]}
    a.session_state["_replace_ask"] = {
        "raw": cases_to_json(one).encode(),
        "filename": "file.json",
        "seen": dict(a.session_state["_case_versions"]),
        "shown": seen_before,
    }
    a.run()
    assert any("Replace the" in m for m in messages(a, "warning"))
    _button(a, "Replace").click().run()
    assert not a.exception
    assert list(backend.load(_token(a))[1]) == ["B-late", "From file"]
