"""Load test of the real app server on loopback: N concurrent sessions (light websocket clients
speaking Streamlit's own protocol, not browsers), each on its own workspace.

What it shows (issue 20, item 8):

* **no cross-talk**: every session's messages carry its own case name and no other session's;
* **bounded memory**: the server's resident memory after each round of updates (it must level
  off, not grow with every round);
* **update latency**: the time from a widget change (the Compare page's "Show only the rows that
  differ" toggle) to the end of the script run it triggers, median and 90th percentile.

Run: ``python -m benchmarks.bench_load [--sessions 12] [--rounds 4] [--updates 5]``. It starts
``streamlit run app.py`` on a free port with a throw-away SQLite data folder (or the database in
``--database-url``), seeds one workspace per session through the store, and exits non-zero on
cross-talk, a failed run, or memory that keeps growing in the last round.
"""

from __future__ import annotations

import argparse
import asyncio
import os
import secrets
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

import psutil
import websockets
from streamlit.proto.BackMsg_pb2 import BackMsg
from streamlit.proto.ForwardMsg_pb2 import ForwardMsg

from aerostat_core.output.report import thesis_gui_cases
from app_ui import store

ROOT = Path(__file__).resolve().parents[1]
TOGGLE_LABEL = "Show only the rows that differ"
#: Memory growth in the last round above which the run fails [MB].
MAX_LAST_ROUND_GROWTH_MB = 64.0


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_server(env_extra: dict[str, str]) -> tuple[subprocess.Popen, str]:
    port = _free_port()
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", **env_extra}
    cmd = [
        sys.executable, "-m", "streamlit", "run", str(ROOT / "app.py"),
        "--server.address", "127.0.0.1", "--server.port", str(port),
        "--server.headless", "true", "--browser.gatherUsageStats", "false",
        "--server.fileWatcherType", "none",
    ]  # fmt: skip
    proc = subprocess.Popen(
        cmd, cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        try:
            with urllib.request.urlopen(f"{url}/_stcore/health", timeout=2) as r:
                if r.read().strip() == b"ok":
                    return proc, url
        except OSError:
            time.sleep(0.3)
    proc.kill()
    raise SystemExit("the server did not start within 120 s")


class Session:
    """One light client: a websocket speaking BackMsg/ForwardMsg, on one workspace."""

    def __init__(self, url: str, token: str, case: str) -> None:
        self.ws_url = url.replace("http://", "ws://") + "/_stcore/stream"
        self.origin = url
        self.token, self.case = token, case
        self.received = bytearray()
        self.toggle_id: str | None = None
        self.toggle = False
        self.latencies: list[float] = []
        self.failures: list[str] = []

    async def _run_once(self, ws, widgets: list | None = None) -> float:
        msg = BackMsg()
        cs = msg.rerun_script
        cs.query_string = f"ws={self.token}"
        cs.page_name = "Compare"
        for w in widgets or []:
            cs.widget_states.widgets.append(w)
        started = time.perf_counter()
        await ws.send(msg.SerializeToString())
        while True:
            raw = await asyncio.wait_for(ws.recv(), timeout=120)
            fwd = ForwardMsg()
            fwd.ParseFromString(raw)
            kind = fwd.WhichOneof("type")
            if kind == "delta":
                self.received += raw
                el = fwd.delta.new_element
                if el.WhichOneof("type") == "checkbox" and el.checkbox.label == TOGGLE_LABEL:
                    self.toggle_id = el.checkbox.id
            elif kind == "script_finished":
                if fwd.script_finished == ForwardMsg.FINISHED_SUCCESSFULLY:
                    return time.perf_counter() - started
                if fwd.script_finished != ForwardMsg.FINISHED_EARLY_FOR_RERUN:
                    self.failures.append(f"run ended with status {fwd.script_finished}")
                    return time.perf_counter() - started

    async def run(self, updates: int) -> None:
        async with websockets.connect(
            self.ws_url,
            subprotocols=["streamlit"],
            origin=self.origin,
            max_size=None,
            open_timeout=60,
        ) as ws:
            await self._run_once(ws)  # the first run of the page
            for _ in range(updates):
                if self.toggle_id is None:
                    self.failures.append("no comparison toggle on the page")
                    return
                from streamlit.proto.WidgetStates_pb2 import WidgetState

                self.toggle = not self.toggle
                w = WidgetState(id=self.toggle_id, bool_value=self.toggle)
                self.latencies.append(await self._run_once(ws, [w]))


def seed(url: str, n: int) -> list[tuple[str, str]]:
    """One workspace per session, each with two cases (one named uniquely for the session)."""
    db = store.Store(url)
    gui = thesis_gui_cases()
    first, second = list(gui.values())[:2]
    out = []
    for i in range(n):
        token = store.new_token()
        case = f"session-{i}-{secrets.token_hex(4)}"
        db.add_cases(token, {case: first, f"{case} other": second})
        out.append((token, case))
    db.dispose()
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sessions", type=int, default=12)
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--updates", type=int, default=5, help="widget changes per session per round")
    ap.add_argument("--database-url", default="")
    args = ap.parse_args()

    tmp = tempfile.mkdtemp(prefix="aerostat-load-")
    if args.database_url:
        env, url = {"AEROSTAT_DATABASE_URL": args.database_url}, args.database_url
    else:
        env = {"AEROSTAT_DATA_DIR": tmp}
        url = f"sqlite:///{Path(tmp) / 'aerostat.sqlite3'}"
    proc, base = start_server(env)
    server = psutil.Process(proc.pid)
    failures: list[str] = []
    try:
        workspaces = seed(url, args.sessions)
        names = [case for _, case in workspaces]
        latencies: list[float] = []
        rss: list[float] = []
        print(f"{args.sessions} concurrent sessions, {args.rounds} rounds x {args.updates} updates")
        for r in range(args.rounds):
            sessions = [Session(base, token, case) for token, case in workspaces]
            t0 = time.perf_counter()

            async def go(sessions=sessions) -> None:
                await asyncio.gather(*(s.run(args.updates) for s in sessions))

            asyncio.run(go())
            wall = time.perf_counter() - t0
            for s in sessions:
                failures += [f"session {s.case}: {f}" for f in s.failures]
                if s.case.encode() not in s.received:
                    failures.append(f"session {s.case} never saw its own case")
                others = [n for n in names if n != s.case and n.encode() in s.received]
                if others:
                    failures.append(f"cross-talk: session {s.case} saw {others}")
                latencies += s.latencies
            mem = server.memory_info().rss / 2**20
            rss.append(mem)
            print(f"  round {r + 1}: {wall:6.1f} s wall, server RSS {mem:7.1f} MB")
        lat = sorted(latencies)
        if lat:
            p90 = lat[min(len(lat) - 1, int(0.9 * len(lat)))]
            print(
                f"update latency (widget change -> run finished), {len(lat)} updates: "
                f"median {statistics.median(lat) * 1000:.0f} ms, p90 {p90 * 1000:.0f} ms"
            )
        if len(rss) >= 2:
            growth = rss[-1] - rss[-2]
            print(f"server memory: last round {growth:+.1f} MB (peak {max(rss):.1f} MB)")
            if growth > MAX_LAST_ROUND_GROWTH_MB:
                failures.append(f"server memory still growing: {growth:+.1f} MB in the last round")
        print("cross-talk: none" if not any("cross-talk" in f for f in failures) else "")
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
