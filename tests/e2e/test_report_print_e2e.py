"""The design report as a design report (issue 24): it fits a 1024 px window and an A4 page, the
verdict comes first, the requirement reads with labels and units, and Chromium's print-to-PDF
gives a bounded number of pages on which no table is cut (every table fits the printed text
width and one page height, and is kept whole by ``break-inside: avoid``)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from playwright.sync_api import Browser

from aerostat_core import design, thesis_baseline
from aerostat_core.output.html_report import build_report

#: A4 minus the report's @page margins (12 mm left/right, 14 mm top/bottom) in CSS px (96/in).
A4_TEXT_WIDTH_PX = (210 - 2 * 12) / 25.4 * 96
A4_TEXT_HEIGHT_PX = (297 - 2 * 14) / 25.4 * 96

_BOXES = """
() => [...document.querySelectorAll('table, figure')].map(e => {
  const r = e.getBoundingClientRect();
  return {tag: e.tagName, section: (e.closest('section') || {}).id || '', width: r.width,
          height: r.height, right: r.right, avoid: getComputedStyle(e).breakInside};
})
"""


@pytest.fixture(scope="module", params=["SI", "US"])
def report(request, tmp_path_factory) -> tuple[str, Path]:
    out = tmp_path_factory.mktemp("report") / f"report-{request.param}.html"
    out.write_text(build_report(design(*thesis_baseline()), n_monte_carlo=300, units=request.param))
    return request.param, out


def test_report_fits_1024_px_and_reads_verdict_first(browser: Browser, report):
    units, path = report
    ctx = browser.new_context(viewport={"width": 1024, "height": 768}, offline=True)
    try:
        page = ctx.new_page()
        page.goto(path.as_uri())
        width = page.evaluate("document.documentElement.scrollWidth")
        assert width <= 1024, f"report {width} px wide in a 1024 px window"
        wide = [b for b in page.evaluate(_BOXES) if b["right"] > 1024]
        assert wide == []
        first = page.locator("section").first
        assert first.get_attribute("id") == "verdict"
        assert re.search(r"^(Feasible|NOT feasible)", first.locator("p").first.inner_text())
        assert first.locator("table").first.bounding_box()["y"] < 768  # key numbers in sight
        req = page.locator("#requirement table")
        labels = req.locator("tbody tr td:first-child").all_inner_texts()
        assert "Payload mass" in labels and not any("_" in t for t in labels)
        assert req.locator("thead th").all_inner_texts() == ["Requirement", "Value", "Unit"]
        text = page.locator("body").inner_text()
        assert not re.search(r"\b(nan|None|True|False)\b", text)
        if units == "US":
            assert (
                "[ft]" in text
                and "[lb]" in text
                and "[kt]" in page.locator("#performance").inner_text()
            )
    finally:
        ctx.close()


def test_report_prints_to_a4_without_a_cut_table(browser: Browser, report):
    _units, path = report
    ctx = browser.new_context(
        viewport={"width": int(A4_TEXT_WIDTH_PX), "height": int(A4_TEXT_HEIGHT_PX)}, offline=True
    )
    try:
        page = ctx.new_page()
        page.goto(path.as_uri())
        page.emulate_media(media="print")
        boxes = page.evaluate(_BOXES)
        assert boxes
        for b in boxes:
            where = f"{b['tag']} in #{b['section']}"
            assert b["width"] <= A4_TEXT_WIDTH_PX + 1, f"{where} {b['width']:.0f} px wide"
            assert b["height"] <= A4_TEXT_HEIGHT_PX, f"{where} taller than a page"
            assert b["avoid"] == "avoid", f"{where} may be split across pages"
        pdf = page.pdf(format="A4", prefer_css_page_size=True)
        pages = len(re.findall(rb"/Type\s*/Page(?!s)", pdf))
        # 16 A4 pages since the verdict, class, envelope-beam and material rows joined it
        assert 5 <= pages <= 20, f"{pages} pages"
    finally:
        ctx.close()
