"""Speed of the dynamics (issue #5): prints medians (no pass/fail).

Run from the repository root: ``.venv/bin/python -m benchmarks.bench_dynamics`` (add ``--scipy``
to also time scipy's Radau/LSODA with the same compiled right-hand side, ``--repeats N``).

Targets: 300 s of the full model (hull + 20-segment tether) in moderate Dryden turbulence in at
most 3 s of wall time; the R3 step case (point aerostat, 32 segments, 300 s) at least 10x faster
than MoorDyn on the same machine with answers within 1 cm. MoorDyn runs only if the optional
``moordyn`` package is importable; otherwise the wall time quoted in docs/dynamics.md §4.1 is printed,
labelled as such.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from aerostat_core.dynamics import cases  # noqa: E402
from aerostat_core.dynamics.model import system_from_design  # noqa: E402
from aerostat_core.dynamics.moordyn_check import moordyn_available, run_point_case  # noqa: E402
from aerostat_core.dynamics.simulate import (  # noqa: E402
    SolverOptions,
    engine_guess,
    simulate,
    straight_state,
)
from aerostat_core.dynamics.wind import (  # noqa: E402
    DrydenTurbulence,
    Gust,
    SpeedSchedule,
    WindScenario,
)


def timed(fn, repeats: int):
    out = fn()  # warm-up (numba cache load / compile)
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--scipy", action="store_true", help="also time scipy Radau and LSODA")
    ap.add_argument("--no-moordyn", action="store_true", help="skip the live MoorDyn run")
    ap.add_argument("--thesis", action="store_true",
                    help="only print the thesis-comparison figures (gust, ramps, turbulence)")
    args = ap.parse_args()
    if args.thesis:
        thesis_comparison()
        return
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}")

    # ---- R3: point aerostat, 32 segments, 300 s, step 5 -> 10 m/s at 150 s ----------------
    system = cases.case_p_system(32)
    y0 = straight_state(system, cases.R3_TOP0)
    t0 = time.perf_counter()
    simulate(system, cases.r3_wind(), 1.0, initial_state=y0)
    print(f"first call (numba cache load or compile): {time.perf_counter() - t0:.2f} s")
    r3 = {}
    for rtol in (1e-5, 1e-6, 1e-7):
        opt = SolverOptions(rtol=rtol, atol_position=10 * rtol, atol_velocity=10 * rtol,
                            output_interval=0.05)
        t, res = timed(lambda opt=opt: simulate(system, cases.r3_wind(), 300.0, opt,
                                                initial_state=y0), args.repeats)
        r3[rtol] = (t, res)
        x = res.signal("x_C")
        print(f"R3 TR-BDF2 rtol={rtol:g}: median {t:.3f} s wall, {res.stats['steps']} steps; "
              f"peak x {x.max():.3f} m (ref {cases.R3['x_peak']}), final {x[-1]:.3f} m")
    if args.scipy:
        for method in ("Radau", "LSODA"):
            opt = SolverOptions(method=method, rtol=1e-6, atol_position=1e-5,
                                atol_velocity=1e-5, output_interval=0.05)
            t0 = time.perf_counter()
            res = simulate(system, cases.r3_wind(), 300.0, opt, initial_state=y0)
            dt = time.perf_counter() - t0
            print(f"R3 scipy {method} (numba RHS, banded FD Jacobian) rtol=1e-6: {dt:.2f} s wall "
                  f"(one run), {res.stats['rhs_calls']} RHS calls, peak x "
                  f"{res.signal('x_C').max():.3f} m")
    if moordyn_available() and not args.no_moordyn:
        sched = SpeedSchedule((0.0, 150.0, 151.0), (5.0, 5.0, 10.0))
        md = run_point_case(cases.case_p_point(), cases.case_p_tether(32), sched, 300.0,
                            cases.R3_TOP0, rho=cases.CASE_P_RHO, g=cases.CASE_P_G, dtm=2e-4)
        print(f"R3 MoorDyn 2.7.2 (RK2, dtM = 2e-4 s), measured here: {md['wall_time']:.2f} s wall "
              "(one run)")
        for rtol, (t, res) in r3.items():
            dx = np.max(np.abs(res.signal("x_C") - np.interp(res.t, md["t"], md["x"])))
            dz = np.max(np.abs(res.signal("z_C") - np.interp(res.t, md["t"], md["z"])))
            print(f"   vs TR-BDF2 rtol={rtol:g}: max |dx| {dx * 1e3:.1f} mm, max |dz| "
                  f"{dz * 1e3:.1f} mm, speed-up {md['wall_time'] / t:.0f}x")
    else:
        quoted = cases.MOORDYN_QUOTED_WALL_400S
        print(f"R3 MoorDyn: not run here. QUOTED reference (docs/dynamics.md §4.1, another 2-core "
              f"machine): {quoted:.0f} s for 400 s simulated, i.e. about {quoted * 0.75:.0f} s "
              f"for R3's 300 s; speed-up vs rtol=1e-6: {quoted * 0.75 / r3[1e-6][0]:.0f}x")

    # ---- full model: thesis design, 20 segments, 300 s of moderate turbulence ---------------
    design = cases.thesis_design()
    hull_sys = system_from_design(design, segments=20)
    guess = engine_guess(hull_sys, design, 10.0)
    turb = WindScenario(SpeedSchedule.constant(10.0),
                        turbulence=DrydenTurbulence.from_intensity("moderate", seed=1))
    t, res = timed(lambda: simulate(hull_sys, turb, 300.0, guess=guess), args.repeats)
    print(f"full model, 20 segments, 300 s moderate Dryden turbulence at 10 m/s: median {t:.3f} s "
          f"wall (target <= 3 s), {res.stats['steps']} steps, status: {res.message}")
    turb_l = WindScenario(SpeedSchedule.constant(10.0),
                          turbulence=DrydenTurbulence.from_intensity("light", seed=1))
    t, res = timed(lambda: simulate(hull_sys, turb_l, 300.0, guess=guess), args.repeats)
    print(f"full model, 20 segments, 300 s light turbulence: median {t:.3f} s wall")
    gust = WindScenario(SpeedSchedule.constant(10.0), gust=Gust(5.0, 0.0, 60.0, 20.0))
    t, res = timed(lambda: simulate(hull_sys, gust, 150.0, guess=guess), args.repeats)
    print(f"full model, 20 segments, 150 s 1-cos gust: median {t:.3f} s wall")


def thesis_comparison() -> None:
    """Responses of the thesis preset's optimised design (about 120 m3, 10 kg at 300 m) to the
    three thesis wind cases, with the parameters printed (the thesis' own are not known)."""
    from aerostat_core.dynamics.simulate import response_metrics

    d = cases.thesis_design()
    print(f"thesis design: V = {d.volume:.0f} m3, f = {float(d.airframe.hull.fineness_ratio):.2f}, "
          f"total mass {d.total_mass:.1f} kg, payload {d.requirement.payload_mass:g} kg, "
          f"tether {d.airframe.tether_length:g} m")
    for unsteady in (True, False):
        system = system_from_design(d, segments=20, unsteady_wind_inertia=unsteady)
        tag = "with" if unsteady else "without"
        print(f"--- {tag} unsteady-wind inertia (added mass x fluid acceleration + Froude-Krylov)")
        for name, sc, u0, t_ev, dur in (
            ("gust: 10 m/s + 1-cos 5 m/s longitudinal, d_m = 60 m (6 s rise), at t = 20 s",
             WindScenario(SpeedSchedule.constant(10.0), gust=Gust(5.0, 0.0, 60.0, 20.0)),
             10.0, 20.0, 150.0),
            ("varying: 5 -> 10 m/s, 5 s ramp at t = 20 s",
             WindScenario(SpeedSchedule.step(5.0, 10.0, 20.0, 5.0)), 5.0, 20.0, 200.0),
        ):
            res = simulate(system, sc, dur, guess=engine_guess(system, d, u0))
            th = res.signal("theta")
            line = [f"  {name}: {res.message};"]
            for k in ("x_C", "theta"):
                m = response_metrics(res.t, res.signal(k), t_ev, 0.05)
                line.append(f"{k} settles (5 %) in {m.settling_time} s")
            line.append(f"pitch {th.min():.2f}..{th.max():.2f} deg (trim {th[0]:.2f}); "
                        f"peak v_x {np.max(np.abs(res.signal('vx'))):.2f} m/s")
            print(" ".join(line))
        for inten in ("light", "moderate", "severe"):
            for vertical in (True, False):
                sc = WindScenario(SpeedSchedule.constant(10.0),
                                  turbulence=DrydenTurbulence.from_intensity(
                                      inten, seed=1, vertical=vertical, fade_in=30.0))
                res = simulate(system, sc, 630.0, guess=engine_guess(system, d, 10.0))
                st = res.stats_table(t_from=30.0)
                txt = ", ".join(f"{k} RMS {st[k].std:.2f} / peak {st[k].peak:.2f}"
                                for k in ("vx", "vz", "theta"))
                print(f"  Dryden {inten:8s} (u{'+w' if vertical else ' only'}), 10 m/s, 600 s: "
                      f"{txt}  [{res.message}]")


if __name__ == "__main__":
    main()
