"""Design optimisation: one problem definition, three solvers that agree, and the trade-off curve.

The problem (thesis §3.2, Tables 4.7-4.12; docs/methods.md §1.12, G4-G6, G14)
------------------------------------------------------------------------
Design variables x = [f, Delta S_f, Delta l_f]: hull fineness ratio [-], fin-area change from
the statistical size [%] and fin root leading-edge station / hull length [-].

Objective: minimise the total mass m_Total(x, V*(x)) [kg] (gas, payload and tether included), or
the hull volume (= the helium bill) as an option.

Volume is *not* a design variable: it enters as the smallest hull that meets the requirement for
the given x, V*(x) = :func:`aerostat_core.sizing.size_volume` (blow-by at the design wind <= the
limit and every other constraint of the table). This nested form is what makes "fins supply dynamic lift,
so a smaller hull suffices" visible to an optimiser that only moves f, S_f and l_f (docs/methods.md
G4). The sizing brackets V* to about 1e-4 relative; :func:`evaluate_designs` finishes it with one
secant step on the binding constraint so that V*(x) is smooth enough for finite-difference gradients.

Constraints g_i(x) <= 0: the whole constraint table of :mod:`aerostat_core.constraints`
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
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import budget
from .airframe import build_airframe
from .constraints import CONSTRAINTS as CONSTRAINT_TABLE
from .constraints import NAMES as CONSTRAINT_NAMES
from .constraints import TOLERANCE, constraint_state, violation_messages
from .cost import gas_fill_cost
from .inputs import Configuration, Requirement
from .sizing import VOLUME_MAX, VOLUME_MIN, size_volume

# ------------------------------------------------------------------------------------------------
# Problem vocabulary
# ------------------------------------------------------------------------------------------------

#: The thesis' design variables, in order.
VARIABLES = ("fineness_ratio", "area_change", "position")

#: Label, unit and the engine's valid range (HullSpec/FinSpec) of each design variable.
VARIABLE_INFO: dict[str, tuple[str, str, tuple[float, float]]] = {
    "fineness_ratio": ("Fineness ratio f", "-", (1.5, 8.0)),
    "area_change": ("Fin-area change ΔS_f", "%", (-50.0, 200.0)),
    "position": ("Fin position Δl_f (root LE / l)", "-", (0.4, 0.95)),
}

#: Default bounds (docs/methods.md G6 with the fin area also allowed to shrink, to -50 %: the
#: statistical fin size is a starting point, not a floor; the lower limit is the engine's).
DEFAULT_BOUNDS: dict[str, tuple[float, float]] = {
    "fineness_ratio": (2.5, 4.5),
    "area_change": (-50.0, 100.0),
    "position": (0.60, 0.75),
}

#: Constraint names, in the column order of ``DesignBatch.constraints``: the one constraint
#: table of aerostat_core.constraints.
CONSTRAINTS = CONSTRAINT_NAMES

#: Plain-language meaning of each constraint (g <= 0 means met).
CONSTRAINT_TEXT = {c.name: c.text for c in CONSTRAINT_TABLE}

#: Objectives: key -> (label, unit).
OBJECTIVES = {"total_mass": ("Total mass", "kg"), "volume": ("Hull volume", "m3")}

#: A design is feasible when every g <= this tolerance [-] (the constraint table's).
FEASIBILITY_TOL = TOLERANCE

#: A constraint counts as active (binding) at the optimum when g > -ACTIVE_TOL [-].
ACTIVE_TOL = 2e-3

#: Thesis headline numbers (abstract and Appendix H; docs/methods.md §3.1, FOUND): baseline 170 m3 /
#: 90.65 kg, optimum 120 m3 / 71.6 kg, helium saved USD 1925 (at 38.5 USD/m3, INFERRED).
THESIS_REPORTED = {
    "baseline_volume_m3": 170.0,
    "baseline_mass_kg": 90.65,
    "optimum_volume_m3": 120.0,
    "optimum_mass_kg": 71.6,
    "helium_cost_saved_USD": 1925.0,
}

# Relative probe below the sized volume for the secant finish of V*(x) (sizing brackets to ~1e-4).
_SECANT_PROBE = 5e-4


class OptimisationCancelled(Exception):
    """Raised inside a solver when its ``stop`` callback asks to stop (caught by the solver)."""


# ------------------------------------------------------------------------------------------------
# Batch evaluation of designs
# ------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class DesignBatch:
    """Evaluated designs (1-D arrays, one entry per design; SI units).

    Attributes
    ----------
    fineness_ratio, area_change, position : ndarray
        Design variables f [-], Delta S_f [%], Delta l_f [-].
    volume : ndarray
        Hull volume [m3] (sized V*(x) or given).
    sized : bool
        True when the volume was sized.
    sizing_feasible : ndarray of bool
        A volume meeting the whole constraint table exists (always True when given).
    binding : ndarray of str
        The constraint that sets the size (see :class:`~aerostat_core.sizing.SizingResult`), or
        ``"given"`` for a given volume.
    sizing_message : ndarray of str
        Why no volume is feasible ("" otherwise).
    total_mass [kg], gas_cost [USD], blow_by [m], alpha [deg], cm_alpha [1/rad],
    cm_alpha_aero (aerodynamic C_m_alpha about the centre of volume) [1/rad],
    moment_slope [N m/rad], dynamic_lift [N], drag [N], free_lift [N], buoyancy [N],
    safety_factor [-], tension_top [N], fin_te_ratio (fin trailing edge / hull length) [-],
    length [m], diameter [m] : ndarray
        Outputs at the design wind.
    blow_by_limit : ndarray
        Limit used for the blow-by constraint [m].
    stall_angle : float
        Fin stall angle [deg].
    min_safety_factor : float
        Required tether safety factor [-].
    constraints : ndarray, shape (n, len(CONSTRAINTS))
        g values in the order of ``CONSTRAINTS`` (<= 0 is met).
    constraint_value, constraint_limit : ndarray, shape (n, len(CONSTRAINTS))
        Value and limit of each constraint in its own unit (for the messages and tables).
    design_wind, survival_wind : float
        Where the wind-dependent constraints were checked [m/s].
    """

    fineness_ratio: np.ndarray
    area_change: np.ndarray
    position: np.ndarray
    volume: np.ndarray
    sized: bool
    sizing_feasible: np.ndarray
    binding: np.ndarray
    sizing_message: np.ndarray
    total_mass: np.ndarray
    gas_cost: np.ndarray
    blow_by: np.ndarray
    alpha: np.ndarray
    cm_alpha: np.ndarray
    cm_alpha_aero: np.ndarray
    moment_slope: np.ndarray
    dynamic_lift: np.ndarray
    drag: np.ndarray
    free_lift: np.ndarray
    buoyancy: np.ndarray
    safety_factor: np.ndarray
    tension_top: np.ndarray
    fin_te_ratio: np.ndarray
    length: np.ndarray
    diameter: np.ndarray
    blow_by_limit: np.ndarray
    stall_angle: float
    min_safety_factor: float
    constraints: np.ndarray
    constraint_value: np.ndarray
    constraint_limit: np.ndarray
    design_wind: float
    survival_wind: float

    def __len__(self) -> int:
        """Number of designs (points) in the batch."""
        return int(self.volume.shape[0])

    @property
    def max_violation(self) -> np.ndarray:
        """Largest constraint value max(0, g_i) per design [-]."""
        return np.maximum(np.max(self.constraints, axis=1), 0.0)

    @property
    def feasible(self) -> np.ndarray:
        """Every constraint met within :data:`FEASIBILITY_TOL` (bool per design)."""
        return np.all(self.constraints <= FEASIBILITY_TOL, axis=1)

    def objective(self, name: str = "total_mass") -> np.ndarray:
        """Objective values per design: ``"total_mass"`` [kg] or ``"volume"`` [m3]."""
        if name not in OBJECTIVES:
            raise ValueError(f"objective = {name!r}: choose one of {', '.join(OBJECTIVES)}")
        return np.asarray(getattr(self, name), float)

    def violations(self, i: int) -> list[str]:
        """Plain-language reasons why design ``i`` is infeasible (empty when feasible)."""
        out = [str(self.sizing_message[i])] if not self.sizing_feasible[i] else []
        return out + violation_messages(self.constraints[i], self.constraint_value[i],
                                        self.constraint_limit[i], self.design_wind,
                                        self.survival_wind)

    def row(self, i: int) -> dict[str, Any]:
        """Design ``i`` as a flat dict with units in the keys (tables, CSV)."""
        return {
            "fineness_ratio": float(self.fineness_ratio[i]),
            "area_change_pct": float(self.area_change[i]),
            "position": float(self.position[i]),
            "volume_m3": float(self.volume[i]),
            "total_mass_kg": float(self.total_mass[i]),
            "gas_cost_USD": float(self.gas_cost[i]),
            "blow_by_m": float(self.blow_by[i]),
            "alpha_eq_deg": float(self.alpha[i]),
            "cm_alpha_per_rad": float(self.cm_alpha[i]),
            "cm_alpha_aero_cv_per_rad": float(self.cm_alpha_aero[i]),
            "dynamic_lift_N": float(self.dynamic_lift[i]),
            "free_lift_N": float(self.free_lift[i]),
            "safety_factor": float(self.safety_factor[i]),
            "fin_te_over_length": float(self.fin_te_ratio[i]),
            "feasible": bool(self.feasible[i]),
            "violations": "; ".join(self.violations(i)),
        }

    def take(self, index) -> DesignBatch:
        """Sub-batch of the designs selected by ``index`` (integer or boolean array)."""
        kw = {}
        for name in self.__dataclass_fields__:
            v = getattr(self, name)
            kw[name] = v[index] if isinstance(v, np.ndarray) else v
        return DesignBatch(**kw)


def _outputs(req: Requirement, cfg: Configuration, volume, f, dsf, pos) -> dict[str, np.ndarray]:
    """Evaluate airframe + the constraint table (design and survival wind) and collect outputs.

    Parameters
    ----------
    req, cfg : Requirement, Configuration
        ``req`` resolved.
    volume, f, dsf, pos : ndarray
        Hull volume [m3] and design variables (same shape).

    Returns
    -------
    dict
        Float arrays (see :class:`DesignBatch`) at the design wind, plus the constraint table's
        ``g``, ``value`` and ``limit`` (shape + (n_constraints,)).
    """
    af = build_airframe(req, cfg, volume, f, dsf, pos)
    st = constraint_state(req, cfg, af)
    ev = st.evaluation
    shape = np.shape(volume)
    one = np.ones(shape)
    col = {n: k for k, n in enumerate(CONSTRAINTS)}
    ncol = (shape + (len(CONSTRAINTS),))
    g = np.broadcast_to(st.g, ncol)
    value = np.broadcast_to(st.value, ncol)
    q = 0.5 * af.air_density * max(float(req.design_wind), 1.0) ** 2
    norm = q * af.hull.reference_area * af.hull.length
    return {
        "total_mass": af.mass.total * one,
        "blow_by": value[..., col["blow_by"]] * one,
        "alpha": np.degrees(ev.equilibrium.alpha[0]) * one,
        "cm_alpha": ev.equilibrium.moment_slope[0] / norm * one,
        "cm_alpha_aero": ev.weathervane_slope[0] / norm * one,
        "moment_slope": ev.equilibrium.moment_slope[0] * one,
        "dynamic_lift": ev.lift[0] * one,
        "drag": ev.drag[0] * one,
        "free_lift": af.free_lift * one,
        "buoyancy": af.buoyancy * one,
        "safety_factor": value[..., col["safety_factor"]] * one,
        "tension_top": ev.tether.tension_top[0] * one,
        "fin_te_ratio": af.fins.xi_root_te / af.hull.length * one,
        "length": af.hull.length * one,
        "diameter": af.hull.diameter * one,
        "g": np.array(g),
        "value": np.array(value),
        "limit": np.array(np.broadcast_to(st.limit, ncol)),
    }


def evaluate_designs(
    req: Requirement,
    cfg: Configuration,
    fineness_ratio=None,
    area_change=None,
    position=None,
    volume=None,
    blow_by_limit=None,
) -> DesignBatch:
    """Size (or take the volume of) and evaluate a batch of designs in one vectorised pass.

    With ``volume=None`` the hull is sized: V*(x) = :func:`~aerostat_core.sizing.size_volume`
    (smallest volume with blow-by <= limit at the design wind, positive free lift, taut tether),
    then refined by one secant step on the blow-by between V_hi (1 - 5e-4) and V_hi (the
    sizing's feasible end of the bracket): V* = V_lo + (x_max - x_lo)(V_hi - V_lo)/(x_hi - x_lo);
    the outputs are interpolated linearly between the two probes (error O(5e-4^2)). This makes
    V*(x) smooth to ~1e-7 instead of a 1e-4 staircase, which finite-difference gradients need.

    Parameters
    ----------
    req, cfg : Requirement, Configuration
    fineness_ratio, area_change, position : array_like or None
        f [-], Delta S_f [%], Delta l_f [-]; broadcast together; ``None`` takes ``cfg``'s value.
    volume : array_like or None
        Hull volume [m3]; ``None`` sizes it (see above).
    blow_by_limit : array_like or None
        Blow-by limit for the constraint [m]; ``None`` takes ``req.blow_by_limit`` (sizing
        always uses ``req.blow_by_limit``).

    Returns
    -------
    DesignBatch
        Flattened to 1-D in C order of the broadcast shape.
    """
    req = req.resolved()
    f = cfg.hull.fineness_ratio if fineness_ratio is None else fineness_ratio
    dsf = cfg.fins.area_change if area_change is None else area_change
    pos = cfg.fins.position if position is None else position
    vol_in = np.nan if volume is None else volume
    lim_in = req.blow_by_limit if blow_by_limit is None else blow_by_limit
    f, dsf, pos, vol_in, lim = (
        np.asarray(a, float).reshape(-1).copy()
        for a in np.broadcast_arrays(*(np.asarray(a, float) for a in (f, dsf, pos, vol_in, lim_in)))
    )
    n = f.size
    col = {name: k for k, name in enumerate(CONSTRAINTS)}
    if volume is None:
        s = size_volume(req, cfg, f, dsf, pos)
        v_hi = np.asarray(s.volume, float).reshape(-1)
        feasible_size = np.asarray(s.feasible, bool).reshape(-1)
        binding = np.asarray(s.binding).reshape(-1).astype(str)
        message = np.asarray(s.message).reshape(-1).astype(str)
        v_lo = v_hi * (1.0 - _SECANT_PROBE)
        both = _outputs(
            req, cfg, np.concatenate([v_lo, v_hi]), np.tile(f, 2), np.tile(dsf, 2), np.tile(pos, 2)
        )
        lo = {k: v[:n] for k, v in both.items()}
        hi = {k: v[n:] for k, v in both.items()}
        # secant on the binding constraint's g between the two probes: g(V*) = 0
        k_bind = np.array([col.get(b, -1) for b in binding])
        rows = np.arange(n)
        g_lo = np.where(k_bind >= 0, lo["g"][rows, k_bind], 0.0)
        g_hi = np.where(k_bind >= 0, hi["g"][rows, k_bind], 0.0)
        others_lo = lo["g"].copy()
        others_lo[rows, np.maximum(k_bind, 0)] = -np.inf
        bracket = (
            feasible_size & (k_bind >= 0) & (g_lo > g_hi) & (g_lo > 0.0) & (g_hi <= FEASIBILITY_TOL)
            & (others_lo.max(axis=1) <= FEASIBILITY_TOL)
        )
        den = np.where(bracket, g_lo - g_hi, 1.0)
        # g_hi may sit within the tolerance above 0: allow the few-% extrapolation that reaches 0
        t = np.clip(np.where(bracket, g_lo / den, 1.0), 0.0, 1.05)
        out = {}
        for k in hi:
            tt = t.reshape((-1,) + (1,) * (hi[k].ndim - 1))
            out[k] = lo[k] + tt * (hi[k] - lo[k])
        vol = v_lo + t * (v_hi - v_lo)
        if np.any(bracket):  # exactly on the limit where the secant applies (removes round-off)
            out["g"][rows[bracket], k_bind[bracket]] = np.minimum(
                out["g"][rows[bracket], k_bind[bracket]], 0.0)
        sized = True
    else:
        vol = vol_in
        if np.any(~np.isfinite(vol)) or np.any(vol <= 0):
            raise ValueError("volume must be positive and finite [m3]")
        out = _outputs(req, cfg, vol, f, dsf, pos)
        feasible_size = np.ones(n, bool)
        binding = np.full(n, "given")
        message = np.full(n, "")
        sized = False
    g, value, limit = out["g"], out["value"], out["limit"]
    if blow_by_limit is not None:  # a limit per design (Pareto front): re-normalise that column
        kb = col["blow_by"]
        limit[:, kb] = lim
        g[:, kb] = value[:, kb] / lim - 1.0
    return DesignBatch(
        fineness_ratio=f,
        area_change=dsf,
        position=pos,
        volume=vol,
        sized=sized,
        sizing_feasible=feasible_size,
        binding=binding,
        sizing_message=message,
        total_mass=out["total_mass"],
        gas_cost=np.asarray(gas_fill_cost(vol, cfg.gas_price_value), float),
        blow_by=out["blow_by"],
        alpha=out["alpha"],
        cm_alpha=out["cm_alpha"],
        cm_alpha_aero=out["cm_alpha_aero"],
        moment_slope=out["moment_slope"],
        dynamic_lift=out["dynamic_lift"],
        drag=out["drag"],
        free_lift=out["free_lift"],
        buoyancy=out["buoyancy"],
        safety_factor=out["safety_factor"],
        tension_top=out["tension_top"],
        fin_te_ratio=out["fin_te_ratio"],
        length=out["length"],
        diameter=out["diameter"],
        blow_by_limit=lim,
        stall_angle=float(cfg.aero.fin_stall_angle_deg),
        min_safety_factor=float(req.min_tether_safety_factor),
        constraints=g,
        constraint_value=value,
        constraint_limit=limit,
        design_wind=float(req.design_wind),
        survival_wind=float(req.survival_wind),
    )


# ------------------------------------------------------------------------------------------------
# The problem
# ------------------------------------------------------------------------------------------------


def _check_bounds(bounds: Any) -> dict[str, tuple[float, float]]:
    """Validate a bounds mapping {variable: (lower, upper)}; raise ValueError naming the cause.

    Parameters
    ----------
    bounds : mapping
        Keys among :data:`VARIABLES`; values pairs of finite numbers (units of
        :data:`VARIABLE_INFO`), lower < upper, inside the engine's valid range.
    """
    if not isinstance(bounds, Mapping):
        raise ValueError("bounds must be a mapping {variable: (lower, upper)}")
    if len(bounds) == 0:
        raise ValueError(
            "bounds are empty: give (lower, upper) for at least one of " + ", ".join(VARIABLES)
        )
    out: dict[str, tuple[float, float]] = {}
    for name, pair in bounds.items():
        if name not in VARIABLE_INFO:
            raise ValueError(
                f"unknown design variable {name!r} in bounds; valid: {', '.join(VARIABLES)}"
            )
        label, unit, (vlo, vhi) = VARIABLE_INFO[name]
        u = "" if unit == "-" else f" {unit}"
        try:
            lo, hi = (float(v) for v in pair)
        except (TypeError, ValueError):
            raise ValueError(
                f"bounds of {name} ({label}) must be two numbers (lower, upper), got {pair!r}"
            ) from None
        if not (math.isfinite(lo) and math.isfinite(hi)):
            raise ValueError(f"bounds of {name} ({label}) must be finite, got ({lo:g}, {hi:g})")
        if lo > hi:
            raise ValueError(f"lower bound {lo:g}{u} > upper bound {hi:g}{u} for {name} ({label})")
        if lo == hi:
            raise ValueError(
                f"bounds of {name} ({label}) are empty: lower = upper = {lo:g}{u}; to hold it "
                "fixed, leave it out of the bounds (its configuration value is then used)"
            )
        if lo < vlo or hi > vhi:
            raise ValueError(
                f"bounds ({lo:g}, {hi:g}){u} of {name} ({label}) leave the valid range "
                f"[{vlo:g}, {vhi:g}]{u}"
            )
        out[name] = (lo, hi)
    return out


class OptimisationProblem:
    """min objective(x, V*(x)) s.t. g(x) <= 0, lower <= x <= upper (module docstring).

    Parameters
    ----------
    requirement : Requirement
        Payload [kg], altitude [m], design wind [m/s], blow-by limit [m], tether safety factor.
    configuration : Configuration
        Everything else; its hull volume is ignored (V is sized), its design-variable values are
        the starting point and hold any variable left out of ``bounds``.
    bounds : mapping or None
        {variable: (lower, upper)} for the variables to optimise (units of
        :data:`VARIABLE_INFO`); ``None`` takes :data:`DEFAULT_BOUNDS`.
    objective : {"total_mass", "volume"}
        Minimise total mass [kg] (thesis) or hull volume [m3] (helium cost).

    Raises
    ------
    ValueError
        Empty bounds, lower > upper, an unknown variable, bounds outside the engine's valid range
        or an unknown objective: the message names the variable and values.
    """

    def __init__(
        self,
        requirement: Requirement,
        configuration: Configuration,
        bounds: Mapping[str, Sequence[float]] | None = None,
        objective: str = "total_mass",
    ) -> None:
        """Validate the inputs and bounds (see the class docstring)."""
        if not isinstance(requirement, Requirement):
            raise ValueError("requirement must be a Requirement")
        if not isinstance(configuration, Configuration):
            raise ValueError("configuration must be a Configuration")
        if objective not in OBJECTIVES:
            raise ValueError(f"objective = {objective!r}: choose one of {', '.join(OBJECTIVES)}")
        checked = _check_bounds(DEFAULT_BOUNDS if bounds is None else bounds)
        self.requirement = requirement.resolved()
        self.configuration = configuration.with_design_variables(volume=None)
        self.objective = objective
        self.names = tuple(v for v in VARIABLES if v in checked)
        self.bounds = {k: checked[k] for k in self.names}
        self.lower = np.array([checked[k][0] for k in self.names])
        self.upper = np.array([checked[k][1] for k in self.names])
        cfg = self.configuration
        self.fixed = {
            "fineness_ratio": cfg.hull.fineness_ratio,
            "area_change": cfg.fins.area_change,
            "position": cfg.fins.position,
        }

    # -- sizes and scaling -------------------------------------------------------------------
    @property
    def n_var(self) -> int:
        """Number of design variables."""
        return len(self.names)

    @property
    def n_constr(self) -> int:
        """Number of inequality constraints."""
        return len(CONSTRAINTS)

    def from_unit(self, u) -> np.ndarray:
        """Physical variables from the unit cube: x = lower + u (upper - lower)."""
        return self.lower + np.asarray(u, float) * (self.upper - self.lower)

    def to_unit(self, x) -> np.ndarray:
        """Unit-cube coordinates of physical variables: u = (x - lower)/(upper - lower)."""
        return (np.asarray(x, float) - self.lower) / (self.upper - self.lower)

    def start(self) -> np.ndarray:
        """The configuration's design variables, clipped into the bounds (physical units)."""
        x = np.array([self.fixed[k] for k in self.names], float)
        return np.clip(x, self.lower, self.upper)

    def full_variables(self, x) -> dict[str, np.ndarray]:
        """All three design variables for a batch x (n, n_var): optimised ones from x, the
        others held at the configuration's values."""
        x = np.atleast_2d(np.asarray(x, float))
        n = x.shape[0]
        out = {k: np.full(n, float(v)) for k, v in self.fixed.items()}
        for j, k in enumerate(self.names):
            out[k] = x[:, j]
        return out

    def variables_dict(self, x) -> dict[str, float]:
        """All three design variables of one design x (n_var,) as {name: value}."""
        v = self.full_variables(np.asarray(x, float)[None, :])
        return {k: float(v[k][0]) for k in VARIABLES}

    # -- evaluation ---------------------------------------------------------------------------
    def evaluate(self, x) -> DesignBatch:
        """Evaluate a batch of designs x (n, n_var) in physical units (one vectorised call)."""
        v = self.full_variables(x)
        return evaluate_designs(
            self.requirement,
            self.configuration,
            v["fineness_ratio"],
            v["area_change"],
            v["position"],
        )

    def evaluate_unit(self, u) -> DesignBatch:
        """Evaluate a batch given in unit-cube coordinates u (n, n_var)."""
        return self.evaluate(self.from_unit(np.clip(np.atleast_2d(u), 0.0, 1.0)))

    def configuration_at(self, x) -> Configuration:
        """Configuration with the design variables x (physical) and a sized volume."""
        v = self.full_variables(x)
        return self.configuration.with_design_variables(
            fineness_ratio=float(v["fineness_ratio"][0]),
            area_change=float(v["area_change"][0]),
            position=float(v["position"][0]),
            volume=None,
        )

    def describe(self) -> list[dict[str, str]]:
        """Problem definition as (item, definition) rows for display."""
        req = self.requirement
        lab, unit = OBJECTIVES[self.objective]
        rows = [
            {
                "item": "objective",
                "definition": f"minimise {lab.lower()} [{unit}] of the sized design",
            },
            {
                "item": "volume",
                "definition": "V*(x): smallest hull meeting the blow-by limit "
                f"{req.blow_by_limit:g} m at {req.design_wind:g} m/s with positive free lift "
                "and a taut tether (nested sizing, not a design variable)",
            },
        ]
        for k in VARIABLES:
            label, u, _ = VARIABLE_INFO[k]
            if k in self.bounds:
                lo, hi = self.bounds[k]
                rows.append(
                    {"item": f"variable {k}", "definition": f"{label}: [{lo:g}, {hi:g}] {u}"}
                )
            else:
                rows.append(
                    {"item": f"fixed {k}", "definition": f"{label} = {self.fixed[k]:g} {u}"}
                )
        for k in CONSTRAINTS:
            rows.append({"item": f"constraint {k}", "definition": CONSTRAINT_TEXT[k]})
        return rows


@dataclass(frozen=True)
class FunctionBatch:
    """Evaluated points of a :class:`FunctionProblem` (the solver-facing part of
    :class:`DesignBatch`): x (n, d), values (n,), constraints (n, m), variable names."""

    x: np.ndarray
    values: np.ndarray
    constraints: np.ndarray
    names: tuple

    def __len__(self) -> int:
        """Number of designs (points) in the batch."""
        return int(self.values.shape[0])

    @property
    def max_violation(self) -> np.ndarray:
        """max(0, max_i g_i) per point [-]."""
        if self.constraints.shape[1] == 0:
            return np.zeros(len(self))
        return np.maximum(np.max(self.constraints, axis=1), 0.0)

    @property
    def feasible(self) -> np.ndarray:
        """Every g <= :data:`FEASIBILITY_TOL`."""
        return np.all(self.constraints <= FEASIBILITY_TOL, axis=1)

    def objective(self, name: str = "value") -> np.ndarray:
        """Objective values (``name`` is ignored: a function problem has one objective)."""
        return self.values

    def violations(self, i: int) -> list[str]:
        """Violated constraints of point ``i`` as text (``g[k] = value > 0``)."""
        return [
            f"g[{k}] = {v:.3g} > 0"
            for k, v in enumerate(self.constraints[i])
            if v > FEASIBILITY_TOL
        ]

    def row(self, i: int) -> dict[str, Any]:
        """Point ``i`` as a flat dict (variables, objective, feasibility)."""
        out = {n: float(v) for n, v in zip(self.names, self.x[i])}
        out.update(objective=float(self.values[i]), feasible=bool(self.feasible[i]))
        return out

    def take(self, index) -> FunctionBatch:
        """Sub-batch selected by ``index``."""
        return FunctionBatch(self.x[index], self.values[index], self.constraints[index], self.names)


class FunctionProblem:
    """A vectorised analytic problem min f(x) s.t. g(x) <= 0, lower <= x <= upper, with the
    interface the solvers use. It verifies the solvers against problems with known optima.

    Parameters
    ----------
    objective : callable
        ``objective(X) -> (n,)`` for X of shape (n, d), vectorised.
    constraints : callable or None
        ``constraints(X) -> (n, m)`` (g <= 0 feasible); ``None`` for bounds only.
    bounds : mapping
        {name: (lower, upper)} in order, lower < upper, finite.
    start : array_like or None
        Starting point (default: the centre of the box).
    """

    def __init__(
        self,
        objective: Callable,
        constraints: Callable | None,
        bounds: Mapping[str, Sequence[float]],
        start=None,
    ) -> None:
        """Validate the bounds and store the functions (see the class docstring)."""
        if not isinstance(bounds, Mapping) or len(bounds) == 0:
            raise ValueError("bounds are empty: give {name: (lower, upper)} for each variable")
        lo, hi = [], []
        for name, pair in bounds.items():
            a, b = (float(v) for v in pair)
            if not (math.isfinite(a) and math.isfinite(b)) or a >= b:
                raise ValueError(
                    f"bounds of {name} must be finite with lower < upper, got ({a:g}, {b:g})"
                )
            lo.append(a)
            hi.append(b)
        self.names = tuple(bounds)
        self.lower, self.upper = np.array(lo), np.array(hi)
        self._f = objective
        self._g = constraints
        self.objective = "value"
        self._start = 0.5 * (self.lower + self.upper) if start is None else np.asarray(start, float)
        self.n_constr = int(np.shape(self._constraints(self._start[None, :]))[1])

    @property
    def n_var(self) -> int:
        """Number of variables."""
        return len(self.names)

    def _constraints(self, x: np.ndarray) -> np.ndarray:
        """Constraint matrix g (n, m) of points x (n, d); (n, 0) without constraints."""
        if self._g is None:
            return np.zeros((x.shape[0], 0))
        return np.asarray(self._g(x), float).reshape(x.shape[0], -1)

    def from_unit(self, u) -> np.ndarray:
        """x = lower + u (upper - lower)."""
        return self.lower + np.asarray(u, float) * (self.upper - self.lower)

    def to_unit(self, x) -> np.ndarray:
        """u = (x - lower)/(upper - lower)."""
        return (np.asarray(x, float) - self.lower) / (self.upper - self.lower)

    def start(self) -> np.ndarray:
        """Starting point, clipped into the bounds."""
        return np.clip(self._start, self.lower, self.upper)

    def variables_dict(self, x) -> dict[str, float]:
        """{name: value} of one point."""
        return {n: float(v) for n, v in zip(self.names, np.asarray(x, float))}

    def evaluate(self, x) -> FunctionBatch:
        """Evaluate a batch x (n, d)."""
        x = np.atleast_2d(np.asarray(x, float))
        return FunctionBatch(
            x, np.asarray(self._f(x), float).reshape(-1), self._constraints(x), self.names
        )


# ------------------------------------------------------------------------------------------------
# Results and book-keeping shared by the solvers
# ------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class History:
    """Convergence history, one entry per evaluated batch.

    evaluations : cumulative number of designs evaluated [-];
    best : best feasible objective so far (NaN before the first feasible design);
    violation : least max-constraint violation so far [-] (0 once a feasible design is found).
    """

    evaluations: np.ndarray
    best: np.ndarray
    violation: np.ndarray

    def rows(self, solver: str = "") -> list[dict[str, Any]]:
        """History as rows (solver, evaluations, best objective, least violation)."""
        return [
            {
                "solver": solver,
                "evaluations": int(e),
                "best_objective": float(b),
                "least_violation": float(v),
            }
            for e, b, v in zip(self.evaluations, self.best, self.violation)
        ]


@dataclass(frozen=True)
class OptimisationResult:
    """Outcome of one solver run.

    Attributes
    ----------
    solver : str
        Key (``"slsqp"``, ``"surrogate"``, ``"pso"``).
    label : str
        Display name.
    x : dict
        Best design variables found {name: value} (physical units), all three variables.
    objective : float
        Its objective value (kg or m3).
    objective_name : str
    design : dict
        The best design's :meth:`DesignBatch.row`.
    feasible : bool
    status : str
        ``"converged"``, ``"budget"`` (evaluation/iteration budget used up), ``"cancelled"`` or
        ``"infeasible"`` (no feasible design found; ``message`` names the binding constraint).
    message : str
    active : tuple of str
        Constraints with g > -ACTIVE_TOL and variables at a bound (``"area_change=lower"``).
    n_evaluations : int
        Designs evaluated (each one a nested V*(x) sizing), finite-difference points included.
    n_batches : int
        Vectorised engine calls.
    time_s : float
        Wall time [s].
    seed : int
    history : History
    settings : dict
        Solver settings used.
    """

    solver: str
    label: str
    x: dict
    objective: float
    objective_name: str
    design: dict
    feasible: bool
    status: str
    message: str
    active: tuple
    n_evaluations: int
    n_batches: int
    time_s: float
    seed: int
    history: History
    settings: dict = field(default_factory=dict)


class _Tracker:
    """Evaluates batches for a solver and keeps every design, the history, budget and callbacks.

    Parameters
    ----------
    problem : OptimisationProblem or FunctionProblem
    budget : int
        Nominal number of evaluations (for the progress fraction only).
    progress : callable or None
        ``progress(fraction, text)`` after every batch.
    stop : callable or None
        ``stop() -> bool``; True raises :class:`OptimisationCancelled` after the batch.
    label : str
        Solver name for the progress text.
    """

    def __init__(self, problem, budget, progress, stop, label):
        """Start an empty record (see the class docstring)."""
        self.problem = problem
        self.budget = max(int(budget), 1)
        self.progress = progress
        self.stop = stop
        self.label = label
        self.x: list[np.ndarray] = []
        self.batches: list[DesignBatch] = []
        self.n = 0
        self.best = np.inf
        self.viol = np.inf
        self.hist_e: list[int] = []
        self.hist_b: list[float] = []
        self.hist_v: list[float] = []
        self.t0 = time.perf_counter()

    def __call__(self, u) -> DesignBatch:
        """Evaluate unit-cube points u (n, d); record; report progress; honour ``stop``."""
        u = np.clip(np.atleast_2d(np.asarray(u, float)), 0.0, 1.0)
        x = self.problem.from_unit(u)
        b = self.problem.evaluate(x)
        self.x.append(x)
        self.batches.append(b)
        self.n += len(b)
        obj = b.objective(self.problem.objective)
        feas = b.feasible
        if np.any(feas):
            self.best = min(self.best, float(np.min(obj[feas])))
            self.viol = 0.0
        else:
            self.viol = min(self.viol, float(np.min(b.max_violation)))
        self.hist_e.append(self.n)
        self.hist_b.append(self.best if np.isfinite(self.best) else np.nan)
        self.hist_v.append(self.viol)
        if self.progress is not None:
            best = f"{self.best:.3f}" if np.isfinite(self.best) else "none feasible yet"
            self.progress(
                min(self.n / self.budget, 1.0), f"{self.label}: {self.n} evaluations, best {best}"
            )
        if self.stop is not None and self.stop():
            raise OptimisationCancelled
        return b

    def history(self) -> History:
        """The :class:`History` recorded so far."""
        return History(
            np.array(self.hist_e, int), np.array(self.hist_b, float), np.array(self.hist_v, float)
        )

    def best_index(self) -> tuple[int, int] | None:
        """(batch, row) of the best feasible design, else of the least-violating one."""
        if not self.batches:
            return None
        best, key = None, None
        for i, b in enumerate(self.batches):
            obj = b.objective(self.problem.objective)
            feas = b.feasible
            # feasible designs first (by objective), then infeasible by violation
            k = np.where(feas, 0.0, 1.0)
            score = np.where(feas, obj, b.max_violation)
            j = int(np.lexsort((score, k))[0])
            cand = (k[j], score[j])
            if key is None or cand < key:
                key, best = cand, (i, j)
        return best

    def result(self, solver, label, status, message, seed, settings) -> OptimisationResult:
        """Package the best design evaluated so far as an :class:`OptimisationResult`."""
        p = self.problem
        where = self.best_index()
        if where is None:
            nan = float("nan")
            return OptimisationResult(
                solver,
                label,
                {k: nan for k in p.variables_dict(p.start())},
                nan,
                p.objective,
                {},
                False,
                "cancelled",
                message or "stopped before any evaluation",
                (),
                0,
                0,
                time.perf_counter() - self.t0,
                seed,
                self.history(),
                settings,
            )
        i, j = where
        b = self.batches[i].take(np.array([j]))
        xs = self.x[i][j]
        feas = bool(b.feasible[0])
        active = [c for c, gv in zip(CONSTRAINTS, b.constraints[0]) if gv > -ACTIVE_TOL]
        span = p.upper - p.lower
        for k, name in enumerate(p.names):
            if xs[k] <= p.lower[k] + 1e-3 * span[k]:
                active.append(f"{name}=lower")
            elif xs[k] >= p.upper[k] - 1e-3 * span[k]:
                active.append(f"{name}=upper")
        if not feas:
            status = "cancelled" if status == "cancelled" else "infeasible"
            why = "; ".join(b.violations(0)) or "constraint tolerance not met"
            message = f"no feasible design found; at the least-violating design: {why}" + (
                f" ({message})" if message else ""
            )
        return OptimisationResult(
            solver=solver,
            label=label,
            x=p.variables_dict(xs),
            objective=float(b.objective(p.objective)[0]),
            objective_name=p.objective,
            design=b.row(0),
            feasible=feas,
            status=status,
            message=message,
            active=tuple(active),
            n_evaluations=int(self.n),
            n_batches=len(self.batches),
            time_s=time.perf_counter() - self.t0,
            seed=int(seed),
            history=self.history(),
            settings=dict(settings),
        )


# ------------------------------------------------------------------------------------------------
# Lock-step driver: several scipy SLSQP runs whose evaluations are pooled into one batch
# ------------------------------------------------------------------------------------------------


class _Aborted(Exception):
    """Raised in worker threads when the lock-step run is torn down."""


class _BudgetExhausted(Exception):
    """Raised in the main thread when a lock-step run reaches its round cap."""


def _run_lockstep(tasks: list[Callable], evaluate_requests: Callable) -> list[Any]:
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
                    raise _Aborted
                pending[i] = np.array(u, float)
                cond.notify_all()
                while i not in results and not state["abort"]:
                    cond.wait()
                if state["abort"]:
                    raise _Aborted
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


def _stencil(u: np.ndarray, h: float) -> tuple[np.ndarray, np.ndarray]:
    """Second-order finite-difference stencil in the unit cube.

    Per coordinate j two points: u -/+ h e_j (central) where both lie in [0, 1], else
    u + h e_j, u + 2h e_j (one-sided, at the lower bound) or u - h e_j, u - 2h e_j (upper).
    Returns the points (2d + 1, d) (centre first) and the per-coordinate kind (d,):
    0 central, +1 forward, -1 backward. See :func:`_fd_gradient`.
    """
    d = u.size
    kind = np.where(u - h < 0.0, 1, np.where(u + h > 1.0, -1, 0))
    a = np.where(kind == 0, -h, kind * h)
    b = np.where(kind == 0, h, 2.0 * kind * h)
    pts = np.repeat(u[None, :], 2 * d + 1, axis=0)
    idx = np.arange(d)
    pts[1 + 2 * idx, idx] += a
    pts[2 + 2 * idx, idx] += b
    return pts, kind


def _fd_gradient(values: np.ndarray, kind: np.ndarray, h: float) -> np.ndarray:
    """Gradient from values on a :func:`_stencil` (first axis: the 2d + 1 points).

    Central: (f(u+h) - f(u-h))/2h; forward: (-3 f(u) + 4 f(u+h) - f(u+2h))/2h; backward: the
    mirror image. All O(h^2). Returns shape (d,) + values.shape[1:].
    """
    f0 = values[0]
    fa, fb = values[1::2], values[2::2]
    k = kind.reshape((-1,) + (1,) * (values.ndim - 1))
    central = (fb - fa) / (2.0 * h)
    onesided = k * (-3.0 * f0[None] + 4.0 * fa - fb) / (2.0 * h)
    return np.where(k == 0, central, onesided)


def _slsqp_task(u0, bounds, maxiter, ftol):
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


def _stencil_evaluator(
    fn_eval: Callable, d: int, h: float, objective_of: Callable, scale: dict
) -> Callable:
    """Build ``evaluate_requests`` for :func:`_run_lockstep` from a batch evaluator: every
    request's point and its :func:`_stencil` go into one batch; the reply is (F, g, dF, dg).

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
    """

    m = 2 * d + 1

    def evaluate_requests(batch: dict[int, np.ndarray]) -> dict[int, tuple]:
        """Evaluate every request's stencil in one batch; reply (F, g, dF, dg) per task."""
        ids = list(batch)
        stencils = [_stencil(batch[i], h) for i in ids]
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
            df = _fd_gradient(f_k, kind, h)
            dg = _fd_gradient(g_k, kind, h).T
            out[i] = (float(f_k[0]), g_k[0].copy(), df, dg)
        return out

    return evaluate_requests


# ------------------------------------------------------------------------------------------------
# Solver 1: SLSQP multi-start
# ------------------------------------------------------------------------------------------------


def _start_points(problem: OptimisationProblem, n_starts: int, seed: int) -> np.ndarray:
    """Multi-start points in the unit cube: the configuration's design (clipped into the bounds)
    followed by a seeded scrambled-Halton sample."""
    from scipy.stats import qmc

    pts = [problem.to_unit(problem.start())]
    if n_starts > 1:
        sampler = qmc.Halton(problem.n_var, scramble=True, seed=np.random.default_rng(seed))
        pts.extend(sampler.random(n_starts - 1))
    return np.array(pts[: max(n_starts, 1)])


def solve_slsqp(
    problem: OptimisationProblem,
    n_starts: int = 4,
    seed: int = 0,
    maxiter: int = 60,
    ftol: float = 1e-8,
    fd_step: float = 1e-3,
    max_rounds: int | None = None,
    progress: Callable | None = None,
    stop: Callable | None = None,
) -> OptimisationResult:
    """Gradient-based SLSQP from several starts (fmincon + MultiStart analogue).

    Each start is a ``scipy.optimize.minimize(method="SLSQP")`` run in the unit cube with the
    objective scaled by its median at the starts and second-order finite-difference gradients
    (central; one-sided three-point at a bound) of the
    objective and every constraint (step ``fd_step`` in the unit cube, i.e. 1e-3 of each range).
    All starts advance in lock-step: at every round the pending points of all starts and their
    d finite-difference neighbours form one batch, so a round costs one vectorised sizing call.

    Parameters
    ----------
    problem : OptimisationProblem or FunctionProblem
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
    OptimisationResult
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
    tr = _Tracker(problem, budget, progress, stop, "SLSQP")
    label = f"SLSQP ({n_starts} starts)"
    starts = _start_points(problem, n_starts, seed)
    scale: dict[str, float | None] = {"value": None}
    cap = int(maxiter) if max_rounds is None else int(max_rounds)
    settings["max_rounds"] = cap

    def fn_eval(pts, owners):
        """Evaluate the stencil points of one lock-step round (round cap enforced)."""
        if len(tr.batches) >= cap:
            raise _BudgetExhausted
        return tr(pts)

    evaluate_requests = _stencil_evaluator(
        fn_eval,
        d,
        fd_step,
        lambda b: b.objective(problem.objective),
        scale,
    )
    bounds = [(0.0, 1.0)] * d
    tasks = [_slsqp_task(u0, bounds, int(maxiter), ftol) for u0 in starts]
    try:
        outcome = _run_lockstep(tasks, evaluate_requests)
    except OptimisationCancelled:
        return tr.result("slsqp", label, "cancelled", "cancelled by the user", seed, settings)
    except _BudgetExhausted:
        return tr.result("slsqp", label, "budget", f"stopped after {cap} rounds", seed, settings)
    msgs = []
    n_iter_limit = 0
    for res in outcome:
        if isinstance(res, BaseException):
            if isinstance(res, _Aborted):
                continue
            raise res
        if res.status == 9:
            n_iter_limit += 1
        msgs.append(res.message)
    status = "converged" if n_iter_limit < len(outcome) else "budget"
    nconv = sum(1 for r in outcome if not isinstance(r, BaseException) and r.success)
    message = f"{nconv} of {len(outcome)} starts converged"
    return tr.result("slsqp", label, status, message, seed, settings)


# ------------------------------------------------------------------------------------------------
# Solver 2: RBF surrogate
# ------------------------------------------------------------------------------------------------


def _min_distance(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Euclidean distance from each row of ``a`` to the nearest row of ``b``."""
    d2 = np.sum((a[:, None, :] - b[None, :, :]) ** 2, axis=-1)
    return np.sqrt(np.min(d2, axis=1))


def _surrogate_minimiser(rbf, u0: np.ndarray, d: int) -> np.ndarray | None:
    """Minimise the surrogate objective subject to the surrogate constraints (SLSQP with
    finite differences on the RBF, which is cheap), from ``u0``; None if it fails.

    Parameters
    ----------
    rbf : callable
        ``rbf(U) -> (n, 1 + m)``: objective then constraints.
    u0 : ndarray
        Start in the unit cube.
    d : int
        Number of variables.
    """
    from scipy.optimize import minimize

    cache: dict[bytes, np.ndarray] = {}

    def pred(u):
        """Surrogate prediction (objective, constraints) at ``u``, cached for the last point."""
        key = np.asarray(u, float).tobytes()
        if key not in cache:
            cache.clear()
            cache[key] = rbf(np.clip(np.asarray(u, float), 0, 1)[None, :])[0]
        return cache[key]

    try:
        with np.errstate(all="ignore"):
            res = minimize(
                lambda u: pred(u)[0],
                u0,
                method="SLSQP",
                bounds=[(0.0, 1.0)] * d,
                constraints=[{"type": "ineq", "fun": lambda u: -pred(u)[1:]}],
                options={"maxiter": 50, "ftol": 1e-10},
            )
    except (ValueError, np.linalg.LinAlgError):
        return None
    u = np.clip(res.x, 0.0, 1.0)
    if not np.all(np.isfinite(u)) or np.max(rbf(u[None, :])[0, 1:]) > 1e-6:
        return None
    return u


def solve_surrogate(
    problem: OptimisationProblem,
    max_evaluations: int = 160,
    batch_size: int = 8,
    n_initial: int = 16,
    seed: int = 0,
    sigma_init: float = 0.2,
    sigma_min: float = 2e-3,
    progress: Callable | None = None,
    stop: Callable | None = None,
) -> OptimisationResult:
    """RBF-surrogate optimisation with batched infill (surrogateopt analogue).

    Algorithm (stochastic RBF method of Regis & Shoemaker 2007 with DYCORS-style candidates,
    constraints modelled by their own surrogates):

    1. Evaluate a scrambled Sobol sample of ``n_initial`` points plus the configuration's design.
    2. Fit one cubic RBF with a linear tail (``scipy.interpolate.RBFInterpolator``) to the
       objective and to every constraint g_i (clipped to [-1, 1]) at once.
    3. Candidates: Gaussian perturbations of the incumbent with radius sigma (clipped to the
       bounds, so bound points are reachable) plus uniform points. Keep those predicted feasible
       (all g_hat <= 0; otherwise the least predicted violation), score each with
       w s_f + (1 - w) s_d, s_f = scaled predicted objective, s_d = scaled closeness to
       evaluated points, w cycling through 0.3, 0.5, 0.8, 0.95, and pick ``batch_size`` points.
       Each batch starts with the surrogate's own constrained minimisers (SLSQP on the RBF from
       the best few evaluated designs and a random point), which gives the fast final
       convergence of a local method and a chance to jump to a neighbouring basin.
    4. Evaluate the batch in one call; halve sigma after ``max(3, d)`` batches without
       improvement, double it (up to ``sigma_init``) after 3 improving batches; stop when sigma
       < ``sigma_min`` or the budget is spent.

    Parameters
    ----------
    problem : OptimisationProblem or FunctionProblem
    max_evaluations : int
        Evaluation budget (designs) [-].
    batch_size : int
        Designs per infill batch.
    n_initial : int
        Sobol points of the initial design (a power of 2 keeps the sample balanced).
    seed : int
        Seed of the Sobol scramble and of the candidate generator.
    sigma_init, sigma_min : float
        Initial and final perturbation radius in the unit cube [-].
    progress, stop : callable or None
        ``progress(fraction, text)`` after every batch; ``stop() -> bool`` cancels.

    Returns
    -------
    OptimisationResult

    Notes
    -----
    Known weakness: a long, narrow curved valley (the thesis preset has one, along which the
    mass falls by 0.4 kg from the Delta S_f = -50 % bound to the Delta l_f = 0.60 bound) is
    poorly resolved by a global RBF fit; the surrogate may stop at its shallow end (+0.6 %).

    References
    ----------
    Regis R.G., Shoemaker C.A., "A stochastic radial basis function method for the global
    optimization of expensive functions", INFORMS J. Computing 19(4):497-509, 2007.
    Regis R.G., Shoemaker C.A., "Combining radial basis function surrogates and dynamic
    coordinate search in high-dimensional expensive black-box optimization", Eng. Optim.
    45(5):529-555, 2013 (DYCORS).
    """
    from scipy.interpolate import RBFInterpolator
    from scipy.stats import qmc

    max_evaluations, batch_size, n_initial = int(max_evaluations), int(batch_size), int(n_initial)
    if max_evaluations < n_initial + 1 or batch_size < 1 or n_initial < problem.n_var + 1:
        raise ValueError(
            f"surrogate settings: need n_initial >= {problem.n_var + 1}, batch_size >= 1 and "
            f"max_evaluations > n_initial (got {n_initial}, {batch_size}, {max_evaluations})"
        )
    settings = {
        "max_evaluations": max_evaluations,
        "batch_size": batch_size,
        "n_initial": n_initial,
        "sigma_init": sigma_init,
        "sigma_min": sigma_min,
    }
    d = problem.n_var
    rng = np.random.default_rng(seed)
    tr = _Tracker(problem, max_evaluations, progress, stop, "Surrogate")
    label = "RBF surrogate"
    u0 = qmc.Sobol(d, scramble=True, seed=rng).random(n_initial)
    u0 = np.vstack([problem.to_unit(problem.start())[None, :], u0])
    status, message = "budget", "evaluation budget used up"
    try:
        b = tr(u0)
        U = np.clip(u0, 0, 1)
        F = b.objective(problem.objective)
        G = b.constraints
        FEAS = b.feasible
        sigma, n_fail, n_succ = float(sigma_init), 0, 0
        n_polish = max(1, min(3, batch_size // 2))
        weights = (0.3, 0.5, 0.8, 0.95)
        wk = 0
        while tr.n < max_evaluations:
            scale = float(np.median(np.abs(F))) or 1.0
            Y = np.column_stack([F / scale, np.clip(G, -1.0, 1.0)])
            rbf = RBFInterpolator(U, Y, kernel="cubic", degree=1, smoothing=1e-10)
            # incumbent: best feasible, else least violation
            viol = np.maximum(G.max(axis=1), 0.0)
            ib = int(np.argmin(np.where(FEAS, F, np.inf))) if FEAS.any() else int(np.argmin(viol))
            best_before = F[ib] if FEAS.any() else np.inf
            n_loc = 200 * d
            loc = U[ib] + sigma * rng.standard_normal((n_loc, d))
            # DYCORS-style: also move one coordinate at a time
            one = np.repeat(U[ib][None, :], n_loc // 2, axis=0)
            jj = rng.integers(0, d, n_loc // 2)
            one[np.arange(n_loc // 2), jj] += sigma * rng.standard_normal(n_loc // 2)
            cand = np.clip(np.vstack([loc, one, rng.random((50 * d, d))]), 0.0, 1.0)
            pred = rbf(cand)
            fh, gh = pred[:, 0], pred[:, 1:]
            pv = np.maximum(gh.max(axis=1), 0.0)
            ok = pv <= 0.0
            if ok.any():
                cand, fh = cand[ok], fh[ok]
            else:  # nothing predicted feasible: the predicted violation takes the objective's role
                fh = pv
            # the surrogate's own constrained minimisers (cheap: RBF only), started from the
            # best few evaluated designs and one random point; they lead the batch
            rank = np.lexsort((np.where(FEAS, F, viol), ~FEAS))
            starts = np.vstack([U[rank[:n_polish]], rng.random((1, d))])
            polished = [
                q for q in (_surrogate_minimiser(rbf, s0, d) for s0 in starts) if q is not None
            ]
            n_lead = 0
            if polished:
                pp = np.unique(np.round(np.array(polished), 9), axis=0)
                fp = rbf(pp)[:, 0]
                pp = pp[np.argsort(fp)][:n_polish]
                n_lead = len(pp)
                fill = rbf(pp)[:, 0] if ok.any() else np.zeros(n_lead)
                cand, fh = np.vstack([pp, cand]), np.concatenate([fill, fh])
            dist = _min_distance(cand, U)
            chosen = []
            n_take = min(batch_size, max_evaluations - tr.n)
            for _ in range(n_take):
                valid = dist > 1e-6
                if not valid.any():
                    break
                sf_ = (fh - fh[valid].min()) / max(np.ptp(fh[valid]), 1e-12)
                dmin, dmax = dist[valid].min(), dist[valid].max()
                sd = (dmax - dist) / max(dmax - dmin, 1e-12)
                w = weights[wk % len(weights)]
                wk += 1
                k = int(np.argmin(np.where(valid, w * sf_ + (1 - w) * sd, np.inf)))
                lead = np.nonzero(valid[:n_lead])[0]
                if lead.size:
                    k = int(lead[0])  # surrogate minimisers first
                chosen.append(cand[k])
                dist = np.minimum(dist, np.linalg.norm(cand - cand[k], axis=1))
            if not chosen:
                status, message = "converged", "no new candidate points left"
                break
            new = np.array(chosen)
            b = tr(new)
            U = np.vstack([U, new])
            F = np.concatenate([F, b.objective(problem.objective)])
            G = np.vstack([G, b.constraints])
            FEAS = np.concatenate([FEAS, b.feasible])
            nf = b.objective(problem.objective)[b.feasible]
            improved = nf.size > 0 and nf.min() < best_before - 1e-6 * abs(best_before)
            if improved:
                n_succ, n_fail = n_succ + 1, 0
            else:
                n_succ, n_fail = 0, n_fail + 1
            if n_succ >= 3:
                sigma, n_succ = min(2.0 * sigma, sigma_init), 0
            if n_fail >= max(3, d):
                sigma, n_fail = sigma / 2.0, 0
            if sigma < sigma_min:
                status, message = "converged", f"search radius below {sigma_min:g}"
                break
    except OptimisationCancelled:
        return tr.result("surrogate", label, "cancelled", "cancelled by the user", seed, settings)
    return tr.result("surrogate", label, status, message, seed, settings)


# ------------------------------------------------------------------------------------------------
# Solver 3: particle swarm (pymoo)
# ------------------------------------------------------------------------------------------------


def solve_pso(
    problem: OptimisationProblem,
    pop_size: int = 24,
    max_generations: int = 50,
    seed: int = 0,
    margin: float = 0.05,
    progress: Callable | None = None,
    stop: Callable | None = None,
) -> OptimisationResult:
    """Particle swarm with feasibility-first constraint handling (pymoo ``PSO``).

    pymoo's adaptive PSO (Zhan et al. 2009) keeps personal and global bests by Deb's rules: a
    feasible design beats an infeasible one, two feasible ones compare by objective, two
    infeasible ones by total violation. The swarm flies in the unit cube widened by ``margin``
    on each side and every particle is evaluated at its projection onto the bounds, so optima on
    a bound (common here) are reachable. Each generation is one vectorised evaluation.

    Parameters
    ----------
    problem : OptimisationProblem or FunctionProblem
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
    OptimisationResult

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
    tr = _Tracker(problem, pop_size * max_generations, progress, stop, "Particle swarm")
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
    except OptimisationCancelled:
        return tr.result("pso", label, "cancelled", "cancelled by the user", seed, settings)
    gens = algorithm.n_gen - 1 if algorithm.n_gen else 0
    status = "budget" if gens >= max_generations else "converged"
    message = f"{gens} generations of {pop_size} particles"
    return tr.result("pso", label, status, message, seed, settings)


# ------------------------------------------------------------------------------------------------
# Running and comparing the three solvers
# ------------------------------------------------------------------------------------------------

#: Solver keys -> (display name, function).
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
    problem: OptimisationProblem,
    solver: str,
    setting: str = "normal",
    seed: int = 0,
    progress: Callable | None = None,
    stop: Callable | None = None,
    **overrides: Any,
) -> OptimisationResult:
    """Run one solver with the settings of a run level.

    Parameters
    ----------
    problem : OptimisationProblem or FunctionProblem
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
    budget.check_optimisation(problem, solver, kw)
    return SOLVERS[solver][1](problem, seed=seed, progress=progress, stop=stop, **kw)


def compare_solvers(
    problem: OptimisationProblem,
    setting: str = "normal",
    seed: int = 0,
    solvers: Sequence[str] = tuple(SOLVERS),
    progress: Callable | None = None,
    stop: Callable | None = None,
) -> list[OptimisationResult]:
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


def agreement(results: Sequence[OptimisationResult]) -> float:
    """Relative spread of the objective among feasible results, (max - min)/min [-]
    (NaN when fewer than two are feasible)."""
    vals = [r.objective for r in results if r.feasible]
    if len(vals) < 2:
        return float("nan")
    return (max(vals) - min(vals)) / min(vals)


def comparison_rows(results: Sequence[OptimisationResult]) -> list[dict[str, Any]]:
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


def history_rows(results: Sequence[OptimisationResult]) -> list[dict[str, Any]]:
    """Convergence histories of several results as one long table."""
    rows = []
    for r in results:
        rows.extend(r.history.rows(r.label))
    return rows


def optimum_inputs(
    problem: OptimisationProblem, result: OptimisationResult
) -> tuple[Requirement, Configuration]:
    """(Requirement, Configuration) of an optimum, volume left to the sizing (``volume=None``),
    ready for :func:`aerostat_core.io.inputs_to_dict` ("save as case")."""
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
    (:func:`aerostat_core.cost.gas_fill_cost`, thesis Appendix H).

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
    from .design import design

    base = design(req, cfg_baseline)
    opt = design(req, cfg_baseline.with_design_variables(volume=None, **dict(x_optimum)))
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


# ------------------------------------------------------------------------------------------------
# Trade-off: total mass (or volume) versus blow-by limit
# ------------------------------------------------------------------------------------------------


def nondominated_mask(a, b) -> np.ndarray:
    """True for points not dominated in (a, b), both minimised.

    Point i is dominated when some j has a_j <= a_i and b_j <= b_i with at least one strict.
    NaN points are never in the set.

    Parameters
    ----------
    a, b : array_like
        Objective values (same length).

    Examples
    --------
    >>> nondominated_mask([1, 2, 3, 2], [3, 2, 1, 3]).tolist()
    [True, True, True, False]
    """
    a, b = np.asarray(a, float), np.asarray(b, float)
    ok = np.isfinite(a) & np.isfinite(b)
    le = (a[None, :] <= a[:, None]) & (b[None, :] <= b[:, None])
    lt = (a[None, :] < a[:, None]) | (b[None, :] < b[:, None])
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
    constraints of :class:`OptimisationProblem`, lower <= x <= upper, V in [2, 2e4] m3 (log
    scaled). V is the fourth variable here because the nested V*(x) exists for one limit at a
    time; with V free every epsilon problem evaluates without a sizing loop, and all of them
    (times the starts) run as lock-step SLSQP in one vectorised call per iteration. At
    epsilon = the requirement's limit the point equals the nested optimum (mass increases with
    V, so the smallest feasible V is optimal).

    Parameters
    ----------
    req, cfg : Requirement, Configuration
    bounds : mapping or None
        Design-variable bounds (see :class:`OptimisationProblem`).
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
        :class:`OptimisationCancelled`).

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
    problem = OptimisationProblem(req, cfg, bounds, objective)
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
            tasks.append(_slsqp_task(np.clip(u0, 0, 1), [(0.0, 1.0)] * d, int(maxiter), 1e-9))
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
            raise OptimisationCancelled
        return b

    scale: dict[str, float | None] = {"value": None}
    evaluate_requests = _stencil_evaluator(
        fn_eval, d, fd_step, lambda b: b.objective(objective), scale
    )
    outcome = _run_lockstep(tasks, evaluate_requests)
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
    problem = OptimisationProblem(req, cfg, bounds, objective)
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
        return evaluate_designs(req, cfg0, v["fineness_ratio"], v["area_change"], v["position"],
                                volume=_volume_from_unit(X[:, d]), blow_by_limit=hi_bb)

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


# ------------------------------------------------------------------------------------------------
# Baseline versus optimum performance (thesis Figs 4.17-4.22)
# ------------------------------------------------------------------------------------------------

#: Performance curves compared between baseline and optimum: key -> (label, unit).
PERFORMANCE_CURVES = {
    "blow_by": ("Blow-by", "m"),
    "alpha_eq": ("Equilibrium angle of attack", "deg"),
    "dynamic_lift": ("Dynamic lift", "N"),
    "tension_top": ("Tether tension at the confluence point", "N"),
}


def performance_curves(req: Requirement, cfg: Configuration) -> dict[str, Any]:
    """Performance versus wind of one design (:func:`aerostat_core.design`), as plain arrays.

    Parameters
    ----------
    req, cfg : Requirement, Configuration
        ``cfg.hull.volume`` None sizes the hull.

    Returns
    -------
    dict
        ``wind_speed`` [m/s] and the keys of :data:`PERFORMANCE_CURVES` (arrays), plus
        ``volume`` [m3], ``total_mass`` [kg], ``feasible`` (bool) and ``violations`` (list).
    """
    req = req.resolved()
    from .design import design

    d = design(req, cfg)
    p = d.performance
    out = {"wind_speed": np.asarray(p.wind_speed, float)}
    for k in PERFORMANCE_CURVES:
        out[k] = np.asarray(getattr(p, k), float)
    out.update(
        volume=float(d.volume),
        total_mass=float(d.total_mass),
        feasible=bool(d.feasible),
        violations=list(d.violations),
    )
    return out


def performance_comparison_rows(
    baseline: Mapping[str, Any], optimum: Mapping[str, Any]
) -> list[dict[str, Any]]:
    """Baseline and optimum performance side by side, one row per wind speed (CSV/table).

    Parameters
    ----------
    baseline, optimum : mapping
        :func:`performance_curves` of the two designs (same wind sweep).
    """
    w = np.asarray(baseline["wind_speed"], float)
    if not np.array_equal(w, np.asarray(optimum["wind_speed"], float)):
        raise ValueError("baseline and optimum were evaluated on different wind sweeps")
    rows = []
    for i, v in enumerate(w):
        row = {"wind_speed_m_s": float(v)}
        for k, (_, unit) in PERFORMANCE_CURVES.items():
            row[f"baseline_{k}_{unit}"] = float(baseline[k][i])
            row[f"optimum_{k}_{unit}"] = float(optimum[k][i])
        rows.append(row)
    return rows
