"""Dynamics page in a real browser: run a short gust case, see the plots and the summary, download
the time histories and parse them, take a screenshot (artifacts/screenshots/dynamics.png); run
the same case again (second click, after leaving the page, from a second browser context whose
session hits the shared result store): never a traceback (issue 9's CacheReplayClosureError)."""

from __future__ import annotations

import csv
import io

import pytest
from playwright.sync_api import Browser, Page, expect

from tests.e2e.helpers import assert_no_exception, goto_page, screenshot, wait_for_rerun

pytestmark = pytest.mark.e2e

SHOT_VIEWPORT = {"width": 1400, "height": 3300}
#: A simulation rerun may take longer than a design rerun (first run: numba cache load).
RUN_TIMEOUT_MS = 120_000


def test_short_gust_run(app_page: Page, console_errors: list[str]):
    page = app_page
    goto_page(page, "Dynamics")
    assert_no_exception(page, "Dynamics page")
    expect(page.get_by_role("heading", name="Dynamics")).to_be_visible()
    box = page.get_by_role("textbox", name="Simulated time [s]", exact=True)
    box.fill("60")
    box.press("Tab")
    page.get_by_role("button", name="Run simulation").click()
    wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
    assert_no_exception(page, "Dynamics page after the run")
    expect(page.get_by_text("Finished: 60 s simulated")).to_be_visible(timeout=RUN_TIMEOUT_MS)
    # the plots are drawn (plotly renders an SVG per chart)
    charts = page.get_by_test_id("stPlotlyChart")
    expect(charts.first).to_be_visible()
    assert charts.count() >= 8
    expect(page.get_by_text("Position of the confluence point").first).to_be_visible()
    expect(page.get_by_text("Summary", exact=True)).to_be_visible()
    # the time histories as CSV
    with page.expect_download() as info:
        page.get_by_role("button", name="Time histories (CSV)").click()
    assert info.value.suggested_filename == "aerostat_dynamics_gust.csv"
    text = info.value.path().read_text()
    meta = [ln for ln in text.splitlines() if ln.startswith("# ")]
    assert "# scenario = gust" in meta and "# duration = 60.0" in meta
    rows = list(csv.DictReader(io.StringIO("\n".join(
        ln for ln in text.splitlines() if not ln.startswith("#")))))
    assert len(rows) == 601
    assert float(rows[-1]["t_s"]) == pytest.approx(60.0)
    wind = [float(r["wind_x_m_s"]) for r in rows]
    assert wind[0] == pytest.approx(10.0) and max(wind) == pytest.approx(15.0, abs=0.01)
    page.set_viewport_size(SHOT_VIEWPORT)
    page.get_by_role("heading", name="Dynamics").scroll_into_view_if_needed()
    wait_for_rerun(page)
    path = screenshot(page, "dynamics")
    assert path.is_file() and path.stat().st_size > 10_000
    assert console_errors == []


def _run_60s(page: Page) -> None:
    box = page.get_by_role("textbox", name="Simulated time [s]", exact=True)
    box.fill("45")
    box.press("Tab")
    page.get_by_role("button", name="Run simulation").click()
    wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
    assert_no_exception(page, "Dynamics page after a run")
    expect(page.get_by_text("Finished: 45 s simulated")).to_be_visible(timeout=RUN_TIMEOUT_MS)
    expect(page.get_by_text("CacheReplayClosureError")).to_have_count(0)


def test_rerun_return_and_second_session(app_page: Page, browser: Browser, base_url: str,
                                         console_errors: list[str]):
    page = app_page
    goto_page(page, "Dynamics")
    _run_60s(page)
    _run_60s(page)  # second click: the same case, served from the store
    goto_page(page, "Design")
    goto_page(page, "Dynamics")
    assert_no_exception(page, "Dynamics page after coming back")
    expect(page.get_by_text("Finished: 45 s simulated")).to_be_visible(timeout=RUN_TIMEOUT_MS)
    _run_60s(page)
    other = browser.new_context(base_url=base_url, viewport={"width": 1400, "height": 900})
    try:
        p2 = other.new_page()
        p2.goto("/")
        wait_for_rerun(p2)
        goto_page(p2, "Dynamics")
        _run_60s(p2)  # a second session whose case is already in the shared store
    finally:
        other.close()
    assert console_errors == []
