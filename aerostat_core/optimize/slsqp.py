"""Solver 1: gradient-based SLSQP from several starts (MATLAB ``fmincon`` + ``MultiStart``), all
starts in lock-step (:mod:`.lockstep`)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from .lockstep import LockstepAborted, RoundCapReached, run_lockstep, slsqp_task, stencil_evaluator
from .problem import OptimizationProblem
from .tracking import OptimizationCancelled, OptimizationResult, Tracker


def _start_points(problem: OptimizationProblem, n_starts: int, seed: int) -> np.ndarray:
    """Multi-start points in the unit cube: the configuration's design (clipped into the bounds)
    followed by a seeded scrambled-Halton sample."""
    from scipy.stats import qmc

    pts = [problem.to_unit(problem.start())]
    if n_starts > 1:
        sampler = qmc.Halton(problem.n_var, scramble=True, seed=np.random.default_rng(seed))
        pts.extend(sampler.random(n_starts - 1))
    return np.array(pts[: max(n_starts, 1)])


def solve_slsqp(
    problem: OptimizationProblem,
    n_starts: int = 4,
    seed: int = 0,
    maxiter: int = 60,
    ftol: float = 1e-8,
    fd_step: float = 1e-3,
    max_rounds: int | None = None,
    progress: Callable | None = None,
    stop: Callable | None = None,
) -> OptimizationResult:
    """Gradient-based SLSQP from several starts (fmincon + MultiStart analogue).

    Each start is a ``scipy.optimize.minimize(method="SLSQP")`` run in the unit cube with the
    objective scaled by its median at the starts and second-order finite-difference gradients
    (central; one-sided three-point at a bound) of the
    objective and every constraint (step ``fd_step`` in the unit cube, i.e. 1e-3 of each range).
    All starts advance in lock-step: at every round the pending points of all starts and their
    d finite-difference neighbours form one batch, so a round costs one vectorised sizing call.

    Parameters
    ----------
    problem : OptimizationProblem or FunctionProblem
    n_starts : int
        Starting points: the configuration's design plus ``n_starts - 1`` scrambled-Halton points.
    seed : int
        Seed of the start sample.
    maxiter : int
        SLSQP iteration limit per start.
    ftol : float
        SLSQP objective tolerance (objective scaled to about 1).
    fd_step : float
        Finite-difference step in the unit cube [-]; larger than the ~1e-7 smoothness of V*(x).
    max_rounds : int or None
        Cap on lock-step rounds (batches); ``None``: ``maxiter``. A converging run needs far
        fewer; the cap stops line searches that wander when the problem is infeasible.
    progress, stop : callable or None
        ``progress(fraction, text)`` after every batch; ``stop() -> bool`` cancels.

    Returns
    -------
    OptimizationResult
        The best feasible design found by any start (or the least violating one).

    References
    ----------
    Kraft D., "A software package for sequential quadratic programming", DFVLR-FB 88-28, 1988.
    """
    n_starts = int(n_starts)
    if n_starts < 1:
        raise ValueError(f"n_starts = {n_starts}: need at least 1 start")
    settings = {"n_starts": n_starts, "maxiter": int(maxiter), "ftol": ftol, "fd_step": fd_step}
    d = problem.n_var
    budget = n_starts * (2 * d + 1) * max(int(maxiter) // 3, 8)
    tr = Tracker(problem, budget, progress, stop, "SLSQP")
    label = f"SLSQP ({n_starts} starts)"
    starts = _start_points(problem, n_starts, seed)
    scale: dict[str, float | None] = {"value": None}
    cap = int(maxiter) if max_rounds is None else int(max_rounds)
    settings["max_rounds"] = cap

    def fn_eval(pts, owners):
        """Evaluate the stencil points of one lock-step round (round cap enforced)."""
        if len(tr.batches) >= cap:
            raise RoundCapReached
        return tr(pts)

    evaluate_requests = stencil_evaluator(
        fn_eval,
        d,
        fd_step,
        lambda b: b.objective(problem.objective),
        scale,
    )
    bounds = [(0.0, 1.0)] * d
    tasks = [slsqp_task(u0, bounds, int(maxiter), ftol) for u0 in starts]
    try:
        outcome = run_lockstep(tasks, evaluate_requests)
    except OptimizationCancelled:
        return tr.result("slsqp", label, "cancelled", "cancelled by the user", seed, settings)
    except RoundCapReached:
        return tr.result("slsqp", label, "budget", f"stopped after {cap} rounds", seed, settings)
    msgs = []
    n_iter_limit = 0
    for res in outcome:
        if isinstance(res, BaseException):
            if isinstance(res, LockstepAborted):
                continue
            raise res
        if res.status == 9:
            n_iter_limit += 1
        msgs.append(res.message)
    status = "converged" if n_iter_limit < len(outcome) else "budget"
    nconv = sum(1 for r in outcome if not isinstance(r, BaseException) and r.success)
    message = f"{nconv} of {len(outcome)} starts converged"
    return tr.result("slsqp", label, status, message, seed, settings)
