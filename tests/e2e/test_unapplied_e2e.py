"""Edits in the Design form never vanish without a word (issue 20): Enter applies them (and
they are kept across a page switch), and a page switch with edits not applied asks first."""

from __future__ import annotations

import pytest
from playwright.sync_api import Page, expect

from tests.e2e.helpers import assert_no_exception, goto_page, sidebar_nav_link, wait_for_rerun

pytestmark = pytest.mark.e2e

PAYLOAD = "Payload mass [kg]"


def _box(page: Page):
    return page.get_by_role("textbox", name=PAYLOAD, exact=True)


def test_enter_applies_and_a_page_switch_asks_before_dropping_edits(page: Page):
    page.goto("/")
    wait_for_rerun(page, timeout=120_000)  # the first run may import plotly, scipy...
    box = _box(page)
    box.fill("33")
    box.press("Enter")  # applies the form, like "Update design"
    wait_for_rerun(page, timeout=90_000)
    goto_page(page, "Compare", timeout=90_000)
    goto_page(page, "Design", timeout=90_000)
    expect(_box(page)).to_have_value("33")  # applied, so kept across the page switch

    asked: list[str] = []

    def dismiss(dialog) -> None:
        asked.append(dialog.message)
        dialog.dismiss()

    page.once("dialog", dismiss)
    _box(page).fill("44")  # typed, not applied
    sidebar_nav_link(page, "Compare").click()
    page.wait_for_timeout(500)
    assert asked and "not applied" in asked[0]
    expect(_box(page)).to_have_value("44")  # still on the Design page, the edit still there
    expect(page.get_by_role("heading", name="Aerostat design")).to_be_visible()
    page.get_by_role("button", name="Update design").first.click()
    wait_for_rerun(page, timeout=90_000)
    goto_page(page, "Compare", timeout=90_000)  # applied now: no question
    goto_page(page, "Design", timeout=90_000)
    expect(_box(page)).to_have_value("44")
    assert len(asked) == 1
    assert_no_exception(page, "Design after Enter and a page switch")
