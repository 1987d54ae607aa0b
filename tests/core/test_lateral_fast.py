"""The fast lateral sweep (issue 24 item 1, docs/dynamics.md §7.5) against the dense reference.

The constraint row "laterally stable up to the survival wind" takes the fast path of
:func:`aerostat_core.dynamics.lateral.lateral_sweep`: one vectorised static-engine call for the
starting points of every wind speed, the 3-DOF equilibrium continued from the previous speed,
the 6-DOF polish skipped when the 3-DOF equilibrium already balances the 6-DOF model, and only
the lateral columns of the Jacobian. ``reference=True`` is the computation as it was (per speed:
its own engine call, the 6-DOF Newton polish, the whole central-difference Jacobian). Both
linearise at every speed of the same grid, so they must agree speed by speed: the largest real
part of the lateral eigenvalues to 1e-6 1/s (the finite-difference Jacobian's own noise is
~1e-7 1/s, the instability threshold 1e-5 1/s), hence the same stable/unstable verdict at each
speed and the same instability speed to 1e-4 m/s (the linear interpolation between the
bracketing speeds moves by the change of the real parts over their slope).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from aerostat_core import Requirement, design
from aerostat_core.dynamics import lateral as lat
from aerostat_core.dynamics.lateral_constraint import clear_cache, lateral_stability
from aerostat_core.dynamics.sixdof import system6_from_design
from aerostat_core.model.presets import practice_configuration

#: Agreement of the largest real part at each speed [1/s].
REAL_TOL = 1e-6
#: Agreement of the instability speed [m/s].
SPEED_TOL = 1e-4


def _design(area_change: float, position: float, survival_wind: float):
    """80 m3 given, confluence point aft and low (the layout of test_lateral_constraint, where
    small fins kite): fin area change [%], fin position [-] and the survival wind [m/s]."""
    c = practice_configuration(volume=80.0)
    cfg = replace(c, fins=replace(c.fins, area_change=area_change, position=position),
                  confluence=replace(c.confluence, xi_offset=0.2, drop_ratio=2.0))
    return design(Requirement(survival_wind=survival_wind), cfg)


def _compare(d) -> bool:
    """Fast and reference sweeps of ``d`` agree; False (nothing more checked) when a speed's
    real part lies within the tolerance of the threshold, where either verdict is right."""
    system = system6_from_design(d, segments=lat.SWEEP_SEGMENTS)
    ref, above_ref = lat.lateral_sweep(d, system=system, reference=True)
    fast, above_fast = lat.lateral_sweep(d, system=system)
    assert [a.speed for a in fast] == [a.speed for a in ref]
    real_ref = np.array([a.max_real for a in ref])
    real_fast = np.array([a.max_real for a in fast])
    np.testing.assert_allclose(real_fast, real_ref, rtol=0.0, atol=REAL_TOL)
    if np.any(np.abs(real_ref - lat.UNSTABLE_TOL) <= REAL_TOL):
        return False
    assert [a.stable for a in fast] == [a.stable for a in ref]
    assert (above_fast is None) == (above_ref is None)
    if above_ref is not None:
        assert above_fast == pytest.approx(above_ref, abs=SPEED_TOL)
    # the slow modes of the table too (frequency and damping of the least stable ones)
    for a, b in zip(fast, ref):
        assert len(a.modes) == len(b.modes)
        for m, n in zip(a.modes, b.modes):
            assert abs(m.eigenvalue - n.eigenvalue) < 1e-5
    return True


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(area=st.floats(-45.0, 10.0), position=st.floats(0.62, 0.74),
       survival=st.floats(10.0, 24.0))
def test_fast_sweep_agrees_with_the_dense_reference(area, position, survival) -> None:
    assume(_compare(_design(area, position, survival)))


@pytest.mark.parametrize("area", [-40.0, 0.0])
def test_fast_sweep_agrees_on_a_kiting_and_a_stable_hull(area) -> None:
    """-40 % fins: a lateral mode unstable from 2 m/s that turns stable again at 7 m/s (the
    case a coarse grid with bisection would get wrong); 0 %: stable throughout."""
    d = _design(area, 0.68, 20.0)
    assert _compare(d)
    analyses, above = lat.lateral_sweep(d, system=system6_from_design(d, segments=8))
    stable = [a.stable for a in analyses]
    if area < 0:
        assert above == 2.0 and not stable[0] and stable[-1]
    else:
        assert above is None and all(stable)


def test_unstable_above_interpolates_inside_the_grid() -> None:
    """The fast path reports the reference's interpolated crossing on a grid where the mode goes
    unstable between two speeds (the kiting hull swept from 9 m/s down: stable above 7 m/s, unstable below)."""
    d = _design(-40.0, 0.68, 20.0)
    system = system6_from_design(d, segments=8)
    speeds = np.arange(9.0, 1.5, -1.0)
    ref, above_ref = lat.lateral_sweep(d, speeds, system=system, reference=True)
    fast, above_fast = lat.lateral_sweep(d, speeds, system=system)
    assert above_ref is not None and 2.0 < above_ref < 9.0
    assert above_fast == pytest.approx(above_ref, abs=SPEED_TOL)


def test_default_sweep_is_shared_by_the_row_and_the_views() -> None:
    """The constraint row, the app's 6-DOF view and ``simulate --dof 6`` of one design share one
    sweep per frozen inputs; its states are read-only."""
    clear_cache()
    d = _design(0.0, 0.68, 20.0)
    lateral_stability(d)
    first = lat.lateral_sweep(d)
    assert lat.lateral_sweep(d) is first
    assert lat.cached_sweep(d) is first
    with pytest.raises(ValueError):
        first[0][0].state[0] = 1.0
    clear_cache()
    assert lat.lateral_sweep(d) is not first


@pytest.mark.parametrize("segments", [3, 8, 20])
def test_grouped_lateral_jacobian_is_the_dense_one_to_the_last_bit(segments) -> None:
    """The lateral columns differenced in groups (the line is local) give exactly the lateral
    block of the whole central-difference Jacobian: same increments, and an equation outside a
    column's group does not read that column's state."""
    from aerostat_core.dynamics.sixdof import Wind3D, initial_state6

    d = _design(-40.0, 0.68, 20.0)
    system = system6_from_design(d, segments=segments)
    wind = Wind3D.steady(6.0)
    field_ = wind.base.realize(system.tether.length, 60.0)
    data = system.data(field_, wind)
    y = initial_state6(system, wind, d, field_, data)
    idx = lat.lateral_indices(system)
    dense = lat.jacobian6(system, data, y)[np.ix_(idx, idx)]
    grouped = lat.lateral_jacobian(system, data, y)
    assert np.count_nonzero(dense) > idx.size  # a real coupled block
    np.testing.assert_array_equal(grouped, dense)
