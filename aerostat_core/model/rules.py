"""Rule sets: the requirement limits a design must meet when the user leaves them open.

A :class:`Requirement` field left as ``None`` takes its value from the requirement's rule set
(``Requirement.rules``). Two rule sets exist:

``"practice"`` (the default, for real missions)
    Limits scaled to the mission, from published practice where a source exists and stated as
    engineering choices where none does (each field below says which). The matching design
    configuration (fineness ratio, fabric) is :func:`aerostat_core.model.presets.practice_configuration`,
    whose fabric areal density is CALIBRATED against fielded aerostats
    (:mod:`aerostat_core.studies.fielded`, docs/validation.md).

``"thesis"``
    The calibrated preset of the thesis (Mahmood 2020): positive free lift, a 3.0 tether safety
    factor and the blow-by limit that makes the optimiser find the thesis' 120 m3 optimum
    (53.4 m at 300 m, expressed here as a fraction of the tether length, 0.178), at the 15 m/s
    design wind. Limits the thesis does not state are off; "positive free lift" is read as at least
    1 % of gross lift, so that a calm design wind cannot size a weightless hull.

Every limit is a fraction of the tether length (= the operating altitude), never one absolute
length for every altitude.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class RuleSet:
    """Default limits of a requirement.

    Parameters
    ----------
    name : str
        Key in :data:`RULE_SETS`.
    title : str
        One-line description shown in the app and the CLI.
    design_wind : float
        Operational (design) wind at the aerostat [m/s] at which the blow-by, altitude-loss,
        tether-angle, stall and stability limits apply.
    survival_wind : float or None
        Wind the moored-aloft aerostat must survive [m/s]; ``None`` turns the survival check off.
    blow_by_fraction : float
        Blow-by limit / tether length [-].
    altitude_loss_fraction : float or None
        Permissible altitude loss (thesis Table 2.4) / tether length [-]; ``None`` turns it off.
    free_lift_fraction : float
        Required free lift / gross lift at rest [-] (0 means "positive free lift").
    min_tether_safety_factor : float
        Breaking strength / largest tether tension at the design wind [-].
    survival_safety_factor : float
        Breaking strength / largest tether tension at the survival wind [-].
    max_tether_angle_deg : float
        Largest tether angle from the vertical at the design wind [deg].
    weathervane_margin : float
        Required margin of aerodynamic (weathervane) stability: C_m_alpha about the centre of
        volume must be at most ``-weathervane_margin`` [1/rad].
    """

    name: str
    title: str
    design_wind: float
    survival_wind: float | None
    blow_by_fraction: float
    altitude_loss_fraction: float | None
    free_lift_fraction: float
    min_tether_safety_factor: float
    survival_safety_factor: float
    max_tether_angle_deg: float
    weathervane_margin: float


#: "practice": limits for real missions.
#:
#: * free lift 15 % of gross lift: the IIT Bombay / ADRDE design practice (Raina, Gawale & Pant
#:   2008, PADS; summarised in docs/methods.md S8);
#: * survival wind 20 m/s: tactical-class aerostats "operate and survive up to 20 m/s" (thesis
#:   §2.3.1, citing TCOM 2018); survival safety factor 1.5 (the tether must not break in the
#:   survival gust; engineering choice, no published standard found);
#: * design wind 10 m/s (about 20 kn): engineering choice for the wind the payload must still work
#:   in; the user sets the vendor's operational rating where one exists;
#: * blow-by 0.5 and permissible altitude loss 0.15 of the tether length, tether at most 60 deg
#:   from the vertical at the winch: engineering choices (no published standard found), set so
#:   that the payload keeps at least 85 % of its height and the winch sees a pull it can level-wind;
#: * tether safety factor 3 at the design wind (the thesis' value, docs/methods.md G10);
#: * weathervane margin 0.02 /rad: about 10 % of the C_m_alpha of a statistical fin set, so the
#:   hull stays aerodynamically stable within the uncertainty of the Munk-moment estimate
#:   (engineering choice).
PRACTICE = RuleSet(
    name="practice",
    title="Practice: free lift 15 % of gross lift, limits scaled to the tether length",
    design_wind=10.0,
    survival_wind=20.0,
    blow_by_fraction=0.5,
    altitude_loss_fraction=0.15,
    free_lift_fraction=0.15,
    min_tether_safety_factor=3.0,
    survival_safety_factor=1.5,
    max_tether_angle_deg=60.0,
    weathervane_margin=0.02,
)

#: Thesis blow-by limit as a fraction of the 300 m tether: 53.4 m / 300 m. CALIBRATED (not in the
#: thesis, docs/methods.md G5): the value at which the optimiser finds the thesis' 120 m3 optimum.
THESIS_BLOW_BY_FRACTION = 53.4 / 300.0

#: "thesis": the calibrated preset that reproduces the thesis' 170 -> 120 m3 (docs/validation.md).
THESIS = RuleSet(
    name="thesis",
    title="Thesis preset (Mahmood 2020): positive free lift, calibrated blow-by limit 0.178 h",
    design_wind=15.0,
    survival_wind=None,
    blow_by_fraction=THESIS_BLOW_BY_FRACTION,
    altitude_loss_fraction=None,
    free_lift_fraction=0.01,
    min_tether_safety_factor=3.0,
    survival_safety_factor=1.0,
    max_tether_angle_deg=45.0,
    weathervane_margin=0.0,
)

#: The rule sets by name; the first is the default.
RULE_SETS: dict[str, RuleSet] = {r.name: r for r in (PRACTICE, THESIS)}
#: Valid rule-set names.
RULE_NAMES = tuple(RULE_SETS)
#: Default rule set.
DEFAULT_RULES = "practice"


def get_rules(name: str) -> RuleSet:
    """The rule set called ``name``; ``ValueError`` listing the valid names otherwise."""
    try:
        return RULE_SETS[name]
    except (KeyError, TypeError):
        raise ValueError(
            f"rules = {name!r} is not a rule set; valid: {', '.join(RULE_NAMES)}"
        ) from None
