"""Solver 1: gradient-based SLSQP from several starts (MATLAB ``fmincon`` + ``MultiStart``), all
starts in lock-step (:mod:`.lockstep`). On the aerostat problem it works with the hull volume as
a variable and the constraint table as its constraints (:mod:`.volume_variable`), not on the
nested V*(x)."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np

from aerostat_core.optimize.batch import DesignBatch
from aerostat_core.optimize.volume_variable import VolumeVariableProblem

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
    fd_step: float | None = None,
    max_rounds: int | None = None,
    progress: Callable | None = None,
    stop: Callable | None = None,
    formulation: str = "volume",
    fd_order: int | None = None,
) -> OptimizationResult:
    """Gradient-based SLSQP from several starts (fmincon + MultiStart analogue).

    Each start is a ``scipy.optimize.minimize(method="SLSQP")`` run in the unit cube with the
    objective scaled by its median at the starts and finite-difference gradients of the
    objective and every constraint (step ``fd_step`` in the unit cube; ``fd_order``). All starts
    advance in lock-step: at every round the pending points of all starts and their
    finite-difference neighbours form one batch, so a round costs one vectorised engine call.

    On an :class:`OptimizationProblem` the default ``formulation="volume"`` solves
    min m(x, V) s.t. g(x, V) <= 0 with the hull volume V a fourth variable
    (:class:`~aerostat_core.optimize.volume_variable.VolumeVariableProblem`): the constraint
    table is smooth in (x, V), whereas the nested V*(x) jumps where the weathervane constraint
    takes over from blow-by, right at the thesis optimum, and finite differences across the
    jump made SLSQP wander (1680 sized evaluations and the round cap, against about 300 plain
    ones now). Each start begins at its sized volume V*(x0); the answer is the sized design at
    the optimum x (one nested evaluation), which equals the free-volume solution because mass
    grows with V. ``formulation="nested"`` keeps the objective m(x, V*(x)) (for comparison).

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
    fd_step : float or None
        Finite-difference step in the unit cube [-]; ``None``: 1e-6 with the volume a variable
        (smooth functions), 1e-3 otherwise (larger than the ~1e-7 smoothness of the nested
        V*(x)).
    max_rounds : int or None
        Cap on lock-step rounds (batches); ``None``: ``maxiter``. A converging run needs far
        fewer; the cap stops line searches that wander when the problem is infeasible.
    progress, stop : callable or None
        ``progress(fraction, text)`` after every batch; ``stop() -> bool`` cancels.
    formulation : {"volume", "nested"}
        How an :class:`OptimizationProblem` is solved (see above); ignored for other problems.
    fd_order : {1, 2} or None
        Order of the finite differences (:func:`~.lockstep.fd_stencil`); ``None``: 1 with the
        volume a variable (d + 1 points per request; with h = 1e-6 on smooth functions the
        O(h) error is far below SLSQP's tolerance), else 2 (2 d + 1 points).

    Returns
    -------
    OptimizationResult
        The best feasible design found by any start (or the least violating one).

    References
    ----------
    Kraft D., "A software package for sequential quadratic programming", DFVLR-FB 88-28, 1988.
    Martins J.R.R.A., Ning A., *Engineering Design Optimization*, Cambridge University Press,
    2021, §13.2 (nested versus simultaneous formulations of a coupled problem).
    """
    n_starts = int(n_starts)
    if n_starts < 1:
        raise ValueError(f"n_starts = {n_starts}: need at least 1 start")
    if formulation not in ("volume", "nested"):
        raise ValueError(f"formulation = {formulation!r}: choose 'volume' or 'nested'")
    free = formulation == "volume" and isinstance(problem, OptimizationProblem)
    if fd_step is None:
        fd_step = 1e-6 if free else 1e-3
    if fd_order is None:
        fd_order = 1 if free else 2
    if fd_order not in (1, 2):
        raise ValueError(f"fd_order = {fd_order!r}: choose 1 or 2")
    settings = {
        "n_starts": n_starts,
        "maxiter": int(maxiter),
        "ftol": ftol,
        "fd_step": fd_step,
        "fd_order": int(fd_order),
        "formulation": "volume" if free else "nested",
    }
    nested = problem
    starts = _start_points(problem, n_starts, seed)
    sized_starts = None
    if free:
        problem = VolumeVariableProblem(nested)
        x_starts = nested.from_unit(starts)
        starts, sized_starts = problem.start_points(starts)
    d = problem.n_var
    per_point = 2 * d + 1 if fd_order == 2 else d + 1
    budget = n_starts * per_point * max(int(maxiter) // 3, 8)
    tr = Tracker(problem, budget, progress, stop, "SLSQP")
    if sized_starts is not None:
        tr.n += len(sized_starts)  # the starts' volumes: designs evaluated (sized)
    label = f"SLSQP ({n_starts} starts)"
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
        fd_order,
    )
    bounds = [(0.0, 1.0)] * d
    tasks = [slsqp_task(u0, bounds, int(maxiter), ftol) for u0 in starts]

    def finish(status: str, message: str) -> OptimizationResult:
        res = tr.result("slsqp", label, status, message, seed, settings)
        return _sized_answer(res, tr, nested, sized_starts, x_starts) if free else res

    try:
        outcome = run_lockstep(tasks, evaluate_requests)
    except OptimizationCancelled:
        return finish("cancelled", "cancelled by the user")
    except RoundCapReached:
        return finish("budget", f"stopped after {cap} rounds")
    n_iter_limit = 0
    for res in outcome:
        if isinstance(res, BaseException):
            if isinstance(res, LockstepAborted):
                continue
            raise res
        if res.status == 9:
            n_iter_limit += 1
    status = "converged" if n_iter_limit < len(outcome) else "budget"
    nconv = sum(1 for r in outcome if not isinstance(r, BaseException) and r.success)
    return finish(status, f"{nconv} of {len(outcome)} starts converged")


#: Steps back from the free-volume optimum toward the best sized start, as fractions of the
#: way (one batch of sized designs; see :func:`_sized_answer`).
_LADDER = np.array([0.0, 1e-3, 2e-3, 5e-3, 1e-2, 2e-2, 5e-2, 0.1, 0.2, 0.5, 1.0])


def _sized_answer(
    res: OptimizationResult,
    tr: Tracker,
    nested: OptimizationProblem,
    starts: DesignBatch,
    x_starts: np.ndarray,
) -> OptimizationResult:
    """The answer as a design the app reproduces: the sized design V*(x) at a design x.

    Where the optimum has the blow-by and the weathervane limits both binding, the volumes
    that meet the table at x_opt form a window far narrower than the sizing's grid step
    (docs/methods.md §1.12: such a window can be missed), so V*(x_opt) is not the free
    volume. The sized designs at x_opt and on a ladder of steps from it back toward each
    feasible sized start (0.1 %, 0.2 %, ..., 100 % of the way; one batch) are evaluated, and
    the lightest feasible one is the answer. Where none is feasible the free-volume
    design is kept (it meets the table)."""
    where = tr.best_index()
    if where is None or not res.feasible:
        return res
    i, j = where
    x = tr.x[i][j][: nested.n_var]
    homes = x_starts[np.asarray(starts.feasible, bool)]
    if len(homes) == 0:
        homes = x[None, :]
    steps = _LADDER[1:] if len(homes) > 1 else _LADDER
    pts = np.concatenate(
        [x[None, :]] + [x[None, :] + steps[:, None] * (h - x)[None, :] for h in homes]
    )
    sized = Tracker(nested, 1, None, None, "SLSQP")
    b = sized(nested.to_unit(pts))
    if not b.feasible.any():
        return res
    one = sized.result(res.solver, res.label, res.status, res.message, res.seed, res.settings)
    history = tr.history()
    n = res.n_evaluations + len(b)
    best = one.objective  # the answer: the sized design (a free-volume best can be lighter)
    return dataclasses.replace(
        one,
        n_evaluations=n,
        n_batches=res.n_batches + 1,
        time_s=res.time_s + one.time_s,
        history=type(history)(
            np.append(history.evaluations, n),
            np.append(history.best, best),
            np.append(history.violation, 0.0),
        ),
    )
