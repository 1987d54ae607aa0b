"""3-DOF dynamics of a tethered aerostat in varying, gust and turbulent wind (docs/dynamics.md).

Typical use::

    from aerostat_core import design, thesis_optimised
    from aerostat_core.dynamics import (Gust, SpeedSchedule, WindScenario, engine_guess,
                                        simulate, system_from_design)
    d = design(*thesis_optimised())
    system = system_from_design(d, segments=20)
    wind = WindScenario(SpeedSchedule.constant(10.0), gust=Gust(5.0, 0.0, 60.0, 20.0))
    res = simulate(system, wind, 150.0, guess=engine_guess(system, d, 10.0))
    res.signal("x_C"), res.signal("theta"), res.stats_table()

Modules: :mod:`.wind` (profiles, ramps, gusts, Dryden), :mod:`.tether` (lumped-mass line),
:mod:`.model` (point aerostat, rigid hull, system assembly), :mod:`.solver` (TR-BDF2, banded
Jacobian), :mod:`.simulate` (equilibrium, runs, results, summaries), :mod:`.linearise` (modes),
:mod:`.cases` (reference cases R1-R4 and the thesis design), :mod:`.moordyn_check` (optional
cross-check). The numba kernels compile on first use and are cached on disk (``cache=True``);
:func:`warm_up` compiles them ahead (e.g. when building a container image).
"""

from ._cache import ensure_fresh_cache

ensure_fresh_cache()

from .linearise import Linearisation, Mode, linearise  # noqa: E402
from .model import (  # noqa: E402
    Atmosphere,
    DynamicSystem,
    HullModel,
    PointAerostat,
    ellipsoid_hull,
    hull_from_airframe,
    system_from_design,
)
from .simulate import (  # noqa: E402
    SIGNALS,
    SimulationResult,
    SolverOptions,
    engine_guess,
    equilibrium,
    response_metrics,
    signal_stats,
    simulate,
    straight_guess,
    straight_state,
)
from .tether import TetherModel  # noqa: E402
from .wind import (  # noqa: E402
    DrydenTurbulence,
    Gust,
    MeanProfile,
    SpeedSchedule,
    WindScenario,
    dryden_parameters,
)


def warm_up() -> None:
    """Compile (or load from the disk cache) every numba kernel with two tiny runs."""
    from . import cases

    system = cases.case_p_system(4)
    simulate(system, cases.r3_wind(), 1.0, initial_state=straight_state(system, (0.0, 319.5)))
    hull = ellipsoid_hull()
    hs = DynamicSystem(hull, TetherModel(length=300.0, segments=4), g=9.81,
                       atmosphere=Atmosphere(1.19))
    turb = WindScenario(SpeedSchedule.constant(5.0), turbulence=DrydenTurbulence(fade_in=0.0))
    simulate(hs, turb, 1.0, initial_state=straight_state(hs, (0.0, 300.3)))
    linearise(system, 5.0)


__all__ = [
    "SIGNALS", "Atmosphere", "DrydenTurbulence", "DynamicSystem", "Gust", "HullModel",
    "Linearisation", "MeanProfile", "Mode", "PointAerostat", "SimulationResult", "SolverOptions",
    "SpeedSchedule", "TetherModel", "WindScenario", "dryden_parameters", "ellipsoid_hull",
    "engine_guess", "equilibrium", "hull_from_airframe", "linearise", "response_metrics",
    "signal_stats", "simulate", "straight_guess", "straight_state", "system_from_design",
    "warm_up",
]
