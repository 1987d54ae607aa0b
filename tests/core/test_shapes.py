"""Hull-shape library (issue 12): closed forms, quadrature convergence, published coefficients,
Lamb's factors, Table 2.2 masses and the Figure 2.5 ordering."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad

from aerostat_core import Configuration, HullSpec, Requirement, design
from aerostat_core.aerodynamics.drag import volumetric_drag_coefficient
from aerostat_core.aerodynamics.helikite import helikite_limits, kite_geometry
from aerostat_core.geometry.added_mass import (
    added_mass_factors,
    added_mass_numerical,
    lamb_factors,
    spheroid_lamb_factors,
)
from aerostat_core.geometry.hull import half_spheroid_area, hull_geometry
from aerostat_core.geometry.shapes import (
    GERTLER_TABLE,
    SHAPE_INFO,
    SHAPES,
    profile_coefficients,
    profile_data,
)
from aerostat_core.model.presets import thesis_baseline
from aerostat_core.studies.reference import LAMB_TABLE
from aerostat_core.studies.shape_comparison import (
    THESIS_TABLE_2_2,
    comparison_notes,
    full_model_shape_comparison,
    thesis_shape_comparison,
)

GSM = 0.130  # thesis hull fabric [kg/m2] (Table 2.2, docs/methods.md §3.2)
GERTLER = ("wang", "zhiyuan-1", "lotte")
#: Every shape integrated from a dimensionless profile: the Gertler fits and the piecewise GNVR.
PROFILED = ("gnvr", *GERTLER)


def test_sphere_closed_forms():
    g = hull_geometry(100.0, 1.0, 0.432, "sphere")
    r = (3 * 100.0 / (4 * math.pi)) ** (1 / 3)
    assert float(g.diameter) == pytest.approx(2 * r, rel=1e-12)
    assert float(g.surface_area) == pytest.approx(4 * math.pi * r**2, rel=1e-10)
    assert float(g.xi_cb) == pytest.approx(r, rel=1e-12)
    assert float(g.xi_surface) == pytest.approx(r, rel=1e-10)
    assert float(g.planform_area) == pytest.approx(math.pi * r**2, rel=1e-6)
    assert [float(k) for k in (g.k1, g.k2, g.k_rot)] == pytest.approx([0.5, 0.5, 0.0])
    xi, rr, ws, wv = __import__("aerostat_core.geometry.hull", fromlist=["x"]).profile_quadrature(g)
    assert float(np.sum(wv)) == pytest.approx(100.0, rel=1e-10)
    assert float(np.sum(ws)) == pytest.approx(float(g.surface_area), rel=1e-12)


@pytest.mark.parametrize(
    "shape,f", [("helikite", 1.24), ("helikite", 1.6), ("oblate", 0.5), ("oblate", 0.9)]
)
def test_spheroid_area_matches_closed_form(shape, f):
    g = hull_geometry(50.0, f, 0.432, shape)
    a, b = float(g.length) / 2, float(g.diameter) / 2
    assert float(g.surface_area) == pytest.approx(2 * float(half_spheroid_area(a, b)), rel=1e-9)
    assert (4 / 3) * math.pi * a * b * b == pytest.approx(50.0, rel=1e-12)


def test_spheroid_lamb_factors_closed_forms_against_lamb_integrals():
    for f in (0.3, 0.5, 0.75, 1.24, 3.0, 6.0):
        a, b = f, 1.0
        al = (
            a
            * b
            * b
            * quad(lambda x, a=a, b=b: 1 / ((a * a + x) ** 1.5 * (b * b + x)), 0, np.inf)[0]
        )
        be = (
            a
            * b
            * b
            * quad(lambda x, a=a, b=b: 1 / ((a * a + x) ** 0.5 * (b * b + x) ** 2), 0, np.inf)[0]
        )
        k1, k2, _ = spheroid_lamb_factors(f)
        assert float(k1) == pytest.approx(al / (2 - al), rel=1e-7)
        assert float(k2) == pytest.approx(be / (2 - be), rel=1e-7)
    # the prolate branch is added_mass.lamb_factors; continuity through the sphere
    assert [float(k) for k in spheroid_lamb_factors(1.0)] == pytest.approx([0.5, 0.5, 0.0])
    lo = [float(k) for k in spheroid_lamb_factors(0.999)]
    hi = [float(k) for k in spheroid_lamb_factors(1.001)]
    assert lo == pytest.approx(hi, abs=2e-3)


@pytest.mark.parametrize("f,k1,k2,kr", [row for row in LAMB_TABLE if 1.5 <= row[0] <= 6.1])
def test_numerical_added_mass_reproduces_lamb_for_prolate_spheroids(f, k1, k2, kr):
    """The line-singularity method on P = x - x^2 (a prolate spheroid) against Lamb's table."""
    n1, n2, nr = added_mass_numerical("helikite", f)
    assert n1 == pytest.approx(k1, rel=0.03, abs=0.002)
    assert n2 == pytest.approx(k2, rel=0.005)
    assert nr == pytest.approx(kr, rel=0.01, abs=0.002)


def test_numerical_added_mass_converges_for_gertler_shapes():
    for shape in PROFILED:
        f = SHAPE_INFO[shape].default_fineness
        coarse = np.array(added_mass_numerical(shape, f, segments=32))
        fine = np.array(added_mass_numerical(shape, f, segments=64))
        assert np.allclose(coarse, fine, rtol=0.01), shape
        # between the prolate spheroid (C_p 2/3) values at the same l/d, like Lamb's factors
        k1, k2, _ = lamb_factors(f)
        assert abs(fine[0] - float(k1)) < 0.03 and abs(fine[1] - float(k2)) < 0.03


@pytest.mark.parametrize("shape", GERTLER)
def test_gertler_profiles_reproduce_the_published_coefficients(shape):
    """The S7 table (attributed to Alam & Pant 2017, unverified; docs/methods.md §1.13): C_p and
    station of maximum diameter recovered from the solved polynomial; the profile is
    non-negative and its maximum radius is d/2."""
    m, r0, r1, cp, _ = GERTLER_TABLE[shape]
    pd = profile_data(shape)
    assert pd.cp == pytest.approx(cp, abs=1e-9)
    assert pd.x_max == pytest.approx(m, abs=1e-3)
    p = np.polynomial.Polynomial(profile_coefficients(shape))
    x = np.linspace(0, 1, 4001)
    assert p(x).min() >= -1e-12
    assert p(x).max() == pytest.approx(0.25, abs=1e-6)
    assert p.deriv()(0.0) == pytest.approx(2 * r0)
    assert p.deriv()(1.0) == pytest.approx(-2 * r1)


def test_npl_prismatic_coefficient_matches_published_table():
    """The S7 table lists C_p = 0.667 for NPL: the double ellipsoid's 2/3."""
    g = hull_geometry(100.0, 4.0)
    cp = float(g.volume) / (math.pi * float(g.diameter) ** 2 * float(g.length) / 4)
    assert cp == pytest.approx(GERTLER_TABLE["npl"][3], abs=5e-4)


#: A second public tabulation of the Gertler parameters (m, r0, r1, C_p, l/d), from another
#: public Gertler-envelope code (an airship-geometry script generator read through the code
#: index, which does not name its repository; docs/methods.md S14). Neither it nor S7 states a
#: source; they are independent copies, so their agreement bounds the transcription error.
SECOND_PUBLIC_TABLE = {
    "gnvr": (0.4143, 0.5999, 0.1762, 0.6163, 3.0500),
    "zhiyuan-1": (0.4193, 0.3306, 0.2500, 0.6489, 3.2592),
    "wang": (0.4040, 0.6000, 0.1000, 0.6100, 3.8540),
    "npl": (0.4319, 0.5886, 0.4248, 0.6667, 4.0000),
    "lotte": (0.4502, 0.5759, 0.1000, 0.5170, 3.902),
}


@pytest.mark.parametrize("shape", sorted(set(SECOND_PUBLIC_TABLE) - {"gnvr"}))
def test_gertler_fits_agree_with_a_second_public_table(shape):
    """C_p and l/d within 0.4 % (largest: Zhiyuan-1's C_p 0.651 against 0.6489), m within 0.2 %,
    r0 and r1 within 2.5 %. The computed C_p and x_max are the solved profile's, not the table's
    inputs read back. GNVR, which is piecewise, is held to both tables in
    test_shape_sources.py."""
    m2, r02, r12, cp2, f2 = SECOND_PUBLIC_TABLE[shape]
    m, r0, r1, cp, f = GERTLER_TABLE[shape]
    if shape == "npl":  # the double ellipsoid: closed form 2/3, maximum at 0.432 l
        g = hull_geometry(100.0, f)
        cp_computed = float(g.volume) / (math.pi * float(g.diameter) ** 2 * float(g.length) / 4)
        x_max = 0.432
    else:
        pd = profile_data(shape)
        cp_computed, x_max = pd.cp, pd.x_max
    assert cp_computed == pytest.approx(cp2, rel=4e-3)
    assert f == pytest.approx(f2, rel=4e-3)
    assert SHAPE_INFO[shape].default_fineness == f
    assert x_max == pytest.approx(m2, rel=2e-3)
    assert r0 == pytest.approx(r02, rel=0.025) and r1 == pytest.approx(r12, rel=0.025)


def _spheroid_area(a, b):
    """Closed-form area of a spheroid of axial semi-axis a and equatorial b (a < b oblate)."""
    if a > b:
        e = math.sqrt(1 - (b / a) ** 2)
        return 2 * math.pi * b * b * (1 + a / (b * e) * math.asin(e))
    e = math.sqrt(1 - (a / b) ** 2)
    return 2 * math.pi * b * b * (1 + (1 - e * e) / e * math.atanh(e))


#: Per shape, the coefficients the tests hold it to, and where each number comes from. No
#: published surface coefficient S/V^(2/3) or volume coefficient V/l^3 was found for GNVR, Wang
#: or Zhiyuan-1 (their papers were not seen). For them the published figures held are the
#: tabulated C_p and l/d (S7 and the second public table above, both second-hand). Lotte's
#: published envelope dimensions (S21) are held in test_shape_sources.py.
PUBLISHED_COEFFICIENTS = [
    # shape, l/d, coefficient, value, tolerance (rel), source
    ("sphere", 1.0, "S/V^(2/3)", (36 * math.pi) ** (1 / 3), 1e-9, "closed form 4 pi r^2"),
    ("sphere", 1.0, "C_p", 2 / 3, 1e-9, "closed form"),
    ("oblate", 0.75, "S/V^(2/3)", None, 1e-9, "closed-form oblate spheroid area"),
    ("oblate", 0.5, "S/V^(2/3)", None, 1e-9, "closed-form oblate spheroid area"),
    ("helikite", 1.24, "S/V^(2/3)", None, 1e-9, "closed-form prolate spheroid area"),
    ("npl", 4.0, "C_p", 2 / 3, 1e-9, "double ellipsoid closed form (Khoury & Gillett)"),
    ("npl", 4.0, "V/l^3", math.pi * (2 / 3) / (4 * 16), 1e-9, "pi C_p / (4 f^2)"),
    ("gnvr", 3.05, "C_p", 0.6163, 3e-3, "second table's Gertler fit of GNVR (S14; S7: 0.615)"),
    ("wang", 3.859, "C_p", 0.610, 3e-3, "tabulated Gertler fit (S7; 0.6100 second table)"),
    ("zhiyuan-1", 3.266, "C_p", 0.651, 3e-3, "tabulated Gertler fit (S7; 0.6489 second table)"),
    ("lotte", 3.9019, "C_p", 0.517, 3e-3, "tabulated Gertler fit (S7; 0.5170 second table)"),
]


@pytest.mark.parametrize("shape,f,coef,value,tol,source", PUBLISHED_COEFFICIENTS)
def test_published_volume_and_area_coefficients_per_shape(shape, f, coef, value, tol, source):
    g = hull_geometry(100.0, f, 0.432, shape)
    v, length, d = float(g.volume), float(g.length), float(g.diameter)
    computed = {
        "S/V^(2/3)": float(g.surface_area) / v ** (2 / 3),
        "C_p": v / (math.pi * d * d * length / 4),
        "V/l^3": v / length**3,
    }[coef]
    if value is None:  # spheroid closed forms
        value = _spheroid_area(length / 2, d / 2) / v ** (2 / 3)
    assert computed == pytest.approx(value, rel=tol), source


@pytest.mark.parametrize("shape", PROFILED)
def test_quadrature_converges(shape):
    f = SHAPE_INFO[shape].default_fineness
    pd32, pd64, pd256 = (profile_data(shape, n) for n in (32, 64, 256))

    def area(pd):
        return float(np.sum(np.sqrt(pd.p + pd.dp**2 / (4 * f * f)) * pd.wx))

    assert abs(area(pd64) - area(pd256)) < 1e-10
    assert abs(area(pd32) - area(pd256)) < 1e-6
    assert abs(pd64.planform - pd256.planform) < 1e-8
    g = hull_geometry(100.0, f, 0.432, shape)
    from aerostat_core.geometry.hull import profile_quadrature

    _, _, ws, wv = profile_quadrature(g)
    assert float(np.sum(wv)) == pytest.approx(100.0, rel=1e-10)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(SHAPES), st.floats(0, 1), st.floats(1.0, 5000.0))
def test_every_shape_recovers_its_volume_and_beats_no_sphere(shape, u, volume):
    lo, hi = SHAPE_INFO[shape].fineness_range
    f = lo + u * (hi - lo)
    g = hull_geometry(volume, f, 0.432, shape)
    assert float(g.length / g.diameter) == pytest.approx(f if shape != "sphere" else 1.0)
    # volume of revolution of the radius profile
    xi = np.linspace(0, float(g.length), 20001)
    r = g.radius_at(xi)
    assert np.trapezoid(np.pi * r**2, xi) == pytest.approx(volume, rel=2e-3)
    assert float(g.volume_to(g.length)) == pytest.approx(volume, rel=1e-9)
    # isoperimetric inequality: the sphere has the least area for a volume
    s_sphere = 4 * math.pi * (3 * volume / (4 * math.pi)) ** (2 / 3)
    assert float(g.surface_area) >= s_sphere * (1 - 1e-9)
    assert 0 < float(g.xi_cb) < float(g.length)


def test_table_2_2_hull_masses_within_2_percent():
    sphere = GSM * float(hull_geometry(100.0, 1.0, 0.432, "sphere").surface_area)
    heli = GSM * float(
        hull_geometry(
            100.0, SHAPE_INFO["helikite"].default_fineness, 0.432, "helikite"
        ).surface_area
    )
    npl = GSM * float(hull_geometry(100.0, 2.7).surface_area)
    assert sphere == pytest.approx(13.54, rel=0.02)
    assert heli == pytest.approx(13.72, rel=0.02)
    assert npl == pytest.approx(15.57, rel=0.02)


def test_thesis_comparison_reproduces_table_2_2_and_figure_2_5_ordering():
    cmp = thesis_shape_comparison()
    rows = {r["key"]: r for r in cmp.rows}
    for key, ref in THESIS_TABLE_2_2.items():
        r = rows[key]
        assert r["hull_kg"] == pytest.approx(ref["hull"], rel=0.02)
        assert r["helium_kg"] == pytest.approx(ref["helium"], rel=1e-9)
        assert r["tether_kg"] == pytest.approx(ref["tether"], rel=1e-9)
        assert r["total_kg"] == pytest.approx(ref["total"], rel=0.02)
    assert rows["helikite"]["free_lift_kg"] == pytest.approx(52.0, rel=0.02)
    assert rows["sphere"]["free_lift_kg"] == pytest.approx(63.55, rel=0.02)
    assert rows["streamlined"]["length_m"] == pytest.approx(11.2, rel=0.01)
    assert rows["sphere"]["length_m"] == pytest.approx(5.76, rel=0.01)
    # Figure 2.5: streamlined < Helikite < sphere at 15 m/s; the streamlined hull is lowest at
    # every wind, the kite beats the sphere once its lift (~U^2) outgrows the sphere's larger
    # free lift (from about 4 m/s with these numbers)
    bb = {k: rows[k]["blow_by_at_design_wind_m"] for k in rows}
    assert bb["streamlined"] < bb["helikite"] < bb["sphere"]
    w = cmp.wind > 0
    assert np.all(cmp.blow_by["streamlined"][w] < cmp.blow_by["helikite"][w])
    w = cmp.wind >= 5.0
    assert np.all(cmp.blow_by["helikite"][w] < cmp.blow_by["sphere"][w])
    assert np.all(np.diff(cmp.blow_by["sphere"]) >= 0)
    assert cmp.blow_by["sphere"][0] == 0.0


def test_full_model_comparison_keeps_the_ordering_and_explains_itself():
    t, f = thesis_shape_comparison(), full_model_shape_comparison()
    bb = {r["key"]: r["blow_by_at_design_wind_m"] for r in f.rows}
    assert bb["streamlined"] < bb["helikite"] < bb["sphere"]
    rows = {r["key"]: r for r in f.rows}
    assert rows["helikite"]["dynamic_lift_kg"] == pytest.approx(48.0, rel=1e-6)
    assert rows["streamlined"]["dynamic_lift_kg"] > 0  # streamlined lift is on
    notes = comparison_notes(t, f)
    assert len(notes) >= 5 and any("same blow-by ranking" in n for n in notes)


def test_helikite_kite_reference_and_limits():
    k = kite_geometry(100.0)
    assert float(k.mass) == pytest.approx(11.38)
    q = 0.5 * 1.190107 * 15**2
    assert q * float(k.area) * k.lift_coefficient / 9.80665 == pytest.approx(48.0, rel=1e-5)
    # geometric similarity: sail area with V^(2/3)
    assert float(kite_geometry(800.0).area) == pytest.approx(4 * float(k.area))
    assert helikite_limits(10, 300, 15) == []
    assert len(helikite_limits(40, 2500, 30)) == 3


def test_volumetric_drag():
    assert float(volumetric_drag_coefficient("npl", 4.0, 1.72e7)) == pytest.approx(0.0215, abs=1e-4)
    # sphere in supercritical flow: C_D 0.2 on frontal area (Achenbach 1972)
    cdv = float(volumetric_drag_coefficient("sphere", 1.0, 5e6))
    assert cdv / ((math.pi / 4) / (math.pi / 6) ** (2 / 3)) == pytest.approx(0.2)
    # drag crisis: subcritical sphere drag is larger
    assert float(volumetric_drag_coefficient("sphere", 1.0, 1e5)) > 2 * cdv


def test_fineness_range_is_enforced_with_a_clear_message():
    with pytest.raises(ValueError, match=r"fineness_ratio = 4 .*\[1, 1\] for shape 'sphere'"):
        HullSpec(shape="sphere", fineness_ratio=4.0)
    with pytest.raises(ValueError, match=r"\[2, 6\] for shape 'gnvr'"):
        HullSpec(shape="gnvr", fineness_ratio=7.0)
    with pytest.raises(ValueError, match="npl, gnvr, wang, zhiyuan-1, lotte, sphere, oblate"):
        HullSpec(shape="blimp")
    assert HullSpec(shape="gnvr").fineness_ratio == pytest.approx(3.05)
    assert HullSpec().fineness_ratio == 4.0 and HullSpec().shape == "npl"


@pytest.mark.parametrize("shape", SHAPES)
def test_design_works_for_every_shape(shape):
    req, cfg = thesis_baseline()
    cfg = replace(cfg, hull=HullSpec(shape=shape, volume=None))
    d = design(req, cfg)
    assert d.airframe.hull.shape == shape
    assert d.free_lift > 0
    if d.feasible:
        assert d.design_point["blow_by_m"] <= req.blow_by_limit * 1.001
    else:
        # bluff hulls under the thesis' 53.4 m limit: the hull big enough for the blow-by limit
        # pulls the tether past its safety factor, and sizing says so
        assert not SHAPE_INFO[shape].streamlined
        assert any("safety factor" in v for v in d.violations), d.violations
    if not SHAPE_INFO[shape].streamlined:
        assert float(d.airframe.fins.area_total) == 0.0
    if shape == "helikite":
        assert float(d.airframe.mass.items["fins"]) > 0  # the kite


def test_npl_default_unchanged():
    """HullSpec() is the NPL hull with the established closed forms."""
    d = design(Requirement(), Configuration(hull=HullSpec(volume=150.0)))
    d_npl = design(Requirement(), Configuration(hull=HullSpec(volume=150.0, shape="npl")))
    assert d.summary() == d_npl.summary()
    g = hull_geometry(100.0, 2.7)
    assert float(g.surface_area) == pytest.approx(119.97, abs=0.01)


def test_added_mass_factors_vectorise():
    f = np.array([2.5, 3.0, 4.0])
    k1, k2, kr = added_mass_factors("gnvr", f)
    assert k1.shape == (3,) and np.all(np.diff(k1) < 0) and np.all(np.diff(k2) > 0)
