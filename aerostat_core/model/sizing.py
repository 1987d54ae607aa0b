"""Hull sizing: the smallest volume that meets every constraint of the table at the design wind
(docs/methods.md §1.15).

Vectorised over a batch of design variables (the optimiser's nested V*(x), docs/methods.md
§1.12). Feasibility need not be monotone in volume: blow-by and free lift improve with volume
while the tether safety factor gets worse (a bigger hull pulls harder), so the feasible set can
be an interval, several, or empty. The search therefore locates each constraint's own boundary
in volume and intersects them:

1. the whole table on a 28-point logarithmic grid from 2 m3 to 1e5 m3 (ratio 1.49 between
   points), one numpy call;
2. the first grid interval [V_i, V_i+1] where every constraint is met at one end or the other
   (the only intervals that can hold a feasible volume when each g crosses its tolerance at
   most once between grid points);
3. in it, the boundary of every constraint that changes between the two ends, found by a
   bracketing root finder (a safeguarded secant in log volume on log(1 + g), where a power law
   is a straight line, with a bisection point each round) to a relative width of
   :data:`RTOL` in volume (a round whose brackets are all rows that need no wind, as free lift
   and endurance, evaluates those rows alone: the same numbers for a third of the cost);
4. the intersection: the largest lower boundary L and the smallest upper boundary U of that
   interval. Where L <= U the answer is the evaluated point just above L (every row of the
   table is checked there, so the answer is feasible by evaluation, not by inference);
   otherwise the next candidate interval is tried.

The table, trim and tether at the chosen volume are those of the evaluation that found it (no
evaluation after the search). A design with no feasible volume gets each constraint's true
feasible interval (its boundaries found the same way) and the change that would help most, in
the words of the requirement (:func:`infeasibility_message`). Assumption, tested against a
dense scan of 400 volumes over 240 random requirements (tests/core/test_sizing_exact.py): no
constraint crosses its tolerance twice within one grid step (a factor 1.49 in volume).

No scipy root-finder is involved, so nothing raises on an infeasible case.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from aerostat_core.base.fields import field_spec
from aerostat_core.geometry.shapes import HullSpec
from aerostat_core.model.airframe import build_airframe
from aerostat_core.model.constraints import (
    BY_NAME,
    CONSTRAINTS,
    NAMES,
    ConstraintState,
    constraint_state,
    static_quantities,
)
from aerostat_core.model.inputs import Configuration, Requirement

#: Volume search range [m3]: from 2 m3 to the top of the hull-volume field's range (the field
#: registry, 1e5 m3: the strategic class of thesis Table 2.3 and above).
VOLUME_MIN = 2.0
VOLUME_MAX = float(field_spec(HullSpec, "volume").hi)
_DECADES = float(np.log(VOLUME_MAX / VOLUME_MIN))
#: The grid: a ratio of about 1.49 between neighbours over the whole range.
_GRID = np.geomspace(VOLUME_MIN, VOLUME_MAX, 1 + round(_DECADES / np.log(1.49)))
#: The grid of a batch of more than :data:`_FEW` designs (ratio about 2.15: the optimiser's
#: batches, where the grid is most of the cost; the same boundaries are found from it).
_GRID_BATCH = np.geomspace(VOLUME_MIN, VOLUME_MAX, 1 + round(_DECADES / np.log(2.15)))
_FEW = 8
#: Relative precision of every constraint boundary in volume [-] (the bracket width at the end).
RTOL = 1e-5
_LOG_RTOL = float(np.log1p(RTOL))
#: Root-finder rounds before a bracket is accepted at its current width.
_MAX_ROUNDS = 12
_TOL = np.array([c.tolerance for c in CONSTRAINTS])


@dataclass(frozen=True)
class SizingResult:
    """Sized volume(s) [m3] and why.

    volume : ndarray
        The smallest feasible volume (within :data:`RTOL`); where none is feasible, the grid
        volume of least total violation.
    feasible : ndarray of bool
    binding : ndarray of str
        Where feasible: the constraint that sets the size (violated just below ``volume``, or
        ``"none"`` at the bottom of the range). Where infeasible: the constraint that no volume
        meets, or ``"a+b"`` for two whose feasible volumes do not overlap.
    blow_by : ndarray
        Design-wind blow-by at ``volume`` [m].
    state : ConstraintState
        The constraint table at ``volume`` (what design() and the optimiser report), as
        evaluated in the search: its ``evaluation`` (trim and tether at the design and survival
        winds) and that evaluation's airframe are the sized design's.
    message : ndarray of str
        Plain-language reason where infeasible ("" where feasible): each constraint's feasible
        volumes and the change that would help most.
    intervals : tuple
        Per design (flattened batch order) where infeasible: {constraint: [(lo, hi), ...]} its
        feasible volume intervals [m3] (boundaries within :data:`RTOL`); None where feasible.
    """

    volume: np.ndarray
    feasible: np.ndarray
    binding: np.ndarray
    blow_by: np.ndarray
    state: ConstraintState
    message: np.ndarray
    intervals: tuple = ()


def _state(req, cfg, volume, f, dsf, pos, heights_hint=None) -> ConstraintState:
    return constraint_state(req, cfg, build_airframe(req, cfg, volume, f, dsf, pos),
                            heights_hint)


#: Rows of the table that need no wind (the airframe alone: free lift, fins on the hull,
#: endurance).
_STATIC = np.array([c.at == "static" for c in CONSTRAINTS])


class _StaticRows:
    """The table's rows that need no wind at a flat batch of points, the others NaN: what a
    round of the root finder reads when all its brackets are such rows (the airframe and
    :func:`static_quantities`, about a third of a whole evaluation). The numbers are those of
    the whole table (:func:`constraint_state` takes these rows from the same functions on the
    same airframe); :func:`_complete` evaluates the whole table at the same points, in the same
    batch, where it is read."""

    def __init__(self, req, cfg, volume, f, dsf, pos):
        self.args = (req, cfg, volume, f, dsf, pos)
        sq = static_quantities(req, build_airframe(req, cfg, volume, f, dsf, pos), cfg)
        self.g = np.full((np.size(volume), len(NAMES)), np.nan)
        for k in np.nonzero(_STATIC)[0]:
            self.g[:, k] = sq[NAMES[k]][2]


def _complete(states, src) -> np.ndarray:
    """The whole table's g row at ``src`` = (state id, index), a state of static rows replaced
    by its whole evaluation first (the same points in the same batch, so the same numbers as a
    round that evaluated it all)."""
    sid, i = int(src[0]), int(src[1])
    st, npts = states[sid]
    if isinstance(st, _StaticRows):
        st = _state(*st.args)
        states[sid] = (st, npts)
    return np.broadcast_to(st.g, (npts, len(NAMES)))[i]


#: How :func:`map_arrays` treats each type met: an array (``fn`` applied), a leaf (kept), a
#: dict, a tuple, or a dataclass (the tuple of its field names; ``dataclasses.fields`` is slow).
_KIND: dict[type, object] = {}
_ARRAY, _LEAF, _DICT, _TUPLE = "array", "leaf", "dict", "tuple"
_PLAIN = (float, int, str, bool, type(None))


def _classify(cls):
    if issubclass(cls, np.ndarray):
        return _ARRAY
    if cls in _PLAIN:
        return _LEAF
    if dataclasses.is_dataclass(cls):
        names = tuple(f.name for f in dataclasses.fields(cls))
        if names:
            return names
    if issubclass(cls, dict):
        return _DICT
    if issubclass(cls, tuple):
        return _TUPLE
    return _LEAF


def map_arrays(fn, *trees):
    """Apply ``fn`` to the array leaves of equal-structured result trees (frozen dataclasses,
    dicts, tuples); other leaves (floats, strings, specs) are taken from the first tree."""
    t = trees[0]
    cls = type(t)
    kind = _KIND.get(cls)
    if kind is None:
        kind = _KIND[cls] = _classify(cls)
    if kind is _ARRAY:
        return fn(*trees)
    if kind is _LEAF:
        return t
    if kind is _DICT:
        return {k: map_arrays(fn, *(x[k] for x in trees)) for k in t}
    if kind is _TUPLE:
        return tuple(map_arrays(fn, *xs) for xs in zip(*trees))
    # a dataclass: a shallow copy without __init__ (the leaves were validated when first
    # built), its array and container fields mapped (leaves checked here, not by a call each)
    new = object.__new__(cls)
    d = new.__dict__
    d.update(t.__dict__)
    single = len(trees) == 1
    for name in kind:
        v = d[name]
        k = _KIND.get(type(v))
        if k is _LEAF:
            continue
        if single:
            d[name] = fn(v) if k is _ARRAY else map_arrays(fn, v)
        else:
            args = [x.__dict__[name] for x in trees]
            d[name] = fn(*args) if k is _ARRAY else map_arrays(fn, *args)
    return new


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


def _gather_flat(st: ConstraintState, idx, n: int) -> ConstraintState:
    """The table and evaluation of a flat batch of ``n`` points (the batch the last axis of its
    arrays) at point(s) ``idx`` (an int or an int array of the result's batch shape)."""
    idx = np.asarray(idx)
    scalar = idx.ndim == 0

    def take(a):
        if a.ndim == 0 or a.shape[-1] not in (1, n):
            return a
        if a.shape[-1] == 1:
            return a[..., 0] if scalar else a
        return a[..., idx]

    table = {k: np.broadcast_to(getattr(st, k), (n, len(NAMES)))[idx] for k in _TABLE}
    return dataclasses.replace(st, **table, evaluation=map_arrays(take, st.evaluation))


def _secant_coordinate(g, tol):
    """The coordinate in which the root finder interpolates g - tol: log(1 + g) - log(1 + tol)
    where g > -0.9 (an upper limit q/q_max - 1 of a power law in volume is then a straight line
    in log volume), else g - tol (same root)."""
    pos = g > -0.9
    return np.where(pos, np.log1p(np.maximum(g, -0.9)) - np.log1p(tol), g - tol)


def _cubic_guess(grid, gg, d_idx, k, j):
    """First guess of each bracket's root [ln m3]: the cubic through the row's secant
    coordinate (:func:`_secant_coordinate`) at four consecutive grid points around the interval
    j (where the coordinate is defined at all four, else g - tol), its root inside the interval
    by bisection. Brackets (d_idx, k, j) as in :func:`_grid_brackets`."""
    n_grid = grid.size
    i0 = np.clip(j - 1, 0, n_grid - 4)
    nodes = i0[:, None] + np.arange(4)[None, :]  # (M, 4)
    g = gg[nodes, d_idx[:, None], k[:, None]]
    tol = _TOL[k][:, None]
    h = np.where((g > -0.9).all(axis=1, keepdims=True), _secant_coordinate(g, tol), g - tol)
    u = np.arange(4, dtype=float)
    coef = np.linalg.solve(np.vander(u, 4, increasing=True)[None], h[..., None])[..., 0]
    a, b = (j - i0).astype(float), (j - i0 + 1).astype(float)
    if a.size <= _FEW:
        # a few brackets: the same bisection on Python floats (the same IEEE operations, so the
        # same numbers, without ~300 numpy calls on arrays of a few elements)
        a, b = _bisect_cubics(coef.tolist(), a.tolist(), b.tolist())
    else:
        fa = ((coef[:, 3] * a + coef[:, 2]) * a + coef[:, 1]) * a + coef[:, 0]
        for _ in range(30):
            m = 0.5 * (a + b)
            fm = ((coef[:, 3] * m + coef[:, 2]) * m + coef[:, 1]) * m + coef[:, 0]
            same = np.sign(fm) == np.sign(fa)
            a, fa = np.where(same, m, a), np.where(same, fm, fa)
            b = np.where(same, b, m)
    xg = np.log(grid)
    return xg[i0] + 0.5 * (a + b) * (xg[1] - xg[0])


def _sign(x: float) -> float:
    """np.sign of a float (NaN for NaN, so that it equals no sign)."""
    return 1.0 if x > 0.0 else -1.0 if x < 0.0 else 0.0 if x == 0.0 else math.nan


def _bisect_cubics(coef, a, b):
    """The 30 bisection steps of :func:`_cubic_guess` on lists of floats (one cubic per
    bracket): the bracket ends (a, b) as arrays."""
    out_a, out_b = [], []
    for (c0, c1, c2, c3), lo, hi in zip(coef, a, b):
        f_lo = ((c3 * lo + c2) * lo + c1) * lo + c0
        for _ in range(30):
            m = 0.5 * (lo + hi)
            fm = ((c3 * m + c2) * m + c1) * m + c0
            if _sign(fm) == _sign(f_lo):
                lo, f_lo = m, fm
            else:
                hi = m
        out_a.append(lo)
        out_b.append(hi)
    return np.array(out_a), np.array(out_b)


def _prune(open_, x_lo, x_hi, group, up):
    """Brackets that can no longer decide the answer, closed: a lower boundary (``up``: the row
    becomes met) whose bracket lies wholly below another of its design's lower boundaries (it
    is not the largest), and an upper boundary whose bracket lies wholly above every lower
    boundary of its design (it cannot cut the window)."""
    if group.size == 0:  # no bracket left to refine (every boundary already found)
        return open_
    n = int(group.max()) + 1
    lo_up = np.full(n, -np.inf)
    hi_up = np.full(n, -np.inf)
    np.maximum.at(lo_up, group[up], x_lo[up])
    np.maximum.at(hi_up, group[up], x_hi[up])
    below = up & (x_hi < lo_up[group])
    above = ~up & (x_lo > hi_up[group]) & np.isfinite(hi_up[group])
    return open_ & ~below & ~above


def _refine(req, cfg, f, dsf, pos, k, x_lo, x_hi, r_lo, r_hi, s_lo, s_hi, states, guess=None,
            ladder=False, group=None, up=None, static_rounds=False):
    """Shrink brackets of constraint boundaries to a width of :data:`RTOL` in volume.

    A flat set of M brackets: bracket m has constraint ``k[m]`` met at one end of
    [exp(x_lo), exp(x_hi)] and broken at the other, design variables ``f, dsf, pos`` [m] (M,),
    the table's g rows at its ends ``r_lo, r_hi`` (M, n) and where they were evaluated
    ``s_lo, s_hi`` (M, 2: state id in ``states``, index). Each round evaluates three points per
    open bracket in one call: the secant root of :func:`_secant_coordinate` between the ends
    (in the first round ``guess`` where given), +-d about it (d = max(0.4 RTOL, 0.002 width): a
    tight bracket when the secant is good) and the middle of the larger side (at least halves
    the bracket when it is not), and keeps the first sub-interval from the low end whose ends
    differ. ``ladder``: the first round also evaluates +-3d and +-9d (a few designs, where a
    call costs more than its points). ``group`` (design of each bracket) and ``up`` (a lower
    boundary): brackets that cannot decide the smallest feasible volume stop early
    (:func:`_prune`). ``static_rounds``: a round whose open brackets are all rows that need no
    wind, and that is unlikely to be the last (its inner step wider than the final one),
    evaluates those rows alone (:class:`_StaticRows`; the same numbers, a third of the cost);
    the caller completes such a state where its whole table is read (:func:`_complete`).
    Returns the updated arrays.
    """
    n = len(NAMES)
    x_lo, x_hi, r_lo, r_hi, s_lo, s_hi = (np.array(a) for a in (x_lo, x_hi, r_lo, r_hi,
                                                               s_lo, s_hi))
    for _ in range(_MAX_ROUNDS):
        open_ = x_hi - x_lo > _LOG_RTOL
        if group is not None:
            open_ = _prune(open_, x_lo, x_hi, group, up)
        act = np.nonzero(open_)[0]
        if act.size == 0:
            break
        ma = act.size
        a_lo, a_hi, kk = x_lo[act], x_hi[act], k[act]
        w = a_hi - a_lo
        tol = _TOL[kk]
        glo, ghi = r_lo[act, kk], r_hi[act, kk]
        h_lo, h_hi = _secant_coordinate(glo, tol), _secant_coordinate(ghi, tol)
        den = h_lo - h_hi
        with np.errstate(invalid="ignore", divide="ignore"):
            t = np.where(den != 0, h_lo / np.where(den != 0, den, 1.0), 0.5)
        t = np.clip(np.nan_to_num(t, nan=0.5), 0.0, 1.0)
        xp = a_lo + w * t
        if guess is not None:
            xp = np.clip(guess[act], a_lo, a_hi)
            t = (xp - a_lo) / np.maximum(w, 1e-300)
        d = np.maximum(0.4 * _LOG_RTOL, 2e-3 * w)
        mid = np.where(t > 0.5, 0.5 * (a_lo + xp), 0.5 * (xp + a_hi))
        steps = (-9.0, -3.0, -1.0, 1.0, 3.0, 9.0) if ladder and guess is not None else (-1.0, 1.0)
        pts = np.stack([xp + c * d for c in steps] + [mid], axis=1)
        pts = np.clip(pts, a_lo[:, None], a_hi[:, None])
        pts.sort(axis=1)
        guess = None
        npts = pts.size
        n_in = pts.shape[1]
        f3, dsf3, pos3 = (np.repeat(a[act], n_in) for a in (f, dsf, pos))
        args = (np.exp(pts).reshape(-1), f3, dsf3, pos3)
        if static_rounds and _STATIC[kk].all() and bool((d > 0.4 * _LOG_RTOL).any()):
            st = _StaticRows(req, cfg, *args)
        else:
            st = _state(req, cfg, *args)
        sid = len(states)
        states.append((st, npts))
        g = np.broadcast_to(st.g, (npts, n)).reshape(ma, n_in, n)
        rows = np.arange(ma)
        met_pts = g[rows[:, None], np.arange(n_in)[None, :], kk[:, None]] <= tol[:, None]
        met_lo = glo <= tol
        seq = np.concatenate([met_pts, ~met_lo[:, None]], axis=1)  # the points, the high end
        j = np.argmax(seq != met_lo[:, None], axis=1)  # the first that differs from the low end
        xs = np.concatenate([a_lo[:, None], pts, a_hi[:, None]], axis=1)
        rs = np.concatenate([r_lo[act][:, None], g, r_hi[act][:, None]], axis=1)
        flat = (rows[:, None] * n_in + np.arange(n_in)[None, :])
        ss = np.concatenate([s_lo[act][:, None],
                             np.stack([np.full((ma, n_in), sid), flat], axis=-1),
                             s_hi[act][:, None]], axis=1)
        x_lo[act], x_hi[act] = xs[rows, j], xs[rows, j + 1]
        r_lo[act], r_hi[act] = rs[rows, j], rs[rows, j + 1]
        s_lo[act], s_hi[act] = ss[rows, j], ss[rows, j + 1]
    return x_lo, x_hi, r_lo, r_hi, s_lo, s_hi


def _grid_brackets(grid, gg, d_idx, k, j):
    """Bracket arrays of intervals j of ``grid`` (designs d_idx, constraints k) from the grid
    table ``gg`` (G, B, n) (see :func:`_refine`)."""
    xg = np.log(grid)
    return (xg[j], xg[j + 1], gg[j, d_idx], gg[j + 1, d_idx],
            np.stack([np.zeros_like(j), j], axis=-1),
            np.stack([np.zeros_like(j), j + 1], axis=-1))


def _row(states, src, b: int, key: str, batch: int) -> np.ndarray:
    """Row ``key`` (g, value, limit, margin) of the table where ``src`` = (state id, index) was
    evaluated, for design ``b`` of the flattened batch (state 0 is the grid)."""
    sid, i = int(src[0]), int(src[1])
    st, npts = states[sid]
    a = np.asarray(getattr(st, key))
    if sid == 0:
        return np.broadcast_to(a, (npts, batch, len(NAMES)) if batch else
                               (npts, len(NAMES)))[(i, b) if batch else i]
    return np.broadcast_to(a, (npts, len(NAMES)))[i]


def _fmt_interval(lo: float, hi: float) -> str:
    if lo <= VOLUME_MIN * (1 + 1e-9) and hi >= VOLUME_MAX * (1 - 1e-9):
        return "any volume"
    if lo <= VOLUME_MIN * (1 + 1e-9):
        return f"at most {hi:.4g} m3"
    if hi >= VOLUME_MAX * (1 - 1e-9):
        return f"at least {lo:.4g} m3"
    return f"{lo:.4g}-{hi:.4g} m3"


def _describe(intervals) -> str:
    return " or ".join(_fmt_interval(a, b) for a, b in intervals) if intervals else "no volume"


def _grid_reason(met) -> tuple:
    """(binding, message, None) of an infeasible design of a large batch, from its grid alone:
    the first constraint met at no grid volume, else "combined"."""
    never = [NAMES[k] for k in range(len(NAMES)) if not met[:, k].any()]
    if never:
        c = BY_NAME[never[0]]
        return never[0], f"no hull volume meets the {c.label.lower()} limit", None
    return "combined", "no single hull volume meets every constraint together", None


def _infeasible(req, cfg, grid, fb, db, pb, gg, met, bad, states, design_wind, survival_wind):
    """Binding name, message and per-constraint feasible intervals of the designs ``bad`` (flat
    indices) that no volume satisfies: every sign change of every constraint on the grid is
    refined (:func:`_refine`), the intervals intersected, and the change that would help most
    chosen (see :func:`infeasibility_message`)."""
    change = met[:-1, bad] != met[1:, bad]  # (G-1, nb, n)
    j, bi, k = np.nonzero(change)
    d_idx = np.asarray(bad)[bi]
    x_lo, x_hi, r_lo, r_hi, s_lo, s_hi = _refine(
        req, cfg, fb[d_idx], db[d_idx], pb[d_idx], k, *_grid_brackets(grid, gg, d_idx, k, j),
        states)
    batch = fb.size if gg.ndim == 3 and states[0][0].g.ndim > 2 else 0
    out = {}
    for pos_b, b in enumerate(bad):
        sel = np.nonzero(bi == pos_b)[0]
        ivals, ends = {}, []
        for kk in range(len(NAMES)):
            mine = sel[k[sel] == kk]
            mine = mine[np.argsort(j[mine])]
            segs, cur, cur_src = [], (VOLUME_MIN if met[0, b, kk] else None), (0, 0)
            for m in mine:
                if met[j[m] + 1, b, kk]:  # broken -> met: a segment starts (its feasible end)
                    cur, cur_src = float(np.exp(x_hi[m])), s_hi[m]
                elif cur is not None:  # met -> broken: the segment ends
                    segs.append((cur, float(np.exp(x_lo[m])), cur_src, s_lo[m]))
                    cur = None
            if cur is not None:
                segs.append((cur, VOLUME_MAX, cur_src, (0, grid.size - 1)))
            ivals[NAMES[kk]] = [(a, c) for a, c, _, _ in segs]
            for a, c, sa, sc in segs:
                ends += [(a, sa, kk), (c, sc, kk)]
        out[b] = _message(ivals, ends, states, b, batch, design_wind, survival_wind)
    return out


def _message(ivals, ends, states, b, batch, design_wind, survival_wind):
    """(binding, message, intervals) of one infeasible design (see :func:`_infeasible`).

    ``ends``: (volume, source, constraint index) of every end of every feasible segment (the
    evaluated point on its feasible side, where the whole table is known). The best compromise
    is the end where the fewest constraints fail (then the least total g); the message gives the
    true intervals of the constraint met there and of those failing there, and the change that
    would help most: the failing constraint nearest its limit there, with its advice."""
    span = f"{VOLUME_MIN:g}-{VOLUME_MAX:g} m3"
    never = [n for n in NAMES if not ivals[n]]
    if never:
        c = BY_NAME[never[0]]
        others = [BY_NAME[n].label.lower() for n in never[1:]]
        also = f"; no volume meets {', '.join(others)} either" if others else ""
        msg = (f"no hull volume in {span} meets the {c.label.lower()} limit{also}. "
               f"What would help most: {c.advice or 'relax that limit'}")
        return never[0], msg, ivals
    best = None
    for v, src, k in ends:
        g = _row(states, src, b, "g", batch)
        bad = g > _TOL
        key = (int(bad.sum()), float(np.clip(g, 0.0, None).sum()))
        if best is None or key < best[0]:
            best = (key, v, src, k, g, bad)
    _, v, src, k, g, bad = best
    failing = [int(i) for i in np.nonzero(bad)[0]]
    if not failing:  # a window narrower than the search's precision
        return "combined", (f"no hull volume in {span} meets every constraint together "
                            f"(the constraints meet only within {RTOL:g} of {v:.4g} m3)"), ivals
    c0 = CONSTRAINTS[k]
    needs = "; ".join(f"{CONSTRAINTS[i].label.lower()} needs {_describe(ivals[NAMES[i]])}"
                      for i in failing)
    nearest = min(failing, key=lambda i: g[i])
    c = CONSTRAINTS[nearest]
    wind = survival_wind if c.at == "survival" else design_wind
    where = c.template.format(value=float(_row(states, src, b, "value", batch)[nearest]),
                              limit=float(_row(states, src, b, "limit", batch)[nearest]),
                              wind=wind)
    msg = (f"{c0.label.lower()} needs a hull of {_describe(ivals[c0.name])} but {needs}: no "
           f"volume in {span} meets them together. What would help most: at {v:.4g} m3, "
           f"{where}; {c.advice or 'relax that limit'}"
           + (f". Otherwise: {c0.advice}" if c0.advice and c0 is not c else ""))
    return f"{c0.name}+{NAMES[failing[0]]}", msg, ivals


def size_volume(req: Requirement, cfg: Configuration, fineness_ratio=None, area_change=None,
                position=None, rounds=None, explain=None) -> SizingResult:
    """Smallest hull volume that meets every constraint of the table.

    Each constraint's boundary in volume is bracketed on the grid and found by a root finder to
    :data:`RTOL`; the boundaries are intersected and the smallest feasible volume is the
    evaluated point just above the largest lower boundary of the first window (module
    docstring). The constraint table at that volume is the one evaluated in the search.

    Parameters
    ----------
    req, cfg : Requirement, Configuration
        ``req`` is resolved against its rule set first.
    fineness_ratio, area_change, position : array_like or None
        Design variables (broadcast together); ``None`` takes ``cfg``'s values.
    rounds : None
        Unused (kept for callers of the former lattice search).
    explain : bool, optional
        Refine every constraint's boundaries of an infeasible design for its message and
        ``intervals`` (default: for batches of at most 8 designs; a larger batch gets the
        constraint never met on the grid, or "combined", and a short message).

    Returns
    -------
    SizingResult
        Arrays of the broadcast shape of the design variables; ``state`` (with its evaluation
        and airframe) at ``volume``.

    Examples
    --------
    The default mission (10 kg at 300 m, practice rules):

    >>> from aerostat_core import Requirement
    >>> from aerostat_core.model.presets import practice_configuration
    >>> s = size_volume(Requirement(), practice_configuration())
    >>> bool(s.feasible), str(s.binding)
    (True, 'endurance')
    """
    req = req.resolved()
    f = cfg.hull.fineness_ratio if fineness_ratio is None else fineness_ratio
    dsf = cfg.fins.area_change if area_change is None else area_change
    pos = cfg.fins.position if position is None else position
    f, dsf, pos = (np.asarray(a, float) for a in np.broadcast_arrays(f, dsf, pos))
    shape = f.shape
    fb, db, pb = (a.reshape(-1) for a in (f, dsf, pos))
    nb, n = fb.size, len(NAMES)
    grid = _GRID if nb <= _FEW else _GRID_BATCH
    n_grid = grid.size
    explain = nb <= _FEW if explain is None else bool(explain)
    st = _state(req, cfg, grid.reshape((-1,) + (1,) * len(shape)), f, dsf, pos)
    gg = np.broadcast_to(st.g, (n_grid,) + shape + (n,)).reshape(n_grid, nb, n)
    met = gg <= _TOL
    ok = met.all(axis=-1)
    cand = (met[:-1] | met[1:]).all(axis=-1)  # (G-1, B): a window can lie in the interval
    states = [(st, n_grid)]
    found = ok[0].copy()
    volume = np.where(found, grid[0], np.nan)
    binding = np.full(nb, "none", dtype=object)
    src = np.zeros((nb, 2), int)
    start = np.zeros(nb, int)
    pend = ~found
    steps = np.arange(n_grid - 1)[:, None]
    while True:
        avail = cand & (steps >= start[None])
        pend &= avail.any(axis=0)
        if not pend.any():
            break
        i = np.argmax(avail, axis=0)
        # a grid point that meets the whole table and opens the next candidate interval: the
        # interval below it held a constraint that crosses its tolerance twice within one grid
        # step (the search's assumption fails there). The point is feasible by evaluation, so
        # it is the answer (the smallest feasible volume lies between it and the lower boundary
        # found below it).
        at_ok = pend & ok[i, np.arange(nb)]
        for b in np.nonzero(at_ok)[0]:
            found[b], volume[b], src[b] = True, grid[i[b]], (0, i[b])
            binding[b] = NAMES[int(np.argmax(gg[i[b], b] - _TOL))]
        pend &= ~at_ok
        if not pend.any():
            break
        bsel = np.nonzero(pend)[0]
        ib = i[bsel]
        sw = met[ib, bsel] != met[ib + 1, bsel]  # the constraints that change in the interval
        bi, k = np.nonzero(sw)
        d_idx = bsel[bi]
        jj = i[d_idx]
        x_lo, x_hi, r_lo, r_hi, s_lo, s_hi = _refine(
            req, cfg, fb[d_idx], db[d_idx], pb[d_idx], k,
            *_grid_brackets(grid, gg, d_idx, k, jj), states,
            guess=_cubic_guess(grid, gg, d_idx, k, jj), ladder=nb <= _FEW, group=d_idx,
            up=met[jj + 1, d_idx, k], static_rounds=True)
        up = met[jj + 1, d_idx, k]  # met at the upper end: a lower boundary of the window
        for pos_b, b in enumerate(bsel):
            mine = np.nonzero((bi == pos_b) & up)[0]
            if mine.size:
                m = mine[np.argmax(x_hi[mine])]  # the largest lower boundary
                if s_hi[m][0] > 0:  # a point of the root finder: its whole table
                    r_hi[m] = _complete(states, s_hi[m])
                if bool((r_hi[m] <= _TOL).all()):  # the whole table met at that point
                    found[b], volume[b], src[b] = True, float(np.exp(x_hi[m])), s_hi[m]
                    binding[b] = NAMES[k[m]]
                    continue
            start[b] = i[b] + 1
        pend &= ~found
    feasible = found.reshape(shape)
    message = np.full(nb, "", dtype=object)
    intervals = [None] * nb
    bad = np.nonzero(~found)[0]
    if bad.size:
        viol = np.clip(gg[:, bad], 0.0, None).sum(axis=-1)
        j_bad = np.argmin(viol, axis=0)
        volume[bad] = grid[j_bad]
        src[bad, 0], src[bad, 1] = 0, j_bad
        if explain:
            why = _infeasible(req, cfg, grid, fb, db, pb, gg, met, bad, states,
                              float(req.design_wind), float(req.survival_wind))
        else:
            why = {b: _grid_reason(met[:, b]) for b in bad}
        for b, (name, msg, iv) in why.items():
            binding[b], message[b], intervals[b] = name, msg, iv
    # the state at each volume, from the evaluation that found it
    final = None
    for sid in np.unique(src[:, 0]):
        mask = src[:, 0] == sid
        s_st, npts = states[sid]
        if sid == 0:
            part = _take_state(s_st, np.where(mask, src[:, 1], 0).reshape(shape), npts)
        else:
            part = _gather_flat(s_st, np.where(mask, src[:, 1], src[mask, 1][0]).reshape(shape),
                                npts)
        final = part if final is None else _select_state(mask.reshape(shape), part, final)
    bb = np.broadcast_to(final.value[..., NAMES.index("blow_by")], shape)
    return SizingResult(volume=volume.reshape(shape), feasible=feasible,
                        binding=binding.astype(str).reshape(shape), blow_by=np.array(bb),
                        state=final, message=message.astype(str).reshape(shape),
                        intervals=tuple(intervals))
