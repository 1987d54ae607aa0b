"""Command line: ``python -m aerostat_core design --payload 10 --altitude 300 [--rules practice]
[--config f.json] [--csv out.csv] [--json]``. Prints a readable summary (or ``Design.summary()``
as JSON); a bad value exits with code 2 and one line naming the field. The CLI and the library
give the same design for the same inputs: limits left open come from the rule set, and without
``--config`` the configuration is the rule set's (presets.rules_configuration)."""

from __future__ import annotations

import argparse
import json
import os
import stat
import sys
from dataclasses import replace
from pathlib import Path

from .commands import add_design_options, add_subcommands, monte_carlo_summary
from .commands import run as run_subcommand
from .design import Design, design
from .inputs import Requirement
from .io import design_from_json, rows_to_csv
from .presets import rules_configuration
from .rules import RULE_NAMES

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
        f"  volume            {s['volume_m3']:9.1f} m3",
        f"  length x diameter {s['length_m']:6.2f} x {s['diameter_m']:.2f} m",
        f"  total mass        {s['total_mass_kg']:9.2f} kg",
        f"  free lift         {s['free_lift_kg']:9.2f} kg "
        f"({s['percent_static_lift']:.0f} % of buoyancy)",
        f"  at {req.design_wind:g} m/s: blow-by {s['blow_by_at_design_wind_m']:.1f} m, "
        f"alpha {s['alpha_at_design_wind_deg']:.1f} deg, tension "
        f"{s['tension_top_at_design_wind_N']:.0f} N, safety factor "
        f"{s['safety_factor_at_design_wind']:.1f}",
        f"  gas fill cost     {s['gas_cost_USD']:9.0f} USD",
        f"  rules             {s['rules']} (sizing set by: {s['binding_constraint']})",
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
    d.add_argument("--volume", type=float, help="hull volume [m3] (default: sized)")
    d.add_argument("--config", type=Path, help="JSON design file with every input")
    d.add_argument("--csv", type=Path, help="write geometry, mass and performance CSV here")
    d.add_argument("--json", action="store_true",
                   help="print Design.summary() as JSON instead of the readable summary")
    add_design_options(d)
    add_subcommands(sub, d)
    return p


def _read_config(path: Path) -> bytes:
    """Read a design file: a regular file of at most CONFIG_SIZE_CAP bytes."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        raise ValueError(f"--config {path}: {exc.strerror}") from None
    with os.fdopen(fd, "rb") as fh:
        if not stat.S_ISREG(os.fstat(fh.fileno()).st_mode):
            raise ValueError(f"--config {path}: not a regular file")
        data = fh.read(CONFIG_SIZE_CAP + 1)
    if len(data) > CONFIG_SIZE_CAP:
        raise ValueError(f"--config {path}: larger than {CONFIG_SIZE_CAP} bytes")
    return data


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
    try:
        if args.config is not None:
            req, cfg = design_from_json(_read_config(args.config))
        else:
            req, cfg = Requirement(), None
        changes = {f: getattr(args, o) for o, f in _OPTIONS.items() if getattr(args, o) is not None}
        req = replace(req, **changes)
        if cfg is None:
            cfg = rules_configuration(req.rules)
        if args.volume is not None:
            cfg = cfg.with_design_variables(volume=args.volume)
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
        print(json.dumps({**d.summary(), **mc}, indent=2))
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
