"""The trade-off (beyond the thesis): minimum mass (or volume) versus the blow-by limit, by the
epsilon-constraint method (:func:`pareto_front`) and by NSGA-II (:func:`pareto_nsga2`, the
independent cross-check)."""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from aerostat_core.model.inputs import Configuration, Requirement
from aerostat_core.model.sizing import VOLUME_MAX, VOLUME_MIN

from .batch import CONSTRAINTS, VARIABLES, DesignBatch, evaluate_designs
from .lockstep import run_lockstep, slsqp_task, stencil_evaluator
from .problem import OptimizationProblem
from .tracking import OptimizationCancelled

#: Relative difference below which two objective values count as equal in
#: :func:`nondominated_mask`: the points of an epsilon-constraint front whose blow-by constraint
#: is not active are the same optimum, found to the solver's tolerance, and differ in the 4th-6th
#: digit; dominance on that noise flipped "on front" between rows that read the same.
DOMINANCE_RTOL = 1e-3


def nondominated_mask(a, b, rtol: float = DOMINANCE_RTOL) -> np.ndarray:
    """True for points not dominated in (a, b), both minimised.

    Point i is dominated when some j has a_j <= a_i and b_j <= b_i with at least one strictly
    better by more than the tolerance ``rtol * max(|a_i|, |a_j|)`` (likewise for b): values
    within the tolerance are equal, so points that differ only by solver noise share their
    verdict. NaN points are never in the set.

    Parameters
    ----------
    a, b : array_like
        Objective values (same length).
    rtol : float
        Relative tolerance of "strictly better" (0 for exact dominance).

    Examples
    --------
    >>> nondominated_mask([1, 2, 3, 2], [3, 2, 1, 3]).tolist()
    [True, True, True, False]
    >>> nondominated_mask([35.0221, 35.0220], [128.0, 128.0001]).tolist()
    [True, True]
    """
    a, b = np.asarray(a, float), np.asarray(b, float)
    ok = np.isfinite(a) & np.isfinite(b)
    ta = rtol * np.maximum(np.abs(a[None, :]), np.abs(a[:, None]))
    tb = rtol * np.maximum(np.abs(b[None, :]), np.abs(b[:, None]))
    le = (a[None, :] <= a[:, None] + ta) & (b[None, :] <= b[:, None] + tb)
    lt = (a[None, :] < a[:, None] - ta) | (b[None, :] < b[:, None] - tb)
    with np.errstate(invalid="ignore"):
        dom = np.any(le & lt & ok[None, :], axis=1)
    return ok & ~dom


@dataclass(frozen=True)
class ParetoFront:
    """Minimum objective versus blow-by limit.

    Attributes
    ----------
    method : str
        ``"epsilon-constraint"`` or ``"nsga2"``.
    objective_name : str
    limits : ndarray
        Blow-by limit epsilon of each point [m] (NaN for NSGA-II).
    fineness_ratio, area_change, position : ndarray
        Design variables [-], [%], [-].
    volume [m3], total_mass [kg], gas_cost [USD], blow_by [m], alpha [deg] : ndarray
        The design at each point (blow-by at the design wind).
    feasible : ndarray of bool
    reason : tuple of str
        Why a point is infeasible (empty when feasible).
    nondominated : ndarray of bool
        Feasible and not dominated in (objective, blow-by).
    n_evaluations : int
    time_s : float
    """

    method: str
    objective_name: str
    limits: np.ndarray
    fineness_ratio: np.ndarray
    area_change: np.ndarray
    position: np.ndarray
    volume: np.ndarray
    total_mass: np.ndarray
    gas_cost: np.ndarray
    blow_by: np.ndarray
    alpha: np.ndarray
    feasible: np.ndarray
    reason: tuple
    nondominated: np.ndarray
    n_evaluations: int
    time_s: float

    @property
    def objective(self) -> np.ndarray:
        """Objective values of the points (kg or m3)."""
        return np.asarray(getattr(self, self.objective_name), float)

    def rows(self) -> list[dict[str, Any]]:
        """Points as rows with units in the keys (CSV/table)."""
        out = []
        for i in range(self.volume.size):
            out.append(
                {
                    "blow_by_limit_m": float(self.limits[i]),
                    "blow_by_m": float(self.blow_by[i]),
                    "total_mass_kg": float(self.total_mass[i]),
                    "volume_m3": float(self.volume[i]),
                    "gas_cost_USD": float(self.gas_cost[i]),
                    "fineness_ratio": float(self.fineness_ratio[i]),
                    "area_change_pct": float(self.area_change[i]),
                    "position": float(self.position[i]),
                    "alpha_eq_deg": float(self.alpha[i]),
                    "feasible": bool(self.feasible[i]),
                    "on_front": bool(self.nondominated[i]),
                    "reason": self.reason[i],
                }
            )
        return out

    def mass_at(self, limit: float) -> float:
        """Objective of the best feasible front point whose blow-by is within ``limit`` [m]."""
        ok = self.feasible & (self.blow_by <= limit * (1 + 1e-6))
        return float(np.min(self.objective[ok])) if ok.any() else float("nan")


_LOGV = (math.log(VOLUME_MIN), math.log(VOLUME_MAX))


def _volume_from_unit(s) -> np.ndarray:
    """Hull volume [m3] from its unit coordinate (log scale over the sizing range)."""
    return np.exp(_LOGV[0] + np.asarray(s, float) * (_LOGV[1] - _LOGV[0]))


def _volume_to_unit(v) -> np.ndarray:
    """Unit coordinate (log scale over the sizing range) of a hull volume [m3]."""
    return (np.log(np.asarray(v, float)) - _LOGV[0]) / (_LOGV[1] - _LOGV[0])


def _check_limits(limits, altitude: float) -> np.ndarray:
    """Validate blow-by limits [m]: non-empty, finite, in (0, altitude]."""
    arr = np.atleast_1d(np.asarray(limits, float))
    if arr.size == 0:
        raise ValueError("the list of blow-by limits is empty")
    bad = arr[~np.isfinite(arr) | (arr <= 0) | (arr > altitude)]
    if bad.size:
        raise ValueError(
            f"blow-by limit {bad[0]:g} m is outside the valid range (0, {altitude:g}] m "
            "(positive and at most the altitude)"
        )
    return np.unique(arr)


def default_limits(
    req: Requirement, n_points: int = 13, low: float = 0.5, high: float = 2.5
) -> np.ndarray:
    """Blow-by limits for the front: ``n_points`` from ``low`` to ``high`` x the requirement's
    limit, capped at the altitude, always including the requirement's own limit [m]."""
    req = req.resolved()
    lim = req.blow_by_limit
    vals = np.linspace(low * lim, min(high * lim, req.altitude), max(int(n_points), 2))
    # drop grid values equal to the limit up to round-off, or the front holds a duplicate point
    vals = vals[np.abs(vals - lim) > 1e-9 * lim]
    return np.unique(np.concatenate([vals, [lim]]))


def _volume_starts(req, cfg, xs: np.ndarray, limits: np.ndarray) -> np.ndarray:
    """Starting volumes (S, K): for each start design and limit, the smallest volume of a
    64-point log grid with blow-by <= limit and positive free lift (one vectorised call)."""
    grid = np.geomspace(VOLUME_MIN, VOLUME_MAX, 64)
    s = xs.shape[0]
    f = np.repeat(xs[:, 0], grid.size)
    dsf = np.repeat(xs[:, 1], grid.size)
    pos = np.repeat(xs[:, 2], grid.size)
    b = evaluate_designs(req, cfg, f, dsf, pos, volume=np.tile(grid, s))
    bb = b.blow_by.reshape(s, -1)
    lift = (b.free_lift > 0).reshape(s, -1)
    out = np.empty((s, limits.size))
    for i in range(s):
        for k, lim in enumerate(limits):
            ok = lift[i] & (bb[i] <= lim)
            if ok.any():
                out[i, k] = grid[np.argmax(ok)]
            else:
                cand = np.where(lift[i], bb[i], np.inf)
                out[i, k] = grid[int(np.argmin(cand))] if np.isfinite(cand).any() else grid[-1]
    return out


def pareto_front(
    req: Requirement,
    cfg: Configuration,
    bounds: Mapping[str, Sequence[float]] | None = None,
    limits=None,
    n_points: int = 13,
    objective: str = "total_mass",
    starts: Sequence[Mapping[str, float]] = (),
    maxiter: int = 80,
    fd_step: float = 1e-6,
    progress: Callable | None = None,
    stop: Callable | None = None,
) -> ParetoFront:
    """Trade-off of the objective against the blow-by limit by the epsilon-constraint method.

    For each limit epsilon_k: min m(x, V) s.t. blow_by(x, V) <= epsilon_k and the other
    constraints of :class:`OptimizationProblem`, lower <= x <= upper, V in [VOLUME_MIN, VOLUME_MAX] = [2, 1e5] m3 (log
    scaled). V is the fourth variable here because the nested V*(x) exists for one limit at a
    time; with V free every epsilon problem evaluates without a sizing loop, and all of them
    (times the starts) run as lock-step SLSQP in one vectorised call per iteration. At
    epsilon = the requirement's limit the point equals the nested optimum (mass increases with
    V, so the smallest feasible V is optimal).

    Parameters
    ----------
    req, cfg : Requirement, Configuration
    bounds : mapping or None
        Design-variable bounds (see :class:`OptimizationProblem`).
    limits : array_like or None
        Blow-by limits [m] in (0, altitude]; ``None``: :func:`default_limits`.
    n_points : int
        Number of limits when ``limits`` is None.
    objective : {"total_mass", "volume"}
    starts : sequence of mapping
        Extra starting designs (e.g. a single-objective optimum) besides the configuration's.
    maxiter : int
        SLSQP iterations per epsilon problem.
    fd_step : float
        Finite-difference step in the unit cube (no sizing noise here, so small).
    progress, stop : callable or None
        ``progress(fraction, text)``; ``stop() -> bool`` cancels (raises
        :class:`OptimizationCancelled`).

    Returns
    -------
    ParetoFront
        One point per limit; ``nondominated`` marks the Pareto-optimal ones.

    References
    ----------
    Haimes Y.Y., Lasdon L.S., Wismer D.A., "On a bicriterion formulation of the problems of
    integrated system identification and system optimization", IEEE TSMC 1(3), 1971.
    """
    req = req.resolved()
    t0 = time.perf_counter()
    problem = OptimizationProblem(req, cfg, bounds, objective)
    eps = default_limits(req, n_points) if limits is None else _check_limits(limits, req.altitude)
    cfg0 = problem.configuration
    xs = [problem.start()]
    for s in starts:
        xs.append(np.clip([float(s[k]) for k in problem.names], problem.lower, problem.upper))
    xs_full = np.array([[problem.full_variables(x[None, :])[k][0] for k in VARIABLES] for x in xs])
    v0 = _volume_starts(req, cfg0, xs_full, eps)
    d = problem.n_var + 1
    tasks, owner_limit = [], []
    for k, e in enumerate(eps):
        for i, x in enumerate(xs):
            u0 = np.append(problem.to_unit(x), _volume_to_unit(v0[i, k]))
            tasks.append(slsqp_task(np.clip(u0, 0, 1), [(0.0, 1.0)] * d, int(maxiter), 1e-9))
            owner_limit.append(e)
    owner_limit = np.array(owner_limit)
    counter = {"n": 0, "rounds": 0}
    budget = len(tasks) * (2 * d + 1) * 25

    def fn_eval(pts, owners):
        """Evaluate stencil points at their free volumes, each against its task's limit."""
        x = problem.from_unit(pts[:, :-1])
        v = problem.full_variables(x)
        b = evaluate_designs(
            req,
            cfg0,
            v["fineness_ratio"],
            v["area_change"],
            v["position"],
            volume=_volume_from_unit(pts[:, -1]),
            blow_by_limit=owner_limit[owners],
        )
        counter["n"] += len(b)
        counter["rounds"] += 1
        if progress is not None:
            progress(min(counter["n"] / budget, 0.99), f"Pareto front: {counter['n']} evaluations")
        if stop is not None and stop():
            raise OptimizationCancelled
        return b

    scale: dict[str, float | None] = {"value": None}
    evaluate_requests = stencil_evaluator(
        fn_eval, d, fd_step, lambda b: b.objective(objective), scale
    )
    outcome = run_lockstep(tasks, evaluate_requests)
    finals = []
    for res in outcome:
        if isinstance(res, BaseException):
            raise res
        finals.append(np.clip(res.x, 0.0, 1.0))
    finals = np.array(finals)
    x = problem.from_unit(finals[:, :-1])
    v = problem.full_variables(x)
    b = evaluate_designs(
        req,
        cfg0,
        v["fineness_ratio"],
        v["area_change"],
        v["position"],
        volume=_volume_from_unit(finals[:, -1]),
        blow_by_limit=owner_limit,
    )
    counter["n"] += len(b)
    n_s = len(xs)
    pick = []
    obj = b.objective(objective)
    for k in range(eps.size):
        idx = np.arange(k * n_s, (k + 1) * n_s)
        feas = b.feasible[idx]
        if feas.any():
            pick.append(int(idx[np.argmin(np.where(feas, obj[idx], np.inf))]))
        else:
            pick.append(int(idx[np.argmin(b.max_violation[idx])]))
    pb = b.take(np.array(pick))
    return _front_from_batch(
        "epsilon-constraint", objective, eps, pb, counter["n"], time.perf_counter() - t0
    )


def _front_from_batch(method, objective, limits, b: DesignBatch, n_eval, dt) -> ParetoFront:
    """Build a :class:`ParetoFront` from the designs at its points."""
    obj = b.objective(objective)
    feas = b.feasible
    nd = nondominated_mask(np.where(feas, obj, np.nan), np.where(feas, b.blow_by, np.nan))
    reason = tuple("" if feas[i] else "; ".join(b.violations(i)) for i in range(len(b)))
    return ParetoFront(
        method=method,
        objective_name=objective,
        limits=np.asarray(limits, float),
        fineness_ratio=b.fineness_ratio,
        area_change=b.area_change,
        position=b.position,
        volume=b.volume,
        total_mass=b.total_mass,
        gas_cost=b.gas_cost,
        blow_by=b.blow_by,
        alpha=b.alpha,
        feasible=feas,
        reason=reason,
        nondominated=nd,
        n_evaluations=int(n_eval),
        time_s=float(dt),
    )


def pareto_nsga2(
    req: Requirement,
    cfg: Configuration,
    bounds: Mapping[str, Sequence[float]] | None = None,
    blow_by_range: tuple[float, float] | None = None,
    objective: str = "total_mass",
    pop_size: int = 60,
    generations: int = 80,
    seed: int = 0,
) -> ParetoFront:
    """Trade-off by NSGA-II (pymoo): objectives (objective, blow-by), variables [x, log V].

    The independent cross-check of :func:`pareto_front`: same variables and constraints, with
    blow-by an objective and ``blow_by_range`` [m] (default 0.5-2.5 x the requirement's limit)
    kept by a constraint blow_by <= upper and the volume bounded to the range that the start
    design needs for that blow-by span.

    Parameters
    ----------
    req, cfg : Requirement, Configuration
    bounds : mapping or None
    blow_by_range : (float, float) or None
        Blow-by span of interest [m].
    objective : {"total_mass", "volume"}
    pop_size, generations : int
    seed : int

    Returns
    -------
    ParetoFront
        The non-dominated feasible members of the final population, sorted by blow-by.

    References
    ----------
    Deb K. et al., "A fast and elitist multiobjective genetic algorithm: NSGA-II", IEEE TEC
    6(2):182-197, 2002.
    """
    req = req.resolved()
    from pymoo.algorithms.moo.nsga2 import NSGA2
    from pymoo.core.problem import Problem
    from pymoo.optimize import minimize as pymoo_minimize

    t0 = time.perf_counter()
    problem = OptimizationProblem(req, cfg, bounds, objective)
    lo_bb, hi_bb = blow_by_range or (
        0.5 * req.blow_by_limit,
        min(2.5 * req.blow_by_limit, req.altitude),
    )
    _check_limits([lo_bb, hi_bb], req.altitude)
    cfg0 = problem.configuration
    x0 = problem.start()
    x0f = np.array([[problem.full_variables(x0[None, :])[k][0] for k in VARIABLES]])
    vs = _volume_starts(req, cfg0, x0f, np.array([lo_bb, hi_bb]))[0]
    s_lo = float(_volume_to_unit(max(vs.min() / 3.0, VOLUME_MIN)))
    s_hi = float(_volume_to_unit(min(vs.max() * 3.0, VOLUME_MAX)))
    d = problem.n_var
    count = {"n": 0}

    def evaluate_population(X):
        """Evaluate unit-cube variables plus the log-volume column as one design batch."""
        v = problem.full_variables(problem.from_unit(X[:, :d]))
        return evaluate_designs(
            req,
            cfg0,
            v["fineness_ratio"],
            v["area_change"],
            v["position"],
            volume=_volume_from_unit(X[:, d]),
            blow_by_limit=hi_bb,
        )

    class _MO(Problem):
        """pymoo view of the two-objective problem: (objective, blow-by) over [x, log V]."""

        def __init__(self):
            """Four variables ([x] in the unit cube, log V), 2 objectives, one constraint per g."""
            super().__init__(
                n_var=d + 1,
                n_obj=2,
                n_ieq_constr=len(CONSTRAINTS),
                xl=np.append(np.zeros(d), s_lo),
                xu=np.append(np.ones(d), s_hi),
            )

        def _evaluate(self, X, out, *args, **kwargs):
            """pymoo hook: one vectorised evaluation of the population X into out['F'], out['G']."""
            b = evaluate_population(X)
            count["n"] += len(b)
            out["F"] = np.column_stack([b.objective(objective), b.blow_by])
            out["G"] = b.constraints

    res = pymoo_minimize(
        _MO(), NSGA2(pop_size=pop_size), ("n_gen", int(generations)), seed=int(seed), verbose=False
    )
    b = evaluate_population(res.pop.get("X"))
    keep = b.feasible & (b.blow_by >= lo_bb)
    b = b.take(np.nonzero(keep)[0])
    nd = nondominated_mask(b.objective(objective), b.blow_by)
    b = b.take(np.nonzero(nd)[0][np.argsort(b.blow_by[nd])])
    return _front_from_batch(
        "nsga2", objective, np.full(len(b), np.nan), b, count["n"], time.perf_counter() - t0
    )
