"""Optimisation: the solvers on analytic problems with known optima, the thesis preset (three
solvers agree within 1 %, the optimum meets every constraint, calibrated ~120 m3), the Pareto front
(non-dominated, contains the single-objective optimum, not beaten by NSGA-II), bad requests."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from aerostat_core import design, thesis_baseline, thesis_optimized
from aerostat_core.model.presets import THESIS_BLOW_BY_LIMIT, THESIS_OPTIMUM
from aerostat_core.optimize import (
    BOUNDS_REASONS,
    CONSTRAINTS,
    DEFAULT_BOUNDS,
    FEASIBILITY_TOL,
    THESIS_REPORTED,
    VARIABLE_INFO,
    BoundsError,
    FunctionProblem,
    OptimizationProblem,
    agreement,
    baseline_vs_optimum,
    check_bounds,
    compare_solvers,
    comparison_rows,
    default_limits,
    evaluate_designs,
    history_rows,
    nondominated_mask,
    optimum_inputs,
    pareto_front,
    pareto_nsga2,
    solve,
    solve_pso,
    solve_slsqp,
    solve_surrogate,
    thesis_comparison_rows,
)
from aerostat_core.optimize.lockstep import fd_gradient, fd_stencil

SOLVER_FUNCS = (solve_slsqp, solve_surrogate, solve_pso)


# --- analytic problems with known optima --------------------------------------------------------


def circle_problem() -> tuple[FunctionProblem, np.ndarray, float]:
    """min (x-2)^2 + (y-1)^2 s.t. x^2 + y^2 <= 1: optimum (2, 1)/sqrt(5), f = (sqrt(5)-1)^2."""
    p = FunctionProblem(
        lambda X: (X[:, 0] - 2) ** 2 + (X[:, 1] - 1) ** 2,
        lambda X: (X[:, 0] ** 2 + X[:, 1] ** 2 - 1.0)[:, None],
        {"x": (-2.0, 3.0), "y": (-2.0, 3.0)},
    )
    return p, np.array([2.0, 1.0]) / np.sqrt(5.0), (np.sqrt(5.0) - 1.0) ** 2


def box_problem() -> tuple[FunctionProblem, np.ndarray, float]:
    """min (a-.3)^2 + (b-.6)^2 + (c+.5)^2 s.t. a + b <= 0.7 on [0,1]^3: a constraint and a bound
    active, optimum (0.2, 0.5, 0), f = 0.27 (like the aerostat problem: one bound, one g)."""
    p = FunctionProblem(
        lambda X: (X[:, 0] - 0.3) ** 2 + (X[:, 1] - 0.6) ** 2 + (X[:, 2] + 0.5) ** 2,
        lambda X: (X[:, 0] + X[:, 1] - 0.7)[:, None],
        {"a": (0.0, 1.0), "b": (0.0, 1.0), "c": (0.0, 1.0)},
    )
    return p, np.array([0.2, 0.5, 0.0]), 0.27


def two_basin_problem() -> tuple[FunctionProblem, np.ndarray, float]:
    """Two minima on [-2, 2]^2 (global at (1.5, 1.5), f = -1; local at (-1.5, -1.5), f = -0.6)
    with x + y >= 0.5 excluding neither: a multi-start/global solver must pick the global one."""

    def f(X):
        g1 = np.exp(-((X[:, 0] - 1.5) ** 2 + (X[:, 1] - 1.5) ** 2))
        g2 = 0.6 * np.exp(-((X[:, 0] + 1.5) ** 2 + (X[:, 1] + 1.5) ** 2))
        return -(g1 + g2)

    p = FunctionProblem(
        f,
        lambda X: (X[:, 0] - X[:, 1] - 3.0)[:, None],
        {"x": (-2.0, 2.0), "y": (-2.0, 2.0)},
        start=[-1.4, -1.6],
    )
    return p, np.array([1.5, 1.5]), -1.0 - 0.6 * np.exp(-18.0)


@pytest.mark.parametrize(
    "make", [circle_problem, box_problem, two_basin_problem], ids=["circle", "box", "two-basin"]
)
@pytest.mark.parametrize("solver", SOLVER_FUNCS, ids=["slsqp", "surrogate", "pso"])
def test_every_solver_finds_the_known_optimum(make, solver) -> None:
    p, x_star, f_star = make()
    r = solver(p, seed=3)
    x = np.array(list(r.x.values()))
    assert r.feasible
    tol_x = 1e-3 if solver is solve_slsqp else 2e-2
    assert np.allclose(x, x_star, atol=tol_x * np.ptp([p.lower, p.upper])), (r.x, x_star)
    assert r.objective == pytest.approx(f_star, rel=1e-2, abs=1e-3)
    assert r.n_evaluations > 0 and r.n_batches > 0
    h = r.history
    assert h.evaluations.size == r.n_batches and h.evaluations[-1] == r.n_evaluations
    best = h.best[np.isfinite(h.best)]
    assert np.all(np.diff(best) <= 0) and best[-1] == pytest.approx(r.objective)


@pytest.mark.parametrize("solver", SOLVER_FUNCS, ids=["slsqp", "surrogate", "pso"])
def test_solvers_are_reproducible_with_a_seed(solver) -> None:
    p, _, _ = box_problem()
    a, b = solver(p, seed=11), solver(p, seed=11)
    assert a.x == b.x and a.n_evaluations == b.n_evaluations
    assert np.array_equal(a.history.best, b.history.best, equal_nan=True)


def test_finite_difference_stencil_is_second_order_everywhere() -> None:
    h = 1e-3
    for u in (np.array([0.5, 0.5, 0.5]), np.array([0.0, 1.0, 0.9995]), np.array([5e-4, 0.3, 1.0])):
        pts, kind = fd_stencil(u, h)
        assert np.all((pts >= 0) & (pts <= 1))
        vals = np.sin(3 * pts[:, 0]) + pts[:, 1] ** 3 + np.exp(pts[:, 2])
        exact = np.array([3 * np.cos(3 * u[0]), 3 * u[1] ** 2, np.exp(u[2])])
        assert np.allclose(fd_gradient(vals, kind, h), exact, atol=2e-5)


def test_cancel_returns_the_best_so_far() -> None:
    p, _, _ = box_problem()
    calls = []
    for solver in SOLVER_FUNCS:
        r = solver(p, seed=1, progress=lambda f, t: calls.append(f), stop=lambda: True)
        assert r.status == "cancelled" and r.n_batches == 1
    assert calls and all(0.0 <= f <= 1.0 for f in calls)


# --- the thesis preset ----------------------------------------------------------------------------


@pytest.fixture(scope="module")
def thesis_problem() -> OptimizationProblem:
    return OptimizationProblem(*thesis_baseline())


@pytest.fixture(scope="module")
def thesis_results(thesis_problem):
    return compare_solvers(thesis_problem, "normal", seed=0)


def test_three_solvers_agree_on_the_thesis_optimum_within_one_percent(thesis_results) -> None:
    assert [r.solver for r in thesis_results] == ["slsqp", "surrogate", "pso"]
    assert all(r.feasible for r in thesis_results)
    assert agreement(thesis_results) < 0.01
    masses = [r.objective for r in thesis_results]
    rows = comparison_rows(thesis_results)
    assert [row["total_mass_kg"] for row in rows] == pytest.approx(masses)
    # The counts are the designs actually evaluated: the history's last cumulative count, one
    # history entry per batch, and each run level's budget (SETTINGS["normal"]) respected.
    for r, row in zip(thesis_results, rows):
        assert row["evaluations"] == r.n_evaluations == r.history.evaluations[-1]
        assert row["batches"] == r.n_batches == len(r.history.evaluations)
        assert np.all(np.diff(r.history.evaluations) > 0) and r.history.evaluations[0] > 0
        assert np.isfinite(row["time_s"]) and row["time_s"] > 0
    slsqp, surrogate, pso = thesis_results
    # SLSQP: a batch holds each live start's point and its 2 d finite-difference points
    per_point = 1 + 2 * len(slsqp.x)
    assert np.all(np.diff(slsqp.history.evaluations, prepend=0) % per_point == 0)
    assert slsqp.n_batches <= slsqp.settings["max_rounds"]
    assert surrogate.n_evaluations == surrogate.settings["max_evaluations"]
    assert pso.n_evaluations == pso.settings["pop_size"] * pso.settings["max_generations"]
    assert len(history_rows(thesis_results)) == sum(r.n_batches for r in thesis_results)


def test_thesis_optimum_meets_every_constraint(thesis_problem, thesis_results) -> None:
    req = thesis_problem.requirement
    for r in thesis_results:
        x = np.array([[r.x[k] for k in thesis_problem.names]])
        b = thesis_problem.evaluate(x)
        assert b.feasible[0], b.violations(0)
        assert np.all(b.constraints[0] <= FEASIBILITY_TOL)
        d = r.design
        assert d["blow_by_m"] <= req.blow_by_limit * (1 + 1e-6)
        assert d["cm_alpha_per_rad"] < 0 and d["free_lift_N"] > 0
        assert d["safety_factor"] >= req.min_tether_safety_factor
        assert d["fin_te_over_length"] <= 1.0
        for k, (lo, hi) in DEFAULT_BOUNDS.items():
            assert lo <= r.x[k] <= hi
        # the blow-by limit binds: V*(x) is the smallest feasible hull
        assert "blow_by" in r.active


def test_thesis_calibration_and_preset_constants(thesis_results) -> None:
    """Calibrated: the blow-by limit puts the optimum at ~120 m3. Predicted: its mass and the
    design variables, which presets.THESIS_OPTIMUM records."""
    best = min(thesis_results, key=lambda r: r.objective)
    assert best.design["volume_m3"] == pytest.approx(THESIS_REPORTED["optimum_volume_m3"], rel=0.02)
    assert THESIS_BLOW_BY_LIMIT == thesis_baseline()[0].blow_by_limit
    # The fineness ratio is pinned by the problem; fin area and fin position trade along a valley
    # of equal weathervane margin (the three solvers stop at different points of it, within
    # 0.05 % in mass), so the recorded point is checked on the valley: near it within 3 % of the
    # bounds' span, and as heavy as the best found within 0.05 %.
    for k, v in THESIS_OPTIMUM.items():
        scale = np.ptp(DEFAULT_BOUNDS[k])
        tol = 0.01 if k == "fineness_ratio" else 0.03
        assert best.x[k] == pytest.approx(v, abs=tol * scale)
    recorded = design(*thesis_optimized())
    assert recorded.feasible
    assert recorded.total_mass == pytest.approx(best.objective, rel=5e-4)
    # prediction, not a calibration: 64.7 kg vs the thesis' 71.6 kg (-9.6 %: smaller fins, f 2.5)
    assert best.objective == pytest.approx(THESIS_REPORTED["optimum_mass_kg"], rel=0.15)


def test_baseline_to_optimum_changes_match_the_thesis_order(thesis_results) -> None:
    req, cfg = thesis_baseline()
    best = min(thesis_results, key=lambda r: r.objective)
    rows = {r["quantity"]: r for r in baseline_vs_optimum(req, cfg, best.x)}
    assert rows["Hull volume"]["baseline"] == pytest.approx(170.0)
    assert rows["Hull volume"]["change"] == pytest.approx(-50.0, abs=2.0)
    # (the gas cost change is not checked: the price is derived from the same USD 1925 / 50 m3,
    # so it would only restate the volume change above)
    assert rows["Total mass"]["change"] < -15.0
    t = {r["quantity"]: r for r in thesis_comparison_rows(list(rows.values()))}
    assert t["Gas fill cost"]["thesis_change"] == -1925.0
    assert t["Total mass"]["thesis_change"] == pytest.approx(71.6 - 90.65)
    req_o, cfg_o = optimum_inputs(OptimizationProblem(req, cfg), best)
    assert cfg_o.hull.volume is None and cfg_o.fins.area_change == best.x["area_change"]


def test_quick_setting_also_agrees(thesis_problem) -> None:
    res = [solve(thesis_problem, s, "quick", seed=0) for s in ("slsqp", "surrogate", "pso")]
    assert all(r.feasible for r in res) and agreement(res) < 0.01


# --- nested sizing -----------------------------------------------------------------------------


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.floats(2.5, 4.5), st.floats(-50.0, 100.0), st.floats(0.6, 0.75), st.floats(25.0, 120.0))
def test_sized_volume_is_the_smallest_meeting_the_limit(f, dsf, pos, limit) -> None:
    req, cfg = thesis_baseline()
    req = dataclasses.replace(req, blow_by_limit=limit)
    cfg = cfg.with_design_variables(volume=None)
    b = evaluate_designs(req, cfg, f, dsf, pos)
    assert np.all(np.isfinite(b.constraints)) and np.all(np.isfinite(b.total_mass))
    if b.sizing_feasible[0]:
        assert b.blow_by[0] <= limit * (1 + 1e-6)
        smaller = evaluate_designs(req, cfg, f, dsf, pos, volume=b.volume * 0.999)
        assert smaller.blow_by[0] > limit or smaller.free_lift[0] <= 0


def test_sized_volume_is_smooth_enough_for_finite_differences() -> None:
    req, cfg = thesis_baseline()
    cfg = cfg.with_design_variables(volume=None)
    f = 3.0 + np.arange(21) * 2e-3
    m = evaluate_designs(req, cfg, f, -30.8, 0.67).total_mass
    second = np.diff(m, 2)
    assert np.max(np.abs(second)) < 5e-5  # a 1e-4 staircase in V would give ~5e-3 kg jumps


# --- Pareto front --------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def front(thesis_results):
    req, cfg = thesis_baseline()
    best = min(thesis_results, key=lambda r: r.objective)
    return pareto_front(req, cfg, starts=[best.x])


def test_pareto_front_is_nondominated_and_feasible(front) -> None:
    on = front.nondominated
    assert on.sum() >= 8
    m, bb = front.total_mass[on], front.blow_by[on]
    for i in range(m.size):
        dominated = (m <= m[i]) & (bb <= bb[i]) & ((m < m[i]) | (bb < bb[i]))
        assert not dominated.any()
    assert np.all(front.feasible[on])
    assert np.all(front.blow_by[front.feasible] <= front.limits[front.feasible] * (1 + 1e-6))
    # mass falls as the limit is relaxed
    order = np.argsort(bb)
    assert np.all(np.diff(m[order]) < 0)
    # infeasible points say why
    for i in np.nonzero(~front.feasible)[0]:
        assert front.reason[i]
    assert len(front.rows()) == front.limits.size


def test_pareto_front_contains_the_single_objective_optimum(front, thesis_results) -> None:
    req = thesis_baseline()[0]
    best = min(thesis_results, key=lambda r: r.objective)
    k = int(np.argmin(np.abs(front.limits - req.blow_by_limit)))
    assert front.limits[k] == pytest.approx(req.blow_by_limit)
    assert front.nondominated[k]
    assert front.total_mass[k] == pytest.approx(best.objective, rel=2e-3)
    assert front.mass_at(req.blow_by_limit) == pytest.approx(best.objective, rel=2e-3)
    # no front point is both lighter and within the limit
    assert not np.any(
        front.feasible
        & (front.blow_by <= req.blow_by_limit)
        & (front.total_mass < best.objective * (1 - 2e-3))
    )


def test_nsga2_does_not_beat_the_epsilon_front(front) -> None:
    req, cfg = thesis_baseline()
    nsga = pareto_nsga2(req, cfg, pop_size=40, generations=40, seed=1)
    assert nsga.volume.size >= 5 and np.all(nsga.nondominated)
    for i in np.nonzero(front.nondominated)[0]:
        better = (nsga.blow_by <= front.blow_by[i]) & (
            nsga.total_mass < front.total_mass[i] * (1 - 5e-3)
        )
        assert not better.any(), (front.blow_by[i], front.total_mass[i])


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 20), st.integers(0, 20)), min_size=1, max_size=30))
def test_nondominated_mask_properties(points) -> None:
    a = np.array([p[0] for p in points], float)
    b = np.array([p[1] for p in points], float)
    nd = nondominated_mask(a, b)
    assert nd.any()
    for i in range(a.size):
        dom = (a <= a[i]) & (b <= b[i]) & ((a < a[i]) | (b < b[i]))
        assert nd[i] == (not dom.any())


def test_default_limits_include_the_requirement() -> None:
    req = thesis_baseline()[0]
    lim = default_limits(req, 7)
    assert req.blow_by_limit in lim and lim.max() <= req.altitude and np.all(np.diff(lim) > 0)


# --- bad requests ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "bounds, words",
    [
        ({}, ["empty"]),
        ({"fineness_ratio": (4.5, 2.5)}, ["lower bound 4.5", "upper bound 2.5", "fineness_ratio"]),
        ({"area_change": (10.0, 10.0)}, ["empty", "area_change"]),
        ({"span": (1.0, 2.0)}, ["unknown", "span"]),
        ({"position": (0.3, 0.7)}, ["position", "valid range [0.4, 0.95]"]),
        ({"fineness_ratio": (float("nan"), 3.0)}, ["finite", "fineness_ratio"]),
        ({"fineness_ratio": ("a", 3.0)}, ["two numbers", "fineness_ratio"]),
        ({"fineness_ratio": (2.0,)}, ["two numbers", "fineness_ratio"]),
    ],
)
def test_bad_bounds_raise_a_clear_value_error(bounds, words) -> None:
    with pytest.raises(ValueError) as exc:
        OptimizationProblem(*thesis_baseline(), bounds=bounds)
    for w in words:
        assert w in str(exc.value)


@pytest.mark.parametrize(
    "bounds, reason, variable, lower, upper",
    [
        ([("position", 0.6, 0.7)], "not a mapping", "", None, None),
        ({}, "no variables", "", None, None),
        ({"span": (1.0, 2.0)}, "unknown", "span", None, None),
        ({"fineness_ratio": ("a", 3.0)}, "not numbers", "fineness_ratio", None, None),
        ({"fineness_ratio": (float("nan"), 3.0)}, "not finite", "fineness_ratio", np.nan, 3.0),
        ({"fineness_ratio": (4.5, 2.5)}, "order", "fineness_ratio", 4.5, 2.5),
        ({"area_change": (10.0, 10.0)}, "empty", "area_change", 10.0, 10.0),
        ({"position": (0.6, 0.99)}, "range", "position", 0.6, 0.99),
        ({"position": (0.3, 0.7)}, "range", "position", 0.3, 0.7),
    ],
)
def test_bounds_error_carries_the_reason_variable_bounds_and_valid_range(
    bounds, reason, variable, lower, upper
) -> None:
    """The one bounds check raises a structured error a form can word in its own units."""
    with pytest.raises(BoundsError) as exc:
        check_bounds(bounds)
    e = exc.value
    assert isinstance(e, ValueError) and e.reason == reason and e.reason in BOUNDS_REASONS
    assert e.variable == variable
    for got, want in ((e.lower, lower), (e.upper, upper)):  # the bounds as given
        assert got is None if want is None else np.array_equal(got, want, equal_nan=True)
    if variable in VARIABLE_INFO:
        label, unit, valid = VARIABLE_INFO[variable]
        assert (e.label, e.unit, e.valid) == (label, unit, valid)
    else:
        assert e.valid is None and e.label == ""
    if variable == "position":
        assert e.valid == (0.4, 0.95)  # the fraction of the hull length, the engine's unit


def test_bounds_inside_the_valid_range_pass_unchanged() -> None:
    assert check_bounds({"position": (0.4, 0.95), "fineness_ratio": (3, 4)}) == {
        "position": (0.4, 0.95),
        "fineness_ratio": (3.0, 4.0),
    }


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(sorted(DEFAULT_BOUNDS)), st.floats(-1e3, 1e3), st.floats(-1e3, 1e3))
def test_any_bounds_are_accepted_or_rejected_with_the_variable_named(name, lo, hi) -> None:
    try:
        p = OptimizationProblem(*thesis_baseline(), bounds={name: (lo, hi)})
    except ValueError as exc:
        assert name in str(exc)
    else:
        assert p.names == (name,) and p.lower[0] < p.upper[0]


def test_other_bad_requests() -> None:
    req, cfg = thesis_baseline()
    with pytest.raises(ValueError, match="objective"):
        OptimizationProblem(req, cfg, objective="cost")
    p = OptimizationProblem(req, cfg)
    with pytest.raises(ValueError, match="solver"):
        solve(p, "newton")
    with pytest.raises(ValueError, match="setting"):
        solve(p, "pso", "slow")
    with pytest.raises(ValueError, match="n_starts"):
        solve_slsqp(p, n_starts=0)
    with pytest.raises(ValueError, match="blow-by limit 400"):
        pareto_front(req, cfg, limits=[30.0, 400.0])
    with pytest.raises(ValueError, match="empty"):
        pareto_front(req, cfg, limits=[])


def test_infeasible_limit_returns_an_infeasible_result_naming_the_binding_constraint() -> None:
    req, cfg = thesis_baseline()
    req = dataclasses.replace(req, blow_by_limit=5.0)
    p = OptimizationProblem(req, cfg)
    small = {
        "slsqp": {"maxiter": 8},
        "surrogate": {"max_evaluations": 40},
        "pso": {"max_generations": 6},
    }
    for name in ("slsqp", "surrogate", "pso"):
        r = solve(p, name, "quick", seed=0, **small[name])
        assert not r.feasible and r.status == "infeasible"
        assert r.message.startswith("no feasible design found")
        assert "safety factor" in r.message or "blow-by" in r.message


def test_fixed_variables_are_held_at_the_configuration() -> None:
    req, cfg = thesis_baseline()
    p = OptimizationProblem(req, cfg, bounds={"area_change": (-50.0, 100.0)})
    r = solve(p, "slsqp", "quick")
    assert r.x["fineness_ratio"] == 4.0 and r.x["position"] == 0.68
    assert len(CONSTRAINTS) == p.n_constr and p.n_var == 1
    assert any(row["item"] == "fixed position" for row in p.describe())


def test_default_limits_hold_the_requirement_limit_once() -> None:
    req = thesis_baseline()[0]
    lims = default_limits(req)
    assert np.sum(np.isclose(lims, req.blow_by_limit, rtol=1e-6)) == 1


def test_rows_and_curves_from_designs_already_made_equal_the_designing_calls() -> None:
    """Optimise designs the baseline and the optimum once and hands them to both tables."""
    from aerostat_core import design
    from aerostat_core.optimize import (
        curves_of,
        design_change_rows,
        optimum_configuration,
        performance_curves,
    )

    req, cfg = thesis_baseline()
    x = {"fineness_ratio": 3.0, "area_change": -20.0, "position": 0.7}
    base, opt = design(req, cfg), design(req, optimum_configuration(cfg, x))
    assert design_change_rows(base, opt) == baseline_vs_optimum(req, cfg, x)
    a, b = curves_of(opt), performance_curves(req, optimum_configuration(cfg, x))
    assert a["total_mass"] == b["total_mass"] and np.array_equal(a["blow_by"], b["blow_by"])
    assert opt.configuration.fins.area_change == -20.0 and base.volume != opt.volume
