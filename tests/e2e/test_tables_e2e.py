"""Tables show all their columns (issue 9, layout): at 1024 x 768 and 1400 x 900 no table of the
Design, Sensitivity, Optimise, Compare, Shapes or Dynamics page scrolls sideways (scrollWidth of the grid's scroller equals
its clientWidth); and the number boxes of the Sensitivity and Optimise pages read a decimal
comma as a decimal point, as the Design form does ("12,5" was 125 in the browser's number box).
"""

from __future__ import annotations

import pytest
from playwright.sync_api import Browser, Page, expect

from tests.e2e.helpers import assert_no_exception, goto_page, wait_for_rerun

pytestmark = pytest.mark.e2e

RUN_TIMEOUT_MS = 120_000
VIEWPORTS = [(1024, 768), (1400, 900)]

#: Every visible table whose content is wider than its box (a sideways scroll bar): the
#: scroller of a dataframe grid, and a static table with every box inside it.
_WIDE = """
() => {
  const shown = e => e.offsetParent !== null;
  const wide = s => s.clientWidth > 0 && s.scrollWidth > s.clientWidth + 1;
  const say = (kind, s) => `${kind}: ${s.scrollWidth} > ${s.clientWidth} ${(s.innerText || '').slice(0, 60)}`;
  const grids = [...document.querySelectorAll('[data-testid="stDataFrame"]')].filter(shown)
    .flatMap(d => [...d.querySelectorAll('.dvn-scroller')].filter(wide).map(s => say('grid', s)));
  const statics = [...document.querySelectorAll('[data-testid="stTable"]')].filter(shown)
    .flatMap(t => [t, ...t.querySelectorAll('div')].filter(wide).map(s => say('table', s)));
  // HTML and Markdown tables (the Geometry tab's is HTML): the table wider than its block
  const md = [...document.querySelectorAll('[data-testid="stHtml"] table, [data-testid="stMarkdownContainer"] table')]
    .filter(shown).filter(t => t.scrollWidth > t.parentElement.clientWidth + 1)
    .map(t => say('html table', t));
  return grids.concat(statics, md);
}
"""
#: Tables drawn so far (grids once their scroller exists).
_COUNT = """() => [...document.querySelectorAll('[data-testid="stDataFrame"]')]
    .filter(d => d.offsetParent !== null && d.querySelector('.dvn-scroller')).length
  + [...document.querySelectorAll('[data-testid="stTable"] table')]
    .filter(t => t.offsetParent !== null).length
  + [...document.querySelectorAll('[data-testid="stHtml"] table, [data-testid="stMarkdownContainer"] table')]
    .filter(t => t.offsetParent !== null).length"""


def _open(browser: Browser, base_url: str, width: int, height: int):
    ctx = browser.new_context(viewport={"width": width, "height": height}, base_url=base_url)
    page = ctx.new_page()
    page.goto("/")
    wait_for_rerun(page)
    assert_no_exception(page, "Design page")
    return ctx, page


@pytest.mark.parametrize("width, height", VIEWPORTS)
def test_design_tables_show_every_column(browser: Browser, base_url: str, width: int, height: int):
    ctx, page = _open(browser, base_url, width, height)
    try:
        for tab, n_tables in (("Geometry", 1), ("Mass", 1), ("Performance", 3), ("Mission", 1)):
            page.get_by_role("tab", name=tab, exact=True).click()
            wait_for_rerun(page)
            page.wait_for_function(f"() => ({_COUNT})() >= {n_tables}", timeout=30_000)
            assert page.evaluate(_WIDE) == [], (tab, width)
            if tab == "Performance":
                expect(page.get_by_text("Forces and stability", exact=True)).to_be_visible()
    finally:
        ctx.close()


@pytest.mark.parametrize("width, height", [(1024, 768)])
def test_sensitivity_and_optimise_tables_show_every_column(
    browser: Browser, base_url: str, width: int, height: int
):
    ctx, page = _open(browser, base_url, width, height)
    try:
        goto_page(page, "Sensitivity", timeout=RUN_TIMEOUT_MS)
        assert_no_exception(page, "Sensitivity page")
        page.wait_for_function(f"() => ({_COUNT})() >= 1", timeout=RUN_TIMEOUT_MS)
        assert page.evaluate(_WIDE) == []
        page.get_by_text("All sweep points", exact=True).click()  # one static table per variable
        page.wait_for_function(f"() => ({_COUNT})() >= 4", timeout=RUN_TIMEOUT_MS)
        assert page.evaluate(_WIDE) == [], "All sweep points"
        goto_page(page, "Optimise", timeout=RUN_TIMEOUT_MS)
        page.get_by_text("Quick", exact=True).click()
        page.get_by_role("button", name="Run optimisation").click()
        wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
        assert_no_exception(page, "Optimise page")
        page.wait_for_function(f"() => ({_COUNT})() >= 3", timeout=RUN_TIMEOUT_MS)
        assert page.evaluate(_WIDE) == []
    finally:
        ctx.close()


def _box(page: Page, label: str):
    return page.get_by_role("textbox", name=label, exact=True)


def test_sensitivity_and_optimise_bounds_read_a_decimal_comma(app_page: Page):
    page = app_page
    goto_page(page, "Sensitivity", timeout=RUN_TIMEOUT_MS)
    _box(page, "Fineness ratio l/d [-] – from").fill("2,5")
    _box(page, "Fin position Δl_f [% of hull length] – to").fill("72,5")
    page.get_by_role("button", name="Update").click()
    wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
    assert_no_exception(page, "Sensitivity page")
    expect(page.get_by_test_id("stAlertContentError")).to_have_count(0)
    xs = page.evaluate(
        """() => { const d = document.querySelectorAll('.js-plotly-plot')[0].data;
        const x = n => d.find(t => t.name === n).x;
        return [Math.min(...x('total_mass vs fineness_ratio')),
                Math.max(...x('total_mass vs position'))]; }"""
    )
    assert xs == pytest.approx([2.5, 72.5])  # never 25 (refused) or 725

    goto_page(page, "Optimise", timeout=RUN_TIMEOUT_MS)
    page.get_by_text("Quick", exact=True).click()
    _box(page, "Fin position Δl_f [% of hull length] – upper").fill("72,5")
    _box(page, "Fin area change ΔS_f [%] – lower").fill("-12,5")
    page.get_by_role("button", name="Run optimisation").click()
    wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
    assert_no_exception(page, "Optimise page")
    expect(
        page.get_by_role("heading", name="Solver comparison (thesis Table 4.12)")
    ).to_be_visible()
    # a comma and a point together is refused, naming the box, in the unit of the box
    _box(page, "Fin area change ΔS_f [%] – lower").fill("-1.2,5")
    page.get_by_role("button", name="Run optimisation").click()
    wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
    expect(page.get_by_test_id("stAlertContentError").first).to_contain_text(
        "Fin area change ΔS_f [%] – lower"
    )
    _box(page, "Fin area change ΔS_f [%] – lower").fill("-10")
    _box(page, "Fin position Δl_f [% of hull length] – upper").fill("99")
    page.get_by_role("button", name="Run optimisation").click()
    wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
    expect(page.get_by_test_id("stAlertContentError").first).to_contain_text("valid range [40, 95]")


def test_compare_and_shapes_tables_show_every_column_at_1024(browser: Browser, base_url: str):
    """Compare's side-by-side table (three long-named cases) and the Shapes page's library and
    Table 2.2 tables fit a 1024 px window: static tables whose cells wrap."""
    ctx, page = _open(browser, base_url, 1024, 768)
    try:
        for name in ("Baseline at the coast, 10 kg", "Mountain site, heavier", "Third case"):
            page.get_by_role("textbox", name="Save the current design as a case").fill(name)
            page.get_by_role("button", name="Save case").click()
            wait_for_rerun(page)
            expect(page.get_by_text(f"Saved case “{name}”")).to_be_visible()
        goto_page(page, "Compare", timeout=RUN_TIMEOUT_MS)
        assert_no_exception(page, "Compare page")
        expect(page.get_by_text("rows differ between the cases")).to_be_visible()
        page.wait_for_function(f"() => ({_COUNT})() >= 1", timeout=RUN_TIMEOUT_MS)
        assert page.evaluate(_WIDE) == [], "Compare"
        goto_page(page, "Shapes", timeout=RUN_TIMEOUT_MS)
        assert_no_exception(page, "Shapes page")
        page.wait_for_function(f"() => ({_COUNT})() >= 3", timeout=RUN_TIMEOUT_MS)
        assert page.evaluate(_WIDE) == [], "Shapes"
    finally:
        ctx.close()


def test_dynamics_tables_show_every_column_at_1024(browser: Browser, base_url: str):
    """The Dynamics page's summary and limits tables after a short run fit a 1024 px window."""
    ctx, page = _open(browser, base_url, 1024, 768)
    try:
        goto_page(page, "Dynamics", timeout=RUN_TIMEOUT_MS)
        box = _box(page, "Simulated time [s]")
        box.fill("30")
        box.press("Tab")
        page.get_by_role("button", name="Run simulation").click()
        wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
        assert_no_exception(page, "Dynamics page after a run")
        expect(page.get_by_text("Finished: 30 s simulated")).to_be_visible(timeout=RUN_TIMEOUT_MS)
        page.wait_for_function(f"() => ({_COUNT})() >= 2", timeout=RUN_TIMEOUT_MS)
        assert page.evaluate(_WIDE) == [], "Dynamics"
    finally:
        ctx.close()


def test_envelope_and_shape_study_tables_show_every_column_at_1024(browser: Browser, base_url: str):
    """After the user's actions, the Envelope tab's flyable-time and Monte Carlo tables and the
    Shapes page's per-shape optima fit a 1024 px window."""
    ctx, page = _open(browser, base_url, 1024, 768)
    try:
        page.get_by_role("tab", name="Envelope", exact=True).click()
        wait_for_rerun(page)
        page.get_by_role("button", name="Compute flyable time").click()
        wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
        page.get_by_role("button", name="Run Monte Carlo").click()
        wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
        assert_no_exception(page, "Envelope tab")
        # flyable time, P(met) per constraint, the input spreads and the rule sets' comparison
        # (the Design page's constraint table is drawn only once its section is opened)
        page.wait_for_function(f"() => ({_COUNT})() >= 4", timeout=RUN_TIMEOUT_MS)
        assert page.evaluate(_WIDE) == [], "Envelope"
        goto_page(page, "Shapes", timeout=RUN_TIMEOUT_MS)
        page.get_by_role("button", name="Optimise every shape").click()
        wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
        assert_no_exception(page, "Shapes page")
        expect(page.get_by_text("Best shape", exact=False).first).to_be_visible()
        page.wait_for_function(f"() => ({_COUNT})() >= 6", timeout=RUN_TIMEOUT_MS)
        assert page.evaluate(_WIDE) == [], "Shapes"
    finally:
        ctx.close()
