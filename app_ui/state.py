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
#: {name: version} of the stored cases as this session last read them.
VERSIONS_KEY = "_case_versions"
#: {name: inputs} of the cases saved while the store was unavailable (not yet written).
UNSAVED_KEY = "_unsaved_cases"
#: True while the current inputs changed during an outage are not yet written.
UNSAVED_CURRENT_KEY = "_unsaved_current"
#: A one-off note about the store (shown by app.py).
STORE_NOTE_KEY = "_store_note"


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


def _token(s: MutableMapping[str, Any]) -> str | None:
    token = s.get(WS_KEY)
    return token if _store.valid_token(token) else None


def _call(s: MutableMapping[str, Any], op: str, *args: Any, **kwargs: Any) -> Any:
    """One store call for the session's workspace. A failure is remembered in
    :data:`STORE_ERR_KEY` and re-raised as :class:`~app_ui.store.StoreUnavailable`; a success
    clears it. :class:`~app_ui.store.CaseConflict` passes through (nothing was changed)."""
    try:
        result = getattr(_store.get_store(), op)(s[WS_KEY], *args, **kwargs)
    except _store.StoreUnavailable as exc:
        s[STORE_ERR_KEY] = str(exc)
        raise
    _discard(s, STORE_ERR_KEY)
    return result


def _show(s: MutableMapping[str, Any], snap: _store.Snapshot) -> None:
    """Make a snapshot of the store what the session shows: its cases in saved order, then the
    cases not yet written (kept from an outage), and remember the versions seen."""
    unsaved = dict(s.get(UNSAVED_KEY) or {})
    cases = dict(snap.cases)
    for name, inputs in unsaved.items():
        cases.setdefault(name, inputs)
    if cases != s.get(CASES_KEY):
        s[CASES_KEY] = cases
    s[VERSIONS_KEY] = dict(snap.versions)


def _refresh(s: MutableMapping[str, Any]) -> None:
    """Re-read the workspace after a write (other tabs' changes come along)."""
    try:
        _show(s, _call(s, "snapshot"))
    except _store.StoreUnavailable:
        pass


def _persist(s: MutableMapping[str, Any], op: str, *args: Any) -> None:
    """Write the current inputs through to the workspace store (no-op for a session without
    one); while the store is unavailable they are marked unsaved and written on its return."""
    if _token(s) is None:
        return
    try:
        _call(s, op, *args)
    except _store.StoreUnavailable:
        s[UNSAVED_CURRENT_KEY] = True
    else:
        _discard(s, UNSAVED_CURRENT_KEY)


def _flush(s: MutableMapping[str, Any]) -> None:
    """Write what an outage left unsaved: the current inputs, and the unsaved cases added
    after the saved ones (identical ones skipped, a name another tab took since kept apart as
    "name (2)", both kept). Raises StoreUnavailable if the store fails again."""
    if s.get(UNSAVED_CURRENT_KEY):
        _call(s, "set_current", s[DESIGN_KEY])
        _discard(s, UNSAVED_CURRENT_KEY)
    unsaved = dict(s.get(UNSAVED_KEY) or {})
    if not unsaved:
        return
    used = _call(s, "add_cases", unsaved, limit=MAX_NAME_CHARS)
    _discard(s, UNSAVED_KEY)
    renamed = (
        [f"“{old}” as “{new}”" for old, new in zip(unsaved, used) if old != new]
        if len(used) == len(unsaved)
        else []
    )
    note = f"The database is back: wrote {len(unsaved)} case(s) saved while it was unavailable."
    if renamed:
        note += " Another tab had taken a name, so both are kept: saved " + ", ".join(renamed)
        note += "."
    s[STORE_NOTE_KEY] = note


def attach_workspace(
    state: MutableMapping[str, Any] | None = None,
    query_params: MutableMapping[str, Any] | None = None,
) -> str:
    """Bind the session to the workspace in the URL (creating one when the URL has none or a
    malformed token) and load its cases and current inputs. Returns the token.

    What an outage left unsaved is written first (never dropped, never overwriting what
    another tab saved meanwhile); while the store stays unavailable the session keeps what it
    has and :data:`STORE_ERR_KEY` says so."""
    s = _s(state)
    qp = st.query_params if query_params is None else query_params
    token = qp.get(WS_PARAM)
    if not _store.valid_token(token):
        token = s.get(WS_KEY) if _store.valid_token(s.get(WS_KEY)) else _store.new_token()
        qp[WS_PARAM] = token
    if s.get(WS_KEY) not in (None, token):  # another workspace: nothing of the old one carries
        for key in (UNSAVED_KEY, UNSAVED_CURRENT_KEY, VERSIONS_KEY):
            _discard(s, key)
    s[WS_KEY] = token
    init_state(s)  # WS_KEY is set: this only fills in the defaults
    try:
        _flush(s)
        snap = _call(s, "snapshot")
    except _store.StoreUnavailable:
        return token  # keep what the session has; never overwrite the store
    if snap.current is not None and snap.current != s.get(DESIGN_KEY):
        s[DESIGN_KEY] = snap.current
    _show(s, snap)
    return token


def unsaved_cases(state: MutableMapping[str, Any] | None = None) -> dict[str, dict[str, Any]]:
    """Cases kept in this session only (saved while the store was unavailable)."""
    return dict(_s(state).get(UNSAVED_KEY) or {})


def case_versions(state: MutableMapping[str, Any] | None = None) -> dict[str, int]:
    """``{name: version}`` of the stored cases as this session last saw them."""
    return dict(_s(state).get(VERSIONS_KEY) or {})


def pop_store_note(state: MutableMapping[str, Any] | None = None) -> str | None:
    """A one-off note about the store (e.g. unsaved cases written on its return), removed."""
    s = _s(state)
    note = s.get(STORE_NOTE_KEY)
    _discard(s, STORE_NOTE_KEY)
    return note


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
    return _store.unique_name(name, taken, MAX_NAME_CHARS)


#: What :func:`save_case` does with a name that is taken: number the new case ("suffix"), refuse
#: with :class:`~app_ui.store.CaseConflict` so that the page can ask ("ask"), or replace it.
ON_TAKEN = ("suffix", "ask", "replace")


def _unavailable(exc: _store.StoreUnavailable, what: str) -> ValueError:
    return ValueError(f"{exc} Nothing was {what}; try again when it is back.")


def save_case(
    name: str,
    req: Requirement,
    cfg: Configuration,
    state: MutableMapping[str, Any] | None = None,
    *,
    overwrite: bool = False,
    on_taken: str = "suffix",
    version: int | None = None,
) -> str:
    """Save (req, cfg) under ``name`` and return the name used.

    A name that exists already (in this session or, saved by another tab, in the store) gets a
    suffix, " (2)", " (3)"... with ``on_taken="suffix"`` (so no case is ever replaced by
    accident); ``on_taken="ask"`` raises :class:`~app_ui.store.CaseConflict` ("taken") instead;
    ``on_taken="replace"`` (or ``overwrite=True``) replaces that case in place, but only the
    version this session saw (or ``version``, the one the user agreed to replace): a case
    changed in another tab since raises CaseConflict ("changed") and stays as it is.

    While the store is unavailable the case is kept in the session, marked unsaved
    (:func:`unsaved_cases`), and written when the store is back."""
    if on_taken not in ON_TAKEN:
        raise ValueError(f"on_taken {on_taken!r} is not one of: {', '.join(ON_TAKEN)}")
    if overwrite:
        on_taken = "replace"
    s = _s(state)
    name = check_case_name(name)
    cases = get_cases(s)
    if name in cases and on_taken == "suffix":
        name = unique_name(name, cases)
    if name in cases and on_taken == "ask":
        raise _store.CaseConflict("taken", name, case_versions(s).get(name))
    if name not in cases and len(cases) >= MAX_CASES:
        raise ValueError(f"At most {MAX_CASES} cases can be saved; delete some first.")
    inputs = inputs_to_dict(req, cfg)
    unsaved = unsaved_cases(s)
    if _token(s) is not None and name not in unsaved:
        if on_taken == "replace":
            expect = version if version is not None else case_versions(s).get(name, 0)
        else:
            expect = 0
        taken = set(cases)
        for _ in range(MAX_CASES + 1):
            try:
                written = _call(s, "put_case", name, inputs, expect=expect)
                s[CASES_KEY] = {**get_cases(s), name: inputs}
                s[VERSIONS_KEY] = {**case_versions(s), name: written}
                break
            except _store.CaseConflict as exc:
                if exc.kind == "taken" and on_taken == "suffix":
                    taken.add(name)  # another tab took it since this page loaded
                    name = unique_name(name, taken)
                elif exc.kind == "gone" and on_taken == "replace":
                    expect = 0  # deleted elsewhere: saving it again is what was asked
                else:
                    raise
            except _store.StoreUnavailable:
                unsaved[name] = inputs
                s[UNSAVED_KEY] = unsaved
                break
        else:  # pragma: no cover - every name up to the case limit taken meanwhile
            raise ValueError("Could not find a free name for the case; choose another.")
        if name not in unsaved:
            _refresh(s)
            return name
    elif name in unsaved:
        unsaved[name] = inputs
        s[UNSAVED_KEY] = unsaved
    cases = get_cases(s)
    cases[name] = inputs
    s[CASES_KEY] = cases
    return name


IMPORT_MODES = ("add", "replace")


def add_cases(
    new: dict[str, dict[str, Any]],
    state: MutableMapping[str, Any] | None = None,
    *,
    mode: str = "add",
    seen: dict[str, int] | None = None,
) -> list[str]:
    """Add validated cases and return the names used.

    ``mode="add"``: the cases are added after the saved ones, which stay untouched (also those
    another tab saved since this page loaded); a case identical to a saved one (same name, same
    inputs) is skipped, so that re-importing your own export duplicates nothing; another case
    whose name is taken gets " (2)", " (3)"...

    ``mode="replace"``: the new cases replace the saved cases the user saw: ``seen``
    ``{name: version}`` (default: every case this session shows). A case another tab saved or
    changed since stays (the new one with its name is numbered). Refused while the store is
    unavailable (nothing removed)."""
    if mode not in IMPORT_MODES:
        raise ValueError(f"import mode {mode!r} is not one of: {', '.join(IMPORT_MODES)}")
    s = _s(state)
    checked = {check_case_name(n): v for n, v in new.items()}
    if _token(s) is not None:
        try:
            if mode == "replace":
                seen = case_versions(s) if seen is None else seen
                used = _call(
                    s,
                    "replace_cases",
                    checked,
                    seen=seen,
                    limit=MAX_NAME_CHARS,
                    max_cases=MAX_CASES,
                )
            else:
                used = _call(s, "add_cases", checked, limit=MAX_NAME_CHARS, max_cases=MAX_CASES)
        except _store.StoreUnavailable as exc:
            if mode == "replace":
                raise _unavailable(exc, "replaced") from None
        else:
            _refresh(s)
            return list(used)
    cases = {} if mode == "replace" else get_cases(s)
    fresh = {n: v for n, v in checked.items() if cases.get(n) != v}
    if len(cases) + len(fresh) > MAX_CASES:
        raise ValueError(
            f"That would make {len(cases) + len(fresh)} cases; at most {MAX_CASES} can be saved."
        )
    used = []
    unsaved = unsaved_cases(s)
    for name, inputs in fresh.items():
        final = unique_name(name, cases)
        cases[final] = inputs
        used.append(final)
        if _token(s) is not None:
            unsaved[final] = inputs  # the store is unavailable: written on its return
    s[CASES_KEY] = cases
    if unsaved:
        s[UNSAVED_KEY] = unsaved
    return used


def rename_case(old: str, new: str, state: MutableMapping[str, Any] | None = None) -> str:
    """Rename a case, keeping its place in the order. Returns the new (stripped) name.

    Refused (``ValueError``, nothing changed) when the new name is taken, here or by another
    tab, when the case was changed or deleted in another tab since this page showed it
    (:class:`~app_ui.store.CaseConflict`), or while the store is unavailable."""
    s = _s(state)
    new = check_case_name(new)
    cases = get_cases(s)
    if old not in cases:
        raise ValueError(f"There is no case named {old!r}.")
    if new == old:
        return new
    if new in cases:
        raise ValueError(f"A case named {new!r} exists already.")
    unsaved = unsaved_cases(s)
    if _token(s) is not None and old not in unsaved:
        try:
            written = _call(s, "rename_case", old, new, expect=case_versions(s).get(old))
        except _store.StoreUnavailable as exc:
            raise _unavailable(exc, "renamed") from None
        s[CASES_KEY] = {(new if k == old else k): v for k, v in cases.items()}
        s[VERSIONS_KEY] = {**{k: v for k, v in case_versions(s).items() if k != old}, new: written}
        _refresh(s)
        return new
    if old in unsaved:
        s[UNSAVED_KEY] = {(new if k == old else k): v for k, v in unsaved.items()}
    s[CASES_KEY] = {(new if k == old else k): v for k, v in cases.items()}
    return new


def delete_case(name: str, state: MutableMapping[str, Any] | None = None) -> None:
    """Delete a case (no error if it is already gone). A case changed in another tab since
    this page showed it is not deleted (:class:`~app_ui.store.CaseConflict`); nor is a stored
    case while the store is unavailable (``ValueError``)."""
    s = _s(state)
    unsaved = unsaved_cases(s)
    if _token(s) is not None and name not in unsaved:
        try:
            _call(s, "delete_case", name, expect=case_versions(s).get(name))
        except _store.StoreUnavailable as exc:
            raise _unavailable(exc, "deleted") from None
        s[VERSIONS_KEY] = {k: v for k, v in case_versions(s).items() if k != name}
        s[CASES_KEY] = {k: v for k, v in get_cases(s).items() if k != name}
        _refresh(s)
        return
    if name in unsaved:
        del unsaved[name]
        s[UNSAVED_KEY] = unsaved
    cases = get_cases(s)
    cases.pop(name, None)
    s[CASES_KEY] = cases


def clear_cases(state: MutableMapping[str, Any] | None = None) -> None:
    """Delete every saved case this session shows (a case another tab saved since stays)."""
    s = _s(state)
    if _token(s) is not None:
        try:
            _call(s, "replace_cases", {}, seen=case_versions(s))
        except _store.StoreUnavailable as exc:
            raise _unavailable(exc, "deleted") from None
        _discard(s, UNSAVED_KEY)
        _refresh(s)
        return
    s[CASES_KEY] = {}


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


def file_kind(raw: bytes) -> str:
    """'cases' when the text mentions the cases format, else 'design' (parsers check properly)."""
    return "cases" if b'"aerostat-cases"' in raw else "design"


def import_file(
    raw: bytes,
    state: MutableMapping[str, Any] | None = None,
    *,
    filename: str = "the file",
    mode: str = "add",
    seen: dict[str, int] | None = None,
) -> tuple[str, str]:
    """Apply an uploaded JSON file: a design file replaces the current inputs, a cases file adds
        its cases (``mode="add"``) or replaces the saved cases the user saw (``mode="replace"``,
    ``seen`` as in :func:`add_cases`). Returns
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
        if file_kind(raw) == "cases":
            new = cases_from_json(raw)
            names = add_cases(new, s, mode=mode, seen=seen)
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
