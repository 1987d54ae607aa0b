"""The air and the gas: the standard atmosphere (:mod:`~aerostat_core.atmosphere.standard`), mean
wind profiles (:mod:`~aerostat_core.atmosphere.wind`), lifting-gas density and free lift
(:mod:`~aerostat_core.atmosphere.gas`) and helium permeation through the envelope
(:mod:`~aerostat_core.atmosphere.permeation`), each with its input spec.

May import: :mod:`aerostat_core.base`.
"""
