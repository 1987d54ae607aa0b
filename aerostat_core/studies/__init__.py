"""Studies built on the design model: sensitivity, Monte Carlo uncertainty, the operating
envelope and site wind, the hull-shape comparison and shape optimisation, the fielded-aerostat
harness, the reference numbers, and the Dask scale-out of batch studies.

May import: the physics packages, model, optimize, dynamics.
"""
