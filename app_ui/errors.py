"""The app's error boundary: an unexpected error shows a short message with a reference id;
the full traceback goes to the server log under the same id (``client.showErrorDetails`` is
"none" in .streamlit/config.toml, so Streamlit's own handler never shows one either)."""

from __future__ import annotations

import logging
import secrets

import streamlit as st

from aerostat_core.base.validation import short

log = logging.getLogger("aerostat.app")


def reference_id() -> str:
    """A short random id that ties a message on screen to its traceback in the log."""
    return secrets.token_hex(4)


def report_unexpected(exc: BaseException, where: str = "this page") -> str:
    """Log ``exc`` with its traceback under a new reference id and show a short message (no
    traceback, no exception text: it may hold internal names or user data). Returns the id."""
    ref = reference_id()
    log.error("unexpected error on %s [ref %s]", where, ref, exc_info=exc)
    st.error(
        short(
            f"Something went wrong on {where} (reference **{ref}**). Your inputs and saved "
            "cases are kept. Try again, or change the inputs; if it happens again, report the "
            "reference so it can be found in the server log."
        ),
        icon=":material/error:",
    )
    return ref
