"""Inputs by their dotted path in the input tree (``requirement.payload_mass``,
``configuration.hull.fineness_ratio``): the registry's specs walked from the two roots.

The field registry (:mod:`aerostat_core.base.fields`) defines one field; this module knows the tree
the model builds from them, so it sits with the model and the registry stays at the base.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from dataclasses import dataclass

from aerostat_core.base.fields import FieldSpec, specs
from aerostat_core.geometry.shapes import SHAPE_INFO
from aerostat_core.model.inputs import Configuration, Requirement


def _roots() -> dict[str, type]:
    return {"requirement": Requirement, "configuration": Configuration}


@dataclass(frozen=True)
class PathSpec:
    """One input by its dotted path in an inputs dict: its owner class, field name, spec and
    the full label (with the labels of the prefixing parts, "Hull fabric areal density")."""

    path: str
    owner: type
    name: str
    spec: FieldSpec
    label: str


def _walk(prefix: str, cls: type, label_prefix: str) -> Iterator[PathSpec]:
    for name, spec in specs(cls).items():
        path = f"{prefix}.{name}"
        if spec.kind == "part":
            f = next(f for f in dataclasses.fields(cls) if f.name == name)
            child = f.default_factory  # type: ignore[misc]
            yield from _walk(path, child, spec.label if spec.prefix else "")
            continue
        if label_prefix:
            label = f"{label_prefix} {spec.label[:1].lower()}{spec.label[1:]}".strip()
            label = label if spec.label else label_prefix
        else:
            label = spec.label
        yield PathSpec(path, cls, name, spec, label)


def all_specs() -> tuple[PathSpec, ...]:
    """Every input of a design (Requirement and Configuration, nested parts walked), in
    declaration order."""
    out: list[PathSpec] = []
    for root, cls in _roots().items():
        out.extend(_walk(root, cls, ""))
    return tuple(out)


def spec_for_path(path: str) -> PathSpec:
    """The :class:`PathSpec` of a dotted input path, e.g. ``"requirement.payload_mass"``.

    >>> spec_for_path("configuration.fins.position").spec.scale
    100.0
    """
    for p in all_specs():
        if p.path == path:
            return p
    raise KeyError(f"no input field {path!r}")


def paths_for(owner: str, name: str) -> tuple[str, ...]:
    """The input paths of field ``name`` of the class named ``owner`` (a class used in two
    places, such as ``Fabric``, has two), from an ``InputError``'s ``owner`` and ``field``."""
    return tuple(p.path for p in all_specs() if p.owner.__name__ == owner and p.name == name)


def column_label(path: str) -> str:
    """Column name of an input in tables: the label with its display unit in brackets
    ("Payload mass [kg]", "Fin position Δl_f [% of hull length]"); an unknown path is its own
    label.

    >>> column_label("configuration.hull_fabric.areal_density")
    'Hull fabric areal density [g/m²]'
    """
    try:
        p = spec_for_path(path)
    except KeyError:
        return path
    unit = p.spec.shown_unit
    return f"{p.label} [{unit}]" if unit else p.label


def report_table() -> dict[str, tuple[str, str, float, str]]:
    """Every input path -> (label, display unit, display scale, CSV unit token), the table the
    report and the CSV export use; an optional input's label says what empty means ("Hull
    volume (empty = sized)"), which also keeps it apart from the result of the same name."""
    return {
        p.path: (
            f"{p.label} (empty = {p.spec.empty})" if p.spec.empty else p.label,
            p.spec.shown_unit,
            float(p.spec.scale),
            p.spec.csv_token,
        )
        for p in all_specs()
    }


#: The optimiser's design variables: name -> input path.
DESIGN_VARIABLES = {
    "fineness_ratio": "configuration.hull.fineness_ratio",
    "area_change": "configuration.fins.area_change",
    "position": "configuration.fins.position",
    "volume": "configuration.hull.volume",
}


def variable_info(path: str) -> tuple[str, str, float]:
    """(label, display unit, display scale) of an input path or of a design-variable name
    (``"position"`` is ``"configuration.fins.position"``), for optimiser and sensitivity tables.

    >>> variable_info("position")
    ('Fin position Δl_f', '% of hull length', 100.0)
    """
    p = spec_for_path(DESIGN_VARIABLES.get(path, path))
    return p.label, p.spec.shown_unit, float(p.spec.scale)


def variable_range(name: str, shape: str = "npl") -> tuple[float, float]:
    """SI valid range (lo, hi) of a design variable or input path; the fineness ratio's is the
    hull shape's (``aerostat_core.geometry.shapes.SHAPE_INFO``), the others the registry's.

    >>> variable_range("fineness_ratio"), variable_range("position")
    ((1.5, 8.0), (0.4, 0.95))
    """
    p = spec_for_path(DESIGN_VARIABLES.get(name, name))
    if p.name == "fineness_ratio" and p.owner.__name__ == "HullSpec":
        lo, hi = SHAPE_INFO[shape].fineness_range
        return float(lo), float(hi)
    return float(p.spec.lo), float(p.spec.hi)
