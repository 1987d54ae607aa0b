"""UI layer of the Dynamics page: the form's request, the result store, figures and tables.

Physics lives in :mod:`aerostat_core.dynamics` (:mod:`~aerostat_core.dynamics.scenarios` turns a
request into a run, :mod:`~aerostat_core.dynamics.thesis` holds the thesis comparison); this
module lists the form's widgets (:data:`LAYOUT`: widget key -> field of the typed
:class:`~aerostat_core.dynamics.request.DynamicsRequest`, whose registry gives label, unit, help,
choices and default, as the Design form's), builds the request from their values (validated
once, by the request), runs it through :func:`run_cached` and draws the plain result.

Caching: results live in the app's one process-wide store (:func:`app_ui.cache.memo`), keyed
by a :class:`DynamicsKey` (read by field name: the design inputs as the frozen Requirement and
Configuration, and the frozen request itself), which the session keeps; no JSON on the way.
The store is filled by :func:`run_cached`, never inside an ``st.cache_data`` function, so the
page's progress bar is drawn by the page itself and a replay (a second click, coming back to the
page, a second session hitting the same case) never re-runs a UI element (no
``CacheReplayClosureError``). A failed or interrupted run stores nothing.

Figures mirror the thesis (Figs 4.36-4.41): tether profile at t = 0 and t_end, x_C(t) and z_C(t),
hull velocities, pitch and angle of attack, tensions at C and at the winch, wind input; limits
(fin stall, safe working load, lowest height) are drawn on them.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np
import plotly.graph_objects as go
import streamlit as st

from aerostat_core import Configuration, Requirement
from aerostat_core.base.fields import FieldSpec
from aerostat_core.base.validation import InputError
from aerostat_core.dynamics.linearize import linearize
from aerostat_core.dynamics.request import (
    DynamicsRequest,
    GustSettings,
    SpeedChange,
    TurbulenceSettings,
    error_text,
)
from aerostat_core.dynamics.results import SIGNALS, limit_flags, response_metrics
from aerostat_core.dynamics.scenarios import limits_of, request_header, run_request
from aerostat_core.dynamics.simulate import kernels_warm, warm_kernels
from aerostat_core.dynamics.thesis import (
    MATCH_FACTOR,
    THESIS_CLAIMS,
    WHY_NOT,
    comparison_rows,
    run_thesis_case,
    thesis_settings_text,
)
from aerostat_core.model.io import inputs_from_dict, inputs_to_dict
from aerostat_core.model.presets import thesis_optimized_label

from . import cache, entry, formats
from .theme import ACCENT, FONT, MARGIN, SECOND, THIRD
from .theme import LIMIT_COLOUR as LIMIT

CURRENT = "Current design"
THESIS = thesis_optimized_label()
#: How each choice of the request reads in the form (the values and the field's label, help and
#: range are the registry's: :class:`aerostat_core.dynamics.request.DynamicsRequest`).
SCENARIOS = {
    "steady": "Steady wind",
    "varying": "Varying wind (ramps)",
    "gust": "Discrete gust (1 − cos)",
    "turbulence": "Dryden turbulence",
}
INTENSITIES = {"profile": "From the wind profile (W20 = wind at 20 ft)",
               "light": "Light (W20 = 15 kt)", "moderate": "Moderate (W20 = 30 kt)",
               "severe": "Severe (W20 = 45 kt)", "custom": "Custom W20"}
PROFILES = {"uniform": "Uniform", "power": "Power law", "log": "Log law"}
BODIES = {"hull": "3-DOF hull (surge, heave, pitch)", "point": "Point aerostat (no pitch)"}
GUST_SHAPES = {"full": "Full 1 − cos (returns to zero)", "ramp-hold": "Ramp and hold"}
CHOICE_NAMES = {"scenario": SCENARIOS, "turbulence.intensity": INTENSITIES,
                "profile": PROFILES, "body": BODIES, "gust.shape": GUST_SHAPES}
#: Key of the form's "Second change" checkbox (how many ramps: the request has a tuple of them).
SECOND_CHANGE = "dyn_second"
#: The form's defaults: the registry's, with a second ramp ready for the checkbox.
DEFAULTS = {sc: DynamicsRequest.for_scenario(sc) for sc in SCENARIOS}
DEFAULTS["varying"] = DynamicsRequest.for_scenario(
    "varying", changes=(SpeedChange(), SpeedChange(start=80.0, speed=7.0)))


@dataclass(frozen=True)
class Box:
    """One widget of the Dynamics form: its key and the request field it shows (a dotted path of
    :class:`DynamicsRequest`, "gust.amplitude_u", "changes.1.start"). Label, unit, help, kind
    and default come from the field registry; nothing about the field is typed here."""

    key: str
    path: str

    @property
    def spec(self) -> FieldSpec:
        return DynamicsRequest.spec_at(self.path)

    @property
    def label(self) -> str:
        s = self.spec
        if s.kind not in ("number", "integer"):
            return s.label
        ordinal = " (second change)" if self.path.startswith("changes.1.") else ""
        return f"{s.label}{ordinal} [{s.shown_unit}]"

    @property
    def help(self) -> str | None:
        return self.spec.help or None

    @property
    def options(self) -> dict[str, str]:
        """{value: shown name} of a choice."""
        names = CHOICE_NAMES.get(self.path, {})
        return {c: names.get(c, c) for c in self.spec.choices}

    def default(self, scenario: str) -> Any:
        return DEFAULTS[scenario].value_at(self.path)


#: The form's widgets by group, in the page's order.
LAYOUT = {
    "run": (Box("dyn_speed", "speed"), Box("dyn_duration", "duration")),
    "varying": (Box("dyn_tc", "changes.0.start"), Box("dyn_unew", "changes.0.speed"),
                Box("dyn_ramp", "changes.0.ramp")),
    "varying2": (Box("dyn_tc2", "changes.1.start"), Box("dyn_unew2", "changes.1.speed")),
    "gust": (Box("dyn_gu", "gust.amplitude_u"), Box("dyn_gw", "gust.amplitude_w"),
             Box("dyn_gl", "gust.length"), Box("dyn_gs", "gust.start_time"),
             Box("dyn_gshape", "gust.shape"), Box("dyn_gconv", "gust.convected")),
    "turbulence": (Box("dyn_int", "turbulence.intensity"), Box("dyn_w20", "turbulence.w20"),
                   Box("dyn_seed", "turbulence.seed"), Box("dyn_fade", "turbulence.fade_in"),
                   Box("dyn_fmax", "turbulence.max_frequency"),
                   Box("dyn_vert", "turbulence.vertical"),
                   Box("dyn_spatial", "turbulence.spatial")),
    "profile": (Box("dyn_profile", "profile"), Box("dyn_exp", "exponent"),
                Box("dyn_z0", "roughness")),
    "model": (Box("dyn_body", "body"), Box("dyn_nseg", "segments"), Box("dyn_zeta", "damping"),
              Box("dyn_wall", "wall"), Box("dyn_unsteady", "unsteady"),
              Box("dyn_modes", "modes")),
}
#: The scenario radio (drawn outside the form: it chooses which boxes the form shows).
SCENARIO_BOX = Box("dyn_scenario", "scenario")
BOXES = {b.key: b for group in LAYOUT.values() for b in group} | {SCENARIO_BOX.key: SCENARIO_BOX}


def box_label(key: str) -> str:
    """The label of a Dynamics form box, with its unit (e.g. "Random seed [-]")."""
    return BOXES[key].label


def widget(box: Box, container: Any, scenario: str, *, radio: bool = False) -> Any:
    """Draw the widget of ``box`` in ``container`` from the registry (a number box read like
    the Design form's, a checkbox for a yes/no field, a select box or, with ``radio``, a
    horizontal radio for a choice) and return its value (a number box's text)."""
    s = box.spec
    default = box.default(scenario)
    if s.kind in ("number", "integer"):
        return entry.number_box(box.label, key=box.key, value=default, container=container,
                                integer=s.integer, help=box.help)
    if s.kind == "flag":
        return container.checkbox(box.label, value=bool(default), key=box.key, help=box.help,
                                  persist_state="session")
    options = box.options
    pick = container.radio if radio else container.selectbox
    kw = {"horizontal": True} if radio else {}
    return pick(box.label, list(options), index=list(options).index(default),
                format_func=options.get, key=box.key, help=box.help, persist_state="session",
                **kw)


# --- request ------------------------------------------------------------------------------------
def _value(box: Box, form: Mapping[str, Any]) -> Any:
    """The value of a widget for the request: a number box's text read like the Design form's
    ("12,5" is 12.5); its range is the request's to check."""
    v = form[box.key]
    s = box.spec
    if s.kind in ("number", "integer") and isinstance(v, str):
        return entry.read(v, box.label, integer=s.integer)
    return v


def _given(form: Mapping[str, Any], group: str, prefix: str = "") -> dict[str, Any]:
    """{field: value} of the boxes of ``group`` that the form holds (a missing box keeps the
    registry's default)."""
    return {b.path.rsplit(".", 1)[-1]: _value(b, form) for b in LAYOUT[group]
            if b.key in form and b.path.startswith(prefix)}


def design_sources(cases_state: Mapping[str, Any] | None) -> list[str]:
    """Design choices: the current design, the thesis design, then saved cases."""
    return [CURRENT, THESIS] + [f"Case: {n}" for n in (cases_state or {})]


def _inputs_of(source: Any, design_inputs: Mapping[str, Any] | None,
               cases_state: Mapping[str, Any] | None) -> dict | None:
    if source == THESIS:
        return None
    if source == CURRENT:
        return dict(design_inputs) if design_inputs else None
    if isinstance(source, str) and source.startswith("Case: ") and cases_state and \
            source[6:] in cases_state:
        return dict(cases_state[source[6:]])
    raise ValueError(f"Design = {source!r} is not available; choose one of the list")


def build_request(form: Mapping[str, Any]) -> DynamicsRequest:
    """The typed request of the form's values ({widget key: value}; number boxes as text),
    validated once by :class:`DynamicsRequest`. Raises ``ValueError`` naming the box's label,
    the value and the valid range."""
    scenario = form.get(SCENARIO_BOX.key, "gust")
    try:
        kw = {**_given(form, "run"), **_given(form, "profile"), **_given(form, "model")}
        if scenario == "varying":
            first = SpeedChange(**_given(form, "varying"))
            changes = [first]
            if form.get(SECOND_CHANGE):
                try:
                    changes.append(SpeedChange(**_given(form, "varying2"), ramp=first.ramp))
                except InputError as exc:
                    raise InputError(str(exc), **{**_error_fields(exc),
                                                  "label": f"{exc.label} (second change)"}) \
                        from None
            kw["changes"] = tuple(changes)
        elif scenario == "gust":
            kw["gust"] = GustSettings(**_given(form, "gust"))
        elif scenario == "turbulence":
            kw["turbulence"] = TurbulenceSettings(**_given(form, "turbulence"))
        return DynamicsRequest(scenario=scenario, **kw)
    except InputError as exc:
        raise ValueError(error_text(exc)) from None


def _error_fields(exc: InputError) -> dict[str, Any]:
    return {k: getattr(exc, k) for k in ("owner", "field", "value", "lo", "hi", "lo_open",
                                         "hi_open", "unit", "reason", "context")}


class DynamicsKey(NamedTuple):
    """Key of one simulation ("dynamics"): the design inputs frozen and the typed request."""

    requirement: Requirement | None  # resolved (:func:`app_ui.cache.frozen_inputs`); None: thesis
    configuration: Configuration | None  # None for the thesis design
    request: DynamicsRequest  # the run's settings, frozen and validated


class ThesisKey(NamedTuple):
    """Key of the live thesis comparison ("dynamics_thesis")."""

    seed: int  # seed of the turbulence scenario


def build_run(form: Mapping[str, Any], design_inputs: Mapping[str, Any] | None,
              cases_state: Mapping[str, Any] | None) -> DynamicsKey:
    """Validate the form (the design chosen in ``form["dyn_source"]`` and the request) and
    return the run's store key, which the session keeps: the design inputs as the frozen
    (resolved Requirement, Configuration) of :func:`app_ui.cache.frozen_inputs` (None, None for
    the thesis design) and the :class:`DynamicsRequest`. No JSON on the way.

    Raises ``ValueError`` naming the field, the value and its valid range.
    """
    inputs = _inputs_of(form.get("dyn_source", CURRENT), design_inputs, cases_state)
    frozen = None if inputs is None else cache.frozen_inputs(*inputs_from_dict(inputs))
    dyn = build_request(form)
    req_k, cfg_k = frozen or (None, None)
    return DynamicsKey(requirement=req_k, configuration=cfg_k, request=dyn)


def run(key: DynamicsKey, progress: Callable[[float], None] | None = None) -> dict:
    """Simulate the run of ``key`` and collect plain results (:func:`collect`)."""
    if key.requirement is None:
        d, inputs = None, None
    else:
        d = cache.design_of(key.requirement, key.configuration)
        inputs = inputs_to_dict(key.requirement, key.configuration)
    res, d = run_request(key.request, progress, design=d)
    return collect(res, key.request, d, inputs)


# --- result store (no UI element inside: see the module docstring) -----------------------------
_STORE_SIZE = 16


def stored(key: DynamicsKey) -> dict | None:
    """The stored result of a run's key (:func:`build_run`), or None."""
    return cache.peek("dynamics", key)


def run_cached(key: DynamicsKey, progress: Callable[[float], None] | None = None) -> dict:
    """The result of the run of ``key`` (:func:`build_run`): from the store, or run now
    (``progress`` is called with the fraction done) and stored. The caller draws any progress
    element; nothing here touches the page."""
    return cache.memo("dynamics", key, lambda: run(key, progress), _STORE_SIZE)


def kernels_ready() -> bool:
    """True when the simulation kernels are loaded in this process."""
    return kernels_warm()


@st.cache_resource(show_spinner=False)
def warm() -> float:
    """Load (compile the first time) the simulation kernels once per server process; seconds."""
    return warm_kernels()


def collect(res, dyn: DynamicsRequest, d=None, inputs: Mapping[str, Any] | None = None) -> dict:
    """Plain data of a :class:`SimulationResult` for the page (lists, floats, strings);
    ``inputs``: the design inputs dict the run used, for the CSV header (None: thesis)."""
    names = res.signal_names()
    sig = {k: res.signal(k).tolist() for k in names}
    t = res.t
    n = t.size
    # tether snapshots every ~1 s (at most 400) for the slider, with the hull outline
    step = max(1, int(round(1.0 / max(t[1] - t[0], 1e-9)))) if n > 1 else 1
    idx = list(range(0, n, step))
    if idx[-1] != n - 1:
        idx.append(n - 1)
    if len(idx) > 400:
        idx = [idx[int(round(i))] for i in np.linspace(0, len(idx) - 1, 400)]
    snaps = []
    for i in idx:
        pos = res.tether(i)
        s = {"t": float(t[i]), "x": pos[:, 0].tolist(), "z": pos[:, 1].tolist()}
        if res.system.is_hull:
            hx, hz = res.hull_outline(i)
            s["hull_x"], s["hull_z"] = hx.tolist(), hz.tolist()
            rx, rz = res.rigging(i)
            s["rig_x"], s["rig_z"] = rx.tolist(), rz.tolist()
        snaps.append(s)
    t_from = 0.0
    if dyn.scenario == "turbulence":
        t_from = min(float(dyn.turbulence.fade_in), float(t[-1]) * 0.5)
    stats = res.stats_table(t_from=t_from)
    stat_rows = []
    for k in names:
        label, unit = SIGNALS[k]
        s = stats[k]
        stat_rows.append({"signal": label, "unit": unit, "mean": s.mean,
                          "rms_fluctuation": s.std, "peak_excursion": s.peak, "min": s.min,
                          "max": s.max})
    metrics = []
    te = dyn.event_time
    if te is not None and t[-1] > te + 5.0:
        final = None
        for k in ("x_C", "z_C", "theta", "vx", "tension_C"):
            if k not in names:
                continue
            m = response_metrics(t, res.signal(k), te, 0.05, final=final)
            m2 = response_metrics(t, res.signal(k), te, 0.02, final=final)
            metrics.append({"signal": SIGNALS[k][0], "unit": SIGNALS[k][1],
                            "settling_5pct_s": m.settling_time, "settling_2pct_s": m2.settling_time,
                            "band_5pct": m.band, "overshoot_pct": m.overshoot,
                            "peak_excursion": m.peak_excursion, "final": m.final})
    out = {
        "ok": bool(res.ok), "status": int(res.status), "message": res.message,
        "t": t.tolist(), "signals": sig, "snapshots": snaps, "stats": stat_rows,
        "stats_from": t_from, "metrics": metrics, "event_time": te,
        "solver": {k: (float(v) if isinstance(v, float) else v) for k, v in res.stats.items()},
        "is_hull": bool(res.system.is_hull),
        "csv": res.to_csv(header=request_header(dyn, res, inputs)),
        "csv_name": f"aerostat_dynamics_{dyn.scenario}.csv",
        "slack_events": res.slack_events(), "limits": None,
        "equilibrium_shift_mm": (1e3 * res.equilibrium.shift if res.equilibrium else None),
        "tether_segments": res.system.tether.segments, "modes": None, "turbulence": None,
    }
    rec = res.wind.turbulence
    if rec is not None:
        p = rec.params
        fu, fw = rec.variance_fraction
        out["turbulence"] = {"sigma_u": p.sigma_u, "sigma_w": p.sigma_w, "length_u": p.length_u,
                             "length_w": p.length_w, "height": p.height_used,
                             "clamped": bool(p.clamped), "speed": rec.speed, "seed": rec.seed,
                             "variance_fraction_u": fu, "variance_fraction_w": fw,
                             "model": rec.model, "levels": int(rec.z_levels.size),
                             "intensity": dyn.turbulence.intensity}
    if d is not None:
        lim = limits_of(d)
        out["limits"] = limit_flags(res, lim)
        out["limit_values"] = {"fin_stall_deg": lim.fin_stall_deg,
                               "safe_working_load": lim.safe_working_load,
                               "min_height": lim.min_height}
    if dyn.modes and res.system.is_hull is not None:
        try:
            lin = linearize(res.system, wind=res.wind, state=res.y[0])
            out["modes"] = [{k: (float(v) if isinstance(v, float) else v) for k, v in r.items()}
                            for r in lin.rows()]
            out["stable"] = bool(lin.stable)
        except Exception as exc:  # noqa: BLE001 - shown to the user, never a traceback
            out["modes_error"] = str(exc)
    return out


def turbulence_caption(tb: Mapping[str, Any]) -> str:
    """One line naming the turbulence model in use and its realised values at the hull."""
    clamp = (" (the hull is above 1000 ft: the low-altitude values at 1000 ft are used)"
             if tb["clamped"] else "")
    src = ("W20 from the run's wind profile" if tb.get("intensity") == "profile"
           else "W20 set by the intensity level")
    return (f"Turbulence model: {tb.get('model', 'Dryden')}; {src}. At the hull "
            f"(h = {tb['height']:.0f} m{clamp}): σ_u = {tb['sigma_u']:.2f} m/s, "
            f"σ_w = {tb['sigma_w']:.2f} m/s, L_u = {tb['length_u']:.0f} m, "
            f"L_w = {tb['length_w']:.0f} m, convected at V = {tb['speed']:.1f} m/s "
            f"(σ_u/V = {100 * tb['sigma_u'] / max(tb['speed'], 1e-9):.0f} %), "
            f"{tb.get('levels', 1)} height levels, seed {tb['seed']}; the synthesised record "
            f"holds {100 * tb['variance_fraction_u']:.1f} % / {100 * tb['variance_fraction_w']:.1f} % "
            "of σ_u² / σ_w² at the hull (the rest lies above the highest frequency).")


def one_decimal(v: float) -> str:
    """``v`` with one decimal, never "-0.0"."""
    txt = f"{v:.1f}"
    return "0.0" if txt == "-0.0" else txt


def limits_frame_rows(out: Mapping[str, Any]) -> list[dict]:
    """Rows of the limits table (limit, value, worst, exceeded, first time)."""
    return [{"limit": r["limit"], "unit": r["unit"], "limit_value": r["value"],
             "worst": r["worst"], "exceeded": "yes" if r["exceeded"] else "no",
             "first_s": r["first_s"]} for r in (out.get("limits") or [])]


# --- thesis comparison --------------------------------------------------------------------------
def thesis_comparison(seed: int = 1) -> dict:
    """The thesis comparison computed live (no UI element inside; shared by every session,
    read-only): table rows, the settings, and the time histories of pitch and hull velocities
    per scenario (plain data)."""
    key = ThesisKey(seed=int(seed))
    return cache.memo("dynamics_thesis", key, lambda: _thesis_comparison(key.seed), 4)


def _thesis_comparison(seed: int) -> dict:
    from aerostat_core.dynamics.scenarios import design_of

    d = design_of(None)
    runs, series = {}, {}
    for sc in THESIS_CLAIMS:
        res, m, _req, _ = run_thesis_case(sc, seed=seed, design=d)
        runs[sc] = m
        series[sc] = {"t": res.t.tolist(), "theta": res.signal("theta").tolist(),
                      "vx": res.signal("vx").tolist(), "vz": res.signal("vz").tolist(),
                      "x_C": res.signal("x_C").tolist(), "window_start": m["window_start_s"],
                      "status": m["status"]}
    return {"rows": comparison_rows(runs), "settings": thesis_settings_text(), "series": series,
            "factor": MATCH_FACTOR, "why": WHY_NOT, "volume": float(d.volume),
            "fineness": float(np.asarray(d.airframe.hull.fineness_ratio).reshape(-1)[0])}


def thesis_figure(cmp: Mapping[str, Any], scenario: str) -> go.Figure:
    """Pitch and hull velocities of one thesis scenario, with the thesis' ± bands about the mean
    over the metrics window."""
    s = cmp["series"][scenario]
    t = np.asarray(s["t"])
    sel = t >= s["window_start"]
    data = [_line(s["t"], s["theta"], "pitch θ [deg]", ACCENT),
            _line(s["t"], s["vx"], "hull v_x [m/s]", SECOND, yaxis="y2"),
            _line(s["t"], s["vz"], "hull v_z [m/s]", THIRD, yaxis="y2")]
    claims = THESIS_CLAIMS[scenario]
    shapes = []
    th = np.asarray(s["theta"])[sel]
    if "pitch_peak_deg" in claims and th.size:
        m = float(th.mean())
        for sgn in (-1, 1):
            y = m + sgn * claims["pitch_peak_deg"]
            shapes.append(dict(type="line", xref="paper", x0=0, x1=1, yref="y", y0=y, y1=y,
                               line=dict(color=ACCENT, dash="dot", width=1)))
    return _fig(data, f"Thesis case: {SCENARIOS[scenario]} (dotted: thesis ± pitch)",
                "Time t [s]", "Pitch [deg]", shapes=shapes,
                yaxis2=dict(title=dict(text="Velocity [m/s]"), overlaying="y", side="right"))


def current_inputs_or_none(state: Mapping[str, Any]) -> dict | None:
    """The session's design inputs dict, or None (then the thesis design is used)."""
    d = state.get("design_inputs")
    if not d:
        return None
    try:
        return inputs_to_dict(*inputs_from_dict(d))
    except (ValueError, TypeError):
        return None


# --- figures ------------------------------------------------------------------------------------
def _fig(data: list, title: str, xt: str, yt: str, **layout: Any) -> go.Figure:
    # hover at the decimals of each axis' quantity (app_ui.formats), not 15 digits
    lay = dict(title=dict(text=title), font=FONT, margin=MARGIN, template="plotly_white",
               xaxis=dict(title=dict(text=xt), hoverformat=formats.axis_hover(xt)),
               yaxis=dict(title=dict(text=yt), hoverformat=formats.axis_hover(yt)),
               legend=dict(orientation="h", y=-0.2), height=360)
    lay.update(layout)
    return go.Figure(dict(data=data, layout=lay))


def _line(x, y, name, colour=ACCENT, **kw) -> dict:
    return dict(type="scatter", mode="lines", x=x, y=y, name=name,
                line=dict(color=colour, width=kw.pop("width", 2), dash=kw.pop("dash", None)), **kw)


def _hline(y: float, yref: str = "y") -> dict:
    return dict(type="line", xref="paper", x0=0, x1=1, yref=yref, y0=y, y1=y,
                line=dict(color=LIMIT, dash="dash", width=1))


def limit_lines(out: Mapping[str, Any], names, limits, unit: str = "") -> tuple[list, str]:
    """Limit lines worth drawing: [(value, label)] for the limits the signals come within half
    of (farther ones would flatten the curves), and a note naming the others with their value
    and ``unit`` ("safe working load 12,000 N")."""
    peak = max((max(abs(v) for v in out["signals"][k]) for k in names if k in out["signals"]),
               default=0.0)
    lines, far = [], []
    for value, label in limits:
        if value is None:
            continue
        (lines if abs(value) == 0.0 or peak >= 0.5 * abs(value) else far).append((value, label))
    u = f" {unit}" if unit else ""
    note = ", ".join(
        sorted({f"{lab} {abs(v):,.0f}{u}" if abs(v) >= 1000 else f"{lab} {abs(v):.4g}{u}"
                for v, lab in far}))
    return lines, (f"; not reached: {note}" if note else "")


def time_figure(out: Mapping[str, Any], names, title: str, ytitle: str, key_names=None,
                hlines=(), note: str = "") -> go.Figure:
    """Signals versus time on one axis (a dotted marker at the event time, dashed red limit
    lines at ``hlines`` = [(value, label)], labelled in the title with ``note``)."""
    cols = (ACCENT, SECOND, THIRD)
    data = [_line(out["t"], out["signals"][k], (key_names or {}).get(k, SIGNALS[k][0]),
                  cols[i % 3]) for i, k in enumerate(names) if k in out["signals"]]
    shapes = [_hline(y) for y, _ in hlines]
    if out.get("event_time") is not None:
        shapes.append(dict(type="line", xref="x", yref="paper", x0=out["event_time"],
                           x1=out["event_time"], y0=0, y1=1,
                           line=dict(color="#7f7f7f", dash="dot", width=1)))
    if hlines:
        title = f"{title} (red: {', '.join(sorted({lab for _, lab in hlines}))}{note})"
    elif note:
        title = f"{title} ({note[2:]})"
    return _fig(data, title, "Time t [s]", ytitle, shapes=shapes)


def position_figure(out: Mapping[str, Any]) -> go.Figure:
    """x_C(t) and z_C(t) (two y axes), as thesis Figs 4.37/4.39/4.41, with the lowest accepted
    height (dashed red)."""
    t = out["t"]
    data = [_line(t, out["signals"]["x_C"], "blow-by x_C [m]", ACCENT),
            _line(t, out["signals"]["z_C"], "altitude z_C [m]", SECOND, yaxis="y2")]
    shapes = []
    title = "Position of the confluence point"
    lim = out.get("limit_values")
    if lim:
        shapes.append(_hline(lim["min_height"], "y2"))
        title += " (red: lowest height)"
    return _fig(data, title, "Time t [s]", "Blow-by x_C [m]", shapes=shapes,
                yaxis2=dict(title=dict(text="Altitude z_C [m]"), overlaying="y", side="right"))


def tether_figure(out: Mapping[str, Any], indices=None, title="Tether profile") -> go.Figure:
    """Tether (and hull) at the given snapshot indices (default: first and last), to scale."""
    snaps = out["snapshots"]
    indices = [0, len(snaps) - 1] if indices is None else indices
    cols = (ACCENT, SECOND, THIRD)
    data = []
    for j, i in enumerate(indices):
        s = snaps[i]
        c = cols[j % 3]
        data.append(_line(s["x"], s["z"], f"tether, t = {s['t']:.1f} s", c))
        if "hull_x" in s:
            data.append(dict(type="scatter", mode="lines", x=s["hull_x"], y=s["hull_z"],
                             name=f"hull, t = {s['t']:.1f} s", fill="toself",
                             line=dict(color=c, width=1), opacity=0.6))
    return _fig(data, title, "Downwind distance x [m]", "Height z [m]",
                yaxis=dict(title=dict(text="Height z [m]"), scaleanchor="x", scaleratio=1),
                height=520)


def hull_zoom_figure(out: Mapping[str, Any], i: int) -> go.Figure:
    """The hull and the top of the tether at snapshot ``i`` (zoomed, to scale), with the path of
    the confluence point."""
    s = out["snapshots"][i]
    data = [_line(out["signals"]["x_C"], out["signals"]["z_C"], "path of C", "#b0b0b0", width=1),
            _line(s["x"][-4:], s["z"][-4:], "tether (top)", ACCENT)]
    if "hull_x" in s:
        data.append(dict(type="scatter", mode="lines", x=s["hull_x"], y=s["hull_z"],
                         name="hull", fill="toself", line=dict(color=SECOND, width=1)))
        data.append(_line(s["rig_x"], s["rig_z"], "confluence lines", "#7f7f7f", width=1))
    xc, zc = s["x"][-1], s["z"][-1]
    half = 20.0 if "hull_x" not in s else max(20.0, 1.3 * (max(s["hull_x"]) - min(s["hull_x"])))
    return _fig(data, f"Hull at t = {s['t']:.1f} s", "Downwind distance x [m]", "Height z [m]",
                xaxis=dict(title=dict(text="Downwind distance x [m]"),
                           range=[xc - half, xc + half]),
                yaxis=dict(title=dict(text="Height z [m]"), scaleanchor="x", scaleratio=1,
                           range=[zc - 0.8 * half, zc + 0.8 * half]),
                height=520)
