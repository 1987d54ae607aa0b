"""Session state shared by every page: the current inputs and the saved cases.

Contract (other pages rely on it):

* ``st.session_state["design_inputs"]``: the current inputs as an
  :func:`aerostat_core.model.io.inputs_to_dict` dict (the practice default until the user changes it);
* ``st.session_state["cases"]``: ``{name: inputs dict}``, in the order they were saved.

Every function takes an optional ``state`` mapping (default ``st.session_state``) so that it can be
tested with a plain dict or with ``AppTest.session_state``. Values are replaced, never mutated in
place, so a reader never sees a half-updated dict.

Persistence: :func:`attach_workspace` (called by ``app.py`` on every run) binds the session to the
workspace named by the ``ws`` query parameter (a new one when it is missing), loads its cases and
current inputs from :mod:`app_ui.store`, and from then on every change below is written through
to the store. When the store is unavailable the session keeps working in memory and
:data:`STORE_ERR_KEY` holds the message to show; nothing stored is ever deleted because of it.
"""

from __future__ import annotations

import json
from collections.abc import MutableMapping
from typing import Any

import streamlit as st

from aerostat_core import Configuration, Requirement
from aerostat_core.base.validation import InputError, check_name, short
from aerostat_core.model.io import (
    MAX_CASES,
    MAX_JSON_BYTES,
    cases_from_json,
    design_from_json,
    inputs_from_dict,
    inputs_to_dict,
)
from aerostat_core.model.presets import practice_configuration

from . import store as _store

DESIGN_KEY = "design_inputs"
CASES_KEY = "cases"
#: Feedback of the last file import: {"level": "success"|"error"|"info", "text": str, "where": str}.
IMPORT_MSG_KEY = "import_feedback"
#: Longest case name [characters].
MAX_NAME_CHARS = 100
#: The session's workspace token (also the ``ws`` query parameter of the page URL).
WS_KEY = "_workspace"
#: Query parameter that carries the workspace token.
WS_PARAM = "ws"
#: Message of the last store failure (shown by app.py), or absent.
STORE_ERR_KEY = "_store_error"


def _s(state: MutableMapping[str, Any] | None) -> MutableMapping[str, Any]:
    return st.session_state if state is None else state


def baseline_inputs() -> dict[str, Any]:
    """The default inputs: 10 kg at 300 m under the default "practice" rules, hull sized, every
    limit left to the rule set (the same design as ``design(Requirement())`` and the CLI)."""
    return inputs_to_dict(Requirement(), practice_configuration())


def init_state(state: MutableMapping[str, Any] | None = None) -> None:
    """Create ``design_inputs`` (the practice default) and ``cases`` (empty) when missing.

    In a live session not yet bound to a workspace, bind it first: on a freshly started server
    Streamlit can run a page script directly (``/Compare?ws=...``) before ``app.py`` has run."""
    s = _s(state)
    if s is st.session_state and WS_KEY not in s and st.runtime.exists():
        attach_workspace()
        return
    if DESIGN_KEY not in s:
        s[DESIGN_KEY] = baseline_inputs()
    if CASES_KEY not in s:
        s[CASES_KEY] = {}


def _discard(s: MutableMapping[str, Any], key: str) -> None:
    # AppTest's session-state proxy has no .pop()
    if key in s:
        del s[key]


def _persist(s: MutableMapping[str, Any], op: str, *args: Any) -> None:
    """Write one change through to the workspace store (no-op for a session without one)."""
    token = s.get(WS_KEY)
    if not _store.valid_token(token):
        return
    try:
        getattr(_store.get_store(), op)(token, *args)
    except _store.StoreUnavailable as exc:
        s[STORE_ERR_KEY] = str(exc)
    else:
        _discard(s, STORE_ERR_KEY)


def attach_workspace(
    state: MutableMapping[str, Any] | None = None,
    query_params: MutableMapping[str, Any] | None = None,
) -> str:
    """Bind the session to the workspace in the URL (creating one when the URL has none or a
    malformed token) and load its cases and current inputs. Returns the token."""
    s = _s(state)
    qp = st.query_params if query_params is None else query_params
    token = qp.get(WS_PARAM)
    if not _store.valid_token(token):
        token = s.get(WS_KEY) if _store.valid_token(s.get(WS_KEY)) else _store.new_token()
        qp[WS_PARAM] = token
    s[WS_KEY] = token
    init_state(s)  # WS_KEY is set: this only fills in the defaults
    try:
        current, saved = _store.get_store().load(token)
    except _store.StoreUnavailable as exc:
        s[STORE_ERR_KEY] = str(exc)  # keep what the session has; never overwrite the store
        return token
    _discard(s, STORE_ERR_KEY)
    if current is not None and current != s.get(DESIGN_KEY):
        s[DESIGN_KEY] = current
    if saved != s.get(CASES_KEY):
        s[CASES_KEY] = saved
    return token


def current_inputs(
    state: MutableMapping[str, Any] | None = None,
) -> tuple[Requirement, Configuration]:
    """The current (Requirement, Configuration). A corrupt ``design_inputs`` (never written by
    this module) is replaced by the thesis baseline rather than breaking every page."""
    s = _s(state)
    init_state(s)
    try:
        return inputs_from_dict(s[DESIGN_KEY])
    except (ValueError, TypeError):
        s[DESIGN_KEY] = baseline_inputs()
        return inputs_from_dict(s[DESIGN_KEY])


def set_current_inputs(
    req: Requirement, cfg: Configuration, state: MutableMapping[str, Any] | None = None
) -> None:
    """Make (req, cfg) the current inputs (the Design page's form follows on its next run)."""
    s = _s(state)
    s[DESIGN_KEY] = inputs_to_dict(req, cfg)
    _persist(s, "set_current", s[DESIGN_KEY])


def set_current_dict(inputs: dict[str, Any], state: MutableMapping[str, Any] | None = None) -> None:
    """Make a validated inputs dict the current inputs (written through to the store)."""
    s = _s(state)
    s[DESIGN_KEY] = inputs
    _persist(s, "set_current", inputs)


def inputs_key(inputs: dict[str, Any]) -> str:
    """Canonical JSON text of an inputs dict: the cache key of the cached wrappers."""
    return json.dumps(inputs, sort_keys=True, separators=(",", ":"))


def current_inputs_key(state: MutableMapping[str, Any] | None = None) -> str:
    """:func:`inputs_key` of the current inputs."""
    s = _s(state)
    init_state(s)
    return inputs_key(s[DESIGN_KEY])


# --- saved cases ------------------------------------------------------------------------------


def get_cases(state: MutableMapping[str, Any] | None = None) -> dict[str, dict[str, Any]]:
    """Saved cases, name -> inputs dict (a copy of the mapping; the dicts are not copied)."""
    s = _s(state)
    init_state(s)
    return dict(s[CASES_KEY])


def check_case_name(name: Any) -> str:
    """Return the stripped name or raise ``ValueError`` saying what is wrong with it (empty,
    too long, control characters or lone surrogates: see
    :func:`aerostat_core.base.validation.check_name`)."""
    if not isinstance(name, str) or not name.strip():
        raise ValueError("Give the case a name.")
    try:
        return check_name("case", "name", name)
    except InputError as exc:
        raise ValueError(f"Case name: {exc.reason}.") from None


def unique_name(name: str, taken: Any) -> str:
    """``name``, or ``name (2)``, ``name (3)``... whichever is not in ``taken``; the suffixed
    name is shortened so that it stays within :data:`MAX_NAME_CHARS`."""
    final, i = name, 2
    while final in taken:
        suffix = f" ({i})"
        final = name[: MAX_NAME_CHARS - len(suffix)].rstrip() + suffix
        i += 1
    return final


def save_case(
    name: str,
    req: Requirement,
    cfg: Configuration,
    state: MutableMapping[str, Any] | None = None,
    *,
    overwrite: bool = False,
) -> str:
    """Save (req, cfg) under ``name`` and return the name used.

    A name that exists already gets a suffix, " (2)", " (3)"... (so no case is ever replaced by
    accident), unless ``overwrite`` is True, which replaces that case in place.
    """
    s = _s(state)
    name = check_case_name(name)
    cases = get_cases(s)
    if name in cases and not overwrite:
        name = unique_name(name, cases)
    if name not in cases and len(cases) >= MAX_CASES:
        raise ValueError(f"At most {MAX_CASES} cases can be saved; delete some first.")
    cases[name] = inputs_to_dict(req, cfg)
    s[CASES_KEY] = cases
    _persist(s, "put_case", name, cases[name])
    return name


IMPORT_MODES = ("add", "replace")


def add_cases(
    new: dict[str, dict[str, Any]],
    state: MutableMapping[str, Any] | None = None,
    *,
    mode: str = "add",
) -> list[str]:
    """Add validated cases and return the names used.

    ``mode="add"``: a case identical to a saved one (same name, same inputs) is skipped, so that
    re-importing your own export duplicates nothing; another case whose name is taken gets
    " (2)", " (3)"... ``mode="replace"``: the new cases replace every saved case.
    """
    if mode not in IMPORT_MODES:
        raise ValueError(f"import mode {mode!r} is not one of: {', '.join(IMPORT_MODES)}")
    s = _s(state)
    cases = {} if mode == "replace" else get_cases(s)
    fresh = {n: v for n, v in new.items() if cases.get(n) != v}
    if len(cases) + len(fresh) > MAX_CASES:
        raise ValueError(
            f"That would make {len(cases) + len(fresh)} cases; at most {MAX_CASES} can be saved."
        )
    used = []
    for name, inputs in fresh.items():
        final = unique_name(check_case_name(name), cases)
        cases[final] = inputs
        used.append(final)
    s[CASES_KEY] = cases
    _persist(s, "replace_cases", cases)
    return used


def rename_case(old: str, new: str, state: MutableMapping[str, Any] | None = None) -> str:
    """Rename a case, keeping its place in the order. Returns the new (stripped) name."""
    s = _s(state)
    new = check_case_name(new)
    cases = get_cases(s)
    if old not in cases:
        raise ValueError(f"There is no case named {old!r}.")
    if new == old:
        return new
    if new in cases:
        raise ValueError(f"A case named {new!r} exists already.")
    s[CASES_KEY] = {(new if k == old else k): v for k, v in cases.items()}
    _persist(s, "rename_case", old, new)
    return new


def delete_case(name: str, state: MutableMapping[str, Any] | None = None) -> None:
    """Delete a case (no error if it is already gone)."""
    s = _s(state)
    cases = get_cases(s)
    cases.pop(name, None)
    s[CASES_KEY] = cases
    _persist(s, "delete_case", name)


def clear_cases(state: MutableMapping[str, Any] | None = None) -> None:
    """Delete every saved case."""
    s = _s(state)
    s[CASES_KEY] = {}
    _persist(s, "replace_cases", {})


# --- file import ------------------------------------------------------------------------------


def read_upload(uploaded: Any) -> bytes:
    """Bytes of an uploaded file (Streamlit ``UploadedFile`` or bytes), refusing oversized files
    before reading them."""
    if uploaded is None:
        raise ValueError("No file was uploaded.")
    if isinstance(uploaded, (bytes, bytearray)):
        raw = bytes(uploaded)
    else:
        size = getattr(uploaded, "size", None)
        if isinstance(size, int) and size > MAX_JSON_BYTES:
            raise ValueError(f"The file is {size:,} bytes; the limit is {MAX_JSON_BYTES:,} bytes.")
        raw = uploaded.getvalue()
    if len(raw) > MAX_JSON_BYTES:
        raise ValueError(f"The file is {len(raw):,} bytes; the limit is {MAX_JSON_BYTES:,} bytes.")
    return raw


def _file_kind(raw: bytes) -> str:
    """'cases' when the text mentions the cases format, else 'design' (parsers check properly)."""
    return "cases" if b'"aerostat-cases"' in raw else "design"


def import_file(
    raw: bytes,
    state: MutableMapping[str, Any] | None = None,
    *,
    filename: str = "the file",
    mode: str = "add",
) -> tuple[str, str]:
    """Apply an uploaded JSON file: a design file replaces the current inputs, a cases file adds
    its cases (``mode="add"``) or replaces every saved case (``mode="replace"``). Returns
    ``(level, message)`` with level "success", "info" or "error".

    All-or-nothing: a malformed, hostile, oversized or out-of-range file changes nothing and the
    message says why (the engine's messages name the field), capped in length.
    """
    s = _s(state)
    init_state(s)
    filename = display_name(filename)
    try:
        if len(raw) > MAX_JSON_BYTES:
            raise ValueError(f"the file is {len(raw):,} bytes; the limit is {MAX_JSON_BYTES:,}")
        if _file_kind(raw) == "cases":
            new = cases_from_json(raw)
            names = add_cases(new, s, mode=mode)
            if not names:
                return "info", f"Every case in {filename} is saved already; nothing was added."
            shown = ", ".join(names[:5]) + (" ..." if len(names) > 5 else "")
            verb = "Replaced the saved cases with" if mode == "replace" else "Added"
            return "success", short(f"{verb} {len(names)} case(s) from {filename}: {shown}.")
        req, cfg = design_from_json(raw)
        set_current_inputs(req, cfg, s)
        return "success", f"Loaded the design inputs from {filename}."
    except ValueError as exc:
        return "error", short(f"Could not import {filename}: {exc}. Nothing was changed.")
    except Exception as exc:  # noqa: BLE001 - a hostile file must never show a traceback
        return "error", (
            f"Could not import {filename}: the file is not a valid design or cases "
            f"file ({type(exc).__name__}). Nothing was changed."
        )


def display_name(name: Any, limit: int = 80) -> str:
    """A file or case name safe to show in a message: control characters and lone surrogates
    replaced, shortened to ``limit`` characters."""
    text = str(name)
    text = "".join(
        "\ufffd" if (ord(ch) < 32 or 0x7F <= ord(ch) < 0xA0 or 0xD800 <= ord(ch) <= 0xDFFF) else ch
        for ch in text
    )
    return text if len(text) <= limit else text[: limit - 1] + "…"


def handle_upload(
    uploaded: Any,
    where: str,
    state: MutableMapping[str, Any] | None = None,
    *,
    mode: str = "add",
) -> tuple[str, str]:
    """Read and import an uploaded file; store the feedback under ``import_feedback`` for the
    page ``where`` ("design" or "compare") to show once. Returns ``(level, message)``.

    The message names this file (``uploaded.name``); the page shows it on the next run only, so
    a file the browser refuses (too large) never leaves an older file's message in sight."""
    s = _s(state)
    name = display_name(getattr(uploaded, "name", "the file"))
    try:
        raw = read_upload(uploaded)
    except ValueError as exc:
        result = ("error", short(f"Could not import {name}: {exc} Nothing was changed."))
    else:
        result = import_file(raw, s, filename=name, mode=mode)
    s[IMPORT_MSG_KEY] = {"level": result[0], "text": result[1], "where": where}
    return result


def pop_import_feedback(
    where: str, state: MutableMapping[str, Any] | None = None
) -> dict[str, str] | None:
    """The import feedback for page ``where``, removed so that it is shown once."""
    s = _s(state)
    fb = s.get(IMPORT_MSG_KEY)
    if fb and fb.get("where") == where:
        _discard(s, IMPORT_MSG_KEY)
        return fb
    return None
