"""Forces of the air on the body: hull and fin loads versus incidence
(:mod:`~aerostat_core.aerodynamics.forces`), zero-lift hull drag
(:mod:`~aerostat_core.aerodynamics.drag`) and the kite balloon's sail and keel
(:mod:`~aerostat_core.aerodynamics.helikite`).

May import: base, atmosphere, geometry.
"""
