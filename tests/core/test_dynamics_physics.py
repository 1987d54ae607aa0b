"""Wind-forcing physics (issue 11): the fluid acceleration for Froude-Krylov, no tether
compression, a reversed relative wind, budgets, and the package's structure (issue 10)."""

import ast
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from aerostat_core.dynamics import cases
from aerostat_core.dynamics.bodies import PointAerostat, fin_post_stall
from aerostat_core.dynamics.options import SolverOptions
from aerostat_core.dynamics.simulate import engine_guess, simulate, straight_state
from aerostat_core.dynamics.system import Atmosphere, DynamicSystem, system_from_design
from aerostat_core.dynamics.wind import DrydenTurbulence, Gust, SpeedSchedule, WindScenario

PKG = Path(__file__).resolve().parents[2] / "aerostat_core" / "dynamics"


@pytest.fixture(scope="module")
def design():
    return cases.thesis_design()


def _point_system(unsteady: bool) -> DynamicSystem:
    p = PointAerostat(
        mass=71.6,
        volume=120.0,
        drag_area=1.0,
        added_mass_coefficient=0.5,
        unsteady_wind_inertia=unsteady,
    )
    return DynamicSystem(p, cases.case_p_tether(8), g=9.81, atmosphere=Atmosphere(1.225))


@pytest.mark.parametrize("convected", [True, False])
def test_frozen_gust_gives_no_froude_krylov_force_on_a_body_carried_with_the_flow(convected):
    """A body moving with the air (v = U at its position) in the steepest part of a gust: the
    Froude-Krylov + added-mass force (1 + C_a) rho V DU/Dt is zero for a frozen convected gust
    (the air carrying it does not accelerate) and (1 + C_a) rho V dg/dt for a uniform one."""
    sc = WindScenario(
        SpeedSchedule.constant(10.0), gust=Gust(5.0, 0.0, 60.0, 20.0, "full", convected=convected)
    )
    on, off = _point_system(True), _point_system(False)
    field = sc.realize(319.5, 100.0, x_ref=0.0)
    y = straight_state(on, (0.0, 319.5))
    t = 23.0  # a quarter of the way: the gust's largest slope at the point
    b = on.hull_index
    ux = field.at(t, 319.5, x=0.0)
    y[b + 2] = ux[0][0]  # carried with the flow
    for i in range(1, on.tether.segments):  # the line too, so that no drag differs either
        k = 4 * (i - 1)
        y[k + 2] = field.at(t, y[k + 1], x=y[k])[0][0]
    dy_on, d_on = on.rhs(t, y, field)
    dy_off, _ = off.rhs(t, y, field)
    rho, vol = 1.225, 120.0
    meff = 71.6 + 0.5 * rho * vol + 0.5 * on.tether.node_mass
    expected = 0.0 if convected else 1.5 * rho * vol * ux[2][0] / meff
    assert dy_on[b + 2] - dy_off[b + 2] == pytest.approx(expected, abs=1e-9)
    assert abs(ux[2][0]) > 0.5  # the gust is steep there: dg/dt = 1.3 m/s2
    assert d_on["wind_accel_x"] == pytest.approx(0.0 if convected else ux[2][0], abs=1e-12)


def test_hull_in_a_frozen_gust_is_not_faster_than_the_gust(design):
    """Issue 11: with dU/dt fed to Froude-Krylov a hull in a 5 m/s gust peaked at 6.36 m/s."""
    system = system_from_design(design, segments=10)
    sc = WindScenario(SpeedSchedule.constant(10.0), gust=Gust(5.0, 0.0, 60.0, 20.0))
    res = simulate(system, sc, 80.0, guess=engine_guess(system, design, 10.0))
    assert res.ok
    assert 1.0 < np.max(res.signal("vx")) < 5.0


def test_uniform_ramp_keeps_the_inertia_force(design):
    """In a uniform speed change the air does accelerate: the force is on and changes the
    response (the default is on only where it is physical)."""
    sc = WindScenario(SpeedSchedule.step(10.0, 15.0, 5.0, 2.0))
    peaks = []
    for unsteady in (True, False):
        system = system_from_design(design, segments=10, unsteady_wind_inertia=unsteady)
        res = simulate(system, sc, 30.0, guess=engine_guess(system, design, 10.0))
        peaks.append(np.max(res.signal("vx")))
    assert peaks[0] > 1.2 * peaks[1]


def test_tether_carries_no_compression_and_slack_is_reported():
    """A line released 10 m short of its length (slack) with the point falling: no segment ever
    pushes, and the slack intervals are listed with their time and segment."""
    point = PointAerostat(unsteady_wind_inertia=False)
    teth = cases.case_p_tether(8)
    from dataclasses import replace

    teth = replace(teth, damper_compression=False)
    system = DynamicSystem(point, teth, g=9.81, atmosphere=Atmosphere(1.225))
    y = straight_state(system, (0.0, 310.0))
    y[system.hull_index + 3] = -3.0  # moving down: the damper would push
    res = simulate(system, WindScenario.steady(2.0), 20.0, initial_state=y)
    assert res.ok
    assert np.min(res.d("tension_min")) == 0.0
    ev = res.slack_events()
    assert ev and ev[0]["start_s"] == 0.0 and 1 <= ev[0]["segment"] <= 8
    assert ev[-1]["end_s"] < 20.0  # taut again once the point has risen
    assert "slack_events = segment" in res.to_csv()


def test_moordyn_convention_lets_the_damper_push():
    """The R cases use MoorDyn's convention (documented in cases.case_p_tether)."""
    system = cases.case_p_system(8)
    y = straight_state(system, (0.0, 310.0))
    y[system.hull_index + 3] = -3.0
    res = simulate(system, WindScenario.steady(2.0), 2.0, initial_state=y)
    assert np.min(res.d("tension_min")) < 0.0


def test_reversed_relative_wind_runs_through(design):
    """A -15 m/s gust at a 5 m/s mean blows from the tail: |alpha| passes 90 deg and the run
    goes on (the aerodynamic tables cover +-180 deg)."""
    system = system_from_design(design, segments=10)
    sc = WindScenario(SpeedSchedule.constant(5.0), gust=Gust(-15.0, 0.0, 20.0, 10.0))
    res = simulate(system, sc, 60.0, guess=engine_guess(system, design, 5.0))
    assert res.ok, res.message
    assert np.max(np.abs(res.signal("alpha"))) > 90.0


def test_aero_tables_are_valid_over_the_whole_circle(design):
    """Axial drag opposes the axial wind; the post-stall fin model is continuous at stall and
    gives zero lift with the wind along the fins (0 and 180 deg)."""
    hull = system_from_design(design, segments=4).body
    a0, da = hull.alpha_grid
    alpha = a0 + da * np.arange(hull.tables.shape[1])
    ax = hull.tables[3]
    assert np.all(ax[np.abs(alpha) < 0.5 * math.pi - 1e-6] > 0)
    assert np.all(ax[np.abs(alpha) > 0.5 * math.pi + 1e-6] < 0)
    lift = hull.tables[4]
    assert np.max(np.abs(np.diff(lift))) < 1e-3 * np.max(np.abs(lift))  # continuous
    assert abs(lift[np.argmin(np.abs(alpha - math.pi))]) < 1e-6 * np.max(np.abs(lift))
    a = np.linspace(-math.pi, math.pi, 3601)
    ln, dr = fin_post_stall(a, 2.0 * a.clip(-0.35, 0.35), 0.1 + 0 * a, 0.35, 1.0, 2.0)
    assert np.all(dr >= 0.1 - 1e-12)
    assert dr.max() == pytest.approx(0.1 + 1.146 * (1.0 - math.sin(0.35) ** 2), abs=1e-3)


def test_output_grid_beyond_the_memory_cap_is_refused():
    system = cases.case_p_system(8)
    with pytest.raises(ValueError, match="duration = 100000 s.*output_interval = 0.001 s"):
        simulate(
            system,
            WindScenario.steady(5.0),
            1e5,
            SolverOptions(output_interval=1e-3),
            initial_state=straight_state(system, cases.R3_TOP0),
        )


def test_wall_clock_budget_stops_a_long_run(design):
    system = system_from_design(design, segments=20)
    sc = WindScenario(SpeedSchedule.constant(10.0), turbulence=DrydenTurbulence(seed=1))
    res = simulate(
        system,
        sc,
        600.0,
        SolverOptions(wall_time_limit=0.05),
        guess=engine_guess(system, design, 10.0),
    )
    assert res.status == 8 and "wall-clock" in res.message
    assert res.stats["t_end"] < 600.0 and res.t.size > 1


# --- structure (issue 10) --------------------------------------------------------------------
def test_importing_the_package_has_no_side_effects():
    code = (
        "import sys, aerostat_core.dynamics as d; from aerostat_core.dynamics import "
        "kernel_cache as k; assert 'numba' not in sys.modules, 'numba imported'; "
        "assert not k._DONE, 'cache touched'"
    )
    subprocess.run([sys.executable, "-c", code], check=True, cwd=PKG.parents[1])


def test_no_private_imports_and_small_files():
    for path in PKG.glob("*.py"):
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.level >= 1:
                assert not (node.module or "").split(".")[-1].startswith("_"), (path, node.module)
                for alias in node.names:
                    assert not alias.name.startswith("_"), (path.name, alias.name)
        assert len(path.read_text().splitlines()) < 800, path.name


def test_integrator_is_not_tied_to_the_model_indices():
    """The solver reads no model parameter or state index: only rhs/check and opaque data."""
    tree = ast.parse((PKG / "solver.py").read_text())
    imported = {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom) and n.level}
    assert imported == {"kernel"}
    names = {n.id for n in ast.walk(tree) if isinstance(n, ast.Name)}
    assert not any(n.startswith(("P_", "W_", "T_")) for n in names - {"W_COEF"})  # TR-BDF2 w
    assert not any("wind" in n for n in names)
