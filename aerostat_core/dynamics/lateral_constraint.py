"""The constraint row "laterally stable up to the survival wind" (docs/dynamics.md §7.5): the
6-DOF lateral-stability result of a sized design, which fills its row of the one constraint
table (:mod:`aerostat_core.model.constraints`, row ``lateral_stability``).

The row needs the 6-DOF model linearised at each wind speed of the sweep (about 25 ms of CPU
for a design once the compiled kernels are loaded), so the static engine's vectorised table,
which sizing and the optimiser evaluate thousands of times, leaves it "not evaluated", and
:func:`assess_lateral` fills it for the finished design. The CLI, the report and the app show
assessed designs. Whether the row is checked is the rule set's
(``RuleSet.check_lateral_stability``: on in the practice rules, off in the thesis rules); the
static lateral derivatives at the design wind are given for every rule set.
"""

from __future__ import annotations

from collections import OrderedDict
from threading import Lock

from aerostat_core.dynamics.lateral import (
    SWEEP_SEGMENTS,
    cached_sweep,
    clear_sweep_cache,
    design_key,
    lateral_modes,
    static_lateral_derivatives,
)
from aerostat_core.dynamics.sixdof import system6_from_design
from aerostat_core.model.constraints import LateralStability, lateral_applies

#: Results kept per frozen inputs (requirement, configuration, volume) in a process.
CACHE_SIZE = 64
_cache: OrderedDict = OrderedDict()
_lock = Lock()


def _key(d) -> str:
    # the exact repr of the frozen inputs and the volume (the app's cache key, docs/architecture.md §2.2)
    return design_key(d)


def lateral_stability(d) -> LateralStability:
    """The lateral-directional stability of design ``d`` (docs/dynamics.md §7.5).

    When the rule set checks the row: the 6-DOF model linearised at 2 m/s to the survival wind
    in 1 m/s steps (:func:`aerostat_core.dynamics.lateral.lateral_sweep`, 8 segments), the wind
    speed at which the first lateral mode goes unstable, and the static lateral derivatives at
    the design wind (:func:`~aerostat_core.dynamics.lateral.static_lateral_derivatives`) from
    the sweep's equilibrium there. Otherwise only the derivatives. A hull that sinks has no
    equilibrium in the wind: no numbers, and a note that says so. Results are cached per frozen
    inputs."""
    key = _key(d)
    with _lock:
        if key in _cache:
            _cache.move_to_end(key)
            return _cache[key]
    out = _compute(d)
    with _lock:
        _cache[key] = out
        while len(_cache) > CACHE_SIZE:
            _cache.popitem(last=False)
    return out


def _compute(d) -> LateralStability:
    req = d.requirement
    checked = lateral_applies(req)
    vs = float(req.survival_wind)
    vd = float(req.design_wind)
    if d.sinks or vd <= 0:
        why = ("the hull cannot lift its weight: no equilibrium in the wind" if d.sinks
               else "no design wind: no equilibrium in a wind to linearise about")
        return LateralStability(checked, None, vs, None, None, None, None, None, note=why)
    system = system6_from_design(d, segments=SWEEP_SEGMENTS)
    above = None
    state = None
    try:
        if checked:
            analyses, above = cached_sweep(d, system=system)
            state = next((a.state for a in analyses if a.speed == vd), None)
        if state is None:
            state = lateral_modes(system, vd, d).state
        der = static_lateral_derivatives(system, vd, d, state=state)
    except RuntimeError as exc:  # no equilibrium found: say so rather than guess
        return LateralStability(checked, above, vs, None, None, None, None, None,
                                note=f"no 6-DOF equilibrium: {exc}")
    return LateralStability(
        checked=checked, unstable_above=above, top_speed=vs, derivative_speed=vd,
        C_Y_beta=der["C_Y_beta_per_rad"], C_n_beta=der["C_n_beta_per_rad"],
        C_l_beta=der["C_l_beta_per_rad"], C_n_beta_confluence=der["C_n_beta_confluence_per_rad"])


def clear_cache() -> None:
    """Forget the cached results and sweeps (a benchmark times the computation itself)."""
    with _lock:
        _cache.clear()
    clear_sweep_cache()


def assess_lateral(d):
    """Design ``d`` with its ``lateral_stability`` row filled (:meth:`Design.with_lateral` of
    :func:`lateral_stability`); a design already assessed is returned as it is."""
    if d.constraints.lateral is not None:
        return d
    return d.with_lateral(lateral_stability(d))
