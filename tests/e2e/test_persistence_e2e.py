"""Saved work survives a reload, a new browser context (another tab or person with the link) and a
server restart: the workspace token in the URL finds the cases in the store (SQLite in a
temporary data folder here; the same store code runs on PostgreSQL in tests/app/test_store.py).
"""

from __future__ import annotations

import re
from urllib.parse import parse_qs, urlparse

import pytest
from playwright.sync_api import Browser, Page, expect

from tests.e2e.conftest import start_streamlit, stop_streamlit
from tests.e2e.helpers import ARTIFACTS_DIR, assert_no_exception, goto_page, wait_for_rerun

pytestmark = pytest.mark.e2e

CASES = ("Alpha ✓", "Beta [2]")


def _token(page: Page) -> str:
    expect(page).to_have_url(re.compile(r"[?&]ws=[A-Za-z0-9_-]{32}"))
    return parse_qs(urlparse(page.url).query)["ws"][0]


def _save(page: Page, name: str) -> None:
    page.get_by_role("textbox", name="Save the current design as a case").fill(name)
    page.get_by_role("button", name="Save case").click()
    wait_for_rerun(page)
    expect(page.get_by_text(f"Saved case “{name}”")).to_be_visible()


def _expect_both_cases(page: Page, where: str) -> None:
    wait_for_rerun(page)
    assert_no_exception(page, where)
    picker = page.get_by_test_id("stMultiSelect").first
    for name in CASES:
        # generous: the first run on a freshly started server imports scipy, plotly...
        expect(picker).to_contain_text(name, timeout=30_000)


def _expect_the_app_around_the_page(page: Page, where: str) -> None:
    """The page runs inside app.py: its navigation (the seven titled pages, not the ``pages/``
    folder's file list with an "app" entry), the unit switch and the page style."""
    nav = page.get_by_test_id("stSidebarNav").get_by_role("link")
    expect(nav, where).to_have_count(7)
    expect(nav.filter(has_text="app"), where).to_have_count(0)
    expect(page.get_by_role("radiogroup", name="Units"), where).to_be_visible()
    assert page.evaluate(
        "() => [...document.querySelectorAll('style')].some(s => s.textContent.includes("
        "'.aerostat-hl'))"), where


def test_cases_survive_reload_new_context_and_restart(browser: Browser, tmp_path):
    env = {"AEROSTAT_DATA_DIR": str(tmp_path / "data")}
    log = ARTIFACTS_DIR / "streamlit-persistence.log"
    server = start_streamlit(log, env)
    contexts = []
    try:
        ctx = browser.new_context(viewport={"width": 1400, "height": 900})
        contexts.append(ctx)
        page = ctx.new_page()
        page.goto(server.url + "/")
        wait_for_rerun(page)
        token = _token(page)
        for name in CASES:
            _save(page, name)
        goto_page(page, "Compare")
        _expect_both_cases(page, "Compare")
        assert _token(page) == token  # page switches keep the workspace in the URL

        page.reload()  # F5
        _expect_both_cases(page, "Compare after a reload")

        other = browser.new_context()  # a new tab / another person with the link
        contexts.append(other)
        page2 = other.new_page()
        page2.goto(f"{server.url}/Compare?ws={token}")
        _expect_both_cases(page2, "Compare in a new context")

        stop_streamlit(server)
        server = start_streamlit(log, env)  # a new process (and port), same data folder
        # two tabs reconnect at once, each on a page's own address, not "/": Streamlit starts
        # both sessions in its folder mode (each page file alone) and the app's guard
        # (app_ui.shell) must turn each back, also the one whose run began before the other
        # ended that mode
        page3, page5 = other.new_page(), other.new_page()
        page3.goto(f"{server.url}/Compare?ws={token}", wait_until="commit")
        page5.goto(f"{server.url}/Method?ws={token}", wait_until="commit")
        _expect_both_cases(page3, "Compare after a server restart")
        _expect_the_app_around_the_page(page3, "Compare, first request after a restart")
        wait_for_rerun(page5)
        _expect_the_app_around_the_page(page5, "Method, opened at the same time")

        # no token: a fresh, empty workspace (there is no way to list the others)
        page4 = other.new_page()
        page4.goto(f"{server.url}/Compare")
        wait_for_rerun(page4)
        expect(page4.get_by_text("No saved cases yet")).to_be_visible()
        assert _token(page4) != token
    finally:
        for c in contexts:
            c.close()
        stop_streamlit(server)
