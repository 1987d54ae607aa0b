"""Runs from a typed request: the one place where the app's Dynamics page, the ``simulate`` CLI
and the thesis comparison turn a :class:`~aerostat_core.dynamics.request.DynamicsRequest` and a
design into a system, a wind and a simulation.

The request holds the run's settings (every field in the field registry, validated once when it
is built: :mod:`.request`); the design is given beside it (None: the thesis optimised design).
The functions here once took the untyped request dict; they still accept one for a release,
with a ``DeprecationWarning`` (docs/architecture.md §7), and :func:`default_request` still
returns one.
"""

from __future__ import annotations

import json
import warnings
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from .bodies import point_from_design
from .options import SolverOptions
from .request import INTENSITIES, SCENARIOS, DynamicsRequest
from .results import Limits, SimulationResult
from .simulate import engine_guess, simulate
from .system import Atmosphere, DynamicSystem, system_from_design
from .tether import TetherModel
from .wind import MeanProfile, SpeedSchedule, WindScenario

__all__ = ["INTENSITIES", "SCENARIOS", "DynamicsRequest", "default_request", "design_of",
           "event_time", "limits_of", "request_header", "run_request", "system_of", "wind_of"]


def _typed(dyn: DynamicsRequest | Mapping[str, Any], caller: str) -> DynamicsRequest:
    """``dyn`` itself, or the typed request of an untyped dict (deprecated: one release)."""
    if isinstance(dyn, DynamicsRequest):
        return dyn
    if isinstance(dyn, Mapping):
        warnings.warn(f"{caller}() of a request dict is deprecated; pass a DynamicsRequest "
                      "(DynamicsRequest.from_dict converts one)", DeprecationWarning,
                      stacklevel=3)
        return DynamicsRequest.from_dict(dyn)
    raise TypeError(f"{caller}() takes a DynamicsRequest, not {type(dyn).__name__}")


def default_request(scenario: str = "gust", **changes: Any) -> dict:
    """Deprecated: the untyped request dict of ``scenario`` with ``changes``; build
    ``DynamicsRequest.for_scenario(scenario, ...)`` instead (kept one release)."""
    warnings.warn("default_request() is deprecated; use DynamicsRequest.for_scenario()",
                  DeprecationWarning, stacklevel=2)
    data = {"source": "thesis", "inputs": None, **DynamicsRequest.for_scenario(scenario).to_dict()}
    data.update(changes)
    return data


def design_of(inputs: Mapping[str, Any] | None = None):
    """The static-engine design of design ``inputs`` (a design file's dict; None: the thesis
    optimised design). An untyped request dict (deprecated) gives the design of its
    ``inputs``."""
    from aerostat_core.model.design import design
    from aerostat_core.model.io import inputs_from_dict
    from aerostat_core.model.presets import thesis_optimized

    if inputs is not None and "scenario" in inputs:  # an untyped request (deprecated)
        warnings.warn("design_of() of a request dict is deprecated; pass the design inputs",
                      DeprecationWarning, stacklevel=2)
        inputs = inputs.get("inputs")
    if inputs is None:
        return design(*thesis_optimized())
    return design(*inputs_from_dict(inputs))


def wind_of(dyn: DynamicsRequest, top_height: float) -> WindScenario:
    """The wind scenario of a request; ``top_height`` [m] is the profile's reference height (the
    static height of the confluence point, so ``speed`` is the wind at the aerostat)."""
    dyn = _typed(dyn, "wind_of")
    profile = MeanProfile(dyn.profile, max(top_height, 1.0), dyn.exponent, dyn.roughness)
    sched = (
        SpeedSchedule.ramps(dyn.speed, [c.as_tuple() for c in dyn.changes])
        if dyn.scenario == "varying"
        else SpeedSchedule.constant(dyn.speed)
    )
    gust = dyn.gust.gust() if dyn.scenario == "gust" else None
    turb = dyn.turbulence.turbulence() if dyn.scenario == "turbulence" else None
    return WindScenario(sched, profile, gust, turb)


def event_time(dyn: DynamicsRequest) -> float | None:
    """Time of the scenario's event [s] (first ramp start or gust start), None otherwise."""
    return _typed(dyn, "event_time").event_time


def system_of(dyn: DynamicsRequest, d) -> DynamicSystem:
    """The dynamic system of a request: the design's hull (3 DOF) or a point aerostat with the
    design's mass, volume and drag area (:func:`.bodies.point_from_design`)."""
    dyn = _typed(dyn, "system_of")
    if dyn.body == "hull":
        return system_from_design(
            d,
            segments=dyn.segments,
            damping_ratio=dyn.damping,
            unsteady_wind_inertia=dyn.unsteady,
        )
    af = d.airframe
    teth = TetherModel.from_spec(d.configuration.tether, af.tether_length, dyn.segments,
                                 dyn.damping)
    point = point_from_design(d, dyn.speed, unsteady_wind_inertia=dyn.unsteady)
    return DynamicSystem(
        point,
        teth,
        g=float(af.g),
        atmosphere=Atmosphere(float(np.asarray(af.air_density).reshape(-1)[0])),
    )


def run_request(
    dyn: DynamicsRequest, progress: Callable[[float], None] | None = None, design=None
) -> tuple[SimulationResult, Any]:
    """Build and simulate a request on ``design`` (None: the thesis optimised design); returns
    (result, design). An untyped request dict (deprecated) runs on the design of its
    ``inputs``."""
    if isinstance(dyn, Mapping) and design is None:
        design = design_of(dyn.get("inputs"))
    dyn = _typed(dyn, "run_request")
    d = design if design is not None else design_of(None)
    system = system_of(dyn, d)
    guess = engine_guess(system, d, dyn.speed)
    top_height = float(system.nodes(guess)[0][-1, 1])
    wind = wind_of(dyn, top_height)
    opt = SolverOptions(
        wall_time_limit=dyn.wall, output_interval=0.1 if dyn.duration <= 900 else 0.5
    )
    return simulate(system, wind, dyn.duration, opt, guess=guess, progress=progress), d


def request_header(dyn: DynamicsRequest, res: SimulationResult,
                   inputs: Mapping[str, Any] | None = None) -> dict:
    """Scenario and every parameter of a run, as plain text (the CSV header); ``inputs``: the
    design inputs dict the run used (None: the thesis optimised design)."""
    if isinstance(dyn, Mapping) and inputs is None:
        inputs = dyn.get("inputs")
    plain = _typed(dyn, "request_header").to_dict()
    h = {
        "scenario": plain["scenario"],
        "design": "thesis optimised (presets.thesis_optimized)"
        if inputs is None
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
        h[k] = plain[k]
    for k in ("changes", "gust", "turbulence"):
        if k in plain:
            h[k] = plain[k]
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
    if inputs is not None:
        h["design_inputs"] = json.dumps(inputs, sort_keys=True, separators=(",", ":"))
    return h


def limits_of(d) -> Limits:
    """Operating limits of a design (:class:`.results.Limits`)."""
    return Limits.from_design(d)
