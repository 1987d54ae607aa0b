"""Speed of every hull shape: prints medians (no pass/fail; issue 12 targets).

Run from the repository root: ``.venv/bin/python -m benchmarks.bench_shapes``.
Targets: a full design of any shape (given volume, 21-point sweep and tether profiles) within
10 ms median; batch evaluation of at least 10 000 designs/s per shape. Also printed: the sized
design (volume found by the blow-by sizing) and the geometry exports.
"""

from __future__ import annotations

import os
import platform
from dataclasses import replace

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from aerostat_core import HullSpec, design, thesis_baseline  # noqa: E402
from aerostat_core.airframe import build_airframe  # noqa: E402
from aerostat_core.export import design_stl, gore_pattern  # noqa: E402
from aerostat_core.performance import evaluate  # noqa: E402
from aerostat_core.shape_comparison import thesis_shape_comparison  # noqa: E402
from aerostat_core.shapes import SHAPE_INFO  # noqa: E402
from benchmarks.bench_core import median_time  # noqa: E402


def main() -> None:
    req, cfg = thesis_baseline()
    print(
        f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}"
    )
    rng = np.random.default_rng(0)
    n = 10_000
    print(f"{'shape':10s} {'design':>9s} {'sized':>9s} {'batch':>14s}")
    for shape, info in SHAPE_INFO.items():
        given = replace(cfg, hull=HullSpec(shape=shape, volume=170.0))
        sized = replace(cfg, hull=HullSpec(shape=shape, volume=None))
        t_design = median_time(lambda c=given: design(req, c), 100)
        t_sized = median_time(lambda c=sized: design(req, c), 15)
        lo, hi = info.fineness_range
        f = rng.uniform(lo, hi, n)
        dsf = rng.uniform(-50, 100, n)
        pos = rng.uniform(0.6, 0.75, n)
        vol = rng.uniform(80, 300, n)

        def batch(c=given, f=f, dsf=dsf, pos=pos, vol=vol):
            return evaluate(req, c, build_airframe(req, c, vol, f, dsf, pos), req.design_wind)

        t_batch = median_time(batch, 5)
        print(
            f"{shape:10s} {t_design * 1e3:6.2f} ms {t_sized * 1e3:6.1f} ms "
            f"{n / t_batch:9,.0f} /s   (targets: design <= 10 ms, batch >= 10,000/s)"
        )
    d = design(req, cfg)
    t = median_time(lambda: design_stl(d), 5)
    print(f"STL of hull and fins:                 median {t * 1e3:.0f} ms")
    t = median_time(lambda: gore_pattern(d, 12), 20)
    print(f"gore and fin patterns (12 gores):     median {t * 1e3:.1f} ms")
    t = median_time(thesis_shape_comparison, 20)
    print(f"Table 2.2 / Figure 2.5 comparison:    median {t * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
