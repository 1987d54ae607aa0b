"""Input checks shared by every dataclass: one message format naming field, value and range.

A rejected value raises :class:`InputError`, a ``ValueError`` that also carries the details as
attributes (owner, field, value, valid range, unit, label), so that a user interface can show its
own label and unit instead of the internal names. The message text is unchanged from the plain
``ValueError`` these helpers used to raise: ``Requirement.payload_mass = -1 kg is outside the
valid range (0, 500] kg``.

The number checks also store the value back as a ``float`` (``int`` for :func:`check_int`) on the
frozen dataclass being validated, so a ``Fraction``, ``Decimal``-free ``numbers.Real`` or numpy
scalar given to a constructor never survives into JSON export or the cache key.
"""

from __future__ import annotations

import math
import sys
import unicodedata
from dataclasses import is_dataclass
from numbers import Real

#: Longest message an :class:`InputError` (or :func:`short`) produces [characters].
MAX_MESSAGE_CHARS = 400
#: Longest rendering of a rejected value inside a message [characters].
MAX_VALUE_CHARS = 40
#: A strictly positive quantity (range ``(0, hi]``) must be at least this fraction of ``hi``:
#: smaller values are degenerate (their squares and cubes in the geometry underflow to 0, which
#: gave NaN blow-by for a fin area ratio of 1e-300). 1e-100 leaves every physical limit case
#: (a gas purity of 1e-12 is almost pure air) and refuses only numbers no input means.
POSITIVE_FLOOR = 1e-100


def short(text: str, limit: int = MAX_MESSAGE_CHARS) -> str:
    """``text`` cut to ``limit`` characters (with an ellipsis), for messages shown to a user.

    >>> short("x" * 10, 5)
    'xxxx…'
    """
    text = str(text)
    return text if len(text) <= limit else text[: limit - 1] + "…"


def shown_value(value: object) -> str:
    """``repr(value)``, shortened to :data:`MAX_VALUE_CHARS` (a 900 kB string stays short)."""
    try:
        text = repr(value)
    except Exception:  # noqa: BLE001 - a hostile __repr__ must not hide the real error
        text = f"<{type(value).__name__}>"
    return text if len(text) <= MAX_VALUE_CHARS else text[: MAX_VALUE_CHARS - 3] + "..."


class InputError(ValueError):
    """A rejected input, with the details a form needs to say what is wrong in its own words.

    Attributes
    ----------
    owner, field : str
        Internal names, e.g. ``"Requirement"``, ``"payload_mass"``.
    value : object
        The rejected value (as given).
    lo, hi : float or None
        Valid range, when the field has one.
    lo_open, hi_open : bool
        Whether the bounds are excluded.
    unit : str
        Unit of the value and the range, e.g. ``"kg"``.
    label : str
        Readable name of the field from the field registry (``aerostat_core.base.fields``), e.g.
        "Payload mass"; the field name with spaces when the check had no spec.
    reason : str
        The message without the ``owner.field = value`` prefix, e.g. ``"is not a number"``.
    context : str
        What the range depends on, as appended to the reason (``" for shape 'npl'"``); "".
    too_small : bool
        The value is inside the range but too small to compute with (``POSITIVE_FLOOR``).
    """

    def __init__(
        self,
        message: str,
        *,
        owner: str = "",
        field: str = "",
        value: object = None,
        lo: float | None = None,
        hi: float | None = None,
        lo_open: bool = False,
        hi_open: bool = False,
        unit: str = "",
        reason: str = "",
        label: str = "",
        context: str = "",
        too_small: bool = False,
    ) -> None:
        super().__init__(short(message))
        self.owner, self.field, self.value = owner, field, value
        self.lo, self.hi, self.lo_open, self.hi_open = lo, hi, lo_open, hi_open
        self.unit = unit
        self.label = label or field.replace("_", " ")
        self.reason = short(reason or message)
        self.context, self.too_small = context, too_small

    @property
    def valid_range(self) -> str:
        """The valid range as text, e.g. ``"(0, 500] kg"``; empty when there is none."""
        if self.lo is None or self.hi is None:
            return ""
        return _range_text(self.lo, self.hi, self.unit, self.lo_open, self.hi_open)


def _range_text(lo: float, hi: float, unit: str, lo_open: bool, hi_open: bool) -> str:
    u = f" {unit}" if unit else ""
    return f"{'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}{u}"


def _store_back(field: str, given: object, converted: object) -> None:
    """Replace ``self.<field>`` by its converted value in the ``__post_init__`` that called the
    check (two frames up), so every dataclass gets the conversion without repeating it."""
    if type(given) is type(converted):
        return
    obj = sys._getframe(2).f_locals.get("self")
    if obj is not None and is_dataclass(obj) and getattr(obj, field, None) is given:
        object.__setattr__(obj, field, converted)


def _valid(v: float, lo: float, hi: float, lo_open: bool, hi_open: bool) -> bool:
    """The one definition of a valid number for :func:`check_number`: finite, inside the range
    (open or closed ends), and for a range open at 0 not below ``POSITIVE_FLOOR`` x ``hi``."""
    return (
        math.isfinite(v)
        and (lo < v if lo_open else lo <= v)
        and (v < hi if hi_open else v <= hi)
        and not (lo_open and lo == 0 and hi > 0 and v < POSITIVE_FLOOR * hi)
    )


def check_number(
    owner: str,
    field: str,
    value: object,
    lo: float,
    hi: float,
    unit: str = "",
    *,
    lo_open: bool = False,
    hi_open: bool = False,
    label: str = "",
    reason_suffix: str = "",
) -> float:
    """Return ``value`` as float or raise :class:`InputError` naming the field, value and range.

    A value given as another ``numbers.Real`` (``int``, ``Fraction``, numpy scalar) is also
    stored back on the dataclass being validated as a ``float``.

    Parameters
    ----------
    owner, field : str
        Names used in the message, e.g. ``"Requirement"``, ``"payload_mass"``.
    value : object
        The value to check; must be a real, finite number (``bool`` is rejected).
    lo, hi : float
        Bounds of the valid range. For ``(0, hi]`` the value must also be at least
        ``POSITIVE_FLOOR * hi`` (smaller is degenerate: it underflows in the geometry).
    unit : str
        Unit shown in the message, e.g. ``"kg"``.
    lo_open, hi_open : bool
        Whether the bounds are excluded.
    label : str
        Readable name for :attr:`InputError.label` (the registry's, ``aerostat_core.base.fields``).
    reason_suffix : str
        Appended to the reason, e.g. ``" for shape 'npl'"`` for a range that depends on another
        field.

    Examples
    --------
    >>> check_number("Requirement", "payload_mass", 10, 0, 500, "kg", lo_open=True)
    10.0
    >>> check_number("Requirement", "payload_mass", -1, 0, 500, "kg", lo_open=True)
    Traceback (most recent call last):
    ...
    aerostat_core.base.validation.InputError: Requirement.payload_mass = -1 kg is outside the valid range (0, 500] kg
    """
    # the message parts are built only on failure: valid inputs (the common case, checked
    # for every field of every dataclass built) pay for the comparisons alone; a valid float
    # (nothing to convert or store back) returns before any of them
    if type(value) is float and _valid(value, lo, hi, lo_open, hi_open):
        return value

    def fail(shown: str, reason: str, too_small: bool = False) -> InputError:
        reason += reason_suffix
        return InputError(
            f"{owner}.{field} = {shown} {reason}", reason=reason, context=reason_suffix,
            too_small=too_small, owner=owner, field=field, value=value, lo=lo, hi=hi,
            unit=unit, label=label, lo_open=lo_open, hi_open=hi_open,
        )

    def rng() -> str:
        return _range_text(lo, hi, unit, lo_open, hi_open)

    def u() -> str:
        return f" {unit}" if unit else ""

    if isinstance(value, bool) or not isinstance(value, Real):
        raise fail(shown_value(value), f"is not a number; valid range {rng()}")
    try:
        v = float(value)
    except OverflowError:  # an integer too large for a float
        v = math.inf
    if _valid(v, lo, hi, lo_open, hi_open):
        _store_back(field, value, v)
        return v
    # invalid: say why
    if not math.isfinite(v):
        raise fail(shown_value(value), f"is not finite; valid range {rng()}")
    below = v <= lo if lo_open else v < lo
    above = v >= hi if hi_open else v > hi
    if below or above:
        raise fail(f"{v:g}{u()}", f"is outside the valid range {rng()}")
    raise fail(  # in range but below the floor of an open-at-zero range
        f"{v:g}{u()}",
        f"is too small to compute with (at least {POSITIVE_FLOOR * hi:g}{u()}); "
        f"valid range {rng()}",
        too_small=True,
    )


def check_choice(
    owner: str, field: str, value: object, choices: tuple[str, ...], *, label: str = ""
) -> str:
    """Return ``value`` if it is one of ``choices``, else raise :class:`InputError` listing them.

    >>> check_choice("LiftingGas", "kind", "argon", ("helium", "hydrogen"))
    Traceback (most recent call last):
    ...
    aerostat_core.base.validation.InputError: LiftingGas.kind = 'argon' is not one of: helium, hydrogen
    """
    if not isinstance(value, str) or value not in choices:
        reason = f"is not one of: {', '.join(choices)}"
        raise InputError(
            f"{owner}.{field} = {shown_value(value)} {reason}",
            owner=owner,
            field=field,
            value=value,
            reason=reason,
            label=label,
        )
    return value


def check_int(
    owner: str, field: str, value: object, lo: int, hi: int, *, label: str = ""
) -> int:
    """Return ``value`` as int if it is a whole number in [lo, hi], else raise
    :class:`InputError`. A whole float or numpy integer is stored back as ``int``."""
    info = dict(owner=owner, field=field, value=value, lo=lo, hi=hi, label=label)
    try:
        bad = (
            isinstance(value, bool)
            or not isinstance(value, Real)
            or not math.isfinite(float(value))
            or float(value) != int(value)
        )
    except OverflowError:
        bad = True
    if bad:
        reason = f"is not a whole number in [{lo}, {hi}]"
        raise InputError(f"{owner}.{field} = {shown_value(value)} {reason}", reason=reason, **info)
    v = int(value)
    if not lo <= v <= hi:
        reason = f"is outside the valid range [{lo}, {hi}]"
        raise InputError(f"{owner}.{field} = {v} {reason}", reason=reason, **info)
    _store_back(field, value, v)
    return v


#: Longest name accepted for catalogue items and cases [characters].
MAX_NAME_LENGTH = 100
#: Format characters refused in names: bidirectional overrides and isolates, which make a name
#: display as something else (Trojan-source style); zero-width joiners stay (emoji sequences).
_BIDI_CONTROLS = frozenset("\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069\u200e\u200f")


def check_name(owner: str, field: str, value: object) -> str:
    """Return ``value`` as a stripped string of 1-100 characters, else raise
    :class:`InputError`. Control characters (Unicode category Cc), lone surrogates (which
    cannot be encoded as UTF-8) and bidirectional overrides are refused.

    >>> check_name("Fabric", "name", "x" * 101)
    Traceback (most recent call last):
    ...
    aerostat_core.base.validation.InputError: Fabric.name is 101 characters long; the limit is 100
    >>> check_name("case", "name", "\\ud83d")
    Traceback (most recent call last):
    ...
    aerostat_core.base.validation.InputError: case.name contains a lone surrogate (U+D83D)
    """
    text = str(value).strip()

    def fail(reason: str) -> InputError:
        return InputError(
            f"{owner}.{field} {reason}", owner=owner, field=field, value=value, reason=reason
        )

    if not text:
        raise fail("must not be empty")
    for ch in text:
        cat = unicodedata.category(ch)
        if cat == "Cs":
            raise fail(f"contains a lone surrogate (U+{ord(ch):04X})")
        if cat == "Cc":
            raise fail("contains control characters")
        if ch in _BIDI_CONTROLS:
            raise fail(f"contains a text-direction control character (U+{ord(ch):04X})")
    if len(text) > MAX_NAME_LENGTH:
        raise fail(f"is {len(text)} characters long; the limit is {MAX_NAME_LENGTH}")
    return text
