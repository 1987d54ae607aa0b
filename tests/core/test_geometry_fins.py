"""Hull closed forms against numerical integration, Lamb factors against Lamb's table, fins."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.integrate import quad

from aerostat_core.geometry.added_mass import lamb_factors
from aerostat_core.geometry.fins import helmbold_lift_slope
from aerostat_core.geometry.hull import (
    half_spheroid_area,
    hull_geometry,
    radius,
    shape_integrals,
    volume_to_station,
)
from aerostat_core.studies.reference import LAMB_TABLE


def _numeric(g):
    a1, a2, b, length = float(g.a1), float(g.a2), float(g.b), float(g.length)

    def r(x):
        return float(radius(x, a1, a2, b))

    def ds(x):  # 2 pi r sqrt(1 + r'^2), written with r r' to stay finite at the ends
        a = a1 if x <= a1 else a2
        u = (x - a1) / a
        return 2 * np.pi * b * np.sqrt(1 - u * u + (b / a) ** 2 * u * u)

    vol = quad(lambda x: np.pi * r(x) ** 2, 0, length, points=[a1])[0]
    area = quad(ds, 0, length, points=[a1])[0]
    xcb = quad(lambda x: x * np.pi * r(x) ** 2, 0, length, points=[a1])[0] / vol
    xs = quad(lambda x: x * ds(x), 0, length, points=[a1])[0] / area
    return vol, area, xcb, xs


@given(v=st.floats(10, 5000), f=st.floats(1.6, 8.0), split=st.floats(0.25, 0.75))
def test_npl_closed_forms_match_numerical_integration(v, f, split):
    g = hull_geometry(v, f, split)
    vol, area, xcb, xs = _numeric(g)
    assert float(g.volume) == pytest.approx(vol, rel=1e-8)
    assert float(g.surface_area) == pytest.approx(area, rel=1e-7)
    assert float(g.xi_cb) == pytest.approx(xcb, rel=1e-7)
    assert float(g.xi_surface) == pytest.approx(xs, rel=1e-7)
    assert float(g.length / g.diameter) == pytest.approx(f, rel=1e-12)


def test_table_2_2_hull_geometry():
    # docs/methods.md §1.4: l = 11.2 m, d = 4.1 m for 100 m3 at f ~ 2.7 (thesis Table 2.2)
    g = hull_geometry(100.0, 2.7)
    assert float(g.length) == pytest.approx(11.2, abs=0.1)
    assert float(g.diameter) == pytest.approx(4.1, abs=0.05)


def test_sphere_and_oblate_area_limits():
    assert half_spheroid_area(2.0, 2.0) == pytest.approx(2 * np.pi * 4)
    # continuity across a = b from both sides
    assert half_spheroid_area(2.0 * (1 + 1e-6), 2.0) == pytest.approx(8 * np.pi, rel=1e-5)
    assert half_spheroid_area(2.0 * (1 - 1e-6), 2.0) == pytest.approx(8 * np.pi, rel=1e-5)


@pytest.mark.parametrize("f, k1, k2, kr", LAMB_TABLE)
def test_lamb_factors_match_lambs_table(f, k1, k2, kr):
    c1, c2, cr = lamb_factors(f)
    assert float(c1) == pytest.approx(k1, abs=0.0015)
    assert float(c2) == pytest.approx(k2, abs=0.0025)
    assert float(cr) == pytest.approx(kr, abs=0.0025)


def test_lamb_sphere_limit():
    k1, k2, kr = lamb_factors(1.0 + 1e-6)
    assert (float(k1), float(k2)) == pytest.approx((0.5, 0.5), abs=1e-3)
    assert float(kr) == pytest.approx(0.0, abs=1e-3)


def test_shape_integrals_give_munks_moment_at_full_length():
    g = hull_geometry(150.0, 3.5)
    i1, i3, j1, j2 = shape_integrals(g, g.length, g.xi_cb)
    assert float(i1) == pytest.approx(0.0, abs=1e-9)
    assert float(i3) == pytest.approx(float(g.volume), rel=1e-12)
    # J1 is the planform area; J2 by quadrature
    a1, a2, b = float(g.a1), float(g.a2), float(g.b)
    assert float(j1) == pytest.approx(quad(lambda x: 2 * float(radius(x, a1, a2, b)), 0,
                                           float(g.length), points=[a1])[0], rel=1e-8)
    xm = float(g.xi_cb)
    j2n = quad(lambda x: 2 * float(radius(x, a1, a2, b)) * (xm - x), 0, float(g.length),
               points=[a1])[0]
    assert float(j2) == pytest.approx(j2n, rel=1e-6, abs=1e-9)
    # partial volume closed form
    lh = 0.7 * float(g.length)
    vn = quad(lambda x: np.pi * float(radius(x, a1, a2, b)) ** 2, 0, lh, points=[a1])[0]
    assert float(volume_to_station(lh, a1, a2, b)) == pytest.approx(vn, rel=1e-9)


def test_helmbold_limits():
    # slender-wing limit pi AR / 2 and the 2-D limit 2 pi as AR grows
    assert float(helmbold_lift_slope(0.05, 0.0)) == pytest.approx(np.pi * 0.05 / 2, rel=1e-3)
    assert float(helmbold_lift_slope(1e4, 0.0)) == pytest.approx(2 * np.pi, rel=1e-3)
    # sweep lowers the slope
    assert helmbold_lift_slope(2.0, 0.5) < helmbold_lift_slope(2.0, 0.0)
