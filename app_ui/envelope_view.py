"""UI of the Design page's Envelope tab: operating envelope heat map with the limit boundaries,
flyable time at a site, Monte Carlo bands with the rule-set spread, and the HTML report button.

Physics lives in :mod:`aerostat_core.studies.envelope`, :mod:`aerostat_core.studies.site_wind`,
:mod:`aerostat_core.studies.uncertainty` and :mod:`aerostat_core.output.html_report`; this module caches their
results (:func:`app_ui.cache.memo`, keyed by the frozen inputs, the site as frozen values and the
sample size and seed, one :class:`~typing.NamedTuple` per study (:class:`FlyableKey` ...), so every
compute reads its key by field name; shared by every session, read-only) and draws them.
"""

from __future__ import annotations

import json
from collections.abc import Hashable
from typing import Any, NamedTuple

import numpy as np
import pandas as pd
import plotly.graph_objects as go
import streamlit as st

from aerostat_core import Configuration, Requirement
from aerostat_core.model.budget import BudgetError, max_monte_carlo_samples
from aerostat_core.model.constraints import BY_NAME
from aerostat_core.output.html_report import build_report
from aerostat_core.output.report import DesignReport
from aerostat_core.studies.envelope import ENVELOPE_NAMES, Envelope, operating_envelope
from aerostat_core.studies.site_wind import MAX_CSV_BYTES, WeibullSite, flyable_time, read_wind_csv
from aerostat_core.studies.uncertainty import monte_carlo, rule_set_spread

from . import cache, entry, formats, show
from .headline import Headline
from .plots import WIND_AXIS
from .text import plain
from .theme import MARGIN, PALETTE

SITE_KEY = "envelope_site"  # session key: {"kind": "weibull", ...} or {"kind": "csv", ...}
MC_KEY = "envelope_mc"  # session key: {"n": N, "seed": S} once the user ran it
#: Markdown characters escaped in messages that quote the user's file (shown as plain text).
_MD = str.maketrans({ch: "\\" + ch for ch in "\\`*_{}[]()#+-.!|<>$~"})
#: Monte Carlo sizes offered in the app (the CLI and API take any size).
MC_SIZES = (1000, 5000, 10000, 20000)


# --- the study keys (one per cache kind; each is a tuple, hashable and equal by value) ----------


class EnvelopeKey(NamedTuple):
    """Key of the operating envelope ("envelope")."""

    requirement: Requirement  # resolved (:func:`app_ui.cache.frozen_inputs`)
    configuration: Configuration


class SiteKey(NamedTuple):
    """The site wind of the session as frozen values (part of the flyable and report keys)."""

    spec: Hashable  # the site form's spec {kind, shape, scale, ...} (:func:`app_ui.cache.freeze`)
    csv: bytes | None  # the hourly wind CSV file's bytes (None for a Weibull site)


class FlyableKey(NamedTuple):
    """Key of the flyable time at a site ("flyable")."""

    requirement: Requirement  # resolved
    configuration: Configuration
    site: SiteKey


class MonteCarloKey(NamedTuple):
    """Key of the Monte Carlo bands ("monte_carlo")."""

    requirement: Requirement  # resolved
    configuration: Configuration
    n_samples: int
    seed: int


class SpreadKey(NamedTuple):
    """Key of the rule-set spread ("rules_spread")."""

    requirement: Requirement  # as given: each rule set fills in its own limits
    seed: int


class ReportKey(NamedTuple):
    """Key of the HTML design report ("report_html")."""

    requirement: Requirement  # as given: the report resolves it under every rule set
    configuration: Configuration
    site: SiteKey | None  # None: the default Weibull site
    n_samples: int  # Monte Carlo samples (0 leaves the uncertainty out)
    seed: int
    units: str = "SI"  # unit system of the values shown (the sidebar's choice)


# --- cached engine calls --------------------------------------------------------------------------


def cached_envelope(inputs_json: str) -> Envelope:
    """:func:`operating_envelope` of the design of ``inputs_json`` (default axes)."""
    key = EnvelopeKey(*cache.inputs_of(inputs_json))
    return cache.memo(
        "envelope",
        key,
        lambda: operating_envelope(cache.design_of(key.requirement, key.configuration)),
        32,
    )


def _site(site: SiteKey):
    """The site wind of a frozen site (:func:`_site_key`)."""
    spec = cache.thaw(site.spec)
    if spec["kind"] == "csv":
        return read_wind_csv(site.csv or b"", spec["reference_height"], spec["shear_exponent"])
    return WeibullSite(
        spec["shape"], spec["scale"], spec["reference_height"], spec["shear_exponent"]
    )


def _site_key(site_json: str | None, csv_bytes: bytes | None) -> SiteKey | None:
    """The site of the session (JSON text of the spec, the CSV file's bytes) as frozen values."""
    if site_json is None:
        return None
    return SiteKey(spec=cache.freeze(json.loads(site_json)), csv=csv_bytes)


def cached_flyable(inputs_json: str, site_json: str, csv_bytes: bytes | None) -> dict:
    """:func:`flyable_time` summary for the design and the site (raises ValueError)."""
    req_k, cfg_k = cache.inputs_of(inputs_json)
    key = FlyableKey(requirement=req_k, configuration=cfg_k, site=_site_key(site_json, csv_bytes))

    def compute() -> dict:
        ft = flyable_time(
            cache.design_of(key.requirement, key.configuration),
            _site(key.site),
            target_availability=cache.thaw(key.site.spec)["target"],
        )
        return ft.summary()

    return cache.memo("flyable", key, compute, 32)


def cached_monte_carlo(inputs_json: str, n: int, seed: int):
    """:func:`monte_carlo` of the design (bands and probabilities)."""
    req_k, cfg_k = cache.inputs_of(inputs_json)
    key = MonteCarloKey(requirement=req_k, configuration=cfg_k, n_samples=int(n), seed=int(seed))

    def compute() -> dict:
        mc = monte_carlo(
            cache.design_of(key.requirement, key.configuration), n=key.n_samples, seed=key.seed
        )
        return {
            "summary": mc.summary(),
            "speeds": mc.speeds,
            "blow_by": mc.blow_by,
            "tension": mc.tension,
            "specs": [
                {
                    "Input": u.label,
                    "1-sigma": u.sigma,
                    "Kind": "relative" if u.relative else "absolute",
                    "Source": u.source,
                }
                for u in mc.specs
            ],
        }

    return cache.memo("monte_carlo", key, compute, 16)


def cached_rules_spread(inputs_json: str, seed: int) -> list[dict]:
    """:func:`rule_set_spread` of the mission of ``inputs_json`` (the requirement as given:
    each rule set fills in its own limits)."""
    req, _ = cache.given_inputs(inputs_json)
    key = SpreadKey(requirement=req, seed=int(seed))
    return cache.memo(
        "rules_spread",
        key,
        lambda: rule_set_spread(key.requirement, n=2000, seed=key.seed),
        16,
    )


def cached_report_html(
    inputs_json: str,
    site_json: str | None = None,
    csv_bytes: bytes | None = None,
    n: int = 2000,
    seed: int = 0,
    units: str = "SI",
) -> bytes:
    """The HTML design report with the tab's site wind and Monte Carlo (defaults: the default
    Weibull site, 2000 samples), its values in unit system ``units``."""
    req, cfg = cache.given_inputs(inputs_json)
    key = ReportKey(
        requirement=req,
        configuration=cfg,
        site=_site_key(site_json, csv_bytes),
        n_samples=int(n),
        seed=int(seed),
        units=str(units),
    )

    def compute() -> bytes:
        return build_report(
            cache.design_of(key.requirement, key.configuration),
            None if key.site is None else _site(key.site),
            n_monte_carlo=key.n_samples,
            seed=key.seed,
            base_requirement=key.requirement,
            units=key.units,
        ).encode("utf-8")

    return cache.memo("report_html", key, compute, 8)


def envelope_figure(env: Envelope) -> go.Figure:
    """Heat map of the largest constraint value g (binding constraint in the hover) over wind x
    altitude, a g = 0 contour per constraint that crosses the map, and the design point."""
    mg = np.clip(env.max_g[0], -1.0, 1.0)
    names = env.binding_names()[0]
    labels = np.vectorize(lambda n: BY_NAME[n].label)(names)
    units = np.vectorize(lambda n: BY_NAME[n].unit)(names)
    text = np.char.add(
        np.char.add(labels, ": margin "),
        np.char.add(np.char.mod("%.3g ", env.binding_margin[0]), units),
    )
    traces: list[dict] = [
        {
            "type": "heatmap",
            "x": env.wind.tolist(),
            "y": env.altitude.tolist(),
            "z": mg.tolist(),
            "zmin": -1,
            "zmax": 1,
            "colorscale": "RdYlGn",
            "reversescale": True,
            "text": text.tolist(),
            "name": "largest g",
            "hovertemplate": "%{x:.1f} m/s, %{y:.0f} m<br>%{text}<br>g = %{z:.3f}<extra></extra>",
            "colorbar": {"title": {"text": "largest g"}},
        }
    ]
    for k, name in enumerate(ENVELOPE_NAMES):
        gk = env.g[0, :, :, k]
        if gk.shape[0] > 1 and gk.min() < 0 < gk.max():
            traces.append(
                {
                    "type": "contour",
                    "x": env.wind.tolist(),
                    "y": env.altitude.tolist(),
                    "z": gk.tolist(),
                    "showscale": False,
                    "name": BY_NAME[name].label,
                    "contours": {"start": 0, "end": 0, "size": 1, "coloring": "lines"},
                    "line": {"color": PALETTE[k % len(PALETTE)], "width": 2},
                    "colorscale": [[0, PALETTE[k % len(PALETTE)]], [1, PALETTE[k % len(PALETTE)]]],
                    "showlegend": True,
                    "hoverinfo": "skip",
                }
            )
    traces.append(
        {
            "type": "scatter",
            "x": [env.design_wind],
            "y": [env.design_altitude],
            "mode": "markers",
            "name": "design point",
            "marker": {"symbol": "star", "size": 14, "color": "black"},
        }
    )
    return go.Figure(  # drawn in SI, shown in the session's unit system
        formats.figure_dict_in_system({
            "data": traces,
            "layout": {
                "title": {
                    "text": "Operating envelope: binding constraint (lines: limit boundaries)"
                },
                "xaxis": {"title": {"text": WIND_AXIS}},
                "yaxis": {"title": {"text": "Altitude = tether length [m]"}},
                "legend": {"orientation": "h", "y": -0.25},
                "height": 520,
                "margin": {"l": 60, "r": 20, "t": 50, "b": 50},
            },
        })
    )


def bands_figure(mc: dict, rep: DesignReport) -> go.Figure:
    """5-95 % bands of blow-by and tension versus wind, with the design's curves."""
    from plotly.subplots import make_subplots

    fig = make_subplots(rows=1, cols=2, subplot_titles=("Blow-by [m]", "Top tension [N]"))
    u = np.asarray(mc["speeds"], float)
    for col, key, perf in ((1, "blow_by", "blow_by"), (2, "tension", "tension_top")):
        band = np.asarray(mc[key], float)
        fig.add_scatter(
            x=np.r_[u, u[::-1]],
            y=np.r_[band[2], band[0][::-1]],
            fill="toself",
            line={"width": 0},
            fillcolor="rgba(31,95,168,0.25)",
            name="5-95 %",
            showlegend=col == 1,
            row=1,
            col=col,
            hoverinfo="skip",
        )
        fig.add_scatter(
            x=u,
            y=band[1],
            name="median",
            line={"color": PALETTE[0]},
            showlegend=col == 1,
            row=1,
            col=col,
        )
        fig.add_scatter(
            x=rep.perf.wind_speed,
            y=getattr(rep.perf, perf),
            name="design",
            line={"color": "black", "dash": "dot"},
            showlegend=col == 1,
            row=1,
            col=col,
        )
        fig.update_xaxes(title_text=WIND_AXIS, row=1, col=col)
        fig.update_yaxes(title_text=("Blow-by [m]", "Top tension [N]")[col - 1], row=1, col=col)
    fig.update_layout(height=380, margin={**MARGIN, "t": 40})
    return formats.figure_in_system(fig)  # drawn in SI, shown in the session's unit system


def report_button(inputs_json: str) -> None:
    """One-click download of the HTML design report (built when clicked), with the site wind
    and Monte Carlo size of the Envelope tab once set there."""
    site = st.session_state.get(SITE_KEY) or {}
    run = dict(st.session_state.get(MC_KEY) or {"n": 2000, "seed": 0})
    # within the compute budget of one process (many tether segments: fewer samples; the
    # report states the sample count it used)
    _, cfg = cache.given_inputs(inputs_json)
    run["n"] = min(run["n"], max_monte_carlo_samples(cfg.tether_segments, 10))
    units = formats.system()  # the sidebar's unit system, read now (the build runs later)

    def build() -> bytes:
        try:
            return cached_report_html(
                inputs_json, site.get("json"), site.get("csv"), run["n"], run["seed"], units
            )
        except ValueError:  # a bad site file (its message is on the tab): the default site
            return cached_report_html(inputs_json, None, None, run["n"], run["seed"], units)

    st.download_button(
        "Design report (HTML)",
        data=build,
        file_name="aerostat-report.html",
        mime="text/html",
        on_click="ignore",
        icon=":material/description:",
        key="dl_report",
        help="Self-contained report (works offline, prints to PDF): requirement, rule set, "
        "geometry, mass, performance, tether, constraint margins, envelope, flyable time, "
        "uncertainty, validation and version; uses the Envelope tab's site wind and Monte "
        "Carlo size once set there.",
    )


#: The site form's number boxes: key -> (label, default, lowest, highest, unit).
_SITE_BOXES = {  # key -> (WeibullSite field, default); label, unit, range from the registry
    "site_k": ("shape", 2.0),
    "site_c": ("scale", 6.0),
    "site_zref": ("reference_height", 10.0),
    "site_alpha": ("shear_exponent", round(1 / 7, 3)),
}


def _site_form() -> None:
    with st.form("site_form", border=True):
        st.markdown("**Site wind**")
        kind = st.radio("Source", ["Weibull", "Hourly CSV"], horizontal=True, key="site_kind")
        c = st.columns(4)
        # text boxes read like the Design form's ("2,5" is 2.5, never 25)
        texts = {
            key: entry.spec_box(col, WeibullSite, name, default, key)
            for col, (key, (name, default)) in zip(c, _SITE_BOXES.items())
        }
        target = st.slider("Target availability [%]", 50.0, 99.9, 95.0, 0.1, key="site_target")
        up = st.file_uploader(
            "Hourly wind CSV (timestamp, speed [m/s])", type=["csv"], key="site_csv"
        )
        if st.form_submit_button("Compute flyable time", icon=":material/air:"):
            try:
                k, cc, zr, al = (
                    entry.spec_read(texts[key], WeibullSite, name, key)
                    for key, (name, _d) in _SITE_BOXES.items()
                )
            except ValueError as exc:
                st.session_state[SITE_KEY] = {"error": str(exc)}
                return
            spec: dict[str, Any] = {
                "kind": "csv" if kind == "Hourly CSV" else "weibull",
                "shape": k,
                "scale": cc,
                "reference_height": zr,
                "shear_exponent": al,
                "target": target / 100.0,
            }
            data = None
            if spec["kind"] == "csv":
                if up is None:
                    st.session_state[SITE_KEY] = {"error": "choose a wind CSV file first"}
                    return
                if up.size > MAX_CSV_BYTES:
                    st.session_state[SITE_KEY] = {
                        "error": f"wind CSV is {up.size} bytes, larger than the "
                        f"{MAX_CSV_BYTES} allowed"
                    }
                    return
                data = up.getvalue()
            st.session_state[SITE_KEY] = {"json": json.dumps(spec, sort_keys=True), "csv": data}


def _flyable(inputs_json: str) -> None:
    _site_form()
    site = st.session_state.get(SITE_KEY) or {
        "json": json.dumps(
            {
                "kind": "weibull",
                "shape": 2.0,
                "scale": 6.0,
                "reference_height": 10.0,
                "shear_exponent": 1 / 7,
                "target": 0.95,
            },
            sort_keys=True,
        ),
        "csv": None,
    }
    if "error" in site:
        st.error(site["error"].translate(_MD), icon=":material/error:")
        return
    try:
        f = cached_flyable(inputs_json, site["json"], site["csv"])
    except ValueError as exc:  # quotes the file's cell: never rendered as markup
        st.error(str(exc).translate(_MD), icon=":material/error:")
        return
    show.headlines([
        Headline(
            "Time flyable [%]",
            f"{f['percent_time_flyable']:.1f}",
            help=formats.text_in_system(f"Share of the time the wind at {f['site_altitude_m']:g} m")
            + " lies in the flyable winds "
            + ", ".join(
                f"{formats.shown(a, 'wind')}-{formats.shown(b, 'wind')}"
                for a, b in f["flyable_winds_m_s"]
            )
            + f" {formats.unit_of('wind')}.",
        ),
        Headline(
            "Longest outage [h]",
            f"{f['longest_outage_h']:.0f}",
            help="Longest run of hours that cannot fly (Weibull: mean yearly longest "
            "run of simulated hours; CSV: in the record).",
        ),
        Headline(
            formats.label(f"Design wind for {100 * f['target_availability']:g} %", "wind"),
            formats.shown(f["design_wind_for_target_m_s"], "wind"),
            help="Wind at the aerostat not exceeded that share of the time: size for it "
            "to fly that often.",
        ),
    ])


def _uncertainty(inputs_json: str, rep: DesignReport) -> None:
    with st.form("mc_form", border=False):
        c = st.columns([1, 1, 1], vertical_alignment="bottom")
        n = c[0].selectbox("Monte Carlo samples", MC_SIZES, index=2, key="mc_n")
        seed_text = entry.number_box("Seed", key="mc_seed", value=0, integer=True, container=c[1])
        if c[2].form_submit_button("Run Monte Carlo", icon=":material/casino:"):
            try:
                seed = entry.read(seed_text, "Seed", integer=True, lo=0, hi=2**31 - 1)
            except ValueError as exc:
                st.error(plain(str(exc)), icon=":material/error:")
                return
            st.session_state[MC_KEY] = {"n": int(n), "seed": int(seed)}
    run = st.session_state.get(MC_KEY)
    if not run:
        st.caption(
            "Bands over drag coefficients, fabric areal density, purity, tether drag and "
            "wind-profile exponent: press Run Monte Carlo."
        )
        return
    try:
        mc = cached_monte_carlo(inputs_json, run["n"], run["seed"])
    except BudgetError as exc:  # the compute budget, shared with the CLI: says what to reduce
        st.error(plain(str(exc)), icon=":material/error:")
        return
    s = mc["summary"]
    lift = formats.display("mass")
    show.headlines([  # in the chosen unit system (ft, lbf, lb in US customary)
        Headline(
            formats.label("Blow-by 5-95 %", "distance"),
            f"{formats.shown(s['blow_by_p05_m'], 'distance')} – "
            f"{formats.shown(s['blow_by_p95_m'], 'distance')}",
        ),
        Headline(
            formats.label("Tension 5-95 %", "force"),
            f"{formats.shown(s['tension_p05_N'], 'force')} – "
            f"{formats.shown(s['tension_p95_N'], 'force')}",
        ),
        Headline(
            formats.label("Free lift 5-95 %", "mass"),
            f"{lift.show(s['free_lift_p05_kg']):.2f} – {lift.show(s['free_lift_p95_kg']):.2f}",
        ),
        Headline("P(all limits met)", f"{100 * s['probability_feasible']:.0f} %"),
    ])
    st.plotly_chart(bands_figure(mc, rep), key="mc_bands")
    # static tables, full width, cells that wrap: every column in sight at 1024 px
    probabilities = pd.DataFrame(
        [{"Constraint": BY_NAME[k].label, "P(met)": v} for k, v in s["probability_met"].items()]
    )
    st.table(probabilities.style.format({"P(met)": "{:.1%}"}), hide_index=True)
    st.table(_text_frame(pd.DataFrame(mc["specs"])), hide_index=True)
    st.markdown("**Rule sets, same mission** (each sized under its own limits, 2000 samples)")
    rows = cached_rules_spread(inputs_json, run["seed"])
    spread = pd.DataFrame(rows).set_index("rules").T  # one column per rule set: it fits
    st.table(_text_frame(spread.rename_axis("Quantity").reset_index()), hide_index=True)


def _text_frame(df: pd.DataFrame) -> pd.DataFrame:
    """Numbers at 4 significant digits as text, so a static table's cells can wrap."""

    def cell(v: Any) -> Any:
        if isinstance(v, (bool, np.bool_)):
            return formats.yes_no(v)  # never True/False
        if isinstance(v, (float, np.floating)):
            return f"{v:.4g}" if np.isfinite(v) else "not computed: no finite sample"
        return v

    return df.map(cell)


def limits_frame(env: Envelope, payload_index: int = 0) -> pd.DataFrame:
    """The envelope's altitude -> highest flyable wind table as text: a wind where there is one,
    else why there is none in words (never "nan": :meth:`Envelope.limit_wind` is NaN where the
    lowest wind of the grid already breaks a limit).

    The wind column is "Flyable up to [m/s]"; the grid's top wind reads "≥ top" when every
    wind of the grid is flyable (the limit lies beyond the map).
    """
    lw = env.limit_wind()[payload_index]
    names = env.binding_names()[payload_index]
    fly = env.flyable[payload_index]
    top = float(env.wind[-1])
    wind, height = formats.display("wind"), formats.display("distance")  # the chosen units
    cells = []
    for ia, w in enumerate(lw):
        if np.isfinite(w):
            at_top = bool(fly[ia].all())
            cells.append(
                f"≥ {wind.show(top):.1f} (top of the map)" if at_top else f"{wind.show(w):.1f}"
            )
        else:
            broken = BY_NAME[str(names[ia, 0])].label.lower()
            cells.append(
                f"not flyable: {broken} broken at {wind.show(float(env.wind[0])):.3g} "
                f"{wind.unit} already"
            )
    return pd.DataFrame(
        {
            formats.label("Altitude", "distance"): [f"{height.show(h):.0f}" for h in env.altitude],
            formats.label("Flyable up to", "wind"): cells,
        }
    )


def render(inputs_json: str, rep: DesignReport) -> None:
    """The Envelope tab."""
    env = cached_envelope(inputs_json)
    st.plotly_chart(envelope_figure(env), key="envelope_map")
    st.caption(
        f"{env.points} points for the built {formats.shown(env.volume, 'volume', with_unit=True)}"
        " aerostat (tether length "
        "= altitude, length limits scaled with it). Colour: the largest normalised "
        "constraint value g (> 0: a limit is broken); hover for the binding constraint "
        "and its margin."
    )
    st.table(limits_frame(env), hide_index=True)
    st.subheader("Flyable time", anchor=False)
    _flyable(inputs_json)
    st.subheader("Uncertainty", anchor=False)
    _uncertainty(inputs_json, rep)
