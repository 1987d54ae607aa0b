"""The public CLI outputs, to floating-point rounding, for a fixed set of inputs (issue #21 item 11).

A refactor that only moves code must leave every one of these files unchanged: the JSON of
``design``, ``simulate`` and ``envelope`` and the HTML of ``report`` are the tool's public
contracts. Every character outside numbers must match exactly; each number must match to
:data:`RTOL` relative (or one unit in the last digit it is printed with, for the report's
rounded figures). Bytes are not compared because the last bits of a float depend on the CPU:
numpy and numba pick other SIMD kernels (AVX-512 or AVX2, with or without FMA) on another
machine, which moved the 14th-10th digit of these outputs and, through matplotlib's content
hashes, the SVG clip-path ids, with the code unchanged. A change that is meant to alter the numbers regenerates the reference files on
purpose, in its own commit, with::

    AEROSTAT_REGENERATE_GOLDEN=1 .venv/bin/python -m pytest tests/core/test_golden_outputs.py

and says why in the commit message. The report's "Generated <time>" stamp and the
simulation's ``wall_time_s`` are the parts masked before comparing (they measure the clock).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "tests" / "golden"

# name -> (CLI arguments, output file suffix); "{out}" is replaced by a temporary file path.
CASES = {
    "design_default": ("design --payload 10 --altitude 300 --json", "json"),
    "design_thesis_gnvr": (
        "design --payload 50 --altitude 800 --rules thesis --shape gnvr --json",
        "json",
    ),
    "design_tether_power": (
        "design --payload 30 --altitude 500 --payload-power 500 --power-via tether "
        "--endurance-days 10 --json",
        "json",
    ),
    "design_monte_carlo": ("design --payload 10 --altitude 300 --monte-carlo 200 --seed 4", "json"),
    "simulate_gust": ("simulate --scenario gust --duration 30 --json", "json"),
    "simulate_turbulence": ("simulate --scenario turbulence --duration 30 --seed 2 --json", "json"),
    "envelope_default": ("envelope --payload 10 --altitude 300 --winds 11 --json", "json"),
    "report_default": ("report --payload 10 --altitude 300 -o {out}", "html"),
}

_STAMP = re.compile(rb"Generated [0-9]{4}-[0-9]{2}-[0-9]{2} [0-9]{2}:[0-9]{2} UTC")
# How long the run took on this machine: a measurement, not a result of the inputs.
_WALL = re.compile(rb'"wall_time_s": [0-9.e+-]+')
# matplotlib names SVG defs by a hash of their content (ids like "p17ed82688f", "m66e5f23c63"),
# so a last-bit change in a path renames them: compared by order of first appearance instead.
_SVG_ID = re.compile(rb"\b([pm][0-9a-f]{10})\b")
_NUMBER = re.compile(rb"-?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?")
#: Relative tolerance of a number [-]: across CPUs the outputs moved by up to 1.4e-9 (the
#: integrated turbulence case); a change of the model moves them by far more than 1e-7.
RTOL = 1e-7
#: Absolute floor [SI unit of the field]: residuals that are zero to rounding (1e-7 N, say).
ATOL = 1e-9


def _canonical_ids(data: bytes) -> bytes:
    names: dict[bytes, bytes] = {}
    return _SVG_ID.sub(lambda m: names.setdefault(m.group(1), b"id%d" % len(names)), data)


def _last_digit(token: bytes) -> float:
    """One unit in the last digit a number token is printed with: a rounded figure ("24.91",
    "1.234e-07", "1262") may move by that much when its unrounded value sits on a rounding
    boundary. Integers of up to 3 digits (counts, seeds, sample sizes) get none."""
    mantissa, _, exponent = token.lower().partition(b"e")
    decimals = len(mantissa.partition(b".")[2])
    if not decimals and len(mantissa.lstrip(b"-")) < 4:
        return 0.0
    return 10.0 ** (int(exponent or 0) - decimals)


def _differences(got: bytes, want: bytes) -> str | None:
    """The first difference beyond rounding, described; ``None`` when there is none."""
    g, w = _canonical_ids(got), _canonical_ids(want)
    gt, wt = _NUMBER.split(g), _NUMBER.split(w)
    gn, wn = _NUMBER.findall(g), _NUMBER.findall(w)
    for k, (a, b) in enumerate(zip(gt, wt)):
        if a != b:
            return f"text differs after {k} numbers: now {a[:120]!r}, was {b[:120]!r}"
    if len(gt) != len(wt):
        return f"{len(gn)} numbers now, {len(wn)} before"
    for k, (a, b) in enumerate(zip(gn, wn)):
        x, y = float(a), float(b)
        if x == y:
            continue
        tol = max(RTOL * max(abs(x), abs(y)), ATOL, _last_digit(a), _last_digit(b))
        if abs(x - y) > tol * (1 + 1e-9):  # the slack: 24.91 - 24.90 is 0.0100000000000016
            return f"number {k} is {a.decode()} now, {b.decode()} before (tolerance {tol:.3g})"
    return None


def _run(args: str, tmp_path: Path) -> bytes:
    out = tmp_path / "out"
    argv = [a.replace("{out}", str(out)) for a in args.split()]
    env = {**os.environ, "PYTHONHASHSEED": "0"}
    proc = subprocess.run(
        [sys.executable, "-m", "aerostat_core", *argv],
        cwd=ROOT,
        env=env,
        capture_output=True,
        timeout=600,
        check=False,
    )
    assert proc.returncode == 0, proc.stderr.decode(errors="replace")
    data = out.read_bytes() if "{out}" in args else proc.stdout
    return _WALL.sub(b'"wall_time_s": <time>', _STAMP.sub(b"Generated <time>", data))


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(CASES))
def test_cli_output_is_unchanged(name, tmp_path):
    args, suffix = CASES[name]
    got = _run(args, tmp_path)
    ref = GOLDEN / f"{name}.{suffix}"
    if os.environ.get("AEROSTAT_REGENERATE_GOLDEN") == "1":
        ref.write_bytes(got)
        pytest.skip(f"regenerated {ref.name}")
    assert ref.exists(), f"no reference {ref.name}: regenerate on purpose (see module docstring)"
    want = ref.read_bytes()
    difference = _differences(got, want)
    if difference is not None:
        pytest.fail(f"{name}: output differs from tests/golden/{ref.name}: {difference}")


def test_the_comparison_sees_a_change_and_forgives_rounding():
    base = b'{"volume_m3": 54.03388578477272, "label": "Blow-by", "x": 0.000}'
    assert _differences(base, base) is None
    # the last bits (another CPU's SIMD kernels) and a rounded "-0.000"
    assert _differences(base.replace(b"54.03388578477272", b"54.0338857847727"), base) is None
    assert _differences(base.replace(b"0.000", b"-0.000"), base) is None
    # a real change of a number, of text, of the count of numbers
    assert "is 54.03398578477272 now" in _differences(base.replace(b"54.0338", b"54.0339"), base)
    assert "text differs" in _differences(base.replace(b"Blow-by", b"Tension"), base)
    assert _differences(base + b" 1", base) is not None
    # a figure printed with 4 digits may move by one unit of its last digit, not by two
    assert _differences(b"<td>24.91</td>", b"<td>24.90</td>") is None
    assert _differences(b"<td>24.92</td>", b"<td>24.90</td>") is not None
    assert _differences(b"<td>1263</td>", b"<td>1262</td>") is None
    assert _differences(b'"samples": 201', b'"samples": 200') is not None
    # matplotlib's content-hash ids are compared by order of appearance
    svg = b'<clipPath id="p17ed82688f"/><g clip-path="url(#p17ed82688f)"/>'
    assert _differences(svg.replace(b"p17ed82688f", b"p0123456789"), svg) is None
