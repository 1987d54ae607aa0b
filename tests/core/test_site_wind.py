"""Site wind and flyable time: analytic Weibull limits, a calm site, records, bad CSVs."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.special import gamma

from aerostat_core import Requirement, design
from aerostat_core.studies.site_wind import (
    MAX_CSV_BYTES,
    WeibullSite,
    flyable_intervals,
    flyable_set,
    flyable_time,
    read_wind_csv,
)


@pytest.fixture(scope="module")
def d():
    return design(Requirement(payload_mass=10.0, altitude=300.0))


def _csv(speeds, start="2009-01-01 00:00", step_h=1):
    t0 = np.datetime64(start)
    rows = [f"{t0 + np.timedelta64(step_h * i, 'h')},{s}" for i, s in enumerate(speeds)]
    return "time,wind_speed\n" + "\n".join(rows) + "\n"


def test_calm_site_is_flyable_all_the_time(d):
    calm = read_wind_csv(_csv([0.0] * 48))
    ft = flyable_time(d, calm)
    assert ft.percent_time_flyable == 100.0
    assert ft.longest_outage_h == 0.0
    assert ft.design_wind_for_target_m_s == 0.0
    still = flyable_time(d, WeibullSite(shape=2.0, scale=0.01))
    assert still.percent_time_flyable == pytest.approx(100.0, abs=1e-9)
    assert still.longest_outage_h == 0.0


def test_weibull_percent_is_the_cdf_at_the_limit_wind(d):
    site = WeibullSite(shape=2.2, scale=5.0, reference_height=10.0, shear_exponent=0.2)
    ((lo, hi),) = flyable_set(d)
    assert lo == 0.0 and 5.0 < hi < 30.0
    c_h = 5.0 * (300.0 / 10.0) ** 0.2
    ft = flyable_time(d, site)
    assert ft.percent_time_flyable == pytest.approx(
        100 * (1 - math.exp(-((hi / c_h) ** 2.2))), rel=1e-9
    )
    assert ft.design_wind_for_target_m_s == pytest.approx(
        c_h * (-math.log(0.05)) ** (1 / 2.2), rel=1e-12
    )


def test_simulated_hours_keep_the_weibull_marginal_and_persistence():
    site = WeibullSite(shape=2.0, scale=6.0, autocorrelation=0.9)
    u = site.simulate(200_000, 10.0, seed=1)
    assert u.mean() == pytest.approx(6.0 * gamma(1.5), rel=0.02)
    assert np.mean(u <= 6.0) == pytest.approx(1 - math.exp(-1), abs=0.01)
    r1 = np.corrcoef(u[:-1], u[1:])[0, 1]
    assert 0.8 < r1 < 0.95  # the Gaussian lag-1 correlation 0.9, a little less after the map
    assert np.array_equal(u, site.simulate(200_000, 10.0, seed=1))


def test_record_outage_percent_and_quantile(d):
    speeds = [3.0] * 10 + [25.0] * 5 + [3.0] * 4 + [25.0] * 2 + [3.0] * 3
    ft = flyable_time(d, read_wind_csv(_csv(speeds), reference_height=300.0))
    assert ft.longest_outage_h == pytest.approx(5.0)
    assert ft.percent_time_flyable == pytest.approx(100 * 17 / 24)
    assert ft.design_wind_for_target_m_s == 25.0
    assert ft.hours == pytest.approx(24.0)


def test_gap_in_record_breaks_an_outage(d):
    t = [
        "2009-01-01 00:00",
        "2009-01-01 01:00",
        "2009-01-01 02:00",
        "2009-01-03 00:00",
        "2009-01-03 01:00",
        "2009-01-03 02:00",
    ]
    text = "time,speed\n" + "\n".join(f"{a},{b}" for a, b in zip(t, [30, 30, 30, 30, 30, 2]))
    ft = flyable_time(d, read_wind_csv(text, reference_height=300.0))
    assert ft.longest_outage_h == pytest.approx(3.0)  # not 5: the 2-day gap is not wind


def test_flyable_intervals_interpolate_the_crossings():
    w = np.array([0.0, 1.0, 2.0, 3.0, 4.0])
    g = np.array([0.5, -0.5, -1.0, -0.5, 0.5])
    assert flyable_intervals(w, g) == [(0.5, 3.5)]
    assert flyable_intervals(w, -np.ones(5)) == [(0.0, 4.0)]
    assert flyable_intervals(w, np.ones(5)) == []


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("time\n2009-01-01\n2009-01-02\n", "needs two columns"),
        ("time,speed\n2009-01-01 00:00,1\n", "has 1 data rows"),
        (
            "time,speed\n2009-01-01 00:00,abc\n2009-01-01 01:00,1\n",
            "column 'speed' row 1: 'abc' is not a wind speed in the valid range [0, 80] m/s",
        ),
        ("time,speed\n2009-01-01 00:00,1\n2009-01-01 01:00,-2\n", "row 2: '-2' is not a wind"),
        (
            "time,speed\nnot a date,1\n2009-01-01 01:00,2\n",
            "row 1: 'not a date' is not a timestamp",
        ),
        ("time,speed\n2009-01-01 02:00,1\n2009-01-01 01:00,2\n", "row 2: timestamp"),
        ("", "cannot be read"),
    ],
)
def test_bad_csv_gets_a_clear_message(text, message):
    with pytest.raises(ValueError, match=message.replace("[", r"\[").replace("]", r"\]")):
        read_wind_csv(text)


def test_oversized_csv_is_refused_before_parsing():
    with pytest.raises(ValueError, match="larger than the 10000000 allowed"):
        read_wind_csv(b"x" * (MAX_CSV_BYTES + 1))


def test_bad_site_parameters_are_named():
    with pytest.raises(ValueError, match="WeibullSite.shape = 0.1"):
        WeibullSite(shape=0.1)
    with pytest.raises(ValueError, match="WeibullSite.scale"):
        WeibullSite(scale=0.0)


@settings(max_examples=25, deadline=None)
@given(k=st.floats(0.8, 5.0), c=st.floats(0.5, 20.0), alpha=st.floats(0.0, 0.4))
def test_weibull_percent_is_the_cdf_and_falls_with_a_windier_site(d, k, c, alpha):
    site = WeibullSite(shape=k, scale=c, shear_exponent=alpha)
    ft = flyable_time(d, site, years=1)
    ((lo, hi),) = ft.intervals
    assert ft.percent_time_flyable == pytest.approx(100 * float(site.cdf(hi, 300.0)), abs=1e-9)
    windier = flyable_time(d, WeibullSite(shape=k, scale=1.2 * c, shear_exponent=alpha), years=1)
    assert windier.percent_time_flyable <= ft.percent_time_flyable + 1e-12
    assert 0.0 <= ft.longest_outage_h <= 8760.0
