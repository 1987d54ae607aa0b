"""Results of a run: time histories, signals in their units, statistics, events and limits.

:class:`SimulationResult` holds the sampled states and kernel diagnostics of one run and derives
the signals of :data:`SIGNALS`; :func:`signal_stats` and :func:`response_metrics` are the
statistics the page, the CLI and the thesis comparison quote; :meth:`SimulationResult.slack_events`
lists the intervals with a slack tether segment; :func:`limit_flags` checks a run against the
fin stall angle, the tether's safe working load and the requirement's altitude.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .kernel import DIAG_NAMES
from .options import SolverOptions
from .system import DynamicSystem
from .wind import WindField


@dataclass(frozen=True)
class EquilibriumInfo:
    """Result of the static Newton solve: iterations, largest remaining acceleration [m/s2 or
    rad/s2], largest position change from the guess [m] (pitch change [rad] separately)."""

    iterations: int
    residual: float
    shift: float
    pitch_shift: float


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


def motion_figures(pitch_deg, vx, vz, tension) -> dict:
    """The response figures of a run's window, one definition for the 3- and 6-DOF summaries:
    pitch range and peak deviation from its mean [deg], hull velocity peaks about their means
    u_peak_mps, w_peak_mps [m/s], the RMS of pitch and velocities, and the range of the tension
    at the confluence point [N]. Arguments: the signals over the window (arrays of one length)."""
    th, vx, vz, ten = (np.asarray(a, float) for a in (pitch_deg, vx, vz, tension))
    return {"pitch_range_deg": [float(th.min()), float(th.max())],
            "pitch_peak_deg": float(np.max(np.abs(th - th.mean()))),
            "u_peak_mps": float(np.max(np.abs(vx - vx.mean()))),
            "w_peak_mps": float(np.max(np.abs(vz - vz.mean()))),
            "pitch_rms_deg": float(np.std(th)),
            "u_rms_mps": float(np.std(vx)),
            "w_rms_mps": float(np.std(vz)),
            "tension_range_N": [float(ten.min()), float(ten.max())]}


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

    def to_csv(self, names=None, header: dict | None = None) -> str:
        """CSV text of the time histories (one row per sample, units in the column names),
        preceded by ``# key = value`` lines: ``header`` (scenario and parameters), the status
        and the slack events."""
        names = names or self.signal_names()
        cols = ["t_s"] + [f"{k}_{SIGNALS[k][1].replace('/', '_')}" for k in names]
        data = np.column_stack([self.t] + [self.signal(k) for k in names])
        meta = dict(header or {})
        meta["status"] = self.message
        meta["slack_events"] = "; ".join(
            f"segment {e['segment']} slack {e['start_s']:.1f}-{e['end_s']:.1f} s"
            for e in self.slack_events()) or "none"
        lines = [f"# {k} = {_csv_text(v)}" for k, v in meta.items()]
        lines.append(",".join(cols))
        lines += [",".join(f"{v:.6g}" for v in row) for row in data]
        return "\n".join(lines) + "\n"

    def slack_events(self) -> list[dict]:
        """Intervals with a slack tether segment (tension <= 0 somewhere), from the samples:
        dicts with start_s, end_s [s] and segment (the slackest one, 1 = at the winch)."""
        slack = self.d("tension_min") <= 0.0
        seg = self.d("tension_min_segment")
        out = []
        i = 0
        n = slack.size
        while i < n:
            if slack[i]:
                j = i
                while j + 1 < n and slack[j + 1]:
                    j += 1
                k = i + int(np.argmin(self.d("tension_min")[i:j + 1]))
                out.append({"start_s": float(self.t[i]), "end_s": float(self.t[j]),
                            "segment": int(seg[k])})
                i = j + 1
            else:
                i += 1
        return out


def _csv_text(v) -> str:
    """One header value as CSV-safe plain text (no newlines, no leading formula characters)."""
    txt = str(v).replace("\n", " ").replace("\r", " ")
    return "'" + txt if txt[:1] in ("=", "+", "-", "@") and not _is_number(txt) else txt


def _is_number(txt: str) -> bool:
    try:
        float(txt)
    except ValueError:
        return False
    return True


@dataclass(frozen=True)
class Limits:
    """Operating limits a run is checked against.

    fin_stall_deg [deg]: fin stall angle; safe_working_load [N]: breaking strength / required
    safety factor; min_height [m]: lowest accepted height of the confluence point (the static
    height at the design wind, where the blow-by reaches the requirement's limit, unless the
    requirement states an altitude-loss limit)."""

    fin_stall_deg: float
    safe_working_load: float
    min_height: float

    @classmethod
    def from_design(cls, design) -> Limits:
        """The limits of a static-engine design (fins, tether, requirement)."""
        req = design.requirement
        cfg = design.configuration
        swl = cfg.tether.breaking_strength / req.min_tether_safety_factor
        loss = getattr(req, "altitude_loss_limit", None)
        length = float(design.airframe.tether_length)
        if loss is not None:
            zmin = length - float(loss)
        else:
            rows = design.performance.rows()
            row = min(rows, key=lambda r: abs(r["wind_speed_m_s"] - req.design_wind))
            zmin = float(row["flying_height_m"])
        return cls(float(cfg.aero.fin_stall_angle_deg), float(swl), zmin)


def limit_flags(res: SimulationResult, limits: Limits) -> list[dict]:
    """One row per limit: limit, value, unit, worst (the run's extreme), exceeded (bool),
    first_s (first time it was exceeded, or None) and the fraction of samples beyond it."""
    t = res.t
    rows = []

    def row(name, unit, limit, series, above=True):
        bad = series > limit if above else series < limit
        worst = float(np.max(series) if above else np.min(series))
        rows.append({"limit": name, "unit": unit, "value": float(limit), "worst": worst,
                     "exceeded": bool(np.any(bad)),
                     "first_s": float(t[np.argmax(bad)]) if np.any(bad) else None,
                     "fraction": float(np.mean(bad)) if bad.size else 0.0})

    if res.system.is_hull:
        row("|alpha| at the fins beyond stall", "deg", limits.fin_stall_deg,
            np.abs(res.signal("alpha_fin")))
    row("tension above the safe working load", "N", limits.safe_working_load,
        res.signal("tension_max"))
    row("a slack tether segment (tension at zero)", "N", 1e-9, res.d("tension_min"), above=False)
    rows[-1]["value"] = 0.0
    row("altitude below the requirement's lowest height", "m", limits.min_height,
        res.signal("z_C"), above=False)
    return rows
