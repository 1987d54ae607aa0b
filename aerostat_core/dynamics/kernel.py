"""Numba kernels of the tethered-aerostat equations of motion (docs/dynamics.md §1).

States. Tether nodes 1..N-1: (x, z, v_x, v_z) each, node after node. Then either the point
aerostat (x, z, v_x, v_z) or the hull (x_O, z_O, theta, u, w, q) with (u, w) the body velocity of
O and q = d theta/dt. Body axes map to earth by R_EB = [[-cos th, -sin th], [sin th, -cos th]].

Hull equations (Newton-Euler about O with a CG offset plus Kirchhoff added mass with a current;
Fossen's relative-velocity form, docs/dynamics.md §1.2):

    (M_RB + M_A) nu_dot = f_RB + f_AM + f_wind + f_aero + f_gb + f_teth

    M_RB = [[m, 0, m z_g], [0, m, -m x_g], [m z_g, -m x_g, I_O]],  M_A = diag(m_x, m_z, I_a)
    f_RB = -[m (q w - q^2 x_g), m (-q u - q^2 z_g), m q (z_g w + x_g u)]
    f_AM = [-q m_z w_r, q m_x u_r, (m_z - m_x) u_r w_r]   (third entry only in "kirchhoff" mode)
    f_wind = M_A (nu_w_dot, 0) + rho V (a_w, 0)           (unsteady-wind inertia, a switch)
    f_gb = (m - rho V) g d_B, moment m g (z_g d_B,x - x_g d_B,z), d_B = (-sin th, cos th)
    f_teth: tether force at C, moment z_c F_x - x_c F_z

with nu_w = R_EB^T U the wind in body axes at O, u_r = u - nu_w,x, w_r = w - nu_w,z, alpha =
atan2(w_r, u_r), a_w = R_EB^T DU/Dt (the fluid acceleration, the material derivative of
:mod:`.wind`: zero for frozen convected gusts and turbulence) and nu_w_dot = a_w - (q nu_w,z,
-q nu_w,x).

Aerodynamics (docs/dynamics.md §1.3): the static engine's functions tabulated against alpha
(:mod:`.bodies`), fed with the instantaneous relative velocity: the J&D inviscid term and the axial
drag at O; the viscous cross-flow term as strips with the local normal velocity w - nu_w,z(x_k) -
q x_k; the fins with the local velocity at their aerodynamic centre. When the wind varies along the
wind direction (turbulence, convected gusts) each strip and the fins take the wind at their own
position (the strips interpolate it between ``N_STATIONS`` stations along the hull). The Munk moment is counted once: the J&D inviscid term already contains it, so the
Kirchhoff entry is only used with the aerodynamics off (energy check V4).

Point aerostat (docs/dynamics.md §3.1 "case P", MoorDyn point): mass M, buoyancy rho V g, drag
1/2 rho C_D A |v_r| v_r, isotropic added mass C_a rho V; optionally the Froude-Krylov and
added-mass forces of an accelerating wind (1 + C_a) rho V DU/Dt.

The integrator (:mod:`.solver`) sees this model only through :func:`rhs_kernel` (t, y, dy, data,
diag) and :func:`check_kernel` (t, y, data, diag); ``data`` is opaque to it.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from aerostat_core.dynamics.sixdof_kernel import check6_kernel, rhs6_kernel

from .layout import (
    DIAG_NAMES,
    N_STATIONS,
    ND,
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
    P_RHO_REF,
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
    table_lookup,
)
from .tether import air_density, tether_loads
from .wind import NT, W_GUST_CONV, W_GUST_ON, W_TURB_ON, wind_point, wind_time_terms


@njit(cache=True)
def nodes_kernel(y, prm, pos, vel):  # pragma: no cover - numba
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
def rhs_kernel(t, y, dy, data, diag):  # pragma: no cover - numba
    """Right-hand side dy/dt of the tethered-aerostat model (module docstring).

    Parameters
    ----------
    t : float
        Time [s].
    y : ndarray
        State (see the module docstring).
    dy : ndarray, out
        Time derivative of the state.
    data : tuple
        (prm, wpar, sched, turb, tab, strips, rho_tab, cdv) from :meth:`.system.DynamicSystem.data`.
    diag : ndarray, out
        Diagnostics, ``DIAG_NAMES`` order.
    """
    prm, wpar, sched, turb, tab, strips, rho_tab, cdv = data
    if prm[P_MODE] == 2.0:  # the 6-DOF hull on a 3-D tether (:mod:`.sixdof_kernel`)
        rhs6_kernel(t, y, dy, data, diag)
        return
    wt = np.empty(NT)
    wind_time_terms(t, wpar, sched, wt)

    n = int(prm[P_NSEG])
    pos = np.empty((n + 1, 2))
    vel = np.empty((n + 1, 2))
    force = np.empty((n + 1, 2))
    tension = np.empty(n)
    seg_len = np.empty(n)
    seg_dir = np.empty((n, 2))
    nodes_kernel(y, prm, pos, vel)
    tether_loads(pos, vel, t, prm, wpar, wt, turb, rho_tab, force, tension, seg_len, seg_dir)
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
    jmin = 0
    for j in range(n):
        tmax = max(tmax, tension[j])
        if tension[j] < tmin:
            tmin = tension[j]
            jmin = j
    diag[20] = jmin + 1
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
        ux, uz, _dux, _duz, axw, azw = wind_point(t, pos[n, 0], z, wpar, wt, turb)
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
            fx += kf * axw
            fz += kf * azw
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
        diag[19] = axw
        return
    # ---- rigid hull ---------------------------------------------------------------------
    zo = y[b + 1]
    th = y[b + 2]
    u = y[b + 3]
    w = y[b + 4]
    q = y[b + 5]
    c = math.cos(th)
    s = math.sin(th)
    xo = y[b]
    rho = air_density(zo, prm, rho_tab)
    ux, uz, _dux, _duz, axw, azw = wind_point(t, xo, zo, wpar, wt, turb)
    # inputs that vary along the wind: every strip and the fins see their own wind
    spatial = wpar[W_TURB_ON] > 0.0 or (wpar[W_GUST_ON] > 0.0 and wpar[W_GUST_CONV] > 0.0)
    nwz_st = np.empty(N_STATIONS)
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
        fx -= q0 * table_lookup(tab, T_A_INV, alpha, al0, dal)
        fz -= q0 * table_lookup(tab, T_N_INV, alpha, al0, dal)
        mm += q0 * table_lookup(tab, T_M_INV, alpha, al0, dal)
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
        fx -= q0 * cd * table_lookup(tab, T_A_AX, alpha, al0, dal)
    if prm[P_AERO_CF] > 0.0:
        kc = 0.5 * rho * prm[P_CDC]
        ns = strips.shape[1]
        x_hi = strips[0, 0]
        x_lo = strips[0, 0]
        for k in range(ns):
            x_hi = max(x_hi, strips[0, k])
            x_lo = min(x_lo, strips[0, k])
        dxs = (x_hi - x_lo) / (N_STATIONS - 1)
        if spatial:
            # body-z wind at N_STATIONS points along the hull, linear in between (the strips are
            # 0.3 m apart; the stations ~2 m, a quarter of a 1 Hz wavelength at 10 m/s)
            for j in range(N_STATIONS):
                xj = x_lo + j * dxs
                wsx, wsz, _d1, _d2, _a1, _a2 = wind_point(t, xo - c * xj, zo + s * xj, wpar, wt,
                                                          turb)
                nwz_st[j] = -s * wsx - c * wsz
        for k in range(ns):
            xk = strips[0, k]
            if spatial:
                sj = min(max((xk - x_lo) / dxs, 0.0), N_STATIONS - 1.0)
                j0 = min(int(sj), N_STATIONS - 2)
                fj = sj - j0
                wl = w - (nwz_st[j0] * (1.0 - fj) + nwz_st[j0 + 1] * fj) - q * xk
            else:
                wl = wr - q * xk
            dn = kc * strips[1, k] * wl * abs(wl)
            fz -= dn
            mm += xk * dn
    af = 0.0
    fin_l = 0.0
    xf = prm[P_XF]
    zf = prm[P_ZF]
    if prm[P_AERO_FIN] > 0.0:
        if spatial:
            wfx, wfz, _d1, _d2, _a1, _a2 = wind_point(t, xo - c * xf - s * zf,
                                                      zo + s * xf - c * zf, wpar, wt, turb)
            uf = u + c * wfx - s * wfz + q * zf
            wf = w + s * wfx + c * wfz - q * xf
        else:
            uf = ur + q * zf
            wf = wr - q * xf
        af = math.atan2(wf, uf)
        qf = 0.5 * rho * (uf * uf + wf * wf)
        fin_l = qf * table_lookup(tab, T_FIN_L, af, al0, dal)
        fin_d = qf * table_lookup(tab, T_FIN_D, af, al0, dal)
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
    # unsteady-wind inertia: M_A nu_w_dot + rho V a_w, a_w = fluid acceleration DU/Dt
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


@njit(cache=True)
def check_kernel(t, y, data, diag):  # pragma: no cover - numba
    """0 if the state is physical, else a ``STATUS`` code: 3 non-finite, 4 pitch beyond the
    hull's limit, 5 below the winch level (ground not modelled). A reversed relative wind is
    inside the aerodynamic model (tables over +-180 deg) and a slack tether carries no
    compression, so neither stops a run."""
    prm = data[0]
    if prm[P_MODE] == 2.0:
        return check6_kernel(t, y, data, diag)
    for i in range(y.size):
        if not math.isfinite(y[i]):
            return 3
    n = int(prm[P_NSEG])
    for i in range(1, n):
        if y[4 * (i - 1) + 1] < -1.0:
            return 5
    b = 4 * (n - 1)
    if prm[P_MODE] > 0.0:
        if abs(y[b + 2]) > prm[P_THETA_MAX]:
            return 4
        if diag[10] < 0.0:
            return 5
    elif y[b + 1] < 0.0:
        return 5
    return 0


#: The kernels, and the diagnostics they write (defined once in :mod:`.layout`, shared with the
#: 6-DOF kernel; re-exported here, where the 3-DOF code has always read them).
__all__ = ["DIAG_NAMES", "ND", "check_kernel", "nodes_kernel", "rhs_kernel"]
