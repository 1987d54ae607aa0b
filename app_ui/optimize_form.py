"""Form model of the Sensitivity and Optimise pages: the design variables in their display units,
the bound boxes (text boxes read like the Design form's: a decimal comma is a decimal point),
the engine's bounds check worded in the unit of the boxes, and the optimisation request.

The fin position is a percentage of the hull length on every page (the Design form's unit); the
engine keeps the fraction. Conversion happens here, in both directions, so every message about
a bound quotes the number as typed.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import replace
from typing import Any

import numpy as np
import streamlit as st

from aerostat_core import Configuration, Requirement, thesis_baseline
from aerostat_core.model import budget, input_paths
from aerostat_core.model.io import inputs_to_dict
from aerostat_core.optimize import (
    DEFAULT_BOUNDS,
    SETTINGS,
    SOLVERS,
    VARIABLE_INFO,
    VARIABLES,
    BoundsError,
    OptimizationProblem,
    check_bounds,
    default_limits,
)

from . import cache, entry
from .formats import unit
from .state import current_inputs, inputs_key

#: Run levels shown in the UI -> engine setting.
RUN_LEVELS = {"Quick": "quick", "Normal": "normal"}
#: Sensitivity resolution: points per sweep and per map axis.
SENS_RESOLUTION = {"Quick": (7, 10), "Normal": (15, 20)}

#: Design variables shown in other units than the engine's: the fin position is a percentage of
#: the hull length on every page (the Design form's unit), the engine keeps the fraction.
DISPLAY: dict[str, tuple[float, str, str]] = {
    name: (scale, label, u)
    for name in VARIABLES
    for label, u, scale in [input_paths.variable_info(name)]
    if scale != 1.0
}


def shown(name: str, value: Any) -> Any:
    """A design variable's value (scalar or array) in its display unit."""
    scale = DISPLAY.get(name, (1.0,))[0]
    if scale == 1.0:
        return value
    return np.asarray(value, float) * scale if not np.isscalar(value) else float(value) * scale


def var_label(name: str) -> str:
    """'Fineness ratio l/d [-]' style label of a design variable, in its display unit."""
    if name in DISPLAY:
        _, label, u = DISPLAY[name]
        return f"{label} [{u}]"
    label, u, _ = VARIABLE_INFO[name]
    return f"{label} [{unit(u)}]"


# --- inputs ------------------------------------------------------------------------------------


def variable_range_inputs(prefix: str, lower: str, upper: str) -> dict[str, tuple[str, str]]:
    """Two number boxes (lower, upper) per design variable, in its display unit, holding
    ``DEFAULT_BOUNDS`` until edited; returns the texts typed, {variable: (lower, upper)}.

    Widget keys are ``{prefix}_lo_{name}`` / ``{prefix}_hi_{name}`` (kept across pages);
    ``lower``/``upper`` are the words after the variable label, e.g. "from"/"to". Read the
    texts with :func:`parse_ranges`.
    """
    out = {}
    for name in VARIABLES:
        scale = DISPLAY.get(name, (1.0,))[0]
        c = st.columns(2)
        out[name] = tuple(
            entry.number_box(
                f"{var_label(name)} – {word}",
                key=f"{prefix}_{side}_{name}",
                value=float(f"{default * scale:.12g}"),
                container=col,
            )
            for col, word, default, side in zip(
                c, (lower, upper), DEFAULT_BOUNDS[name], ("lo", "hi")
            )
        )
    return out


def parse_ranges(
    texts: Mapping[str, Sequence[Any]], lower: str, upper: str
) -> dict[str, tuple[float, float]]:
    """The bounds typed in :func:`variable_range_inputs`' boxes, in the engine's units.

    Checked by the engine's one bounds check (:func:`aerostat_core.optimize.check_bounds`);
    its :class:`~aerostat_core.optimize.BoundsError` is worded here in the unit of the boxes
    (the fin position in % of the hull length), so a message quotes the numbers as typed.
    Raises ``ValueError`` naming the variable's label.
    """
    typed: dict[str, tuple[float, float]] = {}
    si: dict[str, tuple[float, float]] = {}
    for name, (t_lo, t_hi) in texts.items():
        label = var_label(name)
        scale = DISPLAY.get(name, (1.0,))[0]
        typed[name] = (
            entry.read(t_lo, f"{label} – {lower}"),
            entry.read(t_hi, f"{label} – {upper}"),
        )
        si[name] = tuple(float(f"{v / scale:.12g}") for v in typed[name])
    if not si:
        return {}
    try:
        return check_bounds(si)
    except BoundsError as exc:
        raise ValueError(bounds_message(exc, typed)) from None


def bounds_message(exc: BoundsError, typed: Mapping[str, Sequence[float]]) -> str:
    """A :class:`~aerostat_core.optimize.BoundsError` in the form's words: the variable's label
    and display unit, the bounds as typed (``typed``: {variable: (lower, upper)} in the unit of
    the boxes) and the valid range in that unit."""
    if exc.variable not in typed or exc.valid is None:
        return str(exc)
    label = var_label(exc.variable)
    lo, hi = typed[exc.variable]
    vlo, vhi = (float(f"{v:.12g}") for v in shown(exc.variable, np.asarray(exc.valid)))
    return {
        "order": f"{label}: lower bound {lo:g} > upper bound {hi:g}",
        "empty": f"{label}: the bounds are empty (lower = upper = {lo:g}); give a range with "
        "the lower bound below the upper",
        "range": f"{label}: bounds ({lo:g}, {hi:g}) leave the valid range [{vlo:g}, {vhi:g}]",
        "not finite": f"{label}: bounds ({lo:g}, {hi:g}) must be finite numbers",
    }.get(exc.reason, f"{label}: {exc}")


def load_inputs() -> tuple[str, Requirement, Configuration]:
    """The current design inputs (``st.session_state["design_inputs"]``; the default inputs when
    missing or corrupt) as (canonical JSON, resolved Requirement, Configuration)."""
    req, cfg = current_inputs()
    return inputs_key(inputs_to_dict(req, cfg)), req.resolved(), cfg


def is_thesis_preset(req: Requirement, cfg: Configuration) -> bool:
    """True when the inputs are the thesis baseline (the thesis comparison then applies)."""
    return inputs_to_dict(req, cfg) == inputs_to_dict(*thesis_baseline())


def inputs_from_json(inputs_json: str) -> tuple[Requirement, Configuration]:
    """The frozen (resolved Requirement, Configuration) of canonical inputs JSON, parsed once
    per text (:func:`app_ui.cache.inputs_of`; raises ValueError)."""
    return cache.inputs_of(inputs_json)


#: Bounds as a cache key: ((variable, lower, upper), ...) in the order of ``VARIABLES``.
Bounds = tuple[tuple[str, float, float], ...]


def bounds_items(bounds: Mapping[str, Sequence[float]] | Bounds) -> Bounds:
    """Bounds ``{variable: (lower, upper)}`` (or already items) as hashable items in the order
    of ``VARIABLES`` (then any other name, sorted), floats: equal bounds give equal keys."""
    pairs = (
        bounds.items() if isinstance(bounds, Mapping) else ((n, (lo, hi)) for n, lo, hi in bounds)
    )
    rank = {n: i for i, n in enumerate(VARIABLES)}
    items = [(str(n), float(lo), float(hi)) for n, (lo, hi) in pairs]
    return tuple(sorted(items, key=lambda t: (rank.get(t[0], len(rank)), t[0])))


def bounds_dict(bounds: Bounds) -> dict[str, tuple[float, float]]:
    """:func:`bounds_items` back as the engine's ``{variable: (lower, upper)}``."""
    return {n: (lo, hi) for n, lo, hi in bounds}


def build_request(
    inputs_json: str,
    *,
    limit: float,
    bounds: Mapping[str, Sequence[float]],
    objective: str,
    level: str,
    seed: int,
    solvers: Sequence[str],
    pareto: bool,
    pareto_points: int,
    pareto_low: float,
    pareto_high: float,
) -> dict[str, Any]:
    """Validate the Optimise form and return the run request (plain, hashable parts).

    Raises ``ValueError`` naming the field, value and valid range (the page shows it).
    """
    req, cfg = inputs_from_json(inputs_json)
    try:
        req = replace(req, blow_by_limit=float(limit))
    except ValueError as exc:
        raise ValueError(f"Blow-by limit: {exc}") from None
    problem = OptimizationProblem(req, cfg, bounds, objective)  # raises on bad bounds/objective
    if not solvers:
        raise ValueError("Solvers: choose at least one solver")
    if level not in RUN_LEVELS.values():
        raise ValueError(f"Run level {level!r}: choose quick or normal")
    for solver in solvers:  # the compute budget, before anything runs (BudgetError says why)
        budget.check_optimization(problem, solver, SETTINGS[level][solver])
    limits: list[float] = []
    if pareto:
        if not 3 <= int(pareto_points) <= 40:
            raise ValueError(f"Pareto points = {pareto_points}: valid range [3, 40]")
        if not 0 < pareto_low < pareto_high:
            raise ValueError(
                f"Pareto range: lowest factor {pareto_low:g} must be positive and "
                f"below the highest {pareto_high:g}"
            )
        limits = default_limits(req, int(pareto_points), pareto_low, pareto_high).tolist()
    return {
        "inputs": inputs_key(inputs_to_dict(req, cfg)),
        "bounds": bounds_items(problem.bounds),
        "objective": objective,
        "level": level,
        "seed": int(seed),
        "solvers": [s for s in SOLVERS if s in solvers],
        "limits": limits,
    }
