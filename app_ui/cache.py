"""Cached wrappers around the engine for the pages (the only place pages get designs from).

The cache key is the canonical JSON text of an inputs dict (:func:`app_ui.state.inputs_key`), so
two sessions with the same inputs share one computation. Invalid inputs raise ``ValueError``
(nothing is cached for them); the pages catch it and show the message.

Typical use in a page::

    from app_ui import cache, state
    rep = cache.cached_report(state.current_inputs_key())    # plain data for tables and plots
    d = cache.cached_design(state.current_inputs_key())      # the Design object itself
"""

from __future__ import annotations

import json

import streamlit as st

from aerostat_core import Design, design
from aerostat_core.io import cases_to_json, inputs_from_dict, rows_to_csv
from aerostat_core.report import case_designs, cases_csv, comparison_rows, design_report

from .state import inputs_key


def _inputs(inputs_json: str):
    req, cfg = inputs_from_dict(json.loads(inputs_json))
    return req.resolved(), cfg  # the limits as applied (rule-set values filled in)


@st.cache_data(max_entries=256, show_spinner=False)
def cached_design(inputs_json: str) -> Design:
    """:func:`aerostat_core.design` of the inputs in ``inputs_json``."""
    return design(*_inputs(inputs_json))


@st.cache_data(max_entries=256, show_spinner=False)
def cached_report(inputs_json: str) -> dict:
    """:func:`aerostat_core.report.design_report` of the inputs in ``inputs_json``."""
    return design_report(cached_design(inputs_json))


def report_for(inputs: dict) -> dict:
    """:func:`cached_report` of an inputs dict."""
    return cached_report(inputs_key(inputs))


@st.cache_data(max_entries=64, show_spinner=False)
def cached_comparison(cases_json: str) -> list[dict]:
    """:func:`aerostat_core.report.comparison_rows` of ``{name: inputs}`` (JSON text)."""
    cases = json.loads(cases_json)
    return comparison_rows(case_designs(cases))


@st.cache_data(max_entries=64, show_spinner=False)
def cached_cases_csv(cases_json: str) -> str:
    """One tidy CSV of every case in ``{name: inputs}`` (JSON text)."""
    return cases_csv(json.loads(cases_json))


def cases_key(cases: dict) -> str:
    """Canonical JSON of ``{name: inputs}`` (keeps the case order)."""
    return json.dumps(cases, separators=(",", ":"))


def csv_bytes(rows: list[dict]) -> bytes:
    """UTF-8 CSV of flat rows (see :func:`aerostat_core.io.rows_to_csv`)."""
    return rows_to_csv(rows).encode("utf-8")


def cases_json_bytes(cases: dict) -> bytes:
    """The saved-cases JSON file."""
    return cases_to_json(cases).encode("utf-8")
