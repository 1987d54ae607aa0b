"""Public entry point: :func:`design` turns a requirement and a configuration into a
:class:`Design` (geometry, mass breakdown, buoyancy, performance table, tether profiles)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import budget
from .airframe import Airframe, build_airframe
from .cost import gas_fill_cost
from .inputs import Configuration, Requirement
from .mass import ITEM_NAMES
from .performance import (
    FLAG_TEXT,
    PerformanceTable,
    cm_curve,
    evaluate,
    performance_table,
    wind_speeds,
)
from .sizing import SizingResult, size_volume


def _f(x) -> float:
    return float(np.asarray(x).reshape(-1)[0])


@dataclass(frozen=True)
class Design:
    """A sized and trimmed aerostat.

    Attributes
    ----------
    requirement, configuration : the inputs.
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
    feasible : bool
        All requirements met at the design wind (blow-by limit, positive free lift, taut tether,
        stable trim below fin stall, tether safety factor, fins on the hull).
    violations : tuple of str
        Plain-language reasons when not feasible.
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
    feasible: bool
    violations: tuple

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
        """PSL = 100 free lift / gross buoyancy [%] (methods.md §1.3, our definition)."""
        return 100.0 * self.free_lift / self.buoyancy

    def tether_profile(self, speed: float) -> tuple[np.ndarray, np.ndarray]:
        """Tether shape (x downwind, z up, from the winch) [m] at any wind ``speed`` [m/s].

        Re-trims the aerostat at that speed and marches the tether (same model as the sweep).
        """
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

    def summary(self) -> dict:
        """Headline numbers (floats, SI units in the keys)."""
        dp = self.design_point
        return {
            "volume_m3": self.volume,
            "length_m": _f(self.airframe.hull.length),
            "diameter_m": _f(self.airframe.hull.diameter),
            "total_mass_kg": self.total_mass,
            "gross_buoyancy_N": self.buoyancy,
            "free_lift_N": self.free_lift,
            "free_lift_kg": self.free_lift_kg,
            "percent_static_lift": self.percent_static_lift,
            "design_wind_m_s": self.requirement.design_wind,
            "blow_by_at_design_wind_m": dp["blow_by_m"],
            "alpha_at_design_wind_deg": dp["alpha_eq_deg"],
            "tension_top_at_design_wind_N": dp["tension_top_N"],
            "safety_factor_at_design_wind": dp["safety_factor"],
            "gas_cost_USD": self.gas_cost,
            "feasible": self.feasible,
        }


def design(req: Requirement | None = None, cfg: Configuration | None = None) -> Design:
    """Size (if no volume is given), trim and evaluate an aerostat.

    Parameters
    ----------
    req : Requirement, optional
        Defaults to ``Requirement()`` (10 kg at 300 m).
    cfg : Configuration, optional
        Defaults to ``Configuration()``.

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
    req = Requirement() if req is None else req
    cfg = Configuration() if cfg is None else cfg
    budget.check_design(req, cfg)
    sizing = None
    if cfg.hull.volume is None:
        sizing = size_volume(req, cfg)
        volume = _f(sizing.volume)
    else:
        volume = float(cfg.hull.volume)
    af = build_airframe(req, cfg, volume)
    speeds = wind_speeds(req)
    all_speeds = np.append(speeds, req.design_wind)
    ev = evaluate(req, cfg, af, all_speeds)
    table_all = performance_table(ev)
    rows = table_all.rows()
    design_point = rows[-1]
    n = speeds.size
    table = PerformanceTable(**{
        k: (v[:n] if isinstance(v, np.ndarray) else {kk: vv[:n] for kk, vv in v.items()})
        for k, v in table_all.__dict__.items()
    })
    a_deg, cm = cm_curve(af, cfg, req.design_wind if req.design_wind > 0 else 10.0)
    violations = []
    if sizing is not None and not bool(np.asarray(sizing.feasible).reshape(-1)[0]):
        b = str(np.asarray(sizing.binding).reshape(-1)[0])
        violations.append({
            "blow_by": f"blow-by limit {req.blow_by_limit:g} m at {req.design_wind:g} m/s cannot "
                       f"be met by any hull up to 20000 m3 "
                       f"(best {design_point['blow_by_m']:.1f} m)",
            "free_lift": "no hull up to 20000 m3 has positive free lift (fabric too heavy for the "
                         "payload, gas and altitude)",
            "slack": "the tether goes slack at the design wind for every hull volume",
        }.get(b, b))
    if _f(af.free_lift) <= 0:
        violations.append(f"free lift is not positive ({_f(af.free_lift):.0f} N)")
    if design_point["blow_by_m"] > req.blow_by_limit * (1 + 1e-3) and not violations:
        violations.append(f"blow-by {design_point['blow_by_m']:.1f} m exceeds the limit "
                          f"{req.blow_by_limit:g} m at {req.design_wind:g} m/s")
    if sizing is not None and bool(ev.flags["low_safety_factor"][-1]) and not violations:
        violations.append(
            f"tether safety factor {design_point['safety_factor']:.2f} is below the required "
            f"{req.min_tether_safety_factor:g} at the smallest hull that meets the blow-by limit; a "
            "larger hull only pulls harder: choose a stronger tether or relax the blow-by limit")
    for key, text in FLAG_TEXT.items():
        if key == "low_safety_factor" and sizing is not None and violations:
            continue
        if key in ("no_free_lift", "over_blow_by_limit"):  # reported above in more detail
            continue
        if bool(ev.flags[key][-1]):
            violations.append(f"at the design wind: {text}")
    if _f(af.fins.xi_root_te) > _f(af.hull.length):
        violations.append("fin trailing edge lies behind the tail (fins off the hull)")
    return Design(
        requirement=req,
        configuration=cfg,
        volume=volume,
        sized=sizing is not None,
        sizing=sizing,
        airframe=af,
        performance=table,
        design_point=design_point,
        tether_x=ev.tether.x[:, :n],
        tether_z=ev.tether.z[:, :n],
        cm_alpha_deg=a_deg,
        cm=np.asarray(cm, float),
        gas_cost=_f(gas_fill_cost(volume, cfg.gas_price_value)),
        feasible=not violations,
        violations=tuple(violations),
    )
