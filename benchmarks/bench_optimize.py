"""Speed of the optimiser and the sensitivity analysis: prints medians (no pass/fail).

Run from the repository root: ``.venv/bin/python -m benchmarks.bench_optimize``
(``python -m benchmarks.bench_optimize --repeats 3`` for a quicker look).
Targets (issue #4, thesis preset, "normal" setting): SLSQP <= 1 s, surrogate <= 3 s, particle
swarm <= 5 s; a 20 x 20 sensitivity map <= 2 s. Timings include every nested V*(x) sizing; the
first call of each solver (imports) is a warm-up and is not counted.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

from aerostat_core import thesis_baseline  # noqa: E402
from aerostat_core.optimize import (  # noqa: E402
    OptimizationProblem,
    agreement,
    pareto_front,
    solve,
)
from aerostat_core.studies.sensitivity import one_at_a_time, two_variable_map  # noqa: E402


def median_time(fn, repeats: int) -> tuple[float, object]:
    """Median wall time [s] of ``fn()`` over ``repeats`` calls after one warm-up, and the last
    return value. The median process CPU time of the same calls goes to ``median_time.cpu``
    (single-threaded work: close to the wall time on an idle machine, and much less affected
    when other jobs share the cores)."""
    out = fn()
    wall, cpu = [], []
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    median_time.cpu = statistics.median(cpu)
    return statistics.median(wall), out


def main() -> None:
    """Time the three solvers, the Pareto front and the sensitivity sweeps on the thesis preset."""
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--repeats", type=int, default=5)
    args = ap.parse_args()
    n = max(args.repeats, 1)
    req, cfg = thesis_baseline()
    problem = OptimizationProblem(req, cfg)
    print(
        f"machine: {platform.machine()}, {os.cpu_count()} cores, "
        f"Python {platform.python_version()}; thesis preset, blow-by limit "
        f"{req.blow_by_limit:g} m at {req.design_wind:g} m/s"
    )
    targets = {"slsqp": 1.0, "surrogate": 3.0, "pso": 5.0}
    for setting in ("normal", "quick"):
        results = []
        for name in ("slsqp", "surrogate", "pso"):
            t, r = median_time(
                lambda name=name, setting=setting: solve(problem, name, setting, seed=0), n
            )
            results.append(r)
            tgt = f" (target <= {targets[name]:g} s)" if setting == "normal" else ""
            print(
                f"{setting:6s} {r.label:24s} median {t:6.2f} s (CPU {median_time.cpu:5.2f} s)"
                f"{tgt}; {r.n_evaluations:5d} "
                f"evaluations in {r.n_batches:3d} batches; mass {r.objective:.3f} kg, "
                f"V {r.design['volume_m3']:.1f} m3"
            )
        print(
            f"{setting:6s} spread of the optimum mass between solvers: "
            f"{100 * agreement(results):.3f} % (must be < 1 %)"
        )
    t, pf = median_time(lambda: pareto_front(req, cfg), n)
    print(
        f"Pareto front, {pf.limits.size} limits (epsilon-constraint): median {t:.2f} s (CPU {median_time.cpu:.2f} s), "
        f"{pf.n_evaluations} evaluations"
    )
    t, _ = median_time(lambda: two_variable_map(req, cfg, n=20, resize=False), n)
    print(f"20 x 20 sensitivity map, volume held:  median {t:.3f} s (CPU {median_time.cpu:.3f} s)")
    t, _ = median_time(lambda: two_variable_map(req, cfg, n=20, resize=True), n)
    print(
        f"20 x 20 sensitivity map, re-sized:     median {t:.3f} s (CPU {median_time.cpu:.3f} s) "
        "(target <= 2 s)"
    )
    t, _ = median_time(lambda: one_at_a_time(req, cfg, n_points=21, resize=True), n)
    print(f"OFAT sweeps 3 x 21 points, re-sized:   median {t:.3f} s (CPU {median_time.cpu:.3f} s)")


if __name__ == "__main__":
    main()
