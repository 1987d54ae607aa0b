"""aerostat_core: conceptual design of tethered aerostats (no UI imports, SI units inside).

Typical use::

    from aerostat_core import Requirement, Configuration, design
    d = design(Requirement(payload_mass=10, altitude=300))
    d.summary()["volume_m3"]
"""

from .design import Design, design
from .inputs import (
    AeroModel,
    Configuration,
    ConfluenceSpec,
    FinSpec,
    HullSpec,
    LiftingGas,
    Requirement,
    WindProfile,
)
from .materials import FABRICS, TETHERS, Fabric, TetherSpec
from .presets import thesis_baseline, thesis_optimised
from .sizing import SizingResult, size_volume

__all__ = [
    "AeroModel", "ConfluenceSpec", "Configuration", "Design", "FABRICS", "Fabric", "FinSpec",
    "HullSpec", "LiftingGas", "Requirement", "SizingResult", "TETHERS", "TetherSpec",
    "WindProfile", "design", "size_volume", "thesis_baseline", "thesis_optimised",
]
