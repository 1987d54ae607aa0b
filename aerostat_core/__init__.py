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

# Ranges in docstrings come from the field registry: now that every input class is defined, each
# "{range:Owner.field}" in a loaded core module's docstrings becomes the field's range
# (base/fields.py fill_range_docs; a physics function may so quote an input of a package above).
import sys as _sys  # noqa: E402

from aerostat_core.base.fields import fill_range_docs as _fill_range_docs  # noqa: E402

_fill_range_docs([_m for _n, _m in list(_sys.modules.items())
                  if _n.startswith("aerostat_core.") and _m is not None])
