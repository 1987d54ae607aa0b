"""AppTest fixtures for the app's pages (Streamlit's headless test runner, no browser).

The app path is resolved from this file, so the tests run from any working directory.
Helpers for reading charts and tables live in :mod:`tests.app.helpers`.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import streamlit as st
from streamlit.testing.v1 import AppTest

APP_PATH = Path(__file__).resolve().parents[2] / "app.py"
#: Generous per-run timeout [s]: the first run imports plotly/scipy; the machines are shared.
TIMEOUT_S = 60


@pytest.fixture
def at() -> AppTest:
    """A fresh session of the app, run once (Design page), with no exception."""
    app = AppTest.from_file(str(APP_PATH), default_timeout=TIMEOUT_S)
    app.run()
    assert not app.exception, [e.value for e in app.exception]
    return app


@pytest.fixture
def thesis_at() -> AppTest:
    """A fresh session with the thesis baseline loaded (what "Load thesis baseline" does): for
    the tests that check the pages against the thesis' numbers. The app's own default is the
    practice rule set (tests/app/test_design_page.py::test_opens_on_the_practice_default)."""
    from aerostat_core import thesis_baseline
    from aerostat_core.model.io import inputs_to_dict

    app = AppTest.from_file(str(APP_PATH), default_timeout=TIMEOUT_S)
    app.session_state["design_inputs"] = inputs_to_dict(*thesis_baseline())
    app.run()
    assert not app.exception, [e.value for e in app.exception]
    assert app.session_state["design_inputs"] == inputs_to_dict(*thesis_baseline())
    return app


@pytest.fixture
def clear_cache():
    """Start with empty st.cache_data caches (cached results outlive an AppTest session)."""
    st.cache_data.clear()
    yield
    st.cache_data.clear()
