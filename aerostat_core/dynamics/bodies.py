"""Bodies of the dynamic model: the point aerostat and the rigid 3-DOF hull (docs/dynamics.md §1.2-1.3).

Frames (docs/dynamics.md §1.1). Earth E: x downwind, z up, origin at the winch. Body B (aircraft axes
turned 180 deg): origin at the centre of volume O, x_B towards the nose, z_B towards the belly;
pitch theta nose-up. A static-engine station xi (from the nose, aft) and height z (up) map to
body x = xi_CV - xi, z_B = -z.

The hull's aerodynamics are the static engine's functions tabulated against alpha over the whole
circle [-180, 180] deg, so a reversed relative wind (a gust or turbulence that overtakes the hull
from behind) stays inside the model: the axial drag takes the sign of cos(alpha) (it pushes
forward when the wind comes from the tail), and past the fin stall angle the fins follow a
Viterna & Corrigan (1982) flat-plate extension (lift C_L,s sin 2a / sin 2a_s, extra drag
C_D,max (sin^2 a - sin^2 a_s)_+, C_D,max = 1.11 + 0.018 AR), continuous at the stall angle.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field, replace

import numpy as np

from aerostat_core.base.fields import number, validate
from aerostat_core.geometry.added_mass import lamb_factors

from .layout import T_ROWS

#: Spacing of the aerodynamic tables [rad].
ALPHA_STEP = math.radians(0.01)


@functools.cache
def _alpha_grid() -> np.ndarray:
    """The tables' angle grid [rad], -pi to pi in :data:`ALPHA_STEP` (read-only, made once:
    every hull built in a process shares it and the functions of it below)."""
    alpha = np.arange(-math.pi, math.pi + 0.5 * ALPHA_STEP, ALPHA_STEP)
    alpha.flags.writeable = False
    return alpha


@functools.cache
def _grid_functions() -> dict:
    """Functions of the angle grid alone that every table build uses (the same expressions as
    where they are used, evaluated once per process): sign(cos alpha), |alpha|, sign(alpha),
    sin(2 |alpha|) and sin^2(alpha)."""
    alpha = _alpha_grid()
    out = {"sign_cos": np.sign(np.cos(alpha)), "abs": np.abs(alpha), "sign": np.sign(alpha)}
    out["sin_2abs"] = np.sin(2.0 * out["abs"])
    out["sin_sq"] = np.sin(alpha) ** 2
    for v in out.values():
        v.flags.writeable = False
    return out


@functools.cache
def _gauss_legendre(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on [-1, 1] (numpy's ``leggauss``, made once per n)."""
    gx, gw = np.polynomial.legendre.leggauss(n)
    gx.flags.writeable = False
    gw.flags.writeable = False
    return gx, gw
#: Added-mass coefficient of a sphere (point aerostat), C_a = 1/2 [-] (Lamb 1932 §92).
SPHERE_ADDED_MASS_COEFFICIENT = 0.5


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
        C_a: added mass C_a rho V [-], valid [0, 5] (``SPHERE_ADDED_MASS_COEFFICIENT`` = 0.5).
    unsteady_wind_inertia : bool
        Add (1 + C_a) rho V DU/Dt (Froude-Krylov + added mass of the accelerating air, with the
        material derivative of :mod:`.wind`: only uniform time-varying winds drive it). MoorDyn
        points have neither, so the reference cases R1-R4 run without it (default False).

    Examples
    --------
    >>> round(PointAerostat().net_lift(1.225, 9.81), 2)
    739.67
    """

    mass: float = number(71.6, "Moving mass", "kg", 0.0, 1e6, lo_open=True)
    volume: float = number(120.0, "Displaced volume", "m3", 0.0, 1e7, lo_open=True)
    drag_area: float = number(1.0, "Drag area C_D A", "m2", 0.0, 1e5)
    added_mass_coefficient: float = number(0.5, "Added-mass coefficient C_a", "", 0.0, 5.0)
    unsteady_wind_inertia: bool = False

    def __post_init__(self) -> None:
        validate(self)

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
        Switch of f_wind (default True): driven by the fluid acceleration DU/Dt of :mod:`.wind`,
        it acts in a uniform time-varying wind (ramps) and is zero for frozen convected gusts and
        turbulence, so it is on only where it is physical.
    munk : {"jones-delaurier", "kirchhoff"}
        Where the Munk moment comes from. "kirchhoff" adds (m_z - m_x) u_r w_r and must only be
        used with ``aero_inviscid`` off (V4); the two together would count it twice.
    aero_inviscid, aero_axial, aero_crossflow, aero_fins : bool
        Switches of the aerodynamic components.
    theta_limit : float
        |theta| beyond which a run stops as diverged [rad] (90 deg: the hull stands on its nose
        or tail, outside the rigid-bridle model).
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
    theta_limit: float = math.radians(90.0)

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


def lamb_added_mass(fineness_ratio: float, volume: float, rho: float, i_air: float):
    """Added masses of a hull from Lamb's prolate-spheroid factors (static engine's
    :func:`aerostat_core.geometry.added_mass.lamb_factors` when available).

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
    from aerostat_core.geometry.added_mass import lamb_factors

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
    """A prolate-spheroid hull from a few numbers (docs/dynamics.md §3.3 prototype values by default).

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
    k1, k2, kr = (float(k) for k in lamb_factors(fineness_ratio))  # Lamb, prolate spheroid
    # strips over the ellipse: x = a sin(phi), 2 r dx = 2 a b cos^2(phi) dphi
    gx, gw = np.polynomial.legendre.leggauss(32)
    phi = 0.5 * math.pi * gx
    xs = a * np.sin(phi)
    ws = 2.0 * a * b * np.cos(phi) ** 2 * gw * 0.5 * math.pi
    if fin_ac is None:
        fin_ac = (-0.38 * length, 0.0)
    alpha = np.arange(-math.pi, math.pi + 0.5 * ALPHA_STEP, ALPHA_STEP)
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
        strips=np.array([xs, ws]), alpha_grid=(float(alpha[0]), ALPHA_STEP), tables=tab,
        speed_grid=(0.0, 100.0), cdv=np.array([cdv_val, cdv_val]), length=length, diameter=d,
        xi_cv=a, outline=outline, **options,
    )


#: Keys of the per-unit-q aerodynamic tables, in row order (``_layout.T_*``).
TABLE_KEYS = ("normal_inviscid", "axial_inviscid", "moment_inviscid", "axial_drag", "fin_lift",
              "fin_drag")


def hull_from_airframe(af, aero, *, unsteady_wind_inertia: bool = True, strips_per_half: int = 16,
                       index=None, **options) -> HullModel:
    """Build the dynamic hull of a static-engine airframe, calling the engine's aerodynamics.

    The per-unit-q tables are made by calling :func:`aerostat_core.aerodynamics.forces.hull_inviscid`,
    :func:`~aerostat_core.aerodynamics.forces.hull_axial` and
    :func:`~aerostat_core.aerodynamics.forces.fin_lift_drag` on a 0.01 deg grid over [-180, 180] deg,
    and Hoerner's C_DV from :func:`aerostat_core.model.statics.axial_drag_coefficient` on a 0.05 m/s
    airspeed grid; linear interpolation on these grids is exact to ~1e-8 relative. The cross-flow
    term is split into strips whose weights are corrected to reproduce the engine's J1 and J2
    exactly, so with q = 0 the dynamic hull loads equal the static ones.

    Parameters
    ----------
    af : aerostat_core.model.airframe.Airframe
        One design (scalar arrays), or a batch with ``index`` selecting one.
    aero : aerostat_core.model.inputs.AeroModel
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
    Mapping (docs/methods.md -> body axes): x = xi_CV - xi, z_B = -z; N (up) -> Z = -N; A (aft) ->
    X = -A; moments nose-up in both. The CG and pitch inertia come from the engine's mass
    breakdown (lifting gas included, it moves with the hull); the added masses from Lamb's factors
    at the operating air density, with I_air = rho int ((xi - xi_CV)^2 + r^2/4) dV.
    """
    from aerostat_core.aerodynamics import forces as ad
    from aerostat_core.geometry.hull import profile_quadrature, radius
    from aerostat_core.model.statics import axial_drag_coefficient

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
    alpha = _alpha_grid()
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
    a_x = a_x * _grid_functions()["sign_cos"]  # axial drag opposes the axial wind over +-180 deg
    lift, drag = fin_post_stall(alpha, lift * np.ones_like(alpha), drag * np.ones_like(alpha),
                                math.radians(aero.fin_stall_angle_deg), sc(fn.lifting_area),
                                sc(fn.aspect_ratio))
    tab = np.array([n_i, a_i, m_i, a_x, lift, drag])
    speeds = np.arange(0.0, 80.0 + 1e-9, 0.05)
    cdv = np.asarray(axial_drag_coefficient(af, aero, speeds), float)
    if cdv.ndim > 1:
        cdv = cdv[..., k] if cdv.shape[-1] != speeds.size else cdv.reshape(-1, speeds.size)[k]
    cdv = np.broadcast_to(cdv, speeds.shape).copy()
    # cross-flow strips on the NPL profile: u = sin(phi) on each half ellipse
    gx, gw = _gauss_legendre(strips_per_half)
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
        alpha_grid=(float(alpha[0]), ALPHA_STEP), tables=np.ascontiguousarray(tab),
        speed_grid=(0.0, 0.05), cdv=cdv, length=length, diameter=2.0 * b, xi_cv=xi_cv,
        outline=outline, fin_outline=fin_outline, unsteady_wind_inertia=unsteady_wind_inertia,
        **options,
    )


def fin_post_stall(alpha, lift, drag, stall_angle: float, lifting_area: float,
                   aspect_ratio: float):
    """Extend per-unit-q fin lift and drag [m2] beyond stall to +-180 deg (module docstring).

    For |alpha| <= alpha_s the inputs are kept. Beyond: L = L_s sin(2 alpha)/sin(2 alpha_s) (flat-
    plate shape, the sign of alpha kept), D = D_s + S C_D,max (sin^2 alpha - sin^2 alpha_s)_+,
    C_D,max = 1.11 + 0.018 AR. Source: Viterna & Corrigan (1982), NASA CP-2230.

    Parameters
    ----------
    alpha : ndarray
        Angles [rad] in [-pi, pi].
    lift, drag : ndarray
        Engine fin lift and drag per unit q [m2] on ``alpha``.
    stall_angle : float
        alpha_s [rad], in (0, pi/2).
    lifting_area : float
        S [m2].
    aspect_ratio : float
        AR of the fin pair [-].
    """
    alpha = np.asarray(alpha, float)
    if alpha is _alpha_grid():  # the tables' grid: its functions are made once
        g = _grid_functions()
    else:
        g = {"abs": np.abs(alpha), "sign": np.sign(alpha)}
        g["sin_2abs"] = np.sin(2.0 * g["abs"])
        g["sin_sq"] = np.sin(alpha) ** 2
    a_s = float(stall_angle)
    beyond = g["abs"] > a_s
    l_s = np.interp(a_s, alpha, lift)
    s2s = math.sin(2.0 * a_s)
    lift = np.where(beyond, l_s * g["sin_2abs"] / s2s * g["sign"], lift)
    cdmax = 1.11 + 0.018 * aspect_ratio
    d_s = np.interp(a_s, alpha, drag)
    extra = np.maximum(g["sin_sq"] - math.sin(a_s) ** 2, 0.0)
    drag = np.where(beyond, d_s + lifting_area * cdmax * extra, drag)
    return lift, drag


def point_from_design(design, speed: float, unsteady_wind_inertia: bool = False,
                      added_mass_coefficient: float = SPHERE_ADDED_MASS_COEFFICIENT
                      ) -> PointAerostat:
    """A point aerostat with a design's mass, volume and drag area.

    The drag area is the static engine's total aerostat drag D at the performance-table speed
    nearest ``speed`` [m/s] (at least 1 m/s) over its dynamic pressure, C_D A = D/(rho V^2/2); the
    added mass is a sphere's (C_a = 0.5) unless given.
    """
    af = design.airframe
    rows = design.performance.rows()
    row = min(rows, key=lambda r: abs(r["wind_speed_m_s"] - max(speed, 1.0)))
    v = max(row["wind_speed_m_s"], 1.0)
    q = 0.5 * float(np.asarray(af.air_density).reshape(-1)[0]) * v**2
    return PointAerostat(mass=float(af.mass.aerostat), volume=float(af.hull.volume),
                         drag_area=row["drag_N"] / q,
                         added_mass_coefficient=added_mass_coefficient,
                         unsteady_wind_inertia=unsteady_wind_inertia)
