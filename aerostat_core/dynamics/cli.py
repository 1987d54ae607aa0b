"""``python -m aerostat_core simulate``: a dynamics run for scripts.

    aerostat simulate --scenario {steady,varying,gust,turbulence}
        [--design design.json] [--duration S] [--seed N] [--csv out.csv] [--json]
    python -m aerostat_core simulate --dof 6 --scenario {crosswind-gust,veer,direction-step,
        turbulence-3d,reel-in,reel-out,tether-break} [same options]

The default design is the thesis optimised design (:func:`aerostat_core.model.presets.thesis_optimized`)
and each scenario has the thesis comparison's settings (:mod:`.thesis`). ``--json`` prints
settling_time_s, pitch_range_deg [min, max], u_peak_mps, w_peak_mps, pitch_peak_deg (peak
deviations from the mean over the stated window), tension_range_N [min, max], status, the
window, the RMS values, slack events and the limits; the CSV header records the scenario and
every parameter. Bad input exits with code 2 and one line naming the option.

``--dof 6`` runs the 6-DOF model (:mod:`.scenarios6`); its JSON has the same keys plus
roll_peak_deg, yaw_peak_deg, lateral_peak_m, lateral_unstable_above_m_s (null when every lateral
mode is stable up to the survival wind), lateral_modes, static_derivatives,
tension_winch_peak_N, tether_length_range_m (and ascent_m, drift_m after a tether break).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

from aerostat_core.base.cli_input import OptionError, decimal, whole
from aerostat_core.base.fields import FieldSpec
from aerostat_core.base.validation import InputError, range_text
from aerostat_core.dynamics.request import DynamicsRequest, TurbulenceSettings, error_text
from aerostat_core.dynamics.scenarios6 import SCENARIOS6, Request6

#: Largest design file read [bytes].
MAX_DESIGN_BYTES = 1_000_000
#: Options of the run settings: option -> the field of the 3-DOF request (dotted path) and of
#: the 6-DOF one. Their label, unit and range in --help come from the field registry.
RUN_OPTIONS = {"--duration": ("duration", "duration"), "--seed": ("turbulence.seed", "seed")}


def _valid(s: FieldSpec) -> str:
    if s.kind == "integer":
        return f"[{int(s.lo)}, {int(s.hi)}]"
    return range_text(s.lo, s.hi, "", s.lo_open, s.hi_open)


def spec_help(option: str, default: str) -> str:
    """``--help`` of a run option: the registry's label, SI unit and valid range (the 6-DOF
    range too when it differs) and the default."""
    path3, name6 = RUN_OPTIONS[option]
    s3, s6 = DynamicsRequest.spec_at(path3), Request6.spec_at(name6)
    text = f"{s3.label} [{s3.unit or '-'}], valid {_valid(s3)}"
    if _valid(s6) != _valid(s3):
        text += f" ({_valid(s6)} with --dof 6)"
    return f"{text} (default {default})".replace("%", "%%")


def option_error(exc: InputError) -> OptionError:
    """The one-line error of a run setting out of its range, naming the option."""
    option = next((o for o, paths in RUN_OPTIONS.items()
                   if exc.field in (paths[0].rsplit(".", 1)[-1], paths[1])), "input")
    return OptionError(option, error_text(exc))


def add_parser(subparsers) -> argparse.ArgumentParser:
    """Register the ``simulate`` subcommand on an argparse ``subparsers`` object."""
    p = subparsers.add_parser(
        "simulate", help="simulate the aerostat in gusts, ramps or turbulence"
    )
    p.add_argument(
        "--dof",
        type=whole,
        choices=(3, 6),
        default=3,
        help="3: the longitudinal model (thesis scenarios); 6: the 6-DOF hull on a 3-D tether",
    )
    p.add_argument(
        "--scenario",
        choices=("steady", "varying", "gust", "turbulence") + SCENARIOS6,
        default=None,
        help="wind scenario: steady, varying, gust, turbulence (--dof 3, thesis comparison "
        "settings; default gust) or " + ", ".join(SCENARIOS6) + " (--dof 6; default "
        "crosswind-gust)",
    )
    p.add_argument("--design", type=Path, help="JSON design file (default: thesis optimised)")
    p.add_argument("--duration", type=decimal, metavar="VALUE",
                   help=spec_help("--duration", "per scenario"))
    p.add_argument("--seed", type=whole, default=1, metavar="N", help=spec_help("--seed", "1"))
    p.add_argument("--csv", type=Path, help="write the time histories here")
    p.add_argument("--json", action="store_true", help="print the metrics as JSON")
    p.set_defaults(handler=run)
    return p


def _read_design(path: Path) -> dict:
    from aerostat_core.base.cli_input import read_capped
    from aerostat_core.model.io import design_from_json, inputs_to_dict

    text = read_capped(path, MAX_DESIGN_BYTES, "--design")
    try:
        return inputs_to_dict(*design_from_json(text))
    except ValueError as exc:
        raise OptionError("--design", f"{path}: {exc}") from None


def run(args: argparse.Namespace) -> int:
    """Run the subcommand; returns the exit code (0 ok, 1 the run stopped early, 2 bad input)."""
    from aerostat_core.base.cli_input import write_output

    from .results import limit_flags
    from .scenarios import limits_of, request_header, run_request
    from .thesis import metrics, thesis_request, thesis_settings_text

    if args.dof == 6:
        return run_6dof(args)
    if args.scenario is None:
        args.scenario = "gust"
    if args.scenario in SCENARIOS6:
        print(f"error: --scenario {args.scenario} needs --dof 6", file=sys.stderr)
        return 2
    design = None
    try:
        try:
            TurbulenceSettings(seed=args.seed)  # checked in every scenario, used in turbulence
            dyn = thesis_request(args.scenario, args.seed, args.duration)
        except InputError as exc:
            raise option_error(exc) from None
        if args.design is not None:
            from aerostat_core.model.design import design as build
            from aerostat_core.model.io import inputs_from_dict

            inputs = _read_design(args.design)
            design = build(*inputs_from_dict(inputs))
        else:
            inputs = None
        res, d = run_request(dyn, design=design)
    except (ValueError, RuntimeError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    m = metrics(res, dyn)
    m["scenario"] = args.scenario
    # the settings actually used: the seed and duration given, not the thesis defaults
    m["settings"] = thesis_settings_text(args.seed, args.duration).get(
        args.scenario, f"steady wind, {dyn.speed:g} m/s, {dyn.duration:g} s"
    )
    m["limits"] = limit_flags(res, limits_of(d))
    m["wall_time_s"] = res.stats["wall_time"]
    if args.csv is not None:
        try:
            write_output("--csv", args.csv, res.to_csv(header=request_header(dyn, res, inputs)))
        except OptionError as exc:
            print(f"error: {exc}", file=sys.stderr)
            return 2
    try:
        _print(m, args)
    except BrokenPipeError:  # e.g. piped into head: stop quietly
        sys.stdout = open(os.devnull, "w")  # noqa: SIM115 - swallow the interpreter's final flush
    return 0 if res.ok else 1


def run_6dof(args: argparse.Namespace) -> int:
    """``simulate --dof 6``: a 6-DOF scenario (:mod:`.scenarios6`); same exit codes."""
    from aerostat_core.dynamics.scenarios6 import metrics6, run6

    scenario = args.scenario or "crosswind-gust"
    try:
        if scenario not in SCENARIOS6:
            raise ValueError(f"--scenario {scenario} is a 3-DOF scenario: use --dof 3 (or one of "
                             f"{', '.join(SCENARIOS6)})")
        kw = {"seed": args.seed}
        if args.duration is not None:
            kw["duration"] = args.duration
        try:
            dyn6 = Request6.for_scenario(scenario, **kw)
        except InputError as exc:
            raise option_error(exc) from None
        design = None
        if args.design is not None:
            from aerostat_core.model.design import design as build
            from aerostat_core.model.io import inputs_from_dict

            try:
                design = build(*inputs_from_dict(_read_design(args.design)))
            except OSError as exc:
                raise ValueError(f"--design {args.design}: {exc.strerror}") from None
        res, d = run6(dyn6, design)
        m = metrics6(res, dyn6, d)
    except (ValueError, RuntimeError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    m["scenario"] = scenario
    m["dof"] = 6
    m["settings"] = "; ".join(f"{k} = {v}" for k, v in dyn6.header().items())
    m["wall_time_s"] = res.stats["wall_time"]
    if args.csv is not None:
        try:
            args.csv.write_text(res.to_csv(header=dyn6.header()))
        except OSError as exc:
            print(f"error: --csv {args.csv}: {exc.strerror}", file=sys.stderr)
            return 2
    try:
        if args.json:
            print(json.dumps(m, indent=2))
        else:
            above = m["lateral_unstable_above_m_s"]
            lines = [f"{scenario} (6-DOF): {m['status']}",
                     f"  roll peak         {m['roll_peak_deg']:.2f} deg",
                     f"  yaw peak          {m['yaw_peak_deg']:.2f} deg",
                     f"  lateral peak      {m['lateral_peak_m']:.2f} m",
                     f"  tension at C      {m['tension_range_N'][0]:.0f} .. "
                     f"{m['tension_range_N'][1]:.0f} N",
                     "  laterally stable up to the survival wind" if above is None else
                     f"  LATERALLY UNSTABLE above {above:.1f} m/s"]
            if args.csv is not None:
                lines.append(f"  CSV written to {args.csv}")
            print("\n".join(lines))
    except BrokenPipeError:
        sys.stdout = open(os.devnull, "w")  # noqa: SIM115
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
