"""Command line: ``python -m aerostat_core design --payload 10 --altitude 300 [--rules practice]
[--shape gnvr] [--config f.json] [--csv out.csv] [--json] [--stl hull.stl]
[--gores 12 --gores-dxf g.dxf]``. Prints a readable summary (or ``Design.summary()``
as JSON); a bad value exits with code 2 and one line naming the field. The CLI and the library
give the same design for the same inputs: limits left open come from the rule set, and without
``--config`` the configuration is the rule set's (presets.rules_configuration)."""

from __future__ import annotations

import argparse
import json
import os
import sys
from dataclasses import replace
from pathlib import Path

from aerostat_core.cli.commands import (
    add_design_options,
    add_subcommands,
    monte_carlo_summary,
    read_capped,
)
from aerostat_core.cli.commands import run as run_subcommand
from aerostat_core.dynamics import cli as simulate_cli
from aerostat_core.geometry.shapes import SHAPES
from aerostat_core.model.design import Design, design
from aerostat_core.model.inputs import Requirement
from aerostat_core.model.io import design_from_json, rows_to_csv
from aerostat_core.model.presets import rules_configuration
from aerostat_core.model.rules import RULE_NAMES

#: Largest --config file read [bytes] (a design file is a few kB).
CONFIG_SIZE_CAP = 1_000_000

#: Requirement fields settable from the command line: option -> field.
_OPTIONS = {
    "payload": "payload_mass",
    "altitude": "altitude",
    "site_elevation": "site_elevation",
    "isa_offset": "isa_offset",
    "wind_max": "wind_max",
    "design_wind": "design_wind",
    "blow_by_limit": "blow_by_limit",
    "site_temperature": "site_temperature",
    "survival_wind": "survival_wind",
    "altitude_loss_limit": "altitude_loss_limit",
    "free_lift_fraction": "free_lift_fraction",
    "safety_factor": "min_tether_safety_factor",
    "rules": "rules",
    "payload_power": "payload_power",
    "power_via": "power_via",
    "endurance_days": "endurance_days",
}


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


def format_summary(d: Design) -> str:
    """Readable multi-line summary of a design."""
    s = d.summary()
    req = d.requirement
    lines = [
        f"Aerostat for {req.payload_mass:g} kg at {req.altitude:g} m "
        f"({'sized' if d.sized else 'given'} volume)",
        f"  volume            {s.volume_m3:9.1f} m3",
        f"  length x diameter {s.length_m:6.2f} x {s.diameter_m:.2f} m",
        f"  total mass        {s.total_mass_kg:9.2f} kg",
        f"  free lift         {s.free_lift_kg:9.2f} kg "
        f"({s.percent_static_lift:.0f} % of buoyancy)",
        f"  at {req.design_wind:g} m/s: blow-by {s.blow_by_at_design_wind_m:.1f} m, "
        f"alpha {s.alpha_at_design_wind_deg:.1f} deg, tension "
        f"{s.tension_top_at_design_wind_N:.0f} N, safety factor "
        f"{s.safety_factor_at_design_wind:.1f}",
        f"  gas fill cost     {s.gas_cost_USD:9.0f} USD",
        f"  rules             {s.rules} (sizing set by: {s.binding_constraint})",
        "  mass breakdown:",
    ]
    lines += [f"    {r['item']:<15s}{r['mass_kg']:8.2f} kg" for r in d.mass_rows()]
    if d.feasible:
        lines.append("  feasible: all requirements met")
    else:
        lines.append("  NOT FEASIBLE:")
        lines += [f"    - {v}" for v in d.violations]
    return "\n".join(lines)


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m aerostat_core",
                                description="Tethered-aerostat conceptual design.")
    sub = p.add_subparsers(dest="command", required=True)
    d = sub.add_parser("design", help="size and evaluate an aerostat")
    d.add_argument("--payload", type=float, help="payload mass [kg]")
    d.add_argument("--altitude", type=float, help="operating altitude above the site [m]")
    d.add_argument("--site-elevation", type=float, help="launch-site elevation [m]")
    d.add_argument("--isa-offset", type=float, help="ISA temperature offset [K]")
    d.add_argument("--wind-max", type=float, help="largest sweep wind speed [m/s]")
    d.add_argument("--site-temperature", type=float, help="temperature at the launch site [degC]")
    d.add_argument("--design-wind", type=float,
                   help="operational (design) wind [m/s] (default from the rule set)")
    d.add_argument("--survival-wind", type=float,
                   help="survival wind [m/s] (default from the rule set)")
    d.add_argument("--blow-by-limit", type=float,
                   help="blow-by limit at the design wind [m] (default: the rule set's share of "
                        "the tether length)")
    d.add_argument("--altitude-loss-limit", type=float,
                   help="permissible altitude loss at the design wind [m]")
    d.add_argument("--free-lift-fraction", type=float,
                   help="required free lift / gross lift [-]")
    d.add_argument("--safety-factor", type=float,
                   help="required tether safety factor at the design wind [-]")
    d.add_argument("--rules", choices=RULE_NAMES,
                   help="rule set for the limits left open and the default configuration "
                        "(default: practice)")
    d.add_argument("--payload-power", type=float,
                   help="payload electrical power [W] (default 0: no power supply modelled)")
    d.add_argument("--power-via", choices=("onboard", "tether"),
                   help="payload power from an onboard battery or through the tether "
                        "(default onboard)")
    d.add_argument("--endurance-days", type=float,
                   help="days aloft without a helium top-up, keeping the free-lift margin "
                        "(default 0: no endurance requirement)")
    d.add_argument("--volume", type=float, help="hull volume [m3] (default: sized)")
    d.add_argument("--config", type=Path, help="JSON design file with every input")
    d.add_argument("--csv", type=Path, help="write geometry, mass and performance CSV here")
    d.add_argument("--json", action="store_true",
                   help="print Design.summary() as JSON instead of the readable summary "
                        "(adds hull_shape)")
    d.add_argument("--shape", choices=SHAPES, help="hull shape (default: npl, or the config's)")
    d.add_argument("--fineness-ratio", type=float,
                   help="hull l/d (default: the shape's standard value)")
    d.add_argument("--stl", type=Path, help="write an STL of the hull and fins here")
    d.add_argument("--gores", type=int, default=12, help="number of gores (default 12)")
    d.add_argument("--seam-allowance", type=float, default=0.02,
                   help="seam allowance of the patterns [m] (default 0.02)")
    d.add_argument("--gores-dxf", type=Path, help="write gore and fin patterns as DXF here")
    d.add_argument("--gores-svg", type=Path, help="write gore and fin patterns as SVG here")
    d.add_argument("--gores-csv", type=Path, help="write the gore half-widths CSV here")
    simulate_cli.add_parser(sub)  # python -m aerostat_core simulate (aerostat_core.dynamics.cli)
    add_design_options(d)
    add_subcommands(sub, d)
    return p


def summary_json(d: Design) -> str:
    """JSON text of :meth:`Design.summary` plus ``hull_shape``."""
    s = d.summary().to_dict()
    s.setdefault("hull_mass_kg", float(d.airframe.mass.items["hull"]))
    s.setdefault("hull_shape", d.airframe.hull.shape)
    return json.dumps(s, indent=2)


def _write_exports(args, d: Design) -> list[str]:
    """Write the requested geometry files; returns the lines to print (raises OSError)."""
    from aerostat_core.output.export import design_stl, gore_csv, gore_dxf, gore_pattern, gore_svg

    done = []
    if args.stl is not None:
        args.stl.write_bytes(design_stl(d))
        done.append(f"  STL written to {args.stl}")
    if any(x is not None for x in (args.gores_dxf, args.gores_svg, args.gores_csv)):
        pat = gore_pattern(d, args.gores, args.seam_allowance)
        for path, data in ((args.gores_dxf, gore_dxf), (args.gores_svg, gore_svg)):
            if path is not None:
                path.write_bytes(data(pat))
                done.append(f"  patterns written to {path}")
        if args.gores_csv is not None:
            args.gores_csv.write_text(gore_csv(pat))
            done.append(f"  gore half-widths written to {args.gores_csv}")
    return done


def main(argv: list[str] | None = None) -> int:
    """Entry point; returns the exit code (0 ok, 2 bad input). A closed pipe (``| head``) ends
    quietly."""
    try:
        return _main(argv)
    except BrokenPipeError:
        # the reader went away: point stdout at devnull so the interpreter's flush is silent
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0


def _main(argv: list[str] | None) -> int:
    args = _parser().parse_args(argv)
    if args.command == "simulate":
        return args.handler(args)
    try:
        if args.config is not None:
            req, cfg = design_from_json(read_capped(args.config, CONFIG_SIZE_CAP, "--config"))
        else:
            req, cfg = Requirement(), None
        changes = {f: getattr(args, o) for o, f in _OPTIONS.items() if getattr(args, o) is not None}
        req = replace(req, **changes)
        if cfg is None:
            cfg = rules_configuration(req.rules)
        if args.volume is not None:
            cfg = cfg.with_design_variables(volume=args.volume)
        if args.shape is not None or args.fineness_ratio is not None:
            shape = args.shape or cfg.hull.shape
            f = args.fineness_ratio if args.fineness_ratio is not None else (
                cfg.hull.fineness_ratio if shape == cfg.hull.shape else None)
            cfg = replace(cfg, hull=replace(cfg.hull, shape=shape, fineness_ratio=f))
        if not 3 <= args.gores <= 64:
            raise ValueError(f"--gores = {args.gores} is outside the valid range [3, 64]")
        if not 0 <= args.seam_allowance <= 0.2:
            raise ValueError(f"--seam-allowance = {args.seam_allowance:g} is outside the valid "
                             "range [0, 0.2] m")
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if args.command != "design":
        return run_subcommand(args, req, cfg)
    d = design(req, cfg)
    try:
        mc = monte_carlo_summary(d, args)
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if args.json:
        print(json.dumps({**json.loads(summary_json(d)), **mc}, indent=2))
    else:
        print(format_summary(d))
        if mc:
            print(f"  Monte Carlo ({mc['monte_carlo_samples']} samples) at the design wind, 5-95 %:"
                  f" blow-by {mc['blow_by_p05_m']:.1f}-{mc['blow_by_p95_m']:.1f} m, tension "
                  f"{mc['tension_p05_N']:.0f}-{mc['tension_p95_N']:.0f} N, free lift "
                  f"{mc['free_lift_p05_kg']:.2f}-{mc['free_lift_p95_kg']:.2f} kg")
            for r in mc["rule_sets"]:
                print(f"    rules {r['rules']:<9s}{r['volume_m3']:7.1f} m3, blow-by "
                      f"{r['blow_by_p05_m']:.1f}-{r['blow_by_p95_m']:.1f} m at "
                      f"{r['design_wind_m_s']:g} m/s")
    try:
        for line in _write_exports(args, d):
            print(line, file=sys.stderr if args.json else sys.stdout)
    except OSError as exc:
        print(f"error: {exc.filename}: {exc.strerror}", file=sys.stderr)
        return 2
    if args.csv is not None:
        try:
            args.csv.write_text(design_csv(d))
        except OSError as exc:
            print(f"error: --csv {args.csv}: {exc.strerror}", file=sys.stderr)
            return 2
        if not args.json:
            print(f"  CSV written to {args.csv}")
    sys.stdout.flush()
    return 0
