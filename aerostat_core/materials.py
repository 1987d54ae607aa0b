"""Envelope/fin fabrics and tethers: the data types and a small catalogue.

Catalogue values are typical published orders of magnitude, not a supplier's data sheet; every
entry can be replaced by custom values in the app or a JSON design file.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .validation import check_name, check_number


@dataclass(frozen=True)
class Fabric:
    """A coated envelope or fin fabric.

    Parameters
    ----------
    name : str
        Label shown in tables.
    areal_density : float
        Mass per area (GSM / 1000) [kg/m2], valid (0, 2].
    """

    name: str = "Thesis fabric (130 g/m2)"
    areal_density: float = 0.130

    def __post_init__(self) -> None:
        object.__setattr__(self, "name", check_name("Fabric", "name", self.name))
        check_number("Fabric", "areal_density", self.areal_density, 0.0, 2.0, "kg/m2", lo_open=True)


@dataclass(frozen=True)
class TetherSpec:
    """A tether cable.

    Parameters
    ----------
    name : str
        Label shown in tables.
    linear_density : float
        Mass per unstretched length [kg/m], valid (0, 1].
    diameter : float
        Outer diameter used for drag and air buoyancy [m], valid (0, 0.05].
    normal_drag_coefficient : float
        Cross-flow drag coefficient C_dn on d per length [-], valid (0, 3] (round cable 1.0-1.2).
    tangential_drag_coefficient : float
        Skin-friction coefficient C_dt on the wetted perimeter pi d [-], valid [0, 0.1]
        (MoorDyn convention).
    breaking_strength : float
        Minimum breaking load [N], valid (0, 1e7].
    axial_stiffness : float
        EA [N], valid [1e3, 1e9] or ``math.inf`` (inextensible).
    """

    name: str = "Thesis tether (20 g/m)"
    linear_density: float = 0.020
    diameter: float = 0.005
    normal_drag_coefficient: float = 1.0
    tangential_drag_coefficient: float = 0.01
    breaking_strength: float = 20000.0
    axial_stiffness: float = 1.0e6

    def __post_init__(self) -> None:
        object.__setattr__(self, "name", check_name("TetherSpec", "name", self.name))
        o = "TetherSpec"
        check_number(o, "linear_density", self.linear_density, 0, 1, "kg/m", lo_open=True)
        check_number(o, "diameter", self.diameter, 0, 0.05, "m", lo_open=True)
        check_number(o, "normal_drag_coefficient", self.normal_drag_coefficient, 0, 3, lo_open=True)
        check_number(o, "tangential_drag_coefficient", self.tangential_drag_coefficient, 0, 0.1)
        check_number(o, "breaking_strength", self.breaking_strength, 0, 1e7, "N", lo_open=True)
        if self.axial_stiffness != math.inf:
            check_number(o, "axial_stiffness", self.axial_stiffness, 1e3, 1e9, "N")


#: Fabric catalogue. Thesis value INFERRED from Table 2.2 (13.54 kg sphere hull / 104.19 m2);
#: heavier laminates from the IIT-B/ADRDE range 280-385 g/m2 (docs/methods.md S8).
FABRICS: dict[str, Fabric] = {
    f.name: f
    for f in (
        Fabric("Thesis fabric (130 g/m2)", 0.130),
        Fabric("Light PU-coated nylon (100 g/m2)", 0.100),
        Fabric("Medium laminate (200 g/m2)", 0.200),
        Fabric("Heavy laminate (300 g/m2)", 0.300),
        Fabric("Multi-layer laminate (385 g/m2)", 0.385),
    )
}

#: Tether catalogue. The thesis tether mass (20 g/m, 6 kg per 300 m) is INFERRED from Table 2.2;
#: its diameter, strength and stiffness are assumed (docs/methods.md G10): 20 kN is the order of a
#: 5 mm HMPE (Dyneema-type) braid, which weighs about 15-20 g/m. The 4 mm Dyneema data come
#: from OpenSourceAWE KiteModels settings (docs/dynamics.md D12); breaking loads are typical values.
TETHERS: dict[str, TetherSpec] = {
    t.name: t
    for t in (
        TetherSpec("Thesis tether (20 g/m)", 0.020, 0.005, 1.0, 0.01, 20000.0, 1.0e6),
        TetherSpec("Dyneema 4 mm (9 g/m)", 0.009, 0.004, 1.0, 0.01, 14000.0, 6.146e5),
        TetherSpec("Dyneema 6 mm (21 g/m)", 0.021, 0.006, 1.0, 0.01, 30000.0, 1.4e6),
        TetherSpec("Electro-optic tether 8 mm (60 g/m)", 0.060, 0.008, 1.2, 0.01, 20000.0, 2.0e6),
    )
}
