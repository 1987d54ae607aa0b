"""Equations of motion: point aerostat or 3-DOF rigid hull on the lumped-mass tether.

Frames (dynamics.md §1.1). Earth E: x downwind, z up, origin at the winch. Body B (aircraft axes
turned 180 deg): origin at the centre of volume O, x_B towards the nose, z_B towards the belly; pitch
theta nose-up; x_B = (-cos th, sin th), z_B = (-sin th, -cos th) in E, so body components map to
E with R_EB = [[-cos th, -sin th], [sin th, -cos th]]. A static-engine station xi (from the nose,
aft) and height z (up) map to body x = xi_CV - xi, z_B = -z.

States. Tether nodes 1..N-1: (x, z, v_x, v_z) each, node after node. Then either the point
aerostat (x, z, v_x, v_z) or the hull (x_O, z_O, theta, u, w, q) with (u, w) the body velocity of
O and q = d theta/dt.

Hull equations (Newton-Euler about O with a CG offset plus Kirchhoff added mass with a current;
Fossen's relative-velocity form, dynamics.md §1.2):

    (M_RB + M_A) nu_dot = f_RB + f_AM + f_wind + f_aero + f_gb + f_teth

    M_RB = [[m, 0, m z_g], [0, m, -m x_g], [m z_g, -m x_g, I_O]],  M_A = diag(m_x, m_z, I_a)
    f_RB = -[m (q w - q^2 x_g), m (-q u - q^2 z_g), m q (z_g w + x_g u)]
    f_AM = [-q m_z w_r, q m_x u_r, (m_z - m_x) u_r w_r]   (third entry only in "kirchhoff" mode)
    f_wind = M_A (nu_w_dot, 0) + rho V (a_w, 0)           (unsteady-wind inertia, a switch)
    f_gb = (m - rho V) g d_B, moment m g (z_g d_B,x - x_g d_B,z), d_B = (-sin th, cos th)
    f_teth: tether force at C, moment z_c F_x - x_c F_z

with nu_w = R_EB^T U the wind in body axes at O, u_r = u - nu_w,x, w_r = w - nu_w,z, alpha =
atan2(w_r, u_r), a_w = R_EB^T dU/dt and nu_w_dot = a_w - (q nu_w,z, -q nu_w,x).

Aerodynamics (dynamics.md §1.3) uses the static engine's functions, tabulated once per design
against alpha (and airspeed for Hoerner's C_DV), fed with the instantaneous relative velocity:
the J&D inviscid term and the axial drag at O; the viscous cross-flow term as strips with the local
normal velocity w_r - q x(xi); the fins with the local velocity (u_r + q z_f, w_r - q x_f). The
pitch damping therefore follows from the geometry. The Munk moment is counted once: the J&D
inviscid term already contains it, so the Kirchhoff entry is only used with the aerodynamics off
(energy check V4).

Point aerostat (dynamics.md §3.1 "case P", MoorDyn point): mass M, buoyancy rho V g, drag
1/2 rho C_D A |v_r| v_r, isotropic added mass C_a rho V; optionally the Froude-Krylov and
added-mass forces of an accelerating wind (1 + C_a) rho V dU/dt.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np
from numba import njit

from ..constants import G0
from ._layout import (
    P_AERO_AX,
    P_AERO_CF,
    P_AERO_FIN,
    P_AERO_INV,
    P_AL0,
    P_CDC,
    P_DAL,
    P_DV,
    P_G,
    P_HM,
    P_HV,
    P_IA,
    P_KIRCHHOFF,
    P_L0,
    P_MINV,
    P_MODE,
    P_MT,
    P_MX,
    P_MZ,
    P_NSEG,
    P_PCA,
    P_PCDA,
    P_PM,
    P_POINT_FK,
    P_PV,
    P_RHO_DZ,
    P_RHO_REF,
    P_RHO_Z0,
    P_SIZE,
    P_THETA_MAX,
    P_UNSTEADY,
    P_V0,
    P_W,
    P_XA,
    P_XC,
    P_XF,
    P_XG,
    P_XGT,
    P_ZA,
    P_ZC,
    P_ZF,
    P_ZG,
    P_ZGT,
    T_A_AX,
    T_A_INV,
    T_FIN_D,
    T_FIN_L,
    T_M_INV,
    T_N_INV,
    T_ROWS,
)
from .tether import TetherModel, air_density, tether_energy, tether_loads
from .wind import NT, WindField, profile_factor, wind_time_terms

#: Number of diagnostic outputs written by the right-hand side (see ``DIAG_NAMES``).
DIAG_NAMES = (
    "alpha",  # angle of attack at O [rad] (point: 0)
    "airspeed",  # relative airspeed at O [m/s]
    "wind_x",  # wind at O (or the point) [m/s]
    "wind_z",
    "tension_top_x",  # force the body exerts on the tether at its top (C) [N]
    "tension_top_z",
    "tension_winch_x",  # force the tether exerts on the winch [N]
    "tension_winch_z",
    "tension_max",  # largest segment tension [N]
    "x_top",  # confluence point (or point aerostat) position [m]
    "z_top",
    "vx_top",  # its velocity [m/s]
    "vz_top",
    "vx_body",  # velocity of O (hull) or of the point [m/s]
    "vz_body",
    "alpha_fin",  # local angle of attack at the fins [rad]
    "fin_lift",  # fin lift [N]
    "aero_moment",  # aerodynamic pitching moment about O, nose-up [N m]
    "tension_min",  # smallest segment tension [N]
    "wind_accel_x",  # dU_x/dt at O [m/s2]
)
ND = len(DIAG_NAMES)
_ALPHA_STEP = math.radians(0.01)


# --------------------------------------------------------------------------------------------
# Bodies
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class PointAerostat:
    """Point ("spherical") aerostat: no attitude, isotropic drag and added mass.

    Parameters
    ----------
    mass : float
        Everything that moves with it (structure, gas, payload) [kg], valid (0, 1e6].
    volume : float
        Displaced volume [m3], valid (0, 1e7].
    drag_area : float
        C_D A on the relative wind [m2], valid [0, 1e5].
    added_mass_coefficient : float
        C_a: added mass C_a rho V [-], valid [0, 5] (0.5 for a sphere).
    unsteady_wind_inertia : bool
        Add (1 + C_a) rho V dU/dt (Froude-Krylov + added mass of the accelerating air). MoorDyn
        points have neither, so the reference cases R1-R4 run without it.

    Examples
    --------
    >>> round(PointAerostat().net_lift(1.225, 9.81), 2)
    739.67
    """

    mass: float = 71.6
    volume: float = 120.0
    drag_area: float = 1.0
    added_mass_coefficient: float = 0.5
    unsteady_wind_inertia: bool = False

    def __post_init__(self) -> None:
        _num("PointAerostat", "mass", self.mass, 0.0, 1e6, "kg", lo_open=True)
        _num("PointAerostat", "volume", self.volume, 0.0, 1e7, "m3", lo_open=True)
        _num("PointAerostat", "drag_area", self.drag_area, 0.0, 1e5, "m2")
        _num("PointAerostat", "added_mass_coefficient", self.added_mass_coefficient, 0.0, 5.0)

    def net_lift(self, rho: float, g: float) -> float:
        """(rho V - M) g [N]."""
        return (rho * self.volume - self.mass) * g


@dataclass(frozen=True, eq=False)
class HullModel:
    """Rigid hull for the 3-DOF model, in body axes about the centre of volume O.

    Usually built from a static-engine design by :func:`hull_from_airframe`; :func:`ellipsoid_hull`
    builds a simple one from a few numbers (tests, V4, V8).

    Attributes
    ----------
    mass : float
        Mass moving with the hull incl. lifting gas, payload, fins [kg].
    volume : float
        Displaced volume V [m3].
    cg : (float, float)
        CG body position (x forward of O, z below O) [m].
    inertia_cg : float
        Pitch inertia about the CG, I_yy [kg m2].
    confluence : (float, float)
        Confluence point C body position [m].
    fin_ac : (float, float)
        Fin aerodynamic centre body position [m] (x < 0: aft).
    added_mass : (float, float, float)
        m_x [kg], m_z [kg], I_a [kg m2] (Lamb k1 rho V, k2 rho V, k' I_air at ``reference_density``).
    reference_density : float
        Air density used for the added masses [kg/m3].
    crossflow_coefficient : float
        (C_dc)_h [-].
    strips : ndarray (2, K)
        Strip body stations x_k [m] and weights 2 r dxi [m2] (sum = J1).
    alpha_grid : (float, float)
        First angle and spacing of ``tables`` [rad].
    tables : ndarray (6, M)
        Per-unit-q coefficients versus alpha (rows ``_layout.T_*``).
    speed_grid : (float, float)
        First airspeed and spacing of ``cdv`` [m/s].
    cdv : ndarray
        Hull volumetric drag coefficient C_DV versus airspeed [-].
    length, diameter, xi_cv : float
        Hull length, diameter and the CV station from the nose [m] (drawing, frame mapping).
    outline : ndarray (2, P)
        Hull profile (body x, radius) for drawing [m].
    fin_outline : ndarray (2, Q)
        Horizontal-fin planform (body x, z offsets) for drawing [m].
    unsteady_wind_inertia : bool
        Switch of f_wind (default True, dynamics.md §5 decision 3).
    munk : {"jones-delaurier", "kirchhoff"}
        Where the Munk moment comes from. "kirchhoff" adds (m_z - m_x) u_r w_r and must only be
        used with ``aero_inviscid`` off (V4); the two together would count it twice.
    aero_inviscid, aero_axial, aero_crossflow, aero_fins : bool
        Switches of the aerodynamic components.
    theta_limit : float
        |theta| beyond which a run stops as diverged [rad].
    """

    mass: float
    volume: float
    cg: tuple
    inertia_cg: float
    confluence: tuple
    fin_ac: tuple
    added_mass: tuple
    reference_density: float
    crossflow_coefficient: float
    strips: np.ndarray
    alpha_grid: tuple
    tables: np.ndarray
    speed_grid: tuple
    cdv: np.ndarray
    length: float
    diameter: float
    xi_cv: float
    outline: np.ndarray
    fin_outline: np.ndarray = field(default_factory=lambda: np.zeros((2, 0)))
    unsteady_wind_inertia: bool = True
    munk: str = "jones-delaurier"
    aero_inviscid: bool = True
    aero_axial: bool = True
    aero_crossflow: bool = True
    aero_fins: bool = True
    theta_limit: float = math.radians(60.0)

    def __post_init__(self) -> None:
        if self.munk not in ("jones-delaurier", "kirchhoff"):
            raise ValueError(f"HullModel.munk = {self.munk!r}; valid options "
                             "('jones-delaurier', 'kirchhoff')")
        if self.munk == "kirchhoff" and self.aero_inviscid:
            raise ValueError("HullModel.munk = 'kirchhoff' with aero_inviscid = True would count the "
                             "Munk moment twice (the J&D inviscid term contains it)")

    def with_options(self, **kw) -> HullModel:
        """Copy with switches changed (``unsteady_wind_inertia``, ``aero_fins`` ...)."""
        return replace(self, **kw)

    def aero_off(self, munk: str = "kirchhoff") -> HullModel:
        """Copy with every aerodynamic component off (energy check V4)."""
        return replace(self, aero_inviscid=False, aero_axial=False, aero_crossflow=False,
                       aero_fins=False, munk=munk)


def _num(owner, name, value, lo, hi, unit="", lo_open=False) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{owner}.{name} = {value!r} is not a number") from None
    if not math.isfinite(v) or v > hi or (v <= lo if lo_open else v < lo):
        left = "(" if lo_open else "["
        raise ValueError(f"{owner}.{name} = {value!r} is outside the valid range "
                         f"{left}{lo:g}, {hi:g}] {unit}".rstrip())
    return v


def lamb_added_mass(fineness_ratio: float, volume: float, rho: float, i_air: float):
    """Added masses of a hull from Lamb's prolate-spheroid factors (static engine's
    :func:`aerostat_core.geometry.lamb_factors` when available).

    m_x = k1 rho V, m_z = k2 rho V, I_a = k' I_air, with I_air = rho int (x^2 + z^2) dV about O.

    Parameters
    ----------
    fineness_ratio : float
        l/d [-] (> 1).
    volume : float
        [m3].
    rho : float
        Air density [kg/m3].
    i_air : float
        Pitch inertia of the displaced air about O [kg m2].

    Returns
    -------
    (m_x [kg], m_z [kg], I_a [kg m2], (k1, k2, k'))

    Notes
    -----
    Source: Lamb, *Hydrodynamics* (1932) §373; Tuckerman NACA 210; thesis Appendix G.
    """
    from ..geometry import lamb_factors

    k1, k2, kr = (float(k) for k in lamb_factors(fineness_ratio))
    return k1 * rho * volume, k2 * rho * volume, kr * i_air, (k1, k2, kr)


def ellipsoid_hull(
    volume: float = 120.0,
    fineness_ratio: float = 3.5,
    mass: float = 90.0,
    cg=(0.3, 0.6),
    inertia_cg: float = 1400.0,
    confluence=(0.3, 3.5),
    fin_ac=None,
    rho: float = 1.19,
    aero=None,
    **options,
) -> HullModel:
    """A prolate-spheroid hull from a few numbers (dynamics.md §3.3 prototype values by default).

    Parameters
    ----------
    volume : float
        [m3].
    fineness_ratio : float
        l/d [-], > 1.
    mass : float
        Total moving mass incl. gas [kg].
    cg : (float, float)
        CG body (x forward, z down) from the CV [m]. Note the prototype's "0.3 m aft" is x = -0.3.
    inertia_cg : float
        I_yy about the CG [kg m2].
    confluence : (float, float)
        C body (x forward, z down) [m].
    fin_ac : (float, float) or None
        Fin aerodynamic centre [m]; default 0.38 l aft of the CV.
    rho : float
        Air density for the added masses [kg/m3].
    aero : callable or None
        ``aero(alpha) -> dict`` of per-unit-q arrays with keys of ``TABLE_KEYS`` (missing keys are
        zero), and optionally ``"cdv"`` (scalar); ``None`` makes an aerodynamically inert hull
        (switch the components off with :meth:`HullModel.aero_off` for V4).
    **options
        Switches passed to :class:`HullModel`.
    """
    d = (6.0 * volume / (math.pi * fineness_ratio)) ** (1.0 / 3.0)
    length = fineness_ratio * d
    a, b = 0.5 * length, 0.5 * d
    i_air = rho * volume * (a * a + b * b) / 5.0
    e = math.sqrt(1.0 - 1.0 / fineness_ratio**2)
    at = math.atanh(e)
    alpha0 = 2.0 * (1.0 - e**2) / e**3 * (at - e)
    beta0 = 1.0 / e**2 - (1.0 - e**2) / e**3 * at
    k1 = alpha0 / (2.0 - alpha0)
    k2 = beta0 / (2.0 - beta0)
    dba = beta0 - alpha0
    kr = e**4 * dba / ((2.0 - e**2) * (2.0 * e**2 - (2.0 - e**2) * dba))
    # strips over the ellipse: x = a sin(phi), 2 r dx = 2 a b cos^2(phi) dphi
    gx, gw = np.polynomial.legendre.leggauss(32)
    phi = 0.5 * math.pi * gx
    xs = a * np.sin(phi)
    ws = 2.0 * a * b * np.cos(phi) ** 2 * gw * 0.5 * math.pi
    if fin_ac is None:
        fin_ac = (-0.38 * length, 0.0)
    alpha = np.arange(-math.pi, math.pi + 0.5 * _ALPHA_STEP, _ALPHA_STEP)
    tab = np.zeros((T_ROWS, alpha.size))
    cdv_val = 0.0
    if aero is not None:
        res = aero(alpha)
        for key, row in zip(TABLE_KEYS, range(T_ROWS)):
            if key in res:
                tab[row] = np.broadcast_to(res[key], alpha.shape)
        cdv_val = float(res.get("cdv", 0.0))
    xo = np.linspace(-a, a, 81)
    outline = np.array([xo, b * np.sqrt(np.clip(1 - (xo / a) ** 2, 0, 1))])
    return HullModel(
        mass=float(mass), volume=float(volume), cg=tuple(map(float, cg)),
        inertia_cg=float(inertia_cg), confluence=tuple(map(float, confluence)),
        fin_ac=tuple(map(float, fin_ac)),
        added_mass=(k1 * rho * volume, k2 * rho * volume, kr * i_air), reference_density=rho,
        crossflow_coefficient=float(options.pop("crossflow_coefficient", 0.0)),
        strips=np.array([xs, ws]), alpha_grid=(float(alpha[0]), _ALPHA_STEP), tables=tab,
        speed_grid=(0.0, 100.0), cdv=np.array([cdv_val, cdv_val]), length=length, diameter=d,
        xi_cv=a, outline=outline, **options,
    )


#: Keys of the per-unit-q aerodynamic tables, in row order (``_layout.T_*``).
TABLE_KEYS = ("normal_inviscid", "axial_inviscid", "moment_inviscid", "axial_drag", "fin_lift",
              "fin_drag")


def hull_from_airframe(af, aero, *, unsteady_wind_inertia: bool = True, strips_per_half: int = 16,
                       index=None, **options) -> HullModel:
    """Build the dynamic hull of a static-engine airframe, calling the engine's aerodynamics.

    The per-unit-q tables are made by calling :func:`aerostat_core.aerodynamics.hull_inviscid`,
    :func:`~aerostat_core.aerodynamics.hull_axial` and
    :func:`~aerostat_core.aerodynamics.fin_lift_drag` on a 0.01 deg grid over [-180, 180] deg,
    and Hoerner's C_DV from :func:`aerostat_core.statics.axial_drag_coefficient` on a 0.05 m/s
    airspeed grid; linear interpolation on these grids is exact to ~1e-8 relative. The cross-flow
    term is split into strips whose weights are corrected to reproduce the engine's J1 and J2
    exactly, so with q = 0 the dynamic hull loads equal the static ones.

    Parameters
    ----------
    af : aerostat_core.airframe.Airframe
        One design (scalar arrays), or a batch with ``index`` selecting one.
    aero : aerostat_core.inputs.AeroModel
    unsteady_wind_inertia : bool
        Switch of the unsteady-wind inertia terms.
    strips_per_half : int
        Gauss strips on each half ellipse of the NPL profile.
    index : int or None
        Element of a batch airframe.
    **options
        Further :class:`HullModel` switches.

    Notes
    -----
    Mapping (methods.md -> body axes): x = xi_CV - xi, z_B = -z; N (up) -> Z = -N; A (aft) ->
    X = -A; moments nose-up in both. The CG and pitch inertia come from the engine's mass
    breakdown (lifting gas included, it moves with the hull); the added masses from Lamb's factors
    at the operating air density, with I_air = rho int ((xi - xi_CV)^2 + r^2/4) dV.
    """
    from .. import aerodynamics as ad
    from ..geometry import profile_quadrature, radius
    from ..statics import axial_drag_coefficient

    def sc(v):
        a = np.asarray(v, float)
        if index is not None and a.ndim:
            a = a.reshape(-1)[index]
        return float(a)

    h = af.hull
    rho = sc(af.air_density)
    vol = sc(h.volume)
    xi_cv = sc(h.xi_cb)
    xi_m = sc(af.xi_m)
    length = sc(h.length)
    a1, a2, b = sc(h.a1), sc(h.a2), sc(h.b)
    mass = sc(af.mass.aerostat)
    xg = xi_cv - sc(af.mass.xi_cg)
    zg = -sc(af.mass.z_cg)
    icg = sc(af.mass.pitch_inertia)
    xc = xi_cv - sc(af.xi_c)
    zc = -sc(af.z_c)
    xf = xi_cv - sc(af.fins.xi_ac)
    # added masses (Lamb) with the displaced air's inertia from the engine's quadrature
    xi_q, r_q, _ws, wv = profile_quadrature(h)
    xi_q, r_q, wv = (np.asarray(v, float).reshape(-1, xi_q.shape[-1]) for v in (xi_q, r_q, wv))
    k = 0 if index is None else index
    i_air = rho * float(np.sum(wv[k] * ((xi_q[k] - xi_cv) ** 2 + 0.25 * r_q[k] ** 2)))
    mx, mz, ia, _ = lamb_added_mass(sc(h.fineness_ratio), vol, rho, i_air)
    # aero tables from the engine's functions
    alpha = np.arange(-math.pi, math.pi + 0.5 * _ALPHA_STEP, _ALPHA_STEP)
    dk = sc(h.k2) - sc(h.k1)
    n_i, a_i, m_i = ad.hull_inviscid(1.0, alpha, dk, aero.hull_efficiency, sc(af.i1), sc(af.i3))
    # inviscid moment is about xi_m: move it to the CV (M_O = M_m + (xi_CV - xi_m) N)
    m_i = m_i + (xi_cv - xi_m) * n_i
    a_x = ad.hull_axial(1.0, alpha, 1.0, sc(h.reference_area))
    fn = af.fins
    lift, drag = ad.fin_lift_drag(
        1.0, alpha, sc(fn.lift_slope), aero.fin_efficiency, math.radians(aero.fin_stall_angle_deg),
        sc(fn.lifting_area), sc(fn.area_total), aero.fin_zero_lift_drag, sc(fn.aspect_ratio),
        sc(fn.oswald),
    )
    tab = np.array([n_i, a_i, m_i, a_x, lift * np.ones_like(alpha), drag * np.ones_like(alpha)])
    speeds = np.arange(0.0, 80.0 + 1e-9, 0.05)
    cdv = np.asarray(axial_drag_coefficient(af, aero, speeds), float)
    if cdv.ndim > 1:
        cdv = cdv[..., k] if cdv.shape[-1] != speeds.size else cdv.reshape(-1, speeds.size)[k]
    cdv = np.broadcast_to(cdv, speeds.shape).copy()
    # cross-flow strips on the NPL profile: u = sin(phi) on each half ellipse
    gx, gw = np.polynomial.legendre.leggauss(strips_per_half)
    phi_f = 0.25 * math.pi * (gx - 1.0)  # [-pi/2, 0]
    phi_a = 0.25 * math.pi * (gx + 1.0)  # [0, pi/2]
    xi_s = np.concatenate([a1 * (1.0 + np.sin(phi_f)), a1 + a2 * np.sin(phi_a)])
    w_s = np.concatenate([2 * b * a1 * np.cos(phi_f) ** 2, 2 * b * a2 * np.cos(phi_a) ** 2])
    w_s = w_s * np.concatenate([gw, gw]) * 0.25 * math.pi
    x_s = xi_cv - xi_s
    # exact J1 and J2 (about xi_m = xi_CV) of the engine: w_k <- w_k (c0 + c1 x_k)
    j1, j2 = sc(af.j1), sc(af.j2) + (xi_cv - xi_m) * sc(af.j1)
    s0, s1, s2 = np.sum(w_s), np.sum(w_s * x_s), np.sum(w_s * x_s**2)
    c0, c1 = np.linalg.solve([[s0, s1], [s1, s2]], [j1, j2])
    w_s = w_s * (c0 + c1 * x_s)
    xo = np.linspace(0.0, length, 121)
    outline = np.array([xi_cv - xo, np.asarray(radius(xo, a1, a2, b), float)])
    le, te = sc(fn.xi_root_le), sc(fn.xi_root_te)
    rc, tc, span = sc(fn.root_chord), sc(fn.tip_chord), sc(fn.span)
    sweep = math.tan(sc(fn.sweep_le))
    r_root = float(radius(le + 0.5 * rc, a1, a2, b))
    fin_outline = np.array([
        [xi_cv - le, xi_cv - (le + span * sweep), xi_cv - (le + span * sweep + tc), xi_cv - te],
        [r_root, r_root + span, r_root + span, r_root],
    ])
    return HullModel(
        mass=mass, volume=vol, cg=(xg, zg), inertia_cg=icg, confluence=(xc, zc), fin_ac=(xf, 0.0),
        added_mass=(mx, mz, ia), reference_density=rho,
        crossflow_coefficient=float(aero.hull_crossflow_drag), strips=np.array([x_s, w_s]),
        alpha_grid=(float(alpha[0]), _ALPHA_STEP), tables=np.ascontiguousarray(tab),
        speed_grid=(0.0, 0.05), cdv=cdv, length=length, diameter=2.0 * b, xi_cv=xi_cv,
        outline=outline, fin_outline=fin_outline, unsteady_wind_inertia=unsteady_wind_inertia,
        **options,
    )


# --------------------------------------------------------------------------------------------
# The assembled system
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Atmosphere:
    """Air density along the heights of a run.

    ``constant`` (default): one density everywhere, as the static engine does (it takes the air at
    the operating altitude). ``table``: densities ``values`` [kg/m3] on heights ``z0 + k dz`` [m],
    linearly interpolated (e.g. ISA from :func:`aerostat_core.atmosphere.isa`)."""

    density: float = 1.225
    z0: float = 0.0
    dz: float = 1.0
    values: tuple = ()

    @classmethod
    def isa(cls, site_elevation: float = 0.0, isa_offset: float = 0.0, top: float = 1000.0,
            dz: float = 2.0) -> Atmosphere:
        """ISA density (static engine's :func:`aerostat_core.atmosphere.isa`) from the winch
        (height 0) to ``top`` [m] above it."""
        from ..atmosphere import isa

        z = np.arange(0.0, top + dz, dz)
        rho = np.asarray(isa(site_elevation + z, isa_offset).density, float)
        return cls(float(rho[0]), 0.0, dz, tuple(rho))

    def table(self) -> np.ndarray:
        """The kernel's density table."""
        return np.array(self.values if self.values else (self.density,), float)

    def at(self, z) -> np.ndarray:
        """Density at heights ``z`` [m]."""
        if not self.values:
            return np.full(np.shape(z), self.density)
        zz = self.z0 + self.dz * np.arange(len(self.values))
        return np.interp(z, zz, self.values)


class DynamicSystem:
    """A tethered aerostat ready to simulate: body + tether + gravity + air, packed for the kernels.

    Parameters
    ----------
    body : PointAerostat or HullModel
    tether : TetherModel
    g : float
        Gravity [m/s2] (``aerostat_core.constants.G0`` for designs; 9.81 in the R cases).
    atmosphere : Atmosphere
    winch : (float, float)
        Winch position [m] (the earth origin by default).
    """

    def __init__(self, body, tether: TetherModel, g: float = G0,
                 atmosphere: Atmosphere | None = None, winch=(0.0, 0.0)) -> None:
        self.body = body
        self.tether = tether
        self.g = float(_num("DynamicSystem", "g", g, 0.0, 100.0, "m/s2"))
        self.atmosphere = atmosphere or Atmosphere()
        self.winch = (float(winch[0]), float(winch[1]))
        self.is_hull = isinstance(body, HullModel)
        n = tether.segments
        self.n_free = n - 1
        self.n_state = 4 * (n - 1) + (6 if self.is_hull else 4)
        self.hull_index = 4 * (n - 1)
        prm = np.zeros(P_SIZE)
        tether.fill(prm)
        prm[P_G] = self.g
        prm[P_XA], prm[P_ZA] = self.winch
        atm = self.atmosphere
        prm[P_RHO_Z0] = atm.z0
        prm[P_RHO_DZ] = atm.dz
        self.rho_tab = atm.table()
        self.m_top = 0.5 * tether.node_mass
        if self.is_hull:
            h = body
            prm[P_MODE] = 1.0
            rho_ref = h.reference_density
            prm[P_RHO_REF] = rho_ref
            prm[P_HM] = h.mass
            prm[P_HV] = h.volume
            prm[P_XG], prm[P_ZG] = h.cg
            prm[P_XC], prm[P_ZC] = h.confluence
            prm[P_XF], prm[P_ZF] = h.fin_ac
            mx, mz, ia = h.added_mass
            prm[P_MX], prm[P_MZ], prm[P_IA] = mx, mz, ia
            mt = h.mass + self.m_top
            xgt = (h.mass * h.cg[0] + self.m_top * h.confluence[0]) / mt
            zgt = (h.mass * h.cg[1] + self.m_top * h.confluence[1]) / mt
            io = (h.inertia_cg + h.mass * (h.cg[0] ** 2 + h.cg[1] ** 2)
                  + self.m_top * (h.confluence[0] ** 2 + h.confluence[1] ** 2))
            prm[P_MT], prm[P_XGT], prm[P_ZGT] = mt, xgt, zgt
            mm = np.array([[mt + mx, 0.0, mt * zgt], [0.0, mt + mz, -mt * xgt],
                           [mt * zgt, -mt * xgt, io + ia]])
            self.mass_matrix = mm
            self.rigid_mass_matrix = np.array([
                [h.mass, 0.0, h.mass * h.cg[1]], [0.0, h.mass, -h.mass * h.cg[0]],
                [h.mass * h.cg[1], -h.mass * h.cg[0],
                 h.inertia_cg + h.mass * (h.cg[0] ** 2 + h.cg[1] ** 2)]])
            prm[P_MINV:P_MINV + 9] = np.linalg.inv(mm).reshape(-1)
            prm[P_CDC] = h.crossflow_coefficient
            prm[P_UNSTEADY] = 1.0 if h.unsteady_wind_inertia else 0.0
            prm[P_KIRCHHOFF] = 1.0 if h.munk == "kirchhoff" else 0.0
            prm[P_AERO_INV] = 1.0 if h.aero_inviscid else 0.0
            prm[P_AERO_AX] = 1.0 if h.aero_axial else 0.0
            prm[P_AERO_CF] = 1.0 if h.aero_crossflow else 0.0
            prm[P_AERO_FIN] = 1.0 if h.aero_fins else 0.0
            prm[P_AL0], prm[P_DAL] = h.alpha_grid
            prm[P_V0], prm[P_DV] = h.speed_grid
            prm[P_THETA_MAX] = h.theta_limit
            self.tab = np.ascontiguousarray(h.tables, float)
            self.strips = np.ascontiguousarray(h.strips, float)
            self.cdv = np.ascontiguousarray(h.cdv, float)
        else:
            p = body
            prm[P_MODE] = 0.0
            prm[P_RHO_REF] = atm.density
            prm[P_PM] = p.mass
            prm[P_PV] = p.volume
            prm[P_PCDA] = p.drag_area
            prm[P_PCA] = p.added_mass_coefficient
            prm[P_POINT_FK] = 1.0 if p.unsteady_wind_inertia else 0.0
            self.tab = np.zeros((T_ROWS, 2))
            self.strips = np.zeros((2, 1))
            self.cdv = np.zeros(2)
            prm[P_DAL] = 1.0
            prm[P_DV] = 1.0
        self.prm = prm
        self._structure = None

    # ---- packing ------------------------------------------------------------------------
    def data(self, field_: WindField):
        """Kernel data tuple for a realised wind."""
        wpar, sched, turb = field_.pack()
        return (self.prm, wpar, sched, turb, self.tab, self.strips, self.rho_tab, self.cdv)

    def nodes(self, y):
        """Tether node positions (N+1, 2) [m] and velocities [m/s] of a state (winch first)."""
        pos = np.empty((self.tether.segments + 1, 2))
        vel = np.empty_like(pos)
        _nodes(np.asarray(y, float), self.prm, pos, vel)
        return pos, vel

    def body_state(self, y):
        """Hull (x_O, z_O, theta, u, w, q) or point (x, z, v_x, v_z) part of the state."""
        return np.asarray(y, float)[self.hull_index:]

    def pack_state(self, pos, vel, body) -> np.ndarray:
        """State vector from free-node positions/velocities ((N+1, 2) arrays incl. the ends; the
        ends are ignored) and the body part."""
        n = self.tether.segments
        y = np.empty(self.n_state)
        for i in range(1, n):
            y[4 * (i - 1):4 * i] = (pos[i, 0], pos[i, 1], vel[i, 0], vel[i, 1])
        y[self.hull_index:] = body
        return y

    def hull_pose_from_confluence(self, xc_e: float, zc_e: float, theta: float):
        """Position of O [m] that puts C at (xc_e, zc_e) with pitch theta [rad]."""
        xc, zc = self.body.confluence
        c, s = math.cos(theta), math.sin(theta)
        return xc_e + c * xc + s * zc, zc_e - s * xc + c * zc

    # ---- evaluation ---------------------------------------------------------------------
    def rhs(self, t: float, y, field_: WindField):
        """dy/dt and the diagnostics (``DIAG_NAMES``) at (t, y)."""
        data = self.data(field_)
        dy = np.empty(self.n_state)
        diag = np.empty(ND)
        wt = np.empty(NT)
        wind_time_terms(float(t), data[1], data[2], data[3], wt)
        rhs_kernel(np.asarray(y, float), dy, data, wt, diag)
        return dy, dict(zip(DIAG_NAMES, diag))

    def structure(self):
        """Band widths (kl, ku) of the Jacobian of the state derivative.

        With the node-interleaved layout (x, z, v_x, v_z per node) node i's accelerations depend
        on nodes i-1..i+1 (tension, damping, drag tangent): kl = 7, ku = 5. The hull's three
        accelerations depend on the top free node (segment N): kl = 9; that node depends on the
        hull's six states through C: ku = 7. (``tests/core/test_dynamics_solver.py`` checks these
        against a dense finite-difference Jacobian.)
        """
        return (9, 7) if self.is_hull else (7, 5)

    def energy(self, y, rho: float | None = None) -> float:
        """Mechanical energy [J] (V4): hull or point kinetic energy with the added masses, the
        potential of weight and buoyancy (uniform density), the tether's kinetic, potential and
        elastic energy. E = 1/2 nu^T (M_RB + M_A) nu + m g z_G - rho V g z_O + tether terms."""
        rho = self.atmosphere.density if rho is None else rho
        pos, vel = self.nodes(y)
        e = tether_energy(pos, vel, self.tether, self.g, rho)
        b = self.body_state(y)
        if self.is_hull:
            h = self.body
            nu = b[3:6]
            m_a = np.diag(h.added_mass)
            e += 0.5 * nu @ (self.rigid_mass_matrix + m_a) @ nu
            c, s = math.cos(b[2]), math.sin(b[2])
            xg, zg = h.cg
            z_g = b[1] + s * xg - c * zg
            e += h.mass * self.g * z_g - rho * h.volume * self.g * b[1]
        else:
            p = self.body
            e += 0.5 * (p.mass + p.added_mass_coefficient * rho * p.volume) * (b[2] ** 2 + b[3] ** 2)
            e += (p.mass - rho * p.volume) * self.g * b[1]
        return float(e)


def _dense_fd(system: DynamicSystem, y, field_: WindField, eps: float = 1e-7):
    data = system.data(field_)
    wt = np.empty(NT)
    wind_time_terms(0.0, data[1], data[2], data[3], wt)
    n = y.size
    f0 = np.empty(n)
    f1 = np.empty(n)
    diag = np.empty(ND)
    rhs_kernel(y, f0, data, wt, diag)
    jac = np.empty((n, n))
    for j in range(n):
        yp = y.copy()
        h = eps * max(1.0, abs(y[j]))
        yp[j] += h
        rhs_kernel(yp, f1, data, wt, diag)
        jac[:, j] = (f1 - f0) / h
    return jac


# --------------------------------------------------------------------------------------------
# Kernels
# --------------------------------------------------------------------------------------------
@njit(cache=True)
def _nodes(y, prm, pos, vel):  # pragma: no cover - numba
    """Fill node positions/velocities (N+1, 2) from the state (winch, free nodes, top)."""
    n = int(prm[P_NSEG])
    pos[0, 0] = prm[P_XA]
    pos[0, 1] = prm[P_ZA]
    vel[0, 0] = 0.0
    vel[0, 1] = 0.0
    for i in range(1, n):
        k = 4 * (i - 1)
        pos[i, 0] = y[k]
        pos[i, 1] = y[k + 1]
        vel[i, 0] = y[k + 2]
        vel[i, 1] = y[k + 3]
    b = 4 * (n - 1)
    if prm[P_MODE] == 0.0:
        pos[n, 0] = y[b]
        pos[n, 1] = y[b + 1]
        vel[n, 0] = y[b + 2]
        vel[n, 1] = y[b + 3]
    else:
        th = y[b + 2]
        c = math.cos(th)
        s = math.sin(th)
        xc = prm[P_XC]
        zc = prm[P_ZC]
        pos[n, 0] = y[b] - c * xc - s * zc
        pos[n, 1] = y[b + 1] + s * xc - c * zc
        ub = y[b + 3] + y[b + 5] * zc
        wb = y[b + 4] - y[b + 5] * xc
        vel[n, 0] = -c * ub - s * wb
        vel[n, 1] = s * ub - c * wb


@njit(cache=True)
def _table(tab, row, x, x0, dx):  # pragma: no cover - numba
    """Linear interpolation in row ``row`` of a uniform table (clamped at the ends)."""
    m = tab.shape[1]
    s = (x - x0) / dx
    if s <= 0.0:
        return tab[row, 0]
    if s >= m - 1:
        return tab[row, m - 1]
    k = int(s)
    f = s - k
    return tab[row, k] * (1.0 - f) + tab[row, k + 1] * f


@njit(cache=True)
def rhs_kernel(y, dy, data, wt, diag):  # pragma: no cover - numba
    """Right-hand side dy/dt of the tethered-aerostat model (module docstring).

    Parameters
    ----------
    y : ndarray
        State (see the module docstring).
    dy : ndarray, out
        Time derivative of the state.
    data : tuple
        (prm, wpar, sched, turb, tab, strips, rho_tab, cdv) from :meth:`DynamicSystem.data`.
    wt : ndarray
        Wind time terms at the current time (:func:`.wind.wind_time_terms`).
    diag : ndarray, out
        Diagnostics, ``DIAG_NAMES`` order.
    """
    prm, wpar, _sched, _turb, tab, strips, rho_tab, cdv = data
    n = int(prm[P_NSEG])
    pos = np.empty((n + 1, 2))
    vel = np.empty((n + 1, 2))
    force = np.empty((n + 1, 2))
    tension = np.empty(n)
    seg_len = np.empty(n)
    seg_dir = np.empty((n, 2))
    _nodes(y, prm, pos, vel)
    tether_loads(pos, vel, prm, wpar, wt, rho_tab, force, tension, seg_len, seg_dir)
    m_node = prm[P_W] * prm[P_L0]
    for i in range(1, n):
        k = 4 * (i - 1)
        dy[k] = vel[i, 0]
        dy[k + 1] = vel[i, 1]
        dy[k + 2] = force[i, 0] / m_node
        dy[k + 3] = force[i, 1] / m_node
    b = 4 * (n - 1)
    g = prm[P_G]
    tmax = tension[0]
    tmin = tension[0]
    for j in range(n):
        tmax = max(tmax, tension[j])
        tmin = min(tmin, tension[j])
    diag[4] = -force[n, 0]
    diag[5] = -force[n, 1]
    diag[6] = force[0, 0]
    diag[7] = force[0, 1]
    diag[8] = tmax
    diag[18] = tmin
    diag[9] = pos[n, 0]
    diag[10] = pos[n, 1]
    diag[11] = vel[n, 0]
    diag[12] = vel[n, 1]
    if prm[P_MODE] == 0.0:
        # ---- point aerostat -------------------------------------------------------------
        z = pos[n, 1]
        rho = air_density(z, prm, rho_tab)
        pf = profile_factor(z, wpar)
        ux = wt[0] * pf + wt[2]
        uz = wt[4]
        rx = ux - vel[n, 0]
        rz = uz - vel[n, 1]
        vr = math.sqrt(rx * rx + rz * rz)
        vol = prm[P_PV]
        kd = 0.5 * rho * prm[P_PCDA] * vr
        fx = force[n, 0] + kd * rx
        fz = force[n, 1] + kd * rz + (rho * vol - prm[P_PM]) * g
        ca = prm[P_PCA] * prm[P_RHO_REF] * vol
        if prm[P_POINT_FK] > 0.0:
            kf = ca + rho * vol
            fx += kf * (wt[1] * pf + wt[3])
            fz += kf * wt[5]
        meff = prm[P_PM] + ca + 0.5 * m_node
        dy[b] = vel[n, 0]
        dy[b + 1] = vel[n, 1]
        dy[b + 2] = fx / meff
        dy[b + 3] = fz / meff
        diag[0] = 0.0
        diag[1] = vr
        diag[2] = ux
        diag[3] = uz
        diag[13] = vel[n, 0]
        diag[14] = vel[n, 1]
        diag[15] = 0.0
        diag[16] = 0.0
        diag[17] = 0.0
        diag[19] = wt[1] * pf + wt[3]
        return
    # ---- rigid hull ---------------------------------------------------------------------
    zo = y[b + 1]
    th = y[b + 2]
    u = y[b + 3]
    w = y[b + 4]
    q = y[b + 5]
    c = math.cos(th)
    s = math.sin(th)
    rho = air_density(zo, prm, rho_tab)
    pf = profile_factor(zo, wpar)
    ux = wt[0] * pf + wt[2]
    uz = wt[4]
    axw = wt[1] * pf + wt[3]
    azw = wt[5]
    nwx = -c * ux + s * uz
    nwz = -s * ux - c * uz
    ur = u - nwx
    wr = w - nwz
    vr2 = ur * ur + wr * wr
    vr = math.sqrt(vr2)
    alpha = math.atan2(wr, ur)
    q0 = 0.5 * rho * vr2
    al0 = prm[P_AL0]
    dal = prm[P_DAL]
    fx = 0.0
    fz = 0.0
    mm = 0.0
    if prm[P_AERO_INV] > 0.0:
        fx -= q0 * _table(tab, T_A_INV, alpha, al0, dal)
        fz -= q0 * _table(tab, T_N_INV, alpha, al0, dal)
        mm += q0 * _table(tab, T_M_INV, alpha, al0, dal)
    if prm[P_AERO_AX] > 0.0:
        cd = cdv[0]
        if cdv.shape[0] > 1:
            sv = (vr - prm[P_V0]) / prm[P_DV]
            if sv <= 0.0:
                cd = cdv[0]
            elif sv >= cdv.shape[0] - 1:
                cd = cdv[cdv.shape[0] - 1]
            else:
                kv = int(sv)
                fv = sv - kv
                cd = cdv[kv] * (1.0 - fv) + cdv[kv + 1] * fv
        fx -= q0 * cd * _table(tab, T_A_AX, alpha, al0, dal)
    if prm[P_AERO_CF] > 0.0:
        kc = 0.5 * rho * prm[P_CDC]
        for k in range(strips.shape[1]):
            xk = strips[0, k]
            wl = wr - q * xk
            dn = kc * strips[1, k] * wl * abs(wl)
            fz -= dn
            mm += xk * dn
    af = 0.0
    fin_l = 0.0
    xf = prm[P_XF]
    zf = prm[P_ZF]
    if prm[P_AERO_FIN] > 0.0:
        uf = ur + q * zf
        wf = wr - q * xf
        af = math.atan2(wf, uf)
        qf = 0.5 * rho * (uf * uf + wf * wf)
        fin_l = qf * _table(tab, T_FIN_L, af, al0, dal)
        fin_d = qf * _table(tab, T_FIN_D, af, al0, dal)
        caf = math.cos(af)
        saf = math.sin(af)
        nf = fin_l * caf + fin_d * saf
        a_f = fin_d * caf - fin_l * saf
        fx -= a_f
        fz -= nf
        mm += zf * (-a_f) - xf * (-nf)
    m_aero = mm
    # gravity and buoyancy
    hm = prm[P_HM]
    vol = prm[P_HV]
    dbx = -s
    dbz = c
    fx += (hm - rho * vol) * g * dbx
    fz += (hm - rho * vol) * g * dbz
    mm += hm * g * (prm[P_ZG] * dbx - prm[P_XG] * dbz)
    # tether at C
    tbx = -c * force[n, 0] + s * force[n, 1]
    tbz = -s * force[n, 0] - c * force[n, 1]
    fx += tbx
    fz += tbz
    mm += prm[P_ZC] * tbx - prm[P_XC] * tbz
    # rigid-body Coriolis / centripetal about O
    mt = prm[P_MT]
    xgt = prm[P_XGT]
    zgt = prm[P_ZGT]
    fx -= mt * (q * w - q * q * xgt)
    fz -= mt * (-q * u - q * q * zgt)
    mm -= mt * q * (zgt * w + xgt * u)
    # added-mass rotation coupling (Kirchhoff); Munk entry only in "kirchhoff" mode
    mx = prm[P_MX]
    mz = prm[P_MZ]
    fx -= q * mz * wr
    fz += q * mx * ur
    if prm[P_KIRCHHOFF] > 0.0:
        mm += (mz - mx) * ur * wr
    # unsteady-wind inertia: M_A nu_w_dot + rho V a_w
    if prm[P_UNSTEADY] > 0.0:
        awx = -c * axw + s * azw
        awz = -s * axw - c * azw
        fx += mx * (awx - q * nwz) + rho * vol * awx
        fz += mz * (awz + q * nwx) + rho * vol * awz
    mi = prm[P_MINV:P_MINV + 9]
    dy[b] = -c * u - s * w
    dy[b + 1] = s * u - c * w
    dy[b + 2] = q
    dy[b + 3] = mi[0] * fx + mi[1] * fz + mi[2] * mm
    dy[b + 4] = mi[3] * fx + mi[4] * fz + mi[5] * mm
    dy[b + 5] = mi[6] * fx + mi[7] * fz + mi[8] * mm
    diag[0] = alpha
    diag[1] = vr
    diag[2] = ux
    diag[3] = uz
    diag[13] = -c * u - s * w
    diag[14] = s * u - c * w
    diag[15] = af
    diag[16] = fin_l
    diag[17] = m_aero
    diag[19] = axw


def system_from_design(design, *, segments: int = 20, damping_ratio: float = 1.0,
                       unsteady_wind_inertia: bool = True, axial_stiffness: float | None = None,
                       atmosphere: str = "constant", **hull_options) -> DynamicSystem:
    """The dynamic system of a static-engine :class:`aerostat_core.design.Design`.

    Parameters
    ----------
    design : aerostat_core.Design
    segments : int
        Tether segments N, valid [2, 400].
    damping_ratio : float
        Tether internal damping ratio zeta [-].
    unsteady_wind_inertia : bool
        Added-mass and Froude-Krylov forces of the accelerating wind.
    axial_stiffness : float or None
        Override the tether's EA [N] (``None``: the design's tether).
    atmosphere : {"constant", "isa"}
        "constant": the engine's air density at the operating altitude everywhere (exactly the
        static engine's assumption, so steady runs match it); "isa": ISA density versus height.
    **hull_options
        :class:`HullModel` switches (``aero_fins`` ...).

    Notes
    -----
    Gravity is the engine's (``aerostat_core.constants.G0``). The hull's mass, CG, inertia,
    confluence point, fins and aerodynamics come from the design (:func:`hull_from_airframe`).
    """
    af = design.airframe
    cfg = design.configuration
    req = design.requirement
    hull = hull_from_airframe(af, cfg.aero, unsteady_wind_inertia=unsteady_wind_inertia,
                              **hull_options)
    spec = af.tether or cfg.tether  # as flown: with power conductors (aerostat_core.mission)
    tether = TetherModel.from_spec(spec, af.tether_length, segments, damping_ratio)
    if axial_stiffness is not None:
        tether = replace(tether, axial_stiffness=float(axial_stiffness))
    if atmosphere == "constant":
        atm = Atmosphere(float(np.asarray(af.air_density).reshape(-1)[0]))
    elif atmosphere == "isa":
        atm = Atmosphere.isa(req.site_elevation, req.isa_offset, top=af.tether_length + 100.0)
    else:
        raise ValueError(f"atmosphere = {atmosphere!r}; valid options ('constant', 'isa')")
    return DynamicSystem(hull, tether, g=float(af.g), atmosphere=atm)
