"""The constraint table: one definition of feasibility for sizing, ``design()``, the optimiser,
the performance flags, the pages and the CLI.

Each :class:`Constraint` has a name, a dimensionless value g(x) that is met when g <= its
tolerance, a plain-language meaning and violation message, and a margin in the constraint's own
unit (positive when met). :func:`constraint_state` evaluates the whole table for a batch of
airframes at the requirement's design and survival winds (one vectorised trim + tether solve).

Normalisations (docs/methods.md §1.12): an upper limit q <= q_max is g = q/q_max - 1; a lower
limit q >= q_min is g = 1 - q/q_min; the free-lift margin is g = f_req - L_f/F_B (fraction of
gross lift); the moment slopes are already coefficients per radian, g = C_m_alpha - limit.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from aerostat_core.model.airframe import Airframe
from aerostat_core.model.inputs import Configuration, Requirement
from aerostat_core.model.mission import endurance_quantities, structure_quantities
from aerostat_core.model.performance import Evaluation, evaluate

#: Feasibility tolerance on every g [-]: a design meets a constraint when g <= this.
TOLERANCE = 1e-6


@dataclass(frozen=True)
class Constraint:
    """One row of the constraint table.

    name : key; label : short title; unit : unit of the margin and of value/limit;
    text : what "met" means; template : violation message, formatted with ``value``, ``limit``
    and ``wind`` (the wind speed it is checked at); at : "design", "survival" or "static"
    (where it is checked); advice : what to change when no hull volume meets it;
    tolerance : on g [-].
    """

    name: str
    label: str
    unit: str
    text: str
    template: str
    at: str
    advice: str = ""
    tolerance: float = TOLERANCE


#: The table, in display order.
CONSTRAINTS: tuple[Constraint, ...] = (
    Constraint("blow_by", "Blow-by", "m", "blow-by at the design wind within the limit",
               "blow-by {value:.1f} m exceeds the limit {limit:.1f} m at {wind:g} m/s", "design",
               "relax the blow-by limit or the design wind, or lower the drag"),
    Constraint("altitude_loss", "Altitude loss", "m",
               "altitude loss at the design wind within the permissible reduction",
               "altitude loss {value:.1f} m exceeds the permissible {limit:.1f} m at {wind:g} m/s",
               "design", "a larger hull (more free lift), a higher permissible altitude loss or a "
               "lower design wind"),
    Constraint("free_lift", "Free lift", "kg", "free lift at rest at least the required share "
               "of gross lift",
               "free lift {value:.2f} kg is below the required {limit:.2f} kg", "static",
               "a larger hull, a lighter payload, fabric or tether, a lower altitude, or hydrogen"),
    Constraint("taut_tether", "Taut tether", "N", "tether taut (upward tension everywhere) at "
               "the design wind",
               "the tether goes slack at {wind:g} m/s (net upward pull {value:.0f} N)", "design",
               "a larger hull, a lighter payload or a lower altitude"),
    Constraint("tether_angle", "Tether angle", "deg",
               "tether angle from the vertical at the design wind within the limit",
               "tether {value:.0f} deg from the vertical exceeds {limit:.0f} deg at {wind:g} m/s",
               "design", "a larger hull (more free lift), a larger tether-angle limit or a lower "
               "design wind"),
    Constraint("safety_factor", "Tether safety factor", "-",
               "tether safety factor at the design wind at least the required value",
               "tether safety factor {value:.2f} is below the required {limit:g} at {wind:g} m/s",
               "design", "a larger hull only pulls harder: choose a stronger tether or relax the "
               "blow-by limit"),
    Constraint("survival_safety_factor", "Survival safety factor", "-",
               "tether safety factor at the survival wind at least the required value",
               "tether safety factor {value:.2f} is below the required {limit:g} at the "
               "survival wind {wind:g} m/s", "survival",
               "a larger hull only pulls harder: choose a stronger tether"),
    Constraint("stall", "Fin stall", "deg", "equilibrium angle of attack below fin stall",
               "angle of attack {value:.1f} deg is past fin stall ({limit:g} deg) at {wind:g} m/s",
               "design", "larger fins or a different confluence point"),
    Constraint("stability", "Static stability", "1/rad",
               "statically stable trim about the confluence point (C_m_alpha < 0)",
               "statically unstable about the confluence point at {wind:g} m/s "
               "(C_m_alpha {value:+.3f}/rad; no stable trim within +-80 deg if it is not found)",
               "design", "larger fins or a confluence point further forward"),
    Constraint("weathervane", "Weathervane stability", "1/rad",
               "aerodynamically stable hull: C_m_alpha of hull + fins about the centre of volume "
               "at most minus the required margin",
               "aerodynamically unstable about the centre of volume at {wind:g} m/s (C_m_alpha "
               "{value:+.3f}/rad, needs <= {limit:+.3f}/rad): the fins lose to the Munk moment",
               "design", "larger fins, fins further aft or a lower fineness ratio"),
    # checked after sizing by the 6-DOF linearisation (aerostat_core.dynamics.lateral_constraint;
    # docs/dynamics.md §7.5): never binding inside the vectorised table (see LateralStability)
    Constraint("lateral_stability", "Lateral stability", "m/s",
               "laterally stable up to the survival wind: every lateral-directional mode (roll, "
               "yaw, sideslip, the swing on the tether) of the 6-DOF model decays at each wind "
               "speed up to it",
               "a lateral-directional mode grows (kiting) from {value:.1f} m/s, below the "
               "survival wind {limit:g} m/s", "survival",
               "larger fins, fins further aft or a confluence point further forward"),
    Constraint("fins_on_hull", "Fins on the hull", "m", "fin trailing edge on the hull",
               "fin trailing edge {value:.2f} m from the nose lies behind the tail "
               "({limit:.2f} m)", "static", "smaller fins or fins further forward"),
    # mission rows (issue 13, aerostat_core.model.mission); met by today's designs unless the user asks
    Constraint("envelope_stress", "Envelope stress", "N/m",
               "envelope fabric strength at least the safety factor times the membrane load at "
               "the required internal pressure, at the design wind",
               "envelope fabric needs {value:.0f} N/m (load x safety factor) but has "
               "{limit:.0f} N/m at {wind:g} m/s", "design",
               "a larger hull only loads its fabric harder: choose a stronger fabric"),
    Constraint("envelope_wrinkling", "Envelope wrinkling", "N m",
               "envelope bending moment (the hull as a pressurised beam) below the wrinkling "
               "moment pi p r^3/2 of its governing section at the largest pressure the fabric "
               "carries with its safety factor, at the design wind",
               "the envelope bending moment {value:.0f} N m exceeds the wrinkling moment "
               "{limit:.0f} N m at the largest pressure the fabric carries, at {wind:g} m/s: "
               "the hull creases", "design",
               "a stronger envelope fabric, a lower fineness ratio, or confluence lines spread "
               "along more of the hull"),
    Constraint("survival_envelope_pressure", "Survival envelope pressure", "Pa",
               "the fabric carries, with its safety factor, the internal pressure the hull needs "
               "at the survival wind",
               "the hull needs {value:.0f} Pa at the survival wind {wind:g} m/s but the fabric "
               "carries only {limit:.0f} Pa with its safety factor", "survival",
               "choose a stronger fabric, or reel the aerostat in below the survival wind"),
    Constraint("endurance", "Endurance", "day",
               "free lift still at least the required share of gross lift after the top-up "
               "interval (or the endurance asked, if longer) of helium permeation",
               "the free-lift margin lasts {value:.1f} days of permeation, not the required "
               "{limit:g} days", "static",
               "a larger hull, a fabric of lower helium permeability or a shorter time between "
               "top-ups"),
)

#: Constraint names in table order (the column order of every g array).
NAMES: tuple[str, ...] = tuple(c.name for c in CONSTRAINTS)
#: Constraint by name.
BY_NAME: dict[str, Constraint] = {c.name: c for c in CONSTRAINTS}
#: Rows the vectorised table evaluates: all but ``lateral_stability``, which needs the 6-DOF
#: model per design and is filled after sizing; a Monte Carlo sample says nothing about it.
VECTORISED_NAMES: tuple[str, ...] = tuple(n for n in NAMES if n != "lateral_stability")


@dataclass(frozen=True)
class LateralStability:
    """Lateral-directional stability of one design, from the 6-DOF model linearised about its
    equilibrium at each wind speed (computed by :mod:`aerostat_core.dynamics.lateral_constraint`,
    docs/dynamics.md §7.5): what the ``lateral_stability`` row and the summary read.

    Parameters
    ----------
    checked : bool
        The wind sweep ran (the rule set checks the row); False: only the derivatives.
    unstable_above : float or None
        Lowest wind speed [m/s] at which a lateral mode grows (the largest real part of the
        lateral eigenvalues crosses zero); None when every mode decays up to ``top_speed``.
    top_speed : float
        Highest wind speed checked [m/s] (the survival wind).
    derivative_speed : float or None
        Wind speed of the static derivatives [m/s] (the design wind).
    C_Y_beta, C_n_beta, C_l_beta, C_n_beta_confluence : float or None
        Static lateral derivatives [1/rad] (side force; yawing moment about the centre of
        volume; rolling moment about the confluence point; yawing moment about the confluence
        point), None when the design has no equilibrium in the wind (it sinks).
    note : str
        Why a number is missing (empty when none is).
    """

    checked: bool
    unstable_above: float | None
    top_speed: float
    derivative_speed: float | None
    C_Y_beta: float | None
    C_n_beta: float | None
    C_l_beta: float | None
    C_n_beta_confluence: float | None
    note: str = ""

    @property
    def stable(self) -> bool:
        """Every lateral mode decays up to ``top_speed`` (False when not checked)."""
        return self.checked and self.unstable_above is None


def lateral_applies(req: Requirement) -> bool:
    """True when the requirement's rule set checks the ``lateral_stability`` row (and the
    requirement names a survival wind above calm)."""
    req = req.resolved()
    return bool(req.rule_set.check_lateral_stability and req.survival_wind
                and req.survival_wind > 0)


def lateral_quantities(survival_wind: float, lateral: LateralStability | None):
    """Value, limit, g and margin of the ``lateral_stability`` row [m/s].

    value: the lowest wind speed at which a lateral mode grows, or the survival wind when every
    mode decays up to it; limit: the survival wind V_s; g = 1 - value/V_s when a mode grows
    below V_s (> 0: broken), -1 when none does (margin unbounded within the check). Not
    evaluated (``lateral`` None or not checked): value and margin NaN, g = -1 (the vectorised
    table never evaluates the row: it needs a 6-DOF linearisation per design).

    Examples
    --------
    >>> lat = LateralStability(True, 12.0, 20.0, 10.0, -2.0, 0.1, -0.5, 0.3)
    >>> [round(x, 2) for x in lateral_quantities(20.0, lat)]
    [12.0, 20.0, 0.4, -8.0]
    """
    vs = float(survival_wind)
    if lateral is None or not lateral.checked:
        return np.nan, vs, -1.0, np.nan
    u = lateral.unstable_above
    if u is None or u >= vs:
        return vs, vs, -1.0, np.inf
    return float(u), vs, 1.0 - float(u) / vs, float(u) - vs


def violation_messages(g, value, limit, design_wind: float, survival_wind: float) -> list[str]:
    """Messages of the constraints broken by one design (rows of g, value, limit in table order)."""
    out = []
    for k, c in enumerate(CONSTRAINTS):
        if float(g[k]) > c.tolerance:
            wind = survival_wind if c.at == "survival" else design_wind
            out.append(c.template.format(value=float(value[k]), limit=float(limit[k]), wind=wind))
    return out


def _upper(value, limit):
    return value / limit - 1.0, limit - value


def _lower(value, limit):
    return 1.0 - value / limit, value - limit


def limit_met(value: float, limit: float, kind: str) -> bool:
    """Whether ``value`` meets its ``limit`` by the constraint table's rule (module docstring):
    an upper limit ("max") g = value/limit - 1, a lower one ("min") g = 1 - value/limit, met
    when g <= :data:`TOLERANCE`. Dimensionless in any consistent unit; ``limit`` non-zero.
    The headline numbers' deltas use it, so they read as the verdict does.

    >>> limit_met(150.0, 150.0, "max"), limit_met(150.1, 150.0, "max")
    (True, False)
    >>> limit_met(2.9999999, 3.0, "min"), limit_met(2.9, 3.0, "min")
    (True, False)
    """
    g = (_upper if kind == "max" else _lower)(value, limit)[0]
    return bool(g <= TOLERANCE)


def wind_quantities(req: Requirement, cfg: Configuration, ev: Evaluation,
                    structure: dict | None = None) -> dict:
    """Value, limit and g of every wind-dependent constraint for an evaluation at any speed(s).

    Parameters
    ----------
    req : Requirement
        Resolved requirement (its limits are used at every speed of ``ev``).
    cfg : Configuration
    ev : Evaluation
        Trim and tether solution (arrays broadcast over designs and speeds).
    structure : dict, optional
        :func:`aerostat_core.model.mission.structure_quantities` of ``ev`` when the caller
        has them already (computed here otherwise).

    Returns
    -------
    dict
        name -> (value, limit, g, margin) arrays, for the constraints checked at a wind speed
        (the safety factor uses ``req.min_tether_safety_factor``).
    """
    af = ev.airframe
    shape = np.broadcast_shapes(np.shape(ev.equilibrium.alpha), np.shape(ev.tether.blow_by))
    one = np.ones(shape)
    # moment slopes scale with q at the speed itself: normalise by that q (1 m/s in calm air,
    # where only the buoyancy pendulum acts and the weathervane row is not checked; 1 cm/s floor)
    u = np.where(ev.speed > 0, np.maximum(ev.speed, 1e-2), 1.0)
    q = 0.5 * af.air_density * u**2
    norm = q * af.hull.reference_area * af.hull.length
    cma = ev.equilibrium.moment_slope / norm * one
    cma = np.where(ev.equilibrium.found, cma, np.abs(cma) + 1e-3)
    cma_aero = np.where(ev.speed > 0, ev.weathervane_slope / norm, -np.inf) * one
    loss = af.tether_length - ev.tether.height
    out = {}
    bb = ev.tether.blow_by * one
    out["blow_by"] = (bb, req.blow_by_limit * one, *_upper(bb, req.blow_by_limit))
    loss = loss * one
    out["altitude_loss"] = (loss, req.altitude_loss_limit * one,
                            *_upper(loss, req.altitude_loss_limit))
    tz = ev.tension_z * one
    slack = (ev.tether.slack | (ev.tension_z <= 0.0)) * np.ones(shape, bool)
    fb = np.maximum(np.abs(af.buoyancy), 1e-9)
    out["taut_tether"] = (tz, 0.0 * one, np.where(slack, 1.0, -np.minimum(tz / fb, 1.0)),
                          np.where(slack, np.minimum(tz, 0.0), tz))
    ang = np.degrees(ev.tether.max_angle_from_vertical) * one
    out["tether_angle"] = (ang, req.max_tether_angle_deg * one,
                           *_upper(ang, req.max_tether_angle_deg))
    sf = ev.safety_factor * one
    out["safety_factor"] = (sf, req.min_tether_safety_factor * one,
                            *_lower(sf, req.min_tether_safety_factor))
    stall = float(cfg.aero.fin_stall_angle_deg)
    a = np.abs(np.degrees(ev.equilibrium.alpha)) * one
    out["stall"] = (a, stall * one, *_upper(a, stall))
    out["stability"] = (cma, 0.0 * one, cma, -cma)
    lim = -float(req.weathervane_margin)
    wv_g = np.where(np.isfinite(cma_aero), cma_aero - lim, -1.0)
    out["weathervane"] = (np.where(np.isfinite(cma_aero), cma_aero, 0.0), lim * one, wv_g, -wv_g)
    st = structure_quantities(req, cfg, ev) if structure is None else structure
    need, fab = st["strength_required"] * one, st["strength"] * one
    out["envelope_stress"] = (need, fab, need / fab - 1.0, fab - need)
    mb, mw = st["moment_at_governing"] * one, st["wrinkling_moment_allowable"] * one
    if req.rule_set.check_wrinkling:
        out["envelope_wrinkling"] = (mb, mw, mb / np.maximum(mw, 1e-12) - 1.0, mw - mb)
    else:  # off in the rule set (the thesis preset): reported, never binding
        out["envelope_wrinkling"] = (mb, mw, -one, np.inf * one)
    p_req, p_ok = st["pressure_required"] * one, st["pressure_allowable"] * one
    g_p = np.where(p_ok > 0, p_req / np.where(p_ok > 0, p_ok, 1.0) - 1.0, 1.0 + p_req / fab)
    out["survival_envelope_pressure"] = (p_req, p_ok, g_p, p_ok - p_req)
    return out


def static_quantities(req: Requirement, af: Airframe, cfg: Configuration | None = None) -> dict:
    """Value, limit, g and margin of the constraints that do not depend on the wind (the
    endurance row needs ``cfg``; without it the row is off)."""
    g0 = af.g
    fb = np.maximum(np.abs(af.buoyancy), 1e-9)
    fl_kg = af.free_lift / g0
    need_kg = req.free_lift_fraction * af.buoyancy / g0
    out = {"free_lift": (fl_kg, need_kg, req.free_lift_fraction - af.free_lift / fb,
                         fl_kg - need_kg)}
    te = af.fins.xi_root_te * np.ones_like(af.hull.length)
    out["fins_on_hull"] = (te, af.hull.length, *_upper(te, af.hull.length))
    one = np.ones_like(af.hull.length)
    if cfg is None:
        out["endurance"] = (np.inf * one, 0.0 * one, -one, np.inf * one)
    else:
        e = endurance_quantities(req, cfg, af)
        out["endurance"] = (e["days_to_top_up"] * one, req.days_without_top_up * one,
                            e["g"] * one, e["margin"] * one)
    return out


@dataclass(frozen=True)
class ConstraintState:
    """The constraint table evaluated for a batch of designs.

    g, margin, value, limit : ndarray, shape (..., len(NAMES))
        Columns in the order of :data:`NAMES`; ``margin``, ``value`` and ``limit`` are in each
        constraint's unit (``CONSTRAINTS[k].unit``).
    design_wind, survival_wind : float
        Where the wind-dependent rows were checked [m/s].
    evaluation : Evaluation
        The trim + tether solution at [design, survival] wind (first axis of its arrays).
    lateral_on : bool
        The rule set checks the ``lateral_stability`` row (:func:`lateral_applies`); when False
        the row is left out of :meth:`rows`.
    lateral : LateralStability or None
        The 6-DOF result the row was filled from (:meth:`with_lateral`); None: not evaluated.
    """

    g: np.ndarray
    margin: np.ndarray
    value: np.ndarray
    limit: np.ndarray
    design_wind: float
    survival_wind: float
    evaluation: Evaluation
    lateral_on: bool = False
    lateral: LateralStability | None = None

    @property
    def met(self) -> np.ndarray:
        """Per constraint: g <= tolerance (shape of ``g``)."""
        tol = np.array([c.tolerance for c in CONSTRAINTS])
        return self.g <= tol

    @property
    def feasible(self) -> np.ndarray:
        """Every constraint met (shape of the batch)."""
        return self.met.all(axis=-1)

    @property
    def max_violation(self) -> np.ndarray:
        """Largest g over the table (<= tolerance when feasible)."""
        return self.g.max(axis=-1)

    def _wind(self, c: Constraint) -> float:
        return self.survival_wind if c.at == "survival" else self.design_wind

    def messages(self, index=()) -> list[str]:
        """Plain-language violation messages of design ``index`` (empty when feasible)."""
        return violation_messages(self.g[index], self.value[index], self.limit[index],
                                  self.design_wind, self.survival_wind)

    def with_lateral(self, lateral: LateralStability) -> ConstraintState:
        """This table (one design) with the ``lateral_stability`` row filled from ``lateral``
        (:func:`lateral_quantities`); the other rows are unchanged."""
        k = NAMES.index("lateral_stability")
        cols = {n: np.array(getattr(self, n), float, copy=True) for n in
                ("value", "limit", "g", "margin")}
        if self.lateral_on:
            q = lateral_quantities(self.survival_wind, lateral)
            for n, x in zip(("value", "limit", "g", "margin"), q):
                cols[n][..., k] = x
        return replace(self, **cols, lateral=lateral)

    def rows(self, index=()) -> list[dict]:
        """The table for design ``index``: name, label, checked at, value, limit, margin, unit,
        met, g."""
        met = self.met[index]
        rows = []
        for k, c in enumerate(CONSTRAINTS):
            at = {"static": "at rest", "design": f"{self.design_wind:g} m/s",
                  "survival": f"{self.survival_wind:g} m/s"}[c.at]
            if c.name == "lateral_stability":
                if not self.lateral_on:
                    continue  # off in the rule set: not part of this design's table
                lat = self.lateral
                at = (f"2-{self.survival_wind:g} m/s" if lat is not None and lat.checked
                      else "not evaluated")
            rows.append({
                "constraint": c.name, "label": c.label, "checked_at": at,
                "value": float(self.value[index][k]), "limit": float(self.limit[index][k]),
                "margin": float(self.margin[index][k]), "unit": c.unit,
                "met": bool(met[k]), "g": float(self.g[index][k]),
            })
        return rows


def constraint_state(req: Requirement, cfg: Configuration, af: Airframe,
                     heights_hint=None) -> ConstraintState:
    """Evaluate the whole table for an airframe batch (one trim + tether solve at two winds).

    Parameters
    ----------
    req : Requirement
        Resolved inside (``req.resolved()``).
    cfg : Configuration
    af : Airframe
        Any batch shape S.
    heights_hint : array_like, optional
        Tether node heights [m] of shape (nodes, 2, ...) (the [design, survival] wind axis
        second) to warm-start the sheared-wind height passes from
        (:func:`aerostat_core.model.performance.evaluate`); the answer is the same within their
        tolerance.

    Returns
    -------
    ConstraintState
        Arrays of shape S + (len(NAMES),).
    """
    req = req.resolved()
    shape = np.shape(af.hull.volume)
    speeds = np.array([req.design_wind, req.survival_wind], float).reshape((2,) + (1,) * len(shape))
    return table_of(req, cfg, evaluate(req, cfg, af, speeds, heights_hint))


def table_of(req: Requirement, cfg: Configuration, ev: Evaluation) -> ConstraintState:
    """The table of :func:`constraint_state` from its evaluation ``ev`` (trim and tether at the
    [design, survival] wind, the first axis; its airframe the batch), for a caller that has
    one: the selection, whose items' strengths change no trim and no tether line
    (:func:`aerostat_core.model.selection.select_materials`). ``req`` resolved."""
    af = ev.airframe
    shape = np.shape(af.hull.volume)
    wq = wind_quantities(req, cfg, ev)
    sq = static_quantities(req, af, cfg)
    full = (2,) + np.broadcast_shapes(shape, np.shape(ev.tether.blow_by)[1:])
    # the four tables, filled column by column (one broadcasting assignment a row: the same
    # numbers as stacking the rows, without the broadcast and stack of each table)
    tables = tuple(np.empty(full[1:] + (len(CONSTRAINTS),)) for _ in range(4))
    for k, c in enumerate(CONSTRAINTS):
        if c.name == "lateral_stability":
            parts = lateral_quantities(req.survival_wind, None)
        elif c.at == "static":
            parts = sq[c.name]
        else:
            i = 1 if c.at == "survival" else 0
            src = wq["safety_factor"] if c.name == "survival_safety_factor" else wq[c.name]
            # the wind rows carry the speed axis first (wind_quantities broadcasts them); a
            # part without it is the same at both winds (the assignment broadcasts it)
            nd = len(full)
            parts = [x[i] if np.ndim(x) == nd else x for x in src]
            if c.name == "survival_safety_factor":
                lim = req.survival_safety_factor
                v = np.asarray(parts[0], float)
                parts = [v, np.full_like(v, lim), *_lower(v, lim)]
        for table, part in zip(tables, parts):
            table[..., k] = part
    value, limit, g, margin = tables
    return ConstraintState(g=g, margin=margin, value=value, limit=limit,
                           design_wind=float(req.design_wind),
                           survival_wind=float(req.survival_wind), evaluation=ev,
                           lateral_on=lateral_applies(req))


def wind_flags(req: Requirement, cfg: Configuration, ev: Evaluation,
               state: ConstraintState | None = None, structure: dict | None = None) -> dict:
    """Per-speed flags for a wind sweep: constraint name -> bool array, True where the row
    breaks that constraint of the table (limits of the design wind applied at every speed; the
    survival check is the constraint table's, not a per-speed flag).

    ``state``: the constraint table of the same airframe (one design), whose static rows are
    then read instead of recomputed (the same numbers). ``structure``: the envelope's
    :func:`aerostat_core.model.mission.structure_quantities` of ``ev`` if known."""
    req = req.resolved()
    wq = wind_quantities(req, cfg, ev, structure)
    sq = static_quantities(req, ev.airframe, cfg) if state is None else None
    shape = np.shape(wq["blow_by"][0])
    flags = {}
    for k, c in enumerate(CONSTRAINTS):
        if c.at == "survival":
            continue
        if c.at == "static" and state is not None:
            g = np.asarray(state.g)[..., k]
        else:
            g = (sq if c.at == "static" else wq)[c.name][2]
        flags[c.name] = np.broadcast_to(g > c.tolerance, shape).copy()
    return flags


def state_flags(state: ConstraintState) -> dict:
    """The flags of :func:`wind_flags` at the design wind, read from a constraint table of one
    design (its design-wind and static rows are those g): name -> bool."""
    g = np.asarray(state.g).reshape(-1)
    return {c.name: bool(g[k] > c.tolerance) for k, c in enumerate(CONSTRAINTS)
            if c.at != "survival"}
