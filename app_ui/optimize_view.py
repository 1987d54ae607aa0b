"""UI layer of the Sensitivity and Optimise pages: the results panel of a run, and one import
for the pages.

The rooms: :mod:`app_ui.optimize_form` (bound boxes, request), :mod:`app_ui.optimize_jobs`
(cached engine calls, the chunked and cancellable run), :mod:`app_ui.optimize_tables` and
:mod:`app_ui.plots_optimize` (what is shown). Everything physical comes from
:mod:`aerostat_core.optimize` and :mod:`aerostat_core.studies.sensitivity`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import streamlit as st

from aerostat_core import Configuration, Requirement
from aerostat_core.model.presets import THESIS_BLOW_BY_LIMIT
from aerostat_core.optimize import (
    CONSTRAINT_TEXT,
    DEFAULT_BOUNDS,
    OBJECTIVES,
    OptimizationProblem,
    ParetoFront,
    agreement,
    comparison_rows,
    history_rows,
)

from . import formats
from .optimize_form import (
    DISPLAY,
    RUN_LEVELS,
    SENS_RESOLUTION,
    bounds_items,
    build_request,
    inputs_from_json,
    is_thesis_preset,
    load_inputs,
    parse_ranges,
    shown,
    unit,
    var_label,
    variable_range_inputs,
)
from .optimize_jobs import (
    JOB_KEY,
    PREVIOUS_JOB_KEY,
    SHARED_RESULTS,
    TASK_LABELS,
    best_result,
    cached_comparison,
    cached_map,
    cached_pareto,
    cached_sensitivity,
    cached_solve,
    cancel_job,
    current_job,
    run_job,
    solve_shared,
    solver_results,
    start_job,
)
from .optimize_tables import (
    COMPARISON_FORMAT,
    COMPARISON_TABLES,
    PARETO_FORMAT,
    PARETO_TABLES,
    SUMMARY_FORMAT,
    SWEEP_FORMAT,
    changes_frame,
    changes_styler,
    comparison_frame,
    csv_of,
    pareto_frame,
    styled,
    summary_frame,
    summary_table,
    sweep_frame,
    sweep_styler,
    sweep_tables,
    thesis_frame,
)
from .plots_optimize import (
    convergence_figure,
    map_figure,
    pareto_figure,
    performance_figure,
    sensitivity_figure,
)
from .state import save_case
from .widgets import feedback

SAVE_MSG_KEY = "opt_save_feedback"

# --- results panel ------------------------------------------------------------------------------


def _save_case_cb(inputs_json: str, x: dict) -> None:
    """Save-button callback: the optimum's inputs (volume left to the sizing) as a case."""
    name = st.session_state.get("opt_case_name", "")
    try:
        req, cfg = inputs_from_json(inputs_json)
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
    req, cfg = inputs_from_json(req_d["inputs"])
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
    st.caption(formats.text_in_system(  # the numbers in the chosen unit system
        f"Run: minimise {lab.lower()}, blow-by limit {req.blow_by_limit:g} m at "
        f"{req.design_wind:g} m/s, {req_d['level']} setting, seed {req_d['seed']}; "
        "volume = smallest hull meeting the constraints for each design (nested V*(x))."
    ))
    if not results:
        st.info("No solver finished.")
        return
    st.subheader("Solver comparison (thesis Table 4.12)", anchor=False)
    cmp_df = comparison_frame(results)
    for title, columns in COMPARISON_TABLES.items():  # static tables: 14 columns did not fit
        st.markdown(f"**{title}**")
        st.table(styled(cmp_df, columns))
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
            f"(best {formats.text(best.objective, req_d['objective'])} {unit(u)} by {best.label})."
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
    cmp = cached_comparison(req, inputs_from_json(baseline_inputs_json)[1], best.x)
    st.table(changes_styler(changes_frame(cmp["changes"])))
    st.caption(
        "Baseline: the design inputs as given (their volume if set, else sized). "
        "Optimum: the best solver's variables with the hull sized to the requirement."
    )
    if is_thesis_preset(*inputs_from_json(baseline_inputs_json)):
        st.markdown(
            "**Against the thesis** (abstract and Appendix H: 170 → 120 m³, "
            "90.65 → 71.6 kg, USD 1925 of helium saved)"
        )
        tf = thesis_frame(cmp["thesis"])
        st.table(changes_styler(tf, list(tf.columns[1:])))
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
        p_df = pareto_frame(front)
        for title, columns in PARETO_TABLES.items():
            st.markdown(f"**{title}**")
            st.table(styled(p_df, columns))
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
    """The problem definition with default bounds (for the page's explanation); the design
    variables in their display units (the fin position in % of the hull length)."""
    rows = OptimizationProblem(req, cfg).describe()
    for r in rows:
        name = r["item"].removeprefix("variable ")
        if name in DEFAULT_BOUNDS and r["item"] != name:
            lo, hi = (shown(name, v) for v in DEFAULT_BOUNDS[name])
            r["definition"] = f"{var_label(name)}: [{lo:g}, {hi:g}]"
    return rows


__all__ = [
    "COMPARISON_FORMAT",
    "CONSTRAINT_TEXT",
    "DEFAULT_BOUNDS",
    "DISPLAY",
    "JOB_KEY",
    "PARETO_FORMAT",
    "PREVIOUS_JOB_KEY",
    "RUN_LEVELS",
    "SAVE_MSG_KEY",
    "SENS_RESOLUTION",
    "SHARED_RESULTS",
    "SUMMARY_FORMAT",
    "SWEEP_FORMAT",
    "changes_styler",
    "TASK_LABELS",
    "best_result",
    "bounds_items",
    "build_request",
    "cached_comparison",
    "cached_map",
    "cached_pareto",
    "cached_sensitivity",
    "cached_solve",
    "cancel_job",
    "changes_frame",
    "comparison_frame",
    "convergence_figure",
    "csv_of",
    "current_job",
    "is_thesis_preset",
    "load_inputs",
    "map_figure",
    "pareto_figure",
    "pareto_frame",
    "parse_ranges",
    "performance_figure",
    "problem_rows",
    "render_results",
    "run_job",
    "sensitivity_figure",
    "shown",
    "solve_shared",
    "solver_results",
    "start_job",
    "summary_frame",
    "summary_table",
    "sweep_styler",
    "sweep_tables",
    "sweep_frame",
    "thesis_frame",
    "unit",
    "var_label",
    "variable_range_inputs",
]


def resize_caption(res) -> str:
    """The caption of the re-sized sweeps, from the sweeps themselves: whether the blow-by
    reaches its limit (the limit sets the volume) at every, some or none of the feasible points.
    A fixed "the blow-by equals the limit" was wrong where another requirement sizes the hull
    (about 128 m against a 150 m limit on the practice default)."""
    lim = float(res.blow_by_limit)
    ok = [r for r in res.rows() if r["feasible"]]
    at = [abs(float(r["blow_by_m"]) - lim) <= 0.01 * lim for r in ok]
    tail = " Red crosses break another constraint (hover for which)."
    du = formats.display("distance")  # the chosen unit system's (m or ft)
    lim_t = f"{du.show(lim):g} {du.unit}"
    if not ok:
        return f"No sweep point meets every requirement (blow-by limit {lim_t}).{tail}"
    lo = du.show(min(float(r["blow_by_m"]) for r in ok))
    hi = du.show(max(float(r["blow_by_m"]) for r in ok))
    if all(at):
        return (
            f"The blow-by equals the limit, {lim_t}, at every feasible point: the limit is what "
            f"sets the volume.{tail}"
        )
    if not any(at):
        return (
            f"The blow-by stays below the limit {lim_t} at every feasible point ({lo:.0f}-"
            f"{hi:.0f} {du.unit}): another requirement sets the volume, not the blow-by limit.{tail}"
        )
    return (
        f"The blow-by reaches the limit {lim_t} at {sum(at)} of {len(ok)} feasible points (there "
        f"the limit sets the volume); elsewhere another requirement sizes the hull and the "
        f"blow-by is lower (down to {lo:.0f} {du.unit}).{tail}"
    )
