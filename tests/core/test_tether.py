"""Static tether: catenary limit, zero wind, convergence, force balance, reference cases R1/R2."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from aerostat_core import TetherSpec, design, thesis_baseline
from aerostat_core.studies.reference import case_p_static
from aerostat_core.tether.statics import solve_tether

SPEC = TetherSpec("t", 0.02, 0.005, 1.0, 0.01, 1e4, 1.0e6)


def _still(z, h):
    return np.zeros_like(np.asarray(z, float))


def elastic_catenary(h_tension, v_top, w, ea, s):
    """Offsets (X, Z) below the top after unstretched arc s (Irvine, *Cable Structures*, 1981)."""
    v = v_top - w * s
    x = (h_tension / w) * (np.arcsinh(v_top / h_tension) - np.arcsinh(v / h_tension))
    z = (h_tension / w) * (np.hypot(1, v_top / h_tension) - np.hypot(1, v / h_tension))
    if math.isfinite(ea):
        x = x + h_tension * s / ea
        z = z + (v_top * s - 0.5 * w * s * s) / ea
    return -x, -z


@pytest.mark.parametrize("ea", [1.0e6, 5.0e4, math.inf])
@pytest.mark.parametrize("h_tension, v_top", [(60.0, 740.0), (400.0, 500.0)])
def test_no_drag_profile_is_the_analytic_catenary(ea, h_tension, v_top):
    # predicted: without wind there is no tether drag; the march must give the catenary
    spec = TetherSpec("t", 0.02, 0.005, 1.0, 0.01, 1e4, ea)
    w = 0.02 * 9.81
    sol = solve_tether(lambda h: (np.array(h_tension), np.array(v_top)), 320.0, spec, 1.2, _still,
                       w, segments=50, sheared=False)
    s = np.linspace(0, 320.0, 51)
    x_ref, z_ref = elastic_catenary(h_tension, v_top, w, ea, s)
    x = sol.x - sol.x[0]
    z = sol.z - sol.z[0]
    assert np.max(np.abs(x - x_ref)) <= 0.005 * abs(x_ref[-1])
    assert np.max(np.abs(z - z_ref)) <= 0.005 * abs(z_ref[-1])
    # and much tighter than the 0.5 % the issue asks for
    assert abs(sol.blow_by - (-x_ref[-1])) < 1e-3


def test_march_converges_with_segments_at_second_order():
    req, cfg = thesis_baseline()
    from dataclasses import replace

    ref = design(req, replace(cfg, tether_segments=2000)).performance.blow_by
    errs = [np.max(np.abs(design(req, replace(cfg, tether_segments=n)).performance.blow_by - ref))
            for n in (25, 50, 100)]
    assert errs[0] > errs[1] > errs[2]
    assert errs[0] / errs[1] == pytest.approx(4.0, rel=0.3)  # Heun: error ~ ds^2
    assert errs[1] < 1e-3  # the default 50 segments: under a millimetre


def test_zero_wind_gives_a_vertical_tether_and_no_blow_by():
    req, cfg = thesis_baseline()
    d = design(req, cfg)
    assert d.performance.wind_speed[0] == 0.0
    assert d.performance.blow_by[0] == pytest.approx(0.0, abs=1e-9)
    assert np.max(np.abs(d.tether_x[:, 0])) < 1e-9
    assert d.performance.tether_angle_top[0] == pytest.approx(0.0, abs=1e-9)
    assert d.performance.alpha_eq[0] == pytest.approx(0.0, abs=1e-6)
    # tension at the top = net static lift of the aerostat; at the winch less the line weight
    af = d.airframe
    net = float(af.buoyancy - af.aerostat_weight)
    assert d.performance.tension_top[0] == pytest.approx(net, rel=1e-12)
    w_line = af.tether_weight_per_length
    assert d.performance.tension_winch[0] == pytest.approx(net - w_line * 300.0, rel=1e-9)


def test_tension_at_confluence_point_equals_drag_and_net_lift():
    req, cfg = thesis_baseline()
    d = design(req, cfg)
    p = d.performance
    af = d.airframe
    net = float(af.buoyancy - af.aerostat_weight) + p.dynamic_lift
    assert np.allclose(p.tension_top, np.hypot(p.drag, net), rtol=1e-12)
    elev = np.degrees(np.arctan2(net, p.drag))
    assert np.allclose(p.tether_angle_top, 90.0 - elev, atol=1e-9)


def test_reference_case_r1_point_aerostat_uniform_wind():
    # predicted, docs/dynamics.md §3.1 R1: MoorDyn and a shooting solver give (48.539, 316.253) m
    x, z = case_p_static(lambda z: 10.0 * np.ones_like(np.asarray(z, float)))
    assert x == pytest.approx(48.539, abs=0.05)
    assert z == pytest.approx(316.253, abs=0.05)
    assert abs(x - 48.539) < 0.005 and abs(z - 316.253) < 0.005  # in fact within 5 mm


def test_reference_case_r2_point_aerostat_power_law():
    # predicted, docs/dynamics.md §3.1 R2: U = 6 (z/10)^(1/7) -> (44.443, 316.958) m
    x, z = case_p_static(lambda z: 6.0 * (np.maximum(np.asarray(z, float), 1e-9) / 10) ** (1 / 7))
    assert x == pytest.approx(44.443, abs=0.05)
    assert z == pytest.approx(316.958, abs=0.05)


@settings(max_examples=40, deadline=None)
@given(h_t=st.floats(1.0, 2000.0), v_t=st.floats(50.0, 5000.0), u=st.floats(0.0, 30.0))
def test_global_force_balance_of_the_line(h_t, v_t, u):
    # winch force = top force + all line loads: the horizontal tension only grows by drag and
    # the vertical one falls by weight (+ drag component); the line stays within its length
    w = SPEC.linear_density * 9.81
    sol = solve_tether(lambda h: (np.array(h_t), np.array(v_t)), 300.0, SPEC, 1.2,
                       lambda z, h: u * np.ones_like(np.asarray(z, float)), w, 50, sheared=False)
    stretch = 1 + np.max(sol.tension) / SPEC.axial_stiffness
    assert np.hypot(sol.blow_by, sol.height) <= 300.0 * stretch + 1e-9
    assert sol.tension_top == pytest.approx(np.hypot(h_t, v_t))
    assert np.all(np.isfinite(sol.x)) and np.all(np.isfinite(sol.z))
    if u == 0.0:
        assert sol.tension_winch == pytest.approx(np.hypot(h_t, v_t - w * 300.0), rel=1e-9)


def test_profile_at_any_wind_matches_the_sweep_and_interpolates():
    d = design(*thesis_baseline())
    x10, z10 = d.tether_profile(10.0)
    assert np.allclose(x10, d.tether_x[:, 10]) and np.allclose(z10, d.tether_z[:, 10])
    x, z = d.tether_profile(10.5)
    assert d.tether_x[0, 10] < x[0] < d.tether_x[0, 11]
    assert x[-1] == 0.0 and z[-1] == 0.0  # from the winch
