"""Design page in a real browser: change the payload and see the volume change, download the CSV
and JSON files and parse them, upload a bad file and see the message, screenshot each page."""

from __future__ import annotations

import csv
import io
import json
import re

import pytest
from playwright.sync_api import Page, expect

from aerostat_core import thesis_baseline
from aerostat_core.model.io import design_from_json, design_to_json
from tests.e2e.helpers import (
    assert_no_exception,
    goto_page,
    screenshot,
    wait_for_rerun,
)

pytestmark = pytest.mark.e2e

#: Viewport used for the page screenshots (tall enough to show the results and the form).
SHOT_VIEWPORT = {"width": 1400, "height": 2300}


def metric_value(page: Page, label: str):
    """Locator of the value of the headline number with exactly this label."""
    box = page.get_by_test_id("headline").filter(
        has=page.get_by_test_id("headline-label").get_by_text(label, exact=True)
    )
    return box.get_by_test_id("headline-value")


def number(text: str) -> float:
    return float(text.replace(",", "").strip())


def set_number(page: Page, label: str, value: float) -> None:
    box = page.get_by_role("textbox", name=label, exact=True)
    box.fill(str(value))
    box.press("Tab")  # commit the value inside the form (no rerun until submit)


def submit(page: Page) -> None:
    page.get_by_role("button", name="Update design").first.click()
    wait_for_rerun(page)


def test_payload_change_changes_the_sized_volume(thesis_page: Page, console_errors: list[str]):
    page = thesis_page
    volume = metric_value(page, "Volume [m³]")
    expect(volume).to_have_text("170.0")  # thesis baseline: volume given
    page.get_by_text("Sized: smallest hull meeting every constraint", exact=True).click()
    submit(page)
    assert_no_exception(page, "Design page after sizing")
    expect(volume).not_to_have_text("170.0")
    sized_10 = number(volume.inner_text())
    set_number(page, "Payload mass [kg]", 30)
    submit(page)
    expect(volume).not_to_have_text(f"{sized_10:,.1f}")
    sized_30 = number(volume.inner_text())
    assert sized_30 > sized_10  # a heavier payload needs a bigger hull
    expect(page.get_by_role("textbox", name="Payload mass [kg]", exact=True)).to_have_value(
        re.compile(r"^30(\.0+)?$")
    )
    assert console_errors == []


def test_download_tables_and_design_file(thesis_page: Page):
    page = thesis_page
    blow_by = number(metric_value(page, "Blow-by [m]").inner_text())
    page.get_by_role("tab", name="Performance").click()
    wait_for_rerun(page)
    with page.expect_download() as info:
        page.get_by_role("button", name="Performance table (CSV)").click()
    rows = list(csv.DictReader(io.StringIO(info.value.path().read_text())))
    units, rows = rows[0], rows[1:]  # SI columns, then a row of their units
    assert units["wind_speed_m_s"] == "m/s" and units["blow_by_m"] == "m"
    assert len(rows) == 21  # 0, 1, ..., 20 m/s
    assert {"wind_speed_m_s", "blow_by_m", "tension_top_N", "safety_factor", "flags"} <= set(
        rows[0]
    )
    at_15 = next(r for r in rows if float(r["wind_speed_m_s"]) == 15.0)
    assert float(at_15["blow_by_m"]) == pytest.approx(blow_by, abs=0.05)

    page.get_by_role("tab", name="Mass").click()

    wait_for_rerun(page)
    with page.expect_download() as info:
        page.get_by_role("button", name="Mass table (CSV)").click()
    mass = list(csv.DictReader(io.StringIO(info.value.path().read_text())))[1:]  # unit row
    total = next(float(r["mass_kg"]) for r in mass if r["item"] == "total")
    assert sum(float(r["mass_kg"]) for r in mass if r["item"] != "total") == pytest.approx(total)

    page.get_by_text("Design file: export / import").click()
    with page.expect_download() as info:
        page.get_by_role("button", name="Download design inputs (JSON)").click()
    assert info.value.suggested_filename.endswith(".json")
    req, cfg = design_from_json(info.value.path().read_bytes())
    assert (req.payload_mass, req.altitude, cfg.hull.volume) == (10.0, 300.0, 170.0)


def test_bad_json_upload_shows_a_message_and_changes_nothing(thesis_page: Page):
    page = thesis_page
    volume = metric_value(page, "Volume [m³]")
    expect(volume).to_have_text("170.0")
    page.get_by_text("Design file: export / import").click()
    bad = json.dumps({"requirement": {"payload_mass": "heavy"}}).encode()
    page.get_by_test_id("stFileUploaderDropzoneInput").first.set_input_files(
        files=[{"name": "bad-design.json", "mimeType": "application/json", "buffer": bad}]
    )
    wait_for_rerun(page)
    alert = page.get_by_test_id("stAlertContentError").filter(has_text="Could not import")
    expect(alert).to_be_visible()
    expect(alert).to_contain_text("bad-design.json")
    expect(alert).to_contain_text("payload_mass")
    expect(alert).to_contain_text("Nothing was changed")
    expect(volume).to_have_text("170.0")
    expect(page.get_by_role("textbox", name="Payload mass [kg]", exact=True)).to_have_value(
        re.compile(r"^10(\.0+)?$")
    )
    assert_no_exception(page, "Design page after a bad upload")


def test_a_rejected_input_is_reported_in_its_group(thesis_page: Page):
    page = thesis_page
    label = "Blow-by limit at the design wind [m] (empty = rule set)"
    page.get_by_text("Wind and operating limits", exact=True).click()  # closed at the start
    set_number(page, label, 400)  # above the 300 m altitude
    submit(page)
    expect(
        page.get_by_text(re.compile(r"Not applied: " + re.escape(label) + ": 400"))
    ).to_be_visible()
    expect(metric_value(page, "Volume [m³]")).to_have_text("170.0")
    assert_no_exception(page, "Design page after a rejected input")


#: Static drawings (SVG images) decoded and laid out: at least ``n``.
_CHARTS_DRAWN = """(n) => [...document.querySelectorAll(
    '[data-testid="stImage"] img[src^="data:image/svg+xml"]')].filter(i =>
    i.complete && i.naturalWidth > 0 && i.getBoundingClientRect().width > 0).length >= n"""


def test_screenshots_of_each_page(thesis_page: Page, console_errors: list[str]):
    page = thesis_page
    page.set_viewport_size(SHOT_VIEWPORT)
    expect(metric_value(page, "Volume [m³]")).to_have_text("170.0")
    # the first tab's side view is a static drawing (no plotly.js before the first result)
    side = page.get_by_test_id("stImage").locator("img[src^='data:image/svg+xml']")
    expect(side).to_be_visible()
    assert side.evaluate("img => img.complete && img.naturalWidth > 0")  # the SVG decoded
    box = side.bounding_box()
    assert box is not None and box["width"] > 300
    screenshot(page, "design")
    for tab in ("Performance", "Tether profiles", "3-D view"):
        page.get_by_role("tab", name=tab).click()
        wait_for_rerun(page)
        if tab == "Performance":  # five static drawings, decoded and laid out
            page.wait_for_function(_CHARTS_DRAWN, arg=5)
        else:
            expect(page.locator(".js-plotly-plot").filter(visible=True).first).to_be_visible()
        screenshot(page, f"design_{tab.lower().replace(' ', '_').replace('-', '')}")
    goto_page(page, "Compare")
    assert_no_exception(page, "Compare page")
    page.get_by_role("button", name="Load the thesis' GUI test cases").click()
    wait_for_rerun(page)
    expect(page.get_by_test_id("stTable").filter(visible=True).first).to_be_visible()
    screenshot(page, "compare")
    page.get_by_role("tab", name="Performance").click()
    wait_for_rerun(page)
    expect(page.locator(".js-plotly-plot").filter(visible=True).first).to_be_visible()
    screenshot(page, "compare_performance")
    goto_page(page, "Method")
    assert_no_exception(page, "Method page")
    page.get_by_role("tab", name="Validation (live)").click()
    expect(page.get_by_test_id("headline").first).to_be_visible()
    screenshot(page, "method")
    page.get_by_role("tab", name="Equations and assumptions").click()
    wait_for_rerun(page)
    expect(page.get_by_text("Design chain.", exact=True)).to_be_visible()
    screenshot(page, "method_equations")
    assert console_errors == []


def test_an_upload_message_names_the_file_actually_chosen(app_page: Page):
    page = app_page
    page.get_by_text("Design file: export / import").click()
    good = design_to_json(*thesis_baseline()).encode()
    dropzone = page.get_by_test_id("stFileUploaderDropzoneInput").first
    dropzone.set_input_files(
        files=[{"name": "first-file.json", "mimeType": "application/json", "buffer": good}]
    )
    wait_for_rerun(page)
    expect(page.get_by_text("Loaded the design inputs from first-file.json")).to_be_visible()
    # a 2 MB file: the browser refuses it (server limit 1 MB); the old message must not stay
    # next to it as if it were about this file
    big = b" " * 2_000_000
    dropzone.set_input_files(
        files=[{"name": "second-file.json", "mimeType": "application/json", "buffer": big}]
    )
    page.wait_for_timeout(500)
    page.get_by_role("button", name="Update design").first.click()  # any rerun
    wait_for_rerun(page)
    expect(page.get_by_text("Loaded the design inputs from first-file.json")).to_have_count(0)
    assert_no_exception(page, "Design page after a refused upload")
