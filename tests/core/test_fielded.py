"""Validation harness against fielded aerostats of all three classes (thesis Table 2.3;
issue 8 item 5, issue 23 items 3-4)."""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest

from aerostat_core.model.presets import (
    PRACTICE_FINENESS_RATIO,
    PRACTICE_SYSTEMS_MASS_EXPONENT,
    PRACTICE_SYSTEMS_MASS_PER_VOLUME,
    practice_configuration,
)
from aerostat_core.studies.fielded import (
    CLASSES,
    FIELDED,
    INCONSISTENCY_FACTOR,
    FieldedSystem,
    aerostat_class,
    class_figures,
    dominance_pairs,
    fielded_case,
    fit_rms,
    size_fielded,
    validate_fielded,
)


@pytest.fixture(scope="module")
def harness():
    return validate_fielded()


def test_the_harness_spans_every_class_with_a_declared_third_fitted() -> None:
    classes = {s.aerostat_class for s in FIELDED}
    assert classes == set(CLASSES)
    fit = [s for s in FIELDED if s.fit]
    # the fit set: a third of the systems, each class represented
    assert abs(len(fit) - len(FIELDED) / 3) <= 1
    assert {s.aerostat_class for s in fit} == set(CLASSES)
    for s in FIELDED:
        assert s.source and s.payload_mass > 0 and s.altitude > 0
        assert (s.length or 0) > 0 or (s.volume or 0) > 0


#: Systems whose published figures could not be reconciled with their class (docs/validation.md
#: §7, FieldedSystem.readings and .inconsistency): the issue's 15 % bound is not met on them, and
#: the test says so.
OUTLIERS = {"Aeroscraft AEROS 3200", "Raven TIF-1600", "SkySentry HALE testbed"}
#: Of those, the two whose published figures fail the model-free check (dominance_pairs).
FLAGGED = {"Aeroscraft AEROS 3200", "Raven TIF-1600"}


def test_every_fielded_system_sizes_near_its_published_length(harness) -> None:
    assert len(harness.rows) == len(FIELDED) >= 13
    st = harness.statistics()
    # measured on this branch: length median 2.6 % over 13 (fit 2.45 %, held out 2.6 %; 9.0 %
    # before the 74K and 74M flew the shape their length and volume fix), worst 32.4 % (AEROS
    # 3200); volume median 9.7 % (5 published). Issue 23 item 3: median <= 6 % (met), volume
    # median <= 12 % (met), none worse than 15 % (NOT met: AEROS 3200, TIF-1600, SkySentry,
    # see test_no_system_is_worse_than_15_percent).
    assert st["all_median"] <= 0.06
    assert st["fit_median"] <= 0.06 and st["held_out_median"] <= 0.06
    assert st["volume_median"] <= 0.12
    assert st["all_worst"] <= 0.33
    assert all(r.feasible for r in harness.rows)
    for cls in CLASSES:  # every class is sized within 10 % in the median
        e = [abs(r.length_error) for r in harness.rows
             if r.system.aerostat_class == cls and r.length_error is not None]
        assert np.median(e) <= 0.10, cls
    for r in harness.rows:  # every other system within the 15 %
        if r.system.name not in OUTLIERS and r.length_error is not None:
            assert abs(r.length_error) <= 0.15, r.system.name
    for name in OUTLIERS:  # each outlier carries its readings and why it is off
        assert next(s for s in FIELDED if s.name == name).readings


@pytest.mark.xfail(strict=True, reason="issue 23 item 3 worst case not met: AEROS 3200 (-32 %), "
                   "TIF-1600 (+29 %), SkySentry HALE testbed (-20 %), docs/validation.md §7")
def test_no_system_is_worse_than_15_percent(harness) -> None:
    assert harness.statistics()["all_worst"] <= 0.15


def test_the_consistent_statistics_are_reported_beside_the_headline(harness) -> None:
    """Beside (not instead of) the target: without the two systems whose published figures fail
    the model-free check, the worst is the SkySentry testbed (-19.8 %, not flagged: see
    docs/validation.md §7), every other within 9.0 %; the headline statistics count all."""
    st = harness.statistics()
    assert st["consistent_worst"] < st["all_worst"]
    assert st["consistent_worst"] == pytest.approx(0.198, abs=0.005)
    assert st["consistent_median"] <= 0.06 and st["volume_consistent_median"] <= 0.12
    assert {s.name for s in FIELDED if not s.consistent} == FLAGGED
    assert len(harness.consistent()) == len(FIELDED) - len(FLAGGED)
    for row in harness.table():
        assert row["consistent"] == (row["system"] not in FLAGGED)
        assert 0.0 < row["payload_fraction"] < 0.86  # below the helium-air density margin


def test_an_inconsistency_is_the_model_free_check_and_only_it() -> None:
    """A system is flagged exactly when a same-class hull at least as large, flying no higher,
    publishes a payload fraction lower by more than the factor 2 (square-cube and thinner air
    say it should be higher): no sizing model enters. Every inversion above the factor involves
    a flagged system, every flagged system is in one, and the others' inversions stay small."""
    pairs = dominance_pairs()
    big = [(a, b) for a, b, f in pairs if f > INCONSISTENCY_FACTOR]
    flagged = {s.name for s in FIELDED if not s.consistent}
    assert all({a, b} & flagged for a, b in big)
    assert flagged <= {n for pair in big for n in pair}
    clean = [f for a, b, f in pairs if a not in flagged and b not in flagged]
    assert max(clean) < 1.5  # measured 1.07 (420K against the larger TCOM 71M at 4,600 m)
    for s in FIELDED:
        assert bool(s.inconsistency) != s.consistent
        assert (s.name in flagged) == ("payload fraction" in s.inconsistency)


def test_the_payload_fraction_follows_square_cube_and_altitude() -> None:
    """phi = m_payload / (rho_ISA(h) V): a pure function of the published figures."""
    a = FieldedSystem("a", 100.0, 0.0, None, volume=100.0)
    assert a.payload_fraction == pytest.approx(100.0 / (1.225 * 100.0), rel=1e-3)
    assert replace(a, altitude=3000.0).payload_fraction > a.payload_fraction
    # a published length at the published l/d: V = pi/6 d^2 l
    b = FieldedSystem("b", 10.0, 300.0, 12.0, 4.0)
    assert b.hull_volume == pytest.approx(np.pi / 6 * 16 * 12, rel=1e-9)
    # a hull twice the volume, same payload fraction claim, is not an inversion; half the
    # fraction on the larger hull is
    big = replace(b, name="c", length=12.0 * 2 ** (1 / 3), diameter=4.0 * 2 ** (1 / 3),
                  payload_mass=20.0)
    assert dominance_pairs([b, big]) == []
    pairs = dominance_pairs([b, replace(big, payload_mass=5.0)])
    assert pairs == [("b", "c", pytest.approx(4.0))]
    # a system that publishes no size has no fraction and takes part in no pair
    bare = FieldedSystem("d", 10.0, 300.0, None)
    assert np.isnan(bare.payload_fraction) and dominance_pairs([b, bare]) == []
    assert np.isnan(size_fielded(bare).as_dict()["payload_fraction"])


def test_no_wind_reading_brings_the_tif_1600_within_15_percent() -> None:
    """Its lift budget alone (1 m/s: no blow-by) sizes it +16.5 % (docs/validation.md §7), and
    Raven's line-wide 50 kn moves it further off (+38 %): the wind is not the lever."""
    tif = next(s for s in FIELDED if s.name == "Raven TIF-1600")
    calm = size_fielded(replace(tif, design_wind=1.0))
    assert calm.binding != "blow_by" and calm.length_error > 0.15
    raven = size_fielded(replace(tif, design_wind=50 * 0.514444))
    assert raven.length_error > size_fielded(tif).length_error > calm.length_error


def test_a_published_shape_is_flown(harness) -> None:
    """Where the vendor's figures fix the hull shape (length and diameter, else length and
    volume), the hull is sized at that l/d, so the length error is the volume error seen
    through the published shape: with the diameter it equals the diameter error, with the
    volume (1 + e_l)^3 = 1 + e_V."""
    shaped = [r for r in harness.rows if r.system.published_fineness_ratio is not None]
    assert {r.system.name for r in shaped} == {
        "Raven TIF-1600", "Top Vision T.A.S", "Raven TIF-25K", "SkySentry HALE testbed",
        "Lockheed Martin 74K (PTDS)", "TCOM 74M"}
    for r in shaped:
        assert r.length / r.diameter == pytest.approx(r.system.published_fineness_ratio,
                                                      rel=1e-6)
        if r.system.diameter:
            assert r.length_error == pytest.approx(r.diameter_error, abs=1e-9)
        else:
            assert (1 + r.length_error) ** 3 == pytest.approx(1 + r.volume_error, rel=1e-9)
    # the diameter wins where all three are published (TIF-1600's disagree by 21 % in volume)
    tif = next(s for s in FIELDED if s.name == "Raven TIF-1600")
    assert tif.published_fineness_ratio == pytest.approx(9.6 / 3.3)
    # the length-and-volume reading inverts the NPL volume V = pi/6 d^2 l exactly
    k74 = next(s for s in FIELDED if s.name.startswith("Lockheed Martin 74K"))
    assert fielded_case(k74)[1].hull.shape == "npl"  # the hull whose volume it inverts
    d = k74.length / k74.published_fineness_ratio
    assert np.pi / 6 * d**2 * k74.length == pytest.approx(k74.volume, rel=1e-12)
    assert replace(k74, volume=None).published_fineness_ratio is None


def test_each_system_flies_its_published_or_class_wind_and_endurance() -> None:
    """Thesis §2.3: tactical 20 m/s and 5 days, operational 26 m/s and 7 days, strategic the
    rule set's operating wind, 36 m/s survival and 30 days; a published figure overrides."""
    for s in FIELDED:
        req, _ = fielded_case(s)
        cls = s.aerostat_class
        assert req.design_wind == {"tactical": 20.0, "operational": 26.0}.get(cls)
        days = s.endurance_days if s.endurance_days is not None else \
            CLASSES[cls]["endurance_days"][0]
        assert req.endurance_days == days
        if s.endurance_days is not None:  # a published endurance names its source
            assert "aloft" in s.source or "operational for" in s.source, s.name
    s = replace(FIELDED[0], design_wind=12.0)
    assert fielded_case(s)[0].design_wind == 12.0


def test_the_systems_law_is_the_grid_minimum_of_the_declared_fit() -> None:
    """Recompute the fit around the chosen point: its four grid neighbours fit worse."""
    k, c = PRACTICE_SYSTEMS_MASS_PER_VOLUME, PRACTICE_SYSTEMS_MASS_EXPONENT
    best = fit_rms(k, c)
    for dk, dc in ((0.03, 0), (-0.03, 0), (0, 0.04), (0, -0.04)):
        assert fit_rms(k + dk, c + dc) > best


def test_fit_and_held_out_are_reported_apart(harness) -> None:
    st = harness.statistics()
    assert st["fit_median"] is not None and st["held_out_median"] is not None
    # volume apart too: the held-out volumes (74K, 420K, 74M) are predictions within 12 % in
    # the median; the fit set's two (TIF-1600 +158 %, TIF-25K -2 %) are reported, not hidden
    assert st["volume_held_out_median"] <= 0.12
    assert st["volume_fit_median"] == pytest.approx(
        np.median([abs(r.volume_error) for r in harness.fitted() if r.volume_error is not None]))
    assert {r.system.name for r in harness.held_out()} == {
        s.name for s in FIELDED if not s.fit}
    for row in harness.table():
        assert row["role"] in ("fit", "held out (prediction)") and row["source"]
        assert row["class"] in CLASSES


def test_practice_fineness_is_the_fit_set_mean() -> None:
    fit = [s.length / s.diameter for s in FIELDED if s.fit and s.diameter]
    assert PRACTICE_FINENESS_RATIO == pytest.approx(np.mean(fit), abs=1e-4)


def test_practice_configuration_carries_the_fitted_systems_law() -> None:
    cfg = practice_configuration()
    assert cfg.materials == "catalogue"
    assert cfg.systems_mass_per_volume == PRACTICE_SYSTEMS_MASS_PER_VOLUME
    assert cfg.systems_mass_exponent == PRACTICE_SYSTEMS_MASS_EXPONENT


@pytest.mark.parametrize(("payload", "altitude", "name"), [
    (4, 150, "tactical"), (90, 300, "tactical"), (16, 610, "tactical"),
    (190, 900, "operational"), (10, 900, "operational"), (570, 900, "operational"),
    (1499, 2999, "operational"), (1500, 300, "strategic"), (10, 3000, "strategic"),
    (3200, 3000, "strategic"),
])
def test_class_boundaries_follow_the_thesis(payload, altitude, name) -> None:
    assert aerostat_class(payload, altitude) == name


def test_table_2_3_systems_fall_in_their_table_class() -> None:
    table = {"Raven TIF-1600": "tactical", "TCOM 12M": "tactical", "TCOM 17M": "tactical",
             "Sky Crow TA": "tactical", "Top Vision T.A.S": "tactical",
             "Raven TIF-25K": "operational", "TCOM 22M": "operational",
             "TCOM 28M": "operational", "Aeroscraft AEROS 3200": "operational",
             "TCOM 71M": "strategic", "TCOM 74M": "strategic"}
    assert {s.name: s.aerostat_class for s in FIELDED if s.name in table} == table
    assert {s.aerostat_class for s in FIELDED if s.name.startswith("Lockheed")} == {
        "operational", "strategic"}  # 74K (500 kg, 1,500 m) and 420K (1,000 kg, 4,600 m)


def test_design_json_has_the_class_and_its_typical_figures(capsys) -> None:
    from aerostat_core.cli.entry import main

    main(["design", "--json", "--payload", "1600", "--altitude", "4600"])
    out = json.loads(capsys.readouterr().out)
    assert out["class"] == "strategic"
    assert out["class_typical"]["payload_kg"] == [1500.0, 3200.0]
    assert "TCOM 71M" in out["class_typical"]["systems"]
    assert out["tether"] and out["hull_fabric"]
    f = class_figures(10, 300)
    assert f["class"] == "tactical" and "Raven TIF-1600" in f["systems"]
