"""Saved cases in a real browser: save two designs, compare them on the Compare page (sidebar
navigation keeps the session), download every case as one CSV and parse it, upload a bad cases
file and see the message."""

from __future__ import annotations

import csv
import io
import json

import pytest
from playwright.sync_api import Page, expect

from tests.e2e.helpers import assert_no_exception, goto_page, screenshot, wait_for_rerun

pytestmark = pytest.mark.e2e


def save_case(page: Page, name: str) -> None:
    page.get_by_role("textbox", name="Save the current design as a case").fill(name)
    page.get_by_role("button", name="Save case").click()
    wait_for_rerun(page)
    expect(page.get_by_text(f"Saved case “{name}”")).to_be_visible()


def set_payload(page: Page, value: float) -> None:
    box = page.get_by_role("textbox", name="Payload mass [kg]", exact=True)
    box.fill(str(value))
    box.press("Tab")
    page.get_by_role("button", name="Update design").first.click()
    wait_for_rerun(page)


def test_save_two_cases_and_compare_them(thesis_page: Page, console_errors: list[str]):
    page = thesis_page
    page.get_by_text("Sized: smallest hull meeting every constraint", exact=True).click()
    set_payload(page, 10)
    save_case(page, "light")
    set_payload(page, 30)
    save_case(page, "heavy")

    goto_page(page, "Compare")
    assert_no_exception(page, "Compare page")
    expect(page.get_by_role("heading", name="Compare saved cases")).to_be_visible()
    selected = page.get_by_test_id("stMultiSelect").first
    expect(selected).to_contain_text("light")
    expect(selected).to_contain_text("heavy")
    expect(page.get_by_text("rows differ between the cases")).to_be_visible()

    # the side-by-side table, as its CSV: one column per case, differences flagged
    with page.expect_download() as info:
        page.get_by_role("button", name="Comparison table (CSV)").click()
    rows = list(csv.DictReader(io.StringIO(info.value.path().read_text())))
    assert list(rows[0])[:4] == ["section", "quantity", "light", "heavy"]
    by_q = {r["quantity"]: r for r in rows}
    assert float(by_q["Payload mass [kg]"]["light"]) == 10.0
    assert float(by_q["Payload mass [kg]"]["heavy"]) == 30.0
    assert by_q["Payload mass [kg]"]["differs"] == "True"
    assert float(by_q["Hull volume [m³]"]["heavy"]) > float(by_q["Hull volume [m³]"]["light"])

    # overlaid curves: one legend entry per case
    page.get_by_role("tab", name="Performance").click()
    wait_for_rerun(page)
    plot = page.locator(".js-plotly-plot").filter(visible=True).first
    expect(plot).to_be_visible()
    expect(plot.locator(".legendtext").filter(has_text="light")).to_have_count(1)
    expect(plot.locator(".legendtext").filter(has_text="heavy")).to_have_count(1)
    page.get_by_role("tab", name="Tether profiles").click()
    wait_for_rerun(page)
    tether = page.locator(".js-plotly-plot").filter(visible=True).first
    expect(tether.locator(".legendtext").filter(has_text="light (15 m/s)")).to_have_count(1)

    # every case in one tidy CSV, units in the column names
    page.get_by_text("Cases file: export / import").click()
    with page.expect_download() as info:
        page.get_by_role("button", name="Download all cases (CSV)").click()
    tidy = list(csv.DictReader(io.StringIO(info.value.path().read_text())))
    assert {r["case"] for r in tidy} == {"light", "heavy"}
    assert len(tidy) == 2 * 21
    for col in ("payload_mass_kg", "volume_m3", "total_mass_kg", "wind_speed_m_s", "blow_by_m"):
        assert col in tidy[0], col
    heavy = [r for r in tidy if r["case"] == "heavy"]
    assert all(float(r["payload_mass_kg"]) == 30.0 for r in heavy)

    with page.expect_download() as info:
        page.get_by_role("button", name="Download all cases (JSON)").click()
    data = json.loads(info.value.path().read_text())
    assert data["format"] == "aerostat-cases" and list(data["cases"]) == ["light", "heavy"]

    page.mouse.move(0, 0)
    screenshot(page, "compare_two_cases")

    # back on the Design page the inputs are still those of the last change
    goto_page(page, "Design")
    expect(page.get_by_role("textbox", name="Payload mass [kg]", exact=True)).to_have_value("30")
    assert console_errors == []


def test_bad_cases_file_shows_a_message(app_page: Page):
    page = app_page
    goto_page(page, "Compare")
    page.get_by_role("button", name="Load the thesis' GUI test cases").click()
    wait_for_rerun(page)
    expect(page.get_by_test_id("stMultiSelect").first).to_contain_text("GUI test: payload 30 kg")
    page.get_by_text("Cases file: export / import").click()
    bad = {
        "format": "aerostat-cases",
        "version": 1,
        "cases": {"ok?": {"requirement": {"altitude": -50}}},
    }
    page.get_by_test_id("stFileUploaderDropzoneInput").first.set_input_files(
        files=[
            {
                "name": "bad-cases.json",
                "mimeType": "application/json",
                "buffer": json.dumps(bad).encode(),
            }
        ]
    )
    wait_for_rerun(page)
    alert = page.get_by_test_id("stAlertContentError").filter(has_text="Could not import")
    expect(alert).to_be_visible()
    expect(alert).to_contain_text("bad-cases.json")
    expect(alert).to_contain_text("altitude")
    # nothing was added: still the four GUI test cases
    expect(page.get_by_test_id("stMultiSelect").first).not_to_contain_text("ok?")
    with page.expect_download() as info:
        page.get_by_role("button", name="Download all cases (JSON)").click()
    assert len(json.loads(info.value.path().read_text())["cases"]) == 4
    assert_no_exception(page, "Compare page after a bad upload")
