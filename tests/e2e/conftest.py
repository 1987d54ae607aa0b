"""Real-browser fixtures: a live ``streamlit run app.py`` server and Debian chromium via Playwright.

Recipe: docs/architecture.md §6. pytest-playwright (0.10) provides ``page``, ``context``
and ``browser``; this file overrides its ``browser_type_launch_args``, ``browser_context_args``
and ``base_url`` fixtures, so a test only needs::

    def test_something(app_page):          # app opened, first run finished
        ...

or ``page.goto("/")`` (relative to the live server) followed by ``wait_for_rerun(page)``.

Without /usr/bin/chromium the browser tests are skipped, unless AEROSTAT_REQUIRE_BROWSER=1
(set by .ci/run), which turns the skip into a failure: in CI they must run.
"""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest
from playwright.sync_api import Page

from tests.e2e.helpers import ARTIFACTS_DIR, REPO_ROOT, wait_for_rerun, watch_console_errors

CHROMIUM = Path(os.environ.get("AEROSTAT_CHROMIUM", "/usr/bin/chromium"))
APP_SCRIPT = REPO_ROOT / "app.py"
SERVER_START_TIMEOUT_S = 60.0
E2E_DIR = Path(__file__).resolve().parent

CHROMIUM_ARGS = [
    "--no-sandbox",  # we run as root in CI
    "--disable-gpu",
    "--disable-dev-shm-usage",
    # No network here but the package registries: stop chromium's own background traffic.
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--disable-quic",
]


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Mark every test under tests/e2e as ``e2e`` and run them after all the others.

    Last, because the slow browser start should not delay the fast feedback of the core tests,
    and because Playwright's sync API leaves its event loop registered as the running loop of the
    main thread until the session ends (a later ``asyncio.run`` would refuse to start).
    """
    browser_items, other_items = [], []
    for item in items:
        if item.path == E2E_DIR or E2E_DIR in item.path.parents:
            item.add_marker(pytest.mark.e2e)
            browser_items.append(item)
        else:
            other_items.append(item)
    items[:] = other_items + browser_items


def _browser_required() -> bool:
    return os.environ.get("AEROSTAT_REQUIRE_BROWSER", "").strip().lower() in {"1", "true", "yes"}


@pytest.fixture(scope="session")
def chromium_path() -> Path:
    """Debian's chromium; skip (or fail, in CI) when it is not installed."""
    if not (CHROMIUM.is_file() and os.access(CHROMIUM, os.X_OK)):
        message = (
            f"{CHROMIUM} not found: install it with `apt-get install -y chromium` "
            "(make test does so when run as root)"
        )
        if _browser_required():
            pytest.fail(f"AEROSTAT_REQUIRE_BROWSER=1 but {message}", pytrace=False)
        pytest.skip(message)
    return CHROMIUM


@pytest.fixture(scope="session")
def browser_type_launch_args(browser_type_launch_args: dict, chromium_path: Path) -> dict:
    """pytest-playwright's launch options, pointed at Debian chromium (no `playwright install`)."""
    return {
        **browser_type_launch_args,
        "executable_path": str(chromium_path),
        "args": [*browser_type_launch_args.get("args", []), *CHROMIUM_ARGS],
    }


@pytest.fixture(scope="session")
def browser_context_args(browser_context_args: dict) -> dict:
    return {
        **browser_context_args,
        "accept_downloads": True,
        "viewport": {"width": 1400, "height": 1000},
    }


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def _health(url: str) -> str:
    try:
        with urllib.request.urlopen(f"{url}/_stcore/health", timeout=2) as response:
            return response.read().decode(errors="replace").strip()
    except (urllib.error.URLError, ConnectionError, TimeoutError, OSError):
        return ""


@dataclass(frozen=True)
class StreamlitServer:
    url: str
    log_path: Path
    process: subprocess.Popen

    def log(self, tail_chars: int = 6000) -> str:
        try:
            return self.log_path.read_text(errors="replace")[-tail_chars:]
        except OSError:
            return "<no server log>"


def start_streamlit(log_path: Path, env_extra: dict[str, str] | None = None) -> StreamlitServer:
    """``streamlit run app.py`` on a free loopback port, answering /_stcore/health (fails the
    test with the server log otherwise). Stop it with :func:`stop_streamlit`."""
    if not APP_SCRIPT.is_file():
        pytest.fail(f"{APP_SCRIPT} does not exist", pytrace=False)
    port = _free_port()
    url = f"http://127.0.0.1:{port}"
    log_path.parent.mkdir(parents=True, exist_ok=True)
    env = {
        **os.environ,
        "OPENBLAS_NUM_THREADS": "1",
        "OMP_NUM_THREADS": "1",
        "PYTHONUNBUFFERED": "1",
        **(env_extra or {}),
    }
    cmd = [
        sys.executable, "-m", "streamlit", "run", str(APP_SCRIPT),
        "--server.address", "127.0.0.1",
        "--server.port", str(port),
        "--server.headless", "true",
        "--browser.gatherUsageStats", "false",
        "--server.fileWatcherType", "none",
    ]  # fmt: skip
    with log_path.open("ab") as log_file:
        process = subprocess.Popen(
            cmd,
            cwd=REPO_ROOT,
            env=env,
            stdin=subprocess.DEVNULL,
            stdout=log_file,
            stderr=subprocess.STDOUT,
        )
    server = StreamlitServer(url=url, log_path=log_path, process=process)
    deadline = time.monotonic() + SERVER_START_TIMEOUT_S
    while _health(url) != "ok":
        if process.poll() is not None:
            pytest.fail(
                f"streamlit exited with code {process.returncode} before answering "
                f"/_stcore/health. Server log:\n{server.log()}",
                pytrace=False,
            )
        if time.monotonic() > deadline:
            stop_streamlit(server)
            pytest.fail(
                f"streamlit did not answer 'ok' on {url}/_stcore/health within "
                f"{SERVER_START_TIMEOUT_S:.0f} s. Server log:\n{server.log()}",
                pytrace=False,
            )
        time.sleep(0.2)
    return server


def stop_streamlit(server: StreamlitServer) -> None:
    """Stop a server started by :func:`start_streamlit` (SIGTERM, then SIGKILL after 10 s)."""
    server.process.terminate()
    try:
        server.process.wait(timeout=10)
    except subprocess.TimeoutExpired:
        server.process.kill()
        server.process.wait(timeout=10)


@pytest.fixture(scope="session")
def streamlit_server() -> Iterator[StreamlitServer]:
    """``streamlit run app.py`` on a free loopback port, for the whole session."""
    worker = os.environ.get("PYTEST_XDIST_WORKER", "")  # one server per xdist worker
    log_path = ARTIFACTS_DIR / f"streamlit-server{'-' + worker if worker else ''}.log"
    if log_path.exists():
        log_path.unlink()
    server = start_streamlit(log_path)
    try:
        yield server
    finally:
        stop_streamlit(server)


@pytest.fixture(scope="session")
def base_url(streamlit_server: StreamlitServer) -> str:
    """Makes ``page.goto("/")`` open the live app (pytest-playwright passes it to the context)."""
    return streamlit_server.url


@pytest.fixture
def console_errors(page: Page) -> list[str]:
    """Console errors and uncaught page exceptions seen so far (icon/font failures left out)."""
    return watch_console_errors(page)


@pytest.fixture
def app_page(page: Page, console_errors: list[str]) -> Page:
    """A fresh session of the app, opened on its default page with the first run finished."""
    page.goto("/")
    wait_for_rerun(page)
    return page


@pytest.fixture
def thesis_page(app_page: Page) -> Page:
    """The app with the thesis baseline loaded by its button (the app opens on the practice
    default): for the tests that check pages against the thesis' 170 m3 baseline."""
    from playwright.sync_api import expect

    from tests.e2e.helpers import wait_for_rerun as _wait

    app_page.get_by_role("button", name="Load thesis baseline").click()
    _wait(app_page)
    volume = (
        app_page.get_by_test_id("headline")
        .filter(has=app_page.get_by_test_id("headline-label").get_by_text("Volume [m³]", exact=True))
        .get_by_test_id("headline-value")
    )
    expect(volume).to_have_text("170.0")
    return app_page
