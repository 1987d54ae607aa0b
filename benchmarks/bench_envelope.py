"""Speed of the operating envelope, the Monte Carlo, the flyable time and the HTML report:
prints medians (no pass/fail).

Run from the repository root: ``.venv/bin/python -m benchmarks.bench_envelope [--repeats 5]
[--dask]``. Targets (issue #14): 10 000 envelope points <= 2 s, 10 000 Monte Carlo samples
<= 5 s. ``--dask`` also times the Monte Carlo on a 2-worker in-process LocalCluster (the
scale-out path; on this 2-core machine it shows the overhead, not a speed-up).
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from aerostat_core import Requirement, design  # noqa: E402
from aerostat_core.output.html_report import build_report  # noqa: E402
from aerostat_core.studies.envelope import operating_envelope  # noqa: E402
from aerostat_core.studies.site_wind import flyable_time  # noqa: E402
from aerostat_core.studies.uncertainty import monte_carlo  # noqa: E402


def median_time(fn, repeats: int) -> tuple[float, float, object]:
    """Median wall and CPU time [s] of ``fn()`` over ``repeats`` calls after one warm-up."""
    out = fn()
    wall, cpu = [], []
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    return statistics.median(wall), statistics.median(cpu), out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--dask", action="store_true")
    a = ap.parse_args()
    print(
        f"# {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
        f"python {platform.python_version()}, numpy {np.__version__}"
    )
    d = design(Requirement(payload_mass=10.0, altitude=300.0))
    wind, alt = np.linspace(0.0, 30.0, 100), np.linspace(50.0, 1000.0, 100)
    w, c, env = median_time(lambda: operating_envelope(d, wind, alt), a.repeats)
    print(
        f"envelope {env.points} points (100 winds x 100 altitudes): median {w:.3f} s wall, "
        f"{c:.3f} s CPU ({env.points / w:,.0f} points/s)"
    )
    w, c, env3 = median_time(
        lambda: operating_envelope(
            d, np.linspace(0, 30, 50), np.linspace(50, 1000, 20), [5.0, 10.0, 15.0, 20.0, 25.0]
        ),
        a.repeats,
    )
    print(
        f"envelope {env3.points} points (50 winds x 20 altitudes x 5 payloads): median "
        f"{w:.3f} s wall, {c:.3f} s CPU"
    )
    w, c, mc = median_time(lambda: monte_carlo(d, 10_000, seed=1), a.repeats)
    print(
        f"Monte Carlo 10000 samples x {mc.speeds.size} band winds + constraint table: median "
        f"{w:.3f} s wall, {c:.3f} s CPU ({10_000 / w:,.0f} samples/s)"
    )
    w, c, _ = median_time(lambda: flyable_time(d), a.repeats)
    print(f"flyable time (Weibull, 10 simulated years): median {w:.3f} s wall, {c:.3f} s CPU")
    w, c, _ = median_time(lambda: build_report(d), max(1, a.repeats // 2))
    print(
        f"HTML report (envelope, flyable, 2000-sample Monte Carlo, rule sets, validation): "
        f"median {w:.3f} s wall, {c:.3f} s CPU"
    )
    if a.dask:
        from aerostat_core.studies.scale import close_client, dask_client

        client = dask_client("local")
        try:
            w, c, _ = median_time(lambda: monte_carlo(d, 10_000, seed=1, client=client), a.repeats)
            print(
                f"Monte Carlo 10000 samples on a 2-worker LocalCluster (threads): median "
                f"{w:.3f} s wall ({10_000 / w:,.0f} samples/s)"
            )
        finally:
            close_client(client)


if __name__ == "__main__":
    main()
