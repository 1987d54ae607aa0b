"""Command-line options of the design inputs, built from the field registry, and strict numbers.

Every input of a design (:func:`aerostat_core.model.input_paths.all_specs`: the requirement and the whole
configuration, fins included) is an option of ``design``, ``envelope`` and ``report``, named
after its path (``configuration.fins.position`` is ``--fins-position``,
``requirement.wind_step`` is ``--wind-step``), with the registry's label, SI unit and valid range
in ``--help``; a few options keep the short names the CLI always had (:data:`SHORT_NAMES`).
Values are in SI units, as in a JSON design file (a fraction, not a percentage: ``--fins-position
0.6``); the help also gives the range as the app's form shows it when that differs.

Numbers on the command line are plain ASCII decimals (:func:`decimal`, :func:`whole`):
``1_0``, full-width or Arabic-Indic digits, ``inf`` and ``nan`` are refused with a message
naming the option, where Python's ``float()`` would read ``1_0`` and ``１０`` as 10.
"""

from __future__ import annotations

import argparse
import functools
from dataclasses import dataclass, replace
from typing import Any

from aerostat_core.base.cli_input import OptionError, decimal, whole
from aerostat_core.base.fields import FieldSpec
from aerostat_core.base.validation import InputError, range_text
from aerostat_core.model.input_paths import PathSpec, all_specs, paths_for

#: Options that keep the short names of the hand-written CLI (public): input path -> option.
#: The path-derived name is an alias (``--payload-mass`` works as well).
SHORT_NAMES = {
    "requirement.payload_mass": "--payload",
    "requirement.min_tether_safety_factor": "--safety-factor",
    "configuration.hull.volume": "--volume",
    "configuration.hull.shape": "--shape",
    "configuration.hull.fineness_ratio": "--fineness-ratio",
}


@dataclass(frozen=True)
class InputOption:
    """One design input as a command-line option."""

    path: str  # "configuration.fins.position"
    option: str  # "--fins-position"
    aliases: tuple[str, ...]
    dest: str  # attribute of the argparse namespace
    spec: PathSpec


def path_option(path: str) -> str:
    """The option named after an input path (without the root).

    >>> path_option("configuration.fins.area_change")
    '--fins-area-change'
    """
    return "--" + path.split(".", 1)[1].replace(".", "-").replace("_", "-")


@functools.cache
def input_options() -> tuple[InputOption, ...]:
    """Every design input as an option, in the registry's order."""
    out = []
    for p in all_specs():
        long = path_option(p.path)
        short = SHORT_NAMES.get(p.path)
        option, aliases = (short, (long,)) if short else (long, ())
        out.append(InputOption(p.path, option, aliases, f"input:{p.path}", p))
    names = [n for o in out for n in (o.option, *o.aliases)]
    if len(names) != len(set(names)):  # two paths with one option name: a registry change
        raise RuntimeError("two design inputs map to the same command-line option")
    return tuple(out)


def _si_unit(s: FieldSpec) -> str:
    return s.unit or "-"


def help_text(p: PathSpec) -> str:
    """``--help`` text of an input: the registry's label, SI unit and valid range, what leaving
    it out means, and the form's range when the form shows another unit."""
    s = p.spec
    if s.kind == "choice":
        text = f"{p.label}: one of {', '.join(s.choices)}"
    elif s.kind == "text":
        text = f"{p.label} (a name; a catalogue name also sets its properties)"
    else:
        rng = range_text(s.lo, s.hi, "", s.lo_open, s.hi_open) if s.lo is not None else ""
        text = f"{p.label} [{_si_unit(s)}], valid {rng}"
        if s.hi_field:
            text += f", at most the {s.hi_field.replace('_', ' ')}"
        form = s.range_text()
        if form and s.scale != 1.0:  # a percentage or another display unit
            text += f" (the form shows {form})"
    if s.optional:
        text += f"; left out: {s.empty}"
    return text.replace("%", "%%")  # argparse formats help with %


def add_input_options(parser: argparse.ArgumentParser) -> None:
    """Add every design input to ``parser`` (one argument group)."""
    group = parser.add_argument_group(
        "design inputs (SI units, as in a JSON design file; given ones override --config)"
    )
    for o in input_options():
        s = o.spec.spec
        kw: dict[str, Any] = {"dest": o.dest, "help": help_text(o.spec)}
        if s.kind == "choice":
            kw.update(choices=s.choices, metavar="{" + ",".join(s.choices) + "}")
        elif s.kind == "integer":
            kw.update(type=whole, metavar="N")
        elif s.kind == "text":
            kw.update(metavar="NAME")
        else:
            kw.update(type=decimal, metavar="VALUE")
        group.add_argument(o.option, *o.aliases, **kw)


def given_inputs(args: argparse.Namespace) -> dict[str, Any]:
    """{input path: value} of the input options given on the command line."""
    out = {}
    for o in input_options():
        v = getattr(args, o.dest, None)
        if v is not None:
            out[o.path] = v
    return out


def option_of(path: str) -> str:
    """The option of an input path."""
    for o in input_options():
        if o.path == path:
            return o.option
    return path


def option_for_error(exc: InputError, given: dict[str, Any]) -> str | None:
    """The option an input error is about: a given option of the failing field (or, for a field
    used in two places, the one given), else the field's option; None when the error has no
    field."""
    paths = paths_for(exc.owner, exc.field) if exc.owner and exc.field else ()
    for p in paths:
        if p in given:
            return option_of(p)
    return option_of(paths[0]) if paths else None


def _catalogue(part: str) -> dict:
    from aerostat_core.structures.materials import FABRICS, TETHERS

    return TETHERS if part == "tether" else FABRICS if part.endswith("_fabric") else {}


def _fail(exc: InputError, given: dict[str, Any], fallback: list[str]) -> OptionError:
    option = option_for_error(exc, given) or (fallback[0] if fallback else "input")
    return OptionError(option, str(exc))


def apply_requirement(req, given: dict[str, Any]):
    """``req`` with the requirement options of ``given``; :class:`OptionError` naming the
    option."""
    changes = {p.split(".", 1)[1]: v for p, v in given.items() if p.startswith("requirement.")}
    if not changes:
        return req
    try:
        return replace(req, **changes)
    except InputError as exc:
        raise _fail(exc, given, [option_of(f"requirement.{k}") for k in changes]) from None
    except (TypeError, ValueError) as exc:
        raise OptionError(option_of(f"requirement.{next(iter(changes))}"), str(exc)) from None


def apply_configuration(cfg, given: dict[str, Any]):
    """``cfg`` with the configuration options of ``given`` (a catalogue name of a fabric or
    tether takes that item's properties first; a new hull shape without a fineness ratio takes
    the shape's standard one); :class:`OptionError` naming the option."""
    top: dict[str, Any] = {}
    parts: dict[str, dict[str, Any]] = {}
    for path, v in given.items():
        if not path.startswith("configuration."):
            continue
        keys = path.split(".")[1:]
        if len(keys) == 1:
            top[keys[0]] = v
        else:
            parts.setdefault(keys[0], {})[keys[1]] = v
    if not top and not parts:
        return cfg
    new_parts = {}
    for part, fields in parts.items():
        options = [option_of(f"configuration.{part}.{k}") for k in fields]
        obj = getattr(cfg, part)
        try:
            name = fields.get("name")
            if name is not None and name in _catalogue(part):
                obj = _catalogue(part)[name]
                fields = {k: v for k, v in fields.items() if k != "name"}
            if part == "hull" and "shape" in fields and "fineness_ratio" not in fields:
                if fields["shape"] != obj.shape:
                    fields["fineness_ratio"] = None  # the new shape's standard l/d
            new_parts[part] = replace(obj, **fields) if fields else obj
        except InputError as exc:
            raise _fail(exc, given, options) from None
        except (TypeError, ValueError) as exc:
            raise OptionError(options[0], str(exc)) from None
    try:
        return replace(cfg, **new_parts, **top)
    except InputError as exc:
        options = [option_of(f"configuration.{k}") for k in (*top, *parts)]
        raise _fail(exc, given, options) from None
    except (TypeError, ValueError) as exc:
        raise OptionError("configuration options", str(exc)) from None
