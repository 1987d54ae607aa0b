"""Method page (AppTest): equations rendered, live validation table from
aerostat_core.studies.reference, and a clear message when that module is missing."""

from __future__ import annotations

import sys

import pytest

from tests.app.helpers import METHOD_PAGE, goto, messages, metrics, table


@pytest.fixture
def method(at, clear_cache):
    goto(at, METHOD_PAGE)
    assert not at.exception
    return at


def test_equations_and_sections(method):
    at = method
    assert at.title[0].value == "Method"
    latex = [str(el.value) for el in at.latex]
    assert len(latex) >= 20
    joined = " ".join(latex)
    for fragment in (
        r"\rho_{air}",
        r"\rho_{LTA}",
        r"r(\xi)",
        "k_1",
        "N_h",
        "C_{DV}",
        r"C_{L\alpha}",
        r"\xi_C",
        "M_C",
        "T_x = D",
        "SF",
    ):
        assert fragment in joined, fragment
    labels = [e.label for e in at.expander]
    for part in (
        "Atmosphere",
        "Lifting gas",
        "NPL",
        "Lamb",
        "Jones & DeLaurier",
        "Fins",
        "Mass budget",
        "confluence point",
        "Tether",
        "Sizing",
    ):
        assert any(part in lab for lab in labels), part
    text = " ".join(str(m.value) for m in at.markdown)
    assert "Calibrated versus predicted" in text
    assert "Rajani" in text and "Hoerner" in text and "Lamb" in text


def test_live_validation_table(method):
    from aerostat_core.studies.reference import reference_checks

    ref = reference_checks()
    df = table(method, "Quantity")
    assert len(df) == len(ref)
    assert list(df["Quantity"]) == [r["name"] for r in ref]
    assert set(df["Kind"]) <= {"calibrated", "predicted", "check"}
    for row, r in zip(df.itertuples(index=False), ref):
        assert row.Engine == pytest.approx(r["value"])
        assert row.Reference == pytest.approx(r["reference"])
    n_ok = sum(bool(r.get("passed", abs(r["error_pct"]) <= r["tolerance_pct"])) for r in ref)
    shown = next(m.value for m in metrics(method) if m.label == "Checks within tolerance")
    assert shown == f"{n_ok} / {len(ref)}"
    labels = [b.proto.label for b in method.get("download_button")]
    assert "Validation table (CSV)" in labels


def test_missing_reference_module_shows_a_message(at, clear_cache, monkeypatch):
    monkeypatch.setitem(sys.modules, "aerostat_core.studies.reference", None)  # import now fails
    goto(at, METHOD_PAGE)
    assert not at.exception
    assert any("aerostat_core.studies.reference" in i for i in messages(at, "info"))
    assert len(at.latex) >= 20  # the equations are still there


def test_fielded_harness_is_shown_live():
    """The Method page runs the fielded-aerostat harness and shows its figures (issue 8)."""
    from streamlit.testing.v1 import AppTest

    from aerostat_core.studies.fielded import validate_fielded
    from tests.app.conftest import APP_PATH, TIMEOUT_S

    app = AppTest.from_file(str(APP_PATH), default_timeout=TIMEOUT_S)
    app.run()
    app.switch_page("pages/6_Method.py").run()
    assert not app.exception
    v = validate_fielded()
    shown = {m.label: m.value for m in metrics(app)}
    st = v.statistics()
    assert shown["Median |length error|, all [%]"] == f"{100 * st['all_median']:.1f}"
    assert shown["Median |length error|, held out [%]"] == f"{100 * st['held_out_median']:.1f}"
    assert shown["Median |volume error| [%]"] == f"{100 * st['volume_median']:.1f}"
    assert shown["Worst |length error|, consistent figures [%]"] == \
        f"{100 * st['consistent_worst']:.1f}"
    df = next(d.value for d in app.dataframe if "Published length [m]" in d.value.columns)
    assert list(df["System"]) == [r.system.name for r in v.rows]
    assert set(df["Class"]) == {"tactical", "operational", "strategic"}
    flagged = {r.system.name for r in v.rows if not r.system.consistent}
    assert {n for n, t in zip(df["System"], df["Inconsistency"]) if t} == flagged
