"""The workspace in the app's frame (called by ``app.py`` on every run): bind the session to
the workspace in the URL, remember it in this browser, offer recent workspaces back on a bare
address, and say what the saved-cases database is doing (unavailable, cases kept in this
session only with a download, written on its return).

The browser keeps the last few workspace tokens in a first-party cookie (:data:`COOKIE`, tokens
only, never sent anywhere but this app); the server reads it through ``st.context.cookies`` and
never lists workspaces from the database.
"""

from __future__ import annotations

import datetime as _dt
from collections.abc import Iterable
from typing import Any

import streamlit as st

from aerostat_core.model.io import cases_to_json
from app_ui import state
from app_ui import store as _store
from app_ui.text import plain

#: Cookie with the browser's recent workspace tokens, newest first, joined by ".".
COOKIE = "aerostat_ws"
#: How many recent workspaces the browser remembers.
RECENT_MAX = 5
#: Session flag: this session started on an address without a workspace (a new, empty one).
FRESH_KEY = "_ws_fresh"


def recent_tokens(raw: str | None, current: str | None = None) -> list[str]:
    """The valid tokens of a cookie value, newest first, without ``current`` and duplicates.

    >>> recent_tokens("a.b", None)
    []
    """
    seen: list[str] = []
    for token in (raw or "").split("."):
        if _store.valid_token(token) and token != current and token not in seen:
            seen.append(token)
    return seen[:RECENT_MAX]


def _remember(token: str, older: Iterable[str]) -> None:
    """Put ``token`` first in the browser's cookie (a script run in the page, no request)."""
    value = ".".join([token, *[t for t in older if t != token]][:RECENT_MAX])
    st.sidebar.html(
        "<script>document.cookie = "
        f'"{COOKIE}={value}; path=/; max-age=31536000; SameSite=Lax";</script>',
        unsafe_allow_javascript=True,
        width="content",
    )


def _open(token: str) -> None:
    st.query_params[state.WS_PARAM] = token
    st.session_state.pop(FRESH_KEY, None)


def _describe(token: str) -> tuple[int, str] | None:
    """(number of cases, first names) of a remembered workspace, or None if it is empty or
    the database cannot say."""
    try:
        snap = _store.get_store().snapshot(token)
    except (_store.StoreUnavailable, ValueError):
        return None
    if not snap.cases and snap.current is None:
        return None
    names = list(snap.cases)
    shown = ", ".join(f"“{n}”" for n in names[:3]) + (" …" if len(names) > 3 else "")
    return len(names), shown


def attach() -> str:
    """Bind the session (``state.attach_workspace``), remember the workspace in the browser and
    offer recent ones back when this address had none. Returns the token."""
    s = st.session_state
    if state.WS_KEY not in s and not _store.valid_token(st.query_params.get(state.WS_PARAM)):
        s[FRESH_KEY] = True
    token = state.attach_workspace()
    try:
        raw = st.context.cookies.get(COOKIE)
    except Exception:  # noqa: BLE001 - no browser context (headless tests)
        raw = None
    recent = recent_tokens(raw, token)
    _remember(token, recent)
    if s.get(FRESH_KEY) and not state.get_cases():
        _offer(recent)
    return token


def _offer(recent: list[str]) -> None:
    found = [(t, d) for t in recent if (d := _describe(t)) is not None]
    if not found:
        return
    box = st.container(border=True)
    box.markdown(
        "**This is a new, empty workspace.** Your recent workspaces in this browser: open one "
        "to continue where you left off."
    )
    for i, (token, (count, names)) in enumerate(found):
        label = f"{count} case(s): {names}" if count else "current inputs, no saved case"
        box.button(
            plain(label if i else f"Last used: {label}"),
            key=f"open_ws_{token}",
            on_click=_open,
            args=(token,),
            icon=":material/history:",
            type="primary" if i == 0 else "secondary",
        )


#: The unsaved cases the app frame showed in its last full run.
SHOWN_UNSAVED_KEY = "_frame_unsaved"


def frame_is_stale() -> bool:
    """Whether the unsaved cases changed since the app frame (banner, download of the unsaved
    cases) was drawn: a fragment's rerun (the Design page's results) does not redraw it."""
    return tuple(state.unsaved_cases()) != st.session_state.get(SHOWN_UNSAVED_KEY, ())


def status() -> None:
    """What happens to the work (sidebar), the database's state and the cases not yet saved,
    with a download (above the page)."""
    s = st.session_state
    st.sidebar.caption(
        "Your inputs and saved cases are kept in this workspace: bookmark or share this page's "
        "address to come back to them. This browser also remembers your recent workspaces."
    )
    note = state.pop_store_note()
    if note:
        st.success(plain(note), icon=":material/database:")
    error = s.get(state.STORE_ERR_KEY)
    unsaved = state.unsaved_cases()
    s[SHOWN_UNSAVED_KEY] = tuple(unsaved)  # what this frame shows (see frame_is_stale)
    if error:
        st.warning(plain(error), icon=":material/database:")
    if unsaved or s.get(state.UNSAVED_CURRENT_KEY):
        names = ", ".join(f"“{n}”" for n in unsaved)
        st.warning(
            plain(
                (
                    f"Not yet saved: {names}. "
                    if unsaved
                    else "Your latest inputs are not yet saved. "
                )
                + "They are kept in this session and written when the database is back."
            ),
            icon=":material/cloud_off:",
        )
        if unsaved:
            stamp = _dt.datetime.now().strftime("%Y%m%d-%H%M")
            st.download_button(
                "Download the unsaved cases (JSON)",
                data=cases_to_json(unsaved),
                file_name=f"aerostat-unsaved-cases-{stamp}.json",
                mime="application/json",
                on_click="ignore",
                icon=":material/download:",
                key="dl_unsaved_cases",
            )


def unsaved_label(name: Any) -> str:
    """A case name as an option label, marked when it is not yet saved."""
    return f"{name} (not yet saved)" if name in state.unsaved_cases() else str(name)
