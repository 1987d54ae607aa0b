"""The sizing problem with the hull volume as a design variable: what SLSQP works on.

The nested form of :class:`~aerostat_core.optimize.OptimizationProblem` minimises
m(x, V*(x)), with V*(x) the smallest hull meeting the constraint table for the design variables
x. V*(x) has a kink (and, where the weathervane-stability constraint takes over from blow-by, a
jump) wherever the constraint that sizes the hull changes, and the thesis optimum sits on such
a boundary. A finite-difference gradient across it is wrong by the size of the jump, so SLSQP
spent most of its iterations on line searches there, and every evaluation paid a sizing loop.

:class:`VolumeVariableProblem` states the same problem without the inner loop
(docs/methods.md §1.12, G4):

.. math::

    \\min_{x, V} \\; m(x, V) \\quad \\text{s.t.} \\quad g_i(x, V) \\le 0 \\;\\; (i \\in
    \\text{constraint table}), \\quad x_{lo} \\le x \\le x_{hi}, \\quad V_{min} \\le V \\le V_{max}

Each g_i(x, V) and m(x, V) is smooth in (x, V) (no sizing, so no jump), a boundary between two
binding constraints is a corner of the feasible set that SLSQP handles through its active set,
and one evaluation is one design evaluation. Because the total mass and the volume both grow
with V at fixed x, and the feasible volumes at fixed x are the interval above V*(x), the
solution is the nested optimum: V = V*(x_opt). The Pareto front (:mod:`.pareto`) solves the same
formulation with the blow-by limit varied.

The volume's unit coordinate is logarithmic over the sizing range
(:data:`aerostat_core.model.sizing.VOLUME_MIN` to :data:`~aerostat_core.model.sizing.VOLUME_MAX`).
"""

from __future__ import annotations

import math

import numpy as np

from aerostat_core.model.sizing import VOLUME_MAX, VOLUME_MIN
from aerostat_core.optimize.batch import VARIABLES, DesignBatch, evaluate_designs
from aerostat_core.optimize.problem import OptimizationProblem

_LOGV = (math.log(VOLUME_MIN), math.log(VOLUME_MAX))


class VolumeVariableProblem:
    """:class:`OptimizationProblem` ``nested`` with the hull volume V [m3] as the last variable.

    Parameters
    ----------
    nested : OptimizationProblem
        The sized problem: its requirement, configuration, objective, variables and bounds.

    Notes
    -----
    The interface is the one the solvers' :class:`~aerostat_core.optimize.tracking.Tracker`
    uses (``names``, ``lower``, ``upper``, ``from_unit``, ``to_unit``, ``evaluate``,
    ``variables_dict``, ``objective``). ``variables_dict`` returns the three design variables
    only: the volume is in the evaluated design's row.

    Examples
    --------
    >>> from aerostat_core import thesis_baseline
    >>> p = VolumeVariableProblem(OptimizationProblem(*thesis_baseline()))
    >>> p.names
    ('fineness_ratio', 'area_change', 'position', 'volume')
    >>> from aerostat_core.model.sizing import VOLUME_MAX, VOLUME_MIN
    >>> v = float(p.from_unit([0.5, 0.5, 0.5, 0.5])[-1])  # the geometric mean of the range
    >>> abs(v - (VOLUME_MIN * VOLUME_MAX) ** 0.5) < 1e-9 * v
    True
    """

    def __init__(self, nested: OptimizationProblem) -> None:
        """Wrap ``nested`` (see the class docstring)."""
        self.nested = nested
        self.requirement = nested.requirement
        self.configuration = nested.configuration
        self.objective = nested.objective
        self.names = (*nested.names, "volume")
        self.lower = np.append(nested.lower, VOLUME_MIN)
        self.upper = np.append(nested.upper, VOLUME_MAX)

    @property
    def n_var(self) -> int:
        """Number of variables: the nested problem's and the volume."""
        return len(self.names)

    def from_unit(self, u) -> np.ndarray:
        """Physical variables of unit-cube points u (n, d) or (d,): the design variables
        linearly, the volume [m3] logarithmically, V = exp(ln V_min + u (ln V_max - ln V_min))."""
        u = np.asarray(u, float)
        x = np.array(self.nested.from_unit(u[..., :-1]), float)
        v = np.exp(_LOGV[0] + u[..., -1:] * (_LOGV[1] - _LOGV[0]))
        return np.concatenate([x, v], axis=-1)

    def to_unit(self, x) -> np.ndarray:
        """Unit-cube coordinates of physical variables (inverse of :meth:`from_unit`)."""
        x = np.asarray(x, float)
        u = np.array(self.nested.to_unit(x[..., :-1]), float)
        s = (np.log(x[..., -1:]) - _LOGV[0]) / (_LOGV[1] - _LOGV[0])
        return np.concatenate([u, s], axis=-1)

    def evaluate(self, x) -> DesignBatch:
        """Evaluate designs x (n, d) at their own volumes (no sizing; one vectorised call)."""
        x = np.atleast_2d(np.asarray(x, float))
        v = self.nested.full_variables(x[:, :-1])
        return evaluate_designs(
            self.requirement,
            self.configuration,
            v["fineness_ratio"],
            v["area_change"],
            v["position"],
            volume=x[:, -1],
        )

    def variables_dict(self, x) -> dict[str, float]:
        """The three design variables of one point x (d,) as {name: value}."""
        return self.nested.variables_dict(np.asarray(x, float)[: len(self.nested.names)])

    def start_points(self, unit_starts: np.ndarray) -> tuple[np.ndarray, DesignBatch]:
        """Unit-cube starts of this problem from unit-cube starts of the nested one (n, d - 1):
        each with its sized volume V*(x0) (one nested evaluation of all starts). Where no hull
        meets the table at a start, the median of the sized starts' volumes (or the middle of
        the log range) starts it. Returns the starts and the sized batch (it counts as
        evaluations)."""
        x0 = self.nested.from_unit(np.clip(unit_starts, 0.0, 1.0))
        b = self.nested.evaluate(x0)
        vol = np.asarray(b.volume, float)
        ok = np.isfinite(vol) & np.asarray(b.sizing_feasible, bool)
        fill = float(np.median(vol[ok])) if ok.any() else math.sqrt(VOLUME_MIN * VOLUME_MAX)
        vol = np.where(ok, vol, fill)
        s = (np.log(np.clip(vol, VOLUME_MIN, VOLUME_MAX)) - _LOGV[0]) / (_LOGV[1] - _LOGV[0])
        return np.column_stack([np.clip(unit_starts, 0.0, 1.0), s]), b


__all__ = ["VARIABLES", "VolumeVariableProblem"]
