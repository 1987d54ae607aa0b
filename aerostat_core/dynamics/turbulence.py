"""Spatially varying low-altitude turbulence: MIL-HDBK-1797 Dryden spectra, IEC 61400-1 coherence.

The field (docs: docs/dynamics.md §2.4) is Taylor's frozen turbulence convected by the mean wind U_c at
the hull: u'(x, z, t) = F_u(t - (x - x_ref)/U_c, z), the same for w'. It varies

* along the wind (x): the frozen field passes the winch, the tether and the hull one after the
  other (the hull's nose, strips and fins each see their own value);
* with height (z): on levels z_k (one exactly at the hull's height, spacing about 10 m down to
  the winch), each with its own Dryden spectrum from the MIL-HDBK-1797 / MIL-F-8785C
  low-altitude scales and intensities at that height, partially coherent between levels by the
  IEC 61400-1 (Ed. 3, Annex B, eq. B.4) exponential coherence
  Coh(dz, f) = exp(-a sqrt((f dz/U_c)^2 + (0.12 dz/L_c)^2)), a = 12, L_c = 8.1 Lambda_1 = 340.2 m
  (Lambda_1 = 42 m above 60 m); applied to u and to w (the standard gives it for u; w is an
  assumption, stated). Between levels the kernel interpolates linearly in z.

Synthesis (Veers 1988, Sandia SAND88-0152): for each frequency omega_k = k 2 pi/T the cross-
spectral matrix S_ij = Coh_ij sqrt(S_i S_j) of the levels (bin variances from the closed-form
integrals of the spectra) is factorised S = H H^T (Cholesky, hull level first, so that the
hull's own record has exactly the target bin variances); level i's complex amplitude is
sum_j H_ij exp(i phi_jk) with seeded uniform phases. Each level's record is periodic in T; the
kernel reads it from a table of values and derivatives by C1 cubic Hermite interpolation.

Intensity: sigma_w = 0.1 W20 with W20 the wind at 20 ft (6.1 m). ``w20=None`` takes W20 from the
run's own mean profile (physically consistent with the mean wind); the named levels light /
moderate / severe (W20 = 15 / 30 / 45 kt) are MIL-HDBK-1797's exceedance levels and are
independent of the run's mean wind (so a severe level at a 10 m/s mean is 23 % intensity).

Sources: MIL-HDBK-1797 (1997) low-altitude model = MIL-F-8785C §3.7.2 (8785C length form here);
IEC 61400-1 Ed. 3 (2005) Annex B (coherence); Veers (1988) three-dimensional wind simulation.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from aerostat_core.base.deprecation import deprecated_method
from aerostat_core.base.fields import integer, number, validate

from .checks import check_number as _check

#: One knot [m/s] (international knot, 1852 m/h).
KNOT = 1852.0 / 3600.0
#: One foot [m].
FOOT = 0.3048
#: MIL-F-8785C / MIL-HDBK-1797 low-altitude wind speed at 20 ft, W20, per intensity [m/s].
DRYDEN_W20 = {"light": 15.0 * KNOT, "moderate": 30.0 * KNOT, "severe": 45.0 * KNOT}
#: Height band of the low-altitude formulas [m] (10 ft to 1000 ft); heights outside are clamped.
DRYDEN_HEIGHT_RANGE = (10.0 * FOOT, 1000.0 * FOOT)
#: Height of W20 [m] (20 ft).
W20_HEIGHT = 20.0 * FOOT
#: IEC 61400-1 Ed. 3 coherence: decay a [-] and coherence scale L_c = 8.1 x 42 m [m].
IEC_COHERENCE_DECAY = 12.0
IEC_COHERENCE_LENGTH = 8.1 * 42.0
#: Smallest mean wind at the hull that can convect gusts and turbulence [m/s].
MIN_CONVECTION_SPEED = 0.5
#: Largest turbulence table [bytes] (levels x 4 rows x samples x 8); beyond it a run is refused.
MAX_TABLE_BYTES = 256 * 2**20


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


def cumulative_psd_u(omega, sigma, length, speed):
    """Integral of Phi_u from 0 to omega: sigma^2 (2/pi) atan(L omega/V)."""
    return sigma**2 * 2.0 / np.pi * np.arctan(length * np.asarray(omega, float) / speed)


def cumulative_psd_w(omega, sigma, length, speed):
    """Integral of Phi_w from 0 to omega: (sigma^2/pi)(2 atan x - x/(1 + x^2)), x = L omega/V."""
    x = length * np.asarray(omega, float) / speed
    return sigma**2 / np.pi * (2.0 * np.arctan(x) - x / (1.0 + x**2))


def iec_coherence(
    dz, frequency, speed, decay: float = IEC_COHERENCE_DECAY, length: float = IEC_COHERENCE_LENGTH
):
    """IEC 61400-1 Ed. 3 (Annex B) coherence between two points dz [m] apart.

    Coh = exp(-a sqrt((f dz/U)^2 + (0.12 dz/L_c)^2)), f [Hz], U [m/s] the convection speed,
    a [-] (12), L_c [m] (340.2 above 60 m). 1 at dz = 0, falls with frequency and distance.
    """
    dz = np.abs(np.asarray(dz, float))
    f = np.asarray(frequency, float)
    return np.exp(-decay * np.sqrt((f * dz / speed) ** 2 + (0.12 * dz / length) ** 2))


@dataclass(frozen=True)
class DrydenTurbulence:
    """Turbulence settings: MIL-HDBK-1797 low-altitude Dryden u' and w', spatially varying.

    Parameters
    ----------
    w20 : float or None
        Wind at 20 ft [m/s], valid [0, 60] (light 7.7, moderate 15.4, severe 23.2 m/s); ``None``:
        the run's mean wind at 20 ft from its profile (intensity consistent with the mean wind).
    seed : int
        Random-phase seed, valid [0, 2**32 - 1]; the same seed gives the same field.
    sigma_u, sigma_w : float or None
        Override the intensities at the hull [m/s], valid [0, 20] (other levels scale with it).
    max_frequency : float
        Highest synthesised frequency [Hz], valid [0.05, 10].
    fade_in : float
        (1 - cos) fade-in window [s], valid [0, 600]; statistics should skip it.
    vertical : bool
        Include the vertical component w'.
    spatial : bool
        True (default): the frozen field varies along the wind and with height (module
        docstring). False: one record, the same everywhere (the old, simple model; cross-checks).
    level_spacing : float
        Spacing of the height levels [m], valid [2, 100].

    Examples
    --------
    >>> DrydenTurbulence.from_intensity("moderate").w20 == DRYDEN_W20["moderate"]
    True
    """

    w20: float | None = number(
        DRYDEN_W20["moderate"], "W20 (wind at 20 ft)", "m/s", 0.0, 60.0,
        empty="the mean wind profile", source="MIL-HDBK-1797")
    seed: int = integer(1, "Random seed", 0, 2**32 - 1)
    sigma_u: float | None = number(
        None, "Turbulence intensity σ_u", "m/s", 0.0, 20.0, empty="Dryden")
    sigma_w: float | None = number(
        None, "Turbulence intensity σ_w", "m/s", 0.0, 20.0, empty="Dryden")
    max_frequency: float = number(1.0, "Highest turbulence frequency", "Hz", 0.05, 10.0)
    fade_in: float = number(20.0, "Turbulence fade-in", "s", 0.0, 600.0)
    vertical: bool = True
    spatial: bool = True
    level_spacing: float = number(10.0, "Height-level spacing", "m", 2.0, 100.0)

    def __post_init__(self) -> None:
        validate(self)

    @classmethod
    def from_intensity(cls, intensity: str, **kw) -> DrydenTurbulence:
        """Settings for "light", "moderate" or "severe" (MIL-HDBK-1797 W20 = 15/30/45 kt), or
        "profile" (W20 from the run's mean wind profile)."""
        if intensity == "profile":
            return cls(w20=None, **kw)
        if intensity not in DRYDEN_W20:
            raise ValueError(
                f"intensity = {intensity!r}; valid options {('profile',) + tuple(DRYDEN_W20)}"
            )
        return cls(w20=DRYDEN_W20[intensity], **kw)

    def model_name(self) -> str:
        """One line naming the model in use (for the page and the CSV header)."""
        space = (
            "frozen field convected with the mean wind (Taylor), varying along the tether "
            "and over the hull, IEC 61400-1 vertical coherence"
            if self.spatial
            else "one record, the same along the tether"
        )
        return f"MIL-HDBK-1797 low-altitude Dryden (u', w'), {space}"

    def parameters(self, height: float, w20: float | None = None) -> DrydenParameters:
        """Scales and intensities at ``height`` [m] (``w20`` [m/s] when ``self.w20`` is None)."""
        w = self.w20 if self.w20 is not None else w20
        if w is None:
            raise ValueError("DrydenTurbulence.w20 is None: give the mean wind at 20 ft")
        p = dryden_parameters(height, w)
        su = p.sigma_u if self.sigma_u is None else float(self.sigma_u)
        sw = p.sigma_w if self.sigma_w is None else float(self.sigma_w)
        return DrydenParameters(p.length_u, p.length_w, su, sw, p.height_used, p.clamped)

    def realize(
        self,
        height: float,
        speed: float,
        duration: float,
        w20: float | None = None,
        x_ref: float = 0.0,
    ) -> TurbulenceField:
        """Synthesise the field for a hull at ``height`` [m] in a mean wind ``speed`` [m/s] (the
        convection speed) for a run of ``duration`` [s]; ``w20`` [m/s] is the profile's wind at
        20 ft (used when ``self.w20`` is None); ``x_ref`` [m] is the hull's initial x.

        Record period T = max(duration, 60 s); frequencies k 2 pi/T up to ``max_frequency``.
        """
        if speed < MIN_CONVECTION_SPEED:
            raise ValueError(
                f"turbulence needs a mean wind of at least {MIN_CONVECTION_SPEED} m/s at the hull to "
                f"convect it (got {speed:.3g} m/s)"
            )
        p_hull = self.parameters(height, w20)
        period = max(float(duration), 60.0)
        dw = 2.0 * np.pi / period
        k_max = max(int(np.floor(2.0 * np.pi * self.max_frequency / dw)), 1)
        if k_max > 200_000:
            raise ValueError(
                f"turbulence needs {k_max} frequencies: duration x max_frequency is "
                "too large (the limit is 200000); shorten duration or lower "
                "max_frequency"
            )
        omega = np.arange(1, k_max + 1) * dw
        edges = np.concatenate([[0.0], (np.arange(1, k_max + 1) + 0.5) * dw])
        dz = float(self.level_spacing)
        if self.spatial:
            n_below = int(math.ceil(max(height, 0.0) / dz))
            z_levels = height + dz * np.arange(-n_below, 2)  # one level above the hull
        else:
            z_levels = np.array([height])
        hull_k = int(np.argmin(np.abs(z_levels - height)))
        n_lev = z_levels.size
        var_u = np.empty((n_lev, k_max))
        var_w = np.empty((n_lev, k_max))
        params = []
        for i, z in enumerate(z_levels):
            p = self.parameters(max(z, 0.0), w20)
            su, sw = p.sigma_u, p.sigma_w
            if self.sigma_u is not None:  # scale the override with the height profile of sigma_u
                base = dryden_parameters(max(z, 0.0), self._w(w20) or 0.0)
                ref = dryden_parameters(height, self._w(w20) or 0.0)
                su = self.sigma_u * (base.sigma_u / ref.sigma_u if ref.sigma_u > 0 else 1.0)
            params.append(
                DrydenParameters(p.length_u, p.length_w, su, sw, p.height_used, p.clamped)
            )
            var_u[i] = np.diff(cumulative_psd_u(edges, su, p.length_u, speed))
            var_w[i] = np.diff(cumulative_psd_w(edges, sw, p.length_w, speed))
        if not self.vertical:
            var_w[:] = 0.0
        rng = np.random.default_rng(self.seed)
        order = np.concatenate([[hull_k], np.delete(np.arange(n_lev), hull_k)])
        ph_u = rng.uniform(0.0, 2.0 * np.pi, (n_lev, k_max))
        ph_w = rng.uniform(0.0, 2.0 * np.pi, (n_lev, k_max))
        coef_u = _coherent_amplitudes(var_u, ph_u, z_levels, omega, speed, order)
        coef_w = _coherent_amplitudes(var_w, ph_w, z_levels, omega, speed, order)
        return TurbulenceField(
            omega=omega,
            coef_u=coef_u,
            coef_w=coef_w,
            z_levels=z_levels,
            hull_level=hull_k,
            period=period,
            speed=float(speed),
            params=p_hull,
            level_params=tuple(params),
            fade_in=self.fade_in,
            seed=self.seed,
            x_ref=float(x_ref),
            target_var_u=var_u.sum(axis=1),
            target_var_w=var_w.sum(axis=1),
            model=self.model_name(),
        )

    realise = deprecated_method("realise", "realize")

    def _w(self, w20):
        return self.w20 if self.w20 is not None else w20


def _coherent_amplitudes(var, phases, z, omega, speed, order):
    """Complex amplitudes (levels, K) of coherent records (Veers): C = H(k) exp(i phi)."""
    n_lev, k_max = var.shape
    if n_lev == 1:
        return np.sqrt(2.0 * var[0])[None, :] * np.exp(1j * phases[:1])
    zo = z[order]
    dz = zo[:, None] - zo[None, :]
    a = np.sqrt(2.0 * var[order])  # amplitude of each level's own cosine
    xi = np.exp(1j * phases[order]).T  # (K, L)
    c = np.empty((n_lev, k_max), complex)
    for k0 in range(0, k_max, 1024):  # in blocks: (K, L, L) arrays stay small
        ks = slice(k0, min(k0 + 1024, k_max))
        coh = iec_coherence(dz[None], omega[ks, None, None] / (2 * np.pi), speed)  # (k, L, L)
        ak = a[:, ks].T  # (k, L)
        cov = coh * ak[:, :, None] * ak[:, None, :] + 1e-14 * np.eye(n_lev)[None]
        h = np.linalg.cholesky(cov)
        c[:, ks] = np.einsum("kij,kj->ki", h, xi[ks]).T  # ordered levels
    out = np.empty_like(c)
    out[order] = c
    return out


@dataclass(frozen=True, eq=False)
class TurbulenceField:
    """A realised frozen turbulence field on height levels.

    Level i's record: u'_i(tau) = Re sum_k coef_u[i, k] exp(i omega_k tau) (same for w'), with
    tau = t - (x - x_ref)/speed. Attributes: omega [rad/s]; coef_u, coef_w [m/s] complex (levels,
    K); z_levels [m]; hull_level (index of the hull's level); period [s]; speed (convection)
    [m/s]; params (DrydenParameters at the hull); level_params; fade_in [s]; seed; x_ref [m];
    target_var_u, target_var_w [m2/s2] per level (the spectrum's variance up to the cut-off);
    model (name of the model, one line).
    """

    omega: np.ndarray
    coef_u: np.ndarray
    coef_w: np.ndarray
    z_levels: np.ndarray
    hull_level: int
    period: float
    speed: float
    params: DrydenParameters
    level_params: tuple
    fade_in: float
    seed: int
    x_ref: float
    target_var_u: np.ndarray
    target_var_w: np.ndarray
    model: str

    @property
    def variance_fraction(self) -> tuple[float, float]:
        """Synthesised variance at the hull / its sigma^2, for u and w (< 1 by the cut-off)."""
        p = self.params
        k = self.hull_level
        fu = np.sum(np.abs(self.coef_u[k]) ** 2) / 2 / p.sigma_u**2 if p.sigma_u > 0 else 1.0
        fw = np.sum(np.abs(self.coef_w[k]) ** 2) / 2 / p.sigma_w**2 if p.sigma_w > 0 else 1.0
        return float(fu), float(fw)

    def grid(self, n: int, level: int | None = None):
        """tau [s], u', w' [m/s] of one level (default: the hull's) on n points over one period
        (inverse FFT, unfaded; exactly the cosine sum there); n must exceed 2 K."""
        k = self.omega.size
        if n <= 2 * k:
            raise ValueError(f"grid needs n > {2 * k} points, got {n}")
        lev = self.hull_level if level is None else level
        out = []
        for coef in (self.coef_u[lev], self.coef_w[lev]):
            c = np.zeros(n // 2 + 1, complex)
            c[1 : k + 1] = 0.5 * coef * n
            out.append(np.fft.irfft(c, n))
        return np.arange(n) * self.period / n, out[0], out[1]

    def evaluate(self, t, level: int | None = None, faded: bool = True):
        """u', w' [m/s] and their time derivatives [m/s2] at the level's reference point
        (x = x_ref) at times ``t`` [s], by the cosine sums (numpy; for tests)."""
        t = np.atleast_1d(np.asarray(t, float))
        lev = self.hull_level if level is None else level
        out = np.empty((4, t.size))
        for i0 in range(0, t.size, 2048):
            e = np.exp(1j * self.omega * t[i0 : i0 + 2048, None])
            for row, coef in ((0, self.coef_u[lev]), (2, self.coef_w[lev])):
                out[row, i0 : i0 + 2048] = np.real(e @ coef)
                out[row + 1, i0 : i0 + 2048] = np.real(e @ (1j * self.omega * coef))
        if faded and self.fade_in > 0:
            f, df = fade_window(t, self.fade_in)
            out[1] = out[1] * f + out[0] * df
            out[3] = out[3] * f + out[2] * df
            out[0] *= f
            out[2] *= f
        return out[0], out[2], out[1], out[3]

    def table(self, max_step: float = 0.05) -> tuple[float, np.ndarray]:
        """Kernel table: (dt [s], array (4 L, n)) with rows u, du/dtau, w, dw/dtau per level.

        Exact at the grid points (inverse FFT); the kernel's cubic Hermite interpolation errs by
        ~(omega dt)^4/384 (3e-5 at 1 Hz, dt = 0.05 s); its derivative is the polynomial's own.
        """
        k = self.omega.size
        step = min(max_step, 0.05 / max(self.omega[-1] / (2 * np.pi), 1e-9))
        n = max(int(np.ceil(self.period / step)), 2 * k + 2)
        n += n % 2
        n_lev = self.z_levels.size
        if 4 * n_lev * n * 8 > MAX_TABLE_BYTES:
            raise ValueError(
                f"the turbulence table would take {4 * n_lev * n * 8 / 2**20:.0f} MiB (limit "
                f"{MAX_TABLE_BYTES / 2**20:.0f} MiB): shorten duration, lower max_frequency or "
                "widen level_spacing"
            )
        out = np.empty((4 * n_lev, n))
        for lev in range(n_lev):
            for row, coef in ((0, self.coef_u[lev]), (2, self.coef_w[lev])):
                c = np.zeros(n // 2 + 1, complex)
                c[1 : k + 1] = 0.5 * coef * n
                out[4 * lev + row] = np.fft.irfft(c, n)
                c[1 : k + 1] *= 1j * self.omega
                out[4 * lev + row + 1] = np.fft.irfft(c, n)
        return self.period / n, out


def fade_window(t, tf):
    """(1 - cos) fade-in f(t) = (1 - cos(pi t/tf))/2 on [0, tf], 1 after, and df/dt [1/s]."""
    t = np.asarray(t, float)
    s = np.clip(t / tf, 0.0, 1.0)
    f = 0.5 * (1.0 - np.cos(np.pi * s))
    df = np.where((t > 0) & (t < tf), 0.5 * np.pi / tf * np.sin(np.pi * s), 0.0)
    return f, df
