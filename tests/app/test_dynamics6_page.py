"""Dynamics page, 6-DOF section (AppTest): the form comes from the registry, a bad value gives
one message with the label and the range, a crosswind-gust run shows the lateral results, the
mode table and both exports with units."""

from __future__ import annotations

import json

import pytest
from streamlit.testing.v1 import AppTest

from aerostat_core.base.fields import specs
from aerostat_core.dynamics.scenarios6 import Request6
from app_ui import sixdof_view as six
from tests.app.conftest import APP_PATH
from tests.app.helpers import metrics

DYN_PAGE = "pages/5_Dynamics.py"


@pytest.fixture
def dyn() -> AppTest:
    at = AppTest.from_file(str(APP_PATH), default_timeout=300)
    at.run()
    at.switch_page(DYN_PAGE)
    at.run()
    assert not at.exception, [e.value for e in at.exception]
    return at


def _box(at: AppTest, key: str):
    for el in [*at.number_input, *at.selectbox]:
        if getattr(el, "key", None) == key:
            return el
    raise KeyError(key)


def test_form_fields_come_from_the_registry():
    sp = specs(Request6)
    for sc in six.SCENARIO_LABELS:
        for f in six.form_fields(sc):
            s = sp[f["name"]]
            assert f["label"].startswith(s.label) and (f["min"], f["max"]) == (s.lo, s.hi)


def test_bad_value_names_the_label_and_the_range(dyn):
    _box(dyn, "dyn6_crosswind-gust_speed").set_value(99.0)
    dyn.run()
    assert not dyn.exception
    errs = [e.value for e in dyn.error]
    assert any("Mean wind at the aerostat" in e and "99" in e and "40" in e for e in errs), errs


def test_crosswind_gust_run_shows_lateral_results_and_exports(dyn):
    _box(dyn, "dyn6_crosswind-gust_duration").set_value(30.0)
    _box(dyn, "dyn6_crosswind-gust_segments").set_value(6)
    dyn.button(key="dyn6_run").click()
    dyn.run()
    assert not dyn.exception, [e.value for e in dyn.exception]
    labels = {m.label: m.value for m in metrics(dyn)}
    assert float(labels["Roll peak [deg]"]) > 0.1
    assert float(labels["Lateral peak [m]"]) > 1.0
    assert labels["Laterally unstable above [m/s]"] == "stable"
    assert any("Frequency [Hz]" in t.value.columns for t in dyn.table)
    out = dyn.session_state["dyn6_out"]
    head = out["csv"].splitlines()
    cols = next(line for line in head if line.startswith("t_s,"))
    assert "roll_deg" in cols and "y_C_m" in cols and "beta_deg" in cols
    js = json.loads(out["json"])
    assert js["units"]["yaw"] == "deg" and len(js["signals"]["roll"]) == len(js["t"])
