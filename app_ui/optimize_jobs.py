"""Background work of the Sensitivity and Optimise pages: cached engine calls, the solver results
shared by every session, and the optimisation job (one task per solver, then the Pareto front).

Cache keys are canonical JSON texts (inputs dict, bounds), so two sessions with the same request
share one computation, and every stochastic solver is seeded, so a cached result means something.
The page shows a progress bar and a Cancel button while the tasks run. Pressing Cancel
interrupts the script at the next progress update (Streamlit reruns on a click); the finished
tasks are kept in the session and shown, the rest are skipped.
"""

from __future__ import annotations

import json
import threading
from collections import OrderedDict
from collections.abc import Mapping, MutableMapping, Sequence
from typing import Any

import streamlit as st

from aerostat_core.optimize import (
    SOLVERS,
    OptimizationProblem,
    OptimizationResult,
    ParetoFront,
    curves_of,
    design_change_rows,
    optimum_configuration,
    pareto_front,
    performance_comparison_rows,
    solve,
    thesis_comparison_rows,
)
from aerostat_core.sensitivity import (
    SensitivityMap,
    SensitivityResult,
    one_at_a_time,
    two_variable_map,
)

from . import cache
from .optimize_form import inputs_from_json

#: Session keys of the optimisation job and the case-save feedback.
JOB_KEY = "opt_job"
#: The last run that produced results, shown again when a newer run is cancelled before any.
PREVIOUS_JOB_KEY = "opt_previous_job"
TASK_LABELS = {**{k: v[0] for k, v in SOLVERS.items()}, "pareto": "Pareto front"}

# --- cached engine calls --------------------------------------------------------------------------


@st.cache_data(max_entries=64, show_spinner=False)
def cached_sensitivity(
    inputs_json: str, ranges_json: str, n_points: int, resize: bool
) -> SensitivityResult:
    """:func:`aerostat_core.sensitivity.one_at_a_time` of the inputs."""
    return one_at_a_time(*inputs_from_json(inputs_json), json.loads(ranges_json), n_points, resize)


@st.cache_data(max_entries=64, show_spinner=False)
def cached_map(
    inputs_json: str, x_var: str, y_var: str, ranges_json: str, n: int, resize: bool
) -> SensitivityMap:
    """:func:`aerostat_core.sensitivity.two_variable_map` of the inputs."""
    return two_variable_map(*inputs_from_json(inputs_json), x_var, y_var, json.loads(ranges_json), n, resize)


@st.cache_data(max_entries=128, show_spinner=False)
def cached_solve(
    inputs_json: str, bounds_json: str, objective: str, solver: str, level: str, seed: int
) -> OptimizationResult:
    """One seeded solver run (:func:`aerostat_core.optimize.solve`)."""
    p = OptimizationProblem(*inputs_from_json(inputs_json), json.loads(bounds_json), objective)
    return solve(p, solver, level, seed)


#: Largest number of solver results kept for every session (the cache of :func:`solve_shared`).
SHARED_RESULTS = 64
_shared_lock = threading.Lock()


@st.cache_resource(show_spinner=False)
def _shared_results() -> OrderedDict:
    """Solver results shared by every session, keyed by the request (an LRU of
    :data:`SHARED_RESULTS`). A resource cache rather than ``st.cache_data``: the run draws its
    progress bar while it runs, which a replayed ``st.cache_data`` call must never do."""
    return OrderedDict()


def solve_shared(
    inputs_json: str,
    bounds_json: str,
    objective: str,
    solver: str,
    level: str,
    seed: int,
    progress: Any = None,
) -> OptimizationResult:
    """:func:`cached_solve` that reports ``progress(fraction, text)`` after every batch (the
    solver's own callback, which names the solver) when it has to compute; a request any
    session has run before returns at once."""
    key = (inputs_json, bounds_json, objective, solver, level, int(seed))
    cache = _shared_results()
    with _shared_lock:
        if key in cache:
            cache.move_to_end(key)
            return cache[key]
    p = OptimizationProblem(*inputs_from_json(inputs_json), json.loads(bounds_json), objective)
    result = solve(p, solver, level, seed, progress=progress)
    with _shared_lock:
        cache[key] = result
        while len(cache) > SHARED_RESULTS:
            cache.popitem(last=False)
    return result


@st.cache_data(max_entries=64, show_spinner=False)
def cached_pareto(
    inputs_json: str, bounds_json: str, objective: str, limits: tuple, starts_json: str
) -> ParetoFront:
    """Epsilon-constraint front (:func:`aerostat_core.optimize.pareto_front`)."""
    req, cfg = inputs_from_json(inputs_json)
    return pareto_front(
        req,
        cfg,
        json.loads(bounds_json),
        list(limits),
        objective=objective,
        starts=json.loads(starts_json),
    )


@st.cache_data(max_entries=64, show_spinner=False)
def cached_comparison(inputs_json: str, baseline_json: str, x_json: str) -> dict[str, Any]:
    """Baseline (the design inputs as given) versus optimum (sized): change rows, thesis rows
    and performance curves of both."""
    req, _ = inputs_from_json(inputs_json)
    _, cfg_base = inputs_from_json(baseline_json)
    x = json.loads(x_json)
    # each design once, from the shared cache, for both the change rows and the curves
    d_base = cache.design_of(req, cfg_base)
    d_opt = cache.design_of(req, optimum_configuration(cfg_base, x))
    rows = design_change_rows(d_base, d_opt)
    base, opt = curves_of(d_base), curves_of(d_opt)
    return {
        "changes": rows,
        "thesis": thesis_comparison_rows(rows),
        "baseline": base,
        "optimum": opt,
        "performance_rows": performance_comparison_rows(base, opt),
    }


# --- the optimisation job (chunked across tasks, cancellable) ------------------------------------


def start_job(request: dict[str, Any], state: MutableMapping[str, Any] | None = None) -> None:
    """Queue a run: one task per solver, then the Pareto front when limits were given. The
    previous run with results is kept (:data:`PREVIOUS_JOB_KEY`), so cancelling the new one
    before it has any leaves those results on screen."""
    s = st.session_state if state is None else state
    old = s.get(JOB_KEY)
    if old and solver_results(old):
        s[PREVIOUS_JOB_KEY] = old
    tasks = list(request["solvers"]) + (["pareto"] if request["limits"] else [])
    s[JOB_KEY] = {
        "request": request,
        "tasks": tasks,
        "done": {},
        "cancelled": False,
        "finished": False,
    }


def cancel_job() -> None:
    """Cancel button callback: the remaining tasks are skipped."""
    job = st.session_state.get(JOB_KEY)
    if job and not job["finished"]:
        job["cancelled"] = True


def current_job() -> dict[str, Any] | None:
    """The last queued run (finished, cancelled or running), if any."""
    return st.session_state.get(JOB_KEY)


def solver_results(job: Mapping[str, Any]) -> list[OptimizationResult]:
    """Finished solver results of a job, in solver order."""
    return [job["done"][s] for s in job["request"]["solvers"] if s in job["done"]]


def best_result(results: Sequence[OptimizationResult]) -> OptimizationResult | None:
    """The feasible result with the least objective (None when none is feasible)."""
    feas = [r for r in results if r.feasible]
    return min(feas, key=lambda r: r.objective) if feas else None


def _run_task(
    request: Mapping[str, Any], task: str, done: Mapping[str, Any], progress: Any = None
) -> Any:
    """Run one task of a job (a solver, or the Pareto front started from the best optimum); cached."""
    if task == "pareto":
        best = best_result([v for k, v in done.items() if k != "pareto"])
        starts = [best.x] if best is not None else []
        return cached_pareto(
            request["inputs"],
            request["bounds"],
            request["objective"],
            tuple(request["limits"]),
            json.dumps(starts, sort_keys=True),
        )
    return solve_shared(
        request["inputs"],
        request["bounds"],
        request["objective"],
        task,
        request["level"],
        request["seed"],
        progress=progress,
    )


def run_job() -> None:
    """Run the remaining tasks of the current job with a progress bar and a Cancel button."""
    job = current_job()
    if not job or job["finished"] or job["cancelled"]:
        return
    box = st.empty()
    with box.container():
        st.button(
            "Cancel",
            on_click=cancel_job,
            key="opt_cancel",
            icon=":material/cancel:",
            help="Stop after the task that is running; finished results are kept.",
        )
        bar = st.progress(0.0, text="Starting…")
    tasks = job["tasks"]
    for k, task in enumerate(tasks):
        if task in job["done"]:
            continue
        head = f"{TASK_LABELS[task]} ({k + 1}/{len(tasks)})"
        bar.progress(k / len(tasks), text=f"Running {head}…")

        def progress(frac: float, text: str, k: int = k) -> None:
            # Every batch (at most ~0.3 s apart): the bar moves and names the running solver.
            share = min(max(float(frac), 0.0), 1.0)
            bar.progress((k + share) / len(tasks), text=f"{text} (task {k + 1}/{len(tasks)})")

        try:
            job["done"][task] = _run_task(job["request"], task, job["done"], progress)
        except ValueError as exc:  # e.g. a Pareto range the engine rejects
            job["done"][task] = exc
    bar.progress(1.0, text="Done")
    job["finished"] = True
    box.empty()
