"""Layout at the two common laptop sizes: no headline number or label is cut ("1…", "Volu…"),
and "Update design" is in sight without scrolling."""

from __future__ import annotations

import pytest
from playwright.sync_api import Browser, expect

from tests.e2e.helpers import assert_no_exception, goto_page, screenshot, wait_for_rerun

pytestmark = pytest.mark.e2e

VIEWPORTS = [(1024, 768), (1400, 900)]

#: Every headline block, number and element inside one whose text is wider than its box (what
#: an ellipsis or the column's edge hides).
_CUT = """
() => [...document.querySelectorAll('.aerostat-hl')].flatMap(m =>
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
        values = page.get_by_test_id("headline-value")
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
        expect(page.get_by_test_id("headline").filter(has_text="Gas cost")).to_contain_text(
            "34,650"
        )
        assert page.evaluate(_CUT) == []
        screenshot(page, f"design_{width}x{height}", full_page=False)
        goto_page(page, "Method")
        page.get_by_role("tab", name="Validation").click()
        expect(page.get_by_test_id("headline-value").first).to_be_visible(timeout=60_000)
        assert page.evaluate(_CUT) == []
    finally:
        ctx.close()


#: The Performance tab's static charts as laid out: each image's box, the result column's
#: right edge, whether the main area scrolls sideways; and every text drawn in each chart (the
#: SVG set inline, off screen, at its own scale) that leaves the drawing or overlaps another
#: text of the same axis' ticks.
_PERF_LAYOUT = """
() => {
  const imgs = [...document.querySelectorAll('[data-testid="stImage"] img')].filter(i =>
    i.src.startsWith('data:image/svg+xml;base64,') && i.getBoundingClientRect().width > 0);
  const main = document.querySelector('[data-testid="stMain"]');
  const column = imgs.length ? imgs[0].closest('[data-testid="stColumn"]') : null;
  const out = {boxes: imgs.map(i => { const r = i.getBoundingClientRect();
                 return [r.x, r.y, r.width, r.height, i.naturalWidth]; }),
               right: column ? column.getBoundingClientRect().right : null,
               sideways: main.scrollWidth > main.clientWidth + 1, outside: [], overlaps: []};
  for (const i of imgs) {
    const host = document.createElement('div');
    host.style.cssText = 'position:absolute;left:-5000px;top:0';
    host.innerHTML = atob(i.src.split(',')[1]);
    document.body.appendChild(host);
    const svg = host.querySelector('svg');
    const key = svg.getAttribute('data-chart');
    const box = svg.getBoundingClientRect();
    const texts = [...svg.querySelectorAll('text')].filter(t => t.textContent.trim());
    for (const t of texts) {
      const r = t.getBoundingClientRect();
      if (r.left < box.left - 0.5 || r.right > box.right + 0.5 || r.top < box.top - 0.5
          || r.bottom > box.bottom + 0.5)
        out.outside.push(`${key}: "${t.textContent}"`);
    }
    for (const axis of ['x', 'y', 'y2']) {
      const labels = [...svg.querySelectorAll(`[data-tick="${axis}"] text`)]
        .map(t => [t.textContent, t.getBoundingClientRect()]);
      for (let k = 1; k < labels.length; k++) {
        const [a, ra] = labels[k - 1], [b, rb] = labels[k];
        if (ra.right > rb.left + 0.5 && rb.right > ra.left + 0.5 && ra.bottom > rb.top + 0.5
            && rb.bottom > ra.top + 0.5)
          out.overlaps.push(`${key} ${axis}: "${a}" / "${b}"`);
      }
    }
    host.remove();
  }
  return out;
}
"""


@pytest.mark.parametrize("width, height", VIEWPORTS)
def test_performance_charts_are_whole_and_legible(
    browser: Browser, base_url: str, width: int, height: int
):
    """The five static charts of the Performance tab: drawn at their own scale (text at 12 px
    or more on screen), inside the result column, nothing scrolling sideways; one a row at
    1024 px, two a row at 1400 px; no text of a drawing cut at its edge, no tick labels on top
    of each other."""
    from app_ui.perf_view import WIDTH_PX

    ctx = browser.new_context(viewport={"width": width, "height": height}, base_url=base_url)
    try:
        page = ctx.new_page()
        page.goto("/")
        wait_for_rerun(page)
        page.get_by_test_id("stMain").get_by_role("tab", name="Performance", exact=True).click()
        wait_for_rerun(page)
        page.wait_for_function(
            """() => [...document.querySelectorAll('[data-testid="stImage"] img')].filter(i =>
                i.src.startsWith('data:image/svg+xml') && i.complete && i.naturalWidth > 0
                && i.getBoundingClientRect().width > 0).length >= 5"""
        )
        assert_no_exception(page, "Performance tab")
        got = page.evaluate(_PERF_LAYOUT)
        boxes = got["boxes"]
        assert len(boxes) == 5, boxes
        for x, _y, w, _h, natural in boxes:
            assert w == pytest.approx(WIDTH_PX, abs=1), boxes  # not squeezed
            assert w / natural >= 12 / 13  # the drawing's 13 px text at 12 px or more
            assert x + w <= got["right"] + 0.5, (boxes, got["right"])
        assert not got["sideways"]
        rows = len({round(y) for _x, y, *_ in boxes})
        assert rows == (5 if width < 1200 else 3), boxes  # one a row at 1024, two at 1400
        assert got["outside"] == [] and got["overlaps"] == [], got
        screenshot(page, f"design_performance_{width}x{height}", full_page=False)
    finally:
        ctx.close()


#: With each headline number focused in turn (Tab, as a keyboard user reaches it), the focus
#: note drawn under it (its ``::after``): whether its box leaves the page's main area on either
#: side, and whether that area scrolls sideways.
_HELP_NOTES = """
async () => {
  const main = document.querySelector('[data-testid="stMain"]');
  const area = main.getBoundingClientRect();
  const out = [];
  for (const e of document.querySelectorAll('.aerostat-hl [data-help]')) {
    e.focus();
    await new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)));
    const s = getComputedStyle(e, '::after');
    const host = e.closest('.aerostat-hl');
    const anchor = s.position === 'absolute' && getComputedStyle(e).position === 'static'
      ? host.getBoundingClientRect() : e.getBoundingClientRect();
    const left = anchor.left + parseFloat(s.left);
    const right = left + parseFloat(s.width) + parseFloat(s.paddingLeft)
      + parseFloat(s.paddingRight) + parseFloat(s.borderLeftWidth) + parseFloat(s.borderRightWidth);
    if (s.content === 'none' || left < area.left - 0.5 || right > area.right + 0.5
        || main.scrollWidth > main.clientWidth + 1)
      out.push(`${e.querySelector('.hl-label').textContent}: ${s.content === 'none'
        ? 'no note' : `${left.toFixed(0)}-${right.toFixed(0)} in ${area.left.toFixed(0)}-${
        area.right.toFixed(0)}`}`);
    e.blur();
  }
  return out;
}
"""


def test_each_numbers_focus_note_stays_on_the_page(browser: Browser, base_url: str):
    """At 1024 px the right-most numbers sit near the page's edge: the help shown under a
    focused number (for keyboard and touch users) is whole, inside the main area."""
    ctx = browser.new_context(viewport={"width": 1024, "height": 768}, base_url=base_url)
    try:
        page = ctx.new_page()
        page.goto("/")
        wait_for_rerun(page)
        expect(page.get_by_test_id("headline-value").first).to_be_visible()
        assert page.locator(".aerostat-hl [data-help]").count() >= 10
        assert page.evaluate(_HELP_NOTES) == []
    finally:
        ctx.close()
