"""Wind inputs: profiles, schedules, gusts, and the Dryden generator (docs/dynamics.md §2, check V9)."""

import math

import numpy as np
import pytest
from scipy.signal import welch

from aerostat_core.atmosphere.wind import profile_speed
from aerostat_core.dynamics.wind import (
    DRYDEN_W20,
    FOOT,
    KNOT,
    DrydenTurbulence,
    Gust,
    MeanProfile,
    SpeedSchedule,
    WindScenario,
    dryden_parameters,
    dryden_psd_u,
    dryden_psd_w,
)
from aerostat_core.model.inputs import WindProfile


@pytest.mark.parametrize("kind", ["uniform", "power", "log"])
def test_profile_matches_static_engine(kind):
    """P(z) equals the static engine's profile with the same reference (top) height."""
    z = np.array([0.5, 1.0, 10.0, 150.0, 300.0, 450.0])
    ours = MeanProfile(kind, 300.0, 0.12, 0.05).factor(z)
    engine = profile_speed(WindProfile(kind, 0.12, 0.05), z, 1.0, 300.0)
    assert ours == pytest.approx(engine, rel=1e-12)


def test_schedule_ramps_and_derivative():
    s = SpeedSchedule.ramps(5.0, [(10.0, 10.0, 2.0), (30.0, 7.0, 4.0)], shape="cosine")
    t = np.linspace(0.0, 40.0, 4001)
    u, du = s.evaluate(t)
    assert u[t <= 10.0] == pytest.approx(5.0)
    assert u[(t >= 12.0) & (t <= 30.0)] == pytest.approx(10.0)
    assert u[-1] == pytest.approx(7.0)
    # analytic derivative = numerical derivative of the speed (smooth cosine ramps)
    num = np.gradient(u, t)
    assert np.max(np.abs(num - du)) < 0.02  # central differences across the u'' jumps at knots
    assert s.breakpoints() == (0.0, 10.0, 12.0, 30.0, 34.0)


def test_schedule_validation_names_field():
    with pytest.raises(ValueError, match=r"speeds\[1\]"):
        SpeedSchedule((0.0, 1.0), (5.0, 99.0))
    with pytest.raises(ValueError, match="ramp_time"):
        SpeedSchedule.step(5.0, 10.0, 10.0, ramp_time=0.0)
    with pytest.raises(ValueError, match="before the previous"):
        SpeedSchedule.ramps(5.0, [(10.0, 8.0, 5.0), (12.0, 6.0, 1.0)])


def test_one_minus_cosine_gust_shape():
    """g = (A/2)(1 - cos(pi x/d_m)), x = U_c (t - t0): peak A at x = d_m, back to 0 at 2 d_m."""
    sc = WindScenario(SpeedSchedule.constant(10.0), gust=Gust(4.0, 1.0, 50.0, 20.0, "full"))
    f = sc.realize(300.0, 60.0)
    t = np.array([19.0, 20.0, 22.5, 25.0, 30.0, 31.0])
    ux, uz, dux, _, ax, az = f.at(t, 300.0)
    assert ux == pytest.approx([10.0, 10.0, 12.0, 14.0, 10.0, 10.0])
    assert uz == pytest.approx([0.0, 0.0, 0.5, 1.0, 0.0, 0.0])
    assert dux[2] == pytest.approx(0.5 * 4.0 * math.pi / 5.0)
    # frozen and convected: the air carrying the gust does not accelerate (Du/Dt = 0) ...
    assert np.all(ax == 0.0) and np.all(az == 0.0)
    # ... and the gust reaches a point 50 m upwind 5 s earlier (x = U_c (t - t0))
    assert f.at(17.5, 300.0, x=-50.0)[0][0] == pytest.approx(12.0)
    # a uniform (not convected) gust accelerates the air everywhere at once: Du/Dt = dg/dt
    uni = WindScenario(SpeedSchedule.constant(10.0),
                       gust=Gust(4.0, 1.0, 50.0, 20.0, "full", convected=False)).realize(300.0, 60.0)
    ux2, _, dux2, _, ax2, _ = uni.at(t, 300.0, x=-50.0)
    assert ux2 == pytest.approx(ux) and ax2 == pytest.approx(dux2)
    hold = WindScenario(SpeedSchedule.constant(10.0), gust=Gust(4.0, 0.0, 50.0, 20.0,
                                                               "ramp-hold")).realize(300.0, 60.0)
    assert hold.at(40.0, 300.0)[0][0] == pytest.approx(14.0)


def test_gust_needs_mean_wind():
    sc = WindScenario(SpeedSchedule.constant(0.0), gust=Gust())
    with pytest.raises(ValueError, match="gust needs a mean wind"):
        sc.realize(300.0, 60.0)


def test_dryden_parameters_8785c_convention():
    """docs/dynamics.md §2.4 values: h = 100, 200, 300 m -> L_u 263/298/305 m, L_w = h, sigma ratios."""
    for h, lu, ratio in ((100.0, 263.0, 1.380), (200.0, 298.0, 1.142), (300.0, 305.0, 1.005)):
        p = dryden_parameters(h, DRYDEN_W20["moderate"])
        assert p.length_u == pytest.approx(lu, abs=1.0)
        assert p.length_w == pytest.approx(h)
        assert p.sigma_u / p.sigma_w == pytest.approx(ratio, abs=0.002)
        assert p.sigma_w == pytest.approx(0.1 * 30 * KNOT)
    high = dryden_parameters(500.0, DRYDEN_W20["light"])
    assert high.clamped and high.height_used == pytest.approx(1000 * FOOT)


def test_psd_integrates_to_variance():
    w = np.linspace(0.0, 2000.0, 2_000_001)
    for psd, length in ((dryden_psd_u, 305.0), (dryden_psd_w, 300.0)):
        val = np.trapezoid(psd(w, 1.5, length, 10.0), w)
        assert val == pytest.approx(1.5**2, rel=2e-3)  # the rest is the tail beyond 2000 rad/s


@pytest.fixture(scope="module")
def hour_record():
    turb = DrydenTurbulence.from_intensity("moderate", seed=7, max_frequency=2.0)
    rec = turb.realize(300.0, 10.0, 3600.0)
    t, u, w = rec.grid(2**16)
    return rec, t, u, w


def test_v9_sigma_over_one_hour(hour_record):
    rec, _t, u, w = hour_record
    p = rec.params
    assert np.std(u) == pytest.approx(p.sigma_u, rel=0.03)
    assert np.std(w) == pytest.approx(p.sigma_w, rel=0.03)
    fu, fw = rec.variance_fraction
    assert 0.99 < fu <= 1.0 and 0.98 < fw <= 1.0


def test_v9_spectrum_within_90pct_band(hour_record):
    """Welch PSD (16 segments, Hann, ~31 degrees of freedom) inside the chi-square 90 % band of
    the Dryden spectrum over 0.005-1 Hz (at most 10 % of the frequencies outside)."""
    from scipy.stats import chi2

    rec, t, u, w = hour_record
    fs = 1.0 / (t[1] - t[0])
    nper = t.size // 8
    for x, psd, length, sig in ((u, dryden_psd_u, rec.params.length_u, rec.params.sigma_u),
                                (w, dryden_psd_w, rec.params.length_w, rec.params.sigma_w)):
        f, pxx = welch(x, fs=fs, nperseg=nper)
        sel = (f > 0.005) & (f < 1.0)
        target = psd(2 * np.pi * f[sel], sig, length, rec.speed) * 2 * np.pi  # per Hz
        dof = 2 * 15 * 0.9  # 15 half-overlapping segments, Hann efficiency
        lo, hi = chi2.ppf(0.05, dof) / dof, chi2.ppf(0.95, dof) / dof
        ratio = pxx[sel] / target
        outside = np.mean((ratio < lo) | (ratio > hi))
        assert outside < 0.12
        assert np.median(ratio) == pytest.approx(1.0, abs=0.1)


def test_v9_correlation_length(hour_record):
    """u autocorrelation falls to 1/e at a lag of about L_u/V (first-order Dryden)."""
    rec, t, u, _ = hour_record
    dt = t[1] - t[0]
    x = u - u.mean()
    spec = np.fft.rfft(x, 2 * x.size)
    acf = np.fft.irfft(np.abs(spec) ** 2)[: x.size]
    acf /= acf[0]
    lag = np.argmax(acf < 1 / math.e) * dt
    assert lag == pytest.approx(rec.params.length_u / rec.speed, rel=0.25)


def test_turbulence_evaluate_matches_grid_and_fade(hour_record):
    rec, t, u, w = hour_record
    idx = np.array([5000, 12345, 40000])
    uu, ww, du, _ = rec.evaluate(t[idx], faded=False)
    assert uu == pytest.approx(u[idx], abs=1e-9)
    assert ww == pytest.approx(w[idx], abs=1e-9)
    # fade-in: zero at t = 0, the analytic derivative matches finite differences
    short = DrydenTurbulence(seed=2, fade_in=20.0).realize(300.0, 10.0, 300.0)
    tt = np.linspace(0.0, 30.0, 6001)
    uf, _, duf, _ = short.evaluate(tt)
    assert uf[0] == 0.0
    assert np.max(np.abs(np.gradient(uf, tt) - duf)[1:-1]) < 1e-3


def test_same_seed_same_record_and_validation():
    a = DrydenTurbulence(seed=3).realize(300.0, 10.0, 300.0)
    b = DrydenTurbulence(seed=3).realize(300.0, 10.0, 300.0)
    c = DrydenTurbulence(seed=4).realize(300.0, 10.0, 300.0)
    assert np.array_equal(a.coef_u, b.coef_u) and not np.array_equal(a.coef_u, c.coef_u)
    with pytest.raises(ValueError, match="w20"):
        DrydenTurbulence(w20=-1.0)
    with pytest.raises(ValueError, match="at least 0.5 m/s"):
        DrydenTurbulence().realize(300.0, 0.1, 300.0)


def test_kernel_turbulence_table_matches_cosine_sum():
    """The kernel's Hermite-interpolated table reproduces the cosine sum and its derivative."""
    sc = WindScenario(SpeedSchedule.constant(10.0),
                      turbulence=DrydenTurbulence.from_intensity("severe", seed=5, fade_in=0.0))
    field = sc.realize(300.0, 200.0)
    t = np.linspace(0.0, 400.0, 7919)  # beyond one period too (the table is periodic)
    ux, uz, dux, duz, ax, az = field.at(t, 300.0)
    u, w, du, dw = field.turbulence.evaluate(t)
    assert np.max(np.abs(ux - 10.0 - u)) < 1e-4
    assert np.max(np.abs(uz - w)) < 1e-4
    assert np.max(np.abs(dux - du)) < 2e-3 * np.max(np.abs(du))
    assert np.max(np.abs(duz - dw)) < 2e-3 * np.max(np.abs(dw))


# --- the spatial field (Taylor, height levels, IEC coherence) ------------------------------------
@pytest.fixture(scope="module")
def spatial_field():
    sc = WindScenario(SpeedSchedule.constant(10.0),
                      turbulence=DrydenTurbulence.from_intensity("moderate", seed=11, fade_in=0.0))
    return sc.realize(300.0, 1200.0, x_ref=40.0)


def test_field_is_frozen_and_convected(spatial_field):
    """u'(x + U_c dt, t + dt) = u'(x, t): the field moves with the mean wind unchanged."""
    f = spatial_field
    t = np.linspace(100.0, 200.0, 501)
    base = f.at(t, 300.0, x=40.0)
    for dx in (-40.0, 25.0):
        moved = f.at(t + dx / f.convection_speed, 300.0, x=40.0 + dx)
        assert moved[0] == pytest.approx(base[0], abs=1e-9)
        assert moved[1] == pytest.approx(base[1], abs=1e-9)
    # the fluid acceleration of a frozen field is zero; the fixed-point derivative is not
    assert np.all(base[4] == 0.0) and np.std(base[2]) > 0.05


def test_field_varies_with_height_and_levels_have_target_variance(spatial_field):
    """Each level holds its own Dryden variance (sigma_u grows towards the ground): exactly at the
    hull, in the mean over 30 seeds elsewhere; points 100 m apart in height differ."""
    f = spatial_field.turbulence
    _t, u, w = f.grid(2**15)
    assert np.var(u) == pytest.approx(f.target_var_u[f.hull_level], rel=1e-9)
    assert np.var(w) == pytest.approx(f.target_var_w[f.hull_level], rel=1e-9)
    fields = [DrydenTurbulence(seed=s, fade_in=0.0).realize(300.0, 10.0, 600.0)
              for s in range(30)]
    for lev in (f.hull_level - 10, 3):
        vu = np.mean([np.sum(np.abs(g.coef_u[lev]) ** 2) / 2 for g in fields])
        vw = np.mean([np.sum(np.abs(g.coef_w[lev]) ** 2) / 2 for g in fields])
        assert vu == pytest.approx(fields[0].target_var_u[lev], rel=0.12)
        assert vw == pytest.approx(fields[0].target_var_w[lev], rel=0.12)
    assert f.level_params[3].sigma_u > 1.2 * f.params.sigma_u  # 30 m vs 300 m
    t = np.linspace(0.0, 1200.0, 6001)
    top = spatial_field.at(t, 300.0)[0]
    low = spatial_field.at(t, 200.0)[0]
    assert np.corrcoef(top, low)[0, 1] < 0.9


def test_hull_level_has_the_exact_dryden_spectrum(spatial_field):
    """The hull's level is first in the Cholesky order: its bin variances are the spectrum's."""
    f = spatial_field.turbulence
    k = f.hull_level
    p = f.params
    var = np.abs(f.coef_u[k]) ** 2 / 2
    dw = f.omega[1] - f.omega[0]
    target = dryden_psd_u(f.omega, p.sigma_u, p.length_u, f.speed) * dw
    assert var[5:200] == pytest.approx(target[5:200], rel=0.02)


def test_vertical_coherence_matches_iec_model():
    """Ensemble coherence of two levels (100 seeds) = IEC exp(-12 sqrt((f dz/U)^2 + (0.12 dz/Lc)^2))."""
    from aerostat_core.dynamics.turbulence import iec_coherence

    sums = None
    for seed in range(100):
        f = DrydenTurbulence(seed=seed, fade_in=0.0).realize(300.0, 10.0, 300.0)
        a, b = f.coef_u[f.hull_level], f.coef_u[f.hull_level - 2]  # 20 m apart
        s = np.stack([a * np.conj(b), np.abs(a) ** 2, np.abs(b) ** 2])
        sums = s if sums is None else sums + s
    freq = f.omega / (2 * np.pi)
    band = 10  # bins per band: 1000 samples of the cross-spectrum each
    nb = freq.size // band
    sb = sums[:, :nb * band].reshape(3, nb, band).sum(axis=2)
    coh = np.real(sb[0]) / np.sqrt(sb[1].real * sb[2].real)
    fb = freq[:nb * band].reshape(nb, band).mean(axis=1)
    # the band's coherence is the energy-weighted mean of the bins' (the spectrum falls steeply)
    wgt = np.sqrt(sums[1].real * sums[2].real)[:nb * band]
    target = (iec_coherence(20.0, freq[:nb * band], 10.0) * wgt).reshape(nb, band).sum(axis=1)
    target /= np.sqrt(sb[1].real * sb[2].real)
    assert np.max(np.abs(coh - target)[fb < 0.5]) < 0.1
    assert coh[0] > 0.6 and np.mean(coh[fb > 0.5]) < 0.1


def test_w20_from_the_profile_and_model_name():
    """``w20=None`` takes MIL-HDBK-1797's W20 from the run's own mean profile at 20 ft."""
    sc = WindScenario(SpeedSchedule.constant(10.0), MeanProfile("power", 300.0, 1.0 / 7.0),
                      turbulence=DrydenTurbulence.from_intensity("profile", seed=1))
    f = sc.realize(300.0, 120.0)
    w20 = 10.0 * (20 * FOOT / 300.0) ** (1 / 7)
    assert f.turbulence.params.sigma_w == pytest.approx(0.1 * w20)
    assert "MIL-HDBK-1797" in f.turbulence.model and "IEC 61400-1" in f.turbulence.model
