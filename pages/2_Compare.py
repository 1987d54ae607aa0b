"""Compare page: saved cases side by side (differences highlighted), overlaid performance curves
and tether profiles; load the thesis' GUI test cases; rename, delete, export and import cases."""

from __future__ import annotations

import streamlit as st

from aerostat_core.base.validation import short
from aerostat_core.model import budget
from aerostat_core.model.io import inputs_from_dict
from aerostat_core.output.report import thesis_gui_cases
from app_ui import cache, formats, plots, show, state, text, workspace_ui
from app_ui.shell import run_inside_the_app

run_inside_the_app()  # a page reached by its own address still runs inside app.py
st.title("Compare saved cases")
st.caption(
    "Save designs on the Design page (or load the thesis' GUI test cases) and compare them here. "
    "Saved cases are kept in this workspace: bookmark or share the page's address to come back "
    "to them."
)


def _load_gui_cases() -> None:
    try:
        names = state.add_cases(thesis_gui_cases())
    except ValueError as exc:  # e.g. the case limit
        st.session_state["compare_feedback"] = ("error", str(exc))
        return
    if not names:
        st.session_state["compare_feedback"] = (
            "info",
            "The thesis' GUI test cases are saved already.",
        )
        return
    st.session_state["compare_feedback"] = (
        "success",
        f"Added the thesis' GUI test cases: {', '.join(names)}.",
    )


def _rename() -> None:
    old = st.session_state.get("rename_from")
    new = st.session_state.get("rename_to", "")
    try:
        used = state.rename_case(old, new)
    except ValueError as exc:
        st.session_state["compare_feedback"] = ("error", str(exc))
    else:
        st.session_state["compare_feedback"] = ("success", f"Renamed “{old}” to “{used}”.")
        st.session_state["rename_to"] = ""
        # The pickers follow the case to its new name (a stale name made the next rename fail).
        for key in ("rename_from", "load_name"):
            if st.session_state.get(key) == old:
                st.session_state[key] = used
        sel = st.session_state.get("compare_selected")
        if isinstance(sel, list):
            st.session_state["compare_selected"] = [used if n == old else n for n in sel]


def _delete() -> None:
    names = st.session_state.get("delete_names") or []
    done, refused = 0, []
    for n in names:
        try:
            state.delete_case(n)  # only the version shown here: a case changed elsewhere stays
        except ValueError as exc:
            refused.append(str(exc))
        else:
            done += 1
    st.session_state["delete_names"] = []
    if refused:
        st.session_state["compare_feedback"] = (
            "error",
            f"Deleted {done} case(s); not deleted: " + "; ".join(refused) + ".",
        )
    elif names:
        st.session_state["compare_feedback"] = ("success", f"Deleted {len(names)} case(s).")


def _load_into_design() -> None:
    name = st.session_state.get("load_name")
    cases = state.get_cases()
    if name not in cases:
        return
    try:
        state.set_current_inputs(*inputs_from_dict(cases[name]))
    except ValueError as exc:
        st.session_state["compare_feedback"] = ("error", f"“{name}” cannot be opened: {exc}")
        return
    st.session_state["compare_feedback"] = (
        "success",
        f"“{name}” is now the current design: open the Design page to edit it.",
    )


REPLACE_ASK_KEY = "_replace_ask"


def _on_upload() -> None:
    uploaded = st.session_state.get("cases_upload")
    if uploaded is None:
        return
    mode = st.session_state.get("import_mode", "add")
    if mode == "replace":
        try:
            raw = state.read_upload(uploaded)
        except ValueError:
            raw = None  # handle_upload says why
        if raw is not None and state.file_kind(raw) == "cases":
            # Ask first; remember what the user sees now: only those cases are removed.
            st.session_state[REPLACE_ASK_KEY] = {
                "raw": raw,
                "filename": state.display_name(getattr(uploaded, "name", "the file")),
                "seen": state.case_versions(),
                "shown": [n for n in state.get_cases() if n in state.case_versions()],
            }
            return
    state.handle_upload(uploaded, "compare", mode=mode if mode in state.IMPORT_MODES else "add")


def _answer_replace(go: bool) -> None:
    ask = st.session_state.pop(REPLACE_ASK_KEY, None)
    if not ask:
        return
    if not go:
        st.session_state["compare_feedback"] = ("info", "Nothing was replaced.")
        return
    level, msg = state.import_file(
        ask["raw"], filename=ask["filename"], mode="replace", seen=ask["seen"]
    )
    st.session_state[state.IMPORT_MSG_KEY] = {"level": level, "text": msg, "where": "compare"}


def _replace_question() -> None:
    ask = st.session_state.get(REPLACE_ASK_KEY)
    if not ask:
        return
    shown = ask["shown"]
    listed = ", ".join(f"“{n}”" for n in shown[:6]) + (" …" if len(shown) > 6 else "")
    st.warning(
        text.plain(
            f"Replace the {len(shown)} saved case(s) shown here ({listed}) with the cases of "
            f"{ask['filename']}? Cases saved or changed in another tab since are kept."
            if shown
            else f"Add the cases of {ask['filename']}? (No case is saved here yet.)"
        ),
        icon=":material/help:",
    )
    row = st.container(horizontal=True)
    row.button("Replace", key="replace_yes", on_click=_answer_replace, args=(True,), type="primary")
    row.button("Cancel", key="replace_no", on_click=_answer_replace, args=(False,))


top = st.columns([1, 1, 2], vertical_alignment="center")
top[0].button(
    "Load the thesis' GUI test cases",
    on_click=_load_gui_cases,
    icon=":material/playlist_add:",
    help="Payload 10 vs 30 kg at 300 m, and altitude 100 vs 500 m with 10 kg "
    "(thesis §4.5), each from the thesis baseline with the volume sized.",
)

# Messages go into containers that always exist, so that the elements below keep their place
# (and an open expander stays open) whether or not there is a message.
feedback_box = st.container()
fb = st.session_state.pop("compare_feedback", None)
if fb:
    with feedback_box:
        show.feedback(fb[0], fb[1])

cases = state.get_cases()

with st.expander("Cases file: export / import", icon=":material/folder_open:"):
    c1, c2 = st.columns(2)
    with c1:
        st.download_button(
            "Download all cases (JSON)",
            data=cache.cases_json_bytes(cases),
            file_name="aerostat-cases.json",
            mime="application/json",
            on_click="ignore",
            icon=":material/download:",
            key="dl_cases_json",
            disabled=not cases,
            help="Every input of every case; upload it again to restore them.",
        )
        st.download_button(
            "Download all cases (CSV)",
            data=lambda: cache.cases_csv_of(cases).encode("utf-8"),
            file_name="aerostat-cases.csv",
            mime="text/csv",
            on_click="ignore",
            icon=":material/table:",
            key="dl_cases_csv",
            disabled=not cases,
            help="One tidy table: a row per case and wind speed, with every input, the headline "
            "results and the performance at that wind. Units are in the column names.",
        )
    with c2:
        st.radio(
            "Importing a cases file",
            state.IMPORT_MODES,
            format_func={
                "add": "adds its cases",
                "replace": "replaces the saved cases (asks first)",
            }.get,
            key="import_mode",
            horizontal=True,
            help="Add: cases identical to saved ones are skipped, other names that are taken "
            "get a number. Replace: asks, then the cases shown here are replaced by the file's (cases another tab saved since are kept).",
        )
        st.file_uploader(
            "Upload a cases or design file (JSON)",
            type=["json"],
            key="cases_upload",
            on_change=_on_upload,
            help="Cases are added (a name that exists gets a number); a design "
            "file replaces the current inputs. A file with a problem "
            "changes nothing.",
        )

import_box = st.container()
fb = state.pop_import_feedback("compare")  # shown once: never next to a later file
with import_box:
    if fb:
        show.feedback(fb["level"], fb["text"])
    _replace_question()

if not cases:
    st.info(
        "No saved cases yet. Save the current design on the **Design** page, or load the "
        "thesis' GUI test cases, or upload a cases file under *Cases file: export / import*.",
        icon=":material/info:",
    )
    st.stop()

names = list(cases)
# Keep the selection in step with the saved cases: new (or renamed) cases join it, deleted ones
# leave it; the user's own deselections stay.
_prev = st.session_state.get("_compare_names")
if _prev != names or "compare_selected" not in st.session_state:
    _sel = st.session_state.get("compare_selected")
    st.session_state["compare_selected"] = [
        n for n in names if _sel is None or _prev is None or n in _sel or n not in _prev
    ]
    st.session_state["_compare_names"] = names
for _key in ("rename_from", "load_name"):
    if st.session_state.get(_key) not in names:
        st.session_state.pop(_key, None)
selected = st.multiselect(
    "Cases to compare",
    names,
    key="compare_selected",
    format_func=workspace_ui.unsaved_label,
    help="One column per case in the table, one line per case in the plots.",
)
if not selected:
    st.info("Choose at least one case to compare.")
    st.stop()

try:  # the whole comparison against the compute budget, before any case is computed
    budget.check_cases({n: cases[n] for n in selected})
except budget.BudgetError as exc:
    st.error(text.plain(str(exc)), icon=":material/speed:")
    st.stop()
reports: dict = {}  # name -> DesignReport: each case designed once (shared with the table)
for name in selected:
    try:
        reports[name] = cache.report_for(cases[name])
    except Exception as exc:  # noqa: BLE001 - never show a traceback
        st.error(
            text.plain(short(f"Case “{name}” could not be evaluated: {exc}")),
            icon=":material/error:",
        )

# Lazy tabs: only the open tab runs and is sent to the browser.
tab_table, tab_perf, tab_tether, tab_manage = st.tabs(
    ["Side by side", "Performance", "Tether profiles", "Manage cases"],
    key="compare_tab",
    on_change="rerun",
)

with tab_table:
    if tab_table.open:
        ok = [n for n in selected if n in reports]
        sub = {n: cases[n] for n in ok}
        only_diff = st.toggle(
            "Show only the rows that differ", key="compare_only_diff", persist_state="session"
        )
        try:
            rows = cache.comparison_of(sub) if sub else []
        except Exception as exc:  # noqa: BLE001
            st.error(text.plain(short(f"The comparison could not be built: {exc}")))
            rows = []
        if rows:
            df = plots.comparison_frame(rows, ok, only_differences=only_diff)
            # st.table reads Markdown in every cell and header: the case names as typed
            df = df.rename(columns={n: text.plain(n) for n in ok})
            n_diff = int(sum(r["differs"] for r in rows))
            st.caption(f"{n_diff} of {len(rows)} rows differ between the cases (highlighted).")
            # a static table whose cells wrap: every row and column in sight at 1024 px (the
            # data grid scrolled sideways and hid rows below its fixed height)
            st.table(plots.comparison_styler(df), hide_index=True)
            st.download_button(
                "Comparison table (CSV)",
                data=cache.csv_bytes(rows),
                file_name="comparison.csv",
                mime="text/csv",
                on_click="ignore",
                icon=":material/download:",
                key="dl_comparison",
            )

with tab_perf:
    if tab_perf.open and reports:
        r1 = st.columns(2)
        r1[0].plotly_chart(plots.compare_performance_figure(reports, "blow_by"), key="cmp_blow_by")
        r1[1].plotly_chart(plots.compare_performance_figure(reports, "alpha_eq"), key="cmp_alpha")
        r2 = st.columns(2)
        r2[0].plotly_chart(
            plots.compare_performance_figure(reports, "dynamic_lift"), key="cmp_lift"
        )
        r2[1].plotly_chart(
            plots.compare_performance_figure(reports, "tension_top"), key="cmp_tension"
        )
        st.caption("Crosses mark wind speeds where a case breaks an operating limit.")

with tab_tether:
    if tab_tether.open and reports:
        speeds = sorted({float(v) for r in reports.values() for v in r.tether.wind_speed})
        design_winds = {r.limits.design_wind for r in reports.values()}
        default = next(iter(design_winds)) if len(design_winds) == 1 else max(speeds)
        default = min(speeds, key=lambda v: abs(v - default))
        wind = st.select_slider(
            formats.label("Wind speed", "wind"),  # in the chosen unit system
            options=speeds,
            value=default,
            key="compare_wind",
            format_func=lambda v: formats.shown(v, "wind"),
            help="Each case's profile at the sweep speed nearest this.",
        )
        st.plotly_chart(plots.compare_tether_figure(reports, wind), key="cmp_tether")

with tab_manage:
    if tab_manage.open:
        m1, m2, m3 = st.columns(3)
        with m1:
            st.markdown("**Rename**")
            st.selectbox("Case", names, key="rename_from")
            st.text_input("New name", key="rename_to", max_chars=state.MAX_NAME_CHARS)
            st.button("Rename", on_click=_rename, icon=":material/edit:", key="rename_button")
        with m2:
            st.markdown("**Delete**")
            st.multiselect("Cases to delete", names, key="delete_names")
            st.button("Delete", on_click=_delete, icon=":material/delete:", key="delete_button")
        with m3:
            st.markdown("**Open on the Design page**")
            st.selectbox("Case", names, key="load_name")
            st.button(
                "Make it the current design",
                on_click=_load_into_design,
                icon=":material/open_in_new:",
                key="load_button",
            )
