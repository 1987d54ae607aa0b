"""Speed of the Design page: prints medians (no pass/fail).

Run from the repository root: ``.venv/bin/python -m benchmarks.bench_app``.
Targets (issue #3): server time of a Design-page rerun after an input change <= 300 ms;
in the browser, click on "Update design" to the new result visible <= 1 s.

1. Server: Streamlit's AppTest runs the page script headless; we time ``at.run()`` after a new
   payload value is submitted (a new value every time, so the engine and the plots are recomputed:
   no cache hit), and, for comparison, a rerun with inputs already seen (cache hit).
2. Browser: a live ``streamlit run app.py`` and Debian chromium (Playwright); we time from the
   click on "Update design" to (a) the "Total mass" metric showing the new value and (b) the
   script run finished with every chart rendered. Skipped when /usr/bin/chromium is missing.
"""

from __future__ import annotations

import os
import platform
import socket
import statistics
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

ROOT = Path(__file__).resolve().parents[1]
APP = ROOT / "app.py"
CHROMIUM = Path(os.environ.get("AEROSTAT_CHROMIUM", "/usr/bin/chromium"))


def _ms(seconds: list[float]) -> str:
    return (
        f"median {statistics.median(seconds) * 1e3:6.0f} ms  "
        f"(min {min(seconds) * 1e3:.0f}, max {max(seconds) * 1e3:.0f}, n = {len(seconds)})"
    )


# --- 1. server rerun with AppTest -------------------------------------------------------------


def bench_server(repeats: int = 11) -> tuple[list[float], list[float]]:
    from streamlit.testing.v1 import AppTest

    at = AppTest.from_file(str(APP), default_timeout=60)
    at.run()
    assert not at.exception, at.exception
    fresh, cached = [], []
    for i in range(repeats):
        at.number_input(key="in_payload").set_value(11.0 + 0.37 * i)  # never seen before
        at.button(key="in_submit").click()
        t0 = time.perf_counter()
        at.run()
        fresh.append(time.perf_counter() - t0)
        assert not at.exception, at.exception
    for i in range(repeats):
        at.number_input(key="in_payload").set_value(11.0 + 0.37 * (i % 3))  # seen: cache hit
        at.button(key="in_submit").click()
        t0 = time.perf_counter()
        at.run()
        cached.append(time.perf_counter() - t0)
    return fresh, cached


# --- 2. browser: click to visible result ---------------------------------------------------------


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _wait_healthy(url: str, proc: subprocess.Popen, timeout: float = 60.0) -> None:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if proc.poll() is not None:
            raise RuntimeError(f"streamlit exited with code {proc.returncode}")
        try:
            with urllib.request.urlopen(f"{url}/_stcore/health", timeout=2) as r:
                if r.read() == b"ok":
                    return
        except OSError:
            pass
        time.sleep(0.2)
    raise RuntimeError("streamlit did not become healthy")


_METRIC_JS = """(label) => {
  for (const m of document.querySelectorAll('[data-testid="stMetric"]')) {
    const l = m.querySelector('[data-testid="stMetricLabel"]');
    if (l && l.innerText.trim() === label) {
      return m.querySelector('[data-testid="stMetricValue"]').innerText.trim();
    }
  }
  return null;
}"""


def bench_browser(repeats: int = 6, tab: str | None = None) -> tuple[list, list] | None:
    """Medians of click -> metrics visible and click -> rerun finished; ``tab`` is the result
    tab left open while changing the inputs (None: the default, Geometry)."""
    if not CHROMIUM.is_file():
        print(f"browser: skipped ({CHROMIUM} not found; apt-get install chromium)")
        return None
    from playwright.sync_api import sync_playwright

    port = _free_port()
    url = f"http://127.0.0.1:{port}"
    log = open(os.devnull, "wb")  # noqa: SIM115 - closed in finally
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "streamlit",
            "run",
            str(APP),
            "--server.address",
            "127.0.0.1",
            "--server.port",
            str(port),
            "--server.headless",
            "true",
            "--browser.gatherUsageStats",
            "false",
            "--server.fileWatcherType",
            "none",
        ],
        cwd=ROOT,
        stdout=log,
        stderr=subprocess.STDOUT,
        stdin=subprocess.DEVNULL,
        env={**os.environ, "PYTHONUNBUFFERED": "1"},
    )
    visible, finished = [], []
    try:
        _wait_healthy(url, proc)
        with sync_playwright() as pw:
            browser = pw.chromium.launch(
                executable_path=str(CHROMIUM),
                args=[
                    "--no-sandbox",
                    "--disable-gpu",
                    "--disable-dev-shm-usage",
                    "--disable-background-networking",
                    "--no-first-run",
                ],
            )
            page = browser.new_page(viewport={"width": 1400, "height": 1000})
            page.goto(url)
            app = "[data-testid='stApp']"
            page.wait_for_selector(f"{app}[data-test-script-state='notRunning']", timeout=60000)
            page.wait_for_function(
                f"() => ({_METRIC_JS})('Total mass [kg]') !== null", timeout=60000
            )
            if tab:
                page.get_by_role("tab", name=tab).click()
                page.wait_for_timeout(300)
                page.wait_for_selector(f"{app}[data-test-script-state='notRunning']", timeout=60000)
            box = page.get_by_role("textbox", name="Payload mass [kg]", exact=True)
            submit = page.get_by_role("button", name="Update design").first
            for i in range(repeats + 1):  # the first change warms the server's imports up
                before = page.evaluate(_METRIC_JS, "Total mass [kg]")
                box.fill(f"{12.0 + 1.13 * i:.2f}")
                box.press("Tab")
                t0 = time.perf_counter()
                submit.click()
                page.wait_for_function(
                    f"(old) => {{ const v = ({_METRIC_JS})('Total mass [kg]'); "
                    "return v !== null && v !== old; }",
                    arg=before,
                    timeout=30000,
                    polling="raf",
                )
                t1 = time.perf_counter()
                page.wait_for_selector(f"{app}[data-test-script-state='notRunning']", timeout=30000)
                page.wait_for_function(
                    "() => document.querySelectorAll('[data-testid=\"stSkeleton\"]').length === 0",
                    timeout=30000,
                    polling="raf",
                )
                t2 = time.perf_counter()
                if i > 0:
                    visible.append(t1 - t0)
                    finished.append(t2 - t0)
            browser.close()
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
        log.close()
    return visible, finished


def main() -> None:
    print(
        f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}"
    )
    fresh, cached = bench_server()
    print(f"server rerun after an input change (new inputs):  {_ms(fresh)}  target <= 300 ms")
    print(f"server rerun with inputs seen before (cache hit): {_ms(cached)}")
    for tab in (None, "Performance"):
        result = bench_browser(tab=tab)
        if not result:
            break
        visible, finished = result
        where = f"{tab} tab open" if tab else "default tab open"
        print(
            f"browser ({where}): click -> new metrics visible:   {_ms(visible)}  target <= 1000 ms"
        )
        print(f"browser ({where}): click -> rerun finished:        {_ms(finished)}")


if __name__ == "__main__":
    main()
