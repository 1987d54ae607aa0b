"""Layout at the two common laptop sizes: no headline number or label is cut ("1…", "Volu…"),
and "Update design" is in sight without scrolling."""

from __future__ import annotations

import pytest
from playwright.sync_api import Browser, expect

from tests.e2e.helpers import assert_no_exception, goto_page, screenshot, wait_for_rerun

pytestmark = pytest.mark.e2e

VIEWPORTS = [(1024, 768), (1400, 900)]

#: Every element inside a metric whose text is wider than its box (what an ellipsis hides).
_CUT = """
() => [...document.querySelectorAll('[data-testid="stMetric"]')].flatMap(m =>
    [m, ...m.querySelectorAll('*')]
        .filter(e => e.scrollWidth > e.clientWidth + 1 && e.clientWidth > 0)
        .map(e => `${e.getAttribute('data-testid') || e.tagName}: "${e.textContent.trim()}" `
                  + `${e.scrollWidth} > ${e.clientWidth}`))
"""


@pytest.mark.parametrize("width, height", VIEWPORTS)
def test_no_metric_is_truncated_and_submit_is_in_sight(
    browser: Browser, base_url: str, width: int, height: int
):
    ctx = browser.new_context(viewport={"width": width, "height": height}, base_url=base_url)
    try:
        page = ctx.new_page()
        page.goto("/")
        wait_for_rerun(page)
        assert_no_exception(page, "Design page")
        values = page.get_by_test_id("stMetricValue")
        expect(values.first).to_be_visible()
        assert values.count() == 10
        assert page.evaluate(_CUT) == []
        box = page.get_by_role("button", name="Update design").first.bounding_box()
        assert box is not None and box["y"] + box["height"] <= height, box
        # a five-digit number (gas cost of a large hull) still fits
        page.get_by_text("Given", exact=True).first.click()
        page.get_by_role("textbox", name="Hull volume [m³] (when given)", exact=True).fill("900")
        page.get_by_role("button", name="Update design").first.click()
        wait_for_rerun(page)
        expect(page.get_by_test_id("stMetric").filter(has_text="Gas cost")).to_contain_text(
            "34,650"
        )
        assert page.evaluate(_CUT) == []
        screenshot(page, f"design_{width}x{height}", full_page=False)
        goto_page(page, "Method")
        page.get_by_role("tab", name="Validation").click()
        expect(page.get_by_test_id("stMetricValue").first).to_be_visible(timeout=60_000)
        assert page.evaluate(_CUT) == []
    finally:
        ctx.close()
