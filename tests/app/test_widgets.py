"""Pure parts of the UI layer: form values <-> inputs (app_ui.form_model) and the plot/table
builders (app_ui.plots), without a running app."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import plotly.graph_objects as go
import pytest

from aerostat_core import FABRICS, TETHERS, design, thesis_baseline
from aerostat_core.model.io import inputs_from_dict, inputs_to_dict
from aerostat_core.output.report import (
    case_designs,
    comparison_rows,
    design_report,
    thesis_gui_cases,
)
from app_ui import plots, tables
from app_ui.form_model import (
    CHOICES,
    CUSTOM,
    FIELDS,
    GROUPS,
    LAYOUT,
    WIDGET_KEYS,
    InputError,
    build_inputs,
    widget_for,
    widget_values,
)


@pytest.fixture(scope="module")
def base() -> dict:
    return inputs_to_dict(*thesis_baseline())


@pytest.fixture(scope="module")
def rep() -> dict:
    return design_report(design(*thesis_baseline()))


def test_every_widget_is_laid_out_once():
    laid_out = [k for keys in LAYOUT.values() for k in keys]
    assert sorted(laid_out) == sorted(WIDGET_KEYS)
    assert set(LAYOUT) == set(GROUPS)
    for f in FIELDS:
        assert "[" in f.label and "]" in f.label, f"no unit in label {f.label!r}"
        assert f.help, f"no help for {f.key}"


def test_round_trip_is_exact(base):
    values = widget_values(base)
    assert inputs_to_dict(*build_inputs(values, base)) == base


@pytest.mark.parametrize("name", list(thesis_gui_cases()))
def test_round_trip_of_the_gui_cases(name):
    inputs = thesis_gui_cases()[name]
    assert inputs_to_dict(*build_inputs(widget_values(inputs), inputs)) == inputs


def test_display_units_convert(base):
    values = widget_values(base)
    assert values["in_fin_pos"] == "68"  # fraction 0.68 -> % of hull length
    assert values["in_hull_gsm"] == "130"  # 0.130 kg/m2 -> g/m2
    assert values["in_tether_mbl"] == "20"  # 20000 N -> kN
    assert values["in_purity"] == "100"
    assert values["in_segments"] == "50"  # an integer shown as an integer
    values["in_fin_pos"] = "70"
    values["in_purity"] = "98"
    req, cfg = build_inputs(values, base)
    assert cfg.fins.position == 0.7
    assert cfg.gas.purity == 0.98


def test_volume_modes(base):
    values = widget_values(base)
    values["in_volume_mode"] = "sized"
    _, cfg = build_inputs(values, base)
    assert cfg.hull.volume is None
    sized = inputs_to_dict(thesis_baseline()[0], cfg)
    again = widget_values(sized, previous=values)
    assert again["in_volume_mode"] == "sized" and again["in_volume"] == "170"
    again["in_volume_mode"] = "given"
    again["in_volume"] = "150"
    assert build_inputs(again, sized)[1].hull.volume == 150.0


def test_fin_count_follows_the_arrangement(base):
    values = widget_values(base)
    values["in_arrangement"] = "inverted-y"
    _, cfg = build_inputs(values, base)
    assert (cfg.fins.arrangement, cfg.fins.count) == ("inverted-y", 3)


def test_materials_catalogue_and_custom(base):
    values = widget_values(base)
    assert values["in_hull_fabric"] in FABRICS and values["in_tether"] in TETHERS
    values["in_hull_fabric"] = "Heavy laminate (300 g/m2)"
    values["in_tether"] = CUSTOM
    values["in_tether_lin"] = 15.0
    values["in_tether_mbl"] = 12.0
    _, cfg = build_inputs(values, base)
    assert cfg.hull_fabric == FABRICS["Heavy laminate (300 g/m2)"]
    assert cfg.tether.linear_density == 0.015 and cfg.tether.breaking_strength == 12000.0
    assert cfg.tether.name.startswith("Custom")
    assert cfg.tether.axial_stiffness == thesis_baseline()[1].tether.axial_stiffness  # carried
    shown = widget_values(inputs_to_dict(thesis_baseline()[0], cfg))
    assert shown["in_tether"] == CUSTOM and shown["in_hull_fabric"] == "Heavy laminate (300 g/m2)"


def test_a_named_custom_fabric_keeps_its_name(base):
    req, cfg = thesis_baseline()
    fabric = replace(cfg.hull_fabric, name="Vectran laminate", areal_density=0.21)
    inputs = inputs_to_dict(req, replace(cfg, hull_fabric=fabric))
    values = widget_values(inputs)
    assert values["in_hull_fabric"] == CUSTOM and values["in_hull_gsm"] == "210"
    assert build_inputs(values, inputs)[1].hull_fabric.name == "Vectran laminate"


def test_optional_fields_accept_empty(base):
    values = widget_values(base)
    assert values["in_gas_price"] == "" and values["in_cdv"] == ""
    values["in_gas_price"] = "20"
    _, cfg = build_inputs(values, base)
    assert cfg.gas_price == 20.0
    values["in_payload"] = "  "
    with pytest.raises(InputError) as err:
        build_inputs(values, base)
    assert err.value.group == "requirement" and err.value.key == "in_payload"
    assert str(err.value) == "Payload mass [kg]: required; enter a value."


def test_fields_not_in_the_form_are_kept(base):
    data = inputs_from_dict(base)
    cfg = replace(data[1], tether_segments=120)
    inputs = inputs_to_dict(data[0], replace(cfg, aero=replace(cfg.aero, cutoff="tail")))
    _, out = build_inputs(widget_values(inputs), inputs)
    assert out.tether_segments == 120 and out.aero.cutoff == "tail"


@pytest.mark.parametrize(
    "owner, field, key, group",
    [
        ("Requirement", "payload_mass", "in_payload", "requirement"),
        ("Requirement", "altitude", "in_altitude", "requirement"),
        ("Requirement", "design_wind", "in_design_wind", "wind"),
        ("Requirement", "rules", "in_rules", "requirement"),
        ("LiftingGas", "purity", "in_purity", "gas"),
        ("Configuration", "gas_price", "in_gas_price", "gas"),
        ("Fabric", "areal_density", "in_hull_gsm", "materials"),
        ("TetherSpec", "diameter", "in_tether_dia", "materials"),
        ("TetherSpec", "axial_stiffness", None, "materials"),  # not in the form: its siblings'
        ("HullSpec", "fineness_ratio", "in_fineness", "configuration"),
        ("FinSpec", "position", "in_fin_pos", "configuration"),
        ("FinSpec", "count", "in_arrangement", "configuration"),  # set by the arrangement
        ("FinSpec", "taper_ratio", "in_fin_taper", "advanced"),
        ("AeroModel", "fin_efficiency", "in_eta_f", "advanced"),
        ("ConfluenceSpec", "drop_ratio", "in_drop", "advanced"),
        ("MissionSpec", "winch_speed", None, "general"),  # the Mission tab's input
        ("Nothing", "known", None, "general"),
    ],
)
def test_an_engine_error_maps_to_its_widget_by_owner_and_field(owner, field, key, group):
    assert widget_for(owner, field) == (key, group)


def test_a_fabric_error_goes_to_the_fabric_whose_box_holds_the_value(base):
    values = widget_values(base)
    values["in_fin_fabric"] = CUSTOM
    values["in_fin_gsm"] = "5000"  # 5 kg/m2, beyond the 2 kg/m2 limit
    with pytest.raises(InputError) as err:
        build_inputs(values, base)
    assert err.value.key == "in_fin_gsm" and err.value.group == "materials"
    assert str(err.value).startswith("Fin fabric areal density [g/m²]: 5000 is not allowed")


def test_every_form_label_unit_scale_and_help_comes_from_the_registry():
    from aerostat_core.model.input_paths import spec_for_path

    for f in FIELDS:
        entry = spec_for_path(f.path)
        assert f.label.startswith(f"{entry.label} [{entry.spec.shown_unit}]")
        assert f.scale == entry.spec.scale and f.help.startswith(entry.spec.help)
    for c in CHOICES.values():
        assert (c.label, c.help) == (spec_for_path(c.path).label, spec_for_path(c.path).spec.help)


def test_no_label_string_of_the_registry_is_typed_again_in_the_ui():
    """The facts live in aerostat_core: no room of app_ui and no page has a copy of a registry
    label, neither of the design inputs nor of the dynamics model's inputs."""
    import dataclasses
    from pathlib import Path

    from aerostat_core.base.fields import field_spec
    from aerostat_core.dynamics.options import SolverOptions
    from aerostat_core.dynamics.tether import TetherModel
    from aerostat_core.dynamics.wind import DrydenTurbulence, Gust, MeanProfile
    from aerostat_core.model.input_paths import all_specs

    ui = {p.name: p.read_text() for p in [*Path("app_ui").glob("*.py"), *Path("pages").glob("*.py")]}
    labels = {e.label for e in all_specs() if len(e.label) > 12}
    for cls in (Gust, MeanProfile, DrydenTurbulence, TetherModel, SolverOptions):
        for f in dataclasses.fields(cls):
            if "field_spec" in f.metadata or f.metadata:
                try:
                    label = field_spec(cls, f.name).label
                except (KeyError, LookupError, ValueError):
                    continue
                if len(label) > 12:
                    labels.add(label)
    copies = [(lab, n) for lab in labels for n, src in ui.items() if f'"{lab}' in src]
    assert copies == [], copies


# --- plots and tables --------------------------------------------------------------------------


def test_every_figure_is_valid_plotly(rep):
    figs = [
        plots.hull_3d_figure(rep),
        plots.side_view_figure(rep),
        plots.tension_figure(rep),
        plots.cm_figure(rep),
        plots.tether_figure(rep),
    ]
    figs += [plots.performance_figure(rep, k) for k in plots.PERF_QUANTITIES]
    for fig in figs:
        assert isinstance(fig, go.Figure)
        fig.to_json()  # serialises
        title = fig.layout.title.text
        assert title
        for axis in (fig.layout.xaxis, fig.layout.yaxis):
            if axis.title.text:
                assert "[" in axis.title.text, f"{title}: axis without unit {axis.title.text!r}"


def test_tether_figure_is_to_scale_and_marks_winch_and_aerostat(rep):
    fig = plots.tether_figure(rep, [5.0, 10.0])
    assert fig.layout.yaxis.scaleanchor == "x"
    names = [t.name for t in fig.data]
    assert names[:2] == ["5 m/s", "10 m/s"]
    assert "winch" in names and "aerostat (confluence point)" in names
    tops = next(t for t in fig.data if t.name == "aerostat (confluence point)")
    np.testing.assert_allclose(tops.x, rep.perf.blow_by[[5, 10]], rtol=1e-6)


def test_limit_markers_only_on_limited_rows():
    req, cfg = thesis_baseline()
    r = design_report(design(replace(req, min_tether_safety_factor=15.0), cfg))
    fig = plots.performance_figure(r, "blow_by")
    marks = next(t for t in fig.data if t.name == plots.LIMIT_TRACE)
    np.testing.assert_allclose(marks.x, r.perf.wind_speed[r.perf.limited])
    clean = plots.performance_figure(
        design_report(design(replace(req, blow_by_limit=100.0), cfg)), "alpha_eq"
    )
    assert plots.LIMIT_TRACE not in [t.name for t in clean.data]


def test_default_tether_speeds():
    assert plots.default_tether_speeds(list(range(21))) == [4.0, 8.0, 12.0, 16.0, 20.0]
    assert plots.default_tether_speeds([0.0, 1.0, 2.0]) == [1.0, 2.0]


def test_performance_table_highlights_limited_rows():
    req, cfg = thesis_baseline()
    r = design_report(design(replace(req, min_tether_safety_factor=15.0), cfg))
    df = plots.performance_frame(r.performance_rows)
    assert "Blow-by [m]" in df and "Safety factor [-]" in df
    assert not (np.signbit(df["Blow-by [m]"]) & (df["Blow-by [m]"] == 0)).any()  # no -0.0
    styles = plots.performance_styler(df)._compute().ctx
    limited = r.perf.limited
    for i, lim in enumerate(limited):
        has = any(
            "fde2e2" in v
            for (row, _c), props in styles.items()
            if row == i
            for v in (f"{k}: {val}" for k, val in props)
        )
        assert has == bool(lim), i


def test_comparison_frame_and_highlight():
    designs = case_designs(thesis_gui_cases())
    rows = comparison_rows(designs)
    names = list(designs)
    df = plots.comparison_frame(rows, names)
    assert list(df.columns) == ["Section", "Quantity", *names, "Differs"]
    only = plots.comparison_frame(rows, names, only_differences=True)
    assert (only["Differs"] == "yes").all() and len(only) < len(df)
    assert set(df["Differs"]) == {"yes", "no"}  # words: a static table showed True/False
    ctx = plots.comparison_styler(only)._compute().ctx
    assert all(any("fff3c4" in val for _k, val in props) for props in ctx.values())


@pytest.mark.parametrize(
    "value, text",
    [
        (372.96, "373"),
        (12.345, "12.35"),
        (10.0, "10"),
        (0.0123, "0.0123"),
        (12000.0, "12,000"),
        (True, "yes"),
        (False, "no"),
        (None, "auto"),
        ("+", "+"),
    ],
)
def test_format_value(value, text):
    assert plots.format_value(value) == text


@pytest.mark.parametrize(
    "typed, expected",
    [("12,5", 12.5), ("12.5", 12.5), (" 12 ", 12.0), ("1e1", 10.0), ("−3", None), (",5", 0.5)],
)
def test_a_decimal_comma_is_a_decimal_point(base, typed, expected):
    values = widget_values(base)
    values["in_payload"] = typed
    if expected is None:  # -3 kg: parsed (unicode minus), then refused by the range
        with pytest.raises(InputError, match="must be more than 0 and at most 10000"):
            build_inputs(values, base)
        return
    req, _ = build_inputs(values, base)
    assert req.payload_mass == expected  # never 125 for "12,5"


@pytest.mark.parametrize("typed", ["1,234.5", "1.234,5", "1,2,3", "12 5", "ten", "nan", "1e999"])
def test_ambiguous_or_bad_numbers_are_refused_with_the_label(base, typed):
    values = widget_values(base)
    values["in_payload"] = typed
    with pytest.raises(InputError) as err:
        build_inputs(values, base)
    assert str(err.value).startswith("Payload mass [kg]: ")
    assert err.value.key == "in_payload"


def test_engine_errors_use_the_form_label_and_display_unit(base):
    values = widget_values(base)
    values["in_fin_pos"] = "30"  # % of hull length; the engine's range is 0.4-0.95
    with pytest.raises(InputError) as err:
        build_inputs(values, base)
    msg = str(err.value)
    assert (
        msg
        == "Fin position Δl_f [% of hull length]: 30 is not allowed; it must be between 40 and 95."
    )
    assert "FinSpec" not in msg and "position =" not in msg


def test_a_range_set_by_another_field_is_shown_in_its_words(base):
    values = widget_values(base)
    values["in_blow_by"] = "400"  # more than the 300 m altitude
    with pytest.raises(InputError) as err:
        build_inputs(values, base)
    assert str(err.value) == (
        "Blow-by limit at the design wind [m] (empty = rule set): 400 is not allowed; it must be "
        "more than 0 and at most 300."
    )
    assert err.value.group == "wind"


def test_a_cross_field_error_names_the_field_in_the_form_words(base):
    values = widget_values(base)
    values["in_design_wind"] = "15"
    values["in_survival_wind"] = "12"  # below the design wind
    with pytest.raises(InputError) as err:
        build_inputs(values, base)
    assert err.value.key == "in_survival_wind" and err.value.group == "wind"
    assert str(err.value) == (
        "Survival wind [m/s] (empty = rule set): 12 is not allowed; it must be between 15 and 60."
    )


def test_the_compute_budget_is_a_form_error(base):
    values = widget_values(base)
    values["in_segments"] = "5000"
    values["in_wind_step"] = "0,1"
    with pytest.raises(InputError) as err:
        build_inputs(values, base)
    assert err.value.group == "advanced" and "Reduce the tether segments" in str(err.value)


def test_every_requirement_field_is_one_table_entry():
    from dataclasses import fields

    from aerostat_core import Requirement
    paths = {f.path for f in FIELDS} | {c.path for c in CHOICES.values()}
    # the mission inputs have their own form on the Mission tab (app_ui.mission_view)
    mission = {"payload_power", "power_via", "endurance_days", "deployment_days"}
    for fld in fields(Requirement):
        if fld.name in mission:
            continue
        assert f"requirement.{fld.name}" in paths, f"Requirement.{fld.name} has no form field"


def test_signed_never_shows_minus_zero():
    from app_ui.text import signed

    assert [signed(v) for v in (-0.04, -0.0, 0.04, -3.0, 2.25)] == [
        "0.0",
        "0.0",
        "0.0",
        "-3.0",
        "+2.2",
    ]


def test_wind_lists_collapse_into_ranges():
    from app_ui.text import speed_ranges

    assert speed_ranges([0, 1, 2, 3, 4, 5, 17, 18, 19, 20], 1.0) == "0–5, 17–20"
    assert speed_ranges([0.0, 0.1, 0.2, 0.3, 5.0], 0.1) == "0–0.3, 5"
    assert speed_ranges([7]) == "7"


def test_tether_speeds_include_the_design_wind():
    req, cfg = thesis_baseline()
    rep = design_report(design(replace(req, wind_step=2.0, design_wind=15.0), cfg))
    assert 15.0 not in [float(v) for v in rep.tether.wind_speed]  # the sweep skips it
    assert 15.0 in plots.tether_speeds(rep.tether)
    assert 15.0 in plots.default_profile_speeds(rep.tether)
    fig = plots.tether_figure(rep, [14.0, 15.0])
    names = [t.name for t in fig.data]
    assert "15 m/s" in names and "14 m/s" in names
    x15 = np.asarray(next(t for t in fig.data if t.name == "15 m/s").x)
    assert np.allclose(x15, rep.tether.design.x)
    assert max(x15) == pytest.approx(rep.summary.blow_by_at_design_wind_m, abs=0.05)


def test_geometry_counts_are_integers_and_volume_matches_the_metric(rep):
    html = tables.geometry_html(tables.geometry_frame(rep.geometry_rows))  # what the page shows
    import re

    assert re.search(r"Number of fins</td>\s*<td[^>]*>4</td>", html)
    assert re.search(r"Hull volume</td>\s*<td[^>]*>170.0</td>", html)  # the metric's precision
    # ratios at the formatting table's 2 decimals, lengths at the metrics' 2 (app_ui.formats)
    assert re.search(r"Fineness ratio l/d</td>\s*<td[^>]*>4.00</td>", html)
    assert re.search(r"Hull length l</td>\s*<td[^>]*>17.32</td>", html)


def test_secondary_axes_have_round_ticks(rep):
    fig = plots.tension_figure(rep)
    assert fig.layout.yaxis2.tickmode == "auto"  # not synced to the primary grid
