"""Headline numbers (app_ui/headline.py): what the reader sees equals what the page passed, every
text escaped, and the Design page's deltas coloured by what they say about the design."""

from __future__ import annotations

import re

import pytest
from hypothesis import given
from hypothesis import strategies as st

from aerostat_core import design
from app_ui import state
from app_ui.headline import TONE_COLOUR, Headline, Note, headline_html
from app_ui.text import signed
from tests.app.helpers import messages, metric_float, metrics, submit

_TEXT = st.text(st.characters(blacklist_categories=("Cs", "Cc")), max_size=40)


class _FakeHtml:
    def __init__(self, body: str) -> None:
        self.proto = type("P", (), {"body": body})()


class _FakeApp:
    def __init__(self, body: str) -> None:
        self._els = [_FakeHtml(body)]

    def get(self, kind: str) -> list:
        return self._els if kind == "html" else []


@given(
    st.lists(
        st.builds(Headline, _TEXT, _TEXT, _TEXT, _TEXT, st.sampled_from(list(TONE_COLOUR))),
        min_size=1,
        max_size=6,
    ),
    _TEXT,
)
def test_every_text_reads_back_as_given_and_none_becomes_markup(items, note) -> None:
    body = headline_html([items[0], Note(note), *items[1:]])
    shown = metrics(_FakeApp(body))
    assert [(m.label, m.value, m.help, m.delta) for m in shown] == [
        (h.label, h.value, h.help, h.delta) for h in items
    ]
    assert [m.tone for m in shown] == [h.tone if h.delta else "" for h in items]
    # markup in a text stays text: one block, one item element per number
    assert body.count('data-testid="headline"') == len(items)
    assert body.count("<script") == 0 and body.count("<style") == 0


def test_a_delta_takes_its_tones_colour_and_a_note_breaks_the_line() -> None:
    body = headline_html([Headline("a", "1", delta="+1", tone="bad"), Note("n"), Headline("b", "2")])
    assert f"color:{TONE_COLOUR['bad']}" in body
    assert body.index('data-testid="headline-note"') < body.index(">b<")
    assert 'class="hl-note"' in body  # a line of its own (flex-basis 100 % in theme.PAGE_CSS)


def test_the_focus_note_names_the_number_it_explains() -> None:
    """The help shown on focus sits under the whole block (so it stays on the page), so it
    starts with its number's label; the hover tooltip is the help alone."""
    body = headline_html([Headline("Volume [m³]", "170.0", "Hull volume <V>."), Headline("b", "2")])
    assert 'data-help="Volume [m³]: Hull volume &lt;V&gt;."' in body
    assert 'title="Hull volume &lt;V&gt;."' in body
    assert body.count("data-help") == 1 and body.count('tabindex="0"') == 1  # no help, no stop


def test_design_page_headline_matches_the_design_and_its_deltas(at) -> None:
    shown = {m.label: m for m in metrics(at)}
    assert len(shown) == 10
    d = design(*state.current_inputs(at.session_state))
    lim = d.requirement
    assert metric_float(at, "Volume [m³]") == pytest.approx(d.volume, abs=0.05)
    assert shown["Volume [m³]"].delta == "sized" and shown["Volume [m³]"].tone == "neutral"
    bb = float(shown["Blow-by [m]"].value.replace(",", ""))
    assert shown["Blow-by [m]"].delta == f"{signed(bb - lim.blow_by_limit, 1)} m"
    assert shown["Blow-by [m]"].tone == "good"
    sf = shown["Safety factor [-]"]
    required = float(re.search(r"required ([0-9.]+)", sf.help).group(1))
    assert float(sf.delta) == pytest.approx(float(sf.value) - required, abs=0.011)
    assert sf.tone == ("good" if float(sf.value) >= required else "bad")
    assert "limit" in shown["Blow-by [m]"].help


def test_a_blow_by_over_its_limit_is_shown_in_the_limit_colour(at) -> None:
    # a given hull too small for a tight limit: the blow-by exceeds it, the delta says by how much
    submit(at, in_volume_mode="given", in_volume=60.0, in_blow_by=20.0)
    shown = {m.label: m for m in metrics(at)}
    assert shown["Volume [m³]"].delta == "given"
    bb = float(shown["Blow-by [m]"].value.replace(",", ""))
    assert bb > 20.0
    assert shown["Blow-by [m]"].tone == "bad"
    assert shown["Blow-by [m]"].delta.startswith("+")


def test_a_hull_sized_to_its_blow_by_limit_reads_as_meeting_it(at) -> None:
    """Sized by blow-by, the hull sits at the limit within the engine's tolerance: the delta
    rounds to "0.0 m" and reads as met, as the nominal verdict says (a red "0.0" would
    contradict it)."""
    submit(at, in_blow_by=80.0)
    shown = {m.label: m for m in metrics(at)}
    assert at.session_state["design_inputs"]["requirement"]["blow_by_limit"] == 80.0
    assert shown["Blow-by [m]"].delta == "0.0 m"
    assert shown["Blow-by [m]"].tone == "good"
    # the verdict: met nominally (the margin to the limit is nil, so the seeded samples break
    # it half of the time), never "not met"
    verdicts = messages(at, "success") + messages(at, "warning")
    assert any(m.startswith("Meets the requirements nominally") for m in verdicts), verdicts


def test_the_module_examples_hold() -> None:
    import doctest

    import app_ui.headline

    assert doctest.testmod(app_ui.headline).failed == 0
