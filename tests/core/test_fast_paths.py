"""The engine's fast paths give the numbers of the plain formulas they replace.

The tether march runs a compiled kernel and the trim root-finder evaluates an alpha-expanded
moment, and the envelope beam runs a compiled station loop (all for speed: numpy's per-call
overhead dominates on the usual small arrays). Here they are checked against the plain
definitions over hypothesis-drawn inputs: the Heun march in numpy with
:func:`aerostat_core.tether.statics._line_load` (``_march_plain``),
:func:`aerostat_core.model.statics.moment_about_confluence` / ``aerodynamic_moment``, and
:func:`aerostat_core.structures.membrane._envelope_loads_plain`.
"""

import dataclasses
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from aerostat_core import HullSpec, TetherSpec, design, thesis_baseline
from aerostat_core.geometry.shapes import SHAPE_INFO
from aerostat_core.model.airframe import build_airframe
from aerostat_core.model.performance import evaluate
from aerostat_core.model.statics import (
    ALPHA_GRID,
    ALPHA_GRID_WIDE,
    MomentKernel,
    aerodynamic_moment,
    axial_drag_coefficient,
    equilibrium,
    moment_about_confluence,
    weathervane_slope,
)
from aerostat_core.structures.membrane import _envelope_loads_plain, envelope_loads
from aerostat_core.tether.statics import _march_plain, march


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    n=st.integers(1, 7),
    segments=st.integers(1, 60),
    length=st.floats(10.0, 2000.0),
    diameter=st.floats(1e-3, 0.03),
    cdn=st.floats(0.01, 2.0),
    cdt=st.floats(0.0, 0.05),
    ea=st.one_of(st.just(np.inf), st.floats(1e4, 1e8)),
    w=st.floats(0.0, 5.0),
    rho=st.floats(0.3, 1.3),
    u_top=st.floats(-40.0, 40.0),
    shear=st.floats(0.0, 0.5),
    seed=st.integers(0, 2**16),
)
def test_march_is_the_plain_heun_scheme(
    n, segments, length, diameter, cdn, cdt, ea, w, rho, u_top, shear, seed
):
    rng = np.random.default_rng(seed)
    tx0 = rng.uniform(-50.0, 2000.0, n)
    tz0 = rng.uniform(-100.0, 5000.0, n)
    spec = TetherSpec("t", 0.02, diameter, cdn, cdt, 1e4, ea)
    heights = np.linspace(length, 0.0, segments + 1)[:, None] * np.ones(n)
    speed = u_top * rng.uniform(0.5, 1.0, n)

    def wind(z):
        return speed * (np.maximum(z, 1.0) / length) ** shear

    got = march(tx0, tz0, length, spec, rho, wind, heights, w, segments)
    ref = _march_plain(tx0, tz0, length, spec, rho, wind, heights, w, segments, (n,))
    # the same arithmetic compiled: the same floats to rounding over a whole line, on the
    # scale of the tension for T_x, T_z and of the line length for the offsets
    t_scale = np.max(np.abs(ref[:2])) + 1e-300
    for a, b, scale in zip(got, ref, (t_scale, t_scale, length, length)):
        assert a.shape == b.shape == (segments + 1, n)
        assert np.max(np.abs(a - b)) <= 1e-11 * scale


def test_march_keeps_the_batch_shape():
    spec = TetherSpec("t", 0.02, 0.005, 1.0, 0.01, 1e4, 1e6)
    heights = np.linspace(300.0, 0.0, 11).reshape(11, 1, 1) * np.ones((1, 2, 3))
    tx, tz, x, z = march(
        np.full((2, 3), 80.0),
        900.0,
        300.0,
        spec,
        1.1,
        lambda zz: 10.0 * np.ones_like(zz),
        heights,
        0.2,
        10,
    )
    assert tx.shape == tz.shape == x.shape == z.shape == (11, 2, 3)
    assert np.all(x[0] == 0.0) and np.all(z[-1] < -250.0)


@pytest.mark.parametrize("shape", list(SHAPE_INFO))
@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    alpha_deg=st.lists(st.floats(-85.0, 85.0), min_size=1, max_size=6),
    speed=st.floats(0.0, 60.0),
    given_cd0=st.booleans(),
)
def test_moment_kernel_is_the_moment_of_the_loads(shape, alpha_deg, speed, given_cd0):
    req, cfg = thesis_baseline()
    aero = replace(cfg.aero, hull_axial_drag=0.03) if given_cd0 else cfg.aero
    cfg = replace(cfg, hull=HullSpec(shape=shape, volume=170.0), aero=aero)
    af = _airframe(req, cfg)
    alpha = np.radians(np.asarray(alpha_deg))
    cd0 = axial_drag_coefficient(af, aero, speed)
    kernel = MomentKernel(af, aero, speed, cd0)
    # rounding of terms of the size of buoyancy x length and q V^(2/3) x length, which cancel
    # near a trim: a few ulp of those
    q = 0.5 * af.air_density * speed**2
    scale = float((af.buoyancy + q * af.hull.reference_area) * af.hull.length)
    ref = moment_about_confluence(af, aero, alpha, speed, cd0)
    assert np.max(np.abs(kernel(alpha) - ref)) <= 1e-14 * (np.max(np.abs(ref)) + scale)
    about_cv = kernel.about(af.hull.xi_cb)
    ref = aerodynamic_moment(af, aero, alpha, speed, af.hull.xi_cb, cd0)
    assert np.max(np.abs(about_cv(alpha) - ref)) <= 1e-14 * (np.max(np.abs(ref)) + scale)


@pytest.mark.parametrize("shape", list(SHAPE_INFO))
@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    speeds=st.lists(st.floats(0.0, 60.0), min_size=1, max_size=4),
    stall=st.floats(5.0, 40.0),
    static=st.booleans(),
)
def test_moment_on_the_grids_is_the_kernel(shape, speeds, stall, static):
    """The grid form (a cached basis of the grid angles times the coefficients) gives the
    kernel's moment on ALPHA_GRID and on the wide grid's outer angles, to rounding."""
    req, cfg = thesis_baseline()
    aero = replace(cfg.aero, fin_stall_angle_deg=stall)
    cfg = replace(cfg, hull=HullSpec(shape=shape, volume=170.0))
    af = _airframe(req, cfg)
    speed = np.asarray(speeds)
    kernel = MomentKernel(af, aero, speed, axial_drag_coefficient(af, aero, speed))
    if not static:
        kernel = kernel.about(af.hull.xi_cb)
    q = 0.5 * af.air_density * speed**2
    scale = np.max((af.buoyancy + q * af.hull.reference_area) * af.hull.length)
    outer = ALPHA_GRID_WIDE[(ALPHA_GRID_WIDE < ALPHA_GRID[0]) | (ALPHA_GRID_WIDE > ALPHA_GRID[-1])]
    for grid, angles in ((0, ALPHA_GRID), (1, outer)):
        ref = kernel(angles[:, None])
        got = kernel.on_grid(grid)
        assert got.shape == ref.shape == (len(angles), len(speed))
        assert np.max(np.abs(got - ref)) <= 1e-14 * (np.max(np.abs(ref)) + scale)


def _assert_same_fields(got, ref, path, rtol):
    """Every array field of two dataclasses (recursing into dataclasses, dicts and tuples)
    equal to ``rtol`` of the field's largest magnitude."""
    if dataclasses.is_dataclass(ref):
        for f in dataclasses.fields(ref):
            _assert_same_fields(
                getattr(got, f.name), getattr(ref, f.name), f"{path}.{f.name}", rtol
            )
    elif isinstance(ref, dict):
        assert got.keys() == ref.keys()
        for k in ref:
            _assert_same_fields(got[k], ref[k], f"{path}[{k}]", rtol)
    elif isinstance(ref, tuple):
        assert len(got) == len(ref)
        for i, (g, r) in enumerate(zip(got, ref)):
            _assert_same_fields(g, r, f"{path}[{i}]", rtol)
    elif isinstance(ref, (str, int, type(None))) and not isinstance(ref, bool):
        assert got == ref, path
    else:
        g, r = np.asarray(got, float), np.asarray(ref, float)
        assert g.shape == r.shape, path
        np.testing.assert_allclose(
            g, r, rtol=0, atol=rtol * (np.max(np.abs(r)) + 1e-300), err_msg=path
        )


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    shape=st.sampled_from(list(SHAPE_INFO)),
    volumes=st.lists(st.floats(1.0, 5000.0), min_size=1, max_size=4),
    fraction=st.floats(0.0, 1.0),
    area_change=st.floats(-50.0, 100.0),
    position=st.floats(0.55, 0.8),
    cutoff=st.sampled_from(["fin", "tail"]),
)
def test_scaled_airframe_is_the_plain_one(shape, volumes, fraction, area_change, position, cutoff):
    """A scalar fineness ratio and fin variables take the unit-volume geometry scaled by
    V^(1/3) (cached quadratures); the same airframe as the direct computation, which a
    batch of per-design fineness ratios runs, to rounding."""
    req, cfg = thesis_baseline()
    lo, hi = SHAPE_INFO[shape].fineness_range
    f = lo + fraction * (hi - lo)
    cfg = replace(
        cfg, hull=HullSpec(shape=shape, fineness_ratio=f), aero=replace(cfg.aero, cutoff=cutoff)
    )
    v = np.asarray(volumes)
    scaled = build_airframe(req, cfg, v, f, area_change, position)
    plain = build_airframe(req, cfg, v, np.full(v.shape, f), area_change, position)
    _assert_same_fields(scaled, plain, "airframe", 1e-12)


_AIRFRAMES = {}


def _airframe(req, cfg):
    key = (cfg.hull.shape, cfg.aero.hull_axial_drag)
    if key not in _AIRFRAMES:
        _AIRFRAMES[key] = design(req, cfg).airframe
    return _AIRFRAMES[key]


@pytest.mark.parametrize("shape", ["npl", "lotte", "sphere", "helikite"])
def test_trim_is_a_root_of_the_plain_moment(shape):
    """The root-finder on the kernel trims where the plain moment is zero (to its 1e-12 rad
    bracket), with the plain moment's slope there; the weathervane slope likewise."""
    req, cfg = thesis_baseline()
    cfg = replace(cfg, hull=HullSpec(shape=shape, volume=170.0))
    af = _airframe(req, cfg)
    speed = np.linspace(0.0, 40.0, 17)
    eq = equilibrium(af, cfg.aero, speed)
    assert eq.found.all()
    h = 1e-9
    lo = moment_about_confluence(af, cfg.aero, eq.alpha - h, speed)
    hi = moment_about_confluence(af, cfg.aero, eq.alpha + h, speed)
    assert np.all(lo >= 0.0) and np.all(hi <= 0.0)  # a falling zero crossing within 1e-9 rad
    d = 1e-5
    slope = (
        moment_about_confluence(af, cfg.aero, eq.alpha + d, speed)
        - moment_about_confluence(af, cfg.aero, eq.alpha - d, speed)
    ) / (2 * d)
    np.testing.assert_allclose(eq.moment_slope, slope, rtol=1e-9, atol=1e-6)
    wv = weathervane_slope(af, cfg.aero, eq.alpha, speed)
    ref = (
        aerodynamic_moment(af, cfg.aero, eq.alpha + d, speed, af.hull.xi_cb)
        - aerodynamic_moment(af, cfg.aero, eq.alpha - d, speed, af.hull.xi_cb)
    ) / (2 * d)
    np.testing.assert_allclose(wv, ref, rtol=1e-9, atol=1e-6)


def _plain_trim(af, aero, speed):
    """Reference trim of one column: the falling zero of the plain moment nearest alpha = 0
    on the 1-degree grid (then the wide one), refined by Brent's method to 1e-15 rad."""

    def m(a):
        return float(moment_about_confluence(af, aero, a, speed))

    for grid in (ALPHA_GRID, ALPHA_GRID_WIDE):
        g = np.array([m(a) for a in grid])
        down = np.flatnonzero((g[:-1] > 0.0) & (g[1:] <= 0.0))
        if down.size:
            k = down[np.argmin(np.abs(grid[down] + grid[down + 1]))]
            if g[k + 1] == 0.0:
                return grid[k + 1]
            return brentq(m, grid[k], grid[k + 1], xtol=1e-15, rtol=1e-15)
    return None


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    shape=st.sampled_from(["npl", "gnvr", "wang", "zhiyuan-1", "lotte", "sphere", "helikite"]),
    volume=st.floats(20.0, 2000.0),
    stall=st.floats(5.0, 40.0) | st.sampled_from([5.0, 8.0, 12.0, 20.0]),
    xi_offset=st.floats(-0.2, 0.2),
    speeds=st.lists(st.floats(0.0, 45.0), min_size=1, max_size=5),
)
def test_warm_started_trim_is_the_plain_root(shape, volume, stall, xi_offset, speeds):
    """The trim (grid bracket, inverse-cubic warm start, Illinois on the shrunk bracket) is
    the root a plain Brent solve finds in the same grid interval: the same root (within
    the 1e-12 rad tolerance) and the same choice of root, across the fin stall's kink (stall
    angles on and off the grid) and for columns whose trims need the wide grid."""
    req, cfg = thesis_baseline()
    cfg = replace(
        cfg,
        hull=HullSpec(shape=shape, volume=volume),
        aero=replace(cfg.aero, fin_stall_angle_deg=stall),
        confluence=replace(cfg.confluence, xi_offset=xi_offset),
    )
    af = build_airframe(req, cfg, volume)
    speed = np.asarray(speeds)
    eq = equilibrium(af, cfg.aero, speed)
    for i, u in enumerate(speed):
        ref = _plain_trim(af, cfg.aero, u)
        assert bool(eq.found[i]) == (ref is not None)
        if ref is not None:
            assert abs(eq.alpha[i] - ref) <= 1e-11


def test_a_wide_batch_marches_as_its_columns():
    """Every column of a batch is marched on its own: a wide batch gives the numbers of a
    narrow one."""
    rng = np.random.default_rng(3)
    n = 405
    spec = TetherSpec("t", 0.02, 0.005, 1.0, 0.01, 1e4, 1e6)
    tx0, tz0 = rng.uniform(10, 400, n), rng.uniform(200, 2000, n)
    heights = np.linspace(500.0, 0.0, 41)[:, None] * np.ones(n)
    speed = rng.uniform(0, 30, n)

    def wind(z):
        return speed * (np.maximum(z, 1.0) / 500.0) ** 0.14

    wide = march(tx0, tz0, 500.0, spec, 1.1, wind, heights, 0.15, 40)
    cols = slice(0, 7)

    def wind_cols(z):
        return speed[cols] * (np.maximum(z, 1.0) / 500.0) ** 0.14

    narrow = march(tx0[cols], tz0[cols], 500.0, spec, 1.1, wind_cols, heights[:, cols], 0.15, 40)
    for a, b in zip(wide, narrow):
        np.testing.assert_allclose(a[:, cols], b, rtol=1e-12, atol=1e-9)


@pytest.mark.parametrize("shape", ["sphere", "oblate", "helikite"])
def test_a_bluff_hull_trims_level(shape):
    """A drag-only hull's tether acts at its centre: it trims level (alpha = 0 to the
    root-finder's 1e-12 rad) at every wind, with the pendulum's restoring slope."""
    req, cfg = thesis_baseline()
    af = _airframe(req, replace(cfg, hull=HullSpec(shape=shape, volume=170.0)))
    eq = equilibrium(af, cfg.aero, np.linspace(0.0, 20.0, 5))
    assert eq.found.all() and np.all(np.abs(eq.alpha) <= 1e-12)
    assert np.all(eq.moment_slope < 0.0)


@pytest.mark.parametrize("shape", list(SHAPE_INFO))
@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    n=st.integers(1, 5),
    log_volume=st.floats(np.log(5.0), np.log(5e4)),
    area_change=st.floats(-50.0, 100.0),
    position=st.floats(0.6, 0.75),
    speeds=st.lists(st.floats(0.0, 45.0), min_size=1, max_size=4),
    superpressure=st.floats(0.0, 800.0),
    seed=st.integers(0, 2**16),
)
def test_envelope_beam_is_the_plain_beam(shape, n, log_volume, area_change, position, speeds,
                                         superpressure, seed):
    """The compiled station loop of ``envelope_loads`` gives the numpy reference's numbers
    (every key, to rounding) over hull shapes, batches of designs and speeds, for any trim."""
    req, cfg = thesis_baseline()
    lo, hi = SHAPE_INFO[shape].fineness_range
    cfg = replace(cfg, hull=replace(cfg.hull, shape=shape, fineness_ratio=0.5 * (lo + hi)),
                  gas=replace(cfg.gas, superpressure=superpressure))
    rng = np.random.default_rng(seed)
    vol = np.exp(log_volume) * rng.uniform(0.5, 2.0, n)
    af = build_airframe(req, cfg, vol, cfg.hull.fineness_ratio, area_change, position)
    ev = evaluate(req, cfg, af, np.array(speeds).reshape(-1, 1))
    got, ref = envelope_loads(af, cfg, ev), _envelope_loads_plain(af, cfg, ev)
    assert got.keys() == ref.keys()
    for k in ref:
        a, b = np.asarray(got[k]), np.asarray(ref[k])
        assert a.shape == b.shape, k
        scale = np.max(np.abs(b)) + 1e-300
        assert np.max(np.abs(a - b)) <= 1e-11 * scale, k
