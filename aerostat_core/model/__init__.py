"""The static design model: the user's inputs (:mod:`~aerostat_core.model.inputs`) and the rule
sets and presets that complete them, the assembled airframe, trim, performance, the constraint
table, sizing and the public :func:`~aerostat_core.model.design.design` entry point, the mission
systems and their report, the compute budget, gas cost and design files
(:mod:`~aerostat_core.model.io`).

May import: every physics package (base, atmosphere, geometry, aerodynamics, structures,
tether).
"""
