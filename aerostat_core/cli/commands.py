"""Command-line subcommands ``envelope`` and ``report``, and ``design --monte-carlo N --seed S``
(registered by :mod:`aerostat_core.cli.entry`, which builds the requirement and configuration the same
way for every subcommand).

``python -m aerostat_core envelope [design options] [--wind-csv F | --weibull-k K --weibull-c C]
[--json]`` prints the envelope points (binding constraint and margin at each wind x altitude
[x payload]) and the flyable time; ``python -m aerostat_core report [design options] -o
report.html`` writes the HTML design report.
"""

from __future__ import annotations

import argparse
import json
import os
import stat
import sys
from pathlib import Path

import numpy as np

from aerostat_core.model.design import Design
from aerostat_core.model.inputs import Requirement


def add_design_options(d: argparse.ArgumentParser) -> None:
    """``--monte-carlo N``, ``--seed S`` and ``--dask SCHEDULER`` on the design parser (the
    envelope and report subcommands inherit them)."""
    d.add_argument(
        "--monte-carlo",
        type=int,
        metavar="N",
        help="Monte Carlo samples over the uncertain inputs (adds blow_by_p05_m, "
        "blow_by_p95_m, tension_p05_N, ... to --json)",
    )
    d.add_argument("--seed", type=int, default=0, help="Monte Carlo seed (default 0)")
    d.add_argument(
        "--dask",
        metavar="SCHEDULER",
        help="map the batch over a Dask cluster: 'local' (2 workers here) or a "
        "scheduler address tcp://host:8786 (needs pip install .[dask])",
    )


def add_subcommands(sub, design_parser: argparse.ArgumentParser) -> None:
    """The ``envelope`` and ``report`` subcommands, with every option of ``design``."""
    e = sub.add_parser(
        "envelope",
        parents=[design_parser],
        conflict_handler="resolve",
        help="operating envelope and flyable time of the sized aerostat",
    )
    e.add_argument("--winds", type=int, default=61, help="wind points (default 61)")
    e.add_argument(
        "--wind-top", type=float, help="largest envelope wind [m/s] (default 1.5 x survival wind)"
    )
    e.add_argument("--altitudes", type=int, default=21, help="altitude points (default 21)")
    e.add_argument(
        "--altitude-range",
        type=float,
        nargs=2,
        metavar=("LO", "HI"),
        help="altitude range [m] (default 0.25-2 x the design altitude)",
    )
    e.add_argument(
        "--payloads",
        type=float,
        nargs="+",
        metavar="KG",
        help="payload axis [kg] (default: the design payload only)",
    )
    _add_site_options(e)
    r = sub.add_parser(
        "report",
        parents=[design_parser],
        conflict_handler="resolve",
        help="write the self-contained HTML design report",
    )
    r.add_argument("-o", "--output", type=Path, required=True, help="HTML file to write")
    _add_site_options(r)


def _add_site_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--wind-csv", type=Path, help="hourly site wind CSV (timestamp, speed [m/s])")
    p.add_argument("--weibull-k", type=float, help="site Weibull shape k (default 2)")
    p.add_argument("--weibull-c", type=float, help="site Weibull scale c [m/s] (default 6)")
    p.add_argument(
        "--reference-height",
        type=float,
        default=10.0,
        help="height of the site wind data [m] (default 10)",
    )
    p.add_argument(
        "--shear-exponent",
        type=float,
        default=1.0 / 7.0,
        help="power-law shear exponent to the aerostat (default 1/7)",
    )
    p.add_argument(
        "--target-availability",
        type=float,
        default=0.95,
        help="share of time the aerostat must fly, for the implied design wind (default 0.95)",
    )


def read_capped(path: Path, cap: int, option: str, hint: str = "") -> bytes:
    """Read at most ``cap`` bytes of a regular file named by a CLI ``option`` (``/dev/zero``, a
    FIFO or a directory is refused); ``ValueError`` naming the option otherwise."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        raise ValueError(f"{option} {path}: {exc.strerror}") from None
    with os.fdopen(fd, "rb") as fh:
        if not stat.S_ISREG(os.fstat(fh.fileno()).st_mode):
            raise ValueError(f"{option} {path}: not a regular file")
        data = fh.read(cap + 1)
    if len(data) > cap:
        raise ValueError(f"{option} {path}: larger than {cap} bytes{hint}")
    return data


def site_from_args(args):
    """The site wind of the options: ``--wind-csv`` or a Weibull (defaults k 2, c 6 m/s)."""
    from aerostat_core.studies.site_wind import MAX_CSV_BYTES, WeibullSite, read_wind_csv

    if args.wind_csv is not None:
        if args.weibull_k is not None or args.weibull_c is not None:
            raise ValueError("give either --wind-csv or --weibull-k/--weibull-c, not both")
        data = read_capped(args.wind_csv, MAX_CSV_BYTES, "--wind-csv",
                           " (about 200 000 hourly rows)")
        try:
            return read_wind_csv(data, args.reference_height, args.shear_exponent)
        except ValueError as exc:
            raise ValueError(f"--wind-csv {args.wind_csv}: {exc}") from None
    kw = {}
    if args.weibull_k is not None:
        kw["shape"] = args.weibull_k
    if args.weibull_c is not None:
        kw["scale"] = args.weibull_c
    return WeibullSite(
        reference_height=args.reference_height, shear_exponent=args.shear_exponent, **kw
    )


def monte_carlo_summary(d: Design, args) -> dict:
    """The Monte Carlo keys for ``design --json`` (empty without ``--monte-carlo``)."""
    if not getattr(args, "monte_carlo", None):
        return {}
    from aerostat_core.studies.uncertainty import monte_carlo, rule_set_spread

    out = monte_carlo(d, args.monte_carlo, args.seed, client=args.dask).summary()
    # the same mission under every rule set, beside it (at most 2000 samples each)
    out["rule_sets"] = rule_set_spread(d.requirement, n=min(args.monte_carlo, 2000), seed=args.seed)
    return out


def _client(args):
    if not args.dask:
        return None
    from aerostat_core.studies.scale import dask_client

    return dask_client(args.dask)


def run(args, req: Requirement, cfg) -> int:
    """Run the ``envelope`` or ``report`` subcommand; exit code 0, or 2 with one line on bad
    input."""
    from aerostat_core.model.design import design

    client = None
    try:
        site = site_from_args(args)
        d = design(req, cfg)
        client = _client(args)
        if args.command == "envelope":
            return _envelope(args, d, site, client)
        return _report(args, req, d, site, client)
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    finally:
        if client is not None:
            from aerostat_core.studies.scale import close_client

            close_client(client)


def _envelope(args, d: Design, site, client) -> int:
    from aerostat_core.studies.envelope import default_axes, operating_envelope
    from aerostat_core.studies.site_wind import flyable_time

    for name, v, lo, hi in (
        ("--winds", args.winds, 2, 2001),
        ("--altitudes", args.altitudes, 1, 501),
    ):
        if not lo <= v <= hi:
            raise ValueError(f"{name} = {v} is outside the valid range [{lo}, {hi}]")
    w0, h0 = default_axes(d, args.winds, args.altitudes)
    wind = w0 if args.wind_top is None else np.linspace(0.0, args.wind_top, args.winds)
    alt = h0 if args.altitude_range is None else np.linspace(*args.altitude_range, args.altitudes)
    env = operating_envelope(d, wind, alt, args.payloads, client=client)
    ft = flyable_time(d, site, target_availability=args.target_availability, seed=args.seed)
    lw = env.limit_wind()
    out = {
        "n_points": env.points,
        "volume_m3": float(d.volume),
        "constraints": list(env.names),
        "wind_m_s": env.wind.tolist(),
        "altitude_m": env.altitude.tolist(),
        "payload_kg": env.payload.tolist(),
        "limit_wind_m_s": [[None if not np.isfinite(x) else float(x) for x in row] for row in lw],
        **ft.summary(),
        "points": env.rows(),
    }
    if args.csv is not None:
        from aerostat_core.model.io import rows_to_csv

        try:
            args.csv.write_text(rows_to_csv(out["points"]))
        except OSError as exc:
            raise ValueError(f"--csv {args.csv}: {exc.strerror}") from None
    if args.json:
        print(json.dumps(out))
    else:
        print(f"Operating envelope of the {d.volume:.1f} m3 aerostat: {env.points} points")
        k = int(np.argmin(np.abs(env.altitude - d.requirement.altitude)))
        if np.isfinite(lw[0, k]):
            print(f"  flyable up to {lw[0, k]:.1f} m/s at {env.altitude[k]:g} m")
        else:
            print(f"  not flyable at {env.altitude[k]:g} m at any wind of the grid")
        print(f"  time flyable    {ft.percent_time_flyable:6.1f} % ({ft.source})")
        print(f"  longest outage  {ft.longest_outage_h:6.1f} h")
        print(
            f"  design wind for {100 * ft.target_availability:g} % availability: "
            f"{ft.design_wind_for_target_m_s:.1f} m/s"
        )
    return 0


def _report(args, req: Requirement, d: Design, site, client) -> int:
    from aerostat_core.output.html_report import build_report

    n = 2000 if args.monte_carlo is None else args.monte_carlo
    text = build_report(
        d, site, n_monte_carlo=n, seed=args.seed, base_requirement=req, client=client
    )
    try:
        args.output.write_text(text, encoding="utf-8")
    except OSError as exc:
        raise ValueError(f"-o {args.output}: {exc.strerror}") from None
    if not args.json:
        print(f"report written to {args.output} ({len(text) // 1024} kB)")
    return 0
