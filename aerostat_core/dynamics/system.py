"""The assembled dynamic system: body + tether + gravity + air, packed for the kernels.

:class:`DynamicSystem` fills the flat parameter vector of :mod:`.layout` that the kernels of
:mod:`.kernel` read; :func:`system_from_design` builds one from a static-engine design.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from aerostat_core.base.constants import G0

from .bodies import HullModel, hull_from_airframe
from .checks import check_number
from .kernel import DIAG_NAMES, ND, nodes_kernel, rhs_kernel
from .kernel_cache import ensure_fresh_cache
from .layout import (
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
    P_MINV,
    P_MODE,
    P_MT,
    P_MX,
    P_MZ,
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
    T_ROWS,
)
from .tether import TetherModel, tether_energy
from .wind import WindField


@dataclass(frozen=True)
class Atmosphere:
    """Air density along the heights of a run.

    ``constant`` (default): one density everywhere, as the static engine does (it takes the air at
    the operating altitude). ``table``: densities ``values`` [kg/m3] on heights ``z0 + k dz`` [m],
    linearly interpolated (e.g. ISA from :func:`aerostat_core.atmosphere.standard`)."""

    density: float = 1.225
    z0: float = 0.0
    dz: float = 1.0
    values: tuple = ()

    @classmethod
    def isa(cls, site_elevation: float = 0.0, isa_offset: float = 0.0, top: float = 1000.0,
            dz: float = 2.0) -> Atmosphere:
        """ISA density (static engine's :func:`aerostat_core.atmosphere.standard`) from the winch
        (height 0) to ``top`` [m] above it."""
        from aerostat_core.atmosphere.standard import isa

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
        Gravity [m/s2] (``aerostat_core.base.constants.G0`` for designs; 9.81 in the R cases).
    atmosphere : Atmosphere
    winch : (float, float)
        Winch position [m] (the earth origin by default).
    """

    def __init__(self, body, tether: TetherModel, g: float = G0,
                 atmosphere: Atmosphere | None = None, winch=(0.0, 0.0)) -> None:
        ensure_fresh_cache()  # once per process, before the first kernel is loaded
        self.body = body
        self.tether = tether
        self.g = float(check_number("DynamicSystem", "g", g, 0.0, 100.0, "m/s2"))
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
        nodes_kernel(np.asarray(y, float), self.prm, pos, vel)
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
        rhs_kernel(float(t), np.asarray(y, float), dy, data, diag)
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


def dense_jacobian(system: DynamicSystem, y, field_: WindField, eps: float = 1e-7):
    """Dense forward-difference Jacobian of the state derivative at t = 0 (tests of the band)."""
    data = system.data(field_)
    n = y.size
    f0 = np.empty(n)
    f1 = np.empty(n)
    diag = np.empty(ND)
    rhs_kernel(0.0, y, f0, data, diag)
    jac = np.empty((n, n))
    for j in range(n):
        yp = y.copy()
        h = eps * max(1.0, abs(y[j]))
        yp[j] += h
        rhs_kernel(0.0, yp, f1, data, diag)
        jac[:, j] = (f1 - f0) / h
    return jac


def system_from_design(design, *, segments: int = 20, damping_ratio: float = 1.0,
                       unsteady_wind_inertia: bool = True, axial_stiffness: float | None = None,
                       atmosphere: str = "constant", **hull_options) -> DynamicSystem:
    """The dynamic system of a static-engine :class:`aerostat_core.model.design.Design`.

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
    Gravity is the engine's (``aerostat_core.base.constants.G0``). The hull's mass, CG, inertia,
    confluence point, fins and aerodynamics come from the design (:func:`hull_from_airframe`).
    """
    af = design.airframe
    cfg = design.configuration
    req = design.requirement
    hull = hull_from_airframe(af, cfg.aero, unsteady_wind_inertia=unsteady_wind_inertia,
                              **hull_options)
    spec = af.tether or cfg.tether  # as flown: with power conductors (aerostat_core.model.mission)
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
