"""Live 3-D cross-check of the 6-DOF model's tether against MoorDyn (docs/dynamics.md §7.7).

A point aerostat on the 3-D lumped-mass line in a uniform wind whose direction veers with height,
so the line leaves the vertical plane. MoorDyn side: as :mod:`.moordyn_check` (air as its water,
the system below its free surface), with the wind as a steady current profile (``Currents 1``,
``current_profile.txt``: rows z, u_x, u_y, u_z). 6-DOF side: the point is emulated exactly by a
"hull" whose only aerodynamics are the per-unit-q tables N = C_D A sin alpha_t, A = C_D A cos
alpha_t, i.e. the drag 1/2 rho C_D A |v_r| v_r, with its confluence point and CG at O (no
moment reaches the attitude) and the isotropic added mass C_a rho V.
"""

from __future__ import annotations

import math
import os
import tempfile
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

from aerostat_core.dynamics.bodies import PointAerostat, ellipsoid_hull
from aerostat_core.dynamics.moordyn_check import Z_OFFSET, current_heights, input_file
from aerostat_core.dynamics.sixdof import Hull6, System6, Wind3D
from aerostat_core.dynamics.system import Atmosphere
from aerostat_core.dynamics.tether import TetherModel


def point_hull6(point: PointAerostat, rho: float) -> Hull6:
    """A 6-DOF hull that behaves exactly as the point aerostat (module docstring)."""
    cda = point.drag_area

    def aero(alpha):
        return {"normal_inviscid": cda * np.abs(np.sin(alpha)), "axial_inviscid": cda * np.cos(alpha)}

    h = ellipsoid_hull(volume=point.volume, mass=point.mass, cg=(0.0, 0.0), inertia_cg=10.0,
                       confluence=(0.0, 0.0), rho=rho, aero=aero, aero_axial=False,
                       aero_crossflow=False, aero_fins=False, unsteady_wind_inertia=False)
    ca = point.added_mass_coefficient * rho * point.volume
    h = replace(h, added_mass=(ca, ca, 1.0))
    return Hull6(h, roll_inertia=10.0, yaw_inertia=10.0)


def point_system6(point: PointAerostat, tether: TetherModel, rho: float, g: float) -> System6:
    """The 6-DOF system of a point aerostat (:func:`point_hull6`)."""
    return System6(point_hull6(point, rho), tether, g=g, atmosphere=Atmosphere(rho))


def straight_state6(system: System6, top) -> np.ndarray:
    """Rest state with a straight line from the winch to ``top`` = (x, y, z) [m] (the point at
    C = O), body axes at the identity attitude of the upwind frame."""
    n = system.tether.segments
    y = np.zeros(system.n_state)
    top = np.asarray(top, float)
    for i in range(1, n):
        y[6 * (i - 1):6 * (i - 1) + 3] = top * i / n
    b = system.hull_index
    y[b:b + 3] = top
    y[b + 3] = 1.0
    return y


def veer_wind(speed: float, veer_deg_per_100m: float) -> Wind3D:
    """Uniform ``speed`` [m/s] along x at the winch, turning by ``veer_deg_per_100m`` with height."""
    return Wind3D.steady(speed, veer_deg_per_100m=veer_deg_per_100m, veer_height=0.0)


def run_point_case3d(point: PointAerostat, tether: TetherModel, speed: float,
                     veer_deg_per_100m: float, duration: float, top0, rho: float = 1.225,
                     g: float = 9.81, dtm: float = 2e-4, dt_out: float = 0.1,
                     dz: float = 2.0) -> dict:
    """Run the veering-wind point case in MoorDyn; returns t, x, y, z [s, m] of the point and
    the wall time [s]. ``top0`` = (x, y, z) above the winch, the line straight at rest."""
    import moordyn

    t = tether
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp)
        inp = input_file("Tethered point aerostat in a veering wind (aerostat_core.dynamics 6-DOF "
                         "cross-check)", point, t, top0, rho, g, dtm, currents=1)
        path = base / "aerostat.txt"
        path.write_text(inp)
        z = current_heights(t.length, dz)
        h = np.maximum(z, 0.0)
        chi = np.radians(veer_deg_per_100m) / 100.0 * h
        rows = [f"{zi - Z_OFFSET:.4f} {speed * math.cos(c):.8f} {speed * math.sin(c):.8f} 0.0"
                for zi, c in zip(z, chi)]
        (base / "current_profile.txt").write_text(
            "--------------------- MoorDyn steady currents File ---------------\n"
            "wind as a current (aerostat_core.dynamics.moordyn_check3d)\n"
            "z (m), ux (m/s), uy (m/s), uz (m/s)\n" + "\n".join(rows) + "\n")
        cwd = os.getcwd()
        os.chdir(base)
        try:
            t0 = time.perf_counter()
            system = moordyn.Create(str(path))
            moordyn.Init_NoIC(system, [], [])
            top = moordyn.GetPoint(system, 2)
            n = int(math.floor(duration / dt_out + 1e-9))
            ts = np.arange(n + 1) * dt_out
            out = np.empty((n + 1, 3))
            p = moordyn.GetPointPos(top)
            out[0] = (p[0], p[1], p[2] + Z_OFFSET)
            for k in range(1, n + 1):
                moordyn.Step(system, [], [], ts[k - 1], dt_out)
                p = moordyn.GetPointPos(top)
                out[k] = (p[0], p[1], p[2] + Z_OFFSET)
            wall = time.perf_counter() - t0
            moordyn.Close(system)
        finally:
            os.chdir(cwd)
    return {"t": ts, "x": out[:, 0], "y": out[:, 1], "z": out[:, 2], "wall_time": wall}
