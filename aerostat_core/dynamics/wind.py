"""Wind inputs of the dynamic model: mean profile, speed schedules, 1-cosine gusts, Dryden turbulence.

The wind seen by a point at height z at time t is (docs/dynamics.md §2)

    U_x(z, t) = U_ref(t) P(z) + g_u(t) + u'(t),        U_z(t) = g_w(t) + w'(t)

* ``P(z)``: mean profile shape (uniform, power law, log law), 1 at the reference height.
* ``U_ref(t)``: a schedule of ramps between constant speeds ("varying wind", thesis Fig. 3.24).
* ``g_u, g_w``: a MIL-F-8785C "1 - cosine" discrete gust (thesis Fig. 3.25), longitudinal and/or
  vertical, applied uniformly in space (the usual choice).
* ``u', w'``: Dryden turbulence (MIL-F-8785C low-altitude model in the 8785C length convention,
  thesis Fig. 3.26), convected by the mean wind at the hull (Taylor's frozen turbulence) and fully
  correlated along the tether (docs/dynamics.md §2.4: the simple default).

Every input is a smooth function of time with a consistent time derivative (the derivative feeds
the unsteady-wind inertia terms), so implicit integrators meet no piecewise-constant data
(docs/dynamics.md §1.8). Turbulence is a sum of cosines (spectral synthesis) whose amplitudes are the
integrals of the Dryden spectra over each frequency bin, with seeded random phases; the kernel
reads it from an exact periodic table by C1 cubic-Hermite interpolation (:meth:`TurbulenceRecord.table`).

Everything here is plain numpy except :func:`wind_time_terms` and :func:`profile_factor`, the two
numba kernels the integrator calls; :meth:`WindField.pack` turns a realised wind into their arrays.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numba import njit

#: One knot [m/s] (international knot, 1852 m/h).
KNOT = 1852.0 / 3600.0
#: One foot [m].
FOOT = 0.3048

PROFILE_KINDS = ("uniform", "power", "log")
RAMP_SHAPES = ("linear", "cosine")
GUST_SHAPES = ("full", "ramp-hold")
#: MIL-F-8785C low-altitude wind speed at 20 ft, W20, per intensity [m/s] (15, 30, 45 kt).
DRYDEN_W20 = {"light": 15.0 * KNOT, "moderate": 30.0 * KNOT, "severe": 45.0 * KNOT}
#: Height band of the low-altitude Dryden formulas [m] (10 ft to 1000 ft); heights outside are
#: clamped to it (docs/dynamics.md §2.4: "or clamp at 1000 ft and say so").
DRYDEN_HEIGHT_RANGE = (10.0 * FOOT, 1000.0 * FOOT)
#: Smallest mean wind at the hull that can convect gusts and turbulence [m/s].
MIN_CONVECTION_SPEED = 0.5

# codes shared with the numba kernels
_PROFILE_CODE = {"uniform": 0, "power": 1, "log": 2}
_RAMP_CODE = {"linear": 0, "cosine": 1}
_GUST_CODE = {"full": 0, "ramp-hold": 1}
# layout of the wind parameter vector ``wpar``
W_PROFILE, W_ZREF, W_EXPONENT, W_Z0, W_ZMIN = 0, 1, 2, 3, 4
W_RAMP, W_GUST_ON, W_GUST_T0, W_GUST_T, W_GUST_U, W_GUST_W, W_GUST_SHAPE = 5, 6, 7, 8, 9, 10, 11
W_TURB_ON, W_FADE, W_TURB_DT = 12, 13, 14
W_SIZE = 15
#: number of time terms returned by :func:`wind_time_terms`
NT = 6


def _check(owner: str, name: str, value, lo: float, hi: float, unit: str = "") -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{owner}.{name} = {value!r} is not a number; valid range [{lo:g}, {hi:g}] "
                         f"{unit}".rstrip()) from None
    if not math.isfinite(v) or v < lo or v > hi:
        raise ValueError(f"{owner}.{name} = {value!r} is outside the valid range [{lo:g}, {hi:g}] "
                         f"{unit}".rstrip())
    return v


# --------------------------------------------------------------------------------------------
# Mean profile
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class MeanProfile:
    """Shape of the mean wind versus height, P(z), equal to 1 at ``reference_height``.

    uniform: P = 1;  power law: P = (z/z_ref)^p;  log law: P = ln(z/z0)/ln(z_ref/z0),
    with z clipped to >= 1 m (and >= 2 z0 in the log law), as in :mod:`aerostat_core.wind`.

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

    kind: str = "uniform"
    reference_height: float = 10.0
    exponent: float = 1.0 / 7.0
    roughness_length: float = 0.03

    def __post_init__(self) -> None:
        if self.kind not in PROFILE_KINDS:
            raise ValueError(f"MeanProfile.kind = {self.kind!r}; valid options {PROFILE_KINDS}")
        _check("MeanProfile", "reference_height", self.reference_height, 1.0, 5000.0, "m")
        _check("MeanProfile", "exponent", self.exponent, 0.0, 0.6)
        _check("MeanProfile", "roughness_length", self.roughness_length, 1e-5, 2.0, "m")

    def factor(self, z):
        """P(z) [-] at heights ``z`` [m] (broadcasts)."""
        z = np.asarray(z, float)
        out = np.empty(z.shape)
        wpar = self._wpar()
        flat = out.reshape(-1)
        for i, zi in enumerate(z.reshape(-1)):
            flat[i] = profile_factor(float(zi), wpar)
        return out if out.ndim else out[()]

    def _wpar(self) -> np.ndarray:
        w = np.zeros(W_SIZE)
        w[W_PROFILE] = _PROFILE_CODE[self.kind]
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
        arr = self._array()
        code = _RAMP_CODE[self.shape]
        u = np.empty(t.shape)
        du = np.empty(t.shape)
        for i, ti in enumerate(t):
            u[i], du[i] = _schedule(ti, arr, code)
        return u, du

    def breakpoints(self) -> tuple:
        """Times [s] where the speed's slope jumps (the integrator steps onto them)."""
        return self.times

    def _array(self) -> np.ndarray:
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
    vertical (A_w, up positive) wind, uniformly in space.

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

    Notes
    -----
    Source: MIL-F-8785C §3.7.4 (discrete gust); MathWorks "Discrete Wind Gust Model" (docs/dynamics.md
    §2.3). The convection speed U_c is the mean wind at the hull at t = 0.
    """

    amplitude_u: float = 5.0
    amplitude_w: float = 0.0
    length: float = 60.0
    start_time: float = 20.0
    shape: str = "full"

    def __post_init__(self) -> None:
        _check("Gust", "amplitude_u", self.amplitude_u, -30.0, 30.0, "m/s")
        _check("Gust", "amplitude_w", self.amplitude_w, -30.0, 30.0, "m/s")
        _check("Gust", "length", self.length, 1.0, 5000.0, "m")
        _check("Gust", "start_time", self.start_time, 0.0, 1e5, "s")
        if self.shape not in GUST_SHAPES:
            raise ValueError(f"Gust.shape = {self.shape!r}; valid options {GUST_SHAPES}")

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
# Dryden turbulence
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class DrydenParameters:
    """Dryden scales and intensities at one height (8785C convention).

    length_u, length_w [m]; sigma_u, sigma_w [m/s]; height_used [m] (after clamping to the
    low-altitude band) and ``clamped`` (True when the height was outside it)."""

    length_u: float
    length_w: float
    sigma_u: float
    sigma_w: float
    height_used: float
    clamped: bool


def dryden_parameters(height: float, w20: float) -> DrydenParameters:
    """MIL-F-8785C low-altitude Dryden scale lengths and intensities (8785C convention).

    With h in feet: L_w = h, L_u = L_v = h/(0.177 + 0.000823 h)^1.2;
    sigma_w = 0.1 W20, sigma_u = sigma_v = sigma_w/(0.177 + 0.000823 h)^0.4.

    Parameters
    ----------
    height : float
        Height above ground [m]; clamped to the formulas' band 10-1000 ft (3.05-304.8 m). Above
        1000 ft the standard blends towards medium-altitude values; that blend needs the
        exceedance table and is not implemented: the 1000 ft values are used (flagged).
    w20 : float
        Wind speed at 20 ft [m/s], valid [0, 60]: light 15 kt, moderate 30 kt, severe 45 kt.

    Returns
    -------
    DrydenParameters

    Notes
    -----
    Source: MIL-F-8785C §3.7.2 (low altitude), cross-checked in docs/dynamics.md §2.4 (D9, D10). Do not
    mix with MIL-HDBK-1797's halved v/w lengths (2 L_w = h).

    Examples
    --------
    >>> p = dryden_parameters(300.0, DRYDEN_W20["moderate"])
    >>> round(p.length_u, 1), round(p.length_w, 1), round(p.sigma_u, 3), round(p.sigma_w, 3)
    (304.7, 300.0, 1.551, 1.543)
    """
    _check("dryden_parameters", "height", height, -1e3, 2e4, "m")
    _check("dryden_parameters", "w20", w20, 0.0, 60.0, "m/s")
    lo, hi = DRYDEN_HEIGHT_RANGE
    h = min(max(float(height), lo), hi)
    hf = h / FOOT
    k = 0.177 + 0.000823 * hf
    lu = hf / k**1.2 * FOOT
    lw = hf * FOOT
    sw = 0.1 * w20
    su = sw / k**0.4
    clamped = not (lo - 1e-9 <= height <= hi + 1e-9)
    return DrydenParameters(lu, lw, su, sw, h, clamped)


def dryden_psd_u(omega, sigma, length, speed):
    """One-sided Dryden longitudinal PSD in temporal frequency [m2/s2 per rad/s].

    Phi_u(omega) = sigma^2 (2 L/(pi V)) / (1 + (L omega/V)^2); integrates to sigma^2 over [0, inf).

    Parameters
    ----------
    omega : array_like
        Angular frequency [rad/s].
    sigma : float
        Intensity [m/s].
    length : float
        Scale length L_u [m].
    speed : float
        Convection speed V [m/s] (> 0).
    """
    x = length * np.asarray(omega, float) / speed
    return sigma**2 * 2.0 * length / (np.pi * speed) / (1.0 + x**2)


def dryden_psd_w(omega, sigma, length, speed):
    """One-sided Dryden vertical PSD [m2/s2 per rad/s].

    Phi_w(omega) = sigma^2 (L/(pi V)) (1 + 3 (L omega/V)^2)/(1 + (L omega/V)^2)^2; integrates to
    sigma^2. Arguments as :func:`dryden_psd_u` (L = L_w).
    """
    x = length * np.asarray(omega, float) / speed
    return sigma**2 * length / (np.pi * speed) * (1.0 + 3.0 * x**2) / (1.0 + x**2) ** 2


def _cum_u(omega, sigma, length, speed):
    """Integral of Phi_u from 0 to omega: sigma^2 (2/pi) atan(L omega/V)."""
    return sigma**2 * 2.0 / np.pi * np.arctan(length * np.asarray(omega, float) / speed)


def _cum_w(omega, sigma, length, speed):
    """Integral of Phi_w from 0 to omega: (sigma^2/pi)(2 atan x - x/(1 + x^2)), x = L omega/V."""
    x = length * np.asarray(omega, float) / speed
    return sigma**2 / np.pi * (2.0 * np.arctan(x) - x / (1.0 + x**2))


@dataclass(frozen=True)
class DrydenTurbulence:
    """Dryden turbulence settings (longitudinal u and vertical w; MIL-F-8785C low altitude).

    Parameters
    ----------
    w20 : float
        Wind at 20 ft [m/s], valid [0, 60]. Light 7.7, moderate 15.4, severe 23.2 m/s.
    seed : int
        Random-phase seed, valid [0, 2**32 - 1]; the same seed gives the same record.
    sigma_u, sigma_w : float or None
        Override the intensities [m/s], valid [0, 20] (``None``: from W20 and the hull height).
    max_frequency : float
        Highest synthesised frequency [Hz], valid [0.05, 10]. Above ~1 Hz the hull does not
        respond (its fastest rigid mode has a period of a few seconds).
    fade_in : float
        Turbulence is faded in over this time with a (1 - cos) window [s], valid [0, 600], so that
        the run starts from the steady equilibrium without a jump. Statistics should skip it.
    vertical : bool
        Include the vertical component w'.

    Notes
    -----
    Realised by :meth:`realise` as a sum of cosines on the frequency grid k 2 pi/T (T = record
    length >= the simulated time), amplitude a_k = sqrt(2 int_bin Phi d omega) with the bin
    integrals in closed form, phases uniform in [0, 2 pi) from ``numpy.random.default_rng(seed)``.
    Over one period the sample variance equals the sum of a_k^2/2 exactly: the target sigma^2 less
    the spectrum beyond ``max_frequency`` (reported as ``variance_fraction``).

    Examples
    --------
    >>> DrydenTurbulence.from_intensity("moderate").w20 == DRYDEN_W20["moderate"]
    True
    """

    w20: float = DRYDEN_W20["moderate"]
    seed: int = 1
    sigma_u: float | None = None
    sigma_w: float | None = None
    max_frequency: float = 1.0
    fade_in: float = 20.0
    vertical: bool = True

    def __post_init__(self) -> None:
        _check("DrydenTurbulence", "w20", self.w20, 0.0, 60.0, "m/s")
        s = _check("DrydenTurbulence", "seed", self.seed, 0, 2**32 - 1)
        if s != int(s):
            raise ValueError(f"DrydenTurbulence.seed = {self.seed!r} must be an integer")
        object.__setattr__(self, "seed", int(s))
        for name in ("sigma_u", "sigma_w"):
            if getattr(self, name) is not None:
                _check("DrydenTurbulence", name, getattr(self, name), 0.0, 20.0, "m/s")
        _check("DrydenTurbulence", "max_frequency", self.max_frequency, 0.05, 10.0, "Hz")
        _check("DrydenTurbulence", "fade_in", self.fade_in, 0.0, 600.0, "s")

    @classmethod
    def from_intensity(cls, intensity: str, **kw) -> DrydenTurbulence:
        """Settings for "light", "moderate" or "severe" low-altitude turbulence."""
        if intensity not in DRYDEN_W20:
            raise ValueError(f"intensity = {intensity!r}; valid options {tuple(DRYDEN_W20)}")
        return cls(w20=DRYDEN_W20[intensity], **kw)

    def parameters(self, height: float) -> DrydenParameters:
        """Scales and intensities at ``height`` [m], with the sigma overrides applied."""
        p = dryden_parameters(height, self.w20)
        su = p.sigma_u if self.sigma_u is None else float(self.sigma_u)
        sw = p.sigma_w if self.sigma_w is None else float(self.sigma_w)
        return DrydenParameters(p.length_u, p.length_w, su, sw, p.height_used, p.clamped)

    def realise(self, height: float, speed: float, duration: float) -> TurbulenceRecord:
        """Synthesise a record for a hull at ``height`` [m] in mean wind ``speed`` [m/s].

        ``duration`` [s] sets the record period T = max(duration, 60 s); frequencies k 2 pi/T,
        k = 1..K up to ``max_frequency``.
        """
        if speed < MIN_CONVECTION_SPEED:
            raise ValueError(
                f"turbulence needs a mean wind of at least {MIN_CONVECTION_SPEED} m/s at the hull to "
                f"convect it (got {speed:.3g} m/s)"
            )
        p = self.parameters(height)
        period = max(float(duration), 60.0)
        dw = 2.0 * np.pi / period
        k_max = max(int(np.floor(2.0 * np.pi * self.max_frequency / dw)), 1)
        if k_max > 200_000:
            raise ValueError(f"turbulence record needs {k_max} frequencies (duration x "
                             "max_frequency too large); the limit is 200000")
        k = np.arange(1, k_max + 1)
        omega = k * dw
        edges = np.concatenate([[0.0], (k + 0.5) * dw])  # first bin from 0 takes the lowest part
        var_u = np.diff(_cum_u(edges, p.sigma_u, p.length_u, speed))
        var_w = np.diff(_cum_w(edges, p.sigma_w, p.length_w, speed))
        if not self.vertical:
            var_w = np.zeros_like(var_w)
        rng = np.random.default_rng(self.seed)
        ph_u = rng.uniform(0.0, 2.0 * np.pi, k_max)
        ph_w = rng.uniform(0.0, 2.0 * np.pi, k_max)
        return TurbulenceRecord(
            omega=omega, amp_u=np.sqrt(2.0 * var_u), phase_u=ph_u, amp_w=np.sqrt(2.0 * var_w),
            phase_w=ph_w, period=period, speed=float(speed), params=p, fade_in=self.fade_in,
            seed=self.seed,
        )


@dataclass(frozen=True, eq=False)
class TurbulenceRecord:
    """A realised turbulence record u'(t) = sum a_k cos(omega_k t + phi_k) (same for w').

    omega [rad/s], amp_u, amp_w [m/s], phase_u, phase_w [rad]; period [s]; speed (convection) [m/s];
    params (DrydenParameters); fade_in [s]; seed.
    """

    omega: np.ndarray
    amp_u: np.ndarray
    phase_u: np.ndarray
    amp_w: np.ndarray
    phase_w: np.ndarray
    period: float
    speed: float
    params: DrydenParameters
    fade_in: float
    seed: int

    @property
    def variance_fraction(self) -> tuple[float, float]:
        """Synthesised variance / target sigma^2, for u and w (< 1 by the cut-off tail)."""
        p = self.params
        fu = np.sum(self.amp_u**2) / 2 / p.sigma_u**2 if p.sigma_u > 0 else 1.0
        fw = np.sum(self.amp_w**2) / 2 / p.sigma_w**2 if p.sigma_w > 0 else 1.0
        return float(fu), float(fw)

    def evaluate(self, t, faded: bool = True):
        """u'(t), w'(t) [m/s] and their time derivatives [m/s2] at times ``t`` [s] (numpy).

        ``faded`` applies the fade-in window (as the simulation does)."""
        t = np.atleast_1d(np.asarray(t, float))
        out = np.empty((4, t.size))
        for i0 in range(0, t.size, 2048):
            tt = t[i0:i0 + 2048, None]
            au = self.omega * tt + self.phase_u
            aw = self.omega * tt + self.phase_w
            out[0, i0:i0 + 2048] = np.cos(au) @ self.amp_u
            out[1, i0:i0 + 2048] = -np.sin(au) @ (self.amp_u * self.omega)
            out[2, i0:i0 + 2048] = np.cos(aw) @ self.amp_w
            out[3, i0:i0 + 2048] = -np.sin(aw) @ (self.amp_w * self.omega)
        if faded and self.fade_in > 0:
            f, df = _fade_np(t, self.fade_in)
            out[1] = out[1] * f + out[0] * df
            out[3] = out[3] * f + out[2] * df
            out[0] *= f
            out[2] *= f
        return out[0], out[2], out[1], out[3]

    def grid(self, n: int):
        """u', w' [m/s] on the uniform grid t_j = j T/n over one period (inverse FFT, unfaded).

        Exactly the cosine sum at those times; ``n`` must exceed 2 K."""
        k = self.omega.size
        if n <= 2 * k:
            raise ValueError(f"grid needs n > {2 * k} points, got {n}")
        cu = np.zeros(n // 2 + 1, complex)
        cw = np.zeros(n // 2 + 1, complex)
        cu[1:k + 1] = 0.5 * self.amp_u * np.exp(1j * self.phase_u) * n
        cw[1:k + 1] = 0.5 * self.amp_w * np.exp(1j * self.phase_w) * n
        t = np.arange(n) * self.period / n
        return t, np.fft.irfft(cu, n), np.fft.irfft(cw, n)


    def table(self, max_step: float = 0.02):
        """u', du'/dt, w', dw'/dt on a uniform grid over one period (exact, by inverse FFT).

        Returns (dt [s], array (4, n)). The kernel interpolates it with cubic Hermite polynomials
        (C1, error ~ (omega dt)^4/384 ~ 1e-6 at 1 Hz and dt = 0.02 s) instead of summing K cosines
        at every call; the time derivative is the Hermite polynomial's own derivative, so the
        acceleration fed to the unsteady-wind terms is exactly d/dt of the velocity used.
        """
        k = self.omega.size
        n = max(int(np.ceil(self.period / max_step)), 2 * k + 2)
        n += n % 2
        dt = self.period / n
        out = np.empty((4, n))
        for row, amp, ph in ((0, self.amp_u, self.phase_u), (2, self.amp_w, self.phase_w)):
            c = np.zeros(n // 2 + 1, complex)
            c[1:k + 1] = 0.5 * amp * np.exp(1j * ph) * n
            out[row] = np.fft.irfft(c, n)
            dc = np.zeros(n // 2 + 1, complex)
            dc[1:k + 1] = 1j * self.omega * c[1:k + 1]
            out[row + 1] = np.fft.irfft(dc, n)
        return dt, out


def _fade_np(t, tf):
    t = np.asarray(t, float)
    s = np.clip(t / tf, 0.0, 1.0)
    f = 0.5 * (1.0 - np.cos(np.pi * s))
    df = np.where((t > 0) & (t < tf), 0.5 * np.pi / tf * np.sin(np.pi * s), 0.0)
    return f, df


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

    def realise(self, hull_height: float, duration: float) -> WindField:
        """Fix the convection speed (mean wind at ``hull_height`` [m] at t = 0) and synthesise the
        turbulence for a run of ``duration`` [s]."""
        uc = self.initial_speed() * float(self.profile.factor(hull_height))
        if self.gust is not None and abs(uc) < MIN_CONVECTION_SPEED:
            raise ValueError(
                f"a gust needs a mean wind of at least {MIN_CONVECTION_SPEED} m/s at the hull to "
                f"convect it (got {uc:.3g} m/s at t = 0)"
            )
        rec = None
        if self.turbulence is not None:
            rec = self.turbulence.realise(hull_height, abs(uc), duration)
        return WindField(self, abs(uc), hull_height, rec)


@dataclass(frozen=True, eq=False)
class WindField:
    """A realised wind (scenario + convection speed + turbulence record), ready to evaluate.

    Attributes: scenario; convection_speed [m/s]; hull_height [m] used for the Dryden scales;
    turbulence (TurbulenceRecord or None).
    """

    scenario: WindScenario
    convection_speed: float
    hull_height: float
    turbulence: TurbulenceRecord | None

    def pack(self):
        """Arrays for the numba kernels: (wpar, sched, turb)."""
        sc = self.scenario
        wpar = sc.profile._wpar()
        wpar[W_RAMP] = _RAMP_CODE[sc.schedule.shape]
        g = sc.gust
        if g is not None:
            wpar[W_GUST_ON] = 1.0
            wpar[W_GUST_T0] = g.start_time
            wpar[W_GUST_T] = g.rise_time(self.convection_speed)
            wpar[W_GUST_U] = g.amplitude_u
            wpar[W_GUST_W] = g.amplitude_w
            wpar[W_GUST_SHAPE] = _GUST_CODE[g.shape]
        r = self.turbulence
        if r is not None:
            wpar[W_TURB_ON] = 1.0
            wpar[W_FADE] = r.fade_in
            dt, tab = r.table()
            wpar[W_TURB_DT] = dt
            turb = np.ascontiguousarray(tab)
        else:
            turb = np.zeros((4, 2))
        return wpar, np.ascontiguousarray(sc.schedule._array()), turb

    def breakpoints(self) -> np.ndarray:
        """Times [s] where an input's slope jumps (ramp corners, gust start and end)."""
        pts = list(self.scenario.schedule.breakpoints())
        g = self.scenario.gust
        if g is not None:
            pts += [g.start_time, g.start_time + g.duration(self.convection_speed)]
            if g.shape == "full":
                pts.append(g.start_time + g.rise_time(self.convection_speed))
        return np.unique(np.array(pts, float))

    def at(self, t, z):
        """Wind at times ``t`` [s] and height(s) ``z`` [m] (broadcast): U_x, U_z [m/s] and their
        time derivatives [m/s2]."""
        t = np.atleast_1d(np.asarray(t, float))
        z = np.broadcast_to(np.asarray(z, float), t.shape)
        wpar, sched, turb = self.pack()
        terms = np.empty((t.size, NT))
        buf = np.empty(NT)
        for i, ti in enumerate(t):
            wind_time_terms(ti, wpar, sched, turb, buf)
            terms[i] = buf
        p = self.scenario.profile.factor(z)
        ux = terms[:, 0] * p + terms[:, 2]
        dux = terms[:, 1] * p + terms[:, 3]
        return ux, terms[:, 4], dux, terms[:, 5]


@njit(cache=True)
def wind_time_terms(t, wpar, sched, turb, out):  # pragma: no cover - numba
    """Time-only parts of the wind at time t [s], written to ``out`` (length ``NT``):

    out = [U_ref, dU_ref/dt, u_extra, du_extra/dt, U_z, dU_z/dt] with
    U_x(z, t) = U_ref P(z) + u_extra (gust + turbulence) and U_z = vertical gust + turbulence.
    Units m/s and m/s2.
    """
    u, du = _schedule(t, sched, int(wpar[W_RAMP]))
    out[0] = u
    out[1] = du
    ux = 0.0
    dux = 0.0
    uz = 0.0
    duz = 0.0
    if wpar[W_GUST_ON] > 0.0:
        g, dg = _gust(t, wpar[W_GUST_T0], wpar[W_GUST_T], int(wpar[W_GUST_SHAPE]))
        ux += wpar[W_GUST_U] * g
        dux += wpar[W_GUST_U] * dg
        uz += wpar[W_GUST_W] * g
        duz += wpar[W_GUST_W] * dg
    if wpar[W_TURB_ON] > 0.0:
        # cubic Hermite interpolation in the periodic table of the record (see TurbulenceRecord)
        n = turb.shape[1]
        h = wpar[W_TURB_DT]
        sx = t / h
        fl = math.floor(sx)
        f = sx - fl
        k0 = int(fl) % n
        k1 = (k0 + 1) % n
        f2 = f * f
        f3 = f2 * f
        h00 = 2.0 * f3 - 3.0 * f2 + 1.0
        h10 = f3 - 2.0 * f2 + f
        h01 = -2.0 * f3 + 3.0 * f2
        h11 = f3 - f2
        d00 = (6.0 * f2 - 6.0 * f) / h
        d10 = 3.0 * f2 - 4.0 * f + 1.0
        d01 = (-6.0 * f2 + 6.0 * f) / h
        d11 = 3.0 * f2 - 2.0 * f
        tu = h00 * turb[0, k0] + h10 * h * turb[1, k0] + h01 * turb[0, k1] + h11 * h * turb[1, k1]
        dtu = d00 * turb[0, k0] + d10 * turb[1, k0] + d01 * turb[0, k1] + d11 * turb[1, k1]
        tw = h00 * turb[2, k0] + h10 * h * turb[3, k0] + h01 * turb[2, k1] + h11 * h * turb[3, k1]
        dtw = d00 * turb[2, k0] + d10 * turb[3, k0] + d01 * turb[2, k1] + d11 * turb[3, k1]
        tf = wpar[W_FADE]
        if tf > 0.0 and t < tf:
            if t <= 0.0:
                f, df = 0.0, 0.0
            else:
                f = 0.5 * (1.0 - math.cos(math.pi * t / tf))
                df = 0.5 * math.pi / tf * math.sin(math.pi * t / tf)
            dtu = dtu * f + tu * df
            dtw = dtw * f + tw * df
            tu *= f
            tw *= f
        ux += tu
        dux += dtu
        uz += tw
        duz += dtw
    out[2] = ux
    out[3] = dux
    out[4] = uz
    out[5] = duz
