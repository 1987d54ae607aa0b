"""aerostat_core: conceptual design of tethered aerostats (no UI imports, SI units inside).

Typical use::

    from aerostat_core import Requirement, Configuration, design
    d = design(Requirement(payload_mass=10, altitude=300))
    d.summary().volume_m3
"""

from aerostat_core.base.deprecation import deprecated_aliases
from aerostat_core.model.design import Design, design
from aerostat_core.model.inputs import (
    AeroModel,
    Configuration,
    ConfluenceSpec,
    FinSpec,
    HullSpec,
    LiftingGas,
    Requirement,
    WindProfile,
)
from aerostat_core.model.presets import thesis_baseline, thesis_optimized
from aerostat_core.model.sizing import SizingResult, size_volume
from aerostat_core.structures.materials import FABRICS, TETHERS, Fabric, TetherSpec

__all__ = [
    "AeroModel", "ConfluenceSpec", "Configuration", "Design", "FABRICS", "Fabric", "FinSpec",
    "HullSpec", "LiftingGas", "Requirement", "SizingResult", "TETHERS", "TetherSpec",
    "WindProfile", "design", "size_volume", "thesis_baseline", "thesis_optimized",
]

#: Deprecated British spelling -> the current name (docs/architecture.md §7).
DEPRECATED_NAMES = {"thesis_optimised": "thesis_optimized"}

__getattr__ = deprecated_aliases(__name__, globals(), DEPRECATED_NAMES)
