"""The per-request compute budget: what it refuses, what it lets through, and that every library
entry point applies it before doing the work."""

from __future__ import annotations

from dataclasses import replace

import pytest

from aerostat_core import design, thesis_baseline
from aerostat_core.model import budget
from aerostat_core.model.io import inputs_to_dict
from aerostat_core.optimize import OptimizationProblem, solve
from aerostat_core.output.report import case_designs
from aerostat_core.studies.sensitivity import one_at_a_time, two_variable_map


def _heavy():
    req, cfg = thesis_baseline()
    return replace(req, wind_step=0.1), replace(cfg, tether_segments=5000)


def test_units_are_the_product_of_the_three_factors():
    assert budget.units(50, 22, 3) == 3300
    assert budget.check(2000, 22) == 44_000


def test_the_issue_example_is_refused_with_what_to_reduce():
    req, cfg = _heavy()  # 5000 segments, 0.1 m/s steps to 20 m/s: 8 s per design before
    with pytest.raises(budget.BudgetError) as err:
        design(req, cfg)
    msg = str(err.value)
    assert "5000 tether segments x 202 wind speeds x 1 case" in msg
    assert "Reduce the tether segments to at most 2475" in msg and "wind step" in msg
    assert err.value.units == 5000 * 202 > budget.MAX_UNITS


def test_the_suggested_reduction_is_accepted():
    req, cfg = _heavy()
    with pytest.raises(budget.BudgetError):
        budget.check_design(req, cfg)
    ok = replace(cfg, tether_segments=budget.MAX_UNITS // 202)
    assert budget.check_design(req, ok) <= budget.MAX_UNITS
    with pytest.raises(budget.BudgetError):
        budget.check_design(req, replace(cfg, tether_segments=ok.tether_segments + 1))


def test_everyday_requests_pass():
    req, cfg = thesis_baseline()
    assert budget.check_design(req, cfg) == 50 * 22
    cases = {f"c{i}": inputs_to_dict(req, cfg) for i in range(200)}  # the case limit
    assert budget.check_cases(cases) == 200 * 50 * 22


def test_a_comparison_counts_every_case():
    req, cfg = thesis_baseline()
    big = inputs_to_dict(req, replace(cfg, tether_segments=2000))
    cases = {f"c{i}": big for i in range(12)}  # 12 x 2000 x 22 = 528 000
    with pytest.raises(budget.BudgetError, match="fewer cases"):
        case_designs(cases)


def test_sweeps_maps_and_optimisations_are_checked_before_work():
    req, cfg = thesis_baseline()
    cfg = replace(cfg, tether_segments=5000)
    with pytest.raises(budget.BudgetError, match="These sweeps"):
        one_at_a_time(req, cfg, n_points=101)  # 304 designs x 5000
    with pytest.raises(budget.BudgetError, match="This map"):
        two_variable_map(req, cfg, n=20)  # 400 designs x 5000
    with pytest.raises(budget.BudgetError, match="optimisation"):
        solve(OptimizationProblem(req, cfg), "pso")
