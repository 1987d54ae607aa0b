"""Sensitivity and optimisation in a real browser: the Sensitivity page draws its sweeps and map;
a quick optimisation run shows the comparison table, plots and Pareto front; its CSV downloads
and parses; the optimum is saved as a case that the Compare page lists (same session)."""

from __future__ import annotations

import csv
import io

import pytest
from playwright.sync_api import Page, expect

from tests.e2e.helpers import assert_no_exception, goto_page, screenshot, wait_for_rerun

pytestmark = pytest.mark.e2e

#: Optimisation reruns import scipy/pymoo on first use and run three solvers [ms].
RUN_TIMEOUT_MS = 120_000


def test_sensitivity_then_quick_optimisation(thesis_page: Page, console_errors: list[str]):
    page = thesis_page

    goto_page(page, "Sensitivity", timeout=RUN_TIMEOUT_MS)
    assert_no_exception(page, "Sensitivity page")
    expect(page.get_by_role("heading", name="Sensitivity", exact=True)).to_be_visible()
    plots = page.locator(".js-plotly-plot")
    expect(plots).to_have_count(2, timeout=RUN_TIMEOUT_MS)
    expect(plots.nth(1).locator(".legendtext").filter(has_text="blow-by = limit")).to_have_count(1)

    goto_page(page, "Optimise", timeout=RUN_TIMEOUT_MS)
    assert_no_exception(page, "Optimise page")
    page.get_by_text("Quick", exact=True).click()
    page.get_by_role("button", name="Run optimisation").click()
    wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
    assert_no_exception(page, "Optimise page after a run")
    expect(
        page.get_by_role("heading", name="Solver comparison (thesis Table 4.12)")
    ).to_be_visible()
    expect(page.get_by_text("Spread of the optimum total mass between solvers")).to_be_visible()
    expect(page.locator(".js-plotly-plot")).to_have_count(3)
    pareto = page.locator(".js-plotly-plot").nth(2)
    expect(pareto.locator(".legendtext").filter(has_text="Pareto front")).to_have_count(1)

    with page.expect_download() as info:
        page.get_by_role("button", name="Comparison (CSV)").click()
    units, *rows = csv.DictReader(io.StringIO(info.value.path().read_text()))
    assert units["total_mass_kg"] == "kg"  # the row of units under the header
    assert [r["solver"].split(" (")[0] for r in rows] == [
        "SLSQP",
        "RBF surrogate",
        "Particle swarm",
    ]
    masses = [float(r["total_mass_kg"]) for r in rows]
    assert (max(masses) - min(masses)) / min(masses) < 0.01
    assert all(r["feasible"] == "True" for r in rows)

    page.get_by_role("textbox", name="Case name").fill("optimum e2e")
    # commit the name (its own rerun) before the click, as a user's Tab would: on a loaded
    # machine the click's rerun can otherwise start after the 200 ms settle of wait_for_rerun
    page.get_by_role("textbox", name="Case name").press("Tab")
    wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
    page.get_by_role("button", name="Save optimum as case").click()
    wait_for_rerun(page, timeout=RUN_TIMEOUT_MS)
    expect(page.get_by_text("Saved case “optimum e2e”")).to_be_visible(timeout=RUN_TIMEOUT_MS)
    page.get_by_role(
        "heading", name="Solver comparison (thesis Table 4.12)"
    ).scroll_into_view_if_needed()
    screenshot(page, "optimise")

    goto_page(page, "Compare", timeout=RUN_TIMEOUT_MS)
    assert_no_exception(page, "Compare page")
    expect(page.get_by_test_id("stMultiSelect").first).to_contain_text("optimum e2e")
    assert console_errors == []
