"""Live cross-check of the point-aerostat mode against MoorDyn (optional: skipped when the
``moordyn`` package is not installed; it is not a project dependency)."""

import numpy as np
import pytest

from aerostat_core.dynamics import cases
from aerostat_core.dynamics.moordyn_check import moordyn_available, run_point_case
from aerostat_core.dynamics.simulate import SolverOptions, simulate, straight_state
from aerostat_core.dynamics.wind import SpeedSchedule, WindScenario

pytestmark = pytest.mark.skipif(not moordyn_available(), reason="moordyn not installed")


def test_step_case_matches_moordyn_within_1cm():
    """A shortened R3 (N = 16, 5 -> 10 m/s at 30 s, 60 s): positions within 1 cm."""
    schedule = SpeedSchedule((0.0, 30.0, 31.0), (5.0, 5.0, 10.0))
    md = run_point_case(cases.case_p_point(), cases.case_p_tether(16), schedule, 60.0,
                        cases.R3_TOP0, rho=cases.CASE_P_RHO, g=cases.CASE_P_G, dtm=4e-4,
                        dt_out=0.1)
    system = cases.case_p_system(16)
    res = simulate(system, WindScenario(schedule), 60.0,
                   SolverOptions(rtol=1e-7, atol_position=1e-6, atol_velocity=1e-6,
                                 output_interval=0.1),
                   initial_state=straight_state(system, cases.R3_TOP0))
    assert res.ok
    assert np.max(np.abs(res.signal("x_C") - np.interp(res.t, md["t"], md["x"]))) < 0.01
    assert np.max(np.abs(res.signal("z_C") - np.interp(res.t, md["t"], md["z"]))) < 0.01
