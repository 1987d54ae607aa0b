"""The Dynamics page's 6-DOF section: the request form from the field registry, the cached run,
the 3-D view of the motion, the lateral time plots, the lateral mode table and the exports.

The form is built from the registry of :class:`aerostat_core.dynamics.scenarios6.Request6`
(label, unit, range of every field), like the Design form; the request is validated once, by
the dataclass, and a rejected value comes back as one message with the label, the value and
the valid range. No physics here.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import plotly.graph_objects as go
from plotly.subplots import make_subplots

from aerostat_core.base.fields import specs
from aerostat_core.base.validation import InputError
from aerostat_core.dynamics.lateral import lateral_sweep
from aerostat_core.dynamics.scenarios6 import SCENARIOS6, Request6, metrics6, run6
from aerostat_core.dynamics.sixdof_results import SIGNALS6
from aerostat_core.model.io import inputs_from_dict

from . import cache
from .theme import ACCENT, FONT, MARGIN, SECOND, THIRD

#: What each 6-DOF scenario does, for the radio's labels.
SCENARIO_LABELS = {
    "crosswind-gust": "Crosswind gust",
    "veer": "Wind veering with height",
    "direction-step": "Wind direction step",
    "turbulence-3d": "3-D turbulence (u, v, w)",
    "reel-in": "Reel in",
    "reel-out": "Reel out",
    "tether-break": "Tether break",
}
#: Fields of the form per scenario (besides speed, duration, segments, azimuth).
SCENARIO_FIELDS = {
    "crosswind-gust": ("crosswind_gust", "gust_length", "event_time"),
    "veer": ("veer_deg_per_100m",),
    "direction-step": ("direction_step_deg", "direction_step_time", "event_time"),
    "turbulence-3d": ("intensity", "seed"),
    "reel-in": ("reel_speed", "reel_duration", "event_time"),
    "reel-out": ("reel_speed", "reel_duration", "event_time"),
    "tether-break": ("event_time",),
}
COMMON_FIELDS = ("speed", "duration", "segments", "azimuth_deg")


def form_fields(scenario: str) -> list[dict]:
    """Widgets of the form for ``scenario`` from the registry: name, label (with unit), kind,
    min, max, default, options (choices), help."""
    sp = specs(Request6)
    default = Request6.for_scenario(scenario)
    out = []
    for name in COMMON_FIELDS + SCENARIO_FIELDS[scenario]:
        s = sp[name]
        unit = f" [{s.unit}]" if s.unit else ""
        out.append({"name": name, "label": f"{s.label}{unit}", "kind": s.kind,
                    "min": s.lo, "max": s.hi, "default": getattr(default, name),
                    "options": tuple(getattr(s, "choices", None) or ()),
                    "help": getattr(s, "help", None) or None})
    return out


def build_request6(scenario: str, values: Mapping[str, Any]) -> tuple[Request6 | None, str]:
    """The validated request, or (None, message) naming the field's label, the value and the
    valid range."""
    try:
        return Request6.for_scenario(scenario, **dict(values)), ""
    except InputError as exc:
        rng = (f" (valid range {exc.lo:g} to {exc.hi:g} {exc.unit})".replace(" )", ")")
               if exc.lo is not None and exc.hi is not None else "")
        return None, f"{exc.label}: {exc.value!r} is not accepted{rng}."


def _design(inputs: Mapping[str, Any] | None):
    from aerostat_core.dynamics.cases import thesis_design
    from aerostat_core.model.design import design

    return thesis_design() if inputs is None else design(*inputs_from_dict(dict(inputs)))


def run_request6(dyn: Request6, inputs: Mapping[str, Any] | None = None,
                 progress: Callable[[float], None] | None = None) -> dict:
    """Run (or fetch from the store) a request on the design of ``inputs`` (None: the thesis
    design); returns plain data (:func:`collect6`)."""
    import json

    key = (dyn, json.dumps(inputs, sort_keys=True, default=str) if inputs else None)

    def go_run():
        d = _design(inputs)
        res, d = run6(dyn, d, progress)
        analyses, above = lateral_sweep(d)
        return collect6(res, dyn, d, analyses, above)

    return cache.memo("dynamics6", key, go_run, 8)


def collect6(res, dyn: Request6, design, analyses, above) -> dict:
    """Plain data of a 6-DOF run for the page."""
    m = metrics6(res, dyn, design, lateral=False)
    near = min(analyses, key=lambda a: abs(a.speed - dyn.speed))
    m["lateral_unstable_above_m_s"] = above
    n_nodes = res.system.tether.segments + 1
    step = max(1, len(res.t) // 200)
    frames = list(range(0, len(res.t), step))
    nodes = [res.node_positions(i).tolist() for i in frames]
    b = res.system.hull_index
    attitude = [res.y[i, b + 3:b + 7].tolist() for i in frames]
    origin = [res.y[i, b:b + 3].tolist() for i in frames]
    h = res.system.hull6.hull
    return {
        "t": res.t.tolist(),
        "signals": {n: res.signal(n).tolist() for n in SIGNALS6},
        "units": {n: u for n, (_l, u) in SIGNALS6.items()},
        "labels": {n: lab for n, (lab, _u) in SIGNALS6.items()},
        "frames": [res.t[i] for i in frames], "nodes": nodes, "attitude": attitude,
        "origin": origin, "n_nodes": n_nodes, "hull_length": h.length,
        "hull_diameter": h.diameter,
        "metrics": m, "status": res.message, "ok": res.ok,
        "modes": [m_.row() for m_ in near.modes[:8]], "modes_speed": near.speed,
        "sweep": [{"speed_m_s": a.speed, "max_real_1_s": a.max_real} for a in analyses],
        "csv": res.to_csv(header=dyn.header()), "json": res.to_json(header=dyn.header()),
        "wall_time": res.stats["wall_time"],
    }


def _rot(q) -> np.ndarray:
    q0, q1, q2, q3 = np.asarray(q, float) / np.linalg.norm(q)
    r = np.array([[1 - 2 * (q2 * q2 + q3 * q3), 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
                  [2 * (q1 * q2 + q0 * q3), 1 - 2 * (q1 * q1 + q3 * q3), 2 * (q2 * q3 - q0 * q1)],
                  [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), 1 - 2 * (q1 * q1 + q2 * q2)]])
    return np.diag([-1.0, 1.0, -1.0]) @ r


def view3d_figure(out: Mapping[str, Any], k: int) -> go.Figure:
    """3-D view at frame ``k``: the tether, the hull (an ellipsoid outline along its body axes)
    and the hull's track so far."""
    nodes = np.array(out["nodes"][k])
    rot = _rot(out["attitude"][k])
    o = np.array(out["origin"][k])
    a, r = 0.5 * out["hull_length"], 0.5 * out["hull_diameter"]
    ph = np.linspace(0, 2 * np.pi, 25)
    fig = go.Figure()
    fig.add_trace(go.Scatter3d(x=nodes[:, 0], y=nodes[:, 1], z=nodes[:, 2], mode="lines+markers",
                               marker={"size": 2, "color": SECOND},
                               line={"color": SECOND, "width": 3}, name="tether"))
    for xs in np.linspace(-0.9 * a, 0.9 * a, 7):
        rad = r * math.sqrt(max(1 - (xs / a) ** 2, 0.0))
        pts = np.array([[xs, rad * math.cos(p), rad * math.sin(p)] for p in ph]) @ rot.T + o
        fig.add_trace(go.Scatter3d(x=pts[:, 0], y=pts[:, 1], z=pts[:, 2], mode="lines",
                                   line={"color": ACCENT, "width": 3}, showlegend=False))
    for p in (0.0, 0.5 * np.pi, np.pi, 1.5 * np.pi):
        xs = np.linspace(-a, a, 25)
        rad = r * np.sqrt(np.clip(1 - (xs / a) ** 2, 0, 1))
        pts = np.column_stack([xs, rad * math.cos(p), rad * math.sin(p)]) @ rot.T + o
        fig.add_trace(go.Scatter3d(x=pts[:, 0], y=pts[:, 1], z=pts[:, 2], mode="lines",
                                   line={"color": ACCENT, "width": 3}, showlegend=False))
    track = np.array(out["origin"][: k + 1])
    fig.add_trace(go.Scatter3d(x=track[:, 0], y=track[:, 1], z=track[:, 2], mode="lines",
                               line={"color": THIRD, "width": 2, "dash": "dot"},
                               name="hull track"))
    fig.update_layout(
        title=f"t = {out['frames'][k]:.1f} s", font=FONT, margin=MARGIN, height=520,
        scene={"aspectmode": "data", "xaxis_title": "x [m]", "yaxis_title": "y [m]",
               "zaxis_title": "z [m]"})
    return fig


def lateral_figure(out: Mapping[str, Any]) -> go.Figure:
    """Roll, yaw, sideslip and lateral displacement versus time."""
    names = ("roll", "yaw", "beta", "y_C")
    fig = make_subplots(rows=4, cols=1, shared_xaxes=True, vertical_spacing=0.04,
                        subplot_titles=[f"{out['labels'][n]} [{out['units'][n]}]" for n in names])
    for i, n in enumerate(names):
        fig.add_trace(go.Scatter(x=out["t"], y=out["signals"][n], mode="lines",
                                 line={"color": ACCENT}, showlegend=False), row=i + 1, col=1)
    fig.update_xaxes(title_text="t [s]", row=4, col=1)
    fig.update_layout(font=FONT, margin=MARGIN, height=720)
    return fig


__all__ = ["SCENARIOS6", "SCENARIO_LABELS", "build_request6", "form_fields", "lateral_figure",
           "run_request6", "view3d_figure"]
