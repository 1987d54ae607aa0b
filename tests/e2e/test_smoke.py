"""Smoke tests in a real browser: the app opens, renders, and every page loads without an exception.

Generic on purpose (no widget labels), so they hold whatever the pages show.
"""

from __future__ import annotations

import ast
import re
import urllib.request
from pathlib import Path

import pytest
from playwright.sync_api import Page, expect

from tests.e2e.helpers import assert_no_exception, nav_link_label, screenshot, wait_for_rerun

pytestmark = pytest.mark.e2e

#: Pages may optimise or simulate on first render: allow them more than a plain rerun [ms].
PAGE_TIMEOUT_MS = 120_000


def app_page_titles() -> list[str]:
    """The titles of app.py's PAGES, read from its source (app.py is never imported)."""
    tree = ast.parse((Path(__file__).resolve().parents[2] / "app.py").read_text())
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(
            isinstance(t, ast.Name) and t.id == "PAGES" for t in node.targets
        ):
            return [title for _, title, _ in ast.literal_eval(node.value)]
    raise AssertionError("app.py has no PAGES")


def test_server_health(streamlit_server) -> None:
    with urllib.request.urlopen(f"{streamlit_server.url}/_stcore/health", timeout=5) as response:
        assert response.read() == b"ok"


def test_home_renders(app_page: Page, console_errors: list[str]) -> None:
    page = app_page
    expect(page.get_by_test_id("stApp")).to_be_visible()
    # The browser tab shows the app's own title, not Streamlit's loading title.
    expect(page).not_to_have_title(re.compile(r"^\s*(Streamlit)?\s*$"))
    heading = page.get_by_test_id("stMain").get_by_role("heading").first
    expect(heading).to_be_visible()
    expect(heading).not_to_have_text(re.compile(r"^\s*$"))
    assert_no_exception(page, "the home page")
    screenshot(page, "smoke_home")
    assert console_errors == []


def test_every_page_loads(app_page: Page, console_errors: list[str]) -> None:
    """Click through the sidebar navigation (one session), checking each page for exceptions."""
    page = app_page
    view_more = page.get_by_test_id("stSidebarNavViewButton")
    if view_more.count() and "more" in (view_more.text_content() or "").lower():
        view_more.click()
    links = page.get_by_test_id("stSidebarNav").get_by_test_id("stSidebarNavLink")
    n_pages = links.count()
    # every page of app.py is in the navigation: a missing page file fails here (never a skip)
    assert [nav_link_label(links.nth(i)) for i in range(n_pages)] == app_page_titles()
    for i in range(n_pages):
        link = links.nth(i)
        label = nav_link_label(link)
        link.click()
        wait_for_rerun(page, timeout=PAGE_TIMEOUT_MS)
        assert_no_exception(page, f"page {label!r}")
        expect(page.get_by_test_id("stMain")).to_be_visible()
        screenshot(page, f"smoke_page_{i:02d}")
    assert console_errors == []
