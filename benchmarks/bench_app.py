"""App speed as a user feels it: prints medians (no pass/fail).

Run from the repository root: ``.venv/bin/python -m benchmarks.bench_app``; set
``AEROSTAT_BENCH_ROOT`` to another checkout to time that one (the "before" figures).
Targets (issue 9): the first result visible within 3 s of opening the app in a fresh browser,
a result-tab switch within 1 s, the 3-D view within 2 s; (issue 3) a Design-page rerun
<= 300 ms on the server, click on "Update design" to the new result <= 1 s.

1. Server: Streamlit's AppTest runs the page script headless; ``at.run()`` after a new payload is
   submitted (no cache hit), and a rerun with inputs already seen (cache hit).
2. Browser (Debian chromium via Playwright, a live ``streamlit run app.py`` warmed by one visit):
   first result in a fresh browser context, rerun after "Update design", save a case, tab switch,
   3-D view. For the 3-D view it then re-renders the same figure in the page, a copy with the
   hull surface 4x coarser in each direction, and an empty 3-D scene, and prints the WebGL
   renderer: equal times mean the cost is the (software) WebGL scene, not the mesh.
3. Optimisation progress: the longest gap between two progress reports of each solver.
"""

from __future__ import annotations

import json
import os
import platform
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path
from typing import Any

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

ROOT = Path(os.environ.get("AEROSTAT_BENCH_ROOT", Path(__file__).resolve().parents[1]))
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

    def payload(v: float) -> None:  # a text box now, a number box in older versions
        box = [w for w in at.text_input if w.key == "in_payload"]
        box[0].set_value(f"{v:g}") if box else at.number_input(key="in_payload").set_value(v)

    for i in range(repeats):
        payload(11.0 + 0.37 * i)  # never seen before
        at.button(key="in_submit").click()
        t0 = time.perf_counter()
        at.run()
        fresh.append(time.perf_counter() - t0)
        assert not at.exception, at.exception
    for i in range(repeats):
        payload(11.0 + 0.37 * (i % 3))  # seen: cache hit
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


def _start_server() -> tuple[subprocess.Popen, str, Any]:
    port = _free_port()
    url = f"http://127.0.0.1:{port}"
    log = open(os.devnull, "wb")  # noqa: SIM115 - closed by _stop_server
    data = tempfile.mkdtemp(prefix="aerostat-bench-")
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
        ],  # fmt: skip
        cwd=ROOT,
        stdout=log,
        stderr=subprocess.STDOUT,
        stdin=subprocess.DEVNULL,
        env={**os.environ, "PYTHONUNBUFFERED": "1", "AEROSTAT_DATA_DIR": data},
    )
    _wait_healthy(url, proc)
    return proc, url, log


def _stop_server(proc: subprocess.Popen, log: Any) -> None:
    proc.terminate()
    try:
        proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
    log.close()


_APP = "[data-testid='stApp']"
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-dev-shm-usage",
    "--disable-background-networking",
    "--no-first-run",
]


def _settled(page: Any, timeout: float = 30000) -> None:
    page.wait_for_selector(f"{_APP}[data-test-script-state='notRunning']", timeout=timeout)
    page.wait_for_function(
        "() => document.querySelectorAll('[data-testid=\"stSkeleton\"]').length === 0",
        timeout=timeout,
        polling="raf",
    )


def _first_metric(page: Any, timeout: float = 60000) -> None:
    page.wait_for_function(
        f"() => ({_METRIC_JS})('Total mass [kg]') !== null", timeout=timeout, polling="raf"
    )


def bench_3d_cost(browser: Any) -> dict[str, Any]:
    """Where the 3-D view's time goes: render the Design page's 3-D figure with plotly.js (the
    copy shipped with the plotly package) in a blank page, a copy with the hull surface 4x
    coarser in each direction, and an empty 3-D scene; median of 5 renders each [ms], plus the
    WebGL renderer chromium uses."""
    import plotly

    sys.path.insert(0, str(ROOT))
    from aerostat_core import design, thesis_baseline
    from aerostat_core.output.report import design_report
    from app_ui import plots

    fig = plots.hull_3d_figure(design_report(design(*thesis_baseline())))
    coarse = json.loads(json.dumps(fig.to_dict(), default=_np_default))
    full = json.loads(json.dumps(fig.to_dict(), default=_np_default))
    verts = 0
    for t in coarse["data"]:
        if t.get("type") == "surface":
            for k in ("x", "y", "z", "surfacecolor"):
                if k in t:
                    t[k] = [row[::4] for row in _rows(t[k])[::4]]
    for t in full["data"]:
        if t.get("type") == "surface":
            verts += len(_rows(t["x"])) * len(_rows(t["x"])[0])
        elif t.get("type") == "mesh3d":
            verts += len(t["x"])
    empty = {"data": [{"type": "scatter3d", "x": [0], "y": [0], "z": [0]}], "layout": {}}
    js = (Path(plotly.__file__).parent / "package_data" / "plotly.min.js").read_text()
    page = browser.new_page(viewport={"width": 1000, "height": 700})
    page.set_content("<div id='g' style='width:900px;height:600px'></div>")
    page.add_script_tag(content=js)
    timing = """async (fig) => {
      const t = [];
      for (let k = 0; k < 5; k++) {
        const t0 = performance.now();
        await Plotly.newPlot('g', fig.data, fig.layout);
        await new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)));
        t.push(performance.now() - t0);
        Plotly.purge('g');
      }
      t.sort((a, b) => a - b);
      return t[2];
    }"""
    renderer = page.evaluate(
        """() => { const gl = document.createElement('canvas').getContext('webgl');
        if (!gl) return 'no WebGL';
        const d = gl.getExtension('WEBGL_debug_renderer_info');
        return d ? gl.getParameter(d.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER); }"""
    )
    out = {
        "traces": len(full["data"]),
        "has_surface": any(t.get("type") == "surface" for t in full["data"]),
        "renderer": renderer,
        "verts": verts,
        "bytes": len(json.dumps(full)),
        "full": page.evaluate(timing, full),
        "coarse": page.evaluate(timing, coarse),
        "empty": page.evaluate(timing, empty),
    }
    page.close()
    return out


def _rows(v: Any) -> list:
    """A 2-D array of a plotly trace as nested lists (plain lists, or plotly's typed arrays)."""
    if isinstance(v, dict) and "bdata" in v:
        import base64

        import numpy as np

        arr = np.frombuffer(base64.b64decode(v["bdata"]), dtype=np.dtype(v["dtype"]))
        shape = v.get("shape")
        if isinstance(shape, str):
            shape = tuple(int(n) for n in shape.split(","))
        return arr.reshape(shape).tolist()
    return [list(r) for r in v]


def _np_default(o: Any) -> Any:
    import numpy as np

    if isinstance(o, np.ndarray):
        return o.tolist()
    if isinstance(o, np.generic):
        return o.item()
    raise TypeError(type(o))


def bench_browser(repeats: int = 5) -> dict[str, list[float]] | None:
    """Browser timings [s] per step (see the module docstring); None without chromium."""
    if not CHROMIUM.is_file():
        print(f"browser: skipped ({CHROMIUM} not found; apt-get install chromium)")
        return None
    from playwright.sync_api import sync_playwright

    proc, url, log = _start_server()
    out: dict[str, list] = {k: [] for k in ("first", "rerun", "save", "tab", "3d", "webgl")}
    try:
        with sync_playwright() as pw:
            browser = pw.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
            warm = browser.new_page()  # the server's imports and caches warm, as in use
            warm.goto(url)
            _first_metric(warm)
            warm.close()
            for i in range(repeats):
                ctx = browser.new_context(viewport={"width": 1400, "height": 900})
                page = ctx.new_page()
                t0 = time.perf_counter()
                page.goto(url)
                _first_metric(page)
                out["first"].append(time.perf_counter() - t0)
                _settled(page)
                # rerun after a new input
                box = page.get_by_label("Payload mass [kg]", exact=True)
                before = page.evaluate(_METRIC_JS, "Total mass [kg]")
                box.fill(f"{12.0 + 1.13 * i:.2f}")
                box.press("Tab")
                t0 = time.perf_counter()
                page.get_by_role("button", name="Update design").first.click()
                page.wait_for_function(
                    f"(old) => {{ const v = ({_METRIC_JS})('Total mass [kg]'); "
                    "return v !== null && v !== old; }",
                    arg=before,
                    timeout=30000,
                    polling="raf",
                )
                out["rerun"].append(time.perf_counter() - t0)
                _settled(page)
                # save a case
                page.get_by_role("textbox", name="Save the current design as a case").fill(
                    f"bench {i}"
                )
                t0 = time.perf_counter()
                page.get_by_role("button", name="Save case").click()
                page.get_by_text(f"bench {i}”").first.wait_for(timeout=30000)
                out["save"].append(time.perf_counter() - t0)
                _settled(page)
                # tab switch: Mass (table + chart) then back to Geometry
                t0 = time.perf_counter()
                page.get_by_role("tab", name="Mass").click()
                page.locator(".js-plotly-plot .main-svg").filter(visible=True).first.wait_for(
                    timeout=30000
                )
                out["tab"].append(time.perf_counter() - t0)
                _settled(page)
                # 3-D view: click to the WebGL scene drawn
                t0 = time.perf_counter()
                page.get_by_role("tab", name="3-D view").click()
                page.locator(".js-plotly-plot .gl-container canvas").filter(
                    visible=True
                ).first.wait_for(timeout=60000)
                page.wait_for_function(
                    "() => [...document.querySelectorAll('.js-plotly-plot')].some("
                    "d => d._fullLayout && d._fullLayout.scene && d._fullLayout.scene._scene)",
                    timeout=60000,
                    polling="raf",
                )
                out["3d"].append(time.perf_counter() - t0)
                ctx.close()
            out["webgl"].append(bench_3d_cost(browser))
            browser.close()
    finally:
        _stop_server(proc, log)
    return out


def bench_progress() -> None:
    """Longest gap between optimisation progress reports, per solver (quick and normal)."""
    sys.path.insert(0, str(ROOT))
    try:
        from aerostat_core import thesis_baseline
        from aerostat_core.model.io import inputs_to_dict
        from aerostat_core.optimize import DEFAULT_BOUNDS, OptimizationProblem, solve
    except ImportError as exc:
        print(f"optimisation progress: skipped ({exc})")
        return
    inputs = inputs_to_dict(*thesis_baseline())
    json.dumps(inputs)
    for solver in ("slsqp", "surrogate", "pso"):
        for level in ("quick", "normal"):
            stamps = [time.perf_counter()]
            p = OptimizationProblem(*thesis_baseline(), DEFAULT_BOUNDS)
            solve(
                p, solver, level, 0, progress=lambda f, t, s=stamps: s.append(time.perf_counter())
            )
            gaps = [b - a for a, b in zip(stamps, stamps[1:])]
            print(
                f"optimisation progress, {solver:9s} {level:6s}: {len(gaps):3d} reports, "
                f"longest gap {max(gaps) * 1e3:5.0f} ms (first report included), "
                f"run {stamps[-1] - stamps[0]:.2f} s"
            )


def main() -> None:
    print(
        f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}"
    )
    print(f"app: {APP}")
    fresh, cached = bench_server()
    print(f"server rerun after an input change (new inputs):  {_ms(fresh)}  target <= 300 ms")
    print(f"server rerun with inputs seen before (cache hit): {_ms(cached)}")
    out = bench_browser()
    if out:
        print(
            f"browser: fresh browser -> first result visible: {_ms(out['first'])}  target <= 3000 ms"
        )
        print(
            f"browser: Update design -> new metrics visible:  {_ms(out['rerun'])}  target <= 1000 ms"
        )
        print(f"browser: Save case -> confirmation visible:     {_ms(out['save'])}")
        print(
            f"browser: tab switch (Mass) -> chart drawn:      {_ms(out['tab'])}  target <= 1000 ms"
        )
        print(
            f"browser: 3-D view tab -> WebGL scene drawn:     {_ms(out['3d'])}  target <= 2000 ms"
        )
        for w in out["webgl"]:
            coarse = (
                f"4x coarser surface {w['coarse']:.0f} ms, "
                if w["coarse"] != w["full"] and w.get("has_surface")
                else ""
            )
            print(
                f"3-D cost (plotly.js alone, median of 5): the hull figure {w['full']:.0f} ms "
                f"({w['traces']} traces, {w['verts']} vertices, {w['bytes'] / 1e3:.0f} kB JSON), "
                f"{coarse}an empty 3-D scene {w['empty']:.0f} ms; WebGL renderer: {w['renderer']}"
            )
    bench_progress()


if __name__ == "__main__":
    main()
