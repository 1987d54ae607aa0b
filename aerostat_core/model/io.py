"""Reading and writing designs: JSON design files and CSV tables.

The JSON format holds every input::

    {"format": "aerostat-design", "version": 2,
     "requirement": {...Requirement fields...},
     "configuration": {"gas": {...}, "hull": {...}, ..., "misc_mass_ratio": 0.3, ...}}

A file of saved cases is ``{"format": "aerostat-cases", "version": 2, "cases": {name: design}}``.
Version 2 added ``configuration.hull.shape`` (issue 12) and the mission inputs (issue 13:
Requirement ``payload_power``, ``power_via``, ``endurance_days``, ``deployment_days``;
Configuration ``mission``; Fabric ``tensile_strength`` and ``helium_permeability``). Version-1
files still load: their hulls are NPL (the only shape version 1 knew) and the mission inputs
they lack take their defaults, which are off, so they give the same design as before.
Readers are strict: unknown keys, wrong types, out-of-range values, or oversized input raise
``ValueError`` with a message naming the field; nothing is half-applied.
"""

from __future__ import annotations

import csv
import io as _io
import json
import math
from dataclasses import fields, is_dataclass
from typing import Any

from aerostat_core.base.validation import check_name, shown_value
from aerostat_core.model.inputs import (
    AeroModel,
    Configuration,
    ConfluenceSpec,
    FinSpec,
    HullSpec,
    LiftingGas,
    Requirement,
    WindProfile,
)
from aerostat_core.model.mission import MissionSpec
from aerostat_core.structures.materials import Fabric, TetherSpec

FORMAT_DESIGN = "aerostat-design"
FORMAT_CASES = "aerostat-cases"
VERSION = 2
#: Versions this program reads (1: before hull shapes; read as NPL).
READABLE_VERSIONS = (1, 2)
#: Largest JSON document accepted [bytes]; a design is about 2 kB.
MAX_JSON_BYTES = 1_000_000
#: Largest number of cases in one file.
MAX_CASES = 200

_NESTED: dict[str, type] = {
    "gas": LiftingGas,
    "hull_fabric": Fabric,
    "fin_fabric": Fabric,
    "tether": TetherSpec,
    "hull": HullSpec,
    "fins": FinSpec,
    "aero": AeroModel,
    "confluence": ConfluenceSpec,
    "wind_profile": WindProfile,
    "mission": MissionSpec,
}


def _plain(obj: Any) -> Any:
    if is_dataclass(obj):
        return {f.name: _plain(getattr(obj, f.name)) for f in fields(obj)}
    if isinstance(obj, float) and math.isinf(obj):
        return "inf"
    return obj


def inputs_to_dict(requirement: Requirement, configuration: Configuration) -> dict[str, Any]:
    """Every input as plain JSON-ready data (see the module docstring for the layout).

    >>> d = inputs_to_dict(Requirement(), Configuration())
    >>> d["requirement"]["payload_mass"], d["configuration"]["hull"]["fineness_ratio"]
    (10.0, 4.0)
    """
    return {
        "format": FORMAT_DESIGN,
        "version": VERSION,
        "requirement": _plain(requirement),
        "configuration": _plain(configuration),
    }


def _build(cls: type, data: Any, where: str) -> Any:
    if not isinstance(data, dict):
        raise ValueError(f"{where} must be an object with the fields of {cls.__name__}")
    names = {f.name for f in fields(cls)}
    unknown = sorted(set(data) - names)
    if unknown:
        raise ValueError(f"{where} has unknown field(s): {', '.join(map(str, unknown))}")
    kwargs: dict[str, Any] = {}
    for key, value in data.items():
        if cls is Configuration and key in _NESTED:
            kwargs[key] = _build(_NESTED[key], value, f"{where}.{key}")
        else:
            if value == "inf" and key == "axial_stiffness":
                value = math.inf
            if isinstance(value, (dict, list)):
                kind = type(value).__name__
                raise ValueError(f"{where}.{key} must be a single value, not {kind}")
            kwargs[key] = value
    try:
        return cls(**kwargs)
    except TypeError as exc:  # e.g. a str where a number is expected in a comparison
        raise ValueError(f"{where}: {exc}") from None


def inputs_from_dict(data: Any) -> tuple[Requirement, Configuration]:
    """Rebuild and validate (Requirement, Configuration) from :func:`inputs_to_dict` data.

    Missing fields take their defaults; unknown fields, wrong types and out-of-range values raise
    ``ValueError`` naming the field.

    >>> r, c = inputs_from_dict({"requirement": {"payload_mass": 30}})
    >>> r.payload_mass, c.hull.fineness_ratio
    (30.0, 4.0)
    >>> inputs_from_dict({"requirement": {"payload_mass": "heavy"}})
    Traceback (most recent call last):
    ...
    aerostat_core.base.validation.InputError: Requirement.payload_mass = 'heavy' is not a number; valid range (0, 500] kg
    """
    if not isinstance(data, dict):
        raise ValueError("a design must be a JSON object with 'requirement' and 'configuration'")
    fmt = data.get("format", FORMAT_DESIGN)
    if fmt != FORMAT_DESIGN:
        raise ValueError(f"format = {fmt!r}: expected {FORMAT_DESIGN!r}")
    version = data.get("version", VERSION)
    _check_version(version)
    unknown = sorted(set(data) - {"format", "version", "requirement", "configuration", "name"})
    if unknown:
        raise ValueError(f"design has unknown field(s): {', '.join(map(str, unknown))}")
    req = _build(Requirement, data.get("requirement", {}), "requirement")
    cfg = _build(Configuration, data.get("configuration", {}), "configuration")
    return req, cfg


def _check_version(version: Any) -> None:
    """Accept the file versions of ``READABLE_VERSIONS``; anything else is a named error."""
    if type(version) is not int or version not in READABLE_VERSIONS:
        raise ValueError(f"version = {version!r}: this program reads versions "
                         f"{', '.join(map(str, READABLE_VERSIONS))}")
    return None


def _loads_limited(text: str | bytes) -> Any:
    if isinstance(text, bytes):
        if len(text) > MAX_JSON_BYTES:
            raise ValueError(f"file is {len(text)} bytes; the limit is {MAX_JSON_BYTES} bytes")
        try:
            text = text.decode("utf-8")
        except UnicodeDecodeError:
            raise ValueError("file is not UTF-8 text") from None
    if len(text) > MAX_JSON_BYTES:
        raise ValueError(f"file is {len(text)} characters; the limit is {MAX_JSON_BYTES}")
    try:
        return json.loads(text, parse_constant=_reject_constant)
    except json.JSONDecodeError as exc:
        raise ValueError(f"file is not valid JSON: {exc.msg} at line {exc.lineno}") from None
    except RecursionError:
        raise ValueError("file is nested too deeply") from None
    except ValueError as exc:  # e.g. an integer with more digits than Python converts
        raise ValueError(f"file has a number that cannot be read: {exc}") from None


def _reject_constant(name: str) -> Any:
    raise ValueError(f"file contains {name}, which is not a valid number here")


def design_to_json(requirement: Requirement, configuration: Configuration) -> str:
    """JSON design file text."""
    return json.dumps(inputs_to_dict(requirement, configuration), indent=2)


def design_from_json(text: str | bytes) -> tuple[Requirement, Configuration]:
    """Parse a JSON design file (size-limited, strict); see :func:`inputs_from_dict`."""
    return inputs_from_dict(_loads_limited(text))


def cases_to_json(cases: dict[str, dict[str, Any]]) -> str:
    """JSON text of named cases, each an :func:`inputs_to_dict` dict."""
    return json.dumps({"format": FORMAT_CASES, "version": VERSION, "cases": cases}, indent=2)


def cases_from_json(text: str | bytes) -> dict[str, dict[str, Any]]:
    """Parse saved cases; every case is validated, and one bad case rejects the whole file.

    A single design file is accepted too and becomes one case named ``"imported"``.
    """
    data = _loads_limited(text)
    if isinstance(data, dict) and data.get("format") == FORMAT_DESIGN:
        req, cfg = inputs_from_dict(data)
        return {check_name("design", "name", data.get("name", "imported")): inputs_to_dict(req, cfg)}
    if not isinstance(data, dict) or data.get("format") != FORMAT_CASES:
        raise ValueError(f"file is neither {FORMAT_CASES!r} nor {FORMAT_DESIGN!r} JSON")
    _check_version(data.get("version"))
    cases = data.get("cases")
    if not isinstance(cases, dict):
        raise ValueError("'cases' must be an object of name -> design")
    if len(cases) > MAX_CASES:
        raise ValueError(f"file has {len(cases)} cases; the limit is {MAX_CASES}")
    out: dict[str, dict[str, Any]] = {}
    for name, case in cases.items():
        if not isinstance(name, str) or not name.strip() or len(name) > 100:
            raise ValueError(f"case name {shown_value(name)} must be 1-100 characters")
        name = check_name("case", "name", name)  # no control characters or lone surrogates
        try:
            req, cfg = inputs_from_dict(case)
        except ValueError as exc:
            raise ValueError(f"case {shown_value(name)}: {exc}") from None
        out[name] = inputs_to_dict(req, cfg)
    return out


#: First characters that make a spreadsheet read a cell as a formula (OWASP, "CSV Injection"),
#: plus tab and carriage return, which some spreadsheets strip before looking.
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def csv_safe(value: Any) -> Any:
    """A CSV cell that no spreadsheet runs as a formula: text beginning with ``= + - @`` (or tab
    or carriage return) gets a leading apostrophe, as OWASP advises; numbers stay numbers, so a
    negative value is written as ``-5`` and still reads as a number.

    >>> csv_safe("=cmd|' /C calc'!A0"), csv_safe("-2+3"), csv_safe(-2.5), csv_safe("x")
    ("'=cmd|' /C calc'!A0", "'-2+3", -2.5, 'x')
    """
    if isinstance(value, str) and value.startswith(_FORMULA_START):
        return "'" + value
    return value


def rows_to_csv(rows: list[dict[str, Any]]) -> str:
    """CSV text of a list of flat dicts (columns from the first row, in order). Text cells and
    headers are passed through :func:`csv_safe` against formula injection."""
    buf = _io.StringIO()
    if not rows:
        return ""
    names = list(rows[0].keys())
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow([csv_safe(str(n)) for n in names])
    for row in rows:
        writer.writerow([csv_safe(row.get(n, "")) for n in names])
    return buf.getvalue()
