"""The design report as typed data: :class:`DesignReport` and its parts (the core-to-UI contract).

:func:`aerostat_core.output.report.design_report` builds these from a :class:`~aerostat_core.model.design.Design`;
the pages, the plots and the CLI read them as attributes (``rep.perf.blow_by``,
``rep.summary.blow_by_at_design_wind_m``). Each part is a frozen dataclass with SI units (written in
its docstring) and a ``to_dict()`` that gives the plain nested dict the report was before it was
typed. Reading a part by key (``rep["perf"]["blow_by"]``) still works for one release and emits a
``DeprecationWarning`` pointing at the caller's line (docs/architecture.md §7).

Shapes: ``n`` is the number of sweep wind speeds (``PerformanceTable.wind_speed``), ``nodes`` the
number of tether nodes (node 0 the confluence point, the last the winch).
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from aerostat_core.model.design import DesignSummary, FrozenMapping


def _plain(value: Any) -> Any:
    """A field value as in the report's plain dict: parts as dicts, tuples of items as lists."""
    if isinstance(value, ReportPart):
        return value.to_dict()
    if isinstance(value, tuple):
        return list(value)
    return value


class ReportPart(FrozenMapping):
    """Base of the report's parts: attribute access, a deprecated read-only mapping view and
    :meth:`to_dict` (the plain form of before)."""

    # Parts hold arrays: compare and hash them by identity (a Mapping's dict equality would
    # compare arrays element-wise and raise "truth value of an array is ambiguous").
    __eq__ = object.__eq__
    __hash__ = object.__hash__

    def _view(self) -> dict:
        """Legacy key reads: nested parts stay parts (so ``rep["tether"]["design"]["x"]`` and
        ``rep["tether"].design.x`` both read), other values as in :meth:`to_dict`."""
        out = self.to_dict()
        for f in fields(self):
            if isinstance(getattr(self, f.name), ReportPart):
                out[f.name] = getattr(self, f.name)
        return out

    def __getitem__(self, key: str) -> Any:
        _warn_key(self, key)
        return self._view()[key]

    def get(self, key: str, default: Any = None) -> Any:
        _warn_key(self, key)
        return self._view().get(key, default)

    def __contains__(self, key: object) -> bool:  # a membership test reads no value: no warning
        return key in self._view()

    def to_dict(self) -> dict[str, Any]:
        """The part as a plain dict (nested parts as dicts), as the report was before typing."""
        return {f.name: _plain(getattr(self, f.name)) for f in fields(self)}


def _warn_key(part: ReportPart, key: str) -> None:
    warnings.warn(
        f"reading the design report by key ([{key!r}]) is deprecated; read the attribute "
        f"{type(part).__name__}.{key}",
        DeprecationWarning,
        stacklevel=3,
    )


@dataclass(frozen=True, eq=False)
class PerformanceCurves(ReportPart):
    """The performance table versus wind as arrays of shape (n,) (aerostat_core.model.performance).

    Attributes
    ----------
    wind_speed : ndarray of float
        Sweep wind speeds at the flying height [m/s].
    alpha_eq : ndarray of float
        Trim angle of attack [deg].
    dynamic_lift, drag : ndarray of float
        Aerodynamic lift and drag of the trimmed aerostat [N].
    blow_by, flying_height : ndarray of float
        Downwind distance of the confluence point from the winch and its height [m].
    tension_top, tension_winch : ndarray of float
        Tether tension at the confluence point and at the winch [N].
    safety_factor : ndarray of float
        Tether breaking strength / top tension [-].
    limited : ndarray of bool
        True where a requirement is exceeded at that speed.
    flag_text : tuple of str
        Plain-language flags of each speed ("" when none); a list in :meth:`to_dict`.
    """

    wind_speed: np.ndarray
    alpha_eq: np.ndarray
    dynamic_lift: np.ndarray
    drag: np.ndarray
    blow_by: np.ndarray
    flying_height: np.ndarray
    tension_top: np.ndarray
    tension_winch: np.ndarray
    safety_factor: np.ndarray
    limited: np.ndarray
    flag_text: tuple[str, ...]

    def __post_init__(self) -> None:
        n = np.shape(self.wind_speed)
        for f in fields(self):
            if f.name != "flag_text" and np.shape(getattr(self, f.name)) != n:
                raise ValueError(
                    f"PerformanceCurves.{f.name} has shape {np.shape(getattr(self, f.name))}, "
                    f"the sweep {n}"
                )
        if (len(self.flag_text),) != n:
            raise ValueError(
                f"PerformanceCurves.flag_text has {len(self.flag_text)} rows, the sweep {n}"
            )


@dataclass(frozen=True, eq=False)
class MomentCurve(ReportPart):
    """Pitching-moment coefficient about the confluence point versus angle of attack at one wind
    (aerostat_core.model.performance.cm_curve).

    Attributes
    ----------
    alpha_deg : ndarray of float, shape (m,)
        Angles of attack [deg].
    cm : ndarray of float, shape (m,)
        C_m about the confluence point [-].
    alpha_eq_deg : float
        Trim angle at the design wind [deg].
    wind : float
        Wind speed of the curve [m/s] (the design wind; 10 m/s when that is 0).
    """

    alpha_deg: np.ndarray
    cm: np.ndarray
    alpha_eq_deg: float
    wind: float

    def __post_init__(self) -> None:
        if np.shape(self.alpha_deg) != np.shape(self.cm):
            raise ValueError(
                f"MomentCurve: alpha_deg {np.shape(self.alpha_deg)} and cm {np.shape(self.cm)} differ"
            )


@dataclass(frozen=True, eq=False)
class TetherProfile(ReportPart):
    """One tether shape from the winch (origin): x downwind, z up [m], shape (nodes,) each, at
    ``wind`` [m/s]."""

    x: np.ndarray
    z: np.ndarray
    wind: float

    def __post_init__(self) -> None:
        if np.shape(self.x) != np.shape(self.z) or np.ndim(self.x) != 1:
            raise ValueError(
                f"TetherProfile: x {np.shape(self.x)} and z {np.shape(self.z)} "
                "must be one-dimensional of one length"
            )


@dataclass(frozen=True, eq=False)
class TetherProfiles(ReportPart):
    """The tether shapes of the wind sweep and at the design wind (aerostat_core.tether.statics).

    Attributes
    ----------
    x, z : ndarray of float, shape (nodes, n)
        Downwind distance and height from the winch [m]; column j at ``wind_speed[j]``.
    wind_speed : ndarray of float, shape (n,)
        The sweep wind speeds [m/s].
    design : TetherProfile or None
        The shape at the design wind (its own solution, also when the sweep steps over it);
        None only when converted from a dict without one (:func:`tether_profiles`).
    """

    x: np.ndarray
    z: np.ndarray
    wind_speed: np.ndarray
    design: TetherProfile | None = None

    def __post_init__(self) -> None:
        n = np.size(self.wind_speed)
        if np.ndim(self.x) != 2 or np.shape(self.x) != np.shape(self.z) or np.shape(self.x)[1] != n:
            raise ValueError(
                f"TetherProfiles: x {np.shape(self.x)} and z {np.shape(self.z)} must be "
                f"(nodes, {n}), one column per sweep speed"
            )


@dataclass(frozen=True)
class HullDimensions(ReportPart):
    """Hull profile parameters and size [m]: NPL semi-axes a1 (nose to the maximum radius), a2
    (maximum radius to the tail) and b (maximum radius), length a1 + a2, diameter 2b (for the
    other shapes, the same length and diameter with the shape's own profile), and xi_cb, the
    station of the centre of buoyancy from the nose."""

    a1: float
    a2: float
    b: float
    length: float
    diameter: float
    xi_cb: float


@dataclass(frozen=True, eq=False)
class FinView(ReportPart):
    """The fins as drawn: ``outlines``, one array (5, 3) of (xi, y, z) corners [m] per fin,
    closed (:func:`aerostat_core.output.report.fin_outlines`), and the ``arrangement`` name
    (``fins.ARRANGEMENT_ANGLES_DEG``)."""

    outlines: tuple[np.ndarray, ...]
    arrangement: str

    def __post_init__(self) -> None:
        for k, o in enumerate(self.outlines):
            if np.shape(o) != (5, 3):
                raise ValueError(f"FinView.outlines[{k}] has shape {np.shape(o)}, not (5, 3)")


@dataclass(frozen=True)
class KeyPoints(ReportPart):
    """Marked points of the side view, each (xi, z) [m] in the body frame (origin at the nose,
    z up): centre of buoyancy ``cb``, centre of gravity ``cg`` and confluence point ``c``."""

    cb: tuple[float, float]
    cg: tuple[float, float]
    c: tuple[float, float]

    def __post_init__(self) -> None:
        for f in fields(self):
            x, z = getattr(self, f.name)
            object.__setattr__(self, f.name, (float(x), float(z)))

    def to_dict(self) -> dict[str, Any]:
        """{"cb": (xi, z), "cg": ..., "c": ...} [m] (tuples, as before)."""
        return {f.name: getattr(self, f.name) for f in fields(self)}


@dataclass(frozen=True)
class DesignLimits(ReportPart):
    """The requirement lines drawn on the plots: blow-by limit [m] and design wind [m/s], the
    minimum tether safety factor [-], the operating altitude [m] and the fin stall angle [deg]."""

    blow_by_limit: float
    design_wind: float
    min_safety_factor: float
    altitude: float
    stall_deg: float


@dataclass(frozen=True, eq=False)
class DesignReport(ReportPart):
    """Everything the design page shows, as typed data (the core-to-UI contract).

    Attributes
    ----------
    summary : DesignSummary
        Headline numbers (:meth:`Design.summary`).
    constraints : list of dict
        The constraint table rows (:meth:`ConstraintState.rows`): constraint, label, checked_at,
        value, limit, margin (in ``unit``), met, g. Rows, like the other tables: their one
        definition is ``ConstraintState.rows``, which the HTML report reads too.
    violations : tuple of str
        Plain-language reasons the design fails its requirements (empty when feasible).
    feasible, sized : bool
        Every constraint met; the volume was sized (not given).
    geometry_rows, mass_rows, performance_rows : list of dict
        Table rows, units in the keys.
    perf : PerformanceCurves
    cm : MomentCurve
    tether : TetherProfiles
    shape : str
        Hull shape name.
    hull : HullDimensions
    fins : FinView
    points : KeyPoints
    confluence_lines : list of ndarray
        Schematic confluence lines, each (2, 2) of (xi, z) [m].
    limits : DesignLimits
    inputs : dict
        The inputs (:func:`aerostat_core.model.io.inputs_to_dict`).

    :meth:`to_dict` gives the plain nested dict of before; ``report["perf"]`` still reads (and
    warns) for one release.
    """

    summary: DesignSummary
    constraints: list
    violations: tuple[str, ...]
    feasible: bool
    sized: bool
    geometry_rows: list
    mass_rows: list
    performance_rows: list
    perf: PerformanceCurves
    cm: MomentCurve
    tether: TetherProfiles
    shape: str
    hull: HullDimensions
    fins: FinView
    points: KeyPoints
    confluence_lines: list
    limits: DesignLimits
    inputs: dict

    def _view(self) -> dict:
        out = {f.name: getattr(self, f.name) for f in fields(self)}
        out["violations"] = list(self.violations)
        return out

    def to_dict(self) -> dict[str, Any]:
        """The report as the plain nested dict of before (every part a dict)."""
        out = super().to_dict()
        out["summary"] = self.summary.to_dict()
        return out


def tether_profiles(tether: TetherProfiles | Mapping[str, Any]) -> TetherProfiles:
    """``tether`` as :class:`TetherProfiles` (a plain ``{"x", "z", "wind_speed", "design"}`` dict,
    as the report was before it was typed, is converted)."""
    if isinstance(tether, TetherProfiles):
        return tether
    design = tether.get("design")
    if design is not None and not isinstance(design, TetherProfile):
        design = TetherProfile(
            np.asarray(design["x"], float), np.asarray(design["z"], float), float(design["wind"])
        )
    return TetherProfiles(
        np.asarray(tether["x"], float),
        np.asarray(tether["z"], float),
        np.asarray(tether["wind_speed"], float),
        design,
    )


__all__ = [
    "DesignLimits",
    "DesignReport",
    "FinView",
    "HullDimensions",
    "KeyPoints",
    "MomentCurve",
    "PerformanceCurves",
    "ReportPart",
    "TetherProfile",
    "TetherProfiles",
    "tether_profiles",
]
