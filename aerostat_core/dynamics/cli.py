"""``python -m aerostat_core simulate``: a dynamics run for scripts.

    python -m aerostat_core simulate --scenario {steady,varying,gust,turbulence}
        [--design design.json] [--duration S] [--seed N] [--csv out.csv] [--json]

The default design is the thesis optimised design (:func:`aerostat_core.model.presets.thesis_optimized`)
and each scenario has the thesis comparison's settings (:mod:`.thesis`). ``--json`` prints
settling_time_s, pitch_range_deg [min, max], u_peak_mps, w_peak_mps, pitch_peak_deg (peak
deviations from the mean over the stated window), tension_range_N [min, max], status, the
window, the RMS values, slack events and the limits; the CSV header records the scenario and
every parameter. Bad input exits with code 2 and one line naming the option.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

#: Largest design file read [bytes].
MAX_DESIGN_BYTES = 1_000_000


def add_parser(subparsers) -> argparse.ArgumentParser:
    """Register the ``simulate`` subcommand on an argparse ``subparsers`` object."""
    p = subparsers.add_parser(
        "simulate", help="simulate the aerostat in gusts, ramps or turbulence"
    )
    p.add_argument(
        "--scenario",
        choices=("steady", "varying", "gust", "turbulence"),
        default="gust",
        help="wind scenario (thesis comparison settings)",
    )
    p.add_argument("--design", type=Path, help="JSON design file (default: thesis optimised)")
    p.add_argument("--duration", type=float, help="simulated time [s] (default per scenario)")
    p.add_argument("--seed", type=int, default=1, help="turbulence seed [-]")
    p.add_argument("--csv", type=Path, help="write the time histories here")
    p.add_argument("--json", action="store_true", help="print the metrics as JSON")
    p.set_defaults(handler=run)
    return p


def _read_design(path: Path) -> dict:
    from aerostat_core.model.io import design_from_json, inputs_to_dict

    if not path.is_file():
        raise ValueError(f"--design {path}: not a regular file")
    with path.open("rb") as fh:
        text = fh.read(MAX_DESIGN_BYTES + 1)
    if len(text) > MAX_DESIGN_BYTES:
        raise ValueError(f"--design {path}: larger than {MAX_DESIGN_BYTES} bytes")
    return inputs_to_dict(*design_from_json(text))


def run(args: argparse.Namespace) -> int:
    """Run the subcommand; returns the exit code (0 ok, 1 the run stopped early, 2 bad input)."""
    from .results import limit_flags
    from .scenarios import limits_of, request_header, run_request
    from .thesis import metrics, thesis_request, thesis_settings_text

    try:
        if args.duration is not None and not 0 < args.duration <= 3600:
            raise ValueError(
                f"--duration = {args.duration:g} s is outside the valid range (0, 3600] s"
            )
        if not 0 <= args.seed <= 2**32 - 1:
            raise ValueError(f"--seed = {args.seed} is outside the valid range [0, 4294967295]")
        req = thesis_request(args.scenario, args.seed, args.duration)
        if args.design is not None:
            try:
                req["inputs"] = _read_design(args.design)
            except OSError as exc:
                raise ValueError(f"--design {args.design}: {exc.strerror}") from None
        res, d = run_request(req)
    except (ValueError, RuntimeError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    m = metrics(res, req)
    m["scenario"] = args.scenario
    m["settings"] = thesis_settings_text().get(args.scenario, "steady wind, 10 m/s")
    m["limits"] = limit_flags(res, limits_of(d))
    m["wall_time_s"] = res.stats["wall_time"]
    if args.csv is not None:
        try:
            args.csv.write_text(res.to_csv(header=request_header(req, res)))
        except OSError as exc:
            print(f"error: --csv {args.csv}: {exc.strerror}", file=sys.stderr)
            return 2
    try:
        _print(m, args)
    except BrokenPipeError:  # e.g. piped into head: stop quietly
        sys.stdout = open(os.devnull, "w")  # noqa: SIM115 - swallow the interpreter's final flush
    return 0 if res.ok else 1


def _print(m: dict, args: argparse.Namespace) -> None:
    if args.json:
        print(json.dumps(m, indent=2))
    else:
        settle = m["settling_time_s"]
        lines = [
            f"{args.scenario}: {m['settings']}",
            f"  status            {m['status']}",
            f"  window            {m['window_start_s']:.0f}-{m['window_end_s']:.0f} s",
            f"  settling time x_C {'-' if settle is None else f'{settle:.1f} s'}",
            f"  pitch             {m['pitch_range_deg'][0]:.2f} .. {m['pitch_range_deg'][1]:.2f}"
            f" deg (peak deviation {m['pitch_peak_deg']:.2f}, RMS {m['pitch_rms_deg']:.2f})",
            f"  hull v_x          peak deviation {m['u_peak_mps']:.2f} m/s, RMS "
            f"{m['u_rms_mps']:.2f}",
            f"  hull v_z          peak deviation {m['w_peak_mps']:.2f} m/s, RMS "
            f"{m['w_rms_mps']:.2f}",
            f"  tension at C      {m['tension_range_N'][0]:.0f} .. {m['tension_range_N'][1]:.0f} N",
        ]
        lines += [
            f"  LIMIT EXCEEDED: {r['limit']} ({r['worst']:.3g} vs {r['value']:.3g} "
            f"{r['unit']}, first at {r['first_s']:.1f} s)"
            for r in m["limits"]
            if r["exceeded"]
        ]
        if args.csv is not None:
            lines.append(f"  CSV written to {args.csv}")
        print("\n".join(lines))
