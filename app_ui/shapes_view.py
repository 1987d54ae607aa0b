"""Shapes page and shape widgets: cached engine calls, frames and figures (no physics here).

Everything numeric comes from :mod:`aerostat_core.geometry.shapes`, :mod:`aerostat_core.studies.shape_comparison`,
:mod:`aerostat_core.studies.shape_optimize` and :mod:`aerostat_core.output.export`; this module only caches
(:func:`app_ui.cache.memo`, keyed by the frozen inputs and the study's parameters, one
:class:`~typing.NamedTuple` per study (:class:`ShapeStudyKey` ...), so every compute reads its key
by field name; shared by every session, read-only), tabulates and plots.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, NamedTuple

import numpy as np
import pandas as pd
import plotly.graph_objects as go
import streamlit as st

from aerostat_core import Configuration, Requirement
from aerostat_core.geometry.shapes import SHAPE_INFO, profile_radius_ratio
from aerostat_core.model.input_paths import column_label
from aerostat_core.output.export import design_stl, gore_csv, gore_dxf, gore_pattern, gore_svg
from aerostat_core.studies.shape_comparison import (
    TABLE_SHAPES,
    THESIS_SHAPE_PRESET,  # noqa: F401 - re-exported for pages/7_Shapes.py
    comparison_notes,
    full_model_shape_comparison,
    shape_dimensions_rows,
    table_2_2_rows,
    thesis_reference_rows,
    thesis_shape_comparison,
)
from aerostat_core.studies.shape_optimize import fineness_sweeps, optimize_shapes

from . import cache, entry, formats
from .theme import PALETTE, base_layout
from .widgets import plain

_COLOURS = {k: PALETTE[i] for i, k in enumerate(TABLE_SHAPES)}
WIND_AXIS = "Wind speed at the aerostat [m/s]"


# --- the study keys (one per cache kind; each is a tuple, hashable and equal by value) ----------
class LibraryKey(NamedTuple):
    """Key of the shape library table ("shape_library")."""

    volume: float  # hull volume every shape is sized to, at its standard l/d [m3]


class ShapeStudyKey(NamedTuple):
    """Key of the per-shape optima ("shape_study")."""

    requirement: Requirement  # resolved (:func:`app_ui.cache.frozen_inputs`)
    configuration: Configuration
    objective: str  # the quantity minimised for every shape


class SweepsKey(NamedTuple):
    """Key of the fineness-ratio sweep of every shape ("shape_sweeps")."""

    requirement: Requirement  # resolved
    configuration: Configuration
    n_points: int  # l/d points per shape


class ExportKey(NamedTuple):
    """Key of the geometry export files ("exports")."""

    requirement: Requirement  # resolved
    configuration: Configuration
    n_gores: int  # identical gores the hull is cut from
    seam_mm: float  # seam allowance outside every pattern [mm]


# --- cached engine calls -----------------------------------------------------------------------
def cached_comparisons() -> dict[str, Any]:
    """Thesis-preset and full-model comparisons, their rows and the notes (plain data)."""

    def compute() -> dict[str, Any]:
        t, f = thesis_shape_comparison(), full_model_shape_comparison()
        return {
            "thesis": {
                "rows": table_2_2_rows(t),
                "wind": t.wind.tolist(),
                "blow_by": {k: v.tolist() for k, v in t.blow_by.items()},
            },
            "full": {
                "rows": table_2_2_rows(f),
                "wind": f.wind.tolist(),
                "blow_by": {k: v.tolist() for k, v in f.blow_by.items()},
            },
            "reference": thesis_reference_rows(),
            "notes": comparison_notes(t, f),
        }

    return cache.memo("shape_comparisons", (), compute, 4)


def cached_library(volume: float = 100.0) -> list[dict]:
    """:func:`aerostat_core.studies.shape_comparison.shape_dimensions_rows` at ``volume`` [m3]."""
    key = LibraryKey(volume=float(volume))
    return cache.memo("shape_library", key, lambda: shape_dimensions_rows(key.volume), 4)


def cached_shape_study(inputs_json: str, objective: str) -> list[dict]:
    """Rows of :func:`aerostat_core.studies.shape_optimize.optimize_shapes` (SLSQP, quick) for the
    inputs."""
    req_k, cfg_k = cache.inputs_of(inputs_json)
    key = ShapeStudyKey(requirement=req_k, configuration=cfg_k, objective=str(objective))
    return cache.memo(
        "shape_study",
        key,
        lambda: optimize_shapes(key.requirement, key.configuration, objective=key.objective).rows(),
        32,
    )


def cached_sweeps(inputs_json: str, n_points: int = 15) -> dict[str, dict[str, list]]:
    """:func:`aerostat_core.studies.shape_optimize.fineness_sweeps` as plain lists."""
    req_k, cfg_k = cache.inputs_of(inputs_json)
    key = SweepsKey(requirement=req_k, configuration=cfg_k, n_points=int(n_points))

    def compute() -> dict[str, dict[str, list]]:
        out = {}
        sweeps = fineness_sweeps(key.requirement, key.configuration, n_points=key.n_points)
        for s, sw in sweeps.items():
            out[s] = {
                "f": sw.fineness_ratio.tolist(),
                "mass": sw.total_mass.tolist(),
                "volume": sw.volume.tolist(),
                "feasible": sw.feasible.tolist(),
            }
        return out

    return cache.memo("shape_sweeps", key, compute, 32)


def cached_exports(inputs_json: str, n_gores: int, seam_mm: float) -> dict[str, bytes]:
    """STL, DXF, SVG and CSV bytes of the design of the inputs."""
    req_k, cfg_k = cache.inputs_of(inputs_json)
    key = ExportKey(
        requirement=req_k, configuration=cfg_k, n_gores=int(n_gores), seam_mm=float(seam_mm)
    )

    def compute() -> dict[str, bytes]:
        d = cache.design_of(key.requirement, key.configuration)  # the design the page made
        p = gore_pattern(d, n_gores=key.n_gores, seam_allowance=key.seam_mm / 1000.0)
        return {
            "stl": design_stl(d),
            "dxf": gore_dxf(p),
            "svg": gore_svg(p),
            "csv": gore_csv(p).encode("utf-8"),
            "area": f"{p.pattern_area:.2f} m² of gores for {p.hull_area:.2f} m² of hull",
        }

    return cache.memo("exports", key, compute, 16)


# --- frames ----------------------------------------------------------------------------------
def table_frame(rows: list[dict]) -> pd.DataFrame:
    """Table 2.2 layout: parameter rows, one column per shape."""
    return pd.DataFrame(rows).set_index("parameter")


def versus_frame(ours: list[dict], ref: list[dict]) -> pd.DataFrame:
    """Our preset values next to the thesis' printed values, per shape."""
    o = table_frame(ours)
    r = table_frame(ref)
    cols = {}
    for c in r.columns:
        cols[(c, "thesis")] = r[c]
        cols[(c, "this model")] = o[c].reindex(r.index)
    return pd.DataFrame(cols)


def library_frame(rows: list[dict]) -> pd.DataFrame:
    """The shape library at one volume, display column names with units, in the chosen unit
    system ("Length [ft]" in US customary)."""
    names = {
        "label": "Shape",
        "fineness_ratio": "l/d [-]",
        "valid_fineness": "valid l/d",
        "length_m": "Length [m]",
        "diameter_m": "Diameter [m]",
        "prismatic_coefficient": "C_p [-]",
        "surface_area_m2": "Area [m²]",
        "area_coefficient": "Area / V^(2/3) [-]",
        "centre_of_volume_over_l": "CV / l [-]",
        "k1": "k1 [-]",
        "k2": "k2 [-]",
        "k_rot": "k' [-]",
        "source": "Source",
    }
    return formats.frame_in_system(pd.DataFrame(rows)[list(names)].rename(columns=names))[0]


def static_frame(df: pd.DataFrame, transpose: bool = False) -> pd.DataFrame:
    """``df`` as text for a static table whose cells wrap (numbers at 4 significant digits,
    as the other comparison tables), optionally with rows and columns swapped so that a table
    of many quantities for a few shapes fits a 1024 px window."""
    from .tables import format_value

    out = df.T if transpose else df
    return out.map(lambda v: v if isinstance(v, str) else format_value(v))


def study_frame(rows: list[dict], objective: str) -> pd.DataFrame:
    """Per-shape optima table."""
    names = {
        "label": "Shape",
        "best": "Best",
        "feasible": "Feasible",
        objective: objective,
        "fineness_ratio": "l/d [-]",
        "area_change_pct": "ΔS_f [%]",
        "position": "Δl_f [% of l]",  # % of the hull length, as on every page
        "volume_m3": "Volume [m³]",
        "total_mass_kg": "Total mass [kg]",
        "blow_by_m": "Blow-by [m]",
        "method": "Method",
        "message": "Note",
    }
    df = pd.DataFrame(rows)
    if "position" in df:  # the engine's fraction of the hull length -> %
        df["position"] = pd.to_numeric(df["position"], errors="coerce") * 100.0
    return df[[k for k in names if k in df.columns]].rename(columns=names)


#: Numeric columns of the per-shape optima -> quantity kind (app_ui.formats).
STUDY_KINDS = {
    "l/d [-]": "fineness_ratio",
    "ΔS_f [%]": "area_change",
    "Δl_f [% of l]": "position",
    "Volume [m³]": "volume",
    "Total mass [kg]": "total_mass",
    "Blow-by [m]": "blow_by",
}


def study_styler(df: pd.DataFrame):
    """The per-shape optima as a static table (cells wrap), each number at its kind's decimals,
    in the chosen unit system ("Blow-by [ft]" in US customary)."""
    df, names = formats.frame_in_system(df)
    fmt = {names[c]: formats.formatter(k) for c, k in STUDY_KINDS.items() if c in names}
    return df.style.format(fmt, na_rep="–")


# --- figures ---------------------------------------------------------------------------------
def blow_by_figure(cmp: Mapping[str, Any], title: str) -> go.Figure:
    """Blow-by versus wind for the three Table 2.2 hulls (Figure 2.5)."""
    traces = [
        dict(
            type="scatter",
            mode="lines",
            x=cmp["wind"],
            y=cmp["blow_by"][k],
            name=TABLE_SHAPES[k][0],
            line=dict(color=_COLOURS[k], width=2.5),
        )
        for k in TABLE_SHAPES
    ]
    return go.Figure(  # drawn in SI, shown in the session's unit system
        formats.figure_dict_in_system(dict(
            data=traces,
            layout=base_layout(
                title,
                height=420,
                xaxis=dict(title=dict(text=WIND_AXIS), hoverformat=formats.axis_hover(WIND_AXIS)),
                yaxis=dict(
                    title=dict(text="Blow-by [m]"), hoverformat=formats.axis_hover("Blow-by [m]")
                ),
            ),
        ))
    )


def profiles_figure(shapes: list[str] | None = None) -> go.Figure:
    """Dimensionless profiles r/l of every shape at its standard l/d, to scale (Fig. 2.16)."""
    x = 0.5 * (1 - np.cos(np.linspace(0, np.pi, 201)))
    traces = []
    for i, s in enumerate(shapes or list(SHAPE_INFO)):
        info = SHAPE_INFO[s]
        r = profile_radius_ratio(s, x) / info.default_fineness
        xs = np.concatenate([x, x[::-1]])
        ys = np.concatenate([r, -r[::-1]])
        traces.append(
            dict(
                type="scatter",
                mode="lines",
                x=xs.tolist(),
                y=ys.tolist(),
                name=f"{info.label} (l/d {info.default_fineness:g})",
                line=dict(color=PALETTE[i % len(PALETTE)], width=2),
            )
        )
    return go.Figure(
        dict(
            data=traces,
            layout=base_layout(
                "Hull profiles at their standard fineness ratio (length = 1)",
                height=460,
                xaxis=dict(
                    title=dict(text="Station ξ / l [-]"),
                    hoverformat=formats.axis_hover("Station ξ / l [-]"),
                ),
                yaxis=dict(
                    title=dict(text="Radius r / l [-]"),
                    hoverformat=formats.axis_hover("Radius r / l [-]"),
                    scaleanchor="x",
                    scaleratio=1,
                ),
            ),
        )
    )


def sweeps_figure(sweeps: Mapping[str, Mapping[str, list]]) -> go.Figure:
    """Total mass of the re-sized design versus l/d, one line per shape; infeasible points
    hollow."""
    traces = []
    for i, (s, sw) in enumerate(sweeps.items()):
        colour = PALETTE[i % len(PALETTE)]
        ok = np.asarray(sw["feasible"], bool)
        traces.append(
            dict(
                type="scatter",
                mode="lines+markers",
                x=sw["f"],
                y=sw["mass"],
                name=SHAPE_INFO[s].label,
                line=dict(color=colour),
                marker=dict(symbol=np.where(ok, "circle", "circle-open").tolist(), size=7),
            )
        )
    return go.Figure(  # drawn in SI, shown in the session's unit system
        formats.figure_dict_in_system(dict(
            data=traces,
            layout=base_layout(
                "Sized total mass versus fineness ratio, per shape",
                height=440,
                xaxis=dict(
                    title=dict(text=column_label("configuration.hull.fineness_ratio")),
                    hoverformat=formats.axis_hover(
                        column_label("configuration.hull.fineness_ratio")
                    ),
                ),
                yaxis=dict(
                    title=dict(text="Total mass [kg]"),
                    hoverformat=formats.axis_hover("Total mass [kg]"),
                    type="log",
                ),
            ),
        ))
    )


def geometry_note(shape: str) -> str:
    """One sentence on how to read the geometry of a hull of ``shape`` (Design page)."""
    info = SHAPE_INFO.get(shape, SHAPE_INFO["npl"])
    if shape == "npl":
        text = (
            "The hull is the NPL double ellipsoid (nose semi-axis a1, tail semi-axis a2, "
            "maximum radius b)."
        )
    elif info.streamlined:
        text = (
            f"The hull is the {info.label} profile ({info.source}); a1 is the station of "
            "maximum diameter, b the maximum radius."
        )
    else:
        text = (
            f"The hull is a bluff {info.label.lower()} without fins; its tether force is "
            "taken at the centre of buoyancy, so it trims level."
        )
    if info.kite:
        text += (
            " Kite lift and drag from the Table 2.2 reference (48 kg at 15 m/s for 100 m³); "
            "Helikite limits (thesis Table 2.1): wind ≤ 25 m/s, payload < 30 kg, altitude "
            "about 2 km."
        )
    if not info.streamlined:
        return text
    return text + (
        " The confluence point C sits below the centre of net static lift, so the "
        "hull flies level in calm air."
    )


# --- Streamlit pieces used by other pages ------------------------------------------------------
#: The export buttons: key -> label (the format first, so no two read alike), file, MIME type.
EXPORT_BUTTONS = (
    ("stl", "STL: hull and fins", "aerostat.stl", "model/stl"),
    ("dxf", "DXF: gore patterns", "gores.dxf", "application/dxf"),
    ("svg", "SVG: gore patterns", "gores.svg", "image/svg+xml"),
    ("csv", "CSV: gore half-widths", "gores.csv", "text/csv"),
)


def export_panel(inputs_json: str) -> None:
    """Design page: STL of hull and fins, gore and fin patterns (DXF, SVG, CSV) downloads."""
    c = st.columns([1, 1, 2])
    # Text boxes read like the Design form's ("12,5" is 12.5, never 125).
    n_text = entry.number_box(
        "Gores",
        key="exp_gores",
        value=12,
        integer=True,
        container=c[0],
        help="Number of identical gores the hull is cut from (3-64).",
    )
    seam_text = entry.number_box(
        "Seam allowance [mm]",
        key="exp_seam",
        value=20.0,
        container=c[1],
        help="Added outside the seam line of every pattern (0-200 mm).",
    )
    try:
        n = entry.read(n_text, "Gores", integer=True, lo=3, hi=64)
        seam = entry.read(seam_text, "Seam allowance [mm]", lo=0.0, hi=200.0, unit="mm")
        files = cached_exports(inputs_json, int(n), float(seam))
    except ValueError as exc:
        st.error(plain(f"Cannot export the geometry: {exc}"), icon=":material/error:")
        return
    c[2].caption(
        f"Patterns: {files['area']}. STL in metres, body axes (x aft from the nose, "
        "z up); DXF in metres; SVG in millimetres."
    )
    # a wrapping row of whole buttons, the format first: in four columns the labels were cut to
    # "Gore patterns (..." and the DXF and SVG buttons read the same
    row = st.container(horizontal=True, wrap=True)
    for key, label, name, mime in EXPORT_BUTTONS:
        row.download_button(
            label,
            # a callable: the files (the STL is 2 MB) are sent only when asked for, not with
            # every page view (a fresh browser fetched them all before the first result)
            lambda key=key, n=n, seam=seam: cached_exports(inputs_json, int(n), float(seam))[key],
            file_name=name,
            mime=mime,
            on_click="ignore",
            icon=":material/download:",
            key=f"dl_{key}_export",
        )


def sensitivity_per_shape(inputs_json: str) -> None:
    """Sensitivity page: the l/d sweep of every shape (re-sized), as a figure and a CSV."""
    try:
        sw = cached_sweeps(inputs_json)
    except ValueError as exc:
        st.error(f"Cannot compute the shape sweeps: {exc}", icon=":material/error:")
        return
    st.plotly_chart(sweeps_figure(sw), key="sens_shapes")
    rows = [
        {"shape": s, "fineness_ratio": f, "total_mass_kg": m, "volume_m3": v, "feasible": ok}
        for s, x in sw.items()
        for f, m, v, ok in zip(x["f"], x["mass"], x["volume"], x["feasible"])
    ]
    st.download_button(
        "Shape sweeps (CSV)",
        pd.DataFrame(rows).to_csv(index=False),
        file_name="sensitivity-shapes.csv",
        mime="text/csv",
        on_click="ignore",
        icon=":material/download:",
        key="dl_sens_shapes",
    )
