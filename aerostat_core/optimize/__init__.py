"""Design optimisation: one problem definition, three solvers that agree, and the trade-off curve.

The problem (thesis §3.2, Tables 4.7-4.12; docs/methods.md §1.12, G4-G6, G14)
------------------------------------------------------------------------
Design variables x = [f, Delta S_f, Delta l_f]: hull fineness ratio [-], fin-area change from
the statistical size [%] and fin root leading-edge station / hull length [-].

Objective: minimise the total mass m_Total(x, V*(x)) [kg] (gas, payload and tether included), or
the hull volume (= the helium bill) as an option.

Volume is *not* a design variable: it enters as the smallest hull that meets the requirement for
the given x, V*(x) = :func:`aerostat_core.model.sizing.size_volume` (blow-by at the design wind <= the
limit and every other constraint of the table). This nested form is what makes "fins supply dynamic lift,
so a smaller hull suffices" visible to an optimiser that only moves f, S_f and l_f (docs/methods.md
G4). The sizing brackets V* to about 1e-4 relative; :func:`evaluate_designs` finishes it with one
secant step on the binding constraint so that V*(x) is smooth enough for finite-difference gradients.

Constraints g_i(x) <= 0: the whole constraint table of :mod:`aerostat_core.model.constraints`
(blow-by, altitude loss, free-lift margin, taut tether, tether angle, tether safety factor at the
design and the survival wind, fin stall, static and weathervane stability, fins on the hull), all
dimensionless, evaluated on the sized design. The same table sizes V*(x), so an x whose V*
exists meets every constraint except those that volume cannot fix.

Solvers (each seeded, each returns its convergence history and number of evaluations)
-------------------------------------------------------------------------------------
* :func:`solve_slsqp` - gradient-based SLSQP (``scipy.optimize.minimize``) from several starts,
  second-order finite-difference gradients. All starts run in lock-step and every stencil
  of every start is evaluated in one vectorised call (MATLAB ``fmincon`` + ``MultiStart``).
* :func:`solve_surrogate` - RBF surrogate loop (``scipy.stats.qmc`` Sobol start,
  ``scipy.interpolate.RBFInterpolator`` for the objective and every constraint, batches chosen by
  a weighted merit of predicted objective and distance to evaluated points, adaptive search radius;
  Regis & Shoemaker 2007, in the spirit of MATLAB ``surrogateopt``).
* :func:`solve_pso` - particle swarm, pymoo's ``PSO`` with its native feasibility-first rules
  (Deb 2000) for the personal and global bests (MATLAB ``particleswarm``, CPSO in the thesis).

The trade-off (beyond the thesis)
---------------------------------
:func:`pareto_front` - the minimum-mass design for each blow-by limit (epsilon-constraint method).
Because V*(x) only exists for one limit at a time, the front frees the volume instead: each
epsilon problem is min m(x, V) s.t. blow-by(x, V) <= epsilon and the other constraints, with V a
fourth variable. Its solution equals the nested optimum at that limit (tested), all epsilon
problems run in lock-step in one batched evaluation per iteration, and every point is a
converged constrained optimum that meets every constraint. :func:`pareto_nsga2` (pymoo NSGA-II
on the same four variables) is the independent cross-check.

Modules (one job each)
----------------------
* :mod:`.batch` - the vocabulary (variables, bounds, constraints, objectives) and
  :func:`evaluate_designs` (sized V*(x), one vectorised pass per batch);
* :mod:`.problem` - :class:`OptimizationProblem` and :class:`FunctionProblem`;
* :mod:`.tracking` - :class:`History`, :class:`OptimizationResult`, the solvers' ``Tracker`` and
  :class:`OptimizationCancelled`;
* :mod:`.lockstep` - pooled SLSQP runs and their finite-difference stencils;
* :mod:`.slsqp`, :mod:`.surrogate`, :mod:`.pso` - the three solvers;
* :mod:`.compare` - run levels, :func:`solve`, :func:`compare_solvers` and their tables;
* :mod:`.pareto` - the trade-off front (epsilon-constraint and NSGA-II);
* :mod:`.curves` - baseline versus optimum performance over the wind.

Python names use the US spelling of ``optimize`` (as scipy.optimize and pymoo do):
``OptimizationProblem``, ``OptimizationResult``, ``OptimizationCancelled``. The British names
``Optimisation*`` still resolve, with a ``DeprecationWarning``, for one release.
"""

from __future__ import annotations

from aerostat_core.base.deprecation import deprecated_aliases

from .batch import (
    ACTIVE_TOL,
    BOUNDS_REASONS,
    CONSTRAINT_TEXT,
    CONSTRAINTS,
    DEFAULT_BOUNDS,
    FEASIBILITY_TOL,
    OBJECTIVES,
    VARIABLE_INFO,
    VARIABLES,
    BoundsError,
    DesignBatch,
    check_bounds,
    evaluate_designs,
)
from .compare import (
    SETTINGS,
    SOLVERS,
    THESIS_REPORTED,
    agreement,
    baseline_vs_optimum,
    compare_solvers,
    comparison_rows,
    design_change_rows,
    history_rows,
    optimum_configuration,
    optimum_inputs,
    solve,
    thesis_comparison_rows,
)
from .curves import PERFORMANCE_CURVES, curves_of, performance_comparison_rows, performance_curves
from .pareto import ParetoFront, default_limits, nondominated_mask, pareto_front, pareto_nsga2
from .problem import FunctionBatch, FunctionProblem, OptimizationProblem
from .pso import solve_pso
from .slsqp import solve_slsqp
from .surrogate import solve_surrogate
from .tracking import History, OptimizationCancelled, OptimizationResult

__all__ = [
    "ACTIVE_TOL",
    "BOUNDS_REASONS",
    "BoundsError",
    "CONSTRAINTS",
    "CONSTRAINT_TEXT",
    "DEFAULT_BOUNDS",
    "FEASIBILITY_TOL",
    "OBJECTIVES",
    "PERFORMANCE_CURVES",
    "SETTINGS",
    "SOLVERS",
    "THESIS_REPORTED",
    "VARIABLES",
    "VARIABLE_INFO",
    "DesignBatch",
    "FunctionBatch",
    "FunctionProblem",
    "History",
    "OptimizationCancelled",
    "OptimizationProblem",
    "OptimizationResult",
    "ParetoFront",
    "agreement",
    "baseline_vs_optimum",
    "curves_of",
    "design_change_rows",
    "optimum_configuration",
    "check_bounds",
    "compare_solvers",
    "comparison_rows",
    "default_limits",
    "evaluate_designs",
    "history_rows",
    "nondominated_mask",
    "optimum_inputs",
    "pareto_front",
    "pareto_nsga2",
    "performance_comparison_rows",
    "performance_curves",
    "solve",
    "solve_pso",
    "solve_slsqp",
    "solve_surrogate",
    "thesis_comparison_rows",
]

#: Deprecated British spellings -> the current names (removed in the release after next).
DEPRECATED_NAMES = {
    "OptimisationProblem": "OptimizationProblem",
    "OptimisationResult": "OptimizationResult",
    "OptimisationCancelled": "OptimizationCancelled",
}

__getattr__ = deprecated_aliases(__name__, globals(), DEPRECATED_NAMES)
