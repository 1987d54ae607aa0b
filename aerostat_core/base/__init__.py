"""Foundations every other package stands on: physical constants with their sources
(:mod:`~aerostat_core.base.constants`), the field registry that gives each input its label, unit
and valid range (:mod:`~aerostat_core.base.fields`), the input checks and their one message
format (:mod:`~aerostat_core.base.validation`) and deprecated aliases
(:mod:`~aerostat_core.base.deprecation`).

May import: the standard library and numpy only; no other package of aerostat_core.
"""
