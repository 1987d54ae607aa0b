"""One form change (issue 21): the Design form builds the frozen inputs once per submit; the
page, the design cache and the plots read those objects, with no JSON text on the way."""

from __future__ import annotations

from dataclasses import replace

import pytest

from aerostat_core import Configuration, Requirement, design, thesis_baseline
from aerostat_core.model.io import inputs_to_dict
from app_ui import cache, form_model, state
from tests.app.helpers import metric_float, submit


def test_a_submit_builds_the_frozen_inputs_once_and_the_page_reads_them(at, monkeypatch):
    built, parsed = [], []
    real = form_model.inputs_from_dict
    monkeypatch.setattr(form_model, "inputs_from_dict", lambda d: built.append(1) or real(d))
    inputs_of = cache.inputs_of
    monkeypatch.setattr(cache, "inputs_of", lambda text: parsed.append(text) or inputs_of(text))
    submit(at, in_payload=12.75)
    assert not at.exception, [e.value for e in at.exception]
    assert built == [1]  # widget values -> dataclasses, once
    # the design, the report and the plots never parse the inputs' JSON (the report button
    # reads its own JSON argument through cache.given_inputs, off this path)
    assert parsed == []
    held_dict, (req, cfg) = at.session_state[cache.FROZEN_KEY]
    assert held_dict is at.session_state[state.DESIGN_KEY]  # kept beside the dict they are
    assert isinstance(req, Requirement) and isinstance(cfg, Configuration)
    assert req.payload_mass == 12.75 and req == req.resolved()
    d = design(req, cfg)
    assert metric_float(at, "Total mass [kg]") == pytest.approx(d.total_mass, abs=0.05)


def test_inputs_changed_elsewhere_are_built_once_and_then_kept():
    s: dict = {}
    state.init_state(s)
    first = cache.current_inputs(s)
    assert cache.current_inputs(s) is first  # the same objects while the dict is the same
    req, cfg = thesis_baseline()
    s[state.DESIGN_KEY] = inputs_to_dict(replace(req, payload_mass=13.25), cfg)  # an import
    second = cache.current_inputs(s)
    assert second is not first and second[0].payload_mass == 13.25
    assert second == cache.frozen_inputs(replace(req, payload_mass=13.25), cfg)
    cache.set_current(req, cfg, s)  # the form's way: the frozen inputs kept with the dict
    assert cache.current_inputs(s) == cache.frozen_inputs(req, cfg)
    assert s[cache.FROZEN_KEY][0] is s[state.DESIGN_KEY]


def test_the_design_cache_is_keyed_by_every_field_exactly():
    req, cfg = thesis_baseline()
    a = cache.design_of(req, cfg)
    assert cache.design_of(*thesis_baseline()) is a  # equal inputs built again: a hit
    b = cache.design_of(replace(req, payload_mass=req.payload_mass + 1e-9), cfg)
    assert b is not a  # one field different in the last bits: another design
    assert cache.report_of(req, cfg) is cache.report_of(*thesis_baseline())
