"""The design form's field table: which widget key shows which input path, in which group
and order. Label, unit, display scale, step, format and help of each widget come from the core's
field registry (:mod:`aerostat_core.base.fields`); nothing about an input is typed here. No Streamlit
import. Conversions and errors: :mod:`app_ui.form_model`."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from aerostat_core.geometry.shapes import SHAPE_INFO
from aerostat_core.model.input_paths import PathSpec, spec_for_path
from aerostat_core.model.rules import RULE_SETS

from . import formats
from .text import short

CUSTOM = "Custom"
#: Where the last rejected submit's message goes: {"group": str, "text": str, "key": str}.
ERROR_KEY = "input_error"
#: The inputs dict the widgets were last filled from.
SRC_KEY = "_widgets_src"

GROUPS = {
    "requirement": "Requirement",
    "wind": "Wind and operating limits",
    "gas": "Lifting gas",
    "materials": "Materials",
    "configuration": "Configuration (design variables)",
    "advanced": "Advanced model parameters",
}

#: Groups open when a session starts; the others are drawn only once opened (lazy expanders:
#: their widgets keep their values while closed). The wind group starts closed: its 13 boxes
#: default to the rule set's values, which the verdict and the constraint table show, and they
#: were the page's largest block of widgets (a fresh browser's first result 130-280 ms later,
#: "Update design" about 65 ms later with it open; benchmarks/bench_app.py, 2026-12-03).
OPEN_GROUPS = ("requirement", "configuration")


def group_key(group: str) -> str:
    """Session-state key of a form group's expander (True while it is open)."""
    return f"form_group_{group}"


class InputError(ValueError):
    """A rejected form input; ``group`` is a key of :data:`GROUPS`, ``key`` the widget's key
    when the problem is one box. The message uses the form's label and unit."""

    def __init__(self, group: str, message: str, key: str | None = None) -> None:
        super().__init__(short(message))
        self.group = group
        self.key = key


@dataclass(frozen=True)
class Field:
    """One numeric widget: its key, the input path it shows and its group. Label, unit,
    display scale (``display = SI value * scale``), step, format and help come from the field
    registry; ``note`` replaces the registry's "(empty = ...)" hint where the form has its own
    way to leave the value open (the volume's Given/Sized choice)."""

    key: str
    path: str
    group: str
    note: str | None = None

    @cached_property
    def entry(self) -> PathSpec:
        return spec_for_path(self.path)

    @property
    def unit(self) -> str:
        """The SI display unit (see :meth:`unit_in` for a unit system)."""
        return self.unit_in("SI")

    @property
    def label(self) -> str:
        """The SI label (see :meth:`label_in`)."""
        return self.label_in("SI")

    def unit_in(self, system: str) -> str:
        """The unit of the box in unit system ``system`` ("ft" for the altitude in "US")."""
        return formats.box_unit(self.entry.spec, system)

    def label_in(self, system: str) -> str:
        """The box's label in unit system ``system`` (the altitude's unit reads [ft] in US)."""
        s = self.entry.spec
        note = self.note if self.note is not None else (f"empty = {s.empty}" if s.empty else "")
        return f"{self.entry.label} [{self.unit_in(system)}]" + (f" ({note})" if note else "")

    def text_of(self, si: Any, system: str = "SI") -> str:
        """An SI value as the text of this box in ``system`` (:func:`app_ui.formats.box_text`)."""
        return formats.box_text(si, self.entry.spec, system)

    def to_si(self, x: float, system: str = "SI") -> float:
        """A number typed in this box (``system``'s unit) in SI, to 12 significant digits."""
        return formats.box_to_si(x, self.entry.spec, system)

    def shown(self, si: float, system: str = "SI") -> float:
        """An SI value in this box's unit in ``system`` (unrounded)."""
        return formats.field_unit(self.entry.spec, system).show(si)

    @property
    def scale(self) -> float:
        return float(self.entry.spec.scale)

    @property
    def step(self) -> float:
        return self.entry.spec.step or 1.0

    @property
    def fmt(self) -> str:
        return self.entry.spec.fmt

    @property
    def optional(self) -> bool:
        return self.entry.spec.optional and self.note is None

    @property
    def integer(self) -> bool:
        return self.entry.spec.integer

    @property
    def help(self) -> str:
        """The SI help (see :meth:`help_in`)."""
        return self.help_in("SI")

    def help_in(self, system: str) -> str:
        """The registry's help, plus the valid range in ``system``'s display units (not for a
        range that depends on another field: the help says it)."""
        s = self.entry.spec
        rng = s.range_text(system) if s.checked and not s.hi_field else ""
        return f"{s.help} Valid {rng}.".strip() if rng else s.help


#: Numeric widgets: group -> (key, input path) in display order. Selects and the fabric/tether
#: choices are handled separately (:data:`CHOICES`, :data:`LAYOUT`).
_NUMBERS: dict[str, tuple[tuple[str, str], ...]] = {
    "requirement": (
        ("in_payload", "requirement.payload_mass"),
        ("in_altitude", "requirement.altitude"),
        ("in_site", "requirement.site_elevation"),
        ("in_isa", "requirement.isa_offset"),
        ("in_site_temp", "requirement.site_temperature"),
    ),
    "wind": (
        ("in_wind_max", "requirement.wind_max"),
        ("in_wind_step", "requirement.wind_step"),
        ("in_design_wind", "requirement.design_wind"),
        ("in_survival_wind", "requirement.survival_wind"),
        ("in_blow_by", "requirement.blow_by_limit"),
        ("in_loss_limit", "requirement.altitude_loss_limit"),
        ("in_free_lift", "requirement.free_lift_fraction"),
        ("in_min_sf", "requirement.min_tether_safety_factor"),
        ("in_survival_sf", "requirement.survival_safety_factor"),
        ("in_max_angle", "requirement.max_tether_angle_deg"),
        ("in_wv_margin", "requirement.weathervane_margin"),
        ("in_top_up", "requirement.top_up_interval_days"),
        ("in_confidence", "requirement.confidence"),
    ),
    "gas": (
        ("in_purity", "configuration.gas.purity"),
        ("in_superpressure", "configuration.gas.superpressure"),
        ("in_fixed_density", "configuration.gas.fixed_density"),
        ("in_gas_price", "configuration.gas_price"),
    ),
    "materials": (
        ("in_hull_gsm", "configuration.hull_fabric.areal_density"),
        ("in_fin_gsm", "configuration.fin_fabric.areal_density"),
        ("in_tether_lin", "configuration.tether.linear_density"),
        ("in_tether_dia", "configuration.tether.diameter"),
        ("in_tether_mbl", "configuration.tether.breaking_strength"),
        ("in_tether_cd", "configuration.tether.normal_drag_coefficient"),
    ),
    "configuration": (
        ("in_volume", "configuration.hull.volume"),
        ("in_fineness", "configuration.hull.fineness_ratio"),
        ("in_fin_area", "configuration.fins.area_change"),
        ("in_fin_pos", "configuration.fins.position"),
        ("in_nose", "configuration.hull.nose_fraction"),
    ),
    "advanced": (
        ("in_fin_ratio", "configuration.fins.area_ratio"),
        ("in_fin_ar", "configuration.fins.aspect_ratio"),
        ("in_fin_taper", "configuration.fins.taper_ratio"),
        ("in_fin_fabric_factor", "configuration.fins.fabric_factor"),
        ("in_misc", "configuration.misc_mass_ratio"),
        ("in_eta_k", "configuration.aero.hull_efficiency"),
        ("in_cdc", "configuration.aero.hull_crossflow_drag"),
        ("in_cdv", "configuration.aero.hull_axial_drag"),
        ("in_eta_f", "configuration.aero.fin_efficiency"),
        ("in_cla", "configuration.aero.section_lift_slope"),
        ("in_cd0_fin", "configuration.aero.fin_zero_lift_drag"),
        ("in_stall", "configuration.aero.fin_stall_angle_deg"),
        ("in_drop", "configuration.confluence.drop_ratio"),
        ("in_xi_off", "configuration.confluence.xi_offset"),
        ("in_wind_exp", "configuration.wind_profile.exponent"),
        ("in_z0", "configuration.wind_profile.roughness_length"),
        ("in_segments", "configuration.tether_segments"),
    ),
}
#: Form-only notes on a label (the form leaves these open another way).
_NOTES = {"in_volume": "when given"}

FIELDS: tuple[Field, ...] = tuple(
    Field(key, path, group, _NOTES.get(key))
    for group, rows in _NUMBERS.items()
    for key, path in rows
)
FIELD_BY_KEY = {f.key: f for f in FIELDS}


@dataclass(frozen=True)
class Choice:
    """One select or radio widget: key, input path, group and the text shown for each option;
    the label and help come from the field registry."""

    key: str
    path: str
    group: str
    options: Mapping[str, str]

    @cached_property
    def entry(self) -> PathSpec:
        """The registry entry (looked up once: the form draws every choice on every run)."""
        return spec_for_path(self.path)

    @property
    def label(self) -> str:
        return self.entry.label

    @property
    def help(self) -> str:
        return self.entry.spec.help


CHOICES: dict[str, Choice] = {
    c.key: c
    for c in (
        Choice(
            "in_rules",
            "requirement.rules",
            "requirement",
            {name: r.title for name, r in RULE_SETS.items()},
        ),
        Choice(
            "in_shape",
            "configuration.hull.shape",
            "configuration",
            {k: v.label for k, v in SHAPE_INFO.items()},
        ),
        Choice(
            "in_gas_kind",
            "configuration.gas.kind",
            "gas",
            {"helium": "Helium", "hydrogen": "Hydrogen"},
        ),
        Choice(
            "in_density_model",
            "configuration.gas.density_model",
            "gas",
            {
                "ideal": "Ideal gas at altitude (physics)",
                "fixed": "Fixed density (thesis constants)",
            },
        ),
        Choice(
            "in_arrangement",
            "configuration.fins.arrangement",
            "configuration",
            {"+": "4 fins, + (cross)", "x": "4 fins, x", "inverted-y": "3 fins, inverted Y"},
        ),
        Choice(
            "in_cutoff",
            "configuration.aero.cutoff",
            "advanced",
            {"fin": "At the fin root (thesis symbol list)", "tail": "At the tail"},
        ),
        Choice(
            "in_wind_kind",
            "configuration.wind_profile.kind",
            "advanced",
            {"uniform": "Uniform (thesis plots)", "power": "Power law", "log": "Log law"},
        ),
    )
}

VOLUME_MODE_KEY = "in_volume_mode"
VOLUME_MODES = {"given": "Given", "sized": "Sized: smallest hull meeting every constraint"}
HULL_FABRIC_KEY, FIN_FABRIC_KEY, TETHER_KEY = "in_hull_fabric", "in_fin_fabric", "in_tether"
SUBMIT_KEY = "in_submit"

WIDGET_KEYS: tuple[str, ...] = (
    *FIELD_BY_KEY,
    *CHOICES,
    VOLUME_MODE_KEY,
    HULL_FABRIC_KEY,
    FIN_FABRIC_KEY,
    TETHER_KEY,
)


def _keys(group: str) -> tuple[str, ...]:
    return tuple(key for key, _path in _NUMBERS[group])


#: Form layout: group -> widgets in order (field keys, choice keys, or the special keys).
LAYOUT: dict[str, tuple[str, ...]] = {
    "requirement": ("in_rules", *_keys("requirement")),
    "wind": (*_keys("wind")[2:], *_keys("wind")[:2]),  # the limits first, the sweep last
    "configuration": (
        "in_shape",
        VOLUME_MODE_KEY,
        *_keys("configuration")[:4],
        "in_arrangement",
        *_keys("configuration")[4:],
    ),
    "gas": ("in_gas_kind", "in_density_model", *_keys("gas")),
    "materials": (
        HULL_FABRIC_KEY,
        "in_hull_gsm",
        FIN_FABRIC_KEY,
        "in_fin_gsm",
        TETHER_KEY,
        "in_tether_lin",
        "in_tether_dia",
        "in_tether_mbl",
        "in_tether_cd",
    ),
    "advanced": ("in_cutoff", "in_wind_kind", *_keys("advanced")),
}
