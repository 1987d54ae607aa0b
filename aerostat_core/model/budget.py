"""Per-request compute budget: refuse a request whose cost would tie up a server for minutes.

The cost of the static model is nearly proportional to the number of tether-march steps it
takes, so a request is measured in *units*::

    units = tether segments x wind speeds x cases

where "cases" counts the designs the request evaluates (saved cases compared, points of a
sensitivity sweep or map, evaluations of an optimisation). On the 2-core reference machine one
unit costs about 1.5-6 us (the thesis baseline, 50 segments x 22 speeds, designs in about
6 ms of CPU; a 2000-segment design in 0.06 s; measured 2026-12 with benchmarks/bench_core.py
and a 2000-segment run), so :data:`MAX_UNITS` keeps a request to a few seconds
of CPU. Every library entry point checks its request with one call of :func:`check`; the app
catches :class:`BudgetError` like any other input error and shows its message, which says what
to reduce.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from aerostat_core.base.deprecation import deprecated_aliases

#: Largest request [units = segments x wind speeds x cases]. The thesis baseline is 1 100;
#: 200 saved baseline cases 220 000; 5000 segments at 0.1 m/s steps (201 speeds) 1 005 000.
MAX_UNITS = 500_000


class BudgetError(ValueError):
    """A request over :data:`MAX_UNITS`; ``units`` is its cost, the message what to reduce."""

    def __init__(self, message: str, units: int) -> None:
        super().__init__(message)
        self.units = units


def units(segments: int, speeds: int, cases: int = 1) -> int:
    """Cost of a request in units (see the module docstring).

    >>> units(50, 22, 1)
    1100
    """
    return int(segments) * max(int(speeds), 1) * max(int(cases), 1)


def check(segments: int, speeds: int, cases: int = 1, what: str = "This design") -> int:
    """Return the cost of a request, or raise :class:`BudgetError` when it exceeds
    :data:`MAX_UNITS`, naming the three factors and what to reduce.

    Parameters
    ----------
    segments : int
        ``Configuration.tether_segments`` [-].
    speeds : int
        Wind speeds evaluated per design (the sweep plus the design wind) [-].
    cases : int
        Designs evaluated by the request [-].
    what : str
        What the request is, for the message ("This comparison", ...).

    >>> check(50, 22)
    1100
    >>> check(5000, 201)
    Traceback (most recent call last):
    ...
    aerostat_core.model.budget.BudgetError: This design needs 5000 tether segments x 201 wind speeds x 1 case = 1,005,000 units of work; the limit is 500,000. Reduce the tether segments to at most 2487 (50 is within 1 mm of 2000), or use a larger wind step.
    """
    cost = units(segments, speeds, cases)
    if cost <= MAX_UNITS:
        return cost
    speeds, cases = max(int(speeds), 1), max(int(cases), 1)
    max_segments = MAX_UNITS // (speeds * cases)
    hints = []
    if max_segments >= 10:
        hints.append(
            f"Reduce the tether segments to at most {max_segments} (50 is within 1 mm of 2000)"
        )
    else:
        hints.append("Reduce the tether segments (50 is within 1 mm of 2000)")
    if speeds > 1:
        hints.append("use a larger wind step")
    if cases > 1:
        hints.append(f"use fewer cases or points (at most {MAX_UNITS // (segments * speeds)})")
    advice = ", or ".join(hints) + "."
    plural = "" if cases == 1 else "s"
    raise BudgetError(
        f"{what} needs {segments} tether segments x {speeds} wind speeds x {cases} case{plural} "
        f"= {cost:,} units of work; the limit is {MAX_UNITS:,}. {advice}",
        cost,
    )


def check_design(req: Any, cfg: Any, cases: int = 1, what: str = "This design") -> int:
    """:func:`check` for ``cases`` designs of (req, cfg): the sweep's speeds plus the design
    wind."""
    from aerostat_core.model.performance import wind_speeds  # the sweep, defined once

    return check(cfg.tether_segments, wind_speeds(req).size + 1, cases, what)


def check_cases(cases: Mapping[str, Any], what: str = "This comparison") -> int:
    """:func:`check` for a set of saved cases (inputs dicts or (req, cfg) pairs): the sum of
    their costs against the limit."""
    from aerostat_core.model.io import inputs_from_dict
    from aerostat_core.model.performance import wind_speeds

    total, worst = 0, (50, 1)
    for inputs in cases.values():
        try:
            req, cfg = inputs if isinstance(inputs, tuple) else inputs_from_dict(dict(inputs))
        except (ValueError, TypeError):
            continue  # an invalid case is reported, by name, by the caller's own loop
        one = (cfg.tether_segments, wind_speeds(req).size + 1)
        total += units(*one)
        worst = max(worst, one, key=lambda x: x[0] * x[1])
    if total <= MAX_UNITS:
        return total
    n = len(cases)
    # Report it as the costliest case's factors times the number of cases.
    return check(worst[0], worst[1], max(n, math.ceil(total / units(*worst))), what)


def optimization_evaluations(solver: str, settings: Mapping[str, Any]) -> int:
    """Upper estimate of the designs one optimiser run evaluates (each at the design wind).

    >>> optimization_evaluations("pso", {"pop_size": 20, "max_generations": 40})
    820
    """
    if solver == "slsqp":  # finite-difference gradient: 3 variables + 1 per iteration
        return int(settings.get("n_starts", 4)) * int(settings.get("maxiter", 60)) * 4
    if solver == "surrogate":
        return int(settings.get("max_evaluations", 160))
    if solver == "pso":
        pop, gens = int(settings.get("pop_size", 20)), int(settings.get("max_generations", 40))
        return pop * (gens + 1)
    return 1


def check_optimization(problem: Any, solver: str, settings: Mapping[str, Any]) -> int:
    """:func:`check` for one optimiser run on ``problem`` (a problem without a configuration,
    e.g. a test function, costs nothing)."""
    cfg = getattr(problem, "configuration", None) or getattr(problem, "cfg", None)
    segments = getattr(cfg, "tether_segments", None)
    if segments is None:
        return 0
    n = optimization_evaluations(solver, settings)
    return check(segments, 1, n, f"This optimisation ({solver})")


#: Deprecated British spellings -> the current names (docs/architecture.md §7).
DEPRECATED_NAMES = {
    "optimisation_evaluations": "optimization_evaluations",
    "check_optimisation": "check_optimization",
}

__getattr__ = deprecated_aliases(__name__, globals(), DEPRECATED_NAMES)
