"""3-DOF dynamics of a tethered aerostat in varying, gust and turbulent wind (docs/dynamics.md).

Typical use::

    from aerostat_core import design, thesis_optimized
    from aerostat_core.dynamics import (Gust, SpeedSchedule, WindScenario, engine_guess,
                                        simulate, system_from_design)
    d = design(*thesis_optimized())
    system = system_from_design(d, segments=20)
    wind = WindScenario(SpeedSchedule.constant(10.0), gust=Gust(5.0, 0.0, 60.0, 20.0))
    res = simulate(system, wind, 150.0, guess=engine_guess(system, d, 10.0))
    res.signal("x_C"), res.signal("theta"), res.stats_table()

Modules: :mod:`.wind` (profiles, ramps, gusts, the wind kernels), :mod:`.turbulence` (MIL-HDBK-1797
Dryden field with IEC 61400-1 coherence), :mod:`.tether` (lumped-mass line), :mod:`.bodies`
(point aerostat, rigid hull), :mod:`.kernel` (equations of motion), :mod:`.system` (assembly),
:mod:`.solver` (TR-BDF2, banded Jacobian), :mod:`.simulate` (equilibrium, runs), :mod:`.results`
(time histories, statistics, events, limits), :mod:`.linearize` (modes), :mod:`.cases`
(reference cases R1-R4), :mod:`.thesis` (the thesis comparison), :mod:`.request` (the typed run
request, ``DynamicsRequest``: docs/dynamics.md §2.5), :mod:`.scenarios` (runs of a request: the
app and the CLI), :mod:`.moordyn_check` (live MoorDyn cross-check).

``simulate`` and ``linearize`` are the functions, also once their modules (of the same names) are
imported: the package keeps the function under the name and the module stays in ``sys.modules``
(``from aerostat_core.dynamics.simulate import straight_state`` works as before; reach a module
object with ``importlib.import_module("aerostat_core.dynamics.simulate")``).

Importing the package has no side effects. The numba kernels compile on first use and are cached
on disk (``cache=True``); the first :class:`DynamicSystem` of a process drops stale cache files
(:mod:`.kernel_cache`), and :func:`warm_up` compiles everything ahead (server start, image build).
"""

import sys
import types
from importlib import import_module

#: Public names -> the module that defines them (imported on first use: ``import
#: aerostat_core.dynamics`` loads neither numba nor a kernel).
_EXPORTS = {
    "HullModel": "bodies", "PointAerostat": "bodies", "ellipsoid_hull": "bodies",
    "hull_from_airframe": "bodies", "point_from_design": "bodies",
    "Linearization": "linearize", "Mode": "linearize", "linearize": "linearize",
    "SIGNALS": "results", "SimulationResult": "results", "response_metrics": "results",
    "signal_stats": "results", "Limits": "results", "limit_flags": "results",
    "SolverOptions": "options",
    "DynamicsRequest": "request", "GustSettings": "request", "SpeedChange": "request",
    "TurbulenceSettings": "request", "run_request": "scenarios",
    "engine_guess": "simulate", "equilibrium": "simulate", "simulate": "simulate",
    "straight_guess": "simulate", "straight_state": "simulate", "warm_kernels": "simulate",
    "Atmosphere": "system", "DynamicSystem": "system", "system_from_design": "system",
    "TetherModel": "tether",
    "DrydenTurbulence": "wind", "Gust": "wind", "MeanProfile": "wind", "SpeedSchedule": "wind",
    "WindScenario": "wind", "dryden_parameters": "wind",
    # 6-DOF (docs/dynamics.md §7)
    "Events6": "sixdof", "Hull6": "sixdof", "System6": "sixdof", "Wind3D": "sixdof",
    "simulate6": "sixdof", "system6_from_design": "sixdof", "Result6": "sixdof_results",
    "lateral_modes": "lateral", "lateral_sweep": "lateral",
    "static_lateral_derivatives": "lateral", "assess_lateral": "lateral_constraint",
    "lateral_stability": "lateral_constraint", "Request6": "scenarios6", "run6": "scenarios6",
}


#: Names that are both a function of the public API and the module defining it: the package
#: attribute stays the function (see :class:`_Package`).
FUNCTIONS_OVER_MODULES = frozenset({"simulate", "linearize"})


class _Package(types.ModuleType):
    """This package's module type: the import system binds every imported submodule as an
    attribute of its package (``aerostat_core.dynamics.simulate`` = the module), which would
    hide the function of the same name (the documented ``from aerostat_core.dynamics import
    simulate``); that binding is skipped for :data:`FUNCTIONS_OVER_MODULES`, so the name
    resolves through ``__getattr__`` to the function."""

    def __setattr__(self, name: str, value) -> None:
        if name in FUNCTIONS_OVER_MODULES and isinstance(value, types.ModuleType):
            return
        super().__setattr__(name, value)


sys.modules[__name__].__class__ = _Package


#: Old (British) names kept for one release (docs/architecture.md §7).
DEPRECATED_NAMES = {"Linearisation": "Linearization", "linearise": "linearize"}


def __getattr__(name: str):
    if name in _EXPORTS:
        return getattr(import_module(f".{_EXPORTS[name]}", __name__), name)
    if name in DEPRECATED_NAMES:
        import warnings

        new = DEPRECATED_NAMES[name]
        warnings.warn(f"{__name__}.{name} is deprecated; use {new} (US spelling)",
                      DeprecationWarning, stacklevel=2)
        return getattr(import_module(f".{_EXPORTS[new]}", __name__), new)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def warm_up() -> float:
    """Compile (or load from the disk cache) every numba kernel with tiny runs (a point case, a
    hull in spatial turbulence, a linearisation); returns the seconds it took."""
    import time

    from . import cases
    from .bodies import ellipsoid_hull
    from .linearize import linearize
    from .simulate import simulate, straight_state
    from .system import Atmosphere, DynamicSystem
    from .tether import TetherModel
    from .wind import DrydenTurbulence, SpeedSchedule, WindScenario

    t0 = time.perf_counter()
    system = cases.case_p_system(4)
    simulate(system, cases.r3_wind(), 1.0, initial_state=straight_state(system, (0.0, 319.5)))
    hull = ellipsoid_hull()
    hs = DynamicSystem(hull, TetherModel(length=300.0, segments=4), g=9.81,
                       atmosphere=Atmosphere(1.19))
    turb = WindScenario(SpeedSchedule.constant(5.0), turbulence=DrydenTurbulence(fade_in=0.0))
    simulate(hs, turb, 1.0, initial_state=straight_state(hs, (0.0, 300.3)))
    linearize(system, 5.0)
    return time.perf_counter() - t0


__all__ = sorted([*_EXPORTS, "warm_up"])
