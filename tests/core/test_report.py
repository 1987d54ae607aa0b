"""aerostat_core.output.report: plain-data views, hull/fin shapes, comparison table, tidy CSV of cases."""

from __future__ import annotations

import csv
import io
import math
from dataclasses import replace

import numpy as np
import pytest

from aerostat_core import design, thesis_baseline
from aerostat_core.geometry.hull import radius
from aerostat_core.model.io import inputs_from_dict, inputs_to_dict
from aerostat_core.model.presets import PRACTICE_FABRIC_AREAL_DENSITY
from aerostat_core.output.report import (
    INPUT_FIELDS,
    case_designs,
    cases_csv,
    cases_rows,
    comparison_rows,
    confluence_lines,
    csv_column,
    design_report,
    fin_outlines,
    flatten_inputs,
    hull_outline,
    hull_surface,
    input_field_info,
    performance_rows,
    tether_profile_rows,
    thesis_gui_cases,
)


@pytest.fixture(scope="module")
def baseline():
    return design(*thesis_baseline())


def test_hull_outline_matches_the_npl_profile():
    a1, a2, b = 7.0, 9.0, 2.0
    xi, r = hull_outline(a1, a2, b, n=81)
    assert xi[0] == 0.0 and xi[-1] == pytest.approx(a1 + a2)
    assert np.all(np.diff(xi) > 0)
    assert r[0] == pytest.approx(0.0, abs=1e-12) and r[-1] == pytest.approx(0.0, abs=1e-12)
    assert r.max() == pytest.approx(b)  # the station of maximum radius is included exactly
    assert xi[np.argmax(r)] == pytest.approx(a1)
    np.testing.assert_allclose(r, radius(xi, a1, a2, b))


def test_hull_surface_is_a_surface_of_revolution():
    a1, a2, b = 5.0, 6.0, 1.5
    x, y, z = hull_surface(a1, a2, b, n_xi=41, n_theta=25)
    assert x.shape == y.shape == z.shape
    _, r = hull_outline(a1, a2, b, n=41)
    np.testing.assert_allclose(np.hypot(y, z), np.broadcast_to(r, y.shape), atol=1e-12)
    # volume of revolution from the grid's profile ~ closed form (2/3) pi b^2 (a1 + a2)
    xi = x[0]
    vol = np.trapezoid(np.pi * r**2, xi)
    assert vol == pytest.approx(2 / 3 * np.pi * b**2 * (a1 + a2), rel=2e-3)


def test_fin_outlines_follow_the_engine_planform(baseline):
    f = baseline.airframe.fins
    outlines = fin_outlines(baseline)
    assert len(outlines) == int(f.count) == 4
    for p in outlines:
        assert p.shape == (5, 3)
        np.testing.assert_allclose(p[0], p[-1])  # closed
        # root chord and tip chord lengths along xi
        assert p[1, 0] - p[0, 0] == pytest.approx(float(f.root_chord))
        assert p[2, 0] - p[3, 0] == pytest.approx(float(f.tip_chord))
        # root leading edge at the engine's station, on the hull surface
        assert p[0, 0] == pytest.approx(float(f.xi_root_le))
        h = baseline.airframe.hull
        r_le = float(radius(p[0, 0], h.a1, h.a2, h.b))
        assert np.hypot(p[0, 1], p[0, 2]) == pytest.approx(r_le)
        # tip is one span further out than the hull radius at mid root chord
        r_mid = float(radius(p[0, 0] + float(f.root_chord) / 2, h.a1, h.a2, h.b))
        assert np.hypot(p[2, 1], p[2, 2]) == pytest.approx(r_mid + float(f.span))
    # the "+" arrangement: one fin up, one down, two horizontal
    tips_z = sorted(round(float(p[2, 2]), 6) for p in outlines)
    assert tips_z[0] < 0 < tips_z[-1]
    assert tips_z[1] == pytest.approx(0.0, abs=1e-9) and tips_z[2] == pytest.approx(0.0, abs=1e-9)


def test_inverted_y_has_three_fins():
    req, cfg = thesis_baseline()
    cfg = replace(cfg, fins=replace(cfg.fins, arrangement="inverted-y", count=3))
    outlines = fin_outlines(design(req, cfg))
    assert len(outlines) == 3
    assert sum(1 for p in outlines if p[2, 2] > 0) == 1  # one fin on top


def test_confluence_lines_join_the_point_to_the_hull_belly(baseline):
    h, af = baseline.airframe.hull, baseline.airframe
    lines = confluence_lines(baseline, n_lines=3)
    assert len(lines) == 3
    for line in lines:
        assert line[0, 0] == pytest.approx(float(af.xi_c))
        assert line[0, 1] == pytest.approx(float(af.z_c))
        x = line[1, 0]
        assert 0 < x < float(h.length)
        assert line[1, 1] == pytest.approx(-float(radius(x, h.a1, h.a2, h.b)))


def test_design_report_holds_the_engine_numbers(baseline):
    rep = design_report(baseline)
    assert rep.summary == baseline.summary()
    assert rep.violations == tuple(baseline.violations)
    assert rep.feasible is bool(baseline.feasible)
    np.testing.assert_allclose(rep.perf.blow_by, baseline.performance.blow_by)
    np.testing.assert_array_equal(rep.perf.limited, baseline.performance.limited)
    assert rep.tether.x.shape == baseline.tether_x.shape
    assert rep.points.c == (
        pytest.approx(float(baseline.airframe.xi_c)),
        pytest.approx(float(baseline.airframe.z_c)),
    )
    assert rep.limits.blow_by_limit == baseline.requirement.blow_by_limit
    assert inputs_from_dict(rep.inputs) == (baseline.requirement, baseline.configuration)
    # the design-wind tether profile ends at the design-point blow-by, starting at the winch
    prof = rep.tether.design
    assert prof.wind == baseline.requirement.design_wind
    top = int(np.argmax(prof.z))
    assert prof.x[top] == pytest.approx(baseline.design_point["blow_by_m"], rel=1e-6)
    assert min(prof.z) == pytest.approx(0.0, abs=1e-9)


def test_performance_rows_flag_the_limited_rows():
    req, cfg = thesis_baseline()
    d = design(replace(req, min_tether_safety_factor=15.0), cfg)  # SF < 15 above 13 m/s
    rows = performance_rows(d)
    lim = [r["limit_exceeded"] for r in rows]
    assert lim == [bool(x) for x in d.performance.limited]
    assert any(lim) and not all(lim)  # high winds break the limit, calm air does not
    assert lim[0] is False and lim[-1] is True
    for r in rows:
        if r["limit_exceeded"]:
            assert "safety factor" in r["flags"]


def test_tether_profile_rows_are_tidy(baseline):
    rep = design_report(baseline)
    rows = tether_profile_rows(rep.tether)
    assert tether_profile_rows(rep.tether.to_dict()) == rows  # a plain dict, as before typing
    n_nodes, n_winds = baseline.tether_x.shape
    assert len(rows) == n_nodes * n_winds
    assert set(rows[0]) == {"wind_speed_m_s", "node", "x_downwind_m", "z_height_m"}
    last = [r for r in rows if r["wind_speed_m_s"] == baseline.requirement.wind_max]
    assert last[0]["x_downwind_m"] == pytest.approx(baseline.performance.blow_by[-1])


def test_flatten_inputs_and_field_info_cover_every_input():
    flat = flatten_inputs(inputs_to_dict(*thesis_baseline()))
    assert "format" not in flat and "version" not in flat
    missing = [p for p in flat if p not in INPUT_FIELDS]
    assert missing == [], f"input fields without a label/unit: {missing}"
    label, unit, scale, token = input_field_info("configuration.hull_fabric.areal_density")
    assert (unit, scale, token) == ("g/m²", 1000.0, "kg_m2")


def test_csv_columns_are_unique_and_carry_units():
    cols = [csv_column(p, input_field_info(p)[3]) for p in INPUT_FIELDS]
    assert len(cols) == len(set(cols))
    assert "payload_mass_kg" in cols and "tether_breaking_strength_N" in cols
    assert "aero_fin_stall_angle_deg" in cols  # no doubled unit


def test_comparison_rows_mark_the_differences():
    cases = thesis_gui_cases()
    designs = case_designs(cases)
    rows = comparison_rows(designs)
    names = list(cases)
    by_q = {r["quantity"]: r for r in rows}
    payload = by_q["Payload mass [kg]"]
    assert [payload[n] for n in names] == [10.0, 30.0, 10.0, 10.0]
    assert payload["differs"] is True
    assert by_q["Fineness ratio l/d [-]"]["differs"] is False
    vol = by_q["Hull volume [m³]"]
    assert [vol[n] for n in names] == pytest.approx([designs[n].volume for n in names])
    assert vol["differs"] is True
    # display units: fabric in g/m2, fin position in % of length
    assert by_q["Hull fabric areal density [g/m²]"][names[0]] == pytest.approx(
        1000 * PRACTICE_FABRIC_AREAL_DENSITY)
    assert by_q["Fin position Δl_f [% of hull length]"][names[0]] == pytest.approx(68.0)
    assert by_q["Hull volume (empty = sized) [m³]"][names[0]] == "auto"
    sections = [r["section"] for r in rows]
    assert sections.index("input") > sections.index("result")


def test_one_case_never_differs():
    designs = case_designs({"only": thesis_gui_cases()["GUI test: payload 10 kg, 300 m"]})
    assert not any(r["differs"] for r in comparison_rows(designs))


def test_thesis_gui_cases_change_the_sized_hull():
    cases = thesis_gui_cases()
    assert len(cases) == 4
    designs = case_designs(cases)
    v = {n: d.volume for n, d in designs.items()}
    assert all(d.sized for d in designs.values())
    assert v["GUI test: payload 30 kg, 300 m"] > v["GUI test: payload 10 kg, 300 m"]
    assert v["GUI test: altitude 500 m, 10 kg"] > v["GUI test: altitude 100 m, 10 kg"]
    for name, d in designs.items():
        # the default "practice" rules: limits scale with the altitude, and every case is feasible
        assert d.requirement.rules == "practice"
        assert d.requirement.blow_by_limit == pytest.approx(0.5 * d.requirement.altitude), name
        assert d.feasible, (name, d.violations)


def test_cases_csv_is_one_tidy_table():
    cases = thesis_gui_cases()
    text = cases_csv(cases)
    rows = list(csv.DictReader(io.StringIO(text)))
    designs = case_designs(cases)
    n_speeds = {n: d.performance.wind_speed.size for n, d in designs.items()}
    assert len(rows) == sum(n_speeds.values())
    assert [r["case"] for r in rows[: n_speeds[next(iter(cases))]]] == [next(iter(cases))] * 21
    header = list(rows[0])
    for col in (
        "case",
        "payload_mass_kg",
        "altitude_m",
        "hull_volume_m3",
        "volume_m3",
        "total_mass_kg",
        "wind_speed_m_s",
        "blow_by_m",
        "tension_top_N",
        "flags",
        "limit_exceeded",
    ):
        assert col in header, col
    # every row agrees with the engine
    for r in rows:
        d = designs[r["case"]]
        i = int(round(float(r["wind_speed_m_s"]) / d.requirement.wind_step))
        assert float(r["blow_by_m"]) == pytest.approx(float(d.performance.blow_by[i]), rel=1e-9)
        assert float(r["volume_m3"]) == pytest.approx(d.volume)
        assert r["hull_volume_m3"] == ""  # sized: "auto" is an empty cell
    assert float(rows[0]["payload_mass_kg"]) == 10.0


def test_cases_rows_name_the_bad_case():
    good = thesis_gui_cases()
    bad = {"broken": {"requirement": {"payload_mass": -5}}}
    with pytest.raises(ValueError, match="broken.*payload_mass"):
        cases_rows({**good, **bad})


def test_empty_cases_give_an_empty_csv():
    assert cases_csv({}) == ""


def test_report_numbers_are_finite(baseline):
    rep = design_report(baseline)
    for key in ("blow_by", "alpha_eq", "tension_top", "safety_factor"):
        assert np.all(np.isfinite(getattr(rep.perf, key))), key
    assert all(math.isfinite(v) for v in rep.hull.to_dict().values())
