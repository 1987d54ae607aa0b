"""Every page at 1024 px and 1400 px, as an engineer uses it (issue 24):

* no raw value anywhere: no "nan", "None", "True"/"False", "-0.000", "inf", and no unit drawn as
  a Markdown bullet (a static table's "-" cell became an empty list item);
* every label whole (no text cut by its box: an ellipsis or a clipped line);
* every tab reachable without scrolling sideways (the tab bar wraps, no page scrolls sideways);
* on the Design page the verdict and the key numbers are above the fold;
* the unit switch in the sidebar changes the Design page's numbers, labels, plot axes and input
  boxes to US customary (a value typed in feet is applied in metres).

One browser session per width walks every page and every tab (and runs a short simulation on
the Dynamics page so its tables are there too).
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import Browser, Page, expect

from tests.e2e.helpers import assert_no_exception, goto_page, screenshot, wait_for_rerun

pytestmark = pytest.mark.e2e

VIEWPORTS = [(1024, 768), (1400, 900)]
PAGES = ("Design", "Compare", "Sensitivity", "Optimise", "Dynamics", "Method", "Shapes")
#: Pages may optimise or simulate on first render [ms].
PAGE_TIMEOUT_MS = 180_000

#: Raw values that must never reach the screen (whole words; "-0.0..." as a number).
RAW = re.compile(r"\b(nan|NaN|None|True|False|inf)\b|(?<![\w.])-0[.,]0+(?![\d])")

#: Text cut by its box: elements of labels, metrics, buttons, tabs and table cells whose text
#: is wider (or taller) than the box that shows it.
_CUT = """
() => {
  const sel = ['[data-testid="stWidgetLabel"] p', '.aerostat-hl',
               '[data-testid="headline-label"]', '[data-testid="headline-value"]',
               '[role="tab"] p', '[data-testid="stTable"] th', '[data-testid="stTable"] td',
               '[data-testid="stMarkdownContainer"] th', '[data-testid="stMarkdownContainer"] td',
               '[data-testid="stHtml"] th', '[data-testid="stHtml"] td'];
  const out = [];
  const cut = e => e.offsetParent && e.clientWidth > 0 && e.scrollWidth > e.clientWidth + 1;
  for (const e of document.querySelectorAll(sel.join(','))) {
    const style = getComputedStyle(e);
    const clips = style.overflowX !== 'visible' || style.textOverflow === 'ellipsis';
    if (clips && cut(e))
      out.push(`${e.tagName} "${e.textContent.trim().slice(0, 60)}" ${e.scrollWidth} > ${e.clientWidth}`);
  }
  // any text that ends in an ellipsis (buttons: "Sav…"), outside select boxes' chosen value
  for (const e of document.querySelectorAll('[data-testid="stMain"] *, [data-testid="stSidebar"] *')) {
    if (e.closest('[data-baseweb="select"]') || !e.textContent.trim()) continue;
    if (getComputedStyle(e).textOverflow === 'ellipsis' && cut(e))
      out.push(`ellipsis: ${e.tagName} "${e.textContent.trim().slice(0, 60)}" ${e.scrollWidth} > ${e.clientWidth}`);
  }
  return [...new Set(out)];
}
"""
#: Anything that makes the page scroll sideways, and Markdown bullets inside table cells.
_WIDE = """
() => {
  const main = document.querySelector('[data-testid="stMain"]');
  const wide = main.scrollWidth > main.clientWidth + 1 ? [`main ${main.scrollWidth} > ${main.clientWidth}`] : [];
  const bullets = [...document.querySelectorAll('[data-testid="stTable"] td li, [data-testid="stTable"] td ul, '
      + '[data-testid="stMarkdownContainer"] td li, [data-testid="stMarkdownContainer"] td ul, '
      + '[data-testid="stHtml"] td li, [data-testid="stHtml"] td ul')]
      .map(e => `bullet in a table cell: "${e.closest('tr').textContent.trim().slice(0, 60)}"`);
  return wide.concat(bullets);
}
"""
#: Tabs outside the visible part of their tab bar or of the window (reachable only by
#: scrolling sideways).
_HIDDEN_TABS = """
() => [...document.querySelectorAll('[data-testid="stTabs"]')].flatMap(tabs => {
  const box = tabs.getBoundingClientRect();
  return [...tabs.querySelectorAll('[role="tab"]')]
    .filter(t => { const r = t.getBoundingClientRect();
                   return r.right > box.right + 1 || r.left < box.left - 1 || r.right > innerWidth; })
    .map(t => t.textContent.trim());
})
"""


def _raw_hits(page: Page) -> list[str]:
    text = page.get_by_test_id("stMain").inner_text()
    return [
        f"{m.group(0)!r} in …{text[max(0, m.start() - 50) : m.end() + 20]!r}…"
        for m in RAW.finditer(text)
    ]


def _check_view(page: Page, where: str, problems: list[str]) -> None:
    assert_no_exception(page, where)
    for kind, found in (
        ("raw value", _raw_hits(page)),
        ("cut text", page.evaluate(_CUT)),
        ("sideways", page.evaluate(_WIDE)),
        ("tab out of sight", page.evaluate(_HIDDEN_TABS)),
    ):
        problems.extend(f"{where}: {kind}: {f}" for f in found)


def _run_dynamics(page: Page) -> None:
    box = page.get_by_role("textbox", name="Simulated time [s]", exact=True)
    box.fill("30")
    box.press("Tab")
    page.get_by_role("button", name="Run simulation").click()
    wait_for_rerun(page, timeout=PAGE_TIMEOUT_MS)
    expect(page.get_by_text("Finished: 30 s simulated")).to_be_visible(timeout=PAGE_TIMEOUT_MS)


def _walk(page: Page, width: int) -> list[str]:
    problems: list[str] = []
    for label in PAGES:
        if label != "Design":
            goto_page(page, label, timeout=PAGE_TIMEOUT_MS)
        if label == "Dynamics":
            _run_dynamics(page)
        tabs = page.get_by_test_id("stMain").get_by_role("tab")
        names = [tabs.nth(i).inner_text().strip() for i in range(tabs.count())]
        if not names:
            _check_view(page, f"{label} @{width}", problems)
            screenshot(page, f"ux_{width}_{label}", full_page=False)
            continue
        for name in names:
            page.get_by_test_id("stMain").get_by_role("tab", name=name, exact=True).first.click()
            wait_for_rerun(page, timeout=PAGE_TIMEOUT_MS)
            _check_view(page, f"{label}/{name} @{width}", problems)
            screenshot(page, f"ux_{width}_{label}_{name}".replace(" ", "_"), full_page=False)
    return problems


@pytest.mark.parametrize("width, height", VIEWPORTS)
def test_every_page_and_tab_is_whole_in_sight_and_free_of_raw_values(
    browser: Browser, base_url: str, width: int, height: int
):
    ctx = browser.new_context(viewport={"width": width, "height": height}, base_url=base_url)
    try:
        page = ctx.new_page()
        page.goto("/")
        wait_for_rerun(page, timeout=PAGE_TIMEOUT_MS)
        problems = _walk(page, width)
        assert problems == [], "\n".join(problems)
    finally:
        ctx.close()


@pytest.mark.parametrize("width, height", VIEWPORTS)
def test_design_verdict_and_key_numbers_above_the_fold(
    browser: Browser, base_url: str, width: int, height: int
):
    ctx = browser.new_context(viewport={"width": width, "height": height}, base_url=base_url)
    try:
        page = ctx.new_page()
        page.goto("/")
        wait_for_rerun(page, timeout=PAGE_TIMEOUT_MS)
        verdict = page.get_by_test_id("stAlert").filter(
            has_text=re.compile("Meets every requirement|Requirements not met")
        )
        expect(verdict.first).to_be_visible()
        box = verdict.first.bounding_box()
        assert box is not None and box["y"] + box["height"] <= height, box
        values = page.get_by_test_id("headline-value")
        assert values.count() >= 10
        in_sight = [
            b
            for b in (values.nth(i).bounding_box() for i in range(values.count()))
            if b is not None and b["y"] + b["height"] <= height
        ]
        assert len(in_sight) >= 10, f"{len(in_sight)} of {values.count()} numbers above the fold"
        screenshot(page, f"ux_fold_{width}", full_page=False)
    finally:
        ctx.close()


def test_unit_switch_shows_the_design_in_us_customary_units(browser: Browser, base_url: str):
    ctx = browser.new_context(viewport={"width": 1400, "height": 900}, base_url=base_url)
    try:
        page = ctx.new_page()
        page.goto("/")
        wait_for_rerun(page, timeout=PAGE_TIMEOUT_MS)
        _switch_units(page)
    finally:
        ctx.close()


def _switch_units(page: Page) -> None:
    metric = page.get_by_test_id("headline")
    expect(metric.filter(has_text="Volume [m³]").first).to_be_visible(timeout=PAGE_TIMEOUT_MS)
    # st.radio's input is hidden behind its label: a user clicks the label
    us_button = page.get_by_test_id("stSidebar").get_by_text("US customary", exact=True)
    expect(us_button).to_be_visible(timeout=PAGE_TIMEOUT_MS)
    us_button.click()
    wait_for_rerun(page)
    expect(metric.filter(has_text="Volume [ft³]").first).to_be_visible(timeout=PAGE_TIMEOUT_MS)
    expect(metric.filter(has_text="Total mass [lb]").first).to_be_visible(timeout=PAGE_TIMEOUT_MS)
    expect(metric.filter(has_text="Blow-by [ft]").first).to_be_visible(timeout=PAGE_TIMEOUT_MS)
    page.get_by_test_id("stMain").get_by_role("tab", name="Performance", exact=True).click()
    wait_for_rerun(page)
    expect(page.get_by_test_id("stHtml").filter(has_text="Wind [kt]").first).to_be_visible(
        timeout=PAGE_TIMEOUT_MS
    )
    # the plots' axes follow: the static drawings (their text alternative, and the axis titles
    # drawn in them) and, behind the toggle, plotly's
    blow = page.get_by_role("img", name=re.compile(r"^Blow-by .* ft over .* kt;"))
    expect(blow).to_be_visible(timeout=PAGE_TIMEOUT_MS)
    drawn = blow.evaluate("i => atob(i.src.split(',')[1])")
    assert "Blow-by [ft]" in drawn and "Wind speed at the aerostat [kt]" in drawn
    page.get_by_text("Interactive charts (zoom, hover)").click()
    wait_for_rerun(page)
    expect(page.locator(".ytitle", has_text="Blow-by [ft]").first).to_be_visible(
        timeout=PAGE_TIMEOUT_MS
    )
    expect(page.locator(".xtitle", has_text="[kt]").first).to_be_visible(timeout=PAGE_TIMEOUT_MS)
    # the inputs too: a US user types 1000 ft, which the design takes as 304.8 m
    altitude = page.get_by_role("textbox", name="Operating altitude [ft]", exact=True)
    expect(altitude).to_be_visible(timeout=PAGE_TIMEOUT_MS)
    altitude.fill("1000")
    altitude.press("Enter")
    wait_for_rerun(page, timeout=PAGE_TIMEOUT_MS)
    expect(altitude).to_have_value("1000", timeout=PAGE_TIMEOUT_MS)
    assert _raw_hits(page) == []  # converted numbers are never "nan" or "-0.0" either
    goto_page(page, "Compare")  # the choice holds for the whole app
    page.get_by_test_id("stSidebar").get_by_text("SI", exact=True).click()
    wait_for_rerun(page)
    goto_page(page, "Design")
    expect(metric.filter(has_text="Volume [m³]").first).to_be_visible(timeout=PAGE_TIMEOUT_MS)
    si_altitude = page.get_by_role("textbox", name="Operating altitude [m]", exact=True)
    expect(si_altitude).to_have_value("304.8", timeout=PAGE_TIMEOUT_MS)
    assert _raw_hits(page) == []
