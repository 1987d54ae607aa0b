"""Every documented example runs: the README's Python snippets and its command lines.

Each ```python block runs in a fresh interpreter from the repository root. Each ```bash line that
calls the CLI (``.venv/bin/python -m aerostat_core ...`` or ``aerostat ...``) runs with this
interpreter in a scratch folder holding the example files the README names (``design.json``,
the thesis baseline; ``mersing.csv`` and ``site.csv``, a week of synthetic hourly wind): it must
exit 0 (or, where the line handles the exit code itself with ``||``, print one error line) and
never print a traceback. Lines that set up machines or need infrastructure a test cannot have
(make, docker, a Dask scheduler and workers on other hosts) are listed in :data:`NOT_RUN`; any
other line must run, so a new example is either runnable or listed here with its reason.
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from aerostat_core import thesis_baseline
from aerostat_core.model.io import design_to_json

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
#: Command lines of the README that are not run here, by prefix, with the reason.
NOT_RUN = {
    "make ": "sets up .venv, chromium or the whole test suite (CI runs it)",
    "docker ": "no Docker engine on the development and CI machines (tests/test_dockerfile.py)",
    "dask scheduler": "starts a cluster scheduler on another host",
    "dask worker": "starts a cluster worker on another host",
    ".venv/bin/python -m aerostat_core design --monte-carlo 100000000 --dask tcp://scheduler-host":
        "needs that cluster: 10^8 samples (tests/core/test_scale_dask.py runs the same path on a "
        "local cluster)",
}
CLI_PREFIXES = (".venv/bin/python -m aerostat_core ", "aerostat ")


def _blocks(lang: str) -> list[str]:
    return re.findall(rf"^```{lang}\n(.*?)^```", README.read_text(), flags=re.S | re.M)


def _commands() -> list[str]:
    out = []
    for block in _blocks("bash"):
        text = block.replace("\\\n", " ")
        for line in text.splitlines():
            line = re.sub(r"\s+#.*$", "", line).strip()  # trailing comments
            if line and not line.startswith("#"):
                out.append(" ".join(line.split()))
    return out


def _runs(line: str) -> bool:
    return line.startswith(CLI_PREFIXES)


def test_every_readme_command_line_is_run_or_listed():
    lines = _commands()
    assert sum(map(_runs, lines)) >= 8
    unlisted = [ln for ln in lines if not _runs(ln) and not ln.startswith(tuple(NOT_RUN))]
    assert not unlisted, f"README command lines neither run by this test nor listed: {unlisted}"


@pytest.fixture(scope="module")
def example_dir(tmp_path_factory) -> Path:
    """The example files the README's commands name."""
    d = tmp_path_factory.mktemp("readme")
    (d / "design.json").write_text(design_to_json(*thesis_baseline()))
    hours = np.arange(24 * 14)
    speed = 6.0 + 3.0 * np.sin(2 * np.pi * hours / 24.0) + 2.0 * np.sin(hours / 17.0)
    rows = ["timestamp,speed"] + [
        f"2024-01-{1 + h // 24:02d}T{h % 24:02d}:00,{s:.2f}" for h, s in zip(hours, speed)
    ]
    for name in ("mersing.csv", "site.csv"):
        (d / name).write_text("\n".join(rows) + "\n")
    return d


def _env() -> dict:
    env = dict(os.environ)
    env["PYTHONPATH"] = str(ROOT) + os.pathsep + env.get("PYTHONPATH", "")
    env.setdefault("OPENBLAS_NUM_THREADS", "1")
    return env


RUN_LINES = [ln for ln in _commands() if _runs(ln) and not ln.startswith(tuple(NOT_RUN))]


@pytest.mark.slow
@pytest.mark.parametrize("line", RUN_LINES)
def test_readme_command_runs(line, example_dir):
    handled = "||" in line  # the line shows an error on purpose and handles the exit code
    cmd = line.split("||", 1)[0].strip()
    for prefix in CLI_PREFIXES:
        if cmd.startswith(prefix):
            argv = shlex.split(cmd[len(prefix):])
    proc = subprocess.run(
        [sys.executable, "-m", "aerostat_core", *argv], cwd=example_dir, env=_env(),
        capture_output=True, text=True, timeout=600,
    )
    assert "Traceback" not in proc.stderr, proc.stderr[-3000:]
    if handled:
        assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    else:
        assert proc.returncode == 0, proc.stderr[-3000:]
    for token in argv:  # the outputs the line asks for were written
        if token.endswith((".html", ".stl", ".dxf", ".svg")) or token == "out.csv":
            assert (example_dir / token).stat().st_size > 0, token


@pytest.mark.slow
@pytest.mark.parametrize("k", range(len(_blocks("python"))))
def test_readme_python_snippet_runs(k):
    code = _blocks("python")[k]
    proc = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=_env(),
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]


def test_the_dynamics_import_of_the_readme_gives_the_functions():
    """``from aerostat_core.dynamics import simulate`` (and ``linearize``) are the functions,
    also after their modules of the same names were imported."""
    import importlib

    importlib.import_module("aerostat_core.dynamics.simulate")
    importlib.import_module("aerostat_core.dynamics.linearize")
    from aerostat_core.dynamics import linearize, simulate

    assert callable(simulate) and simulate.__name__ == "simulate"
    assert callable(linearize) and linearize.__name__ == "linearize"
    assert any("from aerostat_core.dynamics import" in b and "simulate" in b
               for b in _blocks("python"))
