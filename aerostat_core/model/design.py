"""Public entry point: :func:`design` turns a requirement and a configuration into a
:class:`Design` (geometry, mass breakdown, buoyancy, performance table, tether profiles)."""

from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass, fields, replace

import numpy as np

from aerostat_core.model import budget
from aerostat_core.model.airframe import Airframe, build_airframe
from aerostat_core.model.constraints import NAMES as CONSTRAINT_NAMES
from aerostat_core.model.constraints import (
    ConstraintState,
    LateralStability,
    constraint_state,
    state_flags,
    wind_flags,
)
from aerostat_core.model.cost import gas_fill_cost
from aerostat_core.model.inputs import Configuration, Requirement
from aerostat_core.model.mission import structure_quantities
from aerostat_core.model.mission_report import MissionReport, mission_report
from aerostat_core.model.performance import (
    PerformanceTable,
    cm_curve,
    evaluate,
    performance_table,
    wind_speeds,
)
from aerostat_core.model.presets import rules_configuration
from aerostat_core.model.sizing import SizingResult, size_volume
from aerostat_core.structures.mass import ITEM_NAMES
from aerostat_core.tether.statics import interpolated_heights


def _f(x) -> float:
    return float(np.asarray(x).reshape(-1)[0])


class FrozenMapping(Mapping):
    """Read-only mapping view of a frozen report dataclass (``report["key"]`` as before the
    dataclass; :meth:`to_dict` is the plain-data form). Subclasses define ``_view()``."""

    def _view(self) -> dict:  # pragma: no cover - overridden
        raise NotImplementedError

    def __getitem__(self, key: str):
        return self._view()[key]

    def __iter__(self):
        return iter(self._view())

    def __len__(self) -> int:
        return len(self._view())

    def keys(self):
        return self._view().keys()

    def items(self):
        return self._view().items()

    def values(self):
        return self._view().values()


@dataclass(frozen=True)
class MissionSummary:
    """Mission headline numbers (aerostat_core.model.mission): ballonet volume [m3], days until the
    free-lift margin is used up (None: never), helium top-up per deployment [m3], envelope
    stress margin [-] (strength / required - 1), winch pull [N] and winch power [W]."""

    ballonet_volume_m3: float
    days_to_top_up: float | None
    helium_top_up_m3: float
    envelope_stress_margin: float
    winch_pull_N: float
    winch_power_W: float

    def to_dict(self) -> dict:
        return {f.name: getattr(self, f.name) for f in fields(self)}


@dataclass(frozen=True)
class LateralSummary:
    """Lateral-directional stability keys of the summary (docs/dynamics.md §7.5; present once
    the 6-DOF check ran, :func:`aerostat_core.dynamics.lateral_constraint.assess_lateral`):
    whether the wind sweep ran (the rule set checks it), the wind speed at which the first
    lateral mode goes unstable [m/s] (None: stable up to the survival wind, or not checked),
    the highest wind checked [m/s], and the static lateral derivatives [1/rad] at the design
    wind (None when the hull has no equilibrium in the wind)."""

    lateral_stability_checked: bool
    lateral_unstable_above_m_s: float | None
    lateral_checked_up_to_m_s: float | None
    lateral_derivatives_wind_m_s: float | None
    C_Y_beta_per_rad: float | None
    C_n_beta_per_rad: float | None
    C_l_beta_per_rad: float | None
    C_n_beta_confluence_per_rad: float | None

    @classmethod
    def of(cls, lat: LateralStability) -> LateralSummary:
        return cls(
            lateral_stability_checked=lat.checked,
            lateral_unstable_above_m_s=lat.unstable_above if lat.checked else None,
            lateral_checked_up_to_m_s=lat.top_speed if lat.checked else None,
            lateral_derivatives_wind_m_s=lat.derivative_speed,
            C_Y_beta_per_rad=lat.C_Y_beta, C_n_beta_per_rad=lat.C_n_beta,
            C_l_beta_per_rad=lat.C_l_beta, C_n_beta_confluence_per_rad=lat.C_n_beta_confluence)

    def to_dict(self) -> dict:
        return {f.name: getattr(self, f.name) for f in fields(self)}


@dataclass(frozen=True, eq=True)
class DesignSummary(FrozenMapping):
    """Headline numbers of a design, SI units in the names (the CLI ``design --json`` keys).

    ``feasible``: every constraint of the table met; ``binding_constraint``: what sets the
    size (``"given volume"`` when the volume was given); ``violations``: plain-language
    reasons; ``rules``: the rule set; ``verdict``: "meets", "meets_nominal_only" or "fails"
    (:func:`aerostat_core.studies.robust.assess`); ``probability_meets_operating_limits``: from a
    seeded sample when one was asked for, else None; ``bending_moment_Nm``,
    ``wrinkling_moment_Nm``, ``envelope_pressure_Pa``: the envelope as a pressurised beam at the
    design wind (:func:`aerostat_core.structures.membrane.envelope_loads`: the largest bending moment,
    the wrinkling moment at the governing station, the pressure at the top of the hull);
    ``mission``: the mission rows (None: not computed, and then absent from :meth:`to_dict`);
    ``lateral``: the lateral-stability keys (:class:`LateralSummary`; None until the 6-DOF
    check ran, and then absent from :meth:`to_dict`).
    Quantities with no physical meaning are None: every wind quantity of a hull that sinks
    (free lift <= 0), and an altitude loss not smaller than the altitude. Read it as attributes
    or, as before, ``s["volume_m3"]``.
    """

    volume_m3: float
    length_m: float
    diameter_m: float
    total_mass_kg: float
    gross_buoyancy_N: float
    free_lift_N: float
    free_lift_kg: float
    percent_static_lift: float
    design_wind_m_s: float
    blow_by_at_design_wind_m: float
    alpha_at_design_wind_deg: float
    tension_top_at_design_wind_N: float
    safety_factor_at_design_wind: float
    gas_cost_USD: float
    feasible: bool
    hull_mass_kg: float
    tether_mass_kg: float
    altitude_loss_m: float
    survival_wind_m_s: float
    safety_factor_at_survival_wind: float
    binding_constraint: str
    violations: tuple[str, ...]
    rules: str
    verdict: str
    probability_meets_operating_limits: float | None
    bending_moment_Nm: float
    wrinkling_moment_Nm: float
    envelope_pressure_Pa: float
    mission: MissionSummary | None = None
    lateral: LateralSummary | None = None

    def to_dict(self) -> dict:
        """The summary as a plain dict (JSON types: violations a list), mission keys, then the
        lateral-stability keys, last."""
        out = {f.name: getattr(self, f.name) for f in fields(self)
               if f.name not in ("mission", "lateral")}
        out["violations"] = list(self.violations)
        if self.mission is not None:
            out.update(self.mission.to_dict())
        if self.lateral is not None:
            out.update(self.lateral.to_dict())
        return out

    _view = to_dict


@dataclass(frozen=True)
class Design:
    """A sized and trimmed aerostat.

    Attributes
    ----------
    requirement : Requirement
        The requirement as applied: every limit resolved from its rule set.
    configuration : Configuration
    volume : float
        Hull volume [m3]; ``sized`` says whether it was sized or given.
    sizing : SizingResult or None
    airframe : Airframe
        Geometry, fins, mass, buoyancy, confluence point (0-d arrays).
    performance : PerformanceTable
        Versus the wind sweep.
    design_point : dict
        The performance row at the design wind (same keys as ``PerformanceTable.rows()``).
    tether_x, tether_z : ndarray, shape (nodes, winds)
        Tether profiles from the winch (x downwind, z up) [m] for every sweep speed.
    cm_alpha_deg, cm : ndarray
        C_m about the confluence point versus alpha [deg] at the design wind.
    gas_cost : float
        Gas fill cost [USD].
    constraints : ConstraintState
        The constraint table (aerostat_core.model.constraints) at this volume: value, limit, margin.
    feasible : bool
        Every constraint of the table met (the one definition the optimiser and pages use).
    violations : tuple of str
        Plain-language reasons when not feasible.
    mission : MissionReport or None
        Power, endurance, ballonet, envelope, survival and winch outputs (aerostat_core.model.mission).
    robust : RobustSizing or None
        Set when the volume was sized for a confidence (``Requirement.confidence``,
        :func:`aerostat_core.studies.robust.design_with_confidence`).
    """

    requirement: Requirement
    configuration: Configuration
    volume: float
    sized: bool
    sizing: SizingResult | None
    airframe: Airframe
    performance: PerformanceTable
    design_point: dict
    tether_x: np.ndarray
    tether_z: np.ndarray
    cm_alpha_deg: np.ndarray
    cm: np.ndarray
    gas_cost: float
    constraints: ConstraintState
    feasible: bool
    violations: tuple
    mission: MissionReport | None = None
    robust: object | None = None

    # --- convenience views -------------------------------------------------------------
    @property
    def total_mass(self) -> float:
        """Total mass including gas, payload and tether [kg]."""
        return _f(self.airframe.mass.total)

    @property
    def free_lift(self) -> float:
        """Free lift = gross buoyancy - total weight [N]."""
        return _f(self.airframe.free_lift)

    @property
    def free_lift_kg(self) -> float:
        """Free lift expressed in kilograms [kg]."""
        return self.free_lift / self.airframe.g

    @property
    def buoyancy(self) -> float:
        """Gross buoyancy [N]."""
        return _f(self.airframe.buoyancy)

    @property
    def percent_static_lift(self) -> float:
        """PSL = 100 free lift / gross buoyancy [%] (docs/methods.md §1.3, our definition)."""
        return 100.0 * self.free_lift / self.buoyancy

    def tether_profile(self, speed: float) -> tuple[np.ndarray, np.ndarray]:
        """Tether shape (x downwind, z up, from the winch) [m] at any wind ``speed`` [m/s].

        Re-trims the aerostat at that speed and marches the tether (same model as the sweep).
        """
        if float(speed) == float(self.constraints.design_wind):  # solved with the table
            t = self.constraints.evaluation.tether
            return t.x[:, 0], t.z[:, 0]
        ev = evaluate(self.requirement, self.configuration, self.airframe, float(speed))
        return ev.tether.x, ev.tether.z

    def geometry_rows(self) -> list[dict]:
        """Hull and fin geometry as (quantity, value, unit) rows."""
        h, f, af = self.airframe.hull, self.airframe.fins, self.airframe
        rows = [
            ("Hull volume", h.volume, "m3"), ("Fineness ratio l/d", h.fineness_ratio, "-"),
            ("Hull length l", h.length, "m"), ("Hull diameter d", h.diameter, "m"),
            ("Nose semi-axis a1", h.a1, "m"), ("Tail semi-axis a2", h.a2, "m"),
            ("Max radius b", h.b, "m"), ("Hull surface area", h.surface_area, "m2"),
            ("Centre of buoyancy (from nose)", h.xi_cb, "m"),
            ("Centre of gravity (from nose)", af.mass.xi_cg, "m"),
            ("Centre of gravity below axis", -af.mass.z_cg, "m"),
            ("Confluence point (from nose)", af.xi_c, "m"),
            ("Confluence point below axis", -af.z_c, "m"),
            ("Number of fins", f.count, "-"), ("Fin root chord", f.root_chord, "m"),
            ("Fin tip chord", f.tip_chord, "m"), ("Fin span (exposed, one fin)", f.span, "m"),
            ("Fin leading-edge sweep", np.degrees(f.sweep_le), "deg"),
            ("Fin area (one fin)", f.area_one, "m2"), ("Fin area (all fins)", f.area_total, "m2"),
            ("Fin pair aspect ratio", f.aspect_ratio, "-"),
            ("Fin root leading edge (from nose)", f.xi_root_le, "m"),
            ("Fin root trailing edge (from nose)", f.xi_root_te, "m"),
            ("Fin aerodynamic centre (from nose)", f.xi_ac, "m"),
            ("Fin lift slope C_L_alpha (pair)", f.lift_slope, "1/rad"),
            ("Tether length", af.tether_length, "m"),
        ]
        return [{"quantity": q, "value": _f(v), "unit": u} for q, v, u in rows]

    def mass_rows(self) -> list[dict]:
        """Mass breakdown rows (item, mass [kg], share [%]) ending with the total."""
        m = self.airframe.mass
        tot = _f(m.total)
        rows = [{"item": k, "mass_kg": _f(m.items[k]), "share_pct": 100 * _f(m.items[k]) / tot}
                for k in ITEM_NAMES]
        rows.append({"item": "total", "mass_kg": tot, "share_pct": 100.0})
        return rows

    @property
    def sinks(self) -> bool:
        """The hull cannot lift its weight at rest (free lift <= 0): no tether tension, blow-by
        or safety factor means anything."""
        return self.free_lift <= 0.0

    def verdict(self):
        """The nominal verdict (:func:`aerostat_core.model.verdict.nominal_verdict`): "meets"
        or "fails", with what binds and what to change; with a robust sizing, its probability.
        The verdict with a seeded sample is :func:`aerostat_core.studies.robust.assess`."""
        from aerostat_core.model.verdict import nominal_verdict

        v = nominal_verdict(self)
        r = self.robust
        if r is not None and r.reached and v.verdict == "meets":
            v = replace(v, probability_meets_operating_limits=r.probability,
                        samples=r.samples, seed=r.seed)
        return v

    def envelope_loads(self) -> dict:
        """The envelope as a pressurised beam at the design wind
        (:func:`aerostat_core.structures.membrane.envelope_loads`): floats."""
        from aerostat_core.structures.membrane import envelope_loads

        out = envelope_loads(self.airframe, self.configuration, self.constraints.evaluation)
        return {k: float(np.asarray(v).reshape(-1)[0]) for k, v in out.items()}

    def summary(self, verdict=None) -> DesignSummary:
        """Headline numbers (floats, SI units in the names): :class:`DesignSummary`.
        ``verdict``: a :class:`aerostat_core.model.verdict.Verdict` already computed (with its
        sample); default the nominal one."""
        dp = self.design_point
        v = self.verdict() if verdict is None else verdict
        env = self.envelope_loads()
        sinks = self.sinks
        keep = (lambda x: None if sinks else x)  # noqa: E731 - meaningless when it sinks
        loss = dp["altitude_loss_m"]
        return DesignSummary(
            volume_m3=float(self.volume),
            length_m=_f(self.airframe.hull.length),
            diameter_m=_f(self.airframe.hull.diameter),
            total_mass_kg=self.total_mass,
            gross_buoyancy_N=self.buoyancy,
            free_lift_N=self.free_lift,
            free_lift_kg=self.free_lift_kg,
            percent_static_lift=self.percent_static_lift,
            design_wind_m_s=self.requirement.design_wind,
            blow_by_at_design_wind_m=keep(dp["blow_by_m"]),
            alpha_at_design_wind_deg=keep(dp["alpha_eq_deg"]),
            tension_top_at_design_wind_N=keep(dp["tension_top_N"]),
            safety_factor_at_design_wind=keep(dp["safety_factor"]),
            gas_cost_USD=self.gas_cost,
            feasible=self.feasible,
            hull_mass_kg=_f(self.airframe.mass.items["hull"]),
            tether_mass_kg=_f(self.airframe.mass.items["tether"]),
            altitude_loss_m=(None if sinks or loss >= self.requirement.altitude else loss),
            survival_wind_m_s=self.requirement.survival_wind,
            safety_factor_at_survival_wind=keep(self.constraints.value[
                CONSTRAINT_NAMES.index("survival_safety_factor")].item()),
            binding_constraint=self._binding(),
            violations=tuple(self.violations),
            rules=self.requirement.rules,
            verdict=v.verdict,
            probability_meets_operating_limits=v.probability_meets_operating_limits,
            bending_moment_Nm=env["bending_moment"],
            wrinkling_moment_Nm=env["wrinkling_moment"],
            envelope_pressure_Pa=env["pressure"],
            mission=self._mission_summary(),
            lateral=(None if self.constraints.lateral is None
                     else LateralSummary.of(self.constraints.lateral)),
        )

    def with_lateral(self, lateral: LateralStability) -> Design:
        """This design with the 6-DOF lateral-stability result in its constraint table (the
        ``lateral_stability`` row, :meth:`ConstraintState.with_lateral`), and its feasibility
        and violations updated: the row's message joins them when it is broken. The result is
        computed by :func:`aerostat_core.dynamics.lateral_constraint.assess_lateral`."""
        state = self.constraints.with_lateral(lateral)
        k = CONSTRAINT_NAMES.index("lateral_stability")
        msg = [m for m in state.messages() if m not in self.violations]
        broken = not bool(np.asarray(state.met).reshape(-1)[k])
        return replace(self, constraints=state, feasible=self.feasible and not broken,
                       violations=tuple(self.violations) + tuple(msg))

    def _binding(self) -> str:
        r = self.robust
        if r is not None and r.reached and r.volume > r.nominal_volume:
            return "confidence"
        if self.sizing is not None:
            return str(np.asarray(self.sizing.binding).reshape(-1)[0])
        return "given volume"

    def _mission_summary(self) -> MissionSummary | None:
        m = self.mission
        if m is None:
            return None
        fin = lambda x: None if not np.isfinite(x) else float(x)  # noqa: E731 - JSON has no inf
        return MissionSummary(
            ballonet_volume_m3=m.ballonet_volume,
            days_to_top_up=fin(m.days_to_top_up),
            helium_top_up_m3=m.helium_top_up,
            envelope_stress_margin=m.envelope_stress_margin,
            winch_pull_N=m.winch_pull,
            winch_power_W=m.winch.power,
        )

    def constraint_rows(self) -> list[dict]:
        """The constraint table at this design: value, limit, margin (own unit) and met."""
        return self.constraints.rows()


@functools.lru_cache(maxsize=16)
def _rules_configuration(rules: str) -> Configuration:
    """:func:`aerostat_core.model.presets.rules_configuration` of a rule set, built once (a
    frozen configuration: every default design of the rule set shares it; building and
    validating it again was a twentieth of a tactical design's time)."""
    return rules_configuration(rules)


def design(req: Requirement | None = None, cfg: Configuration | None = None) -> Design:
    """Size (if no volume is given), trim and evaluate an aerostat.

    Parameters
    ----------
    req : Requirement, optional
        Defaults to ``Requirement()`` (10 kg at 300 m, "practice" rules); resolved against its
        rule set.
    cfg : Configuration, optional
        Defaults to the rule set's configuration (:func:`aerostat_core.model.presets.rules_configuration`).

    Returns
    -------
    Design
        Never raises for a physically infeasible requirement: ``feasible`` is False and
        ``violations`` says which constraint binds. Invalid inputs raise ``ValueError`` when the
        dataclasses are built.

    Examples
    --------
    >>> from aerostat_core import Requirement, Configuration, design
    >>> d = design(Requirement(payload_mass=10, altitude=300))
    >>> d.sized, d.performance.wind_speed.size
    (True, 21)
    """
    req = (Requirement() if req is None else req).resolved()
    cfg = _rules_configuration(req.rules) if cfg is None else cfg
    budget.check_design(req, cfg)
    sizing = selection = None
    if cfg.materials == "catalogue":  # fabrics and tether chosen by their loads (issue 23)
        from aerostat_core.model.selection import select_materials

        selection = select_materials(req, cfg)
        cfg = selection.configuration
    if cfg.hull.volume is None:
        # the search evaluated the table (trim + tether at the design and survival winds) at
        # the volume it chose: that airframe and state are the design's
        sizing = selection.sizing if selection is not None else size_volume(req, cfg)
        volume = _f(sizing.volume)
        state = sizing.state
        af = state.evaluation.airframe
    else:
        volume = float(cfg.hull.volume)
        af = build_airframe(req, cfg, volume)
        state = constraint_state(req, cfg, af)
    speeds = wind_speeds(req)
    hint = None
    if cfg.wind_profile.kind != "uniform":
        # warm start of the sweep's height passes (docs/methods.md §1.9): the table's lines at
        # the design and survival winds (and the vertical line at rest), interpolated per
        # speed in the top angle; the converged sweep is the same from any start
        known = state.evaluation.tether
        el, zk = (np.reshape(a, (a.shape[0], 2)) for a in (known.elevation, known.z))
        hint = functools.partial(interpolated_heights, elevation=el, z=zk,
                                 length=af.tether_length, vertical=True)
    ev = evaluate(req, cfg, af, speeds, heights_hint=hint)
    # the sweep's envelope loads, for its flags and for the mission's reel-in wind
    sweep_structure = structure_quantities(req, cfg, ev)
    table = performance_table(ev, wind_flags(req, cfg, ev, state, sweep_structure))
    at_winds = state.evaluation  # [design, survival] wind: the design point is its first row
    # its flags are the table's own design-wind rows (only that first row is kept)
    flags = {k: np.array([v, False]) for k, v in state_flags(state).items()}
    design_point = performance_table(at_winds, flags).rows()[0]
    a_deg, cm = cm_curve(af, cfg, req.design_wind if req.design_wind > 0 else 10.0)
    state = ConstraintState(
        g=np.asarray(state.g).reshape(-1), margin=np.asarray(state.margin).reshape(-1),
        value=np.asarray(state.value).reshape(-1), limit=np.asarray(state.limit).reshape(-1),
        design_wind=state.design_wind, survival_wind=state.survival_wind,
        evaluation=state.evaluation, lateral_on=state.lateral_on)
    violations = []
    if sizing is not None and not bool(np.asarray(sizing.feasible).reshape(-1)[0]):
        violations.append(str(np.asarray(sizing.message).reshape(-1)[0]))
    violations += state.messages()
    if selection is not None:
        violations += selection.messages()
    # the mission's sweep includes the design wind (its reel-in wind may be that speed)
    mission = mission_report(req, cfg, af, state, ev, cfg.gas_price_value, sweep_structure)
    return Design(
        requirement=req,
        configuration=cfg,
        volume=volume,
        sized=sizing is not None,
        sizing=sizing,
        airframe=af,
        performance=table,
        design_point=design_point,
        tether_x=ev.tether.x,
        tether_z=ev.tether.z,
        cm_alpha_deg=a_deg,
        cm=np.asarray(cm, float),
        gas_cost=_f(gas_fill_cost(volume, cfg.gas_price_value)),
        constraints=state,
        feasible=not violations,
        violations=tuple(violations),
        mission=mission,
    )
