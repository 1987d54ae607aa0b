"""The sizing search and design() reuse what they computed (issue 10 item 3, issue 12 item 8).

- size_volume finds the same lattice volume as the plain nested rounds (the reference below),
  with the predicted batch and with the fallback;
- the state it returns is the constraint table at that volume (no second evaluation);
- design() takes its airframe, table and design-wind solution from the search, and matches a
  fresh evaluation at its volume;
- the typed summary and report give the keys of before.
"""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest

from aerostat_core import HullSpec, Requirement, design, size_volume, thesis_baseline
from aerostat_core.geometry.shapes import SHAPE_INFO
from aerostat_core.model import sizing as sizing_mod
from aerostat_core.model.airframe import build_airframe
from aerostat_core.model.constraints import NAMES, constraint_state
from aerostat_core.model.performance import evaluate
from aerostat_core.model.presets import practice_configuration
from aerostat_core.output.report import DesignReport, design_report

#: The keys of ``design --json`` (a public contract), in order, for a design with a mission.
SUMMARY_KEYS = [
    "volume_m3", "length_m", "diameter_m", "total_mass_kg", "gross_buoyancy_N", "free_lift_N",
    "free_lift_kg", "percent_static_lift", "design_wind_m_s", "blow_by_at_design_wind_m",
    "alpha_at_design_wind_deg", "tension_top_at_design_wind_N", "safety_factor_at_design_wind",
    "gas_cost_USD", "feasible", "hull_mass_kg", "tether_mass_kg", "altitude_loss_m",
    "survival_wind_m_s", "safety_factor_at_survival_wind", "binding_constraint", "violations",
    "rules", "ballonet_volume_m3", "days_to_top_up", "helium_top_up_m3",
    "envelope_stress_margin", "winch_pull_N", "winch_power_W",
]


def _reference_volume(req, cfg, f, dsf, pos, rounds=4):
    """The nested search written plainly: first feasible grid volume, then ``rounds`` rounds of
    8 interior points in log volume, each keeping the first feasible point."""
    req = req.resolved()
    grid = sizing_mod._GRID
    out = np.empty(f.size)
    for i in range(f.size):
        ok = constraint_state(req, cfg, build_airframe(req, cfg, grid, f[i], dsf[i], pos[i]))
        ok = ok.feasible
        if not ok.any():
            out[i] = np.nan
            continue
        k = int(np.argmax(ok))
        if k == 0:
            out[i] = grid[0]
            continue
        lo, hi = grid[k - 1], grid[k]
        for _ in range(rounds):
            vs = np.exp(np.log(lo) + (np.log(hi) - np.log(lo)) * np.arange(1, 9) / 9.0)
            st = constraint_state(req, cfg, build_airframe(req, cfg, vs, f[i], dsf[i], pos[i]))
            feas = st.feasible
            if feas.any():
                j = int(np.argmax(feas))
                hi, lo = vs[j], (vs[j - 1] if j > 0 else lo)
            else:
                lo = vs[-1]
        out[i] = hi
    return out


CASES = {
    "practice": (Requirement(), practice_configuration()),
    "thesis": thesis_baseline(),
}


def _batch(shape: str, n: int, seed: int):
    rng = np.random.default_rng(seed)
    lo, hi = SHAPE_INFO[shape].fineness_range
    return rng.uniform(lo, hi, n), rng.uniform(-50, 100, n), rng.uniform(0.6, 0.75, n)


@pytest.mark.parametrize("rules", ["practice", "thesis"])
@pytest.mark.parametrize("shape", ["npl", "lotte"])
def test_search_finds_the_volume_of_the_nested_rounds(rules, shape):
    req, cfg = CASES[rules]
    cfg = replace(cfg, hull=HullSpec(shape=shape, volume=None))
    f, dsf, pos = _batch(shape, 12, 7)
    s = size_volume(req, cfg, f, dsf, pos)
    ref = _reference_volume(req, cfg, f, dsf, pos)
    ok = np.isfinite(ref)
    assert ok.sum() >= 6
    assert np.array_equal(np.asarray(s.feasible), ok)
    np.testing.assert_allclose(np.asarray(s.volume)[ok], ref[ok], rtol=1e-12)


@pytest.mark.parametrize("rules", ["practice", "thesis"])
def test_fallback_gives_the_same_volume_binding_and_state(rules, monkeypatch):
    req, cfg = CASES[rules]
    cfg = cfg.with_design_variables(volume=None)
    f, dsf, pos = _batch("npl", 10, 3)
    fast = size_volume(req, cfg, f, dsf, pos)
    one = size_volume(req, cfg)
    # a prediction at the bottom of every bracket: the batch around it never holds the crossing
    monkeypatch.setattr(sizing_mod, "_predicted_fraction", lambda st, lo_k, met: 0.0 * lo_k)
    slow = size_volume(req, cfg, f, dsf, pos)
    one_slow = size_volume(req, cfg)
    np.testing.assert_allclose(slow.volume, fast.volume, rtol=1e-12)
    assert list(slow.binding) == list(fast.binding)
    np.testing.assert_allclose(slow.state.g, fast.state.g, rtol=1e-9, atol=1e-9)
    assert float(one_slow.volume) == pytest.approx(float(one.volume), rel=1e-12)
    assert str(one_slow.binding) == str(one.binding)
    np.testing.assert_allclose(one_slow.state.g, one.state.g, rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("rules", ["practice", "thesis"])
def test_returned_state_is_the_table_at_the_returned_volume(rules):
    req, cfg = CASES[rules]
    req = req.resolved()
    cfg = cfg.with_design_variables(volume=None)
    f, dsf, pos = _batch("npl", 16, 11)
    s = size_volume(req, cfg, f, dsf, pos)
    fresh = constraint_state(req, cfg, build_airframe(req, cfg, s.volume, f, dsf, pos))
    assert s.state.g.shape == fresh.g.shape == (16, len(NAMES))
    np.testing.assert_allclose(s.state.g, fresh.g, rtol=1e-8, atol=1e-8)
    np.testing.assert_array_equal(s.state.evaluation.airframe.hull.volume, s.volume)
    np.testing.assert_allclose(s.state.evaluation.tether.blow_by, fresh.evaluation.tether.blow_by,
                               rtol=1e-9)
    # binding: met at the volume, broken just below it
    for i in range(16):
        b = str(s.binding[i])
        if s.feasible[i] and b != "none":
            below = constraint_state(req, cfg, build_airframe(
                req, cfg, s.volume[i] * (1 - 1e-4), f[i], dsf[i], pos[i]))
            assert not below.met[NAMES.index(b)]


@pytest.mark.parametrize("shape", list(SHAPE_INFO))
def test_design_reuses_the_search_and_matches_a_fresh_evaluation(shape):
    req = Requirement().resolved()
    cfg = replace(practice_configuration(), hull=HullSpec(shape=shape, volume=None))
    d = design(req, cfg)
    assert d.sized and d.constraints.evaluation.airframe is d.airframe
    af = build_airframe(req, cfg, d.volume)
    ev = evaluate(req, cfg, af, req.design_wind)
    assert d.design_point["blow_by_m"] == pytest.approx(float(ev.tether.blow_by), rel=1e-9)
    assert d.design_point["tension_top_N"] == pytest.approx(float(ev.tether.tension_top),
                                                            rel=1e-9)
    x, z = d.tether_profile(req.design_wind)
    np.testing.assert_allclose(x, ev.tether.x, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(z, ev.tether.z, rtol=1e-9, atol=1e-9)


def test_summary_and_report_are_typed_and_keep_the_keys():
    d = design()
    s = d.summary()
    assert list(s.to_dict()) == SUMMARY_KEYS
    assert list(s) == SUMMARY_KEYS and s["volume_m3"] == s.volume_m3 == d.volume
    assert isinstance(s.to_dict()["violations"], list)
    json.dumps(s.to_dict())  # plain JSON types
    given = design(Requirement(), practice_configuration().with_design_variables(volume=100.0))
    assert given.summary().binding_constraint == "given volume"
    rep = design_report(d)
    assert isinstance(rep, DesignReport)
    plain = rep.to_dict()
    assert plain["summary"] == s.to_dict() and isinstance(plain["summary"], dict)
    with pytest.warns(DeprecationWarning, match=r"\.summary"):  # key reads: one more release
        assert rep["summary"] == s
    with pytest.warns(DeprecationWarning):
        assert rep["violations"] == list(d.violations)
    assert set(plain) == set(rep) and len(rep) == len(plain)
