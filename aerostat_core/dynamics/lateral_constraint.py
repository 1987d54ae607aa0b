"""The constraint row "laterally stable up to the survival wind" (docs/dynamics.md §7.5).

A minimal hook beside the static constraint table (``aerostat_core.model.constraints``): the row
needs a 6-DOF linearisation per design (about a second per wind speed), so it is evaluated for a
finished design, not inside the optimiser's vectorised table. :data:`LATERAL_ROW_RULES` says in
which rule sets it is on (off in the thesis preset, whose survival wind is none); the integrator
may move that flag into the rule sets.
"""

from __future__ import annotations

#: Rule sets in which the row is checked.
LATERAL_ROW_RULES = {"practice": True, "thesis": False}
#: The row's name, label, unit and meaning (the static table's vocabulary).
NAME = "lateral_stability"
LABEL = "Lateral stability"
UNIT = "m/s"
TEXT = "laterally stable up to the survival wind (every lateral-directional mode decays)"


def lateral_row_enabled(requirement) -> bool:
    """True when the requirement's rule set checks the row and names a survival wind."""
    return bool(LATERAL_ROW_RULES.get(getattr(requirement, "rules", ""), False)
                and getattr(requirement, "survival_wind", None))


def lateral_constraint_row(design, analyses=None, unstable_above=None) -> dict | None:
    """The row for a design, in the format of ``ConstraintState.rows()`` (constraint, label,
    checked_at, value, limit, margin, unit, met, g), or None when the rule set does not check it.

    value: the wind speed where the first lateral mode goes unstable, or the survival wind when
    every lateral mode is stable up to it; limit: the survival wind; g = 1 - value/limit (<= 0
    met). ``analyses``/``unstable_above`` reuse a :func:`~.lateral.lateral_sweep`."""
    req = design.requirement
    if not lateral_row_enabled(req):
        return None
    vs = float(req.survival_wind)
    if analyses is None:
        from aerostat_core.dynamics.lateral import lateral_sweep

        analyses, unstable_above = lateral_sweep(design)
    value = vs if unstable_above is None else min(float(unstable_above), vs)
    g = 1.0 - value / vs
    met = unstable_above is None or unstable_above >= vs
    return {"constraint": NAME, "label": LABEL, "checked_at": f"2-{vs:g} m/s", "value": value,
            "limit": vs, "margin": value - vs, "unit": UNIT, "met": bool(met),
            "g": float(0.0 if met else max(g, 1e-9)), "text": TEXT}
