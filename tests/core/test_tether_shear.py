"""Sheared-wind tether: the accelerated height passes reach the plain fixed point.

solve_tether iterates the node heights at which the wind is looked up (power or log profile)
with an Anderson step; its answer must be the fixed point of the plain iteration: re-marching
with the returned heights gives them back, and a far tighter solve gives the same top height.
"""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from aerostat_core import TetherSpec
from aerostat_core.atmosphere.wind import profile_speed
from aerostat_core.model.inputs import WindProfile
from aerostat_core.tether.statics import interpolated_heights, march, solve_tether

SPEC = TetherSpec("t", 0.02, 0.006, 1.2, 0.01, 1.6e4, 2.0e6)  # 20 g/m, 6 mm
TOL = 1e-6

profiles = st.one_of(
    st.builds(lambda p: WindProfile("power", exponent=p), st.floats(0.08, 0.4)),
    st.builds(lambda z0: WindProfile("log", roughness_length=z0), st.floats(0.005, 1.0)),
)


def _case(profile, length, drag, lift, speeds, drag_follows_wind):
    """A line with net lift above its weight in a sheared wind; returns the solve's
    inputs. With ``drag_follows_wind`` the aerostat's drag goes with the wind at its height
    (the point-aerostat model), so the top tension depends on the iterated top height too."""
    rho = 1.2
    w = SPEC.linear_density * 9.81
    speeds = np.asarray(speeds, float)

    def wind(z, h):
        return profile_speed(profile, z, speeds, h)

    if drag_follows_wind:

        def top(h):
            u = profile_speed(profile, h, speeds, 0.8 * length)  # speeds at 0.8 L
            return drag * (u / 10.0) ** 2, lift * np.ones_like(u)
    else:

        def top(h):
            return drag * (speeds / 10.0) ** 2, lift * np.ones_like(speeds)

    return top, length, SPEC, rho, wind, w


@settings(max_examples=60, deadline=None)
@given(
    profile=profiles,
    length=st.floats(100.0, 1200.0),
    drag=st.floats(5.0, 400.0),
    lift_margin=st.floats(1.3, 20.0),
    speeds=st.lists(st.floats(0.0, 30.0), min_size=1, max_size=4),
    drag_follows_wind=st.booleans(),
)
def test_converged_heights_are_the_plain_fixed_point(
    profile, length, drag, lift_margin, speeds, drag_follows_wind
):
    lift = lift_margin * SPEC.linear_density * 9.81 * length
    top, length, spec, rho, wind, w = _case(profile, length, drag, lift, speeds, drag_follows_wind)
    ref = solve_tether(top, length, spec, rho, wind, w, 50, sheared=True, max_passes=60, tol=1e-12)
    # a slack line sags onto the winch's level, where the heights are clipped and the passes
    # need not settle (plain or accelerated): that is the taut_tether constraint's domain
    assume(not np.any(ref.slack))
    # 30 passes as point_aerostat_tether allows: a nearly blown-down line can contract slowly
    # enough that 8 (performance.evaluate) stop before the tolerance (plain passes more so)
    sol = solve_tether(top, length, spec, rho, wind, w, 50, sheared=True, max_passes=30)
    # self-consistent: one more plain pass with the returned heights reproduces them (heights
    # below the winch, where a slack line sags under it, are looked up at 0 as in the solve)
    heights = np.maximum(sol.z, 0.0)
    tx0, tz0 = top(sol.height)
    _, _, _, z = march(tx0, tz0, length, spec, rho, lambda zz: wind(zz, sol.height), heights, w, 50)
    assert np.max(np.abs(np.maximum(z - z[-1], 0.0) - heights)) < TOL
    # the same fixed point as a far tighter solve
    assert np.max(np.abs(sol.height - ref.height)) < TOL
    assert np.max(np.abs(sol.blow_by - ref.blow_by)) < 10 * TOL
    # a height error of tol moves the line drag and so the tension by ~1e-8 of it on a short
    # line, plus (drag_follows_wind) the top tension's own change with the top height
    top_shift = np.hypot(
        *(
            np.asarray(a) - np.asarray(b)
            for a, b in zip(top(sol.height), top(ref.height), strict=True)
        )
    )
    assert np.all(
        np.abs(sol.tension - ref.tension) < 1e-7 * np.max(ref.tension, axis=0) + 2.0 * top_shift
    )


def test_uniform_wind_takes_one_pass_and_sheared_converges_in_few():
    # predicted: a uniform wind needs no height passes; a 1/7 power law on a 300 m line
    # reaches the 1e-6 m tolerance in at most 6 marches (plain passes took 7-8)
    calls = []

    def counting(z, h):
        calls.append(1)
        return profile_speed(WindProfile("power"), z, np.array([5.0, 10.0, 20.0]), h)

    top = lambda h: (np.array([10.0, 40.0, 160.0]), np.array([600.0, 600.0, 600.0]))  # noqa: E731
    w = SPEC.linear_density * 9.81
    solve_tether(top, 300.0, SPEC, 1.2, counting, w, 50, sheared=False)
    assert len(calls) == 1
    calls.clear()
    solve_tether(top, 300.0, SPEC, 1.2, counting, w, 50, sheared=True)
    assert 2 <= len(calls) <= 6


# --- warm starts (heights_hint) ---------------------------------------------------------------


class _Counted:
    """The march, counted (each is the cost of one height pass)."""

    def __init__(self, monkeypatch):
        from aerostat_core.tether import statics as tether

        self.n = 0
        plain = tether.march

        def counted(*args, **kwargs):
            self.n += 1
            return plain(*args, **kwargs)

        monkeypatch.setattr(tether, "march", counted)


def _taut_case(profile=None, speeds=(5.0, 12.0, 20.0), lift=600.0):
    profile = WindProfile("power") if profile is None else profile
    return _case(profile, 300.0, 40.0, lift, speeds, drag_follows_wind=False)


@settings(max_examples=40, deadline=None)
@given(
    profile=profiles,
    length=st.floats(100.0, 1200.0),
    drag=st.floats(5.0, 400.0),
    lift_margin=st.floats(1.3, 20.0),
    speeds=st.lists(st.floats(0.0, 30.0), min_size=1, max_size=4),
    error=st.floats(-0.3, 0.3),
    bend=st.floats(-0.3, 0.3),
)
def test_a_hint_reaches_the_same_fixed_point(
    profile, length, drag, lift_margin, speeds, error, bend
):
    # a hint off by up to 30 % of the line (a scale and a bend, either way) converges to the
    # fixed point of the vertical start: a hint costs passes, never the answer
    lift = lift_margin * SPEC.linear_density * 9.81 * length
    args = _case(profile, length, drag, lift, speeds, drag_follows_wind=True)
    ref = solve_tether(*args, 50, sheared=True, max_passes=60, tol=1e-12)
    assume(not np.any(ref.slack))
    frac = np.linspace(1.0, 0.0, 51).reshape((-1,) + (1,) * ref.z.ndim)[..., 0]
    hint = ref.z * (1.0 + error) + bend * length * frac * (1.0 - frac)
    sol = solve_tether(*args, 50, sheared=True, max_passes=30, heights_hint=hint)
    cold = solve_tether(*args, 50, sheared=True, max_passes=30)
    assert np.max(np.abs(sol.height - ref.height)) < TOL
    assert np.max(np.abs(sol.z - ref.z)) < 2 * TOL
    assert np.max(np.abs(sol.z - cold.z)) < 2 * TOL


def test_bad_hints_still_converge_and_wrong_shapes_are_named():
    args = _taut_case()
    ref = solve_tether(*args, 50, sheared=True, max_passes=60, tol=1e-12)
    bad = {
        "all at the winch": np.zeros((51, 1)),
        "far above the line": np.full((51, 1), 5000.0),
        "below the winch": np.full((51, 1), -50.0),
        "one column not finite": np.where(np.arange(3) == 1, np.nan, ref.z),
    }
    for label, hint in bad.items():
        sol = solve_tether(*args, 50, sheared=True, max_passes=30, heights_hint=hint)
        assert np.max(np.abs(sol.z - ref.z)) < 2 * TOL, label
    with pytest.raises(ValueError, match="heights_hint"):
        solve_tether(*args, 50, sheared=True, heights_hint=np.zeros((50, 3)))


def test_marches_with_and_without_a_hint(monkeypatch):
    # predicted: a uniform wind ignores the hint (one march, the same numbers); the exact
    # heights as the hint take 1-2 marches (one to check them, at most one more), a hint
    # 1 % off takes fewer marches than the vertical line
    args = _taut_case()
    ref = solve_tether(*args, 50, sheared=True, max_passes=60, tol=1e-12)
    count = _Counted(monkeypatch)
    plain = solve_tether(*args, 50, sheared=False)
    with_hint = solve_tether(*args, 50, sheared=False, heights_hint=ref.z * 0.5)
    assert count.n == 2
    assert np.array_equal(plain.z, with_hint.z)
    count.n = 0
    solve_tether(*args, 50, sheared=True)
    cold = count.n
    count.n = 0
    solve_tether(*args, 50, sheared=True, heights_hint=ref.z)
    assert count.n <= 2
    count.n = 0
    sol = solve_tether(
        *args, 50, sheared=True, heights_hint=lambda tx, tz: ref.z * np.array([1.0, 0.99, 1.01])
    )
    assert count.n < cold
    assert np.max(np.abs(sol.z - ref.z)) < 2 * TOL


def test_interpolated_heights_pass_through_the_known_lines():
    # Lagrange in the top elevation: at a known line's own top tension the estimate is that
    # line (its rises are rebuilt from its elevations and its stretch part exactly)
    top, length, spec, rho, wind, w = _taut_case()
    sol = solve_tether(top, length, spec, rho, wind, w, 50, sheared=True, tol=1e-10)
    tx, tz = top(sol.height)
    z = interpolated_heights(tx, tz, sol.elevation[:, None], sol.z[:, None], length)
    assert np.max(np.abs(z - sol.z)) < 1e-9
    z = interpolated_heights(tx, tz, sol.elevation, sol.z, length, vertical=True)
    assert np.max(np.abs(z - sol.z)) < 1e-9
    # and between them it is a start a few metres off at worst on this 300 m line
    mid = interpolated_heights(
        0.5 * (tx[:-1] + tx[1:]),
        0.5 * (tz[:-1] + tz[1:]),
        sol.elevation,
        sol.z,
        length,
        vertical=True,
    )
    between = solve_tether(
        lambda h: (0.5 * (tx[:-1] + tx[1:]), 0.5 * (tz[:-1] + tz[1:])),
        length,
        spec,
        rho,
        lambda zz, h: profile_speed(WindProfile("power"), zz, np.array([8.5, 16.0]), h),
        w,
        50,
    )
    assert np.max(np.abs(mid - between.z)) < 5.0


def test_a_slack_column_does_not_hold_up_the_batch(monkeypatch):
    # a line with less net lift than its own weight lies on the ground: its clipped heights
    # need not settle. Batched with a taut line, the taut one's answer is the same as alone,
    # and the batch stops when the taut one has converged
    rho, w = 1.2, SPEC.linear_density * 9.81
    profile = WindProfile("power")
    speeds = np.array([10.0, 10.0])

    def wind(z, h):
        return profile_speed(profile, z, speeds, h)

    def top(h):
        return np.array([40.0, 40.0]), np.array([600.0, 0.3 * w * 300.0])

    count = _Counted(monkeypatch)
    both = solve_tether(top, 300.0, SPEC, rho, wind, w, 50, sheared=True)
    n_both = count.n
    count.n = 0
    alone = solve_tether(
        lambda h: (40.0, 600.0),
        300.0,
        SPEC,
        rho,
        lambda z, h: profile_speed(profile, z, 10.0, h),
        w,
        50,
        sheared=True,
    )
    assert bool(both.slack[1]) and not bool(both.slack[0])
    assert abs(both.height[0] - alone.height) < TOL
    assert np.max(np.abs(both.z[:, 0] - alone.z)) < 2 * TOL
    assert n_both <= max(count.n, 2)


def test_warm_starts_do_not_change_a_sheared_design(monkeypatch):
    # the design with every warm start replaced by the vertical line (a non-finite hint):
    # the same sized volume, binding constraint, feasibility and violations, and every
    # height within the passes' tolerance
    import importlib
    from dataclasses import replace

    from aerostat_core.model import sizing
    from aerostat_core.model.design import design
    from aerostat_core.model.inputs import Requirement
    from aerostat_core.model.presets import rules_configuration

    for kind in ("power", "log"):
        req = Requirement(payload_mass=10, altitude=300)
        cfg = replace(rules_configuration("practice"), wind_profile=WindProfile(kind))
        design_module = importlib.import_module("aerostat_core.model.design")
        with monkeypatch.context() as m:
            count = _Counted(m)
            warm = design(req, cfg)
            n_warm, count.n = count.n, 0
            nan = lambda tx, tz, *a, **k: np.full((51,) + np.shape(tx), np.nan)  # noqa: E731
            m.setattr(sizing, "interpolated_heights", nan)
            m.setattr(design_module, "interpolated_heights", nan)
            cold = design(req, cfg)
        assert n_warm < count.n  # the warm starts were taken, and pay
        assert warm.volume == cold.volume
        assert warm.summary()["binding_constraint"] == cold.summary()["binding_constraint"]
        assert warm.feasible == cold.feasible and warm.violations == cold.violations
        assert np.max(np.abs(warm.tether_z - cold.tether_z)) < 2 * TOL
        assert np.max(np.abs(warm.performance.blow_by - cold.performance.blow_by)) < 10 * TOL
