"""The command line is strict, bounded and never prints a traceback (issue: many tabs, many users,
faults), and its design options come from the field registry (issue: the house as its own map).

* numbers are plain ASCII decimals: ``1_0``, full-width or Arabic-Indic digits, inf and nan are
  refused with one line naming the option;
* every file and output problem (a directory, /dev/zero, a missing folder, a full disk, a FIFO
  without a reader) and every budget exits 2 with one line naming the option;
* every design input of the registry is an option, fins included, with its label, unit and range
  in --help; the thesis optimum can be given on the command line;
* names must be strings; the power-tether error is an InputError with its field.
"""

from __future__ import annotations

import argparse
import json
import os
from pathlib import Path

import pytest

from aerostat_core import Requirement, design, thesis_baseline, thesis_optimized
from aerostat_core.base.cli_input import decimal, whole
from aerostat_core.base.validation import InputError, check_name
from aerostat_core.cli.entry import _inputs, _parser, main
from aerostat_core.cli.options import input_options
from aerostat_core.model import budget
from aerostat_core.model.input_paths import all_specs
from aerostat_core.model.io import cases_from_json, design_to_json


def _fails(argv, capsys, option):
    """The CLI exits 2 with exactly one stderr line that names ``option`` (no traceback); an
    option argparse refuses exits through SystemExit(2), as argparse does."""
    try:
        code = main(argv)
    except SystemExit as exc:
        code = exc.code
    assert code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    assert err[0].startswith("error: ") and option in err[0], err[0]
    return err[0]


# --- strict numbers -----------------------------------------------------------------------------


@pytest.mark.parametrize("text", ["1_0", "\uff11\uff10", "\u0661\u0660", "inf", "nan", "1e999",
                                  "0x10", "10kg", "", "1,5", "+-1", "1e5000"])
def test_payload_must_be_a_plain_decimal(text, capsys):
    line = _fails(["design", f"--payload={text}"], capsys, "--payload")
    assert "decimal" in line or "finite" in line


@pytest.mark.parametrize("option", ["--monte-carlo", "--seed", "--gores", "--tether-segments"])
@pytest.mark.parametrize("text", ["1_0", "\uff11\uff10", "1.0", "1e3"])
def test_whole_numbers_are_plain_digits(option, text, capsys):
    _fails(["design", f"{option}={text}"], capsys, option)


def test_plain_numbers_are_read_as_written():
    assert decimal("10") == 10.0 and decimal("-0.5") == -0.5 and decimal("2.5E1") == 25.0
    assert whole("12") == 12 and whole("-3") == -3


def test_no_cli_option_reads_numbers_with_float_or_int():
    """Every numeric option of every subcommand parses with the strict readers (float() reads
    '1_0' and full-width digits as 10)."""
    p = _parser()
    subs = next(a for a in p._actions if isinstance(a, argparse._SubParsersAction))
    loose = [
        f"{name} {a.option_strings}"
        for name, sp in subs.choices.items()
        for a in sp._actions
        if a.type in (float, int)
    ]
    assert not loose, loose


def test_simulate_numbers_are_strict(capsys):
    _fails(["simulate", "--seed", "1_2"], capsys, "--seed")
    _fails(["simulate", "--duration", "\uff15"], capsys, "--duration")


# --- files and outputs --------------------------------------------------------------------------


@pytest.mark.parametrize("argv, option", [
    (["design", "--config", "/tmp"], "--config"),
    (["design", "--config", "/dev/zero"], "--config"),
    (["design", "--config", "/nonexistent/d.json"], "--config"),
    (["design", "--volume", "100", "--csv", "/tmp"], "--csv"),
    (["design", "--volume", "100", "--csv", "/dev/full"], "--csv"),
    (["design", "--volume", "100", "--csv", "/nonexistent/dir/x.csv"], "--csv"),
    (["design", "--volume", "100", "--stl", "/dev/full"], "--stl"),
    (["design", "--volume", "100", "--stl", "/tmp"], "--stl"),
    (["design", "--volume", "100", "--gores-dxf", "/dev/full"], "--gores-dxf"),
    (["design", "--volume", "100", "--gores-svg", "/tmp"], "--gores-svg"),
    (["design", "--volume", "100", "--gores-csv", "/dev/full"], "--gores-csv"),
    (["envelope", "--volume", "100", "--winds", "3", "--altitudes", "2", "--csv", "/dev/full"],
     "--csv"),
    (["envelope", "--wind-csv", "/tmp"], "--wind-csv"),
    (["report", "--volume", "100", "--monte-carlo", "50", "-o", "/dev/full"], "--output"),
    (["report", "--volume", "100", "--monte-carlo", "50", "-o", "/tmp"], "--output"),
    (["simulate", "--design", "/tmp"], "--design"),
    (["simulate", "--design", "/dev/zero"], "--design"),
])
def test_bad_files_and_outputs_exit_2_naming_the_option(argv, option, capsys):
    line = _fails(argv, capsys, option)
    assert "None" not in line  # was "error: None: No space left on device"


def test_a_json_config_that_is_not_a_design_names_the_option(tmp_path, capsys):
    f = tmp_path / "x.json"
    f.write_text('{"requirement": {"payload_mass": "ten"}}')
    _fails(["design", "--config", str(f)], capsys, "--config")


def test_a_fifo_without_reader_fails_instead_of_hanging(tmp_path, capsys):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    _fails(["design", "--volume", "100", "--csv", str(fifo)], capsys, "--csv")


# --- budgets --------------------------------------------------------------------------------------


def test_a_design_over_the_budget_names_what_to_reduce(capsys):
    line = _fails(["design", "--tether-segments", "5000", "--wind-step", "0.1"], capsys,
                  "--tether-segments")
    assert "Reduce the tether segments" in line


def test_a_config_over_the_budget_is_one_line(tmp_path, capsys):
    """The compute budget of a --config file (was a traceback: the design ran outside the
    try)."""
    from dataclasses import replace

    req, cfg = thesis_baseline()
    f = tmp_path / "big.json"
    f.write_text(design_to_json(replace(req, wind_step=0.1), replace(cfg, tether_segments=5000)))
    _fails(["design", "--config", str(f)], capsys, "--tether-segments")
    _fails(["envelope", "--config", str(f)], capsys, "--tether-segments")


def test_monte_carlo_over_the_budget_says_how_many_samples_fit(capsys):
    line = _fails(["design", "--monte-carlo", "1000000"], capsys, "--monte-carlo")
    per = 50 * (10 + 2)
    assert f"at most {budget.MAX_MONTE_CARLO_UNITS // per} samples" in line
    assert "Dask" in line


def test_the_app_largest_monte_carlo_fits_the_budget():
    """The budget is the app's: its largest Monte Carlo size (20 000 samples, 10 band winds,
    50 segments) fits; one sample more per segment does not."""
    assert budget.check_monte_carlo(50, 10, 20_000) == budget.MAX_MONTE_CARLO_UNITS
    with pytest.raises(budget.BudgetError):
        budget.check_monte_carlo(51, 10, 20_000)


def test_an_envelope_over_the_budget_is_refused_in_the_library_and_the_cli(capsys):
    from aerostat_core import Requirement
    from aerostat_core.studies.envelope import operating_envelope

    d = design(Requirement())
    with pytest.raises(budget.BudgetError, match="at most 134200 points"):
        operating_envelope(d, wind=[5.0] * 2001, altitude=[300.0] * 101)
    # the app's default grid at the registry's most tether segments fits
    assert budget.check_envelope(5000, 61 * 22) <= budget.MAX_ENVELOPE_UNITS
    _fails(["envelope", "--winds", "2001", "--altitudes", "501"], capsys, "--winds")


def test_monte_carlo_n_and_seed_out_of_range_name_the_option(capsys):
    _fails(["design", "--monte-carlo", "1"], capsys, "--monte-carlo")
    _fails(["design", "--monte-carlo", "10", "--seed", "-1"], capsys, "--monte-carlo")


def test_an_unreachable_dask_scheduler_is_one_line(monkeypatch, capsys):
    from aerostat_core.studies import scale

    monkeypatch.setattr(scale, "CONNECT_TIMEOUT", 1.0)
    _fails(["design", "--monte-carlo", "100", "--dask", "tcp://127.0.0.1:9"], capsys, "--dask")


# --- the options come from the registry -----------------------------------------------------


def test_every_design_input_has_an_option_with_label_unit_and_range_in_help(capsys):
    assert {o.path for o in input_options()} == {p.path for p in all_specs()}
    with pytest.raises(SystemExit):
        _parser().parse_args(["design", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    for o in input_options():
        p = o.spec
        assert o.option in text, o.option
        assert " ".join(p.label.split()) in text, p.label
        if p.spec.kind in ("number", "integer"):
            assert f"[{p.spec.unit or '-'}]" in text or p.spec.kind == "integer", p.path
            assert f"{p.spec.hi:g}" in text, p.path


def _value(p):
    s = p.spec
    if s.kind == "choice":
        return s.choices[-1]
    if s.kind == "text":
        return "My material"
    if p.path == "configuration.hull.fineness_ratio":
        return 3.5  # inside every shape's range used here (npl)
    lo, hi = float(s.lo), float(s.hi)
    if getattr(s, "hi_field", None) == "altitude":
        hi = min(hi, Requirement().altitude)  # bounded by the altitude given with it (default)
    v = lo + 0.1 * (hi - lo)
    return int(round(v)) if s.kind == "integer" else float(f"{v:.6g}")


#: Inputs that depend on another one, given together with it in the test below.
_WITH = {
    "configuration.gas.fixed_density": ["--gas-density-model", "fixed"],
    "configuration.wind_profile.exponent": ["--wind-profile-kind", "power"],
    "configuration.wind_profile.roughness_length": ["--wind-profile-kind", "log"],
    "configuration.hull.nose_fraction": ["--shape", "npl"],
    "configuration.fins.count": ["--fins-arrangement", "inverted-y"],  # 3 fins
    "configuration.fins.arrangement": ["--fins-count", "3"],  # inverted-y
}


@pytest.mark.parametrize("o", input_options(), ids=lambda o: o.option)
def test_every_design_input_can_be_given(o):
    value = _value(o.spec)
    extra = _WITH.get(o.path, [])
    if o.path.startswith("configuration.hull.shape"):
        extra = ["--fineness-ratio", "1.6"] if value in ("helikite",) else []
    args = _parser().parse_args(["design", o.option, str(value), *extra])
    req, cfg, _ = _inputs(args)
    obj = {"requirement": req, "configuration": cfg}
    for key in o.path.split(".")[:-1]:
        obj = obj[key] if isinstance(obj, dict) else getattr(obj, key)
    got = getattr(obj, o.path.rsplit(".", 1)[1])
    assert got == pytest.approx(value) if not isinstance(value, str) else got == value


def test_the_thesis_optimum_can_be_given_on_the_command_line(tmp_path, capsys):
    """Fin area change and position (the thesis' design variables) on the command line give the
    library's thesis optimised design."""
    from aerostat_core.model.presets import THESIS_OPTIMUM

    req, cfg = thesis_baseline()
    f = tmp_path / "baseline.json"
    f.write_text(design_to_json(req, cfg))
    argv = ["design", "--config", str(f), "--json",
            "--fineness-ratio", repr(THESIS_OPTIMUM["fineness_ratio"]),
            "--fins-area-change", repr(THESIS_OPTIMUM["area_change"]),
            "--fins-position", repr(THESIS_OPTIMUM["position"])]
    args = _parser().parse_args([a for a in argv if a != "--json"])
    args.json = True
    req2, cfg2, _ = _inputs(args)
    assert (req2, cfg2) != (req, cfg)
    ref = design(*thesis_optimized())
    # the baseline holds its volume; the optimum is sized: let the CLI size it too
    assert main(argv + ["--volume", repr(ref.volume)]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["volume_m3"] == pytest.approx(ref.volume, rel=1e-12)
    assert out["total_mass_kg"] == pytest.approx(ref.total_mass, rel=1e-9)


def test_a_catalogue_name_takes_its_properties():
    from aerostat_core.structures.materials import FABRICS

    name, fab = list(FABRICS.items())[-1]
    args = _parser().parse_args(["design", "--fin-fabric-name", name,
                                 "--fin-fabric-tensile-strength", "12345"])
    _, cfg, _ = _inputs(args)
    assert cfg.fin_fabric.areal_density == fab.areal_density
    assert cfg.fin_fabric.tensile_strength == 12345.0


def test_an_input_error_names_the_option_and_the_field(capsys):
    line = _fails(["design", "--fins-position", "2"], capsys, "--fins-position")
    assert "position" in line and "0.95" in line
    line = _fails(["design", "--payload", "-1"], capsys, "--payload")
    assert "payload_mass" in line


def test_simulate_reports_the_seed_it_used(capsys):
    assert main(["simulate", "--scenario", "turbulence", "--seed", "7", "--duration", "2",
                 "--json"]) in (0, 1)
    out = json.loads(capsys.readouterr().out)
    assert "seed 7" in out["settings"] and "seed 1," not in out["settings"]
    assert "2 s" in out["settings"]


# --- strict names and structured errors -------------------------------------------------------


@pytest.mark.parametrize("value", [{"a": 1}, ["x"], 12, 1.5, None, b"bytes", True])
def test_a_name_must_be_a_string(value):
    with pytest.raises(InputError) as err:
        check_name("case", "name", value)
    assert err.value.field == "name" and "not text" in str(err.value)


def test_a_file_whose_name_is_an_object_is_refused():
    req, cfg = thesis_baseline()
    data = json.loads(design_to_json(req, cfg))
    data["name"] = {"a": 1}
    with pytest.raises(InputError, match="not text"):
        cases_from_json(json.dumps(data))


def test_the_power_tether_error_is_an_input_error_with_its_field():
    from dataclasses import replace

    from aerostat_core import Requirement
    from aerostat_core.model.mission import effective_tether
    from aerostat_core.model.presets import rules_configuration

    req = Requirement(payload_power=1e5, power_via="tether", altitude=5000)
    with pytest.raises(InputError) as err:
        effective_tether(req, replace(rules_configuration("practice")))
    e = err.value
    assert (e.owner, e.field, e.unit) == ("Requirement", "payload_power", "W")
    assert e.value == 1e5 and "conductors" in e.reason


def test_no_traceback_for_an_unexpected_defect(monkeypatch, capsys):
    """A defect in the code (not in the input) is still one line, never a traceback."""
    import aerostat_core.cli.entry as cli

    def broken(*a, **k):
        raise TypeError("boom")

    monkeypatch.setattr(cli, "format_summary", broken)
    line = _fails(["design", "--volume", "100"], capsys, "internal error")
    assert "boom" in line


def test_help_exits_0(capsys):
    for sub in ("design", "envelope", "report", "simulate"):
        with pytest.raises(SystemExit) as exc:
            main([sub, "--help"])
        assert exc.value.code == 0
    assert "Fin position" in capsys.readouterr().out


def test_every_option_value_can_be_written_as_printed():
    """The help's example ranges parse with the strict reader (no 'e+' surprises)."""
    for p in all_specs():
        if p.spec.kind == "number":
            assert decimal(f"{p.spec.hi:g}") == pytest.approx(p.spec.hi)
    assert Path  # noqa: B018 - keeps the import used in type positions
