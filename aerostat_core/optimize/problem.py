"""The problems the solvers work on: :class:`OptimizationProblem` (the aerostat: min mass of the
sized design over f, Delta S_f, Delta l_f) and :class:`FunctionProblem` (any vectorised
function, for tests on analytic problems with known optima).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from aerostat_core.model.inputs import Configuration, Requirement

from .batch import (
    CONSTRAINT_TEXT,
    CONSTRAINTS,
    DEFAULT_BOUNDS,
    FEASIBILITY_TOL,
    OBJECTIVES,
    VARIABLE_INFO,
    VARIABLES,
    DesignBatch,
    check_bounds,
    evaluate_designs,
)


class OptimizationProblem:
    """min objective(x, V*(x)) s.t. g(x) <= 0, lower <= x <= upper (package docstring).

    Parameters
    ----------
    requirement : Requirement
        Payload [kg], altitude [m], design wind [m/s], blow-by limit [m], tether safety factor.
    configuration : Configuration
        Everything else; its hull volume is ignored (V is sized), its design-variable values are
        the starting point and hold any variable left out of ``bounds``.
    bounds : mapping or None
        {variable: (lower, upper)} for the variables to optimise (units of
        :data:`VARIABLE_INFO`); ``None`` takes :data:`DEFAULT_BOUNDS`.
    objective : {"total_mass", "volume"}
        Minimise total mass [kg] (thesis) or hull volume [m3] (helium cost).

    Raises
    ------
    ValueError
        Empty bounds, lower > upper, an unknown variable, bounds outside the engine's valid range
        or an unknown objective: the message names the variable and values.
    """

    def __init__(
        self,
        requirement: Requirement,
        configuration: Configuration,
        bounds: Mapping[str, Sequence[float]] | None = None,
        objective: str = "total_mass",
    ) -> None:
        """Validate the inputs and bounds (see the class docstring)."""
        if not isinstance(requirement, Requirement):
            raise ValueError("requirement must be a Requirement")
        if not isinstance(configuration, Configuration):
            raise ValueError("configuration must be a Configuration")
        if objective not in OBJECTIVES:
            raise ValueError(f"objective = {objective!r}: choose one of {', '.join(OBJECTIVES)}")
        checked = check_bounds(DEFAULT_BOUNDS if bounds is None else bounds)
        self.requirement = requirement.resolved()
        self.configuration = configuration.with_design_variables(volume=None)
        self.objective = objective
        self.names = tuple(v for v in VARIABLES if v in checked)
        self.bounds = {k: checked[k] for k in self.names}
        self.lower = np.array([checked[k][0] for k in self.names])
        self.upper = np.array([checked[k][1] for k in self.names])
        cfg = self.configuration
        self.fixed = {
            "fineness_ratio": cfg.hull.fineness_ratio,
            "area_change": cfg.fins.area_change,
            "position": cfg.fins.position,
        }

    # -- sizes and scaling -------------------------------------------------------------------
    @property
    def n_var(self) -> int:
        """Number of design variables."""
        return len(self.names)

    @property
    def n_constr(self) -> int:
        """Number of inequality constraints."""
        return len(CONSTRAINTS)

    def from_unit(self, u) -> np.ndarray:
        """Physical variables from the unit cube: x = lower + u (upper - lower)."""
        return self.lower + np.asarray(u, float) * (self.upper - self.lower)

    def to_unit(self, x) -> np.ndarray:
        """Unit-cube coordinates of physical variables: u = (x - lower)/(upper - lower)."""
        return (np.asarray(x, float) - self.lower) / (self.upper - self.lower)

    def start(self) -> np.ndarray:
        """The configuration's design variables, clipped into the bounds (physical units)."""
        x = np.array([self.fixed[k] for k in self.names], float)
        return np.clip(x, self.lower, self.upper)

    def full_variables(self, x) -> dict[str, np.ndarray]:
        """All three design variables for a batch x (n, n_var): optimised ones from x, the
        others held at the configuration's values."""
        x = np.atleast_2d(np.asarray(x, float))
        n = x.shape[0]
        out = {k: np.full(n, float(v)) for k, v in self.fixed.items()}
        for j, k in enumerate(self.names):
            out[k] = x[:, j]
        return out

    def variables_dict(self, x) -> dict[str, float]:
        """All three design variables of one design x (n_var,) as {name: value}."""
        v = self.full_variables(np.asarray(x, float)[None, :])
        return {k: float(v[k][0]) for k in VARIABLES}

    # -- evaluation ---------------------------------------------------------------------------
    def evaluate(self, x) -> DesignBatch:
        """Evaluate a batch of designs x (n, n_var) in physical units (one vectorised call)."""
        v = self.full_variables(x)
        return evaluate_designs(
            self.requirement,
            self.configuration,
            v["fineness_ratio"],
            v["area_change"],
            v["position"],
        )

    def evaluate_unit(self, u) -> DesignBatch:
        """Evaluate a batch given in unit-cube coordinates u (n, n_var)."""
        return self.evaluate(self.from_unit(np.clip(np.atleast_2d(u), 0.0, 1.0)))

    def configuration_at(self, x) -> Configuration:
        """Configuration with the design variables x (physical) and a sized volume."""
        v = self.full_variables(x)
        return self.configuration.with_design_variables(
            fineness_ratio=float(v["fineness_ratio"][0]),
            area_change=float(v["area_change"][0]),
            position=float(v["position"][0]),
            volume=None,
        )

    def describe(self) -> list[dict[str, str]]:
        """Problem definition as (item, definition) rows for display."""
        req = self.requirement
        lab, unit = OBJECTIVES[self.objective]
        rows = [
            {
                "item": "objective",
                "definition": f"minimise {lab.lower()} [{unit}] of the sized design",
            },
            {
                "item": "volume",
                "definition": "V*(x): smallest hull meeting the blow-by limit "
                f"{req.blow_by_limit:g} m at {req.design_wind:g} m/s with positive free lift "
                "and a taut tether (nested sizing, not a design variable)",
            },
        ]
        for k in VARIABLES:
            label, u, _ = VARIABLE_INFO[k]
            if k in self.bounds:
                lo, hi = self.bounds[k]
                rows.append(
                    {"item": f"variable {k}", "definition": f"{label}: [{lo:g}, {hi:g}] {u}"}
                )
            else:
                rows.append(
                    {"item": f"fixed {k}", "definition": f"{label} = {self.fixed[k]:g} {u}"}
                )
        for k in CONSTRAINTS:
            rows.append({"item": f"constraint {k}", "definition": CONSTRAINT_TEXT[k]})
        return rows


@dataclass(frozen=True)
class FunctionBatch:
    """Evaluated points of a :class:`FunctionProblem` (the solver-facing part of
    :class:`DesignBatch`): x (n, d), values (n,), constraints (n, m), variable names."""

    x: np.ndarray
    values: np.ndarray
    constraints: np.ndarray
    names: tuple

    def __len__(self) -> int:
        """Number of designs (points) in the batch."""
        return int(self.values.shape[0])

    @property
    def max_violation(self) -> np.ndarray:
        """max(0, max_i g_i) per point [-]."""
        if self.constraints.shape[1] == 0:
            return np.zeros(len(self))
        return np.maximum(np.max(self.constraints, axis=1), 0.0)

    @property
    def feasible(self) -> np.ndarray:
        """Every g <= :data:`FEASIBILITY_TOL`."""
        return np.all(self.constraints <= FEASIBILITY_TOL, axis=1)

    def objective(self, name: str = "value") -> np.ndarray:
        """Objective values (``name`` is ignored: a function problem has one objective)."""
        return self.values

    def violations(self, i: int) -> list[str]:
        """Violated constraints of point ``i`` as text (``g[k] = value > 0``)."""
        return [
            f"g[{k}] = {v:.3g} > 0"
            for k, v in enumerate(self.constraints[i])
            if v > FEASIBILITY_TOL
        ]

    def row(self, i: int) -> dict[str, Any]:
        """Point ``i`` as a flat dict (variables, objective, feasibility)."""
        out = {n: float(v) for n, v in zip(self.names, self.x[i])}
        out.update(objective=float(self.values[i]), feasible=bool(self.feasible[i]))
        return out

    def take(self, index) -> FunctionBatch:
        """Sub-batch selected by ``index``."""
        return FunctionBatch(self.x[index], self.values[index], self.constraints[index], self.names)


class FunctionProblem:
    """A vectorised analytic problem min f(x) s.t. g(x) <= 0, lower <= x <= upper, with the
    interface the solvers use. It verifies the solvers against problems with known optima.

    Parameters
    ----------
    objective : callable
        ``objective(X) -> (n,)`` for X of shape (n, d), vectorised.
    constraints : callable or None
        ``constraints(X) -> (n, m)`` (g <= 0 feasible); ``None`` for bounds only.
    bounds : mapping
        {name: (lower, upper)} in order, lower < upper, finite.
    start : array_like or None
        Starting point (default: the centre of the box).
    """

    def __init__(
        self,
        objective: Callable,
        constraints: Callable | None,
        bounds: Mapping[str, Sequence[float]],
        start=None,
    ) -> None:
        """Validate the bounds and store the functions (see the class docstring)."""
        if not isinstance(bounds, Mapping) or len(bounds) == 0:
            raise ValueError("bounds are empty: give {name: (lower, upper)} for each variable")
        lo, hi = [], []
        for name, pair in bounds.items():
            a, b = (float(v) for v in pair)
            if not (math.isfinite(a) and math.isfinite(b)) or a >= b:
                raise ValueError(
                    f"bounds of {name} must be finite with lower < upper, got ({a:g}, {b:g})"
                )
            lo.append(a)
            hi.append(b)
        self.names = tuple(bounds)
        self.lower, self.upper = np.array(lo), np.array(hi)
        self._f = objective
        self._g = constraints
        self.objective = "value"
        self._start = 0.5 * (self.lower + self.upper) if start is None else np.asarray(start, float)
        self.n_constr = int(np.shape(self._constraints(self._start[None, :]))[1])

    @property
    def n_var(self) -> int:
        """Number of variables."""
        return len(self.names)

    def _constraints(self, x: np.ndarray) -> np.ndarray:
        """Constraint matrix g (n, m) of points x (n, d); (n, 0) without constraints."""
        if self._g is None:
            return np.zeros((x.shape[0], 0))
        return np.asarray(self._g(x), float).reshape(x.shape[0], -1)

    def from_unit(self, u) -> np.ndarray:
        """x = lower + u (upper - lower)."""
        return self.lower + np.asarray(u, float) * (self.upper - self.lower)

    def to_unit(self, x) -> np.ndarray:
        """u = (x - lower)/(upper - lower)."""
        return (np.asarray(x, float) - self.lower) / (self.upper - self.lower)

    def start(self) -> np.ndarray:
        """Starting point, clipped into the bounds."""
        return np.clip(self._start, self.lower, self.upper)

    def variables_dict(self, x) -> dict[str, float]:
        """{name: value} of one point."""
        return {n: float(v) for n, v in zip(self.names, np.asarray(x, float))}

    def evaluate(self, x) -> FunctionBatch:
        """Evaluate a batch x (n, d)."""
        x = np.atleast_2d(np.asarray(x, float))
        return FunctionBatch(
            x, np.asarray(self._f(x), float).reshape(-1), self._constraints(x), self.names
        )
