"""Design page: inputs (one submit per change set) -> sized aerostat, geometry, mass,
performance versus wind, tether profiles; save as a case; JSON/CSV export and import."""

from __future__ import annotations

import math

import pandas as pd
import streamlit as st

from aerostat_core import thesis_baseline
from aerostat_core.model.io import design_to_json
from aerostat_core.output.report import DesignReport, tether_profile_rows
from aerostat_core.studies.fielded import class_caption
from app_ui import (
    cache,
    envelope_view,
    form,
    form_model,
    formats,
    lateral_view,
    mass_view,
    mission_view,
    perf_view,
    plots,
    preload,
    saving,
    shapes_view,
    show,
    side_view,
    state,
    tables,
    text,
    unapplied,
    verdict_view,
    workspace_ui,
)
from app_ui.errors import report_unexpected
from app_ui.headline import Headline, Note, limit_tone
from app_ui.shell import run_inside_the_app
from app_ui.tables import (
    constraint_styler,
    geometry_frame,
    mass_frame,
    mass_styler,
    performance_frame,
)

run_inside_the_app()  # a page reached by its own address still runs inside app.py
st.title("Aerostat design")
st.caption(  # one line at 1024 px: the verdict stays above the fold
    "Enter the requirement and the design choices, then press **Update design**; results in "
    "the units chosen in the sidebar."
)


def _load_baseline() -> None:
    state.set_current_inputs(*thesis_baseline())
    st.session_state.pop(form_model.ERROR_KEY, None)


def _on_upload() -> None:
    uploaded = st.session_state.get("design_upload")
    if uploaded is not None:
        state.handle_upload(uploaded, "design")
        st.session_state.pop(form_model.ERROR_KEY, None)


def _fmt(v: float, quantity: str) -> str:
    """A headline number at the decimals of its quantity (the same in every table), in the
    unit system chosen in the sidebar (its label from :func:`app_ui.formats.label`)."""
    return formats.shown(v, quantity)


def _headline(name: str, quantity: str, value: float, help: str, **delta) -> Headline:
    """A headline number whose label's unit and whose decimals are its quantity's."""
    return Headline(formats.label(name, quantity), _fmt(value, quantity), help, **delta)


TABS = ("Geometry", "3-D view", "Mass", "Performance", "Tether profiles", "Mission", "Envelope")
TAB_KEY = "design_tab"
#: Session-state key of the Geometry tab's interactive side view (open: True).
SIDE_VIEW_KEY = "side_view_interactive"
#: Session-state key of the Geometry tab's export section (open: True).
EXPORTS_KEY = "design_exports"
#: Session-state key of the constraint table's section (open: True).
CONSTRAINTS_KEY = "design_constraints"
#: Session-state key of the Performance tab's "Interactive charts" toggle (plotly: True).
PERF_INTERACTIVE_KEY = "perf_interactive"
#: Session-state key of the input column's design-file section (open: True).
DESIGN_FILE_KEY = "design_file"


def _geometry_tab(rep: DesignReport) -> None:
    # Static drawing and table on the first tab: a plotly chart or a data grid here pulled
    # 5 MB of JavaScript into a fresh browser before the first result (the interactive side
    # view is in a section below, drawn once opened).
    st.image(side_view.side_view_svg(rep), width="stretch")  # an SVG, sent as a data URL
    st.caption(
        "Side view to scale, level hull, nose on the left: CB centre of buoyancy (green), "
        "CG centre of gravity (black), C confluence point (red), confluence lines schematic."
    )
    # A section drawn once opened, not a toggle: the toggle's code was the last a fresh browser
    # loaded before the first result showed (no element shows before every element's code is
    # loaded); about 100 ms of the first result (interleaved probe, 2026-12-03).
    interactive = st.expander(
        "Interactive side view (zoom, hover)",
        key=SIDE_VIEW_KEY,
        on_change="rerun",
        icon=":material/zoom_in:",
    )
    if interactive.open:
        with interactive:
            st.plotly_chart(plots.side_view_figure(rep), key="side_view")
    g1, g2 = st.container(), st.container()
    with g1:
        # Escaped HTML, not st.table: a static table here made a fresh browser load ~1 MB of
        # table code (Arrow) before the first result showed (benchmarks/bench_app.py).
        st.html(tables.geometry_html(geometry_frame(rep.geometry_rows)))
    with g2:
        st.markdown(
            "**Reading the geometry.** ξ is measured from the nose, aft positive; z is up. "
            + shapes_view.geometry_note(rep.shape)
        )
        st.download_button(
            "Geometry table (CSV)",
            data=cache.csv_bytes(rep.geometry_rows),
            file_name="geometry.csv",
            mime="text/csv",
            on_click="ignore",
            icon=":material/download:",
            key="dl_geometry",
        )
    # Lazy: the files (STL, DXF, SVG, CSV of the gores) took 0.3-0.8 s to make for every new
    # design, longer than the design itself, and were made on every "Update design".
    build = st.expander(
        "Build it: STL for CAD and cutting patterns",
        key=EXPORTS_KEY,
        on_change="rerun",
        icon=":material/precision_manufacturing:",
    )
    if build.open:
        with build:
            shapes_view.export_panel(state.current_inputs_key())


def _mass_tab(rep: DesignReport) -> None:
    # One above the other: beside the chart the table was 150 px wide at 1024 px and scrolled.
    m1, m2 = st.container(), st.container()
    with m1:
        st.table(mass_styler(mass_frame(rep.mass_rows)))  # static: no grid bundle to load
        st.download_button(
            "Mass table (CSV)",
            data=tables.export_csv(rep.mass_rows, formats.system()),  # SI + unit row
            file_name="mass.csv",
            mime="text/csv",
            on_click="ignore",
            icon=":material/download:",
            key="dl_mass",
        )
    with m2:
        # A static drawing: each bar carries its mass and share, the table above has them
        # all; a plotly chart here was most of the tab switch's time (benchmarks/bench_app.py)
        st.image(mass_view.mass_svg(rep), width="stretch")


def _performance_tab(rep: DesignReport) -> None:
    # Three tables by theme (one of 15 columns scrolled sideways at 1024 px, where the result
    # column is under 500 px wide), as one escaped-HTML block: three st.table of a styler
    # were about 0.3 s of the tab switch in a browser without a GPU (benchmarks/bench_app.py)
    st.html(tables.performance_html(performance_frame(rep.performance_rows)))
    st.download_button(
        "Performance table (CSV)",
        data=tables.export_csv(rep.performance_rows, formats.system()),  # SI + unit row
        file_name="performance.csv",
        mime="text/csv",
        on_click="ignore",
        icon=":material/download:",
        key="dl_performance",
    )
    # Static drawings, one image element for the five (one a row at 1024 px, two at 1400 px):
    # five plotly charts here were most of the tab switch's second (benchmarks/bench_app.py).
    # The tables above list every number; zoom and hover are a toggle away.
    if st.toggle("Interactive charts (zoom, hover)", key=PERF_INTERACTIVE_KEY):
        r1 = st.columns(2)
        r1[0].plotly_chart(plots.performance_figure(rep, "blow_by"), key="perf_blow_by")
        r1[1].plotly_chart(plots.performance_figure(rep, "alpha_eq"), key="perf_alpha")
        r2 = st.columns(2)
        r2[0].plotly_chart(plots.performance_figure(rep, "dynamic_lift"), key="perf_lift")
        r2[1].plotly_chart(plots.tension_figure(rep), key="perf_tension")
        r3 = st.columns(2)
        r3[0].plotly_chart(plots.cm_figure(rep), key="perf_cm")
        with r3[1]:
            _stability_notes(rep)  # beside the longitudinal C_m
    else:
        charts = perf_view.performance_charts(rep)
        st.image(
            [c.svg for c in charts], width=perf_view.WIDTH_PX, alt=[c.alt for c in charts]
        )
        _stability_notes(rep)


def _stability_notes(rep: DesignReport) -> None:
    """How to read the C_m chart, and the lateral derivatives (after the longitudinal C_m)."""
    st.caption(
        "C_m is the pitching moment about the confluence point over q V^(2/3) l. The trim "
        "is stable where C_m falls as α rises (negative slope at the green point)."
    )
    lateral_view.render(rep)


def _tether_tab(rep: DesignReport) -> None:
    @st.fragment
    def _tether_panel() -> None:
        show.apply_unit_choice()  # a fragment rerun does not run app.py
        speeds = plots.tether_speeds(rep.tether)  # the sweep and the design wind
        default = plots.default_profile_speeds(rep.tether)
        chosen = st.multiselect(
            "Wind speeds to show [m/s]",
            speeds,
            default=default,
            key="tether_speeds",
            format_func=lambda v: f"{v:g}",
            help="Tether profiles of the sweep, drawn to scale.",
        )
        st.plotly_chart(plots.tether_figure(rep, sorted(chosen) or default), key="tether_plot")

    _tether_panel()
    m = rep.summary.mission
    st.caption(
        f"Winch: line pull {m.winch_pull_N:,.0f} N (largest winch tension, survival wind "
        f"included), motor {m.winch_power_W:,.0f} W; drum and reel-in time on the Mission tab."
    )
    st.download_button(
        "Tether profiles (CSV)",
        data=lambda: cache.csv_bytes(tether_profile_rows(rep.tether)),
        file_name="tether-profiles.csv",
        mime="text/csv",
        on_click="ignore",
        icon=":material/download:",
        key="dl_tether",
    )


# --- results ---------------------------------------------------------------------------------
# A fragment: a tab switch, the case form and the tether speeds rerun the results alone, not the
# input form (half of a full run's script time and elements); "Update design" reruns the page.


def _guarded(body) -> None:
    # A fragment's own error boundary: an error raised in a fragment stops at Streamlit's
    # fragment handler (a redacted exception box), before app.py's boundary could see it.
    try:
        body()
    except Exception as exc:  # noqa: BLE001 - never a traceback; a reference id, logged
        report_unexpected(exc)


@st.fragment
def _results() -> None:
    _guarded(_results_body)


def _results_body() -> None:
    show.apply_unit_choice()  # a fragment rerun does not run app.py
    try:
        frozen = cache.current_inputs()  # built once by the form; no JSON on the way
        rep = cache.report_of(*frozen)
    except Exception as exc:  # noqa: BLE001 - never show a traceback
        st.error(
            f"The design could not be evaluated with these inputs: {exc}", icon=":material/error:"
        )
        st.stop()
    s, lim = rep.summary, rep.limits
    # After a rejected submit the form holds values that were not applied: say whose results
    # these are, so "meets every requirement" is never read as a verdict on the rejected values.
    stale = bool(st.session_state.get(form_model.ERROR_KEY))

    st.subheader("Result", anchor=False)
    d_now = cache.design_of(*frozen)
    verdict_view.render(d_now, stale)  # the verdict first
    rules = form_model.RULE_SETS[rep.inputs["requirement"]["rules"]]
    st.caption(  # short (one line at 1024 px); the rule set's title in its help
        f"Rule set: **{rules.name}**. "
        + (f"Sized by: {s.binding_constraint.replace('_', ' ')}." if rep.sized else ""),
        help=rules.title,
    )
    if stale:
        st.warning(
            "These results are for the last valid inputs: your latest change was not applied "
            "(see the message in the form).",
            icon=":material/history:",
        )
    # The ten headline numbers as one element (app_ui/headline.py: ten st.metric were a
    # quarter of the page's elements, and the first result waited for them).
    items: list[Headline | Note] = [
        _headline(
            "Volume",
            "volume",
            s.volume_m3,
            "Hull volume. Sized: the smallest hull meeting the blow-by limit with positive "
            "free lift."
            if rep.sized
            else "Hull volume, given in the inputs.",
            delta="sized" if rep.sized else "given",
        ),
        _headline("Length", "length", s.length_m, "Hull length l."),
        _headline("Diameter", "diameter", s.diameter_m, "Maximum hull diameter d."),
        _headline(
            "Total mass",
            "total_mass",
            s.total_mass_kg,
            "Hull, fins, lifting gas, miscellaneous, payload and tether.",
        ),
        _headline(
            "Free lift",
            "free_lift",
            s.free_lift_kg,
            "Gross buoyancy minus total weight, as a mass "
            f"({s.percent_static_lift:.0f} % of the gross buoyancy).",
        ),
    ]
    # no wind quantity of a hull that sinks means anything: its design-wind row is not shown
    if not d_now.sinks:
        bb = s.blow_by_at_design_wind_m
        sf = s.safety_factor_at_design_wind
        items += [
            Note(f"At the design wind, {formats.shown(lim.design_wind, 'wind', with_unit=True)}:"),
            _headline(
                "Blow-by",
                "blow_by",
                bb,
                f"Downwind offset of the confluence point from the winch; limit "
                f"{formats.shown(lim.blow_by_limit, 'blow_by', with_unit=True)} (the delta is "
                "blow-by minus limit).",
                delta=text.signed(formats.convert(bb - lim.blow_by_limit, "blow_by"), 1)
                + f" {formats.unit_of('blow_by')}"
                if math.isfinite(bb)
                else "",
                tone=limit_tone(bb, lim.blow_by_limit, "max"),
            ),
            Headline(
                "α_eq [deg]",
                _fmt(s.alpha_at_design_wind_deg, "alpha_eq"),
                "Equilibrium angle of attack (moment balance about the confluence point).",
            ),
            _headline(
                "Tension", "tension", s.tension_top_at_design_wind_N,
                "Tether tension at the confluence point.",
            ),
            Headline(
                "Safety factor [-]",
                _fmt(sf, "safety_factor"),
                "Breaking strength of the tether / largest tension along the tether; required "
                f"{lim.min_safety_factor:g} (the delta is the margin).",
                delta=text.signed(sf - lim.min_safety_factor, formats.decimals("safety_factor"))
                if math.isfinite(sf)
                else "",
                tone=limit_tone(sf, lim.min_safety_factor, "min"),
            ),
            Headline(
                "Gas cost [USD]", _fmt(s.gas_cost_USD, "gas_cost"), "Hull volume × gas price."
            ),
        ]
    show.headlines(items)

    # below the headline numbers: the verdict and the key numbers stay above the fold at 1024 px
    st.caption(text.plain(class_caption(rep.inputs["requirement"]["payload_mass"],
                                        rep.inputs["requirement"]["altitude"])))
    # Lazy: drawn once opened (a rerun of the results), not on every rerun while closed (its
    # styled table was a tenth of a rerun's script time and its largest message).
    constraints = st.expander(
        "Constraint table: every limit, its margin and where it is checked",
        icon=":material/rule:",
        key=CONSTRAINTS_KEY,
        on_change="rerun",
    )
    if constraints.open:
        with constraints:
            # static, cells that wrap: a data grid here loaded 1 MB of JavaScript before the
            # first result, and scrolled sideways at 1024 px
            st.table(constraint_styler(pd.DataFrame(text.constraint_table_rows(rep.constraints))))
    if not rep.feasible:  # the verdict above says it; the table's reasons in full here
        st.error(
            "**Requirements not met:**\n" + "\n".join(f"- {v}" for v in rep.violations),
            icon=":material/error:",
        )
    p = rep.perf
    lim_speeds = [float(v) for v, flag in zip(p.wind_speed, p.limited) if flag]
    if lim_speeds:
        st.warning(
            f"Operating limits exceeded in the sweep at "
            f"{text.speed_ranges(lim_speeds, rep.inputs['requirement']['wind_step'])} m/s "
            "(marked in red in the table and plots).",
            icon=":material/warning:",
        )

    with st.form("save_case_form", border=False, enter_to_submit=True):
        req_cur, _ = state.current_inputs()
        default_name = (
            f"Case {len(state.get_cases()) + 1}: {req_cur.payload_mass:g} kg at "
            f"{req_cur.altitude:g} m"
        )
        st.session_state["_case_name_default"] = default_name
        c1, c2 = st.columns([3, 1], vertical_alignment="bottom")
        c1.text_input(
            "Save the current design as a case",
            key="case_name",
            placeholder=default_name,
            max_chars=state.MAX_NAME_CHARS,
            help="Saved cases are compared on the Compare page. They are kept in this "
            "workspace (the page's address): bookmark it to come back to them.",
        )
        c2.form_submit_button(
            "Save case", on_click=saving.save_current, icon=":material/bookmark_add:", width="stretch"
        )
    case_box = st.container()  # always present: the tabs below keep their place
    envelope_view.report_button(state.current_inputs_key())
    fb = st.session_state.pop(saving.FEEDBACK_KEY, None)
    redrawn = st.session_state.pop("_frame_redrawn", False)
    if fb and not redrawn and workspace_ui.frame_is_stale():
        # a save during an outage changes the app frame, which this fragment's rerun does not
        # redraw: rerun the whole app once (never twice), keeping the message
        st.session_state[saving.FEEDBACK_KEY] = fb
        st.session_state["_frame_redrawn"] = True
        st.rerun()
    with case_box:
        if fb:
            show.feedback(fb[0], fb[1])
        saving.choice_panel()  # a taken name or a case changed elsewhere: asks, never guesses

    _tabs()


@st.fragment
def _tabs() -> None:
    # A fragment of its own inside the results: a tab switch reruns the open tab alone, not the
    # verdict, the headline numbers, the constraint table and the case form above it (a third
    # of the messages and elements of a results rerun). It reads the current inputs itself:
    # a rerun of this fragment alone must not draw the inputs of an older run.
    _guarded(_tabs_body)


def _tabs_body() -> None:
    show.apply_unit_choice()  # a fragment rerun does not run app.py
    frozen = cache.current_inputs()
    rep = cache.report_of(*frozen)  # a cache hit: the results above computed it
    # Lazy tabs: only the open tab runs and is sent to the browser (a rerun draws 1-5 charts
    # instead of 10, which keeps "click Update design -> result" well under a second).
    tabs = dict(zip(TABS, st.tabs(TABS, key=TAB_KEY, on_change="rerun", default=TABS[0])))

    with tabs["Geometry"]:
        if tabs["Geometry"].open:
            _geometry_tab(rep)
    with tabs["3-D view"]:
        if tabs["3-D view"].open:
            st.plotly_chart(plots.hull_3d_figure(rep), key="hull_3d", config=plots.GL_CONFIG)
            s = rep.summary
            st.caption(
                "Drag to rotate, scroll to zoom. To scale: hull length "
                f"{formats.shown(s.length_m, 'length', with_unit=True)}, diameter "
                f"{formats.shown(s.diameter_m, 'diameter', with_unit=True)} (dimensions on "
                "the Geometry tab). Fins in orange; confluence lines are schematic (the engine "
                "models only the confluence point)."
            )
    with tabs["Mass"]:
        if tabs["Mass"].open:
            _mass_tab(rep)
    with tabs["Performance"]:
        if tabs["Performance"].open:
            _performance_tab(rep)
    with tabs["Tether profiles"]:
        if tabs["Tether profiles"].open:
            _tether_tab(rep)
    with tabs["Mission"]:
        if tabs["Mission"].open:
            mission_view.render(cache.design_of(*frozen))
    with tabs["Envelope"]:
        if tabs["Envelope"].open:
            envelope_view.render(state.current_inputs_key(), rep)


def _design_file_panel() -> None:
    """The design file's download and upload (the input column's lazy section)."""
    req_cur, cfg_cur = state.current_inputs()
    st.download_button(
        "Download design inputs (JSON)",
        data=design_to_json(req_cur, cfg_cur),
        file_name="aerostat-design.json",
        mime="application/json",
        on_click="ignore",
        icon=":material/download:",
        key="dl_design_json",
        help="Every input, including those not shown in the form. Upload it again to "
        "restore the design.",
    )
    st.file_uploader(
        "Upload a design or cases file (JSON)",
        type=["json"],
        key="design_upload",
        on_change=_on_upload,
        help="A design file replaces the current inputs; a cases file adds saved cases. "
        "A file with a problem changes nothing.",
    )


# 1 : 2.2 with the app's narrow padding: at 1024 px the input column is ~230 px (labels whole),
# the result column ~500 px (four headline numbers a row)
col_in, col_out = st.columns([1, 2.2], gap="medium")
# The results are drawn first (the columns keep their places): their messages reach the browser
# before the form's 60 widgets, so the first result paints while the form is still arriving.
with col_out:
    _results()

# --- inputs ------------------------------------------------------------------------------------
with col_in:
    st.subheader("Inputs", anchor=False)
    st.button(
        "Load thesis baseline",
        on_click=_load_baseline,
        icon=":material/restart_alt:",
        help="10 kg payload at 300 m, 170 m³ NPL hull with fineness ratio 4.0, thesis "
        "constants (helium 0.169 kg/m³, 130 g/m² fabric, 20 g/m tether).",
    )
    # Lazy: drawn once opened (a rerun). Its file uploader was the only one on the page, and
    # its code held the first result of a fresh browser back (every element's code loads
    # before any of them shows).
    design_file = st.expander(
        "Design file: export / import",
        icon=":material/folder_open:",
        key=DESIGN_FILE_KEY,
        on_change="rerun",
    )
    if design_file.open:
        with design_file:
            _design_file_panel()
    import_box = st.container()  # always present: the form below keeps its place
    fb = state.pop_import_feedback("design")  # shown once: never next to a later file
    if fb:
        with import_box:
            show.feedback(fb["level"], fb["text"])
    form.input_form()
    unapplied.guard()  # edits typed but not applied: asked about before a page switch drops them


# Last element: the chart and grid code loads while the user reads the first result.
preload.warm_bundles()
