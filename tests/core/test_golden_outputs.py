"""The public CLI outputs, byte for byte, for a fixed set of inputs (issue #21 item 11).

A refactor that only moves code must leave every one of these files unchanged: the JSON of
``design``, ``simulate`` and ``envelope`` and the HTML of ``report`` are the tool's public
contracts. A change that is meant to alter the numbers regenerates the reference files on
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
def test_cli_output_is_byte_identical(name, tmp_path):
    args, suffix = CASES[name]
    got = _run(args, tmp_path)
    ref = GOLDEN / f"{name}.{suffix}"
    if os.environ.get("AEROSTAT_REGENERATE_GOLDEN") == "1":
        ref.write_bytes(got)
        pytest.skip(f"regenerated {ref.name}")
    assert ref.exists(), f"no reference {ref.name}: regenerate on purpose (see module docstring)"
    want = ref.read_bytes()
    if got != want:
        # Name the first differing line, so a reviewer sees what moved.
        g, w = got.splitlines(), want.splitlines()
        first = next((i for i, (a, b) in enumerate(zip(g, w)) if a != b), min(len(g), len(w)))
        pytest.fail(
            f"{name}: output differs from tests/golden/{ref.name} at line {first + 1}:\n"
            f"  now : {g[first][:200] if first < len(g) else b'<end>'!r}\n"
            f"  was : {w[first][:200] if first < len(w) else b'<end>'!r}"
        )
