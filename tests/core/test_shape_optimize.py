"""Shape as a categorical choice in the optimisation (issue 12)."""

from __future__ import annotations

import pytest

from aerostat_core.model.presets import thesis_configuration, thesis_requirement
from aerostat_core.optimize import OptimizationProblem, solve
from aerostat_core.studies.shape_optimize import optimize_shapes, shape_bounds


@pytest.fixture(scope="module")
def study():
    return optimize_shapes(
        thesis_requirement(),
        thesis_configuration(None),
        shapes=("npl", "gnvr", "sphere", "helikite"),
    )


def test_best_per_shape_and_overall(study):
    assert list(study.per_shape) == ["npl", "gnvr", "sphere", "helikite"]
    feasible = {s: r.objective for s, r in study.per_shape.items() if r.feasible}
    assert study.best == min(feasible, key=feasible.get)
    rows = study.rows()
    assert rows[0]["shape"] == study.best and rows[0]["best"]
    assert study.per_shape["sphere"].method == "grid"
    assert study.per_shape["sphere"].x["fineness_ratio"] == 1.0
    lo, hi = 2.0, 6.0
    assert lo <= study.per_shape["gnvr"].x["fineness_ratio"] <= hi


def test_npl_optimum_is_the_plain_optimiser(study):
    req, cfg = thesis_requirement(), thesis_configuration(None)
    r = solve(OptimizationProblem(req, cfg), "slsqp", "quick")
    assert study.per_shape["npl"].objective == pytest.approx(r.objective, rel=1e-9)
    # the streamlined thesis hull beats the bluff ones at this blow-by limit (Figure 2.5)
    assert study.per_shape["npl"].objective < study.per_shape["helikite"].objective
    assert study.per_shape["helikite"].objective < study.per_shape["sphere"].objective


def test_bounds_are_cut_to_the_shape_range_and_inputs_checked():
    assert shape_bounds("gnvr", {"fineness_ratio": (1.5, 2.5)})["fineness_ratio"] == (2.0, 2.5)
    assert "fineness_ratio" not in shape_bounds(
        "gnvr", {"fineness_ratio": (1.5, 1.9), "position": (0.6, 0.7)}
    )
    req, cfg = thesis_requirement(), thesis_configuration(None)
    with pytest.raises(ValueError, match="not a known hull shape"):
        optimize_shapes(req, cfg, shapes=("cigar",))
    with pytest.raises(ValueError, match="objective"):
        optimize_shapes(req, cfg, objective="cost")


def test_fineness_sweeps_per_shape():
    from aerostat_core.studies.shape_optimize import fineness_sweeps

    sw = fineness_sweeps(thesis_requirement(), thesis_configuration(None), ("npl", "sphere"), 5)
    assert sw["sphere"].fineness_ratio.tolist() == [1.0]
    assert sw["npl"].fineness_ratio[0] == 1.5 and sw["npl"].fineness_ratio[-1] == 8.0
    assert sw["npl"].volume.shape == (5,) and sw["npl"].feasible.any()


def test_fineness_outside_the_shape_range_is_refused_in_batches():
    from aerostat_core.optimize import evaluate_designs

    cfg = thesis_configuration(None)
    from dataclasses import replace

    from aerostat_core import HullSpec

    cfg = replace(cfg, hull=HullSpec(shape="helikite"))
    with pytest.raises(ValueError, match=r"2.5 is outside .*\[1, 1.6\] for shape 'helikite'"):
        evaluate_designs(thesis_requirement(), cfg, fineness_ratio=[1.2, 2.5])
