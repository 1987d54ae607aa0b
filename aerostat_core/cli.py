"""Command line: ``python -m aerostat_core design --payload 10 --altitude 300 [--config f.json]
[--csv out.csv]``. Prints a readable summary; a bad value exits with code 2 and one line naming
the field."""

from __future__ import annotations

import argparse
import sys
from dataclasses import replace
from pathlib import Path

from .design import Design, design
from .dynamics import cli as simulate_cli
from .inputs import Configuration, Requirement
from .io import design_from_json, rows_to_csv

#: Requirement fields settable from the command line: option -> field.
_OPTIONS = {
    "payload": "payload_mass",
    "altitude": "altitude",
    "site_elevation": "site_elevation",
    "isa_offset": "isa_offset",
    "wind_max": "wind_max",
    "design_wind": "design_wind",
    "blow_by_limit": "blow_by_limit",
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
    d.add_argument("--design-wind", type=float, help="design wind speed [m/s]")
    d.add_argument("--blow-by-limit", type=float,
                   help="blow-by limit at the design wind [m] (default 0.1 x altitude)")
    d.add_argument("--volume", type=float, help="hull volume [m3] (default: sized)")
    d.add_argument("--config", type=Path, help="JSON design file with every input")
    d.add_argument("--csv", type=Path, help="write geometry, mass and performance CSV here")
    simulate_cli.add_parser(sub)  # python -m aerostat_core simulate (aerostat_core.dynamics.cli)
    return p


def main(argv: list[str] | None = None) -> int:
    """Entry point; returns the exit code (0 ok, 2 bad input)."""
    args = _parser().parse_args(argv)
    if args.command == "simulate":
        return args.handler(args)
    try:
        if args.config is not None:
            try:
                text = args.config.read_bytes()
            except OSError as exc:
                raise ValueError(f"--config {args.config}: {exc.strerror}") from None
            req, cfg = design_from_json(text)
        else:
            req, cfg = Requirement(), Configuration()
        changes = {f: getattr(args, o) for o, f in _OPTIONS.items() if getattr(args, o) is not None}
        if "blow_by_limit" not in changes and "altitude" in changes and args.config is None:
            changes["blow_by_limit"] = 0.1 * changes["altitude"]  # methods.md G5 default
        req = replace(req, **changes)
        if args.volume is not None:
            cfg = cfg.with_design_variables(volume=args.volume)
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    d = design(req, cfg)
    print(format_summary(d))
    if args.csv is not None:
        try:
            args.csv.write_text(design_csv(d))
        except OSError as exc:
            print(f"error: --csv {args.csv}: {exc.strerror}", file=sys.stderr)
            return 2
        print(f"  CSV written to {args.csv}")
    return 0
