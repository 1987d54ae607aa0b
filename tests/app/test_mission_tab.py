"""Design page, Mission tab (AppTest): the mission outputs of the current design, the survival
verdict, and the mission inputs form writing into the design inputs."""

from __future__ import annotations

from dataclasses import replace

import pytest

from aerostat_core import design
from app_ui import state
from tests.app.helpers import messages, metric, metric_float, show_tab, table


@pytest.fixture
def at(thesis_at):
    """The thesis baseline (given volume), as these checks assume."""
    return thesis_at


def test_mission_tab_shows_the_design_mission_outputs(at):
    show_tab(at, "Mission")
    assert not at.exception
    d = design(*state.current_inputs(at.session_state))
    s = d.summary()
    assert metric_float(at, "Winch pull [N]") == pytest.approx(s["winch_pull_N"], abs=0.5)
    assert metric_float(at, "Ballonet [m³]") == pytest.approx(s["ballonet_volume_m3"], abs=0.05)
    t = table(at, "Group")
    assert set(t["Group"]) == {"Power", "Endurance", "Ballonet", "Envelope", "Survival", "Winch"}
    row = t[t["Quantity"] == "Motor power"]
    assert float(row["Value"].iloc[0]) == pytest.approx(s["winch_power_W"])
    assert any("survival wind" in m for m in messages(at, "success") + messages(at, "warning"))


def test_mission_form_writes_the_inputs_and_resizes(at):
    show_tab(at, "Mission")
    before = design(*state.current_inputs(at.session_state))
    at.text_input(key="mission_power").set_value("50")  # a text box: "12,5" reads as 12.5
    at.text_input(key="mission_endurance").set_value("3,0")
    at.button(key="FormSubmitter:mission_form-Apply mission inputs").click()
    at.run()
    assert not at.exception
    req, cfg = state.current_inputs(at.session_state)
    assert (req.payload_power, req.power_via, req.endurance_days) == (50.0, "onboard", 3.0)
    after = design(req, cfg)
    assert float(after.airframe.mass.items["battery"]) > 0
    # the thesis baseline keeps its given volume: the battery eats into the free lift instead
    assert after.free_lift < before.free_lift
    assert metric(at, "Days to top-up") in {f"{after.summary().mission.days_to_top_up:,.1f}", "never"}


def test_ballonet_hint_where_the_500_m_rule_calls_for_one(at):
    req, cfg = state.current_inputs(at.session_state)
    state.set_current_inputs(replace(req, altitude=1000.0), cfg, at.session_state)
    show_tab(at, "Mission")
    assert not at.exception
    assert any("500 m rule" in m for m in messages(at, "info"))
    at.selectbox(key="mission_ballonet").set_value("auto")
    at.button(key="FormSubmitter:mission_form-Apply mission inputs").click()
    at.run()
    req2, cfg2 = state.current_inputs(at.session_state)
    assert cfg2.mission.ballonet == "auto"
    assert float(design(req2, cfg2).airframe.mass.items["ballonet"]) > 0
    assert not any("500 m rule" in m for m in messages(at, "info"))
