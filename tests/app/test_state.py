"""app_ui.state with a plain dict as session state: the shared contract (design_inputs, cases),
saved-case management and the all-or-nothing file import."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest

from aerostat_core import thesis_baseline
from aerostat_core.model.io import (
    MAX_CASES,
    MAX_JSON_BYTES,
    cases_to_json,
    design_to_json,
    inputs_from_dict,
    inputs_to_dict,
)
from aerostat_core.output.report import thesis_gui_cases
from app_ui import state


@pytest.fixture
def s() -> dict:
    d: dict = {}
    state.init_state(d)
    return d


def _snapshot(d: dict) -> str:
    return json.dumps({k: d[k] for k in ("design_inputs", "cases")}, sort_keys=True)


def test_init_state_sets_the_contract(s):
    # the default: the practice rules, 10 kg at 300 m, hull sized (the CLI's and design()'s)
    assert s["design_inputs"] == state.baseline_inputs()
    assert s["design_inputs"]["requirement"]["rules"] == "practice"
    assert s["cases"] == {}
    s["design_inputs"]["requirement"]["payload_mass"] = 99.0
    state.init_state(s)  # never overwrites
    assert s["design_inputs"]["requirement"]["payload_mass"] == 99.0


def test_current_and_set_inputs_round_trip(s):
    req, cfg = thesis_baseline()
    req2 = replace(req, payload_mass=25.0)
    state.set_current_inputs(req2, cfg, s)
    assert state.current_inputs(s) == (req2, cfg)
    assert s["design_inputs"]["requirement"]["payload_mass"] == 25.0
    assert state.current_inputs_key(s) == state.inputs_key(s["design_inputs"])


def test_corrupt_inputs_fall_back_to_the_baseline(s):
    s["design_inputs"] = {"requirement": {"payload_mass": "lots"}}
    assert state.current_inputs(s) == inputs_from_dict(state.baseline_inputs())


def test_save_rename_delete(s):
    req, cfg = thesis_baseline()
    assert state.save_case("  first ", req, cfg, s) == "first"
    state.save_case("second", replace(req, payload_mass=30.0), cfg, s)
    assert list(state.get_cases(s)) == ["first", "second"]
    # an existing name gets a suffix: "first" still holds its own design
    assert state.save_case("first", replace(req, payload_mass=30.0), cfg, s) == "first (2)"
    assert s["cases"]["first"]["requirement"]["payload_mass"] == 10.0
    assert s["cases"]["first (2)"]["requirement"]["payload_mass"] == 30.0
    state.delete_case("first (2)", s)
    state.save_case("first", replace(req, payload_mass=12.0), cfg, s, overwrite=True)
    assert list(state.get_cases(s)) == ["first", "second"]  # replaced in place
    assert s["cases"]["first"]["requirement"]["payload_mass"] == 12.0
    assert state.rename_case("first", "renamed", s) == "renamed"
    assert list(state.get_cases(s)) == ["renamed", "second"]  # order kept
    with pytest.raises(ValueError, match="exists already"):
        state.rename_case("renamed", "second", s)
    with pytest.raises(ValueError, match="no case"):
        state.rename_case("ghost", "x", s)
    state.delete_case("renamed", s)
    state.delete_case("renamed", s)  # already gone: fine
    assert list(state.get_cases(s)) == ["second"]
    state.clear_cases(s)
    assert s["cases"] == {}


@pytest.mark.parametrize("name", ["", "   ", None, "x" * 101, 5])
def test_bad_case_names_are_refused(s, name):
    with pytest.raises(ValueError):
        state.save_case(name, *thesis_baseline(), s)
    assert s["cases"] == {}


def test_case_limit(s):
    req, cfg = thesis_baseline()
    s["cases"] = {f"c{i}": inputs_to_dict(req, cfg) for i in range(MAX_CASES)}
    with pytest.raises(ValueError, match="At most"):
        state.save_case("one more", req, cfg, s)
    state.save_case("c0", req, cfg, s, overwrite=True)  # replacing one is still fine


def test_add_cases_never_overwrites_nor_duplicates(s):
    names = state.add_cases(thesis_gui_cases(), s)
    assert state.add_cases(thesis_gui_cases(), s) == []  # identical cases: nothing added
    assert len(s["cases"]) == 4
    changed = {
        n: {**v, "requirement": {**v["requirement"], "payload_mass": 42.0}}
        for n, v in thesis_gui_cases().items()
    }
    again = state.add_cases(changed, s)  # same names, other inputs: kept apart by a suffix
    assert again == [f"{n} (2)" for n in names]
    assert len(s["cases"]) == 8
    assert state.add_cases(thesis_gui_cases(), s, mode="replace") == names
    assert list(s["cases"]) == names


def test_reimporting_an_export_duplicates_nothing(s):
    state.add_cases(thesis_gui_cases(), s)
    raw = cases_to_json(state.get_cases(s)).encode()
    level, msg = state.import_file(raw, s, filename="mine.json")
    assert level == "info" and "nothing was added" in msg
    assert len(s["cases"]) == 4
    level, msg = state.import_file(raw, s, filename="mine.json", mode="replace")
    assert level == "success" and "Replaced" in msg and len(s["cases"]) == 4


@pytest.mark.parametrize(
    "name", ["\ud83d", "tab\there", "bell\x07", "del\x7f", "c1\x85x", "rtl\u202eevil"]
)
def test_hostile_case_names_are_refused(s, name):
    with pytest.raises(ValueError, match="Case name"):
        state.save_case(name, *thesis_baseline(), s)
    assert s["cases"] == {}


def test_suffix_keeps_the_name_within_the_limit(s):
    req, cfg = thesis_baseline()
    long = "n" * state.MAX_NAME_CHARS
    state.save_case(long, req, cfg, s)
    used = state.save_case(long, req, cfg, s)
    assert used.endswith(" (2)") and len(used) == state.MAX_NAME_CHARS


def test_messages_name_the_file_and_are_capped(s):
    level, msg = state.import_file(b"{" * 10, s, filename="x" * 5000 + ".json")
    assert level == "error" and len(msg) <= 400
    huge = json.dumps(
        {"format": "aerostat-design", "version": 1, "requirement": {"payload_mass": "y" * 900_000}}
    ).encode()
    level, msg = state.import_file(huge, s, filename="big.json")
    assert level == "error" and "big.json" in msg and len(msg) <= 400


def test_import_design_file(s):
    req, cfg = thesis_baseline()
    text = design_to_json(replace(req, payload_mass=33.0), cfg)
    level, msg = state.import_file(text.encode(), s, filename="d.json")
    assert level == "success" and "d.json" in msg
    assert s["design_inputs"]["requirement"]["payload_mass"] == 33.0
    assert s["cases"] == {}


def test_import_cases_file(s):
    level, msg = state.import_file(cases_to_json(thesis_gui_cases()).encode(), s)
    assert level == "success" and "Added 4 case(s)" in msg
    assert list(s["cases"]) == list(thesis_gui_cases())
    assert s["design_inputs"] == state.baseline_inputs()


HOSTILE = [
    (b"", "not valid JSON"),
    (b"\xff\xfe\x00", "not UTF-8"),
    (b"{", "not valid JSON"),
    (b"[1, 2, 3]", "JSON object"),
    (b'{"requirement": {"payload_mass": NaN}}', "NaN"),
    (b'{"requirement": {"payload_mass": 1e999}}', "not finite"),
    (b'{"requirement": {"payload_mass": true}}', "not a number"),
    (b'{"requirement": {"payload_mass": [1]}}', "single value"),
    (b'{"requirement": {"payload_mass": 10, "extra": 1}}', "unknown field"),
    (b'{"requirement": {"blow_by_limit": 500}}', "blow_by_limit"),
    (b'{"configuration": {"fins": {"count": 3.5}}}', "count"),
    (b'{"configuration": {"tether_segments": 1e400}}', "tether_segments"),
    (b'{"format": "aerostat-design", "version": 99}', "version"),
    (b'{"format": "aerostat-cases", "version": 1, "cases": []}', "cases"),
    (b'{"format": "aerostat-cases", "version": 1, "cases": {"": {}}}', "case name"),
    (b"[" * 100_000 + b"]" * 100_000, "nested too deeply"),
    (b"{}" + b" " * MAX_JSON_BYTES, "limit"),
]


@pytest.mark.parametrize("raw, fragment", HOSTILE)
def test_hostile_files_change_nothing(s, raw, fragment):
    state.save_case("kept", *thesis_baseline(), s)
    before = _snapshot(s)
    level, msg = state.import_file(raw, s)
    assert level == "error"
    assert fragment in msg and "Nothing was changed" in msg
    assert _snapshot(s) == before


def test_one_bad_case_rejects_the_whole_file(s):
    data = json.loads(cases_to_json(thesis_gui_cases()))
    data["cases"]["bad"] = {"requirement": {"payload_mass": -1}}
    level, msg = state.import_file(json.dumps(data).encode(), s)
    assert level == "error" and "'bad'" in msg
    assert s["cases"] == {}


def test_too_many_cases_in_a_file(s):
    one = inputs_to_dict(*thesis_baseline())
    s["cases"] = {f"c{i}": one for i in range(MAX_CASES - 1)}
    text = cases_to_json({"a": one, "b": one})
    level, msg = state.import_file(text.encode(), s)
    assert level == "error" and "at most" in msg
    assert len(s["cases"]) == MAX_CASES - 1


class FakeUpload:
    """Stands in for Streamlit's UploadedFile."""

    def __init__(self, data: bytes, name: str = "f.json", size: int | None = None):
        self._data, self.name = data, name
        self.size = len(data) if size is None else size
        self.read_called = False

    def getvalue(self) -> bytes:
        self.read_called = True
        return self._data


def test_handle_upload_reports_and_stores_feedback(s):
    up = FakeUpload(design_to_json(*thesis_baseline()).encode(), "base.json")
    level, msg = state.handle_upload(up, "design", s)
    assert level == "success"
    assert s[state.IMPORT_MSG_KEY] == {"level": "success", "text": msg, "where": "design"}


def test_oversized_upload_is_refused_before_reading(s):
    up = FakeUpload(b"{}", "huge.json", size=50_000_000)
    level, msg = state.handle_upload(up, "compare", s)
    assert level == "error" and "limit" in msg and "huge.json" in msg
    assert not up.read_called
    assert s[state.IMPORT_MSG_KEY]["where"] == "compare"


def test_read_upload_needs_a_file():
    with pytest.raises(ValueError, match="No file"):
        state.read_upload(None)
    assert state.read_upload(b"{}") == b"{}"
