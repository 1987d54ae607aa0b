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
    load: :func:`_march_plain` steps it in numpy; :func:`march` steps the same arithmetic in a
    compiled kernel (:mod:`aerostat_core.tether.march_kernel`; the test suite checks the two
    agree).
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


def _march_plain(tx0, tz0, length, spec, air_density, wind, heights, weight_per_length,
                 segments, shape):
    """:func:`march` in numpy: Heun's method with :func:`_line_load` on one array per
    component (the plain definition, which the compiled kernel of :func:`march` steps; the
    test suite checks the two agree)."""
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
    r"""Integrate the tether from the top (confluence point) down to the winch.

    Heun's method in unstretched arc length s (down the line), elevation theta = atan2(T_z, T_x):

    .. math::

        \frac{dT_x}{ds} = f_x, \quad \frac{dT_z}{ds} = f_z - w', \quad
        \frac{dX}{ds} = -\left(1 + \frac{T}{EA}\right)\cos\theta, \quad
        \frac{dZ}{ds} = -\left(1 + \frac{T}{EA}\right)\sin\theta,

        \mathbf f = \tfrac12 \rho d C_{dn} |U \sin\theta| U \sin\theta\, (\sin\theta, -\cos\theta)
        + \tfrac12 \rho \pi d C_{dt} |U \cos\theta| U \cos\theta\, (\cos\theta, \sin\theta)

    Parameters
    ----------
    top_tension_x, top_tension_z : array_like
        Tension components at the top [N] = (aerostat drag, aerostat net lift).
    length : float
        Unstretched tether length [m], > 0.
    spec : TetherSpec
        Diameter, drag coefficients and EA of the line.
    air_density : array_like
        [kg/m3] (uniform along the line).
    wind : callable
        ``wind(z)`` -> horizontal wind [m/s] at heights ``z`` [m] (broadcasts).
    heights : array_like
        Estimated node heights above the winch [m], shape (segments + 1, ...), used to look up
        the wind (the caller iterates for sheared wind).
    weight_per_length : float
        Line weight in air net of buoyancy w' [N/m].
    segments : int
        Number of segments n_s [-], valid >= 1 (the tether_segments input:
        {range:Configuration.tether_segments}).

    Returns
    -------
    tx, tz, dx, dz : ndarray, shape (segments + 1, ...)
        Tension components [N] and node offsets from the top [m].

    Notes
    -----
    Valid for a taut line (T_z > 0: the elevation stays defined) in steady wind; second order in
    ds. Every column and segment is stepped in one compiled loop
    (:func:`aerostat_core.tether.march_kernel.heun_march`, the arithmetic of ``_line_load``):
    numpy's per-call overhead, ~1,250 calls a 50-segment line, was the cost of the numpy form
    (``_march_plain``, kept as the reference definition).
    Source: Rajani, Pant & Sudhakar (2010) (thesis Fig. 3.10), extended as in docs/methods.md
    §1.9 (S2); drag split as in MoorDyn.

    Examples
    --------
    No wind, 1000 N up at the top, 2 N/m of line, EA = 1e6 N: the winch sees 1000 - 200 = 800 N
    and the line stretches int T/EA ds = (1000 x 100 - 2 x 100^2/2)/1e6 = 0.09 m (by hand; Heun
    is exact for this linear tension):

    >>> from aerostat_core.structures.materials import TetherSpec
    >>> h = np.linspace(100.0, 0.0, 51)
    >>> tx, tz, dx, dz = march(0.0, 1000.0, 100.0, TetherSpec(axial_stiffness=1e6), 1.2,
    ...                        lambda z: 0.0 * z, h, 2.0)
    >>> round(float(tz[-1]), 9), round(float(dz[-1]), 9)
    (800.0, -100.09)
    """
    tx0 = np.asarray(top_tension_x, float)
    tz0 = np.asarray(top_tension_z, float)
    shape = np.broadcast(tx0, tz0, heights[0]).shape
    n = int(np.prod(shape, dtype=int))
    full = (segments + 1,) + shape
    rho = np.asarray(air_density, float)
    kn = 0.5 * rho * spec.diameter * spec.normal_drag_coefficient
    kt = 0.5 * rho * np.pi * spec.diameter * spec.tangential_drag_coefficient
    u = wind(heights)
    out = _heun_march()(
        _flat(tx0, shape, n), _flat(tz0, shape, n), _flat(u, full, (segments + 1, n)),
        _flat(kn, shape, n), _flat(kt, shape, n),
        float(weight_per_length), float(1.0 / spec.axial_stiffness), float(length / segments),
    )
    return out[0].reshape(full), out[1].reshape(full), out[2].reshape(full), out[3].reshape(full)


def _flat(a, shape, flat):
    """``a`` broadcast to ``shape`` as a C-contiguous float64 array of shape ``flat`` (the
    kernel's argument types; no copy when it already is one)."""
    a = np.asarray(a, float)
    if a.shape != shape or not a.flags.c_contiguous:
        a = np.ascontiguousarray(np.broadcast_to(a, shape))
    return a.reshape(flat)


def _heun_march():
    """The compiled kernel of :func:`march` (:func:`aerostat_core.tether.march_kernel.heun_march`),
    imported on the first march so that importing the library does not import numba."""
    from aerostat_core.tether.march_kernel import heun_march

    return heun_march


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
    r"""Static tether shape with the wind evaluated at the converged node heights.

    Solves the fixed point H = G(H): the node heights H (winch = 0) at which the wind is looked
    up reproduce themselves through the march G of :func:`march`:

    .. math::

        H^{(n+1)} = G\left(H^{(n)}\right) - \gamma_n \left(G(H^{(n)}) - G(H^{(n-1)})\right),
        \qquad \gamma_n = \frac{\langle F_n, F_n - F_{n-1} \rangle}{\| F_n - F_{n-1} \|^2},
        \; F_n = G(H^{(n)}) - H^{(n)}

    (Anderson acceleration of depth 1 from the third march on; gamma = 0 is the plain pass).

    Parameters
    ----------
    top_tension : callable
        ``top_tension(height)`` -> (T_x, T_z) at the top [N] given the top's height [m] (the
        aerostat's drag can depend on the wind at its height).
    length : float
        Unstretched length [m], > 0.
    spec : TetherSpec
        The line.
    air_density : array_like
        [kg/m3].
    wind : callable
        ``wind(z, height)`` -> wind [m/s] at heights ``z`` given the top height ``height``.
    weight_per_length : float
        Line weight in air net of buoyancy [N/m].
    segments : int
        Number of segments [-], valid >= 1.
    sheared : bool
        False when the wind is uniform in height (one pass is exact).
    max_passes : int
        Fixed-point passes on the node heights (sheared wind) [-], >= 1.
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
    Valid as :func:`march`. From a vertical line, plain passes contract by ~0.03 a pass on a 300 m
    line (the slowest mode of dG/dH, nearly a scaling of the line); the Anderson step (Walker &
    Ni, SIAM J. Numer. Anal. 49, 2011) takes the rate to ~0.002-0.02, so ~5 marches instead of
    ~7. It only recombines the two latest outputs of G, so a converged answer is G's own fixed
    point.

    Warm start (``heights_hint``): the passes start from given heights instead of the vertical
    line. A pass shrinks the error ~30-100 times, so a start within ~0.5 m saves one march of the
    ~5 from the vertical line, one within a few cm two. For a power law the wind depends only on
    z / z_top, so a hint of the right shape but the wrong scale is as good as the answer itself.
    The passes stop when every column has converged or was slack in the last two marches (its
    clipped heights need not settle; the taut_tether constraint rejects the line), or after
    ``max_passes``. Source: docs/methods.md §1.9.

    Examples
    --------
    The no-wind line of :func:`march`: height 100.09 m, 800 N at the winch, no blow-by:

    >>> from aerostat_core.structures.materials import TetherSpec
    >>> s = solve_tether(lambda h: (0.0 * h, 1000.0 + 0.0 * h), 100.0,
    ...                  TetherSpec(axial_stiffness=1e6), 1.2, lambda z, h: 0.0 * z, 2.0,
    ...                  sheared=False)
    >>> round(float(s.height), 9), round(float(s.tension_winch), 9), float(s.blow_by)
    (100.09, 800.0, 0.0)
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
    r"""Estimated node heights of a tether from solved ones: a warm start (``heights_hint``) for
    :func:`solve_tether`.

    The elevation profile theta_i of the K known solutions, and the part of each segment's rise
    that is not ds sin(theta) (its stretch, e_i), are interpolated per node in the top elevation
    theta_0 = atan2(T_z, T_x) by Lagrange polynomials, then the rises summed from the winch up:

    .. math::

        \theta_i(x) = \sum_{k=1}^{K} \ell_k(x)\, \theta_{i,k}, \qquad
        \ell_k(x) = \prod_{j \ne k} \frac{x - x_j}{x_k - x_j}, \qquad
        z_i = \sum_{j \ge i} \left[ds \sin\frac{\theta_j + \theta_{j+1}}{2} + e_j\right]

    (with ``vertical``, the vertical line theta = pi/2 without stretch is one more known column).
    A line's shape follows its top angle far more closely than its heights do (on a 300 m line at
    0-20 m/s, within ~0.5 m where heights interpolated in wind speed miss by ~4 m).

    Parameters
    ----------
    top_tension_x, top_tension_z : array_like
        Top tension of the lines to estimate [N] (shape S).
    elevation : array_like, shape (nodes, K, ...)
        ``TetherSolution.elevation`` [rad] of K solved lines (the second axis) of the same length
        and segments on the same tether; ``...`` broadcasts against S.
    z : array_like, shape (nodes, K, ...)
        ``TetherSolution.z`` [m] of the same lines.
    length : float
        Unstretched tether length [m].
    vertical : bool
        Add the vertical line as a known column (the zero-wind solution, stretch ignored).

    Returns
    -------
    ndarray, shape (nodes,) + S
        Node heights above the winch [m]; only a start: :func:`solve_tether` converges to the
        same heights from it as from any other start.

    Notes
    -----
    Valid between the known top elevations (a Lagrange polynomial extrapolates poorly).
    Source: docs/methods.md §1.9 (warm start).

    Examples
    --------
    At a known column's own top angle the estimate is that column (the no-wind line of
    :func:`solve_tether`, 100.09 m high):

    >>> from aerostat_core.structures.materials import TetherSpec
    >>> s = solve_tether(lambda h: (0.0 * h, 1000.0 + 0.0 * h), 100.0,
    ...                  TetherSpec(axial_stiffness=1e6), 1.2, lambda z, h: 0.0 * z, 2.0,
    ...                  sheared=False)
    >>> h = interpolated_heights(0.0, 1.0, s.elevation[:, None], s.z[:, None], 100.0)
    >>> round(float(h[0]), 9), bool(np.allclose(h, s.z))
    (100.09, True)
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
    r"""Static equilibrium of a point (spherical) aerostat on an elastic tether.

    Drag along the wind at the aerostat's height and net static lift at the top; the tether shape
    from :func:`solve_tether`, iterated until the top height (and so the wind there) converges:

    .. math::

        T_{x,top} = \tfrac12 \rho\, C_D A\, |U(z_{top})|\, U(z_{top}), \qquad
        T_{z,top} = \rho V g - M g, \qquad
        w' = \left(\lambda - \rho \frac{\pi d^2}{4}\right) g

    Parameters
    ----------
    mass : float
        Aerostat mass M [kg].
    volume : float
        Displaced volume V [m3].
    drag_area : float
        C_D A [m2].
    spec : TetherSpec
        The line (linear density lambda, diameter d).
    length : float
        Unstretched tether length [m].
    air_density : float
        Uniform air density [kg/m3].
    wind : callable
        ``wind(z)`` -> horizontal wind [m/s] at height ``z`` [m] above the anchor.
    g : float
        Gravity [m/s2].
    segments : int
        Tether segments [-], valid >= 1.
    max_passes : int
        Fixed-point passes [-] (:func:`solve_tether`).

    Returns
    -------
    TetherSolution

    Notes
    -----
    Valid for positive net lift (T_z > 0 along the line). Used for the reference cases R1/R2 of
    docs/dynamics.md §3.1 and as the initial condition of the point-aerostat dynamic mode.
    Source: docs/dynamics.md §3.1; statics as :func:`march`.

    Examples
    --------
    No wind, inextensible 20 g/m line: the top pulls (1.2 x 100 - 50) g = 686.47 N, the winch
    686.47 - 100 (0.020 - 1.2 pi 0.005^2/4) g = 666.88 N (by hand):

    >>> import math
    >>> from aerostat_core.structures.materials import TetherSpec
    >>> s = point_aerostat_tether(50.0, 100.0, 1.0, TetherSpec(axial_stiffness=math.inf), 100.0,
    ...                           1.2, lambda z: 0.0 * np.asarray(z, float), 9.80665)
    >>> round(float(s.height), 6), round(float(s.tension_top), 2), round(float(s.tension_winch), 2)
    (100.0, 686.47, 666.88)
    """
    net = air_density * volume * g - mass * g
    w_line = (spec.linear_density - air_density * np.pi * spec.diameter**2 / 4.0) * g

    def top(h):
        u = wind(h)
        return 0.5 * air_density * drag_area * np.abs(u) * u, net * np.ones_like(u)

    return solve_tether(top, length, spec, air_density, lambda z, h: wind(z), w_line,
                        segments, sheared=True, max_passes=max_passes, tol=1e-9)
