"""The verdict an engineer can sign, nominally: design margins and operating limits as two
things, and one verdict for a design (issue 22 items 2-3; docs/methods.md §1.16).

* :func:`operating_requirement`: the requirement and configuration whose limits are the rule
  set's operating limits (:class:`aerostat_core.model.rules.OperatingLimits`) instead of its
  design margins; the constraint table evaluated with them says whether the design flies.
* :func:`nominal_verdict`: "meets" when every design margin holds nominally (the margins are
  what covers the uncertainty then), "fails" otherwise, with what binds and what to change.
  The verdict with a seeded sample of the uncertain inputs, which can also say
  "meets_nominal_only", is :func:`aerostat_core.studies.robust.assess`.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from aerostat_core.model.constraints import BY_NAME, NAMES
from aerostat_core.model.inputs import Configuration, Requirement

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
    >>> from aerostat_core.model.presets import practice_configuration
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


def advice(names) -> tuple:
    """The advice of constraints ``names`` (in the requirement's words), each once."""
    out = []
    for n in names:
        a = BY_NAME[n].advice
        if a and a not in out:
            out.append(a)
    return tuple(out)


def nominal_verdict(d) -> Verdict:
    """The verdict of design ``d`` without a sample: "fails" with the broken rows and their
    advice, or "meets" (every design margin holds nominally)."""
    met = np.asarray(d.constraints.met).reshape(-1)
    broken = [NAMES[k] for k in range(len(NAMES)) if not met[k]]
    p_req = required_probability(d.requirement)
    if broken:
        return Verdict("fails", False, None, None, p_req, tuple(broken), advice(broken))
    return Verdict("meets", True, None, None, p_req, (), ())
