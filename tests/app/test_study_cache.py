"""The study caches (Sensitivity, Optimise, Envelope, Shapes, Dynamics) share the app's one
process-wide store, keyed by the frozen inputs and hashable request values, never JSON text.

Each test uses inputs no other test computes (a payload of 11.37 kg etc.), and the engine
calls are replaced by counters, so a count of 1 means one computation for equal requests."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest

from aerostat_core import Configuration, Requirement, thesis_baseline
from aerostat_core.dynamics.request import DynamicsRequest
from aerostat_core.model.io import inputs_from_dict, inputs_to_dict
from app_ui import cache, dynamics_view, envelope_view, optimize_jobs, shapes_view
from app_ui.state import inputs_key


def _inputs(payload: float) -> tuple[Requirement, Configuration]:
    """Inputs built from scratch every call (equal values, distinct objects)."""
    req, cfg = thesis_baseline()
    return inputs_from_dict(inputs_to_dict(replace(req, payload_mass=payload), cfg))


def test_memo_computes_once_per_distinct_key_and_never_stores_a_failure():
    calls = []

    def compute(value):
        calls.append(value)
        if value == "bad":
            raise ValueError("rejected")
        return value

    kind = "test_memo_counts"
    a, b = _inputs(11.11), _inputs(11.11)
    assert a[0] is not b[0] and a == b  # built separately, equal
    key_a, key_b = cache.frozen_inputs(*a), cache.frozen_inputs(*b)
    assert cache.memo(kind, key_a, lambda: compute("x")) == "x"
    assert cache.memo(kind, key_b, lambda: compute("y")) == "x"  # hit: equal frozen inputs
    assert calls == ["x"]
    other = cache.frozen_inputs(*_inputs(11.12))  # one field differs
    assert cache.memo(kind, other, lambda: compute("z")) == "z"
    assert calls == ["x", "z"]
    for _ in range(2):  # a failure stores nothing: the next call computes again
        with pytest.raises(ValueError):
            cache.memo(kind, ("bad",), lambda: compute("bad"))
    assert calls == ["x", "z", "bad", "bad"]
    keys = cache.memo_keys(kind)
    assert keys == [key_a, other]
    assert all(isinstance(k[0], Requirement) and isinstance(k[1], Configuration) for k in keys)
    with pytest.raises(TypeError):  # an unhashable part (a dict) is refused, never stringified
        cache.memo(kind, ({"a": 1},), lambda: 1)


def test_memo_keeps_at_most_its_size():
    kind = "test_memo_size"
    for i in range(5):
        cache.memo(kind, (i,), lambda i=i: i, size=3)
    assert cache.memo_keys(kind) == [(2,), (3,), (4,)]
    assert cache.peek(kind, (1,)) is None and cache.peek(kind, (2,)) == 2


def test_sensitivity_is_keyed_by_the_frozen_inputs_and_the_bounds(monkeypatch):
    calls = []

    def fake(req, cfg, ranges, n_points, resize):
        calls.append((req.payload_mass, ranges, n_points, resize))
        return object()

    monkeypatch.setattr(optimize_jobs, "one_at_a_time", fake)
    ranges = {"position": (0.6, 0.7), "fineness_ratio": (2.5, 4.0)}
    first = optimize_jobs.cached_sensitivity(*_inputs(11.37), ranges, 7, True)
    again = optimize_jobs.cached_sensitivity(
        *_inputs(11.37), {"fineness_ratio": [2.5, 4.0], "position": [0.6, 0.7]}, 7, 1
    )
    assert again is first and len(calls) == 1  # equal request built separately: one compute
    assert calls[0][1] == {"fineness_ratio": (2.5, 4.0), "position": (0.6, 0.7)}
    optimize_jobs.cached_sensitivity(*_inputs(11.38), ranges, 7, True)  # payload differs
    optimize_jobs.cached_sensitivity(*_inputs(11.37), {"position": (0.6, 0.71)}, 7, True)
    assert len(calls) == 3
    key = next(k for k in cache.memo_keys("sensitivity") if k[0].payload_mass == 11.37)
    assert isinstance(key, optimize_jobs.SensitivityKey)
    req, cfg = key.requirement, key.configuration
    assert isinstance(req, Requirement) and isinstance(cfg, Configuration)
    assert req == req.resolved()  # the limits as applied
    assert key.bounds == (("fineness_ratio", 2.5, 4.0), ("position", 0.6, 0.7))
    assert (key.n_points, key.resize) == (7, True)
    assert not any(
        isinstance(part, str) and "{" in part for k in cache.memo_keys("sensitivity") for part in k
    )


def test_a_solver_run_is_shared_and_reports_progress_only_when_it_computes(monkeypatch):
    calls = []

    def fake(problem, solver, level, seed, progress=None):
        calls.append((problem.requirement.payload_mass, solver, seed))
        if progress is not None:
            progress(1.0, "Fake: done")
        return object()

    monkeypatch.setattr(optimize_jobs, "solve", fake)
    shown = []
    args = ({"position": (0.6, 0.7)}, "total_mass", "pso", "quick", 5)
    first = optimize_jobs.solve_shared(
        *_inputs(11.41), *args, progress=lambda f, t: shown.append(t)
    )
    second = optimize_jobs.cached_solve(*_inputs(11.41), *args)  # another session, same request
    assert second is first and calls == [(11.41, "pso", 5)] and shown == ["Fake: done"]
    optimize_jobs.cached_solve(*_inputs(11.41), *args[:-1], 6)  # another seed
    assert len(calls) == 2


def test_a_cancelled_run_is_not_stored(monkeypatch):
    class Cancelled(Exception):  # what Streamlit raises from the progress bar on Cancel
        pass

    def fake(problem, solver, level, seed, progress=None):
        progress(0.5, "half")
        return object()

    def cancel(frac, text):
        raise Cancelled

    monkeypatch.setattr(optimize_jobs, "solve", fake)
    args = (*_inputs(11.43), {"position": (0.6, 0.7)}, "total_mass", "pso", "quick", 0)
    with pytest.raises(Cancelled):
        optimize_jobs.solve_shared(*args, progress=cancel)
    assert not [k for k in cache.memo_keys("solve") if k[0].payload_mass == 11.43]
    assert optimize_jobs.solve_shared(*args, progress=lambda f, t: None) is not None


def test_page_studies_key_their_json_text_inputs_by_the_frozen_inputs(monkeypatch):
    """Envelope and Shapes take the session's inputs JSON: two texts of equal inputs (keys in
    another order) hit one entry, keyed by the frozen inputs."""
    calls = []
    monkeypatch.setattr(envelope_view, "operating_envelope", lambda d: calls.append(d) or "env")
    monkeypatch.setattr(
        shapes_view, "optimize_shapes", lambda r, c, objective: calls.append(objective) or _Rows()
    )
    d = inputs_to_dict(*_inputs(11.47))
    text = inputs_key(d)
    shuffled = json.dumps({k: d[k] for k in reversed(list(d))})
    assert shuffled != text
    assert envelope_view.cached_envelope(text) == envelope_view.cached_envelope(shuffled) == "env"
    assert shapes_view.cached_shape_study(text, "volume") == shapes_view.cached_shape_study(
        shuffled, "volume"
    )
    assert len(calls) == 2
    (key,) = [k for k in cache.memo_keys("envelope") if k[0].payload_mass == 11.47]
    assert key == cache.frozen_inputs(*_inputs(11.47))


class _Rows:
    def rows(self):
        return [{"shape": "npl"}]


def test_dynamics_store_key_is_the_frozen_request():
    """The Dynamics form's run key: the frozen design inputs and the typed request, equal for
    equal values however they were typed ("5" or 5.0, inputs rebuilt from JSON)."""
    req, cfg = _inputs(11.53)
    inputs = inputs_to_dict(req, cfg)
    a = {"dyn_source": "Current design", "dyn_speed": "10", "dyn_gu": "5", "dyn_gw": "0"}
    b = {"dyn_gw": 0.0, "dyn_gu": 5.0, "dyn_speed": "10,0", "dyn_source": "Current design"}
    ka = dynamics_view.build_run(a, inputs, {})
    kb = dynamics_view.build_run(b, json.loads(json.dumps(inputs)), {})
    assert ka == kb and hash(ka) == hash(kb)
    assert isinstance(ka, dynamics_view.DynamicsKey)
    assert (ka.requirement, ka.configuration) == cache.frozen_inputs(req, cfg)
    assert type(ka.request) is DynamicsRequest  # typed, validated once, never JSON
    assert ka.request.speed == 10.0 and ka.request.gust.amplitude_u == 5.0
    thesis = dynamics_view.build_run({**a, "dyn_source": dynamics_view.THESIS}, inputs, {})
    assert thesis.requirement is None and thesis.configuration is None
    assert thesis.request == ka.request and thesis != ka
    other = dynamics_view.build_run({**a, "dyn_gu": "5.5"}, inputs, {})
    assert other.request != ka.request and other != ka


def test_freeze_makes_plain_data_hashable_and_keeps_kinds_apart():
    plain = {"b": [1, {"c": 2}], "a": None, "on": True}
    frozen = cache.freeze(plain)
    hash(frozen)
    assert cache.thaw(frozen) == plain
    assert cache.freeze({"b": [1], "a": None}) == cache.freeze({"a": None, "b": [1]})  # key order
    # Equal in Python, different requests: they must not share a cache entry.
    assert cache.freeze({"a": True}) != cache.freeze({"a": 1})
    assert cache.freeze({"a": 1}) != cache.freeze([["a", 1]])
    assert cache.freeze([1, 2]) != cache.freeze({"1": 2})
    with pytest.raises(TypeError):
        cache.freeze({"a": {1, 2}})


def test_a_second_caller_of_a_key_being_computed_waits_for_it_instead_of_computing_again():
    import threading
    import time

    calls = []
    started = threading.Event()

    def compute():
        calls.append(1)
        started.set()
        time.sleep(0.2)  # long enough for the second caller to arrive while this runs
        return object()

    results = []
    first = threading.Thread(target=lambda: results.append(cache.memo("test_wait", 1, compute)))
    first.start()
    started.wait(5)
    second = cache.memo("test_wait", 1, compute)
    first.join(5)
    assert len(calls) == 1 and results == [second]


def test_a_waiter_computes_for_itself_when_the_first_compute_fails():
    import threading
    import time

    started = threading.Event()

    def failing():
        started.set()
        time.sleep(0.1)
        raise ValueError("rejected request")

    errors = []

    def run_first():
        try:
            cache.memo("test_wait_fail", 1, failing)
        except ValueError as exc:
            errors.append(str(exc))

    first = threading.Thread(target=run_first)
    first.start()
    started.wait(5)
    assert cache.memo("test_wait_fail", 1, lambda: "computed") == "computed"
    first.join(5)
    assert errors == ["rejected request"]
    assert cache.memo_keys("test_wait_fail") == [1]


def test_a_dynamics_request_whose_inputs_no_longer_read_is_refused_and_says_why():
    bad = inputs_to_dict(*_inputs(11.59))
    bad["requirement"]["payload_mass"] = -1.0
    with pytest.raises(ValueError, match="payload_mass"):
        dynamics_view.build_run({"dyn_source": "Current design", "dyn_speed": "10"}, bad, {})


# --- every study key of the Sensitivity and Optimise pages is a NamedTuple read by name ---------

_BOUNDS = {"position": (0.6, 0.7), "fineness_ratio": (2.5, 4.0)}


def _run_studies(monkeypatch, payload: float) -> dict[str, dict]:
    """Every cached study of :mod:`app_ui.optimize_jobs` once, on fake engines that record the
    arguments by the engine's parameter names: {cache kind: arguments}."""
    seen: dict[str, dict] = {}

    def one_at_a_time(req, cfg, ranges, n_points, resize):
        seen["sensitivity"] = dict(
            req=req, cfg=cfg, ranges=ranges, n_points=n_points, resize=resize
        )
        return object()

    def two_variable_map(req, cfg, x_variable, y_variable, ranges, n, resize):
        seen["sensitivity_map"] = dict(
            req=req, x_variable=x_variable, y_variable=y_variable, ranges=ranges, n=n, resize=resize
        )
        return object()

    def solve(problem, solver, level, seed, progress=None):
        seen["solve"] = dict(
            req=problem.requirement,
            objective=problem.objective,
            solver=solver,
            level=level,
            seed=seed,
        )
        return object()

    def pareto_front(req, cfg, bounds, limits, objective, starts):
        seen["pareto"] = dict(
            req=req, bounds=bounds, limits=limits, objective=objective, starts=starts
        )
        return object()

    designs = []
    monkeypatch.setattr(optimize_jobs, "one_at_a_time", one_at_a_time)
    monkeypatch.setattr(optimize_jobs, "two_variable_map", two_variable_map)
    monkeypatch.setattr(optimize_jobs, "solve", solve)
    monkeypatch.setattr(optimize_jobs, "pareto_front", pareto_front)
    monkeypatch.setattr(optimize_jobs, "optimum_configuration", lambda base, x: ("optimum", x))
    monkeypatch.setattr(cache, "design_of", lambda req, cfg: designs.append(cfg) or cfg)
    monkeypatch.setattr(optimize_jobs, "design_change_rows", lambda b, o: [b, o])
    monkeypatch.setattr(optimize_jobs, "thesis_comparison_rows", lambda rows: rows)
    monkeypatch.setattr(optimize_jobs, "curves_of", lambda d: d)
    monkeypatch.setattr(optimize_jobs, "performance_comparison_rows", lambda b, o: [])

    req, cfg = _inputs(payload)
    optimize_jobs.cached_sensitivity(req, cfg, _BOUNDS, 7, False)
    optimize_jobs.cached_map(req, cfg, "position", "fineness_ratio", _BOUNDS, 9, True)
    optimize_jobs.cached_solve(req, cfg, _BOUNDS, "volume", "de", "normal", 3)
    optimize_jobs.cached_pareto(req, cfg, _BOUNDS, "volume", [40, 60.5], [{"position": 0.65}])
    optimize_jobs.cached_comparison(req, cfg, {"position": 0.65, "fineness_ratio": 3.0})
    seen["optimum_comparison"] = dict(designs=designs)
    return seen


#: Cache kind -> (key type, the fields after requirement and configuration).
STUDY_KEYS = {
    "sensitivity": (optimize_jobs.SensitivityKey, ("bounds", "n_points", "resize")),
    "sensitivity_map": (
        optimize_jobs.MapKey,
        ("x_variable", "y_variable", "bounds", "n_points", "resize"),
    ),
    "solve": (optimize_jobs.SolveKey, ("bounds", "objective", "solver", "level", "seed")),
    "pareto": (optimize_jobs.ParetoKey, ("bounds", "objective", "limits", "starts")),
    "optimum_comparison": (optimize_jobs.ComparisonKey, ("optimum",)),
}


def test_each_study_key_is_a_named_tuple_whose_values_reach_the_engine_by_name(monkeypatch):
    seen = _run_studies(monkeypatch, 11.61)
    assert set(seen) == set(STUDY_KEYS)
    for kind, (key_type, rest) in STUDY_KEYS.items():
        assert issubclass(key_type, tuple)
        assert key_type._fields == ("requirement", "configuration", *rest)
        (key,) = [k for k in cache.memo_keys(kind) if k.requirement.payload_mass == 11.61]
        assert type(key) is key_type, kind
        assert isinstance(key.requirement, Requirement) and key.requirement.resolved() == (
            key.requirement
        )
        assert isinstance(key.configuration, Configuration)
        hash(key)
    bounds = {"fineness_ratio": (2.5, 4.0), "position": (0.6, 0.7)}
    assert seen["sensitivity"]["ranges"] == bounds
    assert (seen["sensitivity"]["n_points"], seen["sensitivity"]["resize"]) == (7, False)
    m = seen["sensitivity_map"]
    assert (m["x_variable"], m["y_variable"], m["n"], m["resize"]) == (
        "position",
        "fineness_ratio",
        9,
        True,
    )
    s = seen["solve"]
    assert (s["objective"], s["solver"], s["level"], s["seed"]) == ("volume", "de", "normal", 3)
    p = seen["pareto"]
    assert (p["bounds"], p["limits"], p["objective"]) == (bounds, [40.0, 60.5], "volume")
    assert p["starts"] == [{"position": 0.65}]
    base, optimum = seen["optimum_comparison"]["designs"]
    assert isinstance(base, Configuration)
    assert optimum == ("optimum", {"fineness_ratio": 3.0, "position": 0.65})


def test_a_study_key_built_in_another_field_order_hits_only_when_every_value_is_equal(
    monkeypatch,
):
    _run_studies(monkeypatch, 11.67)
    for kind, (key_type, rest) in STUDY_KEYS.items():
        (key,) = [k for k in cache.memo_keys(kind) if k.requirement.payload_mass == 11.67]
        held = cache.peek(kind, key)
        assert held is not None
        # The same values by keyword, the fields named in reverse order and the inputs rebuilt.
        req, cfg = cache.frozen_inputs(*_inputs(11.67))
        values = {**key._asdict(), "requirement": req, "configuration": cfg}
        rebuilt = key_type(**dict(reversed(values.items())))
        assert rebuilt == key and rebuilt is not key
        assert cache.memo(kind, rebuilt, lambda: pytest.fail("a hit must not compute")) is held
        # One field differing (the last, whatever it is) misses.
        last = rest[-1]
        value = getattr(key, last)
        other = (
            not value
            if isinstance(value, bool)
            else value + 1
            if isinstance(value, int)
            else value + "x"
            if isinstance(value, str)
            else value[:-1]
        )
        assert cache.peek(kind, key._replace(**{last: other})) is None, kind
    # Two fields of one type swapped: a different request, a different entry.
    (m,) = [k for k in cache.memo_keys("sensitivity_map") if k.requirement.payload_mass == 11.67]
    swapped = m._replace(x_variable=m.y_variable, y_variable=m.x_variable)
    assert swapped != m and cache.peek("sensitivity_map", swapped) is None


# --- the Envelope, Shapes and Dynamics study keys: NamedTuples read by name as well ----------

_SITE = {
    "kind": "weibull",
    "shape": 2.2,
    "scale": 6.5,
    "reference_height": 10.0,
    "shear_exponent": 0.14,
    "target": 0.9,
}
_CSV_SITE = {**_SITE, "kind": "csv", "reference_height": 12.0, "shear_exponent": 0.2}
_CSV = b"timestamp,speed\n2020-01-01T00:00,5.0\n"


def _run_page_studies(monkeypatch, payload: float) -> dict[str, dict]:
    """Every cached study of :mod:`app_ui.envelope_view`, :mod:`app_ui.shapes_view` and
    :mod:`app_ui.dynamics_view` once, on fake engines that record the arguments by the engine's
    parameter names: {cache kind: arguments}. The library volume is ``payload`` m3 and the
    thesis seed ``round(100 * payload)``, so every key of the run can be found again."""
    seen: dict[str, dict] = {}

    def record(kind, result=None, **kwargs):
        seen[kind] = kwargs
        return object() if result is None else result

    monkeypatch.setattr(cache, "design_of", lambda req, cfg: ("design", req, cfg))
    e, s, d = envelope_view, shapes_view, dynamics_view
    monkeypatch.setattr(e, "operating_envelope", lambda d: record("envelope", d=d))
    monkeypatch.setattr(
        e,
        "flyable_time",
        lambda d, site, target_availability: record(
            "flyable", _Summary(), d=d, site=site, target_availability=target_availability
        ),
    )
    monkeypatch.setattr(
        e,
        "monte_carlo",
        lambda d, n, seed: record("monte_carlo", _MonteCarlo(), d=d, n=n, seed=seed),
    )
    monkeypatch.setattr(
        e, "rule_set_spread", lambda req, n, seed: record("rules_spread", req=req, n=n, seed=seed)
    )
    monkeypatch.setattr(
        e,
        "read_wind_csv",
        lambda data, reference_height, shear_exponent: (
            "csv",
            data,
            reference_height,
            shear_exponent,
        ),
    )

    def build_report(d, site, n_monte_carlo, seed, base_requirement, units="SI"):
        return record(
            "report_html",
            "html",
            d=d,
            site=site,
            n_monte_carlo=n_monte_carlo,
            seed=seed,
            base_requirement=base_requirement,
            units=units,
        )

    monkeypatch.setattr(e, "build_report", build_report)
    monkeypatch.setattr(
        s, "shape_dimensions_rows", lambda volume: record("shape_library", volume=volume)
    )
    monkeypatch.setattr(
        s,
        "optimize_shapes",
        lambda req, cfg, objective: record(
            "shape_study", _Rows(), req=req, cfg=cfg, objective=objective
        ),
    )
    monkeypatch.setattr(
        s,
        "fineness_sweeps",
        lambda req, cfg, n_points: record("shape_sweeps", {}, req=req, cfg=cfg, n_points=n_points),
    )
    monkeypatch.setattr(
        s,
        "gore_pattern",
        lambda d, n_gores, seam_allowance: record(
            "exports", _Pattern(), d=d, n_gores=n_gores, seam_allowance=seam_allowance
        ),
    )
    for name in ("design_stl", "gore_dxf", "gore_svg"):
        monkeypatch.setattr(s, name, lambda p: b"")
    monkeypatch.setattr(s, "gore_csv", lambda p: "")
    monkeypatch.setattr(d, "run", lambda key, progress=None: record("dynamics", key=key))
    monkeypatch.setattr(d, "_thesis_comparison", lambda seed: record("dynamics_thesis", seed=seed))

    req, cfg = _inputs(payload)
    text = inputs_key(inputs_to_dict(req, cfg))
    site_json = json.dumps(_SITE, sort_keys=True)
    e.cached_envelope(text)
    e.cached_flyable(text, site_json, None)
    e.cached_monte_carlo(text, 5000, 17)
    e.cached_rules_spread(text, 23)
    e.cached_report_html(text, json.dumps(_CSV_SITE, sort_keys=True), _CSV, 3000, 29)
    s.cached_library(payload)
    s.cached_shape_study(text, "volume")
    s.cached_sweeps(text, 11)
    s.cached_exports(text, 14, 25.0)
    d.run_cached(d.build_run({"dyn_source": "Current design", "dyn_speed": "9"},
                             inputs_to_dict(req, cfg), {}))
    d.thesis_comparison(round(100 * payload))
    return seen


class _Summary:
    def summary(self):
        return {}


class _MonteCarlo(_Summary):
    speeds = blow_by = tension = specs = ()


class _Pattern:
    pattern_area = hull_area = 1.0


#: Cache kind -> (key type, its fields, whether its requirement is resolved (False: as given,
#: each rule set fills in its own limits; None: no requirement)).
PAGE_STUDY_KEYS = {
    "envelope": (envelope_view.EnvelopeKey, ("requirement", "configuration"), True),
    "flyable": (envelope_view.FlyableKey, ("requirement", "configuration", "site"), True),
    "monte_carlo": (
        envelope_view.MonteCarloKey,
        ("requirement", "configuration", "n_samples", "seed"),
        True,
    ),
    "rules_spread": (envelope_view.SpreadKey, ("requirement", "seed"), False),
    "report_html": (
        envelope_view.ReportKey,
        ("requirement", "configuration", "site", "n_samples", "seed", "units"),
        False,
    ),
    "shape_library": (shapes_view.LibraryKey, ("volume",), None),
    "shape_study": (shapes_view.ShapeStudyKey, ("requirement", "configuration", "objective"), True),
    "shape_sweeps": (shapes_view.SweepsKey, ("requirement", "configuration", "n_points"), True),
    "exports": (
        shapes_view.ExportKey,
        ("requirement", "configuration", "n_gores", "seam_mm"),
        True,
    ),
    "dynamics": (dynamics_view.DynamicsKey, ("requirement", "configuration", "request"), True),
    "dynamics_thesis": (dynamics_view.ThesisKey, ("seed",), None),
}


def _page_key(kind: str, payload: float):
    """The one key of ``kind`` that :func:`_run_page_studies` (``payload``) stored."""
    resolved = PAGE_STUDY_KEYS[kind][2]
    if resolved is None:
        field, value = (
            ("volume", payload) if kind == "shape_library" else ("seed", round(100 * payload))
        )
        found = [k for k in cache.memo_keys(kind) if getattr(k, field) == value]
    else:
        found = [k for k in cache.memo_keys(kind) if k.requirement.payload_mass == payload]
    (key,) = found
    return key


def _parts(value):
    """Every value nested in a key (tuples opened)."""
    if isinstance(value, tuple):
        for v in value:
            yield from _parts(v)
    else:
        yield value


def test_each_page_study_key_is_a_named_tuple_whose_values_reach_the_engine_by_name(monkeypatch):
    seen = _run_page_studies(monkeypatch, 11.73)
    assert set(seen) == set(PAGE_STUDY_KEYS)
    req, cfg = _inputs(11.73)
    for kind, (key_type, fields, resolved) in PAGE_STUDY_KEYS.items():
        assert issubclass(key_type, tuple) and key_type._fields == fields, kind
        key = _page_key(kind, 11.73)
        assert type(key) is key_type, kind
        hash(key)
        if resolved is not None:
            assert isinstance(key.requirement, Requirement), kind
            assert key.requirement == (req.resolved() if resolved else req), kind
        if "configuration" in fields:
            assert isinstance(key.configuration, Configuration) and key.configuration == cfg
        # frozen values only: never the JSON text of the inputs, the site or the request
        assert not any(isinstance(v, str) and v.lstrip()[:1] in "{[" for v in _parts(key)), kind
    resolved_design = ("design", req.resolved(), cfg)
    given_design = ("design", req, cfg)
    assert seen["envelope"] == {"d": resolved_design}
    fly = seen["flyable"]
    assert fly["d"] == resolved_design and fly["target_availability"] == 0.9
    site = fly["site"]
    assert (site.shape, site.scale, site.reference_height, site.shear_exponent) == (
        2.2,
        6.5,
        10.0,
        0.14,
    )
    assert seen["monte_carlo"] == {"d": resolved_design, "n": 5000, "seed": 17}
    assert seen["rules_spread"] == {"req": req, "n": 2000, "seed": 23}
    assert seen["report_html"] == {
        "d": given_design,
        "site": ("csv", _CSV, 12.0, 0.2),
        "n_monte_carlo": 3000,
        "seed": 29,
        "base_requirement": req,
        "units": "SI",
    }
    report = _page_key("report_html", 11.73)
    assert type(report.site) is envelope_view.SiteKey and report.site.csv == _CSV
    assert cache.thaw(report.site.spec) == _CSV_SITE
    assert seen["shape_library"] == {"volume": 11.73}
    assert seen["shape_study"] == {"req": req.resolved(), "cfg": cfg, "objective": "volume"}
    assert seen["shape_sweeps"] == {"req": req.resolved(), "cfg": cfg, "n_points": 11}
    assert seen["exports"] == {"d": resolved_design, "n_gores": 14, "seam_allowance": 0.025}
    assert seen["dynamics"]["key"].request.speed == 9.0
    assert _page_key("dynamics", 11.73).request == DynamicsRequest(speed=9.0)
    assert seen["dynamics_thesis"] == {"seed": 1173}


def _other(value):
    """A value of the same kind as ``value`` that differs from it."""
    if isinstance(value, bool):
        return not value
    if isinstance(value, (int, float)):
        return value + 1
    if isinstance(value, str):
        return value + "x"
    if isinstance(value, DynamicsRequest):  # another run
        return replace(value, duration=value.duration + 1.0)
    if isinstance(value, Configuration):  # another hull
        return replace(
            value, hull=replace(value.hull, fineness_ratio=value.hull.fineness_ratio + 0.1)
        )
    return value[:-1]


def test_a_page_study_key_built_in_another_field_order_hits_only_when_every_value_is_equal(
    monkeypatch,
):
    _run_page_studies(monkeypatch, 11.79)
    for kind, (key_type, fields, resolved) in PAGE_STUDY_KEYS.items():
        key = _page_key(kind, 11.79)
        held = cache.peek(kind, key)
        assert held is not None, kind
        # The same values by keyword, the fields named in reverse order and the inputs rebuilt.
        values = key._asdict()
        if resolved is not None:
            req, cfg = _inputs(11.79)
            values["requirement"] = req.resolved() if resolved else req
            if "configuration" in values:
                values["configuration"] = cfg
        rebuilt = key_type(**dict(reversed(values.items())))
        assert rebuilt == key and rebuilt is not key
        assert cache.memo(kind, rebuilt, lambda: pytest.fail("a hit must not compute")) is held
        # One field differing (the last, whatever it is) misses.
        last = fields[-1]
        assert cache.peek(kind, key._replace(**{last: _other(getattr(key, last))})) is None, kind
    # Two fields of one type swapped (samples and seed): a different request, a different entry.
    mc = _page_key("monte_carlo", 11.79)
    swapped = mc._replace(n_samples=mc.seed, seed=mc.n_samples)
    assert swapped != mc and cache.peek("monte_carlo", swapped) is None
    # The same site with another CSV file is another request.
    fly = _page_key("flyable", 11.79)
    assert cache.peek("flyable", fly._replace(site=fly.site._replace(csv=b"x"))) is None


def _memo_modules():
    """Every module of app_ui/ that caches a study through :func:`app_ui.cache.memo` (the store
    itself aside)."""
    import importlib
    import pathlib

    root = pathlib.Path(cache.__file__).parent
    return [
        importlib.import_module(f"app_ui.{path.stem}")
        for path in sorted(root.glob("*.py"))
        if path.stem != "cache" and "cache.memo(" in path.read_text(encoding="utf-8")
    ]


def test_no_study_key_is_read_by_position():
    """The computes of every study read ``key.bounds``, ``key.seed`` etc., never ``key[2]``,
    ``*key`` or ``a, b = key``."""
    import ast
    import inspect

    modules = _memo_modules()
    names = {m.__name__ for m in modules}
    assert {
        "app_ui.optimize_jobs",
        "app_ui.envelope_view",
        "app_ui.shapes_view",
        "app_ui.dynamics_view",
    } <= names

    def is_key(node) -> bool:
        return isinstance(node, ast.Name) and node.id == "key"

    for module in modules:
        tree = ast.parse(inspect.getsource(module))
        found = [
            ast.unparse(node)
            for node in ast.walk(tree)
            if (isinstance(node, (ast.Subscript, ast.Starred)) and is_key(node.value))
            or (
                isinstance(node, ast.Assign)
                and is_key(node.value)
                and any(isinstance(t, (ast.Tuple, ast.List)) for t in node.targets)
            )
        ]
        assert found == [], module.__name__
