"""JSON/CSV I/O (strict on hostile files) and the command line."""

import csv
import io
import json

import pytest

from aerostat_core import Configuration, Requirement, design, thesis_baseline
from aerostat_core.cli.entry import design_csv, main
from aerostat_core.model.io import (
    MAX_JSON_BYTES,
    cases_from_json,
    cases_to_json,
    design_from_json,
    design_to_json,
    inputs_from_dict,
    inputs_to_dict,
)


def test_json_round_trip_keeps_every_input():
    req, cfg = thesis_baseline()
    req2, cfg2 = design_from_json(design_to_json(req, cfg))
    assert (req2, cfg2) == (req, cfg)
    inf_cfg = Configuration(tether=cfg.tether.__class__("x", 0.02, 0.005, 1, 0.01, 1e4,
                                                       float("inf")))
    assert design_from_json(design_to_json(req, inf_cfg))[1] == inf_cfg


@pytest.mark.parametrize(
    "text, message",
    [
        (b"{not json", "not valid JSON"),
        (b"[1, 2]", "must be a JSON object"),
        (json.dumps({"requirement": {"payload_mass": -5}}), "payload_mass = -5"),
        (json.dumps({"requirement": {"payload_mass": "10"}}), "payload_mass = '10' is not a"),
        (json.dumps({"requirement": {"payload": 10}}), "unknown field"),
        (json.dumps({"configuration": {"gas": {"purity": [1]}}}), "gas.purity must be a single"),
        (json.dumps({"configuration": {"gas": 5}}), "configuration.gas must be an object"),
        (json.dumps({"format": "other"}), "format"),
        (json.dumps({"version": 99}), "version"),
        (b'{"requirement": {"payload_mass": NaN}}', "NaN"),
        (b"\xff\xfe", "UTF-8"),
        (b"[" * 100000 + b"]" * 100000, "nested"),
        (b" " * (MAX_JSON_BYTES + 1), "limit"),
        (b'{"requirement": {"payload_mass": 1' + b"0" * 400 + b"}}", "payload_mass .* not finite"),
        (b'{"requirement": {"payload_mass": 1' + b"0" * 5000 + b"}}", "number that cannot"),
        (b'{"configuration": {"tether_segments": 1' + b"0" * 400 + b"}}", "tether_segments"),
        (json.dumps({"version": True}), "version"),
        (json.dumps({"configuration": {"tether": {"name": "a\nb"}}}), "control characters"),
        (json.dumps({"configuration": {"tether": {"axial_stiffness": 1e-3}}}), "axial_stiffness"),
    ],
)
def test_hostile_design_files_get_a_clear_message(text, message):
    with pytest.raises(ValueError, match=message):
        design_from_json(text)


def test_cases_round_trip_and_one_bad_case_rejects_the_file():
    req, cfg = thesis_baseline()
    cases = {"a": inputs_to_dict(req, cfg), "b": inputs_to_dict(Requirement(payload_mass=30), cfg)}
    assert cases_from_json(cases_to_json(cases)) == cases
    bad = dict(cases)
    bad["c"] = {"requirement": {"altitude": -3}}
    with pytest.raises(ValueError, match="case 'c'.*altitude"):
        cases_from_json(cases_to_json(bad))
    single = cases_from_json(design_to_json(req, cfg))
    assert list(single) == ["imported"]


def test_missing_fields_take_defaults():
    req, cfg = inputs_from_dict({})
    assert (req, cfg) == (Requirement(), Configuration())


def test_cli_prints_summary_and_writes_csv(tmp_path, capsys):
    out = tmp_path / "d.csv"
    assert main(["design", "--payload", "10", "--altitude", "300", "--volume", "170",
                 "--csv", str(out)]) == 0
    text = capsys.readouterr().out
    assert "volume" in text and "170.0 m3" in text and "total mass" in text
    sections = out.read_text().split("\n\n")
    assert [s.splitlines()[0] for s in sections] == [
        "# geometry", "# mass breakdown", "# performance versus wind speed"]
    perf = list(csv.DictReader(io.StringIO(sections[2].split("\n", 1)[1])))
    assert len(perf) == 21 and float(perf[0]["wind_speed_m_s"]) == 0.0
    assert "blow_by_m" in perf[0]


def test_cli_config_file_is_used(tmp_path, capsys):
    req, cfg = thesis_baseline()
    f = tmp_path / "design.json"
    f.write_text(design_to_json(req, cfg))
    assert main(["design", "--config", str(f)]) == 0
    text = capsys.readouterr().out
    assert f"{design(req, cfg).total_mass:.2f} kg" in text


@pytest.mark.parametrize("argv, field", [
    (["design", "--payload", "-1"], "payload_mass"),
    (["design", "--altitude", "99999"], "altitude"),
    (["design", "--volume", "0"], "volume"),
    (["design", "--config", "/nonexistent.json"], "--config"),
])
def test_cli_bad_value_exits_2_with_one_line(argv, field, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and field in err[0]


def test_design_csv_has_units_in_columns():
    text = design_csv(design(*thesis_baseline()))
    assert "mass_kg" in text and "tension_top_N" in text and "alpha_eq_deg" in text


def test_cli_default_limits_scale_with_the_altitude(capsys):
    """Practice rules: blow-by limit 0.5 x altitude, altitude loss 0.15 x altitude."""
    assert main(["design", "--payload", "10", "--altitude", "500", "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["rules"] == "practice" and s["feasible"]
    assert main(["design", "--payload", "10", "--altitude", "500", "--volume", "20"]) == 0
    out = capsys.readouterr().out
    assert "NOT FEASIBLE" in out and "free lift" in out


def test_cli_unwritable_csv_exits_2(capsys):
    assert main(["design", "--volume", "170", "--csv", "/nonexistent/dir/x.csv"]) == 2
    assert "--csv" in capsys.readouterr().err


def test_cli_config_reads_only_a_bounded_regular_file(tmp_path, capsys):
    assert main(["design", "--config", "/dev/zero"]) == 2
    assert "not a regular file" in capsys.readouterr().err
    big = tmp_path / "big.json"
    big.write_bytes(b" " * 1_000_001)
    assert main(["design", "--config", str(big)]) == 2
    assert "larger than 1000000 bytes" in capsys.readouterr().err


def test_cli_closed_pipe_exits_quietly():
    """A reader that goes away (``| head``) before the output is written: exit 0, no BrokenPipe
    traceback. The read end is closed before the child has computed its design, so its first
    write meets a closed pipe."""
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parents[2]
    proc = subprocess.Popen(
        [sys.executable, "-m", "aerostat_core", "design", "--json"],
        cwd=root, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
    )
    proc.stdout.close()
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 0, err
    assert b"Traceback" not in err and b"BrokenPipe" not in err
