"""Static tether: segment-by-segment march from the confluence point to the winch.

The scheme of Rajani, Pant & Sudhakar (2010) (thesis Fig. 3.10; docs/methods.md §1.9), written as an
ODE in unstretched arc length and integrated with Heun's method (second order), vectorised over
any batch of wind speeds or designs. Extensions over the thesis: elastic stretch (T/EA), air
buoyancy of the line, tangential skin friction, and a height-varying wind.

Going down the tether (ds > 0 towards the winch), with elevation theta = atan2(T_z, T_x):
  dT_x/ds = f_x,  dT_z/ds = f_z - w',  dX/ds = -(1 + T/EA) cos theta,  dZ/ds = -(1 + T/EA) sin theta
where w' is the weight per length net of air buoyancy, and the drag per length on the relative wind
(U, 0) split into normal and tangential parts (MoorDyn convention):
  f = 1/2 rho d C_dn |U sin theta| U sin theta (sin theta, -cos theta)
    + 1/2 rho pi d C_dt |U cos theta| U cos theta (cos theta, sin theta).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from aerostat_core.structures.materials import TetherSpec


@dataclass(frozen=True)
class TetherSolution:
    """Static tether shape and loads (arrays: first axis = node from the top (0) to the winch).

    x, z : node positions relative to the winch [m] (x downwind, z up); top = confluence point.
    tension : tension magnitude at each node [N].
    elevation : tether elevation above the horizontal at each node [rad].
    blow_by : horizontal offset of the top from the winch [m]; height : its height [m].
    slack : True where the vertical tension fell to zero or below somewhere along the line.
    """

    x: np.ndarray
    z: np.ndarray
    tension: np.ndarray
    elevation: np.ndarray
    blow_by: np.ndarray
    height: np.ndarray
    slack: np.ndarray

    @property
    def tension_top(self) -> np.ndarray:
        """Tension at the confluence point [N]."""
        return self.tension[0]

    @property
    def tension_winch(self) -> np.ndarray:
        """Tension at the winch [N]."""
        return self.tension[-1]

    @property
    def max_angle_from_vertical(self) -> np.ndarray:
        """Largest tether angle from the vertical along the line [rad]."""
        return np.max(0.5 * np.pi - self.elevation, axis=0)


def _line_load(tx, tz, u, kn, kt, w_line, inv_ea):
    """Line load per length (f_x, f_z) [N/m] and stretched direction (dX/ds, dZ/ds) [-].

    ``kn`` = 1/2 rho d C_dn, ``kt`` = 1/2 rho pi d C_dt [kg/m2]. The plain definition of the
    load: :func:`_march_plain` steps it; :func:`march` evaluates the same load on a stacked
    complex state for narrow batches (for speed; the test suite checks the two agree).
    """
    t = np.sqrt(tx * tx + tz * tz) + 1e-300
    ct = tx / t
    st = tz / t
    un = u * st
    ut = u * ct
    fn = kn * np.abs(un) * un
    ft = kt * np.abs(ut) * ut
    stretch = 1.0 + t * inv_ea
    return fn * st + ft * ct, ft * st - fn * ct - w_line, stretch * ct, stretch * st


#: Batch width above which the march runs on separate arrays (:func:`_march_plain`): there
#: the arithmetic, not numpy's per-call overhead, is the cost, and the real-valued form has
#: less of it than the complex one (about 450 columns on a 2026 x86-64 machine).
_WIDE = 400


def _march_plain(tx0, tz0, length, spec, air_density, wind, heights, weight_per_length,
                 segments, shape):
    """:func:`march` for wide batches: Heun's method with :func:`_line_load` on one array per
    component (the plain definition)."""
    ds = length / segments
    tx = np.empty((segments + 1,) + shape)
    tz = np.empty_like(tx)
    x = np.empty_like(tx)
    z = np.empty_like(tx)
    tx[0], tz[0], x[0], z[0] = tx0, tz0, 0.0, 0.0
    u_nodes = wind(heights) * np.ones((segments + 1,) + shape)
    rho = np.asarray(air_density, float)
    kn = 0.5 * rho * spec.diameter * spec.normal_drag_coefficient
    kt = 0.5 * rho * np.pi * spec.diameter * spec.tangential_drag_coefficient
    inv_ea = 1.0 / spec.axial_stiffness
    w = weight_per_length
    h = 0.5 * ds
    tx_i, tz_i, x_i, z_i = tx[0], tz[0], x[0], z[0]  # the running node, kept as locals
    u_i = u_nodes[0]
    for i in range(segments):
        u_j = u_nodes[i + 1]
        fx1, fz1, cx1, cz1 = _line_load(tx_i, tz_i, u_i, kn, kt, w, inv_ea)
        fx2, fz2, cx2, cz2 = _line_load(tx_i + ds * fx1, tz_i + ds * fz1, u_j, kn, kt, w, inv_ea)
        tx_i = tx[i + 1] = tx_i + h * (fx1 + fx2)
        tz_i = tz[i + 1] = tz_i + h * (fz1 + fz2)
        x_i = x[i + 1] = x_i - h * (cx1 + cx2)
        z_i = z[i + 1] = z_i - h * (cz1 + cz2)
        u_i = u_j
    return tx, tz, x, z


def march(
    top_tension_x,
    top_tension_z,
    length: float,
    spec: TetherSpec,
    air_density,
    wind: Callable[[np.ndarray], np.ndarray],
    heights,
    weight_per_length: float,
    segments: int = 50,
):
    """Integrate the tether from the top (confluence point) down to the winch.

    Parameters
    ----------
    top_tension_x, top_tension_z : array_like
        Tension components at the top [N] = (aerostat drag, aerostat net lift).
    length : float
        Unstretched tether length [m].
    spec : TetherSpec
    air_density : array_like
        [kg/m3] (uniform along the line).
    wind : callable
        ``wind(z)`` -> horizontal wind [m/s] at heights ``z`` [m] (broadcasts).
    heights : array_like
        Estimated node heights above the winch [m], shape (segments + 1, ...), used to look up
        the wind (the caller iterates for sheared wind).
    weight_per_length : float
        Line weight in air net of buoyancy [N/m].
    segments : int
        Number of segments n_s.

    Returns
    -------
    tx, tz, dx, dz : ndarray, shape (segments + 1, ...)
        Tension components and node offsets from the top [m].

    Notes
    -----
    Heun's method on the ODE of the module docstring, with the load of :func:`_line_load`.
    Batches of up to ``_WIDE`` columns (every single design, sweep and sizing grid) step it
    on a stacked complex state (below); wider ones run :func:`_march_plain`. Both give the
    same numbers to a few ulp per step.
    """
    tx0 = np.asarray(top_tension_x, float)
    tz0 = np.asarray(top_tension_z, float)
    shape = np.broadcast(tx0, tz0, heights[0]).shape
    n = int(np.prod(shape, dtype=int))
    if n > _WIDE:
        return _march_plain(tx0, tz0, length, spec, air_density, wind, heights,
                            weight_per_length, segments, shape)
    ds = length / segments
    rho = np.asarray(air_density, float)
    kn = 0.5 * rho * spec.diameter * spec.normal_drag_coefficient
    kt = 0.5 * rho * np.pi * spec.diameter * spec.tangential_drag_coefficient
    # The Heun scheme of _line_load, stepped over a complex state: a pair (a, b) is a + ib,
    # so the tension is T = T_x + i T_z, its direction e = T/|T| = cos + i sin, and the load
    # f = e (f_t - i f_n) - i w' is one complex product, with (f_t, -f_n) = (k_t |u| u |cos|
    # cos, -k_n |u| u |sin| sin). Each step is ~25 numpy calls on same-shape contiguous arrays
    # with the output given positionally (no broadcasting, no scalar conversion, no
    # allocation): numpy's per-call overhead, not the arithmetic, is the cost at the usual
    # 20-60 columns. The floats are those of _line_load to a few ulp (products regrouped; |T|
    # is np.hypot; the stretched direction (1 + T/EA) e is written e + T/EA).
    y = np.zeros((segments + 1, 2, n), complex)  # y[node] = (T, -(X + iZ))
    yf = y.view(float).reshape(segments + 1, 2, n, 2)
    yf[0, 0, :, 0] = np.broadcast_to(tx0, shape).reshape(n)
    yf[0, 0, :, 1] = np.broadcast_to(tz0, shape).reshape(n)
    u = (wind(heights) * np.ones((segments + 1,) + shape)).reshape(segments + 1, n, 1)
    k = np.empty((n, 2))
    k[:, 0] = np.broadcast_to(kt, shape).reshape(n)
    k[:, 1] = -np.broadcast_to(kn, shape).reshape(n)
    ku = k * (np.abs(u) * u)  # (k_t |u| u, -k_n |u| u) at every node
    tiny, ds_, h = np.array(1e-300), np.array(ds, complex), np.array(0.5 * ds, complex)
    inv_ea = np.array(1.0 / spec.axial_stiffness, complex)
    iw = np.array(1j * weight_per_length)
    t = np.zeros(n, complex)  # |T| + 0i (the imaginary part stays 0)
    t_re = t.view(float)[0::2]
    e = np.empty(n, complex)
    ef = e.view(float).reshape(n, 2)
    g = np.empty((n, 2))  # (f_t, -f_n)
    gc = g.view(complex)[:, 0]
    va = np.empty((n, 2))
    k1, k2, acc = (np.empty((2, n), complex) for _ in range(3))  # d/ds of y: (f, e + T/EA)
    tp = np.empty(n, complex)  # the Heun predictor of the tension
    mul, add, sub, div, absolute = np.multiply, np.add, np.subtract, np.divide, np.absolute

    # views made once (indexing an array costs as much as a small ufunc call)
    rows = list(y)
    tens = [r[0] for r in rows]
    kus = list(ku)
    f1, d1, f2, d2 = k1[0], k1[1], k2[0], k2[1]

    # the two load evaluations of a step, written out (a Python call per stage costs too)
    for i in range(segments):
        tc = tens[i]
        absolute(tc, t_re)
        add(t_re, tiny, t_re)
        div(tc, t, e)
        absolute(ef, va)
        mul(va, ef, va)
        mul(va, kus[i], g)
        mul(e, gc, f1)
        sub(f1, iw, f1)  # f_x + i f_z
        mul(tc, inv_ea, d1)
        add(d1, e, d1)  # -d(X + iZ)/ds
        mul(f1, ds_, tp)
        add(tc, tp, tp)
        absolute(tp, t_re)
        add(t_re, tiny, t_re)
        div(tp, t, e)
        absolute(ef, va)
        mul(va, ef, va)
        mul(va, kus[i + 1], g)
        mul(e, gc, f2)
        sub(f2, iw, f2)
        mul(tp, inv_ea, d2)
        add(d2, e, d2)
        add(k1, k2, acc)
        mul(acc, h, acc)
        add(rows[i], acc, rows[i + 1])
    full = (segments + 1,) + shape
    tx = np.ascontiguousarray(yf[:, 0, :, 0]).reshape(full)
    tz = np.ascontiguousarray(yf[:, 0, :, 1]).reshape(full)
    x = (-yf[:, 1, :, 0]).reshape(full)
    z = (-yf[:, 1, :, 1]).reshape(full)
    return tx, tz, x, z


def solve_tether(
    top_tension: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]],
    length: float,
    spec: TetherSpec,
    air_density,
    wind: Callable[[np.ndarray, np.ndarray], np.ndarray],
    weight_per_length: float,
    segments: int = 50,
    sheared: bool = True,
    max_passes: int = 8,
    tol: float = 1e-6,
    heights_hint=None,
) -> TetherSolution:
    """Static tether shape with the wind evaluated at the converged node heights.

    Parameters
    ----------
    top_tension : callable
        ``top_tension(height)`` -> (T_x, T_z) at the top [N] given the top's height [m] (the
        aerostat's drag can depend on the wind at its height).
    length : float
        Unstretched length [m].
    spec : TetherSpec
    air_density : array_like [kg/m3]
    wind : callable
        ``wind(z, height)`` -> wind [m/s] at heights ``z`` given the top height ``height``.
    weight_per_length : float [N/m]
    segments : int
    sheared : bool
        False when the wind is uniform in height (one pass is exact).
    max_passes : int
        Fixed-point passes on the node heights (sheared wind).
    tol : float
        Height convergence tolerance [m]: the passes stop when the top height and every node
        height of a march's output are within ``tol`` of the heights it was marched with.
    heights_hint : array_like or callable, optional
        Node heights above the winch [m] (top first) to start the passes from instead of the
        vertical line: a warm start, e.g. the converged heights of a neighbouring solve
        (:func:`interpolated_heights`). Broadcast to shape (segments + 1, ...) of the batch;
        negative heights are taken as 0 and a column with a non-finite entry starts from the
        vertical line. A callable is called as ``heights_hint(T_x, T_z)`` with the top
        tension at the tether length's height. Ignored when ``sheared`` is False. A hint
        changes only the number of passes, not the fixed point they converge to (to within
        ``tol``).

    Returns
    -------
    TetherSolution

    Notes
    -----
    The fixed point is H = G(H): the node heights H (winch = 0) at which the wind is looked up
    reproduce themselves through the march G. From a vertical line, plain passes H <- G(H)
    contract by ~0.03 a pass on a 300 m line (the slowest mode of dG/dH, nearly a scaling of
    the line); from the third march on, an Anderson step of depth 1 (Walker & Ni, SIAM J.
    Numer. Anal. 49, 2011) takes the rate to ~0.002-0.02, so ~5 marches instead of ~7. It
    only recombines the two latest outputs of G, so a converged answer is G's own fixed point.

    Warm start (``heights_hint``; docs/methods.md §1.9): the passes start from given heights
    instead of the vertical line. A pass shrinks the error ~30-100 times, so a start within
    ~0.5 m saves one march of the ~5 from the vertical line, one within a few cm two. For a
    power law the wind depends only on z / z_top, so a hint of the right shape but the wrong
    scale is as good as the answer itself. The passes stop when every column has converged
    or was slack in the last two marches (its clipped heights need not settle; the
    taut_tether constraint rejects the line), or after ``max_passes``.
    """
    s = np.linspace(0.0, length, segments + 1)
    height = np.asarray(length, float)
    tx0, tz0 = top_tension(height)
    shape = np.broadcast(tx0, tz0).shape
    vertical = (length - s).reshape((-1,) + (1,) * len(shape))
    if sheared and heights_hint is not None:
        if callable(heights_hint):
            heights_hint = heights_hint(tx0, tz0)
        hint = np.asarray(heights_hint, float)
        try:
            shape = np.broadcast_shapes(shape, hint.shape[1:])
            hint = np.broadcast_to(hint, (segments + 1,) + shape)
        except ValueError:
            raise ValueError(f"heights_hint: shape {hint.shape} does not broadcast to "
                             f"({segments + 1} nodes,) + batch {shape}") from None
        heights = np.where(np.isfinite(hint).all(axis=0), np.maximum(hint, 0.0), vertical)
        height = heights[0].copy()
    else:
        heights = vertical * np.ones((1,) + shape)
        height = np.full(shape, float(length))
    passes = max_passes if sheared else 1
    prev = None  # (plain update, its residual, top height) of the previous pass
    was_slack = np.zeros(shape, bool)
    for p in range(passes):
        tx0, tz0 = top_tension(height)
        tx, tz, x, z = march(
            tx0, tz0, length, spec, air_density, lambda zz, h=height: wind(zz, h), heights,
            weight_per_length, segments,
        )
        new_height = -z[-1]
        if p == passes - 1:  # no next pass to prepare
            break
        g = np.maximum(z - z[-1], 0.0)  # the plain fixed-point update of the node heights
        f = g - heights
        # converged: the top and every node within tol (an accelerated step can leave the top
        # closer than the nodes below it, unlike a plain pass), in every column but those
        # slack in this march and the one before: a line that sags onto the winch's level has
        # clipped heights that need not settle (the taut_tether constraint rejects it), and
        # waiting for it would only hold up the rest of the batch (it never gets a pass more
        # than before: max_passes still ends it)
        slack = np.any(tz <= 0.0, axis=0)
        settled = (np.abs(new_height - height) < tol) & np.all(np.abs(f) < tol, axis=0)
        if np.all(settled | (slack & was_slack)):
            break
        was_slack = slack
        if prev is None:
            heights, height_next = g, new_height
        else:
            # Anderson acceleration of depth 1, per column: the plain update moved back along
            # the last change of the update, by the secant estimate gamma = c/(c - 1) of the
            # slowest contraction c from the last two residuals (the fixed point is the plain
            # iteration's; it takes ~5 marches instead of ~7 on a 300 m line). Safeguards:
            # gamma kept to c in [-1, 0.5], and the plain update where the top's residual
            # grew.
            g_prev, f_prev, top_prev = prev
            df = f - f_prev
            den = np.sum(df * df, axis=0)
            gamma = np.sum(f * df, axis=0) / np.where(den > 0.0, den, 1.0)
            shrinking = np.abs(f[0]) < np.abs(f_prev[0])
            gamma = np.where(shrinking & (den > 0.0), np.clip(gamma, -1.0, 0.5), 0.0)
            heights = np.maximum(g - gamma * (g - g_prev), 0.0)
            height_next = new_height - gamma * (new_height - top_prev)
        prev = g, f, new_height
        height = height_next
    tension = np.hypot(tx, tz)
    elevation = np.arctan2(tz, tx)
    return TetherSolution(
        x=x - x[-1],
        z=z - z[-1],
        tension=tension,
        elevation=elevation,
        blow_by=-x[-1],
        height=-z[-1],
        slack=np.any(tz <= 0.0, axis=0),
    )


def interpolated_heights(top_tension_x, top_tension_z, elevation, z, length: float,
                         vertical: bool = False) -> np.ndarray:
    """Estimated node heights of a tether from solved ones: a warm start (``heights_hint``)
    for :func:`solve_tether`.

    The elevation profile theta_i (node i) of the known solutions, and the part of each
    segment's rise that is not ds sin(theta) (its stretch), are interpolated per node in the
    top elevation theta_0 = atan2(T_z, T_x) (Lagrange, through the K known columns and, with
    ``vertical``, the vertical line theta = pi/2 without stretch), then the rises summed from
    the winch up: z_i = sum_{j >= i} [ds sin((theta_j + theta_{j+1}) / 2) + stretch part].
    A line's shape follows its top angle far more closely than its heights do (on a 300 m
    line at 0-20 m/s, within ~0.5 m where heights interpolated in wind speed miss by ~4 m).

    Parameters
    ----------
    top_tension_x, top_tension_z : array_like
        Top tension of the lines to estimate [N] (shape S).
    elevation, z : array_like, shape (nodes, K, ...)
        ``TetherSolution.elevation`` [rad] and ``.z`` [m] of K solved lines (the second axis)
        of the same length and segments on the same tether; ``...`` broadcasts against S.
    length : float
        Unstretched tether length [m].
    vertical : bool
        Add the vertical line as a known column (the zero-wind solution, stretch ignored).

    Returns
    -------
    ndarray, shape (nodes,) + S
        Node heights above the winch [m]; only a start: :func:`solve_tether` converges to the
        same heights from it as from any other start (docs/methods.md §1.9).
    """
    el = np.asarray(elevation, float)
    z = np.asarray(z, float)
    n = el.shape[0] - 1
    ds = length / n
    rise = z[:-1] - z[1:]
    extra = rise - ds * np.sin(0.5 * (el[:-1] + el[1:]))
    x_known = el[0]  # (K, ...)
    if vertical:
        el = np.concatenate([np.full((n + 1, 1) + el.shape[2:], 0.5 * np.pi), el], axis=1)
        extra = np.concatenate([np.zeros((n, 1) + extra.shape[2:]), extra], axis=1)
        x_known = el[0]
    x = np.arctan2(np.asarray(top_tension_z, float), np.asarray(top_tension_x, float))
    k_count = x_known.shape[0]
    batch = np.broadcast_shapes(x.shape, x_known.shape[1:])
    pad = (1,) * (len(batch) - (el.ndim - 2))  # the known columns' batch axes, right-aligned

    def column(a, k):
        return a[:, k].reshape(a.shape[:1] + pad + a.shape[2:])

    el_h = extra_h = 0.0
    with np.errstate(divide="ignore", invalid="ignore"):  # coincident columns: non-finite,
        for k in range(k_count):                          # so solve_tether starts vertical
            w = np.ones(batch)
            for j in range(k_count):
                if j != k:
                    w = w * (x - x_known[j]) / (x_known[k] - x_known[j])
            el_h = el_h + w * column(el, k)
            extra_h = extra_h + w * column(extra, k)
        rise_h = ds * np.sin(0.5 * (el_h[:-1] + el_h[1:])) + extra_h
    heights = np.zeros((n + 1,) + rise_h.shape[1:])
    heights[:-1] = np.cumsum(rise_h[::-1], axis=0)[::-1]
    return heights


def point_aerostat_tether(
    mass: float,
    volume: float,
    drag_area: float,
    spec: TetherSpec,
    length: float,
    air_density: float,
    wind: Callable[[np.ndarray], np.ndarray],
    g: float,
    segments: int = 200,
    max_passes: int = 30,
) -> TetherSolution:
    """Static equilibrium of a point (spherical) aerostat on an elastic tether.

    Top tension = (1/2 rho C_D A U(z_top)^2, rho V g - M g): drag along the wind at the aerostat's
    height and net static lift; the tether shape from :func:`solve_tether`, iterated until the
    top height (and so the wind there) converges. Used for the reference cases R1/R2 of
    docs/dynamics.md §3.1 and as the initial condition of the point-aerostat dynamic mode.

    Parameters
    ----------
    mass : float
        Aerostat mass [kg].
    volume : float
        Displaced volume [m3].
    drag_area : float
        C_D A [m2].
    spec : TetherSpec
    length : float
        Unstretched tether length [m].
    air_density : float
        Uniform air density [kg/m3].
    wind : callable
        ``wind(z)`` -> horizontal wind [m/s] at height ``z`` [m] above the anchor.
    g : float
        Gravity [m/s2].
    segments : int
        Tether segments.

    Returns
    -------
    TetherSolution
    """
    net = air_density * volume * g - mass * g
    w_line = (spec.linear_density - air_density * np.pi * spec.diameter**2 / 4.0) * g

    def top(h):
        u = wind(h)
        return 0.5 * air_density * drag_area * np.abs(u) * u, net * np.ones_like(u)

    return solve_tether(top, length, spec, air_density, lambda z, h: wind(z), w_line,
                        segments, sheared=True, max_passes=max_passes, tol=1e-9)
