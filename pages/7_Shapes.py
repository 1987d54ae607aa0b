"""Shapes page: the hull-shape library, the thesis' shape comparison (Table 2.2, Figure 2.5)
reproduced with its assumptions and then with the full model, and the best design per shape."""

from __future__ import annotations

import streamlit as st

from aerostat_core.optimize import OBJECTIVES
from app_ui import formats, state, widgets
from app_ui import shapes_view as view
from app_ui.shell import run_inside_the_app

run_inside_the_app()  # a page reached by its own address still runs inside app.py
st.title("Hull shapes")
st.caption(
    "The thesis chooses its hull from a comparison of sphere, Helikite and streamlined hulls "
    "(§2.2.1(b), Tables 2.1-2.2, Figure 2.5) and names the standard streamlined envelopes NPL, "
    "GNVR, Wang and Zhiyuan-1 (§2.4.3(a), Figure 2.16). Pick a shape for your design on the "
    "Design page."
)

st.subheader("Shape library", anchor=False)
st.plotly_chart(view.profiles_figure(), key="shape_profiles")
st.markdown(formats.text_in_system("**Every shape at 100 m³ and its standard l/d**"))
# one column per shape, one row per property, streamlined and bluff hulls in two static tables,
# so every cell is in sight at 1024 px
_lib = view.static_frame(view.library_frame(view.cached_library(100.0)).set_index("Shape"), True)
_props = _lib.drop(index="Source")  # the sources, long, are listed below the tables
st.table(_props.iloc[:, :5])
st.table(_props.iloc[:, 5:])
st.caption("Sources. " + " ".join(f"{shape}: {src}." for shape, src in _lib.loc["Source"].items()))
st.caption(
    "Wang, Zhiyuan-1 and LOTTE are Gertler profiles from a published parameter table "
    "(attributed to Alam & Pant 2017); GNVR is its ellipse, circular arc and parabola "
    "(second-hand constants, cross-checked against two Gertler tables); docs/methods.md §1.13 "
    "says what was checked for each. k1, k2, k' are Lamb's closed forms for the spheroids and "
    "the equivalent spheroid for NPL, and a potential-flow computation (line singularities, "
    "checked against Lamb) for the Gertler shapes and GNVR. Bluff hulls (sphere, oblate, Helikite) carry no fins; their drag is the sphere's "
    "(Achenbach 1972) at the hull Reynolds number."
)

data = view.cached_comparisons()
p = view.THESIS_SHAPE_PRESET
st.subheader("Table 2.2 and Figure 2.5 with the thesis' assumptions", anchor=False)
st.markdown(
    f"Equal {p.volume:g} m³ hulls at {p.altitude:g} m; buoyancy {p.gross_lift_per_m3:g} kg/m³ "
    f"(the table's 100 kg); tether sag ignored (straight tether); streamlined lift ignored; "
    f"C_D 0.2 (Helikite, sphere, on frontal area) and 0.03 (streamlined, on V^(2/3)); fabric "
    f"{p.fabric_areal_density * 1000:g} g/m², helium {p.helium_density:g} kg/m³, tether "
    f"{p.tether_linear_density * 1000:g} g/m; kite {p.kite_mass:g} kg with "
    f"{p.kite_lift_kg:g} kg of lift at {p.kite_lift_wind:g} m/s (scaled with U²)."
)
# full width and static: the thesis' and this model's columns side by side in sight at 1024 px
st.table(view.static_frame(view.versus_frame(data["thesis"]["rows"], data["reference"])))
st.caption(
    "The thesis' streamlined total (50.92 kg) and free lift (47 kg) do not add up "
    "(16.9 + 15.57 + 7.8 + 4.7 + 6 = 50.97; 100 - 50.97 = 49.03); this model adds them up. "
    "Its Helikite is a spheroid of Table 2.2's l/d (6.2/5) scaled to 100 m³."
)
st.plotly_chart(
    view.blow_by_figure(data["thesis"], "Figure 2.5: blow-by, thesis assumptions"),
    key="shape_fig_thesis",
)

st.subheader("The same comparison with the full model", anchor=False)
st.markdown(
    "ISA buoyancy, drag correlations, trim with hull and fin lift, tether sag and weight "
    "(Design-page engine with the thesis constants)."
)
st.table(view.static_frame(view.table_frame(data["full"]["rows"])))
st.plotly_chart(view.blow_by_figure(data["full"], "Blow-by, full model"), key="shape_fig_full")
st.markdown("**Why the numbers differ**")
for note in data["notes"]:
    st.markdown(f"- {note}")

st.subheader("Best design per shape for the current requirement", anchor=False)
st.caption(
    "The optimiser (SLSQP, quick) runs once per streamlined shape, the l/d of the bluff hulls "
    "is searched on a grid; the hull is sized to the blow-by limit every time. Uses the inputs "
    "of the Design page."
)
with st.form("shape_opt_form"):
    objective = st.radio(
        "Objective",
        list(OBJECTIVES),
        key="shape_objective",
        horizontal=True,
        format_func=lambda k: OBJECTIVES[k][0],
    )
    run = st.form_submit_button(
        "Optimise every shape", type="primary", key="shape_opt_run", icon=":material/auto_graph:"
    )
if run or st.session_state.get("shape_opt_done"):
    st.session_state["shape_opt_done"] = True
    try:
        with st.spinner("Optimising every shape..."):
            rows = view.cached_shape_study(state.current_inputs_key(), objective)
    except ValueError as exc:
        st.error(widgets.plain(f"Cannot optimise the shapes: {exc}"), icon=":material/error:")
    else:
        best = [r for r in rows if r["best"]]
        if best:
            st.success(
                f"Best shape: **{best[0]['label']}**, {OBJECTIVES[objective][0].lower()} "
                f"{best[0][objective]:.1f} {OBJECTIVES[objective][1]}.",
                icon=":material/check_circle:",
            )
        else:
            st.warning("No shape meets every requirement.", icon=":material/warning:")
        study = view.study_frame(rows, objective)
        # two static tables (design variables, then results), so every column is in sight
        design_cols = ["Shape", "Best", "Feasible", "l/d [-]", "ΔS_f [%]", "Δl_f [% of l]"]
        first = [c for c in design_cols if c in study.columns]
        rest = ["Shape", *[c for c in study.columns if c not in first and c != objective]]
        st.table(view.study_styler(study[first]), hide_index=True)
        st.table(view.study_styler(study[rest]), hide_index=True)
