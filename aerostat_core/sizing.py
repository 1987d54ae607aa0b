"""Hull sizing: the smallest volume that meets every constraint of the table at the design wind.

Vectorised over a batch of design variables (the optimiser's nested V*(x), docs/methods.md
§1.12). Every design is evaluated on a 24-point logarithmic volume grid (ratio 1.49 between
points) in one numpy call, with the whole constraint table (aerostat_core.constraints) at the
design and the survival wind. Feasibility need not be monotone in volume: blow-by and free lift
improve with volume while the tether safety factor gets worse (a bigger hull pulls harder), so
the feasible set can be an interval or empty. The first feasible grid volume brackets the
smallest feasible one; four rounds of 8 interior points shrink the bracket to
1.49^(1/9^4) - 1 = 6e-5 relative, each round keeping the first feasible point. A feasible
window narrower than one grid step (a factor 1.49 in volume) below the first feasible grid point
can be missed; this is stated, and tested on a window that the grid brackets.

No scipy root-finder is involved, so nothing raises on an infeasible case: the result names the
constraint that cannot be met, or the pair that cannot be met together, with the volume range
searched.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .airframe import build_airframe
from .constraints import BY_NAME, CONSTRAINTS, NAMES, ConstraintState, constraint_state
from .inputs import Configuration, Requirement

#: Volume search range [m3].
VOLUME_MIN, VOLUME_MAX = 2.0, 2.0e4
_GRID = np.geomspace(VOLUME_MIN, VOLUME_MAX, 24)
#: Points per refinement round inside the bracket.
_REFINE = 8


@dataclass(frozen=True)
class SizingResult:
    """Sized volume(s) [m3] and why.

    volume : ndarray
        The smallest feasible volume; where none is feasible, the grid volume of least total
        violation.
    feasible : ndarray of bool
    binding : ndarray of str
        Where feasible: the constraint that sets the size (violated just below ``volume``, or
        ``"none"`` at the bottom of the range). Where infeasible: the constraint that no volume
        meets, or ``"a+b"`` for two that no single volume meets together.
    blow_by : ndarray
        Design-wind blow-by at ``volume`` [m].
    state : ConstraintState
        The constraint table at ``volume`` (what design() and the optimiser report).
    message : ndarray of str
        Plain-language reason where infeasible ("" where feasible).
    """

    volume: np.ndarray
    feasible: np.ndarray
    binding: np.ndarray
    blow_by: np.ndarray
    state: ConstraintState
    message: np.ndarray


def _state(req, cfg, volume, f, dsf, pos) -> ConstraintState:
    return constraint_state(req, cfg, build_airframe(req, cfg, volume, f, dsf, pos))


def _infeasible_reason(st, met, shape):
    """Binding name and message per design from the grid's per-constraint feasibility."""
    any_met = met.any(axis=0)  # (..., n): constraint met at some grid volume
    full = met.shape
    g = np.broadcast_to(st.g, full)
    value = np.broadcast_to(st.value, full)
    limit = np.broadcast_to(st.limit, full)
    lo_txt = f"{VOLUME_MIN:g}-{VOLUME_MAX:g} m3"
    binding = np.full(shape, "none", dtype=object)
    message = np.full(shape, "", dtype=object)
    for idx in np.ndindex(*shape):
        never = [NAMES[k] for k in range(len(NAMES)) if not any_met[idx + (k,)]]
        if never:
            binding[idx] = never[0]
            c = BY_NAME[never[0]]
            k = NAMES.index(c.name)
            j = int(np.argmin(g[(slice(None),) + idx + (k,)]))
            wind = st.survival_wind if c.at == "survival" else st.design_wind
            best = c.template.format(value=float(value[(j,) + idx + (k,)]),
                                     limit=float(limit[(j,) + idx + (k,)]), wind=wind)
            others = [BY_NAME[n].label.lower() for n in never[1:]]
            also = f"; never met either: {', '.join(others)}" if others else ""
            advice = f": {c.advice}" if c.advice else ""
            message[idx] = (f"no hull volume in {lo_txt} meets the {c.label.lower()} limit "
                            f"(closest, at {_GRID[j]:.3g} m3: {best}){also}{advice}")
            continue
        # every constraint is met somewhere, never all together: find the conflicting pair
        m = met[(slice(None),) + idx]  # (grid, n)
        pair = None
        for a in range(len(NAMES)):
            for b in range(a + 1, len(NAMES)):
                if not (m[:, a] & m[:, b]).any():
                    pair = (a, b)
                    break
            if pair:
                break
        if pair is None:
            binding[idx] = "combined"
            message[idx] = f"no single hull volume in {lo_txt} meets every constraint together"
            continue
        a, b = pair
        va, vb = _GRID[m[:, a]], _GRID[m[:, b]]
        binding[idx] = f"{NAMES[a]}+{NAMES[b]}"
        message[idx] = (
            f"{CONSTRAINTS[a].label.lower()} needs a hull of {va.min():.3g}-{va.max():.3g} m3 "
            f"but {CONSTRAINTS[b].label.lower()} needs {vb.min():.3g}-{vb.max():.3g} m3 "
            f"(searched {lo_txt}): no volume meets both"
            + (f"; {CONSTRAINTS[b].advice}" if CONSTRAINTS[b].advice else "")
        )
    return binding.astype(str), message.astype(str)


def size_volume(req: Requirement, cfg: Configuration, fineness_ratio=None, area_change=None,
                position=None, rounds: int = 4) -> SizingResult:
    """Smallest hull volume that meets every constraint of the table.

    Parameters
    ----------
    req, cfg : Requirement, Configuration
        ``req`` is resolved against its rule set first.
    fineness_ratio, area_change, position : array_like or None
        Design variables (broadcast together); ``None`` takes ``cfg``'s values.
    rounds : int
        Bracket refinement rounds (8 interior points each).

    Returns
    -------
    SizingResult
        Arrays of the broadcast shape of the design variables.
    """
    req = req.resolved()
    f = cfg.hull.fineness_ratio if fineness_ratio is None else fineness_ratio
    dsf = cfg.fins.area_change if area_change is None else area_change
    pos = cfg.fins.position if position is None else position
    f, dsf, pos = (np.asarray(a, float) for a in np.broadcast_arrays(f, dsf, pos))
    shape = f.shape
    grid = _GRID.reshape((-1,) + (1,) * len(shape))
    st = _state(req, cfg, grid, f, dsf, pos)
    met = np.broadcast_to(st.met, (len(_GRID),) + shape + (len(NAMES),))
    ok = met.all(axis=-1)
    any_ok = ok.any(axis=0)
    k = np.argmax(ok, axis=0)
    lo = np.where(k > 0, _GRID[np.maximum(k - 1, 0)], VOLUME_MIN)
    hi = _GRID[k]
    t = np.linspace(0.0, 1.0, _REFINE + 2)[1:-1].reshape((-1,) + (1,) * len(shape))
    idx = np.indices(shape)
    for _ in range(rounds):
        vs = np.exp(np.log(lo) + (np.log(hi) - np.log(lo)) * t)
        oks = np.broadcast_to(_state(req, cfg, vs, f, dsf, pos).feasible, vs.shape)
        first = np.where(oks.any(axis=0), np.argmax(oks, axis=0), vs.shape[0])
        last = vs.shape[0] - 1
        new_hi = np.where(first <= last, vs[(np.minimum(first, last),) + tuple(idx)], hi)
        new_lo = np.where(first > 0, vs[(np.maximum(first - 1, 0),) + tuple(idx)], lo)
        lo, hi = np.where(any_ok, new_lo, lo), np.where(any_ok, new_hi, hi)
    # infeasible designs: the grid volume of least total violation, and the reason
    viol = np.broadcast_to(np.clip(st.g, 0.0, None), met.shape).sum(axis=-1)
    best = _GRID[np.argmin(viol, axis=0)]
    volume = np.where(any_ok, hi, best)
    final = _state(req, cfg, volume, f, dsf, pos)
    lo_state = _state(req, cfg, np.where(k > 0, lo, volume), f, dsf, pos)
    lo_met = np.broadcast_to(lo_state.met, shape + (len(NAMES),))
    broken = np.argmax(~lo_met, axis=-1)
    bind_ok = np.where((k > 0) & ~lo_met.all(axis=-1), np.asarray(NAMES)[broken], "none")
    bind_bad, msg_bad = _infeasible_reason(st, met, shape)
    binding = np.where(any_ok, bind_ok, bind_bad)
    message = np.where(any_ok, "", msg_bad)
    bb = np.broadcast_to(final.value[..., NAMES.index("blow_by")], shape)
    return SizingResult(volume=volume, feasible=any_ok, binding=binding, blow_by=np.array(bb),
                        state=final, message=message)
