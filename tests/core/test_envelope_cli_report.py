"""CLI contract of ``envelope``, ``report`` and ``design --monte-carlo``; the HTML report's
content (sections, inline plots, no network, escaped text)."""

from __future__ import annotations

import json
import re
from dataclasses import replace

import pytest

from aerostat_core import Requirement, design
from aerostat_core.cli.entry import main
from aerostat_core.output.html_report import SECTIONS, render_report
from aerostat_core.studies.envelope import operating_envelope
from aerostat_core.studies.site_wind import flyable_time
from aerostat_core.studies.uncertainty import monte_carlo


def test_envelope_json_has_points_and_flyable_time(capsys):
    assert (
        main(
            [
                "envelope",
                "--payload",
                "10",
                "--altitude",
                "300",
                "--winds",
                "11",
                "--altitudes",
                "4",
                "--json",
            ]
        )
        == 0
    )
    out = json.loads(capsys.readouterr().out)
    assert out["n_points"] == len(out["points"]) == 11 * 5  # 4 altitudes + the design one
    assert 0.0 < out["percent_time_flyable"] < 100.0
    p = out["points"][0]
    assert set(p) == {
        "wind_m_s",
        "altitude_m",
        "payload_kg",
        "binding",
        "margin",
        "unit",
        "g",
        "flyable",
    }
    d = design(Requirement(payload_mass=10, altitude=300))
    assert out["percent_time_flyable"] == pytest.approx(flyable_time(d).percent_time_flyable)


def test_envelope_with_a_calm_wind_csv_is_flyable_all_the_time(tmp_path, capsys):
    f = tmp_path / "calm.csv"
    f.write_text("timestamp,speed\n" + "".join(f"2009-01-01 {h:02d}:00,0.0\n" for h in range(24)))
    assert (
        main(["envelope", "--wind-csv", str(f), "--winds", "5", "--altitudes", "2", "--json"]) == 0
    )
    out = json.loads(capsys.readouterr().out)
    assert out["percent_time_flyable"] == 100.0 and out["wind_source"] == "csv"


def test_bad_wind_csv_exits_2_with_one_line(tmp_path, capsys):
    f = tmp_path / "bad.csv"
    f.write_text("time,speed\n2009-01-01 00:00,fast\n2009-01-01 01:00,3\n")
    assert main(["envelope", "--wind-csv", str(f)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "row 1: 'fast' is not a wind speed" in err[0]
    big = tmp_path / "big.csv"
    big.write_bytes(b"0" * 10_000_001)
    assert main(["envelope", "--wind-csv", str(big)]) == 2
    assert "larger than 10000000 bytes" in capsys.readouterr().err
    assert main(["envelope", "--wind-csv", str(tmp_path / "none.csv")]) == 2
    assert "No such file" in capsys.readouterr().err


def test_design_monte_carlo_keys(capsys):
    assert main(["design", "--monte-carlo", "400", "--seed", "5", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    for q, u in (("blow_by", "m"), ("tension", "N"), ("free_lift", "kg")):
        assert out[f"{q}_p05_{u}"] < out[f"{q}_p95_{u}"]
    assert out["blow_by_p05_m"] < out["blow_by_at_design_wind_m"] < out["blow_by_p95_m"]
    assert out["monte_carlo_samples"] == 400
    assert [r["rules"] for r in out["rule_sets"]] == ["practice", "thesis"]  # shown beside it
    d = design(Requirement())
    assert out["blow_by_p95_m"] == monte_carlo(d, 400, 5).summary()["blow_by_p95_m"]


def test_design_monte_carlo_on_local_dask_equals_one_process(capsys):
    assert main(["design", "--monte-carlo", "300", "--seed", "2", "--json"]) == 0
    a = json.loads(capsys.readouterr().out)
    assert main(["design", "--monte-carlo", "300", "--seed", "2", "--dask", "local", "--json"]) == 0
    b = json.loads(capsys.readouterr().out)
    assert a == b


@pytest.fixture(scope="module")
def html():
    d = design(Requirement(payload_mass=10, altitude=300))
    d = replace(
        d,
        configuration=replace(
            d.configuration,
            hull_fabric=replace(d.configuration.hull_fabric, name="<script>alert(1)</script>"),
        ),
    )
    env = operating_envelope(d)
    return render_report(d, env, flyable_time(d), monte_carlo(d, 200, 1))


def test_report_has_every_section_and_inline_plots(html):
    for sid in SECTIONS:
        assert f'<section id="{sid}">' in html, sid
    plots = re.findall(r'<figure class="plot" data-plot="(\w+)"><svg', html)
    assert set(plots) == {"side_view", "performance", "tether", "envelope"}
    assert html.count("<svg") == 4


def test_report_is_offline_and_escapes_text(html):
    assert "<script" not in html
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in html
    assert not re.search(r"""(src|href)=["']?(https?:)?//""", html)
    assert "@import" not in html and "url(http" not in html
    assert "@media print" in html


def test_report_cli_writes_the_file(tmp_path, capsys):
    out = tmp_path / "r.html"
    assert main(["report", "--payload", "8", "--monte-carlo", "0", "-o", str(out)]) == 0
    text = out.read_text()
    assert text.startswith("<!DOCTYPE html>") and "8 kg at 300 m" in text
    assert "Monte Carlo not run." in text
    assert "report written to" in capsys.readouterr().out
