"""Fielded aerostats and the validation harness that sizes them (docs/validation.md).

Each :class:`FieldedSystem` holds a system's published figures and their source. The harness
(:func:`validate_fielded`) sizes every system from its payload and altitude alone (and its
published wind rating where one exists) with the default "practice" rule set and configuration,
and reports the predicted against the published hull length (and diameter or volume where
published).

Which numbers are fitted and which are predicted: the practice fineness ratio
(presets.PRACTICE_FINENESS_RATIO, their mean l/d) and fabric areal density
(presets.PRACTICE_FABRIC_AREAL_DENSITY, least squares) were chosen on the FIT set, the three
systems that publish both length and diameter; every other system is a prediction (HELD OUT).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from aerostat_core.model.design import design
from aerostat_core.model.inputs import Requirement
from aerostat_core.model.mission import MissionSpec
from aerostat_core.model.presets import practice_configuration, rules_configuration

#: Thesis Table 2.3 (Mahmood 2020, citing SAVER 2013 "Tethered aerostat systems" market survey).
TABLE_2_3 = "thesis Table 2.3 (SAVER 2013)"


@dataclass(frozen=True)
class FieldedSystem:
    """Published figures of a fielded aerostat.

    Parameters
    ----------
    name : str
    payload_mass : float
        Maximum payload [kg].
    altitude : float
        Maximum operating altitude above the site [m].
    length : float
        Hull length [m].
    diameter : float or None
        Hull diameter [m] where published.
    volume : float or None
        Hull volume [m3] where published (the "1600" and "25K" of Raven's model names are the
        volume in cubic feet).
    design_wind : float or None
        Published operational wind rating [m/s]; ``None`` takes the rule set's.
    source : str
    fit : bool
        True for the systems the practice calibration was chosen on.
    endurance_days : float or None
        Days aloft without helium addition published for the system's class (issue 13 item 9):
        thesis §2.3, tactical (payload <= 30 kg) "flight endurance 5 to 7 days" (TCOM 2018),
        operational "from 7 days to 4 weeks on helium gas addition" (Krausman & Petersen 2013);
        the lower ends, 5 and 7 days, are used. No system of the table publishes its payload
        power, so power is not used.
    """

    name: str
    payload_mass: float
    altitude: float
    length: float
    diameter: float | None = None
    volume: float | None = None
    design_wind: float | None = None
    source: str = TABLE_2_3
    fit: bool = False
    endurance_days: float | None = None

    @property
    def class_endurance_days(self) -> float:
        """The published class endurance (see ``endurance_days``) [day]."""
        if self.endurance_days is not None:
            return float(self.endurance_days)
        return TACTICAL_ENDURANCE_DAYS if self.payload_mass <= 30.0 else OPERATIONAL_ENDURANCE_DAYS


#: Class endurance without helium addition [day] (thesis §2.3; lower ends of 5-7 days and of
#: "7 days to 4 weeks on helium gas addition").
TACTICAL_ENDURANCE_DAYS = 5.0
OPERATIONAL_ENDURANCE_DAYS = 7.0

_FT3 = 0.3048**3

#: The tactical and operational streamlined systems of thesis Table 2.3 that publish a length.
#: Left out: White Hawk (4.4 x 3.4 m, l/d 1.3, not a streamlined hull of the NPL family), Sky
#: Sentry HEA-150 and HEA-3000 (no size published), and the systems whose payload exceeds the
#: engine's 500 kg range (TCOM 28M, 71M, 74M).
FIELDED: tuple[FieldedSystem, ...] = (
    FieldedSystem("Raven TIF-1600", 16.0, 610.0, 9.6, 3.3, 1600 * _FT3,
                  source=TABLE_2_3 + "; volume from the model name (1600 ft3)", fit=True),
    FieldedSystem("TCOM 12M", 27.0, 300.0, 12.0),
    FieldedSystem("TCOM 17M", 90.0, 300.0, 17.0),
    FieldedSystem("Sky Crow TA", 9.0, 305.0, 10.3),
    FieldedSystem("Top Vision T.A.S", 4.0, 150.0, 9.1, 2.9, fit=True),
    FieldedSystem("Raven TIF-25K", 227.0, 900.0, 23.2, 7.6, 25000 * _FT3,
                  source=TABLE_2_3 + "; volume from the model name (25,000 ft3)", fit=True),
    FieldedSystem("TCOM 22M", 190.0, 900.0, 22.0),
)


@dataclass(frozen=True)
class FieldedRow:
    """One system sized by the harness (lengths [m], volume [m3], errors relative [-])."""

    system: FieldedSystem
    length: float
    diameter: float
    volume: float
    feasible: bool
    binding: str
    length_error: float
    diameter_error: float | None
    volume_error: float | None

    def as_dict(self) -> dict:
        """Flat dict for tables and CSV (errors in %)."""
        s = self.system
        return {
            "system": s.name, "role": "fit" if s.fit else "held out (prediction)",
            "payload_kg": s.payload_mass, "altitude_m": s.altitude,
            "published_length_m": s.length, "predicted_length_m": self.length,
            "length_error_pct": 100 * self.length_error,
            "published_diameter_m": s.diameter, "predicted_diameter_m": self.diameter,
            "diameter_error_pct": None if self.diameter_error is None else 100 * self.diameter_error,
            "published_volume_m3": s.volume, "predicted_volume_m3": self.volume,
            "volume_error_pct": None if self.volume_error is None else 100 * self.volume_error,
            "feasible": self.feasible, "sized_by": self.binding, "source": s.source,
        }


def size_fielded(system: FieldedSystem, rules: str = "practice",
                 mission: bool = False) -> FieldedRow:
    """Size one fielded system from its payload and altitude (and wind rating if published).

    ``mission=True`` also asks for its class endurance (``class_endurance_days``) and builds a
    ballonet where the thesis' 500 m rule calls for one (MissionSpec ballonet "auto"), with the
    practice configuration otherwise unchanged (issue 13 item 9)."""
    req = Requirement(payload_mass=system.payload_mass, altitude=system.altitude,
                      design_wind=system.design_wind, rules=rules,
                      endurance_days=system.class_endurance_days if mission else 0.0)
    cfg = None
    if mission:
        cfg = replace(rules_configuration(rules), mission=MissionSpec(ballonet="auto"))
    d = design(req, cfg)
    s = d.summary()
    rel = lambda p, q: None if q is None else p / q - 1.0  # noqa: E731
    return FieldedRow(
        system=system, length=s.length_m, diameter=s.diameter_m, volume=s.volume_m3,
        feasible=d.feasible, binding=s.binding_constraint,
        length_error=s.length_m / system.length - 1.0,
        diameter_error=rel(s.diameter_m, system.diameter),
        volume_error=rel(s.volume_m3, system.volume),
    )


@dataclass(frozen=True)
class FieldedValidation:
    """The harness result: rows and the summary statistics of the hull-length error."""

    rows: tuple[FieldedRow, ...]

    @property
    def length_errors(self) -> np.ndarray:
        """Relative hull-length errors [-], in the order of ``rows``."""
        return np.array([r.length_error for r in self.rows])

    @property
    def median_abs_length_error(self) -> float:
        """Median of |length error| [-] (target <= 0.10)."""
        return float(np.median(np.abs(self.length_errors)))

    @property
    def max_abs_length_error(self) -> float:
        """Largest |length error| [-] (target <= 0.25)."""
        return float(np.max(np.abs(self.length_errors)))

    def held_out(self) -> tuple[FieldedRow, ...]:
        """Rows of the systems the calibration was not chosen on."""
        return tuple(r for r in self.rows if not r.system.fit)

    def table(self) -> list[dict]:
        """Rows as flat dicts."""
        return [r.as_dict() for r in self.rows]


def validate_fielded(systems=FIELDED, rules: str = "practice",
                     mission: bool = False) -> FieldedValidation:
    """Size every fielded system with the default rule set and compare with the published size
    (``mission=True``: with the class endurance and the 500 m ballonet rule, see
    :func:`size_fielded`).

    Examples
    --------
    >>> v = validate_fielded()
    >>> round(100 * v.median_abs_length_error), round(100 * v.max_abs_length_error)
    (9, 16)
    """
    return FieldedValidation(tuple(size_fielded(s, rules, mission) for s in systems))


def practice_configuration_for(areal_density: float):
    """Practice configuration with another fabric areal density [kg/m2] (for the calibration
    scan in benchmarks and tests)."""
    from dataclasses import replace

    cfg = practice_configuration()
    fab = replace(cfg.hull_fabric, areal_density=areal_density)
    return replace(cfg, hull_fabric=fab, fin_fabric=fab)
