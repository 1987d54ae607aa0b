"""Command line: ``aerostat design --payload 10 --altitude 300 [--rules practice]
[--shape gnvr] [--fins-position 0.6] [--config f.json] [--csv out.csv] [--json] [--stl hull.stl]
[--gores 12 --gores-dxf g.dxf]`` (or ``python -m aerostat_core ...``). Prints a readable summary
(or ``Design.summary()`` as JSON). Every design input is an option, built from the field registry
(:mod:`aerostat_core.cli.options`). The CLI and the library give the same design for the same
inputs: limits left open come from the rule set, and without ``--config`` the configuration is
the rule set's (presets.rules_configuration).

No input gives a traceback: a bad value, file or output (a directory, no permission, a full disk),
a request over the compute budget or a lost Dask cluster exits with code 2 and one line
``error: --option: what is wrong``.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

from aerostat_core.base.cli_input import OptionError, decimal, whole
from aerostat_core.base.validation import InputError
from aerostat_core.cli.commands import (
    add_design_options,
    add_subcommands,
    monte_carlo_summary,
    read_capped,
    write_output,
)
from aerostat_core.cli.commands import run as run_subcommand
from aerostat_core.cli.options import (
    add_input_options,
    apply_configuration,
    apply_requirement,
    given_inputs,
    option_for_error,
)
from aerostat_core.dynamics import cli as simulate_cli
from aerostat_core.model.budget import BudgetError
from aerostat_core.model.design import Design
from aerostat_core.model.inputs import Requirement
from aerostat_core.model.io import design_from_json, rows_to_csv
from aerostat_core.model.presets import rules_configuration
from aerostat_core.studies.robust import assess, design_with_confidence

#: Largest sample of the verdict's probabilities under ``--monte-carlo N`` (a larger N still runs
#: the bands on N samples; the probability's standard error at 1e5 is below 0.002).
VERDICT_SAMPLES_MAX = 100_000
#: Largest --config file read [bytes] (a design file is a few kB).
CONFIG_SIZE_CAP = 1_000_000
#: Valid ranges of the pattern options: option -> (lo, hi, unit).
PATTERN_RANGES = {"--gores": (3, 64, ""), "--seam-allowance": (0.0, 0.2, "m")}


def design_csv(d: Design) -> str:
    """One CSV text with three sections (geometry, mass breakdown, performance), units in the
    column names; sections are separated by a blank line and start with a ``# section`` line."""
    geo = [{"quantity": r["quantity"], "unit": r["unit"], "value": r["value"]}
           for r in d.geometry_rows()]
    parts = [
        "# geometry\n" + rows_to_csv(geo),
        "# mass breakdown\n" + rows_to_csv(d.mass_rows()),
        "# performance versus wind speed\n" + rows_to_csv(d.performance.rows()),
    ]
    return "\n".join(parts)


def _num(x, fmt: str) -> str:
    """``x`` formatted, or "n/a" for a quantity with no physical meaning (None)."""
    return "n/a" if x is None else format(x, fmt)


def format_summary(d: Design, verdict=None) -> str:
    """Readable multi-line summary of a design, the verdict first (``verdict``: one already
    computed with its sample; default the nominal one)."""
    v = d.verdict() if verdict is None else verdict
    s = d.summary(v)
    req = d.requirement
    lines = [f"VERDICT: {v.verdict} - {v.headline}"]
    lines += [f"  what to change: {a}" for a in v.what_to_change]
    if d.sinks:
        lines.append(f"  the hull cannot lift its weight (free lift {s.free_lift_kg:.1f} kg): no "
                     "wind performance is shown")
    lines += [
        f"Aerostat for {req.payload_mass:g} kg at {req.altitude:g} m "
        f"({'sized' if d.sized or d.robust is not None else 'given'} volume)",
        f"  volume            {s.volume_m3:9.1f} m3",
        f"  length x diameter {s.length_m:6.2f} x {s.diameter_m:.2f} m",
        f"  total mass        {s.total_mass_kg:9.2f} kg",
        f"  free lift         {s.free_lift_kg:9.2f} kg "
        f"({s.percent_static_lift:.0f} % of buoyancy)",
        f"  at {req.design_wind:g} m/s: blow-by {_num(s.blow_by_at_design_wind_m, '.1f')} m, "
        f"alpha {_num(s.alpha_at_design_wind_deg, '.1f')} deg, tension "
        f"{_num(s.tension_top_at_design_wind_N, '.0f')} N, safety factor "
        f"{_num(s.safety_factor_at_design_wind, '.1f')}",
        f"  envelope          {s.envelope_pressure_Pa:9.0f} Pa, bending moment "
        f"{s.bending_moment_Nm:.0f} N m (wrinkles at {s.wrinkling_moment_Nm:.0f} N m)",
        f"  gas fill cost     {s.gas_cost_USD:9.0f} USD",
        f"  rules             {s.rules} (sizing set by: {s.binding_constraint})",
        *_lateral_lines(s.lateral),
        "  mass breakdown:",
    ]
    lines += [f"    {r['item']:<15s}{r['mass_kg']:8.2f} kg" for r in d.mass_rows()]
    if d.feasible:
        lines.append("  feasible: all requirements met")
    else:
        lines.append("  NOT FEASIBLE:")
        lines += [f"    - {v}" for v in d.violations]
    return "\n".join(lines)


def _lateral_lines(lat) -> list[str]:
    """The lateral-stability lines of the readable summary (none before the 6-DOF check)."""
    if lat is None:
        return []
    if not lat.lateral_stability_checked:
        head = "not checked by the rule set"
    elif lat.lateral_unstable_above_m_s is None:
        head = f"stable up to the survival wind {lat.lateral_checked_up_to_m_s:g} m/s"
    else:
        head = f"a lateral mode goes unstable from {lat.lateral_unstable_above_m_s:.1f} m/s"
    out = [f"  lateral stability {head}"]
    if lat.C_n_beta_per_rad is not None:
        out.append(f"    at {lat.lateral_derivatives_wind_m_s:g} m/s: C_Y_beta "
                   f"{lat.C_Y_beta_per_rad:+.3f}, C_n_beta {lat.C_n_beta_per_rad:+.3f}, C_l_beta "
                   f"{lat.C_l_beta_per_rad:+.3f} /rad")
    return out


class ArgumentParser(argparse.ArgumentParser):
    """argparse with one-line errors: ``error: argument --payload: ...`` and exit code 2 (no
    usage block: the line names the option; ``--help`` lists them)."""

    def error(self, message: str):  # noqa: D102 - argparse's hook
        self.exit(2, f"error: {message}\n")


def _parser() -> argparse.ArgumentParser:
    p = ArgumentParser(prog="aerostat", description="Tethered-aerostat conceptual design.")
    sub = p.add_subparsers(dest="command", required=True)
    d = sub.add_parser("design", help="size and evaluate an aerostat")
    d.add_argument("--config", type=Path, help="JSON design file with every input")
    d.add_argument("--csv", type=Path, help="write geometry, mass and performance CSV here")
    d.add_argument("--json", action="store_true",
                   help="print Design.summary() as JSON instead of the readable summary "
                        "(adds hull_shape)")
    d.add_argument("--stl", type=Path, help="write an STL of the hull and fins here")
    d.add_argument("--gores", type=whole, default=12, help="number of gores, valid [3, 64] "
                   "(default 12)")
    d.add_argument("--seam-allowance", type=decimal, default=0.02,
                   help="seam allowance of the patterns [m], valid [0, 0.2] (default 0.02)")
    d.add_argument("--gores-dxf", type=Path, help="write gore and fin patterns as DXF here")
    d.add_argument("--gores-svg", type=Path, help="write gore and fin patterns as SVG here")
    d.add_argument("--gores-csv", type=Path, help="write the gore half-widths CSV here")
    add_input_options(d)
    simulate_cli.add_parser(sub)  # aerostat simulate (aerostat_core.dynamics.cli)
    add_design_options(d)
    add_subcommands(sub, d)
    return p


def summary_json(d: Design, verdict=None) -> str:
    """JSON text of :meth:`Design.summary` plus ``hull_shape`` (``verdict``: one computed with
    a seeded sample, which sets ``probability_meets_operating_limits``)."""
    s = d.summary(verdict).to_dict()
    s.setdefault("hull_mass_kg", float(d.airframe.mass.items["hull"]))
    s.setdefault("hull_shape", d.airframe.hull.shape)
    # the class of thesis Table 2.3 and its fielded systems' figures (issue 23)
    from aerostat_core.studies.fielded import class_figures

    req = d.requirement
    figures = class_figures(req.payload_mass, req.altitude)
    s.setdefault("class", figures.pop("class"))
    s.setdefault("class_typical", figures)
    cfg = d.configuration
    s.setdefault("hull_fabric", cfg.hull_fabric.name)
    s.setdefault("fin_fabric", cfg.fin_fabric.name)
    s.setdefault("tether", cfg.tether.name)
    return json.dumps(s, indent=2)


def _write_exports(args, d: Design) -> list[str]:
    """Write the requested geometry files; returns the lines to print (raises OptionError)."""
    from aerostat_core.output.export import design_stl, gore_csv, gore_dxf, gore_pattern, gore_svg

    done = []
    if args.stl is not None:
        write_output("--stl", args.stl, design_stl(d))
        done.append(f"  STL written to {args.stl}")
    if any(x is not None for x in (args.gores_dxf, args.gores_svg, args.gores_csv)):
        pat = gore_pattern(d, args.gores, args.seam_allowance)
        for option, path, data in (("--gores-dxf", args.gores_dxf, gore_dxf),
                                   ("--gores-svg", args.gores_svg, gore_svg)):
            if path is not None:
                write_output(option, path, data(pat))
                done.append(f"  patterns written to {path}")
        if args.gores_csv is not None:
            write_output("--gores-csv", args.gores_csv, gore_csv(pat))
            done.append(f"  gore half-widths written to {args.gores_csv}")
    return done


def make_design(req: Requirement, cfg, given: dict | None = None) -> Design:
    """:func:`design` with its errors named by option: an input error by the option of its
    field, the compute budget by the options that reduce it."""
    try:
        return design_with_confidence(req, cfg)
    except BudgetError as exc:
        raise OptionError("--tether-segments/--wind-step", str(exc)) from None
    except InputError as exc:
        raise OptionError(option_for_error(exc, given or {}) or "input", str(exc)) from None


def main(argv: list[str] | None = None) -> int:
    """Entry point (the ``aerostat`` console script); returns the exit code (0 ok, 1 a
    simulation stopped early, 2 bad input: one line naming the option). An option argparse
    refuses (an unknown choice, a number that is not plain decimal) and ``--help`` exit through
    ``SystemExit`` as argparse does (code 2, one line; 0). A closed pipe (``| head``) ends
    quietly; no input ever prints a traceback."""
    for stream in (sys.stdout, sys.stderr):  # a non-UTF-8 terminal: never an encoding error
        if hasattr(stream, "reconfigure"):
            stream.reconfigure(errors="backslashreplace")
    try:
        return _main(argv)
    except BrokenPipeError:
        # the reader went away: point stdout at devnull so the interpreter's flush is silent
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0
    except (ValueError, OSError, RecursionError, MemoryError) as exc:
        print(f"error: {_one_line(exc)}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("error: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # noqa: BLE001 - a defect: one line, never a traceback
        if os.environ.get("AEROSTAT_TRACEBACK"):
            raise
        print(f"error: internal error ({type(exc).__name__}: {_one_line(exc)}); please report "
              "it with the command line (AEROSTAT_TRACEBACK=1 shows the traceback)",
              file=sys.stderr)
        return 2


def _one_line(exc: BaseException) -> str:
    if isinstance(exc, OSError) and exc.strerror:
        text = f"{exc.filename}: {exc.strerror}" if exc.filename else exc.strerror
    else:
        text = str(exc) or type(exc).__name__
    return " ".join(text.split())[:1000]


def _inputs(args) -> tuple:
    """The requirement and configuration of the options (``--config`` first, then every input
    option given); OptionError naming the option."""
    given = given_inputs(args)
    if args.config is not None:
        data = read_capped(args.config, CONFIG_SIZE_CAP, "--config")
        try:
            req, cfg = design_from_json(data)
        except ValueError as exc:
            raise OptionError("--config", f"{args.config}: {exc}") from None
    else:
        req, cfg = Requirement(), None
    req = apply_requirement(req, given)
    if cfg is None:
        cfg = rules_configuration(req.rules)
    cfg = apply_configuration(cfg, given)
    return req, cfg, given


def _main(argv: list[str] | None) -> int:
    args = _parser().parse_args(argv)
    if args.command == "simulate":
        return args.handler(args)
    req, cfg, given = _inputs(args)
    for option, value in (("--gores", args.gores), ("--seam-allowance", args.seam_allowance)):
        lo, hi, unit = PATTERN_RANGES[option]
        if not lo <= value <= hi:
            u = f" {unit}" if unit else ""
            raise OptionError(option, f"{value:g}{u} is outside the valid range [{lo:g}, {hi:g}]{u}")
    if args.command != "design":
        return run_subcommand(args, req, cfg, lambda r, c: make_design(r, c, given))
    d = make_design(req, cfg, given)
    mc = monte_carlo_summary(d, args)
    verdict = (assess(d, min(args.monte_carlo, VERDICT_SAMPLES_MAX), args.seed)
               if args.monte_carlo else None)
    if args.json:
        print(json.dumps({**json.loads(summary_json(d, verdict)), **mc}, indent=2))
    else:
        print(format_summary(d, verdict))
        if mc:
            print(f"  Monte Carlo ({mc['monte_carlo_samples']} samples) at the design wind, 5-95 %:"
                  f" blow-by {mc['blow_by_p05_m']:.1f}-{mc['blow_by_p95_m']:.1f} m, tension "
                  f"{mc['tension_p05_N']:.0f}-{mc['tension_p95_N']:.0f} N, free lift "
                  f"{mc['free_lift_p05_kg']:.2f}-{mc['free_lift_p95_kg']:.2f} kg")
            for r in mc["rule_sets"]:
                print(f"    rules {r['rules']:<9s}{r['volume_m3']:7.1f} m3, blow-by "
                      f"{r['blow_by_p05_m']:.1f}-{r['blow_by_p95_m']:.1f} m at "
                      f"{r['design_wind_m_s']:g} m/s")
    for line in _write_exports(args, d):
        print(line, file=sys.stderr if args.json else sys.stdout)
    if args.csv is not None:
        write_output("--csv", args.csv, design_csv(d))
        if not args.json:
            print(f"  CSV written to {args.csv}")
    sys.stdout.flush()
    return 0
