"""Baseline versus optimum performance over the wind (thesis Figs 4.17-4.22)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from aerostat_core.model.inputs import Configuration, Requirement

#: Performance curves compared between baseline and optimum: key -> (label, unit).
PERFORMANCE_CURVES = {
    "blow_by": ("Blow-by", "m"),
    "alpha_eq": ("Equilibrium angle of attack", "deg"),
    "dynamic_lift": ("Dynamic lift", "N"),
    "tension_top": ("Tether tension at the confluence point", "N"),
}


def performance_curves(req: Requirement, cfg: Configuration) -> dict[str, Any]:
    """Performance versus wind of one design (:func:`aerostat_core.model.design`), as plain arrays.

    Parameters
    ----------
    req, cfg : Requirement, Configuration
        ``cfg.hull.volume`` None sizes the hull.

    Returns
    -------
    dict
        ``wind_speed`` [m/s] and the keys of :data:`PERFORMANCE_CURVES` (arrays), plus
        ``volume`` [m3], ``total_mass`` [kg], ``feasible`` (bool) and ``violations`` (list).
    """
    req = req.resolved()
    from aerostat_core.model.design import design

    return curves_of(design(req, cfg))


def curves_of(d: Any) -> dict[str, Any]:
    """:func:`performance_curves` of a design already made (:class:`aerostat_core.model.design.Design`)."""
    p = d.performance
    out = {"wind_speed": np.asarray(p.wind_speed, float)}
    for k in PERFORMANCE_CURVES:
        out[k] = np.asarray(getattr(p, k), float)
    out.update(
        volume=float(d.volume),
        total_mass=float(d.total_mass),
        feasible=bool(d.feasible),
        violations=list(d.violations),
    )
    return out


def performance_comparison_rows(
    baseline: Mapping[str, Any], optimum: Mapping[str, Any]
) -> list[dict[str, Any]]:
    """Baseline and optimum performance side by side, one row per wind speed (CSV/table).

    Parameters
    ----------
    baseline, optimum : mapping
        :func:`performance_curves` of the two designs (same wind sweep).
    """
    w = np.asarray(baseline["wind_speed"], float)
    if not np.array_equal(w, np.asarray(optimum["wind_speed"], float)):
        raise ValueError("baseline and optimum were evaluated on different wind sweeps")
    rows = []
    for i, v in enumerate(w):
        row = {"wind_speed_m_s": float(v)}
        for k, (_, unit) in PERFORMANCE_CURVES.items():
            row[f"baseline_{k}_{unit}"] = float(baseline[k][i])
            row[f"optimum_{k}_{unit}"] = float(optimum[k][i])
        rows.append(row)
    return rows
