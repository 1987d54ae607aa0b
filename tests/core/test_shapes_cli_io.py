"""CLI --shape/--json/export options and versioned JSON design files (issue 12)."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest

from aerostat_core import Configuration, HullSpec, Requirement
from aerostat_core.cli.entry import main
from aerostat_core.geometry.shapes import SHAPES
from aerostat_core.model.io import VERSION, cases_from_json, design_from_json, design_to_json
from aerostat_core.output.export import mesh_properties


def test_cli_shape_json_has_hull_mass_and_blow_by(capsys):
    assert main(["design", "--shape", "gnvr", "--volume", "150", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["hull_shape"] == "gnvr"
    assert out["hull_mass_kg"] > 0 and out["blow_by_at_design_wind_m"] > 0
    assert out["volume_m3"] == pytest.approx(150.0)


def test_cli_shapes_differ(capsys):
    masses = {}
    for s in ("npl", "sphere"):
        assert main(["design", "--shape", s, "--volume", "150", "--json"]) == 0
        masses[s] = json.loads(capsys.readouterr().out)["hull_mass_kg"]
    assert masses["sphere"] < masses["npl"]  # least area for the volume


def test_cli_unknown_shape_exits_2_listing_the_valid_names(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["design", "--shape", "zeppelin"])
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert all(s in err for s in SHAPES)


def test_cli_bad_fineness_for_shape_exits_2(capsys):
    assert main(["design", "--shape", "sphere", "--fineness-ratio", "3"]) == 2
    assert "for shape 'sphere'" in capsys.readouterr().err


def test_cli_writes_stl_and_patterns(tmp_path, capsys):
    stl, dxf, svg, csv = (tmp_path / n for n in ("h.stl", "g.dxf", "g.svg", "g.csv"))
    rc = main(
        [
            "design",
            "--shape",
            "wang",
            "--volume",
            "120",
            "--stl",
            str(stl),
            "--gores",
            "10",
            "--gores-dxf",
            str(dxf),
            "--gores-svg",
            str(svg),
            "--gores-csv",
            str(csv),
        ]
    )
    assert rc == 0
    assert mesh_properties(stl.read_bytes())["volume"] > 120.0  # hull + fins
    assert dxf.read_bytes()[:20].strip() and svg.read_text().startswith("<svg")
    assert csv.read_text().startswith("# 10 gores")
    assert main(["design", "--gores", "2"]) == 2


def test_json_files_are_versioned_and_carry_the_shape():
    cfg = replace(Configuration(), hull=HullSpec(shape="lotte", volume=200.0))
    text = design_to_json(Requirement(), cfg)
    data = json.loads(text)
    assert data["version"] == VERSION == 2
    assert data["configuration"]["hull"]["shape"] == "lotte"
    _, cfg2 = design_from_json(text)
    assert cfg2 == cfg


def test_version_1_files_load_as_npl():
    v1 = {
        "format": "aerostat-design",
        "version": 1,
        "configuration": {"hull": {"fineness_ratio": 3.5, "nose_fraction": 0.432, "volume": None}},
    }
    _, cfg = design_from_json(json.dumps(v1))
    assert cfg.hull.shape == "npl" and cfg.hull.fineness_ratio == 3.5
    cases = cases_from_json(
        json.dumps({"format": "aerostat-cases", "version": 1, "cases": {"old": v1}})
    )
    assert cases["old"]["configuration"]["hull"]["shape"] == "npl"
    with pytest.raises(ValueError, match="reads versions 1, 2"):
        design_from_json(json.dumps({"format": "aerostat-design", "version": 3}))


def test_compare_rows_show_the_shape():
    from aerostat_core import design
    from aerostat_core.output.report import comparison_rows

    a = design(Requirement(), Configuration(hull=HullSpec(volume=150.0)))
    b = design(Requirement(), Configuration(hull=HullSpec(shape="wang", volume=150.0)))
    rows = comparison_rows({"A": a, "B": b})
    row = [r for r in rows if r["quantity"] == "Hull shape"][0]
    assert (row["A"], row["B"], row["differs"]) == ("npl", "wang", True)
    mass = [r for r in rows if r["quantity"] == "Hull fabric mass [kg]"][0]
    assert mass["A"] == pytest.approx(float(a.airframe.mass.items["hull"]))
