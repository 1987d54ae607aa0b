"""Design vocabulary and batch evaluation: the variables, bounds, constraints and objectives of
the optimisation problem, and :func:`evaluate_designs`, which sizes V*(x) and evaluates a whole
batch of designs in one vectorised pass (docs/methods.md §1.12, G4-G6).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from aerostat_core.model import input_paths
from aerostat_core.model.airframe import build_airframe
from aerostat_core.model.constraints import CONSTRAINTS as CONSTRAINT_TABLE
from aerostat_core.model.constraints import NAMES as CONSTRAINT_NAMES
from aerostat_core.model.constraints import TOLERANCE, constraint_state, violation_messages
from aerostat_core.model.cost import gas_fill_cost
from aerostat_core.model.inputs import Configuration, Requirement
from aerostat_core.model.sizing import size_volume

# ------------------------------------------------------------------------------------------------
# Problem vocabulary
# ------------------------------------------------------------------------------------------------

#: The thesis' design variables, in order.
VARIABLES = ("fineness_ratio", "area_change", "position")

#: Label, unit (of the value the optimiser works in, the input's own unit) and the engine's valid
#: range of each design variable, all read from the field registry (docs/architecture.md §8).
VARIABLE_INFO: dict[str, tuple[str, str, tuple[float, float]]] = {
    name: (
        input_paths.spec_for_path(input_paths.DESIGN_VARIABLES[name]).label,
        input_paths.spec_for_path(input_paths.DESIGN_VARIABLES[name]).spec.unit or "-",
        input_paths.variable_range(name),
    )
    for name in VARIABLES
}

#: Default bounds (docs/methods.md G6 with the fin area also allowed to shrink, to -50 %: the
#: statistical fin size is a starting point, not a floor; the lower limit is the engine's).
DEFAULT_BOUNDS: dict[str, tuple[float, float]] = {
    "fineness_ratio": (2.5, 4.5),
    "area_change": (-50.0, 100.0),
    "position": (0.60, 0.75),
}

#: Constraint names, in the column order of ``DesignBatch.constraints``: the one constraint
#: table of aerostat_core.model.constraints.
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
# Relative probe below the sized volume for the secant finish of V*(x) (sizing brackets to ~1e-4).
_SECANT_PROBE = 5e-4


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
        The constraint that sets the size (see :class:`~aerostat_core.model.sizing.SizingResult`), or
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
        return out + violation_messages(
            self.constraints[i],
            self.constraint_value[i],
            self.constraint_limit[i],
            self.design_wind,
            self.survival_wind,
        )

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
    ncol = shape + (len(CONSTRAINTS),)
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

    With ``volume=None`` the hull is sized: V*(x) = :func:`~aerostat_core.model.sizing.size_volume`
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
            feasible_size
            & (k_bind >= 0)
            & (g_lo > g_hi)
            & (g_lo > 0.0)
            & (g_hi <= FEASIBILITY_TOL)
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
                out["g"][rows[bracket], k_bind[bracket]], 0.0
            )
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


#: Why :func:`check_bounds` rejects bounds (:attr:`BoundsError.reason`).
BOUNDS_REASONS = (
    "not a mapping",  # the bounds are not a {variable: (lower, upper)} mapping
    "no variables",  # the mapping is empty
    "unknown",  # a name that is not a design variable
    "not numbers",  # a value that is not two numbers
    "not finite",  # a bound that is NaN or infinite
    "order",  # lower > upper
    "empty",  # lower == upper
    "range",  # the pair leaves the variable's valid range
)


class BoundsError(ValueError):
    """Rejected bounds of the design variables, with what a form needs to word the problem in
    its own labels and units (the message itself quotes engine units).

    Attributes
    ----------
    reason : str
        One of :data:`BOUNDS_REASONS`.
    variable : str
        The design variable (a key of :data:`VARIABLE_INFO`, or the unknown name as given); ""
        when the whole mapping is wrong.
    label, unit : str
        The variable's label and unit from the field registry ("" when unknown).
    lower, upper : float or None
        The bounds as given [unit of :data:`VARIABLE_INFO`]; None when they are not numbers.
    valid : tuple of float or None
        The variable's valid range (lowest, highest) in the same unit; None when unknown.
    """

    def __init__(
        self,
        message: str,
        reason: str,
        variable: str = "",
        lower: float | None = None,
        upper: float | None = None,
    ) -> None:
        super().__init__(message)
        if reason not in BOUNDS_REASONS:
            raise AssertionError(f"unknown bounds reason {reason!r}")
        self.reason, self.variable = reason, variable
        self.lower, self.upper = lower, upper
        info = VARIABLE_INFO.get(variable)
        self.label = info[0] if info else ""
        self.unit = info[1] if info else ""
        self.valid = info[2] if info else None


def check_bounds(bounds: Any) -> dict[str, tuple[float, float]]:
    """Validate a bounds mapping {variable: (lower, upper)}: the one check of design-variable
    bounds (the optimiser, the sensitivity sweeps and the app's forms all call it).

    Parameters
    ----------
    bounds : mapping
        Keys among :data:`VARIABLES`; values pairs of finite numbers (units of
        :data:`VARIABLE_INFO`), lower < upper, inside the engine's valid range.

    Returns
    -------
    dict
        {variable: (lower, upper)} as floats, in the order given.

    Raises
    ------
    BoundsError
        A ``ValueError`` naming the variable, the bounds and the valid range, with the
        details as attributes (:attr:`BoundsError.reason` says which rule failed).
    """
    if not isinstance(bounds, Mapping):
        raise BoundsError("bounds must be a mapping {variable: (lower, upper)}", "not a mapping")
    if len(bounds) == 0:
        raise BoundsError(
            "bounds are empty: give (lower, upper) for at least one of " + ", ".join(VARIABLES),
            "no variables",
        )
    out: dict[str, tuple[float, float]] = {}
    for name, pair in bounds.items():
        if name not in VARIABLE_INFO:
            raise BoundsError(
                f"unknown design variable {name!r} in bounds; valid: {', '.join(VARIABLES)}",
                "unknown",
                str(name),
            )
        label, unit, (vlo, vhi) = VARIABLE_INFO[name]
        u = "" if unit == "-" else f" {unit}"
        try:
            lo, hi = (float(v) for v in pair)
        except (TypeError, ValueError):
            raise BoundsError(
                f"bounds of {name} ({label}) must be two numbers (lower, upper), got {pair!r}",
                "not numbers",
                name,
            ) from None
        what = f"{name} ({label})"
        if not (math.isfinite(lo) and math.isfinite(hi)):
            msg = f"bounds of {what} must be finite, got ({lo:g}, {hi:g})"
            raise BoundsError(msg, "not finite", name, lo, hi)
        if lo > hi:
            msg = f"lower bound {lo:g}{u} > upper bound {hi:g}{u} for {what}"
            raise BoundsError(msg, "order", name, lo, hi)
        if lo == hi:
            msg = (
                f"bounds of {what} are empty: lower = upper = {lo:g}{u}; to hold it fixed, "
                "leave it out of the bounds (its configuration value is then used)"
            )
            raise BoundsError(msg, "empty", name, lo, hi)
        if lo < vlo or hi > vhi:
            msg = (
                f"bounds ({lo:g}, {hi:g}){u} of {what} leave the valid range [{vlo:g}, {vhi:g}]{u}"
            )
            raise BoundsError(msg, "range", name, lo, hi)
        out[name] = (lo, hi)
    return out
