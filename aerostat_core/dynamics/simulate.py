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

import numpy as np

from .kernel import ND, rhs_kernel
from .options import MAX_OUTPUT_BYTES, METHODS, STATUS_DRIVER, SolverOptions
from .results import (
    SIGNALS,
    EquilibriumInfo,
    ResponseMetrics,
    SignalStats,
    SimulationResult,
    response_metrics,
    signal_stats,
)
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
    band_width,
    integrate_chunk,
)
from .system import DynamicSystem
from .wind import WindField, WindScenario

__all__ = ["METHODS", "SIGNALS", "STATUS_DRIVER", "EquilibriumInfo", "ResponseMetrics",
           "SignalStats", "SimulationResult", "SolverOptions", "engine_guess", "equilibrium",
           "index_sets", "integrate", "output_times", "response_metrics", "signal_stats",
           "simulate", "straight_guess",
           "straight_state", "kernels_warm", "warm_kernels"]


# --------------------------------------------------------------------------------------------
# Initial states
# --------------------------------------------------------------------------------------------
def index_sets(system: DynamicSystem):
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
    pos, _, vel = index_sets(system)
    sc[pos] = max(1.0, 0.01 * system.tether.length)
    sc[vel] = 1.0
    if system.is_hull:
        sc[system.hull_index + 2] = 0.1
        sc[system.hull_index + 5] = 0.1
    return sc


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
    pos, acc, vel = index_sets(system)
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
        rhs_kernel(0.0, v, f, data, diag)
        return f[acc].copy()

    r = resid(y)
    it = 0
    while it < max_iter:
        it += 1
        band_jacobian(0.0, y, f, data, kl, ku, jac, scale)
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
    rhs_kernel(0.0, y, f, data, diag)
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
# Driver
# --------------------------------------------------------------------------------------------
def _atol(system: DynamicSystem, opt: SolverOptions) -> np.ndarray:
    pos, _, vel = index_sets(system)
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
        A scenario is realised at the hull's initial height and position (the convected gust
        and turbulence reach the hull at their nominal times).
    duration : float
        Simulated time [s], valid (0, 1e5].
    options : SolverOptions
        The output grid (duration / output_interval samples) must fit in ``MAX_OUTPUT_BYTES``.
    initial_state : ndarray or None
        Start here (e.g. :func:`straight_state`); ``None`` starts from the static equilibrium in
        the wind at t = 0, found by :func:`equilibrium` from ``guess`` (default
        :func:`straight_guess`).
    guess : ndarray or None
        Starting point of the equilibrium search.
    progress : callable or None
        Called with the fraction done (0-1) between chunks (at least every ~0.2 s of wall time).

    Returns
    -------
    SimulationResult
        Check ``.ok``/``.status``/``.message``: a run stops early only on an unphysical state
        (non-finite, below the winch level, pitch beyond the hull's limit) or a budget, with
        its history up to there; ``.stats["wall_time"]`` excludes the kernels' compilation.
    """
    opt = options or SolverOptions()
    out_t = output_times(duration, opt, system.n_state + ND)
    warm_kernels()
    t_wall0 = time.perf_counter()
    info = None
    if isinstance(wind, WindField):
        field_ = wind
    else:
        y_tmp = initial_state if initial_state is not None else guess
        if y_tmp is None:
            y_tmp = straight_guess(system, wind.realize(system.tether.length, 60.0))
        y_tmp = np.asarray(y_tmp, float)
        b = system.hull_index
        field_ = wind.realize(float(y_tmp[b + 1]), duration, x_ref=float(y_tmp[b]))
    if initial_state is None:
        g0 = guess if guess is not None else straight_guess(system, field_)
        y0, info = equilibrium(system, field_, g0)
    else:
        y0 = np.array(initial_state, float)
        if y0.shape != (system.n_state,):
            raise ValueError(f"initial_state has shape {y0.shape}; expected ({system.n_state},)")
    if opt.method != "trbdf2":
        return _simulate_scipy(system, field_, duration, opt, y0, out_t, info, t_wall0)
    data = system.data(field_)
    stops = field_.breakpoints()
    stops = stops[(stops > 0) & (stops < duration)]
    run = integrate(data, y0, out_t, duration, opt, _atol(system, opt), _scale(system),
                    stops, system.structure(), progress, t_wall0)
    out_y, out_d, stats, fs, status, wall = run
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


#: Wall time one integrator call aims at [s]: progress and the wall-clock budget are checked
#: between calls, so at least every second even when the steps become small.
CHUNK_WALL = 0.2


def output_times(duration: float, opt: SolverOptions, columns: int) -> np.ndarray:
    """The output times [s] of a run of ``duration`` [s], valid (0, 1e5]: the grid of
    ``opt.output_interval`` from 0, then the end; checked to fit, with ``columns`` float
    columns, the output budget ``MAX_OUTPUT_BYTES`` (``ValueError`` saying what to change
    otherwise). The 3- and 6-DOF runs share it."""
    if not (isinstance(duration, (int, float)) and math.isfinite(duration)
            and 0 < duration <= 1e5):
        raise ValueError(f"duration = {duration!r} s is outside the valid range (0, 100000] s")
    n_out = int(math.floor(duration / opt.output_interval + 1e-9)) + 2
    need = n_out * columns * 8
    if need > MAX_OUTPUT_BYTES:
        raise ValueError(
            f"the output grid of duration = {duration:g} s at output_interval = "
            f"{opt.output_interval:g} s needs {need / 2**20:.0f} MiB (limit "
            f"{MAX_OUTPUT_BYTES / 2**20:.0f} MiB): shorten duration or lengthen output_interval "
            f"(at least {duration * columns * 8 / MAX_OUTPUT_BYTES:.3g} s)")
    out_t = np.arange(n_out - 1) * opt.output_interval
    if out_t[-1] < duration - 1e-9:
        out_t = np.append(out_t, duration)
    return out_t


def integrate(data, y0: np.ndarray, out_t: np.ndarray, duration: float, opt: SolverOptions,
              atol: np.ndarray, scale: np.ndarray, stops: np.ndarray, structure: tuple,
              progress: Callable[[float], None] | None, t_wall0: float):
    """The compiled TR-BDF2 (docs/dynamics.md §1.8) from ``y0`` to ``duration`` [s], in chunks
    that each last about :data:`CHUNK_WALL` seconds, so that ``progress`` runs and the step and
    wall-clock budgets of ``opt`` are enforced between them. One driver for the 3- and 6-DOF
    models: the compiled kernel dispatches on the mode entry of ``data``.

    ``atol``, ``scale``: per-state absolute tolerance and Newton scale; ``stops``: times the
    step must land on (wind and event breakpoints); ``structure``: the Jacobian's band (kl, ku).

    Returns (out_y, out_d, stats, fs, status, wall): the states and the 3-DOF diagnostics at
    ``out_t`` (NaN past the end), the solver's counters and float state (``fs[F_T]`` the time
    reached), the status (0: done; 8, 9: a budget; else the kernel's) and the wall time [s]
    since ``t_wall0``.
    """
    kl, ku = structure
    n = y0.size
    out_y = np.full((out_t.size, n), np.nan)
    out_d = np.full((out_t.size, ND), np.nan)
    y = y0.copy()
    f = np.empty(n)
    diag = np.empty(ND)
    rhs_kernel(0.0, y, f, data, diag)
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
    jac = np.zeros((n, n))
    wmat = np.zeros((n, band_width(kl, ku)))
    piv = np.zeros(n, np.int64)
    status = 0
    chunk = 200  # steps per call, adapted so that one call lasts about CHUNK_WALL seconds
    t_chunk = max(duration / 50.0, 1.0)
    while fs[F_T] < duration - 1e-12 * duration:
        remaining = int(opt.max_steps - stats[S_STEPS])
        if remaining <= 0:
            status = 9
            break
        o[O_MAXSTEPS] = min(chunk, remaining)
        # Stops on a fixed grid of t_chunk: a call cut short by its step budget (which follows
        # the wall clock) resumes towards the same stop, so the step sequence, and the result,
        # do not depend on the machine's speed or load.
        t_stop = min(duration, (np.floor(fs[F_T] / t_chunk + 1e-9) + 1.0) * t_chunk)
        steps0 = int(stats[S_STEPS])
        tc = time.perf_counter()
        code = integrate_chunk(fs, y, f, t_stop, data, o, atol, stops, out_t, out_y, out_d,
                               stats, jac, wmat, piv, scale, kl, ku)
        dt_call = time.perf_counter() - tc
        done = int(stats[S_STEPS]) - steps0
        if done > 0 and dt_call > 0:
            chunk = int(min(max(CHUNK_WALL * done / dt_call, 20), 20000))
        if code not in (0, 1):
            status = int(code)
            break
        if progress is not None:
            progress(min(1.0, fs[F_T] / duration))
        if time.perf_counter() - t_wall0 > opt.wall_time_limit:
            if fs[F_T] < duration - 1e-12 * duration:
                status = 8
            break
    return out_y, out_d, stats, fs, status, time.perf_counter() - t_wall0
_WARM: list[bool] = []


def kernels_warm() -> bool:
    """True when :func:`warm_kernels` has run in this process."""
    return bool(_WARM)


def warm_kernels() -> float:
    """Load (or compile, the first time on a machine) every kernel of a run; returns the seconds
    it took (0 after the first call in a process). :func:`simulate` calls it before starting its
    clock, so the reported wall time excludes compilation."""
    if _WARM:
        return 0.0
    from .cases import case_p_system

    t0 = time.perf_counter()
    system = case_p_system(4)
    y = straight_state(system, (0.0, 319.5))
    data = system.data(WindScenario.steady(5.0).realize(319.5, 1.0))
    n = system.n_state
    f = np.empty(n)
    diag = np.empty(ND)
    rhs_kernel(0.0, y, f, data, diag)
    kl, ku = system.structure()
    fs = np.array([0.0, 1e-3, 1.0, 0.0, 1.0])
    o = np.array([1e-6, 1.0, 1e-10, 10.0, 0.05, 50.0, 6.0])
    stats = np.zeros(S_SIZE, np.int64)
    out_t = np.array([0.0])
    integrate_chunk(fs, y, f, 1e-3, data, o, np.full(n, 1e-5), np.zeros(0), out_t,
                    np.empty((1, n)), np.empty((1, ND)), stats, np.zeros((n, n)),
                    np.zeros((n, band_width(kl, ku))), np.zeros(n, np.int64), np.ones(n), kl, ku)
    band_jacobian(0.0, y, f, data, kl, ku, np.zeros((n, n)), np.ones(n))
    system.nodes(y)
    WindScenario.steady(5.0).realize(319.5, 1.0).at(0.0, 100.0)
    _WARM.append(True)
    return time.perf_counter() - t0


def _simulate_scipy(system, field_, duration, opt, y0, out_t, info, t_wall0):
    from scipy.integrate import solve_ivp

    data = system.data(field_)
    n = system.n_state
    kl, ku = system.structure()
    diag = np.empty(ND)
    scale = _scale(system)
    jac = np.zeros((n, n))
    counter = {"f": 0, "j": 0}

    def fun(t, y):
        dy = np.empty(n)
        rhs_kernel(t, y, dy, data, diag)
        counter["f"] += 1
        if time.perf_counter() - t_wall0 > opt.wall_time_limit:
            raise TimeoutError
        return dy

    def jacf(t, y):
        f0 = fun(t, y)
        counter["j"] += 1
        jac[:] = 0.0
        band_jacobian(t, y, f0, data, kl, ku, jac, scale)
        return jac.copy()

    atol = _atol(system, opt)
    stops = field_.breakpoints()
    edges = np.unique(np.concatenate([[0.0], stops[(stops > 0) & (stops < duration)],
                                      [duration]]))
    ys, ts = [], []
    y = y0.copy()
    status, msg = 0, STATUS[0]
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
        rhs_kernel(ti, yi, dy, data, d_all[i])
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
    from aerostat_core.model.performance import evaluate

    ev = evaluate(design.requirement, design.configuration, design.airframe, float(speed))
    x = np.asarray(ev.tether.x, float).reshape(-1)
    z = np.asarray(ev.tether.z, float).reshape(-1)
    alpha = float(np.asarray(ev.equilibrium.alpha).reshape(-1)[0])
    return _rest_state_on_profile(system, x, z, alpha)


def engine_guesses(system: DynamicSystem, design, speeds) -> np.ndarray:
    """:func:`engine_guess` at each wind speed of ``speeds`` [m/s] (1-D), from one vectorised
    call of the static engine instead of one per speed; row k is the rest state at
    ``speeds[k]``. The engine solves each speed of the batch as it solves it alone (the trim and
    the tether march are elementwise), so row k is :func:`engine_guess` at ``speeds[k]`` to
    rounding (~1e-18 rad in the trim angle)."""
    from aerostat_core.model.performance import evaluate

    speeds = np.asarray(speeds, float).reshape(-1)
    ev = evaluate(design.requirement, design.configuration, design.airframe, speeds)
    x = np.asarray(ev.tether.x, float).reshape(-1, speeds.size)
    z = np.asarray(ev.tether.z, float).reshape(-1, speeds.size)
    alpha = np.asarray(ev.equilibrium.alpha, float).reshape(-1) * np.ones(speeds.size)
    return np.array([_rest_state_on_profile(system, x[:, k], z[:, k], float(alpha[k]))
                     for k in range(speeds.size)])


def _rest_state_on_profile(system: DynamicSystem, x: np.ndarray, z: np.ndarray,
                           alpha: float) -> np.ndarray:
    """Rest state on the engine's tether profile (x, z) [m] (nodes from the top) with the hull
    at the trim angle ``alpha`` [rad] (:func:`engine_guess`)."""
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
