"""UI layer of the Sensitivity and Optimise pages: cached engine wrappers, figures, tables and the
chunked optimisation run (progress bar + cancel).

Everything physical comes from :mod:`aerostat_core.optimize` and :mod:`aerostat_core.sensitivity`;
this module only caches, arranges and draws. Cache keys are canonical JSON texts (inputs dict,
bounds), so two sessions with the same request share one computation, and every stochastic solver
is seeded, so a cached result means something.

Optimisation runs in tasks (one per solver, then the Pareto front), each a cached call; the page
shows a progress bar and a Cancel button while they run. Pressing Cancel interrupts the script at
the next progress update (Streamlit reruns on a click); the finished tasks are kept in the session
and shown, the rest are skipped.
"""

from __future__ import annotations

import json
import threading
from collections import OrderedDict
from collections.abc import Mapping, MutableMapping, Sequence
from dataclasses import replace
from typing import Any

import numpy as np
import pandas as pd
import plotly.graph_objects as go
import streamlit as st
from plotly.subplots import make_subplots

from aerostat_core import Configuration, Requirement, budget, thesis_baseline
from aerostat_core.io import inputs_from_dict, inputs_to_dict
from aerostat_core.optimize import (
    CONSTRAINT_TEXT,
    DEFAULT_BOUNDS,
    OBJECTIVES,
    PERFORMANCE_CURVES,
    SETTINGS,
    SOLVERS,
    VARIABLE_INFO,
    VARIABLES,
    OptimisationProblem,
    OptimisationResult,
    ParetoFront,
    agreement,
    baseline_vs_optimum,
    comparison_rows,
    default_limits,
    history_rows,
    pareto_front,
    performance_comparison_rows,
    performance_curves,
    solve,
    thesis_comparison_rows,
)
from aerostat_core.presets import THESIS_BLOW_BY_LIMIT
from aerostat_core.sensitivity import (
    OUTPUTS,
    SensitivityMap,
    SensitivityResult,
    one_at_a_time,
    two_variable_map,
)

from .cache import csv_bytes
from .plots import ACCENT, LIMIT_COLOUR, PALETTE
from .state import current_inputs, inputs_key, save_case
from .widgets import feedback

#: Session keys of the optimisation job and the case-save feedback.
JOB_KEY = "opt_job"
#: The last run that produced results, shown again when a newer run is cancelled before any.
PREVIOUS_JOB_KEY = "opt_previous_job"
SAVE_MSG_KEY = "opt_save_feedback"
#: Run levels shown in the UI -> engine setting.
RUN_LEVELS = {"Quick": "quick", "Normal": "normal"}
#: Sensitivity resolution: points per sweep and per map axis.
SENS_RESOLUTION = {"Quick": (7, 10), "Normal": (15, 20)}
TASK_LABELS = {**{k: v[0] for k, v in SOLVERS.items()}, "pareto": "Pareto front"}
_UNIT = {"m3": "m³", "-": "-"}
_FONT = dict(family="sans-serif", size=13)


def unit(u: str) -> str:
    """Display form of a unit string (m3 -> m³)."""
    return _UNIT.get(u, u)


#: Design variables shown in other units than the engine's: the fin position is a percentage of
#: the hull length on every page (the Design form's unit), the engine keeps the fraction.
DISPLAY: dict[str, tuple[float, str, str]] = {
    "position": (100.0, "Fin position Δl_f (root LE)", "% of hull length"),
}


def shown(name: str, value: Any) -> Any:
    """A design variable's value (scalar or array) in its display unit."""
    scale = DISPLAY.get(name, (1.0,))[0]
    if scale == 1.0:
        return value
    return np.asarray(value, float) * scale if not np.isscalar(value) else float(value) * scale


def var_label(name: str) -> str:
    """'Fineness ratio f [-]' style label of a design variable, in its display unit."""
    if name in DISPLAY:
        _, label, u = DISPLAY[name]
        return f"{label} [{u}]"
    label, u, _ = VARIABLE_INFO[name]
    return f"{label} [{unit(u)}]"


# --- inputs ------------------------------------------------------------------------------------


def variable_range_inputs(prefix: str, lower: str, upper: str) -> dict[str, tuple[float, float]]:
    """Two number inputs (lower, upper) per design variable, defaulting to ``DEFAULT_BOUNDS``.

    Widget keys are ``{prefix}_lo_{name}`` / ``{prefix}_hi_{name}`` (kept across pages);
    ``lower``/``upper`` are the words after the variable label, e.g. "from"/"to".
    Returns {variable: (lower, upper)} in the variables' units.
    """
    out = {}
    for name in VARIABLES:
        lo, hi = DEFAULT_BOUNDS[name]
        scale = DISPLAY.get(name, (1.0,))[0]
        c = st.columns(2)
        values = [
            col.number_input(
                f"{var_label(name)} – {word}",
                value=float(f"{default * scale:.12g}"),
                key=f"{prefix}_{side}_{name}",
                format="%.1f" if scale != 1.0 else "%.3f",
                persist_state="session",
            )
            for col, word, default, side in ((c[0], lower, lo, "lo"), (c[1], upper, hi, "hi"))
        ]
        out[name] = tuple(float(f"{v / scale:.12g}") for v in values)
    return out


def load_inputs() -> tuple[str, Requirement, Configuration]:
    """The current design inputs (``st.session_state["design_inputs"]``; the default inputs when
    missing or corrupt) as (canonical JSON, resolved Requirement, Configuration)."""
    req, cfg = current_inputs()
    return inputs_key(inputs_to_dict(req, cfg)), req.resolved(), cfg


def is_thesis_preset(req: Requirement, cfg: Configuration) -> bool:
    """True when the inputs are the thesis baseline (the thesis comparison then applies)."""
    return inputs_to_dict(req, cfg) == inputs_to_dict(*thesis_baseline())


def _load(inputs_json: str) -> tuple[Requirement, Configuration]:
    """(Requirement, Configuration) from canonical inputs JSON (raises ValueError)."""
    req, cfg = inputs_from_dict(json.loads(inputs_json))
    return req.resolved(), cfg  # the limits as applied (rule-set values filled in)


def bounds_key(bounds: Mapping[str, Sequence[float]]) -> str:
    """Canonical JSON of a bounds mapping (cache key)."""
    return json.dumps({k: [float(v) for v in bounds[k]] for k in bounds}, sort_keys=True)


def build_request(
    inputs_json: str,
    *,
    limit: float,
    bounds: Mapping[str, Sequence[float]],
    objective: str,
    level: str,
    seed: int,
    solvers: Sequence[str],
    pareto: bool,
    pareto_points: int,
    pareto_low: float,
    pareto_high: float,
) -> dict[str, Any]:
    """Validate the Optimise form and return the run request (plain, hashable parts).

    Raises ``ValueError`` naming the field, value and valid range (the page shows it).
    """
    req, cfg = _load(inputs_json)
    try:
        req = replace(req, blow_by_limit=float(limit))
    except ValueError as exc:
        raise ValueError(f"Blow-by limit: {exc}") from None
    problem = OptimisationProblem(req, cfg, bounds, objective)  # raises on bad bounds/objective
    if not solvers:
        raise ValueError("Solvers: choose at least one solver")
    if level not in RUN_LEVELS.values():
        raise ValueError(f"Run level {level!r}: choose quick or normal")
    for solver in solvers:  # the compute budget, before anything runs (BudgetError says why)
        budget.check_optimisation(problem, solver, SETTINGS[level][solver])
    limits: list[float] = []
    if pareto:
        if not 3 <= int(pareto_points) <= 40:
            raise ValueError(f"Pareto points = {pareto_points}: valid range [3, 40]")
        if not 0 < pareto_low < pareto_high:
            raise ValueError(
                f"Pareto range: lowest factor {pareto_low:g} must be positive and "
                f"below the highest {pareto_high:g}"
            )
        limits = default_limits(req, int(pareto_points), pareto_low, pareto_high).tolist()
    return {
        "inputs": inputs_key(inputs_to_dict(req, cfg)),
        "bounds": bounds_key(bounds),
        "objective": objective,
        "level": level,
        "seed": int(seed),
        "solvers": [s for s in SOLVERS if s in solvers],
        "limits": limits,
    }


# --- cached engine calls --------------------------------------------------------------------------


@st.cache_data(max_entries=64, show_spinner=False)
def cached_sensitivity(
    inputs_json: str, ranges_json: str, n_points: int, resize: bool
) -> SensitivityResult:
    """:func:`aerostat_core.sensitivity.one_at_a_time` of the inputs."""
    return one_at_a_time(*_load(inputs_json), json.loads(ranges_json), n_points, resize)


@st.cache_data(max_entries=64, show_spinner=False)
def cached_map(
    inputs_json: str, x_var: str, y_var: str, ranges_json: str, n: int, resize: bool
) -> SensitivityMap:
    """:func:`aerostat_core.sensitivity.two_variable_map` of the inputs."""
    return two_variable_map(*_load(inputs_json), x_var, y_var, json.loads(ranges_json), n, resize)


@st.cache_data(max_entries=128, show_spinner=False)
def cached_solve(
    inputs_json: str, bounds_json: str, objective: str, solver: str, level: str, seed: int
) -> OptimisationResult:
    """One seeded solver run (:func:`aerostat_core.optimize.solve`)."""
    p = OptimisationProblem(*_load(inputs_json), json.loads(bounds_json), objective)
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
) -> OptimisationResult:
    """:func:`cached_solve` that reports ``progress(fraction, text)`` after every batch (the
    solver's own callback, which names the solver) when it has to compute; a request any
    session has run before returns at once."""
    key = (inputs_json, bounds_json, objective, solver, level, int(seed))
    cache = _shared_results()
    with _shared_lock:
        if key in cache:
            cache.move_to_end(key)
            return cache[key]
    p = OptimisationProblem(*_load(inputs_json), json.loads(bounds_json), objective)
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
    req, cfg = _load(inputs_json)
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
    req, _ = _load(inputs_json)
    _, cfg_base = _load(baseline_json)
    x = json.loads(x_json)
    rows = baseline_vs_optimum(req, cfg_base, x)
    base = performance_curves(req, cfg_base)
    opt = performance_curves(req, cfg_base.with_design_variables(volume=None, **x))
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


def solver_results(job: Mapping[str, Any]) -> list[OptimisationResult]:
    """Finished solver results of a job, in solver order."""
    return [job["done"][s] for s in job["request"]["solvers"] if s in job["done"]]


def best_result(results: Sequence[OptimisationResult]) -> OptimisationResult | None:
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


# --- tables ----------------------------------------------------------------------------------------


def comparison_frame(results: Sequence[OptimisationResult]) -> pd.DataFrame:
    """Table 4.12-like comparison: variables, mass, volume, blow-by, evaluations, time."""
    rows = comparison_rows(results)
    return pd.DataFrame(
        [
            {
                "Solver": r["solver"],
                "f [-]": r["fineness_ratio"],
                "ΔS_f [%]": r["area_change_pct"],
                "Δl_f [% of l]": shown("position", r["position"]),
                "Total mass [kg]": r["total_mass_kg"],
                "Volume [m³]": r["volume_m3"],
                "Blow-by [m]": r["blow_by_m"],
                "α_eq [deg]": r["alpha_eq_deg"],
                "Gas cost [USD]": r["gas_cost_USD"],
                "Evaluations": r["evaluations"],
                "Batches": r["batches"],
                "Time [s]": r["time_s"],
                "Status": r["status"],
                "Active constraints / bounds": r["active"],
            }
            for r in rows
        ]
    )


COMPARISON_FORMAT = {
    "f [-]": st.column_config.NumberColumn(format="%.3f"),
    "ΔS_f [%]": st.column_config.NumberColumn(format="%.2f"),
    "Δl_f [% of l]": st.column_config.NumberColumn(format="%.1f"),
    "Total mass [kg]": st.column_config.NumberColumn(format="%.2f"),
    "Volume [m³]": st.column_config.NumberColumn(format="%.1f"),
    "Blow-by [m]": st.column_config.NumberColumn(format="%.2f"),
    "α_eq [deg]": st.column_config.NumberColumn(format="%.2f"),
    "Gas cost [USD]": st.column_config.NumberColumn(format="%.0f"),
    "Time [s]": st.column_config.NumberColumn(format="%.2f"),
}


#: Pareto table: each quantity at the precision it has in the solver comparison.
PARETO_FORMAT = {
    "Blow-by limit [m]": st.column_config.NumberColumn(format="%.1f"),
    "Gas cost [USD]": st.column_config.NumberColumn(format="%.0f"),
    **{k: v for k, v in COMPARISON_FORMAT.items() if k not in ("Time [s]", "Gas cost [USD]")},
}


def changes_frame(rows: Sequence[Mapping[str, Any]]) -> pd.DataFrame:
    """Baseline-to-optimum changes (quantity, baseline, optimum, change) with units."""
    return pd.DataFrame(
        [
            {
                "Quantity": f"{r['quantity']} [{unit(r['unit'])}]",
                "Baseline": r["baseline"],
                "Optimum": r["optimum"],
                "Change": r["change"],
            }
            for r in rows
        ]
    )


def thesis_frame(rows: Sequence[Mapping[str, Any]]) -> pd.DataFrame:
    """Our baseline-to-optimum changes next to the thesis'."""
    return pd.DataFrame(
        [
            {
                "Quantity": f"{r['quantity']} [{unit(r['unit'])}]",
                "Thesis baseline": r["thesis_baseline"],
                "Thesis optimum": r["thesis_optimum"],
                "Thesis change": r["thesis_change"],
                "Our baseline": r["our_baseline"],
                "Our optimum": r["our_optimum"],
                "Our change": r["our_change"],
            }
            for r in rows
        ]
    )


def pareto_frame(front: ParetoFront) -> pd.DataFrame:
    """Pareto points with units."""
    return pd.DataFrame(
        [
            {
                "Blow-by limit [m]": r["blow_by_limit_m"],
                "Blow-by [m]": r["blow_by_m"],
                "Total mass [kg]": r["total_mass_kg"],
                "Volume [m³]": r["volume_m3"],
                "Gas cost [USD]": r["gas_cost_USD"],
                "f [-]": r["fineness_ratio"],
                "ΔS_f [%]": r["area_change_pct"],
                "Δl_f [% of l]": shown("position", r["position"]),
                "On front": r["on_front"],
                "Why infeasible": r["reason"],
            }
            for r in front.rows()
        ]
    )


def sweep_frame(res: SensitivityResult) -> pd.DataFrame:
    """All sweep points with units."""
    return pd.DataFrame(
        [
            {
                "Variable": r["variable"],
                "Value": shown(r["variable"], r["value"])
                if r["variable"] in DISPLAY
                else r["value"],
                "Volume [m³]": r["volume_m3"],
                "Total mass [kg]": r["total_mass_kg"],
                "Blow-by [m]": r["blow_by_m"],
                "α_eq [deg]": r["alpha_eq_deg"],
                "Dynamic lift [N]": r["dynamic_lift_N"],
                "Feasible": r["feasible"],
                "Violations": r["violations"],
            }
            for r in res.rows()
        ]
    )


def summary_frame(res: SensitivityResult) -> pd.DataFrame:
    """Mass and volume change over each sweep range, relative to the baseline [%]."""
    return pd.DataFrame(
        [
            {
                "Variable": var_label(r["variable"]),
                "Baseline": shown(r["variable"], r["baseline"]),
                "Low": shown(r["variable"], r["low"]),
                "High": shown(r["variable"], r["high"]),
                "Mass change at low [%]": r["mass_change_low_pct"],
                "Mass change at high [%]": r["mass_change_high_pct"],
                "Volume change at low [%]": r["volume_change_low_pct"],
                "Volume change at high [%]": r["volume_change_high_pct"],
                "Feasible from": shown(r["variable"], r["feasible_from"]),
                "Feasible to": shown(r["variable"], r["feasible_to"]),
            }
            for r in res.summary_rows()
        ]
    )


def csv_of(rows: list[dict]) -> bytes:
    """CSV bytes of flat rows (pure: :func:`aerostat_core.io.rows_to_csv`)."""
    return csv_bytes(rows)


# --- figures ----------------------------------------------------------------------------------------


def _layout(fig: go.Figure, title: str, **kw: Any) -> go.Figure:
    """Common layout (title, font, margins, legend below) of the page's figures."""
    fig.update_layout(
        title=dict(text=title, font=dict(size=15)),
        font=_FONT,
        margin=dict(l=60, r=20, t=60, b=50),
        # Legend right of the plot: below it, it sat on the x-axis title.
        legend=dict(orientation="v", x=1.02, xanchor="left", y=1.0, yanchor="top"),
        **kw,
    )
    return fig


def sensitivity_figure(res: SensitivityResult) -> go.Figure:
    """One-factor-at-a-time sweeps: outputs (rows) versus each variable (columns); points that
    break a constraint are red crosses; the dotted line marks the baseline."""
    outs = list(OUTPUTS)
    fig = make_subplots(
        rows=len(outs),
        cols=len(VARIABLES),
        shared_xaxes="columns",
        vertical_spacing=0.035,
        horizontal_spacing=0.07,
        column_titles=[var_label(n) for n in VARIABLES],
    )
    for c, name in enumerate(VARIABLES, start=1):
        sw = res.sweeps[name]
        feas = sw.designs.feasible
        for r, key in enumerate(outs, start=1):
            y = sw.output(key)
            fig.add_trace(
                go.Scatter(
                    x=shown(name, sw.values).tolist(),
                    y=y.tolist(),
                    mode="lines+markers",
                    name=f"{key} vs {name}",
                    line=dict(color=ACCENT),
                    marker=dict(size=5),
                    showlegend=False,
                    hovertemplate=f"{var_label(name)} %{{x:.3g}}<br>{OUTPUTS[key][0]} "
                    f"%{{y:.4g}} {unit(OUTPUTS[key][1])}<extra></extra>",
                ),
                row=r,
                col=c,
            )
            if (~feas).any():
                fig.add_trace(
                    go.Scatter(
                        x=shown(name, sw.values[~feas]).tolist(),
                        y=y[~feas].tolist(),
                        mode="markers",
                        name="constraint violated",
                        legendgroup="viol",
                        showlegend=(r == c == 1),
                        marker=dict(symbol="x", size=9, color=LIMIT_COLOUR),
                        text=[
                            sw.designs.violations(i)[0] if sw.designs.violations(i) else ""
                            for i in np.nonzero(~feas)[0]
                        ],
                        hovertemplate="%{x:.3g}: %{text}<extra></extra>",
                    ),
                    row=r,
                    col=c,
                )
            fig.add_vline(
                x=shown(name, res.baseline[name]),
                line=dict(color="#7f7f7f", dash="dot", width=1),
                row=r,
                col=c,
            )
            if c == 1:
                fig.update_yaxes(
                    title_text=f"{OUTPUTS[key][0].split(' at ')[0]} [{unit(OUTPUTS[key][1])}]",
                    row=r,
                    col=c,
                )
            if r == len(outs):
                fig.update_xaxes(title_text=var_label(name), row=r, col=c)
    mode = (
        "hull re-sized at every point" if res.resize else f"hull held at {res.volume_held:.1f} m³"
    )
    fig = _layout(
        fig,
        f"One factor at a time around the baseline ({mode}; outputs at {res.design_wind:g} m/s)",
        height=1000,
    )
    fig.update_layout(
        legend=dict(orientation="h", y=1.06, x=1.0, xanchor="right"), margin=dict(t=110)
    )
    return fig


def map_figure(m: SensitivityMap) -> go.Figure:
    """Total mass over two variables, with the blow-by-limit contour (held volume) or the
    infeasible points (re-sized), and the baseline."""
    fig = go.Figure()
    fig.add_trace(
        go.Contour(
            x=shown(m.x_variable, m.x).tolist(),
            y=shown(m.y_variable, m.y).tolist(),
            z=m.total_mass.tolist(),
            name="total mass",
            colorscale="Blues",
            contours=dict(showlabels=True, labelfont=dict(size=10)),
            colorbar=dict(title=dict(text="Total mass [kg]")),
            hovertemplate="%{x:.3g}, %{y:.3g}: %{z:.2f} kg<extra></extra>",
        )
    )
    if not m.resize:
        fig.add_trace(
            go.Contour(
                x=shown(m.x_variable, m.x).tolist(),
                y=shown(m.y_variable, m.y).tolist(),
                z=m.blow_by.tolist(),
                name=f"blow-by = limit {m.blow_by_limit:g} m",
                showscale=False,
                contours=dict(
                    type="constraint", operation="=", value=m.blow_by_limit, showlabels=False
                ),
                line=dict(color=LIMIT_COLOUR, width=3),
                showlegend=True,
                hovertemplate="blow-by %{z:.1f} m<extra></extra>",
            )
        )
    bad = ~m.feasible
    if bad.any():
        X, Y = np.meshgrid(shown(m.x_variable, m.x), shown(m.y_variable, m.y))
        fig.add_trace(
            go.Scatter(
                x=X[bad].tolist(),
                y=Y[bad].tolist(),
                mode="markers",
                name="constraint violated",
                marker=dict(symbol="x", size=5, color=LIMIT_COLOUR, opacity=0.45),
            )
        )
    fig.add_trace(
        go.Scatter(
            x=[shown(m.x_variable, m.baseline[m.x_variable])],
            y=[shown(m.y_variable, m.baseline[m.y_variable])],
            mode="markers",
            name="baseline",
            marker=dict(symbol="diamond", size=12, color="#000000"),
        )
    )
    fig.update_xaxes(title_text=var_label(m.x_variable))
    fig.update_yaxes(title_text=var_label(m.y_variable))
    mode = "hull re-sized at every point" if m.resize else f"hull held at {m.volume_held:.1f} m³"
    return _layout(
        fig,
        f"Total mass over {VARIABLE_INFO[m.x_variable][0]} × "
        f"{VARIABLE_INFO[m.y_variable][0]} ({mode})",
        height=560,
    )


def convergence_figure(results: Sequence[OptimisationResult]) -> go.Figure:
    """Best feasible objective versus evaluations, one line per solver."""
    fig = go.Figure()
    name = label = None
    for i, r in enumerate(results):
        h = r.history
        name = r.objective_name
        fig.add_trace(
            go.Scatter(
                x=h.evaluations.tolist(),
                y=h.best.tolist(),
                mode="lines",
                line=dict(shape="hv", color=PALETTE[i % len(PALETTE)], width=2),
                name=r.label,
            )
        )
    if name is not None:
        lab, u = OBJECTIVES[name]
        label = f"Best feasible {lab.lower()} [{unit(u)}]"
    fig.update_xaxes(title_text="Designs evaluated (each with its nested sizing)", type="log")
    fig.update_yaxes(title_text=label or "Best objective")
    return _layout(fig, "Convergence", height=420)


def pareto_figure(
    front: ParetoFront,
    results: Sequence[OptimisationResult],
    limit: float,
    baseline: Mapping[str, float] | None = None,
) -> go.Figure:
    """Objective versus blow-by: the front, infeasible limits, each solver's optimum, baseline;
    gas cost on the right axis."""
    lab, u = OBJECTIVES[front.objective_name]
    fig = make_subplots(specs=[[{"secondary_y": True}]])
    on = front.nondominated
    order = np.argsort(front.blow_by[on])
    fig.add_trace(
        go.Scatter(
            x=front.blow_by[on][order].tolist(),
            y=front.objective[on][order].tolist(),
            mode="lines+markers",
            name=f"Pareto front ({lab.lower()})",
            line=dict(color=ACCENT, width=2),
            marker=dict(size=7),
            customdata=np.column_stack(
                [
                    front.volume[on][order],
                    front.fineness_ratio[on][order],
                    front.area_change[on][order],
                    shown("position", front.position[on][order]),
                ]
            ).tolist(),
            hovertemplate="blow-by %{x:.1f} m: %{y:.2f} " + unit(u) + "<br>V %{customdata[0]:.1f} "
            "m³, f %{customdata[1]:.2f}, ΔS_f %{customdata[2]:.1f} %, Δl_f "
            "%{customdata[3]:.1f} % of l<extra></extra>",
        ),
        secondary_y=False,
    )
    fig.add_trace(
        go.Scatter(
            x=front.blow_by[on][order].tolist(),
            y=front.gas_cost[on][order].tolist(),
            mode="lines",
            name="gas fill cost (right axis)",
            line=dict(color=PALETTE[1], dash="dash"),
            hovertemplate="blow-by %{x:.1f} m: USD %{y:,.0f}<extra></extra>",
        ),
        secondary_y=True,
    )
    bad = ~front.feasible
    if bad.any():
        fig.add_trace(
            go.Scatter(
                x=front.limits[bad].tolist(),
                y=front.objective[bad].tolist(),
                mode="markers",
                name="limit not achievable",
                marker=dict(symbol="x", size=10, color=LIMIT_COLOUR),
                text=[front.reason[i] for i in np.nonzero(bad)[0]],
                hovertemplate="limit %{x:.1f} m: %{text}<extra></extra>",
            ),
            secondary_y=False,
        )
    for i, r in enumerate(results):
        if r.feasible:
            fig.add_trace(
                go.Scatter(
                    x=[r.design["blow_by_m"]],
                    y=[r.objective],
                    mode="markers",
                    name=f"{r.label} optimum",
                    marker=dict(
                        symbol="star",
                        size=14,
                        color=PALETTE[(i + 2) % len(PALETTE)],
                        line=dict(width=1, color="#000000"),
                    ),
                ),
                secondary_y=False,
            )
    if baseline is not None:
        fig.add_trace(
            go.Scatter(
                x=[baseline["blow_by"]],
                y=[baseline["objective"]],
                mode="markers",
                name="baseline (as given)",
                marker=dict(symbol="diamond", size=12, color="#000000"),
            ),
            secondary_y=False,
        )
    fig.add_vline(
        x=limit,
        line=dict(color=LIMIT_COLOUR, dash="dash", width=1.5),
        annotation_text=f"limit {limit:g} m",
        annotation_position="top",
    )
    fig.update_xaxes(title_text="Blow-by at the design wind [m]")
    fig.update_yaxes(title_text=f"{lab} [{unit(u)}]", secondary_y=False)
    # tickmode "auto": plotly.js syncs an overlaying axis to the primary grid by default, which
    # gave ticks such as 5.12 / 10.23 / 15.35.
    fig.update_yaxes(
        title_text="Gas fill cost [USD]", secondary_y=True, showgrid=False, tickmode="auto"
    )
    return _layout(fig, f"Trade-off: least {lab.lower()} for each blow-by limit", height=500)


def performance_figure(base: Mapping[str, Any], opt: Mapping[str, Any]) -> go.Figure:
    """Baseline versus optimum: blow-by, angle, dynamic lift and tension versus wind (2 x 2)."""
    keys = list(PERFORMANCE_CURVES)
    fig = make_subplots(
        rows=2,
        cols=2,
        subplot_titles=[PERFORMANCE_CURVES[k][0] for k in keys],
        horizontal_spacing=0.1,
        vertical_spacing=0.16,
    )
    for j, k in enumerate(keys):
        r, c = j // 2 + 1, j % 2 + 1
        for name, d, colour, dash in (
            ("baseline", base, "#7f7f7f", "dash"),
            ("optimum", opt, ACCENT, "solid"),
        ):
            fig.add_trace(
                go.Scatter(
                    x=np.asarray(d["wind_speed"]).tolist(),
                    y=np.asarray(d[k]).tolist(),
                    mode="lines+markers",
                    name=name,
                    legendgroup=name,
                    showlegend=(j == 0),
                    line=dict(color=colour, dash=dash),
                    marker=dict(size=4),
                ),
                row=r,
                col=c,
            )
        fig.update_yaxes(title_text=f"[{unit(PERFORMANCE_CURVES[k][1])}]", row=r, col=c)
        fig.update_xaxes(title_text="Wind speed [m/s]", row=r, col=c)
    return _layout(fig, "Baseline versus optimum performance (thesis Figs 4.17-4.22)", height=640)


# --- results panel ------------------------------------------------------------------------------


def _save_case_cb(inputs_json: str, x: dict) -> None:
    """Save-button callback: the optimum's inputs (volume left to the sizing) as a case."""
    name = st.session_state.get("opt_case_name", "")
    try:
        req, cfg = _load(inputs_json)
        used = save_case(name, req, cfg.with_design_variables(volume=None, **x))
    except ValueError as exc:
        st.session_state[SAVE_MSG_KEY] = ("error", str(exc))
    else:
        st.session_state[SAVE_MSG_KEY] = (
            "success",
            f"Saved case “{used}” (volume sized to the "
            "requirement). Compare it on the Compare page.",
        )


def render_results(job: Mapping[str, Any], baseline_inputs_json: str) -> None:
    """Everything a finished (or cancelled) run shows: comparison, convergence, baseline vs
    optimum, performance curves, Pareto front, save as case, CSV downloads."""
    req_d = job["request"]
    req, cfg = _load(req_d["inputs"])
    results = solver_results(job)
    n_done, n_all = len(job["done"]), len(job["tasks"])
    previous = st.session_state.get(PREVIOUS_JOB_KEY)
    if job["cancelled"] and not results and previous and previous is not job:
        st.warning(
            "Run cancelled before any solver finished; the previous run's results are shown.",
            icon=":material/cancel:",
        )
        render_results(previous, baseline_inputs_json)
        return
    if job["cancelled"]:
        st.warning(
            f"Run cancelled: {n_done} of {n_all} tasks finished; their results are shown.",
            icon=":material/cancel:",
        )
    lab, u = OBJECTIVES[req_d["objective"]]
    st.caption(
        f"Run: minimise {lab.lower()}, blow-by limit {req.blow_by_limit:g} m at "
        f"{req.design_wind:g} m/s, {req_d['level']} setting, seed {req_d['seed']}; "
        "volume = smallest hull meeting the constraints for each design (nested V*(x))."
    )
    if not results:
        st.info("No solver finished.")
        return
    st.subheader("Solver comparison (thesis Table 4.12)", anchor=False)
    st.dataframe(
        comparison_frame(results), hide_index=True, column_config=COMPARISON_FORMAT, key="opt_table"
    )
    st.download_button(
        "Comparison (CSV)",
        csv_of(comparison_rows(results)),
        file_name="optimisation-comparison.csv",
        mime="text/csv",
        on_click="ignore",
        icon=":material/download:",
        key="dl_opt_cmp",
    )
    best = best_result(results)
    for r in results:
        if not r.feasible:
            st.error(f"**{r.label}:** {r.message}", icon=":material/error:")
    spread = agreement(results)
    if best is not None and np.isfinite(spread):
        text = (
            f"Spread of the optimum {lab.lower()} between solvers: {100 * spread:.2f} % "
            f"(best {best.objective:.2f} {unit(u)} by {best.label})."
        )
        (st.success if spread < 0.01 else st.warning)(text)
    st.plotly_chart(convergence_figure(results), key="opt_convergence")
    st.download_button(
        "Convergence histories (CSV)",
        csv_of(history_rows(results)),
        file_name="optimisation-history.csv",
        mime="text/csv",
        on_click="ignore",
        icon=":material/download:",
        key="dl_opt_hist",
    )
    if best is None:
        return

    st.subheader("Baseline versus optimum", anchor=False)
    cmp = cached_comparison(
        req_d["inputs"], baseline_inputs_json, json.dumps(best.x, sort_keys=True)
    )
    st.dataframe(
        changes_frame(cmp["changes"]),
        hide_index=True,
        key="opt_changes",
        column_config={
            c: st.column_config.NumberColumn(format="%.2f")
            for c in ("Baseline", "Optimum", "Change")
        },
    )
    st.caption(
        "Baseline: the design inputs as given (their volume if set, else sized). "
        "Optimum: the best solver's variables with the hull sized to the requirement."
    )
    if is_thesis_preset(*_load(baseline_inputs_json)):
        st.markdown(
            "**Against the thesis** (abstract and Appendix H: 170 → 120 m³, "
            "90.65 → 71.6 kg, USD 1925 of helium saved)"
        )
        st.dataframe(
            thesis_frame(cmp["thesis"]),
            hide_index=True,
            key="opt_thesis",
            column_config={
                c: st.column_config.NumberColumn(format="%.1f")
                for c in thesis_frame(cmp["thesis"]).columns[1:]
            },
        )
        st.caption(
            f"Calibrated: the blow-by limit ({THESIS_BLOW_BY_LIMIT:g} m at 15 m/s, not given "
            "in the thesis) so that the optimum is ~120 m³. Predicted: the optimum's mass and "
            "variables. Our optimum is lighter than the thesis' because it shrinks the fins "
            "(ΔS_f ≈ −31 %, as far as weathervane stability allows) and takes the shortest "
            "hull allowed (f = 2.5); the thesis' 'fin area increase' variable probably did "
            "not let the fins shrink."
        )
    st.plotly_chart(performance_figure(cmp["baseline"], cmp["optimum"]), key="opt_performance")
    st.download_button(
        "Performance, baseline and optimum (CSV)",
        csv_of(cmp["performance_rows"]),
        file_name="baseline-vs-optimum.csv",
        mime="text/csv",
        on_click="ignore",
        icon=":material/download:",
        key="dl_opt_perf",
    )

    front = job["done"].get("pareto")
    if isinstance(front, ParetoFront):
        st.subheader("Trade-off: mass versus blow-by limit", anchor=False)
        b = cmp["baseline"]
        base_pt = None
        if req_d["objective"] == "total_mass":
            i = int(np.argmin(np.abs(np.asarray(b["wind_speed"]) - req.design_wind)))
            if abs(b["wind_speed"][i] - req.design_wind) < 1e-9:
                base_pt = {"blow_by": float(b["blow_by"][i]), "objective": b["total_mass"]}
        st.plotly_chart(pareto_figure(front, results, req.blow_by_limit, base_pt), key="opt_pareto")
        st.caption(
            "Each point is the least-mass design whose blow-by at the design wind stays "
            "within that limit (epsilon-constraint method, volume free, every constraint "
            "met); red crosses: limits no design within the bounds can meet."
        )
        st.dataframe(
            pareto_frame(front),
            hide_index=True,
            column_config=PARETO_FORMAT,
            key="opt_pareto_table",
        )
        st.download_button(
            "Pareto front (CSV)",
            csv_of(front.rows()),
            file_name="pareto-front.csv",
            mime="text/csv",
            on_click="ignore",
            icon=":material/download:",
            key="dl_opt_pareto",
        )
    elif isinstance(front, Exception):
        st.error(f"Pareto front: {front}")

    st.subheader("Save the optimum as a case", anchor=False)
    c1, c2 = st.columns([2, 1], vertical_alignment="bottom")
    c1.text_input("Case name", value=f"Optimum ({best.label})", key="opt_case_name", max_chars=100)
    c2.button(
        "Save optimum as case",
        key="opt_save",
        icon=":material/bookmark_add:",
        on_click=_save_case_cb,
        args=(req_d["inputs"], dict(best.x)),
    )
    fb = st.session_state.pop(SAVE_MSG_KEY, None)
    if fb:
        feedback(fb[0], fb[1])


def problem_rows(req: Requirement, cfg: Configuration) -> list[dict[str, str]]:
    """The problem definition with default bounds (for the page's explanation)."""
    return OptimisationProblem(req, cfg).describe()


__all__ = [
    "CONSTRAINT_TEXT",
    "DEFAULT_BOUNDS",
    "RUN_LEVELS",
    "SENS_RESOLUTION",
    "build_request",
    "cached_map",
    "cached_sensitivity",
    "load_inputs",
    "render_results",
    "run_job",
    "start_job",
]
