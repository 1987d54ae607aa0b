"""User text is inert everywhere (issue 20): every page rendered with hostile case names and a
hostile file name (a Markdown image, a link, HTML, a script) carries no live URL or tag of
theirs in any element: messages, captions, labels, help, tabs, table headers and cells, chart
labels, the sidebar. Widget options are plain text by design and are checked only for tags.
"""

from __future__ import annotations

import re

import pandas as pd
import pytest
from google.protobuf.json_format import MessageToDict
from streamlit.testing.v1 import AppTest

from aerostat_core import thesis_baseline
from aerostat_core.model.io import cases_to_json, inputs_to_dict
from app import PAGES
from app_ui import state
from tests.app.conftest import APP_PATH, TIMEOUT_S
from tests.app.helpers import COMPARE_PAGE, goto, show_tab

HOSTILE = (
    "![t](http://evil.invalid/x.png)",
    "[click](http://evil.invalid/link)",
    "<img src=http://evil.invalid/i.png>",
    "<script>alert(666)</script>",
    "<a href='http://evil.invalid/a'>a</a> http://evil.invalid/auto",
)
#: Per-run timeout [s]: the Compare tabs design every case; generous on a shared machine.
SLOW_S = 3 * TIMEOUT_S
HOSTILE_FILE = "<img src=http://evil.invalid/f.png>[f](http://evil.invalid/f).json"

#: A URL of the hostile names that Markdown would make live: a link, an image, or a bare URL
#: (GitHub-flavoured Markdown links those after reading the escapes, so they are removed first).
_URL = re.compile(r"https?://evil\.invalid")
_ESCAPE = re.compile(r"\\([!-/:-@\[-`{-~])")


class _LiveUrl:
    @staticmethod
    def search(text: str):
        return _URL.search(_ESCAPE.sub(r"\1", text))


LIVE_URL = _LiveUrl()
#: An unescaped tag of theirs (HTML in Markdown, or in a plotly label).
LIVE_TAG = re.compile(r"(?<!\\)<\s*(?:img|script|a)\b[^<]*?(?:evil|666)", re.IGNORECASE)
#: Proto fields that Streamlit shows as plain text (widget options and values), and ids.
PLAIN_FIELDS = {
    "options", "default", "value", "rawValue", "rawValues", "defaultValues", "id", "formId"
}  # fmt: skip


class _Upload:
    def __init__(self, data: bytes, name: str) -> None:
        self._data, self.name, self.size = data, name, len(data)

    def getvalue(self) -> bytes:
        return self._data


def _walk(node):
    yield node
    for child in (getattr(node, "children", None) or {}).values():
        yield from _walk(child)


def _strings(value, key: str = ""):
    if isinstance(value, str):
        yield key, value
    elif isinstance(value, dict):
        for k, v in value.items():
            yield from _strings(v, k)
    elif isinstance(value, list):
        for v in value:
            yield from _strings(v, key)


def _live(at: AppTest, where: str) -> list[str]:
    """Every hostile URL or tag still live in the rendered elements of ``at``."""
    found = []
    for node in _walk(at._tree):
        proto = getattr(node, "proto", None)
        if proto is None:
            continue
        kind = getattr(node, "type", type(node).__name__)
        if kind == "table" or kind == "arrow_data_frame":
            df = node.value
            texts = [str(c) for c in df.columns] + [
                str(v) for v in df.to_numpy().ravel() if isinstance(v, str)
            ]
            found += [f"{where}: {kind} {t!r}" for t in texts if LIVE_URL.search(t)]
            found += [f"{where}: {kind} {t!r}" for t in texts if LIVE_TAG.search(t)]
            continue
        for key, text in _strings(MessageToDict(proto)):
            if key in PLAIN_FIELDS or key in ("data", "arrowData"):
                continue  # shown as text nodes (the browser test checks the DOM as well)
            if LIVE_TAG.search(text):
                found.append(f"{where}: {kind}.{key} has a tag: {text[:160]!r}")
            elif key != "spec" and LIVE_URL.search(text):  # plotly reads no Markdown
                found.append(f"{where}: {kind}.{key} has a live URL: {text[:160]!r}")
    return found


def _session(monkeypatch, tmp_path) -> AppTest:
    monkeypatch.setenv("AEROSTAT_DATA_DIR", str(tmp_path / "data"))
    at = AppTest.from_file(str(APP_PATH), default_timeout=SLOW_S)
    at.run()
    assert not at.exception
    return at


def _pages():
    return [path for path, _, _ in PAGES]


def test_every_page_keeps_hostile_names_inert(monkeypatch, tmp_path):
    at = _session(monkeypatch, tmp_path)
    # saved through the Design page's form (its message quotes the name), one asked about again
    for name in HOSTILE:
        at.text_input(key="case_name").set_value(name)
        next(b for b in at.button if b.label == "Save case").click().run()
    at.text_input(key="case_name").set_value(HOSTILE[0])
    next(b for b in at.button if b.label == "Save case").click().run()
    assert not at.exception
    problems = _live(at, "Design after saving (taken-name question shown)")
    assert any("exists already" in str(w.value) for w in at.warning)
    # a cases file with a hostile file name and hostile case names
    one = inputs_to_dict(*thesis_baseline())
    raw = cases_to_json({f"file {n}": one for n in HOSTILE[:2]}).encode()
    state.handle_upload(_Upload(raw, HOSTILE_FILE), "compare", at.session_state)
    goto(at, COMPARE_PAGE)
    problems += _live(at, "Compare (import message)")
    assert len(at.session_state["cases"]) == len(HOSTILE) + 2
    for label in ("Side by side", "Performance", "Tether profiles", "Manage cases"):
        show_tab(at, label, key="compare_tab")
        assert not at.exception
        problems += _live(at, f"Compare / {label}")
    # the replace question quotes the names and the file name
    at.session_state["_replace_ask"] = {
        "raw": raw,
        "filename": HOSTILE_FILE,
        "seen": dict(at.session_state["_case_versions"]),
        "shown": list(at.session_state["cases"]),
    }
    at.run()
    assert any("Replace the" in str(w.value) for w in at.warning)
    problems += _live(at, "Compare (replace question)")
    # a rename message
    show_tab(at, "Manage cases", key="compare_tab")
    at.selectbox(key="rename_from").set_value(HOSTILE[1])
    at.text_input(key="rename_to").set_value(HOSTILE[1] + " <b>2</b>")
    next(b for b in at.button if b.label == "Rename").click().run()
    problems += _live(at, "Compare (rename message)")
    for page in _pages():
        goto(at, page)
        assert not at.exception, (page, [e.value for e in at.exception])
        problems += _live(at, page)
    assert not problems, "\n".join(problems)


def test_unsaved_hostile_names_during_an_outage_are_inert(monkeypatch, tmp_path):
    blocked = tmp_path / "file"
    blocked.write_text("not a folder")  # the database's folder cannot be made: unavailable
    monkeypatch.setenv("AEROSTAT_DATABASE_URL", f"sqlite:///{blocked}/sub/aerostat.sqlite3")
    at = AppTest.from_file(str(APP_PATH), default_timeout=TIMEOUT_S)
    at.run()
    for name in HOSTILE:
        at.text_input(key="case_name").set_value(name)
        next(b for b in at.button if b.label == "Save case").click().run()
    assert not at.exception
    assert list(state.unsaved_cases(at.session_state)) == list(HOSTILE)
    assert any("in this session only" in str(w.value) for w in at.warning)
    problems = _live(at, "Design during an outage")
    goto(at, COMPARE_PAGE)
    options = at.multiselect(key="compare_selected").options
    assert len(options) == len(HOSTILE) and all(o.endswith("(not yet saved)") for o in options)
    problems += _live(at, "Compare during an outage")
    assert not problems, "\n".join(problems)


def _frame() -> None:
    """The app frame's workspace banner alone (AppTest keeps only the page's elements)."""
    from app_ui import workspace_ui

    workspace_ui.status()


def test_the_outage_banner_quotes_hostile_names_inertly():
    at = AppTest.from_function(_frame, default_timeout=TIMEOUT_S)
    one = inputs_to_dict(*thesis_baseline())
    at.session_state[state.UNSAVED_KEY] = {n: one for n in HOSTILE}
    at.session_state[state.STORE_ERR_KEY] = "Could not save the case: unavailable."
    at.session_state[state.STORE_NOTE_KEY] = "Saved " + ", ".join(HOSTILE)
    at.run()
    assert not at.exception, [e.value for e in at.exception]
    assert any("Not yet saved" in str(w.value) for w in at.warning)
    assert at.get("download_button")
    problems = _live(at, "workspace banner")
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize("text", HOSTILE)
def test_the_detector_finds_raw_hostile_text(text):
    """The check itself can fail: raw hostile names are found, escaped ones are not."""
    from app_ui.plots import plain_label
    from app_ui.text import plain

    assert LIVE_URL.search(text) or LIVE_TAG.search(text)
    assert not LIVE_URL.search(plain(text)) and not LIVE_TAG.search(plain(text))
    if "http" in text:  # backslash escapes alone leave a bare URL that the autolinker links
        assert LIVE_URL.search(re.sub(r"([!-/:-@\[-`{-~])", r"\\\1", text))
    assert not LIVE_TAG.search(plain_label(text))
    assert isinstance(pd.DataFrame({plain(text): [1]}).columns[0], str)
