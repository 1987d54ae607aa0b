"""Run a simulation: initial equilibrium, integration with budgets, time histories and summaries.

:func:`simulate` integrates a :class:`~.model.DynamicSystem` in a wind (:class:`~.wind.WindScenario`)
from its static equilibrium (or a given state) with the TR-BDF2 integrator of :mod:`.solver`
(default) or scipy's ``solve_ivp`` (cross-checks). It works in chunks so that a progress callback
runs and the wall-clock and step budgets are enforced: a diverging case ends with a clear status,
never a hang.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from .model import DIAG_NAMES, ND, DynamicSystem, rhs_kernel
from .solver import (
    F_ETA,
    F_H,
    F_SIZE,
    F_STALE,
    F_T,
    O_HMAX,
    O_HMIN,
    O_JAC_EVERY,
    O_KAPPA,
    O_MAXIT,
    O_MAXSTEPS,
    O_RTOL,
    O_SIZE,
    S_FEVAL,
    S_IOUT,
    S_JAC,
    S_LU,
    S_NFAIL,
    S_REJECT,
    S_SIZE,
    S_STEPS,
    STATUS,
    band_jacobian,
    integrate_chunk,
)
from .wind import NT, WindField, WindScenario, wind_time_terms

#: Extra status codes of the driver.
STATUS_DRIVER = {
    8: "wall-clock budget exceeded",
    9: "step budget exhausted",
    10: "scipy solver failed",
}
METHODS = ("trbdf2", "Radau", "BDF", "LSODA")


@dataclass(frozen=True)
class SolverOptions:
    """Integrator settings.

    Parameters
    ----------
    method : {"trbdf2", "Radau", "BDF", "LSODA"}
        "trbdf2": the compiled L-stable integrator of :mod:`.solver` (default, fast).
        Others: ``scipy.integrate.solve_ivp`` with the same compiled right-hand side and a banded
        Jacobian (cross-checks, V6).
    rtol : float
        Relative tolerance [-], valid [1e-10, 1e-2].
    atol_position, atol_velocity : float
        Absolute tolerances on positions [m] and velocities [m/s], valid [1e-12, 1].
    atol_angle : float
        Absolute tolerance on pitch [rad] and pitch rate [rad/s], valid [1e-12, 1].
    initial_step, max_step : float
        [s]; ``max_step`` valid (0, 100].
    output_interval : float
        Sampling of the time histories [s], valid [1e-3, 10].
    max_steps : int
        Step budget of the whole run, valid [10, 1e8].
    wall_time_limit : float
        Wall-clock budget [s], valid (0, 1e5]; the run stops with status 8 beyond it.
    jacobian_refresh : int
        Refresh the Jacobian at least every this many accepted steps, valid [1, 10000].
    """

    method: str = "trbdf2"
    rtol: float = 1e-6
    atol_position: float = 1e-5
    atol_velocity: float = 1e-5
    atol_angle: float = 1e-7
    initial_step: float = 1e-3
    max_step: float = 1.0
    output_interval: float = 0.1
    max_steps: int = 5_000_000
    wall_time_limit: float = 300.0
    jacobian_refresh: int = 50

    def __post_init__(self) -> None:
        if self.method not in METHODS:
            raise ValueError(f"SolverOptions.method = {self.method!r}; valid options {METHODS}")
        for name, lo, hi in (("rtol", 1e-10, 1e-2), ("atol_position", 1e-12, 1.0),
                             ("atol_velocity", 1e-12, 1.0), ("atol_angle", 1e-12, 1.0),
                             ("initial_step", 1e-9, 10.0), ("max_step", 1e-6, 100.0),
                             ("output_interval", 1e-3, 10.0), ("max_steps", 10, 1e8),
                             ("wall_time_limit", 1e-3, 1e5), ("jacobian_refresh", 1, 1e4)):
            v = getattr(self, name)
            if not isinstance(v, (int, float)) or not math.isfinite(v) or v < lo or v > hi:
                raise ValueError(f"SolverOptions.{name} = {v!r} is outside the valid range "
                                 f"[{lo:g}, {hi:g}]")


# --------------------------------------------------------------------------------------------
# Initial states
# --------------------------------------------------------------------------------------------
def _index_sets(system: DynamicSystem):
    n = system.tether.segments
    pos, acc, vel = [], [], []
    for i in range(1, n):
        k = 4 * (i - 1)
        pos += [k, k + 1]
        vel += [k + 2, k + 3]
        acc += [k + 2, k + 3]
    b = system.hull_index
    if system.is_hull:
        pos += [b, b + 1, b + 2]
        vel += [b + 3, b + 4, b + 5]
        acc += [b + 3, b + 4, b + 5]
    else:
        pos += [b, b + 1]
        vel += [b + 2, b + 3]
        acc += [b + 2, b + 3]
    return np.array(pos), np.array(acc), np.array(vel)


def _scale(system: DynamicSystem) -> np.ndarray:
    sc = np.ones(system.n_state)
    pos, _, vel = _index_sets(system)
    sc[pos] = max(1.0, 0.01 * system.tether.length)
    sc[vel] = 1.0
    if system.is_hull:
        sc[system.hull_index + 2] = 0.1
        sc[system.hull_index + 5] = 0.1
    return sc


@dataclass(frozen=True)
class EquilibriumInfo:
    """Result of the static Newton solve: iterations, largest remaining acceleration [m/s2 or
    rad/s2], largest position change from the guess [m] (pitch change [rad] separately)."""

    iterations: int
    residual: float
    shift: float
    pitch_shift: float


def equilibrium(system: DynamicSystem, wind: WindField, guess: np.ndarray, tol: float = 1e-10,
                max_iter: int = 60) -> tuple[np.ndarray, EquilibriumInfo]:
    """Static equilibrium of the discretised model at t = 0 (all velocities zero).

    Damped Newton on the positions (free nodes and the body) with the banded finite-difference
    Jacobian of the kernel, from ``guess`` (the static engine's solution for designs, or
    :func:`straight_guess`). Converges quadratically in a few iterations from the engine's
    profile; the remaining shift is the discretisation difference between the engine's
    continuous tether march and the lumped-mass line (mm).
    """
    data = system.data(wind)
    wt = np.empty(NT)
    wind_time_terms(0.0, data[1], data[2], data[3], wt)
    pos, acc, vel = _index_sets(system)
    y = np.array(guess, float)
    y[vel] = 0.0
    y0 = y.copy()
    n = system.n_state
    kl, ku = system.structure()
    jac = np.zeros((n, n))
    f = np.empty(n)
    diag = np.empty(ND)
    scale = _scale(system)

    def resid(v):
        rhs_kernel(v, f, data, wt, diag)
        return f[acc].copy()

    r = resid(y)
    it = 0
    while it < max_iter:
        it += 1
        band_jacobian(y, f, data, wt, kl, ku, jac, scale)
        a = jac[np.ix_(acc, pos)]
        try:
            dx = np.linalg.solve(a, -r)
        except np.linalg.LinAlgError:
            raise RuntimeError("static equilibrium: singular Jacobian (is the tether slack?)") from None
        lam = 1.0
        norm0 = np.linalg.norm(r)
        for _ in range(30):
            yt = y.copy()
            yt[pos] += lam * dx
            rt = resid(yt)
            # plain Newton converges here even when the residual first grows (stiff axial
            # terms); only guard against blow-ups
            if np.all(np.isfinite(rt)) and np.linalg.norm(rt) < 1e4 * norm0 + 1e-6:
                break
            lam *= 0.5
        y, r = yt, rt
        if np.max(np.abs(lam * dx)) < tol * max(1.0, system.tether.length):
            break
    rhs_kernel(y, f, data, wt, diag)
    d = np.abs(y - y0)
    if system.is_hull:
        b = system.hull_index
        pshift = float(d[b + 2])
        d[b + 2] = 0.0
    else:
        pshift = 0.0
    info = EquilibriumInfo(it, float(np.max(np.abs(f[acc]))), float(np.max(d[pos])), pshift)
    if not np.all(np.isfinite(y)) or info.residual > 1e-3:
        raise RuntimeError(
            f"static equilibrium not found (largest residual acceleration {info.residual:.3g} after "
            f"{it} iterations): check that the aerostat has free lift"
        )
    return y, info


def straight_state(system: DynamicSystem, top, theta: float = 0.0) -> np.ndarray:
    """State at rest with the tether straight from the winch to ``top`` = (x, z) [m] (the top node:
    the point aerostat, or the confluence point of a hull at pitch ``theta`` [rad])."""
    n = system.tether.segments
    s = np.linspace(0.0, 1.0, n + 1)[:, None]
    a = np.array(system.winch)
    pos = a + s * (np.asarray(top, float) - a)
    vel = np.zeros_like(pos)
    if system.is_hull:
        xo, zo = system.hull_pose_from_confluence(float(top[0]), float(top[1]), theta)
        body = np.array([xo, zo, theta, 0.0, 0.0, 0.0])
    else:
        body = np.array([top[0], top[1], 0.0, 0.0])
    return system.pack_state(pos, vel, body)


def straight_guess(system: DynamicSystem, wind: WindField, theta: float = 0.0) -> np.ndarray:
    """A rest state on a straight, stretched line along the estimated top-tension direction.

    Tension at the top ~ (drag, net lift) of the body in the wind at the tether length's height.
    Good enough a start for :func:`equilibrium` (the sag of the real line is a few metres).
    """
    t = system.tether
    rho = system.atmosphere.density
    u = float(wind.at(0.0, t.length)[0][0])
    if system.is_hull:
        h = system.body
        lift = (rho * h.volume - h.mass) * system.g
        drag = 0.5 * rho * u * abs(u) * 0.05 * h.volume ** (2 / 3)
    else:
        p = system.body
        lift = p.net_lift(rho, system.g)
        drag = 0.5 * rho * p.drag_area * u * abs(u)
    lift -= 0.5 * t.linear_density * t.length * system.g
    if lift <= 0.0:
        raise ValueError(f"the aerostat has no net lift to hold the tether up ({lift:.1f} N)")
    ang = math.atan2(lift, drag)
    tens = math.hypot(lift, drag)
    r = t.length * (1.0 + tens / t.stiffness)
    top = (system.winch[0] + r * math.cos(ang), system.winch[1] + r * math.sin(ang))
    return straight_state(system, top, theta)


# --------------------------------------------------------------------------------------------
# Results
# --------------------------------------------------------------------------------------------
#: Signals of the time histories: name -> (label, unit).
SIGNALS = {
    "x_C": ("blow-by of the confluence point x_C", "m"),
    "z_C": ("altitude of the confluence point z_C", "m"),
    "vx": ("horizontal velocity of the hull", "m/s"),
    "vz": ("vertical velocity of the hull", "m/s"),
    "vx_C": ("horizontal velocity of the confluence point", "m/s"),
    "vz_C": ("vertical velocity of the confluence point", "m/s"),
    "theta": ("pitch angle theta", "deg"),
    "alpha": ("angle of attack alpha", "deg"),
    "alpha_fin": ("angle of attack at the fins", "deg"),
    "tension_C": ("tether tension at the confluence point", "N"),
    "tension_winch": ("tether tension at the winch", "N"),
    "tension_max": ("largest segment tension", "N"),
    "wind_x": ("horizontal wind at the hull", "m/s"),
    "wind_z": ("vertical wind at the hull", "m/s"),
    "airspeed": ("airspeed of the hull", "m/s"),
}


@dataclass(frozen=True)
class SignalStats:
    """Statistics of one signal over a time window (units of the signal).

    mean; std = RMS of the fluctuation about the mean (the "±" of a turbulence response);
    rms = RMS about zero; min, max; peak = max |x - mean| (the largest single excursion);
    initial, final = values at the window's ends."""

    mean: float
    std: float
    rms: float
    min: float
    max: float
    peak: float
    initial: float
    final: float


@dataclass(frozen=True)
class ResponseMetrics:
    """Transient metrics of a signal after an event (a ramp start or a gust).

    settling_time [s] after the event to stay within ``band`` of the final value (None if never);
    band [unit]; overshoot [%] of the change (step-like records; None for a return-to-level gust);
    peak_excursion = max |x - final| after the event [unit]; final [unit]."""

    settling_time: float | None
    band: float
    overshoot: float | None
    peak_excursion: float
    final: float


def signal_stats(x: np.ndarray) -> SignalStats:
    """:class:`SignalStats` of a sampled signal (uniform sampling assumed)."""
    x = np.asarray(x, float)
    m = float(np.mean(x))
    return SignalStats(m, float(np.std(x)), float(np.sqrt(np.mean(x**2))), float(np.min(x)),
                       float(np.max(x)), float(np.max(np.abs(x - m))), float(x[0]), float(x[-1]))


def response_metrics(t, x, t_event: float, fraction: float = 0.05, final: float | None = None,
                     min_band: float = 0.0) -> ResponseMetrics:
    """Settling time and overshoot of ``x(t)`` after ``t_event`` [s].

    final = mean of the last 5 % of the record unless given. For a step (|final - x(t_event)|
    larger than 20 % of the largest excursion) the band is ``fraction`` x the change and the
    overshoot is the largest excursion beyond the final value in the direction of the change, in
    % of the change. For a gust that returns to the initial level the band is ``fraction`` x the
    largest excursion from the final value. The band is at least ``min_band``.
    """
    t = np.asarray(t, float)
    x = np.asarray(x, float)
    after = t >= t_event
    if not np.any(after):
        raise ValueError(f"t_event = {t_event:g} s is after the end of the record")
    ta, xa = t[after], x[after]
    if final is None:
        final = float(np.mean(xa[-max(1, xa.size // 20):]))
    x0 = float(xa[0])
    change = final - x0
    exc = float(np.max(np.abs(xa - final)))
    overshoot = None
    if abs(change) > 0.2 * exc and abs(change) > 0:
        band = fraction * abs(change)
        beyond = np.max((xa - final) * np.sign(change))
        overshoot = float(max(beyond, 0.0) / abs(change) * 100.0)
    else:
        band = fraction * exc
    band = max(band, min_band)
    outside = np.nonzero(np.abs(xa - final) > band)[0]
    if outside.size == 0:
        ts = 0.0
    elif outside[-1] == xa.size - 1:
        ts = None
    else:
        ts = float(ta[outside[-1] + 1] - t_event)
    return ResponseMetrics(ts, float(band), overshoot, exc, float(final))


@dataclass(frozen=True, eq=False)
class SimulationResult:
    """Time histories of one run.

    Attributes
    ----------
    t : ndarray (M,)
        Sample times [s].
    y : ndarray (M, n)
        States.
    diag : ndarray (M, ND)
        Kernel diagnostics (:data:`.model.DIAG_NAMES`).
    system, wind : DynamicSystem, WindField
    status : int
        0 = finished; other codes in :data:`.solver.STATUS` / ``STATUS_DRIVER``.
    message : str
    stats : dict
        steps, rejected, rhs_calls, jacobians, factorisations, newton_failures, wall_time [s].
    equilibrium : EquilibriumInfo or None
    """

    t: np.ndarray
    y: np.ndarray
    diag: np.ndarray
    system: DynamicSystem
    wind: WindField
    status: int
    message: str
    stats: dict
    equilibrium: EquilibriumInfo | None = None
    options: SolverOptions = field(default_factory=SolverOptions)

    @property
    def ok(self) -> bool:
        """True when the run reached the end time."""
        return self.status == 0

    def d(self, name: str) -> np.ndarray:
        """A diagnostic by name (``DIAG_NAMES``)."""
        return self.diag[:, DIAG_NAMES.index(name)]

    def signal(self, name: str) -> np.ndarray:
        """A time history of ``SIGNALS`` in its unit (angles in degrees)."""
        b = self.system.hull_index
        if name == "x_C":
            return self.d("x_top")
        if name == "z_C":
            return self.d("z_top")
        if name == "vx":
            return self.d("vx_body")
        if name == "vz":
            return self.d("vz_body")
        if name == "vx_C":
            return self.d("vx_top")
        if name == "vz_C":
            return self.d("vz_top")
        if name == "theta":
            if self.system.is_hull:
                return np.degrees(self.y[:, b + 2])
            return np.zeros(self.t.size)
        if name in ("alpha", "alpha_fin"):
            return np.degrees(self.d(name))
        if name == "tension_C":
            return np.hypot(self.d("tension_top_x"), self.d("tension_top_z"))
        if name == "tension_winch":
            return np.hypot(self.d("tension_winch_x"), self.d("tension_winch_z"))
        if name in ("tension_max", "wind_x", "wind_z", "airspeed"):
            return self.d(name)
        raise KeyError(f"unknown signal {name!r}; valid: {tuple(SIGNALS)}")

    def signal_names(self) -> tuple:
        """Signals that make sense for this body (no pitch for a point aerostat)."""
        if self.system.is_hull:
            return tuple(SIGNALS)
        return tuple(k for k in SIGNALS if k not in ("theta", "alpha", "alpha_fin"))

    def stats_table(self, t_from: float = 0.0, names=None) -> dict:
        """:class:`SignalStats` of each signal over t >= ``t_from`` [s]."""
        sel = self.t >= t_from
        if not np.any(sel):
            raise ValueError(f"t_from = {t_from:g} s is after the end of the record")
        return {k: signal_stats(self.signal(k)[sel]) for k in (names or self.signal_names())}

    def tether(self, i: int):
        """Tether node positions (N+1, 2) [m] at sample ``i`` (winch first, top last)."""
        return self.system.nodes(self.y[i])[0]

    def rigging(self, i: int):
        """Confluence lines from C to the belly at 25 % of the length fore and aft of the CV
        (drawing only: the bridle is rigid in the model), as (x, z) [m] with a NaN break."""
        if not self.system.is_hull:
            raise ValueError("a point aerostat has no rigging")
        h = self.system.body
        b = self.system.hull_index
        xo, zo, th = self.y[i, b], self.y[i, b + 1], self.y[i, b + 2]
        c, s = math.cos(th), math.sin(th)
        xc, zc = h.confluence
        ox, orad = h.outline
        order = np.argsort(ox)
        pts = []
        for xb in (0.25 * h.length, -0.25 * h.length):
            zb = float(np.interp(xb, ox[order], orad[order]))
            pts.append((xo - c * xb - s * zb, zo + s * xb - c * zb))
        cx, cz = xo - c * xc - s * zc, zo + s * xc - c * zc
        x = np.array([pts[0][0], cx, pts[1][0]])
        z = np.array([pts[0][1], cz, pts[1][1]])
        return x, z

    def hull_outline(self, i: int):
        """Hull outline (x, z) [m] in the earth frame at sample ``i`` (hull mode)."""
        if not self.system.is_hull:
            raise ValueError("a point aerostat has no outline")
        h = self.system.body
        b = self.system.hull_index
        xo, zo, th = self.y[i, b], self.y[i, b + 1], self.y[i, b + 2]
        bx = np.concatenate([h.outline[0], h.outline[0][::-1]])
        bz = np.concatenate([-h.outline[1], h.outline[1][::-1]])
        c, s = math.cos(th), math.sin(th)
        return xo - c * bx - s * bz, zo + s * bx - c * bz

    def rows(self, names=None) -> list:
        """Time histories as a list of dicts with units in the keys (for CSV)."""
        names = names or self.signal_names()
        cols = {f"{k}_{SIGNALS[k][1].replace('/', '_')}": self.signal(k) for k in names}
        out = []
        for j in range(self.t.size):
            row = {"t_s": float(self.t[j])}
            for k, v in cols.items():
                row[k] = float(v[j])
            out.append(row)
        return out

    def to_csv(self, names=None) -> str:
        """CSV text of the time histories (one row per sample, units in the header)."""
        names = names or self.signal_names()
        cols = ["t_s"] + [f"{k}_{SIGNALS[k][1].replace('/', '_')}" for k in names]
        data = np.column_stack([self.t] + [self.signal(k) for k in names])
        lines = [",".join(cols)]
        lines += [",".join(f"{v:.6g}" for v in row) for row in data]
        return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------------------------
# Driver
# --------------------------------------------------------------------------------------------
def _atol(system: DynamicSystem, opt: SolverOptions) -> np.ndarray:
    pos, _, vel = _index_sets(system)
    a = np.empty(system.n_state)
    a[pos] = opt.atol_position
    a[vel] = opt.atol_velocity
    if system.is_hull:
        b = system.hull_index
        a[b + 2] = opt.atol_angle
        a[b + 5] = opt.atol_angle
    return a


def simulate(
    system: DynamicSystem,
    wind: WindScenario | WindField,
    duration: float,
    options: SolverOptions | None = None,
    initial_state: np.ndarray | None = None,
    guess: np.ndarray | None = None,
    progress: Callable[[float], None] | None = None,
) -> SimulationResult:
    """Integrate ``system`` in ``wind`` for ``duration`` seconds.

    Parameters
    ----------
    system : DynamicSystem
    wind : WindScenario or WindField
        A scenario is realised with the hull height of the initial state.
    duration : float
        Simulated time [s], valid (0, 1e5].
    options : SolverOptions
    initial_state : ndarray or None
        Start here (e.g. :func:`straight_state`); ``None`` starts from the static equilibrium in
        the wind at t = 0, found by :func:`equilibrium` from ``guess`` (default
        :func:`straight_guess`).
    guess : ndarray or None
        Starting point of the equilibrium search.
    progress : callable or None
        Called with the fraction done (0-1) between chunks.

    Returns
    -------
    SimulationResult
        Check ``.ok``/``.status``/``.message``: a diverging run stops early with its history.
    """
    opt = options or SolverOptions()
    if not (isinstance(duration, (int, float)) and math.isfinite(duration)
            and 0 < duration <= 1e5):
        raise ValueError(f"duration = {duration!r} s is outside the valid range (0, 100000] s")
    t_wall0 = time.perf_counter()
    info = None
    if isinstance(wind, WindField):
        field_ = wind
    else:
        if initial_state is not None:
            y_tmp = np.asarray(initial_state, float)
        else:
            y_tmp = guess if guess is not None else None
        if y_tmp is None:
            height = system.tether.length
        else:
            b = system.hull_index
            height = float(y_tmp[b + 1])
        field_ = wind.realise(height, duration)
    if initial_state is None:
        g0 = guess if guess is not None else straight_guess(system, field_)
        y0, info = equilibrium(system, field_, g0)
    else:
        y0 = np.array(initial_state, float)
        if y0.shape != (system.n_state,):
            raise ValueError(f"initial_state has shape {y0.shape}; expected ({system.n_state},)")
    n_out = int(math.floor(duration / opt.output_interval + 1e-9)) + 1
    out_t = np.arange(n_out) * opt.output_interval
    if out_t[-1] < duration - 1e-9:
        out_t = np.append(out_t, duration)
    if opt.method != "trbdf2":
        return _simulate_scipy(system, field_, duration, opt, y0, out_t, info, t_wall0)
    data = system.data(field_)
    n = system.n_state
    kl, ku = system.structure()
    out_y = np.full((out_t.size, n), np.nan)
    out_d = np.full((out_t.size, ND), np.nan)
    y = y0.copy()
    f = np.empty(n)
    wt = np.empty(NT)
    diag = np.empty(ND)
    wind_time_terms(0.0, data[1], data[2], data[3], wt)
    rhs_kernel(y, f, data, wt, diag)
    out_y[0] = y
    out_d[0] = diag
    stats = np.zeros(S_SIZE, np.int64)
    stats[S_IOUT] = 1
    fs = np.zeros(F_SIZE)
    fs[F_T] = 0.0
    fs[F_H] = opt.initial_step
    fs[F_ETA] = 1.0
    fs[F_STALE] = 1.0
    o = np.zeros(O_SIZE)
    o[O_RTOL] = opt.rtol
    o[O_HMAX] = opt.max_step
    o[O_HMIN] = 1e-10 * max(1.0, duration)
    o[O_KAPPA] = 0.05
    o[O_JAC_EVERY] = opt.jacobian_refresh
    o[O_MAXIT] = 6
    atol = _atol(system, opt)
    stops = field_.breakpoints()
    stops = stops[(stops > 0) & (stops < duration)]
    jac = np.zeros((n, n))
    wmat = np.zeros((n, n))
    piv = np.zeros(n, np.int64)
    scale = _scale(system)
    status = 0
    chunk = max(50, min(2000, int(opt.max_steps)))
    t_chunk = max(duration / 50.0, 1.0)
    while fs[F_T] < duration - 1e-12 * duration:
        remaining = int(opt.max_steps - stats[S_STEPS])
        if remaining <= 0:
            status = 9
            break
        o[O_MAXSTEPS] = min(chunk, remaining)
        t_stop = min(duration, fs[F_T] + t_chunk)
        code = integrate_chunk(fs, y, f, t_stop, data, o, atol, stops, out_t, out_y, out_d,
                               stats, jac, wmat, piv, scale, kl, ku)
        if code not in (0, 1):
            status = int(code)
            break
        if progress is not None:
            progress(min(1.0, fs[F_T] / duration))
        if time.perf_counter() - t_wall0 > opt.wall_time_limit:
            if fs[F_T] < duration - 1e-12 * duration:
                status = 8
            break
    wall = time.perf_counter() - t_wall0
    m = int(stats[S_IOUT])
    msg = STATUS.get(status, STATUS_DRIVER.get(status, "unknown"))
    if status != 0:
        msg = f"stopped at t = {fs[F_T]:.2f} s: {msg}"
    st = {
        "steps": int(stats[S_STEPS]), "rejected": int(stats[S_REJECT]),
        "rhs_calls": int(stats[S_FEVAL]), "jacobians": int(stats[S_JAC]),
        "factorisations": int(stats[S_LU]), "newton_failures": int(stats[S_NFAIL]),
        "wall_time": wall, "t_end": float(fs[F_T]),
    }
    return SimulationResult(out_t[:m], out_y[:m], out_d[:m], system, field_, status, msg, st, info,
                            opt)


def _simulate_scipy(system, field_, duration, opt, y0, out_t, info, t_wall0):
    from scipy.integrate import solve_ivp

    data = system.data(field_)
    n = system.n_state
    kl, ku = system.structure()
    wt = np.empty(NT)
    diag = np.empty(ND)
    scale = _scale(system)
    jac = np.zeros((n, n))
    counter = {"f": 0, "j": 0}

    def fun(t, y):
        wind_time_terms(t, data[1], data[2], data[3], wt)
        dy = np.empty(n)
        rhs_kernel(y, dy, data, wt, diag)
        counter["f"] += 1
        if time.perf_counter() - t_wall0 > opt.wall_time_limit:
            raise TimeoutError
        return dy

    def jacf(t, y):
        f0 = fun(t, y)
        wind_time_terms(t, data[1], data[2], data[3], wt)
        counter["j"] += 1
        jac[:] = 0.0
        band_jacobian(y, f0, data, wt, kl, ku, jac, scale)
        return jac.copy()

    atol = _atol(system, opt)
    stops = field_.breakpoints()
    edges = np.unique(np.concatenate([[0.0], stops[(stops > 0) & (stops < duration)],
                                      [duration]]))
    ys, ts = [], []
    y = y0.copy()
    status, msg = 0, STATUS[0]
    steps = 0
    for a, b in zip(edges[:-1], edges[1:]):
        sel = (out_t >= a) & (out_t <= b)
        if ts and sel.any() and abs(out_t[sel][0] - ts[-1][-1]) < 1e-12:
            sel &= out_t > a
        kw = dict(method=opt.method, rtol=opt.rtol, atol=atol, max_step=opt.max_step,
                  first_step=min(opt.initial_step, b - a), t_eval=out_t[sel])
        if opt.method == "LSODA":
            kw.update(lband=kl, uband=ku)
        else:
            kw["jac"] = jacf
        try:
            sol = solve_ivp(fun, (a, b), y, **kw)
        except TimeoutError:
            status, msg = 8, STATUS_DRIVER[8]
            break
        steps += int(getattr(sol, "nfev", 0))
        if not sol.success:
            status, msg = 10, f"{STATUS_DRIVER[10]}: {sol.message}"
            break
        ts.append(sol.t)
        ys.append(sol.y.T)
        y = sol.y[:, -1].copy() if sol.t.size and sol.t[-1] == b else _final(fun, a, b, y, kw)
    t_all = np.concatenate(ts) if ts else np.zeros(0)
    y_all = np.concatenate(ys) if ys else np.zeros((0, n))
    d_all = np.empty((t_all.size, ND))
    dy = np.empty(n)
    for i, (ti, yi) in enumerate(zip(t_all, y_all)):
        wind_time_terms(ti, data[1], data[2], data[3], wt)
        rhs_kernel(yi, dy, data, wt, d_all[i])
    st = {"steps": None, "rejected": None, "rhs_calls": counter["f"], "jacobians": counter["j"],
          "factorisations": None, "newton_failures": None,
          "wall_time": time.perf_counter() - t_wall0, "t_end": float(t_all[-1]) if t_all.size
          else 0.0}
    return SimulationResult(t_all, y_all, d_all, system, field_, status, msg, st, info, opt)


def _final(fun, a, b, y, kw):
    from scipy.integrate import solve_ivp

    kw = dict(kw)
    kw["t_eval"] = None
    sol = solve_ivp(fun, (a, b), y, **kw)
    return sol.y[:, -1].copy()


def engine_guess(system: DynamicSystem, design, speed: float) -> np.ndarray:
    """Rest state from the static engine's solution at wind ``speed`` [m/s] at the hull.

    The hull at the engine's trim alpha_eq with its confluence point on the top of the engine's
    tether profile; the lumped-mass nodes on that profile at their unstretched arc lengths.
    :func:`equilibrium` then polishes it (the shift it reports is the difference between the
    engine's continuous march and the lumped-mass line).
    """
    from ..performance import evaluate

    ev = evaluate(design.requirement, design.configuration, design.airframe, float(speed))
    x = np.asarray(ev.tether.x, float).reshape(-1)
    z = np.asarray(ev.tether.z, float).reshape(-1)
    alpha = float(np.asarray(ev.equilibrium.alpha).reshape(-1)[0])
    n_eng = x.size - 1
    length = system.tether.length
    s_eng = np.linspace(0.0, length, n_eng + 1)  # from the top
    n = system.tether.segments
    s = length - np.arange(n + 1) * length / n  # node i from the winch
    pos = np.column_stack([np.interp(s, s_eng, x), np.interp(s, s_eng, z)])
    pos = pos + np.array(system.winch)
    vel = np.zeros_like(pos)
    if system.is_hull:
        xo, zo = system.hull_pose_from_confluence(pos[-1, 0], pos[-1, 1], alpha)
        body = np.array([xo, zo, alpha, 0.0, 0.0, 0.0])
    else:
        body = np.array([pos[-1, 0], pos[-1, 1], 0.0, 0.0])
    return system.pack_state(pos, vel, body)
