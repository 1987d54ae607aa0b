"""What the hull is made of and what it weighs: the fabric and tether catalogue
(:mod:`~aerostat_core.structures.materials`), the pressurised envelope's membrane loads
(:mod:`~aerostat_core.structures.membrane`), the mass budget (:mod:`~aerostat_core.structures.mass`)
and the ballonet (:mod:`~aerostat_core.structures.ballonet`).

May import: base, atmosphere, geometry, aerodynamics.
"""
