"""Running and comparing the solvers: run levels, :func:`solve`, :func:`compare_solvers`, the
comparison tables (thesis Table 4.12) and the baseline-to-optimum changes (thesis abstract and
Appendix H)."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from aerostat_core.model import budget
from aerostat_core.model.inputs import Configuration, Requirement

from .problem import OptimizationProblem
from .pso import solve_pso
from .slsqp import solve_slsqp
from .surrogate import solve_surrogate
from .tracking import OptimizationResult

THESIS_REPORTED = {
    "baseline_volume_m3": 170.0,
    "baseline_mass_kg": 90.65,
    "optimum_volume_m3": 120.0,
    "optimum_mass_kg": 71.6,
    "helium_cost_saved_USD": 1925.0,
}


SOLVERS: dict[str, tuple[str, Callable]] = {
    "slsqp": ("SLSQP, multi-start", solve_slsqp),
    "surrogate": ("RBF surrogate", solve_surrogate),
    "pso": ("Particle swarm (pymoo)", solve_pso),
}

#: Solver settings for the "quick" and "normal" run levels (the app's switch).
SETTINGS: dict[str, dict[str, dict[str, Any]]] = {
    "quick": {
        "slsqp": {"n_starts": 2, "maxiter": 30},
        "surrogate": {"max_evaluations": 72, "batch_size": 8, "n_initial": 16},
        "pso": {"pop_size": 16, "max_generations": 20},
    },
    "normal": {
        "slsqp": {"n_starts": 4, "maxiter": 60},
        "surrogate": {"max_evaluations": 160, "batch_size": 8, "n_initial": 16},
        "pso": {"pop_size": 20, "max_generations": 40},
    },
}


def solve(
    problem: OptimizationProblem,
    solver: str,
    setting: str = "normal",
    seed: int = 0,
    progress: Callable | None = None,
    stop: Callable | None = None,
    **overrides: Any,
) -> OptimizationResult:
    """Run one solver with the settings of a run level.

    Parameters
    ----------
    problem : OptimizationProblem or FunctionProblem
    solver : {"slsqp", "surrogate", "pso"}
    setting : {"quick", "normal"}
        Run level (:data:`SETTINGS`); ``overrides`` replace individual settings.
    seed : int
    progress, stop : callable or None
        See the solvers.
    """
    if solver not in SOLVERS:
        raise ValueError(f"solver = {solver!r}: choose one of {', '.join(SOLVERS)}")
    if setting not in SETTINGS:
        raise ValueError(f"setting = {setting!r}: choose one of {', '.join(SETTINGS)}")
    kw = {**SETTINGS[setting][solver], **overrides}
    budget.check_optimization(problem, solver, kw)
    return SOLVERS[solver][1](problem, seed=seed, progress=progress, stop=stop, **kw)


def compare_solvers(
    problem: OptimizationProblem,
    setting: str = "normal",
    seed: int = 0,
    solvers: Sequence[str] = tuple(SOLVERS),
    progress: Callable | None = None,
    stop: Callable | None = None,
) -> list[OptimizationResult]:
    """Run several solvers on the same problem (thesis Table 4.12).

    ``progress(fraction, text)`` receives the overall fraction (each solver an equal share).
    """
    out = []
    n = len(solvers)
    for k, name in enumerate(solvers):
        sub = None
        if progress is not None:

            def sub(frac, text, k=k):
                """Map a solver's own progress fraction onto its share of the comparison."""
                progress((k + frac) / n, text)

        r = solve(problem, name, setting, seed, sub, stop)
        out.append(r)
        if r.status == "cancelled":
            break
    return out


def agreement(results: Sequence[OptimizationResult]) -> float:
    """Relative spread of the objective among feasible results, (max - min)/min [-]
    (NaN when fewer than two are feasible)."""
    vals = [r.objective for r in results if r.feasible]
    if len(vals) < 2:
        return float("nan")
    return (max(vals) - min(vals)) / min(vals)


def comparison_rows(results: Sequence[OptimizationResult]) -> list[dict[str, Any]]:
    """Thesis-Table-4.12-like rows: variables, mass, volume, blow-by, evaluations, time."""
    rows = []
    for r in results:
        d = r.design
        rows.append(
            {
                "solver": r.label,
                "fineness_ratio": r.x["fineness_ratio"],
                "area_change_pct": r.x["area_change"],
                "position": r.x["position"],
                "total_mass_kg": d.get("total_mass_kg", float("nan")),
                "volume_m3": d.get("volume_m3", float("nan")),
                "blow_by_m": d.get("blow_by_m", float("nan")),
                "alpha_eq_deg": d.get("alpha_eq_deg", float("nan")),
                "gas_cost_USD": d.get("gas_cost_USD", float("nan")),
                "evaluations": r.n_evaluations,
                "batches": r.n_batches,
                "time_s": r.time_s,
                "feasible": r.feasible,
                "status": r.status,
                "active": ", ".join(r.active),
            }
        )
    return rows


def history_rows(results: Sequence[OptimizationResult]) -> list[dict[str, Any]]:
    """Convergence histories of several results as one long table."""
    rows = []
    for r in results:
        rows.extend(r.history.rows(r.label))
    return rows


def optimum_inputs(
    problem: OptimizationProblem, result: OptimizationResult
) -> tuple[Requirement, Configuration]:
    """(Requirement, Configuration) of an optimum, volume left to the sizing (``volume=None``),
    ready for :func:`aerostat_core.model.io.inputs_to_dict` ("save as case")."""
    if not all(math.isfinite(v) for v in result.x.values()):
        raise ValueError("the result has no design (the run stopped before any evaluation)")
    cfg = problem.configuration.with_design_variables(volume=None, **result.x)
    return problem.requirement, cfg


def baseline_vs_optimum(
    req: Requirement,
    cfg_baseline: Configuration,
    x_optimum: Mapping[str, float],
) -> list[dict[str, Any]]:
    """Baseline-to-optimum changes: volume, total mass, gas (helium) cost, blow-by, alpha.

    The baseline is ``cfg_baseline`` as given (its volume if set, else sized); the optimum has
    the design variables ``x_optimum`` and a sized volume. Gas cost = V x price
    (:func:`aerostat_core.model.cost.gas_fill_cost`, thesis Appendix H).

    Parameters
    ----------
    req : Requirement
    cfg_baseline : Configuration
    x_optimum : mapping
        {"fineness_ratio": [-], "area_change": [%], "position": [-]}.

    Returns
    -------
    list of dict
        Rows (quantity, unit, baseline, optimum, change).
    """
    req = req.resolved()
    from aerostat_core.model.design import design

    base = design(req, cfg_baseline)
    opt = design(req, optimum_configuration(cfg_baseline, x_optimum))
    return design_change_rows(base, opt)


def optimum_configuration(
    cfg_baseline: Configuration, x_optimum: Mapping[str, float]
) -> Configuration:
    """The baseline configuration with the design variables ``x_optimum`` and a sized volume
    (the optimum that :func:`baseline_vs_optimum` designs)."""
    return cfg_baseline.with_design_variables(volume=None, **dict(x_optimum))


def design_change_rows(base: Any, opt: Any) -> list[dict[str, Any]]:
    """The rows of :func:`baseline_vs_optimum` from two designs already made
    (:class:`aerostat_core.model.design.Design`), so a caller that has them designs nothing again."""
    items = [
        ("Hull volume", "m3", base.volume, opt.volume),
        ("Total mass", "kg", base.total_mass, opt.total_mass),
        ("Gas fill cost", "USD", base.gas_cost, opt.gas_cost),
        (
            "Fineness ratio",
            "-",
            base.configuration.hull.fineness_ratio,
            opt.configuration.hull.fineness_ratio,
        ),
        (
            "Fin-area change",
            "%",
            base.configuration.fins.area_change,
            opt.configuration.fins.area_change,
        ),
        ("Fin position", "-", base.configuration.fins.position, opt.configuration.fins.position),
        (
            "Blow-by at design wind",
            "m",
            base.design_point["blow_by_m"],
            opt.design_point["blow_by_m"],
        ),
        (
            "Equilibrium angle at design wind",
            "deg",
            base.design_point["alpha_eq_deg"],
            opt.design_point["alpha_eq_deg"],
        ),
        (
            "Dynamic lift at design wind",
            "N",
            base.design_point["dynamic_lift_N"],
            opt.design_point["dynamic_lift_N"],
        ),
        ("Free lift", "kg", base.free_lift_kg, opt.free_lift_kg),
    ]
    return [
        {
            "quantity": q,
            "unit": u,
            "baseline": float(b),
            "optimum": float(o),
            "change": float(o) - float(b),
        }
        for q, u, b, o in items
    ]


def thesis_comparison_rows(changes: Sequence[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """Our baseline-to-optimum changes next to the thesis' (abstract, Appendix H).

    Parameters
    ----------
    changes : rows of :func:`baseline_vs_optimum`.
    """
    t = THESIS_REPORTED
    ours = {r["quantity"]: r for r in changes}
    spec = [
        ("Hull volume", "m3", t["baseline_volume_m3"], t["optimum_volume_m3"]),
        ("Total mass", "kg", t["baseline_mass_kg"], t["optimum_mass_kg"]),
        ("Gas fill cost", "USD", None, None),
    ]
    rows = []
    for q, u, tb, to in spec:
        r = ours[q]
        tchange = -t["helium_cost_saved_USD"] if q == "Gas fill cost" else to - tb
        rows.append(
            {
                "quantity": q,
                "unit": u,
                "thesis_baseline": float("nan") if tb is None else tb,
                "thesis_optimum": float("nan") if to is None else to,
                "thesis_change": tchange,
                "our_baseline": r["baseline"],
                "our_optimum": r["optimum"],
                "our_change": r["change"],
            }
        )
    return rows
