"""The typed design report (aerostat_core.output.report_parts): the plain dict of before, the documented
shapes of every part, the deprecated key reads, and that no module reads the report by key."""

from __future__ import annotations

import ast
import pickle
from dataclasses import fields, replace
from pathlib import Path

import numpy as np
import pytest

from aerostat_core.geometry.fins import ARRANGEMENT_ANGLES_DEG
from aerostat_core.model.design import Design, DesignSummary, design
from aerostat_core.model.inputs import Requirement
from aerostat_core.model.io import inputs_to_dict
from aerostat_core.model.presets import practice_configuration, thesis_baseline
from aerostat_core.output.report import (
    DesignLimits,
    DesignReport,
    FinView,
    HullDimensions,
    KeyPoints,
    MomentCurve,
    PerformanceCurves,
    TetherProfile,
    TetherProfiles,
    confluence_lines,
    design_report,
    fin_outlines,
    performance_rows,
)

ROOT = Path(__file__).resolve().parents[2]


def _f(x) -> float:
    return float(np.asarray(x, dtype=float).reshape(-1)[0])


def _pre_typing_report(d: Design) -> dict:
    """The report dict as ``design_report`` built it before the parts were typed (the contract
    ``DesignReport.to_dict()`` keeps), written out from the Design's public attributes."""
    p, req, cfg = d.performance, d.requirement, d.configuration
    h, af = d.airframe.hull, d.airframe
    prow = performance_rows(d)
    x, z = d.tether_profile(float(req.design_wind))
    return {
        "summary": d.summary().to_dict(),
        "constraints": d.constraint_rows(),
        "violations": list(d.violations),
        "feasible": bool(d.feasible),
        "sized": bool(d.sized),
        "geometry_rows": d.geometry_rows(),
        "mass_rows": d.mass_rows(),
        "performance_rows": prow,
        "perf": {
            "wind_speed": np.asarray(p.wind_speed, float),
            "alpha_eq": np.asarray(p.alpha_eq, float),
            "dynamic_lift": np.asarray(p.dynamic_lift, float),
            "drag": np.asarray(p.drag, float),
            "blow_by": np.asarray(p.blow_by, float),
            "flying_height": np.asarray(p.flying_height, float),
            "tension_top": np.asarray(p.tension_top, float),
            "tension_winch": np.asarray(p.tension_winch, float),
            "safety_factor": np.asarray(p.safety_factor, float),
            "limited": np.asarray(p.limited, bool),
            "flag_text": [r["flags"] for r in prow],
        },
        "cm": {
            "alpha_deg": np.asarray(d.cm_alpha_deg, float),
            "cm": np.asarray(d.cm, float),
            "alpha_eq_deg": float(d.design_point["alpha_eq_deg"]),
            "wind": float(req.design_wind if req.design_wind > 0 else 10.0),
        },
        "tether": {
            "x": np.asarray(d.tether_x, float),
            "z": np.asarray(d.tether_z, float),
            "wind_speed": np.asarray(p.wind_speed, float),
            "design": {
                "x": np.asarray(x, float).reshape(-1),
                "z": np.asarray(z, float).reshape(-1),
                "wind": float(req.design_wind),
            },
        },
        "shape": h.shape,
        "hull": {
            "a1": _f(h.a1),
            "a2": _f(h.a2),
            "b": _f(h.b),
            "length": _f(h.length),
            "diameter": _f(h.diameter),
            "xi_cb": _f(h.xi_cb),
        },
        "fins": {"outlines": fin_outlines(d), "arrangement": cfg.fins.arrangement},
        "points": {
            "cb": (_f(h.xi_cb), 0.0),
            "cg": (_f(af.mass.xi_cg), _f(af.mass.z_cg)),
            "c": (_f(af.xi_c), _f(af.z_c)),
        },
        "confluence_lines": confluence_lines(d),
        "limits": {
            "blow_by_limit": float(req.blow_by_limit),
            "design_wind": float(req.design_wind),
            "min_safety_factor": float(req.min_tether_safety_factor),
            "altitude": float(req.altitude),
            "stall_deg": float(cfg.aero.fin_stall_angle_deg),
        },
        "inputs": inputs_to_dict(req, cfg),
    }


def _assert_same(old, new, path: str = "report") -> None:
    """Same type, keys in the same order, same dtype and shape, same values (NaN equal)."""
    assert type(new) is type(old), f"{path}: {type(new).__name__} != {type(old).__name__}"
    if isinstance(old, dict):
        assert list(new) == list(old), f"{path}: keys {list(new)} != {list(old)}"
        for k in old:
            _assert_same(old[k], new[k], f"{path}.{k}")
    elif isinstance(old, list | tuple):
        assert len(new) == len(old), f"{path}: length {len(new)} != {len(old)}"
        for i, (a, b) in enumerate(zip(old, new)):
            _assert_same(a, b, f"{path}[{i}]")
    elif isinstance(old, np.ndarray):
        assert (new.dtype, new.shape) == (old.dtype, old.shape), path
        np.testing.assert_array_equal(new, old, err_msg=path)
    elif isinstance(old, float) and old != old:
        assert new != new, path
    else:
        assert new == old, f"{path}: {new!r} != {old!r}"


def _designs() -> dict[str, Design]:
    req, cfg = thesis_baseline()
    practice = practice_configuration()
    return {
        "thesis baseline": design(req, cfg),
        "practice, sized": design(Requirement(payload_mass=30.0, altitude=500.0), practice),
        # the design wind between two sweep speeds: its own profile
        "design wind off the sweep": design(replace(req, wind_step=2.0, design_wind=15.0), cfg),
        "infeasible (limited rows)": design(replace(req, min_tether_safety_factor=15.0), cfg),
        "helikite": design(
            Requirement(),
            replace(practice, hull=replace(practice.hull, shape="helikite", fineness_ratio=None)),
        ),
    }


DESIGNS = _designs()


@pytest.fixture(params=list(DESIGNS), scope="module")
def case(request) -> tuple[Design, DesignReport]:
    d = DESIGNS[request.param]
    return d, design_report(d)


def test_to_dict_is_the_plain_dict_of_before(case):
    d, rep = case
    _assert_same(_pre_typing_report(d), rep.to_dict())


def test_every_part_is_a_frozen_dataclass_of_its_type(case):
    _, rep = case
    types = {
        "summary": DesignSummary,
        "perf": PerformanceCurves,
        "cm": MomentCurve,
        "tether": TetherProfiles,
        "hull": HullDimensions,
        "fins": FinView,
        "points": KeyPoints,
        "limits": DesignLimits,
    }
    for name, cls in types.items():
        part = getattr(rep, name)
        assert type(part) is cls, name
        field = fields(part)[0].name
        with pytest.raises(AttributeError):  # frozen
            setattr(part, field, None)
    assert type(rep.tether.design) is TetherProfile
    assert isinstance(rep.violations, tuple)
    assert pickle.loads(pickle.dumps(rep)).to_dict().keys() == rep.to_dict().keys()


def test_parts_carry_the_documented_shapes(case):
    d, rep = case
    n = np.size(d.performance.wind_speed)
    p = rep.perf
    for f in fields(p):
        value = getattr(p, f.name)
        if f.name == "flag_text":
            assert len(value) == n and all(isinstance(t, str) for t in value)
        else:
            assert np.shape(value) == (n,), f.name
            assert value.dtype == (bool if f.name == "limited" else float), f.name
    nodes = np.shape(d.tether_x)[0]
    t = rep.tether
    assert t.x.shape == t.z.shape == (nodes, n) and t.wind_speed.shape == (n,)
    assert t.design.x.shape == t.design.z.shape == (nodes,)
    assert t.design.wind == d.requirement.design_wind
    # each profile starts at the winch (last node, origin) and rises to the confluence point
    np.testing.assert_allclose(t.z[-1], 0.0, atol=1e-9)
    np.testing.assert_allclose(t.z[0], p.flying_height, rtol=1e-6)
    assert rep.cm.alpha_deg.shape == rep.cm.cm.shape and rep.cm.alpha_deg.ndim == 1
    assert rep.cm.alpha_deg.min() <= rep.cm.alpha_eq_deg <= rep.cm.alpha_deg.max()
    h = rep.hull
    assert h.length == pytest.approx(h.a1 + h.a2) and h.diameter == pytest.approx(2 * h.b)
    assert 0 < h.xi_cb < h.length
    assert len(rep.fins.outlines) == len(ARRANGEMENT_ANGLES_DEG[rep.fins.arrangement])
    for o in rep.fins.outlines:
        assert o.shape == (5, 3)
        np.testing.assert_array_equal(o[0], o[-1])  # closed
    for name in ("cb", "cg", "c"):
        pt = getattr(rep.points, name)
        assert isinstance(pt, tuple) and len(pt) == 2 and all(type(v) is float for v in pt)
    assert all(type(getattr(rep.limits, f.name)) is float for f in fields(rep.limits))
    assert rep.limits.design_wind == rep.summary.design_wind_m_s


def test_key_reads_still_work_for_one_release_and_warn():
    d = DESIGNS["thesis baseline"]
    rep = design_report(d)
    with pytest.warns(DeprecationWarning, match=r"DesignReport\.perf$"):
        perf = rep["perf"]
    with pytest.warns(DeprecationWarning, match=r"PerformanceCurves\.blow_by$"):
        np.testing.assert_array_equal(perf["blow_by"], rep.perf.blow_by)
    with pytest.warns(DeprecationWarning):
        assert rep["tether"]["design"]["x"] is rep.tether.design.x
    with pytest.warns(DeprecationWarning):
        assert rep.get("shape", "npl") == rep.shape
    with pytest.warns(DeprecationWarning):
        assert rep["fins"]["outlines"] == list(rep.fins.outlines)  # a list, as before
    # iteration, len and membership read no values: no warning (the suite makes it an error)
    assert list(rep) == list(rep.to_dict()) and list(rep.hull) == list(rep.hull.to_dict())
    assert "perf" in rep and "blow_by" in rep.perf and "nothing" not in rep


def test_parts_reject_arrays_of_the_wrong_shape():
    rep = design_report(DESIGNS["thesis baseline"])
    p = rep.perf
    with pytest.raises(ValueError, match="blow_by"):
        replace(p, blow_by=p.blow_by[:-1])
    with pytest.raises(ValueError, match="flag_text"):
        replace(p, flag_text=p.flag_text[:-1])
    t = rep.tether
    with pytest.raises(ValueError, match=r"\(nodes, "):
        replace(t, x=t.x[:, :-1], z=t.z[:, :-1])
    with pytest.raises(ValueError, match=r"\(5, 3\)"):
        replace(rep.fins, outlines=(rep.fins.outlines[0][:4],))


# --- nobody reads the report by key any more -------------------------------------------------

#: Keys that name a report part, or a field only the report or its summary has (the summary's
#: generic names, volume_m3 or feasible, are also the columns of many other rows).
REPORT_KEYS = frozenset(
    {f.name for f in fields(DesignReport)} - {"violations", "feasible", "sized", "shape", "inputs"}
) | {
    # part fields
    "flag_text", "outlines", "blow_by_limit", "min_safety_factor", "stall_deg", "xi_cb",
    "alpha_deg", "tension_winch",
    # summary fields
    "gross_buoyancy_N", "percent_static_lift", "blow_by_at_design_wind_m",
    "alpha_at_design_wind_deg", "tension_top_at_design_wind_N", "safety_factor_at_design_wind",
    "hull_mass_kg", "survival_wind_m_s", "safety_factor_at_survival_wind", "binding_constraint",
    "winch_pull_N", "winch_power_W", "ballonet_volume_m3", "helium_top_up_m3",
    "envelope_stress_margin",
}  # fmt: skip
#: Dicts that are not the report but share a key with it: (file, base name) -> what they are.
NOT_THE_REPORT = {
    ("aerostat_core/dynamics/sixdof.py", "mass"): "mass items by name (floats)",
    ("aerostat_core/cli/commands.py", "out"): "the envelope sweep (its points)",
    ("aerostat_core/dynamics/cli.py", "m"): "dynamics metrics (limit flags)",
    ("aerostat_core/studies/reference.py", "p"): "the point-aerostat reference case",
    ("aerostat_core/studies/shape_comparison.py", "m"): "mass items by name",
    ("aerostat_core/studies/shape_comparison.py", "t"): "ShapeComparison rows (thesis model)",
    ("aerostat_core/studies/shape_comparison.py", "f"): "ShapeComparison rows (full model)",
    ("app_ui/dynamics_view.py", "out"): "a dynamics run",
    ("app_ui/envelope_view.py", "mc"): "the Monte Carlo result",
    ("app_ui/form_model.py", "cfg"): "the configuration part of an inputs dict",
    ("app_ui/optimize_jobs.py", "request"): "an optimiser request (Pareto limits)",
    ("app_ui/optimize_view.py", "cmp"): "the optimiser's baseline-vs-optimum comparison",
    ("pages/5_Dynamics.py", "out"): "a dynamics run",
}


def _base_name(node: ast.expr) -> str:
    while isinstance(node, ast.Subscript | ast.Attribute | ast.Call):
        node = node.func if isinstance(node, ast.Call) else node.value
    return node.id if isinstance(node, ast.Name) else ast.unparse(node)


def _key_reads(text: str, rel: str) -> list[str]:
    """``x["key"]`` and ``x.get("key")`` reads of a report key in the source ``text`` of the
    file ``rel``, except mass items and the dicts of :data:`NOT_THE_REPORT`."""
    found = []
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Subscript) and isinstance(node.ctx, ast.Load):
            key, obj = node.slice, node.value
        elif (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr == "get"
            and node.args
        ):
            key, obj = node.args[0], node.func.value
        else:
            continue
        if not isinstance(key, ast.Constant):
            continue
        of_summary = (  # rep.summary["..."] or d.summary()["..."]: any key
            obj.func if isinstance(obj, ast.Call) else obj
        )
        of_summary = isinstance(of_summary, ast.Attribute) and of_summary.attr == "summary"
        if key.value not in REPORT_KEYS and not of_summary:
            continue
        if isinstance(obj, ast.Attribute) and obj.attr == "items":
            continue  # mass items by name (MassBreakdown.items["hull"])
        if (rel, _base_name(obj)) in NOT_THE_REPORT:
            continue
        found.append(f"{rel}:{node.lineno}: {ast.unparse(node)}")
    return found


def test_no_module_reads_the_report_by_string_key():
    found = []
    for folder in ("aerostat_core", "app_ui", "pages"):
        for path in sorted((ROOT / folder).rglob("*.py")):
            rel = path.relative_to(ROOT).as_posix()
            if rel != "aerostat_core/output/report_parts.py":  # defines the deprecated key reads
                found += _key_reads(path.read_text(encoding="utf-8"), rel)
    assert not found, (
        "read the design report by attribute (rep.perf.blow_by, rep.summary.volume_m3), "
        "not by key:\n" + "\n".join(found)
    )


def test_the_key_scan_finds_key_reads():
    """The scan is not vacuous: report reads by key are found, the listed other dicts are not."""
    text = (
        'p = rep["perf"]\n'
        'y = p["tension_winch"]\n'
        'bb = rep.summary["blow_by_at_design_wind_m"]\n'
        'shape = rep.get("hull")\n'
        'v = d.summary()["volume_m3"]\n'
        'hull = d.airframe.mass.items["hull"]\n'
        'kite = m["fins"]\n'
    )
    found = _key_reads(text, "aerostat_core/studies/shape_comparison.py")
    assert [f.split(": ", 1)[1] for f in found] == [
        "rep['perf']",
        "p['tension_winch']",
        "rep.summary['blow_by_at_design_wind_m']",
        "rep.get('hull')",
        "d.summary()['volume_m3']",
    ]
    assert len(_key_reads(text, "app_ui/plots.py")) == 6  # m["fins"] is listed only there


def test_the_scanned_keys_are_report_fields():
    from aerostat_core.model.design import MissionSummary

    classes = (DesignReport, PerformanceCurves, MomentCurve, TetherProfiles, HullDimensions,
               FinView, KeyPoints, DesignLimits, DesignSummary, MissionSummary)  # fmt: skip
    names = {f.name for cls in classes for f in fields(cls)}
    assert REPORT_KEYS <= names, sorted(REPORT_KEYS - names)


def test_report_arrays_are_read_only_views_and_the_design_keeps_its_own(case):
    """The app shares one report between sessions: a write into it must fail, not leak."""
    d, rep = case
    arrays = [getattr(rep.perf, f.name) for f in fields(rep.perf) if f.name != "flag_text"]
    arrays += [rep.cm.alpha_deg, rep.cm.cm, rep.tether.x, rep.tether.z, rep.tether.wind_speed]
    arrays += [rep.tether.design.x, rep.tether.design.z, *rep.fins.outlines, *rep.confluence_lines]
    for a in arrays:
        assert not a.flags.writeable
        with pytest.raises(ValueError, match="read-only"):
            a[...] = 0.0
    assert d.performance.blow_by.flags.writeable  # a view: the design's array is untouched
    np.testing.assert_array_equal(rep.perf.blow_by, d.performance.blow_by)


def test_reports_and_array_parts_compare_by_identity_without_raising():
    d = next(iter(DESIGNS.values()))
    a, b = design_report(d), design_report(d)
    assert a == a and a != b  # before: "truth value of an array is ambiguous"
    assert a.perf == a.perf and a.perf != b.perf and a.tether != b.tether
    assert a.hull == b.hull and a.limits == b.limits  # scalar parts compare by value
    assert len({a, b, a}) == 2
