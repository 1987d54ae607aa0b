"""Catalogue entries and sourced constants carry their source, and match it where it states the
number (issues 12 and 13; docs/methods.md §1.14, S14-S20)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from aerostat_core.base import constants as c
from aerostat_core.structures.materials import (
    ADRDE_HELIUM_PERMEABILITY,
    ASSUMED_TENSILE_STRENGTH,
    FABRIC_SOURCES,
    FABRICS,
    KITEUTILS_TETHER,
    LV_2022_FIGURES,
    POWER_TETHER_CONDUCTORS,
    TETHER_SOURCES,
    TETHERS,
    VIDEORAY_STRENGTH_RATING_KG,
    VIDEORAY_TETHERS,
    awg_area,
)
from aerostat_core.tether.power import Conductors, power_tether

SEED = Path("/work/shared/seed/000_fe1dc8fde547e527.txt")
KGF_PER_CM = 9.80665 * 100.0  # 1 kgf/cm in N/m
FABRIC_FIELDS = ("areal_density", "tensile_strength", "helium_permeability")
#: The words that say where a number comes from when it is not a published figure.
PROVENANCE = ("INFERRED", "ASSUMED", "COMPUTED", "second-hand", "Lv et al. 2022", "not in")


def test_every_catalogue_fabric_names_a_source_for_every_field():
    assert set(FABRIC_SOURCES) == set(FABRICS)
    for name, src in FABRIC_SOURCES.items():
        assert set(src) == set(FABRIC_FIELDS), name
        for field, text in src.items():
            assert any(w in text for w in PROVENANCE), (name, field, text)


def test_every_catalogue_tether_names_a_source():
    assert set(TETHER_SOURCES) == set(TETHERS)
    for name, text in TETHER_SOURCES.items():
        assert len(text) > 20, name
    # the Dyneema power tethers are the project's own computation, not a product, and say so;
    # the VideoRay ones are a product and name its maker and pages
    for name in POWER_TETHER_CONDUCTORS:
        if name in VIDEORAY_TETHERS:
            assert "kb.videoray.com" in TETHER_SOURCES[name], name
        else:
            assert TETHER_SOURCES[name].startswith("COMPUTED example, not a product"), name
    assert "ASSUMED" in TETHER_SOURCES["Electro-optic tether 8 mm (60 g/m)"]


@pytest.mark.parametrize("name", sorted(LV_2022_FIGURES))
def test_lv_2022_laminates_match_the_published_figures(name):
    """Lv et al. 2022 (Front. Mater. 9:992984), abstract: new-sample tensile strength in kgf/cm
    and helium permeability in L/(m2 day atm)."""
    strength_kgf_cm, permeability = LV_2022_FIGURES[name]
    f = FABRICS[name]
    assert f.tensile_strength == pytest.approx(strength_kgf_cm * KGF_PER_CM, rel=1e-12)
    if permeability is None:  # HV150: none published, the default is kept and says so
        assert f.helium_permeability == ADRDE_HELIUM_PERMEABILITY
        assert "not in Lv 2022" in FABRIC_SOURCES[name]["helium_permeability"]
    else:
        assert f.helium_permeability == pytest.approx(permeability, rel=1e-12)
    assert f"{strength_kgf_cm} kgf/cm" in FABRIC_SOURCES[name]["tensile_strength"]


def test_assumed_strength_is_half_the_lightest_published_laminate():
    """About half of HV150 (150 g/m2, 82.13 kgf/cm), below every new Lv 2022 sample."""
    hv150 = LV_2022_FIGURES["HV150 laminate (Lv 2022)"][0] * KGF_PER_CM  # 80.5 kN/m
    assert ASSUMED_TENSILE_STRENGTH == pytest.approx(hv150 / 2, rel=0.01)
    assert ASSUMED_TENSILE_STRENGTH < min(s for s, _ in LV_2022_FIGURES.values()) * KGF_PER_CM
    for name, f in FABRICS.items():
        if "ASSUMED" in FABRIC_SOURCES[name]["tensile_strength"]:
            assert f.tensile_strength == ASSUMED_TENSILE_STRENGTH, name


def test_thesis_fabric_is_table_2_2_sphere_hull_mass_over_its_area():
    """13.54 kg of hull on the 100 m3 sphere of Table 2.2 (area 4 pi r^2 = 104.19 m2)."""
    r = (3 * 100.0 / (4 * math.pi)) ** (1 / 3)
    area = 4 * math.pi * r * r
    assert area == pytest.approx(104.19, abs=0.005)
    assert FABRICS["Thesis fabric (130 g/m2)"].areal_density == pytest.approx(
        13.54 / area, rel=1e-3
    )


def test_dyneema_4mm_matches_the_kiteutils_settings():
    """OpenSourceAWE KiteUtils.jl data/settings.yaml: d 4 mm, 724 kg/m3, EA 614.6 kN."""
    t = TETHERS["Dyneema 4 mm (9 g/m)"]
    d = KITEUTILS_TETHER["diameter"]
    assert t.diameter == d
    assert t.axial_stiffness == pytest.approx(KITEUTILS_TETHER["axial_stiffness"], rel=1e-12)
    rho_l = KITEUTILS_TETHER["density"] * math.pi * d * d / 4  # 9.10 g/m
    assert t.linear_density == pytest.approx(rho_l, rel=0.02)
    # the 6 mm entry is that rope scaled with d^2 (mass and EA), as its source says
    t6 = TETHERS["Dyneema 6 mm (21 g/m)"]
    assert t6.linear_density == pytest.approx(rho_l * 2.25, rel=0.03)
    assert t6.axial_stiffness == pytest.approx(KITEUTILS_TETHER["axial_stiffness"] * 2.25, rel=0.02)


@pytest.mark.parametrize("name", sorted(VIDEORAY_TETHERS))
def test_videoray_tethers_match_the_published_figures(name):
    """kb.videoray.com tether specifications: Neutral 11.18 mm (bend radius 114 mm, 2 x 20 AWG
    per power pole), Performance 8.18 mm (82.5 mm, 2 x 24 AWG); 450 kg strength rating;
    neutrally buoyant in fresh water, so their mass per metre is the water they displace."""
    published = {
        "VideoRay Neutral ROV tether 11.2 mm (400 V DC)": (0.01118, 0.114, 20),
        "VideoRay Performance ROV tether 8.2 mm (400 V DC)": (0.00818, 0.0825, 24),
    }[name]
    assert VIDEORAY_TETHERS[name] == published
    d, r_bend, awg = published
    t = TETHERS[name]
    assert t.diameter == d
    assert t.breaking_strength == pytest.approx(450.0 * 9.80665, rel=1e-12)
    assert VIDEORAY_STRENGTH_RATING_KG == 450.0
    # neutral in fresh water (998-1000 kg/m3): mass per metre within 0.3 % of the displaced water
    assert t.linear_density == pytest.approx(1000.0 * math.pi * d * d / 4, rel=3e-3)
    # the maker's minimum bend radius is about 10 d: the static figure of S17, below the drum's
    assert 10.0 <= r_bend / d <= 10.5 < c.TETHER_BEND_RADIUS_RATIO
    # the conductors the mission model uses are the published pairs per pole
    assert POWER_TETHER_CONDUCTORS[name] == pytest.approx(2 * awg_area(awg), rel=1e-12)


def test_awg_areas_match_the_gauge_table():
    """ASTM B258 diameters: 16 AWG 1.291 mm, 20 AWG 0.812 mm, 24 AWG 0.511 mm."""
    for gauge, dia_mm in ((16, 1.291), (20, 0.812), (24, 0.511)):
        assert awg_area(gauge) == pytest.approx(math.pi / 4 * (dia_mm * 1e-3) ** 2, rel=3e-3)


@pytest.mark.parametrize(
    "name", sorted(n for n in POWER_TETHER_CONDUCTORS if n not in VIDEORAY_TETHERS)
)
def test_computed_power_tethers_are_what_power_tether_gives(name):
    """The catalogue's power tethers are the Dyneema 6 mm entry plus two ETFE-insulated copper
    conductors (0.25 mm wall), exactly as aerostat_core.tether.power.power_tether bundles them."""
    area = POWER_TETHER_CONDUCTORS[name]
    dia = math.sqrt(4 * area / math.pi)
    d_ins = dia + 2 * 0.25e-3
    a_ins = math.pi / 4 * (d_ins**2 - dia**2)
    k = Conductors(
        area=area,
        diameter=dia,
        insulated_diameter=d_ins,
        current=0.0,
        supply_power=0.0,
        loss=0.0,
        loop_resistance=math.inf,
        linear_density=2 * (area * c.COPPER_DENSITY + a_ins * c.ETFE_DENSITY),
        strength=2 * area * c.COPPER_YIELD_STRENGTH,
    )
    built = power_tether(TETHERS["Dyneema 6 mm (21 g/m)"], k)
    t = TETHERS[name]
    assert t.linear_density == pytest.approx(built.linear_density, rel=2e-3)
    assert t.diameter == pytest.approx(built.diameter, rel=2e-3)
    assert t.breaking_strength == pytest.approx(built.breaking_strength, rel=1e-4)
    assert t.axial_stiffness == built.axial_stiffness


def test_winch_speed_is_the_thesis_60_feet_per_minute():
    assert c.THESIS_WINCH_SPEED == pytest.approx(60 * 0.3048 / 60, rel=1e-15)


@pytest.mark.skipif(not SEED.exists(), reason="thesis seed text not on this machine")
def test_thesis_states_the_winch_speed_and_the_ballonet_rule():
    text = " ".join(SEED.read_text(encoding="utf-8").split())
    assert "retrieval speeds around 60 feet per minutes" in text  # §2.2.4, as printed
    assert "less than 500 m, it can be flown without a ballonet" in text  # §2.2.1(c)
    assert c.BALLONET_RULE_ALTITUDE == 500.0


def test_drum_bend_radius_is_the_dynamic_data_sheet_figure():
    """Cable specification 2020102013 §3.1: static 10 d, dynamic 20 d; a drum is dynamic."""
    assert c.TETHER_BEND_RADIUS_RATIO == 20.0


def test_unverified_rules_stay_inputs_with_their_stated_values():
    """No primary source was found for these (docs/validation.md §8): they are the figures the
    issue states, kept as inputs, and the constants say so."""
    assert c.PRESSURE_DYNAMIC_FACTOR == 1.2
    assert c.ENVELOPE_SAFETY_FACTOR == 4.0
    assert ADRDE_HELIUM_PERMEABILITY == 2.5
    src = Path(c.__file__).read_text(encoding="utf-8")
    for marker in ("NO primary", "attribution is unverified"):
        assert marker in src, marker


def test_battery_default_lies_between_the_published_packs():
    """CONSSIN CSP1280-12.8-A: 1280 Wh, 12 kg (107 Wh/kg); DJI Mavic pack: 43.6 Wh, 202 g
    (216 Wh/kg, second-hand). The default 150 Wh/kg is a choice between them."""
    figures = {k: e / m for k, (e, m, _) in c.BATTERY_PACK_REFERENCES.items()}
    assert figures["CONSSIN CSP1280-12.8-A LiFePO4 pack, IP65"] == pytest.approx(106.67, abs=0.01)
    assert figures["DJI Mavic flight pack, LiPo"] == pytest.approx(215.8, abs=0.1)
    assert min(figures.values()) < c.BATTERY_ENERGY_DENSITY < max(figures.values())
    assert all(src for _, _, src in c.BATTERY_PACK_REFERENCES.values())
