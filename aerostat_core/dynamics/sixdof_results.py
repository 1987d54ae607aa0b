"""Time histories of a 6-DOF run: signals with units, peaks, CSV and JSON exports
(docs/dynamics.md §7.6).

Positions are reported in the wind frame of the reference azimuth chi_0: x along the wind
(blow-by), y to its left (lateral displacement), z up; yaw is the heading of the nose relative
to the upwind direction of chi_0 (0 when the hull points into the reference wind).
"""

from __future__ import annotations

import json
import math

import numpy as np

from aerostat_core.dynamics.sixdof_kernel import DIAG6_NAMES

#: Signals of a 6-DOF run: name -> (label, unit).
SIGNALS6 = {
    "x_C": ("blow-by of the confluence point (along the wind)", "m"),
    "y_C": ("lateral displacement of the confluence point", "m"),
    "z_C": ("altitude of the confluence point", "m"),
    "roll": ("roll angle", "deg"),
    "pitch": ("pitch angle", "deg"),
    "yaw": ("yaw angle from the upwind direction", "deg"),
    "beta": ("sideslip angle at the centre of volume", "deg"),
    "alpha": ("angle of attack at the centre of volume", "deg"),
    "p": ("roll rate", "deg/s"),
    "q": ("pitch rate", "deg/s"),
    "r": ("yaw rate", "deg/s"),
    "vx": ("hull velocity along the wind", "m/s"),
    "vy": ("hull velocity across the wind", "m/s"),
    "vz": ("hull vertical velocity", "m/s"),
    "tension_top": ("tether tension at the confluence point", "N"),
    "tension_winch": ("tether tension at the winch", "N"),
    "tension_max": ("largest segment tension", "N"),
    "tether_length": ("unstretched tether length", "m"),
    "wind_x": ("wind at the hull along the reference direction", "m/s"),
    "wind_y": ("wind at the hull across the reference direction", "m/s"),
    "wind_z": ("vertical wind at the hull", "m/s"),
}


def column_name(name: str) -> str:
    """CSV column of a signal with its unit, the 3-DOF export's convention (``y_C_m``,
    ``roll_deg``, ``vx_m_s``)."""
    return f"{name}_{SIGNALS6[name][1].replace('/', '_')}"


class Result6:
    """Time histories of one 6-DOF run (:func:`.sixdof.simulate6`).

    Attributes: t [s]; y (states); d (diagnostics, ``DIAG6_NAMES``); system; wind3; status (0:
    finished); message; stats.
    """

    def __init__(self, t, y, d, system, wind3, status, message, stats) -> None:
        self.t = np.asarray(t, float)
        self.y = np.asarray(y, float)
        self.d = np.asarray(d, float)
        self.system = system
        self.wind3 = wind3
        self.status = int(status)
        self.message = message
        self.stats = stats

    @property
    def ok(self) -> bool:
        return self.status == 0

    def diag(self, name: str) -> np.ndarray:
        """A raw diagnostic (``DIAG6_NAMES``, SI units)."""
        return self.d[:, DIAG6_NAMES.index(name)]

    def euler(self) -> np.ndarray:
        """(roll, pitch, yaw) [rad] per sample, yaw from the upwind direction of chi_0."""
        b = self.system.hull_index
        q = self.y[:, b + 3:b + 7]
        q = q / np.linalg.norm(q, axis=1)[:, None]
        q0, q1, q2, q3 = q.T
        roll = np.arctan2(2 * (q0 * q1 + q2 * q3), 1 - 2 * (q1 * q1 + q2 * q2))
        pitch = np.arcsin(np.clip(2 * (q0 * q2 - q3 * q1), -1.0, 1.0))
        yaw = np.arctan2(2 * (q0 * q3 + q1 * q2), 1 - 2 * (q2 * q2 + q3 * q3))
        yaw = np.angle(np.exp(1j * (yaw + math.radians(self.wind3.azimuth_deg))))
        return np.array([roll, pitch, yaw])

    def signal(self, name: str) -> np.ndarray:
        """A time history of ``SIGNALS6`` in its unit (angles in degrees)."""
        b = self.system.hull_index
        if name in ("roll", "pitch", "yaw"):
            return np.degrees(self.euler()[("roll", "pitch", "yaw").index(name)])
        if name in ("p", "q", "r"):
            return np.degrees(self.y[:, b + 10 + ("p", "q", "r").index(name)])
        simple = {"x_C": "x_top", "y_C": "y_top", "z_C": "z_top", "vx": "vx_body",
                  "vy": "vy_body", "vz": "vz_body", "tension_top": "tension_top",
                  "tension_winch": "tension_winch", "tension_max": "tension_max",
                  "tether_length": "tether_length", "wind_x": "wind_x", "wind_y": "wind_y",
                  "wind_z": "wind_z"}
        if name in simple:
            return self.diag(simple[name]).copy()
        if name in ("beta", "alpha"):
            return np.degrees(self.diag(name))
        raise KeyError(f"unknown signal {name!r}; valid: {tuple(SIGNALS6)}")

    def node_positions(self, i: int) -> np.ndarray:
        """Tether node positions (N+1, 3) [m] of sample i (winch first)."""
        return self.system.nodes(self.y[i])[0]

    def peaks(self, t_from: float = 0.0) -> dict:
        """Peak |roll|, |yaw| (from the upwind direction of the reference azimuth) and |lateral
        displacement of C| (from the vertical plane of the reference wind through the winch)
        after ``t_from`` [s]."""
        sel = self.t >= t_from
        if not np.any(sel):
            sel = np.ones_like(self.t, bool)
        roll = self.signal("roll")
        yaw = self.signal("yaw")
        lat = self.signal("y_C")
        return {
            "roll_peak_deg": float(np.max(np.abs(roll[sel]))),
            "yaw_peak_deg": float(np.max(np.abs(yaw[sel]))),
            "lateral_peak_m": float(np.max(np.abs(lat[sel]))),
        }

    def to_csv(self, header: dict | None = None) -> str:
        """CSV of every signal with its unit in the column name, after ``# key = value`` lines."""
        lines = [f"# {k} = {v}" for k, v in (header or {}).items()]
        lines.append(f"# status = {self.message}")
        names = list(SIGNALS6)
        cols = [self.t] + [self.signal(n) for n in names]
        lines.append(",".join(["t_s"] + [column_name(n) for n in names]))
        arr = np.column_stack(cols)
        lines += [",".join(f"{v:.6g}" for v in row) for row in arr]
        return "\n".join(lines) + "\n"

    def to_json(self, header: dict | None = None) -> str:
        """JSON: {"header", "status", "units", "t", "signals": {name: [...]}}."""
        out = {"header": header or {}, "status": self.message,
               "units": {"t": "s", **{n: u for n, (_l, u) in SIGNALS6.items()}},
               "t": self.t.tolist(),
               "signals": {n: self.signal(n).tolist() for n in SIGNALS6}}
        return json.dumps(out)
