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

Design margins and operating limits are two things (docs/methods.md §1.16):

* the **design margins** (free lift 15 % of gross lift, tether safety factor 3, envelope safety
  factor 4, weathervane margin...) are what sizing applies, at the end of a top-up interval
  (``top_up_interval_days``): the margins cover what the model does not know;
* the **operating limits** (:class:`OperatingLimits`) are what physics needs in flight: free
  lift enough to keep the tether taut through a night's gas cooling, a tether and a fabric that
  do not break, an aerodynamically stable hull. The Monte Carlo reports the probability of
  meeting each set (:func:`aerostat_core.studies.uncertainty.limit_probabilities`), and the design's
  verdict asks that probability of the operating limits to reach ``required_probability``.
"""

from __future__ import annotations

from dataclasses import dataclass

from aerostat_core.base.validation import InputError, shown_value


@dataclass(frozen=True)
class OperatingLimits:
    """What must hold in flight (not a margin): each value with its source.

    Parameters
    ----------
    free_lift_fraction : float
        Least free lift / gross lift in flight [-], after permeation over the top-up interval.
    tether_safety_factor : float
        Least breaking load / tension at the design and survival winds [-] (1: the tether holds).
    envelope_safety_factor : float
        Least fabric strength / membrane load [-] (1: the fabric holds).
    weathervane_margin : float
        C_m_alpha about the centre of volume at most minus this [1/rad] (0: stable).
    required_probability : float
        Probability of meeting every operating limit, under the Monte Carlo spreads
        (:mod:`aerostat_core.studies.uncertainty`), that a "meets" verdict asks for [-].
    sources : dict
        Field -> where the value comes from.
    """

    free_lift_fraction: float
    tether_safety_factor: float
    envelope_safety_factor: float
    weathervane_margin: float
    required_probability: float
    sources: dict


#: Operating limits of the practice rule set.
PRACTICE_OPERATING = OperatingLimits(
    free_lift_fraction=0.05,
    tether_safety_factor=1.0,
    envelope_safety_factor=1.0,
    weathervane_margin=0.0,
    required_probability=0.9,
    sources={
        "free_lift_fraction": "engineering estimate: the lifting gas can cool up to ~15 K below "
        "the air at night (supercooling; Khoury 2012, Airships and Aerostats ch. 4), which "
        "takes dT/T = 15/288 = 5 % of gross lift; the tether stays taut only if the free lift "
        "covers it. No published standard found.",
        "tether_safety_factor": "definition: the tether breaks at a safety factor of 1",
        "envelope_safety_factor": "definition: the fabric tears at a safety factor of 1",
        "weathervane_margin": "definition: aerodynamically stable hull, C_m_alpha < 0",
        "required_probability": "engineering choice: a design that flies in 9 of 10 draws of "
        "the model's uncertain inputs; none of the peer tools states one",
    },
)


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
    top_up_interval_days : float
        Days between helium top-ups [day]: the free-lift margin must still hold at the end of
        one (0: checked at the fill).
    operating : OperatingLimits or None
        What must hold in flight; ``None``: the design margins themselves (no separate rows).
    check_wrinkling : bool
        Check the envelope wrinkling row (the hull as a pressurised beam); off in the thesis
        preset, whose method has no envelope structure.
    check_lateral_stability : bool
        Check the row "laterally stable up to the survival wind" (every lateral-directional
        mode of the 6-DOF model linearised at each wind speed decays; docs/dynamics.md §7.5);
        off in the thesis preset, which has no survival wind and no lateral model.
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
    top_up_interval_days: float = 0.0
    operating: OperatingLimits | None = None
    check_wrinkling: bool = True
    check_lateral_stability: bool = True


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
#:   (engineering choice);
#: * top-up interval 7 days: the free-lift margin must hold a week after the fill - tactical
#:   aerostats stay up 5-7 days between helium top-ups (thesis §2.3, citing TCOM and ILC
#:   Dover), and a weekly top-up is the common field practice;
#: * laterally stable up to the survival wind: small tethered aerostats are lost to kiting
#:   (Skydoc and Helikite aerostats went unstable at 40-50 km/h in towed tests, issue 25); the
#:   6-DOF linearisation checks it (docs/dynamics.md §7.5);
#: * operating limits: :data:`PRACTICE_OPERATING` (each with its source).
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
    top_up_interval_days=7.0,
    operating=PRACTICE_OPERATING,
)

#: Thesis blow-by limit as a fraction of the 300 m tether: 53.4 m / 300 m. CALIBRATED (not in the
#: thesis, docs/methods.md G5): the value at which the optimiser finds the thesis' 120 m3 optimum.
THESIS_BLOW_BY_FRACTION = 53.4 / 300.0

#: "thesis": the calibrated preset that reproduces the thesis' 170 -> 120 m3 (docs/validation.md);
#: no top-up interval and no separate operating limits (the thesis states neither).
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
    check_wrinkling=False,
    check_lateral_stability=False,
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
        reason = f"is not a rule set; valid: {', '.join(RULE_NAMES)}"
        raise InputError(
            f"rules = {shown_value(name)} {reason}", owner="Requirement", field="rules",
            value=name, reason=reason,
        ) from None
