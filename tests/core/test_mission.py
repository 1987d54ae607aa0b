"""Mission models (issue 13): payload power, endurance, ballonet, envelope structure, survival
wind, winch; their rows in the constraint table; JSON versioning and the CLI."""

import json
import math
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from aerostat_core import Requirement, design
from aerostat_core.atmosphere.permeation import (
    days_to_top_up,
    helium_top_up,
    lift_loss_after,
    permeation_time_constant,
    purity_after,
)
from aerostat_core.atmosphere.standard import isa
from aerostat_core.base import constants as c
from aerostat_core.cli.entry import main
from aerostat_core.model.constraints import NAMES
from aerostat_core.model.io import design_from_json, design_to_json
from aerostat_core.model.mission import (
    MissionSpec,
    ballonet_state,
    effective_tether,
    onboard_battery_mass,
    tether_conductors,
)
from aerostat_core.model.presets import practice_configuration
from aerostat_core.model.sizing import size_volume
from aerostat_core.structures.ballonet import ballonet_fabric_mass, ballonet_fraction, sphere_area
from aerostat_core.structures.materials import FABRICS, POWER_TETHER_CONDUCTORS, TETHERS, Fabric
from aerostat_core.structures.membrane import allowable_pressure, membrane_loads, required_pressure
from aerostat_core.tether.power import battery_mass, size_conductors
from aerostat_core.tether.winch import size_winch

#: Sized volume of the default requirement before the mission work (CLI JSON at commit 2e23b90).
DEFAULT_VOLUME_BEFORE = 55.16168682221109


# --- physics limits ----------------------------------------------------------------------------
def test_no_power_gives_no_conductor_and_no_battery():
    k = size_conductors(0.0, 300.0, 400.0, 0.1, 5e6, 0.25e-3)
    assert k.area == 0.0 and k.linear_density == 0.0 and k.strength == 0.0
    cfg = practice_configuration()
    for via in ("onboard", "tether"):
        req = Requirement(payload_power=0.0, power_via=via)
        assert tether_conductors(req, cfg) == (None, False)
        assert effective_tether(req, cfg) == cfg.tether
        assert onboard_battery_mass(req, cfg) == 0.0


def test_no_permeation_gives_no_top_up():
    assert float(helium_top_up(120.0, 0.0, 0.98, 101325.0, 365.0)) == 0.0
    tau = permeation_time_constant(100.0, 110.0, 0.0, 288.15)
    assert np.isinf(tau)
    assert float(purity_after(0.98, 365.0, tau)) == 0.98
    assert np.isinf(days_to_top_up(10.0, 100.0, 9.81, 1.2, 0.17, 0.98, tau))
    fab = Fabric("impermeable", 0.2, 40000.0, 0.0)
    cfg = replace(practice_configuration(), hull_fabric=fab, fin_fabric=fab)
    d = design(Requirement(endurance_days=30.0), cfg)
    s = d.summary()
    assert s["helium_top_up_m3"] == 0.0 and s["days_to_top_up"] is None  # never (JSON has no inf)
    # no permeation: the endurance requirement costs nothing
    assert d.volume == pytest.approx(design(Requirement(), cfg).volume, rel=1e-12)


def test_launch_at_the_operating_altitude_gives_no_ballonet():
    a = isa(1200.0)
    assert float(ballonet_fraction(a.pressure, a.temperature, a.pressure, a.temperature)) == 0.0
    assert float(ballonet_fabric_mass(0.0, 0.2)) == 0.0


def test_default_designs_do_not_change():
    """The mission inputs are off by default: same sized volume as before, no battery, no
    ballonet mass, the configured tether, and every mission row met with room to spare."""
    d = design(Requirement())
    assert d.volume == pytest.approx(DEFAULT_VOLUME_BEFORE, rel=1e-9)
    items = d.airframe.mass.items
    assert float(items["battery"]) == 0.0 and float(items["ballonet"]) == 0.0
    assert d.airframe.tether == d.configuration.tether
    for name in ("envelope_stress", "survival_envelope_pressure", "endurance"):
        assert d.constraints.g[NAMES.index(name)] < -0.5
    assert d.mission.ballonet.fraction > 0 and d.mission.ballonet_mass == 0.0  # reported only


# --- hand-checked numbers, one case per model --------------------------------------------------
def test_battery_hand_check():
    # 200 W for 2 days at 150 Wh/kg, 80 % usable: 9600 Wh / 120 Wh/kg = 80 kg
    assert float(battery_mass(200.0, 48.0, 150.0, 0.8)) == pytest.approx(80.0)
    cfg = practice_configuration()
    req = Requirement(payload_power=200.0, endurance_days=2.0)
    assert onboard_battery_mass(req, cfg) == pytest.approx(80.0)
    # no endurance: one day between recharges
    assert onboard_battery_mass(Requirement(payload_power=200.0), cfg) == pytest.approx(40.0)


def test_conductor_hand_check():
    # 2 kW at 800 V through 500 m, 5 % loss: P_s = 2105.26 W, I = 2.6316 A,
    # R = 0.05 * 800^2 / 2105.26 = 15.2 ohm, A = 2 rho L / R = 2 * 1.7241e-8 * 500 / 15.2
    k = size_conductors(2000.0, 500.0, 800.0, 0.05, 5e6, 0.3e-3)
    ps = 2000.0 / 0.95
    assert k.supply_power == pytest.approx(ps)
    assert k.current == pytest.approx(ps / 800.0)
    r = 0.05 * 800.0**2 / ps
    assert k.loop_resistance == pytest.approx(r)
    assert k.area == pytest.approx(2 * c.COPPER_RESISTIVITY * 500.0 / r)
    assert k.loss == pytest.approx(0.05 * ps)  # the allowed loss exactly
    assert ps - k.loss == pytest.approx(2000.0)  # the payload gets its power
    d = math.sqrt(4 * k.area / math.pi)
    ins = math.pi / 4 * ((d + 0.6e-3) ** 2 - d**2)
    assert k.linear_density == pytest.approx(2 * (k.area * 8890.0 + ins * 1700.0))
    # a short line is limited by the current density, not the loss
    k2 = size_conductors(2000.0, 5.0, 48.0, 0.2, 5e6, 0.0)
    assert k2.area == pytest.approx(2000.0 / 0.8 / 48.0 / 5e6)
    assert k2.current / k2.area <= 5e6 and k2.loss < 0.2 * k2.supply_power
    assert k2.supply_power - k2.loss == pytest.approx(2000.0)


def test_endurance_hand_check():
    # 100 m3, 110 m2, 2.5 L/(m2 day atm), 288.15 K: tau = 100 * 273.15 / (0.0025 * 110 * 288.15)
    tau = float(permeation_time_constant(100.0, 110.0, 2.5, 288.15))
    assert tau == pytest.approx(100 * 273.15 / (0.0025 * 110 * 288.15))
    k10 = float(purity_after(0.98, 10.0, tau))
    assert k10 == pytest.approx(0.98 * math.exp(-10 / tau))
    loss = float(lift_loss_after(100.0, 9.80665, 1.225, 0.169, 0.98, 10.0, tau))
    assert loss == pytest.approx(100 * 9.80665 * (1.225 - 0.169) * (0.98 - k10))
    # the excess lift lost in exactly 10 days gives 10 days to top-up
    assert float(days_to_top_up(loss, 100.0, 9.80665, 1.225, 0.169, 0.98, tau)) == pytest.approx(
        10.0
    )
    assert float(days_to_top_up(-1.0, 100.0, 9.80665, 1.225, 0.169, 0.98, tau)) == 0.0
    # 110 m2 x 2.5 L/m2/day x 0.98 x 1 atm x 30 days = 8.085 m3
    assert float(helium_top_up(110.0, 2.5, 0.98, 101325.0, 30.0)) == pytest.approx(8.085)


def test_ballonet_hand_check():
    site, op = isa(0.0), isa(1000.0)
    f = float(ballonet_fraction(site.pressure, site.temperature, op.pressure, op.temperature, 10.0))
    want = 1 - (float(op.pressure) * 288.15) / (101325.0 * (float(op.temperature) + 10.0))
    assert f == pytest.approx(want)
    assert 0.12 < f < 0.13  # 11.3 % for 1000 m, the rest from the 10 K superheat
    assert float(sphere_area(4 / 3 * math.pi)) == pytest.approx(4 * math.pi)
    b = ballonet_state(Requirement(altitude=1000.0), practice_configuration())
    assert b.fraction == pytest.approx(f) and b.needed
    assert not ballonet_state(Requirement(altitude=300.0), practice_configuration()).needed


def test_structure_hand_check():
    # q = 0.5 * 1.2 * 20^2 = 240 Pa; p = 1.2 q + (1.2 - 0.2) g d, d = 4 m
    p = float(required_pressure(240.0, 1.2, 0.2, 9.81, 4.0, 1.2))
    assert p == pytest.approx(288.0 + 39.24)
    hoop, long = membrane_loads(p, 2.0, 1000.0)
    assert float(hoop) == pytest.approx(2 * p)
    assert float(long) == pytest.approx(p + 1000.0 / (math.pi * 4.0))
    # allowable pressure inverts the loads at the safety factor
    pa = float(allowable_pressure(4 * float(hoop), 4.0, 2.0, 1000.0))
    assert pa == pytest.approx(p)  # hoop governs here (hoop > long)


def test_winch_hand_check():
    w = size_winch(2000.0, 0.3048, 0.8, 600.0, 0.006, 15.0, 8)
    assert w.power == pytest.approx(2000 * 0.3048 / 0.8)
    assert w.drum_diameter == pytest.approx(2 * 15 * 0.006)
    # stored length pi (W/d) n (D + n d) equals the tether length
    assert math.pi * (w.drum_length / 0.006) * 8 * (0.18 + 8 * 0.006) == pytest.approx(600.0)
    assert w.reel_time == pytest.approx(600 / 0.3048)
    assert c.THESIS_WINCH_SPEED == pytest.approx(60 * 0.3048 / 60)  # 60 ft/min


# --- through design(): rows, survival, winch ---------------------------------------------------
def test_sized_design_meets_the_endurance_it_asks_for():
    d0 = design(Requirement())
    d = design(Requirement(endurance_days=7.0))
    assert d.feasible
    assert d.mission.days_to_top_up >= 7.0 - 1e-3
    assert d.volume > d0.volume  # lift to burn over the week
    assert d.summary().binding_constraint == "endurance"


def test_lift_decay_curve_crosses_the_requirement_at_the_top_up_day():
    d = design(Requirement(endurance_days=7.0))
    m = d.mission
    dec = m.decay
    assert dec["free_lift_kg"][0] == pytest.approx(d.free_lift_kg)
    assert np.all(np.diff(dec["free_lift_kg"]) < 0) and np.all(np.diff(dec["purity"]) < 0)
    cross = np.interp(0.0, -(dec["free_lift_kg"] - dec["required_kg"]), dec["day"])
    assert cross == pytest.approx(m.days_to_top_up, rel=2e-3)  # linear interpolation of a curve
    assert m.survival_tension * m.survival_safety_factor == pytest.approx(
        m.tether.breaking_strength
    )


def test_weak_fabric_fails_the_envelope_and_must_be_reeled_in():
    fab = Fabric("weak", 0.2, 1500.0, 2.5)
    cfg = replace(practice_configuration(60.0), hull_fabric=fab, fin_fabric=fab)
    d = design(Requirement(), cfg)
    m = d.mission
    assert m.survival_pressure_margin < 0 and not m.stay_up
    assert m.reel_in_wind is not None and m.reel_in_wind <= d.requirement.survival_wind
    assert any("survival" in v for v in d.violations)
    # sizing cannot fix a fabric that is too weak (a larger hull loads it harder)
    s = size_volume(Requirement(), replace(cfg, hull=replace(cfg.hull, volume=None)))
    assert not bool(s.feasible) and "fabric" in str(s.message)


def test_envelope_stress_margin_is_strength_over_required_minus_one():
    d = design(Requirement())
    e = d.mission.envelope
    assert d.summary().mission.envelope_stress_margin == pytest.approx(
        e["strength"] / e["strength_required"] - 1
    )
    assert e["strength"] == d.configuration.hull_fabric.tensile_strength
    assert e["strength_required"] == pytest.approx(4.0 * max(e["hoop"], e["longitudinal"]))


def test_winch_pull_is_the_largest_winch_tension_survival_included():
    d = design(Requirement(wind_max=15.0))  # survival 20 m/s lies beyond the sweep
    m = d.mission
    assert m.winch_pull >= max(r["tension_winch_N"] for r in d.performance.rows())
    ev = d.constraints.evaluation
    assert m.winch_pull == pytest.approx(float(np.max(ev.tether.tension_winch)))
    assert m.winch.power == pytest.approx(m.winch_pull * 0.3048 / 0.75)
    # drum core = 2 x (dynamic bend radius 20 d), constants.TETHER_BEND_RADIUS_RATIO
    assert m.winch.drum_diameter == pytest.approx(40 * d.airframe.tether.diameter)
    assert m.winch.reel_time == pytest.approx(300.0 / 0.3048)


def test_too_heavy_conductors_are_refused_with_the_fields_named():
    with pytest.raises(ValueError, match="supply_voltage = 100 V.*raise the supply voltage"):
        design(
            Requirement(payload_power=5000.0, power_via="tether", altitude=1000.0),
            replace(practice_configuration(), mission=MissionSpec(supply_voltage=100.0)),
        )


def test_catalogue_power_tether_uses_its_own_conductors():
    name = next(iter(POWER_TETHER_CONDUCTORS))
    cfg = replace(practice_configuration(), tether=TETHERS[name])
    req = Requirement(payload_power=300.0, power_via="tether")
    k, own = tether_conductors(req, cfg)
    assert own and k.area < POWER_TETHER_CONDUCTORS[name]
    assert effective_tether(req, cfg) == TETHERS[name]


def test_catalogue_fabrics_have_sourced_strengths():
    f = FABRICS["Uretek 3216LV laminate (Lv 2022)"]
    assert f.tensile_strength == pytest.approx(101.43 * 9.80665 * 100)  # 101.43 kgf/cm
    assert f.helium_permeability == pytest.approx(0.8818)


# --- trends ------------------------------------------------------------------------------------
def test_more_power_gives_a_heavier_tether_and_a_larger_hull():
    vols, teth = [], []
    for p in (0.0, 500.0, 2000.0, 5000.0):
        d = design(Requirement(payload_power=p, power_via="tether"))
        vols.append(d.volume)
        teth.append(d.mission.tether_mass)
    assert all(b > a for a, b in zip(vols, vols[1:]))
    assert all(b > a for a, b in zip(teth, teth[1:]))
    onboard = [design(Requirement(payload_power=p)).volume for p in (0.0, 50.0, 100.0)]
    assert onboard[0] < onboard[1] < onboard[2]


def test_higher_altitude_gives_a_larger_ballonet():
    cfg = practice_configuration()
    f = [ballonet_state(Requirement(altitude=h), cfg).fraction for h in (100, 300, 500, 1000, 2000)]
    assert all(b > a for a, b in zip(f, f[1:]))
    # building it adds its fabric to the mass breakdown
    on = replace(cfg, mission=MissionSpec(ballonet="on"))
    d = design(Requirement(altitude=1000.0), on)
    assert d.mission.ballonet_mass == pytest.approx(
        cfg.hull_fabric.areal_density * float(sphere_area(d.mission.ballonet.fraction * d.volume))
    )
    assert d.volume > design(Requirement(altitude=1000.0), cfg).volume


# --- hypothesis over the new inputs ------------------------------------------------------------
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    power=st.one_of(st.just(0.0), st.floats(1e-3, 3000)),
    via=st.sampled_from(["onboard", "tether"]),
    days=st.floats(0, 60),
    altitude=st.floats(50, 1500),
    voltage=st.floats(100, 2000),
    loss=st.floats(0.02, 0.3),
    superheat=st.floats(0, 30),
    ballonet=st.sampled_from(["off", "auto", "on"]),
)
def test_mission_inputs_over_their_domain(
    power, via, days, altitude, voltage, loss, superheat, ballonet
):
    req = Requirement(payload_power=power, power_via=via, endurance_days=days, altitude=altitude)
    base = practice_configuration()
    spec = MissionSpec(
        supply_voltage=voltage, power_loss_fraction=loss, superheat=superheat, ballonet=ballonet
    )
    cfg = replace(base, mission=spec)
    try:
        d = design(req, cfg)
    except ValueError as exc:  # conductors beyond the tether model: a message, never a crash
        assert "supply_voltage" in str(exc) and via == "tether"
        return
    m = d.mission
    t = d.airframe.tether
    assert t.linear_density >= base.tether.linear_density
    assert t.breaking_strength >= base.tether.breaking_strength
    if via == "tether" and power > 0:
        assert m.conductors.loss <= loss * m.conductors.supply_power * (1 + 1e-9)
        assert m.conductors.supply_power - m.conductors.loss == pytest.approx(power)
    else:
        assert t == base.tether
    assert m.battery_mass >= 0
    if not (via == "onboard" and power > 0):
        assert m.battery_mass == 0
    elif power > 1e-3:  # (a vanishing power times a vanishing time underflows to 0 kg)
        hours = 24 * days if days > 0 else 24  # one day between recharges without endurance
        assert m.battery_mass == pytest.approx(power * hours / (150 * 0.8))
    assert 0.0 <= m.ballonet.fraction < 1.0
    assert (m.ballonet_mass > 0) == (ballonet == "on" or (ballonet == "auto" and m.ballonet.needed))
    assert m.helium_top_up > 0 and m.top_up_cost >= 0
    # the table's endurance row and the report's days agree up to the row's 1e-6 tolerance on
    # the lift fraction, i.e. about 1e-6 rho_air tau/((rho_air - rho_He) k0) days
    slack = 2e-6 * m.permeation_tau
    if d.feasible:
        assert m.days_to_top_up >= days - slack
        assert m.envelope_stress_margin >= 0 and m.stay_up
    met = bool(d.constraints.met[NAMES.index("endurance")])
    if met:
        assert m.days_to_top_up >= days - slack
    if m.days_to_top_up >= days + slack:
        assert met


# --- inputs, files, CLI ------------------------------------------------------------------------
@pytest.mark.parametrize(
    "field, value",
    [
        ("payload_power", -1.0),
        ("payload_power", 2e5),
        ("power_via", "laser"),
        ("endurance_days", 400.0),
        ("deployment_days", -1.0),
    ],
)
def test_requirement_mission_fields_name_field_value_and_range(field, value):
    with pytest.raises(ValueError, match=f"Requirement.{field}"):
        Requirement(**{field: value})


@pytest.mark.parametrize(
    "field, value",
    [
        ("battery_energy_density", 5.0),
        ("supply_voltage", 1.0),
        ("power_loss_fraction", 0.0),
        ("ballonet", "maybe"),
        ("superheat", 50.0),
        ("envelope_safety_factor", 0.5),
        ("winch_efficiency", 1.5),
        ("drum_layers", 0),
    ],
)
def test_mission_spec_fields_name_field_value_and_range(field, value):
    with pytest.raises(ValueError, match=f"MissionSpec.{field}"):
        MissionSpec(**{field: value})


def test_version_1_files_load_with_the_mission_off():
    text = json.dumps(
        {
            "format": "aerostat-design",
            "version": 1,
            "requirement": {"payload_mass": 20.0, "altitude": 400.0},
            "configuration": {"hull_fabric": {"name": "old", "areal_density": 0.2}},
        }
    )
    req, cfg = design_from_json(text)
    assert req.payload_power == 0.0 and req.endurance_days == 0.0
    assert cfg.mission == MissionSpec() and cfg.hull_fabric.tensile_strength == 40000.0
    req2 = Requirement(payload_power=250.0, power_via="tether", endurance_days=5.0)
    cfg2 = replace(practice_configuration(), mission=MissionSpec(ballonet="auto"))
    data = json.loads(design_to_json(req2, cfg2))
    assert data["version"] == 2
    assert design_from_json(json.dumps(data)) == (req2, cfg2)


def test_cli_mission_options_and_keys(capsys):
    assert (
        main(
            [
                "design",
                "--json",
                "--payload-power",
                "800",
                "--power-via",
                "tether",
                "--endurance-days",
                "5",
            ]
        )
        == 0
    )
    s = json.loads(capsys.readouterr().out)
    for key in (
        "ballonet_volume_m3",
        "days_to_top_up",
        "helium_top_up_m3",
        "envelope_stress_margin",
        "tether_mass_kg",
        "winch_pull_N",
        "winch_power_W",
    ):
        assert key in s
    assert s["days_to_top_up"] >= 5.0 - 1e-3
    assert s["tether_mass_kg"] > 0.009 * 300.0  # conductors added to the 9 g/m practice tether
    assert main(["design", "--json"]) == 0
    s0 = json.loads(capsys.readouterr().out)
    assert s0["tether_mass_kg"] == pytest.approx(0.009 * 300.0)
    assert s0["volume_m3"] == pytest.approx(DEFAULT_VOLUME_BEFORE, rel=1e-9)
    with pytest.raises(SystemExit) as exc:  # argparse refuses a choice outside the list
        main(["design", "--power-via", "laser"])
    assert exc.value.code == 2
    capsys.readouterr()
    assert main(["design", "--endurance-days", "-2"]) == 2
    assert "endurance_days" in capsys.readouterr().err


# --- validation (issue 13 item 9) --------------------------------------------------------------
def test_fielded_systems_sized_with_their_class_endurance_move_closer():
    """Sized with the thesis' class endurance (tactical 5 days, operational 7) and the 500 m
    ballonet rule, every held-out system's predicted length moves closer to the published one
    (all were under-predicted); the median error drops from 9.3 % to 8.3 %. The fit system
    TIF-1600, already 16 % long, grows to 22 % (the calibration was chosen without them)."""
    from aerostat_core.studies.fielded import validate_fielded

    before = validate_fielded()
    after = validate_fielded(mission=True)
    for b, a in zip(before.rows, after.rows):
        assert a.length > b.length  # more lift to lose and (above 500 m) a ballonet to carry
        if not b.system.fit:
            assert abs(a.length_error) < abs(b.length_error)
    assert before.median_abs_length_error == pytest.approx(0.0927, abs=5e-4)
    assert after.median_abs_length_error == pytest.approx(0.0833, abs=5e-4)
    assert after.max_abs_length_error == pytest.approx(0.2200, abs=5e-4)
    assert all(r.feasible for r in after.rows)
