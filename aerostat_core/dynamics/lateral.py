"""Lateral-directional stability of the tethered aerostat from the 6-DOF model
(docs/dynamics.md §7.5): modes about the equilibrium at each wind speed, the wind speed where
the first lateral mode goes unstable, and the static lateral derivatives.

Linearisation. At the equilibrium y_e in a steady wind along x (no veer), the model is symmetric
about the vertical plane of the wind, so its Jacobian A = df/dy splits exactly into a
longitudinal and a lateral block; the lateral states are the nodes' y and v_y, the hull's y_O,
the quaternion's q1 and q3, v, p and r. The eigenvalues lambda of the lateral block are the
lateral-directional modes (hull roll-yaw "kiting", tail swing, the pendulum and the line's
lateral string modes): frequency |Im lambda|/2 pi, damping ratio -Re lambda/|lambda|, and when
Re lambda > 0 the time to double ln 2/Re lambda. A is built by central differences of the
compiled right-hand side (increments 1e-6 of each state's scale).
"""

from __future__ import annotations

import functools
import math
from collections import OrderedDict
from dataclasses import dataclass
from threading import Lock

import numpy as np

from aerostat_core.dynamics.simulate import engine_guesses
from aerostat_core.dynamics.sixdof import System6, Wind3D, initial_state6, system6_from_design
from aerostat_core.dynamics.sixdof_kernel import DIAG6_NAMES, ND6, rhs6_kernel

#: Real part above which a mode counts as unstable [1/s] (the finite-difference Jacobian's
#: noise is ~1e-7 1/s).
UNSTABLE_TOL = 1e-5
#: Highest frequency listed in the mode table [Hz] (faster ones are the line's string modes).
TABLE_MAX_FREQUENCY = 1.0


@dataclass(frozen=True)
class LateralMode:
    """One lateral-directional mode: eigenvalue [1/s], frequency [Hz], damping ratio [-], time to
    double [s] (None when it decays), time to half [s] (None when it grows)."""

    eigenvalue: complex
    frequency_hz: float
    damping_ratio: float
    time_to_double_s: float | None
    time_to_half_s: float | None

    @property
    def unstable(self) -> bool:
        return self.eigenvalue.real > UNSTABLE_TOL

    def row(self) -> dict:
        """Table row with units in the keys."""
        return {"real_1_s": self.eigenvalue.real, "imag_rad_s": abs(self.eigenvalue.imag),
                "frequency_Hz": self.frequency_hz, "damping_ratio": self.damping_ratio,
                "time_to_double_s": self.time_to_double_s, "time_to_half_s": self.time_to_half_s}


def mode_of(lam: complex) -> LateralMode:
    """The :class:`LateralMode` of an eigenvalue.

    Examples
    --------
    >>> m = mode_of(complex(0.1, 2 * math.pi))
    >>> round(m.frequency_hz, 3), round(m.time_to_double_s, 3), m.unstable
    (1.0, 6.931, True)
    """
    mag = abs(lam)
    zeta = -lam.real / mag if mag > 0 else 1.0
    grow = lam.real > UNSTABLE_TOL
    decay = lam.real < -UNSTABLE_TOL
    return LateralMode(complex(lam), abs(lam.imag) / (2 * math.pi), float(zeta),
                       math.log(2.0) / lam.real if grow else None,
                       math.log(2.0) / -lam.real if decay else None)


def lateral_indices(system: System6) -> np.ndarray:
    """Indices of the lateral states (module docstring)."""
    return _lateral_indices(system.tether.segments)


@functools.lru_cache(maxsize=32)
def _lateral_indices(segments: int) -> np.ndarray:
    idx = []
    for i in range(1, segments):
        k = 6 * (i - 1)
        idx += [k + 1, k + 4]
    b = 6 * (segments - 1)  # System6.hull_index
    idx += [b + 1, b + 4, b + 6, b + 8, b + 10, b + 12]
    out = np.array(idx)
    out.flags.writeable = False
    return out


def jacobian6(system: System6, data, y: np.ndarray) -> np.ndarray:
    """Dense central-difference Jacobian df/dy of the 6-DOF right-hand side at t = 0."""
    n = y.size
    jac = np.empty((n, n))
    b = system.hull_index
    for j in range(n):
        h = 1e-6 * (max(1.0, 0.01 * system.tether.length) if j < b + 3 else 1.0)
        yp = y.copy()
        ym = y.copy()
        yp[j] += h
        ym[j] -= h
        jac[:, j] = (system.rhs(0.0, yp, data)[0] - system.rhs(0.0, ym, data)[0]) / (2 * h)
    return jac


@functools.lru_cache(maxsize=32)
def _column_groups(segments: int, length: float) -> tuple:
    """Lateral columns that can be differenced together, and the lateral rows each one moves.

    The lumped-mass line is local: node i's states enter only the equations of nodes i-1, i and
    i+1 (its two segments), the top free node's also the hull's (the top segment ends at the
    confluence point), and the hull's states only its own equations and the top free node's.
    Columns whose sets of moved equations do not overlap are perturbed in one kernel call each
    way (Curtis-Powell-Reid colouring, greedy); each keeps its own increment, and each lateral
    row is read from the one column of the group that moves it. Returns a tuple of groups, each
    a tuple of (column position in the lateral block, state index, increment, row positions),
    for a line of ``segments`` segments and ``length`` [m] (the position increments scale with
    it, as in :func:`jacobian6`)."""
    n = segments
    b = 6 * (n - 1)  # System6.hull_index
    idx = _lateral_indices(n)
    scale = max(1.0, 0.01 * length)
    hull = n  # block label of the hull's equations (nodes are 1 .. n-1)

    def block_of(j: int) -> int:
        return hull if j >= b else j // 6 + 1

    def moved(j: int) -> set:
        k = block_of(j)
        if k == hull:
            return {hull, n - 1}
        out = {m for m in (k - 1, k, k + 1) if 1 <= m <= n - 1}
        if k == n - 1:
            out.add(hull)
        return out

    groups: list = []  # [blocks moved, members]
    for c, j in enumerate(idx):
        blocks = moved(int(j))
        rows = np.array([r for r, i in enumerate(idx) if block_of(int(i)) in blocks])
        h = 1e-6 * (scale if j < b + 3 else 1.0)
        for g in groups:
            if not g[0] & blocks:
                g[0] |= blocks
                g[1].append((c, int(j), h, rows))
                break
        else:
            groups.append([set(blocks), [(c, int(j), h, rows)]])
    return tuple(tuple(g[1]) for g in groups)


def lateral_jacobian(system: System6, data, y: np.ndarray) -> np.ndarray:
    """The lateral block of :func:`jacobian6` (rows and columns :func:`lateral_indices`) by the
    same central differences with the same increments, differencing only the lateral columns and
    several at a time where their equations do not overlap (:func:`_column_groups`): 2 x 10
    kernel calls for 8 segments instead of 2 x 55. An entry outside a column's moved equations
    is zero, as it is in :func:`jacobian6` (the kernel's other equations do not read that
    state)."""
    idx = lateral_indices(system)
    groups = _column_groups(system.tether.segments, float(system.tether.length))
    out = np.zeros((idx.size, idx.size))
    y = np.asarray(y, float)
    yp = y.copy()
    fp = np.empty(system.n_state)
    fm = np.empty(system.n_state)
    diag = np.empty(ND6)
    for group in groups:
        for _c, j, h, _rows in group:
            yp[j] = y[j] + h
        rhs6_kernel(0.0, yp, fp, data, diag)
        for _c, j, h, _rows in group:
            yp[j] = y[j] - h
        rhs6_kernel(0.0, yp, fm, data, diag)
        for c, j, h, rows in group:
            yp[j] = y[j]
            r = idx[rows]
            out[rows, c] = (fp[r] - fm[r]) / (2 * h)
    return out


@dataclass(frozen=True)
class LateralAnalysis:
    """Lateral modes at one wind speed [m/s]: ``modes`` (slow ones, least stable first), the
    largest real part of all lateral eigenvalues [1/s] and the equilibrium state."""

    speed: float
    modes: tuple
    max_real: float
    state: np.ndarray

    @property
    def stable(self) -> bool:
        return self.max_real <= UNSTABLE_TOL


#: Largest 6-DOF acceleration [m/s2, rad/s2] left at the turned 3-DOF equilibrium for which the
#: sweep skips the 6-DOF Newton polish (:func:`~.sixdof.initial_state6`). The 3-DOF Newton
#: leaves ~1e-9 m/s2; a larger residual (a 6-DOF model that differs in the plane) is polished.
POLISH_TOL = 1e-6


def lateral_modes(system: System6, speed: float, design=None, guess3: np.ndarray | None = None,
                  reference: bool = False) -> LateralAnalysis:
    """Linearise ``system`` about its equilibrium in a steady wind ``speed`` [m/s] along x and
    return the lateral-directional modes (module docstring).

    ``guess3``: the 3-DOF rest state the equilibrium search starts from (default: the static
    engine's at this speed). ``reference``: the full computation (6-DOF Newton polish always,
    the whole Jacobian by :func:`jacobian6`), which the fast path (polish skipped when the 3-DOF
    equilibrium already balances the 6-DOF model to :data:`POLISH_TOL`, lateral columns only by
    :func:`lateral_jacobian`) is tested against."""
    y, block = _linearise(system, speed, design, guess3, reference)
    return _analysis(speed, np.linalg.eigvals(block), y)


@functools.lru_cache(maxsize=256)
def _steady_wind(speed: float) -> Wind3D:
    """``Wind3D.steady(speed)``, made (and validated) once per speed in a process: every design's
    sweep uses the same grid of speeds."""
    return Wind3D.steady(speed)


def _linearise(system: System6, speed: float, design, guess3, reference: bool):
    """(equilibrium state, lateral block of the Jacobian) at ``speed`` (:func:`lateral_modes`)."""
    wind = _steady_wind(float(speed))
    field_ = wind.base.realize(system.tether.length, 60.0)
    data = system.data(field_, wind)
    if reference:
        y = initial_state6(system, wind, design, field_, data, guess3=guess3)
        idx = lateral_indices(system)
        return y, jacobian6(system, data, y)[np.ix_(idx, idx)]
    y = initial_state6(system, wind, design, field_, data, guess3=guess3, polish_tol=POLISH_TOL)
    return y, lateral_jacobian(system, data, y)


def _analysis(speed: float, lam: np.ndarray, y: np.ndarray) -> LateralAnalysis:
    """The :class:`LateralAnalysis` of the lateral eigenvalues ``lam`` at ``speed``."""
    lam = lam[np.argsort(-lam.real)]
    modes = []
    for v in lam:
        if v.imag < -1e-9:
            continue  # one of each conjugate pair
        m = mode_of(complex(v))
        if m.frequency_hz <= TABLE_MAX_FREQUENCY and abs(v) < 2 * math.pi * 2.0:
            modes.append(m)
    return LateralAnalysis(float(speed), tuple(modes), float(np.max(lam.real)), y)


def planar_state3(system: System6, y: np.ndarray) -> np.ndarray:
    """The 3-DOF state (:class:`~.system.DynamicSystem` of ``system.base``) of a 6-DOF state in
    the vertical x-z plane, the inverse of :meth:`~.sixdof.System6.from_3dof` at azimuth 0:
    node (x, z, v_x, v_z), O's (x, z), the pitch theta = 2 atan2(q2, q0) and (u, w, q)."""
    n = system.tether.segments
    b = system.hull_index
    y = np.asarray(y, float)
    nodes = y[:b].reshape(n - 1, 6)[:, [0, 2, 3, 5]].reshape(-1)
    theta = 2.0 * math.atan2(y[b + 5], y[b + 3])
    return np.concatenate([nodes, [y[b], y[b + 2], theta, y[b + 7], y[b + 9], y[b + 11]]])


def sweep_speeds(design) -> np.ndarray:
    """The sweep's wind speeds [m/s]: 2 m/s to the survival wind in 1 m/s steps (the survival
    wind added when the steps miss it)."""
    top = float(design.requirement.survival_wind)
    speeds = np.arange(2.0, top + 1e-9, 1.0)
    if speeds[-1] < top:
        speeds = np.append(speeds, top)
    return speeds


def lateral_sweep(design, speeds=None, segments: int = 8, system: System6 | None = None,
                  reference: bool = False):
    """Lateral stability over wind speeds (default :func:`sweep_speeds`).

    Returns (analyses, unstable_above [m/s] or None): the speed where the largest real part of
    the lateral eigenvalues crosses zero (linear interpolation between the bracketing speeds),
    None when every lateral mode is stable up to the survival wind. A speed without an
    equilibrium (a line too slack to converge) is left out of ``analyses``. ``system``: the
    design's 6-DOF system when already built (``segments`` is then its own).

    With the defaults (no ``speeds``, ``system`` or ``reference``) the sweep is computed once
    per frozen inputs (:func:`cached_sweep`).

    Every speed of the grid is linearised (no coarse grid and bisection: a mode that goes
    unstable and stable again between two coarse speeds would be missed). The static engine's
    starting points for all speeds come from one vectorised call
    (:func:`~.simulate.engine_guesses`), and each speed takes the fast path of
    :func:`lateral_modes`; ``reference=True`` runs the full computation per speed instead
    (its own engine call, 6-DOF polish, whole Jacobian), the dense reference the fast path is
    tested against (tests/core/test_lateral_fast.py)."""
    if speeds is None and system is None and segments == SWEEP_SEGMENTS and not reference:
        return cached_sweep(design)
    return _sweep(design, speeds, segments, system, reference)


def _sweep(design, speeds, segments, system, reference):
    if speeds is None:
        speeds = sweep_speeds(design)
    if system is None:
        system = system6_from_design(design, segments=segments)
    speeds = np.asarray(speeds, float).reshape(-1)
    out = []
    if design is None or reference:
        for v in speeds:
            try:
                out.append(lateral_modes(system, float(v), design, reference=reference))
            except RuntimeError:
                continue  # no equilibrium found at this speed: the sweep goes on without it
    else:
        engine = engine_guesses(system.base, design, speeds)
        prev = None  # (index, 3-DOF equilibrium) of the last speed with an equilibrium
        found = []  # (speed, equilibrium, lateral block)
        for k, v in enumerate(speeds):
            starts = [engine[k]]
            if prev is not None:
                # the engine's profile at this speed moved by the lumped-mass line's own
                # departure from it at the previous speed (it varies slowly with the speed):
                # one Newton iteration fewer than from the engine's profile; the engine's
                # profile itself when that fails
                starts.insert(0, engine[k] + (prev[1] - engine[prev[0]]))
            for g3 in starts:
                try:
                    y, block = _linearise(system, float(v), design, g3, False)
                except RuntimeError:
                    continue
                found.append((float(v), y, block))
                prev = (k, planar_state3(system, y))
                break  # a speed without an equilibrium is left out: the sweep goes on
        if found:  # the eigenvalues of every speed's block in one call
            lams = np.linalg.eigvals(np.array([f[2] for f in found]))
            out = [_analysis(v, lam, y) for (v, y, _), lam in zip(found, lams)]
    if not out:
        raise RuntimeError("lateral stability: no equilibrium found at any wind speed")
    return out, unstable_above(out)


#: Segments of the line in the default sweep (the constraint row's, docs/dynamics.md §7.5).
SWEEP_SEGMENTS = 8
#: Default sweeps kept per frozen inputs in a process (the constraint row, the app's 6-DOF
#: view and ``simulate --dof 6`` of the same design share one).
SWEEP_CACHE_SIZE = 64
_sweeps: OrderedDict = OrderedDict()
_sweeps_lock = Lock()


def design_key(design) -> str:
    """The cache key of a design's frozen inputs: the exact repr of its requirement,
    configuration and volume (the app's key, docs/architecture.md §2.2)."""
    return repr((design.requirement, design.configuration, float(design.volume)))


def cached_sweep(design, system: System6 | None = None):
    """:func:`lateral_sweep` with its defaults (:func:`sweep_speeds`, :data:`SWEEP_SEGMENTS`
    segments, the 6-DOF system of :func:`~.sixdof.system6_from_design`), computed once per
    frozen inputs in a process. ``system``: that same system when the caller has built it.
    The analyses are shared: their states are read-only."""
    key = design_key(design)
    with _sweeps_lock:
        if key in _sweeps:
            _sweeps.move_to_end(key)
            return _sweeps[key]
    if system is None:
        system = system6_from_design(design, segments=SWEEP_SEGMENTS)
    analyses, above = _sweep(design, None, SWEEP_SEGMENTS, system, False)
    for a in analyses:
        a.state.flags.writeable = False
    out = (analyses, above)
    with _sweeps_lock:
        _sweeps[key] = out
        while len(_sweeps) > SWEEP_CACHE_SIZE:
            _sweeps.popitem(last=False)
    return out


def clear_sweep_cache() -> None:
    """Forget the cached sweeps (a benchmark times the computation itself)."""
    with _sweeps_lock:
        _sweeps.clear()


def unstable_above(analyses) -> float | None:
    """Wind speed [m/s] where the first lateral mode goes unstable (None: stable throughout).

    Examples
    --------
    >>> A = LateralAnalysis
    >>> round(unstable_above([A(5.0, (), -0.1, None), A(6.0, (), 0.1, None)]), 3)
    5.5
    """
    prev = None
    for a in analyses:
        if not a.stable:
            if prev is None:
                return a.speed
            x0, y0 = prev.speed, prev.max_real
            x1, y1 = a.speed, a.max_real
            return float(x0 + (x1 - x0) * (UNSTABLE_TOL - y0) / (y1 - y0))
        prev = a
    return None


def static_lateral_derivatives(system: System6, speed: float, design=None,
                               state: np.ndarray | None = None, dpsi: float = 1e-3) -> dict:
    """Static lateral derivatives of the hull + fins about the centre of volume at the trim in a
    steady wind ``speed`` [m/s] (body axes; beta > 0: wind from starboard):

    C_Y_beta = dY/dbeta/(q S), C_n_beta = dN/dbeta/(q S l), C_l_beta = dL/dbeta/(q S l) [1/rad]

    with q = rho V^2/2, S the hull reference area (V^(2/3)) and l its length, the normalisation
    of the static engine's C_m_alpha (weathervane stability: C_n_beta > 0; C_l_beta < 0 rolls
    away from the sideslip). The hull is yawed by +-``dpsi`` [rad] at rest in the wind.

    About the centre of volume an axisymmetric hull with symmetric fins has no roll moment, so
    C_l_beta is given about the confluence point C (x_c, 0, z_c), where the side force acts with
    the arm z_c: C_l,C = C_l,O + z_c C_Y/l; C_n_beta_confluence = C_n,O - x_c C_Y/l likewise."""
    from aerostat_core.dynamics.sixdof import quat_mul

    wind = Wind3D.steady(float(speed))
    field_ = wind.base.realize(system.tether.length, 60.0)
    data = system.data(field_, wind)
    y = state if state is not None else initial_state6(system, wind, design, field_, data)
    b = system.hull_index
    out = []
    for sgn in (1.0, -1.0):
        yy = y.copy()
        dq = np.array([math.cos(0.5 * sgn * dpsi), 0.0, 0.0, math.sin(0.5 * sgn * dpsi)])
        yy[b + 3:b + 7] = quat_mul(dq, y[b + 3:b + 7])
        d = system.rhs(0.0, yy, data)[1]
        out.append([d[DIAG6_NAMES.index(k)] for k in ("beta", "aero_side", "aero_yaw",
                                                       "aero_roll")])
    (b1, y1, n1, l1), (b2, y2, n2, l2) = out
    db = b1 - b2
    h = system.hull6.hull
    rho = system.atmosphere.density
    qs = 0.5 * rho * speed**2 * h.volume ** (2.0 / 3.0)
    cy = (y1 - y2) / db / qs
    cn = (n1 - n2) / db / (qs * h.length)
    cl = (l1 - l2) / db / (qs * h.length)
    xc, zc = h.confluence
    return {"C_Y_beta_per_rad": float(cy), "C_n_beta_per_rad": float(cn),
            "C_l_beta_per_rad": float(cl + zc * cy / h.length),
            "C_n_beta_confluence_per_rad": float(cn - xc * cy / h.length)}
