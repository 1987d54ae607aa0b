"""Physical constants and documented default coefficients, each with its unit and source.

Every module imports its constants from here so that a value is typed once. Values tagged
*INFERRED* or *calibrated* are documented in ``presets.py`` and in docs/methods.md §3.
"""

from __future__ import annotations

import math

# --- Fundamental ---------------------------------------------------------------------------
#: Standard gravity [m/s2]. Source: ISO 2533:1975 (ISA), CGPM 1901.
G0 = 9.80665
#: Universal gas constant [J/(mol K)]. Source: CODATA 2018 (exact).
R_UNIVERSAL = 8.314462618
#: Molar mass of dry air [kg/mol]. Source: ISO 2533:1975.
M_AIR = 0.0289644
#: Specific gas constant of dry air [J/(kg K)], R_UNIVERSAL / M_AIR as used by ISA (287.05287).
R_AIR = 287.05287
#: Molar mass of helium-4 [kg/mol]. Source: IUPAC 2013 standard atomic weight.
M_HELIUM = 4.002602e-3
#: Molar mass of hydrogen H2 [kg/mol]. Source: IUPAC 2013 (2 x 1.00794).
M_HYDROGEN = 2.01588e-3

# --- International Standard Atmosphere (troposphere) ---------------------------------------
#: Sea-level ISA temperature [K]. Source: ISO 2533:1975.
ISA_T0 = 288.15
#: Sea-level ISA pressure [Pa]. Source: ISO 2533:1975.
ISA_P0 = 101325.0
#: Tropospheric temperature lapse rate [K/m] (temperature falls with height). Source: ISO 2533:1975.
ISA_LAPSE = 0.0065
#: Upper limit of the troposphere model used here [m] (geopotential). Source: ISO 2533:1975.
ISA_TROPOPAUSE = 11000.0
#: Earth radius used to convert geometric to geopotential altitude [m]. Source: ISO 2533:1975.
ISA_EARTH_RADIUS = 6356766.0
#: Lowest altitude accepted by the atmosphere model [m] (Dead Sea shore is about -430 m).
ISA_MIN_ALTITUDE = -500.0
#: Sutherland's law reference constant [kg/(m s K^0.5)]. Source: U.S. Standard Atmosphere 1976.
SUTHERLAND_BETA = 1.458e-6
#: Sutherland temperature [K]. Source: U.S. Standard Atmosphere 1976.
SUTHERLAND_S = 110.4

# --- Thesis constants (Mahmood 2020, seed text) ----------------------------------------------
#: Helium density the thesis uses for gas mass [kg/m3] (Table 2.5; 16.9 kg per 100 m3 in Table 2.2).
THESIS_HELIUM_DENSITY = 0.169
#: Hydrogen density the thesis lists [kg/m3] (Table 2.5).
THESIS_HYDROGEN_DENSITY = 0.085
#: Helium price [USD/m3], INFERRED: USD 1925 saved for 50 m3 less volume (thesis abstract, App. H).
HELIUM_PRICE_USD_PER_M3 = 38.5
#: Hydrogen price [USD/m3]. Assumed order of magnitude for industrial cylinders (not from the
#: thesis).
HYDROGEN_PRICE_USD_PER_M3 = 10.0

# --- Aerodynamic defaults (docs/methods.md §1.7, sources S1, S6, S10, S11) ---------------------------
#: Jones & DeLaurier hull efficiency factor eta_k [-] (S6, YEZ-2A value).
HULL_EFFICIENCY = 1.19
#: Hull cross-flow drag coefficient (C_dc)_h [-] (S6; 0.32 Skyship-type value).
HULL_CROSSFLOW_DRAG = 0.32
#: Fin efficiency eta_f used with a 3-D (Helmbold/DATCOM) lift slope [-] (docs/methods.md G7).
#: Why not the Jones & DeLaurier / Gomes pairing of the design notes (eta_f = 0.29 on a section
#: slope of 5.73 /rad, i.e. 1.66 /rad per fin pair): there eta_f lumps the finite-span loss and
#: the hull-fin interference into one factor fitted to a 2-D slope. Here the finite-span loss is
#: already in the Helmbold slope (2.60 /rad at aspect ratio 2; Helmbold 1942, USAF DATCOM
#: §4.1.3.2), so 0.29 on top would count it twice; the interference that remains (typically a
#: 10-30 % loss on a fin pair at the hull, DATCOM §4.3.1) is NOT modelled, is listed as an
#: uncertainty in docs/validation.md, and is covered in the "practice" rules by the weathervane
#: margin (aerostat_core.model.rules).
FIN_EFFICIENCY = 1.0
#: Two-dimensional section lift slope [1/rad] (thin-aerofoil theory, 2 pi).
SECTION_LIFT_SLOPE = 2.0 * math.pi
#: Fin zero-lift drag coefficient on planform area [-] (S6: 0.003-0.010).
FIN_ZERO_LIFT_DRAG = 0.008
#: Fin stall angle [deg] for low-aspect-ratio fins (docs/methods.md §1.7: 15-20 deg).
FIN_STALL_ANGLE_DEG = 20.0
#: Smallest Reynolds number used in Hoerner's drag law [-]; guards the V -> 0 limit where q -> 0.
MIN_REYNOLDS = 1.0e4

# --- Helikite-style kite balloon (issue 12; aerostat_core.aerodynamics.helikite) ----------------------------
#: Thesis Table 2.2 Helikite reference (Allsopp Helikites "Aerostar", via the thesis): 100 m3 hull,
#: 6.2 m x 5 m, kite (sail, spars, keel) 11.38 kg, dynamic lift 48 kg at 15 m/s at 300 m, C_D 0.2.
HELIKITE_REF_VOLUME = 100.0
#: [kg] kite mass of the reference (Table 2.2).
HELIKITE_REF_KITE_MASS = 11.38
#: [kg] dynamic lift of the reference at HELIKITE_REF_WIND (Table 2.2).
HELIKITE_REF_DYNAMIC_LIFT_KG = 48.0
#: [m/s] wind of the reference dynamic lift (Table 2.2, "at 15 m/s").
HELIKITE_REF_WIND = 15.0
#: [m] altitude of the reference (Table 2.2; ISA density there sets q).
HELIKITE_REF_ALTITUDE = 300.0
#: Kite sail aspect ratio [-]. ASSUMED (low-aspect-ratio sail on a Helikite; not in the thesis).
HELIKITE_KITE_ASPECT_RATIO = 1.5
#: Kite incidence to the wind held by the bridle [deg]. ASSUMED (typical kite bridle angle).
HELIKITE_KITE_INCIDENCE_DEG = 15.0
#: [m/s] Helikite wind limit (thesis Table 2.1, "wind conditions 25 m/s").
HELIKITE_MAX_WIND = 25.0
#: [kg] Helikite payload limit (thesis Table 2.1, "< 30 kg").
HELIKITE_MAX_PAYLOAD = 30.0
#: [m] Helikite operating altitude (thesis Table 2.1, "~2 km").
HELIKITE_MAX_ALTITUDE = 2000.0

# --- Mission: power, endurance, structure, winch (aerostat_core.model.mission, issue 13) -----------
#: Resistivity of annealed copper at 20 degC [ohm m]. Source: IEC 60028 (International Annealed
#: Copper Standard, 1/58 ohm mm2/m).
COPPER_RESISTIVITY = 1.0 / 58.0e6
#: Density of annealed copper [kg/m3]. Source: IEC 60028 (8.89 g/cm3).
COPPER_DENSITY = 8890.0
#: Yield strength of annealed copper (C11000, O temper) [Pa]: the stress copper conductors carry
#: when the strength member of a power tether breaks at a few % strain (they have long yielded).
#: Source: ASM Handbook Vol. 2 (C11000 annealed, 69 MPa).
COPPER_YIELD_STRENGTH = 69.0e6
#: Density of ETFE conductor insulation [kg/m3]. Source: Chemours Tefzel ETFE data (1.70 g/cm3).
ETFE_DENSITY = 1700.0
#: Standard conditions of gas-permeability and gas-volume figures: 0 degC, 1 atm [K], [Pa].
STANDARD_TEMPERATURE = 273.15
STANDARD_PRESSURE = 101325.0
#: Hours per day and seconds per day.
HOURS_PER_DAY = 24.0
SECONDS_PER_DAY = 86400.0
#: Reel speed of DC-motor winches for synthetic tethers [m/s]: "The DC Electric motors are used
#: for synthetic tethers that can provide extension and retrieval speeds around 60 feet per
#: minutes" (thesis §2.2.4, read in the seed text; the thesis cites no source for the figure)
#: = 0.3048 m/s.
THESIS_WINCH_SPEED = 60.0 * 0.3048 / 60.0
#: Operating altitude below which an aerostat "can be flown without a ballonet" [m]
#: (thesis §2.2.1(c), citing Bajoria et al. 2017).
BALLONET_RULE_ALTITUDE = 500.0
#: Safety factor on envelope fabric strength [-], 4: the value issue 13 attributes to Carichner
#: & Nicolai, Fundamentals of Aircraft and Airship Design Vol. 2 (AIAA 2013). That book was NOT
#: available here, so the attribution is unverified; it is an input
#: (MissionSpec.envelope_safety_factor). The one regulation read, 14 CFR §31.25 (manned free
#: balloons; stored copy of the eCFR text, faraim.org), asks at least five for "all fibrous or
#: non-metallic parts of the rigging" (§31.25(c)) and applies the envelope factor of §31.25(b)
#: "to the more critical of the maximum operating pressure or envelope stress"; the number of
#: §31.25(b) itself was cut off in the copy read, so it is not quoted here. EASA CS 31GB.25
#: (gas balloons, ED Decision 2011/012/R; balloonwiki.org copy of the CS text) tabulates an
#: envelope factor of 5.00 (integral load tapes included), suspension 2.25 (fibrous) and 1.50
#: (metallic): the published figure for manned gas balloons, one step more conservative than
#: 4. Unmanned tethered aerostats are outside Part 31 and CS-31GB.
ENVELOPE_SAFETY_FACTOR = 4.0
#: Internal pressure / dynamic pressure needed to keep a non-rigid hull's nose from dimpling
#: [-]: the rule of thumb p >= 1.2 q (+ the hydrostatic gas head) quoted in issue 13. NO primary
#: source for the factor 1.2 was found: Khoury & Gillett (Airship Technology, CUP 1999),
#: Carichner & Nicolai (2013), FAA-P-8110-2 (Airship Design Criteria) and the ADRDE envelope
#: paper (Kumar, Sati & Ghosh, Defence Sci. J. 66(2) 2016) were searched for but only their
#: titles or abstracts were readable. The physics it encodes (the nose stagnation pressure is
#: about q, so the gas must exceed q there) is standard; 1.2 is an engineering margin, kept as
#: an input (MissionSpec.pressure_dynamic_factor).
PRESSURE_DYNAMIC_FACTOR = 1.2
#: Pack-level specific energy of an onboard battery [Wh/kg]: 150, an engineering choice between
#: the two pack figures read (BATTERY_PACK_REFERENCES): an enclosed LiFePO4 pack with its
#: management system, 107 Wh/kg, and a bare lithium-polymer drone pack, 216 Wh/kg. An input
#: (MissionSpec.battery_energy_density); enter the pack's own data sheet figure.
BATTERY_ENERGY_DENSITY = 150.0
#: Published pack figures behind BATTERY_ENERGY_DENSITY: name -> (nominal energy [Wh], mass
#: [kg], source). The CONSSIN sheet prints "Nominal Energy 1280 Wh" and "Weight 12 kg"; the
#: DJI Mavic figure is second-hand, from the README of the public repository
#: kopern/smarter_mavic_battery ("a weight for 202grams and provide 43.6 Watts [Wh]").
BATTERY_PACK_REFERENCES = {
    "CONSSIN CSP1280-12.8-A LiFePO4 pack, IP65": (
        1280.0,
        12.0,
        "FUZHOU CONSSIN LIGHTING CO., LTD product specification, public copy "
        "github.com/conssin2003-oss/conssin-files (CSP1280-12.8 datasheet.pdf)",
    ),
    "DJI Mavic flight pack, LiPo": (
        43.6,
        0.202,
        "second-hand: README of github.com/kopern/smarter_mavic_battery",
    ),
}
#: Usable fraction of a battery's rated energy [-], ASSUMED (long cycle life).
BATTERY_DEPTH_OF_DISCHARGE = 0.8
#: Ground supply voltage of a power tether [V], ASSUMED (low-voltage DC/AC class).
POWER_TETHER_VOLTAGE = 400.0
#: Allowed resistive loss / supply power in the tether conductors [-], engineering choice.
POWER_TETHER_LOSS_FRACTION = 0.10
#: Current-density ceiling of bundled insulated copper [A/m2] (5 A/mm2), ASSUMED stand-in for a
#: conductor-temperature limit.
MAX_CURRENT_DENSITY = 5.0e6
#: Day-time gas superheat at the operating altitude [K], ASSUMED clear-sky order of magnitude.
GAS_SUPERHEAT = 10.0
#: Winch motor x drive efficiency [-], ASSUMED (motor 0.85 x gearbox 0.9).
WINCH_EFFICIENCY = 0.75
#: Tether minimum bend radius / diameter [-] on the winch drum: 20, the "Dynamic: 20 x cable
#: diameter" of a published fibre-optic cable specification ("Min. bending radius for
#: installation Static: 10 x cable diameter, Dynamic: 20 x cable diameter", Tech.
#: Specification 2020102013 rev 1.0, ADSS single-jacket cable CFOA-SM-AS-S-KP, §3.1; public copy
#: github.com/andretavaresrj/imagens/files/14474304). A drum winds the tether under tension while
#: it moves, the dynamic case. An aerostat tether with optical fibres is held to its fibres'
#: limit; use the tether's own data sheet where it has one (MissionSpec.bend_radius_ratio).
TETHER_BEND_RADIUS_RATIO = 20.0
