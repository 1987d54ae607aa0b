"""Lumped-mass tether: elastic, damped segments with weight, air buoyancy and drag (2-D).

Option A of docs/dynamics.md §1.6 (Lambert & Nahon 2003, MoorDyn-C v2 conventions): N segments of
unstretched length l0 = L/N; node 0 is the winch (fixed), nodes 1..N-1 are free point masses
w l0, node N is the top (the confluence point of the hull, or the point aerostat).

Segment j joins nodes j-1 and j, length l_j, unit vector e_j (from j-1 to j), strain rate
ldot_j/l0 with ldot_j = e_j . (v_j - v_j-1). Tension (Kelvin-Voigt, no compression in the spring)

    T_j = max(EA (l_j/l0 - 1)_+ + c ldot_j / l0, 0),      c = zeta l0 sqrt(EA w)

(MoorDyn's BA = -zeta). A line carries no compression: when the damper would push (a slack or
fast-shortening segment) the tension is zero, and the segment is reported slack. MoorDyn lets
the damper push (T < 0) while a segment shortens; ``TetherModel.damper_compression=True``
reproduces that convention for the MoorDyn cross-checks (cases R1-R4) only.

Node i carries weight and air buoyancy (w - rho A) g l0_i (l0_i = l0, halved at the ends) and drag
on the relative wind v_r = U(z_i, t) - v_i split along the node tangent t_i (direction of
r_i+1 - r_i-1; the segment direction at the ends) into v_q = (v_r . t) t and v_p = v_r - v_q:

    F_drag = 1/2 rho d l0_i [C_dn |v_p| v_p + pi C_dt |v_q| v_q]

with l0_i the unstretched length belonging to the node (half of each adjacent segment), as
MoorDyn (``Line.cpp``: drag and weight on unstretched lengths) and the static engine's march.
The line's transverse added mass (rho pi d^2/4 per metre, ~0.1 % of w) is neglected.

Sources: docs/dynamics.md §1.6 (D1, D7); MoorDyn-C ``Line.cpp`` v2.7.1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from aerostat_core.base.fields import integer, number, validate

from .layout import (
    P_CD,
    P_CDN,
    P_CDT,
    P_D,
    P_EA,
    P_G,
    P_L0,
    P_NSEG,
    P_RHO_DZ,
    P_RHO_Z0,
    P_TBUOY,
    P_TDRAG,
    P_TPUSH,
    P_W,
)
from .wind import W_GUST_ON, W_TURB_ON, profile_factor, wind_point

#: Largest axial stiffness used for an "inextensible" (EA = inf) tether [N].
EA_INEXTENSIBLE = 1.0e8


@dataclass(frozen=True)
class TetherModel:
    """Lumped-mass tether parameters.

    Parameters
    ----------
    length : float
        Unstretched length L [m], valid (1, 20000].
    segments : int
        Number of segments N, valid [2, 400] (10-20 is enough for the hull response and the
        static shape; docs/dynamics.md §3.1 R4).
    linear_density : float
        Mass per unstretched length w [kg/m], valid (0, 10].
    diameter : float
        d [m], valid (0, 0.2].
    axial_stiffness : float
        EA [N], valid (0, inf]; inf is replaced by ``EA_INEXTENSIBLE`` = 1e8 N.
    damping_ratio : float
        zeta of the segment's axial mode [-], valid [0, 10]; c = zeta l0 sqrt(EA w) (MoorDyn
        "BA/-zeta"). 0.5-1 kills spurious axial ringing without touching the slow dynamics.
    normal_drag_coefficient : float
        C_dn on d [-], valid [0, 3].
    tangential_drag_coefficient : float
        C_dt on pi d [-], valid [0, 0.5].
    air_buoyancy : bool
        Include the air buoyancy rho A g of the line (MoorDyn parity; ~0.1 % of the weight).
    drag : bool
        Include tether drag (switched off for the energy check V4).
    damper_compression : bool
        Let the internal damper push (T < 0) in a shortening segment, as MoorDyn does (MoorDyn
        parity of the R cases). Default False: the line carries no compression.

    Examples
    --------
    >>> t = TetherModel(length=320.0, segments=32)
    >>> round(t.segment_length, 3), round(t.damping_coefficient, 2)
    (10.0, 1414.21)
    """

    length: float = number(300.0, "Tether length", "m", 1.0, 20000.0, lo_open=True)
    segments: int = integer(20, "Tether segments", 2, 400, source="docs/dynamics.md §3.1")
    linear_density: float = number(
        0.02, "Tether linear density", "kg/m", 0.0, 10.0, lo_open=True, scale=1000.0,
        display_unit="g/m")
    diameter: float = number(
        0.004, "Tether diameter", "m", 0.0, 0.2, lo_open=True, scale=1000.0, display_unit="mm")
    axial_stiffness: float = number(
        1.0e6, "Tether axial stiffness EA", "N", 0.0, 1e12, lo_open=True, allow_inf=True)
    damping_ratio: float = number(
        1.0, "Tether damping ratio", "", 0.0, 10.0, help="zeta of the segment's axial mode.",
        source="MoorDyn BA/-zeta")
    normal_drag_coefficient: float = number(
        1.2, "Tether normal drag coefficient", "", 0.0, 3.0)
    tangential_drag_coefficient: float = number(
        0.01, "Tether tangential drag coefficient", "", 0.0, 0.5)
    air_buoyancy: bool = True
    drag: bool = True
    damper_compression: bool = False

    def __post_init__(self) -> None:
        validate(self)

    @classmethod
    def from_spec(cls, spec, length: float, segments: int = 20, damping_ratio: float = 1.0,
                  **kw) -> TetherModel:
        """From the static engine's :class:`aerostat_core.structures.materials.TetherSpec`."""
        return cls(
            length=float(length), segments=segments, linear_density=spec.linear_density,
            diameter=spec.diameter, axial_stiffness=spec.axial_stiffness,
            damping_ratio=damping_ratio, normal_drag_coefficient=spec.normal_drag_coefficient,
            tangential_drag_coefficient=spec.tangential_drag_coefficient, **kw,
        )

    @property
    def stiffness(self) -> float:
        """EA used in the model [N] (inf replaced by ``EA_INEXTENSIBLE``)."""
        return min(float(self.axial_stiffness), EA_INEXTENSIBLE)

    @property
    def segment_length(self) -> float:
        """l0 = L/N [m]."""
        return self.length / self.segments

    @property
    def node_mass(self) -> float:
        """w l0 [kg] (free nodes; the ends carry half)."""
        return self.linear_density * self.segment_length

    @property
    def damping_coefficient(self) -> float:
        """c = zeta l0 sqrt(EA w) [N s]."""
        return self.damping_ratio * self.segment_length * math.sqrt(self.stiffness
                                                                    * self.linear_density)

    @property
    def axial_frequency(self) -> float:
        """Highest axial mode of the discretised line, omega = (2N/L) sqrt(EA/w) [rad/s]."""
        return 2.0 * self.segments / self.length * math.sqrt(self.stiffness / self.linear_density)

    def fill(self, prm: np.ndarray) -> None:
        """Write the tether entries of the kernel parameter vector."""
        prm[P_NSEG] = self.segments
        prm[P_L0] = self.segment_length
        prm[P_W] = self.linear_density
        prm[P_D] = self.diameter
        prm[P_EA] = self.stiffness
        prm[P_CD] = self.damping_coefficient / self.segment_length
        prm[P_CDN] = self.normal_drag_coefficient
        prm[P_CDT] = self.tangential_drag_coefficient
        prm[P_TBUOY] = 1.0 if self.air_buoyancy else 0.0
        prm[P_TDRAG] = 1.0 if self.drag else 0.0
        prm[P_TPUSH] = 1.0 if self.damper_compression else 0.0


@njit(cache=True)
def air_density(z, prm, rho_tab):  # pragma: no cover - numba
    """Air density [kg/m3] at height z [m]: linear interpolation in a uniform table (clamped)."""
    n = rho_tab.shape[0]
    if n == 1:
        return rho_tab[0]
    s = (z - prm[P_RHO_Z0]) / prm[P_RHO_DZ]
    if s <= 0.0:
        return rho_tab[0]
    if s >= n - 1:
        return rho_tab[n - 1]
    k = int(s)
    f = s - k
    return rho_tab[k] * (1.0 - f) + rho_tab[k + 1] * f


@njit(cache=True)
def tether_loads(pos, vel, t_now, prm, wpar, wt, turb, rho_tab, force, tension, seg_len, seg_dir):
    # pragma: no cover - numba
    """Forces on every node of the lumped-mass tether (see the module docstring).

    Parameters
    ----------
    pos, vel : ndarray (N+1, 2)
        Node positions [m] and velocities [m/s] in the earth frame (x downwind, z up), node 0 at
        the winch, node N at the top.
    t_now : float
        Time [s].
    prm : ndarray
        Kernel parameters (:mod:`.layout`).
    wpar, turb : ndarray
        Wind parameters and turbulence table (:meth:`.wind.WindField.pack`).
    wt : ndarray
        Wind time terms at ``t_now`` (:func:`.wind.wind_time_terms`).
    rho_tab : ndarray
        Air-density table [kg/m3].
    force : ndarray (N+1, 2), out
        Sum of tension, weight + buoyancy and drag on each node [N].
    tension : ndarray (N,), out
        Segment tensions [N] (spring + damper).
    seg_len : ndarray (N,), out
        Stretched segment lengths [m].
    seg_dir : ndarray (N, 2), out
        Unit vectors from the lower to the upper node of each segment.
    """
    n = int(prm[P_NSEG])
    l0 = prm[P_L0]
    ea = prm[P_EA]
    cdamp = prm[P_CD]
    g = prm[P_G]
    w = prm[P_W]
    d = prm[P_D]
    area = 0.25 * math.pi * d * d
    no_push = prm[P_TPUSH] == 0.0
    mean_only = wpar[W_TURB_ON] == 0.0 and wpar[W_GUST_ON] == 0.0
    for i in range(n + 1):
        force[i, 0] = 0.0
        force[i, 1] = 0.0
    for j in range(n):
        dx = pos[j + 1, 0] - pos[j, 0]
        dz = pos[j + 1, 1] - pos[j, 1]
        ll = math.sqrt(dx * dx + dz * dz)
        ex = dx / ll
        ez = dz / ll
        ldot = ex * (vel[j + 1, 0] - vel[j, 0]) + ez * (vel[j + 1, 1] - vel[j, 1])
        t = cdamp * ldot
        if ll > l0:
            t += ea * (ll / l0 - 1.0)
        if t < 0.0 and no_push:
            t = 0.0  # a line carries no compression
        tension[j] = t
        seg_len[j] = ll
        seg_dir[j, 0] = ex
        seg_dir[j, 1] = ez
        force[j, 0] += t * ex
        force[j, 1] += t * ez
        force[j + 1, 0] -= t * ex
        force[j + 1, 1] -= t * ez
    do_drag = prm[P_TDRAG] > 0.0
    buoy = prm[P_TBUOY] > 0.0
    cdn = prm[P_CDN]
    cdt = prm[P_CDT] * math.pi
    for i in range(n + 1):
        z = pos[i, 1]
        rho = air_density(z, prm, rho_tab)
        lw = l0 if (i > 0 and i < n) else 0.5 * l0
        wl = w
        if buoy:
            wl = w - rho * area
        force[i, 1] -= wl * g * lw
        if do_drag:
            if i == 0:
                tx = seg_dir[0, 0]
                tz = seg_dir[0, 1]
            elif i == n:
                tx = seg_dir[n - 1, 0]
                tz = seg_dir[n - 1, 1]
            else:
                tx = pos[i + 1, 0] - pos[i - 1, 0]
                tz = pos[i + 1, 1] - pos[i - 1, 1]
                tn = math.sqrt(tx * tx + tz * tz)
                tx /= tn
                tz /= tn
            if mean_only:  # the mean profile alone: no need for the full point evaluation
                ux = wt[0] * profile_factor(z, wpar) - vel[i, 0]
                uz = -vel[i, 1]
            else:
                wx, wz, _d1, _d2, _a1, _a2 = wind_point(t_now, pos[i, 0], z, wpar, wt, turb)
                ux = wx - vel[i, 0]
                uz = wz - vel[i, 1]
            vq = ux * tx + uz * tz
            qx = vq * tx
            qz = vq * tz
            px = ux - qx
            pz = uz - qz
            vp = math.sqrt(px * px + pz * pz)
            k = 0.5 * rho * d * lw
            force[i, 0] += k * (cdn * vp * px + cdt * abs(vq) * qx)
            force[i, 1] += k * (cdn * vp * pz + cdt * abs(vq) * qz)


def tether_energy(pos, vel, tether: TetherModel, g: float, rho: float = 0.0) -> float:
    """Mechanical energy of the line [J]: kinetic of the free nodes (and half masses at the ends
    when their velocities are given), potential of the net weight, elastic of taut segments.

    E = sum 1/2 m_i |v_i|^2 + sum (w - rho A) g l0_i z_i + sum 1/2 (EA/l0)(l_j - l0)_+^2

    Parameters
    ----------
    pos, vel : ndarray (N+1, 2)
        Node positions [m] and velocities [m/s] (node 0 = winch, node N = top).
    tether : TetherModel
    g : float
        Gravity [m/s2].
    rho : float
        Air density for the line buoyancy [kg/m3] (0 when ``air_buoyancy`` is off).
    """
    n = tether.segments
    l0 = tether.segment_length
    share = np.full(n + 1, l0)
    share[[0, n]] = 0.5 * l0
    wl = tether.linear_density - (rho * np.pi * tether.diameter**2 / 4 if tether.air_buoyancy
                                  else 0.0)
    ke = 0.5 * np.sum(tether.linear_density * share * np.sum(vel**2, axis=1))
    pe = np.sum(wl * g * share * pos[:, 1])
    ll = np.hypot(*np.diff(pos, axis=0).T)
    ee = 0.5 * tether.stiffness / l0 * np.sum(np.maximum(ll - l0, 0.0) ** 2)
    return float(ke + pe + ee)
