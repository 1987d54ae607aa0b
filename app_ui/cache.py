"""Cached wrappers around the engine for the pages (the only place pages get designs from).

The cache key is the frozen inputs themselves: a resolved :class:`~aerostat_core.Requirement`
and a :class:`~aerostat_core.Configuration` (frozen dataclasses, compared field by field), so two
sessions with the same inputs share one computation. The Design form builds them once per
submit and keeps them beside the inputs dict (:func:`set_current`, :func:`current_inputs`): the
page, the cache and the plots read those objects, with no JSON text on the way. Designs,
reports and the case comparison are kept by Streamlit's own ``st.cache_resource`` (shared by
every session, one compute per key while other sessions wait for it, nothing stored when the
compute raises), hashed by the exact ``repr`` of the frozen inputs. The results are shared, not
copied: treat them as read-only. Invalid inputs raise ``ValueError`` (nothing is cached for
them); the pages catch it and show the message.

The study pages (Sensitivity, Optimise, Envelope, Shapes, Dynamics) cache through :func:`memo`:
the key is the frozen inputs plus the study's other parameters as hashable values (tuples,
numbers, names; :func:`freeze` for a plain request dict), never JSON text. That store is this
module's own small LRU, for what ``st.cache_resource`` does not offer: :func:`peek` (is a result
there, without computing: a page draws a progress bar only when there is something to compute),
a size per kind of study, and the keys held (:func:`memo_keys`, which the tests read). A compute
that raises (a rejected request, a cancelled run) stores nothing, a second caller of a key being
computed waits for it, and a hit returns at once without running ``compute``, so a progress bar
drawn by it is never replayed (``st.cache_resource`` replays the elements a cached function
drew).

Inputs that arrive as the canonical JSON text of the session state (:func:`inputs_of`, used by
the Envelope, Shapes and Optimise views) are parsed once per distinct text.

Typical use in a page::

    from app_ui import cache
    req, cfg = cache.current_inputs()        # frozen, built once by the form
    rep = cache.report_of(req, cfg)          # DesignReport for tables and plots
    d = cache.design_of(req, cfg)            # the Design object itself
    env = cache.memo("envelope", cache.frozen_inputs(req, cfg), lambda: operating_envelope(d), 32)
"""

from __future__ import annotations

import functools
import json
import threading
from collections import OrderedDict
from collections.abc import Callable, Hashable, Mapping, MutableMapping
from typing import Any, TypeVar

import streamlit as st

from aerostat_core import Configuration, Design, Requirement
from aerostat_core.model import budget
from aerostat_core.model.io import cases_to_json, inputs_from_dict
from aerostat_core.output.report import DesignReport, cases_csv, comparison_rows, design_report
from aerostat_core.studies.robust import design_with_confidence
from app_ui import formats, state, tables

#: Designs (and reports) kept for every session together.
MAX_DESIGNS = 256

T = TypeVar("T")


class _LRU:
    """A least-recently-used map shared by every session (thread-safe).

    A key being computed has a lock of its own, so a second caller of the same key (another
    session, or this session's next rerun) waits for the first result instead of computing it
    again on the same 2 cores, as ``st.cache_data`` did. When the first compute raises, nothing
    is stored and the waiter computes for itself.
    """

    def __init__(self, size: int) -> None:
        self.size = size
        self._data: OrderedDict = OrderedDict()
        self._lock = threading.Lock()
        self._computing: dict[Hashable, threading.Lock] = {}

    def get(self, key: Hashable, compute: Callable[[], T]) -> T:
        with self._lock:
            if key in self._data:
                self._data.move_to_end(key)
                return self._data[key]
            key_lock = self._computing.setdefault(key, threading.Lock())
        try:
            with key_lock:  # outside the store's lock: other keys and sessions keep going
                with self._lock:
                    if key in self._data:  # computed by the caller we waited for
                        self._data.move_to_end(key)
                        return self._data[key]
                value = compute()
                with self._lock:
                    self._data[key] = value
                    while len(self._data) > self.size:
                        self._data.popitem(last=False)
                return value
        finally:
            with self._lock:
                if self._computing.get(key) is key_lock and not key_lock.locked():
                    del self._computing[key]

    def peek(self, key: Hashable) -> Any:
        """The value held for ``key`` (now the most recently used), or None."""
        with self._lock:
            if key not in self._data:
                return None
            self._data.move_to_end(key)
            return self._data[key]

    def keys(self) -> list:
        """The keys held, least recently used first."""
        with self._lock:
            return list(self._data)


@st.cache_resource(show_spinner=False)
def _stores() -> tuple[dict[str, _LRU], threading.Lock]:
    """Every process-wide LRU by kind ("design", "report", "comparison", a study's name)."""
    return {}, threading.Lock()


def _store(kind: str, size: int = MAX_DESIGNS) -> _LRU:
    """The LRU of ``kind``, made with ``size`` entries on first use."""
    stores, lock = _stores()
    with lock:
        if kind not in stores:
            stores[kind] = _LRU(size)
        return stores[kind]


def memo(kind: str, key: Hashable, compute: Callable[[], T], size: int = MAX_DESIGNS) -> T:
    """``compute()`` once per distinct ``key`` of ``kind``, shared by every session.

    ``key`` holds frozen, hashable values: the frozen inputs (:func:`frozen_inputs`) and the
    request's other parameters as tuples, numbers and names (an unhashable part raises
    ``TypeError``). At most ``size`` results of a kind are kept (the size of its first call). When
    ``compute`` raises, nothing is stored. The result is shared, not copied: treat it as
    read-only.
    """
    return _store(kind, size).get(key, compute)


def peek(kind: str, key: Hashable) -> Any:
    """The result :func:`memo` holds for ``key`` of ``kind``, or None (nothing is computed):
    for a page that draws a progress bar only when there is something to compute."""
    stores, lock = _stores()
    with lock:
        lru = stores.get(kind)
    return lru.peek(key) if lru is not None else None


def memo_keys(kind: str) -> list:
    """The keys :func:`memo` holds for ``kind``, least recently used first ([] for none)."""
    stores, lock = _stores()
    with lock:
        lru = stores.get(kind)
    return lru.keys() if lru is not None else []


def freeze(value: Any) -> Hashable:
    """Plain data (dicts, lists, numbers, strings, None) as nested tuples, hashable and tagged by
    kind, so values that compare equal in Python but mean different requests stay apart
    (``True`` and ``1``, a dict and a list of pairs): a dict becomes ``("dict", sorted (key,
    value) pairs)``, a list or tuple ``("list", items)``, a bool ``("bool", value)``."""
    if isinstance(value, Mapping):
        return ("dict", tuple(sorted((str(k), freeze(v)) for k, v in value.items())))
    if isinstance(value, (list, tuple)):
        return ("list", tuple(freeze(v) for v in value))
    if isinstance(value, bool):
        return ("bool", value)
    hash(value)  # a set or an object without a hash raises TypeError here
    return value


def thaw(frozen: Hashable) -> Any:
    """The plain data of :func:`freeze` (dicts, lists, bools) again: ``thaw(freeze(v)) == v``
    for plain data whose tuples are lists."""
    if isinstance(frozen, tuple) and len(frozen) == 2 and frozen[0] in ("dict", "list", "bool"):
        kind, body = frozen
        if kind == "dict":
            return {k: thaw(v) for k, v in body}
        if kind == "list":
            return [thaw(v) for v in body]
        return body
    return frozen


def frozen_inputs(req: Requirement, cfg: Configuration) -> tuple[Requirement, Configuration]:
    """The cache key of a design: the resolved Requirement (rule-set limits filled in) and the
    Configuration, both frozen and hashed field by field."""
    return req.resolved(), cfg  # the limits as applied (rule-set values filled in)


def _exact(obj: Requirement | Configuration) -> str:
    """The hash key of frozen inputs for ``st.cache_resource``: their ``repr``, which lists every
    field exactly (floats to the last bit, ``True`` apart from ``1``)."""
    return repr(obj)


_HASH_FUNCS = {Requirement: _exact, Configuration: _exact}


@st.cache_resource(max_entries=MAX_DESIGNS, show_spinner=False, hash_funcs=_HASH_FUNCS)
def _design(req: Requirement, cfg: Configuration) -> Design:
    # design(), or the robust sizing when the requirement asks a confidence (issue 22)
    return design_with_confidence(req, cfg)


@st.cache_resource(max_entries=MAX_DESIGNS, show_spinner=False, hash_funcs=_HASH_FUNCS)
def _report(req: Requirement, cfg: Configuration) -> DesignReport:
    return design_report(_design(req, cfg))


def design_of(req: Requirement, cfg: Configuration) -> Design:
    """:func:`aerostat_core.model.design` of the inputs, computed once per distinct inputs."""
    return _design(*frozen_inputs(req, cfg))


def report_of(req: Requirement, cfg: Configuration) -> DesignReport:
    """:func:`aerostat_core.output.report.design_report` of :func:`design_of` the inputs."""
    return _report(*frozen_inputs(req, cfg))


#: Session-state key of the current inputs' frozen form: (the inputs dict it was built from,
#: (resolved Requirement, Configuration)).
FROZEN_KEY = "_design_frozen"


def set_current(
    req: Requirement, cfg: Configuration, session: MutableMapping[str, Any] | None = None
) -> None:
    """Make (req, cfg) the current inputs (:func:`app_ui.state.set_current_inputs`: the dict
    for the workspace store) and keep their frozen form beside that dict, so that
    :func:`current_inputs` returns these objects without building them again."""
    s = st.session_state if session is None else session
    state.set_current_inputs(req, cfg, s)
    s[FROZEN_KEY] = (s[state.DESIGN_KEY], frozen_inputs(req, cfg))


def current_inputs(
    session: MutableMapping[str, Any] | None = None,
) -> tuple[Requirement, Configuration]:
    """The current inputs, frozen and resolved (the cache key of the design). Built from the
    session's inputs dict only when that dict changed by another way than the form (the
    baseline button, a file import, the workspace store), then kept."""
    s = st.session_state if session is None else session
    state.init_state(s)
    held = s.get(FROZEN_KEY)
    current = s[state.DESIGN_KEY]
    if held is not None and held[0] is current:
        return held[1]
    frozen = frozen_inputs(*state.current_inputs(s))
    s[FROZEN_KEY] = (s[state.DESIGN_KEY], frozen)
    return frozen


@functools.lru_cache(maxsize=MAX_DESIGNS)
def given_inputs(inputs_json: str) -> tuple[Requirement, Configuration]:
    """(Requirement as given, Configuration) of canonical inputs JSON, parsed once per text
    (raises ``ValueError``; failures are not cached): the key of a study that resolves the
    requirement under other rule sets itself (the rule-set spread, the HTML report)."""
    req, cfg = inputs_from_dict(json.loads(inputs_json))
    return req, cfg


@functools.lru_cache(maxsize=MAX_DESIGNS)
def inputs_of(inputs_json: str) -> tuple[Requirement, Configuration]:
    """(resolved Requirement, Configuration) of canonical inputs JSON, parsed once per text
    (raises ``ValueError``; failures are not cached)."""
    return frozen_inputs(*given_inputs(inputs_json))


def cached_design(inputs_json: str) -> Design:
    """:func:`design_of` the inputs in ``inputs_json``."""
    return design_of(*inputs_of(inputs_json))


def cached_report(inputs_json: str) -> DesignReport:
    """:func:`report_of` the inputs in ``inputs_json``."""
    return report_of(*inputs_of(inputs_json))


def report_for(inputs: Mapping[str, Any]) -> DesignReport:
    """:func:`report_of` an inputs dict."""
    return report_of(*inputs_from_dict(dict(inputs)))


def case_inputs(cases: Mapping[str, Mapping[str, Any]]) -> dict[str, tuple]:
    """Frozen inputs of every saved case, in order, after the compute budget of them all.
    Raises ``ValueError`` naming the case."""
    budget.check_cases(cases)
    out = {}
    for name, inputs in cases.items():
        try:
            out[name] = frozen_inputs(*inputs_from_dict(dict(inputs)))
        except ValueError as exc:
            raise ValueError(f"case {name!r}: {exc}") from None
    return out


def designs_of(cases: Mapping[str, Mapping[str, Any]]) -> dict[str, Design]:
    """:func:`design_of` every saved case (each computed once, shared with the reports)."""
    return {name: design_of(*key) for name, key in case_inputs(cases).items()}


@st.cache_resource(max_entries=64, show_spinner=False, hash_funcs=_HASH_FUNCS)
def _comparison(keys: tuple[tuple[str, Requirement, Configuration], ...]) -> list[dict]:
    return comparison_rows({name: _design(req, cfg) for name, req, cfg in keys})


def comparison_of(cases: Mapping[str, Mapping[str, Any]]) -> list[dict]:
    """:func:`aerostat_core.output.report.comparison_rows` of ``{name: inputs}``."""
    return _comparison(tuple((n, *k) for n, k in case_inputs(cases).items()))


def cases_csv_of(cases: Mapping[str, Mapping[str, Any]]) -> str:
    """One tidy CSV of every case in ``{name: inputs}`` (the cached designs)."""
    return cases_csv(cases, designs_of(cases))


def cases_key(cases: dict) -> str:
    """Canonical JSON of ``{name: inputs}`` (keeps the case order)."""
    return json.dumps(cases, separators=(",", ":"))


def cached_comparison(cases_json: str) -> list[dict]:
    """:func:`comparison_of` the cases in ``cases_json`` (JSON text)."""
    return comparison_of(json.loads(cases_json))


def cached_cases_csv(cases_json: str) -> str:
    """:func:`cases_csv_of` the cases in ``cases_json`` (JSON text)."""
    return cases_csv_of(json.loads(cases_json))


def csv_bytes(rows: list[dict]) -> bytes:
    """UTF-8 CSV of flat rows for download: the SI columns, a row of units, and in US customary
    units a converted column after each SI one (:func:`app_ui.tables.export_csv`)."""
    return tables.export_csv(rows, formats.system())


def cases_json_bytes(cases: dict) -> bytes:
    """The saved-cases JSON file."""
    return cases_to_json(cases).encode("utf-8")
