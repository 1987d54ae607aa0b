"""Saving the current design as a case from the Design page: a taken name asks (replace, keep
both, or another name), a case changed in another tab since this page showed it is never
overwritten silently (keep both, or reload), and a case saved while the database is unavailable
says that it is kept in this session only.

The page calls :func:`save_current` as the "Save case" callback and :func:`choice_panel` where
the feedback goes; every message quotes the user's name through :func:`app_ui.text.plain`.
"""

from __future__ import annotations

from collections.abc import MutableMapping
from typing import Any

import streamlit as st

from aerostat_core.model.io import inputs_from_dict, inputs_to_dict
from app_ui import state
from app_ui.store import CaseConflict
from app_ui.text import plain

#: The pending question after a refused save: {"name", "inputs", "kind", "version"}.
CHOICE_KEY = "_save_choice"
#: Feedback of the last save: (level, text), shown once by the page.
FEEDBACK_KEY = "case_feedback"
NAME_KEY = "case_name"
DEFAULT_NAME_KEY = "_case_name_default"


def _s(s: MutableMapping[str, Any] | None) -> MutableMapping[str, Any]:
    return st.session_state if s is None else s


def _saved(s: MutableMapping[str, Any], used: str) -> None:
    if used in state.unsaved_cases(s):
        s[FEEDBACK_KEY] = (
            "warning",
            f"Kept case “{used}” in this session only: the saved-cases database is "
            "unavailable. It is written as soon as the database is back; until then it can be "
            "downloaded from the sidebar.",
        )
    else:
        s[FEEDBACK_KEY] = (
            "success",
            f"Saved case “{used}”. Compare saved cases on the Compare page.",
        )
    s[NAME_KEY] = ""


def _ask(s: MutableMapping[str, Any], exc: CaseConflict, inputs: dict[str, Any]) -> None:
    s[CHOICE_KEY] = {
        "name": exc.name,
        "inputs": inputs,
        "kind": exc.kind,
        "version": exc.version,
    }


def save_current(s: MutableMapping[str, Any] | None = None) -> None:
    """The "Save case" callback: save the current inputs under the typed (or default) name;
    a taken name leaves a question for :func:`choice_panel` instead of saving."""
    s = _s(s)
    if CHOICE_KEY in s:  # a new save answers an old question
        del s[CHOICE_KEY]
    name = s.get(NAME_KEY, "") or s.get(DEFAULT_NAME_KEY, "")
    req, cfg = state.current_inputs(s)
    try:
        used = state.save_case(name, req, cfg, s, on_taken="ask")
    except CaseConflict as exc:
        _ask(s, exc, inputs_to_dict(req, cfg))
    except ValueError as exc:
        s[FEEDBACK_KEY] = ("error", str(exc))
    else:
        _saved(s, used)


def resolve(action: str, s: MutableMapping[str, Any] | None = None) -> None:
    """Answer the pending question: "replace" (the version the user was told about, never a
    newer one), "keep" (save as "name (2)"), "rename" or "reload" (save nothing)."""
    s = _s(s)
    choice = s.get(CHOICE_KEY)
    if not choice:
        return
    del s[CHOICE_KEY]
    name = choice["name"]
    if action in ("rename", "reload"):
        s[FEEDBACK_KEY] = (
            "info",
            "Nothing was saved: type another name and press Save case."
            if action == "rename"
            else f"Nothing was saved; “{name}” shows what was saved in the other tab.",
        )
        s[NAME_KEY] = name if action == "rename" else ""
        return
    req, cfg = inputs_from_dict(choice["inputs"])
    try:
        if action == "replace":
            used = state.save_case(name, req, cfg, s, on_taken="replace", version=choice["version"])
        else:
            used = state.save_case(name, req, cfg, s, on_taken="suffix")
    except CaseConflict as exc:
        _ask(s, exc, choice["inputs"])
    except ValueError as exc:
        s[FEEDBACK_KEY] = ("error", str(exc))
    else:
        _saved(s, used)
        if action == "replace":
            s[FEEDBACK_KEY] = ("success", f"Replaced case “{used}” with the current design.")


def choice_panel() -> None:
    """The pending question with its buttons (nothing when there is none)."""
    choice = st.session_state.get(CHOICE_KEY)
    if not choice:
        return
    name = choice["name"]
    both = state.unique_name(name, set(state.get_cases()) | {name})
    if choice["kind"] == "taken":
        st.warning(
            plain(
                f"A case named “{name}” exists already (perhaps saved in another tab). "
                f"Replace it with the current design, keep both (yours as “{both}”), or "
                "choose another name."
            ),
            icon=":material/help:",
        )
        actions = (("replace", "Replace it"), ("keep", "Keep both"), ("rename", "Rename"))
    else:
        st.warning(
            plain(
                f"{CaseConflict(choice['kind'], name)}: it was not overwritten. Keep both "
                f"(yours as “{both}”), or reload (keep the saved one, save nothing)."
            ),
            icon=":material/sync_problem:",
        )
        actions = (("keep", "Keep both"), ("reload", "Reload"))
    row = st.container(horizontal=True)
    for action, label in actions:
        row.button(label, key=f"save_choice_{action}", on_click=resolve, args=(action,))
