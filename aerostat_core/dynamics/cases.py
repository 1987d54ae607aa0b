"""Reference cases of docs/dynamics.md §3.1 (point aerostat "case P", R1-R4) and the thesis design.

The R numbers were computed twice, independently, with MoorDyn 2.7.2 and with a quasi-static
shooting solver / own lumped-mass code (docs/dynamics.md §3.1); they agree to millimetres. Tests,
the benchmark and the app use these definitions so that all of them run the same cases.
"""

from __future__ import annotations

from .bodies import PointAerostat
from .system import Atmosphere, DynamicSystem
from .tether import TetherModel
from .wind import MeanProfile, SpeedSchedule, WindScenario

#: Case P constants: air density [kg/m3] and gravity [m/s2] of the reference runs.
CASE_P_RHO = 1.225
CASE_P_G = 9.81

#: Reference values (docs/dynamics.md §3.1) [m, N, s, m/s].
R1 = {"x": 48.539, "z": 316.253, "tension_top": (61.25, 739.67), "tension_winch": (151.89, 663.14)}
R2 = {"x": 44.443, "z": 316.958, "tension_winch": (127.91, 667.84)}
R3 = {"x_before": 12.28, "z_before": 319.97, "x_peak": 55.38, "t_peak": 29.1, "z_min": 315.12,
      "x_final": 48.54, "crossings": (19.4, 48.9, 78.2, 106.7), "settle_5pct": 43.0,
      "settle_2pct": 66.0, "vx_max": 2.56, "vz_absmax": 0.29}
R4 = {8: (48.535, 316.258), 16: (48.538, 316.254), 32: (48.539, 316.253), 64: (48.539, 316.253)}
#: MoorDyn's wall time quoted in docs/dynamics.md §4.1 [s] for 400 s simulated, N = 32, dtM = 2e-4 s,
#: on a shared 2-core machine (so about 32 s for the 300 s R3 case).
MOORDYN_QUOTED_WALL_400S = 43.0


def case_p_point() -> PointAerostat:
    """M = 71.6 kg, V = 120 m3, C_D A = 1 m2, C_a = 0.5, no Froude-Krylov."""
    return PointAerostat(mass=71.6, volume=120.0, drag_area=1.0, added_mass_coefficient=0.5,
                         unsteady_wind_inertia=False)


def case_p_tether(segments: int = 32) -> TetherModel:
    """L = 320 m, d = 4 mm, w = 0.02 kg/m, EA = 1 MN, C_dn = 1.2, C_dt = 0.01, zeta = 1, in
    MoorDyn's convention (the damper may push while a segment shortens: the R3 start from a
    straight, unstretched line has brief slack moments)."""
    return TetherModel(length=320.0, segments=segments, linear_density=0.02, diameter=0.004,
                       axial_stiffness=1.0e6, damping_ratio=1.0, normal_drag_coefficient=1.2,
                       tangential_drag_coefficient=0.01, damper_compression=True)


def case_p_system(segments: int = 32) -> DynamicSystem:
    """The point-aerostat system of case P."""
    return DynamicSystem(case_p_point(), case_p_tether(segments), g=CASE_P_G,
                         atmosphere=Atmosphere(CASE_P_RHO))


def r1_wind() -> WindScenario:
    """R1: uniform 10 m/s."""
    return WindScenario.steady(10.0)


def r2_wind() -> WindScenario:
    """R2: power law U = 6 (z/10)^(1/7)."""
    return WindScenario.steady(6.0, MeanProfile("power", 10.0, 1.0 / 7.0))


def r3_wind() -> WindScenario:
    """R3: 5 m/s from t = 0, linear ramp to 10 m/s over 150-151 s."""
    return WindScenario(SpeedSchedule((0.0, 150.0, 151.0), (5.0, 5.0, 10.0)))


#: R3 initial state: straight vertical line, point at 319.5 m (MoorDyn file "Free 0 0 -680.5"
#: with the anchor at -1000 m), at rest.
R3_TOP0 = (0.0, 319.5)


def thesis_design(volume: float | None = None, fineness_ratio: float | None = None):
    """The thesis' optimised aerostat: the static engine's ``thesis_optimized()`` preset (about
    120 m3, 10 kg payload at 300 m, volume sized to the calibrated blow-by limit). ``volume`` [m3]
    and ``fineness_ratio`` [-] override the preset (e.g. 120 m3 with f = 4, the issue's reading of
    the thesis)."""
    from aerostat_core.model.design import design
    from aerostat_core.model.presets import thesis_optimized

    req, cfg = thesis_optimized()
    if volume is not None:
        cfg = cfg.with_design_variables(volume=volume)
    if fineness_ratio is not None:
        cfg = cfg.with_design_variables(fineness_ratio=fineness_ratio)
    return design(req, cfg)
