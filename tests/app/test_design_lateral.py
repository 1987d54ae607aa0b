"""The Design page shows lateral stability beside the longitudinal C_m (issue 25 item 3): the
static lateral derivatives with their units, the wind speed at which the first lateral mode goes
unstable or "stable up to the survival wind", and the lateral row of the constraint table."""

from __future__ import annotations

from aerostat_core import Requirement
from aerostat_core.studies.robust import design_with_confidence
from tests.app.helpers import show_tab, shown_table


def _lateral_text(at) -> str:
    return "\n".join(m.value for m in at.markdown if "C_Yβ" in m.value or "ateral" in m.value)


def test_performance_tab_shows_the_lateral_derivatives_beside_c_m(at):
    d = design_with_confidence(Requirement())  # the page's default design, as the app makes it
    s = d.summary().lateral
    show_tab(at, "Performance")
    assert not at.exception
    text = _lateral_text(at)
    assert "Laterally stable up to the survival wind" in text and "20.0 m/s" in text
    for name, x in (("C_Yβ", s.C_Y_beta_per_rad), ("C_nβ", s.C_n_beta_per_rad),
                    ("C_lβ", s.C_l_beta_per_rad)):
        shown = f"{name} {x:+.3f}".replace("-", "−") + " /rad"
        assert shown in text, (shown, text)
    for raw in ("None", "nan", "inf"):
        assert raw not in text
    # the row of the constraint table, checked over the sweep to the survival wind
    rows = shown_table(at, "Constraint")
    lat = rows[rows["Constraint"].str.startswith("Lateral stability")]
    assert list(lat["Constraint"]) == ["Lateral stability, at 2-20 m/s"]
    assert list(lat["Met"]) == ["yes"]


def test_thesis_rule_set_leaves_the_row_out(thesis_at):
    rows = shown_table(thesis_at, "Constraint")
    assert not rows["Constraint"].str.startswith("Lateral stability").any()
    show_tab(thesis_at, "Performance")
    text = _lateral_text(thesis_at)
    assert "does not check it" in text and "C_nβ" in text
