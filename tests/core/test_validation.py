"""Structured input errors, numbers.Real conversion, degenerate values and hostile names."""

from __future__ import annotations

import json
import math
from dataclasses import replace
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from aerostat_core import (
    Configuration,
    FinSpec,
    HullSpec,
    Requirement,
    design,
    thesis_baseline,
)
from aerostat_core.base.validation import (
    MAX_MESSAGE_CHARS,
    POSITIVE_FLOOR,
    InputError,
    check_name,
    check_number,
)
from aerostat_core.model.io import design_to_json, inputs_to_dict


def test_input_error_is_a_value_error_with_the_details():
    with pytest.raises(InputError) as err:
        Requirement(payload_mass=-5)
    e = err.value
    assert isinstance(e, ValueError)
    assert str(e) == "Requirement.payload_mass = -5 kg is outside the valid range (0, 500] kg"
    assert (e.owner, e.field, e.value, e.lo, e.hi, e.unit) == (
        "Requirement",
        "payload_mass",
        -5,
        0,
        500,
        "kg",
    )
    assert e.lo_open and not e.hi_open and e.valid_range == "(0, 500] kg"
    assert e.label == "Payload mass" and e.reason == "is outside the valid range (0, 500] kg"


def test_not_a_number_keeps_the_old_message_and_is_capped():
    with pytest.raises(InputError, match=r"HullSpec.volume = 'big' is not a number"):
        HullSpec(volume="big")
    with pytest.raises(InputError) as err:
        HullSpec(volume="x" * 900_000)
    assert len(str(err.value)) <= MAX_MESSAGE_CHARS and err.value.field == "volume"


@pytest.mark.parametrize("value", [Fraction(21, 2), np.float32(10.5), np.int64(10), 10])
def test_any_real_is_stored_as_float(value):
    req = Requirement(payload_mass=value)
    assert type(req.payload_mass) is float and req.payload_mass == float(value)
    json.loads(design_to_json(req, Configuration()))  # exports without TypeError


def test_whole_numbers_are_stored_as_int():
    cfg = Configuration(tether_segments=np.int64(60), fins=FinSpec(count=np.float64(4.0)))
    assert type(cfg.tether_segments) is int and type(cfg.fins.count) is int
    assert json.loads(json.dumps(inputs_to_dict(Requirement(), cfg)))


def test_degenerate_tiny_values_are_refused():
    with pytest.raises(InputError, match="too small to compute with"):
        FinSpec(area_ratio=1e-300)
    assert FinSpec(area_ratio=POSITIVE_FLOOR * 2).area_ratio > 0


@settings(deadline=None)  # a design takes 30 ms, 300 ms on a loaded 2-core machine
@given(st.floats(min_value=-99.0, max_value=0.0))
def test_tiny_accepted_fin_areas_give_finite_results(exp10):
    area = 10.0**exp10
    if area < 2 * POSITIVE_FLOOR:
        return
    req, cfg = thesis_baseline()
    s = design(req, replace(cfg, fins=replace(cfg.fins, area_ratio=area))).summary()
    assert all(math.isfinite(v) for v in s.values() if isinstance(v, float))


@pytest.mark.parametrize(
    "name, reason",
    [
        ("\ud83d", "lone surrogate"),
        ("a\udc00b", "lone surrogate"),
        ("x\x00y", "control"),
        ("x\x1by", "control"),
        ("x\x7fy", "control"),
        ("x\x9by", "control"),
        ("x\u202ey", "text-direction"),
    ],
)
def test_hostile_names_are_refused(name, reason):
    with pytest.raises(InputError, match=reason):
        check_name("case", "name", name)


def test_ordinary_unicode_names_pass():
    assert check_name("case", "name", "  Ballon d’essai 🎈 ×2 (ü) ") == "Ballon d’essai 🎈 ×2 (ü)"
    assert check_name("case", "name", "family 👨‍👩‍👧") == "family 👨‍👩‍👧"  # ZWJ kept


def test_check_number_range_text():
    with pytest.raises(InputError) as err:
        check_number("X", "y", 7, 1, 5, "m", hi_open=True)
    assert err.value.valid_range == "[1, 5) m"
