"""Sensitivity page: one-factor-at-a-time sweeps of f, ΔS_f and Δl_f around the current design,
and a two-variable map of total mass with the blow-by-limit contour."""

from __future__ import annotations

import streamlit as st

from aerostat_core.base.validation import short
from aerostat_core.optimize import VARIABLE_INFO, VARIABLES
from app_ui import formats, shapes_view, widgets
from app_ui import optimize_view as view
from app_ui.shell import run_inside_the_app

run_inside_the_app()  # a page reached by its own address still runs inside app.py
st.title("Sensitivity")
st.caption(
    "How the design responds to each design variable (thesis §3.2.2): one factor at a time "
    "around the current design, the other two held; then two variables at once. Outputs at the "
    "design wind. Change the centre of the sweeps on the Design page."
)

inputs_json, req, cfg = view.load_inputs()
base = {
    "fineness_ratio": cfg.hull.fineness_ratio,
    "area_change": cfg.fins.area_change,
    "position": cfg.fins.position,
}
shown = {k: view.shown(k, v) for k, v in base.items()}  # the fin position in % of l
vol_txt = f"given volume {cfg.hull.volume:g} m³" if cfg.hull.volume is not None else "volume sized"
st.markdown(formats.text_in_system(  # the numbers in the chosen unit system
    f"**Baseline:** f = {shown['fineness_ratio']:g}, ΔS_f = {shown['area_change']:g} %, "
    f"Δl_f = {shown['position']:g} % of l, {vol_txt}; payload {req.payload_mass:g} kg at "
    f"{req.altitude:g} m; blow-by limit {req.blow_by_limit:g} m at {req.design_wind:g} m/s; "
    f"rule set **{req.rules}** (every constraint of its table applies)."
))

VOLUME_MODES = {
    "resize": "Re-sized at every point (smallest hull meeting the requirement)",
    "held": "Held at the baseline volume (shows how the blow-by moves)",
}

with st.form("sens_form"):
    c = st.columns([1, 2, 2])
    level = c[0].radio(
        "Resolution",
        list(view.SENS_RESOLUTION),
        index=1,
        key="sens_level",
        persist_state="session",
        help="Quick: 7 points per sweep, 10 × 10 map. Normal: 15 points, 20 × 20.",
    )
    sweep_mode = c[1].radio(
        "Hull volume in the sweeps",
        list(VOLUME_MODES),
        key="sens_sweep_mode",
        format_func=VOLUME_MODES.get,
        persist_state="session",
    )
    map_mode = c[2].radio(
        "Hull volume in the map",
        list(VOLUME_MODES),
        index=1,
        key="sens_map_mode",
        format_func=VOLUME_MODES.get,
        persist_state="session",
        help="Held: mass and blow-by of the baseline hull, with the blow-by "
        "limit as a contour (the feasible side is the design space). "
        "Re-sized: mass of the smallest feasible hull.",
    )
    m = st.columns(2)
    x_var = m[0].selectbox(
        "Map: horizontal variable",
        VARIABLES,
        index=0,
        key="sens_x",
        format_func=view.var_label,
        persist_state="session",
    )
    y_var = m[1].selectbox(
        "Map: vertical variable",
        VARIABLES,
        index=1,
        key="sens_y",
        format_func=view.var_label,
        persist_state="session",
    )
    st.markdown("**Ranges**")
    range_texts = view.variable_range_inputs("sens", "from", "to")
    st.form_submit_button("Update", type="primary", key="sens_run", icon=":material/refresh:")

n_points, n_map = view.SENS_RESOLUTION[level]
try:  # the boxes as typed: a decimal comma is a decimal point, bounds checked in their unit
    ranges = view.parse_ranges(range_texts, "from", "to")
except ValueError as exc:
    st.error(widgets.plain(short(f"Ranges: {exc}")), icon=":material/error:")
    ranges = None

st.subheader("One factor at a time", anchor=False)
try:
    if ranges is None:
        raise ValueError("fix the ranges above first")
    res = view.cached_sensitivity(req, cfg, ranges, n_points, sweep_mode == "resize")
except ValueError as exc:
    st.error(widgets.plain(short(f"Cannot compute the sweeps: {exc}")), icon=":material/error:")
else:
    if sweep_mode == "resize":
        st.caption(view.resize_caption(res))  # says what the plot shows
    st.plotly_chart(view.sensitivity_figure(res), key="sens_ofat")
    st.markdown("**Mass and volume change over each range** (relative to the baseline)")
    st.table(view.summary_table(res))  # transposed: 4 columns fit at 1024 px, 10 did not
    with st.expander("All sweep points"):
        for table in view.sweep_tables(view.sweep_frame(res)):  # static, one per variable
            st.table(table)
    c1, c2 = st.columns(2)
    c1.download_button(
        "Sweeps (CSV)",
        view.csv_of(res.rows()),
        file_name="sensitivity-sweeps.csv",
        mime="text/csv",
        on_click="ignore",
        icon=":material/download:",
        key="dl_sens_sweeps",
    )
    c2.download_button(
        "Range summary (CSV)",
        view.csv_of(res.summary_rows()),
        file_name="sensitivity-summary.csv",
        mime="text/csv",
        on_click="ignore",
        icon=":material/download:",
        key="dl_sens_summary",
    )

st.subheader("Two variables at once", anchor=False)
if ranges is None:
    st.info("Map: fix the ranges above first.", icon=":material/info:")
elif x_var == y_var:
    st.error(
        f"Map: choose two different variables (both are {VARIABLE_INFO[x_var][0]}).",
        icon=":material/error:",
    )
else:
    try:
        smap = view.cached_map(req, cfg, x_var, y_var, ranges, n_map, map_mode == "resize")
    except ValueError as exc:
        st.error(widgets.plain(short(f"Cannot compute the map: {exc}")), icon=":material/error:")
    else:
        held = [k for k in VARIABLES if k not in (x_var, y_var)][0]
        st.caption(
            f"{view.var_label(held)} held at {shown[held]:g}. "
            + (
                "Red line: blow-by = limit; designs beyond it (crosses) break the limit "
                "or another constraint."
                if map_mode == "held"
                else "Crosses: no feasible hull or another constraint broken."
            )
        )
        st.plotly_chart(view.map_figure(smap), key="sens_map")
        st.download_button(
            "Map (CSV)",
            view.csv_of(smap.rows()),
            file_name="sensitivity-map.csv",
            mime="text/csv",
            on_click="ignore",
            icon=":material/download:",
            key="dl_sens_map",
        )

st.subheader("Per hull shape", anchor=False)
st.caption(
    "Every shape re-sized over its own valid fineness-ratio range, the fins and everything else "
    f"as on the Design page (current shape: {cfg.hull.shape}). The sweeps above use the current "
    "shape; their l/d range must lie inside its valid range."
)
if st.button("Sweep every shape", key="sens_shapes_run", icon=":material/category:") or (
    st.session_state.get("sens_shapes_done")
):
    st.session_state["sens_shapes_done"] = True
    shapes_view.sensitivity_per_shape(inputs_json)
