"""6-DOF runs from a typed request: the one place where the ``simulate --dof 6`` CLI and the
Dynamics page turn settings into a system, a 3-D wind, events and a run (docs/dynamics.md §7.4).

:class:`Request6` is a frozen dataclass whose every field is in the field registry (label, unit,
range), validated once when it is built; :func:`run6` runs it and :func:`metrics6` gives the
CLI's figures (the 3-DOF run's keys plus the lateral ones).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from aerostat_core.base.fields import choice, integer, number
from aerostat_core.dynamics.options import SolverOptions
from aerostat_core.dynamics.request import RunRequest
from aerostat_core.dynamics.results import motion_figures, response_metrics
from aerostat_core.dynamics.sixdof import Events6, Wind3D, simulate6, system6_from_design
from aerostat_core.dynamics.turbulence import DRYDEN_W20
from aerostat_core.dynamics.wind import DrydenTurbulence, SpeedSchedule, WindScenario

SCENARIOS6 = ("crosswind-gust", "veer", "direction-step", "turbulence-3d", "reel-in", "reel-out",
              "tether-break")
INTENSITIES6 = ("light", "moderate", "severe")


@dataclass(frozen=True)
class Request6(RunRequest):
    """Settings of one 6-DOF run (every field in the registry, validated once when it is built,
    like the 3-DOF :class:`~aerostat_core.dynamics.request.DynamicsRequest`; defaults per
    scenario from :meth:`for_scenario`)."""

    scenario: str = choice("crosswind-gust", "6-DOF scenario", SCENARIOS6)
    speed: float = number(10.0, "Mean wind at the aerostat", "m/s", 0.5, 40.0)
    duration: float = number(120.0, "Simulated time", "s", 1.0, 3600.0)
    segments: int = integer(20, "Tether segments", 4, 60)
    azimuth_deg: float = number(0.0, "Wind azimuth", "deg", -360.0, 360.0)
    crosswind_gust: float = number(5.0, "Crosswind gust amplitude", "m/s", -30.0, 30.0)
    gust_length: float = number(60.0, "Crosswind gust length d_m", "m", 1.0, 5000.0)
    event_time: float = number(20.0, "Event time (gust, step, reel start, break)", "s", 0.0,
                               3600.0)
    veer_deg_per_100m: float = number(20.0, "Wind veer with height", "deg/100 m", -90.0, 90.0)
    direction_step_deg: float = number(30.0, "Wind direction step", "deg", -180.0, 180.0)
    direction_step_time: float = number(5.0, "Direction step duration", "s", 0.1, 600.0)
    intensity: str = choice("moderate", "Turbulence intensity (MIL-HDBK-1797)", INTENSITIES6)
    seed: int = integer(1, "Random seed", 0, 2**32 - 1)
    reel_speed: float = number(0.3048, "Winch reel speed", "m/s", 0.01, 5.0,
                               source="thesis §2.2.4 (60 ft/min)")
    reel_duration: float = number(30.0, "Reel duration", "s", 0.0, 3600.0)

    @classmethod
    def for_scenario(cls, scenario: str, **changes: Any) -> Request6:
        """The defaults of ``scenario`` (a direction step only in "direction-step", a veer only
        in "veer", ...) with ``changes``."""
        base = cls(scenario=scenario)
        if scenario == "turbulence-3d":
            base = replace(base, duration=300.0)
        if scenario == "tether-break":
            base = replace(base, duration=60.0)
        return replace(base, **changes)

    def wind3(self, top_height: float) -> Wind3D:
        """The 3-D wind of this request (``top_height``: the reference height of the profile)."""
        sched = SpeedSchedule.constant(self.speed)
        turb = None
        if self.scenario == "turbulence-3d":
            turb = DrydenTurbulence(w20=DRYDEN_W20[self.intensity], seed=self.seed)
        base = WindScenario(sched, turbulence=turb)
        kw: dict[str, Any] = {"azimuth_deg": self.azimuth_deg}
        if self.scenario == "crosswind-gust":
            kw.update(crosswind_gust=self.crosswind_gust, crosswind_gust_length=self.gust_length,
                      crosswind_gust_start=self.event_time)
        elif self.scenario == "veer":
            kw.update(veer_deg_per_100m=self.veer_deg_per_100m, veer_height=top_height)
        elif self.scenario == "direction-step":
            kw.update(direction_step_deg=self.direction_step_deg,
                      direction_step_start=self.event_time,
                      direction_step_time=self.direction_step_time)
        return Wind3D(base, **kw)

    def events(self) -> Events6:
        if self.scenario in ("reel-in", "reel-out"):
            sign = -1.0 if self.scenario == "reel-in" else 1.0
            return Events6(reel_speed=sign * self.reel_speed, reel_start=self.event_time,
                           reel_duration=self.reel_duration)
        if self.scenario == "tether-break":
            return Events6(break_time=self.event_time)
        return Events6()

    def header(self) -> dict:
        """``key = value`` lines for the CSV header (every setting, with units)."""
        return self.labelled()


def run6(dyn: Request6, design=None, progress=None):
    """Run a request on ``design`` (default: the thesis optimised design); returns
    (Result6, design)."""
    if design is None:
        from aerostat_core.dynamics.cases import thesis_design

        design = thesis_design()
    system = system6_from_design(design, segments=dyn.segments, events=dyn.events())
    wind3 = dyn.wind3(float(design.airframe.tether_length))
    if dyn.scenario == "veer":
        # the profile turns about the aerostat's height: chi = chi_0 there
        wind3 = replace(wind3, veer_height=_top_height(design, dyn.speed))
    opts = SolverOptions(output_interval=0.1 if dyn.duration <= 600 else 0.5,
                         wall_time_limit=120.0)
    res = simulate6(system, wind3, dyn.duration, opts, design=design, progress=progress)
    return res, design


def _top_height(design, speed: float) -> float:
    rows = design.performance.rows()
    row = min(rows, key=lambda r: abs(r["wind_speed_m_s"] - speed))
    return float(row["flying_height_m"])


def metrics6(res, dyn: Request6, design, lateral: bool = True) -> dict:
    """The CLI's figures: the 3-DOF run's keys (status, window, settling time, pitch range and
    peak, hull velocity peaks, RMS, tension range) plus roll_peak_deg, yaw_peak_deg,
    lateral_peak_m, lateral_unstable_above_m_s (None when stable to the survival wind), the
    static lateral derivatives and, for reel and break runs, the tension peak and the ascent."""
    t = res.t
    t0 = min(dyn.event_time if dyn.scenario != "turbulence-3d" else 20.0, float(t[-1]))
    sel = t >= t0
    out: dict[str, Any] = {"status": res.message, "ok": bool(res.ok), "window_start_s": t0,
                           "window_end_s": float(t[-1])}
    settle = None
    if dyn.scenario not in ("turbulence-3d", "tether-break") and t[-1] > dyn.event_time + 5.0:
        settle = response_metrics(t, res.signal("x_C"), dyn.event_time, 0.05).settling_time
    out["settling_time_s"] = settle
    out.update(motion_figures(*(res.signal(k)[sel] for k in ("pitch", "vx", "vz", "tension_top"))))
    out.update(res.peaks(t0))
    out["tension_winch_peak_N"] = float(np.max(res.signal("tension_winch")))
    out["tether_length_range_m"] = [float(np.min(res.signal("tether_length"))),
                                    float(np.max(res.signal("tether_length")))]
    if dyn.scenario == "tether-break":
        z = res.signal("z_C")
        out["ascent_m"] = float(z[-1] - z[0])
        out["drift_m"] = float(math.hypot(res.signal("x_C")[-1] - res.signal("x_C")[0],
                                          res.signal("y_C")[-1] - res.signal("y_C")[0]))
    if lateral:
        from aerostat_core.dynamics.lateral import (
            lateral_sweep,
            static_lateral_derivatives,
        )

        analyses, above = lateral_sweep(design)
        out["lateral_unstable_above_m_s"] = above
        out["lateral_speeds_m_s"] = [a.speed for a in analyses]  # speeds with an equilibrium
        near = min(analyses, key=lambda a: abs(a.speed - dyn.speed))
        out["lateral_modes"] = [m.row() for m in near.modes[:6]]
        out["lateral_modes_speed_m_s"] = near.speed
        s8 = system6_from_design(design, segments=8)
        out["static_derivatives"] = {
            "C_m_alpha_cv_per_rad": _cm_alpha_cv(design, dyn.speed),
            **static_lateral_derivatives(s8, dyn.speed, design, state=near.state
                                         if near.speed == dyn.speed else None)}
    return out


def _cm_alpha_cv(design, speed: float) -> float:
    rows = design.performance.rows()
    row = min(rows, key=lambda r: abs(r["wind_speed_m_s"] - speed))
    return float(row["cm_alpha_aero_cv_per_rad"])
