"""Figures of the Sensitivity and Optimise pages: sweeps, the two-variable map, convergence, the
Pareto front and baseline versus optimum (plotly; no Streamlit). Look from :mod:`app_ui.theme`,
hover decimals from :mod:`app_ui.formats`, the fin position in % of the hull length.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import plotly.graph_objects as go
from plotly.subplots import make_subplots

from aerostat_core.optimize import (
    OBJECTIVES,
    PERFORMANCE_CURVES,
    VARIABLE_INFO,
    VARIABLES,
    OptimizationResult,
    ParetoFront,
)
from aerostat_core.studies.sensitivity import OUTPUTS, SensitivityMap, SensitivityResult

from . import formats
from .optimize_form import shown, unit, var_label
from .theme import ACCENT, LEGEND_RIGHT, LIMIT_COLOUR, MARGIN, NEUTRAL, PALETTE, base_layout

#: Quantity (:mod:`app_ui.formats`) of each sweep output, objective and performance curve.
_KIND = {"alpha": "alpha_eq", "tension_top": "tension"}
_VAR = {"fineness_ratio": "fineness_ratio", "area_change": "percent", "position": "percent"}


def _d3(key: str) -> str:
    """d3 hover format of an output or curve key."""
    return formats.d3(_KIND.get(key, key))


def _layout(fig: go.Figure, title: str, **kw: Any) -> go.Figure:
    """Common layout of the page's figures; the legend right of the plot (below it, it sat on
    the x-axis title)."""
    fig.update_layout(**base_layout(title, margin={**MARGIN, "t": 60}, legend=LEGEND_RIGHT, **kw))
    return formats.figure_in_system(fig)  # drawn in SI, shown in the session's unit system


def sensitivity_figure(res: SensitivityResult) -> go.Figure:
    """One-factor-at-a-time sweeps: outputs (rows) versus each variable (columns); points that
    break a constraint are red crosses; the dotted line marks the baseline."""
    outs = list(OUTPUTS)
    fig = make_subplots(
        rows=len(outs),
        cols=len(VARIABLES),
        shared_xaxes="columns",
        vertical_spacing=0.035,
        horizontal_spacing=0.07,
        column_titles=[var_label(n) for n in VARIABLES],
    )
    for c, name in enumerate(VARIABLES, start=1):
        sw = res.sweeps[name]
        feas = sw.designs.feasible
        for r, key in enumerate(outs, start=1):
            y = sw.output(key)
            fig.add_trace(
                go.Scatter(
                    x=shown(name, sw.values).tolist(),
                    y=y.tolist(),
                    mode="lines+markers",
                    name=f"{key} vs {name}",
                    line=dict(color=ACCENT),
                    marker=dict(size=5),
                    showlegend=False,
                    hovertemplate=f"{var_label(name)} %{{x:{formats.d3(_VAR[name])}}}<br>"
                    f"{OUTPUTS[key][0]} %{{y:{_d3(key)}}} {unit(OUTPUTS[key][1])}"
                    "<extra></extra>",
                ),
                row=r,
                col=c,
            )
            if (~feas).any():
                fig.add_trace(
                    go.Scatter(
                        x=shown(name, sw.values[~feas]).tolist(),
                        y=y[~feas].tolist(),
                        mode="markers",
                        name="constraint violated",
                        legendgroup="viol",
                        showlegend=(r == c == 1),
                        marker=dict(symbol="x", size=9, color=LIMIT_COLOUR),
                        text=[
                            sw.designs.violations(i)[0] if sw.designs.violations(i) else ""
                            for i in np.nonzero(~feas)[0]
                        ],
                        hovertemplate=f"%{{x:{formats.d3(_VAR[name])}}}: %{{text}}<extra></extra>",
                    ),
                    row=r,
                    col=c,
                )
            fig.add_vline(
                x=shown(name, res.baseline[name]),
                line=dict(color=NEUTRAL, dash="dot", width=1),
                row=r,
                col=c,
            )
            if c == 1:
                fig.update_yaxes(
                    title_text=f"{OUTPUTS[key][0].split(' at ')[0]} [{unit(OUTPUTS[key][1])}]",
                    row=r,
                    col=c,
                )
            if r == len(outs):
                fig.update_xaxes(title_text=var_label(name), row=r, col=c)
    mode = (
        "hull re-sized at every point"
        if res.resize
        else f"hull held at {formats.text(res.volume_held, 'volume')} m³"
    )
    fig = _layout(
        fig,
        f"One factor at a time around the baseline ({mode}; outputs at {res.design_wind:g} m/s)",
        height=1000,
    )
    fig.update_layout(
        legend=dict(orientation="h", y=1.06, x=1.0, xanchor="right"), margin=dict(t=110)
    )
    return fig


#: Legend of the two-variable map: one row above the plot area, left-aligned (clear of the
#: colour bar and its title on the right).
MAP_LEGEND = dict(orientation="h", x=0.0, xanchor="left", y=1.02, yanchor="bottom")


def map_figure(m: SensitivityMap) -> go.Figure:
    """Total mass over two variables, with the blow-by-limit contour (held volume) or the
    infeasible points (re-sized), and the baseline."""
    fig = go.Figure()
    fig.add_trace(
        go.Contour(
            x=shown(m.x_variable, m.x).tolist(),
            y=shown(m.y_variable, m.y).tolist(),
            z=m.total_mass.tolist(),
            name="total mass",
            colorscale="Blues",
            contours=dict(showlabels=True, labelfont=dict(size=10)),
            colorbar=dict(title=dict(text="Total mass [kg]")),
            hovertemplate=f"%{{x:{formats.d3(_VAR[m.x_variable])}}}, "
            f"%{{y:{formats.d3(_VAR[m.y_variable])}}}: %{{z:{_d3('total_mass')}}} kg"
            "<extra></extra>",
        )
    )
    if not m.resize:
        fig.add_trace(
            go.Contour(
                x=shown(m.x_variable, m.x).tolist(),
                y=shown(m.y_variable, m.y).tolist(),
                z=m.blow_by.tolist(),
                name=f"blow-by = limit {m.blow_by_limit:g} m",
                showscale=False,
                contours=dict(
                    type="constraint", operation="=", value=m.blow_by_limit, showlabels=False
                ),
                line=dict(color=LIMIT_COLOUR, width=3),
                showlegend=True,
                hovertemplate=f"blow-by %{{z:{_d3('blow_by')}}} m<extra></extra>",
            )
        )
    bad = ~m.feasible
    if bad.any():
        X, Y = np.meshgrid(shown(m.x_variable, m.x), shown(m.y_variable, m.y))
        fig.add_trace(
            go.Scatter(
                x=X[bad].tolist(),
                y=Y[bad].tolist(),
                mode="markers",
                name="constraint violated",
                marker=dict(symbol="x", size=5, color=LIMIT_COLOUR, opacity=0.45),
            )
        )
    fig.add_trace(
        go.Scatter(
            x=[shown(m.x_variable, m.baseline[m.x_variable])],
            y=[shown(m.y_variable, m.baseline[m.y_variable])],
            mode="markers",
            name="baseline",
            marker=dict(symbol="diamond", size=12, color="#000000"),
        )
    )
    fig.update_xaxes(title_text=var_label(m.x_variable))
    fig.update_yaxes(title_text=var_label(m.y_variable))
    mode = (
        "hull re-sized at every point"
        if m.resize
        else f"hull held at {formats.text(m.volume_held, 'volume')} m³"
    )
    fig = _layout(
        fig,
        f"Total mass over {VARIABLE_INFO[m.x_variable][0]} × "
        f"{VARIABLE_INFO[m.y_variable][0]} ({mode})",
        height=560,
    )
    # the legend above the plot, the colour bar alone on the right: both on the right, the
    # legend sat on the colour bar's title
    fig.update_layout(legend=MAP_LEGEND, margin_t=fig.layout.margin.t + 25)
    return fig


def convergence_figure(results: Sequence[OptimizationResult]) -> go.Figure:
    """Best feasible objective versus evaluations, one line per solver."""
    fig = go.Figure()
    name = label = None
    for i, r in enumerate(results):
        h = r.history
        name = r.objective_name
        fig.add_trace(
            go.Scatter(
                x=h.evaluations.tolist(),
                y=h.best.tolist(),
                mode="lines",
                line=dict(shape="hv", color=PALETTE[i % len(PALETTE)], width=2),
                name=r.label,
                hovertemplate=f"%{{x}} designs: %{{y:{_d3(name)}}} "
                f"{unit(OBJECTIVES[name][1])}<extra>%{{fullData.name}}</extra>",
            )
        )
    if name is not None:
        lab, u = OBJECTIVES[name]
        label = f"Best feasible {lab.lower()} [{unit(u)}]"
    fig.update_xaxes(title_text="Designs evaluated (each with its nested sizing)", type="log")
    fig.update_yaxes(title_text=label or "Best objective")
    return _layout(fig, "Convergence", height=420)


def pareto_figure(
    front: ParetoFront,
    results: Sequence[OptimizationResult],
    limit: float,
    baseline: Mapping[str, float] | None = None,
) -> go.Figure:
    """Objective versus blow-by: the front, infeasible limits, each solver's optimum, baseline;
    gas cost on the right axis."""
    lab, u = OBJECTIVES[front.objective_name]
    fig = make_subplots(specs=[[{"secondary_y": True}]])
    on = front.nondominated
    order = np.argsort(front.blow_by[on])
    fig.add_trace(
        go.Scatter(
            x=front.blow_by[on][order].tolist(),
            y=front.objective[on][order].tolist(),
            mode="lines+markers",
            name=f"Pareto front ({lab.lower()})",
            line=dict(color=ACCENT, width=2),
            marker=dict(size=7),
            customdata=np.column_stack(
                [
                    front.volume[on][order],
                    front.fineness_ratio[on][order],
                    front.area_change[on][order],
                    shown("position", front.position[on][order]),
                ]
            ).tolist(),
            hovertemplate=f"blow-by %{{x:{_d3('blow_by')}}} m: "
            f"%{{y:{_d3(front.objective_name)}}} {unit(u)}<br>"
            f"V %{{customdata[0]:{_d3('volume')}}} m³, "
            f"f %{{customdata[1]:{_d3('fineness_ratio')}}}, "
            f"ΔS_f %{{customdata[2]:{_d3('area_change')}}} %, "
            f"Δl_f %{{customdata[3]:{_d3('position')}}} % of l<extra></extra>",
        ),
        secondary_y=False,
    )
    fig.add_trace(
        go.Scatter(
            x=front.blow_by[on][order].tolist(),
            y=front.gas_cost[on][order].tolist(),
            mode="lines",
            name="gas fill cost (right axis)",
            line=dict(color=PALETTE[1], dash="dash"),
            hovertemplate=f"blow-by %{{x:{_d3('blow_by')}}} m: USD %{{y:,{_d3('gas_cost')}}}"
            "<extra></extra>",
        ),
        secondary_y=True,
    )
    bad = ~front.feasible
    if bad.any():
        fig.add_trace(
            go.Scatter(
                x=front.limits[bad].tolist(),
                y=front.objective[bad].tolist(),
                mode="markers",
                name="limit not achievable",
                marker=dict(symbol="x", size=10, color=LIMIT_COLOUR),
                text=[front.reason[i] for i in np.nonzero(bad)[0]],
                hovertemplate=f"limit %{{x:{_d3('blow_by')}}} m: %{{text}}<extra></extra>",
            ),
            secondary_y=False,
        )
    for i, r in enumerate(results):
        if r.feasible:
            fig.add_trace(
                go.Scatter(
                    x=[r.design["blow_by_m"]],
                    y=[r.objective],
                    mode="markers",
                    name=f"{r.label} optimum",
                    marker=dict(
                        symbol="star",
                        size=14,
                        color=PALETTE[(i + 2) % len(PALETTE)],
                        line=dict(width=1, color="#000000"),
                    ),
                ),
                secondary_y=False,
            )
    if baseline is not None:
        fig.add_trace(
            go.Scatter(
                x=[baseline["blow_by"]],
                y=[baseline["objective"]],
                mode="markers",
                name="baseline (as given)",
                marker=dict(symbol="diamond", size=12, color="#000000"),
            ),
            secondary_y=False,
        )
    fig.add_vline(
        x=limit,
        line=dict(color=LIMIT_COLOUR, dash="dash", width=1.5),
        annotation_text=f"limit {limit:g} m",
        annotation_position="top",
    )
    fig.update_xaxes(title_text="Blow-by at the design wind [m]")
    fig.update_yaxes(title_text=f"{lab} [{unit(u)}]", secondary_y=False)
    # tickmode "auto": plotly.js syncs an overlaying axis to the primary grid by default, which
    # gave ticks such as 5.12 / 10.23 / 15.35.
    fig.update_yaxes(
        title_text="Gas fill cost [USD]", secondary_y=True, showgrid=False, tickmode="auto"
    )
    return _layout(fig, f"Trade-off: least {lab.lower()} for each blow-by limit", height=500)


def performance_figure(base: Mapping[str, Any], opt: Mapping[str, Any]) -> go.Figure:
    """Baseline versus optimum: blow-by, angle, dynamic lift and tension versus wind (2 x 2)."""
    keys = list(PERFORMANCE_CURVES)
    fig = make_subplots(
        rows=2,
        cols=2,
        subplot_titles=[PERFORMANCE_CURVES[k][0] for k in keys],
        horizontal_spacing=0.1,
        vertical_spacing=0.16,
    )
    for j, k in enumerate(keys):
        r, c = j // 2 + 1, j % 2 + 1
        for name, d, colour, dash in (
            ("baseline", base, NEUTRAL, "dash"),
            ("optimum", opt, ACCENT, "solid"),
        ):
            fig.add_trace(
                go.Scatter(
                    x=np.asarray(d["wind_speed"]).tolist(),
                    y=np.asarray(d[k]).tolist(),
                    mode="lines+markers",
                    name=name,
                    legendgroup=name,
                    showlegend=(j == 0),
                    line=dict(color=colour, dash=dash),
                    marker=dict(size=4),
                    hovertemplate=f"%{{x:{_d3('wind')}}} m/s: %{{y:{_d3(k)}}} "
                    f"{unit(PERFORMANCE_CURVES[k][1])}<extra>{name}</extra>",
                ),
                row=r,
                col=c,
            )
        fig.update_yaxes(title_text=f"[{unit(PERFORMANCE_CURVES[k][1])}]", row=r, col=c)
        fig.update_xaxes(title_text="Wind speed [m/s]", row=r, col=c)
    return _layout(fig, "Baseline versus optimum performance (thesis Figs 4.17-4.22)", height=640)
