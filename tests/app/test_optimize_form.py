"""The Sensitivity and Optimise forms' bounds: one check in the engine (``check_bounds``), its
structured error worded in the unit of the boxes (the fin position in % of the hull length)."""

from __future__ import annotations

import pytest

from aerostat_core.optimize import BOUNDS_REASONS, BoundsError, check_bounds
from app_ui.optimize_form import bounds_items, bounds_message, parse_ranges


@pytest.mark.parametrize(
    "texts, message",
    [
        (
            {"position": ("60", "99")},
            "Fin position Δl_f [% of hull length]: bounds (60, 99) leave the valid range [40, 95]",
        ),
        (
            {"position": ("70", "60")},
            "Fin position Δl_f [% of hull length]: lower bound 70 > upper bound 60",
        ),
        (
            {"position": ("70", "70,0")},
            "Fin position Δl_f [% of hull length]: the bounds are empty (lower = upper = 70)",
        ),
        (
            {"area_change": ("-60", "10")},
            "Fin area change ΔS_f [%]: bounds (-60, 10) leave the valid range [-50, 200]",
        ),
    ],
)
def test_a_bad_bound_quotes_the_numbers_as_typed(texts, message):
    with pytest.raises(ValueError) as exc:
        parse_ranges(texts, "from", "to")
    assert str(exc.value).startswith(message)
    assert "0.99" not in str(exc.value) and "0.95" not in str(exc.value)  # never the fraction


def test_the_form_words_the_engine_error_it_catches():
    """The form has no check of its own: the engine's error, reworded with the typed numbers."""
    with pytest.raises(BoundsError) as exc:
        check_bounds({"position": (0.605, 0.99)})
    assert exc.value.reason == "range"
    text = bounds_message(exc.value, {"position": (60.5, 99.0)})
    assert text.endswith("bounds (60.5, 99) leave the valid range [40, 95]")


@pytest.mark.parametrize(
    "bounds, reason",
    [
        ({"position": (0.7, 0.6)}, "order"),
        ({"position": (0.7, 0.7)}, "empty"),
        ({"position": (0.3, 0.7)}, "range"),
        ({"position": (float("nan"), 0.7)}, "not finite"),
    ],
)
def test_every_reason_a_typed_box_can_give_is_worded_in_the_boxes_unit(bounds, reason):
    """A reason the form does not word would fall back to the engine's text, which quotes the fin
    position as a fraction: every reason two number boxes can produce has the form's words."""
    with pytest.raises(BoundsError) as exc:
        check_bounds(bounds)
    assert exc.value.reason == reason and reason in BOUNDS_REASONS
    typed = {k: tuple(100.0 * v for v in pair) for k, pair in bounds.items()}
    text = bounds_message(exc.value, typed)
    assert text.startswith("Fin position Δl_f [% of hull length]: ")
    assert str(exc.value) not in text  # the form's own wording, not the engine's message


def test_good_bounds_reach_the_engine_in_its_units():
    got = parse_ranges({"position": ("60,5", "72,5"), "fineness_ratio": ("2,5", "4")}, "a", "b")
    assert got == {"position": (0.605, 0.725), "fineness_ratio": (2.5, 4.0)}


def test_bounds_items_are_one_canonical_hashable_key():
    a = bounds_items({"position": (0.6, 0.75), "fineness_ratio": (2.5, 4.5)})
    b = bounds_items({"fineness_ratio": [2.5, 4.5], "position": [0.6, 0.75]})
    assert a == b and hash(a) == hash(b)
    assert a == (("fineness_ratio", 2.5, 4.5), ("position", 0.6, 0.75))  # variable order
    assert bounds_items(a) == a
