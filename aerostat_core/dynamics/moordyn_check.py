"""Optional live cross-check against MoorDyn (PyPI ``moordyn``, BSD-3) for point-aerostat cases.

MoorDyn has no aerostat aerodynamics, so only the point-aerostat mode (the R cases of
docs/dynamics.md §3.1) can be compared. The air is MoorDyn's "water" (``rho 1.225``), the wind its
current (``Currents 2``: a time table on a height grid), and the whole system sits below its free
surface (winch at z = -1000 m, ``WtrDpth 1001``, no seabed stiffness) because MoorDyn switches off
buoyancy and drag above z = 0 (docs/dynamics.md §4.3). ``moordyn`` (PyPI, 2.7.2) is a pinned
test dependency (requirements-dev.txt), not a runtime one: :func:`moordyn_available` says whether
it is importable.
"""

from __future__ import annotations

import math
import tempfile
import time
from pathlib import Path

import numpy as np

from .bodies import PointAerostat
from .tether import TetherModel
from .wind import MeanProfile, SpeedSchedule

#: Depth of the winch below MoorDyn's free surface [m].
Z_OFFSET = 1000.0


def moordyn_available() -> bool:
    """True when the ``moordyn`` package can be imported."""
    try:
        import moordyn  # noqa: F401
    except Exception:  # pragma: no cover - depends on the machine
        return False
    return True


#: MoorDyn's ``Currents`` options used here: 1 a steady profile (``current_profile.txt``), 2 a
#: time table on a height grid (``current_profile_dynamic.txt``).
CURRENTS = {1: "steady current profile", 2: "dynamic current table"}


def input_file(title: str, point: PointAerostat, tether: TetherModel, top, rho: float, g: float,
               dtm: float, currents: int) -> str:
    """MoorDyn's input file of a point aerostat on the tether (module docstring): the line from
    the winch to the point at ``top`` = (x, y, z) above the winch [m], air of density ``rho``
    [kg/m3] as its water, gravity ``g`` [m/s2], time step ``dtm`` [s] and the wind as the
    current option ``currents`` (:data:`CURRENTS`). The 2-D and the 3-D cross-checks share it."""
    t = tether
    zeta = -1.0 * t.damping_ratio
    return f"""--------------------- MoorDyn Input File ------------------------------------
{title}
----------------------- LINE TYPES ------------------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI    Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2) (-)  (-)    (-)     (-)
tether     {t.diameter:.6g}  {t.linear_density:.6g}  {t.stiffness:.6g}  {zeta:.6g}  0  {t.normal_drag_coefficient:.6g}  1.0  {t.tangential_drag_coefficient:.6g}  0.0
---------------------- POINTS --------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     0       0       {-Z_OFFSET:.6f}   0      0       0      0
2     Free      {top[0]:.6f}  {top[1]:.6f}   {top[2] - Z_OFFSET:.6f}  {point.mass:.6g}  {point.volume:.6g}  {point.drag_area:.6g}  {point.added_mass_coefficient:.6g}
-------------------------- LINES -------------------------------------------------
ID   LineType AttachA  AttachB  UnstrLen  NumSegs  Outputs
(#)   (name)   (#)      (#)      (m)       (-)      (-)
1     tether   1        2        {t.length:.6f}  {t.segments}    -
-------------------------- OPTIONS -----------------------------------------------
0         writeLog     - no log file
{dtm:.6g}    dtM          - time step
{rho:.6g}     rho          - fluid density
{g:.6g}      g            - gravity
{Z_OFFSET + 1.0:.1f}    WtrDpth      - depth
0         kBot         - no seabed
0         cBot         - no seabed
{currents}         Currents     - {CURRENTS[currents]}
1         disableOutTime - quiet
------------------------- need this line -------------------------------------
"""


def current_heights(length: float, dz: float) -> np.ndarray:
    """Heights of MoorDyn's current grid above the winch [m]: from 1 m below it to MoorDyn's
    free surface (``Z_OFFSET`` above it) in steps of ``dz`` [m]; ``length`` is the tether's [m]."""
    z = np.arange(-1.0, Z_OFFSET + length + dz, dz)
    return z[z <= Z_OFFSET]


def write_case(folder, point: PointAerostat, tether: TetherModel, schedule: SpeedSchedule,
               profile: MeanProfile, top0, rho: float, g: float, dtm: float,
               dz: float = 5.0) -> Path:
    """Write MoorDyn's input file and current table for a point-aerostat case; returns the file.

    The schedule must use linear ramps (MoorDyn interpolates its current table linearly in time).
    """
    if schedule.shape != "linear":
        raise ValueError("MoorDyn interpolates the current table linearly: use linear ramps")
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    t = tether
    inp = input_file("Tethered point aerostat in air (aerostat_core.dynamics cross-check)", point,
                     t, (top0[0], 0.0, top0[1]), rho, g, dtm, currents=2)
    path = folder / "aerostat.txt"
    path.write_text(inp)
    z = current_heights(t.length, dz)
    zw = z - Z_OFFSET
    pf = profile.factor(np.maximum(z, 0.0))
    lines = ["--------------------- MoorDyn dynamic currents File ---------------",
             "wind as a current (aerostat_core.dynamics.moordyn_check)", "", "",
             " ".join(f"{v:.4f}" for v in zw), ""]
    times = list(schedule.times)
    speeds = list(schedule.speeds)
    if times[0] > 0.0:
        times.insert(0, 0.0)
        speeds.insert(0, speeds[0])
    times.append(max(times[-1], 0.0) + 1e5)
    speeds.append(speeds[-1])
    for ti, ui in zip(times, speeds):
        lines.append(f"{ti:.6f} " + " ".join(f"{ui * p:.6f}" for p in pf))
    (folder / "current_profile_dynamic.txt").write_text("\n".join(lines) + "\n")
    return path


def run_point_case(point: PointAerostat, tether: TetherModel, schedule: SpeedSchedule,
                   duration: float, top0, profile: MeanProfile | None = None, rho: float = 1.225,
                   g: float = 9.81, dtm: float = 2e-4, dt_out: float = 0.05, folder=None) -> dict:
    """Run a point-aerostat case in MoorDyn.

    Parameters
    ----------
    point, tether : PointAerostat, TetherModel
    schedule : SpeedSchedule
        Linear ramps (uniform or profiled by ``profile``).
    duration : float
        [s].
    top0 : (float, float)
        Initial point position (x, z) above the winch [m]; the line starts straight (MoorDyn's
        ``Init_NoIC``).
    rho, g : float
        Air density [kg/m3] and gravity [m/s2].
    dtm : float
        MoorDyn's internal time step [s] (it must resolve the axial mode; 2e-4 s for N = 32).
    dt_out : float
        Sampling [s].

    Returns
    -------
    dict with t, x, z, vx, vz [s, m, m/s] of the point, anchor_force (M, 3) [N], wall_time [s].
    """
    import moordyn

    profile = profile or MeanProfile()
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(folder) if folder is not None else Path(tmp)
        path = write_case(base, point, tether, schedule, profile, top0, rho, g, dtm)
        import os

        cwd = os.getcwd()
        os.chdir(base)  # MoorDyn looks for the current file next to the input and in cwd
        try:
            t0 = time.perf_counter()
            system = moordyn.Create(str(path))
            moordyn.SetVerbosity(system, moordyn.LEVEL_NONE) if hasattr(moordyn, "SetVerbosity") \
                else None
            moordyn.Init_NoIC(system, [], [])
            anchor = moordyn.GetPoint(system, 1)
            top = moordyn.GetPoint(system, 2)
            n = int(math.floor(duration / dt_out + 1e-9))
            ts = np.arange(n + 1) * dt_out
            out = np.empty((n + 1, 4))
            fa = np.empty((n + 1, 3))
            p = moordyn.GetPointPos(top)
            v = moordyn.GetPointVel(top)
            out[0] = (p[0], p[2] + Z_OFFSET, v[0], v[2])
            fa[0] = moordyn.GetPointForce(anchor)
            for k in range(1, n + 1):
                moordyn.Step(system, [], [], ts[k - 1], dt_out)
                p = moordyn.GetPointPos(top)
                v = moordyn.GetPointVel(top)
                out[k] = (p[0], p[2] + Z_OFFSET, v[0], v[2])
                fa[k] = moordyn.GetPointForce(anchor)
            wall = time.perf_counter() - t0
            moordyn.Close(system)
        finally:
            os.chdir(cwd)
    return {"t": ts, "x": out[:, 0], "z": out[:, 1], "vx": out[:, 2], "vz": out[:, 3],
            "anchor_force": fa, "wall_time": wall}
