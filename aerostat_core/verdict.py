"""The verdict an engineer can sign: design margins, operating limits and the probability of
meeting them (issue 22 items 2-4; docs/methods.md §1.16).

* :func:`operating_requirement`: the requirement and configuration whose limits are the rule
  set's operating limits (:class:`aerostat_core.rules.OperatingLimits`) instead of its design
  margins; the constraint table evaluated with them says whether the design flies.
* :func:`assess`: one verdict for a design: ``"meets"`` (the design margins hold and, when a
  seeded sample is asked for, the probability of meeting the operating limits reaches the rule
  set's ``required_probability``), ``"meets_nominal_only"`` (the margins hold nominally but that
  probability falls short) or ``"fails"`` (a design margin is broken); with what binds and what
  to change.
* :func:`robust_size`: the smallest hull whose probability of meeting the operating limits is at
  least ``confidence`` under the Monte Carlo spreads.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from types import SimpleNamespace

import numpy as np

from aerostat_core.airframe import build_airframe
from aerostat_core.constraints import BY_NAME, CONSTRAINTS, NAMES, constraint_state
from aerostat_core.inputs import Configuration, Requirement
from aerostat_core.validation import check_int, check_number

#: The verdicts, best first.
VERDICTS = ("meets", "meets_nominal_only", "fails")
#: Default Monte Carlo samples of a verdict's probability (the page and ``--confidence``).
VERDICT_SAMPLES = 1000


def operating_requirement(req: Requirement, cfg: Configuration
                          ) -> tuple[Requirement, Configuration]:
    """``req`` and ``cfg`` with the operating limits of the rule set in place of the design
    margins: free-lift fraction, tether safety factors (design and survival wind), weathervane
    margin and envelope fabric safety factor. Each is the smaller of the two (an operating limit
    never asks more than the margin). A rule set without operating limits returns ``req``
    (resolved) and ``cfg`` unchanged.

    Examples
    --------
    >>> from aerostat_core.presets import practice_configuration
    >>> r, c = operating_requirement(Requirement(), practice_configuration())
    >>> r.free_lift_fraction, r.min_tether_safety_factor, c.mission.envelope_safety_factor
    (0.05, 1.0, 1.0)
    """
    req = req.resolved()
    op = req.rule_set.operating
    if op is None:
        return req, cfg
    r = replace(
        req,
        free_lift_fraction=min(req.free_lift_fraction, op.free_lift_fraction),
        min_tether_safety_factor=min(req.min_tether_safety_factor, op.tether_safety_factor),
        survival_safety_factor=min(req.survival_safety_factor, op.tether_safety_factor),
        weathervane_margin=min(req.weathervane_margin, op.weathervane_margin),
    )
    m = cfg.mission
    c = replace(cfg, mission=replace(
        m, envelope_safety_factor=min(m.envelope_safety_factor, op.envelope_safety_factor)))
    return r, c


def required_probability(req: Requirement) -> float | None:
    """The rule set's required probability of meeting the operating limits (None: no
    operating limits in the rule set, the verdict is nominal)."""
    op = req.rule_set.operating
    return None if op is None else float(op.required_probability)


@dataclass(frozen=True)
class Verdict:
    """One verdict for a design.

    verdict : "meets", "meets_nominal_only" or "fails"
    meets_design_margins : bool
        Every row of the constraint table holds at its design margin, nominally.
    probability_meets_operating_limits, probability_meets_design_margins : float or None
        From a seeded Monte Carlo sample (None when none was asked for).
    required_probability : float or None
        The rule set's (None: no operating limits).
    binding : list of str
        Constraint names that are broken (fails), or that are most often broken in the sample
        (meets_nominal_only); empty when it meets.
    what_to_change : list of str
        The advice of those constraints, in the words of the requirement.
    samples, seed : int or None
    """

    verdict: str
    meets_design_margins: bool
    probability_meets_operating_limits: float | None
    probability_meets_design_margins: float | None
    required_probability: float | None
    binding: tuple
    what_to_change: tuple
    samples: int | None = None
    seed: int | None = None

    @property
    def headline(self) -> str:
        """One plain sentence for the top of a page."""
        if self.verdict == "meets":
            p = self.probability_meets_operating_limits
            tail = (f"; it meets the operating limits with probability {p:.2f}"
                    if p is not None else "")
            return "Meets every requirement with its design margins" + tail
        if self.verdict == "meets_nominal_only":
            return (f"Meets the requirements nominally, but meets the operating limits with "
                    f"probability {self.probability_meets_operating_limits:.2f} only (the rule "
                    f"set asks {self.required_probability:g})")
        labels = ", ".join(BY_NAME[n].label.lower() for n in self.binding) or "a constraint"
        return f"Fails: {labels}"

    def to_dict(self) -> dict:
        return {"verdict": self.verdict,
                "probability_meets_operating_limits": self.probability_meets_operating_limits,
                "probability_meets_design_margins": self.probability_meets_design_margins}


def _advice(names) -> tuple:
    out = []
    for n in names:
        a = BY_NAME[n].advice
        if a and a not in out:
            out.append(a)
    return tuple(out)


def assess(d, samples: int | None = None, seed: int = 0) -> Verdict:
    """The verdict of design ``d`` (:class:`aerostat_core.design.Design`).

    Parameters
    ----------
    d : Design
    samples : int, optional
        Monte Carlo samples, valid [10, 1e6]; None: the verdict is the nominal one ("meets" when
        every design margin holds, since the margins are what covers the uncertainty) and the
        probabilities are None.
    seed : int
        Seed, valid [0, 2^32).

    Returns
    -------
    Verdict
    """
    met = np.asarray(d.constraints.met).reshape(-1)
    broken = [NAMES[k] for k in range(len(NAMES)) if not met[k]]
    if samples is None:
        if broken:
            return Verdict("fails", False, None, None, required_probability(d.requirement),
                           tuple(broken), _advice(broken))
        return Verdict("meets", True, None, None, required_probability(d.requirement), (), ())
    from aerostat_core.uncertainty import limit_probabilities

    samples = check_int("verdict", "samples", samples, 10, 1_000_000)
    seed = check_int("verdict", "seed", seed, 0, 2**32 - 1)
    pr = limit_probabilities(d, n=samples, seed=seed)
    p_req = required_probability(d.requirement)
    p_op, p_dm = pr["operating"], pr["design"]
    if broken:
        return Verdict("fails", False, p_op, p_dm, p_req, tuple(broken), _advice(broken),
                       samples, seed)
    if p_req is not None and p_op < p_req:
        worst = sorted(pr["operating_by_constraint"].items(), key=lambda kv: kv[1])
        names = tuple(n for n, p in worst if p < 1.0)[:2]
        return Verdict("meets_nominal_only", True, p_op, p_dm, p_req, names,
                       _advice(names) + ("a larger hull (size for a confidence: --confidence)",),
                       samples, seed)
    return Verdict("meets", True, p_op, p_dm, p_req, (), (), samples, seed)


@dataclass(frozen=True)
class RobustSizing:
    """The result of :func:`robust_size`: confidence asked [-], the probability reached at the
    volume [-], the nominal sized volume and the robust one [m3], whether it was reached, and
    the samples and seed used."""

    confidence: float
    probability: float
    nominal_volume: float
    volume: float
    reached: bool
    samples: int
    seed: int
    message: str = ""


def robust_size(req: Requirement, cfg: Configuration | None = None, confidence: float = 0.95,
                samples: int = VERDICT_SAMPLES, seed: int = 0):
    """Size the smallest hull whose probability of meeting the operating limits is at least
    ``confidence`` (issue 22 item 4).

    P(V) is estimated from one seeded sample of the uncertain inputs (common random numbers:
    the same draws at every volume, so P(V) is a step function of V without sampling noise
    between volumes). From the nominal sized volume V0 the volume grows by factors of 1.25 until
    P reaches ``confidence`` (or the design margins break, or the search range ends), then
    bisection in log volume narrows the step to 0.1 %.

    Parameters
    ----------
    req, cfg : Requirement, Configuration
        ``cfg`` defaults to the rule set's; its hull volume is ignored (sized here).
    confidence : float
        Probability asked, valid [0.5, 0.999].
    samples : int
        Monte Carlo samples, valid [100, 100000].
    seed : int
        Valid [0, 2^32).

    Returns
    -------
    (Design, RobustSizing)
        The design at the robust volume (or the nominal one where ``confidence`` is not
        reached, with the reason).
    """
    from aerostat_core.design import design
    from aerostat_core.presets import rules_configuration
    from aerostat_core.sizing import VOLUME_MAX
    from aerostat_core.uncertainty import limit_probabilities

    confidence = check_number("robust sizing", "confidence", confidence, 0.5, 0.999)
    samples = check_int("robust sizing", "samples", samples, 100, 100_000)
    seed = check_int("robust sizing", "seed", seed, 0, 2**32 - 1)
    req = req.resolved()
    cfg = rules_configuration(req.rules) if cfg is None else cfg
    cfg = cfg.with_design_variables(volume=None)
    d0 = design(req, cfg)
    v0 = float(d0.volume)

    def prob(v):
        """(design margins met nominally at v, probability of the operating limits at v)."""
        ok = bool(np.all(constraint_state(req, cfg, build_airframe(req, cfg, v)).met))
        held = SimpleNamespace(requirement=req, configuration=cfg, volume=v)
        return ok, limit_probabilities(held, n=samples, seed=seed)["operating"]

    if not d0.feasible:
        return d0, RobustSizing(confidence, float("nan"), v0, v0, False, samples, seed,
                                "the nominal sizing is infeasible")
    p0 = limit_probabilities(d0, n=samples, seed=seed)["operating"]
    if p0 >= confidence:
        return d0, RobustSizing(confidence, p0, v0, v0, True, samples, seed)
    lo, p_lo, hi, best = v0, p0, None, None
    v = v0
    while v < VOLUME_MAX:
        v = min(v * 1.25, VOLUME_MAX)
        ok, p = prob(v)
        if not ok:
            return d0, RobustSizing(confidence, max(p0, p_lo), v0, v0, False, samples, seed,
                                    f"the design margins break at {v:.4g} m3 before the "
                                    f"probability reaches {confidence:g}")
        if p >= confidence:
            hi, best = v, p
            break
        lo, p_lo = v, p
    if hi is None:
        return d0, RobustSizing(confidence, p_lo, v0, v0, False, samples, seed,
                                f"no hull up to {VOLUME_MAX:g} m3 reaches {confidence:g}")
    while hi / lo - 1.0 > 1e-3:
        mid = float(np.sqrt(lo * hi))
        ok, p = prob(mid)
        if p >= confidence and ok:
            hi, best = mid, p
        else:
            lo = mid
    return (design(req, cfg.with_design_variables(volume=hi)),
            RobustSizing(confidence, best, v0, hi, True, samples, seed))


__all__ = ["VERDICTS", "Verdict", "RobustSizing", "assess", "operating_requirement",
           "required_probability", "robust_size", "CONSTRAINTS"]
