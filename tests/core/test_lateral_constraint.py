"""The constraint row "laterally stable up to the survival wind" (issue 25 item 3,
docs/dynamics.md §7.5): a row of the one constraint table, filled after sizing from the 6-DOF
linearisation, on in the practice rules and off in the thesis rules, in the verdict, the
summary and ``design --json``."""

from __future__ import annotations

import json
import math
from dataclasses import replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from aerostat_core import Requirement, design
from aerostat_core.cli.entry import main
from aerostat_core.dynamics.lateral_constraint import assess_lateral, lateral_stability
from aerostat_core.model.constraints import BY_NAME, NAMES, LateralStability, lateral_quantities
from aerostat_core.model.presets import practice_configuration
from aerostat_core.studies.robust import design_with_confidence

K = NAMES.index("lateral_stability")


def _cfg(area_change: float, xi_offset: float = 0.2, drop_ratio: float = 2.0):
    """80 m3 given (the static rows all hold for these fins), confluence point far aft and low:
    small fins let the hull kite."""
    c = practice_configuration(volume=80.0)
    return replace(c, fins=replace(c.fins, area_change=area_change, position=0.68),
                   confluence=replace(c.confluence, xi_offset=xi_offset, drop_ratio=drop_ratio))


def _row(d) -> dict:
    return next(r for r in d.constraint_rows() if r["constraint"] == "lateral_stability")


def test_default_practice_design_is_laterally_stable_and_says_so() -> None:
    d = design_with_confidence(Requirement())  # what the CLI and the app show
    row = _row(d)
    assert row["checked_at"] == "2-20 m/s" and row["met"]
    assert row["value"] == row["limit"] == 20.0 and math.isinf(row["margin"])
    s = d.summary().to_dict()
    assert s["lateral_stability_checked"] is True
    assert s["lateral_unstable_above_m_s"] is None and s["lateral_checked_up_to_m_s"] == 20.0
    # weathervane-stable hull (C_n_beta > 0 turns the nose into the wind) pushed sideways by a
    # sideslip from starboard (C_Y_beta < 0), as its longitudinal C_m_alpha says in pitch
    assert s["C_n_beta_per_rad"] > 0 > s["C_Y_beta_per_rad"]
    assert s["lateral_derivatives_wind_m_s"] == d.requirement.design_wind
    assert d.feasible and d.verdict().verdict == "meets"


def test_a_hull_that_kites_below_the_survival_wind_fails_with_the_advice() -> None:
    plain = design(Requirement(), _cfg(-40.0))
    # every static row holds: only the 6-DOF check finds it out
    assert plain.feasible and _row(plain)["checked_at"] == "not evaluated"
    d = assess_lateral(plain)
    row = _row(d)
    assert not row["met"] and row["value"] < row["limit"] == 20.0 and row["margin"] < 0
    assert row["g"] == pytest.approx(1.0 - row["value"] / 20.0)
    assert not d.feasible
    assert any("kiting" in v for v in d.violations)
    v = d.verdict()
    assert v.verdict == "fails" and v.binding == ("lateral_stability",)
    assert v.what_to_change == (BY_NAME["lateral_stability"].advice,)
    assert "larger fins" in v.what_to_change[0] and "further aft" in v.what_to_change[0]
    assert "lateral stability" in v.headline
    s = d.summary().to_dict()
    assert s["lateral_unstable_above_m_s"] == pytest.approx(row["value"])


def test_thesis_rules_do_not_show_the_row() -> None:
    d = design_with_confidence(Requirement(rules="thesis"))
    assert "lateral_stability" not in [r["constraint"] for r in d.constraint_rows()]
    assert d.constraints.g[K] < 0  # never binding
    s = d.summary().to_dict()
    assert s["lateral_stability_checked"] is False and s["lateral_unstable_above_m_s"] is None
    assert s["C_n_beta_per_rad"] is not None  # the derivatives are given for every rule set


def test_row_normalisation_and_not_evaluated() -> None:
    lat = LateralStability(True, 12.0, 20.0, 10.0, -2.0, 0.1, -0.5, 0.3)
    assert lateral_quantities(20.0, lat) == (12.0, 20.0, pytest.approx(0.4), -8.0)
    stable = replace(lat, unstable_above=None)
    v, lim, g, m = lateral_quantities(20.0, stable)
    assert (v, lim, g) == (20.0, 20.0, -1.0) and math.isinf(m)
    v, lim, g, m = lateral_quantities(20.0, None)
    assert math.isnan(v) and math.isnan(m) and g == -1.0 and lim == 20.0
    # an instability exactly at the survival wind is not below it
    assert lateral_quantities(20.0, replace(lat, unstable_above=20.0))[2] == -1.0


def test_result_is_cached_per_frozen_inputs() -> None:
    d = design(Requirement())
    assert lateral_stability(d) is lateral_stability(design(Requirement()))
    a = assess_lateral(d)
    assert assess_lateral(a) is a


def _onset(area_change: float) -> float:
    """Wind speed at which a lateral mode goes unstable (inf: stable up to the survival wind)."""
    lat = lateral_stability(design(Requirement(), _cfg(area_change)))
    return math.inf if lat.unstable_above is None else lat.unstable_above


@settings(max_examples=5, deadline=None)
@given(a=st.floats(-50.0, 40.0), grow=st.floats(5.0, 60.0))
def test_larger_fins_never_make_the_hull_less_laterally_stable(a, grow) -> None:
    """Larger fins raise the directional stiffness about the confluence point: the wind speed
    at which the first lateral mode goes unstable never falls (measured over -50..+50 % fin
    area in four fin/confluence layouts: stable once, stable for every larger fin)."""
    b = min(a + grow, 100.0)
    assert _onset(b) >= _onset(a)


def test_fin_area_crosses_from_kiting_to_stable() -> None:
    """The limit the hypothesis test relies on is not empty: the same layout kites with 40 %
    less fin area and is stable with the statistical fins."""
    assert _onset(-40.0) < 20.0 and _onset(0.0) == math.inf


def test_design_json_has_the_lateral_keys(capsys) -> None:
    assert main(["design", "--payload", "10", "--altitude", "300", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    for k in ("lateral_unstable_above_m_s", "lateral_stability_checked", "C_Y_beta_per_rad",
              "C_n_beta_per_rad", "C_l_beta_per_rad", "C_n_beta_confluence_per_rad",
              "lateral_checked_up_to_m_s", "lateral_derivatives_wind_m_s"):
        assert k in out
    # the keys design --json had before are all still there
    for k in ("volume_m3", "verdict", "feasible", "violations", "binding_constraint"):
        assert k in out
    assert out["lateral_unstable_above_m_s"] is None and out["verdict"] == "meets"
