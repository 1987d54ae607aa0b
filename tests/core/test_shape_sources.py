"""Shape library against dimensions published for real envelopes (docs/methods.md §1.13, S21).

The only published envelope whose length, diameter and volume were all found for one of the
Gertler shapes is LOTTE. The German Wikipedia article "LOTTE (Luftschiff)" (read through the
English copy at https://de.zxc.wiki/wiki/LOTTE_(Luftschiff)) gives: length 16 m, diameter 4 m,
total volume 109 m3. No such figures were found for GNVR, Wang or Zhiyuan-1 (S18). There is a
PADD Micro airship, 5 m long and 6.64 m3 (Gawale & Pant) or 6.8 m3 (Jane's), which IIT Bombay
flew to assess the GNVR shape. Its diameter was not found, so its fineness ratio is unknown and
it is not tested here.
"""

from __future__ import annotations

import pytest

from aerostat_core.geometry import hull_geometry
from aerostat_core.shapes import SHAPE_INFO

#: LOTTE as published: length [m], diameter [m], volume [m3].
LOTTE_PUBLISHED = (16.0, 4.0, 109.0)


def _at_length(shape: str, f: float, length: float):
    """Hull of the given shape and l/d scaled to a given length: V = (V/l^3) l^3."""
    g = hull_geometry(100.0, f, 0.432, shape)
    v_over_l3 = float(g.volume) / float(g.length) ** 3
    return v_over_l3, hull_geometry(v_over_l3 * length**3, f, 0.432, shape)


def test_lotte_volume_coefficient_matches_the_published_envelope():
    """V/l^3 = 109 / 16^3 = 0.02661. The fit (C_p 0.517, l/d 3.9019) gives 0.02667, +0.22 %.

    Tolerance 1.5 %: it covers the rounding of the published figures, volume to 3 significant
    figures (0.46 %) and length taken as 16.0 m (±0.05 m, i.e. 3 × 0.31 % in V/l^3). The check
    can fail: a C_p of 2/3 (NPL double ellipsoid) at the same l/d would be 29 % high.
    """
    length, _, volume = LOTTE_PUBLISHED
    f = SHAPE_INFO["lotte"].default_fineness
    v_over_l3, g = _at_length("lotte", f, length)
    assert v_over_l3 == pytest.approx(volume / length**3, rel=0.015)
    assert float(g.volume) == pytest.approx(volume, rel=0.015)


def test_lotte_diameter_agrees_with_the_published_metre():
    """At 16 m and the tabulated l/d 3.9019 the diameter is 4.10 m. The published "4 m" is
    given to the metre, so the test is |d - 4| <= 0.5 m. With exactly 4.0 m, the published
    triple would imply C_p = 4 V / (pi d^2 l) = 0.542. The fit's 0.517 needs d = 4.10 m."""
    length, diameter, _ = LOTTE_PUBLISHED
    f = SHAPE_INFO["lotte"].default_fineness
    _, g = _at_length("lotte", f, length)
    assert float(g.length) == pytest.approx(length, rel=1e-12)
    assert abs(float(g.diameter) - diameter) <= 0.5
    assert float(g.diameter) == pytest.approx(length / f, rel=1e-12)
