"""Deprecated alias (one release): the model now lives in :mod:`.bodies` (point aerostat, hull),
:mod:`.kernel` (the equations of motion) and :mod:`.system` (the assembled system). Import from
those, or from :mod:`aerostat_core.dynamics`."""

from .bodies import (
    ALPHA_STEP,
    TABLE_KEYS,
    HullModel,
    PointAerostat,
    ellipsoid_hull,
    hull_from_airframe,
    lamb_added_mass,
    point_from_design,
)
from .kernel import DIAG_NAMES, ND, rhs_kernel
from .system import Atmosphere, DynamicSystem, dense_jacobian, system_from_design

__all__ = ["ALPHA_STEP", "DIAG_NAMES", "ND", "TABLE_KEYS", "Atmosphere", "DynamicSystem",
           "HullModel", "PointAerostat", "dense_jacobian", "ellipsoid_hull", "hull_from_airframe",
           "lamb_added_mass", "point_from_design", "rhs_kernel", "system_from_design"]
