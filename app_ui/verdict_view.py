"""The verdict at the top of the Design page (issue 22 item 3): "meets", "meets nominally
only" or "fails", the probability of meeting the operating limits from a seeded sample, and for
a failing design what binds and what to change. No physics here: the verdict is
:func:`aerostat_core.studies.robust.assess`."""

from __future__ import annotations

import streamlit as st

from aerostat_core.model.constraints import BY_NAME
from aerostat_core.model.design import Design
from aerostat_core.studies.robust import assess

from .text import plain

#: Samples of the page's verdict (seeded: the same inputs give the same probability).
PAGE_SAMPLES = 500
PAGE_SEED = 0


def verdict_of(d: Design):
    """The verdict with its seeded probability, computed once per distinct inputs (keyed by the
    design's frozen inputs, no JSON on the way); the nominal one if the sample cannot run."""
    from .cache import frozen_inputs, memo

    key = frozen_inputs(d.requirement, d.configuration)
    try:
        return memo("verdict", key, lambda: assess(d, PAGE_SAMPLES, PAGE_SEED), size=64)
    except Exception:  # noqa: BLE001 - the nominal verdict is still a verdict
        return d.verdict()


def render(d: Design, stale: bool = False) -> None:
    """Lead the results with the verdict; a failing design shows what binds and what to
    change, and a hull that sinks says that its wind quantities are not shown."""
    v = verdict_of(d)
    who = "The last valid inputs: " if stale else ""
    p = v.probability_meets_operating_limits
    prob = (f" Probability of meeting the operating limits: {p:.2f} ({v.samples} seeded "
            f"samples of the model's uncertain inputs; the rule set asks "
            f"{v.required_probability:g})." if p is not None and v.required_probability
            else "")
    if v.verdict == "meets":
        st.success(plain(f"{who}Meets every requirement with its design margins.{prob}"),
                   icon=":material/check_circle:")
    elif v.verdict == "meets_nominal_only":
        st.warning(plain(f"{who}Meets the requirements nominally only.{prob} Most often "
                         "broken: " + ", ".join(BY_NAME[n].label.lower() for n in v.binding)
                         + ". What to change: " + "; ".join(v.what_to_change) + "."),
                   icon=":material/warning:")
    else:
        lines = [f"{who}Fails. What binds: "
                 + ", ".join(BY_NAME[n].label.lower() for n in v.binding) + "."]
        if d.sizing is not None and not bool(d.sizing.feasible):
            lines.append(str(d.sizing.message))
        else:
            lines += [f"What to change: {a}." for a in v.what_to_change[:3]]
        if d.sinks:
            lines.append(f"The hull cannot lift its weight (free lift {d.free_lift_kg:.1f} kg): "
                         "tether tension, blow-by and safety factors of a hull that sinks "
                         "have no meaning and are not shown.")
        st.error(plain("\n\n".join(lines)), icon=":material/error:")
    r = d.robust
    if r is not None:
        st.caption(plain(
            f"Sized for a confidence of {r.confidence:g}: {r.volume:.4g} m³ (the design "
            f"margins alone need {r.nominal_volume:.4g} m³)." if r.reached else
            f"Sizing for a confidence of {r.confidence:g} was not possible: {r.message}."))
