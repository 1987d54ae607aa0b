"""The design pipeline: requirement + configuration -> a sized, trimmed aerostat with its tether.

:func:`design` is the public entry point; :func:`evaluate` is the vectorised core used by the
sweep, the sizing root-finder and the batch evaluator.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from aerostat_core.atmosphere.wind import profile_speed
from aerostat_core.model.airframe import Airframe
from aerostat_core.model.inputs import Configuration, Requirement
from aerostat_core.model.statics import (
    Equilibrium,
    MomentKernel,
    aero_loads,
    axial_drag_coefficient,
    central_difference,
    moment_coefficient,
    trim_equilibrium,
)
from aerostat_core.tether.statics import TetherSolution, solve_tether

#: Short text of each constraint broken at a sweep speed (the table's ``flags`` column); the
#: constraint definitions themselves live in aerostat_core.model.constraints.
FLAG_LABELS = {
    "blow_by": "blow-by above the limit",
    "altitude_loss": "altitude loss above the permissible reduction",
    "free_lift": "free lift below the required share of gross lift",
    "taut_tether": "slack tether (no upward tension somewhere along it)",
    "tether_angle": "tether angle from the vertical above the limit",
    "safety_factor": "tether safety factor below the required value",
    "stall": "angle of attack past fin stall",
    "stability": "statically unstable (no stable trim within +-80 deg)",
    "weathervane": "aerodynamically unstable about the centre of volume (fins lose to the Munk "
                   "moment)",
    "fins_on_hull": "fin trailing edge behind the tail",
    "envelope_stress": "envelope fabric strength below the safety factor times the load",
    "endurance": "free lift after the endurance below the required share",
}

@dataclass(frozen=True)
class Evaluation:
    """Static solution of an airframe at given wind speed(s) (all arrays broadcast together).

    alpha [rad], moment_slope dM_C/dalpha [N m/rad], lift (dynamic) [N], drag [N] (= the
    horizontal tension at the confluence point), tension_z (vertical tension there) [N], tether (TetherSolution), safety_factor [-],
    weathervane_slope (d aerodynamic moment about the centre of volume / d alpha) [N m/rad].
    Which limits a solution breaks is the constraint table's job (aerostat_core.model.constraints).
    """

    airframe: Airframe
    speed: np.ndarray
    equilibrium: Equilibrium
    lift: np.ndarray
    drag: np.ndarray
    tension_z: np.ndarray
    tether: TetherSolution
    safety_factor: np.ndarray
    weathervane_slope: np.ndarray


def tether_safety_factor(breaking_strength: float, tension) -> np.ndarray:
    """Tether safety factor at each wind: SF = F_break / max_s T(s) [-].

    Parameters
    ----------
    breaking_strength : float
        Breaking load of the tether as flown [N].
    tension : array, shape (nodes, ...)
        Tension along the line [N]; its largest value per wind is the load the tether carries.
        A slack line (T <= 1e-9 N) counts as 1e-9 N, so SF stays finite.

    Source: docs/methods.md §1.10 (the performance table and the safety-factor rows of the
    constraint table).

    >>> float(tether_safety_factor(1000.0, np.array([[100.0], [250.0]]))[0])
    4.0
    """
    tmax = np.max(tension, axis=0)
    return breaking_strength / np.maximum(tmax, 1e-9)


def evaluate(req: Requirement, cfg: Configuration, af: Airframe, speed,
             heights_hint=None) -> Evaluation:
    """Trim the aerostat and solve the tether at wind speed(s) ``speed`` [m/s] at the hull.

    Force balance on the aerostat at the confluence point (docs/methods.md §1.9):
    T_x = D, T_z = F_B + L_dyn - W_a; then the tether march down to the winch.

    ``heights_hint`` (optional, sheared wind only): node heights above the winch [m], shape
    (nodes, ...) broadcast to the batch, to start the tether's height passes from
    (:func:`aerostat_core.tether.statics.solve_tether`): a warm start that changes the number of
    passes, not the answer beyond their 1e-6 m tolerance.
    """
    speed = np.asarray(speed, float)
    cd0 = axial_drag_coefficient(af, cfg.aero, speed)
    moment = MomentKernel(af, cfg.aero, speed, cd0)  # statics.equilibrium, built once
    eq = trim_equilibrium(moment)
    loads = aero_loads(af, cfg.aero, eq.alpha, speed, cd0)
    tx = loads.drag * np.ones_like(eq.alpha)
    tz = (af.buoyancy - af.aerostat_weight + loads.lift) * np.ones_like(eq.alpha)
    profile = cfg.wind_profile
    spec = cfg.tether if af.tether is None else af.tether  # as flown (power conductors)
    teth = solve_tether(
        lambda h: (tx, tz),
        af.tether_length,
        spec,
        af.air_density,
        lambda z, h: profile_speed(profile, z, speed, h),
        af.tether_weight_per_length,
        cfg.tether_segments,
        sheared=profile.kind != "uniform",
        heights_hint=heights_hint,
    )
    sf = tether_safety_factor(spec.breaking_strength, teth.tension)
    # statics.weathervane_slope: the same loads about the centre of volume
    wv = central_difference(moment.about(af.hull.xi_cb), eq.alpha) * np.ones_like(eq.alpha)
    return Evaluation(af, speed, eq, loads.lift, tx, tz, teth, sf, wv)


@dataclass(frozen=True)
class PerformanceTable:
    """Performance versus wind speed (one row per speed). Columns as arrays, SI units:
    wind_speed [m/s], alpha_eq [deg], dynamic_lift [N], drag [N], blow_by [m], flying_height [m],
    altitude_loss [m], tension_top [N], tension_winch [N], tether_angle_top [deg from vertical],
    tether_angle_winch [deg from vertical], safety_factor [-], cm_alpha [1/rad] (C_m slope about
    the confluence point; NaN-free: 0 at zero wind, where C_m is undefined), cm_alpha_aero
    [1/rad] (aerodynamic moment slope about the centre of volume, the weathervane stability;
    0 at zero wind), flags (constraint name -> bool array: the constraint of the table that
    this wind speed breaks, with the requirement's design-wind limits; see
    aerostat_core.model.constraints) and ``limited`` (any flag set)."""

    wind_speed: np.ndarray
    alpha_eq: np.ndarray
    dynamic_lift: np.ndarray
    drag: np.ndarray
    blow_by: np.ndarray
    flying_height: np.ndarray
    altitude_loss: np.ndarray
    tension_top: np.ndarray
    tension_winch: np.ndarray
    tether_angle_top: np.ndarray
    tether_angle_winch: np.ndarray
    safety_factor: np.ndarray
    cm_alpha: np.ndarray
    cm_alpha_aero: np.ndarray
    flags: dict

    @property
    def limited(self) -> np.ndarray:
        """True for rows where any operating-limit flag is set."""
        out = np.zeros(self.wind_speed.shape, bool)
        for v in self.flags.values():
            out |= v
        return out

    def rows(self) -> list[dict]:
        """Rows as dicts with units in the column names (for tables and CSV)."""
        out = []
        for i, v in enumerate(self.wind_speed):
            out.append({
                "wind_speed_m_s": float(v),
                "alpha_eq_deg": float(self.alpha_eq[i]),
                "dynamic_lift_N": float(self.dynamic_lift[i]),
                "drag_N": float(self.drag[i]),
                "blow_by_m": float(self.blow_by[i]),
                "flying_height_m": float(self.flying_height[i]),
                "altitude_loss_m": float(self.altitude_loss[i]),
                "tension_top_N": float(self.tension_top[i]),
                "tension_winch_N": float(self.tension_winch[i]),
                "tether_angle_top_deg": float(self.tether_angle_top[i]),
                "tether_angle_winch_deg": float(self.tether_angle_winch[i]),
                "safety_factor": float(self.safety_factor[i]),
                "cm_alpha_per_rad": float(self.cm_alpha[i]),
                "cm_alpha_aero_cv_per_rad": float(self.cm_alpha_aero[i]),
                "flags": "; ".join(FLAG_LABELS.get(k, k) for k, f in self.flags.items() if f[i]),
            })
        return out


def performance_table(ev: Evaluation, flags: dict) -> PerformanceTable:
    """Collect a :class:`PerformanceTable` from an :class:`Evaluation` over a wind sweep and the
    per-speed constraint flags (:func:`aerostat_core.model.constraints.wind_flags`)."""
    af = ev.airframe
    q = 0.5 * af.air_density * ev.speed**2
    denom = q * af.hull.reference_area * af.hull.length
    safe = np.where(q > 0, denom, 1.0)
    cma = np.where(q > 0, ev.equilibrium.moment_slope / safe, 0.0)
    cma_aero = np.where(q > 0, ev.weathervane_slope / safe, 0.0)
    t = ev.tether
    return PerformanceTable(
        wind_speed=ev.speed,
        alpha_eq=np.degrees(ev.equilibrium.alpha),
        dynamic_lift=ev.lift,
        drag=ev.drag,
        blow_by=t.blow_by,
        flying_height=t.height,
        altitude_loss=af.tether_length - t.height,
        tension_top=t.tension_top,
        tension_winch=t.tension_winch,
        tether_angle_top=90.0 - np.degrees(t.elevation[0]),
        tether_angle_winch=90.0 - np.degrees(t.elevation[-1]),
        safety_factor=ev.safety_factor,
        cm_alpha=cma,
        cm_alpha_aero=cma_aero,
        flags=flags,
    )


def wind_speeds(req: Requirement) -> np.ndarray:
    """Sweep speeds 0, step, ..., wind_max [m/s] (the last point is wind_max itself)."""
    n = int(np.floor(req.wind_max / req.wind_step + 1e-9))
    v = np.arange(n + 1) * req.wind_step
    if v[-1] < req.wind_max - 1e-9:
        v = np.append(v, req.wind_max)
    return v


def cm_curve(af: Airframe, cfg: Configuration, speed: float, alpha_deg=None):
    """C_m about the confluence point versus alpha [deg] at wind ``speed`` [m/s] (> 0)."""
    a = np.arange(-10.0, 30.01, 1.0) if alpha_deg is None else np.asarray(alpha_deg, float)
    return a, moment_coefficient(af, cfg.aero, np.radians(a), max(float(speed), 1.0))
