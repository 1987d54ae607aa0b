"""Deprecated: the old home of the design form and the text helpers, kept for one release so
pages and views that still import it keep working. New code imports the rooms directly:

* :mod:`app_ui.form_model` - the form as data (fields, keys, groups, conversions, errors);
* :mod:`app_ui.form` - its rendering;
* :mod:`app_ui.text` - plain text helpers (``plain``, ``signed``, ``format_value``, ...);
* :mod:`app_ui.show` - ``feedback`` and ``headlines``.
"""

from __future__ import annotations

from .form import input_form, sync_widgets
from .form_fields import RULE_SETS
from .form_model import (
    CHOICES,
    CUSTOM,
    ERROR_KEY,
    FIELD_BY_KEY,
    FIELDS,
    GROUPS,
    LAYOUT,
    SRC_KEY,
    WIDGET_KEYS,
    Field,
    InputError,
    build_inputs,
    form_error,
    parse_number,
    widget_for,
    widget_values,
)
from .show import feedback, headlines
from .text import constraint_table_rows, format_value, plain, short, signed, speed_ranges

__all__ = [
    "CHOICES",
    "CUSTOM",
    "ERROR_KEY",
    "FIELDS",
    "FIELD_BY_KEY",
    "GROUPS",
    "LAYOUT",
    "RULE_SETS",
    "SRC_KEY",
    "WIDGET_KEYS",
    "Field",
    "InputError",
    "build_inputs",
    "constraint_table_rows",
    "feedback",
    "form_error",
    "format_value",
    "headlines",
    "input_form",
    "parse_number",
    "plain",
    "short",
    "signed",
    "speed_ranges",
    "sync_widgets",
    "widget_for",
    "widget_values",
]
