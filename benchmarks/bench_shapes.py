"""Speed of every hull shape: prints medians (no pass/fail; issue 12 targets).

Run from the repository root: ``.venv/bin/python -m benchmarks.bench_shapes``.
Targets: a full design of any shape within 10 ms median; batch evaluation of at least 10 000
designs/s per shape. Printed per shape: the design at a given volume (thesis baseline, 170 m3),
the sized design of the thesis baseline, the sized design of ``Requirement()`` with
``practice_configuration()`` (volume sized to the smallest hull meeting the whole constraint
table: the app's default), and two batch rates of 10 000 random designs: trim + tether at the
design wind, and the whole constraint table at the design and survival winds. Medians of wall
time and of process CPU time (the CPU time is the steadier figure on a shared machine).
Then the geometry exports.
"""

from __future__ import annotations

import os
import platform
from dataclasses import replace

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from aerostat_core import HullSpec, Requirement, design, thesis_baseline  # noqa: E402
from aerostat_core.geometry.shapes import SHAPE_INFO  # noqa: E402
from aerostat_core.model.airframe import build_airframe  # noqa: E402
from aerostat_core.model.constraints import constraint_state  # noqa: E402
from aerostat_core.model.performance import evaluate  # noqa: E402
from aerostat_core.model.presets import practice_configuration  # noqa: E402
from aerostat_core.output.export import design_stl, gore_pattern  # noqa: E402
from aerostat_core.studies.shape_comparison import thesis_shape_comparison  # noqa: E402
from benchmarks.bench_core import median_cpu, median_time  # noqa: E402


def main() -> None:
    req, cfg = thesis_baseline()
    print(
        f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}"
    )
    rng = np.random.default_rng(0)
    n = 10_000
    default_req, practice = Requirement(), practice_configuration()
    print("medians, wall / CPU [ms]; batch: designs per second (wall)")
    print(
        f"{'shape':10s} {'given 170 m3':>14s} {'sized thesis':>14s} {'sized default':>14s} "
        f"{'batch trim':>11s} {'batch table':>12s}"
    )
    for shape, info in SHAPE_INFO.items():
        given = replace(cfg, hull=HullSpec(shape=shape, volume=170.0))
        sized = replace(cfg, hull=HullSpec(shape=shape, volume=None))
        default = replace(practice, hull=HullSpec(shape=shape, volume=None))
        cells = []
        for r, c, k in ((req, given, 60), (req, sized, 25), (default_req, default, 25)):
            w = median_time(lambda r=r, c=c: design(r, c), k)
            u = median_cpu(lambda r=r, c=c: design(r, c), k)
            cells.append(f"{w * 1e3:6.1f}/{u * 1e3:5.1f}")
        lo, hi = info.fineness_range
        f = rng.uniform(lo, hi, n)
        dsf = rng.uniform(-50, 100, n)
        pos = rng.uniform(0.6, 0.75, n)
        vol = rng.uniform(80, 300, n)

        def batch(c=given, f=f, dsf=dsf, pos=pos, vol=vol):
            return evaluate(req, c, build_airframe(req, c, vol, f, dsf, pos), req.design_wind)

        def table(c=given, f=f, dsf=dsf, pos=pos, vol=vol):
            return constraint_state(req, c, build_airframe(req, c, vol, f, dsf, pos))

        t_batch = median_time(batch, 5)
        t_table = median_time(table, 3)
        print(
            f"{shape:10s} {cells[0]:>14s} {cells[1]:>14s} {cells[2]:>14s} "
            f"{n / t_batch:9,.0f}/s {n / t_table:9,.0f}/s"
        )
    print("targets: design <= 10 ms median, batch >= 10,000 designs/s per shape")
    d = design(req, cfg)
    t = median_time(lambda: design_stl(d), 5)
    print(f"STL of hull and fins:                 median {t * 1e3:.0f} ms")
    t = median_time(lambda: gore_pattern(d, 12), 20)
    print(f"gore and fin patterns (12 gores):     median {t * 1e3:.1f} ms")
    t = median_time(thesis_shape_comparison, 20)
    print(f"Table 2.2 / Figure 2.5 comparison:    median {t * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
