"""Results and book-keeping shared by the solvers: the convergence :class:`History`, the
:class:`OptimizationResult`, the :class:`Tracker` that evaluates, records and reports every batch,
and the :class:`OptimizationCancelled` signal of a ``stop`` callback.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .batch import ACTIVE_TOL, CONSTRAINTS, DesignBatch


class OptimizationCancelled(Exception):
    """Raised inside a solver when its ``stop`` callback asks to stop (caught by the solver)."""


@dataclass(frozen=True)
class History:
    """Convergence history, one entry per evaluated batch.

    evaluations : cumulative number of designs evaluated [-];
    best : best feasible objective so far (NaN before the first feasible design);
    violation : least max-constraint violation so far [-] (0 once a feasible design is found).
    """

    evaluations: np.ndarray
    best: np.ndarray
    violation: np.ndarray

    def rows(self, solver: str = "") -> list[dict[str, Any]]:
        """History as rows (solver, evaluations, best objective, least violation)."""
        return [
            {
                "solver": solver,
                "evaluations": int(e),
                "best_objective": float(b),
                "least_violation": float(v),
            }
            for e, b, v in zip(self.evaluations, self.best, self.violation)
        ]


@dataclass(frozen=True)
class OptimizationResult:
    """Outcome of one solver run.

    Attributes
    ----------
    solver : str
        Key (``"slsqp"``, ``"surrogate"``, ``"pso"``).
    label : str
        Display name.
    x : dict
        Best design variables found {name: value} (physical units), all three variables.
    objective : float
        Its objective value (kg or m3).
    objective_name : str
    design : dict
        The best design's :meth:`DesignBatch.row`.
    feasible : bool
    status : str
        ``"converged"``, ``"budget"`` (evaluation/iteration budget used up), ``"cancelled"`` or
        ``"infeasible"`` (no feasible design found; ``message`` names the binding constraint).
    message : str
    active : tuple of str
        Constraints with g > -ACTIVE_TOL and variables at a bound (``"area_change=lower"``).
    n_evaluations : int
        Designs evaluated (each one a nested V*(x) sizing), finite-difference points included.
    n_batches : int
        Vectorised engine calls.
    time_s : float
        Wall time [s].
    seed : int
    history : History
    settings : dict
        Solver settings used.
    """

    solver: str
    label: str
    x: dict
    objective: float
    objective_name: str
    design: dict
    feasible: bool
    status: str
    message: str
    active: tuple
    n_evaluations: int
    n_batches: int
    time_s: float
    seed: int
    history: History
    settings: dict = field(default_factory=dict)


class Tracker:
    """Evaluates batches for a solver and keeps every design, the history, budget and callbacks.

    Parameters
    ----------
    problem : OptimizationProblem or FunctionProblem
    budget : int
        Nominal number of evaluations (for the progress fraction only).
    progress : callable or None
        ``progress(fraction, text)`` after every batch.
    stop : callable or None
        ``stop() -> bool``; True raises :class:`OptimizationCancelled` after the batch.
    label : str
        Solver name for the progress text.
    """

    def __init__(self, problem, budget, progress, stop, label):
        """Start an empty record (see the class docstring)."""
        self.problem = problem
        self.budget = max(int(budget), 1)
        self.progress = progress
        self.stop = stop
        self.label = label
        self.x: list[np.ndarray] = []
        self.batches: list[DesignBatch] = []
        self.n = 0
        self.best = np.inf
        self.viol = np.inf
        self.hist_e: list[int] = []
        self.hist_b: list[float] = []
        self.hist_v: list[float] = []
        self.t0 = time.perf_counter()

    def __call__(self, u) -> DesignBatch:
        """Evaluate unit-cube points u (n, d); record; report progress; honour ``stop``."""
        u = np.clip(np.atleast_2d(np.asarray(u, float)), 0.0, 1.0)
        x = self.problem.from_unit(u)
        b = self.problem.evaluate(x)
        self.x.append(x)
        self.batches.append(b)
        self.n += len(b)
        obj = b.objective(self.problem.objective)
        feas = b.feasible
        if np.any(feas):
            self.best = min(self.best, float(np.min(obj[feas])))
            self.viol = 0.0
        else:
            self.viol = min(self.viol, float(np.min(b.max_violation)))
        self.hist_e.append(self.n)
        self.hist_b.append(self.best if np.isfinite(self.best) else np.nan)
        self.hist_v.append(self.viol)
        if self.progress is not None:
            best = f"{self.best:.3f}" if np.isfinite(self.best) else "none feasible yet"
            self.progress(
                min(self.n / self.budget, 1.0), f"{self.label}: {self.n} evaluations, best {best}"
            )
        if self.stop is not None and self.stop():
            raise OptimizationCancelled
        return b

    def history(self) -> History:
        """The :class:`History` recorded so far."""
        return History(
            np.array(self.hist_e, int), np.array(self.hist_b, float), np.array(self.hist_v, float)
        )

    def best_index(self) -> tuple[int, int] | None:
        """(batch, row) of the best feasible design, else of the least-violating one."""
        if not self.batches:
            return None
        best, key = None, None
        for i, b in enumerate(self.batches):
            obj = b.objective(self.problem.objective)
            feas = b.feasible
            # feasible designs first (by objective), then infeasible by violation
            k = np.where(feas, 0.0, 1.0)
            score = np.where(feas, obj, b.max_violation)
            j = int(np.lexsort((score, k))[0])
            cand = (k[j], score[j])
            if key is None or cand < key:
                key, best = cand, (i, j)
        return best

    def result(self, solver, label, status, message, seed, settings) -> OptimizationResult:
        """Package the best design evaluated so far as an :class:`OptimizationResult`."""
        p = self.problem
        where = self.best_index()
        if where is None:
            nan = float("nan")
            return OptimizationResult(
                solver,
                label,
                {k: nan for k in p.variables_dict(p.start())},
                nan,
                p.objective,
                {},
                False,
                "cancelled",
                message or "stopped before any evaluation",
                (),
                0,
                0,
                time.perf_counter() - self.t0,
                seed,
                self.history(),
                settings,
            )
        i, j = where
        b = self.batches[i].take(np.array([j]))
        xs = self.x[i][j]
        feas = bool(b.feasible[0])
        active = [c for c, gv in zip(CONSTRAINTS, b.constraints[0]) if gv > -ACTIVE_TOL]
        span = p.upper - p.lower
        for k, name in enumerate(p.names):
            if xs[k] <= p.lower[k] + 1e-3 * span[k]:
                active.append(f"{name}=lower")
            elif xs[k] >= p.upper[k] - 1e-3 * span[k]:
                active.append(f"{name}=upper")
        if not feas:
            status = "cancelled" if status == "cancelled" else "infeasible"
            why = "; ".join(b.violations(0)) or "constraint tolerance not met"
            message = f"no feasible design found; at the least-violating design: {why}" + (
                f" ({message})" if message else ""
            )
        return OptimizationResult(
            solver=solver,
            label=label,
            x=p.variables_dict(xs),
            objective=float(b.objective(p.objective)[0]),
            objective_name=p.objective,
            design=b.row(0),
            feasible=feas,
            status=status,
            message=message,
            active=tuple(active),
            n_evaluations=int(self.n),
            n_batches=len(self.batches),
            time_s=time.perf_counter() - self.t0,
            seed=int(seed),
            history=self.history(),
            settings=dict(settings),
        )
