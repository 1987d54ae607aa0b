"""Session state shared by every page: the current inputs and the saved cases.

Contract (other pages rely on it):

* ``st.session_state["design_inputs"]``: the current inputs as an
  :func:`aerostat_core.io.inputs_to_dict` dict (the thesis baseline until the user changes it);
* ``st.session_state["cases"]``: ``{name: inputs dict}``, in the order they were saved.

Every function takes an optional ``state`` mapping (default ``st.session_state``) so that it can be
tested with a plain dict or with ``AppTest.session_state``. Values are replaced, never mutated in
place, so a reader never sees a half-updated dict.
"""

from __future__ import annotations

import json
from collections.abc import MutableMapping
from typing import Any

import streamlit as st

from aerostat_core import Configuration, Requirement, thesis_baseline
from aerostat_core.io import (
    MAX_CASES,
    MAX_JSON_BYTES,
    cases_from_json,
    design_from_json,
    inputs_from_dict,
    inputs_to_dict,
)

DESIGN_KEY = "design_inputs"
CASES_KEY = "cases"
#: Feedback of the last file import: {"level": "success"|"error"|"info", "text": str, "where": str}.
IMPORT_MSG_KEY = "import_feedback"
#: Longest case name [characters].
MAX_NAME_CHARS = 100


def _s(state: MutableMapping[str, Any] | None) -> MutableMapping[str, Any]:
    return st.session_state if state is None else state


def baseline_inputs() -> dict[str, Any]:
    """The thesis baseline as an inputs dict."""
    return inputs_to_dict(*thesis_baseline())


def init_state(state: MutableMapping[str, Any] | None = None) -> None:
    """Create ``design_inputs`` (thesis baseline) and ``cases`` (empty) when missing."""
    s = _s(state)
    if DESIGN_KEY not in s:
        s[DESIGN_KEY] = baseline_inputs()
    if CASES_KEY not in s:
        s[CASES_KEY] = {}


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
    _s(state)[DESIGN_KEY] = inputs_to_dict(req, cfg)


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
    """Return the stripped name or raise ``ValueError`` saying what is wrong with it."""
    if not isinstance(name, str) or not name.strip():
        raise ValueError("Give the case a name.")
    name = name.strip()
    if len(name) > MAX_NAME_CHARS:
        raise ValueError(f"A case name has at most {MAX_NAME_CHARS} characters.")
    return name


def save_case(
    name: str,
    req: Requirement,
    cfg: Configuration,
    state: MutableMapping[str, Any] | None = None,
    *,
    overwrite: bool = True,
) -> str:
    """Save (req, cfg) under ``name`` and return the name used (stripped).

    Saving under an existing name replaces that case (in place, keeping its order) unless
    ``overwrite`` is False, which raises ``ValueError``.
    """
    s = _s(state)
    name = check_case_name(name)
    cases = get_cases(s)
    if name in cases and not overwrite:
        raise ValueError(f"A case named {name!r} exists already.")
    if name not in cases and len(cases) >= MAX_CASES:
        raise ValueError(f"At most {MAX_CASES} cases can be saved; delete some first.")
    cases[name] = inputs_to_dict(req, cfg)
    s[CASES_KEY] = cases
    return name


def add_cases(
    new: dict[str, dict[str, Any]], state: MutableMapping[str, Any] | None = None
) -> list[str]:
    """Add validated cases; a name that exists gets " (2)", " (3)"... Returns the names used."""
    s = _s(state)
    cases = get_cases(s)
    if len(cases) + len(new) > MAX_CASES:
        raise ValueError(
            f"That would make {len(cases) + len(new)} cases; at most {MAX_CASES} can be saved."
        )
    used = []
    for name, inputs in new.items():
        name = check_case_name(name)
        final, i = name, 2
        while final in cases:
            final = f"{name} ({i})"
            i += 1
        cases[final] = inputs
        used.append(final)
    s[CASES_KEY] = cases
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
    return new


def delete_case(name: str, state: MutableMapping[str, Any] | None = None) -> None:
    """Delete a case (no error if it is already gone)."""
    s = _s(state)
    cases = get_cases(s)
    cases.pop(name, None)
    s[CASES_KEY] = cases


def clear_cases(state: MutableMapping[str, Any] | None = None) -> None:
    """Delete every saved case."""
    _s(state)[CASES_KEY] = {}


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
    raw: bytes, state: MutableMapping[str, Any] | None = None, *, filename: str = "the file"
) -> tuple[str, str]:
    """Apply an uploaded JSON file: a design file replaces the current inputs, a cases file adds
    its cases. Returns ``(level, message)`` with level "success" or "error".

    All-or-nothing: a malformed, hostile, oversized or out-of-range file changes nothing and the
    message says why (the engine's messages name the field).
    """
    s = _s(state)
    init_state(s)
    try:
        if len(raw) > MAX_JSON_BYTES:
            raise ValueError(f"the file is {len(raw):,} bytes; the limit is {MAX_JSON_BYTES:,}")
        if _file_kind(raw) == "cases":
            new = cases_from_json(raw)
            names = add_cases(new, s)
            shown = ", ".join(names[:5]) + (" ..." if len(names) > 5 else "")
            return "success", f"Added {len(names)} case(s) from {filename}: {shown}."
        req, cfg = design_from_json(raw)
        set_current_inputs(req, cfg, s)
        return "success", f"Loaded the design inputs from {filename}."
    except ValueError as exc:
        return "error", f"Could not import {filename}: {exc}. Nothing was changed."
    except Exception as exc:  # noqa: BLE001 - a hostile file must never show a traceback
        return "error", (
            f"Could not import {filename}: the file is not a valid design or cases "
            f"file ({type(exc).__name__}). Nothing was changed."
        )


def handle_upload(
    uploaded: Any, where: str, state: MutableMapping[str, Any] | None = None
) -> tuple[str, str]:
    """Read and import an uploaded file; store the feedback under ``import_feedback`` for the
    page ``where`` ("design" or "compare") to show. Returns ``(level, message)``."""
    s = _s(state)
    name = getattr(uploaded, "name", "the file")
    try:
        raw = read_upload(uploaded)
    except ValueError as exc:
        result = ("error", f"Could not import {name}: {exc} Nothing was changed.")
    else:
        result = import_file(raw, s, filename=name)
    s[IMPORT_MSG_KEY] = {"level": result[0], "text": result[1], "where": where}
    return result
