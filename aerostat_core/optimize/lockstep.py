"""Lock-step SLSQP: several ``scipy.optimize.minimize(method="SLSQP")`` runs whose evaluation
requests are pooled into one vectorised batch per round, with second-order finite-difference
gradients from one stencil per request. Used by the multi-start solver (:mod:`.slsqp`) and by the
epsilon-constraint Pareto front (:mod:`.pareto`).
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

import numpy as np


class LockstepAborted(Exception):
    """Raised in worker threads when the lock-step run is torn down."""


class RoundCapReached(Exception):
    """Raised in the main thread when a lock-step run reaches its round cap."""


def run_lockstep(tasks: list[Callable], evaluate_requests: Callable) -> list[Any]:
    """Run ``tasks`` in threads; pool their evaluation requests into one batch per round.

    Each task is ``task(request)`` where ``request(u)`` blocks until the main thread has
    evaluated ``u`` together with the pending requests of every other live task:
    ``evaluate_requests({task_id: u, ...}) -> {task_id: value}``. The main thread does all the
    evaluating (progress callbacks, cancellation and exceptions stay in the caller's thread);
    batches are composed in task order, so runs are reproducible.

    Parameters
    ----------
    tasks : list of callables
    evaluate_requests : callable

    Returns
    -------
    list
        Each task's return value, or the exception it raised.
    """
    cond = threading.Condition()
    pending: dict[int, np.ndarray] = {}
    results: dict[int, Any] = {}
    alive = set(range(len(tasks)))
    outcome: list[Any] = [None] * len(tasks)
    state = {"abort": False}

    def make_request(i):
        """Bind ``request`` to task ``i``."""

        def request(u):
            """Queue ``u`` [unit cube] for the next batch and block until its value is back."""
            with cond:
                if state["abort"]:
                    raise LockstepAborted
                pending[i] = np.array(u, float)
                cond.notify_all()
                while i not in results and not state["abort"]:
                    cond.wait()
                if state["abort"]:
                    raise LockstepAborted
                return results.pop(i)

        return request

    def runner(i):
        """Thread body: run task ``i`` and record its result or exception."""
        try:
            outcome[i] = tasks[i](make_request(i))
        except BaseException as exc:  # noqa: BLE001 - handed back to the caller
            outcome[i] = exc
        finally:
            with cond:
                alive.discard(i)
                cond.notify_all()

    threads = [threading.Thread(target=runner, args=(i,), daemon=True) for i in range(len(tasks))]
    for t in threads:
        t.start()
    try:
        while True:
            with cond:
                cond.wait_for(lambda: len(pending) == len(alive))
                if not alive:
                    break
                batch = {i: pending.pop(i) for i in sorted(pending)}
            values = evaluate_requests(batch)
            with cond:
                results.update(values)
                cond.notify_all()
    except BaseException:
        with cond:
            state["abort"] = True
            cond.notify_all()
        for t in threads:
            t.join()
        raise
    for t in threads:
        t.join()
    return outcome


def fd_stencil(u: np.ndarray, h: float, order: int = 2) -> tuple[np.ndarray, np.ndarray]:
    """Finite-difference stencil in the unit cube.

    ``order=2`` (second order): per coordinate j two points, u -/+ h e_j (central) where both
    lie in [0, 1], else u + h e_j, u + 2h e_j (one-sided, at the lower bound) or u - h e_j,
    u - 2h e_j (upper). Returns the points (2d + 1, d) (centre first) and the per-coordinate kind
    (d,): 0 central, +1 forward, -1 backward.

    ``order=1`` (first order, for smooth functions and a small h): one point per coordinate,
    u + h e_j (kind +1), or u - h e_j (kind -1) where u + h e_j leaves the cube; (d + 1, d)
    points. See :func:`fd_gradient`.
    """
    d = u.size
    idx = np.arange(d)
    if order == 1:
        kind = np.where(u + h > 1.0, -1, 1)
        pts = np.repeat(u[None, :], d + 1, axis=0)
        pts[1 + idx, idx] += kind * h
        return pts, kind
    kind = np.where(u - h < 0.0, 1, np.where(u + h > 1.0, -1, 0))
    a = np.where(kind == 0, -h, kind * h)
    b = np.where(kind == 0, h, 2.0 * kind * h)
    pts = np.repeat(u[None, :], 2 * d + 1, axis=0)
    pts[1 + 2 * idx, idx] += a
    pts[2 + 2 * idx, idx] += b
    return pts, kind


def fd_gradient(values: np.ndarray, kind: np.ndarray, h: float, order: int = 2) -> np.ndarray:
    """Gradient from values on a :func:`fd_stencil` of the same ``order`` (first axis: the
    stencil's points).

    Order 2: central (f(u+h) - f(u-h))/2h; forward (-3 f(u) + 4 f(u+h) - f(u+2h))/2h; backward
    the mirror image; all O(h^2). Order 1: k (f(u + k h) - f(u))/h with k = +/-1, O(h).
    Returns shape (d,) + values.shape[1:].
    """
    f0 = values[0]
    k = kind.reshape((-1,) + (1,) * (values.ndim - 1))
    if order == 1:
        return k * (values[1:] - f0[None]) / h
    fa, fb = values[1::2], values[2::2]
    central = (fb - fa) / (2.0 * h)
    onesided = k * (-3.0 * f0[None] + 4.0 * fa - fb) / (2.0 * h)
    return np.where(k == 0, central, onesided)


def slsqp_task(u0, bounds, maxiter, ftol):
    """A scipy SLSQP run whose function values come from a pooled ``request``.

    ``request(u)`` returns (F, G, dF, dG) at u: objective/scale, constraints g (m,), and their
    finite-difference gradient (d,) and Jacobian (m, d). SLSQP wants c(u) >= 0: c = -g.
    """
    from scipy.optimize import minimize

    def task(request):
        """One SLSQP run whose evaluations go through ``request``."""
        cache: dict[bytes, tuple] = {}

        def get(u):
            """(F, g, dF, dg) at ``u`` (clipped to the unit cube), from a small cache."""
            u = np.clip(np.asarray(u, float), 0.0, 1.0)
            key = u.tobytes()
            if key not in cache:
                if len(cache) > 16:
                    cache.clear()
                cache[key] = request(u)
            return cache[key]

        cons = {"type": "ineq", "fun": lambda u: -get(u)[1], "jac": lambda u: -get(u)[3]}
        return minimize(
            lambda u: get(u)[0],
            u0,
            jac=lambda u: get(u)[2],
            method="SLSQP",
            bounds=bounds,
            constraints=[cons],
            options={"maxiter": maxiter, "ftol": ftol},
        )

    return task


def stencil_evaluator(
    fn_eval: Callable, d: int, h: float, objective_of: Callable, scale: dict, order: int = 2
) -> Callable:
    """Build ``evaluate_requests`` for :func:`run_lockstep` from a batch evaluator: every
    request's point and its :func:`fd_stencil` go into one batch; the reply is (F, g, dF, dg).

    Parameters
    ----------
    fn_eval : callable
        ``fn_eval(U, owners) -> DesignBatch`` for unit points U (N, d) owned by request ids.
    d : int
        Number of (unit) variables.
    h : float
        Finite-difference step in the unit cube.
    objective_of : callable
        ``objective_of(batch) -> ndarray`` objective per design.
    scale : dict
        ``{"value": float or None}``; set from the first batch (median |objective|) when None.
    order : {1, 2}
        Order of the :func:`fd_stencil`.
    """

    m = 2 * d + 1 if order == 2 else d + 1

    def evaluate_requests(batch: dict[int, np.ndarray]) -> dict[int, tuple]:
        """Evaluate every request's stencil in one batch; reply (F, g, dF, dg) per task."""
        ids = list(batch)
        stencils = [fd_stencil(batch[i], h, order) for i in ids]
        pts = np.concatenate([s[0] for s in stencils])
        owners = np.repeat(ids, m)
        b = fn_eval(pts, owners)
        obj = objective_of(b)
        if scale["value"] is None:
            first = obj[::m]
            scale["value"] = float(np.median(np.abs(first))) or 1.0
        fval = obj / scale["value"]
        g = b.constraints
        out = {}
        for k, i in enumerate(ids):
            sl = slice(k * m, (k + 1) * m)
            f_k, g_k = fval[sl], g[sl]
            kind = stencils[k][1]
            df = fd_gradient(f_k, kind, h, order)
            dg = fd_gradient(g_k, kind, h, order).T
            out[i] = (float(f_k[0]), g_k[0].copy(), df, dg)
        return out

    return evaluate_requests
