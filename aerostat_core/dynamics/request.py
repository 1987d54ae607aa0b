"""The typed settings of a dynamics run: what the Dynamics page, the ``simulate`` command and the
thesis comparison ask the 3-DOF model to do (docs/dynamics.md §2, §3.4).

A :class:`DynamicsRequest` is a frozen dataclass whose every field is in the field registry
(:mod:`aerostat_core.base.fields`: label, unit, valid range, help), validated once, when it is
built; the rules that tie fields together (ramps in order, a convected gust or turbulence needs a
mean wind, a gust needs an amplitude, a custom intensity needs its W20) are checked there too.
It holds the run's settings only: the design it runs on is given beside it (none: the thesis
optimised design), so the app keys its store by the frozen design inputs and the request.

The tree: :class:`DynamicsRequest` holds the wind profile, body, tether and solver settings and,
per scenario, its :class:`SpeedChange` ramps ("varying"), :class:`GustSettings` ("gust") or
:class:`TurbulenceSettings` ("turbulence"). Fields that stand for a model input (the gust
amplitude, the tether's damping ratio, ...) take that input's label and unit from the registry
(:func:`~aerostat_core.base.fields.like`) and keep a narrower range: a run requested from the app
or the command line stays small enough to compute.

:class:`RunRequest` is what the 3-DOF and the 6-DOF requests
(:class:`~aerostat_core.dynamics.scenarios6.Request6`) share: validation at construction, the
registry's specs by dotted path, and the ``Label [unit] = value`` lines of a CSV header.

>>> dyn = DynamicsRequest.for_scenario("gust", speed=8.0)
>>> dyn.gust.amplitude_u, dyn.event_time
(5.0, 20.0)
>>> DynamicsRequest.for_scenario("gust", speed=45.0)
Traceback (most recent call last):
...
aerostat_core.base.validation.InputError: DynamicsRequest.speed = 45 m/s is outside the valid range [0, 30] m/s
"""

from __future__ import annotations

import dataclasses
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from aerostat_core.base.fields import (
    SPEC_KEY,
    FieldSpec,
    choice,
    field_spec,
    flag,
    like,
    number,
    specs,
    validate,
)
from aerostat_core.base.validation import InputError, range_text, shown_value
from aerostat_core.dynamics.options import SolverOptions
from aerostat_core.dynamics.tether import TetherModel
from aerostat_core.dynamics.turbulence import DRYDEN_W20, DrydenTurbulence
from aerostat_core.dynamics.wind import Gust, MeanProfile

SCENARIOS = ("steady", "varying", "gust", "turbulence")
#: Turbulence intensities: "profile" = W20 from the run's mean profile; "light", "moderate" and
#: "severe" the MIL-HDBK-1797 levels; "custom" the W20 given.
INTENSITIES = ("profile", "light", "moderate", "severe", "custom")
BODIES = ("hull", "point")
#: Most speed changes of one varying-wind run.
MAX_CHANGES = 20
#: Lowest mean wind that convects a gust or turbulence [m/s].
MIN_CONVECTING_SPEED = 0.5


def error_text(exc: InputError) -> str:
    """An input error in the user's words: the field's label, the value with its unit and the
    reason with the valid range ("Mean wind at the aerostat = 45 m/s is outside the valid range
    [0, 30] m/s"), never the class and field names.

    >>> try:
    ...     DynamicsRequest(duration=0.0)
    ... except InputError as exc:
    ...     print(error_text(exc))
    Simulated time = 0 s is outside the valid range (0, 3600] s
    """
    v = exc.value
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        shown = (str(v) if isinstance(v, int) else f"{v:g}") + (f" {exc.unit}" if exc.unit else "")
    else:
        shown = shown_value(v)
    return f"{exc.label} = {shown} {exc.reason}"


class RunRequest:
    """What every typed dynamics request shares (3-DOF :class:`DynamicsRequest`, 6-DOF
    ``Request6``): a frozen dataclass whose fields are in the registry, checked once by
    ``__post_init__`` (:func:`~aerostat_core.base.fields.validate`, then :meth:`check_rules` for
    the rules between fields)."""

    def __post_init__(self) -> None:
        validate(self)
        self.check_rules()

    def check_rules(self) -> None:
        """The rules between fields (none here); raise InputError naming the field."""

    @classmethod
    def spec_at(cls, path: str) -> FieldSpec:
        """The registry's spec of a field by dotted path ("speed", "gust.amplitude_u",
        "changes.0.start": a number is an index into a tuple of parts)."""
        owner: Any = cls
        *head, last = path.split(".")
        for name in head:
            if name.isdigit():
                continue
            owner = _part_type(owner, name)
        return field_spec(owner, last)

    def value_at(self, path: str) -> Any:
        """The value of a field by dotted path (see :meth:`spec_at`)."""
        obj: Any = self
        for name in path.split("."):
            obj = obj[int(name)] if name.isdigit() else getattr(obj, name)
        return obj

    def labelled(self) -> dict:
        """``{"Label [unit]": value}`` of every registry field, in declaration order (the 6-DOF
        CSV header)."""
        out = {}
        for name, spec in specs(type(self)).items():
            unit = f" [{spec.unit}]" if spec.unit else ""
            out[f"{spec.label}{unit}"] = getattr(self, name)
        return out


def _part_type(owner: type, name: str) -> type:
    parts = getattr(owner, "PARTS", {})
    if name not in parts:
        raise KeyError(f"{owner.__name__}.{name} is not a part")
    return parts[name]


def _part(label: str, default: Any, **kw: Any) -> Any:
    """A nested part (or tuple of parts) of a request, None or empty when the scenario does not
    use it (its class: the request's ``PARTS``)."""
    spec = FieldSpec(label, "part", checked=False, **kw)
    return dataclasses.field(default=default, metadata={SPEC_KEY: spec})


@dataclass(frozen=True)
class SpeedChange:
    """One change of the varying wind: from ``start`` the reference speed ramps linearly to
    ``speed`` over ``ramp`` (docs/dynamics.md §2.2)."""

    start: float = number(20.0, "Change starts at", "s", 0.0, 3600.0)
    speed: float = number(15.0, "New wind speed", "m/s", 0.0, 30.0)
    ramp: float = number(
        5.0, "Ramp time", "s", 0.1, 600.0,
        help="With the unsteady-wind inertia on, a short ramp gives a much harsher transient.")

    def __post_init__(self) -> None:
        validate(self)

    @property
    def end(self) -> float:
        """When the ramp ends [s]."""
        return self.start + self.ramp

    def as_tuple(self) -> tuple[float, float, float]:
        """(start [s], new speed [m/s], ramp time [s]), as ``SpeedSchedule.ramps`` takes it."""
        return (self.start, self.speed, self.ramp)


@dataclass(frozen=True)
class GustSettings:
    """The 1 - cos discrete gust of a run (docs/dynamics.md §2.3): the fields of
    :class:`~aerostat_core.dynamics.wind.Gust`, in a request's narrower ranges."""

    amplitude_u: float = like(Gust, "amplitude_u", 5.0, lo=-15.0, hi=15.0)
    amplitude_w: float = like(Gust, "amplitude_w", 0.0, lo=-10.0, hi=10.0)
    length: float = like(Gust, "length", 60.0, lo=5.0, hi=1000.0,
                         help="Rise time = d_m / mean wind.")
    start_time: float = like(Gust, "start_time", 20.0, lo=0.0, hi=3600.0)
    shape: str = like(Gust, "shape", "full",
                      help="full: the 1 − cos gust returns to zero; ramp-hold: it rises and "
                           "holds.")
    convected: bool = flag(
        True, "Convected with the mean wind",
        help="On (default): a frozen gust travelling with the mean wind (it reaches the winch, "
             "the tether and the hull in turn; the air carrying it does not accelerate, so no "
             "Froude–Krylov force). Off: the whole air mass changes at once.")

    def __post_init__(self) -> None:
        validate(self)
        if self.amplitude_u == 0.0 and self.amplitude_w == 0.0:
            s = field_spec(self, "amplitude_u")
            reason = ("and the vertical amplitude are both 0 m/s: give a horizontal or vertical "
                      f"amplitude; valid range {range_text(s.lo, s.hi, s.unit)}")
            raise InputError(f"GustSettings.amplitude_u = 0 m/s {reason}", owner="GustSettings",
                             field="amplitude_u", value=0.0, lo=s.lo, hi=s.hi, unit=s.unit,
                             label=s.label, reason=reason)

    def gust(self) -> Gust:
        """The model's :class:`~aerostat_core.dynamics.wind.Gust`."""
        return Gust(self.amplitude_u, self.amplitude_w, self.length, self.start_time,
                    self.shape, self.convected)


#: The W20 a turbulence request holds when its intensity is not "custom" [m/s].
_W20_DEFAULT = round(DRYDEN_W20["moderate"], 1)


@dataclass(frozen=True)
class TurbulenceSettings:
    """MIL-HDBK-1797 Dryden turbulence of a run (docs/dynamics.md §2.4): the intensity level (or
    W20 from the run's profile, or a custom W20) and the fields of
    :class:`~aerostat_core.dynamics.turbulence.DrydenTurbulence`, in a request's ranges."""

    intensity: str = choice("profile", "Turbulence intensity", INTENSITIES,
                            help="profile: W20 from the run's wind profile (the wind at 20 ft); "
                                 "light, moderate, severe: W20 = 15, 30, 45 kt; custom: the W20 "
                                 "below.", source="MIL-HDBK-1797")
    w20: float = like(DrydenTurbulence, "w20", _W20_DEFAULT, lo=0.0,
                      hi=40.0, empty="",
                      help="Read with the custom intensity only (any other keeps the default). "
                           "σ_w = 0.1 W20.")
    seed: int = like(DrydenTurbulence, "seed", 1)
    max_frequency: float = like(DrydenTurbulence, "max_frequency", 1.0, lo=0.05, hi=5.0)
    fade_in: float = like(DrydenTurbulence, "fade_in", 20.0, lo=0.0, hi=120.0,
                          help="Statistics skip the fade-in.")
    vertical: bool = flag(True, "Vertical turbulence w′")
    spatial: bool = flag(
        True, "Varies along the tether and over the hull",
        help="A frozen field convected with the mean wind, on height levels with IEC 61400-1 "
             "coherence. Off: one record, the same everywhere.")

    def __post_init__(self) -> None:
        if self.intensity != "custom":  # W20 is read with a custom intensity only
            object.__setattr__(self, "w20", _W20_DEFAULT)
        validate(self)

    @property
    def w20_used(self) -> float | None:
        """W20 of the run [m/s]: the level's, the custom one, or None (from the profile)."""
        if self.intensity == "profile":
            return None
        return DRYDEN_W20[self.intensity] if self.intensity in DRYDEN_W20 else self.w20

    def turbulence(self) -> DrydenTurbulence:
        """The model's :class:`~aerostat_core.dynamics.turbulence.DrydenTurbulence`."""
        return DrydenTurbulence(w20=self.w20_used, seed=self.seed,
                                max_frequency=self.max_frequency, fade_in=self.fade_in,
                                vertical=self.vertical, spatial=self.spatial)


@dataclass(frozen=True)
class DynamicsRequest(RunRequest):
    """Settings of one 3-DOF run (module docstring). Build with :meth:`for_scenario` (the
    scenario's defaults) or directly; the parts a scenario does not use are None (ramps: empty),
    and a part it needs and was not given takes its defaults, so equal runs compare equal.

    Raises :class:`~aerostat_core.base.validation.InputError` naming the field's label, the value
    and the valid range.
    """

    scenario: str = choice("gust", "Wind scenario", SCENARIOS,
                           help="steady; varying (speed ramps); gust (1 − cos); turbulence "
                                "(Dryden).")
    profile: str = like(MeanProfile, "kind", "uniform")
    exponent: float = like(MeanProfile, "exponent", 1.0 / 7.0, lo=0.0, hi=0.6)
    roughness: float = like(MeanProfile, "roughness_length", 0.03, lo=1e-5, hi=2.0)
    body: str = choice("hull", "Body model", BODIES,
                       help="hull: surge, heave and pitch of the design's hull; point: a point "
                            "aerostat with its mass, volume and drag area (no pitch).")
    speed: float = number(10.0, "Mean wind at the aerostat", "m/s", 0.0, 30.0,
                          help="Wind at the confluence point's static height at t = 0.")
    duration: float = number(150.0, "Simulated time", "s", 0.0, 3600.0, lo_open=True)
    segments: int = like(TetherModel, "segments", 20, lo=4, hi=80)
    damping: float = like(TetherModel, "damping_ratio", 1.0, lo=0.0, hi=5.0)
    unsteady: bool = flag(
        True, "Unsteady-wind inertia (added mass × fluid acceleration + Froude–Krylov)",
        help="Driven by the acceleration of the air itself (the material derivative): it acts "
             "in a uniform speed change and is zero for frozen convected gusts and turbulence.")
    wall: float = like(SolverOptions, "wall_time_limit", 60.0, lo=5.0, hi=600.0)
    modes: bool = flag(False, "Linearised modes about the initial equilibrium")
    changes: tuple[SpeedChange, ...] = _part("Speed changes", (), empty="not a varying wind")
    gust: GustSettings | None = _part("Discrete gust", None, empty="not a gust")
    turbulence: TurbulenceSettings | None = _part("Dryden turbulence", None,
                                                  empty="not turbulence")

    #: The class of each part (the ramps' class for ``changes``).
    PARTS = {"changes": SpeedChange, "gust": GustSettings, "turbulence": TurbulenceSettings}

    def check_rules(self) -> None:
        sc = self.scenario
        changes = tuple(self.changes or ())
        if sc == "varying" and not changes:
            changes = (SpeedChange(),)
        if sc != "varying":
            changes = ()
        for k, c in enumerate(changes):
            if not isinstance(c, SpeedChange):
                raise InputError(f"DynamicsRequest.changes[{k}] = {c!r} is not a SpeedChange",
                                 owner="DynamicsRequest", field="changes", value=c,
                                 label="Speed changes", reason="is not a SpeedChange")
        if len(changes) > MAX_CHANGES:
            reason = f"are too many; at most {MAX_CHANGES}"
            raise InputError(f"DynamicsRequest.changes: {len(changes)} {reason}",
                             owner="DynamicsRequest", field="changes", value=len(changes),
                             label="Speed changes", reason=reason)
        for k in range(1, len(changes)):
            before, c = changes[k - 1], changes[k]
            if c.start < before.end - 1e-9:
                s = field_spec(SpeedChange, "start")
                reason = (f"must be after the previous ramp ends; valid range "
                          f"{range_text(before.end, s.hi, s.unit)}")
                raise InputError(
                    f"SpeedChange.start = {c.start:g} s (change {k + 1}) {reason}",
                    owner="SpeedChange", field="start", value=c.start, lo=before.end, hi=s.hi,
                    unit=s.unit, label=f"{s.label} (change {k + 1})", reason=reason)
        object.__setattr__(self, "changes", changes)
        self._fill("gust", GustSettings)
        self._fill("turbulence", TurbulenceSettings)
        if sc in ("gust", "turbulence") and self.speed < MIN_CONVECTING_SPEED:
            s = field_spec(self, "speed")
            reason = (f"is too little: a {'gust' if sc == 'gust' else 'turbulence'} needs at "
                      f"least {MIN_CONVECTING_SPEED:g} m/s to be convected; valid range "
                      f"{range_text(MIN_CONVECTING_SPEED, s.hi, s.unit)}")
            raise InputError(f"DynamicsRequest.speed = {self.speed:g} m/s {reason}",
                             owner="DynamicsRequest", field="speed", value=self.speed,
                             lo=MIN_CONVECTING_SPEED, hi=s.hi, unit=s.unit, label=s.label,
                             reason=reason)

    def _fill(self, name: str, cls: type) -> None:
        value = getattr(self, name)
        if self.scenario != name:
            value = None
        elif value is None:
            value = cls()
        elif not isinstance(value, cls):
            raise InputError(f"DynamicsRequest.{name} = {value!r} is not a {cls.__name__}",
                             owner="DynamicsRequest", field=name, value=value,
                             label=field_spec(self, name).label, reason=f"is not a {cls.__name__}")
        object.__setattr__(self, name, value)

    @classmethod
    def for_scenario(cls, scenario: str = "gust", **changes: Any) -> DynamicsRequest:
        """The defaults of ``scenario`` with ``changes`` (field names of this class)."""
        return cls(scenario=scenario, **changes)

    @property
    def event_time(self) -> float | None:
        """Time of the scenario's event [s] (the first ramp's start or the gust's), else None."""
        if self.scenario == "varying":
            return float(self.changes[0].start)
        if self.scenario == "gust":
            return float(self.gust.start_time)
        return None

    def to_dict(self) -> dict:
        """The request as plain data (the CSV header's values; the keys the untyped request
        had): the fields and, for its scenario, ``changes`` [(start, speed, ramp)], ``gust``
        {u, w, length, start, shape, convected} or ``turbulence`` {intensity, w20, seed,
        max_frequency, fade_in, vertical, spatial}."""
        out: dict[str, Any] = {
            k: getattr(self, k)
            for k in ("scenario", "profile", "exponent", "roughness", "body", "speed",
                      "duration", "segments", "damping", "unsteady", "wall", "modes")
        }
        if self.scenario == "varying":
            out["changes"] = [c.as_tuple() for c in self.changes]
        elif self.scenario == "gust":
            g = self.gust
            out["gust"] = {"u": g.amplitude_u, "w": g.amplitude_w, "length": g.length,
                           "start": g.start_time, "shape": g.shape, "convected": g.convected}
        elif self.scenario == "turbulence":
            t = self.turbulence
            out["turbulence"] = {"intensity": t.intensity, "w20": t.w20_used, "seed": t.seed,
                                 "max_frequency": t.max_frequency, "fade_in": t.fade_in,
                                 "vertical": t.vertical, "spatial": t.spatial}
        return out

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> DynamicsRequest:
        """A request from the plain data of :meth:`to_dict` (the untyped request of earlier
        releases; its ``source`` and ``inputs`` keys are not settings and are ignored)."""
        known = {f.name for f in dataclasses.fields(cls)}
        kw = {k: v for k, v in data.items() if k in known and k not in
              ("changes", "gust", "turbulence")}
        if "changes" in data and data["changes"] is not None:
            kw["changes"] = tuple(SpeedChange(*c) for c in data["changes"])
        if data.get("gust") is not None:
            g = data["gust"]
            kw["gust"] = GustSettings(g["u"], g["w"], g["length"], g["start"],
                                      g.get("shape", "full"), g.get("convected", True))
        if data.get("turbulence") is not None:
            t = data["turbulence"]
            inten = t.get("intensity", "custom")
            extra = {"w20": t["w20"]} if inten == "custom" and t.get("w20") is not None else {}
            kw["turbulence"] = TurbulenceSettings(
                intensity=inten, seed=t["seed"], max_frequency=t["max_frequency"],
                fade_in=t["fade_in"], vertical=t["vertical"], spatial=t.get("spatial", True),
                **extra)
        return cls(**kw)

    def __getitem__(self, key: str) -> Any:
        """Deprecated: the dict reads of the untyped request (``dyn["speed"]``); read the
        attribute (``dyn.speed``). Kept one release (docs/architecture.md §7)."""
        warnings.warn(f"DynamicsRequest[{key!r}] is deprecated; read the attribute "
                      "(the request is typed)", DeprecationWarning, stacklevel=2)
        return self.to_dict()[key]
