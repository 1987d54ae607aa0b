"""Wind inputs of the dynamic model: mean profile, speed schedules, 1-cosine gusts, turbulence.

The wind at a point (x, z) at time t is (docs/dynamics.md §2)

    U_x = U_ref(t) P(z) + g_u(tau) + f(t) u'(tau, z),     U_z = g_w(tau) + f(t) w'(tau, z)

* ``P(z)``: mean profile shape (uniform, power law, log law), 1 at the reference height;
* ``U_ref(t)``: a schedule of ramps between constant speeds ("varying wind", thesis Fig. 3.24),
  uniform in space: the whole air mass speeds up at once;
* ``g_u, g_w``: a MIL-F-8785C "1 - cosine" discrete gust (thesis Fig. 3.25), frozen and convected
  by the mean wind: tau = t - (x - x_ref)/U_c, so it reaches the winch, the tether and the hull in
  turn (``Gust.convected=False``: the same at every point at once);
* ``u', w'``: MIL-HDBK-1797 Dryden turbulence, a frozen field convected by U_c and varying with
  height (:mod:`.turbulence`), faded in by f(t).

Fluid acceleration. The Froude-Krylov and added-mass forces of an unsteady wind are driven by the
acceleration of the air itself, the material derivative Du/Dt = du/dt + U du/dx (not the
fixed-point du/dt). For a frozen field advected at U_c, du/dt = -U_c du/dx, so Du/Dt =
(U(z) - U_c) du/dx: zero at the hull (U = U_c) and O(shear) elsewhere; the kernel takes it as zero
for the convected gust and the turbulence (plus the fade-in's own f'(t) u'). For the uniform
schedule (and a non-convected gust) du/dx = 0 and Du/Dt = du/dt, the analytic slope. The kernel
returns both: the local du/dt (diagnostics) and Du/Dt (forces).

Every input is a smooth function of time with a consistent derivative, so implicit integrators
meet no piecewise-constant data (docs/dynamics.md §1.8). The numba kernels are
:func:`wind_time_terms` (time-only parts, once per right-hand side) and :func:`wind_point`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numba import njit

from aerostat_core.base.deprecation import deprecated_method
from aerostat_core.base.fields import choice, number, validate

from .checks import check_number as _check
from .turbulence import (
    DRYDEN_W20,
    FOOT,
    KNOT,
    MIN_CONVECTION_SPEED,
    W20_HEIGHT,
    DrydenParameters,
    DrydenTurbulence,
    TurbulenceField,
    dryden_parameters,
    dryden_psd_u,
    dryden_psd_w,
)

__all__ = ["DRYDEN_W20", "FOOT", "KNOT", "NT", "NW", "DrydenParameters", "DrydenTurbulence",
           "Gust", "MeanProfile", "SpeedSchedule", "TurbulenceField", "WindField",
           "WindScenario", "dryden_parameters", "dryden_psd_u", "dryden_psd_w", "profile_factor",
           "turbulence_at", "wind_point", "wind_points", "wind_time_terms"]

PROFILE_KINDS = ("uniform", "power", "log")
RAMP_SHAPES = ("linear", "cosine")
GUST_SHAPES = ("full", "ramp-hold")

# codes shared with the numba kernels
PROFILE_CODE = {"uniform": 0, "power": 1, "log": 2}
RAMP_CODE = {"linear": 0, "cosine": 1}
GUST_CODE = {"full": 0, "ramp-hold": 1}
# layout of the wind parameter vector ``wpar``
W_PROFILE, W_ZREF, W_EXPONENT, W_Z0, W_ZMIN = 0, 1, 2, 3, 4
W_RAMP, W_GUST_ON, W_GUST_T0, W_GUST_T, W_GUST_U, W_GUST_W, W_GUST_SHAPE = 5, 6, 7, 8, 9, 10, 11
W_GUST_CONV, W_TURB_ON, W_FADE, W_TURB_DT, W_TURB_Z0, W_TURB_DZ, W_TURB_NL = 12, 13, 14, 15, 16, 17, 18
W_UC, W_XREF = 19, 20
W_SIZE = 21
#: number of time terms returned by :func:`wind_time_terms` (U_ref, dU_ref/dt, fade, dfade/dt)
NT = 4
#: number of outputs of :func:`wind_point` (U_x, U_z, dU_x/dt, dU_z/dt, DU_x/Dt, DU_z/Dt)
NW = 6


# --------------------------------------------------------------------------------------------
# Mean profile
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class MeanProfile:
    """Shape of the mean wind versus height, P(z), equal to 1 at ``reference_height``.

    uniform: P = 1;  power law: P = (z/z_ref)^p;  log law: P = ln(z/z0)/ln(z_ref/z0),
    with z clipped to >= 1 m (and >= 2 z0 in the log law), as in :mod:`aerostat_core.atmosphere.wind`.

    Parameters
    ----------
    kind : {"uniform", "power", "log"}
    reference_height : float
        z_ref, height where the schedule speed U_ref applies [m], valid [1, 5000]. The app uses
        the static flying height of the confluence point, so "wind speed" means the wind at the
        aerostat, as in the static performance table.
    exponent : float
        Power-law exponent p [-], valid [0, 0.6] (1/7 open terrain).
    roughness_length : float
        Log-law roughness z0 [m], valid [1e-5, 2].

    Notes
    -----
    Sources: Hellmann power law; neutral surface-layer log law (docs/dynamics.md §2.1).

    Examples
    --------
    >>> round(float(MeanProfile("power", 10.0).factor(320.0)), 4)
    1.6407
    """

    kind: str = choice("uniform", "Wind profile", PROFILE_KINDS)
    reference_height: float = number(10.0, "Reference height", "m", 1.0, 5000.0)
    exponent: float = number(1.0 / 7.0, "Power-law exponent", "", 0.0, 0.6)
    roughness_length: float = number(0.03, "Roughness length", "m", 1e-5, 2.0)

    def __post_init__(self) -> None:
        validate(self)

    def factor(self, z):
        """P(z) [-] at heights ``z`` [m] (broadcasts)."""
        z = np.asarray(z, float)
        out = np.empty(z.shape)
        wpar = self.kernel_parameters()
        flat = out.reshape(-1)
        for i, zi in enumerate(z.reshape(-1)):
            flat[i] = profile_factor(float(zi), wpar)
        return out if out.ndim else out[()]

    def kernel_parameters(self) -> np.ndarray:
        w = np.zeros(W_SIZE)
        w[W_PROFILE] = PROFILE_CODE[self.kind]
        w[W_ZREF] = self.reference_height
        w[W_EXPONENT] = self.exponent
        w[W_Z0] = self.roughness_length
        w[W_ZMIN] = 1.0
        return w


@njit(cache=True)
def profile_factor(z, wpar):  # pragma: no cover - numba
    """Mean-profile factor P(z) [-] (see :class:`MeanProfile`); ``z`` in [m]."""
    kind = int(wpar[W_PROFILE])
    if kind == 0:
        return 1.0
    zc = max(z, wpar[W_ZMIN])
    zr = max(wpar[W_ZREF], wpar[W_ZMIN])
    if kind == 1:
        return (zc / zr) ** wpar[W_EXPONENT]
    z0 = wpar[W_Z0]
    return math.log(max(zc, 2.0 * z0) / z0) / math.log(max(zr, 2.0 * z0) / z0)


# --------------------------------------------------------------------------------------------
# Speed schedule ("varying wind")
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class SpeedSchedule:
    """Reference wind speed U_ref(t): constant between knots, ramps between them.

    Between knots (t_k, U_k) and (t_k+1, U_k+1), with s = (t - t_k)/(t_k+1 - t_k):
    linear ramp U = U_k + (U_k+1 - U_k) s; cosine ramp U = U_k + (U_k+1 - U_k)(1 - cos(pi s))/2
    (smooth: zero slope at both ends). Before the first knot U = U_0, after the last U = U_last.

    Parameters
    ----------
    times : tuple of float
        Knot times [s], strictly increasing, in [0, 1e5].
    speeds : tuple of float
        Speeds at the knots [m/s], each in [-60, 60].
    shape : {"linear", "cosine"}

    Examples
    --------
    >>> s = SpeedSchedule.step(5.0, 10.0, t_step=150.0, ramp_time=1.0)
    >>> [float(v) for v in s.evaluate(np.array([0.0, 150.5, 200.0]))[0]]
    [5.0, 7.5, 10.0]
    """

    times: tuple = (0.0,)
    speeds: tuple = (10.0,)
    shape: str = "linear"

    def __post_init__(self) -> None:
        t = tuple(float(x) for x in np.atleast_1d(self.times))
        u = tuple(float(x) for x in np.atleast_1d(self.speeds))
        object.__setattr__(self, "times", t)
        object.__setattr__(self, "speeds", u)
        if len(t) == 0 or len(t) != len(u):
            raise ValueError(f"SpeedSchedule needs as many times ({len(t)}) as speeds ({len(u)}), "
                             "at least one of each")
        if len(t) > 1000:
            raise ValueError(f"SpeedSchedule has {len(t)} knots; the limit is 1000")
        for i, (ti, ui) in enumerate(zip(t, u)):
            _check("SpeedSchedule", f"times[{i}]", ti, 0.0, 1e5, "s")
            _check("SpeedSchedule", f"speeds[{i}]", ui, -60.0, 60.0, "m/s")
        for i in range(1, len(t)):
            if t[i] - t[i - 1] < 0.05:
                raise ValueError(
                    f"SpeedSchedule.times[{i}] = {t[i]:g} s: knots must be at least 0.05 s apart "
                    f"(previous {t[i - 1]:g} s); a ramp shorter than that is a discontinuity"
                )
        if self.shape not in RAMP_SHAPES:
            raise ValueError(f"SpeedSchedule.shape = {self.shape!r}; valid options {RAMP_SHAPES}")

    @classmethod
    def constant(cls, speed: float) -> SpeedSchedule:
        """U_ref = ``speed`` [m/s] at all times."""
        return cls((0.0,), (float(speed),))

    @classmethod
    def step(cls, u0: float, u1: float, t_step: float, ramp_time: float = 1.0,
             shape: str = "linear") -> SpeedSchedule:
        """From ``u0`` to ``u1`` [m/s], starting at ``t_step`` [s], over ``ramp_time`` [s]."""
        _check("SpeedSchedule", "ramp_time", ramp_time, 0.05, 1e4, "s")
        return cls((t_step, t_step + ramp_time), (u0, u1), shape)

    @classmethod
    def ramps(cls, u0: float, changes, shape: str = "linear") -> SpeedSchedule:
        """Start at ``u0`` [m/s]; ``changes`` = [(t_start [s], new speed [m/s], ramp time [s]), ...]."""
        times, speeds = [0.0], [float(u0)]
        for k, (ts, un, tau) in enumerate(changes):
            _check("SpeedSchedule", f"changes[{k}].ramp_time", tau, 0.05, 1e4, "s")
            if ts < times[-1] - 1e-9:
                raise ValueError(f"SpeedSchedule change {k} starts at {ts:g} s, before the previous "
                                 f"ramp ends ({times[-1]:g} s)")
            if ts > times[-1] + 1e-9:
                times.append(float(ts))
                speeds.append(speeds[-1])
            times.append(float(ts + tau))
            speeds.append(float(un))
        return cls(tuple(times), tuple(speeds), shape)

    def evaluate(self, t):
        """U_ref(t) [m/s] and dU_ref/dt [m/s2] at times ``t`` [s]."""
        t = np.atleast_1d(np.asarray(t, float))
        arr = self.kernel_array()
        code = RAMP_CODE[self.shape]
        u = np.empty(t.shape)
        du = np.empty(t.shape)
        for i, ti in enumerate(t):
            u[i], du[i] = _schedule(ti, arr, code)
        return u, du

    def breakpoints(self) -> tuple:
        """Times [s] where the speed's slope jumps (the integrator steps onto them)."""
        return self.times

    def kernel_array(self) -> np.ndarray:
        return np.array([self.times, self.speeds], float)


@njit(cache=True)
def _schedule(t, sched, code):  # pragma: no cover - numba
    n = sched.shape[1]
    if t <= sched[0, 0] or n == 1:
        return sched[1, 0], 0.0
    if t >= sched[0, n - 1]:
        return sched[1, n - 1], 0.0
    k = 0
    lo, hi = 0, n - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if sched[0, mid] <= t:
            lo = mid
        else:
            hi = mid
    k = lo
    t0, t1 = sched[0, k], sched[0, k + 1]
    u0, u1 = sched[1, k], sched[1, k + 1]
    dt = t1 - t0
    s = (t - t0) / dt
    if code == 0:
        return u0 + (u1 - u0) * s, (u1 - u0) / dt
    return (u0 + 0.5 * (u1 - u0) * (1.0 - math.cos(math.pi * s)),
            0.5 * (u1 - u0) * math.pi / dt * math.sin(math.pi * s))


# --------------------------------------------------------------------------------------------
# Discrete gust
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Gust:
    """MIL-F-8785C "1 - cosine" discrete gust, frozen and convected by the mean wind.

    With x = U_c (t - t0) the distance the gust front has travelled past the hull and d_m the gust
    length: g = (A/2)(1 - cos(pi x/d_m)) for 0 <= x <= d_m; then ``"full"`` continues the cosine
    back to zero at x = 2 d_m, ``"ramp-hold"`` holds g = A. Applied to the longitudinal (A_u) and
    vertical (A_w, up positive) wind. ``convected`` (default): a frozen gust travelling with the
    mean wind, reaching a point at x at t0 + (x - x_ref)/U_c (x_ref: the hull's initial x), so
    the air carrying it does not accelerate (Du/Dt = 0: no Froude-Krylov force); otherwise the
    gust blows at every point at once (a uniform time-varying wind, Du/Dt = dg/dt).

    Parameters
    ----------
    amplitude_u : float
        Longitudinal gust amplitude V_m [m/s], valid [-30, 30] (typical 3-8).
    amplitude_w : float
        Vertical gust amplitude [m/s], valid [-30, 30].
    length : float
        d_m, gust half-length [m], valid [1, 5000] (typical 30-120 m: rise 3-12 s at 10 m/s).
    start_time : float
        t0 [s], valid [0, 1e5].
    shape : {"full", "ramp-hold"}
    convected : bool
        Frozen and convected by the mean wind (True) or uniform in space (False).

    Notes
    -----
    Source: MIL-F-8785C §3.7.4 (discrete gust); MathWorks "Discrete Wind Gust Model" (docs/dynamics.md
    §2.3). The convection speed U_c is the mean wind at the hull at t = 0.
    """

    amplitude_u: float = number(5.0, "Gust amplitude, horizontal", "m/s", -30.0, 30.0)
    amplitude_w: float = number(0.0, "Gust amplitude, vertical", "m/s", -30.0, 30.0)
    length: float = number(60.0, "Gust length d_m", "m", 1.0, 5000.0)
    start_time: float = number(20.0, "Gust start time", "s", 0.0, 1e5)
    shape: str = choice("full", "Gust shape", GUST_SHAPES)
    convected: bool = True

    def __post_init__(self) -> None:
        validate(self)

    def rise_time(self, convection_speed: float) -> float:
        """Time for the gust to build up, d_m / U_c [s]."""
        return self.length / convection_speed

    def duration(self, convection_speed: float) -> float:
        """Time the gust lasts [s]: 2 d_m/U_c ("full") or d_m/U_c to reach the hold ("ramp-hold")."""
        k = 2.0 if self.shape == "full" else 1.0
        return k * self.rise_time(convection_speed)


@njit(cache=True)
def _gust(t, t0, tr, shape):  # pragma: no cover - numba
    """Unit gust shape and its time derivative [1/s] at time t (rise time tr)."""
    tau = t - t0
    if tau <= 0.0:
        return 0.0, 0.0
    end = 2.0 * tr if shape == 0 else tr
    if tau >= end:
        return (0.0 if shape == 0 else 1.0), 0.0
    a = math.pi * tau / tr
    return 0.5 * (1.0 - math.cos(a)), 0.5 * math.pi / tr * math.sin(a)


# --------------------------------------------------------------------------------------------
# Scenario -> realised field -> numba arrays
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class WindScenario:
    """Everything that defines the wind of one run.

    Parameters
    ----------
    schedule : SpeedSchedule
        Reference speed U_ref(t) at the profile's reference height.
    profile : MeanProfile
    gust : Gust or None
    turbulence : DrydenTurbulence or None

    Examples
    --------
    >>> WindScenario.steady(10.0).schedule.speeds
    (10.0,)
    """

    schedule: SpeedSchedule = field(default_factory=SpeedSchedule)
    profile: MeanProfile = field(default_factory=MeanProfile)
    gust: Gust | None = None
    turbulence: DrydenTurbulence | None = None

    @classmethod
    def steady(cls, speed: float, profile: MeanProfile | None = None) -> WindScenario:
        """Constant wind ``speed`` [m/s] at the reference height."""
        return cls(SpeedSchedule.constant(speed), profile or MeanProfile())

    def initial_speed(self) -> float:
        """U_ref at t = 0 [m/s]."""
        return float(self.schedule.evaluate(0.0)[0][0])

    def w20(self) -> float:
        """Mean wind at 20 ft (6.1 m) at t = 0 [m/s], from the profile (MIL-HDBK-1797's W20)."""
        return abs(self.initial_speed() * float(self.profile.factor(W20_HEIGHT)))

    def realize(self, hull_height: float, duration: float, x_ref: float = 0.0) -> WindField:
        """Fix the convection speed U_c (mean wind at ``hull_height`` [m] at t = 0) and the
        reference x_ref [m] (the hull's initial x) and synthesise the turbulence for a run of
        ``duration`` [s]."""
        uc = self.initial_speed() * float(self.profile.factor(hull_height))
        if self.gust is not None and abs(uc) < MIN_CONVECTION_SPEED:
            raise ValueError(
                f"a gust needs a mean wind of at least {MIN_CONVECTION_SPEED} m/s at the hull to "
                f"convect it (got {uc:.3g} m/s at t = 0)"
            )
        rec = None
        if self.turbulence is not None:
            rec = self.turbulence.realize(hull_height, abs(uc), duration, w20=self.w20(),
                                          x_ref=x_ref)
        return WindField(self, abs(uc), hull_height, rec, float(x_ref))

    realise = deprecated_method("realise", "realize")


@dataclass(frozen=True, eq=False)
class WindField:
    """A realised wind (scenario + convection speed + turbulence field), ready to evaluate.

    Attributes: scenario; convection_speed U_c [m/s]; hull_height [m]; turbulence
    (TurbulenceField or None); x_ref [m] (where the convected inputs have their nominal timing).
    """

    scenario: WindScenario
    convection_speed: float
    hull_height: float
    turbulence: TurbulenceField | None
    x_ref: float = 0.0

    def pack(self):
        """Arrays for the numba kernels: (wpar, sched, turb), built once per field (the
        turbulence table takes tens of ms); the kernels only read them."""
        cached = self.__dict__.get("_packed")
        if cached is None:
            cached = self._pack()
            self.__dict__["_packed"] = cached  # frozen dataclass: a cache, not state
        return cached

    def _pack(self):
        sc = self.scenario
        wpar = sc.profile.kernel_parameters()
        wpar[W_RAMP] = RAMP_CODE[sc.schedule.shape]
        wpar[W_UC] = max(self.convection_speed, MIN_CONVECTION_SPEED)
        wpar[W_XREF] = self.x_ref
        g = sc.gust
        if g is not None:
            wpar[W_GUST_ON] = 1.0
            wpar[W_GUST_T0] = g.start_time
            wpar[W_GUST_T] = g.rise_time(self.convection_speed)
            wpar[W_GUST_U] = g.amplitude_u
            wpar[W_GUST_W] = g.amplitude_w
            wpar[W_GUST_SHAPE] = GUST_CODE[g.shape]
            wpar[W_GUST_CONV] = 1.0 if g.convected else 0.0
        r = self.turbulence
        if r is not None:
            wpar[W_TURB_ON] = 1.0
            wpar[W_FADE] = r.fade_in
            dt, tab = r.table()
            wpar[W_TURB_DT] = dt
            wpar[W_TURB_Z0] = r.z_levels[0]
            wpar[W_TURB_DZ] = (r.z_levels[1] - r.z_levels[0]) if r.z_levels.size > 1 else 1.0
            wpar[W_TURB_NL] = r.z_levels.size
            turb = np.ascontiguousarray(tab)
        else:
            turb = np.zeros((4, 2))
        return wpar, np.ascontiguousarray(sc.schedule.kernel_array()), turb

    def breakpoints(self) -> np.ndarray:
        """Times [s] where an input's slope jumps at the hull (ramp corners, gust start/end)."""
        pts = list(self.scenario.schedule.breakpoints())
        g = self.scenario.gust
        if g is not None:
            pts += [g.start_time, g.start_time + g.duration(self.convection_speed)]
            if g.shape == "full":
                pts.append(g.start_time + g.rise_time(self.convection_speed))
        return np.unique(np.array(pts, float))

    def at(self, t, z, x=None):
        """Wind at times ``t`` [s], heights ``z`` [m] and downwind positions ``x`` [m] (default
        x_ref; broadcast): U_x, U_z [m/s], the local time derivatives dU_x/dt, dU_z/dt [m/s2]
        and the fluid accelerations DU_x/Dt, DU_z/Dt [m/s2] (module docstring)."""
        t = np.atleast_1d(np.asarray(t, float))
        x = self.x_ref if x is None else x
        t, z, x = np.broadcast_arrays(t, np.asarray(z, float), np.asarray(x, float))
        wpar, sched, turb = self.pack()
        out = np.empty((t.size, NW))
        wind_points(t.ravel().copy(), x.ravel().copy(), z.ravel().copy(), wpar, sched, turb, out)
        return tuple(out[:, k].reshape(t.shape) for k in range(NW))


@njit(cache=True)
def wind_time_terms(t, wpar, sched, out):  # pragma: no cover - numba
    """Time-only parts of the wind at time t [s], written to ``out`` (length ``NT``):
    [U_ref, dU_ref/dt, fade f(t), df/dt] in m/s, m/s2, -, 1/s."""
    u, du = _schedule(t, sched, int(wpar[W_RAMP]))
    out[0] = u
    out[1] = du
    f = 1.0
    df = 0.0
    tf = wpar[W_FADE]
    if wpar[W_TURB_ON] > 0.0 and tf > 0.0 and t < tf:
        if t <= 0.0:
            f = 0.0
        else:
            f = 0.5 * (1.0 - math.cos(math.pi * t / tf))
            df = 0.5 * math.pi / tf * math.sin(math.pi * t / tf)
    out[2] = f
    out[3] = df


@njit(cache=True)
def frozen_weights(tau, z, wpar, n):  # pragma: no cover - numba
    """Where the frozen turbulence table is read at frozen time tau [s] and height z [m]: the
    columns k0, k1 (periodic, ``n`` of them) and the cubic Hermite weights in tau of the values
    (h00, h10, h01, h11) and of the tau-derivatives (d00, d10, d01, d11), then the lower height
    level la and the fraction fz towards the next one (linear in z, clamped at the ends).
    :func:`turbulence_at` (u', w') and the 6-DOF lateral component v' read the table with it."""
    h = wpar[W_TURB_DT]
    sx = tau / h
    fl = math.floor(sx)
    f = sx - fl
    k0 = int(fl) % n
    k1 = k0 + 1
    if k1 == n:
        k1 = 0
    f2 = f * f
    f3 = f2 * f
    h00 = 2.0 * f3 - 3.0 * f2 + 1.0
    h10 = (f3 - 2.0 * f2 + f) * h
    h01 = -2.0 * f3 + 3.0 * f2
    h11 = (f3 - f2) * h
    d00 = (6.0 * f2 - 6.0 * f) / h
    d10 = 3.0 * f2 - 4.0 * f + 1.0
    d01 = -d00
    d11 = 3.0 * f2 - 2.0 * f
    nl = int(wpar[W_TURB_NL])
    sz = (z - wpar[W_TURB_Z0]) / wpar[W_TURB_DZ]
    if nl == 1 or sz <= 0.0:
        la, fz = 0, 0.0
    elif sz >= nl - 1:
        la, fz = nl - 1, 0.0
    else:
        la = int(sz)
        fz = sz - la
    return k0, k1, h00, h10, h01, h11, d00, d10, d01, d11, la, fz


@njit(cache=True)
def hermite(turb, r, k0, k1, w00, w10, w01, w11):  # pragma: no cover - numba
    """One cubic Hermite read of the table row pair (value row r, slope row r + 1) between
    columns k0 and k1 with the weights of :func:`frozen_weights`."""
    return w00 * turb[r, k0] + w10 * turb[r + 1, k0] + w01 * turb[r, k1] + w11 * turb[r + 1, k1]


@njit(cache=True)
def turbulence_at(tau, z, wpar, turb):  # pragma: no cover - numba
    """u', w' [m/s] and their tau-derivatives [m/s2] of the frozen field at frozen time tau [s]
    and height z [m] (cubic Hermite in tau, linear between height levels; unfaded)."""
    k0, k1, h00, h10, h01, h11, d00, d10, d01, d11, la, fz = frozen_weights(
        tau, z, wpar, turb.shape[1])
    r = 4 * la
    u = hermite(turb, r, k0, k1, h00, h10, h01, h11)
    du = hermite(turb, r, k0, k1, d00, d10, d01, d11)
    w = hermite(turb, r + 2, k0, k1, h00, h10, h01, h11)
    dw = hermite(turb, r + 2, k0, k1, d00, d10, d01, d11)
    if fz > 0.0:
        r += 4
        u2 = hermite(turb, r, k0, k1, h00, h10, h01, h11)
        du2 = hermite(turb, r, k0, k1, d00, d10, d01, d11)
        w2 = hermite(turb, r + 2, k0, k1, h00, h10, h01, h11)
        dw2 = hermite(turb, r + 2, k0, k1, d00, d10, d01, d11)
        u += fz * (u2 - u)
        du += fz * (du2 - du)
        w += fz * (w2 - w)
        dw += fz * (dw2 - dw)
    return u, w, du, dw


@njit(cache=True, inline="always")
def wind_point(t, x, z, wpar, wt, turb):  # pragma: no cover - numba
    """Wind at (x, z) [m] and time t [s] (module docstring): the tuple (U_x, U_z [m/s],
    dU_x/dt, dU_z/dt (local) [m/s2], DU_x/Dt, DU_z/Dt (fluid acceleration) [m/s2]).
    ``wt``: :func:`wind_time_terms` at t."""
    pf = profile_factor(z, wpar)
    ux = wt[0] * pf
    dux = wt[1] * pf
    uz = 0.0
    duz = 0.0
    ax = dux
    az = 0.0
    if wpar[W_GUST_ON] > 0.0:
        conv = wpar[W_GUST_CONV] > 0.0
        tau = t - (x - wpar[W_XREF]) / wpar[W_UC] if conv else t
        g, dg = _gust(tau, wpar[W_GUST_T0], wpar[W_GUST_T], int(wpar[W_GUST_SHAPE]))
        ux += wpar[W_GUST_U] * g
        uz += wpar[W_GUST_W] * g
        dux += wpar[W_GUST_U] * dg
        duz += wpar[W_GUST_W] * dg
        if not conv:
            ax += wpar[W_GUST_U] * dg
            az += wpar[W_GUST_W] * dg
    if wpar[W_TURB_ON] > 0.0:
        u, w, du, dw = turbulence_at(t - (x - wpar[W_XREF]) / wpar[W_UC], z, wpar, turb)
        fd = wt[2]
        dfd = wt[3]
        ux += fd * u
        uz += fd * w
        dux += fd * du + dfd * u
        duz += fd * dw + dfd * w
        ax += dfd * u  # frozen field: only the fade-in's own slope accelerates the air
        az += dfd * w
    return ux, uz, dux, duz, ax, az


@njit(cache=True)
def wind_points(ts, xs, zs, wpar, sched, turb, out):  # pragma: no cover - numba
    """:func:`wind_point` at many (t, x, z) (rows of ``out``)."""
    wt = np.empty(NT)
    for i in range(ts.size):
        wind_time_terms(ts[i], wpar, sched, wt)
        res = wind_point(ts[i], xs[i], zs[i], wpar, wt, turb)
        for k in range(NW):
            out[i, k] = res[k]
