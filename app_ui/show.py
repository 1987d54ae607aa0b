"""Small Streamlit display helpers shared by the pages: messages as plain text and a wrapping
row of headline numbers."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import streamlit as st
from streamlit.runtime.scriptrunner import get_script_run_ctx

from aerostat_core.base.fields import UNIT_SYSTEM_LABELS, UNIT_SYSTEMS

from . import formats
from .headline import Item, headline_html
from .text import plain

#: Session key of the unit system chosen in the sidebar ("SI" or "US").
UNIT_KEY = "unit_system"


def headlines(items: Sequence[Item]) -> None:
    """A page's headline numbers as one element (:func:`app_ui.headline.headline_html`): a
    wrapping row whose numbers keep their width, so a narrow window moves a number to the next
    line instead of cutting it."""
    st.html(headline_html(items))


def feedback(level: str, text: str) -> None:
    """Show a message (level "success", "info", "warning" or anything else for an error) as
    plain text (see :func:`~app_ui.text.plain`)."""
    show = {"success": st.success, "info": st.info, "warning": st.warning}.get(level, st.error)
    show(plain(text))


#: The session's unit choice, kept apart from the widget's own state: Streamlit drops the state
#: of a widget drawn by app.py on a rerun (the switch's widget state did not survive the rerun
#: its own click starts), so the choice is copied here by the widget's callback.
CHOICE_KEY = "_unit_choice"


def chosen_system(state: Any = None) -> str:
    """The session's unit system ("SI" or "US"), read from the session state: callbacks (the
    Design form's submit) run before ``app.py`` applies the choice to the run, so they read it
    here instead of :func:`app_ui.formats.system`."""
    s = st.session_state if state is None else state
    chosen = s.get(CHOICE_KEY) or "SI"
    return chosen if chosen in UNIT_SYSTEMS else "SI"


def _session_choice() -> str | None:
    """The session's unit system while a script of a session runs, else ``None``."""
    if get_script_run_ctx(suppress_warning=True) is None:
        return None
    return chosen_system()


formats.read_choice_with(_session_choice)


def _keep_choice() -> None:
    st.session_state[CHOICE_KEY] = st.session_state.get(UNIT_KEY) or "SI"


def unit_switch() -> None:
    """The unit-system switch (SI / US customary), once for the whole app (``app.py`` draws it in
    the sidebar before running the page), and the choice applied to this script run
    (:func:`app_ui.formats.use_system`): every page's inputs, results and plots and the design
    report follow it; exports stay SI, with the chosen units offered beside them."""
    chosen = st.session_state.get(CHOICE_KEY, "SI")
    st.radio(
        "Units",
        UNIT_SYSTEMS,
        index=UNIT_SYSTEMS.index(chosen) if chosen in UNIT_SYSTEMS else 0,
        format_func=UNIT_SYSTEM_LABELS.get,
        key=UNIT_KEY,
        on_change=_keep_choice,
        horizontal=True,
        help="SI (m, kg, N, m/s, °C) or US customary (ft, lb, lbf, kt, ft³, °F): the units of "
        "every page's inputs, results and plots and of the design report (you type 1000 ft, "
        "22 lb, 30 kt). The program computes in SI; every export (CSV, JSON) keeps SI with a "
        "unit row, and a CSV of the Design page adds the chosen units.",
    )
    apply_unit_choice()


def apply_unit_choice() -> None:
    """Apply the session's unit choice to this run: app.py does it for a full run, and every
    fragment does it again, because a fragment's rerun does not run app.py (the choice lives in
    a context variable of the script run)."""
    formats.use_system(chosen_system())
