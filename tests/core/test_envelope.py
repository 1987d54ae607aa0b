"""Operating envelope: agreement with single designs, binding constraint, grid checks."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from aerostat_core import Requirement, design
from aerostat_core.model.constraints import NAMES
from aerostat_core.studies.envelope import (
    ENVELOPE_NAMES,
    MAX_POINTS,
    operating_envelope,
    requirement_at,
)


@pytest.fixture(scope="module")
def d():
    return design(Requirement(payload_mass=10.0, altitude=300.0))


@pytest.fixture(scope="module")
def env(d):
    return operating_envelope(
        d, wind=np.linspace(0.0, 30.0, 31), altitude=np.linspace(100.0, 600.0, 11)
    )


def test_envelope_matches_single_designs_at_sampled_points(d, env):
    """At (U, h) the envelope's g equals the constraint table of design() for the same built
    aerostat (its volume) with design wind U at altitude h."""
    rng = np.random.default_rng(7)
    cols = [NAMES.index(n) for n in ENVELOPE_NAMES]
    for _ in range(6):
        ia = int(rng.integers(env.altitude.size))
        iw = int(rng.integers(1, env.wind.size))
        h, u = float(env.altitude[ia]), float(env.wind[iw])
        r = requirement_at(d.requirement, h)
        r = replace(r, design_wind=u, survival_wind=max(u, r.survival_wind))
        single = design(r, d.configuration.with_design_variables(volume=d.volume))
        np.testing.assert_allclose(
            env.g[0, ia, iw], single.constraints.g[cols], rtol=1e-9, atol=1e-12
        )
        np.testing.assert_allclose(
            env.margin[0, ia, iw], single.constraints.margin[cols], rtol=1e-9, atol=1e-9
        )
        assert env.flyable[0, ia, iw] == all(
            single.constraints.met[NAMES.index(n)] for n in ENVELOPE_NAMES
        )


def test_envelope_matches_single_designs_in_light_wind(d):
    """Below 1 m/s too (the moment slopes are normalised by q at the speed itself, so a stable
    hull stays weathervane-stable near calm)."""
    cols = [NAMES.index(n) for n in ENVELOPE_NAMES]
    e = operating_envelope(d, wind=[0.3, 0.6], altitude=[300.0])
    for iw, u in enumerate((0.3, 0.6)):
        r = requirement_at(d.requirement, 300.0)
        r = replace(r, design_wind=u, survival_wind=max(u, r.survival_wind))
        single = design(r, d.configuration.with_design_variables(volume=d.volume))
        np.testing.assert_allclose(e.g[0, 0, iw], single.constraints.g[cols], rtol=1e-9,
                                   atol=1e-12)
        assert single.constraints.met[NAMES.index("weathervane")]


def test_design_point_is_flyable_and_binding_is_largest_g(d, env):
    e = operating_envelope(d, wind=[d.requirement.design_wind], altitude=[300.0])
    assert d.feasible and bool(e.flyable[0, 0, 0])
    k = env.binding_index
    assert np.array_equal(np.take_along_axis(env.g, k[..., None], -1)[..., 0], env.max_g)
    names = env.binding_names()
    assert set(np.unique(names)) <= set(ENVELOPE_NAMES)
    assert env.points == 31 * 11
    assert len(env.rows()) == env.points


def test_calm_air_at_design_altitude_is_flyable_and_strong_wind_is_not(d):
    e = operating_envelope(d, wind=[0.0, 0.3, 1.0, 60.0], altitude=[300.0])
    assert e.flyable[0, 0].tolist() == [True, True, True, False]


def test_limit_wind_falls_with_altitude_where_blow_by_binds(d, env):
    """Blow-by ~ h at a given wind while its limit also scales with h, but the tether drag
    grows with h: the flyable wind cannot rise with the tether length."""
    lw = env.limit_wind()[0]
    ok = np.isfinite(lw)
    assert ok.sum() >= 3
    assert np.all(np.diff(lw[ok]) <= 1e-9)


def test_heavier_payload_eats_free_lift(d):
    e = operating_envelope(d, wind=[5.0], altitude=[300.0], payload=[5.0, 10.0, 15.0])
    k = ENVELOPE_NAMES.index("free_lift")
    fl = e.g[:, 0, 0, k]
    assert np.all(np.diff(fl) > 0)
    assert e.flyable[:, 0, 0].tolist() == [True, True, False]


def test_requirement_at_scales_length_limits(d):
    r = requirement_at(d.requirement, 150.0)
    assert r.altitude == 150.0
    assert r.blow_by_limit == pytest.approx(d.requirement.blow_by_limit / 2)
    assert r.altitude_loss_limit == pytest.approx(d.requirement.altitude_loss_limit / 2)


@pytest.mark.parametrize(
    ("kw", "text"),
    [
        ({"wind": [-1.0]}, "wind = -1 m/s is outside the valid range [0, 60] m/s"),
        ({"altitude": [5.0]}, "altitude = 5 m is outside the valid range [10, 3000] m"),
        ({"wind": []}, "no values"),
        ({"wind": np.zeros(MAX_POINTS + 1)}, "more than"),
    ],
)
def test_bad_grid_is_named(d, kw, text):
    with pytest.raises(ValueError, match=text.replace("[", r"\[").replace("]", r"\]")):
        operating_envelope(d, **{"altitude": [300.0], **kw})
