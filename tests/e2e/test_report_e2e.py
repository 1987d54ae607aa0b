"""The HTML design report in a real browser (Debian chromium): every section is there, every
plot is an inline SVG with drawn content, nothing is fetched from the network, and it prints to
PDF."""

from __future__ import annotations

from pathlib import Path

import pytest
from playwright.sync_api import Browser

from aerostat_core.cli.entry import main
from aerostat_core.output.html_report import SECTIONS


@pytest.fixture(scope="module")
def report_file(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("report") / "report.html"
    assert (
        main(
            [
                "report",
                "--payload",
                "10",
                "--altitude",
                "300",
                "--monte-carlo",
                "500",
                "-o",
                str(out),
            ]
        )
        == 0
    )
    return out


def test_report_opens_offline_with_sections_and_plots(browser: Browser, report_file: Path):
    context = browser.new_context(viewport={"width": 1200, "height": 900}, offline=True)
    page = context.new_page()
    requests: list[str] = []
    errors: list[str] = []
    page.on("request", lambda r: requests.append(r.url))
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.goto(report_file.as_uri())
    assert page.title().startswith("Aerostat design report")
    for sid in SECTIONS:
        section = page.locator(f"section#{sid}")
        assert section.count() == 1, sid
        assert section.locator("h2").inner_text().strip(), sid
    plots = page.locator("figure.plot")
    assert plots.count() == 4
    for i in range(plots.count()):
        fig = plots.nth(i)
        box = fig.locator("svg").bounding_box()
        assert box and box["width"] > 200 and box["height"] > 100, fig.get_attribute("data-plot")
        assert fig.locator("svg path").count() > 10  # drawn content, not an empty frame
    assert page.locator("#envelope svg").count() == 1
    assert page.locator("#constraints table tbody tr").count() >= 10
    assert page.locator("#uncertainty").inner_text().count("500 samples") == 1
    assert "Program version" in page.locator("#version").inner_text()
    # only the file itself was loaded: no CDN, no fonts, no scripts
    assert [u for u in requests if not u.startswith("file://")] == []
    assert errors == []
    pdf = page.pdf(format="A4")
    assert pdf[:4] == b"%PDF" and len(pdf) > 50_000
    context.close()


def test_envelope_tab_and_one_click_report_in_the_app(app_page, console_errors):
    """The Design page's Envelope tab draws the heat map and the flyable time; the report
    button downloads the same self-contained report."""
    from playwright.sync_api import expect

    from tests.e2e.helpers import assert_no_exception, screenshot, wait_for_rerun

    page = app_page
    page.get_by_role("tab", name="Envelope").click()
    wait_for_rerun(page)
    assert_no_exception(page, "Envelope tab")
    expect(page.locator(".js-plotly-plot").filter(visible=True).first).to_be_visible(timeout=30_000)
    expect(page.get_by_text("Time flyable [%]")).to_be_visible()
    screenshot(page, "design_envelope")
    with page.expect_download(timeout=60_000) as info:
        page.get_by_role("button", name="Design report (HTML)").click()
    assert info.value.suggested_filename == "aerostat-report.html"
    text = info.value.path().read_text()
    for sid in SECTIONS:
        assert f'<section id="{sid}">' in text, sid
    assert text.count("<svg") == 4 and "<script" not in text
    assert console_errors == []
