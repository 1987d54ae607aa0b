"""Aerodynamic loads, moment balance about the confluence point, equilibrium and stability.

Sign conventions (docs/methods.md §1): earth X downwind, Z up; the nose faces the wind; alpha is the
nose-up pitch (= angle of attack in a horizontal wind); moments are nose-up positive.
A body point (xi, z) sits at X = xi cos a + z sin a, Z = -xi sin a + z cos a from the nose.
"""

from __future__ import annotations

import copy
import functools
from dataclasses import dataclass

import numpy as np

from aerostat_core.aerodynamics.drag import volumetric_drag_coefficient
from aerostat_core.aerodynamics.forces import (
    body_to_wind,
    fin_lift_drag,
    hull_axial,
    hull_crossflow,
    hull_inviscid,
    reynolds_number,
)
from aerostat_core.aerodynamics.helikite import kite_lift_drag
from aerostat_core.geometry.shapes import SHAPE_INFO
from aerostat_core.model.airframe import Airframe
from aerostat_core.model.inputs import AeroModel


@dataclass(frozen=True)
class AeroLoads:
    """Loads at (alpha, q): lift and drag [N] of hull and fins, and the hull's couple about xi_m
    [N m]. Hull forces act at xi_m (body axis), fin forces at the fin aerodynamic centre."""

    hull_lift: np.ndarray
    hull_drag: np.ndarray
    hull_moment: np.ndarray
    fin_lift: np.ndarray
    fin_drag: np.ndarray

    @property
    def lift(self) -> np.ndarray:
        """Total dynamic lift [N]."""
        return self.hull_lift + self.fin_lift

    @property
    def drag(self) -> np.ndarray:
        """Total drag [N]."""
        return self.hull_drag + self.fin_drag


def axial_drag_coefficient(af: Airframe, aero: AeroModel, speed):
    """Hull zero-lift drag coefficient on V^(2/3): the shape's C_DV(f, Re)
    (:func:`aerostat_core.aerodynamics.drag.volumetric_drag_coefficient`; Hoerner for NPL) or the given
    value."""
    if aero.hull_axial_drag is not None:
        return np.full(np.broadcast(af.hull.length, speed).shape, aero.hull_axial_drag)
    re = reynolds_number(af.air_density, speed, af.hull.length, af.viscosity)
    return volumetric_drag_coefficient(af.hull.shape, af.hull.fineness_ratio, re)


def aero_loads(af: Airframe, aero: AeroModel, alpha, speed, cd0=None) -> AeroLoads:
    """Hull and fin loads at angle of attack ``alpha`` [rad] and airspeed ``speed`` [m/s].

    Hull (Jones & DeLaurier): N_h = inviscid + cross-flow, A_h = axial + inviscid,
    M_h about xi_m; fins: lift and drag from :func:`aerostat_core.aerodynamics.forces.fin_lift_drag`.
    ``cd0`` (volumetric drag coefficient) may be passed to avoid recomputing it.
    Bluff hulls (sphere, oblate, Helikite) are drag-only: D_h = q C_DV V^(2/3) along the wind,
    no hull lift or moment; the Helikite's kite lift and drag act at the centre of buoyancy.
    """
    q = 0.5 * af.air_density * np.asarray(speed, float) ** 2
    if cd0 is None:
        cd0 = axial_drag_coefficient(af, aero, speed)
    h = af.hull
    dk = h.k2 - h.k1
    n_i, a_i, m_i = hull_inviscid(q, alpha, dk, aero.hull_efficiency, af.i1, af.i3)
    n_c, m_c = hull_crossflow(q, alpha, aero.hull_crossflow_drag, af.j1, af.j2)
    a_x = hull_axial(q, alpha, cd0, h.reference_area)
    lift_h, drag_h = body_to_wind(n_i + n_c, a_i + a_x, alpha)
    m_h = m_i + m_c
    if not SHAPE_INFO[h.shape].streamlined:
        drag_h = q * cd0 * h.reference_area * np.ones_like(lift_h)
        lift_h, m_h = np.zeros_like(drag_h), np.zeros_like(drag_h)
        if af.kite is not None:
            lk, dk = kite_lift_drag(q, af.kite)
            lift_h, drag_h = lift_h + lk, drag_h + dk
    fn = af.fins
    lift_f, drag_f = fin_lift_drag(
        q, alpha, fn.lift_slope, aero.fin_efficiency, np.radians(aero.fin_stall_angle_deg),
        fn.lifting_area, fn.area_total, aero.fin_zero_lift_drag, fn.aspect_ratio, fn.oswald,
    )
    return AeroLoads(lift_h, drag_h, m_h, lift_f, drag_f)


def _ccw(dxi, dz, ca, sa, fx, fz):
    """Counter-clockwise moment of earth force (fx, fz) at body offset (dxi, dz) from C."""
    dx = dxi * ca + dz * sa
    dzz = -dxi * sa + dz * ca
    return dx * fz - dzz * fx


def moment_about_confluence(af: Airframe, aero: AeroModel, alpha, speed, cd0=None):
    """Nose-up pitching moment about the confluence point M_C(alpha) [N m].

    M_C = -sum_P (dX_P F_Z,P - dZ_P F_X,P) + M_h, over buoyancy (0, F_B) at the centre of
    buoyancy, weight (0, -W_a) at the CG, hull aero (D_h, L_h) at xi_m with its couple M_h, and
    fin aero (D_f, L_f) at the fin aerodynamic centre. The tether acts at C: no moment.

    Parameters
    ----------
    af : Airframe
    aero : AeroModel
    alpha : array_like
        Pitch = angle of attack [rad].
    speed : array_like
        Horizontal wind at the hull [m/s].

    Notes
    -----
    Source: docs/methods.md §1.8 (Rajani et al. 2010 method, S2/S4).
    """
    ld = aero_loads(af, aero, alpha, speed, cd0)
    ca, sa = np.cos(alpha), np.sin(alpha)
    xc, zc = af.xi_c, af.z_c
    m = _ccw(af.hull.xi_cb - xc, -zc, ca, sa, 0.0, af.buoyancy)
    m = m + _ccw(af.mass.xi_cg - xc, af.mass.z_cg - zc, ca, sa, 0.0, -af.aerostat_weight)
    m = m + _ccw(af.xi_m - xc, -zc, ca, sa, ld.hull_drag, ld.hull_lift)
    m = m + _ccw(af.fins.xi_ac - xc, -zc, ca, sa, ld.fin_drag, ld.fin_lift)
    return -m + ld.hull_moment


def aerodynamic_moment(af: Airframe, aero: AeroModel, alpha, speed, xi_ref, cd0=None):
    """Nose-up aerodynamic pitching moment of hull and fins about axis station ``xi_ref`` [N m].

    M = -sum (dX F_Z - dZ F_X) + M_h over the hull force (D_h, L_h) at xi_m with its couple M_h
    and the fin force (D_f, L_f) at the fin aerodynamic centre; no buoyancy, weight or tether.
    Its slope dM/dalpha about the centre of volume is the weathervane (aerodynamic) stability of
    the free hull: negative means the hull turns into a change of the flow direction, as a
    vertical gust, without help from the buoyancy pendulum below the confluence point.

    Parameters
    ----------
    af : Airframe
    aero : AeroModel
    alpha : array_like
        Angle of attack [rad].
    speed : array_like
        Airspeed [m/s].
    xi_ref : array_like
        Reference station on the hull axis, from the nose [m].

    Notes
    -----
    Source: docs/methods.md §1.8 ("Cm_alpha can also be quoted about CB/CG"); the need for the fins to
    beat the Munk moment: docs/dynamics.md §1.3.
    """
    ld = aero_loads(af, aero, alpha, speed, cd0)
    ca, sa = np.cos(alpha), np.sin(alpha)
    m = _ccw(af.xi_m - xi_ref, 0.0, ca, sa, ld.hull_drag, ld.hull_lift)
    m = m + _ccw(af.fins.xi_ac - xi_ref, 0.0, ca, sa, ld.fin_drag, ld.fin_lift)
    return -m + ld.hull_moment


#: Step of the central differences of the moment in alpha [rad]: truncation error O(h^2) and
#: rounding O(eps M / h) balance near 1e-5 for moments of 1-1e4 N m (docs/methods.md §1.8).
DIFFERENCE_STEP = 1e-5


def weathervane_slope(
    af: Airframe, aero: AeroModel, alpha, speed, cd0=None, h: float = DIFFERENCE_STEP
):
    """d(aerodynamic moment about the centre of volume)/d(alpha) at ``alpha`` [N m/rad]
    (central difference, step ``h`` [rad]); negative = weathervane stable.

    The moment is :func:`aerodynamic_moment` about ``af.hull.xi_cb`` (evaluated through the
    alpha-expanded form of :class:`MomentKernel`, the same model)."""
    if cd0 is None:
        cd0 = axial_drag_coefficient(af, aero, speed)
    k = MomentKernel(af, aero, speed, cd0, af.hull.xi_cb, static=False)
    return central_difference(k, np.asarray(alpha, float), h)


def central_difference(moment, alpha, h: float = DIFFERENCE_STEP):
    """Slope of a moment function by central difference: (M(alpha + h) - M(alpha - h)) / 2h.

    Parameters
    ----------
    moment : callable
        ``moment(alpha)`` -> pitching moment [N m] (e.g. a :class:`MomentKernel`).
    alpha : array_like
        Angle of attack [rad].
    h : float
        Step [rad]; the default 1e-5 rad is the engine's everywhere (truncation error
        h^2 |d3M/dalpha3| / 6, far below the rounding of M / h).

    Returns
    -------
    ndarray
        dM/dalpha [N m/rad].
    """
    a = np.asarray(alpha, float)
    if isinstance(moment, MomentKernel) and a.shape == moment.shape:
        # one kernel call on both angles (a leading axis of 2): the same floats, half the calls
        pm = moment(np.stack((a + h, a - h)))
        return (pm[0] - pm[1]) / (2.0 * h)
    return (moment(alpha + h) - moment(alpha - h)) / (2.0 * h)


class MomentKernel:
    """A pitching moment M(alpha) [N m] with everything that does not depend on alpha
    computed once: the trim root-finder evaluates it ~10 times per solve, where numpy's
    per-call overhead on small arrays (and not the arithmetic) is the cost.

    ``MomentKernel(af, aero, speed, cd0)`` is the moment about the confluence point of
    :func:`moment_about_confluence`; ``.about(xi_ref)`` the aerodynamic moment about the axis
    station ``xi_ref`` [m] of :func:`aerodynamic_moment`. ``speed`` [m/s] and ``cd0`` (the
    volumetric drag coefficient, :func:`axial_drag_coefficient`) broadcast with the
    airframe's arrays to the batch shape ``.shape``; calling it with alpha [rad] of that shape
    (or with leading axes, as a grid of angles) returns M [N m]. Validity: that of the loads
    (Jones & DeLaurier, |alpha| < 90 deg; docs/methods.md §1.7-1.8).

    The same model as :func:`moment_about_confluence` (``static=True``, about the confluence
    point) or :func:`aerodynamic_moment` (``static=False``, about ``(xi_ref, 0)``), expanded in
    alpha. The hull's body-axis forces (N, A) at xi_m have the moment dxi N - dz A about any
    point, whatever alpha (the rotation cancels), so with c = clip(alpha, +-alpha_s):

    M = cos a (C0 + P4 cos a + c (F2 c - F1)) + sin a (C1 - c (F3 + F4 c))
        + sin 2a (P1 cos a/2 - P3 sin a/2) + P2 sin a |sin a|,

    where C0, C1 hold buoyancy, weight, the fins' zero-lift drag and a bluff hull's constant
    forces; P1-P4 the Jones & DeLaurier hull terms; F1-F4 the fins' lift and induced drag. The
    same floats as the plain functions to rounding (a few ulp of the largest term).

    Parameters
    ----------
    af : Airframe
        The airframe (scalar or batched arrays).
    aero : AeroModel
        Aerodynamic model constants (hull efficiency, cross-flow drag, fin model).
    speed : array_like
        Wind speed at the aerostat [m/s], >= 0.
    cd0 : array_like
        Volumetric zero-lift drag coefficient of the hull [-].
    xi_ref : array_like, optional
        Axis station of the moment reference [m from the nose]; None (default) with
        ``static=True``: the confluence point.
    static : bool
        True: buoyancy and weight included (moment about the confluence point); False: the
        aerodynamic moment only, about ``(xi_ref, 0)``.

    Calling the kernel: ``kernel(alpha)`` with alpha [rad] of the batch shape (or with leading
    axes) returns M [N m], positive nose up.
    """

    def __init__(self, af: Airframe, aero: AeroModel, speed, cd0, xi_ref=None,
                 static: bool = True):
        speed = np.asarray(speed, float)
        self.af = af
        self.shape = np.broadcast(af.hull.length, speed).shape
        q = 0.5 * af.air_density * speed**2
        h, fn = af.hull, af.fins
        # forces per term, independent of the reference point
        if SHAPE_INFO[h.shape].streamlined:
            q1 = q * (h.k2 - h.k1) * aero.hull_efficiency
            qc = q * aero.hull_crossflow_drag
            self._hull = (q1 * af.i1, q1 * af.i3, qc * af.j1, qc * af.j2,
                          q * cd0 * h.reference_area)
            self._bluff = None
        else:  # drag-only hull (and the Helikite's kite): forces constant in alpha
            lift, drag = 0.0, q * cd0 * h.reference_area
            if af.kite is not None:
                lk, dk = kite_lift_drag(q, af.kite)
                lift, drag = lift + lk, drag + dk
            self._hull, self._bluff = None, (lift, drag)
        e = aero.fin_efficiency * fn.lift_slope
        ql = q * fn.lifting_area
        self._fins = (ql * e, ql / (np.pi * fn.oswald * fn.aspect_ratio) * e * e,
                      q * (aero.fin_zero_lift_drag * fn.area_total))
        self.fins = bool(np.any(fn.lifting_area != 0) or np.any(fn.area_total != 0))
        self.stall = np.array(np.radians(aero.fin_stall_angle_deg))
        # angles [deg] where M is not smooth: the fin stall clip (M' jumps) and, with a
        # streamlined hull, alpha = 0 (the cross-flow term's sin a |sin a|: M'' jumps)
        stall = float(aero.fin_stall_angle_deg)
        self.kinks_deg = ((-stall, stall) if self.fins else ()) + (
            (0.0,) if self._hull is not None else ())
        self.two, self.half = np.array(2.0), np.array(0.5)
        self._about(xi_ref, static)

    def about(self, xi_ref, static: bool = False) -> MomentKernel:
        """The same loads' moment about ``(xi_ref, 0)`` (``static``: with buoyancy and weight)."""
        k = copy.copy(self)
        k._about(xi_ref, static)
        return k

    def _about(self, xi_ref, static):
        af, shape = self.af, self.shape
        one = np.ones(shape)

        def full(a):  # every coefficient has the batch shape (on_grid stacks them)
            return a if np.shape(a) == shape else a * one

        xr = af.xi_c if xi_ref is None else xi_ref
        zr = af.z_c if xi_ref is None else 0.0
        dxm, dzm = af.xi_m - xr, -zr
        if static:
            b, w = af.buoyancy, af.aerostat_weight
            c0 = -((af.hull.xi_cb - xr) * b - (af.mass.xi_cg - xr) * w)
            c1 = -(-zr * b - (af.mass.z_cg - zr) * w)
        else:
            c0 = c1 = 0.0
        if self._hull is not None:
            n1, m1, nc, mc, ax = self._hull
            self.p = tuple(full(a) for a in (m1 - dxm * n1, mc - dxm * nc, dzm * n1, dzm * ax))
        else:
            lift, drag = self._bluff
            c0 = c0 - dxm * lift + dzm * drag
            c1 = c1 - dzm * lift - dxm * drag
            self.p = None
        dxf, dzf = af.fins.xi_ac - xr, -zr
        lf, di, d0 = self._fins
        self.c0 = full(c0 + dzf * d0)
        self.c1 = full(c1 - dxf * d0)
        self.f = tuple(full(a) for a in (dxf * lf, dzf * di, dzf * lf, dxf * di))

    def on_grid(self, grid: int):
        """M [N m] on a fixed angle grid, shape (angles,) + ``.shape``: ``grid`` 0 is
        ``ALPHA_GRID``, 1 the angles of ``ALPHA_GRID_WIDE`` outside it. The expansion of
        ``__call__`` is linear in its coefficients, so on fixed angles it is the product of a
        cached basis (the angle functions, :func:`_grid_basis`) with the coefficients: one
        small matrix product instead of ~25 array operations on (angles x batch) elements.
        The same M to rounding (sums in another order: a few ulp of the largest term)."""
        coef = [self.c0, self.c1]
        if self.fins:
            coef += self.f
        if self.p is not None:
            coef += self.p
        basis = _grid_basis(grid, float(self.stall), self.fins, self.p is not None)
        c = np.stack(coef).reshape(len(coef), -1)
        n = c.shape[1]
        if n <= _GRID_BLOCK:
            m = basis @ c
        else:  # blocks small enough for BLAS to stay on one thread (see _GRID_BLOCK)
            m = np.empty((basis.shape[0], n))
            for s in range(0, n, _GRID_BLOCK):
                np.matmul(basis, c[:, s:s + _GRID_BLOCK], out=m[:, s:s + _GRID_BLOCK])
        return m.reshape((basis.shape[0],) + self.shape)

    def __call__(self, alpha):
        """M(alpha) [N m], positive nose up, at angles of attack ``alpha`` [rad] (batch shape,
        optionally with leading axes)."""
        a = np.asarray(alpha, float)
        ca, sa = np.cos(a), np.sin(a)
        if self.fins:
            f1, f2, f3, f4 = self.f
            c = np.minimum(np.maximum(a, -self.stall), self.stall)
            m = ca * (self.c0 + c * (f2 * c - f1)) + sa * (self.c1 - c * (f3 + f4 * c))
        else:
            m = ca * self.c0 + sa * self.c1
        if self.p is not None:
            p1, p2, p3, p4 = self.p
            hv = a * self.half
            m = (m + ca * (p4 * ca) + np.sin(a * self.two) * (p1 * np.cos(hv) - p3 * np.sin(hv))
                 + p2 * (sa * np.abs(sa)))
        return m


#: Angle-of-attack grid used to bracket the equilibrium [rad]: where every usual trim lies.
ALPHA_GRID = np.radians(np.arange(-30.0, 60.01, 1.0))
#: Wider grid searched only where the usual one holds no stable root [rad] (J&D: |alpha| < 90).
ALPHA_GRID_WIDE = np.radians(np.arange(-80.0, 80.01, 1.0))
# The wide grid is the usual one with angles added below and above (the same floats).
_WIDE_BELOW = int(np.sum(ALPHA_GRID_WIDE < ALPHA_GRID[0]))
_WIDE_OUTSIDE = (ALPHA_GRID_WIDE < ALPHA_GRID[0]) | (ALPHA_GRID_WIDE > ALPHA_GRID[-1])
assert np.array_equal(ALPHA_GRID_WIDE[~_WIDE_OUTSIDE], ALPHA_GRID)
#: |midpoint| of each grid interval (the bracket nearest alpha = 0 wins), usual and wide grid.
_ABS_MID = tuple(np.abs(0.5 * (a[:-1] + a[1:])) for a in (ALPHA_GRID, ALPHA_GRID_WIDE))
#: The grid intervals in order of |midpoint| (stable: of two at the same distance the lower
#: first), so the first falling crossing in this order is the one nearest alpha = 0.
_NEAREST_FIRST = tuple(np.argsort(a, kind="stable") for a in _ABS_MID)
_DIAG4 = (np.arange(4), np.arange(4))


#: Batch columns per grid matrix product: OpenBLAS runs a product of fewer than 4 x 65536
#: multiply-adds (91 angles x 10 terms x 256 columns is 232,960) on the calling thread; larger
#: ones start its thread pool, which on a loaded machine (the app's default thread count) made
#: a 10,000-design batch trim 3-5x slower than the same products in blocks.
_GRID_BLOCK = 256


@functools.lru_cache(maxsize=64)
def _grid_basis(grid: int, stall: float, fins: bool, hull: bool) -> np.ndarray:
    """Angle functions of :meth:`MomentKernel.__call__` on grid ``grid`` (0: ALPHA_GRID, 1: the
    wide grid's outer angles), one column per coefficient (c0, c1, [f1-f4], [p1-p4]).

    Cached (read-only) on the grid, the fin stall angle [rad] and which terms the kernel has:
    the only inputs of these functions, shared by every trim of the same aerodynamic model."""
    a = ALPHA_GRID if grid == 0 else ALPHA_GRID_WIDE[_WIDE_OUTSIDE]
    ca, sa = np.cos(a), np.sin(a)
    cols = [ca, sa]
    if fins:
        c = np.minimum(np.maximum(a, -stall), stall)
        cols += [-ca * c, ca * c * c, -sa * c, -sa * c * c]
    if hull:
        s2, hv = np.sin(a * 2.0), a * 0.5
        cols += [s2 * np.cos(hv), sa * np.abs(sa), -s2 * np.sin(hv), ca * ca]
    basis = np.stack(cols, axis=-1)
    basis.flags.writeable = False
    return basis


@dataclass(frozen=True)
class Equilibrium:
    """Trim solution: alpha [rad], dM/dalpha there [N m/rad] (negative = statically stable),
    and ``found`` (False where no stable root exists; alpha is then the least-moment angle)."""

    alpha: np.ndarray
    moment_slope: np.ndarray
    found: np.ndarray


def equilibrium(af: Airframe, aero: AeroModel, speed, iterations: int = 40) -> Equilibrium:
    """Equilibrium pitch: the stable root of M_C(alpha) = 0 nearest to alpha = 0.

    Brackets on a 1 deg grid over [-30, 60] deg (then [-80, 80] deg where that holds no stable
    root; J&D needs |alpha| < 90 deg) (roots where M_C falls through zero), then refines
    every bracket at once with the Illinois (modified regula falsi) method to 1e-12 rad.

    Parameters
    ----------
    af : Airframe
    aero : AeroModel
    speed : array_like
        Wind speed at the hull [m/s]; broadcasts with the airframe's arrays.

    Returns
    -------
    Equilibrium
    """
    speed = np.asarray(speed, float)
    cd0 = axial_drag_coefficient(af, aero, speed)
    return trim_equilibrium(MomentKernel(af, aero, speed, cd0), iterations)


#: Half-widths of the brackets tried around the interpolated root [rad]: the inverse cubic
#: through four 1-degree grid values is within 1e-6 rad of a smooth root in ~99 % of trims
#: (median 5e-8), so x0 -+ 1e-6 usually holds it and x0 -+ 2e-5 nearly always. The inverse
#: cubic through these four points is then the root to rounding: Illinois starts there and
#: usually stops after that one iteration (~5 from the 1-degree interval).
_WARM_STEPS = np.array([-2e-5, -1e-6, 1e-6, 2e-5])
_WINDOW = np.arange(4)


@functools.lru_cache(maxsize=64)
def _window_starts(grid: int, kinks_deg: tuple) -> np.ndarray:
    """First index of the 4-point interpolation window for each grid interval k (grid 0:
    ALPHA_GRID, 1: ALPHA_GRID_WIDE): k-1 (k-1..k+2 around the interval), moved to k (k..k+3)
    or k-2 (k-2..k+1) where a kink of M at a grid angle (MomentKernel.kinks_deg) would fall
    inside the window, so that M is smooth over it; shifted inside the grid at its ends. A
    kink inside the interval itself or off the grid leaves the estimate poor and the bracket
    falls back (_warm_bracket). Cached (read-only) on the grid and the kinks: every trim of one
    aerodynamic model shares them."""
    alphas = ALPHA_GRID if grid == 0 else ALPHA_GRID_WIDE
    k = np.arange(len(alphas) - 1)
    j = k - 1
    start = float(np.degrees(alphas[0]))
    for kink in kinks_deg:
        p = kink - start  # the kink's grid position (on a grid angle: an integer)
        if abs(p - round(p)) < 1e-9:
            p = round(p)
            j = np.where(p <= k, np.maximum(j, p), np.where(p >= k + 1, np.minimum(j, p - 3), j))
    j = np.clip(j, 0, len(alphas) - 4)
    j.flags.writeable = False
    return j


def _warm_bracket(moment, grid, m, k, idx):
    """Bracket [lo, hi] (M(lo) > 0 >= M(hi)) of each column's root, shrunk from the grid
    interval k (grid 0: ALPHA_GRID, 1: ALPHA_GRID_WIDE; grid values ``m``) around a first
    estimate x0: the inverse cubic (Lagrange in M) through four grid values around the
    interval (:func:`_window_starts`), clipped to the interval (M not monotone there).

    One kernel call on x0 + _WARM_STEPS (points clipped to the interval) gives the first
    iterate x1, the inverse cubic through them, and the points from which
    :func:`_shrunk_bracket` cuts the interval to the first sign change along
    (lo, x0 - 2e-5, x0 - 1e-6, x0 + 1e-6, x0 + 2e-5, hi): 2e-6 rad wide when the estimate is
    good, else a wider part of the grid interval that still brackets (a kink of M inside the
    interval: the fin stall, where M is only piecewise smooth). Either way inside the same
    grid interval, so the root found (of an interval holding one root) and the choice of root
    are those of the plain 1-degree start.

    Returns (the points, x1, the grid interval's 1 + f_lo - f_hi).
    """
    alphas = ALPHA_GRID if grid == 0 else ALPHA_GRID_WIDE
    lo, hi = alphas[k], alphas[k + 1]
    f_lo, f_hi = m[(k,) + idx], m[(k + 1,) + idx]
    lead = (1,) * len(idx)
    win = _window_starts(grid, moment.kinks_deg)[k] + _WINDOW.reshape((4,) + lead)
    y = m[(win,) + idx]  # (4,) + shape
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = y[None] / (y[None] - y[:, None])  # [i, j] = -y_j / (y_i - y_j)
        ratio[_DIAG4] = 1.0
        x0 = np.sum(alphas[win] * np.prod(ratio, axis=1), axis=0)
    # outside the interval: its nearer end; NaN (equal grid values): lo (fmax/fmin drop NaN).
    # The bracket then narrows little and Illinois takes its usual iterations
    x0 = np.fmin(np.fmax(x0, lo), hi)
    inner = np.fmin(np.fmax(x0 + _WARM_STEPS.reshape((4,) + lead), lo), hi)
    f_in = moment(inner)
    # the inverse cubic through the four new points (all within 2e-5 rad of the root when the
    # estimate was good: the root to rounding where M is smooth there), NaN where it is not
    # finite or leaves the interval
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = f_in[None] / (f_in[None] - f_in[:, None])
        ratio[_DIAG4] = 1.0
        x1 = np.sum(inner * np.prod(ratio, axis=1), axis=0)
    # not finite (points clipped together at an end of the interval: a root on or next to a
    # grid angle, as a bluff hull's level trim at 0): the grid estimate x0
    x1 = np.where(np.isnan(x1), x0, x1)
    x1 = np.where((x1 >= lo) & (x1 <= hi), x1, np.nan)
    return (lo, f_lo, hi, f_hi, inner, f_in), x1, (1.0 + f_lo) - f_hi


def _shrunk_bracket(points, idx):
    """The first sign change along (lo, inner points, hi) of :func:`_warm_bracket`'s points:
    (lo, f_lo, hi, f_hi) of the narrowest bracket they give (M(lo) > 0 >= M(hi))."""
    lo, f_lo, hi, f_hi, inner, f_in = points
    pts = np.concatenate((lo[None], inner, hi[None]))
    f = np.concatenate((f_lo[None], f_in, f_hi[None]))
    pos = f > 0.0
    i = np.argmax(pos[:-1] & ~pos[1:], axis=0)  # the first sign change (f_lo > 0 >= f_hi)
    lo_w, hi_w, f_lo_w, f_hi_w = (a[(r,) + idx] for a in (pts, f) for r in (i, i + 1))
    return lo_w, f_lo_w, hi_w, f_hi_w


def trim_equilibrium(moment: MomentKernel, iterations: int = 40) -> Equilibrium:
    """:func:`equilibrium` on a built :class:`MomentKernel` (the algorithm, grids and
    tolerance are documented there), for callers that reuse the kernel (the weathervane slope
    of :func:`aerostat_core.model.performance.evaluate`).

    Parameters
    ----------
    moment : MomentKernel
        Moment about the confluence point at the wind speed(s) of the solve.
    iterations : int
        Most Illinois iterations.

    Returns
    -------
    Equilibrium
    """
    shape = moment.shape
    m_first = None
    for alphas in (ALPHA_GRID, ALPHA_GRID_WIDE):
        if m_first is None:
            m = moment.on_grid(0)  # (grid,) + shape
            m_first = m
        else:  # the wide grid holds the first one: only its other angles are new
            m_out = moment.on_grid(1)
            m = np.concatenate([m_out[:_WIDE_BELOW], m_first, m_out[_WIDE_BELOW:]])
        down = (m[:-1] > 0.0) & (m[1:] <= 0.0)
        order = _NEAREST_FIRST[0 if alphas is ALPHA_GRID else 1]
        nearest = down[order]
        k = order[np.argmax(nearest, axis=0)]  # the crossing nearest 0 (0 where none)
        found = nearest.any(axis=0)
        if np.all(found):
            break
    idx = tuple(np.indices(shape))
    grid = 0 if alphas is ALPHA_GRID else 1
    points, first, spread = _warm_bracket(moment, grid, m, k, idx)
    # Illinois iterations on all brackets at once; x is the running root estimate. ``was_pos``
    # / ``was_neg``: the sign of the previous iterate's moment (neither before the first)
    was_pos = was_neg = np.zeros(shape, bool)
    half, one, eps = np.array(0.5), np.array(1.0), np.array(1e-12)
    # |M| small on the scale of the grid interval's moment change (1 + |f_lo| + |f_hi| there,
    # = 1 + f_lo - f_hi as f_lo > 0 >= f_hi): |fx| <= 1e-12 (1 + |M'| 1 deg) puts x within
    # 1e-12/|M'| + 2e-14 rad of the root. The scale is the 1-degree bracket's, not the warm
    # one's (2e-6 rad wide: it would ask |M| below its rounding, ~1e-11 N m at 5e4 N m of
    # buoyancy moment, and iterate until hi - lo < 1e-12)
    tol = eps * spread
    unfound = ~found
    # the warm start's root, where every column with a bracket has one and it is tiny: done
    # (columns without one take their grid angle below)
    done = False
    if np.all(~np.isnan(first) | unfound):
        x = first
        fx = moment(x)
        done = bool(np.all((np.abs(fx) <= tol) | unfound))
        if done:  # one secant step from the nearest warm point: the root to rounding
            inner, f_in = points[4], points[5]
            j = np.argmin(np.abs(inner - x), axis=0)
            xa, fa = inner[(j,) + idx], f_in[(j,) + idx]
            df = fx - fa
            x = np.where(df != 0.0, x - fx * (x - xa) / np.where(df != 0.0, df, 1.0), x)
    if not done:
        lo, f_lo, hi, f_hi = _shrunk_bracket(points, idx)
        first = np.where((first >= lo) & (first <= hi), first, np.nan)
        x = half * (lo + hi)
    for it in range(0 if done else iterations):
        df = f_hi - f_lo
        same = df == 0.0
        secant = (lo * f_hi - hi * f_lo) / np.where(same, one, df)
        x = np.where(same, half * (lo + hi), secant) if same.any() else secant
        if it == 0:  # the warm start's interpolated root, where it has one
            x = np.where(np.isnan(first), x, first)
        fx = moment(x)
        pos = fx > 0.0
        lo = np.where(pos, x, lo)
        f_lo = np.where(pos, fx, np.where(was_neg, half * f_lo, f_lo))
        hi = np.where(pos, hi, x)
        f_hi = np.where(pos, np.where(was_pos, half * f_hi, f_hi), fx)
        was_pos, was_neg = pos, ~pos
        # in a bracket lo < hi, so |hi - lo| = hi - lo (columns without one stop on ``unfound``)
        tiny = np.abs(fx) <= tol
        # columns without a stable root take the least-|moment| grid angle below: they have no
        # bracket to converge, so they must not keep the others iterating to the limit
        if np.all((hi - lo < eps) | tiny | unfound):
            break
    alpha = x + 0.0  # a level trim is +0.0, not -0.0 (shown as "-0.0 deg")
    # where no stable root: the grid angle with the least |moment|
    if not found.all():
        kmin = np.argmin(np.abs(m), axis=0)
        alpha = np.where(found, alpha, alphas[kmin])
    return Equilibrium(alpha=alpha, moment_slope=central_difference(moment, alpha), found=found)


def moment_coefficient(af: Airframe, aero: AeroModel, alpha, speed):
    """C_m = M_C / (q V^(2/3) l) about the confluence point [-] (speed > 0)."""
    q = 0.5 * af.air_density * np.asarray(speed, float) ** 2
    return moment_about_confluence(af, aero, alpha, speed) / (
        q * af.hull.reference_area * af.hull.length
    )
