"""The verdict with a seeded sample, and robust sizing (issue 22 items 2-4;
docs/methods.md §1.16).

* :func:`assess`: one verdict for a design: ``"meets"`` (the design margins hold and, when a
  seeded sample is asked for, the probability of meeting the operating limits reaches the rule
  set's ``required_probability``), ``"meets_nominal_only"`` (the margins hold nominally but that
  probability falls short) or ``"fails"`` (a design margin is broken); with what binds and what
  to change.
* :func:`robust_size`: the smallest hull whose probability of meeting the operating limits is at
  least ``confidence`` under the Monte Carlo spreads; :func:`design_with_confidence` applies
  ``Requirement.confidence`` (what the CLI and the app call instead of ``design()``).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from types import SimpleNamespace

import numpy as np

from aerostat_core.base.validation import check_int, check_number
from aerostat_core.model.airframe import build_airframe
from aerostat_core.model.constraints import NAMES, constraint_state
from aerostat_core.model.inputs import Configuration, Requirement
from aerostat_core.model.verdict import (
    VERDICT_SAMPLES,
    VERDICTS,
    Verdict,
    advice,
    nominal_verdict,
    operating_requirement,
    required_probability,
)


def assess(d, samples: int | None = None, seed: int = 0) -> Verdict:
    """The verdict of design ``d`` (:class:`aerostat_core.model.design.Design`).

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
        return nominal_verdict(d)
    from aerostat_core.studies.uncertainty import limit_probabilities

    samples = check_int("verdict", "samples", samples, 10, 1_000_000)
    seed = check_int("verdict", "seed", seed, 0, 2**32 - 1)
    pr = limit_probabilities(d, n=samples, seed=seed)
    p_req = required_probability(d.requirement)
    p_op, p_dm = pr["operating"], pr["design"]
    if broken:
        return Verdict("fails", False, p_op, p_dm, p_req, tuple(broken), advice(broken),
                       samples, seed)
    if p_req is not None and p_op < p_req:
        worst = sorted(pr["operating_by_constraint"].items(), key=lambda kv: kv[1])
        names = tuple(n for n, p in worst if p < 1.0)[:2]
        return Verdict("meets_nominal_only", True, p_op, p_dm, p_req, names,
                       advice(names) + ("a larger hull (size for a confidence: --confidence)",),
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
    from aerostat_core.model.design import design
    from aerostat_core.model.presets import rules_configuration
    from aerostat_core.model.sizing import VOLUME_MAX
    from aerostat_core.studies.uncertainty import limit_probabilities

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




def design_with_confidence(req: Requirement | None = None, cfg: Configuration | None = None):
    """The design the front ends show: ``design(req, cfg)``, or, when ``req.confidence`` is set
    and the volume is sized, the robust design of :func:`robust_size` (its ``robust``
    attribute says how it was sized); either with its ``lateral_stability`` row filled by the
    6-DOF linearisation (:func:`aerostat_core.dynamics.lateral_constraint.assess_lateral`,
    after sizing: the row never drives the volume)."""
    from aerostat_core.dynamics.lateral_constraint import assess_lateral
    from aerostat_core.model.design import design

    req = Requirement() if req is None else req
    if req.confidence is None or (cfg is not None and cfg.hull.volume is not None):
        return assess_lateral(design(req, cfg))
    d, info = robust_size(replace(req, confidence=None), cfg, req.confidence)
    return assess_lateral(replace(d, requirement=req.resolved(), robust=info))


__all__ = ["VERDICTS", "Verdict", "RobustSizing", "assess", "design_with_confidence",
           "operating_requirement", "robust_size"]
