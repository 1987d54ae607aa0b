"""The integrator: Jacobian band structure, banded LU, grid and tolerance convergence (V5, V6),
scipy cross-check, budgets (docs/dynamics.md §1.8, §3.1)."""

import math

import numpy as np
import pytest

from aerostat_core.dynamics import cases
from aerostat_core.dynamics.simulate import (
    SolverOptions,
    engine_guess,
    equilibrium,
    response_metrics,
    simulate,
    straight_guess,
)
from aerostat_core.dynamics.solver import band_lu, band_pack, band_solve
from aerostat_core.dynamics.system import dense_jacobian, system_from_design
from aerostat_core.dynamics.wind import Gust, SpeedSchedule, WindScenario


@pytest.fixture(scope="module")
def design():
    return cases.thesis_design()


@pytest.mark.parametrize("hull", [False, True])
def test_jacobian_band_contains_every_coupling(design, hull):
    """The declared (kl, ku) band holds every nonzero of a dense finite-difference Jacobian, at a
    generic state with every segment taut and every velocity nonzero."""
    system = system_from_design(design, segments=8) if hull else cases.case_p_system(8)
    field = WindScenario.steady(8.0).realize(300.0, 10.0)
    guess = engine_guess(system, design, 8.0) if hull else straight_guess(system, field)
    y, _ = equilibrium(system, field, guess)
    rng = np.random.default_rng(1)
    y = y + rng.normal(scale=0.05, size=y.size)
    jac = dense_jacobian(system, y, field)
    kl, ku = system.structure()
    i, j = np.nonzero(np.abs(jac) > 1e-12 * np.abs(jac).max())
    assert np.max(i - j) == kl
    assert np.max(j - i) == ku


def test_band_lu_matches_dense_solve():
    rng = np.random.default_rng(0)
    n, kl, ku = 40, 5, 3
    a = np.zeros((n, n))
    for i in range(n):
        for j in range(max(0, i - kl), min(n, i + ku + 1)):
            a[i, j] = rng.normal()
    b = rng.normal(size=n)
    work = band_pack(a, kl, ku)  # compact storage; the fill-in columns start at zero
    assert work.shape == (n, 2 * kl + ku + 1)
    piv = np.zeros(n, np.int64)
    assert band_lu(work, n, kl, ku, piv)
    x = b.copy()
    band_solve(work, n, kl, ku, piv, x)
    assert x == pytest.approx(np.linalg.solve(a, b), rel=1e-9, abs=1e-9)


def _step_run(system, design, opt=None):
    return simulate(system, WindScenario(SpeedSchedule.step(8.0, 11.0, 5.0, 3.0)), 90.0,
                    opt or SolverOptions(rtol=1e-7, atol_position=1e-6, atol_velocity=1e-6,
                                         atol_angle=1e-8),
                    guess=engine_guess(system, design, 8.0))


def test_v5_grid_convergence(design):
    """N = 10, 20, 40: steady x_C, z_C change < 0.1 % (20 -> 40); step-response peak < 1 %."""
    out = {}
    for n in (10, 20, 40):
        system = system_from_design(design, segments=n)
        res = _step_run(system, design)
        assert res.ok, res.message
        x = res.signal("x_C")
        out[n] = (x[0], res.signal("z_C")[0], x.max(), res.signal("theta").max())
    for k in range(2):
        assert out[40][k] == pytest.approx(out[20][k], rel=1e-3)
        assert out[20][k] == pytest.approx(out[10][k], rel=2e-3)
    assert out[40][2] == pytest.approx(out[20][2], rel=1e-2)
    assert out[40][3] == pytest.approx(out[20][3], rel=1e-2)


@pytest.fixture(scope="module")
def gust_runs(design):
    system = system_from_design(design, segments=10)
    sc = WindScenario(SpeedSchedule.constant(10.0), gust=Gust(4.0, 0.0, 40.0, 5.0))
    guess = engine_guess(system, design, 10.0)
    runs = {}
    for key, opt in (
        ("tight", SolverOptions(rtol=1e-8, atol_position=1e-7, atol_velocity=1e-7,
                                atol_angle=1e-9, output_interval=0.1)),
        ("default", SolverOptions(rtol=1e-6, atol_position=1e-5, atol_velocity=1e-5,
                                  output_interval=0.1)),
        ("radau", SolverOptions(method="Radau", rtol=1e-7, atol_position=1e-6, atol_velocity=1e-6,
                                atol_angle=1e-8, output_interval=0.1)),
    ):
        res = simulate(system, sc, 40.0, opt, guess=guess)
        assert res.ok, (key, res.message)
        runs[key] = res
    return runs


@pytest.mark.parametrize("other", ["default", "radau"])
def test_v6_tolerance_and_method(gust_runs, other):
    """rtol 1e-6 vs 1e-8 and TR-BDF2 vs scipy's Radau: time histories within 0.1 % of each
    signal's range."""
    ref, res = gust_runs["tight"], gust_runs[other]
    assert res.t.size == ref.t.size
    for name in ("x_C", "z_C", "theta", "vx", "tension_C"):
        a, b = ref.signal(name), res.signal(name)
        scale = max(np.ptp(a), 1e-3 * np.max(np.abs(a)))
        assert np.max(np.abs(a - b)) < 1e-3 * scale, name


def test_budgets_stop_with_status(design):
    system = system_from_design(design, segments=10)
    res = simulate(system, WindScenario.steady(10.0), 100.0, SolverOptions(max_steps=20),
                   guess=engine_guess(system, design, 10.0))
    assert res.status == 9 and "step budget" in res.message
    res = simulate(system, WindScenario(SpeedSchedule.constant(10.0), gust=Gust()), 300.0,
                   SolverOptions(wall_time_limit=1e-3),
                   guess=engine_guess(system, design, 10.0))
    assert res.status == 8 and "wall-clock" in res.message
    assert res.t.size >= 1


def test_options_validation():
    with pytest.raises(ValueError, match="rtol"):
        SolverOptions(rtol=0.5)
    with pytest.raises(ValueError, match="method"):
        SolverOptions(method="Euler")


def test_response_metrics_step_and_gust():
    t = np.linspace(0, 100, 1001)
    step = 1 - np.exp(-0.1 * t) * np.cos(0.3 * t)
    m = response_metrics(t, step, 0.0, 0.05, final=1.0)
    tp = (math.pi - math.atan(0.1 / 0.3)) / 0.3  # first peak of 1 - exp(-0.1 t) cos(0.3 t)
    peak = 1 - math.exp(-0.1 * tp) * math.cos(0.3 * tp)
    assert m.overshoot == pytest.approx(100 * (peak - 1), rel=0.01)
    gust = np.exp(-0.1 * t) * np.sin(0.3 * t)
    g = response_metrics(t, gust, 0.0, 0.05, final=0.0)
    assert g.overshoot is None and g.band == pytest.approx(0.05 * np.max(np.abs(gust)))
