"""Solver 3: particle swarm with feasibility-first constraint handling (pymoo ``PSO``; MATLAB
``particleswarm``, CPSO in the thesis)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from .problem import OptimizationProblem
from .tracking import OptimizationCancelled, OptimizationResult, Tracker


def solve_pso(
    problem: OptimizationProblem,
    pop_size: int = 24,
    max_generations: int = 50,
    seed: int = 0,
    margin: float = 0.05,
    progress: Callable | None = None,
    stop: Callable | None = None,
) -> OptimizationResult:
    """Particle swarm with feasibility-first constraint handling (pymoo ``PSO``).

    pymoo's adaptive PSO (Zhan et al. 2009) keeps personal and global bests by Deb's rules: a
    feasible design beats an infeasible one, two feasible ones compare by objective, two
    infeasible ones by total violation. The swarm flies in the unit cube widened by ``margin``
    on each side and every particle is evaluated at its projection onto the bounds, so optima on
    a bound (common here) are reachable. Each generation is one vectorised evaluation.

    Parameters
    ----------
    problem : OptimizationProblem or FunctionProblem
    pop_size : int
        Swarm size.
    max_generations : int
        Generation limit (pymoo's default termination may stop earlier on stagnation).
    seed : int
        pymoo seed (Latin-hypercube start, velocities, coefficients).
    margin : float
        Widening of the flight box in the unit cube [-].
    progress, stop : callable or None
        ``progress(fraction, text)`` after every generation; ``stop() -> bool`` cancels.

    Returns
    -------
    OptimizationResult

    References
    ----------
    Kennedy J., Eberhart R., "Particle swarm optimization", Proc. ICNN 1995.
    Zhan Z.-H. et al., "Adaptive particle swarm optimization", IEEE TSMC-B 39(6), 2009.
    Deb K., "An efficient constraint handling method for genetic algorithms", CMAME 186, 2000.
    Blank J., Deb K., "pymoo: Multi-objective optimization in Python", IEEE Access 8, 2020.
    """
    from pymoo.algorithms.soo.nonconvex.pso import PSO
    from pymoo.core.problem import Problem
    from pymoo.termination.default import DefaultSingleObjectiveTermination

    pop_size, max_generations = int(pop_size), int(max_generations)
    if pop_size < 2 or max_generations < 1:
        raise ValueError(
            f"PSO settings: need pop_size >= 2 and max_generations >= 1 "
            f"(got {pop_size}, {max_generations})"
        )
    settings = {"pop_size": pop_size, "max_generations": max_generations, "margin": margin}
    d = problem.n_var
    tr = Tracker(problem, pop_size * max_generations, progress, stop, "Particle swarm")
    label = "Particle swarm (pymoo)"

    class _Swarm(Problem):
        """pymoo view of the problem: unit cube widened by ``margin``, evaluated at its projection."""

        def __init__(self):
            """Unit-cube problem widened by ``margin``, 1 objective, one constraint per g."""
            super().__init__(
                n_var=d,
                n_obj=1,
                n_ieq_constr=problem.n_constr,
                xl=np.full(d, -margin),
                xu=np.full(d, 1.0 + margin),
            )

        def _evaluate(self, X, out, *args, **kwargs):
            """pymoo hook: one vectorised evaluation of the population X into out['F'], out['G']."""
            b = tr(np.clip(X, 0.0, 1.0))
            out["F"] = b.objective(problem.objective)[:, None]
            out["G"] = b.constraints

    algorithm = PSO(pop_size=pop_size, adaptive=True)
    termination = DefaultSingleObjectiveTermination(
        xtol=1e-6, cvtol=1e-8, ftol=1e-7, period=15, n_max_gen=max_generations
    )
    algorithm.setup(_Swarm(), termination=termination, seed=int(seed), verbose=False)
    try:
        while algorithm.has_next():
            algorithm.next()
    except OptimizationCancelled:
        return tr.result("pso", label, "cancelled", "cancelled by the user", seed, settings)
    gens = algorithm.n_gen - 1 if algorithm.n_gen else 0
    status = "budget" if gens >= max_generations else "converged"
    message = f"{gens} generations of {pop_size} particles"
    return tr.result("pso", label, status, message, seed, settings)
