"""aerostat_core: conceptual design of tethered aerostats (no UI imports, SI units inside).

Typical use::

    from aerostat_core import Requirement, Configuration, design
    d = design(Requirement(payload_mass=10, altitude=300))
    d.summary().volume_m3
"""

from .deprecation import deprecated_aliases
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
from .presets import thesis_baseline, thesis_optimized
from .sizing import SizingResult, size_volume

__all__ = [
    "AeroModel", "ConfluenceSpec", "Configuration", "Design", "FABRICS", "Fabric", "FinSpec",
    "HullSpec", "LiftingGas", "Requirement", "SizingResult", "TETHERS", "TetherSpec",
    "WindProfile", "design", "size_volume", "thesis_baseline", "thesis_optimized",
]

#: Deprecated British spelling -> the current name (docs/architecture.md §7).
DEPRECATED_NAMES = {"thesis_optimised": "thesis_optimized"}

__getattr__ = deprecated_aliases(__name__, globals(), DEPRECATED_NAMES)
