"""Envelope/fin fabrics and tethers: the data types and a small catalogue.

Catalogue values are typical published orders of magnitude, not a supplier's data sheet; every
entry can be replaced by custom values in the app or a JSON design file.
"""

from __future__ import annotations

from dataclasses import dataclass

from .fields import number, text, validate
from .validation import check_name


@dataclass(frozen=True)
class Fabric:
    """A coated envelope or fin fabric.

    Parameters
    ----------
    name : str
        Label shown in tables.
    areal_density : float
        Mass per area (GSM / 1000) [kg/m2], valid (0, 2].
    tensile_strength : float
        Ultimate tensile strength of the laminate, weaker of warp and fill [N/m], valid
        (0, 1e6]. Default :data:`ASSUMED_TENSILE_STRENGTH` (no strength is published for the
        thesis fabric).
    helium_permeability : float
        Helium permeability at 0 degC, 1 atm of helium partial pressure [L/(m2 day atm)], valid
        [0, 100]. Default :data:`ADRDE_HELIUM_PERMEABILITY`.
    """

    name: str = text("Thesis fabric (130 g/m2)", "")
    areal_density: float = number(
        0.130, "Areal density", "kg/m2", 0.0, 2.0, lo_open=True, scale=1000.0,
        display_unit="g/m²", step=10.0, fmt="%.0f", help="Thesis fabric 130 g/m².",
        source="thesis Table 2.2 (INFERRED)")
    tensile_strength: float = number(
        40000.0, "Tensile strength", "N/m", 0.0, 1e6, lo_open=True, scale=1e-3,
        display_unit="kN/m", step=1.0, fmt="%.1f", source="Lv et al. 2022 (ASSUMED default)")
    helium_permeability: float = number(
        2.5, "Helium permeability", "L/(m2 day atm)", 0.0, 100.0, step=0.1, fmt="%.2f",
        source="ADRDE figure (issue 13)")

    def __post_init__(self) -> None:
        object.__setattr__(self, "name", check_name("Fabric", "name", self.name))
        validate(self)


#: Default envelope strength [N/m], ASSUMED for fabrics without a published figure (the thesis
#: fabric, the calibrated practice laminate): half of the weakest aerostat laminate measured by
#: Lv et al. 2022 (HV150, 80.5 kN/m), i.e. a light coated fabric with a margin for seams.
ASSUMED_TENSILE_STRENGTH = 40000.0
assert Fabric().tensile_strength == ASSUMED_TENSILE_STRENGTH
#: Default helium permeability [L/(m2 day atm)]: the ADRDE envelope figure of 2.5 L/m2/day quoted
#: in issue 13 (primary source not located); conservative against the 0.64-0.88 L/(m2 day atm)
#: Lv et al. 2022 measured on new laminates, and it leaves room for seams and valves.
ADRDE_HELIUM_PERMEABILITY = 2.5
assert Fabric().helium_permeability == ADRDE_HELIUM_PERMEABILITY
#: kgf/cm -> N/m (Lv et al. quote strengths in kgf/cm).
_KGF_PER_CM = 9.80665 / 0.01


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

    name: str = text("Thesis tether (20 g/m)", "")
    linear_density: float = number(
        0.020, "Linear density", "kg/m", 0, 1, lo_open=True, scale=1000.0, display_unit="g/m",
        step=1.0, fmt="%.1f", help="Thesis 20 g/m (6 kg per 300 m).")
    diameter: float = number(
        0.005, "Diameter", "m", 0, 0.05, lo_open=True, scale=1000.0, display_unit="mm",
        step=0.5, fmt="%.1f", help="Sets the tether drag and air buoyancy.")
    normal_drag_coefficient: float = number(
        1.0, "Normal drag coefficient", "", 0, 3, lo_open=True, step=0.1, fmt="%.2f",
        help="Cross-flow drag coefficient of the cable (round cable 1.0-1.2).")
    tangential_drag_coefficient: float = number(
        0.01, "Tangential drag coefficient", "", 0, 0.1, step=0.005, fmt="%.3f",
        help="Skin friction on the wetted perimeter (MoorDyn convention).")
    breaking_strength: float = number(
        20000.0, "Breaking strength", "N", 0, 1e7, lo_open=True, scale=1e-3, display_unit="kN",
        step=1.0, fmt="%.2f", help="Minimum breaking load.")
    axial_stiffness: float = number(
        1.0e6, "Axial stiffness EA", "N", 1e3, 1e9, allow_inf=True, scale=1e-3,
        display_unit="kN", step=100.0, fmt="%.0f", help="inf: inextensible.")

    def __post_init__(self) -> None:
        object.__setattr__(self, "name", check_name("TetherSpec", "name", self.name))
        validate(self)


#: Fabric catalogue. Thesis value INFERRED from Table 2.2 (13.54 kg sphere hull / 104.19 m2);
#: heavier laminates from the IIT-B/ADRDE range 280-385 g/m2 (docs/methods.md S8). Strengths and
#: helium permeabilities: the generic entries take the assumed defaults above; the three named
#: laminates are the new-sample values of Lv, Zhou, Zhang, Nie & Wang, "Study of performance of
#: aerostat envelope materials on the coast", Front. Mater. 9:992984 (2022), doi
#: 10.3389/fmats.2022.992984 (3216LV 101.43 kgf/cm and 0.8818 L/(m2 day atm); FV1175 76.15
#: kgf/cm and 0.6360; HV150 82.13 kgf/cm, permeability not given, default kept). Their areal
#: densities are not in that paper: 3216LV and FV1175 take the 200 g/m2 class of the catalogue
#: and HV150 150 g/m2 from its name (ASSUMED, replace with the supplier's data sheet).
FABRICS: dict[str, Fabric] = {
    f.name: f
    for f in (
        Fabric("Thesis fabric (130 g/m2)", 0.130),
        Fabric("Light PU-coated nylon (100 g/m2)", 0.100),
        Fabric("Medium laminate (200 g/m2)", 0.200),
        Fabric("Heavy laminate (300 g/m2)", 0.300),
        Fabric("Multi-layer laminate (385 g/m2)", 0.385),
        Fabric("Uretek 3216LV laminate (Lv 2022)", 0.200, 101.43 * _KGF_PER_CM, 0.8818),
        Fabric("FV1175 laminate (Lv 2022)", 0.200, 76.15 * _KGF_PER_CM, 0.6360),
        Fabric("HV150 laminate (Lv 2022)", 0.150, 82.13 * _KGF_PER_CM),
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
        TetherSpec("Power tether 2 x 1.5 mm2 Cu on Dyneema 6 mm (52 g/m)", 0.0520, 0.00656,
                   1.0, 0.01, 30207.0, 1.4e6),
        TetherSpec("Power tether 2 x 2.5 mm2 Cu on Dyneema 6 mm (71 g/m)", 0.0709, 0.00681,
                   1.0, 0.01, 30345.0, 1.4e6),
    )
}

#: Copper area of each of the two conductors of the catalogue's power tethers [m2]. These
#: entries are DERIVED (no supplier data sheet was found): the Dyneema 6 mm strength member with
#: a pair of ETFE-insulated (0.25 mm wall) copper conductors, bundled as in
#: aerostat_core.power.power_tether (mass, diameter and strength from IEC 60028 copper and ETFE
#: densities). With ``power_via="tether"`` such a tether's own conductors are used when they
#: are large enough; otherwise a pair sized for the load is added.
POWER_TETHER_CONDUCTORS: dict[str, float] = {
    "Power tether 2 x 1.5 mm2 Cu on Dyneema 6 mm (52 g/m)": 1.5e-6,
    "Power tether 2 x 2.5 mm2 Cu on Dyneema 6 mm (71 g/m)": 2.5e-6,
}
