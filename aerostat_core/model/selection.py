"""Materials chosen by the loads they carry (docs/methods.md §1.19, issue 23 item 2).

With ``Configuration.materials == "catalogue"`` (the practice configuration) the hull fabric,
the fin fabric and the tether are not fixed inputs: each is the lightest item of its catalogue
(:data:`aerostat_core.structures.materials.SELECTABLE_FABRICS`, :data:`~aerostat_core.structures.materials.
SELECTABLE_TETHERS`) that carries the load it sees on the sized hull with the rule set's
safety factor:

* envelope fabric: strength >= SF_env x N, N the envelope's membrane load at the required
  internal pressure at the design and at the survival wind (:func:`envelope_stress`);
* fin fabric: the same on the fin's inflated section (the hull pressure on a radius of half the
  fin root thickness, :data:`FIN_THICKNESS_RATIO`);
* tether: breaking load >= SF x the largest tension at the design wind and SF_s x that at the
  survival wind, with the conductor pair of :func:`aerostat_core.model.mission.effective_tether`
  bundled in where the payload power goes through it (the mass compared is the bundle's).

The loads depend on the hull and the hull on the materials' mass, so the choice is a fixed
point, found by :func:`select_materials`: size the hull with the candidate items' masses (their
strengths held out of the constraint table), read the loads at the sized volume, take the
lightest items that carry them, repeat until nothing changes (items only ever get stronger, so
this ends within the catalogue), then read the table of that hull with the chosen items'
strengths (the same airframe, trim and tether line: a strength changes no mass, so no solve is
run again); where an item row fails there, the
hull is sized again with the chosen items. Where the first
candidates (the lightest) already carry their loads on a feasible design, that first sizing is
the answer. An item no catalogue entry can supply is reported with its shortfall
(:class:`Shortfall`), and the design then carries the strongest entry.

The envelope stress used here is the hoop load p r at the required pressure of
:func:`aerostat_core.structures.membrane.required_pressure` (:func:`envelope_stress`), a separate function
so that a fuller structural model (bending, wrinkling) can replace it in one place.
"""

from __future__ import annotations

import copy
import functools
from dataclasses import dataclass, replace

import numpy as np

from aerostat_core.model.constraints import NAMES
from aerostat_core.model.mission import effective_tether
from aerostat_core.structures.materials import (
    SELECTABLE_FABRICS,
    SELECTABLE_TETHERS,
    Fabric,
    TetherSpec,
)
from aerostat_core.structures.membrane import required_pressure

#: Half-thickness of an inflated fin section / fin root chord [-]: a 15 %-thick section
#: (NACA 0015-like fins of fielded aerostats, ASSUMED; the fin fabric sees p x this radius).
FIN_THICKNESS_RATIO = 0.075
#: Iteration cap of the fixed point (the catalogues have fewer entries than this).
MAX_ROUNDS = 12
#: Strength values that take an item's strength out of the constraint table while the loads
#: are found (the field registry's upper limits).
_RELAXED_FABRIC = 9.0e5
_RELAXED_TETHER = 5.0e6


def envelope_stress(q, rho_air, rho_gas, g, diameter, factor):
    """Governing envelope membrane load [N/m]: the hoop load p r at the required pressure.

    N = p_req d/2, p_req = factor q + (rho_air - rho_gas) g d
    (:func:`aerostat_core.structures.membrane.required_pressure`); the hoop load of a pressurised
    cylinder is twice the axial one, so it governs while the bending moment stays below
    pi r^3 p/2 (docs/methods.md §1.14).

    Parameters
    ----------
    q : array_like
        Dynamic pressure [Pa].
    rho_air, rho_gas : array_like
        [kg/m3].
    g : float
        [m/s2].
    diameter : array_like
        Hull maximum diameter [m].
    factor : float
        Required pressure / q [-] (1.2).

    Notes
    -----
    Valid for a thin membrane away from the caps and attachment patches. A stand-in: it ignores
    the bending term that :func:`aerostat_core.structures.membrane.membrane_loads` adds to the axial
    load, so the constraint table (which includes it) has the last word; the selection bumps
    the fabric where the table still finds the envelope rows broken. Source: thin-shell statics
    (docs/methods.md §1.14).

    Examples
    --------
    >>> round(float(envelope_stress(100.0, 1.2, 0.2, 10.0, 4.0, 1.2)), 1)
    320.0
    """
    p = required_pressure(q, rho_air, rho_gas, g, diameter, factor)
    return p * 0.5 * np.asarray(diameter, float)


@dataclass(frozen=True)
class Shortfall:
    """An item no catalogue entry can supply: ``item`` ("hull fabric", "fin fabric",
    "tether"), the strength needed and the strongest entry's [N/m or N], the entry's name."""

    item: str
    needed: float
    best: float
    best_name: str
    unit: str

    @property
    def fraction(self) -> float:
        """By how much the strongest entry falls short, as a share of the need [-]."""
        return 1.0 - self.best / self.needed

    def message(self) -> str:
        """Plain-language reason: which item, what it needs and by how much the best misses."""
        scale, shown = (1e-3, "kN/m") if self.unit == "N/m" else (1e-3, "kN")
        return (f"no catalogue {self.item} is strong enough: it needs "
                f"{self.needed * scale:.1f} {shown} (load x safety factor) but the strongest, "
                f"{self.best_name}, has {self.best * scale:.1f} {shown}, "
                f"{100 * self.fraction:.0f} % short; enter a custom {self.item}, relax the "
                "safety factor or the survival wind, or lower the payload")


@dataclass(frozen=True)
class Needs:
    """Strengths the items must have on one sized hull [N/m, N/m, N]."""

    hull_fabric: float
    fin_fabric: float
    tether: float


def _lightest(items, needed: float, weights):
    """(index, shortfall?) of the lightest ``items`` entry (``weights`` per entry) whose
    strength meets ``needed``."""
    ok = [i for i, it in enumerate(items) if _strength(it) >= needed]
    if not ok:
        best = max(range(len(items)), key=lambda i: _strength(items[i]))
        return best, True
    return min(ok, key=lambda i: weights[i]), False


def _strength(item) -> float:
    return float(item.tensile_strength if isinstance(item, Fabric) else item.breaking_strength)


def needs_of(req, cfg, af, state) -> Needs:
    """Strengths the items must have on the sized airframe ``af`` with constraint table
    ``state`` (evaluated at the design and the survival wind).

    Fabric: SF_env x :func:`envelope_stress` at the larger of the two winds (the hull's
    radius; a fin's half-thickness for the fin fabric). Tether: the tension at each wind is the
    breaking load over the table's safety factor there (T = F / SF_actual), times the required
    factor."""
    resolved = req.resolved()
    m = cfg.mission
    winds = np.array([resolved.design_wind, resolved.survival_wind], float)
    rho_a = np.asarray(af.air_density, float).reshape(-1)[0]
    rho_g = np.asarray(af.gas_density, float).reshape(-1)[0]
    d = float(np.asarray(af.hull.diameter).reshape(-1)[0])
    q = 0.5 * rho_a * winds**2
    n_hull = float(np.max(envelope_stress(q, rho_a, rho_g, af.g, d, m.pressure_dynamic_factor)))
    p = float(np.max(required_pressure(q, rho_a, rho_g, af.g, d, m.pressure_dynamic_factor)))
    p = max(p, float(cfg.gas.superpressure))
    root = float(np.asarray(af.fins.root_chord).reshape(-1)[0])
    n_fin = p * FIN_THICKNESS_RATIO * root
    value = np.asarray(state.value).reshape(-1, len(NAMES))[0]
    sf = value[[NAMES.index("safety_factor"), NAMES.index("survival_safety_factor")]]
    strength = float(af.tether.breaking_strength)
    with np.errstate(divide="ignore"):
        tension = np.where(sf > 0, strength / np.maximum(sf, 1e-300), 0.0)
    need_t = max(resolved.min_tether_safety_factor * tension[0],
                 resolved.survival_safety_factor * tension[1])
    se = m.envelope_safety_factor
    return Needs(se * n_hull, se * n_fin, float(need_t))


def _flown(req, cfg, tether: TetherSpec) -> TetherSpec:
    """The tether as flown (conductors bundled in where power goes through it)."""
    # ``cfg`` with the catalogue tether, copied without re-validating the whole configuration
    # (a validated configuration and a validated catalogue entry: ``replace`` would check
    # every field again for each entry compared)
    c = copy.copy(cfg)
    object.__setattr__(c, "tether", tether)
    return effective_tether(req, c)


class _FlownDensities:
    """Linear density of each :data:`SELECTABLE_TETHERS` entry as flown [kg/m]
    (:func:`_flown`), each computed when first read (an entry whose conductors do not fit
    raises then, as it did when compared) and kept."""

    def __init__(self, req, cfg):
        self.req, self.cfg = req, cfg
        self.values = [None] * len(SELECTABLE_TETHERS)

    def __getitem__(self, i: int) -> float:
        v = self.values[i]
        if v is None:
            v = self.values[i] = _flown(self.req, self.cfg, SELECTABLE_TETHERS[i]).linear_density
        return v


#: The densities per (requirement, mission technology): the conductors bundled in depend on
#: nothing else (mission.tether_conductors), so the selection's rounds share them.
_FLOWN_DENSITIES: dict = {}


def _flown_densities(req, cfg) -> _FlownDensities:
    key = (req, cfg.mission)
    try:
        hit = _FLOWN_DENSITIES.get(key)
    except TypeError:  # an unhashable field (an array): no cache
        return _FlownDensities(req, cfg)
    if hit is None:
        if len(_FLOWN_DENSITIES) > 256:
            _FLOWN_DENSITIES.clear()
        hit = _FLOWN_DENSITIES[key] = _FlownDensities(req, cfg)
    return hit


def choose(req, cfg, needs: Needs) -> tuple[tuple[int, int, int], tuple[Shortfall, ...]]:
    """Catalogue indices (hull fabric, fin fabric, tether) of the lightest items meeting
    ``needs``, and the shortfalls where none does."""
    fabrics, tethers = SELECTABLE_FABRICS, SELECTABLE_TETHERS
    short = []
    areal = [f.areal_density for f in fabrics]
    i_h, bad = _lightest(fabrics, needs.hull_fabric, areal)
    if bad:
        short.append(Shortfall("hull fabric", needs.hull_fabric, _strength(fabrics[i_h]),
                               fabrics[i_h].name, "N/m"))
    i_f, bad = _lightest(fabrics, needs.fin_fabric, areal)
    if bad:
        short.append(Shortfall("fin fabric", needs.fin_fabric, _strength(fabrics[i_f]),
                               fabrics[i_f].name, "N/m"))
    i_t, bad = _lightest(tethers, needs.tether, _flown_densities(req, cfg))
    if bad:
        short.append(Shortfall("tether", needs.tether, _strength(tethers[i_t]),
                               tethers[i_t].name, "N"))
    return (i_h, i_f, i_t), tuple(short)


def with_items(cfg, idx, relaxed: bool = False):
    """``cfg`` with the catalogue items ``idx`` (hull fabric, fin fabric, tether); ``relaxed``
    sets their strengths to the registry maxima (mass kept) so that no strength row binds."""
    h, f, t = (_relaxed(idx) if relaxed else
               (SELECTABLE_FABRICS[idx[0]], SELECTABLE_FABRICS[idx[1]], SELECTABLE_TETHERS[idx[2]]))
    # ``cfg`` (validated) with validated catalogue entries, copied without validating every
    # field of the configuration again (what ``replace`` does: a third of a millisecond, eight
    # times a selection); a Configuration checks its fields one by one, none against another
    c = copy.copy(cfg)
    object.__setattr__(c, "hull_fabric", h)
    object.__setattr__(c, "fin_fabric", f)
    object.__setattr__(c, "tether", t)
    return c


@functools.lru_cache(maxsize=64)
def _relaxed(idx):
    """The catalogue items ``idx`` with their strengths at the registry maxima (see
    :func:`with_items`); the catalogues are constants, so each is built once."""
    h, f, t = SELECTABLE_FABRICS[idx[0]], SELECTABLE_FABRICS[idx[1]], SELECTABLE_TETHERS[idx[2]]
    return (replace(h, tensile_strength=_RELAXED_FABRIC),
            replace(f, tensile_strength=_RELAXED_FABRIC),
            replace(t, breaking_strength=_RELAXED_TETHER))


@dataclass(frozen=True)
class Selection:
    """Result of :func:`select_materials`: the configuration with the chosen items, the
    sizing on it (None for a given volume), the needs on the final hull, the shortfalls and
    the number of sizings run."""

    configuration: object
    sizing: object
    needs: Needs
    shortfalls: tuple[Shortfall, ...]
    sizings: int

    def messages(self) -> list[str]:
        """Shortfall messages (empty when every item was found)."""
        return [s.message() for s in self.shortfalls]


def _table(req, cfg, relaxed):
    """The constraint table of the relaxed state ``relaxed`` (one design, evaluated with the
    items' strengths held out) with ``cfg``'s items, whose strengths change no mass: its
    airframe with the tether as flown by ``cfg`` (the same mass, the real breaking load), its
    trim and tether line as they are, and the tether's safety factor at each wind from the
    real breaking load (:func:`aerostat_core.model.performance.tether_safety_factor`); then :func:`aerostat_core.model.constraints.table_of`. The same numbers as
    evaluating ``cfg`` at that volume again, to rounding (the relaxed state comes from the
    sizing's batch)."""
    from aerostat_core.model.constraints import table_of
    from aerostat_core.model.performance import tether_safety_factor

    ev = relaxed.evaluation
    spec = effective_tether(req, cfg)
    af = copy.copy(ev.airframe)
    object.__setattr__(af, "tether", spec)
    ev = copy.copy(ev)
    object.__setattr__(ev, "airframe", af)
    object.__setattr__(ev, "safety_factor",
                       tether_safety_factor(spec.breaking_strength, ev.tether.tension))
    return table_of(req, cfg, ev)


def _evaluate(req, cfg, explain=None):
    """(sizing or None, airframe, state) of ``cfg`` (sized when its volume is None).

    ``explain=False``: an infeasible sizing skips the refinement of every constraint's
    boundaries that only its message and intervals need (volume, state and feasibility are the
    same); for the sizings whose result is read for its loads only and then dropped."""
    from aerostat_core.model.airframe import build_airframe
    from aerostat_core.model.constraints import constraint_state
    from aerostat_core.model.sizing import size_volume

    if cfg.hull.volume is None:
        s = size_volume(req, cfg, explain=explain)
        return s, s.state.evaluation.airframe, s.state
    af = build_airframe(req, cfg, float(cfg.hull.volume))
    return None, af, constraint_state(req, cfg, af)


_MATERIAL_ROWS = ("envelope_stress", "survival_envelope_pressure", "safety_factor",
                  "survival_safety_factor")


def _rows_met(state) -> dict:
    met = np.asarray(state.met).reshape(-1, len(NAMES))[0]
    return {k: bool(met[NAMES.index(k)]) for k in _MATERIAL_ROWS}


def select_materials(req, cfg) -> Selection:
    """Choose the hull fabric, fin fabric and tether by the loads they carry (module docstring)
    and size the hull with them.

    Parameters
    ----------
    req : Requirement
        Resolved against its rule set first.
    cfg : Configuration
        Its ``hull_fabric``, ``fin_fabric`` and ``tether`` are replaced by catalogue items.

    Returns
    -------
    Selection
    """
    req = req.resolved()
    idx = (0, 0, 0)  # the catalogues are sorted lightest first
    runs = 0
    c = with_items(cfg, idx)
    # returned only when feasible: an infeasible first sizing is read for its loads only
    sizing, af, state = _evaluate(req, c, explain=False)
    runs += 1
    needs = needs_of(req, c, af, state)
    new, short = choose(req, c, needs)
    feasible = sizing is None or bool(np.asarray(sizing.feasible).reshape(-1)[0])
    if new == idx and feasible and all(_rows_met(state).values()):
        return Selection(c, sizing, needs, short, runs)
    # the fixed point on the items' masses, strengths held out of the table
    for _ in range(MAX_ROUNDS):
        idx = tuple(max(a, b) for a, b in zip(idx, new))
        # read for its loads, and returned only when feasible
        s_r, af_r, st_r = _evaluate(req, with_items(cfg, idx, relaxed=True), explain=False)
        runs += 1
        cr = with_items(cfg, idx)
        # the loads with the real tether's strength (the table's factors were the relaxed one's)
        needs = needs_of(req, with_items(cfg, idx, relaxed=True), af_r, st_r)
        new, short = choose(req, cr, needs)
        if all(b <= a for a, b in zip(idx, new)):
            break
    c = with_items(cfg, idx)
    # the relaxed hull with the chosen items' strengths: the strengths change no mass, so the
    # airframe, its trim and its tether line are the same and only the table is read again
    # from them (no search, no solve); where every item row holds there, the first feasible
    # volume is the relaxed one (the loads grow with the hull, so the items hold below it too)
    state = _table(req, c, st_r)
    af = state.evaluation.airframe
    relaxed_ok = s_r is None or bool(np.asarray(s_r.feasible).reshape(-1)[0])
    if relaxed_ok and all(_rows_met(state).values()):
        sizing = None if s_r is None else replace(s_r, state=state)
        return Selection(c, sizing, needs_of(req, c, af, state), short, runs)
    sizing, af, state = _evaluate(req, c)
    runs += 1
    # the table has the last word (bending on the envelope): the next stronger item there
    for _ in range(MAX_ROUNDS):
        met = _rows_met(state)
        # an infeasible sizing names the constraint, or the pair, no volume meets: an item's
        # row there means the item closes the window (a stronger one opens it)
        named = set()
        if sizing is not None and not bool(np.asarray(sizing.feasible).reshape(-1)[0]):
            named = set(str(np.asarray(sizing.binding).reshape(-1)[0]).split("+"))
        bump = list(idx)
        if (not (met["envelope_stress"] and met["survival_envelope_pressure"])
                or named & {"envelope_stress", "survival_envelope_pressure"}):
            bump[0] = _next_stronger(SELECTABLE_FABRICS, idx[0])
        if (not (met["safety_factor"] and met["survival_safety_factor"])
                or named & {"safety_factor", "survival_safety_factor"}):
            bump[2] = _next_stronger(SELECTABLE_TETHERS, idx[2])
        if tuple(bump) == idx:
            break
        idx = tuple(bump)
        c = with_items(cfg, idx)
        sizing, af, state = _evaluate(req, c)
        runs += 1
    needs = needs_of(req, c, af, state)
    _, short = choose(req, c, needs)
    return Selection(c, sizing, needs, short, runs)


def _next_stronger(items, i: int) -> int:
    """Index of the lightest entry stronger than ``items[i]`` (``i`` if there is none)."""
    s = _strength(items[i])
    stronger = [j for j, it in enumerate(items) if _strength(it) > s]
    if not stronger:
        return i
    return min(stronger, key=lambda j: (getattr(items[j], "areal_density", None)
                                        or items[j].linear_density))
