"""The mission report of one design: endurance, power, ballonet, structure, winch and gas
figures beside the constraint rows that judge them (docs/methods.md)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from aerostat_core.atmosphere.permeation import helium_top_up
from aerostat_core.model.constraints import NAMES
from aerostat_core.model.mission import (
    DAYS_CAP,
    BallonetState,
    ballonet_state,
    effective_tether,
    endurance_quantities,
    lift_decay,
    onboard_battery_mass,
    scalar,
    structure_quantities,
    tether_conductors,
)
from aerostat_core.structures.materials import TetherSpec
from aerostat_core.tether.power import Conductors
from aerostat_core.tether.winch import Winch, size_winch


# --- the report of one design ------------------------------------------------------------------
@dataclass(frozen=True)
class MissionReport:
    """Mission outputs of one design (floats, SI; days in days, gas in m3 at 0 degC and 1 atm).

    battery_mass [kg]; conductors (None without tether power); conductors_own (the configured
    power tether's conductors suffice); tether (as flown); tether_mass [kg];
    ballonet (BallonetState); ballonet_volume [m3]; ballonet_mass [kg];
    permeation_tau [day]; days_to_top_up [day] (inf: never); purity_after_endurance [-];
    helium_top_up [m3]; top_up_cost [USD]; deployment_days [day];
    envelope (dict of structure quantities at the design wind, floats);
    envelope_stress_margin : strength / required - 1 at the design wind [-];
    survival_pressure_margin : allowable / required pressure - 1 at the survival wind [-];
    survival_safety_factor [-] and its requirement; survival_tension : largest tether tension
    at the survival wind [N] (against ``tether.breaking_strength``); stay_up : both survival
    checks met;
    reel_in_wind : lowest sweep speed at which either fails (None if none in the sweep) [m/s];
    winch (Winch) sized for ``winch_pull`` [N], the largest winch tension over the sweep, the
    design and the survival wind; decay : purity and free lift versus day without top-up
    (:func:`lift_decay`).
    """

    battery_mass: float
    conductors: Conductors | None
    conductors_own: bool
    tether: TetherSpec
    tether_mass: float
    ballonet: BallonetState
    ballonet_volume: float
    ballonet_mass: float
    permeation_tau: float
    days_to_top_up: float
    purity_after_endurance: float
    helium_top_up: float
    top_up_cost: float
    deployment_days: float
    envelope: dict
    envelope_stress_margin: float
    survival_pressure_margin: float
    survival_safety_factor: float
    survival_safety_factor_required: float
    stay_up: bool
    reel_in_wind: float | None
    winch_pull: float
    winch: Winch
    survival_tension: float = float("nan")
    decay: dict | None = None

    def rows(self) -> list[dict]:
        """(group, quantity, value, unit) rows for tables and CSV."""
        k = self.conductors
        e = self.envelope
        days = self.days_to_top_up
        out = [
            ("Power", "Onboard battery mass", self.battery_mass, "kg"),
            (
                "Power",
                "Conductor copper area (each of 2)",
                0.0 if k is None else k.area * 1e6,
                "mm2",
            ),
            ("Power", "Conductor current", 0.0 if k is None else k.current, "A"),
            ("Power", "Conductor loss", 0.0 if k is None else k.loss, "W"),
            ("Power", "Tether as flown: mass per metre", 1000 * self.tether.linear_density, "g/m"),
            ("Power", "Tether as flown: diameter", 1000 * self.tether.diameter, "mm"),
            ("Power", "Tether as flown: breaking strength", self.tether.breaking_strength, "N"),
            ("Power", "Tether mass", self.tether_mass, "kg"),
            ("Endurance", "Purity decay time constant", min(self.permeation_tau, DAYS_CAP), "day"),
            ("Endurance", "Days to top-up (free-lift margin kept)", min(days, DAYS_CAP), "day"),
            ("Endurance", "Purity after the endurance", self.purity_after_endurance, "-"),
            (
                "Endurance",
                f"Helium top-up over {self.deployment_days:g} days",
                self.helium_top_up,
                "m3",
            ),
            ("Endurance", "Top-up gas cost", self.top_up_cost, "USD"),
            ("Ballonet", "Ballonet volume / hull volume", self.ballonet.fraction, "-"),
            ("Ballonet", "Same at the 500 m rule altitude", self.ballonet.rule_fraction, "-"),
            ("Ballonet", "Ballonet needed (500 m rule)", float(self.ballonet.needed), "yes=1"),
            ("Ballonet", "Ballonet volume", self.ballonet_volume, "m3"),
            ("Ballonet", "Ballonet fabric mass (in the mass breakdown)", self.ballonet_mass, "kg"),
            ("Envelope", "Required internal pressure (design wind)", e["pressure_required"], "Pa"),
            ("Envelope", "Hoop load", e["hoop"], "N/m"),
            ("Envelope", "Longitudinal load", e["longitudinal"], "N/m"),
            (
                "Envelope",
                "Required fabric strength (x safety factor)",
                e["strength_required"],
                "N/m",
            ),
            ("Envelope", "Fabric tensile strength", e["strength"], "N/m"),
            (
                "Envelope",
                "Envelope stress margin (strength/required - 1)",
                self.envelope_stress_margin,
                "-",
            ),
            ("Survival", "Largest tether tension at the survival wind", self.survival_tension, "N"),
            ("Survival", "Tether breaking strength", self.tether.breaking_strength, "N"),
            (
                "Survival",
                "Tether safety factor at the survival wind",
                self.survival_safety_factor,
                "-",
            ),
            (
                "Survival",
                "Envelope pressure margin at the survival wind",
                self.survival_pressure_margin,
                "-",
            ),
            ("Survival", "Can stay up at the survival wind", float(self.stay_up), "yes=1"),
            ("Winch", "Line pull (largest winch tension, survival included)", self.winch_pull, "N"),
            ("Winch", "Reel speed", self.winch.speed, "m/s"),
            ("Winch", "Motor power", self.winch.power, "W"),
            ("Winch", "Drum diameter (from the bend radius)", self.winch.drum_diameter, "m"),
            ("Winch", f"Drum length ({self.winch.layers} layers)", self.winch.drum_length, "m"),
            (
                "Winch",
                "Reel-in time from the operating altitude",
                self.winch.reel_time / 60.0,
                "min",
            ),
        ]
        return [{"group": g, "quantity": q, "value": float(v), "unit": u} for g, q, v, u in out]


def mission_report(req, cfg, af, state, sweep_ev, gas_price: float,
                   sweep_structure: dict | None = None) -> MissionReport:
    """Mission outputs of one sized design.

    Parameters
    ----------
    req, cfg : Requirement (resolved), Configuration
    af : Airframe
        0-d airframe of the design.
    state : ConstraintState
        The table at the design (its evaluation is at [design, survival] wind).
    sweep_ev : Evaluation
        The wind sweep (any speeds); the design wind of ``state`` is checked with it (its
        reel-in wind may be that speed).
    gas_price : float
        [USD/m3].
    sweep_structure : dict, optional
        :func:`aerostat_core.model.mission.structure_quantities` of ``sweep_ev`` if known.
    """
    k, own = tether_conductors(req, cfg)
    tether = effective_tether(req, cfg)
    b = ballonet_state(req, cfg)
    vol = scalar(af.hull.volume)
    endq = endurance_quantities(req, cfg, af)
    tau = scalar(endq["tau"])
    days = scalar(endq["days_to_top_up"])
    days = np.inf if days >= DAYS_CAP else days
    purity = (
        float(cfg.gas.purity * np.exp(-req.endurance_days / tau))
        if np.isfinite(tau)
        else float(cfg.gas.purity)
    )
    p_hull = scalar(af.pressure) + cfg.gas.superpressure
    top = scalar(
        helium_top_up(
            af.hull.surface_area,
            cfg.hull_fabric.helium_permeability,
            cfg.gas.purity,
            p_hull,
            req.deployment_days,
        )
    )
    ev2 = state.evaluation
    sq = structure_quantities(req, cfg, ev2)
    # the design-wind value of each (first element of its broadcast over designs and winds)
    env = {key: float(np.asarray(v, float).flat[0]) for key, v in sq.items()}
    val = np.asarray(state.value).reshape(-1)
    lim = np.asarray(state.limit).reshape(-1)
    i_s = NAMES.index("survival_envelope_pressure")
    i_sf = NAMES.index("survival_safety_factor")
    p_margin = float(lim[i_s] / val[i_s] - 1.0) if val[i_s] > 0 else np.inf
    sf_s, sf_req = float(val[i_sf]), float(lim[i_sf])
    met = np.asarray(state.met).reshape(-1)
    stay = bool(met[i_s] and met[i_sf])
    # the lowest speed of the sweep and the design wind (the table's first wind) at which the
    # tether or the envelope gives out
    sw = structure_quantities(req, cfg, sweep_ev) if sweep_structure is None else sweep_structure

    def with_design(sweep, at_winds):
        return np.concatenate([np.asarray(sweep).reshape(-1), np.asarray(at_winds).reshape(-1)[:1]])

    sf_sweep = with_design(np.asarray(sweep_ev.safety_factor, float), ev2.safety_factor)
    ok_p = with_design(sw["pressure_allowable"] >= sw["pressure_required"],
                       sq["pressure_allowable"] >= sq["pressure_required"])
    bad = (sf_sweep < req.survival_safety_factor) | ~ok_p
    speeds = with_design(np.asarray(sweep_ev.speed, float), np.asarray(ev2.speed, float))
    reel = float(speeds[bad].min()) if bad.any() else None
    pulls = [np.max(sweep_ev.tether.tension_winch), np.max(ev2.tether.tension_winch)]
    pull = float(max(pulls))
    m = cfg.mission
    w = size_winch(
        pull,
        m.winch_speed,
        m.winch_efficiency,
        af.tether_length,
        tether.diameter,
        m.bend_radius_ratio,
        m.drum_layers,
    )
    return MissionReport(
        battery_mass=onboard_battery_mass(req, cfg),
        conductors=k,
        conductors_own=own,
        tether=tether,
        tether_mass=tether.linear_density * af.tether_length,
        ballonet=b,
        ballonet_volume=b.fraction * vol,
        ballonet_mass=scalar(af.mass.items["ballonet"]),
        permeation_tau=tau,
        days_to_top_up=days,
        purity_after_endurance=purity,
        helium_top_up=top,
        top_up_cost=top * gas_price,
        deployment_days=float(req.deployment_days),
        envelope=env,
        envelope_stress_margin=env["strength"] / env["strength_required"] - 1.0,
        survival_pressure_margin=p_margin,
        survival_safety_factor=sf_s,
        survival_safety_factor_required=sf_req,
        stay_up=stay,
        reel_in_wind=reel,
        winch_pull=pull,
        winch=w,
        survival_tension=float(np.max(np.asarray(ev2.tether.tension).reshape(-1, 2)[:, 1])),
        decay=lift_decay(req, cfg, af, max(30.0, 2.0 * req.endurance_days)),
    )
