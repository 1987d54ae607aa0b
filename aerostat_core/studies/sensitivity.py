"""Sensitivity of the design to its three variables (thesis §3.2.2, Fig. 3.12, Tables 4.4-4.6).

* :func:`one_at_a_time` - one-factor-at-a-time sweeps of f, Delta S_f and Delta l_f around a
  baseline, the others held; by default the hull is re-sized at every point (V*(x), as in the
  optimiser), optionally held at the baseline volume. Outputs at the design wind: total mass,
  volume, blow-by, equilibrium angle, dynamic lift, plus which constraints fail.
* :func:`two_variable_map` - a grid over two variables (the third held) of total mass, volume
  and blow-by. Held volume (default) shows how the blow-by moves and where it crosses the limit
  (the feasible region for that hull); re-sized shows the mass of the smallest feasible hull.

Every sweep or map is one vectorised call of :func:`aerostat_core.optimize.evaluate_designs`.
The thesis' sweep ranges were not found (docs/methods.md §1.11); the defaults are the optimiser's
bounds (:data:`aerostat_core.optimize.DEFAULT_BOUNDS`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from aerostat_core.model import budget
from aerostat_core.model.inputs import Configuration, Requirement
from aerostat_core.optimize.batch import (
    DEFAULT_BOUNDS,
    VARIABLE_INFO,
    VARIABLES,
    DesignBatch,
    check_bounds,
)
from aerostat_core.optimize.batch import evaluate_designs as _evaluate

#: Sweep outputs: key of :class:`DesignBatch` -> (label, unit).
OUTPUTS: dict[str, tuple[str, str]] = {
    "total_mass": ("Total mass", "kg"),
    "volume": ("Hull volume", "m3"),
    "blow_by": ("Blow-by at the design wind", "m"),
    "alpha": ("Equilibrium angle at the design wind", "deg"),
    "dynamic_lift": ("Dynamic lift at the design wind", "N"),
}

#: Largest number of points per sweep axis (keeps one batch call within memory and time).
MAX_POINTS = 101


def _check_points(n: Any, name: str = "n_points") -> int:
    """Validate a point count: an integer in [2, MAX_POINTS]."""
    try:
        k = int(n)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {n!r} is not an integer; valid [2, {MAX_POINTS}]") from None
    if k != n or not 2 <= k <= MAX_POINTS:
        raise ValueError(f"{name} = {n!r} is outside the valid range [2, {MAX_POINTS}]")
    return k


def baseline_variables(cfg: Configuration) -> dict[str, float]:
    """The configuration's design variables {name: value} (f [-], Delta S_f [%], Delta l_f [-])."""
    return {
        "fineness_ratio": float(cfg.hull.fineness_ratio),
        "area_change": float(cfg.fins.area_change),
        "position": float(cfg.fins.position),
    }


def baseline_volume(req: Requirement, cfg: Configuration) -> float:
    """The baseline hull volume [m3]: the configuration's, or V*(x0) sized when it has none."""
    req = req.resolved()
    if cfg.hull.volume is not None:
        return float(cfg.hull.volume)
    return float(_evaluate(req, cfg).volume[0])


def _ranges(ranges: Mapping[str, Sequence[float]] | None) -> dict[str, tuple[float, float]]:
    """Sweep ranges for all three variables (missing ones from DEFAULT_BOUNDS), validated."""
    full = dict(DEFAULT_BOUNDS)
    if ranges is not None and not (isinstance(ranges, Mapping) and len(ranges) == 0):
        full.update(check_bounds(ranges))  # the one bounds check (it refuses a non-mapping)
    return check_bounds(full)


@dataclass(frozen=True)
class Sweep:
    """One variable swept, the others at the baseline.

    Attributes
    ----------
    variable : str
    values : ndarray
        Swept values (units of :data:`aerostat_core.optimize.VARIABLE_INFO`).
    designs : DesignBatch
        The evaluated designs, one per value.
    """

    variable: str
    values: np.ndarray
    designs: DesignBatch

    def output(self, key: str) -> np.ndarray:
        """Values of an output of :data:`OUTPUTS` along the sweep."""
        if key not in OUTPUTS:
            raise ValueError(f"output = {key!r}: choose one of {', '.join(OUTPUTS)}")
        return np.asarray(getattr(self.designs, key), float)


@dataclass(frozen=True)
class SensitivityResult:
    """One-factor-at-a-time sweeps around a baseline.

    Attributes
    ----------
    baseline : dict
        Baseline design variables.
    baseline_design : dict
        :meth:`DesignBatch.row` of the baseline (at the baseline or sized volume).
    resize : bool
        True: hull re-sized at every point; False: held at ``volume_held``.
    volume_held : float or None
        Held volume [m3].
    blow_by_limit, design_wind : float
        Requirement values [m], [m/s].
    sweeps : dict
        {variable: Sweep}.
    """

    baseline: dict
    baseline_design: dict
    resize: bool
    volume_held: float | None
    blow_by_limit: float
    design_wind: float
    sweeps: dict

    def rows(self) -> list[dict[str, Any]]:
        """Every sweep point as a row (variable, value, design outputs with units)."""
        out = []
        for name, sw in self.sweeps.items():
            for i, v in enumerate(sw.values):
                out.append({"variable": name, "value": float(v), **sw.designs.row(i)})
        return out

    def summary_rows(self) -> list[dict[str, Any]]:
        """Per variable: the change of mass and volume over the sweep range relative to the
        baseline [%], and the least and largest feasible value."""
        b = self.baseline_design
        rows = []
        for name, sw in self.sweeps.items():
            m, vol = sw.designs.total_mass, sw.designs.volume
            feas = sw.designs.feasible
            label, unit, _ = VARIABLE_INFO[name]
            rows.append(
                {
                    "variable": name,
                    "label": label,
                    "unit": unit,
                    "baseline": self.baseline[name],
                    "low": float(sw.values[0]),
                    "high": float(sw.values[-1]),
                    "mass_at_low_kg": float(m[0]),
                    "mass_at_high_kg": float(m[-1]),
                    "mass_change_low_pct": float(100.0 * (m[0] / b["total_mass_kg"] - 1.0)),
                    "mass_change_high_pct": float(100.0 * (m[-1] / b["total_mass_kg"] - 1.0)),
                    "volume_change_low_pct": float(100.0 * (vol[0] / b["volume_m3"] - 1.0)),
                    "volume_change_high_pct": float(100.0 * (vol[-1] / b["volume_m3"] - 1.0)),
                    "feasible_from": float(sw.values[feas].min()) if feas.any() else float("nan"),
                    "feasible_to": float(sw.values[feas].max()) if feas.any() else float("nan"),
                }
            )
        return rows


def one_at_a_time(
    req: Requirement,
    cfg: Configuration,
    ranges: Mapping[str, Sequence[float]] | None = None,
    n_points: int = 11,
    resize: bool = True,
) -> SensitivityResult:
    """One-factor-at-a-time sweeps of f, Delta S_f and Delta l_f around the configuration.

    Each variable takes ``n_points`` evenly spaced values over its range (plus its baseline
    value when that lies inside), the other two stay at the baseline. All 3 sweeps and the
    baseline are evaluated in one vectorised call.

    Parameters
    ----------
    req, cfg : Requirement, Configuration
        The baseline; ``cfg``'s design variables are the centre of the sweeps.
    ranges : mapping or None
        {variable: (low, high)} (units of :data:`~aerostat_core.optimize.VARIABLE_INFO`);
        missing variables use :data:`~aerostat_core.optimize.DEFAULT_BOUNDS`.
    n_points : int
        Points per sweep, valid [2, 101].
    resize : bool
        True: V*(x) at each point (smallest hull meeting the blow-by limit, positive free lift,
        taut tether); False: the baseline volume throughout (the configuration's, or V*(x0)).

    Returns
    -------
    SensitivityResult

    Raises
    ------
    ValueError
        Bad ranges (empty, low > high, outside the engine's valid range) or point count.
    """
    req = req.resolved()
    rng = _ranges(ranges)
    n = _check_points(n_points)
    budget.check(cfg.tether_segments, 1, 3 * n + 1, "These sweeps")
    x0 = baseline_variables(cfg)
    vol = None if resize else baseline_volume(req, cfg)
    values = {}
    for name in VARIABLES:
        lo, hi = rng[name]
        v = np.linspace(lo, hi, n)
        if lo < x0[name] < hi:
            v = np.unique(np.append(v, x0[name]))
        values[name] = v
    cols = {k: [np.array([x0[k]])] for k in VARIABLES}
    for name in VARIABLES:
        for k in VARIABLES:
            cols[k].append(values[name] if k == name else np.full(values[name].size, x0[k]))
    f, dsf, pos = (np.concatenate(cols[k]) for k in VARIABLES)
    b = _evaluate(req, cfg, f, dsf, pos, volume=vol)
    sweeps, start = {}, 1
    for name in VARIABLES:
        m = values[name].size
        sweeps[name] = Sweep(name, values[name], b.take(np.arange(start, start + m)))
        start += m
    return SensitivityResult(
        baseline=x0,
        baseline_design=b.row(0),
        resize=bool(resize),
        volume_held=vol,
        blow_by_limit=float(req.blow_by_limit),
        design_wind=float(req.design_wind),
        sweeps=sweeps,
    )


@dataclass(frozen=True)
class SensitivityMap:
    """Two variables on a grid, the third held at the baseline.

    Attributes
    ----------
    x_variable, y_variable : str
    x, y : ndarray
        Grid values (nx,), (ny,).
    total_mass [kg], volume [m3], blow_by [m] : ndarray, shape (ny, nx)
    feasible : ndarray of bool, shape (ny, nx)
        Every constraint met (at the held or sized volume).
    resize : bool
    volume_held : float or None
        Held volume [m3] when ``resize`` is False.
    blow_by_limit : float
        [m], the contour drawn on the map.
    baseline : dict
        Baseline design variables.
    """

    x_variable: str
    y_variable: str
    x: np.ndarray
    y: np.ndarray
    total_mass: np.ndarray
    volume: np.ndarray
    blow_by: np.ndarray
    feasible: np.ndarray
    resize: bool
    volume_held: float | None
    blow_by_limit: float
    baseline: dict

    def rows(self) -> list[dict[str, Any]]:
        """Grid points as rows (long format, units in the keys)."""
        out = []
        for j, yv in enumerate(self.y):
            for i, xv in enumerate(self.x):
                out.append(
                    {
                        self.x_variable: float(xv),
                        self.y_variable: float(yv),
                        "total_mass_kg": float(self.total_mass[j, i]),
                        "volume_m3": float(self.volume[j, i]),
                        "blow_by_m": float(self.blow_by[j, i]),
                        "feasible": bool(self.feasible[j, i]),
                    }
                )
        return out


def two_variable_map(
    req: Requirement,
    cfg: Configuration,
    x_variable: str = "fineness_ratio",
    y_variable: str = "area_change",
    ranges: Mapping[str, Sequence[float]] | None = None,
    n: int = 20,
    resize: bool = False,
) -> SensitivityMap:
    """Total mass, volume and blow-by over a grid of two design variables (one batch call).

    Parameters
    ----------
    req, cfg : Requirement, Configuration
    x_variable, y_variable : str
        Two different names of :data:`~aerostat_core.optimize.VARIABLES`.
    ranges : mapping or None
        As in :func:`one_at_a_time`.
    n : int
        Points per axis, valid [2, 101] (n x n designs).
    resize : bool
        False (default): hull held at the baseline volume, so the map shows mass and blow-by of
        that hull and the blow-by-limit contour bounds its feasible region. True: V*(x) at each
        point (mass of the smallest feasible hull; blow-by equals the limit wherever sizing
        succeeds).

    Returns
    -------
    SensitivityMap
    """
    req = req.resolved()
    for v in (x_variable, y_variable):
        if v not in VARIABLES:
            raise ValueError(f"map variable {v!r} is unknown; valid: {', '.join(VARIABLES)}")
    if x_variable == y_variable:
        raise ValueError(f"the map needs two different variables (both are {x_variable!r})")
    rng = _ranges(ranges)
    k = _check_points(n, "n")
    budget.check(cfg.tether_segments, 1, k * k, "This map")
    x0 = baseline_variables(cfg)
    xs = np.linspace(*rng[x_variable], k)
    ys = np.linspace(*rng[y_variable], k)
    X, Y = np.meshgrid(xs, ys)
    cols = {name: np.full(X.size, x0[name]) for name in VARIABLES}
    cols[x_variable] = X.ravel()
    cols[y_variable] = Y.ravel()
    vol = None if resize else baseline_volume(req, cfg)
    b = _evaluate(
        req, cfg, cols["fineness_ratio"], cols["area_change"], cols["position"], volume=vol
    )
    shape = X.shape
    return SensitivityMap(
        x_variable=x_variable,
        y_variable=y_variable,
        x=xs,
        y=ys,
        total_mass=b.total_mass.reshape(shape),
        volume=b.volume.reshape(shape),
        blow_by=b.blow_by.reshape(shape),
        feasible=b.feasible.reshape(shape),
        resize=bool(resize),
        volume_held=vol,
        blow_by_limit=float(req.blow_by_limit),
        baseline=x0,
    )
