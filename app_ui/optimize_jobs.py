"""Background work of the Sensitivity and Optimise pages: cached engine calls, the solver results
shared by every session, and the optimisation job (one task per solver, then the Pareto front).

Every engine call is cached through :func:`app_ui.cache.memo`, the one process-wide store: the
key is the frozen inputs (resolved Requirement, Configuration) plus the request's other
parameters as hashable values (bounds as ``((variable, lower, upper), ...)`` in the order of
the variables, numbers, names), one :class:`~typing.NamedTuple` per study (:class:`SensitivityKey`
...), so every compute reads its key by field name, never by position. A NamedTuple is a tuple
(hashed and compared by value), so two sessions with the same request share one computation,
and every stochastic solver is seeded, so a cached result means something. A request the engine
rejects (``ValueError``) or a cancelled run stores nothing. Results are shared, not copied:
read-only.

The page shows a progress bar and a Cancel button while the tasks run. Pressing Cancel
interrupts the script at the next progress update (Streamlit reruns on a click); the finished
tasks are kept in the session and shown, the rest are skipped. The solvers draw that bar only
when they compute: a cached result returns at once, so no bar is ever replayed.
"""

from __future__ import annotations

from collections.abc import Mapping, MutableMapping, Sequence
from typing import Any, NamedTuple

import streamlit as st

from aerostat_core import Configuration, Requirement
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
from aerostat_core.studies.sensitivity import (
    SensitivityMap,
    SensitivityResult,
    one_at_a_time,
    two_variable_map,
)

from . import cache
from .optimize_form import Bounds, bounds_dict, bounds_items

#: Session keys of the optimisation job and the case-save feedback.
JOB_KEY = "opt_job"
#: The last run that produced results, shown again when a newer run is cancelled before any.
PREVIOUS_JOB_KEY = "opt_previous_job"
TASK_LABELS = {**{k: v[0] for k, v in SOLVERS.items()}, "pareto": "Pareto front"}

#: Largest number of results of each study kept for every session.
STUDY_RESULTS = 64
#: Largest number of solver results kept for every session (the cache of :func:`solve_shared`).
SHARED_RESULTS = 64

#: Design variables {name: value} as a cache key: ((name, value), ...) sorted by name.
Variables = tuple[tuple[str, float], ...]

# --- the study keys (one per cache kind; each is a tuple, hashable and equal by value) ----------


class SensitivityKey(NamedTuple):
    """Key of the one-at-a-time sweeps ("sensitivity")."""

    requirement: Requirement  # resolved (:func:`app_ui.cache.frozen_inputs`)
    configuration: Configuration
    bounds: Bounds  # the sweep range of each variable
    n_points: int  # points per sweep
    resize: bool  # hull re-sized to the requirement at every point


class MapKey(NamedTuple):
    """Key of the two-variable map ("sensitivity_map")."""

    requirement: Requirement
    configuration: Configuration
    x_variable: str
    y_variable: str
    bounds: Bounds
    n_points: int  # grid points per axis
    resize: bool


class SolveKey(NamedTuple):
    """Key of one seeded solver run ("solve")."""

    requirement: Requirement
    configuration: Configuration
    bounds: Bounds
    objective: str
    solver: str
    level: str  # run level ("quick", "normal")
    seed: int


class ParetoKey(NamedTuple):
    """Key of the epsilon-constraint front ("pareto")."""

    requirement: Requirement
    configuration: Configuration
    bounds: Bounds
    objective: str
    limits: tuple[float, ...]  # blow-by limits of the front [m]
    starts: tuple[Variables, ...]  # starting designs besides the configuration's


class ComparisonKey(NamedTuple):
    """Key of the baseline-versus-optimum comparison ("optimum_comparison")."""

    requirement: Requirement  # the run's requirement, for both designs
    configuration: Configuration  # the baseline: the design inputs as given
    optimum: Variables  # the optimum's design variables (the hull sized)


# --- cached engine calls --------------------------------------------------------------------------


def cached_sensitivity(
    req: Requirement,
    cfg: Configuration,
    ranges: Mapping[str, Sequence[float]] | Bounds,
    n_points: int,
    resize: bool,
) -> SensitivityResult:
    """:func:`aerostat_core.studies.sensitivity.one_at_a_time` of the inputs (raises ValueError)."""
    req_k, cfg_k = cache.frozen_inputs(req, cfg)
    key = SensitivityKey(
        requirement=req_k,
        configuration=cfg_k,
        bounds=bounds_items(ranges),
        n_points=int(n_points),
        resize=bool(resize),
    )
    return cache.memo(
        "sensitivity",
        key,
        lambda: one_at_a_time(
            key.requirement,
            key.configuration,
            ranges=bounds_dict(key.bounds),
            n_points=key.n_points,
            resize=key.resize,
        ),
        STUDY_RESULTS,
    )


def cached_map(
    req: Requirement,
    cfg: Configuration,
    x_var: str,
    y_var: str,
    ranges: Mapping[str, Sequence[float]] | Bounds,
    n: int,
    resize: bool,
) -> SensitivityMap:
    """:func:`aerostat_core.studies.sensitivity.two_variable_map` of the inputs (raises ValueError)."""
    req_k, cfg_k = cache.frozen_inputs(req, cfg)
    key = MapKey(
        requirement=req_k,
        configuration=cfg_k,
        x_variable=str(x_var),
        y_variable=str(y_var),
        bounds=bounds_items(ranges),
        n_points=int(n),
        resize=bool(resize),
    )
    return cache.memo(
        "sensitivity_map",
        key,
        lambda: two_variable_map(
            key.requirement,
            key.configuration,
            x_variable=key.x_variable,
            y_variable=key.y_variable,
            ranges=bounds_dict(key.bounds),
            n=key.n_points,
            resize=key.resize,
        ),
        STUDY_RESULTS,
    )


def solve_shared(
    req: Requirement,
    cfg: Configuration,
    bounds: Mapping[str, Sequence[float]] | Bounds,
    objective: str,
    solver: str,
    level: str,
    seed: int,
    progress: Any = None,
) -> OptimizationResult:
    """One seeded solver run (:func:`aerostat_core.optimize.solve`), shared by every session.

    ``progress(fraction, text)`` is called after every batch (the solver's own callback, which
    names the solver) only when the run has to compute; a request any session has run before
    returns at once. A run interrupted from ``progress`` (Cancel) stores nothing.
    """
    req_k, cfg_k = cache.frozen_inputs(req, cfg)
    key = SolveKey(
        requirement=req_k,
        configuration=cfg_k,
        bounds=bounds_items(bounds),
        objective=str(objective),
        solver=str(solver),
        level=str(level),
        seed=int(seed),
    )

    def compute() -> OptimizationResult:
        problem = OptimizationProblem(
            key.requirement, key.configuration, bounds_dict(key.bounds), key.objective
        )
        return solve(problem, key.solver, key.level, key.seed, progress=progress)

    return cache.memo("solve", key, compute, SHARED_RESULTS)


def cached_solve(
    req: Requirement,
    cfg: Configuration,
    bounds: Mapping[str, Sequence[float]] | Bounds,
    objective: str,
    solver: str,
    level: str,
    seed: int,
) -> OptimizationResult:
    """:func:`solve_shared` without a progress callback (the same cache)."""
    return solve_shared(req, cfg, bounds, objective, solver, level, seed)


def _x_items(x: Mapping[str, float]) -> Variables:
    """Design variables {name: value} as hashable items, sorted by name."""
    return tuple(sorted((str(k), float(v)) for k, v in x.items()))


def cached_pareto(
    req: Requirement,
    cfg: Configuration,
    bounds: Mapping[str, Sequence[float]] | Bounds,
    objective: str,
    limits: Sequence[float],
    starts: Sequence[Mapping[str, float]] = (),
) -> ParetoFront:
    """Epsilon-constraint front (:func:`aerostat_core.optimize.pareto_front`), started from
    ``starts`` (design-variable dicts; raises ValueError)."""
    req_k, cfg_k = cache.frozen_inputs(req, cfg)
    key = ParetoKey(
        requirement=req_k,
        configuration=cfg_k,
        bounds=bounds_items(bounds),
        objective=str(objective),
        limits=tuple(float(v) for v in limits),
        starts=tuple(_x_items(x) for x in starts),
    )
    return cache.memo(
        "pareto",
        key,
        lambda: pareto_front(
            key.requirement,
            key.configuration,
            bounds=bounds_dict(key.bounds),
            limits=list(key.limits),
            objective=key.objective,
            starts=[dict(x) for x in key.starts],
        ),
        STUDY_RESULTS,
    )


def cached_comparison(
    req: Requirement, cfg_base: Configuration, x: Mapping[str, float]
) -> dict[str, Any]:
    """Baseline (the design inputs ``cfg_base`` as given) versus optimum (variables ``x``, sized)
    under the run's requirement ``req``: change rows, thesis rows and performance curves of
    both."""
    req_k, cfg_k = cache.frozen_inputs(req, cfg_base)
    key = ComparisonKey(requirement=req_k, configuration=cfg_k, optimum=_x_items(x))

    def compute() -> dict[str, Any]:
        # each design once, from the shared cache, for both the change rows and the curves
        d_base = cache.design_of(key.requirement, key.configuration)
        d_opt = cache.design_of(
            key.requirement, optimum_configuration(key.configuration, dict(key.optimum))
        )
        rows = design_change_rows(d_base, d_opt)
        b, o = curves_of(d_base), curves_of(d_opt)
        return {
            "changes": rows,
            "thesis": thesis_comparison_rows(rows),
            "baseline": b,
            "optimum": o,
            "performance_rows": performance_comparison_rows(b, o),
        }

    return cache.memo("optimum_comparison", key, compute, STUDY_RESULTS)


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
    req, cfg = cache.inputs_of(request["inputs"])
    if task == "pareto":
        best = best_result([v for k, v in done.items() if k != "pareto"])
        return cached_pareto(
            req,
            cfg,
            request["bounds"],
            request["objective"],
            request["limits"],
            [best.x] if best is not None else [],
        )
    return solve_shared(
        req,
        cfg,
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
