"""Sensitivity and Optimise pages (AppTest, quick settings): plotted data and tables match the
engine, bad inputs give a message naming the field, a cancelled run keeps its finished tasks,
the optimum can be saved as a case."""

from __future__ import annotations

import json

import numpy as np
import pytest

from aerostat_core import thesis_baseline
from aerostat_core.model.io import inputs_from_dict, inputs_to_dict
from aerostat_core.optimize import DEFAULT_BOUNDS, VARIABLES
from aerostat_core.studies.sensitivity import one_at_a_time, two_variable_map
from tests.app.helpers import chart, chart_keys, goto, messages, table, table_with, values

SENS_PAGE = "pages/3_Sensitivity.py"
OPT_PAGE = "pages/4_Optimise.py"


@pytest.fixture
def at(thesis_at):
    """These tests check the page against the thesis' numbers: start from the thesis baseline
    (the app itself opens on the practice default)."""
    return thesis_at


def _set(at, key, value):
    for kind in ("number_input", "radio", "selectbox", "text_input", "checkbox", "multiselect"):
        for el in getattr(at, kind):
            if getattr(el, "key", None) == key:
                # number boxes are text boxes (read like the Design form's): type the number
                typed = (
                    f"{value:g}" if kind == "text_input" and not isinstance(value, str) else value
                )
                el.set_value(typed)
                return
    raise KeyError(key)


def _traces(fig, prefix):
    return [t for t in fig["data"] if str(t.get("name", "")).startswith(prefix)]


# --- Sensitivity ----------------------------------------------------------------------------------


@pytest.fixture
def sens(at):
    goto(at, SENS_PAGE)
    _set(at, "sens_level", "Quick")
    at.button(key="sens_run").click().run()
    assert not at.exception, [e.value for e in at.exception]
    return at


def test_sensitivity_sweeps_plot_the_engine_values(sens):
    req, cfg = thesis_baseline()
    assert sens.title[0].value == "Sensitivity"
    assert chart_keys(sens) == ["sens_ofat", "sens_map"]
    fig = chart(sens, "sens_ofat")
    from app_ui.optimize_view import shown

    res = one_at_a_time(req, cfg, n_points=7, resize=True)
    for name in VARIABLES:
        mass = _traces(fig, f"total_mass vs {name}")[0]
        # x in display units: the fin position in % of the hull length, as on the Design page
        assert np.allclose(values(mass, "x"), shown(name, res.sweeps[name].values))
        assert np.allclose(values(mass, "y"), res.sweeps[name].designs.total_mass, rtol=1e-9)
        bb = _traces(fig, f"blow_by vs {name}")[0]
        # re-sized: on the blow-by limit wherever it sets the size, below it elsewhere
        y = values(bb, "y")
        assert np.all(y <= req.blow_by_limit * (1 + 1e-6))
        on = res.sweeps[name].designs.binding == "blow_by"
        assert on.sum() >= 4 and np.allclose(y[on], req.blow_by_limit, rtol=1e-6)
    # the range summary, transposed (one column per variable, so it fits at 1024 px)
    df = table(sens, "Over each range").set_index("Over each range")
    from app_ui.optimize_view import var_label

    assert list(df.columns) == [var_label(k) for k in VARIABLES]
    assert df.columns[2] == "Fin position Δl_f [% of hull length]"
    low = df.loc["Low end of the range"]
    assert list(low) == pytest.approx([shown(k, DEFAULT_BOUNDS[k][0]) for k in VARIABLES])
    assert low.iloc[2] == pytest.approx(60.0)
    assert df.loc["Mass change at the high end [%]"].iloc[1] == pytest.approx(
        res.summary_rows()[1]["mass_change_high_pct"]
    )


def test_sensitivity_map_is_the_held_volume_map_with_the_limit_contour(sens):
    req, cfg = thesis_baseline()
    fig = chart(sens, "sens_map")
    m = two_variable_map(req, cfg, n=10, resize=False)
    mass = _traces(fig, "total mass")[0]
    assert np.allclose(np.array(mass["z"], float), m.total_mass, rtol=1e-9)
    limit = _traces(fig, "blow-by = limit")[0]
    assert limit["contours"]["value"] == req.blow_by_limit
    assert np.allclose(np.array(limit["z"], float), m.blow_by, rtol=1e-9)
    base = _traces(fig, "baseline")[0]
    assert values(base, "x")[0] == 4.0 and values(base, "y")[0] == 0.0


def test_sensitivity_held_sweep_and_other_map(sens):
    _set(sens, "sens_sweep_mode", "held")
    _set(sens, "sens_x", "area_change")
    _set(sens, "sens_y", "position")
    _set(sens, "sens_map_mode", "resize")
    sens.button(key="sens_run").click().run()
    assert not sens.exception
    fig = chart(sens, "sens_ofat")
    vol = _traces(fig, "volume vs area_change")[0]
    assert np.allclose(values(vol, "y"), 170.0)
    assert "hull held at 170.0 m³" in fig["layout"]["title"]["text"].replace("<br>", " ")
    mfig = chart(sens, "sens_map")
    assert "re-sized" in mfig["layout"]["title"]["text"].replace("<br>", " ")
    assert not _traces(mfig, "blow-by = limit")


@pytest.mark.parametrize(
    "changes, words",
    [
        (
            {"sens_lo_fineness_ratio": 4.0, "sens_hi_fineness_ratio": 3.0},
            ["lower bound 4 > upper bound 3", "Fineness ratio l/d"],
        ),
        # in the unit of the boxes: the fin position in % of the hull length, never a fraction
        (
            {"sens_hi_position": 99.0},
            ["Fin position", "bounds (60, 99)", "valid range [40, 95]"],
        ),
        ({"sens_lo_area_change": "-10,5.0"}, ["Fin area change", "ambiguous"]),
        ({"sens_lo_area_change": ""}, ["Fin area change", "required"]),
    ],
)
def test_sensitivity_bad_range_names_the_field(sens, changes, words):
    for k, v in changes.items():
        _set(sens, k, v)
    sens.button(key="sens_run").click().run()
    assert not sens.exception
    errs = messages(sens, "error")
    assert errs and all(w in errs[0] for w in words), errs


def test_sensitivity_same_map_variables_is_refused(sens):
    _set(sens, "sens_y", "fineness_ratio")
    sens.button(key="sens_run").click().run()
    assert not sens.exception
    assert any("two different variables" in e for e in messages(sens, "error"))
    assert chart_keys(sens) == ["sens_ofat"]


# --- Optimise -------------------------------------------------------------------------------------


@pytest.fixture
def opt(at):
    goto(at, OPT_PAGE)
    assert not at.exception
    assert at.title[0].value == "Optimise"
    _set(at, "opt_level", "Quick")
    return at


@pytest.fixture
def ran(opt):
    opt.button(key="opt_run").click().run()
    assert not opt.exception, [e.value for e in opt.exception]
    return opt


def test_optimise_quick_run_shows_agreeing_solvers_and_every_plot(ran):
    df = table(ran, "Solver")
    assert len(df) == 3
    mass = df["Total mass [kg]"].to_numpy()
    assert np.ptp(mass) / mass.min() < 0.01
    assert np.allclose(df["Blow-by [m]"], thesis_baseline()[0].blow_by_limit, rtol=1e-6)
    runs = table_with(ran, "Solver", "Evaluations")  # the comparison by theme, 3 tables
    assert list(runs["Solver"]) == list(df["Solver"])
    assert (runs["Evaluations"] > 0).all() and (runs["Time [s]"] > 0).all()
    variables = table_with(ran, "Solver", "Δl_f [% of l]")
    assert ((variables["Δl_f [% of l]"] >= 40) & (variables["Δl_f [% of l]"] <= 95)).all()
    assert any("Spread of the optimum total mass" in s for s in messages(ran, "success"))
    assert chart_keys(ran) == ["opt_convergence", "opt_performance", "opt_pareto"]
    conv = chart(ran, "opt_convergence")
    assert [t["name"] for t in conv["data"]] == list(df["Solver"])
    for t, m in zip(conv["data"], mass):
        assert values(t, "y")[-1] == pytest.approx(m)
    perf = chart(ran, "opt_performance")
    assert {t["name"] for t in perf["data"]} == {"baseline", "optimum"} and len(perf["data"]) == 8
    changes = table(ran, "Quantity")
    vol = changes[changes["Quantity"] == "Hull volume [m³]"].iloc[0]
    assert vol["Baseline"] == pytest.approx(170.0) and vol["Change"] == pytest.approx(-50, abs=2)


def test_optimise_pareto_front_contains_the_optimum(ran):
    fig = chart(ran, "opt_pareto")
    front = _traces(fig, "Pareto front")[0]
    bb, m = values(front, "x"), values(front, "y")
    assert np.all(np.diff(bb) > 0) and np.all(np.diff(m) < 0)
    df = table(ran, "Solver")
    best = df["Total mass [kg]"].min()
    limit = thesis_baseline()[0].blow_by_limit
    k = int(np.argmin(np.abs(bb - limit)))
    assert bb[k] == pytest.approx(limit, rel=1e-6) and m[k] == pytest.approx(best, rel=2e-3)
    stars = _traces(fig, "SLSQP")
    assert stars and values(stars[0], "y")[0] == pytest.approx(best, rel=1e-6)
    pt = table(ran, "Blow-by limit [m]")
    assert (pt["On front"] == "yes").sum() >= 5
    assert set(pt["On front"]) <= {"yes", "no"}  # words, never True/False


def test_save_optimum_as_case(ran):
    _set(ran, "opt_case_name", "Thesis optimum")
    ran.button(key="opt_save").click().run()
    assert not ran.exception
    cases = ran.session_state["cases"]
    assert list(cases) == ["Thesis optimum"]
    req, cfg = inputs_from_dict(cases["Thesis optimum"])
    assert cfg.hull.volume is None and -50 <= cfg.fins.area_change < -30
    assert any("Saved case" in s for s in messages(ran, "success"))


@pytest.mark.parametrize(
    "changes, words",
    [
        (
            {"opt_lo_fineness_ratio": 4.5, "opt_hi_fineness_ratio": 2.5},
            ["lower bound 4.5", "upper bound 2.5", "Fineness ratio l/d"],
        ),
        ({"opt_lo_area_change": 20.0, "opt_hi_area_change": 20.0}, ["empty", "Fin area change"]),
        ({"opt_hi_position": "96"}, ["Fin position", "% of hull length", "[40, 95]"]),
        ({"opt_pareto_n": "11,5"}, ["Points", "not a whole number"]),
        ({"opt_seed": "abc"}, ["Random seed", "not a number"]),
        ({"opt_limit": 400.0}, ["Blow-by limit", "blow_by_limit", "400"]),
        ({"opt_solvers": []}, ["choose at least one solver"]),
    ],
)
def test_optimise_bad_request_names_the_cause(opt, changes, words):
    for k, v in changes.items():
        _set(opt, k, v)
    opt.button(key="opt_run").click().run()
    assert not opt.exception
    errs = messages(opt, "error")
    assert errs and all(w in errs[0] for w in words), errs
    assert "opt_job" not in opt.session_state


def test_optimise_infeasible_limit_says_which_constraint_binds(opt):
    _set(opt, "opt_limit", 5.0)
    _set(opt, "opt_solvers", ["surrogate", "pso"])
    _set(opt, "opt_pareto_on", False)
    opt.button(key="opt_run").click().run()
    assert not opt.exception
    errs = messages(opt, "error")
    assert len(errs) == 2 and all("no feasible design found" in e for e in errs)
    assert all("safety factor" in e or "blow-by" in e for e in errs)
    assert chart_keys(opt) == ["opt_convergence"]


def test_cancelled_run_keeps_finished_tasks(opt):
    from app_ui import optimize_view as view

    inputs = json.dumps(inputs_to_dict(*thesis_baseline()), sort_keys=True, separators=(",", ":"))
    request = view.build_request(
        inputs,
        limit=thesis_baseline()[0].blow_by_limit,
        bounds=DEFAULT_BOUNDS,
        objective="total_mass",
        level="quick",
        seed=0,
        solvers=["slsqp", "pso"],
        pareto=True,
        pareto_points=5,
        pareto_low=0.8,
        pareto_high=1.5,
    )
    state = {}
    view.start_job(request, state)
    job = state[view.JOB_KEY]
    assert job["tasks"] == ["slsqp", "pso", "pareto"]
    job["done"]["slsqp"] = view.cached_solve(
        *view.inputs_from_json(request["inputs"]),
        request["bounds"],
        "total_mass",
        "slsqp",
        "quick",
        0,
    )
    job["cancelled"] = True
    opt.session_state[view.JOB_KEY] = job
    opt.run()
    assert not opt.exception
    assert any("Run cancelled: 1 of 3 tasks" in w for w in messages(opt, "warning"))
    assert list(table(opt, "Solver")["Solver"]) == ["SLSQP (2 starts)"]
    assert "opt_pareto" not in chart_keys(opt)
    assert list(opt.session_state[view.JOB_KEY]["done"]) == ["slsqp"]


def _quick_request(solvers=("pso",)):
    from app_ui import optimize_view as view

    inputs = json.dumps(inputs_to_dict(*thesis_baseline()), sort_keys=True, separators=(",", ":"))
    return view.build_request(
        inputs,
        limit=thesis_baseline()[0].blow_by_limit,
        bounds=DEFAULT_BOUNDS,
        objective="total_mass",
        level="quick",
        seed=0,
        solvers=list(solvers),
        pareto=False,
        pareto_points=5,
        pareto_low=0.8,
        pareto_high=1.5,
    )


def test_progress_is_reported_per_batch_naming_the_solver_and_shared_runs_skip_it():
    from app_ui import optimize_view as view

    r = _quick_request()
    calls: list[tuple[float, str]] = []
    args = (*view.inputs_from_json(r["inputs"]), r["bounds"], "total_mass", "pso", "quick", 123)
    first = view.solve_shared(*args, progress=lambda f, t: calls.append((f, t)))
    # one report per generation of the swarm (quick: 20), each naming the solver
    assert len(calls) >= 20
    assert all(t.startswith("Particle swarm: ") for _, t in calls)
    fracs = [f for f, _ in calls]
    assert fracs == sorted(fracs) and fracs[-1] == pytest.approx(1.0)
    again: list = []
    assert view.solve_shared(*args, progress=lambda f, t: again.append(t)) is first
    assert again == []  # a second session gets the shared result without recomputing


def test_cancelling_a_new_run_keeps_the_previous_results(opt):
    from app_ui import optimize_view as view

    old = _quick_request(["slsqp"])
    view.start_job(old, opt.session_state)
    opt.run()  # the first run finishes
    assert not opt.exception
    assert list(table(opt, "Solver")["Solver"]) == ["SLSQP (2 starts)"]
    new = _quick_request(["pso"])
    view.start_job(new, opt.session_state)
    job = opt.session_state[view.JOB_KEY]
    job["cancelled"] = True  # Cancel pressed before the swarm finished
    opt.session_state[view.JOB_KEY] = job
    opt.run()
    assert not opt.exception
    assert any("previous run's results are shown" in w for w in messages(opt, "warning"))
    assert list(table(opt, "Solver")["Solver"]) == ["SLSQP (2 starts)"]


def test_an_optimisation_over_the_compute_budget_is_refused_before_it_runs():
    from dataclasses import replace

    from aerostat_core.model.budget import BudgetError
    from app_ui import optimize_view as view

    req, cfg = thesis_baseline()
    heavy = json.dumps(
        inputs_to_dict(req, replace(cfg, tether_segments=2000)),
        sort_keys=True,
        separators=(",", ":"),
    )
    with pytest.raises(BudgetError, match="This optimisation"):
        view.build_request(
            heavy,
            limit=req.blow_by_limit,
            bounds=DEFAULT_BOUNDS,
            objective="total_mass",
            level="quick",
            seed=0,
            solvers=["pso"],
            pareto=False,
            pareto_points=5,
            pareto_low=0.8,
            pareto_high=1.5,
        )


# --- decimal comma (issue 9: "12,5" was read as 125 by the browser's number boxes) -------------


def test_sensitivity_reads_a_decimal_comma_as_a_point(sens):
    _set(sens, "sens_lo_fineness_ratio", "2,5")
    _set(sens, "sens_hi_fineness_ratio", "4,5")
    _set(sens, "sens_hi_position", "72,5")  # % of the hull length
    sens.button(key="sens_run").click().run()
    assert not sens.exception and not messages(sens, "error")
    fig = chart(sens, "sens_ofat")
    f = values(_traces(fig, "total_mass vs fineness_ratio")[0], "x")
    assert f.min() == pytest.approx(2.5) and f.max() == pytest.approx(4.5)
    pos = values(_traces(fig, "total_mass vs position")[0], "x")
    assert pos.max() == pytest.approx(72.5)  # never 725 (refused) nor 7.25


def test_optimise_reads_a_decimal_comma_as_a_point(opt):
    _set(opt, "opt_lo_area_change", "-12,5")
    _set(opt, "opt_hi_position", "72,5")
    _set(opt, "opt_limit", "53,5")
    _set(opt, "opt_pareto_low", "0,8")
    _set(opt, "opt_solvers", ["slsqp"])
    opt.button(key="opt_run").click().run()
    assert not opt.exception and not messages(opt, "error")
    request = opt.session_state["opt_job"]["request"]
    bounds = {name: (lo, hi) for name, lo, hi in request["bounds"]}
    assert bounds["area_change"][0] == -12.5
    assert bounds["position"][1] == pytest.approx(0.725)
    assert json.loads(request["inputs"])["requirement"]["blow_by_limit"] == 53.5
    assert min(request["limits"]) == pytest.approx(0.8 * 53.5)
