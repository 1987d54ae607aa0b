"""The line to the ground: the static tether march (:mod:`~aerostat_core.tether.statics`), power
through the tether or on board (:mod:`~aerostat_core.tether.power`) and the winch
(:mod:`~aerostat_core.tether.winch`). The tether in motion is :mod:`aerostat_core.dynamics.tether`.

May import: base, atmosphere, geometry, aerodynamics, structures.
"""
