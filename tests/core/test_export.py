"""Geometry export (issue 12): the STL re-read recovers the hull; the gores add up to its area."""

from __future__ import annotations

from dataclasses import replace

import ezdxf
import numpy as np
import pytest

from aerostat_core import HullSpec, design
from aerostat_core.geometry.shapes import SHAPES
from aerostat_core.model.presets import thesis_baseline
from aerostat_core.output.export import (
    design_stl,
    fin_meshes,
    gore_csv,
    gore_dxf,
    gore_pattern,
    gore_svg,
    mesh_properties,
)


@pytest.fixture(scope="module")
def designs():
    req, cfg = thesis_baseline()
    return {s: design(req, replace(cfg, hull=HullSpec(shape=s, volume=150.0))) for s in SHAPES}


@pytest.mark.parametrize("shape", SHAPES)
def test_stl_recovers_volume_area_and_centre_of_volume(designs, shape):
    d = designs[shape]
    h = d.airframe.hull
    p = mesh_properties(design_stl(d, "hull"))
    assert p["volume"] == pytest.approx(float(h.volume), rel=0.005)
    assert p["area"] == pytest.approx(float(h.surface_area), rel=0.005)
    assert p["centre"][0] == pytest.approx(float(h.xi_cb), rel=0.005)
    assert abs(p["centre"][1]) < 1e-6 and abs(p["centre"][2]) < 1e-6


def test_fin_mesh_is_closed_and_outward(designs):
    d = designs["npl"]
    tris = fin_meshes(d)
    p = mesh_properties(design_stl(d, "fins"))
    f = d.airframe.fins
    # slab volume ~ planform area x thickness (0.12 root chord); the exported root follows the
    # hull surface (root LE and TE at their own radii), so the in-plane area differs a little
    expected = float(f.area_total) * 0.12 * float(f.root_chord)
    assert p["volume"] == pytest.approx(expected, rel=0.15)
    assert tris.shape == (4 * 12, 3, 3)
    # closed: every edge is shared by exactly two triangles, once in each direction
    edges = {}
    for t in np.round(tris, 9):
        for k in range(3):
            e = (tuple(t[k]), tuple(t[(k + 1) % 3]))
            edges[e] = edges.get(e, 0) + 1
    assert all(edges.get((b, a), 0) == 1 for (a, b) in edges)
    assert len(fin_meshes(designs["sphere"])) == 0
    with pytest.raises(ValueError, match="STL part"):
        design_stl(d, "tail")


@pytest.mark.parametrize("shape", SHAPES)
@pytest.mark.parametrize("n", [4, 12, 30])
def test_gore_pattern_area_equals_hull_area(designs, shape, n):
    p = gore_pattern(designs[shape], n_gores=n, seam_allowance=0.02)
    assert p.pattern_area == pytest.approx(p.hull_area, rel=0.01)
    assert np.max(p.half_width) == pytest.approx(
        np.pi * float(designs[shape].airframe.hull.b) / n, rel=1e-3
    )
    # the cut line encloses the seam line by the allowance all round
    assert np.max(p.cut_outline[:, 1]) == pytest.approx(
        np.max(p.seam_outline[:, 1]) + 0.02, rel=1e-3
    )
    assert np.min(p.cut_outline[:, 0]) < 0 < np.max(p.seam_outline[:, 0])


def test_fin_patterns_and_files(designs, tmp_path):
    d = designs["npl"]
    p = gore_pattern(d, n_gores=8, seam_allowance=0.015)
    assert p.fin_pattern_area == pytest.approx(2 * float(d.airframe.fins.area_total), rel=1e-9)
    path = tmp_path / "g.dxf"
    path.write_bytes(gore_dxf(p))
    doc = ezdxf.readfile(path)
    polys = doc.modelspace().query("LWPOLYLINE")
    assert len(polys) == 2 + 2 * 2 * 4  # gore seam + cut, 8 fin faces x (seam + cut)
    assert {e.dxf.layer for e in polys} == {"SEAM", "CUT", "FIN_SEAM", "FIN_CUT"}
    seam = [e for e in polys if e.dxf.layer == "SEAM"][0]
    xy = np.array([(v[0], v[1]) for v in seam.get_points()])
    area = 0.5 * abs(
        np.dot(xy[:, 0], np.roll(xy[:, 1], -1)) - np.dot(xy[:, 1], np.roll(xy[:, 0], -1))
    )
    assert 8 * area == pytest.approx(p.hull_area, rel=0.01)
    svg = gore_svg(p).decode()
    assert svg.startswith("<svg") and svg.count("<polygon") == 18
    csv = gore_csv(p).splitlines()
    assert csv[1].startswith("s_m,xi_m,radius_m,half_width_m")
    assert len(csv) == 2 + p.s.size


def test_gore_inputs_are_checked(designs):
    with pytest.raises(ValueError, match=r"n_gores = 2 .*\[3, 64\]"):
        gore_pattern(designs["npl"], n_gores=2)
    with pytest.raises(ValueError, match="seam_allowance"):
        gore_pattern(designs["npl"], seam_allowance=-1.0)
