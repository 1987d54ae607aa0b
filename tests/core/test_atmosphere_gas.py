"""Atmosphere and lifting gas: ISA against the independent ``ambiance`` package, gas law."""

import numpy as np
import pytest
from ambiance import Atmosphere

from aerostat_core import LiftingGas
from aerostat_core.atmosphere.gas import gas_density
from aerostat_core.atmosphere.standard import isa

HEIGHTS = np.linspace(0.0, 11000.0, 111)


@pytest.mark.parametrize("field, amb", [("density", "density"), ("pressure", "pressure"),
                                        ("temperature", "temperature"),
                                        ("viscosity", "dynamic_viscosity")])
def test_isa_matches_ambiance(field, amb):
    # predicted: an independent ISA implementation, 0-11 km, within 1e-5 relative
    ours = getattr(isa(HEIGHTS), field)
    ref = getattr(Atmosphere(HEIGHTS), amb)
    assert np.max(np.abs(ours / ref - 1.0)) < 1e-5


@pytest.mark.parametrize("offset", [-20.0, 15.0])
def test_isa_offset_shifts_temperature_at_constant_pressure(offset):
    ours = isa(HEIGHTS, offset)
    ref = Atmosphere(HEIGHTS)
    assert np.max(np.abs(ours.pressure / ref.pressure - 1)) < 1e-5
    assert np.max(np.abs(ours.temperature - (ref.temperature + offset))) < 1e-9
    rho = ref.pressure / (287.05287 * (ref.temperature + offset))
    assert np.max(np.abs(ours.density / rho - 1)) < 1e-5


def test_isa_rejects_altitudes_outside_the_model():
    with pytest.raises(ValueError, match=r"altitude = 12000 m .*\[-500, 11000\]"):
        isa(12000.0)


def test_pure_helium_density_matches_methods_check_values():
    # docs/methods.md §1.2: pure He at ambient P, T = 0.1693 / 0.1645 kg/m3 at 0 / 300 m
    for h, ref in ((0.0, 0.1693), (300.0, 0.1645)):
        a = isa(h)
        assert gas_density(LiftingGas(purity=1.0), a.pressure, a.temperature) == pytest.approx(
            ref, abs=1e-4)


def test_impurity_and_superpressure_make_gas_heavier_and_hydrogen_is_lighter():
    a = isa(300.0)
    pure = gas_density(LiftingGas(purity=1.0), a.pressure, a.temperature)
    impure = gas_density(LiftingGas(purity=0.95), a.pressure, a.temperature)
    pressed = gas_density(LiftingGas(purity=1.0, superpressure=400), a.pressure, a.temperature)
    h2 = gas_density(LiftingGas(kind="hydrogen", purity=1.0), a.pressure, a.temperature)
    assert impure > pure and pressed > pure and h2 < pure
    # purity 0 is air at hull pressure: no net lift left
    air = gas_density(LiftingGas(purity=1e-12), a.pressure, a.temperature)
    assert air == pytest.approx(a.density, rel=1e-9)


def test_fixed_density_is_the_thesis_constant():
    g = LiftingGas(density_model="fixed")
    assert gas_density(g, 9e4, 250.0) == pytest.approx(0.169)
    assert LiftingGas(kind="hydrogen", density_model="fixed").fixed_density_value == 0.085
