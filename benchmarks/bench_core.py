"""Speed of the core engine: prints medians (no pass/fail; see issue #2 for the targets).

Run from the repository root: ``.venv/bin/python -m benchmarks.bench_core``.
Targets: full design with a 21-point sweep
and tether profiles <= 5 ms; sizing with the full constraint table <= 50 ms; batch evaluation
(the whole constraint table at the design and survival winds) >= 10,000 designs per second.
"""

from __future__ import annotations

import os
import platform
import statistics
import time
from dataclasses import replace

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")


import numpy as np  # noqa: E402

from aerostat_core import design, size_volume, thesis_baseline  # noqa: E402
from aerostat_core.model.airframe import build_airframe  # noqa: E402
from aerostat_core.model.constraints import constraint_state  # noqa: E402
from aerostat_core.model.inputs import Requirement, WindProfile  # noqa: E402
from aerostat_core.model.performance import evaluate  # noqa: E402
from aerostat_core.model.presets import rules_configuration  # noqa: E402


def median_time(fn, repeats: int) -> float:
    fn()  # warm up
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def median_cpu(fn, repeats: int) -> float:
    """Median process CPU time of ``fn()`` [s]: steadier than wall time on a shared machine."""
    fn()
    times = []
    for _ in range(repeats):
        t0 = time.process_time()
        fn()
        times.append(time.process_time() - t0)
    return statistics.median(times)


def marches(fn) -> int:
    """Number of tether marches ``fn()`` runs (each is ~50 steps of ~25 numpy calls: the cost
    of a sheared-wind height pass)."""
    from aerostat_core.tether import statics as tether

    plain, count = tether.march, [0]

    def counted(*args, **kwargs):
        count[0] += 1
        return plain(*args, **kwargs)

    tether.march = counted
    try:
        fn()
    finally:
        tether.march = plain
    return count[0]


def kernel_calls_per_trim(fn) -> float:
    """Moment-kernel evaluations (grid products and calls) per trim while ``fn()`` runs, the
    weathervane slopes excluded (a figure the shared machine's load cannot move)."""
    from aerostat_core.model import performance, statics

    counts = {"trims": 0, "calls": 0}
    plain_trim, plain_call, plain_grid = (
        statics.trim_equilibrium, statics.MomentKernel.__call__, statics.MomentKernel.on_grid)
    active = [False]

    def trim(*args, **kwargs):
        counts["trims"] += 1
        active[0] = True
        try:
            return plain_trim(*args, **kwargs)
        finally:
            active[0] = False

    def counted(plain):
        def call(self, *args):
            counts["calls"] += active[0]
            return plain(self, *args)
        return call

    performance.trim_equilibrium = trim
    statics.MomentKernel.__call__ = counted(plain_call)
    statics.MomentKernel.on_grid = counted(plain_grid)
    try:
        fn()
    finally:
        performance.trim_equilibrium = plain_trim
        statics.MomentKernel.__call__, statics.MomentKernel.on_grid = plain_call, plain_grid
    return counts["calls"] / max(counts["trims"], 1)


def main() -> None:
    req, cfg = thesis_baseline()
    sized_cfg = cfg.with_design_variables(volume=None)
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}")
    t = median_time(lambda: design(req, cfg), 200)
    print(f"design (given volume, 21-point sweep + tether profiles): median {t * 1e3:.2f} ms "
          "(target <= 5 ms)")
    t = median_time(lambda: design(req, sized_cfg), 30)
    print(f"design (sized volume, 21-point sweep):                  median {t * 1e3:.2f} ms")
    t = median_time(lambda: size_volume(req, sized_cfg), 30)
    print(f"sizing, full constraint table (thesis rules):           median {t * 1e3:.2f} ms "
          "(target <= 50 ms)")
    practice = Requirement(payload_mass=10, altitude=300)
    t = median_time(lambda: design(practice), 30)
    print(f"design(Requirement(10 kg, 300 m)), practice rules:       median {t * 1e3:.2f} ms")
    sheared = replace(rules_configuration("practice"), wind_profile=WindProfile("power"))
    t = median_time(lambda: design(practice, sheared), 20)
    print(f"design(), practice rules, power-law wind (height passes): median {t * 1e3:.2f} ms")
    log_wind = replace(sheared, wind_profile=WindProfile("log"))
    print(f"  tether marches per design: uniform wind {marches(lambda: design(practice))}, "
          f"power-law wind {marches(lambda: design(practice, sheared))}, "
          f"log wind {marches(lambda: design(practice, log_wind))} (load-independent)")
    print(f"  moment-kernel evaluations per trim: {kernel_calls_per_trim(lambda: design(practice)):.1f}"
          " (grid, warm start, check, slope; load-independent)")
    for label, fn in (("design, given volume", lambda: design(req, cfg)),
                      ("design, sized (thesis rules)", lambda: design(req, sized_cfg)),
                      ("design(), sized (practice default)", lambda: design(practice)),
                      ("design(), power-law wind", lambda: design(practice, sheared))):
        print(f"  CPU time, {label + ':':36s} median {median_cpu(fn, 30) * 1e3:.2f} ms")
    rng = np.random.default_rng(0)
    n = 10_000
    f = rng.uniform(2.5, 4.5, n)
    dsf = rng.uniform(-50, 100, n)
    pos = rng.uniform(0.6, 0.75, n)
    vol = rng.uniform(80, 300, n)

    def batch():
        af = build_airframe(req, cfg, vol, f, dsf, pos)
        return evaluate(req, cfg, af, req.design_wind)

    t = median_time(batch, 7)
    print(f"batch trim + tether of {n} designs at the design wind:  median {t * 1e3:.0f} ms "
          f"= {n / t:,.0f} designs/s")

    def table():
        return constraint_state(req, cfg, build_airframe(req, cfg, vol, f, dsf, pos))

    t = median_time(table, 7)
    print(f"batch constraint table of {n} designs (2 winds):       median {t * 1e3:.0f} ms "
          f"= {n / t:,.0f} designs/s (target >= 10,000/s)")
    m = 200
    t = median_time(lambda: size_volume(req, sized_cfg, f[:m], dsf[:m], pos[:m]), 5)
    print(f"batch sizing of {m} designs:                           median {t * 1e3:.0f} ms "
          f"= {m / t:,.0f} sized designs/s")


if __name__ == "__main__":
    main()
