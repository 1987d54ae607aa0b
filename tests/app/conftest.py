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
def clear_cache():
    """Start with empty st.cache_data caches (cached results outlive an AppTest session)."""
    st.cache_data.clear()
    yield
    st.cache_data.clear()
