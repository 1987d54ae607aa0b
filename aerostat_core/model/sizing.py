"""Hull sizing: the smallest volume that meets every constraint of the table at the design wind.

Vectorised over a batch of design variables (the optimiser's nested V*(x), docs/methods.md
§1.12). Every design is evaluated on a 24-point logarithmic volume grid (ratio 1.49 between
points) in one numpy call, with the whole constraint table (aerostat_core.model.constraints) at the
design and the survival wind. Feasibility need not be monotone in volume: blow-by and free lift
improve with volume while the tether safety factor gets worse (a bigger hull pulls harder), so
the feasible set can be an interval or empty. The first feasible grid volume brackets the
smallest feasible one; the answer is the first feasible volume of the lattice that splits that
bracket into 9^4 equal steps in log volume, 1.49^(1/9^4) - 1 = 6e-5 relative (what four nested
rounds of 8 interior points find). A cubic through four grid values of the last constraint
broken below the bracket (in log(1 + g), where a power law is a straight line) predicts the
crossing, and one batch of 32 lattice points around it finds it: two evaluations in all. Where
those points do not contain the crossing (a g that is not smooth there), the nested rounds run.
The constraint table, trim and tether at the chosen volume come from the search itself (no
evaluation after it). A feasible window narrower than one grid step (a factor 1.49 in volume)
below the first feasible grid point can be missed; this is stated, and tested on a window that
the grid brackets.

No scipy root-finder is involved, so nothing raises on an infeasible case: the result names the
constraint that cannot be met, or the pair that cannot be met together, with the volume range
searched.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from aerostat_core.model.airframe import build_airframe
from aerostat_core.model.constraints import (
    BY_NAME,
    CONSTRAINTS,
    NAMES,
    ConstraintState,
    constraint_state,
)
from aerostat_core.model.inputs import Configuration, Requirement
from aerostat_core.tether.statics import interpolated_heights

#: Volume search range [m3].
VOLUME_MIN, VOLUME_MAX = 2.0, 2.0e4
_GRID = np.geomspace(VOLUME_MIN, VOLUME_MAX, 24)
#: Points per refinement round inside the bracket.
_REFINE = 8
#: Lattice points evaluated around the predicted crossing (one batch).
_CLUSTER = 32
#: The same for batches of designs (the misses, ~15 %, run the nested rounds alone).
_CLUSTER_BATCH = 8


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
        The constraint table at ``volume`` (what design() and the optimiser report), as
        evaluated in the search: its ``evaluation`` (trim and tether at the design and survival
        winds) and that evaluation's airframe are the sized design's.
    message : ndarray of str
        Plain-language reason where infeasible ("" where feasible).
    """

    volume: np.ndarray
    feasible: np.ndarray
    binding: np.ndarray
    blow_by: np.ndarray
    state: ConstraintState
    message: np.ndarray


def _state(req, cfg, volume, f, dsf, pos, heights_hint=None) -> ConstraintState:
    return constraint_state(req, cfg, build_airframe(req, cfg, volume, f, dsf, pos),
                            heights_hint)


def _lines_hint(cfg, st, first, pad: int = 0):
    """Warm start of the tether height passes of a finer set of volumes (sheared wind;
    docs/methods.md §1.9), from a state ``st`` evaluated at a set of volumes (the axis after
    the wind axis of its tether arrays): a callable ``(T_x, T_z) -> heights`` that
    interpolates its converged lines at volumes ``first``, ``first + 1`` and ``first + 2``
    (int array of the batch shape; per wind, quadratic) in the top elevation
    (:func:`aerostat_core.tether.statics.interpolated_heights`); ``pad`` trailing axes are added for
    the new volumes' batch. None in a uniform wind (one march is exact).

    Only a start: a poor hint (a bracket where the line changes, as where the trim jumps
    to another branch) costs passes, not accuracy. The lines above a bracket's lower end,
    not below, because the line below a first feasible volume is more often on another
    branch (smaller hulls trim at larger angles; two grid points below is often slack)."""
    if cfg.wind_profile.kind == "uniform":
        return None
    t = st.evaluation.tether
    shape = np.shape(first)
    idx = np.stack([first, first + 1, first + 2]).reshape((1, 3, 1, 1) + shape)

    def known(a):  # (nodes, 2 winds, volumes) + batch -> (nodes, 3, 2 winds, 1) + batch
        a = np.broadcast_to(a, a.shape[:3] + shape)[:, None, :, :]
        k = np.take_along_axis(a, idx, axis=3)
        return k.reshape(k.shape + (1,) * pad)

    el, z = known(t.elevation), known(t.z)
    length = float(np.asarray(st.evaluation.airframe.tether_length).reshape(-1)[0])
    return lambda tx, tz: interpolated_heights(tx, tz, el, z, length)


def _infeasible_reason(st, met, shape, skip=None):
    """Binding name and message per design from the grid's per-constraint feasibility
    (designs where ``skip`` holds, the feasible ones, get "none" and "")."""
    any_met = met.any(axis=0)  # (..., n): constraint met at some grid volume
    full = met.shape
    g = np.broadcast_to(st.g, full)
    value = np.broadcast_to(st.value, full)
    limit = np.broadcast_to(st.limit, full)
    lo_txt = f"{VOLUME_MIN:g}-{VOLUME_MAX:g} m3"
    binding = np.full(shape, "none", dtype=object)
    message = np.full(shape, "", dtype=object)
    for idx in np.ndindex(*shape):
        if skip is not None and skip[idx]:
            continue
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


#: Field names of each dataclass met by :func:`map_arrays` (``dataclasses.fields`` is slow).
_FIELD_NAMES: dict[type, tuple[str, ...]] = {}
_PLAIN = (float, int, str, bool, type(None))


def map_arrays(fn, *trees):
    """Apply ``fn`` to the array leaves of equal-structured result trees (frozen dataclasses,
    dicts, tuples); other leaves (floats, strings, specs) are taken from the first tree."""
    t = trees[0]
    if isinstance(t, np.ndarray):
        return fn(*trees)
    cls = type(t)
    if cls in _PLAIN:
        return t
    names = _FIELD_NAMES.get(cls)
    if names is None:
        names = _FIELD_NAMES[cls] = (
            tuple(f.name for f in dataclasses.fields(cls))
            if dataclasses.is_dataclass(cls) else ())
    if names:
        # a shallow copy without __init__ (the leaves were validated when first built)
        new = object.__new__(cls)
        d = new.__dict__
        d.update(t.__dict__)
        if len(trees) == 1:
            for name in names:
                d[name] = map_arrays(fn, d[name])
        else:
            for name in names:
                d[name] = map_arrays(fn, *[x.__dict__[name] for x in trees])
        return new
    if isinstance(t, dict):
        return {k: map_arrays(fn, *(x[k] for x in trees)) for k in t}
    if isinstance(t, tuple):
        return tuple(map_arrays(fn, *xs) for xs in zip(*trees))
    return t


def _take(result, index, npts: int):
    """A batch result evaluated at ``npts`` volumes per design (axis just before the batch axes,
    by broadcasting from the right) at the volume ``index`` (int array of the batch shape)."""
    shape = np.shape(index)
    rank = len(shape)

    one = int(index) if rank == 0 else None

    def take(a):
        p = a.ndim - rank - 1
        if p < 0 or a.shape[p] not in (1, npts):
            return a  # no volume axis (a per-design or a global quantity)
        if a.shape[p] == 1:
            return a[(slice(None),) * p + (0,)]
        if one is not None:
            return a[(slice(None),) * p + (one,)]
        b = np.broadcast_to(a, a.shape[: p + 1] + shape)
        idx = np.reshape(index, (1,) * (p + 1) + shape)
        return np.take_along_axis(b, idx, axis=p).squeeze(p)

    return map_arrays(take, result)


def _select(mask, a, b):
    """Result tree ``a`` where ``mask`` (batch shape) holds, else ``b``."""
    return map_arrays(lambda x, y: x if x is y else np.where(mask, x, y), a, b)


_TABLE = ("g", "margin", "value", "limit")


def _take_state(st: ConstraintState, index, npts: int) -> ConstraintState:
    """The constraint table (columns last) and its evaluation at volume ``index``."""
    full = (npts,) + np.shape(index) + (len(NAMES),)
    if np.ndim(index) == 0:
        table = {k: np.broadcast_to(getattr(st, k), full)[int(index)] for k in _TABLE}
    else:
        idx = np.asarray(index)[None, ..., None]
        table = {k: np.take_along_axis(np.broadcast_to(getattr(st, k), full), idx, axis=0)[0]
                 for k in _TABLE}
    return dataclasses.replace(st, **table, evaluation=_take(st.evaluation, index, npts))


def _select_state(mask, a: ConstraintState, b: ConstraintState) -> ConstraintState:
    m = np.asarray(mask)[..., None]
    table = {k: np.where(m, getattr(a, k), getattr(b, k)) for k in _TABLE}
    return dataclasses.replace(a, **table, evaluation=_select(mask, a.evaluation, b.evaluation))


#: Inverse Vandermonde matrices of the cubic through four consecutive grid points u = o..o+3
#: (u = 0 at grid[k-1], 1 at grid[k]; the grid is uniform in log volume), o = 0, -1, -2, -3.
_VANDERMONDE_INV = np.stack([
    np.linalg.inv(np.vander(np.arange(o, o + 4, dtype=float), 4, increasing=True))
    for o in (0, -1, -2, -3)
])


def _predicted_fraction(st, lo_k, met):
    """Where in the grid bracket [grid[k-1], grid[k]] the last constraint broken at grid[k-1]
    is met, as a fraction u of the bracket in log volume: the root of the cubic through that
    constraint's g - tolerance at four consecutive grid volumes (it passes through grid[k-1]
    and grid[k], so the sign change lies inside the bracket), by vectorised bisection."""
    n_grid = _GRID.size
    shape = lo_k.shape
    tol = np.array([c.tolerance for c in CONSTRAINTS])
    g = np.broadcast_to(st.g, (n_grid,) + shape + (len(NAMES),))
    i0 = np.clip(lo_k, 0, n_grid - 4)  # nodes i0..i0+3 contain k-1 and k (feasible side first)
    nodes = i0[None] + np.arange(4).reshape((4,) + (1,) * len(shape))
    gn = np.take_along_axis(g, nodes[..., None], axis=0)  # (4, ..., n)
    # an upper limit q/q_max - 1 of a power law in volume is linear in log(1 + g): interpolate
    # that where it is defined at every node (the root is the same), else g itself
    pos = (gn > -1.0).all(axis=0)
    gn = np.where(pos, np.log1p(np.maximum(gn, -0.5)) - np.log1p(tol), gn - tol)
    inv = _VANDERMONDE_INV[lo_k - i0]  # (..., 4, 4), offset o = i0 - (k - 1)
    coef = np.einsum("...ij,j...n->i...n", inv, gn)  # c0 + c1 u + c2 u^2 + c3 u^3
    broken = ~np.take_along_axis(met, lo_k[None, ..., None], axis=0)[0]  # (..., n)
    a = np.zeros(broken.shape)
    b = np.ones(broken.shape)
    for _ in range(20):  # 2^-20 of the bracket: below one lattice step (9^-4)
        u = 0.5 * (a + b)
        above = ((coef[3] * u + coef[2]) * u + coef[1]) * u + coef[0] > 0.0
        a = np.where(above, u, a)
        b = np.where(above, b, u)
    return np.where(broken, 0.5 * (a + b), -np.inf).max(axis=-1)


def _nested_rounds(req, cfg, lo, hi, f, dsf, pos, rounds, hint=None):
    """Nested rounds of 8 interior points on brackets [lo, hi] (1-D batch): the volume, the
    state there and which constraints are met at the last infeasible volume below it.
    ``hint``: the first round's tether warm start (:func:`_lines_hint`); each later round
    starts from the round before it."""
    t = np.linspace(0.0, 1.0, _REFINE + 2)[1:-1].reshape(-1, 1)
    idx = np.arange(lo.size)
    for _ in range(rounds):
        vr = np.exp(np.log(lo) + (np.log(hi) - np.log(lo)) * t)
        rst = _state(req, cfg, vr, f, dsf, pos, hint)
        oks = np.broadcast_to(rst.feasible, vr.shape)
        first = np.where(oks.any(axis=0), np.argmax(oks, axis=0), vr.shape[0])
        last = vr.shape[0] - 1
        hi = np.where(first <= last, vr[np.minimum(first, last), idx], hi)
        lo = np.where(first > 0, vr[np.maximum(first - 1, 0), idx], lo)
        hint = _lines_hint(cfg, rst, np.clip(first - 1, 0, _REFINE - 3))
    pair = np.stack([lo, hi])
    pst = _state(req, cfg, pair, f, dsf, pos, hint)
    met = np.broadcast_to(pst.met, pair.shape + (len(NAMES),))[0]
    return hi, _take_state(pst, np.ones(lo.shape, int), 2), met


def _scatter_state(full: ConstraintState, sel, sub: ConstraintState) -> ConstraintState:
    """``full`` with the designs at ``sel`` (np.nonzero of the batch shape) taken from ``sub``
    (a 1-D batch of those designs)."""
    batch = full.g.shape[:-1]

    def put(x, y):
        if x is y or y.ndim == 0:
            return x  # no design axis
        out = np.array(np.broadcast_to(x, np.broadcast_shapes(x.shape, y.shape[:-1] + batch)))
        out[(Ellipsis,) + sel] = y
        return out

    table = {}
    for k in _TABLE:
        out = np.array(getattr(full, k))
        out[sel] = getattr(sub, k)
        table[k] = out
    return dataclasses.replace(full, **table,
                               evaluation=map_arrays(put, full.evaluation, sub.evaluation))


def size_volume(req: Requirement, cfg: Configuration, fineness_ratio=None, area_change=None,
                position=None, rounds: int = 4) -> SizingResult:
    """Smallest hull volume that meets every constraint of the table.

    The answer is the first feasible volume of the lattice that splits the grid bracket into
    9^rounds equal steps in log volume (what ``rounds`` nested rounds of 8 interior points
    find). It is found with one evaluation of a few lattice points around the crossing that a
    cubic through the grid's g values predicts; where those points do not contain the crossing
    (a g that is not smooth there), the nested rounds run as the fallback. The constraint table
    at the chosen volume is the one evaluated in the search (no second evaluation).

    Parameters
    ----------
    req, cfg : Requirement, Configuration
        ``req`` is resolved against its rule set first.
    fineness_ratio, area_change, position : array_like or None
        Design variables (broadcast together); ``None`` takes ``cfg``'s values.
    rounds : int
        Bracket refinement rounds (8 interior points each): the lattice has 9^rounds steps.

    Returns
    -------
    SizingResult
        Arrays of the broadcast shape of the design variables; ``state`` (with its evaluation
        and airframe) at ``volume``.
    """
    req = req.resolved()
    f = cfg.hull.fineness_ratio if fineness_ratio is None else fineness_ratio
    dsf = cfg.fins.area_change if area_change is None else area_change
    pos = cfg.fins.position if position is None else position
    f, dsf, pos = (np.asarray(a, float) for a in np.broadcast_arrays(f, dsf, pos))
    shape = f.shape
    n_grid = _GRID.size
    grid = _GRID.reshape((-1,) + (1,) * len(shape))
    st = _state(req, cfg, grid, f, dsf, pos)
    met = np.broadcast_to(st.met, (n_grid,) + shape + (len(NAMES),))
    ok = met.all(axis=-1)
    any_ok = ok.any(axis=0)
    k = np.argmax(ok, axis=0)
    # infeasible designs: the grid volume of least total violation, and the reason
    viol = np.broadcast_to(np.clip(st.g, 0.0, None), met.shape).sum(axis=-1)
    j_grid = np.where(any_ok, k, np.argmin(viol, axis=0))
    volume = _GRID[j_grid]
    final = None  # the state at the volume, gathered once from where it was evaluated
    lo_met = np.take_along_axis(met, np.maximum(k - 1, 0)[None, ..., None], axis=0)[0]
    refine = any_ok & (k > 0)
    if refine.any():
        lo_k = np.maximum(k - 1, 0)
        lo, hi = _GRID[lo_k], _GRID[k]
        x_lo, span = np.log(lo), np.log(hi) - np.log(lo)
        steps = (_REFINE + 1) ** rounds
        frac = np.where(refine, _predicted_fraction(st, lo_k, met), 1.0)
        centre = np.clip(np.ceil(frac * steps), 0, steps)
        m = _CLUSTER if f.size <= 4 else _CLUSTER_BATCH  # a batch: fewer points, more fallbacks
        j = centre + np.arange(-m // 2, m // 2).reshape((-1,) + (1,) * len(shape))
        j = np.clip(j, 0, steps)
        vs = np.where(refine, np.exp(x_lo + span * j / steps), volume)
        # the cluster's tether passes start from the grid's lines around the bracket
        first_line = np.minimum(np.where(refine, lo_k, j_grid), n_grid - 3)
        cst = _state(req, cfg, vs, f, dsf, pos, _lines_hint(cfg, st, first_line))
        cok = np.broadcast_to(cst.feasible, vs.shape)
        valid = refine & ~cok[0] & cok[-1]
        first = np.argmax(cok, axis=0)
        c_met = np.broadcast_to(cst.met, vs.shape + (len(NAMES),))
        prev_met = np.take_along_axis(c_met, np.maximum(first - 1, 0)[None, ..., None], axis=0)[0]
        volume = np.where(valid, np.take_along_axis(vs, first[None], axis=0)[0], volume)
        if valid.all():
            final = _take_state(cst, first, vs.shape[0])
        elif valid.any():
            final = _select_state(valid, _take_state(cst, first, vs.shape[0]),
                                  _take_state(st, j_grid, n_grid))
        lo_met = np.where(valid[..., None], prev_met, lo_met)
        fall = refine & ~valid
        if fall.any():  # the nested rounds on those brackets, then [lo, hi] evaluated once
            if not shape:  # one design
                v_sub, st_sub, met_sub = _nested_rounds(
                    req, cfg, *(np.reshape(a, 1) for a in (lo, hi, f, dsf, pos)), rounds,
                    _lines_hint(cfg, st, np.minimum(lo_k, n_grid - 3), pad=1))
                volume, lo_met = v_sub[0], met_sub[0]
                final = _take_state(st_sub, np.array(0), 1)
            else:
                sel = np.nonzero(fall)
                v_sub, st_sub, met_sub = _nested_rounds(
                    req, cfg, lo[sel], hi[sel], f[sel], dsf[sel], pos[sel], rounds)
                volume = np.array(volume)
                volume[sel] = v_sub
                if final is None:
                    final = _take_state(st, j_grid, n_grid)
                final = _scatter_state(final, sel, st_sub)
                lo_met = np.array(lo_met)
                lo_met[sel] = met_sub
    if final is None:
        final = _take_state(st, j_grid, n_grid)
    broken = np.argmax(~lo_met, axis=-1)
    bind_ok = np.where((k > 0) & ~lo_met.all(axis=-1), np.asarray(NAMES)[broken], "none")
    bind_bad, msg_bad = _infeasible_reason(st, met, shape, skip=any_ok)
    binding = np.where(any_ok, bind_ok, bind_bad)
    message = np.where(any_ok, "", msg_bad)
    bb = np.broadcast_to(final.value[..., NAMES.index("blow_by")], shape)
    return SizingResult(volume=volume, feasible=any_ok, binding=binding, blow_by=np.array(bb),
                        state=final, message=message)
