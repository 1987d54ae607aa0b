"""Rendering of the design-input form (Streamlit): grouped, labelled widgets with units, one
submit per change set. What the form shows and how its values convert is
:mod:`app_ui.form_model`; labels, units and help come from the core's field registry.

Call :func:`sync_widgets` before the form renders (or from a callback), then :func:`input_form`.
"""

from __future__ import annotations

import copy
from collections.abc import MutableMapping
from typing import Any

import streamlit as st

from aerostat_core import FABRICS, TETHERS
from app_ui import cache, show

from .form_model import (
    CHOICES,
    CUSTOM,
    ERROR_KEY,
    FIELD_BY_KEY,
    FIN_FABRIC_KEY,
    GROUPS,
    HULL_FABRIC_KEY,
    LAYOUT,
    OPEN_GROUPS,
    SRC_KEY,
    SUBMIT_KEY,
    TETHER_KEY,
    VOLUME_MODE_KEY,
    VOLUME_MODES,
    WIDGET_KEYS,
    Field,
    InputError,
    build_inputs,
    group_key,
    texts_in_system,
    widget_values,
)
from .state import DESIGN_KEY, init_state
from .text import plain

#: The unit system the number boxes' texts are in (the sidebar's choice when they were filled).
UNITS_SRC_KEY = "_widgets_units"


def sync_widgets(state: MutableMapping[str, Any] | None = None, *, force: bool = False) -> None:
    """Fill the form's widgets from the current inputs when those changed elsewhere (baseline
    button, file import, another page) or when a widget value is missing, in the session's unit
    system; after a switch of the unit system, show the boxes' texts in the new units (an edit
    not applied yet is kept, converted). Call before the form renders, or from a callback."""
    s = st.session_state if state is None else state
    init_state(s)
    for group in GROUPS:
        if group_key(group) not in s:
            s[group_key(group)] = group in OPEN_GROUPS
    inputs = s[DESIGN_KEY]
    system = show.chosen_system(s)
    missing = any(k not in s for k in WIDGET_KEYS)
    if force or missing or s.get(SRC_KEY) != inputs:
        previous = {k: s[k] for k in WIDGET_KEYS if k in s}
        for k, v in widget_values(inputs, previous, system).items():
            s[k] = v
        s[SRC_KEY] = copy.deepcopy(inputs)
    elif s.get(UNITS_SRC_KEY, "SI") != system:
        values = {k: s[k] for k in WIDGET_KEYS if k in s}
        for k, v in texts_in_system(values, inputs, s.get(UNITS_SRC_KEY, "SI"), system).items():
            s[k] = v
    s[UNITS_SRC_KEY] = system


def _on_submit() -> None:
    s = st.session_state
    values = {k: s[k] for k in WIDGET_KEYS if k in s}
    try:
        # the boxes' texts are in the units they were filled in (sync_widgets keeps them so)
        req, cfg = build_inputs(values, s[DESIGN_KEY], s.get(UNITS_SRC_KEY, "SI"))
    except InputError as exc:
        s[ERROR_KEY] = {"group": exc.group, "text": str(exc), "key": exc.key}
        if exc.group in GROUPS:
            s[group_key(exc.group)] = True  # the box with the problem in sight
        return
    s.pop(ERROR_KEY, None)
    # The frozen inputs are built here, once; the page, the cache and the plots read these
    # objects (the dict beside them is for the workspace store and the widgets).
    cache.set_current(req, cfg, s)
    sync_widgets(s, force=True)  # show the canonical values (catalogue materials, rounding)


def _group_error(group: str) -> None:
    err = st.session_state.get(ERROR_KEY)
    if err and err.get("group") == group:
        st.error(plain(f"Not applied: {err['text']}"), icon=":material/error:")


def _number(f: Field, system: str) -> None:
    # A text box, parsed by parse_number: the browser's number box read "12,5" as 125 and showed
    # an emptied box as 0. Label, unit and valid range in the session's unit system.
    st.text_input(
        f.label_in(system),
        key=f.key,
        help=f.help_in(system),
        placeholder="auto" if f.optional else "required",
        persist_state="session",
    )


def _choice(key: str, horizontal: bool = False) -> None:
    c = CHOICES[key]
    options = dict(c.options)
    if len(options) <= 3 and horizontal:
        st.radio(
            c.label,
            list(options),
            format_func=options.get,
            key=key,
            help=c.help,
            horizontal=True,
            persist_state="session",
        )
    else:
        st.selectbox(
            c.label,
            list(options),
            format_func=options.get,
            key=key,
            help=c.help,
            persist_state="session",
        )


_GROUP_ICONS = {
    "requirement": ":material/flag:",
    "wind": ":material/air:",
    "configuration": ":material/tune:",
    "gas": ":material/bubble_chart:",
    "materials": ":material/layers:",
    "advanced": ":material/science:",
}


def _widget(key: str, system: str = "SI") -> None:
    if key in FIELD_BY_KEY:
        _number(FIELD_BY_KEY[key], system)
    elif key in CHOICES:
        _choice(key)
    elif key == VOLUME_MODE_KEY:
        st.radio(
            "Hull volume",
            list(VOLUME_MODES),
            format_func=VOLUME_MODES.get,
            key=VOLUME_MODE_KEY,
            persist_state="session",
            help="Given: use the volume below. Sized: the smallest hull that meets the "
            "blow-by limit at the design wind with positive free lift.",
        )
    elif key in (HULL_FABRIC_KEY, FIN_FABRIC_KEY):
        what = "Hull" if key == HULL_FABRIC_KEY else "Fin"
        st.selectbox(
            f"{what} fabric",
            [*FABRICS, CUSTOM],
            key=key,
            persist_state="session",
            help="Catalogue fabric (areal density in the name), or 'Custom' to use "
            "the value below.",
        )
    elif key == TETHER_KEY:
        st.selectbox(
            "Tether",
            [*TETHERS, CUSTOM],
            key=TETHER_KEY,
            persist_state="session",
            help="Catalogue tether, or 'Custom' to use the values below.",
        )


def _submit_button(key: str) -> None:
    st.form_submit_button(
        "Update design",
        type="primary",
        on_click=_on_submit,
        key=key,
        icon=":material/refresh:",
        width="stretch",
    )


def input_form() -> None:
    """The grouped design-input form (one rerun per submit); an input the engine rejects is
    reported inside its group and nothing is applied. The submit button comes first, so it is
    in sight without scrolling, and again after the last group."""
    sync_widgets()
    system = st.session_state.get(UNITS_SRC_KEY, "SI")  # the units the boxes' texts are in
    err = st.session_state.get(ERROR_KEY)
    # Enter in a box applies the form, as "Update design" does (issue 20: it did nothing)
    with st.form("design_inputs_form", border=False, enter_to_submit=True):
        _submit_button(SUBMIT_KEY)
        with st.container():  # always present: the groups below keep their place
            if err and err.get("group") == "general":
                st.error(plain(f"Not applied: {err['text']}"), icon=":material/error:")
            elif err:
                st.warning(
                    plain(f"Inputs not applied: see {GROUPS.get(err['group'], '')} below."),
                    icon=":material/warning:",
                )
        for group, keys in LAYOUT.items():
            # Lazy: a closed group's widgets are not drawn (they keep their values, and
            # opening it reruns the page): the closed groups hold 34 of the 59 widgets, which
            # made up most of the page's elements and of a rerun's script time.
            box = st.expander(
                GROUPS[group], key=group_key(group), on_change="rerun", icon=_GROUP_ICONS[group]
            )
            if not box.open:
                continue
            with box:
                with st.container():
                    _group_error(group)
                if group == "advanced":
                    st.caption("Model coefficients with documented defaults (Method page).")
                if group == "materials":
                    st.caption("The custom values are used when 'Custom' is chosen above them.")
                for key in keys:
                    _widget(key, system)
        _submit_button(SUBMIT_KEY + "_bottom")
