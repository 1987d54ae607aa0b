"""Property-based tests over the whole valid input domain (hypothesis)."""

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from aerostat_core import (
    AeroModel,
    Configuration,
    ConfluenceSpec,
    Fabric,
    FinSpec,
    HullSpec,
    LiftingGas,
    Requirement,
    TetherSpec,
    WindProfile,
    design,
)
from aerostat_core.model.statics import moment_about_confluence


@st.composite
def requirements(draw):
    altitude = draw(st.floats(10, 3000))
    return Requirement(
        payload_mass=draw(st.floats(0.1, 500)),
        altitude=altitude,
        site_elevation=draw(st.floats(-400, 5000)),
        isa_offset=draw(st.floats(-40, 40)),
        wind_max=draw(st.floats(0.5, 40)),
        wind_step=draw(st.floats(0.5, 10)),
        design_wind=draw(st.floats(0, 40)),
        blow_by_limit=draw(st.floats(0.01, 1.0)) * altitude,
    )


@st.composite
def configurations(draw):
    arrangement = draw(st.sampled_from(["+", "x", "inverted-y"]))
    return Configuration(
        gas=LiftingGas(kind=draw(st.sampled_from(["helium", "hydrogen"])),
                       purity=draw(st.floats(0.5, 1.0)),
                       superpressure=draw(st.floats(0, 5000)),
                       density_model=draw(st.sampled_from(["ideal", "fixed"]))),
        hull_fabric=Fabric("h", draw(st.floats(0.02, 2.0))),
        fin_fabric=Fabric("f", draw(st.floats(0.02, 2.0))),
        tether=TetherSpec("t", draw(st.floats(0.001, 1.0)), draw(st.floats(0.001, 0.05)),
                          draw(st.floats(0.1, 3.0)), draw(st.floats(0, 0.1)),
                          draw(st.floats(100, 1e7)), draw(st.floats(1e4, 1e9))),
        hull=HullSpec(fineness_ratio=draw(st.floats(1.5, 8.0)),
                      nose_fraction=draw(st.floats(0.2, 0.8)),
                      volume=draw(st.one_of(st.none(), st.floats(1.0, 1e5)))),
        fins=FinSpec(count=3 if arrangement == "inverted-y" else 4, arrangement=arrangement,
                     area_change=draw(st.floats(-50, 200)), position=draw(st.floats(0.4, 0.95)),
                     aspect_ratio=draw(st.floats(0.5, 6)), taper_ratio=draw(st.floats(0.1, 1))),
        aero=AeroModel(hull_efficiency=draw(st.floats(0, 2)),
                       hull_crossflow_drag=draw(st.floats(0, 2)),
                       cutoff=draw(st.sampled_from(["fin", "tail"])),
                       fin_efficiency=draw(st.floats(0, 1.5)),
                       fin_stall_angle_deg=draw(st.floats(5, 40))),
        confluence=ConfluenceSpec(drop_ratio=draw(st.floats(0.05, 3)),
                                  xi_offset=draw(st.floats(-0.2, 0.2))),
        wind_profile=WindProfile(kind=draw(st.sampled_from(["uniform", "power", "log"]))),
        misc_mass_ratio=draw(st.floats(0, 2)),
    )


def _finite(x):
    return bool(np.all(np.isfinite(np.asarray(x, float))))


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(req=requirements(), cfg=configurations())
def test_design_invariants_hold_over_the_whole_input_domain(req, cfg):
    d = design(req, cfg)
    # no NaN or inf leaves the engine
    for v in d.summary().values():
        if isinstance(v, float):
            assert np.isfinite(v)
    for row in d.performance.rows() + d.mass_rows() + d.geometry_rows():
        for v in row.values():
            if isinstance(v, float):
                assert np.isfinite(v), row
    assert _finite(d.tether_x) and _finite(d.tether_z) and _finite(d.cm)
    # mass breakdown closes; buoyancy = weight + free lift
    rows = d.mass_rows()
    assert np.isclose(sum(r["mass_kg"] for r in rows[:-1]), rows[-1]["mass_kg"], rtol=1e-12)
    assert np.isclose(d.buoyancy, d.total_mass * d.airframe.g + d.free_lift, rtol=1e-9,
                      atol=1e-9)
    # wherever a stable trim was found, the moment about the confluence point vanishes
    p = d.performance
    found = ~p.flags["stability"]
    if found.any():
        m = moment_about_confluence(d.airframe, cfg.aero, np.radians(p.alpha_eq[found]),
                                    p.wind_speed[found])
        af = d.airframe
        q_max = 0.5 * float(af.air_density) * float(p.wind_speed.max()) ** 2
        force = float(af.buoyancy + af.aerostat_weight) + q_max * float(
            af.hull.reference_area + af.fins.area_total)
        assert np.max(np.abs(m)) <= 1e-7 * force * float(af.hull.length)
    # a feasible design meets its blow-by limit
    if d.feasible:
        assert d.design_point["blow_by_m"] <= req.blow_by_limit * (1 + 1e-3)
