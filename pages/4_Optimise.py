"""Optimise page: minimise total mass (or volume) over f, ΔS_f, Δl_f with the hull sized to the
requirement; three solvers compared, convergence, baseline vs optimum, Pareto front, save."""

from __future__ import annotations

import pandas as pd
import streamlit as st

from aerostat_core import Requirement
from aerostat_core.base.validation import short
from aerostat_core.optimize import OBJECTIVES, SOLVERS
from app_ui import entry, formats, widgets
from app_ui import optimize_view as view
from app_ui.shell import run_inside_the_app

run_inside_the_app()  # a page reached by its own address still runs inside app.py
st.title("Optimise")
st.caption(
    "Minimise the total mass over the three design variables of the thesis: fineness ratio f, "
    "fin-area change ΔS_f and fin position Δl_f. The hull volume is not a variable: for each "
    "design it is the smallest hull that meets every constraint of the rule set's table "
    "(nested sizing V*(x)). Three solvers must agree."
)

inputs_json, req, cfg = view.load_inputs()
st.caption(formats.text_in_system(  # the numbers in the chosen unit system
    f"Requirement from the Design page: {req.payload_mass:g} kg at {req.altitude:g} m, rule set "
    f"**{req.rules}** (same limits and the same sized design as the Design page)."
))

with st.expander("Problem definition", icon=":material/functions:"):
    st.dataframe(pd.DataFrame(view.problem_rows(req, cfg)), hide_index=True, key="opt_problem")
    st.caption(
        "Every constraint is g(x) ≤ 0 on the sized design at the design wind. Default "
        "bounds: docs/methods.md G6, with the fin area also allowed to shrink to −50 % (the "
        "statistical fin size is a starting point, not a floor)."
    )

# The limit box follows the design inputs unless the user edits it here.
if st.session_state.get("_opt_limit_src") != req.blow_by_limit:
    st.session_state.pop("opt_limit", None)  # refilled from the design (entry.spec_box)
    st.session_state["_opt_limit_src"] = req.blow_by_limit

# Every number is a text box read like the Design form's ("12,5" is 12.5, never 125).
with st.form("opt_form"):
    c = st.columns(4)
    objective = c[0].radio(
        "Objective",
        list(OBJECTIVES),
        key="opt_objective",
        format_func=lambda k: formats.text_in_system(f"{OBJECTIVES[k][0]} [{view.unit(OBJECTIVES[k][1])}]"),
        persist_state="session",
    )
    level = c[1].radio(
        "Run setting",
        list(view.RUN_LEVELS),
        index=1,
        key="opt_level",
        horizontal=True,
        persist_state="session",
        help="Quick: fewer starts, evaluations and generations (seconds). "
        "Normal: the settings of the comparison table.",
    )
    seed_text = entry.number_box(
        "Random seed [-]",
        key="opt_seed",
        value=0,
        integer=True,
        container=c[2],
        help="Seeds the starts, the surrogate sample and the swarm: the "
        "same seed gives the same result.",
    )
    # the registry's box in the chosen unit system (ft in US customary)
    limit_text = entry.spec_box(c[3], Requirement, "blow_by_limit", req.blow_by_limit, "opt_limit")
    solvers = st.multiselect(
        "Solvers",
        list(SOLVERS),
        default=list(SOLVERS),
        key="opt_solvers",
        format_func=lambda k: SOLVERS[k][0],
        persist_state="session",
    )
    st.markdown("**Bounds of the design variables**")
    bound_texts = view.variable_range_inputs("opt", "lower", "upper")
    st.markdown("**Trade-off curve**")
    p = st.columns(4)
    pareto = p[0].checkbox(
        "Compute the Pareto front", value=True, key="opt_pareto_on", persist_state="session"
    )
    n_text = entry.number_box(
        "Points [-]", key="opt_pareto_n", value=11, integer=True, container=p[1]
    )
    low_text = entry.number_box(
        "Lowest limit [× limit]", key="opt_pareto_low", value=0.6, container=p[2]
    )
    high_text = entry.number_box(
        "Highest limit [× limit]", key="opt_pareto_high", value=2.0, container=p[3]
    )
    submitted = st.form_submit_button(
        "Run optimisation", type="primary", key="opt_run", icon=":material/play_arrow:"
    )

if submitted:
    try:
        request = view.build_request(
            inputs_json,
            limit=entry.spec_read(limit_text, Requirement, "blow_by_limit", "opt_limit"),
            bounds=view.parse_ranges(bound_texts, "lower", "upper"),
            objective=objective,
            level=view.RUN_LEVELS[level],
            seed=entry.read(seed_text, "Random seed [-]", integer=True, lo=0, hi=999_999_999),
            solvers=solvers,
            pareto=pareto,
            pareto_points=entry.read(n_text, "Points [-]", integer=True) if pareto else 11,
            pareto_low=entry.read(low_text, "Lowest limit [× limit]") if pareto else 0.6,
            pareto_high=entry.read(high_text, "Highest limit [× limit]") if pareto else 2.0,
        )
    except ValueError as exc:
        st.error(widgets.plain(short(f"Cannot run: {exc}")), icon=":material/error:")
    else:
        view.start_job(request)

view.run_job()
job = view.current_job()
if job is None:
    st.info(
        "Set the bounds and press **Run optimisation** (Quick takes a few seconds).",
        icon=":material/info:",
    )
else:
    view.render_results(job, inputs_json)
