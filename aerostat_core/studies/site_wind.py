"""Site wind and flyable time: how often a built aerostat can fly at a site.

The site wind is either a Weibull distribution of the hourly mean speed at a reference height
(:class:`WeibullSite`) or an hourly record with timestamps (:func:`read_wind_csv`, the kind of
data the thesis sizes against: Mersing, Jan 2009, thesis Figure 3.3). Either is moved to the
aerostat's height with the power law U(h) = U(z_ref) (h / z_ref)^alpha (Hellmann; docs/methods.md
§1.2), which keeps the Weibull shape k and scales c by the same factor.

The aerostat can fly at wind U when every constraint of the envelope is met at U
(:mod:`aerostat_core.studies.envelope`, on a 0.05 m/s grid up to 60 m/s at the operating altitude).

* % time flyable: P(U_h in the flyable set), from the Weibull CDF
  F(u) = 1 - exp(-(u/c_h)^k), or the share of recorded hours.
* Longest expected outage: the longest run of hours in a row that cannot fly. For a record, the
  longest run in it; for a Weibull site, the mean over simulated years of the yearly longest run,
  with hourly persistence from a Gaussian AR(1) process mapped onto the Weibull marginal
  (u_t = F^-1(Phi(z_t)), z_t = rho z_{t-1} + sqrt(1 - rho^2) e_t; Brown, Katz & Murphy 1984,
  J. Climate Appl. Meteor. 23, 1184: hourly wind speed as a transformed autoregressive process).
* For a target availability A, the design wind it implies: the wind at the aerostat not exceeded
  a share A of the time, u_A = c_h (-ln(1 - A))^(1/k), or the record's A-quantile.
"""

from __future__ import annotations

import io
import math
from dataclasses import dataclass

import numpy as np
from scipy.special import ndtr

from aerostat_core.base.fields import number, validate
from aerostat_core.base.validation import check_number
from aerostat_core.model.design import Design
from aerostat_core.studies.envelope import point_state, requirement_at

#: Default hourly lag-1 autocorrelation of the (Gaussian-transformed) hourly mean wind [-]:
#: of the order of 0.9 for hourly data (Brown, Katz & Murphy 1984); a site's record supersedes it.
HOURLY_AUTOCORRELATION = 0.9
#: Power-law shear exponent of open terrain (1/7; docs/methods.md §1.2).
OPEN_TERRAIN_SHEAR = 1.0 / 7.0
#: Largest wind CSV read [bytes] and rows (22 years of hourly data).
MAX_CSV_BYTES = 10_000_000
MAX_CSV_ROWS = 200_000
#: Valid recorded wind speed [m/s].
MAX_RECORDED_SPEED = 80.0
#: Wind grid on which the flyable set is found [m/s].
FLYABLE_GRID = np.arange(0.0, 60.0 + 1e-9, 0.05)
HOURS_PER_YEAR = 8760


@dataclass(frozen=True)
class WeibullSite:
    """Weibull distribution of the hourly mean wind at a reference height.

    Parameters
    ----------
    shape : float
        Weibull k [-], valid [0.5, 10] (k = 2 is the Rayleigh distribution of IEC 61400-1).
    scale : float
        Weibull c at ``reference_height`` [m/s], valid (0, 40].
    reference_height : float
        Height of the distribution above the site [m], valid [1, 1000] (10 m: meteorological mast).
    shear_exponent : float
        Power-law exponent alpha [-], valid [0, 0.6] (1/7 open terrain).
    autocorrelation : float
        Hourly lag-1 autocorrelation of the transformed wind [-], valid [0, 0.999].
    """

    shape: float = number(2.0, "Weibull k", "", 0.5, 10, step=0.1, fmt="%.2f")
    scale: float = number(6.0, "Weibull c", "m/s", 0, 40, lo_open=True, step=0.5, fmt="%.1f")
    reference_height: float = number(
        10.0, "Reference height", "m", 1, 1000, step=1.0, fmt="%.0f",
        help="Height of the wind distribution above the site (10 m: meteorological mast).")
    shear_exponent: float = number(
        OPEN_TERRAIN_SHEAR, "Shear exponent", "", 0, 0.6, step=0.01, fmt="%.3f",
        help="Power-law exponent (1/7 open terrain).")
    autocorrelation: float = number(
        HOURLY_AUTOCORRELATION, "Hourly autocorrelation", "", 0, 0.999, step=0.01, fmt="%.3f")

    def __post_init__(self) -> None:
        validate(self)

    def scale_at(self, height: float) -> float:
        """c at ``height`` [m]: c (h / z_ref)^alpha [m/s]."""
        return self.scale * (max(float(height), 1.0) / self.reference_height) ** self.shear_exponent

    def cdf(self, u, height: float):
        """P(U_h <= u) = 1 - exp(-(u / c_h)^k)."""
        u = np.maximum(np.asarray(u, float), 0.0)
        return 1.0 - np.exp(-((u / self.scale_at(height)) ** self.shape))

    def quantile(self, p: float, height: float) -> float:
        """Wind at ``height`` not exceeded with probability ``p``: c_h (-ln(1 - p))^(1/k)."""
        return self.scale_at(height) * (-math.log1p(-p)) ** (1.0 / self.shape)

    def simulate(self, hours: int, height: float, seed: int = 0) -> np.ndarray:
        """Hourly speeds at ``height`` [m/s] with the AR(1) persistence (seeded)."""
        rng = np.random.default_rng(seed)
        e = rng.standard_normal(hours)
        r = self.autocorrelation
        z = np.empty(hours)
        z[0] = e[0]
        s = math.sqrt(1.0 - r * r)
        for i in range(1, hours):  # scalar recursion; 87 600 steps take ~20 ms
            z[i] = r * z[i - 1] + s * e[i]
        p = np.clip(ndtr(z), 1e-15, 1.0 - 1e-15)
        return self.scale_at(height) * (-np.log1p(-p)) ** (1.0 / self.shape)


@dataclass(frozen=True)
class HourlyRecord:
    """Recorded wind: ``time`` (datetime64[s]), ``speed`` [m/s] at ``reference_height`` [m],
    sheared to other heights with ``shear_exponent``."""

    time: np.ndarray
    speed: np.ndarray
    reference_height: float = number(10.0, "Reference height", "m", 1, 1000)
    shear_exponent: float = number(OPEN_TERRAIN_SHEAR, "Shear exponent", "", 0, 0.6)

    def __post_init__(self) -> None:
        validate(self)

    def speed_at(self, height: float) -> np.ndarray:
        """Speeds at ``height`` [m]: U (h / z_ref)^alpha [m/s]."""
        return self.speed * (max(float(height), 1.0) / self.reference_height) ** self.shear_exponent

    def durations(self) -> np.ndarray:
        """Hours each record stands for: the time to the next record (the last one: the median
        step); a record followed by a gap (more than 1.5 median steps) stands for one median
        step, so that the missing time does not count as wind."""
        dt = np.diff(self.time).astype("timedelta64[s]").astype(float) / 3600.0
        step = float(np.median(dt)) if dt.size else 1.0
        dt = np.append(dt, step)
        return np.where(dt > 1.5 * step, step, dt)

    def gaps(self) -> np.ndarray:
        """True after record i when the next one is more than 1.5 median steps later."""
        dt = np.diff(self.time).astype("timedelta64[s]").astype(float)
        return dt > 1.5 * float(np.median(dt))


def read_wind_csv(
    data, reference_height: float = 10.0, shear_exponent: float = OPEN_TERRAIN_SHEAR
) -> HourlyRecord:
    """Parse an hourly wind CSV: a header, a timestamp column and a speed column [m/s].

    The time column is the one named like ``time``/``date``/``timestamp`` (else the first), the
    speed column the one named like ``speed``/``wind`` (else the second). Timestamps are ISO 8601
    or anything pandas reads, strictly increasing. At most :data:`MAX_CSV_BYTES` bytes and
    :data:`MAX_CSV_ROWS` rows.

    Raises
    ------
    ValueError
        Naming the column, the row (1 = first data row), the value and the valid range.
    """
    import pandas as pd

    if isinstance(data, str):
        data = data.encode()
    if len(data) > MAX_CSV_BYTES:
        raise ValueError(
            f"wind CSV is {len(data)} bytes, larger than the {MAX_CSV_BYTES} allowed"
            f" (about {MAX_CSV_ROWS} hourly rows)"
        )
    try:
        df = pd.read_csv(io.BytesIO(data), nrows=MAX_CSV_ROWS + 1, dtype=str, skipinitialspace=True)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        raise ValueError(f"wind CSV cannot be read as CSV: {str(exc).strip()[:200]}") from None
    if len(df) > MAX_CSV_ROWS:
        raise ValueError(f"wind CSV has more than {MAX_CSV_ROWS} rows; valid 2 to {MAX_CSV_ROWS}")
    if df.shape[1] < 2:
        raise ValueError(
            f"wind CSV needs two columns, a timestamp and a wind speed [m/s]; found {df.shape[1]}"
        )
    if len(df) < 2:
        raise ValueError(f"wind CSV has {len(df)} data rows; valid 2 to {MAX_CSV_ROWS}")
    cols = [str(c) for c in df.columns]
    low = [c.lower() for c in cols]
    t_col = next((c for c, lc in zip(cols, low) if any(k in lc for k in ("time", "date"))), cols[0])
    s_col = next(
        (c for c, lc in zip(cols, low) if c != t_col and any(k in lc for k in ("speed", "wind"))),
        next(c for c in cols if c != t_col),
    )
    t = pd.to_datetime(df[t_col], errors="coerce", format="mixed")
    bad = np.flatnonzero(t.isna().to_numpy())
    if bad.size:
        i = int(bad[0])
        raise ValueError(
            f"wind CSV column {t_col!r} row {i + 1}: {df[t_col].iloc[i]!r} is not a "
            "timestamp (e.g. 2009-01-01 00:00)"
        )
    if getattr(t.dt, "tz", None) is not None:
        t = t.dt.tz_convert("UTC").dt.tz_localize(None)
    u = pd.to_numeric(df[s_col], errors="coerce").to_numpy(float)
    bad = np.flatnonzero(~np.isfinite(u) | (u < 0) | (u > MAX_RECORDED_SPEED))
    if bad.size:
        i = int(bad[0])
        raise ValueError(
            f"wind CSV column {s_col!r} row {i + 1}: {df[s_col].iloc[i]!r} is not a "
            f"wind speed in the valid range [0, {MAX_RECORDED_SPEED:g}] m/s"
        )
    time = t.to_numpy().astype("datetime64[s]")
    dt = np.diff(time).astype(float)
    bad = np.flatnonzero(dt <= 0)
    if bad.size:
        i = int(bad[0]) + 1
        raise ValueError(
            f"wind CSV column {t_col!r} row {i + 1}: timestamp {df[t_col].iloc[i]!r} "
            "is not after the one before it; timestamps must increase"
        )
    return HourlyRecord(time, u, reference_height, shear_exponent)


def flyable_intervals(wind, max_g, tolerance: float = 0.0) -> list[tuple[float, float]]:
    """Wind intervals [lo, hi] where the largest constraint value g <= ``tolerance``.

    Ends between grid points are found by linear interpolation of g; an interval reaching the
    grid's last wind ends there (winds beyond the grid count as not flyable).
    """
    w = np.asarray(wind, float)
    g = np.asarray(max_g, float) - tolerance
    ok = g <= 0
    out = []
    i = 0
    n = w.size
    while i < n:
        if not ok[i]:
            i += 1
            continue
        j = i
        while j + 1 < n and ok[j + 1]:
            j += 1

        def cross(a, b):
            return w[a] + (w[b] - w[a]) * (0.0 - g[a]) / (g[b] - g[a]) if g[b] != g[a] else w[a]

        lo = w[i] if i == 0 else cross(i - 1, i)
        hi = w[j] if j == n - 1 else cross(j, j + 1)
        out.append((float(lo), float(hi)))
        i = j + 1
    return out


def _longest_run(bad: np.ndarray, hours: np.ndarray, breaks: np.ndarray | None = None) -> float:
    """Longest sum of ``hours`` over consecutive True entries of ``bad`` (a True in ``breaks``
    after entry i ends a run there)."""
    best = run = 0.0
    for i in range(bad.size):
        if bad[i]:
            run += hours[i]
            best = max(best, run)
            if breaks is not None and i < breaks.size and breaks[i]:
                run = 0.0
        else:
            run = 0.0
    return float(best)


def _runs_per_row(bad: np.ndarray) -> np.ndarray:
    """Longest run of True along the last axis (vectorised, whole-hour entries)."""
    b = np.asarray(bad, bool)
    out = np.zeros(b.shape[:-1])
    for idx in np.ndindex(*b.shape[:-1]):
        row = np.concatenate([[False], b[idx], [False]]).astype(np.int8)
        d = np.diff(row)
        starts, ends = np.flatnonzero(d == 1), np.flatnonzero(d == -1)
        out[idx] = float((ends - starts).max()) if starts.size else 0.0
    return out


@dataclass(frozen=True)
class FlyableTime:
    """How often the aerostat can fly at the site.

    percent_time_flyable : float  [%]
    longest_outage_h : float  longest expected run of hours that cannot fly [h]
    target_availability : float  [-]
    design_wind_for_target_m_s : float  wind at the aerostat not exceeded a share
        ``target_availability`` of the time [m/s]
    altitude_m : float  operating altitude the site wind was sheared to [m]
    intervals : tuple of (lo, hi)  flyable winds at the aerostat [m/s]
    source : str  "weibull" or "csv"
    hours : float  hours of record (csv) or simulated (weibull outage) [h]
    """

    percent_time_flyable: float
    longest_outage_h: float
    target_availability: float
    design_wind_for_target_m_s: float
    altitude_m: float
    intervals: tuple
    source: str
    hours: float

    def summary(self) -> dict:
        """Plain dict (JSON keys with units)."""
        return {
            "percent_time_flyable": self.percent_time_flyable,
            "longest_outage_h": self.longest_outage_h,
            "target_availability": self.target_availability,
            "design_wind_for_target_m_s": self.design_wind_for_target_m_s,
            "flyable_winds_m_s": [list(iv) for iv in self.intervals],
            "site_altitude_m": self.altitude_m,
            "wind_source": self.source,
            "hours": self.hours,
        }


def flyable_set(d: Design, altitude: float | None = None) -> list[tuple[float, float]]:
    """Flyable wind intervals [m/s] of the built aerostat ``d`` at ``altitude`` [m] (default: the
    design altitude), from the envelope constraints on :data:`FLYABLE_GRID`."""
    h = float(d.requirement.altitude if altitude is None else altitude)
    g, _ = point_state(requirement_at(d.requirement, h), d.configuration, d.volume, FLYABLE_GRID)
    return flyable_intervals(FLYABLE_GRID, g.max(axis=-1), tolerance=1e-6)


def flyable_time(
    d: Design,
    site: WeibullSite | HourlyRecord | None = None,
    altitude: float | None = None,
    target_availability: float = 0.95,
    seed: int = 0,
    years: int = 10,
) -> FlyableTime:
    """Percent of time flyable, longest expected outage and the design wind of a target
    availability for the built aerostat ``d`` at a site.

    Parameters
    ----------
    d : Design
    site : WeibullSite or HourlyRecord, optional
        Default ``WeibullSite()`` (Rayleigh, c = 6 m/s at 10 m, 1/7 shear).
    altitude : float, optional
        Operating altitude [m] (default the design altitude); the site wind is sheared to it.
    target_availability : float
        Share of time the aerostat must fly [-], valid (0, 1).
    seed : int
        Seed of the simulated hours (Weibull outage only).
    years : int
        Simulated years for the Weibull outage, valid [1, 100].
    """
    site = WeibullSite() if site is None else site
    check_number(
        "flyable_time", "target_availability", target_availability, 0, 1, lo_open=True, hi_open=True
    )
    years = int(check_number("flyable_time", "years", years, 1, 100))
    h = float(d.requirement.altitude if altitude is None else altitude)
    iv = flyable_set(d, h)
    if isinstance(site, WeibullSite):
        p = sum(float(site.cdf(b, h) - site.cdf(a, h)) for a, b in iv)
        u = site.simulate(years * HOURS_PER_YEAR, h, seed).reshape(years, HOURS_PER_YEAR)
        bad = ~_in_intervals(u, iv)
        outage = float(_runs_per_row(bad).mean())
        u_a = site.quantile(target_availability, h)
        hours = float(years * HOURS_PER_YEAR)
        source = "weibull"
    else:
        u = site.speed_at(h)
        w = site.durations()
        bad = ~_in_intervals(u, iv)
        p = float(np.sum(w[~bad]) / np.sum(w))
        outage = _longest_run(bad, w, site.gaps())
        order = np.argsort(u, kind="stable")
        cum = np.cumsum(w[order]) / np.sum(w)
        u_a = float(u[order][min(np.searchsorted(cum, target_availability - 1e-12), u.size - 1)])
        hours = float(np.sum(w))
        source = "csv"
    return FlyableTime(
        percent_time_flyable=100.0 * min(max(p, 0.0), 1.0),
        longest_outage_h=outage,
        target_availability=float(target_availability),
        design_wind_for_target_m_s=float(u_a),
        altitude_m=h,
        intervals=tuple(iv),
        source=source,
        hours=hours,
    )


def _in_intervals(u, intervals) -> np.ndarray:
    u = np.asarray(u, float)
    ok = np.zeros(u.shape, bool)
    for a, b in intervals:
        ok |= (u >= a - 1e-12) & (u <= b + 1e-12)
    return ok
