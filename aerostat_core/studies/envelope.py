"""Operating envelope: which constraint of the table binds first, over wind x altitude (x payload).

A built aerostat (fixed hull volume, fins, fabric and tether type) is flown at wind speed U (at the
aerostat), operating altitude h (tether length = h, as in the sizing) and payload m_p. At every
point the wind-dependent rows of the constraint table (:mod:`aerostat_core.model.constraints`) are
evaluated at U with the design-wind limits, and the static rows (free lift, fins on the hull) at
the point's altitude and payload; the binding constraint is the one with the largest normalised
value g (docs/methods.md §1.12), and its margin is given in that constraint's own unit. The
survival-wind safety factor is a property of the requirement, not of a wind speed, and is left
out (at every wind the operating safety factor row applies), as in
:func:`aerostat_core.model.constraints.wind_flags`.

Length limits scale with the tether length: a blow-by or altitude-loss limit L0 set for the
design altitude h0 becomes L0 h/h0 at altitude h (the rule sets state every limit as a fraction
of the tether length, :mod:`aerostat_core.model.rules`).

The map is one vectorised trim + tether solve over the wind axis per (altitude, payload) pair;
the pairs are independent blocks, which :mod:`aerostat_core.studies.scale` can map over a Dask cluster.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from aerostat_core.model.airframe import build_airframe
from aerostat_core.model.constraints import CONSTRAINTS, static_quantities, wind_quantities
from aerostat_core.model.design import Design
from aerostat_core.model.inputs import Configuration, Requirement
from aerostat_core.model.performance import evaluate

#: Constraints mapped by the envelope (the table without the survival-wind row), in table order.
ENVELOPE_CONSTRAINTS = tuple(c for c in CONSTRAINTS if c.at != "survival")
#: Their names (the last axis of ``Envelope.g``).
ENVELOPE_NAMES = tuple(c.name for c in ENVELOPE_CONSTRAINTS)
_TOL = np.array([c.tolerance for c in ENVELOPE_CONSTRAINTS])

#: Largest number of envelope points in one call (memory: ~10 arrays of this many floats per
#: constraint).
MAX_POINTS = 2_000_000


def requirement_at(req: Requirement, altitude: float, payload: float | None = None) -> Requirement:
    """The resolved requirement ``req`` moved to ``altitude`` [m] (and ``payload`` [kg]).

    Blow-by and altitude-loss limits scale with the tether length, L(h) = L(h0) h / h0
    (the rule sets' fractions of the tether length); the blow-by limit is capped at h (its valid
    range) and the altitude-loss limit at 3000 m.
    """
    req = req.resolved()
    s = float(altitude) / float(req.altitude)
    changes = {
        "altitude": float(altitude),
        "blow_by_limit": min(req.blow_by_limit * s, float(altitude)),
        "altitude_loss_limit": min(req.altitude_loss_limit * s, 3000.0),
    }
    if payload is not None:
        changes["payload_mass"] = float(payload)
    return replace(req, **changes)


def point_state(req: Requirement, cfg: Configuration, volume: float, wind) -> tuple:
    """g and margin of every envelope constraint for one (altitude, payload) at winds ``wind``.

    Parameters
    ----------
    req : Requirement
        Resolved, at the point's altitude and payload (:func:`requirement_at`).
    cfg : Configuration
    volume : float
        Hull volume [m3].
    wind : array_like, shape (W,)
        Wind at the aerostat [m/s], valid [0, 60].

    Returns
    -------
    g, margin : ndarray, shape (W, len(ENVELOPE_NAMES))
    """
    wind = np.asarray(wind, float)
    af = build_airframe(req, cfg, float(volume))
    ev = evaluate(req, cfg, af, wind)
    wq = wind_quantities(req, cfg, ev)
    sq = static_quantities(req, af, cfg)
    g = np.empty(wind.shape + (len(ENVELOPE_NAMES),))
    m = np.empty_like(g)
    for k, c in enumerate(ENVELOPE_CONSTRAINTS):
        src = sq if c.at == "static" else wq
        g[..., k] = np.broadcast_to(np.asarray(src[c.name][2], float).reshape(-1), wind.shape)
        m[..., k] = np.broadcast_to(np.asarray(src[c.name][3], float).reshape(-1), wind.shape)
    return g, m


def envelope_block(req: Requirement, cfg: Configuration, volume: float, wind, pairs) -> tuple:
    """:func:`point_state` for a list of (altitude, payload) pairs; stacked (len(pairs), W, K).

    A pure function of its arguments: the unit of work that :mod:`aerostat_core.studies.scale` maps.
    """
    gs, ms = [], []
    for h, p in pairs:
        g, m = point_state(requirement_at(req, h, p), cfg, volume, wind)
        gs.append(g)
        ms.append(m)
    return np.stack(gs), np.stack(ms)


@dataclass(frozen=True)
class Envelope:
    """The operating envelope of one built aerostat.

    Attributes
    ----------
    wind : ndarray, shape (W,)
        Wind at the aerostat [m/s].
    altitude : ndarray, shape (A,)
        Operating altitude = tether length [m].
    payload : ndarray, shape (P,)
        Payload [kg] (one value unless the payload axis was asked for).
    g, margin : ndarray, shape (P, A, W, K)
        Normalised constraint value (met when <= tolerance) and margin in the constraint's unit,
        for the constraints :data:`ENVELOPE_NAMES`.
    volume : float
        Hull volume of the aerostat [m3].
    design_altitude, design_payload, design_wind : float
        The requirement the aerostat was designed for.
    """

    wind: np.ndarray
    altitude: np.ndarray
    payload: np.ndarray
    g: np.ndarray
    margin: np.ndarray
    volume: float
    design_altitude: float
    design_payload: float
    design_wind: float

    names = ENVELOPE_NAMES

    @property
    def points(self) -> int:
        """Number of (payload, altitude, wind) points."""
        return int(np.prod(self.g.shape[:-1]))

    @property
    def met(self) -> np.ndarray:
        """Per constraint: g <= tolerance, shape (P, A, W, K)."""
        return self.g <= _TOL

    @property
    def flyable(self) -> np.ndarray:
        """Every constraint met, shape (P, A, W)."""
        return self.met.all(axis=-1)

    @property
    def binding_index(self) -> np.ndarray:
        """Index into :data:`ENVELOPE_NAMES` of the constraint with the largest g, (P, A, W)."""
        return np.argmax(self.g, axis=-1)

    @property
    def max_g(self) -> np.ndarray:
        """Largest g over the constraints (the binding one's), (P, A, W)."""
        return np.max(self.g, axis=-1)

    @property
    def binding_margin(self) -> np.ndarray:
        """Margin of the binding constraint in its own unit, (P, A, W)."""
        return np.take_along_axis(self.margin, self.binding_index[..., None], axis=-1)[..., 0]

    def binding_names(self) -> np.ndarray:
        """Name of the binding constraint at every point, (P, A, W)."""
        return np.asarray(ENVELOPE_NAMES)[self.binding_index]

    def limit_wind(self) -> np.ndarray:
        """Highest wind of the grid up to which every grid wind from the lowest is flyable [m/s],
        shape (P, A); NaN where the lowest wind is already not flyable. Linear interpolation of
        the largest g between the last flyable and the first unflyable grid wind."""
        fly = self.flyable
        out = np.full(fly.shape[:-1], np.nan)
        mg = self.max_g
        for idx in np.ndindex(*fly.shape[:-1]):
            row = fly[idx]
            if not row[0]:
                continue
            bad = np.flatnonzero(~row)
            if bad.size == 0:
                out[idx] = self.wind[-1]
                continue
            j = bad[0]
            g0, g1 = mg[idx][j - 1], mg[idx][j]
            t = 0.0 if g1 == g0 else float(np.clip((0.0 - g0) / (g1 - g0), 0.0, 1.0))
            out[idx] = self.wind[j - 1] + t * (self.wind[j] - self.wind[j - 1])
        return out

    def rows(self) -> list[dict]:
        """One dict per point: wind_m_s, altitude_m, payload_kg, binding, margin, unit, g,
        flyable (for JSON and CSV)."""
        units = {c.name: c.unit for c in ENVELOPE_CONSTRAINTS}
        names = self.binding_names()
        marg, mg, fly = self.binding_margin, self.max_g, self.flyable
        out = []
        for ip, p in enumerate(self.payload):
            for ia, h in enumerate(self.altitude):
                for iw, u in enumerate(self.wind):
                    n = str(names[ip, ia, iw])
                    out.append(
                        {
                            "wind_m_s": float(u),
                            "altitude_m": float(h),
                            "payload_kg": float(p),
                            "binding": n,
                            "margin": float(marg[ip, ia, iw]),
                            "unit": units[n],
                            "g": float(mg[ip, ia, iw]),
                            "flyable": bool(fly[ip, ia, iw]),
                        }
                    )
        return out


def _grid(name: str, values, lo: float, hi: float, unit: str) -> np.ndarray:
    a = np.asarray(values, float).reshape(-1)
    if a.size == 0:
        raise ValueError(
            f"envelope {name}: no values; give at least one in [{lo:g}, {hi:g}] {unit}"
        )
    if not np.all(np.isfinite(a)) or a.min() < lo or a.max() > hi:
        bad = a[~np.isfinite(a) | (a < lo) | (a > hi)][0]
        raise ValueError(
            f"envelope {name} = {bad:g} {unit} is outside the valid range [{lo:g}, {hi:g}] {unit}"
        )
    return a


def default_axes(d: Design, n_wind: int = 61, n_altitude: int = 21) -> tuple:
    """Default grid: wind 0 ... max(1.5 x survival wind, sweep maximum) and altitude
    0.25 ... 2 x the design altitude (within [10, 3000] m), with the design altitude itself."""
    req = d.requirement
    top = min(max(1.5 * float(req.survival_wind), float(req.wind_max), 5.0), 60.0)
    h0 = float(req.altitude)
    alt = np.linspace(max(10.0, 0.25 * h0), min(2.0 * h0, 3000.0), n_altitude)
    return np.linspace(0.0, top, n_wind), np.union1d(alt, [h0])


def operating_envelope(
    d: Design, wind=None, altitude=None, payload=None, client=None, chunk: int = 8
) -> Envelope:
    """Map the constraint table over wind x altitude (x payload) for the built aerostat ``d``.

    Parameters
    ----------
    d : Design
        The aerostat (its hull volume, fins, fabric, tether and gas are kept).
    wind : array_like, optional
        Wind at the aerostat [m/s], valid [0, 60]; default :func:`default_axes`.
    altitude : array_like, optional
        Operating altitude = tether length [m], valid [10, 3000]; default :func:`default_axes`.
    payload : array_like, optional
        Payload [kg], valid (0, 500]; default the design payload only.
    client : dask.distributed.Client or str, optional
        Map the (altitude, payload) blocks over a Dask cluster (:mod:`aerostat_core.studies.scale`);
        ``None`` runs in this process. Same result either way.
    chunk : int
        (altitude, payload) pairs per task.

    Returns
    -------
    Envelope
    """
    from aerostat_core.studies.scale import map_blocks

    req = d.requirement
    w_def, h_def = default_axes(d)
    wind = _grid("wind", w_def if wind is None else wind, 0.0, 60.0, "m/s")
    altitude = _grid("altitude", h_def if altitude is None else altitude, 10.0, 3000.0, "m")
    payload = _grid(
        "payload", [req.payload_mass] if payload is None else payload, 1e-9, 500.0, "kg"
    )
    n = wind.size * altitude.size * payload.size
    if n > MAX_POINTS:
        raise ValueError(
            f"envelope has {n} points, more than the {MAX_POINTS} allowed in one call;"
            " use fewer wind, altitude or payload values"
        )
    pairs = [(float(h), float(p)) for p in payload for h in altitude]
    blocks = [pairs[i : i + chunk] for i in range(0, len(pairs), chunk)]
    results = map_blocks(
        envelope_block, [(req, d.configuration, d.volume, wind, b) for b in blocks], client=client
    )
    g = np.concatenate([r[0] for r in results]).reshape(payload.size, altitude.size, wind.size, -1)
    m = np.concatenate([r[1] for r in results]).reshape(g.shape)
    return Envelope(
        wind=wind,
        altitude=altitude,
        payload=payload,
        g=g,
        margin=m,
        volume=float(d.volume),
        design_altitude=float(req.altitude),
        design_payload=float(req.payload_mass),
        design_wind=float(req.design_wind),
    )
