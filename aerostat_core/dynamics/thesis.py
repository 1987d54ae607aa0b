"""The thesis comparison: its optimised design under its three wind scenarios, computed live.

Thesis claims (Mahmood 2020, abstract / §4.6; docs/dynamics.md §3.2): after a varying wind or a gust the
optimised aerostat is steady within 40 s with +-3 deg of pitch; in high-intensity turbulence it
moves +-1.2 m/s horizontally, +-0.2 m/s vertically, with +-3.5 deg of pitch. The thesis text
available here stops in Ch. 2, so its wind settings are not known; the settings below are
physical ones, stated, and never tuned to the claims:

* design: the thesis optimised design of :func:`aerostat_core.model.presets.thesis_optimized` (the one
  the Optimise page finds), 20 tether segments, unsteady-wind inertia on (physical: it acts on
  the uniform ramp only);
* varying wind: 10 -> 15 m/s (the design wind) at the aerostat, 5 s linear ramp at t = 20 s;
* gust: 10 m/s + a frozen, convected 1 - cos gust of 5 m/s over d_m = 60 m (6 s rise) at 20 s;
* high-intensity turbulence: the design wind (15 m/s at the aerostat) over open terrain (power law
  1/7), MIL-HDBK-1797 low-altitude Dryden u' and w' with W20 from that profile (the intensity
  consistent with the mean wind), spatially varying (:mod:`.turbulence`), seed 1, 20 s fade-in.

Metrics ("peak deviation from the mean over a stated window"): settling_time_s = time after the
event until x_C stays within 5 % of its change (or of its largest excursion, for a gust);
pitch_peak_deg = max |theta - mean(theta)| and u_peak_mps / w_peak_mps = max |v - mean(v)| of the
hull's horizontal / vertical velocity over the window (event to end, or fade-in + 40 s to end in
turbulence). Each is compared with the claim; within a factor of 1.5 is a match.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Any

from .request import DynamicsRequest, TurbulenceSettings
from .results import SimulationResult, motion_figures, response_metrics
from .scenarios import run_request

#: The thesis' claims per scenario: metric -> value.
THESIS_CLAIMS = {
    "varying": {"settling_time_s": 40.0, "pitch_peak_deg": 3.0},
    "gust": {"settling_time_s": 40.0, "pitch_peak_deg": 3.0},
    "turbulence": {"u_peak_mps": 1.2, "w_peak_mps": 0.2, "pitch_peak_deg": 3.5},
}
#: A figure matches when ours / thesis is within [1/1.5, 1.5].
MATCH_FACTOR = 1.5
#: Turbulence statistics start this long after the fade-in [s].
TURBULENCE_SETTLE = 40.0
METRIC_LABELS = {
    "settling_time_s": ("settling time of x_C (5 % band)", "s"),
    "pitch_peak_deg": ("peak pitch deviation from the mean", "deg"),
    "u_peak_mps": ("peak horizontal hull velocity deviation from the mean", "m/s"),
    "w_peak_mps": ("peak vertical hull velocity deviation from the mean", "m/s"),
}
#: Why a figure may not match with physical settings (shown next to the table).
WHY_NOT = (
    "The thesis does not state (in the text available) its ramp, gust and turbulence settings, "
    "its mean wind, nor whether its ± values are peaks or RMS. Peaks of a random response are "
    "typically 3-4 x its RMS: the RMS columns show which reading the thesis' turbulence numbers "
    "fit. Our hull also sees the turbulence vary over its length and along the tether, which a "
    "single-point (Simulink Dryden) model does not."
)


def thesis_request(scenario: str, seed: int = 1, duration: float | None = None,
                   ) -> DynamicsRequest:
    """The request of one thesis scenario (module docstring); ``duration`` [s] overrides.

    Raises :class:`~aerostat_core.base.validation.InputError` naming the field (the seed or the
    duration out of its range) and ``ValueError`` for an unknown scenario.

    >>> thesis_request("turbulence", seed=7).turbulence.seed
    7
    """
    if scenario == "varying":
        dyn = DynamicsRequest.for_scenario("varying", duration=150.0, wall=120.0)
    elif scenario == "gust":
        dyn = DynamicsRequest.for_scenario("gust", duration=150.0, wall=120.0)
    elif scenario == "turbulence":
        dyn = DynamicsRequest.for_scenario(
            "turbulence", speed=15.0, profile="power", duration=600.0, wall=120.0,
            turbulence=TurbulenceSettings(intensity="profile", seed=seed))
    elif scenario == "steady":
        dyn = DynamicsRequest.for_scenario("steady", duration=60.0, wall=120.0)
    else:
        raise ValueError(
            f"scenario = {scenario!r}; valid options ('steady', 'varying', 'gust', 'turbulence')"
        )
    if duration is not None:
        dyn = replace(dyn, duration=duration)
    return dyn


def window_start(dyn: DynamicsRequest) -> float:
    """Start of the metrics window [s]: the event, or the fade-in + 40 s in turbulence."""
    te = dyn.event_time
    if te is not None:
        return te
    if dyn.scenario == "turbulence":
        return float(dyn.turbulence.fade_in) + TURBULENCE_SETTLE
    return 0.0


def metrics(res: SimulationResult, dyn: DynamicsRequest) -> dict:
    """The CLI's and the comparison's figures of one run (module docstring), plain numbers."""
    t0 = min(window_start(dyn), float(res.t[-1]))
    sel = res.t >= t0
    out: dict[str, Any] = {
        "status": res.message,
        "ok": bool(res.ok),
        "window_start_s": t0,
        "window_end_s": float(res.t[-1]),
    }
    te = dyn.event_time
    settle = None
    if te is not None and res.t[-1] > te + 5.0:
        settle = response_metrics(res.t, res.signal("x_C"), te, 0.05).settling_time
    out["settling_time_s"] = settle
    th = res.signal("theta")[sel]
    vx = res.signal("vx")[sel]
    vz = res.signal("vz")[sel]
    ten = res.signal("tension_C")[sel]
    out.update(motion_figures(th, vx, vz, ten))
    out["slack_events"] = res.slack_events()
    return out


def run_thesis_case(scenario: str, seed: int = 1, design=None, duration: float | None = None):
    """Simulate one thesis scenario; returns (result, metrics, request, design)."""
    dyn = thesis_request(scenario, seed, duration)
    res, d = run_request(dyn, design=design)
    return res, metrics(res, dyn), dyn, d


def comparison_rows(runs: Mapping[str, Mapping[str, Any]]) -> list[dict]:
    """Rows of the comparison table from ``{scenario: metrics}``: scenario, metric, unit, thesis,
    ours, ratio, match (within ``MATCH_FACTOR``), claim_holds (the settling time is a bound:
    "steady within 40 s"), our RMS where the metric has one, and the window."""
    rows = []
    for sc, claims in THESIS_CLAIMS.items():
        if sc not in runs:
            continue
        m = runs[sc]
        for key, claim in claims.items():
            ours = m.get(key)
            ratio = None if ours is None else ours / claim
            rms_key = {
                "pitch_peak_deg": "pitch_rms_deg",
                "u_peak_mps": "u_rms_mps",
                "w_peak_mps": "w_rms_mps",
            }.get(key)
            rms = m.get(rms_key) if rms_key and sc == "turbulence" else None
            label, unit = METRIC_LABELS[key]
            rows.append(
                {
                    "scenario": sc,
                    "metric": label,
                    "unit": unit,
                    "thesis": claim,
                    "ours": ours,
                    "ratio": ratio,
                    "our_rms": rms,
                    "match": bool(ratio is not None and 1 / MATCH_FACTOR <= ratio <= MATCH_FACTOR),
                    # "settles within 40 s" is an upper bound: a shorter settling time satisfies it
                    "claim_holds": bool(
                        ours is not None
                        and (
                            ours <= claim * MATCH_FACTOR
                            if key == "settling_time_s"
                            else 1 / MATCH_FACTOR <= ratio <= MATCH_FACTOR
                        )
                    ),
                    "window": f"{m['window_start_s']:.0f}-{m['window_end_s']:.0f} s",
                }
            )
    return rows


def thesis_settings_text(seed: int = 1, duration: float | None = None) -> dict:
    """One line per scenario describing its settings (page, README, CLI): the turbulence
    ``seed`` and, when given, the simulated ``duration`` [s] actually used (the CLI's ``--seed``
    and ``--duration``); the defaults are the thesis comparison's.

    >>> thesis_settings_text(seed=7)["turbulence"].count("seed 7")
    1
    """

    def span(default: float) -> str:
        return f"{default if duration is None else duration:g} s"

    end = 600.0 if duration is None else float(duration)  # the turbulence run's end [s]

    return {
        "varying": "10 -> 15 m/s at the aerostat, 5 s linear ramp at t = 20 s, uniform in space "
        f"(Froude-Krylov and added mass of the accelerating air on), {span(150.0)}",
        "gust": "10 m/s + frozen convected 1 - cos gust, 5 m/s, d_m = 60 m (6 s rise) at "
        f"t = 20 s, {span(150.0)}",
        "turbulence": "15 m/s at the aerostat (the design wind), power law 1/7, MIL-HDBK-1797 "
        "Dryden u' + w' with W20 from the profile, spatially varying with IEC "
        f"61400-1 coherence, seed {int(seed)}, 20 s fade-in, {span(600.0)} (window "
        f"{min(TURBULENCE_SETTLE + 20.0, end):g}-{span(600.0)})",
    }
