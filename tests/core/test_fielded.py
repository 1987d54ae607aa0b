"""Validation harness against fielded aerostats (thesis Table 2.3; issue 8 item 5)."""

from __future__ import annotations

import numpy as np
import pytest

from aerostat_core.model.design import design
from aerostat_core.model.inputs import Requirement
from aerostat_core.model.presets import PRACTICE_FABRIC_AREAL_DENSITY, PRACTICE_FINENESS_RATIO
from aerostat_core.studies.fielded import FIELDED, practice_configuration_for, validate_fielded


@pytest.fixture(scope="module")
def harness():
    return validate_fielded()


def test_every_fielded_system_sizes_feasibly_near_its_published_length(harness) -> None:
    assert len(harness.rows) == len(FIELDED) >= 7
    for r in harness.rows:
        assert r.feasible, r.system.name
        assert abs(r.length_error) < 0.25, (r.system.name, r.length_error)
    # targets: median |error| <= 10 %, none worse than 25 % (measured 9.3 % and 16 %: TIF-1600,
    # whose 16 kg at 610 m does not fit its published 45 m3 with a 15 % free-lift margin)
    assert harness.median_abs_length_error <= 0.10
    assert harness.max_abs_length_error <= 0.25


def test_held_out_systems_are_predictions(harness) -> None:
    held = harness.held_out()
    assert {r.system.name for r in held} == {"TCOM 12M", "TCOM 17M", "Sky Crow TA", "TCOM 22M"}
    assert np.median([abs(r.length_error) for r in held]) < 0.12
    for row in harness.table():
        assert row["role"] in ("fit", "held out (prediction)") and row["source"]


def test_practice_fineness_is_the_fit_set_mean() -> None:
    fit = [s.length / s.diameter for s in FIELDED if s.fit]
    assert PRACTICE_FINENESS_RATIO == pytest.approx(np.mean(fit), abs=1e-4)


def test_practice_fabric_is_the_least_squares_fit_on_the_fit_set() -> None:
    """Recompute the calibration: RMS log length error of the fit set over a scan."""

    def rms(gsm: float) -> float:
        cfg = practice_configuration_for(gsm)
        assert cfg.hull.fineness_ratio == PRACTICE_FINENESS_RATIO
        e = [np.log(design(Requirement(payload_mass=s.payload_mass, altitude=s.altitude),
                           cfg).summary().length_m / s.length) for s in FIELDED if s.fit]
        return float(np.sqrt(np.mean(np.square(e))))

    scan = np.arange(0.20, 0.2401, 0.005)
    best = scan[int(np.argmin([rms(g) for g in scan]))]
    assert best == pytest.approx(PRACTICE_FABRIC_AREAL_DENSITY, abs=0.0051)


def test_old_absolute_limit_would_oversize(harness) -> None:
    """The failure this harness guards against: an absolute 30 m blow-by limit at every
    altitude sizes TIF-1600 several times too long."""
    s = FIELDED[0]
    old = design(Requirement(payload_mass=s.payload_mass, altitude=s.altitude,
                             blow_by_limit=30.0, design_wind=15.0))
    assert old.summary().length_m > 1.8 * s.length
    assert abs(harness.rows[0].length_error) < 0.25
