"""Envelope/fin fabrics and tethers: the data types and a small catalogue.

Every catalogue value carries its source (:data:`FABRIC_SOURCES`, :data:`TETHER_SOURCES`):
a published figure where one was found, otherwise INFERRED (from a thesis number), ASSUMED (an
engineering choice) or COMPUTED (from the project's own models). Every entry can be replaced by
custom values in the app or a JSON design file.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from aerostat_core.base.fields import number, text, validate
from aerostat_core.base.validation import check_name


@dataclass(frozen=True)
class Fabric:
    """A coated envelope or fin fabric.

    Parameters
    ----------
    name : str
        Label shown in tables.
    areal_density : float
        Mass per area (GSM / 1000) [kg/m2], valid {range:Fabric.areal_density}.
    tensile_strength : float
        Ultimate tensile strength of the laminate, weaker of warp and fill [N/m], valid
        {range:Fabric.tensile_strength}. Default :data:`ASSUMED_TENSILE_STRENGTH` (no strength is published for the
        thesis fabric).
    helium_permeability : float
        Helium permeability at 0 degC, 1 atm of helium partial pressure [L/(m2 day atm)], valid
        {range:Fabric.helium_permeability}. Default :data:`ADRDE_HELIUM_PERMEABILITY`.
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
#: fabric, the calibrated practice laminate): about half of the lightest (150 g/m2 class)
#: laminate measured by Lv et al. 2022, HV150 (82.13 kgf/cm = 80.5 kN/m; the weakest new sample
#: there is FV1175, 76.15 kgf/cm = 74.7 kN/m), i.e. a light coated fabric with a margin for
#: seams. An engineering choice, not a published number.
ASSUMED_TENSILE_STRENGTH = 40000.0
assert Fabric().tensile_strength == ASSUMED_TENSILE_STRENGTH
#: Default helium permeability [L/(m2 day atm)]: the ADRDE envelope figure of 2.5 L/m2/day. Its
#: primary source was NOT found: the only place it was seen is a reference list in the public
#: repository empyrealgalaxy/Aerostat-Sizing (data/reference.js, docs/methods.md S8), which
#: credits "IIT Bombay / ADRDE envelope design papers ... leak 2.5 L/m2/day"; the paper itself
#: was not readable. Kept as the default because it is conservative against the 0.64-0.88
#: L/(m2 day atm) Lv et al. 2022 measured on new laminates, leaving room for seams and valves.
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
        Mass per unstretched length [kg/m], valid {range:TetherSpec.linear_density} (strategic electro-mechanical
        tethers weigh up to a few kg/m).
    diameter : float
        Outer diameter used for drag and air buoyancy [m], valid {range:TetherSpec.diameter}.
    normal_drag_coefficient : float
        Cross-flow drag coefficient C_dn on d per length [-], valid
        {range:TetherSpec.normal_drag_coefficient} (round cable 1.0-1.2).
    tangential_drag_coefficient : float
        Skin-friction coefficient C_dt on the wetted perimeter pi d [-], valid
        {range:TetherSpec.tangential_drag_coefficient}
        (MoorDyn convention).
    breaking_strength : float
        Minimum breaking load [N], valid {range:TetherSpec.breaking_strength}.
    axial_stiffness : float
        EA [N], valid {range:TetherSpec.axial_stiffness} or ``math.inf`` (inextensible).
    """

    name: str = text("Thesis tether (20 g/m)", "")
    linear_density: float = number(
        0.020, "Linear density", "kg/m", 0, 5, lo_open=True, scale=1000.0, display_unit="g/m",
        step=1.0, fmt="%.1f", help="Thesis 20 g/m (6 kg per 300 m).")
    diameter: float = number(
        0.005, "Diameter", "m", 0, 0.1, lo_open=True, scale=1000.0, display_unit="mm",
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


#: Fabric catalogue. Each entry's source, value by value, is in :data:`FABRIC_SOURCES`.
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

#: Lv, Zhou, Zhang, Nie & Wang, "Study of performance of aerostat envelope materials on the
#: coast", Front. Mater. 9:992984 (2022), doi 10.3389/fmats.2022.992984, abstract: new-sample
#: tensile strengths 101.43 (3216LV), 76.15 (FV1175), 82.13 (HV150) kgf/cm; helium
#: permeabilities 0.8818 (3216LV) and 0.6360 (FV1175) L/(m2 day atm), none for HV150.
LV_2022 = "Lv et al. 2022, Front. Mater. 9:992984, doi 10.3389/fmats.2022.992984 (abstract)"
#: Source of every catalogue fabric, field by field: "areal_density", "tensile_strength",
#: "helium_permeability". ASSUMED marks an engineering choice with no published figure behind
#: it (tests/core/test_sources.py checks that every entry and field has one).
FABRIC_SOURCES: dict[str, dict[str, str]] = {
    "Thesis fabric (130 g/m2)": {
        "areal_density": "INFERRED from thesis Table 2.2: 13.54 kg sphere hull / 104.19 m2 "
        "(docs/methods.md §3.2, G3)",
        "tensile_strength": "ASSUMED (ASSUMED_TENSILE_STRENGTH; the thesis gives none)",
        "helium_permeability": "ADRDE 2.5 L/m2/day, second-hand (ADRDE_HELIUM_PERMEABILITY)",
    },
    "Light PU-coated nylon (100 g/m2)": {
        "areal_density": "ASSUMED order of magnitude of a light coated nylon (no data sheet)",
        "tensile_strength": "ASSUMED (ASSUMED_TENSILE_STRENGTH)",
        "helium_permeability": "ADRDE 2.5 L/m2/day, second-hand (ADRDE_HELIUM_PERMEABILITY)",
    },
    "Medium laminate (200 g/m2)": {
        "areal_density": "ASSUMED order of magnitude (no data sheet)",
        "tensile_strength": "ASSUMED (ASSUMED_TENSILE_STRENGTH)",
        "helium_permeability": "ADRDE 2.5 L/m2/day, second-hand (ADRDE_HELIUM_PERMEABILITY)",
    },
    "Heavy laminate (300 g/m2)": {
        "areal_density": "IIT-B/ADRDE range 280-385 g/m2, second-hand (docs/methods.md S8)",
        "tensile_strength": "ASSUMED (ASSUMED_TENSILE_STRENGTH)",
        "helium_permeability": "ADRDE 2.5 L/m2/day, second-hand (ADRDE_HELIUM_PERMEABILITY)",
    },
    "Multi-layer laminate (385 g/m2)": {
        "areal_density": "IIT-B/ADRDE range 280-385 g/m2, second-hand (docs/methods.md S8)",
        "tensile_strength": "ASSUMED (ASSUMED_TENSILE_STRENGTH)",
        "helium_permeability": "ADRDE 2.5 L/m2/day, second-hand (ADRDE_HELIUM_PERMEABILITY)",
    },
    "Uretek 3216LV laminate (Lv 2022)": {
        "areal_density": "ASSUMED 200 g/m2 class (not in Lv 2022; use the data sheet). Lv 2022 "
        "names the laminate 3216LV; the maker 'Uretek' in the label is not in the abstract read",
        "tensile_strength": LV_2022 + ": 101.43 kgf/cm",
        "helium_permeability": LV_2022 + ": 0.8818 L/(m2 day atm)",
    },
    "FV1175 laminate (Lv 2022)": {
        "areal_density": "ASSUMED 200 g/m2 class (not in Lv 2022; use the data sheet)",
        "tensile_strength": LV_2022 + ": 76.15 kgf/cm",
        "helium_permeability": LV_2022 + ": 0.6360 L/(m2 day atm)",
    },
    "HV150 laminate (Lv 2022)": {
        "areal_density": "ASSUMED 150 g/m2 from the name (not in Lv 2022)",
        "tensile_strength": LV_2022 + ": 82.13 kgf/cm",
        "helium_permeability": "not in Lv 2022; ADRDE default kept (ADRDE_HELIUM_PERMEABILITY)",
    },
}
#: The laminates' published figures as Lv et al. 2022 print them (kgf/cm, L/(m2 day atm)), for
#: the tests that check the catalogue against its source.
LV_2022_FIGURES = {
    "Uretek 3216LV laminate (Lv 2022)": (101.43, 0.8818),
    "FV1175 laminate (Lv 2022)": (76.15, 0.6360),
    "HV150 laminate (Lv 2022)": (82.13, None),
}

#: Tether catalogue. Each entry's source is in :data:`TETHER_SOURCES`. No aerostat power or
#: electro-optic tether data sheet with mass per metre, diameter and breaking load was found in
#: the stored sources (searched: Linden Photonics, Elistair, TCOM, tethered-drone cable pages,
#: power/fibre-optic tether patents). The one power tether product with published figures is an
#: underwater one, VideoRay's ROV tethers (:data:`VIDEORAY_TETHERS`); the two Dyneema-based
#: power tethers are COMPUTED examples and the electro-optic tether an ASSUMED order of
#: magnitude, named so in their sources.
TETHERS: dict[str, TetherSpec] = {
    t.name: t
    for t in (
        TetherSpec("Thesis tether (20 g/m)", 0.020, 0.005, 1.0, 0.01, 20000.0, 1.0e6),
        TetherSpec("Dyneema 4 mm (9 g/m)", 0.009, 0.004, 1.0, 0.01, 14000.0, 6.146e5),
        TetherSpec("Dyneema 6 mm (21 g/m)", 0.021, 0.006, 1.0, 0.01, 30000.0, 1.4e6),
        TetherSpec("Electro-optic tether 8 mm (60 g/m)", 0.060, 0.008, 1.2, 0.01, 20000.0, 2.0e6),
        TetherSpec("Power tether 2 x 1.5 mm2 Cu on Dyneema 6 mm (52 g/m)", 0.0520, 0.00656,
                   1.0, 0.01, 30000.0, 1.4e6),
        TetherSpec("Power tether 2 x 2.5 mm2 Cu on Dyneema 6 mm (71 g/m)", 0.0709, 0.00681,
                   1.0, 0.01, 30000.0, 1.4e6),
    )
}

#: VideoRay ROV tethers (docs/methods.md S20), 400 V DC power on two poles of paired conductors inside a Kevlar
#: strength member (kb.videoray.com/knowledge-base/tether-specifications: diameters, minimum
#: bend radii and conductor gauges; .../tether-care-and-handling: "Tether cable = 450 kg (1,000
#: pounds) (internal rated Kevlar)", the maker's maximum strength rating; download.videoray.com
#: MSS Defender manual: Neutral and Performance tethers are "neutrally buoyant in fresh water").
#: name -> (diameter [m], min bend radius [m], AWG of each of the 2 conductors per power pole).
#: Mass per metre is DERIVED from the neutral buoyancy: rho_water pi d^2/4 (fresh water
#: 998 kg/m3 at 20 degC). The Negative tether is left out: its mass is not published.
VIDEORAY_TETHERS = {
    "VideoRay Neutral ROV tether 11.2 mm (400 V DC)": (0.01118, 0.114, 20),
    "VideoRay Performance ROV tether 8.2 mm (400 V DC)": (0.00818, 0.0825, 24),
}
#: [kg] the maker's maximum strength rating of the tether cable (tether-care-and-handling page).
VIDEORAY_STRENGTH_RATING_KG = 450.0
#: [kg/m3] fresh water at 20 degC (the medium the tethers are neutral in).
FRESH_WATER_DENSITY = 998.0


def awg_area(gauge: int) -> float:
    """Cross-section of a solid round wire of American Wire Gauge ``gauge`` [m2].

    d = 0.127 mm x 92^((36 - n)/39) (ASTM B258 definition of the gauge), A = pi d^2/4.

    .. math::

        d = 0.127\\,\\mathrm{mm} \\times 92^{(36 - n)/39}, \\qquad A = \\frac{\\pi d^2}{4}

    Parameters
    ----------
    gauge : int
        AWG number n [-], valid -3 (0000) to 40.

    Returns
    -------
    float [m2]

    Notes
    -----
    Source: ASTM B258 (the gauge's definition); docs/methods.md S20.

    Examples
    --------
    ASTM B258's table gives 0.518 mm2 for AWG 20:

    >>> round(awg_area(20) * 1e6, 4)
    0.5176
    """
    d = 0.127e-3 * 92.0 ** ((36 - gauge) / 39.0)
    return math.pi * d * d / 4.0


TETHERS.update(
    {
        name: TetherSpec(
            name,
            FRESH_WATER_DENSITY * math.pi * d * d / 4.0,
            d,
            1.0,
            0.01,
            VIDEORAY_STRENGTH_RATING_KG * 9.80665,
            5.0e5,
        )
        for name, (d, _, _) in VIDEORAY_TETHERS.items()
    }
)

#: OpenSourceAWE KiteUtils.jl data/settings.yaml, "tether:" block (docs/dynamics.md D12): a
#: 4 mm Dyneema tether, d_tether 4 mm, rho_tether 724 kg/m3 (so 9.10 g/m), axial_stiffness
#: 614600 N, cd_tether 0.958. It gives no breaking load.
KITEUTILS_TETHER = {"diameter": 0.004, "density": 724.0, "axial_stiffness": 614600.0,
                    "drag_coefficient": 0.958}
#: Source of every catalogue tether (one line each: where each number comes from).
TETHER_SOURCES: dict[str, str] = {
    "Thesis tether (20 g/m)": "mass INFERRED from thesis Table 2.2 (6 kg per 300 m); diameter, "
    "strength and EA ASSUMED for a 5 mm HMPE braid (docs/methods.md G10)",
    "Dyneema 4 mm (9 g/m)": "diameter, mass (724 kg/m3) and EA from OpenSourceAWE KiteUtils.jl "
    "data/settings.yaml (docs/dynamics.md D12); C_dn 1.0 and breaking load 14 kN ASSUMED "
    "(typical 4 mm HMPE braid; no data sheet read)",
    "Dyneema 6 mm (21 g/m)": "ASSUMED: the 4 mm entry scaled with d^2 (mass 20.5 g/m) and a "
    "typical 6 mm HMPE breaking load; no data sheet read",
    "Electro-optic tether 8 mm (60 g/m)": "ASSUMED order of magnitude of an electro-optic "
    "aerostat tether; no product data sheet was found",
    "Power tether 2 x 1.5 mm2 Cu on Dyneema 6 mm (52 g/m)": "COMPUTED example, not a product: "
    "the Dyneema 6 mm entry plus two 1.5 mm2 ETFE-insulated copper conductors "
    "(aerostat_core.tether.power.power_tether)",
    "Power tether 2 x 2.5 mm2 Cu on Dyneema 6 mm (71 g/m)": "COMPUTED example, not a product: "
    "the Dyneema 6 mm entry plus two 2.5 mm2 ETFE-insulated copper conductors "
    "(aerostat_core.tether.power.power_tether)",
    **{
        name: "VideoRay LLC ROV tether (underwater product, not an aerostat tether): diameter "
        "and conductor gauge from kb.videoray.com/knowledge-base/tether-specifications; "
        "strength = the maker's 450 kg maximum rating (tether-care-and-handling); mass DERIVED "
        "from its published neutral buoyancy in fresh water; C_dn 1.0 and EA 0.5 MN ASSUMED"
        for name in VIDEORAY_TETHERS
    },
}

#: Copper area of each of the two conductors of the catalogue's power tethers [m2]. These
#: entries are DERIVED (no supplier data sheet was found): the Dyneema 6 mm strength member with
#: a pair of ETFE-insulated (0.25 mm wall) copper conductors, bundled as in
#: aerostat_core.tether.power.power_tether (mass, diameter and strength from IEC 60028 copper and ETFE
#: densities). With ``power_via="tether"`` such a tether's own conductors are used when they
#: are large enough; otherwise a pair sized for the load is added.
POWER_TETHER_CONDUCTORS: dict[str, float] = {
    "Power tether 2 x 1.5 mm2 Cu on Dyneema 6 mm (52 g/m)": 1.5e-6,
    "Power tether 2 x 2.5 mm2 Cu on Dyneema 6 mm (71 g/m)": 2.5e-6,
    # VideoRay: each power pole (400 V DC +, ground) is two conductors of the published gauge
    **{name: 2.0 * awg_area(awg) for name, (_, _, awg) in VIDEORAY_TETHERS.items()},
}


# --- catalogue for selection by load (issue 23; docs/methods.md §1.19) -------------------------
#: DSM Dyneema fact sheet "UHMWPE fiber from DSM Dyneema" (ref. CIS YA100, issued 15-11-2010):
#: tensile strength of SK75/SK78 fibre 3.4-4.0 N/tex; the lower end is used [N/(kg/m)].
HMPE_TENACITY = 3.4e6
#: Kevlar 29 fibre: tensile strength 3.6 GPa at a density of 1.44 g/cm3 (DuPont's grade table
#: as quoted by the University of Bristol chemistry pages, chm.bris.ac.uk ... /edwards) ->
#: 2.5 N/tex [N/(kg/m)].
ARAMID_TENACITY = 3.6e9 / 1440.0
#: Bulk density of a braided HMPE line [kg/m3]: KiteUtils.jl's 4 mm Dyneema tether, 724 kg/m3
#: (KITEUTILS_TETHER), i.e. a fibre fill of 724/970 = 0.746 of the circle (970 kg/m3 HMPE).
HMPE_BRAID_DENSITY = 724.0
#: Fibre fill of a braid [-] (the HMPE figure above), used for aramid braids too (ASSUMED).
BRAID_FILL = HMPE_BRAID_DENSITY / 970.0
#: Realisation efficiency of a braided rope: rope breaking load / (fibre tenacity x rope mass
#: per length) [-]. DERIVED: Marlow Excel D12, 4 mm, 2050 kg breaking load (marlowropes.com
#: product page, as quoted in a totalwind.net forum thread; the page itself was not read) over
#: 3.4 N/tex x 9.1 g/m (the 4 mm braid above): 20.1 kN / 30.9 kN = 0.65.
BRAID_EFFICIENCY = 2050.0 * 9.80665 / (HMPE_TENACITY * HMPE_BRAID_DENSITY * math.pi * 0.004**2 / 4)
#: Axial stiffness of the 4 mm HMPE braid [N] (KiteUtils.jl, KITEUTILS_TETHER); braids of other
#: diameters scale it with the cross-section (d^2), aramid ones with its modulus ratio 83/110
#: (Kevlar 29 83 GPa, chm.bris.ac.uk; Dyneema SK75 109-132 GPa, the DSM fact sheet).
_EA_4MM = 614600.0
#: Braid diameters of the selection catalogue [mm] (common rope sizes).
BRAID_DIAMETERS_MM = (3, 4, 5, 6, 8, 10, 12, 14, 16, 20, 24, 28, 32, 40)


def braid(fibre: str, diameter_mm: float) -> TetherSpec:
    """A braided tether of HMPE ("hmpe") or aramid ("aramid") fibre of diameter ``diameter_mm``.

    .. math::

        m' = \\rho_f\\, \\phi\\, \\pi d^2/4, \\qquad F = \\eta\\, \\tau\\, m', \\qquad
        EA = EA_{4} \\left(d / 4\\,\\mathrm{mm}\\right)^2

    (EA x 83/110 for aramid), with eta = :data:`BRAID_EFFICIENCY` (0.65), phi =
    :data:`BRAID_FILL`, tau the fibre tenacity.

    Parameters
    ----------
    fibre : {"hmpe", "aramid"}
    diameter_mm : float
        Rope diameter [mm], valid (0, 50].

    Notes
    -----
    Valid for a plain braid without jacket (a jacket adds mass, not strength). Sources: the
    constants above (DSM fact sheet, DuPont figures, Marlow D12, KiteUtils.jl).

    Examples
    --------
    >>> t = braid("hmpe", 4)
    >>> round(t.linear_density * 1000, 2), round(t.breaking_strength / 9.80665)
    (9.1, 2050)
    """
    d = diameter_mm / 1000.0
    area = math.pi * d * d / 4.0
    if fibre == "hmpe":
        rho, ten, ea, label = 970.0, HMPE_TENACITY, _EA_4MM, "HMPE (Dyneema SK78)"
    elif fibre == "aramid":
        rho, ten, ea, label = 1440.0, ARAMID_TENACITY, _EA_4MM * 83.0 / 110.0, "aramid (Kevlar 29)"
    else:
        raise ValueError(f"fibre = {fibre!r} is not a braid fibre; valid: 'hmpe', 'aramid'")
    m = rho * BRAID_FILL * area
    return TetherSpec(f"{label} braid {diameter_mm:g} mm ({1000 * m:.0f} g/m)", m, d, 1.0, 0.01,
                      BRAID_EFFICIENCY * ten * m, ea * (diameter_mm / 4.0) ** 2)


#: Laminate family of the selection catalogue: (name, areal density [kg/m2], strength [N/m],
#: helium permeability, source). The two lightest are the laminates of Lv et al. 2022 with the
#: best strength per weight (HV150 at 150 g/m2 by its name; 3216LV, 200 g/m2 ASSUMED); the
#: heavier ones are ASSUMED scalings of the 3216LV construction (strength proportional to areal
#: density, the load-bearing cloth and the barrier films growing together), for the operational
#: and strategic hulls, whose data sheets were not found.
_SPECIFIC_3216LV = 101.43 * _KGF_PER_CM / 0.200  # [N/m per kg/m2]
LAMINATES = (
    ("HV150 laminate (Lv 2022)", 0.150, 82.13 * _KGF_PER_CM, 2.5, LV_2022 + ": 82.13 kgf/cm; "
     "150 g/m2 ASSUMED from the name; permeability not published (ADRDE default)"),
    ("Uretek 3216LV laminate (Lv 2022)", 0.200, 101.43 * _KGF_PER_CM, 0.8818,
     LV_2022 + ": 101.43 kgf/cm, 0.8818 L/(m2 day atm); 200 g/m2 ASSUMED"),
    *((f"Heavy laminate {g} g/m2 (3216LV scaled)", g / 1000.0, _SPECIFIC_3216LV * g / 1000.0,
       0.8818, {"areal_density": f"ASSUMED step of the catalogue ({g} g/m2)",
                "tensile_strength": "COMPUTED: 3216LV's strength per weight (Lv et al. 2022, "
                "101.43 kgf/cm at the 200 g/m2 taken for it) x areal density, a scaling "
                "assumption (no data sheet of a heavy aerostat laminate was found)",
                "helium_permeability": "Lv et al. 2022, 3216LV's 0.8818 L/(m2 day atm)"})
      for g in (300, 400, 550, 700, 900)),
)
#: Fabrics the selection chooses from, lightest first (aerostat_core.model.selection).
SELECTABLE_FABRICS: tuple[Fabric, ...] = tuple(
    Fabric(n, w, s, p) for n, w, s, p, _ in LAMINATES)
#: Tethers the selection chooses from, lightest first: HMPE and aramid braids.
SELECTABLE_TETHERS: tuple[TetherSpec, ...] = tuple(sorted(
    (braid(f, d) for f in ("hmpe", "aramid") for d in BRAID_DIAMETERS_MM),
    key=lambda t: t.linear_density))
for _f in SELECTABLE_FABRICS:
    FABRICS.setdefault(_f.name, _f)
for _n, _w, _s, _p, _src in LAMINATES:
    FABRIC_SOURCES.setdefault(_n, _src if isinstance(_src, dict) else {
        "areal_density": _src, "tensile_strength": _src, "helium_permeability": _src})
for _t in SELECTABLE_TETHERS:
    TETHERS[_t.name] = _t
    TETHER_SOURCES[_t.name] = (
        "DERIVED braid (materials.braid): fibre tenacity from the DSM Dyneema fact sheet "
        "(HMPE 3.4 N/tex) or DuPont's Kevlar 29 figures (3.6 GPa, 1.44 g/cm3); braid fill and "
        "EA from KiteUtils.jl's 4 mm tether; efficiency 0.65 from Marlow Excel D12 4 mm "
        "(2050 kg); C_dn 1.0 ASSUMED")
