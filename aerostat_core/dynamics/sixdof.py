"""The 6-DOF tethered aerostat: hull, 3-D wind settings, assembly, equilibrium and runs
(docs/dynamics.md §7).

Typical use::

    from aerostat_core import design, thesis_optimized
    from aerostat_core.dynamics.sixdof import Wind3D, simulate6, system6_from_design
    d = design(*thesis_optimized())
    s6 = system6_from_design(d, segments=20)
    res = simulate6(s6, Wind3D.steady(10.0, azimuth_deg=30.0), 60.0, design=d)
    res.signal("roll"), res.signal("y_C")

The kernels are :mod:`.sixdof_kernel`; the integrator is the 3-DOF model's TR-BDF2 of
:mod:`.solver` (the kernel dispatches on the mode of the parameter vector).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from aerostat_core.base.fields import number, validate
from aerostat_core.dynamics.bodies import HullModel
from aerostat_core.dynamics.kernel_cache import ensure_fresh_cache
from aerostat_core.dynamics.layout import P_MODE, P_SIZE, P_XA, P_XC, P_ZA, P_ZC
from aerostat_core.dynamics.sixdof_kernel import (
    DIAG6_NAMES,
    ND6,
    STATUS6,
    nodes6_kernel,
    rhs6_kernel,
)
from aerostat_core.dynamics.sixdof_layout import (
    Q_AZ,
    Q_BREAK_T,
    Q_DIR_STEP,
    Q_DIR_T0,
    Q_DIR_TR,
    Q_FIN_CD0,
    Q_FIN_KP,
    Q_FIN_SIDE,
    Q_GV_AMP,
    Q_GV_CONV,
    Q_GV_T0,
    Q_GV_TR,
    Q_IA,
    Q_IAX,
    Q_IO,
    Q_LEN0,
    Q_MINV,
    Q_MY,
    Q_QSTAB,
    Q_REEL_RAMP,
    Q_REEL_SPEED,
    Q_REEL_T0,
    Q_REEL_T1,
    Q_SIZE,
    Q_TV_ON,
    Q_VEER,
    Q_VEER_Z,
    Q_YA,
    Q_ZW,
)
from aerostat_core.dynamics.system import Atmosphere, DynamicSystem, system_from_design
from aerostat_core.dynamics.tether import TetherModel
from aerostat_core.dynamics.wind import WindField, WindScenario

#: Quaternion norm stabilisation gain [1/s] (Baumgarte-type; the kernel normalises anyway).
QUATERNION_GAIN = 1.0
#: Fin angles from the horizontal [deg] per arrangement (the static model's).
FIN_ANGLES_DEG = {"+": (0.0, 90.0, 180.0, 270.0), "x": (45.0, 135.0, 225.0, 315.0),
                  "inverted-y": (90.0, 210.0, 330.0)}


# --------------------------------------------------------------------------------------------
# Hull
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class Hull6:
    """The 3-DOF :class:`~.bodies.HullModel` plus what the lateral-directional motion needs.

    Attributes
    ----------
    hull : HullModel
        Mass, CG, pitch inertia, confluence point, added masses, aerodynamic tables.
    roll_inertia, yaw_inertia : float
        I_xx, I_zz about the CG [kg m2] (products of inertia neglected: the hull is symmetric
        about its vertical plane and the payload's fore-aft offset is small).
    fin_side_ratio : float
        Vertical / horizontal projected fin area, sum S_1 sin^2 phi_k / sum S_1 cos^2 phi_k [-]
        (1 for the symmetric "+", "x" and inverted-"Y" layouts; the lift slope is the static
        model's for every layout).
    fin_roll_damping : float
        K_p = 1/2 eta_f C_L,alpha S_1 sum r_k^2 [m4]: roll moment -rho |u_f| K_p p of the panels.
    arrangement : str
        "+", "x" or "inverted-y".
    roll_added_inertia : float
        Roll added inertia [kg m2] (0 for a body of revolution; the fins' is neglected).
    """

    hull: HullModel
    roll_inertia: float
    yaw_inertia: float
    fin_side_ratio: float = 1.0
    fin_roll_damping: float = 0.0
    arrangement: str = "+"
    roll_added_inertia: float = 0.0


def fin_layout_factors(arrangement: str, panel_area: float, lift_slope: float, efficiency: float,
                       radius: float) -> tuple[float, float]:
    """(vertical/horizontal projected area ratio [-], roll damping K_p [m4]) of a fin layout.

    ratio = sum sin^2 phi_k / sum cos^2 phi_k; K_p = 1/2 eta C_L,alpha S_1 n r^2, with phi_k the
    fin angles from the horizontal (:data:`FIN_ANGLES_DEG`), S_1 one panel's area [m2],
    C_L,alpha the static model's fin lift slope [1/rad], eta its efficiency [-] and r the radius
    of the panels' centroid [m]. Source: strip theory of each panel (docs/dynamics.md §7.2).

    Examples
    --------
    >>> [round(fin_layout_factors(a, 1.0, 2.0, 1.0, 1.0)[0], 6) for a in ("+", "x", "inverted-y")]
    [1.0, 1.0, 1.0]
    >>> fin_layout_factors("inverted-y", 2.0, 2.5, 0.8, 2.0)[1]
    24.0
    """
    if arrangement not in FIN_ANGLES_DEG:
        raise ValueError(f"fin arrangement = {arrangement!r}; valid options "
                         f"{tuple(FIN_ANGLES_DEG)}")
    ph = np.radians(FIN_ANGLES_DEG[arrangement])
    ratio = float(np.sum(np.sin(ph) ** 2) / np.sum(np.cos(ph) ** 2))
    kp = 0.5 * efficiency * lift_slope * panel_area * ph.size * radius**2
    return ratio, float(kp)


def hull6_from_design(design, hull: HullModel | None = None, **hull_options) -> Hull6:
    """The 6-DOF hull of a static-engine design.

    Roll inertia about the CG: thin shell (2/3) m_shell b^2 + gas (2/5) m_gas b^2 (a sphere's
    factors on the maximum radius b, an upper estimate for a slender hull) + fins m_f r_f^2 +
    belly items m_k (z_k - z_CG)^2 + shell and gas m z_CG^2. Yaw inertia: the engine's pitch
    inertia less the vertical offsets' share sum m_k (z_k - z_CG)^2 (which does not resist yaw).
    """
    from aerostat_core.dynamics.bodies import hull_from_airframe

    af = design.airframe
    cfg = design.configuration
    h = hull or hull_from_airframe(af, cfg.aero, **hull_options)
    m = af.mass
    b = float(np.asarray(af.hull.b).reshape(-1)[0])
    zc = float(np.asarray(m.z_cg).reshape(-1)[0])
    mass = {k: float(np.asarray(v).reshape(-1)[0]) for k, v in m.items.items()}
    pos = {k: tuple(float(np.asarray(c).reshape(-1)[0]) for c in v) for k, v in m.positions.items()}
    fins = af.fins
    z_f = np.abs(np.array([float(np.asarray(z).reshape(-1)[0]) for z in fins.z_fins]))
    arr = cfg.fins.arrangement
    ph = np.radians(FIN_ANGLES_DEG[arr])
    r_f = float(np.max(z_f) / np.max(np.abs(np.sin(ph)))) if np.max(z_f) > 0 else b
    i_xx = (2.0 / 3.0) * mass["hull"] * b**2 + 0.4 * mass["lifting gas"] * b**2
    i_xx += mass["fins"] * r_f**2 + (mass["hull"] + mass["lifting gas"] + mass["fins"]) * zc**2
    vertical = 0.0
    for k in ("miscellaneous", "payload", "battery", "ballonet"):
        if k in mass and k in pos:
            d2 = (pos[k][1] - zc) ** 2
            i_xx += mass[k] * d2
            vertical += mass[k] * d2
    i_yy = float(np.asarray(m.pitch_inertia).reshape(-1)[0])
    i_zz = max(i_yy - vertical - (mass["hull"] + mass["lifting gas"]) * zc**2, 0.1 * i_yy)
    ratio, kp = fin_layout_factors(arr, float(np.asarray(fins.area_one).reshape(-1)[0]),
                                   float(np.asarray(fins.lift_slope).reshape(-1)[0]),
                                   cfg.aero.fin_efficiency, r_f)
    return Hull6(h, float(i_xx), float(i_zz), ratio, kp, arr)


def hull6_simple(hull: HullModel, arrangement: str = "+", roll_inertia: float | None = None,
                 yaw_inertia: float | None = None) -> Hull6:
    """A 6-DOF hull from a 3-DOF one (tests): yaw inertia = pitch inertia, roll inertia = the
    pitch inertia x (d/l)^2 x 2.5 (a spheroid's ratio order), no fin roll damping."""
    ratio = fin_layout_factors(arrangement, 1.0, 1.0, 1.0, 1.0)[0]
    iyy = hull.inertia_cg
    ixx = roll_inertia if roll_inertia is not None else 2.5 * iyy * (hull.diameter / hull.length) ** 2
    return Hull6(hull, float(ixx), float(yaw_inertia if yaw_inertia is not None else iyy), ratio,
                 0.0, arrangement)


# --------------------------------------------------------------------------------------------
# Wind in 3-D, winch and break events
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Wind3D:
    """A 3-D wind: the 3-DOF :class:`~.wind.WindScenario` (speed along the wind, vertical) turned
    to an azimuth, veering with height, stepping in direction, with a crosswind gust and lateral
    turbulence (docs/dynamics.md §7.3).

    Parameters
    ----------
    base : WindScenario
    azimuth_deg : float
        chi_0: the direction the wind blows to, from the earth x axis [deg], valid [-360, 360].
    veer_deg_per_100m : float
        Veer with height, d chi/dz [deg/100 m], valid [-90, 90] (chi = chi_0 at ``veer_height``).
    veer_height : float
        Height where the direction is chi_0 [m], valid [0, 5000].
    direction_step_deg : float
        Change of direction [deg], valid [-180, 180], as a (1 - cos) ramp ...
    direction_step_start, direction_step_time : float
        ... starting at [s], valid [0, 1e5], lasting [s], valid [0.1, 600].
    crosswind_gust : float
        1 - cos crosswind gust amplitude (to the left of the wind, +y at chi_0 = 0) [m/s],
        valid [-30, 30]; 0: none.
    crosswind_gust_length, crosswind_gust_start : float
        Gust half-length d_m [m], valid [1, 5000]; start [s], valid [0, 1e5]. Convected with the
        mean wind like the 3-DOF gust.
    lateral_turbulence : bool
        Add the lateral Dryden component v' to the base scenario's turbulence (needs one).
    """

    base: WindScenario = field(default_factory=WindScenario)
    azimuth_deg: float = number(0.0, "Wind azimuth", "deg", -360.0, 360.0)
    veer_deg_per_100m: float = number(0.0, "Wind veer with height", "deg/100 m", -90.0, 90.0)
    veer_height: float = number(0.0, "Height of the reference direction", "m", 0.0, 5000.0)
    direction_step_deg: float = number(0.0, "Wind direction step", "deg", -180.0, 180.0)
    direction_step_start: float = number(20.0, "Direction step start", "s", 0.0, 1e5)
    direction_step_time: float = number(5.0, "Direction step duration", "s", 0.1, 600.0)
    crosswind_gust: float = number(0.0, "Crosswind gust amplitude", "m/s", -30.0, 30.0)
    crosswind_gust_length: float = number(60.0, "Crosswind gust length d_m", "m", 1.0, 5000.0)
    crosswind_gust_start: float = number(20.0, "Crosswind gust start", "s", 0.0, 1e5)
    lateral_turbulence: bool = True

    def __post_init__(self) -> None:
        validate(self)

    @classmethod
    def steady(cls, speed: float, **kw) -> Wind3D:
        """A steady wind of ``speed`` [m/s] (``kw``: the other fields)."""
        return cls(WindScenario.steady(speed), **kw)


@dataclass(frozen=True)
class Events6:
    """Winch and tether events of a 6-DOF run.

    Parameters
    ----------
    reel_speed : float
        Winch line speed [m/s], valid [-5, 5]: > 0 pays out (reel-out), < 0 reels in; 0 none.
    reel_start, reel_duration, reel_ramp : float
        Start [s] valid [0, 1e5], duration at full speed [s] valid [0, 1e5], (1 - cos) speed ramp
        [s] valid [0.1, 60].
    break_time : float or None
        Time the tether breaks at the confluence point [s], valid [0, 1e5]; None: never.
    """

    reel_speed: float = number(0.0, "Winch reel speed (+ out)", "m/s", -5.0, 5.0)
    reel_start: float = number(10.0, "Reel start", "s", 0.0, 1e5)
    reel_duration: float = number(30.0, "Reel duration", "s", 0.0, 1e5)
    reel_ramp: float = number(2.0, "Reel speed ramp", "s", 0.1, 60.0)
    break_time: float | None = number(None, "Tether break time", "s", 0.0, 1e5, empty="never")

    def __post_init__(self) -> None:
        validate(self)


# --------------------------------------------------------------------------------------------
# System
# --------------------------------------------------------------------------------------------
class System6:
    """A 6-DOF hull on a 3-D lumped-mass tether, packed for the kernels (mode 2).

    Built on the 3-DOF :class:`~.system.DynamicSystem` of the same hull and tether (``base``),
    whose parameter vector is extended with the 6-DOF entries (:mod:`.sixdof_kernel`).
    """

    def __init__(self, hull6: Hull6, tether: TetherModel, g: float = 9.81,
                 atmosphere: Atmosphere | None = None, events: Events6 | None = None) -> None:
        ensure_fresh_cache()
        self.hull6 = hull6
        self.events = events or Events6()
        self.base = DynamicSystem(hull6.hull, tether, g=g, atmosphere=atmosphere)
        self.tether = tether
        self.g = self.base.g
        self.atmosphere = self.base.atmosphere
        n = tether.segments
        self.n_state = 6 * (n - 1) + 13
        self.hull_index = 6 * (n - 1)
        h = hull6.hull
        prm = np.zeros(Q_SIZE)
        prm[:P_SIZE] = self.base.prm
        prm[P_MODE] = 2.0
        prm[Q_YA] = 0.0
        prm[Q_ZW] = prm[P_ZA]
        m_top = 0.5 * tether.node_mass
        rg = np.array([h.cg[0], 0.0, h.cg[1]])
        rc = np.array([h.confluence[0], 0.0, h.confluence[1]])
        mt = h.mass + m_top
        rgt = (h.mass * rg + m_top * rc) / mt
        icg = np.diag([hull6.roll_inertia, h.inertia_cg, hull6.yaw_inertia])
        io = (icg + h.mass * (rg @ rg * np.eye(3) - np.outer(rg, rg))
              + m_top * (rc @ rc * np.eye(3) - np.outer(rc, rc)))
        mx, mz, ia = h.added_mass
        m_rb = np.zeros((6, 6))
        m_rb[:3, :3] = mt * np.eye(3)
        s = np.array([[0.0, -rgt[2], rgt[1]], [rgt[2], 0.0, -rgt[0]], [-rgt[1], rgt[0], 0.0]])
        m_rb[:3, 3:] = -mt * s
        m_rb[3:, :3] = mt * s
        m_rb[3:, 3:] = io
        m_a = np.diag([mx, mz, mz, hull6.roll_added_inertia, ia, ia])
        self.mass_matrix = m_rb + m_a
        # rigid mass matrix of the hull alone (energy; the top half segment is the tether's)
        rgs = np.array([[0.0, -rg[2], rg[1]], [rg[2], 0.0, -rg[0]], [-rg[1], rg[0], 0.0]])
        m_h = np.zeros((6, 6))
        m_h[:3, :3] = h.mass * np.eye(3)
        m_h[:3, 3:] = -h.mass * rgs
        m_h[3:, :3] = h.mass * rgs
        m_h[3:, 3:] = icg + h.mass * (rg @ rg * np.eye(3) - np.outer(rg, rg))
        self.hull_mass_matrix = m_h
        self.added_mass_matrix = m_a
        prm[Q_MINV:Q_MINV + 36] = np.linalg.inv(self.mass_matrix).reshape(-1)
        prm[Q_IO:Q_IO + 9] = io.reshape(-1)
        prm[Q_IAX] = hull6.roll_added_inertia
        prm[Q_IA] = ia
        prm[Q_MY] = mz
        prm[Q_FIN_SIDE] = hull6.fin_side_ratio
        prm[Q_FIN_KP] = hull6.fin_roll_damping if h.aero_fins else 0.0
        prm[Q_FIN_CD0] = float(np.interp(0.0, np.arange(h.tables.shape[1]) * h.alpha_grid[1]
                                         + h.alpha_grid[0], h.tables[5]))
        prm[Q_QSTAB] = QUATERNION_GAIN
        prm[Q_LEN0] = tether.length
        ev = self.events
        prm[Q_BREAK_T] = math.inf if ev.break_time is None else float(ev.break_time)
        prm[Q_REEL_SPEED] = ev.reel_speed
        prm[Q_REEL_T0] = ev.reel_start
        prm[Q_REEL_RAMP] = ev.reel_ramp
        prm[Q_REEL_T1] = ev.reel_start + ev.reel_ramp + ev.reel_duration
        self.prm = prm

    # ---- packing ------------------------------------------------------------------------
    def structure(self) -> tuple[int, int]:
        """Band widths (kl, ku) of the Jacobian: node i's six states couple to nodes i-1..i+1
        (11), the hull's 13 to the top free node and back (18)."""
        return (18, 18)

    def data(self, field_: WindField, wind3: Wind3D | None = None):
        """Kernel data tuple for a realised 3-DOF wind and its 3-D settings."""
        prm = self.prm.copy()
        wpar, sched, turb = field_.pack()
        w3 = wind3 or Wind3D(field_.scenario)
        prm[Q_AZ] = math.radians(w3.azimuth_deg)
        prm[Q_VEER] = math.radians(w3.veer_deg_per_100m) / 100.0
        prm[Q_VEER_Z] = w3.veer_height
        prm[Q_DIR_STEP] = math.radians(w3.direction_step_deg)
        prm[Q_DIR_T0] = w3.direction_step_start
        prm[Q_DIR_TR] = w3.direction_step_time
        prm[Q_GV_AMP] = w3.crosswind_gust
        prm[Q_GV_T0] = w3.crosswind_gust_start
        prm[Q_GV_TR] = w3.crosswind_gust_length / max(field_.convection_speed, 0.5)
        prm[Q_GV_CONV] = 1.0
        if w3.lateral_turbulence and field_.turbulence is not None:
            from aerostat_core.dynamics.turbulence_lateral import lateral_table

            turb = np.ascontiguousarray(np.vstack([turb, lateral_table(field_)]))
            prm[Q_TV_ON] = 1.0
        b = self.base
        return (prm, wpar, sched, turb, b.tab, b.strips, b.rho_tab, b.cdv)

    def nodes(self, y):
        """Node positions and velocities (N+1, 3) [m, m/s] (winch first, C last) and R_EB."""
        n = self.tether.segments
        pos = np.empty((n + 1, 3))
        vel = np.empty_like(pos)
        rot = np.empty((3, 3))
        nodes6_kernel(np.asarray(y, float), self.prm, pos, vel, rot)
        return pos, vel, rot

    def from_3dof(self, y3, azimuth_deg: float = 0.0) -> np.ndarray:
        """The 6-DOF state of a 3-DOF hull state, turned to the wind azimuth [deg] about the
        vertical through the winch (the vertical plane of the 3-DOF model is the plane of the
        wind)."""
        y3 = np.asarray(y3, float)
        n = self.tether.segments
        c, s = math.cos(math.radians(azimuth_deg)), math.sin(math.radians(azimuth_deg))
        y = np.zeros(self.n_state)
        for i in range(1, n):
            x, z, vx, vz = y3[4 * (i - 1):4 * i]
            y[6 * (i - 1):6 * i] = (c * x, s * x, z, c * vx, s * vx, vz)
        b3 = 4 * (n - 1)
        xo, zo, th, u, w, q = y3[b3:b3 + 6]
        b = self.hull_index
        y[b:b + 3] = (c * xo, s * xo, zo)
        # body -> N': yaw psi = -chi_0 (the nose against the wind), then the pitch
        half = -0.5 * math.radians(azimuth_deg)
        y[b + 3:b + 7] = quat_mul(np.array([math.cos(half), 0.0, 0.0, math.sin(half)]),
                                  np.array([math.cos(0.5 * th), 0.0, math.sin(0.5 * th), 0.0]))
        y[b + 7:b + 13] = (u, 0.0, w, 0.0, q, 0.0)
        return y

    def euler(self, y) -> tuple[float, float, float]:
        """Roll, pitch, yaw [rad] (aerospace Euler angles of the body relative to the upwind NED
        frame of the earth x axis)."""
        b = self.hull_index
        return quat_euler(np.asarray(y, float)[b + 3:b + 7])

    def rhs(self, t: float, y, data) -> tuple[np.ndarray, np.ndarray]:
        """dy/dt and the diagnostics (``DIAG6_NAMES``) at (t, y)."""
        dy = np.empty(self.n_state)
        diag = np.empty(ND6)
        rhs6_kernel(float(t), np.asarray(y, float), dy, data, diag)
        return dy, diag

    def energy(self, y) -> float:
        """Mechanical energy [J]: 1/2 nu^T (M_RB + M_A) nu of the hull, m g z_G - rho V g z_O,
        and the line's kinetic (half masses at the ends), potential and elastic energy (uniform
        density)."""
        rho = self.atmosphere.density
        y = np.asarray(y, float)
        pos, vel, rot = self.nodes(y)
        t = self.tether
        n = t.segments
        l0 = t.segment_length
        share = np.full(n + 1, l0)
        share[[0, n]] = 0.5 * l0
        wl = t.linear_density - (rho * np.pi * t.diameter**2 / 4 if t.air_buoyancy else 0.0)
        e = 0.5 * np.sum(t.linear_density * share * np.sum(vel**2, axis=1))
        e += np.sum(wl * self.g * share * pos[:, 2])
        ll = np.linalg.norm(np.diff(pos, axis=0), axis=1)
        e += 0.5 * t.stiffness / l0 * np.sum(np.maximum(ll - l0, 0.0) ** 2)
        b = self.hull_index
        nu = y[b + 7:b + 13]
        e += 0.5 * nu @ (self.hull_mass_matrix + self.added_mass_matrix) @ nu
        h = self.hull6.hull
        z_g = y[b + 2] + rot[2, 0] * h.cg[0] + rot[2, 2] * h.cg[1]
        e += h.mass * self.g * z_g - rho * h.volume * self.g * y[b + 2]
        return float(e)


def quat_mul(a, b) -> np.ndarray:
    """Hamilton product a (x) b of quaternions (scalar first)."""
    a0, a1, a2, a3 = a
    b0, b1, b2, b3 = b
    return np.array([a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3, a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
                     a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1, a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0])


def quat_euler(q) -> tuple[float, float, float]:
    """(roll, pitch, yaw) [rad] of a quaternion (scalar first), aerospace 3-2-1 sequence.

    Examples
    --------
    >>> [round(v, 6) for v in quat_euler([math.cos(0.1), 0.0, math.sin(0.1), 0.0])]
    [0.0, 0.2, 0.0]
    """
    q0, q1, q2, q3 = np.asarray(q, float) / np.linalg.norm(q)
    roll = math.atan2(2 * (q0 * q1 + q2 * q3), 1 - 2 * (q1 * q1 + q2 * q2))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (q0 * q2 - q3 * q1))))
    yaw = math.atan2(2 * (q0 * q3 + q1 * q2), 1 - 2 * (q2 * q2 + q3 * q3))
    return roll, pitch, yaw


def system6_from_design(design, *, segments: int = 20, damping_ratio: float = 1.0,
                        events: Events6 | None = None, atmosphere: str = "constant",
                        **hull_options) -> System6:
    """The 6-DOF system of a static-engine design (the hull and tether of
    :func:`~.system.system_from_design`, with :func:`hull6_from_design`)."""
    base = system_from_design(design, segments=segments, damping_ratio=damping_ratio,
                              atmosphere=atmosphere, **hull_options)
    if atmosphere == "constant" and events is not None and events.break_time is not None:
        pass  # a free ascent at constant density keeps the engine's assumption (documented)
    h6 = hull6_from_design(design, hull=base.body)
    return System6(h6, base.tether, g=base.g, atmosphere=base.atmosphere, events=events)


# --------------------------------------------------------------------------------------------
# Equilibrium
# --------------------------------------------------------------------------------------------
def _apply(system: System6, y, dx) -> np.ndarray:
    """State y moved by dx = (free-node positions, O position, body rotation vector)."""
    y = np.array(y, float)
    n = system.tether.segments
    for i in range(1, n):
        y[6 * (i - 1):6 * (i - 1) + 3] += dx[3 * (i - 1):3 * i]
    b = system.hull_index
    k = 3 * (n - 1)
    y[b:b + 3] += dx[k:k + 3]
    rv = np.asarray(dx[k + 3:k + 6], float)
    ang = float(np.linalg.norm(rv))
    if ang > 0:
        dq = np.concatenate([[math.cos(0.5 * ang)], math.sin(0.5 * ang) * rv / ang])
        qn = quat_mul(y[b + 3:b + 7], dq)
        y[b + 3:b + 7] = qn / np.linalg.norm(qn)
    return y


def _max_acceleration6(system: System6, data, y) -> float:
    """Largest |acceleration| [m/s2, rad/s2] of the rest state ``y`` (the residual that
    :func:`equilibrium6` drives to zero): the free nodes' and the hull's."""
    n = system.tether.segments
    b = system.hull_index
    dy = system.rhs(0.0, y, data)[0]
    acc = np.concatenate([dy[:b].reshape(n - 1, 6)[:, 3:].reshape(-1), dy[b + 7:b + 13]])
    return float(np.max(np.abs(acc))) if np.all(np.isfinite(acc)) else math.inf


def equilibrium6(system: System6, data, guess, tol: float = 1e-9, max_iter: int = 40):
    """Static equilibrium of the 6-DOF model at t = 0 (velocities zero): Newton on the free-node
    positions, the position of O and a body rotation vector, with a dense finite-difference
    Jacobian of the accelerations. Returns (state, largest residual acceleration [m/s2])."""
    n = system.tether.segments
    b = system.hull_index
    acc = np.concatenate([np.concatenate([np.arange(6 * (i - 1) + 3, 6 * i) for i in range(1, n)]),
                          np.arange(b + 7, b + 13)])
    y = np.array(guess, float)
    for i in range(1, n):
        y[6 * (i - 1) + 3:6 * i] = 0.0
    y[b + 7:] = 0.0
    m = 3 * (n - 1) + 6

    def resid(v):
        return system.rhs(0.0, v, data)[0][acc]

    r = resid(y)
    scale = max(1.0, 0.01 * system.tether.length)
    for _ in range(max_iter):
        jac = np.empty((m, m))
        for j in range(m):
            h = 1e-6 * (scale if j < 3 * n else 1.0)
            e = np.zeros(m)
            e[j] = h
            jac[:, j] = (resid(_apply(system, y, e)) - r) / h
        try:
            dx = np.linalg.solve(jac, -r)
        except np.linalg.LinAlgError:
            raise RuntimeError("6-DOF equilibrium: singular Jacobian (is the tether slack?)") from None
        lam = 1.0
        n0 = np.linalg.norm(r)
        for _k in range(30):
            yt = _apply(system, y, lam * dx)
            rt = resid(yt)
            if np.all(np.isfinite(rt)) and np.linalg.norm(rt) < 1e4 * n0 + 1e-6:
                break
            lam *= 0.5
        y, r = yt, rt
        if np.max(np.abs(lam * dx)) < tol * max(1.0, system.tether.length):
            break
    res = float(np.max(np.abs(r)))
    if not np.all(np.isfinite(y)) or res > 1e-3:
        raise RuntimeError(f"6-DOF static equilibrium not found (largest residual acceleration "
                           f"{res:.3g}): check that the aerostat has free lift")
    return y, res


# --------------------------------------------------------------------------------------------
# Runs
# --------------------------------------------------------------------------------------------
def initial_state6(system: System6, wind3: Wind3D, design=None, field_: WindField | None = None,
                   data=None, guess3: np.ndarray | None = None,
                   polish_tol: float | None = None):
    """Equilibrium at t = 0 in ``wind3``: the 3-DOF equilibrium of the same hull and tether in
    the wind at the hull, turned to the azimuth, then polished by :func:`equilibrium6` (it moves
    the line out of the plane when the wind veers).

    ``guess3``: the 3-DOF rest state to start from (default: the static engine's solution,
    :func:`~.simulate.engine_guess`, for a design; else a straight line); a start that fails
    falls back to the straight line as the engine's does. ``polish_tol`` [m/s2, rad/s2]: when
    given, the 6-DOF polish is skipped if the turned 3-DOF equilibrium already balances every
    6-DOF acceleration to within it. In a steady wind without veer the 6-DOF model in the
    vertical plane of the wind is the 3-DOF model (the lateral accelerations vanish by symmetry
    and the in-plane ones are the 3-DOF kernel's), so the polish would move the state by about
    the 3-DOF Newton's own tolerance (~1e-9 m) and costs more than the rest together
    (docs/dynamics.md §7.5)."""
    from aerostat_core.dynamics.simulate import engine_guess, equilibrium, straight_guess

    base = system.base
    f0 = wind3.base.realize(system.tether.length, 60.0) if field_ is None else field_
    if guess3 is not None:
        g3 = guess3
    else:
        g3 = engine_guess(base, design, wind3.base.initial_speed()) if design is not None \
            else straight_guess(base, f0)
    try:
        y3, _ = equilibrium(base, f0, g3)
    except RuntimeError:
        if design is None and guess3 is None:
            raise
        y3, _ = equilibrium(base, f0, straight_guess(base, f0))  # the engine's line too coarse
    y6 = system.from_3dof(y3, wind3.azimuth_deg)
    if data is None:
        data = system.data(f0, wind3)
    if polish_tol is not None and _max_acceleration6(system, data, y6) <= polish_tol:
        y = y6
    else:
        y = equilibrium6(system, data, y6)[0]
    roll, pitch, yaw = system.euler(y)
    yaw_rel = math.remainder(yaw + math.radians(wind3.azimuth_deg), 2 * math.pi)
    if max(abs(roll), abs(pitch), abs(yaw_rel)) > 0.5 * math.pi:
        raise RuntimeError("static equilibrium not found with the nose into the wind (the search "
                           f"ended at roll {math.degrees(roll):.0f}, pitch "
                           f"{math.degrees(pitch):.0f}, yaw {math.degrees(yaw_rel):.0f} deg)")
    return y


def simulate6(system: System6, wind3: Wind3D, duration: float, options=None,
              initial_state=None, design=None, progress=None):
    """Integrate the 6-DOF model for ``duration`` [s], valid (0, 1e5], with the TR-BDF2 of
    :mod:`.solver`, from the static equilibrium (or ``initial_state``). Returns a
    :class:`~.sixdof_results.Result6`; a run that leaves the physical domain stops with its
    history up to there and the reason in ``message``."""
    from aerostat_core.dynamics.options import STATUS_DRIVER, SolverOptions
    from aerostat_core.dynamics.simulate import integrate, output_times, warm_kernels
    from aerostat_core.dynamics.sixdof_results import Result6
    from aerostat_core.dynamics.solver import F_T, S_FEVAL, S_IOUT, S_JAC, S_STEPS, STATUS

    opt = options or SolverOptions()
    out_t = output_times(duration, opt, system.n_state + ND6)
    warm_kernels()
    t_wall0 = time.perf_counter()
    height = system.tether.length if initial_state is None else \
        float(np.asarray(initial_state)[system.hull_index + 2])
    field_ = wind3.base.realize(height, duration)
    data = system.data(field_, wind3)
    if initial_state is None:
        y0 = initial_state6(system, wind3, design, field_, data)
        field_ = wind3.base.realize(float(y0[system.hull_index + 2]), duration,
                                    x_ref=_along(y0, system, wind3))
        data = system.data(field_, wind3)
    else:
        y0 = np.array(initial_state, float)
        if y0.shape != (system.n_state,):
            raise ValueError(f"initial_state has shape {y0.shape}; expected ({system.n_state},)")
    n = system.n_state
    atol = np.full(n, opt.atol_position)
    for i in range(1, system.tether.segments):
        atol[6 * (i - 1) + 3:6 * i] = opt.atol_velocity
    b = system.hull_index
    atol[b + 3:b + 7] = opt.atol_angle
    atol[b + 7:b + 10] = opt.atol_velocity
    atol[b + 10:b + 13] = opt.atol_angle
    scale = np.ones(n)
    scale[:b + 3] = max(1.0, 0.01 * system.tether.length)
    scale[b + 3:] = 0.1
    stops = list(field_.breakpoints())
    ev = system.events
    w3 = wind3
    if w3.direction_step_deg:
        stops += [w3.direction_step_start, w3.direction_step_start + w3.direction_step_time]
    if ev.reel_speed:
        t1 = ev.reel_start + ev.reel_ramp + ev.reel_duration
        stops += [ev.reel_start, ev.reel_start + ev.reel_ramp, t1, t1 + ev.reel_ramp]
    if ev.break_time is not None:
        stops.append(ev.break_time)
    stops = np.unique(np.array([s for s in stops if 0 < s < duration], float))
    out_y, _, stats, fs, status, wall = integrate(data, y0, out_t, duration, opt, atol, scale,
                                                  stops, system.structure(), progress, t_wall0)
    m = int(stats[S_IOUT])
    msg = STATUS.get(status, STATUS6.get(status, STATUS_DRIVER.get(status, "unknown")))
    if status != 0:
        msg = f"stopped at t = {fs[F_T]:.2f} s: {msg}"
    d6 = np.empty((m, ND6))
    dy = np.empty(n)
    for i in range(m):
        rhs6_kernel(out_t[i], out_y[i], dy, data, d6[i])
    st = {"steps": int(stats[S_STEPS]), "rhs_calls": int(stats[S_FEVAL]),
          "jacobians": int(stats[S_JAC]),
          "wall_time": wall, "t_end": float(fs[F_T])}
    return Result6(out_t[:m], out_y[:m], d6, system, wind3, status, msg, st)


def _along(y, system: System6, wind3: Wind3D) -> float:
    b = system.hull_index
    a = math.radians(wind3.azimuth_deg)
    return float(y[b] * math.cos(a) + y[b + 1] * math.sin(a))


__all__ = ["DIAG6_NAMES", "FIN_ANGLES_DEG", "Events6", "Hull6", "System6", "Wind3D",
           "equilibrium6", "fin_layout_factors", "hull6_from_design", "hull6_simple",
           "initial_state6", "quat_euler", "quat_mul", "simulate6", "system6_from_design",
           "P_XA", "P_XC", "P_ZC", "DIAG6_NAMES"]
