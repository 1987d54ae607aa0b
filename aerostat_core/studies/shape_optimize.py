"""Hull shape as a categorical design choice: the best design per shape and the overall best.

The continuous optimiser (:mod:`aerostat_core.optimize`) is run once per shape, unchanged:

* streamlined shapes (NPL, GNVR, Wang, Zhiyuan-1, Lotte): :func:`aerostat_core.optimize.solve`
  over (f, Delta S_f, Delta l_f), the fineness bounds cut to the shape's valid range
  (``ShapeInfo.fineness_range``);
* bluff shapes (sphere, oblate, Helikite) carry no fins, so the fin variables do nothing; their
  only variable is l/d within the shape's range (sphere: none). It lies outside the optimiser's
  bounds for streamlined hulls, so a grid of ``grid_points`` sized designs over the range
  (:func:`aerostat_core.optimize.evaluate_designs`, one vectorised call) is searched instead.

The overall best is the feasible per-shape optimum of least objective. A categorical variable
with 8 levels is small enough that enumeration is exact: no relaxation is needed.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from aerostat_core.base.deprecation import deprecated_aliases
from aerostat_core.geometry.shapes import SHAPE_INFO, SHAPES
from aerostat_core.model.inputs import Configuration, Requirement
from aerostat_core.optimize import (
    DEFAULT_BOUNDS,
    OBJECTIVES,
    OptimizationProblem,
    evaluate_designs,
    solve,
)


@dataclass(frozen=True)
class ShapeOptimum:
    """The best design of one shape.

    shape : str; method : "slsqp"/"surrogate"/"pso" or "grid"; x : {variable: value};
    objective : float (kg or m3); feasible : bool; design : dict (``DesignBatch.row``);
    message : str; n_evaluations : int.
    """

    shape: str
    method: str
    x: dict
    objective: float
    feasible: bool
    design: dict
    message: str
    n_evaluations: int

    def configuration(self, base: Configuration) -> Configuration:
        """``base`` with this optimum's shape and design variables (volume left to sizing)."""
        cfg = replace(
            base,
            hull=replace(
                base.hull, shape=self.shape, fineness_ratio=self.x["fineness_ratio"], volume=None
            ),
        )
        return cfg.with_design_variables(
            area_change=self.x["area_change"], position=self.x["position"]
        )


@dataclass(frozen=True)
class ShapeStudy:
    """Per-shape optima {shape: ShapeOptimum} (in ``SHAPES`` order), the overall ``best`` shape
    (None when no shape is feasible) and the objective name."""

    per_shape: dict
    best: str | None
    objective: str

    def rows(self) -> list[dict[str, Any]]:
        """One row per shape, best first among the feasible, for tables and CSV."""
        out = []
        for s, r in self.per_shape.items():
            row = {
                "shape": s,
                "label": SHAPE_INFO[s].label,
                "method": r.method,
                "feasible": r.feasible,
                "best": s == self.best,
                f"{self.objective}": r.objective,
            }
            row.update({k: v for k, v in r.design.items()})
            row["message"] = r.message
            out.append(row)
        return sorted(out, key=lambda x: (not x["feasible"], x[self.objective]))


def shape_bounds(shape: str, bounds: Mapping[str, Sequence[float]] | None) -> dict:
    """Bounds (or sweep ranges) for a shape: the given ones (default
    :data:`~aerostat_core.optimize.DEFAULT_BOUNDS`) with f cut to the shape's valid range; f is
    left out when the cut leaves no interval (it is then held at the configuration's value)."""
    b = dict(DEFAULT_BOUNDS if bounds is None else bounds)
    lo, hi = SHAPE_INFO[shape].fineness_range
    if "fineness_ratio" in b:
        flo, fhi = (float(v) for v in b["fineness_ratio"])
        flo, fhi = max(flo, lo), min(fhi, hi)
        if fhi - flo < 1e-6:
            b.pop("fineness_ratio")
        else:
            b["fineness_ratio"] = (flo, fhi)
    return b


def _grid_optimum(req, cfg, shape, objective, grid_points) -> ShapeOptimum:
    lo, hi = SHAPE_INFO[shape].fineness_range
    fs = np.linspace(lo, hi, grid_points) if hi > lo else np.array([lo])
    batch = evaluate_designs(req, cfg, fineness_ratio=fs)
    obj = batch.objective(objective)
    ok = batch.feasible
    i = (
        int(np.argmin(np.where(ok, obj, np.inf)))
        if ok.any()
        else int(np.argmin(batch.max_violation))
    )
    x = {
        "fineness_ratio": float(fs[i]),
        "area_change": float(cfg.fins.area_change),
        "position": float(cfg.fins.position),
    }
    msg = "grid over l/d (finless hull)" if ok.any() else "; ".join(batch.violations(i))
    return ShapeOptimum(shape, "grid", x, float(obj[i]), bool(ok[i]), batch.row(i), msg, fs.size)


def optimize_shapes(
    req: Requirement,
    cfg: Configuration,
    shapes: Sequence[str] | None = None,
    bounds: Mapping[str, Sequence[float]] | None = None,
    objective: str = "total_mass",
    solver: str = "slsqp",
    setting: str = "quick",
    seed: int = 0,
    grid_points: int = 25,
) -> ShapeStudy:
    """Optimise every shape and pick the best (module docstring).

    Parameters
    ----------
    req, cfg : Requirement, Configuration
        ``cfg``'s hull shape and fineness ratio are replaced per shape (each starts from its
        standard l/d); everything else is shared.
    shapes : sequence of str or None
        Shapes to compare (default all of ``SHAPES``).
    bounds : mapping or None
        Optimiser bounds (:data:`aerostat_core.optimize.DEFAULT_BOUNDS` by default).
    objective : {"total_mass", "volume"}
    solver, setting, seed
        Passed to :func:`aerostat_core.optimize.solve`.
    grid_points : int
        l/d grid size for bluff shapes, valid [2, 101].

    Returns
    -------
    ShapeStudy
    """
    if objective not in OBJECTIVES:
        raise ValueError(f"objective = {objective!r}: choose one of {', '.join(OBJECTIVES)}")
    names = list(SHAPES if shapes is None else shapes)
    if not names:
        raise ValueError("shapes is empty: choose at least one of " + ", ".join(SHAPES))
    for s in names:
        if s not in SHAPE_INFO:
            raise ValueError(f"shape {s!r} is not a known hull shape; valid: {', '.join(SHAPES)}")
    if not 2 <= int(grid_points) <= 101:
        raise ValueError(f"grid_points = {grid_points!r} is outside the valid range [2, 101]")
    out: dict[str, ShapeOptimum] = {}
    for s in names:
        info = SHAPE_INFO[s]
        c = replace(cfg, hull=replace(cfg.hull, shape=s, fineness_ratio=None, volume=None))
        if not info.streamlined:
            out[s] = _grid_optimum(req, c, s, objective, int(grid_points))
            continue
        problem = OptimizationProblem(req, c, shape_bounds(s, bounds), objective)
        r = solve(problem, solver, setting, seed=seed)
        out[s] = ShapeOptimum(
            s,
            solver,
            dict(r.x),
            float(r.objective),
            bool(r.feasible),
            dict(r.design),
            r.message,
            int(r.n_evaluations),
        )
    feasible = [s for s in names if out[s].feasible]
    best = min(feasible, key=lambda s: out[s].objective) if feasible else None
    return ShapeStudy(per_shape=out, best=best, objective=objective)


@dataclass(frozen=True)
class FinenessSweep:
    """Sized designs of one shape over its valid l/d range (1-D arrays): fineness_ratio [-],
    volume [m3], total_mass [kg], blow_by [m], feasible (bool), plus the shape's standard l/d."""

    shape: str
    fineness_ratio: np.ndarray
    volume: np.ndarray
    total_mass: np.ndarray
    blow_by: np.ndarray
    feasible: np.ndarray
    standard: float


def fineness_sweeps(
    req: Requirement, cfg: Configuration, shapes: Sequence[str] | None = None, n_points: int = 15
) -> dict[str, FinenessSweep]:
    """Sensitivity per shape: the hull re-sized (V*(f)) over each shape's valid l/d range, fins
    and everything else from ``cfg`` (one vectorised :func:`evaluate_designs` call per shape).

    Parameters
    ----------
    req, cfg : Requirement, Configuration
    shapes : sequence of str or None
        Default all of ``SHAPES``; the sphere has the single point l/d = 1.
    n_points : int
        Points per sweep, valid [2, 101].
    """
    if not 2 <= int(n_points) <= 101:
        raise ValueError(f"n_points = {n_points!r} is outside the valid range [2, 101]")
    out = {}
    for s in SHAPES if shapes is None else shapes:
        info = SHAPE_INFO[s]
        lo, hi = info.fineness_range
        fs = np.linspace(lo, hi, int(n_points)) if hi > lo else np.array([lo])
        c = replace(cfg, hull=replace(cfg.hull, shape=s, fineness_ratio=None, volume=None))
        b = evaluate_designs(req, c, fineness_ratio=fs)
        out[s] = FinenessSweep(
            s, fs, b.volume, b.total_mass, b.blow_by, b.feasible, info.default_fineness
        )
    return out


#: Deprecated British spelling -> the current name (docs/architecture.md §7).
DEPRECATED_NAMES = {"optimise_shapes": "optimize_shapes"}

__getattr__ = deprecated_aliases(__name__, globals(), DEPRECATED_NAMES)
