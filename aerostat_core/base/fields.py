"""The field registry: every input's label, unit, valid range, display hints and help, once.

Each input dataclass declares its fields with :func:`number`, :func:`integer`, :func:`choice`,
:func:`flag`, :func:`text` or :func:`part` (or :func:`like`, a field standing for another
class' field with a narrower range), which put a :class:`FieldSpec` in the ``dataclasses.field``
metadata. Everything else reads it from there:

* validation: :func:`validate` checks every numeric and choice field of an instance against its
  spec (a ``__post_init__`` keeps only the cross-field checks explicit), and the
  :class:`~aerostat_core.base.validation.InputError` it raises carries the spec's range, unit and label;
* the app's form (``app_ui.form_model``): label, display unit and scale, step, format and help;
* report column names (:func:`column_label`, :func:`report_table`);
* the optimiser's variable info (:func:`variable_info`).

Ranges are in SI units (the unit in ``FieldSpec.unit``); a display is ``SI value * scale`` in
``display_unit``. The registry has no UI imports and knows no input class: the walk through the
input tree (column labels, report table, optimiser variables) is :mod:`aerostat_core.model.input_paths`.
"""

from __future__ import annotations

import dataclasses
import functools
import inspect
import math
import re
from collections.abc import Iterable
from dataclasses import dataclass
from types import ModuleType
from typing import Any

from aerostat_core.base.validation import (
    InputError,
    check_choice,
    check_int,
    check_number,
    shown_value,
)

#: Key of the spec in ``dataclasses.Field.metadata``.
SPEC_KEY = "aerostat_spec"

#: Readable form of the SI unit tokens used in messages (a spec may set its own display unit).
_PRETTY_UNIT = {
    "m3": "m³",
    "m2": "m²",
    "kg/m3": "kg/m³",
    "kg/m2": "kg/m²",
    "USD/m3": "USD/m³",
    "degC": "°C",
    "m/s2": "m/s²",
    "A/m2": "A/m²",
    "L/(m2 day atm)": "L/(m² day atm)",
}
#: CSV column suffix of each SI unit (column names are public: keep them stable).
_CSV_UNIT = {
    "m/s": "m_s",
    "kg/m3": "kg_m3",
    "kg/m2": "kg_m2",
    "kg/m": "kg_m",
    "1/rad": "per_rad",
    "USD/m3": "USD_m3",
    "N/m": "N_m",
    "L/(m2 day atm)": "L_m2_day_atm",
    "Wh/kg": "Wh_kg",
    "A/m2": "A_m2",
    "%": "pct",
    "m/s2": "m_s2",
}


@dataclass(frozen=True)
class FieldSpec:
    """What is known about one input field.

    Attributes
    ----------
    label : str
        Readable name, without unit ("Payload mass").
    kind : {"number", "integer", "choice", "flag", "text", "part"}
        ``"part"`` is a nested input dataclass (its fields carry their own specs); ``"flag"``
        a yes/no value (``bool``).
    unit : str
        SI unit of the value and of the range, as in messages ("kg", "m3", "degC"); "" for a
        dimensionless value.
    lo, hi : float or None
        Valid range in SI units; ``None`` for no range (choices, text).
    lo_open, hi_open : bool
        Whether the bounds are excluded.
    scale : float
        Display value = SI value * scale (100 for a fraction shown in %).
    display_unit : str
        Unit of the displayed value ("%", "g/m²"); "-" for a dimensionless one.
    step, fmt : float, str
        Step and format hints for an input box.
    help : str
        What the field means, in the user's words (the valid range is added by the UI).
    source : str
        Where the default or the range comes from (a docs/ section, a paper).
    empty : str
        What ``None`` means ("rule set", "Hoerner"); non-empty marks the field optional.
    choices : tuple of str
        Allowed values of a choice field.
    hi_field : str or None
        Name of the field of the same object whose value is the upper bound (the blow-by limit is
        at most the altitude); ``hi`` is then the largest value that field may take.
    checked : bool
        False when ``__post_init__`` checks the field itself (a range that depends on another
        field, such as the fineness ratio on the hull shape); :func:`validate` skips it.
    allow_inf : bool
        ``math.inf`` is accepted as well (an inextensible tether's EA).
    prefix : bool
        For a ``"part"``: its label prefixes the labels of its fields in column names
        ("Hull fabric" + "areal density").
    csv_unit : str or None
        CSV column suffix, when it is not derived from ``unit``.
    """

    label: str
    kind: str = "number"
    unit: str = ""
    lo: float | None = None
    hi: float | None = None
    lo_open: bool = False
    hi_open: bool = False
    scale: float = 1.0
    display_unit: str = ""
    step: float | None = None
    fmt: str = "%.2f"
    help: str = ""
    source: str = ""
    empty: str = ""
    choices: tuple[str, ...] = ()
    hi_field: str | None = None
    checked: bool = True
    allow_inf: bool = False
    prefix: bool = False
    csv_unit: str | None = None

    @property
    def optional(self) -> bool:
        """Whether ``None`` is a valid value (the engine's automatic value)."""
        return bool(self.empty)

    @property
    def integer(self) -> bool:
        return self.kind == "integer"

    @property
    def shown_unit(self) -> str:
        """The display unit, "-" for a dimensionless number, "" for a choice or text."""
        if self.kind not in ("number", "integer"):
            return ""
        return self.display_unit or _PRETTY_UNIT.get(self.unit, self.unit) or "-"

    @property
    def csv_token(self) -> str:
        """CSV column suffix of the SI value ("m_s", "kg"); "" when dimensionless."""
        if self.csv_unit is not None:
            return self.csv_unit
        return _CSV_UNIT.get(self.unit, self.unit)

    def range_text(self) -> str:
        """The valid range in display units, e.g. ``"(0, 500] kg"``, ``"[40, 95] % of hull
        length"``; empty when the field has no range."""
        if self.lo is None or self.hi is None:
            return ""
        lo, hi = _clean(self.lo * self.scale), _clean(self.hi * self.scale)
        unit = self.shown_unit
        u = f" {unit}" if unit and unit != "-" else ""
        left, right = "(" if self.lo_open else "[", ")" if self.hi_open else "]"
        return f"{left}{lo:g}, {hi:g}{right}{u}"

    def si_range_text(self) -> str:
        """The valid range in the SI unit of the value, as a model function takes it, e.g.
        ``"(0, 2] kg/m2"``, ``"(0, 1]"`` for a fraction; empty when the field has no range.

        >>> FieldSpec("Gas purity", lo=0, hi=1, lo_open=True, scale=100.0).si_range_text()
        '(0, 1]'
        """
        if self.lo is None or self.hi is None:
            return ""
        left, right = "(" if self.lo_open else "[", ")" if self.hi_open else "]"
        u = f" {self.unit}" if self.unit else ""
        return f"{left}{_clean(self.lo):g}, {_clean(self.hi):g}{right}{u}"


def _clean(x: float) -> float:
    return float(f"{x:.12g}")


def _spec_field(default: Any, spec: FieldSpec, default_factory: Any = None) -> Any:
    meta = {SPEC_KEY: spec}
    if default_factory is not None:
        return dataclasses.field(default_factory=default_factory, metadata=meta)
    return dataclasses.field(default=default, metadata=meta)


def number(
    default: float | None,
    label: str,
    unit: str = "",
    lo: float | None = None,
    hi: float | None = None,
    **kw: Any,
) -> Any:
    """A numeric dataclass field with its spec (keywords: the other :class:`FieldSpec`
    attributes). Use as ``payload_mass: float = number(10.0, "Payload mass", "kg", 0, 500,
    lo_open=True)``."""
    return _spec_field(default, FieldSpec(label, "number", unit, lo, hi, **kw))


def integer(default: int, label: str, lo: int, hi: int, **kw: Any) -> Any:
    """A whole-number dataclass field with its spec (stored as ``int``)."""
    kw.setdefault("fmt", "%d")
    return _spec_field(default, FieldSpec(label, "integer", "", lo, hi, **kw))


def choice(default: str, label: str, choices: tuple[str, ...], **kw: Any) -> Any:
    """A dataclass field whose value is one of ``choices``."""
    return _spec_field(default, FieldSpec(label, "choice", choices=tuple(choices), **kw))


def text(default: str, label: str, **kw: Any) -> Any:
    """A free-text dataclass field (a name); checked by its ``__post_init__``."""
    return _spec_field(default, FieldSpec(label, "text", checked=False, **kw))


def flag(default: bool, label: str, **kw: Any) -> Any:
    """A yes/no dataclass field (stored as ``bool``; :func:`validate` refuses anything else,
    numpy booleans are stored back as ``bool``). Use as ``vertical: bool = flag(True,
    "Vertical turbulence w'")``."""
    return _spec_field(bool(default), FieldSpec(label, "flag", **kw))


def like(owner: type, name: str, default: Any, *, lo: float | None = None,
         hi: float | None = None, **kw: Any) -> Any:
    """A field that stands for field ``name`` of input dataclass ``owner`` (its label, unit,
    display and help), with a narrower range ``lo``/``hi`` where a request accepts less than
    the model (a run from the app or the command line keeps its compute small). A range that
    leaves the model's fails at import.

    >>> from aerostat_core.atmosphere.gas import LiftingGas
    >>> from dataclasses import dataclass
    >>> @dataclass(frozen=True)
    ... class Gas:
    ...     purity: float = like(LiftingGas, "purity", 0.98, lo=0.9)
    >>> s = field_spec(Gas, "purity")
    >>> s.label, s.lo, s.hi, s.lo_open
    ('Gas purity', 0.9, 1, False)
    """
    base = field_spec(owner, name)
    changes: dict[str, Any] = dict(kw)
    if lo is not None:
        if base.lo is not None and (lo < base.lo or (lo == base.lo and base.lo_open)):
            raise ValueError(f"like({owner.__name__}.{name}): lo = {lo:g} leaves the model's "
                             f"range {base.si_range_text()}")
        changes.update(lo=lo, lo_open=kw.get("lo_open", False))
    if hi is not None:
        if base.hi is not None and (hi > base.hi or (hi == base.hi and base.hi_open)):
            raise ValueError(f"like({owner.__name__}.{name}): hi = {hi:g} leaves the model's "
                             f"range {base.si_range_text()}")
        changes.update(hi=hi, hi_open=kw.get("hi_open", False))
    return _spec_field(default, dataclasses.replace(base, **changes))


def part(factory: type, label: str, *, prefix: bool = False, **kw: Any) -> Any:
    """A nested input dataclass; ``prefix`` puts ``label`` before its fields' labels."""
    spec = FieldSpec(label, "part", checked=False, prefix=prefix, **kw)
    return _spec_field(None, spec, default_factory=factory)


# --- lookup -------------------------------------------------------------------------------------


@functools.cache
def _specs(cls: type) -> tuple[tuple[str, FieldSpec], ...]:
    # cached: validate() runs on every construction (the optimiser builds thousands)
    return tuple(
        (f.name, f.metadata[SPEC_KEY]) for f in dataclasses.fields(cls) if SPEC_KEY in f.metadata
    )


def specs(cls: type) -> dict[str, FieldSpec]:
    """The specs of a dataclass' fields, by field name, in declaration order."""
    return dict(_specs(cls))


def field_spec(owner: type | object, name: str) -> FieldSpec:
    """The spec of field ``name`` of dataclass ``owner`` (a class or an instance).

    >>> from aerostat_core.model.inputs import Requirement
    >>> s = field_spec(Requirement, "payload_mass")
    >>> s.label, s.unit, s.lo, s.hi, s.lo_open
    ('Payload mass', 'kg', 0, 10000, True)
    """
    cls = owner if isinstance(owner, type) else type(owner)
    try:
        return specs(cls)[name]
    except KeyError:
        raise KeyError(f"{cls.__name__}.{name} has no field spec") from None


# --- validation ---------------------------------------------------------------------------------


def check(
    obj: object,
    name: str,
    value: Any = None,
    *,
    lo: float | None = None,
    hi: float | None = None,
    reason_suffix: str = "",
) -> Any:
    """Check one field of ``obj`` against its spec (``lo``/``hi`` override the spec's bounds,
    for a range that depends on another field) and store the converted value back.

    Returns the checked value. Raises :class:`~aerostat_core.base.validation.InputError` with the
    spec's label and unit.
    """
    spec = field_spec(obj, name)
    value = getattr(obj, name) if value is None else value
    return _check(obj, name, spec, value, lo, hi, reason_suffix)


def _check(
    obj: object,
    name: str,
    spec: FieldSpec,
    value: Any,
    lo: float | None,
    hi: float | None,
    reason_suffix: str = "",
) -> Any:
    owner = type(obj).__name__
    if spec.kind == "choice":
        return check_choice(owner, name, value, spec.choices, label=spec.label)
    if spec.kind == "flag":
        return _check_flag(obj, owner, name, spec, value)
    if spec.allow_inf and isinstance(value, (int, float)) and value == math.inf:
        return value
    lo = spec.lo if lo is None else lo
    hi = spec.hi if hi is None else hi
    if spec.kind == "integer":
        v: Any = check_int(owner, name, value, int(lo), int(hi), label=spec.label)
    else:
        v = check_number(
            owner,
            name,
            value,
            lo,
            hi,
            spec.unit,
            lo_open=spec.lo_open,
            hi_open=spec.hi_open,
            label=spec.label,
            reason_suffix=reason_suffix,
        )
    if type(v) is not type(value) or v != value:
        object.__setattr__(obj, name, v)
    return v


def _check_flag(obj: object, owner: str, name: str, spec: FieldSpec, value: Any) -> bool:
    # bool or numpy.bool_ only: 1, "yes" or "False" are refused, never read as a truth value
    if type(value) is bool:
        return value
    if type(value).__module__ == "numpy" and type(value).__name__ in ("bool", "bool_"):
        object.__setattr__(obj, name, bool(value))
        return bool(value)
    reason = "is not yes or no (True or False)"
    raise InputError(f"{owner}.{name} = {shown_value(value)} {reason}", owner=owner,
                     field=name, value=value, reason=reason, label=spec.label)


def validate(obj: object) -> None:
    """Check every numeric, choice and flag field of dataclass ``obj`` that has a spec (``None`` is
    accepted where the spec is optional); converted numbers are stored back as ``float``
    (``int`` for integers). Raises :class:`~aerostat_core.base.validation.InputError`."""
    for name, spec in _specs(type(obj)):
        if not spec.checked or spec.kind not in ("number", "integer", "choice", "flag"):
            continue
        value = getattr(obj, name)
        if value is None and spec.optional:
            continue
        hi = float(getattr(obj, spec.hi_field)) if spec.hi_field else None
        _check(obj, name, spec, value, None, hi)


# --- ranges in docstrings -----------------------------------------------------------------------

#: A docstring placeholder for the valid range of a registry field: ``{range:<Owner>.<field>}``
#: (written here with angle brackets, which the pattern does not match, so that this module's
#: own docstrings stay as they are).
RANGE_PLACEHOLDER = re.compile(r"\{range:(\w+)\.(\w+)\}")


def range_doc(owner: type, name: str) -> str:
    """The text that replaces ``{range:<Owner>.<name>}`` in a docstring: the field's SI range and
    where it comes from.

    >>> from aerostat_core.atmosphere.gas import LiftingGas
    >>> range_doc(LiftingGas, "purity")
    '(0, 1] (registry: LiftingGas.purity)'
    """
    spec = field_spec(owner, name)
    text = spec.si_range_text()
    if not text:
        raise ValueError(f"{owner.__name__}.{name} has no range to put in a docstring")
    return f"{text} (registry: {owner.__name__}.{name})"


def spec_owners(modules: Iterable[ModuleType]) -> dict[str, type]:
    """The input dataclasses (those with at least one field spec) defined in ``modules``, by
    class name; a name defined twice maps to ``None`` (ambiguous, refused by
    :func:`fill_range_docs`)."""
    owners: dict[str, Any] = {}
    for mod in modules:
        for obj in vars(mod).values():
            if (inspect.isclass(obj) and obj.__module__ == mod.__name__
                    and dataclasses.is_dataclass(obj) and _specs(obj)):
                owners[obj.__name__] = None if owners.get(obj.__name__, obj) is not obj else obj
    return owners


def fill_range_docs(modules: Iterable[ModuleType]) -> int:
    """Put the registry's ranges into the docstrings of ``modules``: each
    ``{range:<Owner>.<field>}`` in the docstring of a module-level function or class defined
    there is replaced by :func:`range_doc`, so a range is typed once, in the field's spec. ``Owner`` is an input
    dataclass of any of ``modules`` (the library's face passes every loaded core module, so a
    physics function may name an input class of a package above it without importing it).

    Returns the number of placeholders filled. Raises ``ValueError`` for an unknown or ambiguous
    owner and ``KeyError`` for a field without a spec, so a typo fails at import.

    >>> import types
    >>> m = types.ModuleType("demo")
    >>> def f(purity): pass
    >>> f.__doc__ = "purity : float, valid {" + "range:LiftingGas.purity}."
    >>> f.__module__ = "demo"; m.f = f
    >>> from aerostat_core.atmosphere import gas
    >>> fill_range_docs([m, gas]), f.__doc__
    (1, 'purity : float, valid (0, 1] (registry: LiftingGas.purity).')
    """
    modules = list(modules)
    owners = spec_owners(modules)

    def one(match: re.Match) -> str:
        cls = owners.get(match.group(1))
        if cls is None:
            state = "ambiguous" if match.group(1) in owners else "unknown"
            raise ValueError(f"docstring placeholder {match.group(0)}: {state} input class")
        return range_doc(cls, match.group(2))

    count = 0
    for mod in modules:
        for obj in list(vars(mod).values()):
            if not (inspect.isfunction(obj) or inspect.isclass(obj)):
                continue
            if obj.__module__ != mod.__name__ or not obj.__doc__ or "{range:" not in obj.__doc__:
                continue
            doc, n = RANGE_PLACEHOLDER.subn(one, obj.__doc__)
            obj.__doc__ = doc
            count += n
    return count


# --- display units of the unit systems ----------------------------------------------------------

#: The unit systems values can be shown in (values are stored, computed and exported in SI).
UNIT_SYSTEMS = ("SI", "US")
#: How each system reads in a chooser.
UNIT_SYSTEM_LABELS = {"SI": "SI", "US": "US customary"}

_FT = 0.3048  # m, exact (international foot, 1959)
_LB = 0.45359237  # kg, exact (international pound, 1959)
_LBF = _LB * 9.80665  # N, exact (standard gravity)
_KT = 1852.0 / 3600.0  # m/s, exact (international nautical mile per hour)
_IN = 0.0254  # m, exact


@dataclass(frozen=True)
class DisplayUnit:
    """A unit a value is shown in: ``shown = SI value * scale + offset``.

    >>> US_CUSTOMARY["degC"].show(20.0), US_CUSTOMARY["m/s"].show(10.0)
    (68.0, 19.438444924406046)
    """

    unit: str
    scale: float = 1.0
    offset: float = 0.0

    def show(self, si: float) -> float:
        """The SI value in this unit."""
        return si * self.scale + self.offset

    def to_si(self, shown: float) -> float:
        """A value in this unit back in SI."""
        return (shown - self.offset) / self.scale


#: US customary display of an SI unit token (as in ``FieldSpec.unit``) or of an SI display unit
#: ("mm", "kN"); exact factors (1 ft = 0.3048 m, 1 lb = 0.45359237 kg, 1 lbf = 1 lb x 9.80665
#: m/s², 1 kt = 1852 m/h, °F = 1.8 °C + 32). A unit not listed is shown as in SI (deg, W, Pa,
#: USD, %, and the fabric and tether data, whose vendor sheets are metric).
US_CUSTOMARY: dict[str, DisplayUnit] = {
    "m": DisplayUnit("ft", 1.0 / _FT),
    "m2": DisplayUnit("ft²", 1.0 / _FT**2),
    "m3": DisplayUnit("ft³", 1.0 / _FT**3),
    "kg": DisplayUnit("lb", 1.0 / _LB),
    "N": DisplayUnit("lbf", 1.0 / _LBF),
    "m/s": DisplayUnit("kt", 1.0 / _KT),
    "degC": DisplayUnit("°F", 1.8, 32.0),
    "kg/m3": DisplayUnit("lb/ft³", _FT**3 / _LB),
    "USD/m3": DisplayUnit("USD/ft³", _FT**3),
    "mm": DisplayUnit("in", 1.0 / _IN),  # per m: a spec shown in mm has its SI value in m
    "kN": DisplayUnit("lbf", 1.0 / _LBF),  # per N
    "m above sea level": DisplayUnit("ft above sea level", 1.0 / _FT),
}
#: SI display of the units above ("m3" -> "m³"), for values not from a spec.
_SI_TEXT = {k: DisplayUnit(_PRETTY_UNIT.get(k, k)) for k in US_CUSTOMARY}


def unit_in(unit: str, system: str = "SI") -> DisplayUnit:
    """How a value in SI unit ``unit`` (a token as in :data:`US_CUSTOMARY`: "m", "m3", "N",
    "m/s", "degC") is shown in ``system``; a unit the system does not change is shown as is.

    >>> unit_in("m3", "US").unit, round(unit_in("m3", "US").show(170.0), 1)
    ('ft³', 6003.5)
    >>> unit_in("m3").unit, unit_in("deg", "US").unit
    ('m³', 'deg')
    """
    if system not in UNIT_SYSTEMS:
        raise ValueError(f"unit system {system!r}: use one of {', '.join(UNIT_SYSTEMS)}")
    if system == "US" and unit in US_CUSTOMARY:
        return US_CUSTOMARY[unit]
    return _SI_TEXT.get(unit, DisplayUnit(_PRETTY_UNIT.get(unit, unit)))


def spec_display(spec: FieldSpec, system: str = "SI") -> DisplayUnit:
    """The display unit of a field in ``system``: its own display unit and scale in SI; in US
    customary the US unit of its SI unit (or of its SI display unit, "mm" -> "in"), when there
    is one.

    >>> from aerostat_core.model.inputs import Requirement
    >>> d = spec_display(field_spec(Requirement, "payload_mass"), "US")
    >>> d.unit, round(d.show(10.0), 2)
    ('lb', 22.05)
    """
    si = DisplayUnit(spec.shown_unit, float(spec.scale))
    if system == "SI" or spec.kind not in ("number", "integer"):
        return si
    plain_si = spec.scale == 1.0 and spec.shown_unit == _PRETTY_UNIT.get(spec.unit, spec.unit)
    if plain_si and spec.unit in US_CUSTOMARY:
        return US_CUSTOMARY[spec.unit]
    if spec.shown_unit in _PER_SI_BASE:  # "mm", "kN": their US unit applies to the SI value
        return US_CUSTOMARY[spec.shown_unit]
    return si


#: SI display units whose :data:`US_CUSTOMARY` entry converts the SI value (m, N) directly.
_PER_SI_BASE = ("mm", "kN", "m above sea level")
