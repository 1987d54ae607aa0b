"""Lateral-directional stability beside the longitudinal C_m on the Design page (issue 25 item
3): the static lateral derivatives C_Yβ, C_nβ, C_lβ at the design wind and the wind speed at
which the first lateral mode goes unstable (or "stable up to the survival wind"). No physics
here: the numbers are the design summary's (:class:`aerostat_core.model.design.LateralSummary`,
computed by the 6-DOF linearisation)."""

from __future__ import annotations

import streamlit as st

from . import formats


def _coef(x: float | None) -> str:
    return "–" if x is None else f"{x:+.3f}".replace("-", "−")


def lateral_lines(lat, survival_wind: float | None) -> list[str]:
    """Markdown lines (no user text in them): the stability sentence, then one line per
    derivative with its unit and meaning. ``lat``: the summary's lateral keys (None: not
    computed)."""
    if lat is None:
        return ["Lateral stability: not computed for this design."]
    wind = (lambda v: formats.shown(v, "wind", with_unit=True))  # noqa: E731
    if not lat.lateral_stability_checked:
        head = ("Lateral stability: the rule set does not check it (no survival wind); the "
                "static derivatives below are for information.")
    elif lat.lateral_unstable_above_m_s is None:
        top = lat.lateral_checked_up_to_m_s or survival_wind
        head = (f"**Laterally stable up to the survival wind** ({wind(top)}): every "
                "lateral-directional mode of the 6-DOF model decays.")
    else:
        head = (f"**A lateral mode goes unstable from {wind(lat.lateral_unstable_above_m_s)}** "
                f"(kiting), below the survival wind {wind(survival_wind)}: larger fins, fins "
                "further aft or a confluence point further forward.")
    if lat.C_n_beta_per_rad is None:
        return [head, "Static lateral derivatives: not computed (no equilibrium in the wind)."]
    at = wind(lat.lateral_derivatives_wind_m_s)
    return [
        head,
        f"Static lateral derivatives at {at} (per radian of sideslip β):",
        f"- C_Yβ {_coef(lat.C_Y_beta_per_rad)} /rad: side force",
        f"- C_nβ {_coef(lat.C_n_beta_per_rad)} /rad: yawing moment about the centre of volume "
        "(> 0 turns the nose into the wind)",
        f"- C_nβ,C {_coef(lat.C_n_beta_confluence_per_rad)} /rad: the same about the "
        "confluence point",
        f"- C_lβ {_coef(lat.C_l_beta_per_rad)} /rad: rolling moment about the confluence point",
    ]


def render(rep) -> None:
    """The lateral block of the Performance tab, from the design report ``rep``."""
    s = rep.summary
    lines = lateral_lines(s.lateral, s.survival_wind_m_s)
    # one element (each costs the tab switch front-end time): the title, the sentences, the list
    st.markdown(
        "**Lateral stability**\n\n" + "\n\n".join(lines[:2]) + "\n" + "\n".join(lines[2:])
    )
