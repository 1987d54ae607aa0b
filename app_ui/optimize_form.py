"""Form model of the Sensitivity and Optimise pages: the design variables in their display units,
the bound boxes (text boxes read like the Design form's: a decimal comma is a decimal point),
the bounds checked in the unit of the boxes, and the optimisation request.

The fin position is a percentage of the hull length on every page (the Design form's unit); the
engine keeps the fraction. Conversion happens here, in both directions, so every message about
a bound quotes the number as typed.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from dataclasses import replace
from typing import Any

import numpy as np
import streamlit as st

from aerostat_core import Configuration, Requirement, budget, fields, thesis_baseline
from aerostat_core.io import inputs_from_dict, inputs_to_dict
from aerostat_core.optimize import (
    DEFAULT_BOUNDS,
    SETTINGS,
    SOLVERS,
    VARIABLE_INFO,
    VARIABLES,
    OptimizationProblem,
    default_limits,
)

from . import entry
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
    for label, u, scale in [fields.variable_info(name)]
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

    Checked in the unit of the boxes (the fin position in % of the hull length), so a message
    quotes the numbers as typed: lower below upper, not equal, inside the variable's valid
    range. Raises ``ValueError`` naming the variable's label.
    """
    out: dict[str, tuple[float, float]] = {}
    for name, (t_lo, t_hi) in texts.items():
        label = var_label(name)
        scale = DISPLAY.get(name, (1.0,))[0]
        lo = entry.read(t_lo, f"{label} – {lower}")
        hi = entry.read(t_hi, f"{label} – {upper}")
        vlo, vhi = (float(f"{v * scale:.12g}") for v in VARIABLE_INFO[name][2])
        if lo > hi:
            raise ValueError(f"{label}: lower bound {lo:g} > upper bound {hi:g}")
        if lo == hi:
            raise ValueError(
                f"{label}: the bounds are empty (lower = upper = {lo:g}); give a range with "
                "the lower bound below the upper"
            )
        if lo < vlo or hi > vhi:
            raise ValueError(
                f"{label}: bounds ({lo:g}, {hi:g}) leave the valid range [{vlo:g}, {vhi:g}]"
            )
        out[name] = (float(f"{lo / scale:.12g}"), float(f"{hi / scale:.12g}"))
    return out


def load_inputs() -> tuple[str, Requirement, Configuration]:
    """The current design inputs (``st.session_state["design_inputs"]``; the default inputs when
    missing or corrupt) as (canonical JSON, resolved Requirement, Configuration)."""
    req, cfg = current_inputs()
    return inputs_key(inputs_to_dict(req, cfg)), req.resolved(), cfg


def is_thesis_preset(req: Requirement, cfg: Configuration) -> bool:
    """True when the inputs are the thesis baseline (the thesis comparison then applies)."""
    return inputs_to_dict(req, cfg) == inputs_to_dict(*thesis_baseline())


def inputs_from_json(inputs_json: str) -> tuple[Requirement, Configuration]:
    """(Requirement, Configuration) from canonical inputs JSON (raises ValueError)."""
    req, cfg = inputs_from_dict(json.loads(inputs_json))
    return req.resolved(), cfg  # the limits as applied (rule-set values filled in)


def bounds_key(bounds: Mapping[str, Sequence[float]]) -> str:
    """Canonical JSON of a bounds mapping (cache key)."""
    return json.dumps({k: [float(v) for v in bounds[k]] for k in bounds}, sort_keys=True)


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
        "bounds": bounds_key(bounds),
        "objective": objective,
        "level": level,
        "seed": int(seed),
        "solvers": [s for s in SOLVERS if s in solvers],
        "limits": limits,
    }
