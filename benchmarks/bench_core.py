"""Speed of the core engine: CPU and wall medians of each line, with its target and a verdict.

Run from the repository root: ``.venv/bin/python -m benchmarks.bench_core``.

Every timed line prints the median process CPU time (``time.process_time``) and the median wall
time of the same calls, its target, and PASS or MISS. The verdict is the CPU median's: on a
shared machine the wall time also counts the time the process waited for a core (run ``uptime``
beside it); on a quiet machine the two agree. Targets: a full design at a given volume
(21-point sweep and tether profiles) <= 5 ms; sizing with the full constraint table (thesis
rules) <= 50 ms; sizing of the default design (10 kg at 300 m, practice rules, exact search)
<= 20 ms (issue #22 item 9) and ``design()`` of each class's line <= 20 ms (issue #23 item 7);
the batch constraint table >= 10,000 designs/s; batch sizing >= 1,000 designs/s in every class.
Figures measured on this project's 2-core machine are in the README ("Speed").
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


def medians(fn, repeats: int) -> tuple[float, float]:
    """(CPU, wall) medians of ``fn()`` over ``repeats`` calls after one warm-up [s]: both clocks
    read around the same calls."""
    fn()  # warm up
    cpu, wall = [], []
    for _ in range(repeats):
        c0, w0 = time.process_time(), time.perf_counter()
        fn()
        w1, c1 = time.perf_counter(), time.process_time()
        cpu.append(c1 - c0)
        wall.append(w1 - w0)
    return statistics.median(cpu), statistics.median(wall)


def verdict(ok: bool) -> str:
    return "PASS" if ok else "MISS"


def line_ms(label: str, fn, repeats: int, target_ms: float | None = None, note: str = "") -> float:
    """Print ``label``'s CPU and wall medians [ms], its target and verdict; returns the CPU
    median [s]."""
    cpu, wall = medians(fn, repeats)
    tail = ""
    if target_ms is not None:
        tail = f" (target <= {target_ms:g} ms): {verdict(cpu * 1e3 <= target_ms)}"
    print(f"{label:58s} CPU {cpu * 1e3:7.2f} ms, wall {wall * 1e3:7.2f} ms{tail}{note}")
    return cpu


def line_rate(label: str, fn, repeats: int, count: int, target: float | None = None,
              note: str = "") -> float:
    """Print the throughput of ``fn()`` (``count`` designs a call) from its CPU and wall
    medians [designs/s], its target and verdict; returns the CPU rate."""
    cpu, wall = medians(fn, repeats)
    tail = ""
    if target is not None:
        tail = f" (target >= {target:,.0f}/s): {verdict(count / cpu >= target)}"
    print(f"{label:58s} CPU {count / cpu:9,.0f}/s, wall {count / wall:9,.0f}/s "
          f"({wall * 1e3:.0f} ms){tail}{note}")
    return count / cpu


def marches(fn) -> int:
    """Number of tether marches ``fn()`` runs (each is one call of the compiled Heun kernel
    over the batch: the cost of a sheared-wind height pass)."""
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


def table_calls(fn) -> str:
    """Constraint-table evaluations that ``fn()`` runs (the sizing's, the selection's): whole
    tables, and rounds of the root finder that evaluate only the rows needing no wind (a third
    of the cost). A whole table costs about the same at a few volumes as at 28. The selection's
    check of its last hull with the chosen items' strengths re-reads the table from the sized
    state's trim and tether (no solve): counted apart."""
    from aerostat_core.model import selection, sizing

    count = [0, 0, 0]
    plain_state, plain_table, plain_rows = sizing._state, selection._table, sizing._StaticRows

    def state(*args, **kwargs):
        count[0] += 1
        return plain_state(*args, **kwargs)

    def table(*args, **kwargs):
        count[2] += 1
        return plain_table(*args, **kwargs)

    class Rows(plain_rows):
        def __init__(self, *args, **kwargs):
            count[1] += 1
            super().__init__(*args, **kwargs)

    sizing._state, selection._table, sizing._StaticRows = state, table, Rows
    try:
        fn()
    finally:
        sizing._state, selection._table, sizing._StaticRows = plain_state, plain_table, plain_rows
    reread = f" + {count[2]} strength re-read" if count[2] else ""
    return f"{count[0]} whole + {count[1]} static-row{reread}"


def main() -> None:
    req, cfg = thesis_baseline()
    sized_cfg = cfg.with_design_variables(volume=None)
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}, load average "
          f"{', '.join(f'{x:.2f}' for x in os.getloadavg())}")
    line_ms("design (given volume, 21-point sweep + tether profiles):", lambda: design(req, cfg),
            200, 5.0)
    line_ms("design (sized volume, thesis rules, 21-point sweep):", lambda: design(req, sized_cfg),
            30)
    line_ms("sizing, full constraint table (thesis rules):", lambda: size_volume(req, sized_cfg),
            30, 50.0)
    practice = Requirement(payload_mass=10, altitude=300)
    practice_cfg = rules_configuration("practice")
    line_ms("sizing, default design (practice, 10 kg at 300 m), exact:",
            lambda: size_volume(practice, practice_cfg), 30, 20.0)
    line_ms("design(Requirement(10 kg, 300 m)), practice rules:", lambda: design(practice), 30,
            20.0)
    sheared = replace(rules_configuration("practice"), wind_profile=WindProfile("power"))
    line_ms("design(), practice rules, power-law wind (height passes):",
            lambda: design(practice, sheared), 20)
    log_wind = replace(sheared, wind_profile=WindProfile("log"))
    print(f"  tether marches per design: uniform wind {marches(lambda: design(practice))}, "
          f"power-law wind {marches(lambda: design(practice, sheared))}, "
          f"log wind {marches(lambda: design(practice, log_wind))} (load-independent)")
    print(f"  moment-kernel evaluations per trim: {kernel_calls_per_trim(lambda: design(practice)):.1f}"
          " (grid, warm start, check, slope; load-independent)")
    print(f"  constraint-table evaluations: sizing of the default design "
          f"{table_calls(lambda: size_volume(practice, practice_cfg))}, its design() "
          f"{table_calls(lambda: design(practice))} (load-independent)")
    rng = np.random.default_rng(0)
    n = 10_000
    f = rng.uniform(2.5, 4.5, n)
    dsf = rng.uniform(-50, 100, n)
    pos = rng.uniform(0.6, 0.75, n)
    vol = rng.uniform(80, 300, n)

    def batch():
        af = build_airframe(req, cfg, vol, f, dsf, pos)
        return evaluate(req, cfg, af, req.design_wind)

    line_rate(f"batch trim + tether of {n} designs at the design wind:", batch, 7, n)

    def table():
        return constraint_state(req, cfg, build_airframe(req, cfg, vol, f, dsf, pos))

    line_rate(f"batch constraint table of {n} designs (2 winds):", table, 7, n, 10_000)
    m = 200
    line_rate(f"batch sizing of {m} designs (thesis rules):",
              lambda: size_volume(req, sized_cfg, f[:m], dsf[:m], pos[:m]), 5, m, 1_000)
    # every class of thesis Table 2.3 (issue 23): the default design (materials chosen by load,
    # a few sizings where the lightest items do not carry the loads) and batch sizing with the
    # chosen items, tactical to strategic
    from aerostat_core.model.selection import select_materials
    from aerostat_core.studies.fielded import aerostat_class

    for payload, altitude, survival in ((10, 300, None), (227, 900, None), (1600, 4600, 36.0),
                                        (3200, 3000, 36.0)):
        r = Requirement(payload_mass=payload, altitude=altitude, survival_wind=survival)
        name = aerostat_class(payload, altitude)
        sel = select_materials(r, rules_configuration("practice"))
        line_ms(f"design(), {name} ({payload:g} kg, {altitude:g} m):", lambda r=r: design(r), 15,
                20.0, f"; {sel.sizings} sizing(s), {table_calls(lambda r=r: design(r))} table "
                f"evaluations, tether {sel.configuration.tether.name}")
        chosen = sel.configuration
        line_rate(f"  batch sizing of {m} {name} designs, chosen items:",
                  lambda r=r, c=chosen: size_volume(r, c, f[:m], dsf[:m], pos[:m]), 5, m, 1_000)
    print("verdicts are the CPU medians'; wall time also counts waiting for a core on a loaded "
          "machine")


if __name__ == "__main__":
    main()
