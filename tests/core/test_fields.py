"""The field registry (aerostat_core.base.fields): every input has one spec, and validation, report
columns and the optimiser's variable info are derived from it."""

from __future__ import annotations

import dataclasses
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from aerostat_core.base import fields
from aerostat_core.base.fields import SPEC_KEY, field_spec
from aerostat_core.base.validation import POSITIVE_FLOOR, InputError
from aerostat_core.geometry.shapes import SHAPE_INFO
from aerostat_core.model.input_paths import (
    all_specs,
    column_label,
    paths_for,
    report_table,
    spec_for_path,
    variable_info,
)
from aerostat_core.model.inputs import Configuration, HullSpec, Requirement
from aerostat_core.model.io import inputs_to_dict
from aerostat_core.model.presets import thesis_baseline
from aerostat_core.output.report import flatten_inputs


def _input_classes() -> set[type]:
    """Every dataclass reachable from Requirement and Configuration (the nested parts)."""
    seen: set[type] = set()
    todo = [Requirement, Configuration]
    while todo:
        cls = todo.pop()
        if cls in seen:
            continue
        seen.add(cls)
        for f in dataclasses.fields(cls):
            if f.default_factory is not dataclasses.MISSING and dataclasses.is_dataclass(
                f.default_factory
            ):
                todo.append(f.default_factory)
    return seen


def test_every_field_of_every_input_dataclass_has_a_spec():
    classes = _input_classes()
    assert len(classes) >= 11  # Requirement, Configuration and their nine kinds of part
    missing = [
        f"{cls.__name__}.{f.name}"
        for cls in classes
        for f in dataclasses.fields(cls)
        if SPEC_KEY not in f.metadata
    ]
    assert missing == [], f"fields without a spec (add one with aerostat_core.base.fields): {missing}"


def test_every_input_path_of_a_design_is_in_the_registry():
    flat = flatten_inputs(inputs_to_dict(*thesis_baseline()))
    known = {p.path for p in all_specs()}
    assert set(flat) <= known
    assert len(known) == len({p.path for p in all_specs()})  # paths are unique


def test_specs_are_complete_and_consistent():
    for p in all_specs():
        s = p.spec
        assert p.label and p.label[0].isupper(), p.path
        if s.kind in ("number", "integer"):
            assert s.lo is not None and s.hi is not None and s.lo < s.hi, p.path
            assert s.scale > 0 and s.shown_unit, p.path
        if s.kind == "choice":
            assert s.choices, p.path
            default = getattr(p.owner(), p.name)
            assert default in s.choices, p.path


def _numeric_entries():
    out, seen = [], set()
    for p in all_specs():
        key = (p.owner, p.name)
        if p.spec.kind in ("number", "integer") and p.spec.checked and key not in seen:
            seen.add(key)
            out.append(pytest.param(p, id=f"{p.owner.__name__}.{p.name}"))
    return out


def _make(owner: type, name: str, value):
    extra = {}
    if (owner.__name__, name) == ("FinSpec", "count"):
        extra["arrangement"] = "inverted-y" if value == 3 else "+"
    return owner(**{name: value, **extra})


def _bounds(p):
    hi = p.spec.hi
    if p.spec.hi_field:  # the bound is another field's value: its default here
        hi = float(getattr(p.owner(), p.spec.hi_field))
    return p.spec.lo, hi


@pytest.mark.parametrize("entry", _numeric_entries())
@settings(max_examples=15, deadline=None)
@given(data=st.data())
def test_validation_accepts_inside_and_refuses_outside_the_registry_range(entry, data):
    s = entry.spec
    lo, hi = _bounds(entry)
    if s.integer:
        inside = data.draw(st.integers(int(lo), int(hi)))
        outside = data.draw(
            st.one_of(
                st.integers(int(lo) - 10**6, int(lo) - 1), st.integers(int(hi) + 1, int(hi) + 10**6)
            )
        )
    else:
        floor = POSITIVE_FLOOR * hi if (s.lo_open and lo == 0) else lo
        inside = data.draw(
            st.floats(floor, hi, exclude_min=s.lo_open and floor == lo, exclude_max=s.hi_open)
        )
        below = st.floats(
            max_value=lo,
            exclude_max=not s.lo_open,
            allow_infinity=False,
            allow_nan=False,
            min_value=lo - 1e12,
        )
        above = st.floats(
            min_value=hi,
            exclude_min=not s.hi_open,
            allow_infinity=False,
            allow_nan=False,
            max_value=hi + 1e12,
        )
        outside = data.draw(st.one_of(below, above))
    obj = _make(entry.owner, entry.name, inside)
    assert getattr(obj, entry.name) == inside
    with pytest.raises(InputError) as err:
        _make(entry.owner, entry.name, outside)
    e = err.value
    assert (e.owner, e.field) == (entry.owner.__name__, entry.name)
    assert (e.lo, e.hi) == (lo, hi)
    assert e.label == s.label
    if not s.integer:
        assert (e.unit, e.lo_open, e.hi_open) == (s.unit, s.lo_open, s.hi_open)


@pytest.mark.parametrize("shape", list(SHAPE_INFO))
def test_the_fineness_range_depends_on_the_shape(shape):
    lo, hi = SHAPE_INFO[shape].fineness_range
    assert HullSpec(shape=shape, fineness_ratio=hi).fineness_ratio == hi
    with pytest.raises(InputError) as err:
        HullSpec(shape=shape, fineness_ratio=hi + 0.5)
    e = err.value
    assert (e.lo, e.hi, e.label, e.context) == (
        lo,
        hi,
        "Fineness ratio l/d",
        f" for shape {shape!r}",
    )
    assert str(e).endswith(f"for shape {shape!r}")
    spec = field_spec(HullSpec, "fineness_ratio")
    assert spec.lo <= lo and hi <= spec.hi  # the registry holds the widest range


def test_messages_keep_their_format():
    with pytest.raises(InputError) as err:
        Requirement(payload_mass=-5)
    assert str(err.value) == (
        "Requirement.payload_mass = -5 kg is outside the valid range (0, 500] kg"
    )
    assert err.value.label == "Payload mass" and err.value.valid_range == "(0, 500] kg"


def test_cross_field_checks_are_structured():
    with pytest.raises(InputError) as err:
        Requirement(design_wind=15.0, survival_wind=12.0)
    e = err.value
    assert (e.owner, e.field, e.value, e.lo, e.hi) == (
        "Requirement",
        "survival_wind",
        12.0,
        15.0,
        60,
    )
    with pytest.raises(InputError) as err:
        from aerostat_core.model.inputs import FinSpec

        FinSpec(count=3, arrangement="+")
    assert (err.value.field, err.value.label) == ("count", "Number of fins")


def test_numbers_are_stored_as_float_and_int():
    from fractions import Fraction

    import numpy as np

    r = Requirement(payload_mass=Fraction(21, 2), altitude=np.float32(250.0))
    assert type(r.payload_mass) is float and r.payload_mass == 10.5
    assert type(r.altitude) is float
    c = Configuration(tether_segments=np.int64(60))
    assert type(c.tether_segments) is int


def test_lookup_by_path_and_by_owner():
    p = spec_for_path("configuration.fins.position")
    assert (p.owner.__name__, p.name, p.spec.scale, p.spec.shown_unit) == (
        "FinSpec",
        "position",
        100.0,
        "% of hull length",
    )
    assert paths_for("Fabric", "areal_density") == (
        "configuration.hull_fabric.areal_density",
        "configuration.fin_fabric.areal_density",
    )
    with pytest.raises(KeyError):
        spec_for_path("configuration.nothing")


def test_column_labels_and_variable_info():
    assert column_label("requirement.payload_mass") == "Payload mass [kg]"
    assert column_label("configuration.tether.breaking_strength") == "Tether breaking strength [kN]"
    assert column_label("configuration.hull.shape") == "Hull shape"
    assert column_label("no.such.path") == "no.such.path"
    assert variable_info("fineness_ratio") == ("Fineness ratio l/d", "-", 1.0)
    assert variable_info("area_change") == ("Fin area change ΔS_f", "%", 1.0)
    assert variable_info("position") == ("Fin position Δl_f", "% of hull length", 100.0)
    assert variable_info("volume") == ("Hull volume", "m³", 1.0)
    assert variable_info("volume") == variable_info("configuration.hull.volume")


def test_the_report_table_is_the_registry():
    table = report_table()
    assert table["configuration.hull_fabric.areal_density"] == (
        "Hull fabric areal density",
        "g/m²",
        1000.0,
        "kg_m2",
    )
    assert table["configuration.fins.position"][3] == "fraction_of_length"
    assert table["configuration.hull.volume"][0] == "Hull volume (empty = sized)"


def test_range_text_is_in_display_units():
    assert spec_for_path("configuration.fins.position").spec.range_text() == (
        "[40, 95] % of hull length"
    )
    assert spec_for_path("requirement.payload_mass").spec.range_text() == "(0, 500] kg"
    assert math.isclose(spec_for_path("configuration.gas.purity").spec.scale, 100.0)


def _dynamics_entries():
    """The dynamics inputs and the site wind, validated from the registry too."""
    from aerostat_core.dynamics.bodies import PointAerostat
    from aerostat_core.dynamics.options import SolverOptions
    from aerostat_core.dynamics.tether import TetherModel
    from aerostat_core.dynamics.turbulence import DrydenTurbulence
    from aerostat_core.dynamics.wind import Gust, MeanProfile
    from aerostat_core.studies.site_wind import WeibullSite

    out = []
    for cls in (
        PointAerostat,
        TetherModel,
        DrydenTurbulence,
        Gust,
        MeanProfile,
        SolverOptions,
        WeibullSite,
    ):
        for name, spec in fields.specs(cls).items():
            if spec.kind in ("number", "integer"):
                out.append(pytest.param(cls, name, spec, id=f"{cls.__name__}.{name}"))
    return out


def test_the_dynamics_inputs_have_specs():
    from aerostat_core.dynamics.tether import TetherModel

    numeric = [
        f.name
        for f in dataclasses.fields(TetherModel)
        if f.type in ("float", "int", "float | None")
    ]
    assert numeric and all(n in fields.specs(TetherModel) for n in numeric)


@pytest.mark.parametrize("cls, name, spec", _dynamics_entries())
def test_dynamics_validation_uses_the_registry_range(cls, name, spec):
    cls(**{name: spec.hi})  # the bound itself is valid (closed above in every dynamics spec)
    with pytest.raises(InputError) as err:
        cls(**{name: spec.hi + max(1.0, abs(spec.hi))})
    e = err.value
    assert (e.owner, e.field, e.lo, e.hi, e.label) == (
        cls.__name__,
        name,
        spec.lo,
        spec.hi,
        spec.label,
    )


def test_variable_ranges_reproduce_the_optimiser_bounds():
    from aerostat_core.model.input_paths import variable_range
    from aerostat_core.optimize import VARIABLE_INFO

    for name, (_label, _unit, bounds) in VARIABLE_INFO.items():
        assert variable_range(name) == bounds, name
    assert variable_range("fineness_ratio", "oblate") == SHAPE_INFO["oblate"].fineness_range
