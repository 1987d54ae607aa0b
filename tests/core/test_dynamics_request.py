"""The typed 3-DOF dynamics request (issue: the house as its own map, item 4): every field in the
field registry, validated once at construction with the label, the value and the valid range;
the rules between fields live there, not in the page; the untyped dict survives only as a
deprecated adapter; ``simulate`` reads its options' label, unit and range from the registry."""

from __future__ import annotations

import dataclasses
import math
import warnings

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from aerostat_core.base.fields import SPEC_KEY, field_spec, like, specs
from aerostat_core.base.validation import InputError
from aerostat_core.cli.entry import main
from aerostat_core.dynamics import scenarios
from aerostat_core.dynamics.request import (
    SCENARIOS,
    DynamicsRequest,
    GustSettings,
    RunRequest,
    SpeedChange,
    TurbulenceSettings,
    error_text,
)
from aerostat_core.dynamics.scenarios6 import Request6
from aerostat_core.dynamics.thesis import thesis_request
from aerostat_core.dynamics.turbulence import DRYDEN_W20
from aerostat_core.dynamics.wind import Gust

CLASSES = (DynamicsRequest, SpeedChange, GustSettings, TurbulenceSettings)
#: The scenario each class' fields are read in.
SCENARIO_OF = {DynamicsRequest: "gust", SpeedChange: "varying", GustSettings: "gust",
               TurbulenceSettings: "turbulence"}


def _numeric():
    return [pytest.param(cls, name, spec, id=f"{cls.__name__}.{name}")
            for cls in CLASSES for name, spec in specs(cls).items()
            if spec.kind in ("number", "integer")]


def _build(cls, name, value):
    """A request whose field ``name`` of part ``cls`` is ``value``."""
    if cls is DynamicsRequest:
        return DynamicsRequest(scenario="steady", **{name: value})  # no speed rule there
    extra = {"intensity": "custom"} if cls is TurbulenceSettings else {}  # W20 is read then
    part = cls(**{name: value}, **extra)
    if cls is SpeedChange:
        return DynamicsRequest(scenario="varying", changes=(part,))
    if cls is GustSettings:
        return DynamicsRequest(scenario="gust", gust=part)
    return DynamicsRequest(scenario="turbulence", turbulence=part)


def test_every_field_is_in_the_registry():
    for cls in CLASSES:
        missing = [f.name for f in dataclasses.fields(cls) if SPEC_KEY not in f.metadata]
        assert missing == [], (cls.__name__, missing)
        for name, s in specs(cls).items():
            assert s.label, (cls.__name__, name)
            if s.kind in ("number", "integer"):
                assert s.lo is not None and s.hi is not None and s.lo < s.hi, (cls, name)
            if s.kind == "choice":
                assert s.choices and getattr(cls(), name) in s.choices
    # the parts of the request are reached by path, as the form reads them
    assert DynamicsRequest.spec_at("gust.amplitude_u") is field_spec(GustSettings, "amplitude_u")
    assert DynamicsRequest.spec_at("changes.1.ramp") is field_spec(SpeedChange, "ramp")
    assert DynamicsRequest.for_scenario("varying").value_at("changes.0.speed") == 15.0


def test_fields_standing_for_model_inputs_take_their_label_and_keep_inside_their_range():
    own, model = field_spec(GustSettings, "amplitude_u"), field_spec(Gust, "amplitude_u")
    assert (own.label, own.unit) == (model.label, model.unit)
    assert model.lo <= own.lo < own.hi <= model.hi
    with pytest.raises(ValueError, match="leaves the model's range"):
        like(Gust, "amplitude_u", 0.0, hi=31.0)


@settings(max_examples=25, deadline=None)
@given(data=st.data())
@pytest.mark.parametrize("cls, name, spec", _numeric())
def test_values_inside_the_range_build_and_outside_are_refused_by_label_value_range(
    cls, name, spec, data
):
    if spec.kind == "integer":
        inside = data.draw(st.integers(int(spec.lo), int(spec.hi)))
    else:
        # an open lower bound: from just above it (a value below 1e-100 of the range is too
        # small to compute with and says so)
        lo = spec.lo + 1e-9 * (spec.hi - spec.lo) if spec.lo_open else spec.lo
        inside = data.draw(st.floats(lo, spec.hi, allow_nan=False))
    if not (cls is GustSettings and name in ("amplitude_u", "amplitude_w") and inside == 0):
        dyn = _build(cls, name, inside)
        part = {SpeedChange: lambda: dyn.changes[0], GustSettings: lambda: dyn.gust,
                TurbulenceSettings: lambda: dyn.turbulence}.get(cls, lambda: dyn)()
        assert getattr(part, name) == inside
        assert type(getattr(part, name)) is (int if spec.kind == "integer" else float)
    span = spec.hi - spec.lo
    above = data.draw(st.floats(spec.hi + max(1e-6 * span, 1.0), spec.hi + 10 * span + 1.0))
    below = data.draw(st.floats(spec.lo - 10 * span - 1.0, spec.lo - max(1e-6 * span, 1.0)))
    for bad in (above, below, math.nan, "12"):
        if spec.kind == "integer" and isinstance(bad, float) and math.isfinite(bad):
            bad = math.floor(bad) if bad > spec.hi else math.ceil(bad)
        with pytest.raises(InputError) as err:
            _build(cls, name, bad)
        e = err.value
        assert (e.owner, e.field, e.label) == (cls.__name__, name, spec.label)
        assert e.value is bad or (isinstance(bad, float) and math.isnan(bad))
        text = error_text(e)
        assert text.startswith(f"{spec.label} = ")
        if isinstance(bad, (int, float)) and math.isfinite(bad):
            shown = str(bad) if isinstance(bad, int) else f"{bad:g}"
            assert shown in text and (e.lo, e.hi) == (spec.lo, spec.hi)
            lo = f"{int(spec.lo)}" if spec.kind == "integer" else f"{spec.lo:g}"
            assert lo in text and "valid range" in text


@pytest.mark.parametrize("bad", [1, 0, "yes", "False", None, 1.0])
def test_a_flag_is_yes_or_no_only(bad):
    with pytest.raises(InputError) as err:
        DynamicsRequest(unsteady=bad)
    assert err.value.label.startswith("Unsteady-wind inertia")
    import numpy as np

    assert DynamicsRequest(modes=np.bool_(True)).modes is True  # stored back as bool


def test_the_rules_between_fields_are_the_requests():
    # a second ramp must start after the first one ends (the page checked this by hand)
    with pytest.raises(InputError) as err:
        DynamicsRequest(scenario="varying",
                        changes=(SpeedChange(20.0, 15.0, 5.0), SpeedChange(24.0, 7.0, 5.0)))
    e = err.value
    assert (e.owner, e.field, e.value, e.lo, e.hi) == ("SpeedChange", "start", 24.0, 25.0, 3600.0)
    assert error_text(e) == ("Change starts at (change 2) = 24 s must be after the previous "
                             "ramp ends; valid range [25, 3600] s")
    ok = DynamicsRequest(scenario="varying",
                         changes=(SpeedChange(20.0, 15.0, 5.0), SpeedChange(25.0, 7.0, 5.0)))
    assert [c.as_tuple() for c in ok.changes] == [(20.0, 15.0, 5.0), (25.0, 7.0, 5.0)]
    # a gust or turbulence needs a mean wind to be convected
    for sc in ("gust", "turbulence"):
        with pytest.raises(InputError) as err:
            DynamicsRequest(scenario=sc, speed=0.2)
        assert (err.value.field, err.value.lo, err.value.hi) == ("speed", 0.5, 30.0)
        assert "Mean wind at the aerostat = 0.2 m/s" in error_text(err.value)
    assert DynamicsRequest(scenario="steady", speed=0.0).speed == 0.0
    # a gust needs an amplitude
    with pytest.raises(InputError, match="both 0 m/s") as err:
        GustSettings(amplitude_u=0.0, amplitude_w=0.0)
    assert err.value.label == "Gust amplitude, horizontal"
    assert GustSettings(amplitude_u=0.0, amplitude_w=2.0).gust().amplitude_w == 2.0


def test_each_scenario_holds_its_own_parts_only_so_equal_runs_compare_equal():
    for sc in SCENARIOS:
        dyn = DynamicsRequest.for_scenario(sc)
        assert (len(dyn.changes) > 0) == (sc == "varying")
        assert (dyn.gust is not None) == (sc == "gust")
        assert (dyn.turbulence is not None) == (sc == "turbulence")
        assert DynamicsRequest.from_dict(dyn.to_dict()) == dyn
        hash(dyn)
    gusty = DynamicsRequest(scenario="gust", gust=GustSettings(amplitude_u=3.0))
    assert dataclasses.replace(gusty, scenario="steady") == DynamicsRequest(scenario="steady")
    # the custom W20 is read with the custom intensity only; the levels are MIL-HDBK-1797's
    t = TurbulenceSettings(intensity="light")
    assert t.w20_used == DRYDEN_W20["light"] and t.turbulence().w20 == DRYDEN_W20["light"]
    assert TurbulenceSettings(intensity="profile").turbulence().w20 is None
    assert TurbulenceSettings(intensity="custom", w20=12.0).turbulence().w20 == 12.0
    assert TurbulenceSettings(intensity="light", w20=99.0) == TurbulenceSettings(intensity="light")
    with pytest.raises(InputError, match="w20 = 99 m/s"):
        TurbulenceSettings(intensity="custom", w20=99.0)


def test_the_thesis_requests_are_the_settings_the_untyped_ones_had():
    """The thesis comparison's settings, as the dict of earlier releases wrote them (the
    golden simulate outputs hold them too)."""
    base = {"profile": "uniform", "exponent": 1.0 / 7.0, "roughness": 0.03, "body": "hull",
            "speed": 10.0, "segments": 20, "damping": 1.0, "unsteady": True, "wall": 120.0,
            "modes": False}
    assert thesis_request("varying").to_dict() == {
        **base, "scenario": "varying", "duration": 150.0, "changes": [(20.0, 15.0, 5.0)]}
    assert thesis_request("gust", duration=30.0).to_dict() == {
        **base, "scenario": "gust", "duration": 30.0,
        "gust": {"u": 5.0, "w": 0.0, "length": 60.0, "start": 20.0, "shape": "full",
                 "convected": True}}
    assert thesis_request("turbulence", seed=2).to_dict() == {
        **base, "scenario": "turbulence", "duration": 600.0, "speed": 15.0, "profile": "power",
        "turbulence": {"intensity": "profile", "w20": None, "seed": 2, "max_frequency": 1.0,
                       "fade_in": 20.0, "vertical": True, "spatial": True}}
    assert thesis_request("steady").duration == 60.0
    with pytest.raises(InputError) as err:
        thesis_request("turbulence", seed=-1)
    assert err.value.label == "Random seed"
    with pytest.raises(ValueError, match="valid options"):
        thesis_request("hurricane")


def test_the_untyped_dict_is_a_deprecated_adapter_only():
    dyn = DynamicsRequest.for_scenario("turbulence")
    with pytest.warns(DeprecationWarning, match="default_request"):
        old = scenarios.default_request("turbulence")
    assert old["inputs"] is None and old["turbulence"]["seed"] == 1
    with pytest.warns(DeprecationWarning, match="wind_of"):
        wind_old = scenarios.wind_of(old, 300.0)
    assert wind_old == scenarios.wind_of(dyn, 300.0)
    with pytest.warns(DeprecationWarning, match="read the attribute"):
        assert dyn["speed"] == 10.0
    with pytest.warns(DeprecationWarning):
        assert scenarios.event_time({**old, "scenario": "steady", "turbulence": None}) is None
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert scenarios.wind_of(dyn, 300.0).turbulence.seed == 1  # the typed path is quiet
    with pytest.raises(TypeError):
        scenarios.wind_of(("gust",), 300.0)


def test_the_six_dof_request_shares_the_base():
    assert issubclass(Request6, RunRequest) and issubclass(DynamicsRequest, RunRequest)
    r6 = Request6.for_scenario("veer")
    assert r6.header()["Mean wind at the aerostat [m/s]"] == 10.0
    assert list(r6.header())[0] == "6-DOF scenario"
    with pytest.raises(InputError) as err:
        Request6(duration=0.5)
    assert err.value.label == "Simulated time"


def _fails(argv, capsys, option):
    try:
        code = main(argv)
    except SystemExit as exc:
        code = exc.code
    assert code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    assert err[0].startswith(f"error: {option}: "), err[0]
    return err[0]


@pytest.mark.parametrize("argv, option, text", [
    (["--duration", "0"], "--duration", "Simulated time = 0 s is outside the valid range "
                                        "(0, 3600] s"),
    (["--duration", "4000", "--scenario", "turbulence"], "--duration", "(0, 3600] s"),
    (["--seed", "4294967296"], "--seed", "Random seed = 4294967296 is outside the valid range "
                                         "[0, 4294967295]"),
    (["--seed", "-1", "--scenario", "steady"], "--seed", "Random seed = -1"),
    (["--dof", "6", "--duration", "0.5"], "--duration", "[1, 3600] s"),
])
def test_simulate_bad_input_exits_2_with_one_line(argv, option, text, capsys):
    assert text in _fails(["simulate", *argv], capsys, option)


def test_simulate_help_reads_the_registry(capsys):
    with pytest.raises(SystemExit):
        main(["simulate", "--help"])
    out = " ".join(capsys.readouterr().out.split())
    d = field_spec(DynamicsRequest, "duration")
    s = field_spec(TurbulenceSettings, "seed")
    assert f"{d.label} [{d.unit}], valid (0, 3600] ([1, 3600] with --dof 6)" in out
    assert f"{s.label} [-], valid [0, 4294967295] (default 1)" in out
