"""Runs from plain settings: the one place where the app's Dynamics page and the ``simulate`` CLI
turn a request (a JSON-able dict) into a system, a wind and a simulation.

A request holds: ``inputs`` (design inputs dict, or None for the thesis optimised design),
``scenario`` ({"steady", "varying", "gust", "turbulence"}), ``profile``, ``exponent``,
``roughness``, ``body`` ({"hull", "point"}), ``speed`` (mean wind at the aerostat [m/s]),
``duration`` [s], ``segments``, ``damping``, ``unsteady`` (unsteady-wind inertia), ``wall`` [s],
and per scenario ``changes`` [(t [s], speed [m/s], ramp [s])], ``gust`` {u, w, length, start,
shape, convected} or ``turbulence`` {intensity, w20, seed, max_frequency, fade_in, vertical,
spatial}. :func:`default_request` fills every key.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from .bodies import point_from_design
from .options import SolverOptions
from .results import Limits, SimulationResult
from .simulate import engine_guess, simulate
from .system import Atmosphere, DynamicSystem, system_from_design
from .tether import TetherModel
from .turbulence import DRYDEN_W20
from .wind import DrydenTurbulence, Gust, MeanProfile, SpeedSchedule, WindScenario

SCENARIOS = ("steady", "varying", "gust", "turbulence")
#: Turbulence intensities: "profile" = W20 from the run's mean profile; the others MIL-HDBK-1797.
INTENSITIES = ("profile", "light", "moderate", "severe", "custom")


def default_request(scenario: str = "gust", **changes: Any) -> dict:
    """A complete request with the page's defaults for ``scenario`` (``changes`` override keys)."""
    if scenario not in SCENARIOS:
        raise ValueError(f"scenario = {scenario!r}; valid options {SCENARIOS}")
    req = {
        "source": "thesis",
        "inputs": None,
        "scenario": scenario,
        "profile": "uniform",
        "exponent": 1.0 / 7.0,
        "roughness": 0.03,
        "body": "hull",
        "speed": 10.0,
        "duration": 150.0,
        "segments": 20,
        "damping": 1.0,
        "unsteady": True,
        "wall": 60.0,
        "modes": False,
    }
    if scenario == "varying":
        req["changes"] = [(20.0, 15.0, 5.0)]
    elif scenario == "gust":
        req["gust"] = {
            "u": 5.0,
            "w": 0.0,
            "length": 60.0,
            "start": 20.0,
            "shape": "full",
            "convected": True,
        }
    elif scenario == "turbulence":
        req["turbulence"] = {
            "intensity": "profile",
            "w20": None,
            "seed": 1,
            "max_frequency": 1.0,
            "fade_in": 20.0,
            "vertical": True,
            "spatial": True,
        }
    req.update(changes)
    return req


def design_of(req: Mapping[str, Any]):
    """The static-engine design of a request (the thesis optimised design when no inputs)."""
    from aerostat_core.model.design import design
    from aerostat_core.model.io import inputs_from_dict
    from aerostat_core.model.presets import thesis_optimized

    if req.get("inputs") is None:
        return design(*thesis_optimized())
    return design(*inputs_from_dict(req["inputs"]))


def wind_of(req: Mapping[str, Any], top_height: float) -> WindScenario:
    """The wind scenario of a request; ``top_height`` [m] is the profile's reference height (the
    static height of the confluence point, so ``speed`` is the wind at the aerostat)."""
    profile = MeanProfile(req["profile"], max(top_height, 1.0), req["exponent"], req["roughness"])
    u0 = req["speed"]
    gust = turb = None
    sched = (
        SpeedSchedule.ramps(u0, req["changes"])
        if req["scenario"] == "varying"
        else SpeedSchedule.constant(u0)
    )
    if req["scenario"] == "gust":
        g = req["gust"]
        gust = Gust(
            g["u"],
            g["w"],
            g["length"],
            g["start"],
            g.get("shape", "full"),
            g.get("convected", True),
        )
    if req["scenario"] == "turbulence":
        t = req["turbulence"]
        inten = t.get("intensity", "custom")
        w20 = (
            None if inten == "profile" else (DRYDEN_W20[inten] if inten in DRYDEN_W20 else t["w20"])
        )
        turb = DrydenTurbulence(
            w20=w20,
            seed=t["seed"],
            max_frequency=t["max_frequency"],
            fade_in=t["fade_in"],
            vertical=t["vertical"],
            spatial=t.get("spatial", True),
        )
    return WindScenario(sched, profile, gust, turb)


def event_time(req: Mapping[str, Any]) -> float | None:
    """Time of the scenario's event [s] (first ramp start or gust start), None otherwise."""
    if req["scenario"] == "varying":
        return float(req["changes"][0][0])
    if req["scenario"] == "gust":
        return float(req["gust"]["start"])
    return None


def system_of(req: Mapping[str, Any], d) -> DynamicSystem:
    """The dynamic system of a request: the design's hull (3 DOF) or a point aerostat with the
    design's mass, volume and drag area (:func:`.bodies.point_from_design`)."""
    if req["body"] == "hull":
        return system_from_design(
            d,
            segments=req["segments"],
            damping_ratio=req["damping"],
            unsteady_wind_inertia=req["unsteady"],
        )
    af = d.airframe
    teth = TetherModel.from_spec(
        d.configuration.tether, af.tether_length, req["segments"], req["damping"]
    )
    point = point_from_design(d, req["speed"], unsteady_wind_inertia=req["unsteady"])
    return DynamicSystem(
        point,
        teth,
        g=float(af.g),
        atmosphere=Atmosphere(float(np.asarray(af.air_density).reshape(-1)[0])),
    )


def run_request(
    req: Mapping[str, Any], progress: Callable[[float], None] | None = None, design=None
) -> tuple[SimulationResult, Any]:
    """Build and simulate a request; returns (result, design)."""
    d = design if design is not None else design_of(req)
    system = system_of(req, d)
    guess = engine_guess(system, d, req["speed"])
    top_height = float(system.nodes(guess)[0][-1, 1])
    wind = wind_of(req, top_height)
    opt = SolverOptions(
        wall_time_limit=req["wall"], output_interval=0.1 if req["duration"] <= 900 else 0.5
    )
    return simulate(system, wind, req["duration"], opt, guess=guess, progress=progress), d


def request_header(req: Mapping[str, Any], res: SimulationResult) -> dict:
    """Scenario and every parameter of a run, as plain text (the CSV header)."""
    h = {
        "scenario": req["scenario"],
        "design": "thesis optimised (presets.thesis_optimized)"
        if req.get("inputs") is None
        else "given inputs",
    }
    for k in (
        "speed",
        "duration",
        "profile",
        "exponent",
        "roughness",
        "body",
        "segments",
        "damping",
        "unsteady",
    ):
        h[k] = req[k]
    for k in ("changes", "gust", "turbulence"):
        if k in req:
            h[k] = req[k]
    rec = res.wind.turbulence
    if rec is not None:
        p = rec.params
        h["turbulence_model"] = rec.model
        h["turbulence_at_hull"] = (
            f"sigma_u {p.sigma_u:.3f} m/s, sigma_w {p.sigma_w:.3f} m/s, "
            f"L_u {p.length_u:.1f} m, L_w {p.length_w:.1f} m, "
            f"convected at {rec.speed:.2f} m/s"
        )
    h["tether_segments"] = res.system.tether.segments
    o = res.options
    h["solver"] = (
        f"{o.method}, rtol {o.rtol:g}, output_interval {o.output_interval:g} s, "
        f"wall_time_limit {o.wall_time_limit:g} s"
    )
    if req.get("inputs") is not None:
        h["design_inputs"] = json.dumps(req["inputs"], sort_keys=True, separators=(",", ":"))
    return h


def limits_of(d) -> Limits:
    """Operating limits of a design (:class:`.results.Limits`)."""
    return Limits.from_design(d)
