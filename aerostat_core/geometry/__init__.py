"""The hull and fin shapes: the profile library (:mod:`~aerostat_core.geometry.shapes`), hull
geometry and its integrals (:mod:`~aerostat_core.geometry.hull`), the fin planform
(:mod:`~aerostat_core.geometry.fins`) and the added mass of the hull
(:mod:`~aerostat_core.geometry.added_mass`), each with its input spec.

May import: :mod:`aerostat_core.base`, :mod:`aerostat_core.atmosphere.standard`.
"""
