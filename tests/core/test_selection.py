"""Materials chosen by the loads they carry (aerostat_core.model.selection; issue 23 items 2 and 8)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from aerostat_core.model.design import design
from aerostat_core.model.inputs import Requirement
from aerostat_core.model.mission import effective_tether
from aerostat_core.model.presets import practice_configuration
from aerostat_core.model.selection import (
    Needs,
    Shortfall,
    choose,
    envelope_stress,
    select_materials,
)
from aerostat_core.structures.materials import (
    BRAID_EFFICIENCY,
    FABRIC_SOURCES,
    SELECTABLE_FABRICS,
    SELECTABLE_TETHERS,
    TETHER_SOURCES,
    braid,
)


def test_catalogues_are_sorted_lightest_first_and_sourced() -> None:
    w = [f.areal_density for f in SELECTABLE_FABRICS]
    m = [t.linear_density for t in SELECTABLE_TETHERS]
    assert w == sorted(w) and m == sorted(m)
    for f in SELECTABLE_FABRICS:
        assert FABRIC_SOURCES[f.name]["tensile_strength"]
    for t in SELECTABLE_TETHERS:
        assert TETHER_SOURCES[t.name]
    kinds = " ".join(t.name for t in SELECTABLE_TETHERS)
    assert "HMPE" in kinds and "aramid" in kinds


def test_braid_reproduces_its_calibration_point() -> None:
    """Marlow D12 4 mm: 2050 kg; the 4 mm HMPE braid is KiteUtils' 9.1 g/m."""
    t = braid("hmpe", 4)
    assert t.breaking_strength == pytest.approx(2050 * 9.80665, rel=1e-9)
    assert t.linear_density == pytest.approx(724 * np.pi * 0.004**2 / 4, rel=1e-12)
    assert 0.5 < BRAID_EFFICIENCY < 0.8
    # strength per mass is a fibre property: independent of the diameter
    for d in (3, 10, 32):
        b = braid("hmpe", d)
        assert b.breaking_strength / b.linear_density == pytest.approx(
            t.breaking_strength / t.linear_density)
    # aramid is heavier than HMPE for the same strength
    a = braid("aramid", 10)
    assert a.breaking_strength / a.linear_density < t.breaking_strength / t.linear_density


def test_envelope_stress_is_the_hoop_load() -> None:
    # p = 1.2 x 100 + (1.2 - 0.2) x 10 x 4 = 160 Pa, r = 2 m
    assert float(envelope_stress(100.0, 1.2, 0.2, 10.0, 4.0, 1.2)) == pytest.approx(320.0)
    # doubles with the radius at a fixed pressure head-free case
    a = envelope_stress(100.0, 1.0, 1.0, 9.8, 2.0, 1.0)
    b = envelope_stress(100.0, 1.0, 1.0, 9.8, 4.0, 1.0)
    assert float(b) == pytest.approx(2 * float(a))


def test_choose_takes_the_lightest_item_that_carries_the_load() -> None:
    req = Requirement().resolved()
    cfg = practice_configuration()
    for need in (1e3, 9e4, 1.2e5, 3e5):
        (i_h, _, _), short = choose(req, cfg, Needs(need, 1.0, 1.0))
        ok = [f for f in SELECTABLE_FABRICS if f.tensile_strength >= need]
        assert SELECTABLE_FABRICS[i_h].areal_density == min(f.areal_density for f in ok)
        assert not short
    for need in (1e4, 1e5, 1e6):
        (_, _, i_t), short = choose(req, cfg, Needs(1.0, 1.0, need))
        ok = [t for t in SELECTABLE_TETHERS if t.breaking_strength >= need]
        assert SELECTABLE_TETHERS[i_t].linear_density == min(t.linear_density for t in ok)


def test_a_need_beyond_the_catalogue_names_the_item_and_the_shortfall() -> None:
    req = Requirement().resolved()
    best = max(f.tensile_strength for f in SELECTABLE_FABRICS)
    _, short = choose(req, practice_configuration(), Needs(2 * best, 1.0, 1e8))
    items = {s.item: s for s in short}
    assert set(items) == {"hull fabric", "tether"}
    assert items["hull fabric"].fraction == pytest.approx(0.5)
    msg = items["hull fabric"].message()
    assert "hull fabric" in msg and "50 % short" in msg
    assert "tether" in items["tether"].message()
    assert Shortfall("tether", 200.0, 150.0, "x", "N").fraction == pytest.approx(0.25)


def test_selected_items_carry_their_loads_and_no_lighter_one_does() -> None:
    for req in (Requirement(payload_mass=227, altitude=900),
                Requirement(payload_mass=1600, altitude=4600, survival_wind=36.0)):
        s = select_materials(req, practice_configuration())
        cfg = s.configuration
        assert cfg.hull_fabric.tensile_strength >= s.needs.hull_fabric
        assert cfg.fin_fabric.tensile_strength >= s.needs.fin_fabric
        assert cfg.tether.breaking_strength >= s.needs.tether
        assert s.sizing is not None and bool(s.sizing.feasible)
    # where the first sizing closed (no window bump), no lighter braid carries the load
    s = select_materials(Requirement(payload_mass=227, altitude=900), practice_configuration())
    lighter = [t for t in SELECTABLE_TETHERS
               if t.linear_density < s.configuration.tether.linear_density]
    assert all(t.breaking_strength < s.needs.tether for t in lighter)
    # a strategic hull needs a stronger tether than a tactical one
    small = select_materials(Requirement(), practice_configuration())
    big = select_materials(Requirement(payload_mass=1600, altitude=4600, survival_wind=36.0),
                           practice_configuration())
    assert small.needs.tether < big.needs.tether
    assert small.configuration.tether.linear_density < big.configuration.tether.linear_density


def test_power_through_the_tether_is_carried_by_the_flown_bundle() -> None:
    req = Requirement(payload_mass=200, altitude=900, payload_power=3000,
                      power_via="tether").resolved()
    s = select_materials(req, practice_configuration())
    flown = effective_tether(req, s.configuration)
    assert flown.linear_density > s.configuration.tether.linear_density  # conductors added


def test_design_reports_a_catalogue_shortfall_as_a_violation() -> None:
    # an envelope safety factor of 20 at a 60 m/s survival wind: no laminate of the catalogue
    from aerostat_core.model.mission import MissionSpec

    cfg = replace(practice_configuration(), mission=MissionSpec(envelope_safety_factor=20.0))
    d = design(Requirement(payload_mass=3000, altitude=3000, survival_wind=60.0), cfg)
    assert not d.feasible
    assert any("no catalogue hull fabric" in v and "% short" in v for v in d.violations)


def test_given_materials_are_left_alone() -> None:
    cfg = replace(practice_configuration(), materials="given")
    d = design(Requirement(), cfg)
    assert d.configuration.tether == cfg.tether
    assert d.configuration.hull_fabric == cfg.hull_fabric
