"""No page shows a traceback: each page's main action pressed twice, then again from a second
session that finds the result in the shared cache; an unexpected error becomes a short message
with a reference id whose traceback is in the server log. (The Dynamics page has its own tests.)
"""

from __future__ import annotations

import logging
import re

import pytest
from streamlit.testing.v1 import AppTest

from tests.app.conftest import APP_PATH, TIMEOUT_S
from tests.app.helpers import goto, messages, metrics

SENS_PAGE = "pages/3_Sensitivity.py"
OPT_PAGE = "pages/4_Optimise.py"


def _session() -> AppTest:
    app = AppTest.from_file(str(APP_PATH), default_timeout=TIMEOUT_S)
    app.run()
    assert not app.exception, [e.value for e in app.exception]
    return app


def _set(at: AppTest, key: str, value) -> None:
    for kind in ("radio", "selectbox", "text_input", "multiselect"):
        for el in getattr(at, kind):
            if getattr(el, "key", None) == key:
                el.set_value(value)
                return
    raise KeyError(key)


def _design(at: AppTest) -> None:
    _set(at, "in_payload", "13")
    at.button(key="in_submit").click().run()


def _compare(at: AppTest) -> None:
    goto(at, "pages/2_Compare.py")
    next(b for b in at.button if b.label == "Load the thesis' GUI test cases").click().run()


def _sensitivity(at: AppTest) -> None:
    goto(at, SENS_PAGE)
    _set(at, "sens_level", "Quick")
    at.button(key="sens_run").click().run()


def _optimise(at: AppTest) -> None:
    goto(at, OPT_PAGE)
    _set(at, "opt_level", "Quick")
    _set(at, "opt_solvers", ["pso"])
    at.button(key="opt_run").click().run()


def _method(at: AppTest) -> None:
    goto(at, "pages/6_Method.py")


ACTIONS = {
    "design": (_design, "Total mass [kg]"),
    "compare": (_compare, None),
    "sensitivity": (_sensitivity, None),
    "optimise": (_optimise, None),
    "method": (_method, None),
}


def _no_trouble(at: AppTest, where: str) -> None:
    assert not at.exception, (where, [e.value for e in at.exception])
    assert not [e for e in messages(at, "error") if "reference" in e], where


@pytest.mark.parametrize("page", list(ACTIONS))
def test_main_action_twice_and_from_a_second_session(page):
    action, metric = ACTIONS[page]
    first = _session()
    action(first)
    _no_trouble(first, f"{page}: first press")
    shown = [m.value for m in metrics(first)]
    tables = len(first.dataframe)
    charts = len(first.get("plotly_chart"))
    action(first)  # the same request again: every result now comes from the cache
    _no_trouble(first, f"{page}: second press")
    second = _session()  # another user with the same request hits the shared cache
    action(second)
    _no_trouble(second, f"{page}: second session")
    assert [m.value for m in metrics(second)] == shown
    assert len(second.dataframe) == tables and len(second.get("plotly_chart")) == charts
    if metric:
        assert any(m.label == metric for m in metrics(second))


def test_an_unexpected_error_is_a_reference_not_a_traceback(monkeypatch, caplog):
    from app_ui import side_view

    def broken(*_a, **_k):
        raise RuntimeError("internal detail that must not reach the screen")

    monkeypatch.setattr(side_view, "side_view_svg", broken)  # drawn by the first run
    caplog.set_level(logging.ERROR, logger="aerostat.app")
    at = AppTest.from_file(str(APP_PATH), default_timeout=TIMEOUT_S)
    at.run()
    assert not at.exception  # no st.exception box, no traceback
    errors = messages(at, "error")
    ref = [re.search(r"reference \*\*([0-9a-f]{8})\*\*", e) for e in errors]
    ref = [m.group(1) for m in ref if m]
    assert len(ref) == 1, errors
    assert not any("internal detail" in e for e in errors)
    logged = [r for r in caplog.records if ref[0] in r.getMessage()]
    assert logged and logged[0].exc_info is not None  # the full traceback is in the log
    assert "internal detail" in str(logged[0].exc_info[1])


def test_show_error_details_is_off():
    import tomllib

    from tests.app.conftest import APP_PATH as app

    config = tomllib.loads((app.parent / ".streamlit" / "config.toml").read_text())
    assert config["client"]["showErrorDetails"] == "none"


def test_the_server_skips_the_full_collection_after_each_run(monkeypatch):
    """Streamlit reads ``runner.postScriptGC = false`` from the app's config (a misspelt key
    would be ignored): its gc.collect(2) after every run held the GIL for 60-470 ms on this
    app's heap, and the server answered nothing meanwhile (.streamlit/config.toml)."""
    from streamlit import config

    from tests.app.conftest import APP_PATH as app

    assert config._config_options_template["runner.postScriptGC"].default_val is True
    monkeypatch.chdir(app.parent)
    try:
        config.get_config_options(force_reparse=True)
        assert config.get_option("runner.postScriptGC") is False
    finally:
        monkeypatch.undo()
        config.get_config_options(force_reparse=True)
