"""Numba kernels of the 6-DOF tethered-aerostat model (docs/dynamics.md §7).

States (mode 2 of the parameter vector). Tether nodes 1..N-1: (x, y, z, v_x, v_y, v_z) each, node
after node (earth axes: x along the reference wind direction, z up, y = z x x... completing the
right-handed set, origin at the winch). Then the hull: position of the centre of volume O (3),
attitude quaternion (q0, q1, q2, q3) (4), body velocity of O (u, v, w) (3), body rates (p, q, r)
(3): 13 states.

Frames. Body B: x_B to the nose, y_B to starboard, z_B to the belly. The quaternion gives the
attitude of B relative to the "upwind NED" frame N' (x' against the reference wind, y' = y_E,
z' down), so R_EB = R_0 R(q) with R_0 = diag(-1, 1, -1); with q = (cos th/2, 0, sin th/2, 0) this
is the 3-DOF model's R_EB (pitch th nose-up). Roll, pitch and yaw are the aerospace Euler angles
of R(q).

Equations (Newton-Euler about O with the CG offset, Kirchhoff added mass with a current, Fossen's
relative-velocity form; the 3-DOF model's equations are their x-z restriction)::

    (M_RB + M_A) nu_dot = f_RB + f_AM + f_wind + f_aero + f_gb + f_teth
    M_RB = [[m 1, -m S(r_g)], [m S(r_g), I_O]]      M_A = diag(m_x, m_z, m_z, 0, I_a, I_a)
    f_RB = -[m (w x v + w x (w x r_g)), w x I_O w + m r_g x (w x v)]
    f_AM = -[w x M_l v_r, w x I_A w + k v_r x M_l v_r]  (k = 1 only in "kirchhoff" mode)
    f_wind = M_A (nu_w_dot, 0) + rho V (a_w, 0),   nu_w_dot = a_w - w x nu_w

Aerodynamics: the hull is axisymmetric, so its inviscid (J&D) and axial terms are the 3-DOF
tables at the total incidence alpha_t = atan2(sqrt(v_r^2 + w_r^2), u_r) in the plane of the
cross-flow; the cross-flow strips take the local cross-flow vector (v_r + r x_k, w_r - q x_k) and
drag 1/2 rho C_dc 2r dx |v_c| v_c (cross-flow principle); the fins take the local velocity at
their aerodynamic centre, split into the pitch plane (the 3-DOF fin tables of the horizontal
projected area) and the yaw plane (the same tables scaled by the vertical projected area of the
fin layout, without the zero-lift drag counted twice), plus the roll damping of the fin panels.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from aerostat_core.dynamics.layout import (
    DIAG_NAMES,
    N_STATIONS,
    P_AERO_AX,
    P_AERO_CF,
    P_AERO_FIN,
    P_AERO_INV,
    P_AL0,
    P_CD,
    P_CDC,
    P_CDN,
    P_CDT,
    P_D,
    P_DAL,
    P_DV,
    P_EA,
    P_G,
    P_HM,
    P_HV,
    P_KIRCHHOFF,
    P_MT,
    P_MX,
    P_MZ,
    P_NSEG,
    P_TBUOY,
    P_TDRAG,
    P_TPUSH,
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
from aerostat_core.dynamics.sixdof_layout import (
    Q_AZ,
    Q_BREAK_T,
    Q_FIN_CD0,
    Q_FIN_KP,
    Q_FIN_SIDE,
    Q_GV_AMP,
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
    Q_YA,
    Q_ZW,
)
from aerostat_core.dynamics.sixdof_wind import wind3
from aerostat_core.dynamics.tether import air_density
from aerostat_core.dynamics.wind import (
    NT,
    W_GUST_CONV,
    W_GUST_ON,
    W_TURB_ON,
    wind_time_terms,
)

#: Diagnostics of the 6-DOF kernel: the 3-DOF names first (same meaning, in the vertical plane of
#: the reference wind where it applies), then the lateral ones.
DIAG6_NAMES = DIAG_NAMES + (
    "beta",  # sideslip at O, asin(v_r/V) [rad]
    "wind_y",  # wind at O [m/s]
    "tension_top_y", "tension_winch_y",  # [N]
    "y_top", "vy_top",  # confluence point [m, m/s]
    "vy_body",  # velocity of O [m/s]
    "tension_top", "tension_winch",  # magnitudes [N]
    "tether_length",  # unstretched length [m]
    "beta_fin",  # sideslip at the fins [rad]
    "fin_side",  # fin side force [N]
    "aero_roll", "aero_yaw",  # aerodynamic moments about O (body x, z) [N m]
    "aero_side",  # aerodynamic side force (body y) [N]
    "broken",  # 1 after the tether broke
)
ND6 = len(DIAG6_NAMES)
#: Status codes of the 6-DOF checks (beside the integrator's).
STATUS6 = {
    11: "a tether node went below the winch level: the tether would pass through the ground",
    12: "the hull's confluence point went below the winch: the aerostat hit the ground",
}


@njit(cache=True)
def tether_length_at(t, prm):  # pragma: no cover - numba
    """Unstretched tether length [m] and its rate [m/s] at time t (reel-in/out schedule).

    L(t) = L_0 + int_0^t v(s) ds with v a (1 - cos) ramp up to the reel speed from t_0 over
    t_r, held, and ramped down from t_1 over t_r (closed form)."""
    l0 = prm[Q_LEN0]
    vs = prm[Q_REEL_SPEED]
    if vs == 0.0:
        return l0, 0.0
    t0 = prm[Q_REEL_T0]
    tr = max(prm[Q_REEL_RAMP], 1e-6)
    t1 = max(prm[Q_REEL_T1], t0 + tr)
    # integral of the ramp-up from t0, f(s) = (1 - cos(pi s/tr))/2 on [0, tr]
    ln = l0
    v = 0.0
    if t > t0:
        s = min(t - t0, tr)
        ln += vs * 0.5 * (s - tr / math.pi * math.sin(math.pi * s / tr))
        if t - t0 < tr:
            v = vs * 0.5 * (1.0 - math.cos(math.pi * s / tr))
        else:
            v = vs
        if t > t0 + tr:
            ln += vs * (min(t, t1) - (t0 + tr))
    if t > t1:
        s = min(t - t1, tr)
        ln += vs * (s - 0.5 * (s - tr / math.pi * math.sin(math.pi * s / tr)))
        if t - t1 < tr:
            v = vs * 0.5 * (1.0 + math.cos(math.pi * s / tr))
        else:
            v = 0.0
    return ln, v


@njit(cache=True)
def rotation(y, b, rot):  # pragma: no cover - numba
    """R_EB (3x3, body -> earth) from the normalised quaternion at y[b+3:b+7]."""
    q0 = y[b + 3]
    q1 = y[b + 4]
    q2 = y[b + 5]
    q3 = y[b + 6]
    nq = math.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    q0 /= nq
    q1 /= nq
    q2 /= nq
    q3 /= nq
    # R(q) body -> N', then R_0 = diag(-1, 1, -1)
    rot[0, 0] = -(1.0 - 2.0 * (q2 * q2 + q3 * q3))
    rot[0, 1] = -(2.0 * (q1 * q2 - q0 * q3))
    rot[0, 2] = -(2.0 * (q1 * q3 + q0 * q2))
    rot[1, 0] = 2.0 * (q1 * q2 + q0 * q3)
    rot[1, 1] = 1.0 - 2.0 * (q1 * q1 + q3 * q3)
    rot[1, 2] = 2.0 * (q2 * q3 - q0 * q1)
    rot[2, 0] = -(2.0 * (q1 * q3 - q0 * q2))
    rot[2, 1] = -(2.0 * (q2 * q3 + q0 * q1))
    rot[2, 2] = -(1.0 - 2.0 * (q1 * q1 + q2 * q2))


@njit(cache=True)
def nodes6_kernel(y, prm, pos, vel, rot):  # pragma: no cover - numba
    """Node positions/velocities (N+1, 3) from a 6-DOF state (winch, free nodes, C) and R_EB."""
    n = int(prm[P_NSEG])
    pos[0, 0] = prm[P_XA]
    pos[0, 1] = prm[Q_YA]
    pos[0, 2] = prm[P_ZA]
    for k in range(3):
        vel[0, k] = 0.0
    for i in range(1, n):
        k = 6 * (i - 1)
        for j in range(3):
            pos[i, j] = y[k + j]
            vel[i, j] = y[k + 3 + j]
    b = 6 * (n - 1)
    rotation(y, b, rot)
    xc = prm[P_XC]
    zc = prm[P_ZC]
    u = y[b + 7]
    v = y[b + 8]
    w = y[b + 9]
    p = y[b + 10]
    q = y[b + 11]
    r = y[b + 12]
    # velocity of C in body axes: v + omega x r_C, r_C = (xc, 0, zc)
    vcx = u + q * zc
    vcy = v + r * xc - p * zc
    vcz = w - q * xc
    for j in range(3):
        pos[n, j] = y[b + j] + rot[j, 0] * xc + rot[j, 2] * zc
        vel[n, j] = rot[j, 0] * vcx + rot[j, 1] * vcy + rot[j, 2] * vcz


@njit(cache=True)
def tether3_loads(pos, vel, t_now, l0, prm, wpar, wt, turb, rho_tab, force, tension, seg_dir,
                  broken):  # pragma: no cover - numba
    """Forces on the nodes of the 3-D lumped-mass tether: the 2-D model of :mod:`.tether` in
    three dimensions (tension, weight and air buoyancy, drag by the cross-flow principle on the
    relative wind split along the node tangent). ``l0``: unstretched segment length [m];
    ``broken``: the top segment carries nothing. Fills force (N+1, 3), tension (N,), seg_dir."""
    n = int(prm[P_NSEG])
    ea = prm[P_EA]
    g = prm[P_G]
    w = prm[P_W]
    d = prm[P_D]
    area = 0.25 * math.pi * d * d
    no_push = prm[P_TPUSH] == 0.0
    # c = zeta l0 sqrt(EA w): c/l0 does not depend on l0 (prm[P_CD] holds it)
    cdamp = prm[P_CD]
    for i in range(n + 1):
        for k in range(3):
            force[i, k] = 0.0
    for j in range(n):
        dx = pos[j + 1, 0] - pos[j, 0]
        dy = pos[j + 1, 1] - pos[j, 1]
        dz = pos[j + 1, 2] - pos[j, 2]
        ll = math.sqrt(dx * dx + dy * dy + dz * dz)
        ex = dx / ll
        ey = dy / ll
        ez = dz / ll
        seg_dir[j, 0] = ex
        seg_dir[j, 1] = ey
        seg_dir[j, 2] = ez
        if broken and j == n - 1:
            tension[j] = 0.0
            continue
        ldot = (ex * (vel[j + 1, 0] - vel[j, 0]) + ey * (vel[j + 1, 1] - vel[j, 1])
                + ez * (vel[j + 1, 2] - vel[j, 2]))
        tt = cdamp * ldot
        if ll > l0:
            tt += ea * (ll / l0 - 1.0)
        if tt < 0.0 and no_push:
            tt = 0.0
        tension[j] = tt
        force[j, 0] += tt * ex
        force[j, 1] += tt * ey
        force[j, 2] += tt * ez
        force[j + 1, 0] -= tt * ex
        force[j + 1, 1] -= tt * ey
        force[j + 1, 2] -= tt * ez
    do_drag = prm[P_TDRAG] > 0.0
    buoy = prm[P_TBUOY] > 0.0
    cdn = prm[P_CDN]
    cdt = prm[P_CDT] * math.pi
    wv = np.empty(6)
    for i in range(n + 1):
        z = pos[i, 2]
        rho = air_density(z, prm, rho_tab)
        lw = l0 if (i > 0 and i < n) else 0.5 * l0
        if broken and i == n:
            continue  # the top half segment went with the hull: see the hull's mass
        wl = w
        if buoy:
            wl = w - rho * area
        force[i, 2] -= wl * g * lw
        if do_drag:
            if i == 0:
                tx, ty, tz = seg_dir[0, 0], seg_dir[0, 1], seg_dir[0, 2]
            elif i == n:
                tx, ty, tz = seg_dir[n - 1, 0], seg_dir[n - 1, 1], seg_dir[n - 1, 2]
            else:
                tx = pos[i + 1, 0] - pos[i - 1, 0]
                ty = pos[i + 1, 1] - pos[i - 1, 1]
                tz = pos[i + 1, 2] - pos[i - 1, 2]
                tn = math.sqrt(tx * tx + ty * ty + tz * tz)
                tx /= tn
                ty /= tn
                tz /= tn
            wind3(t_now, pos[i, 0], pos[i, 1], z, prm, wpar, wt, turb, wv)
            ux = wv[0] - vel[i, 0]
            uy = wv[1] - vel[i, 1]
            uz = wv[2] - vel[i, 2]
            vq = ux * tx + uy * ty + uz * tz
            qx = vq * tx
            qy = vq * ty
            qz = vq * tz
            px = ux - qx
            py = uy - qy
            pz = uz - qz
            vp = math.sqrt(px * px + py * py + pz * pz)
            k = 0.5 * rho * d * lw
            force[i, 0] += k * (cdn * vp * px + cdt * abs(vq) * qx)
            force[i, 1] += k * (cdn * vp * py + cdt * abs(vq) * qy)
            force[i, 2] += k * (cdn * vp * pz + cdt * abs(vq) * qz)


@njit(cache=True)
def _cross(a0, a1, a2, b0, b1, b2):  # pragma: no cover - numba
    return a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0


@njit(cache=True)
def rhs6_kernel(t, y, dy, data, diag):  # pragma: no cover - numba
    """Right-hand side of the 6-DOF model (module docstring); ``data`` as the 3-DOF kernel's
    (prm, wpar, sched, turb, tab, strips, rho_tab, cdv). Writes the first ``diag.size`` entries of
    ``DIAG6_NAMES``."""
    prm, wpar, sched, turb, tab, strips, rho_tab, cdv = data
    dg = np.zeros(ND6)
    wt = np.empty(NT)
    wind_time_terms(t, wpar, sched, wt)
    n = int(prm[P_NSEG])
    broken = t >= prm[Q_BREAK_T]
    length, _ldot = tether_length_at(t, prm)
    l0 = length / n
    pos = np.empty((n + 1, 3))
    vel = np.empty((n + 1, 3))
    rot = np.empty((3, 3))
    force = np.empty((n + 1, 3))
    tension = np.empty(n)
    seg_dir = np.empty((n, 3))
    nodes6_kernel(y, prm, pos, vel, rot)
    tether3_loads(pos, vel, t, l0, prm, wpar, wt, turb, rho_tab, force, tension, seg_dir, broken)
    m_node = prm[P_W] * l0
    zw = prm[Q_ZW]
    for i in range(1, n):
        k = 6 * (i - 1)
        fz_ground = 0.0
        fx_ground = 0.0
        fy_ground = 0.0
        if broken and pos[i, 2] < zw:
            # the fallen line lies on the ground: a stiff, critically damped contact
            om = 2.0 * math.pi * 2.0
            fz_ground = m_node * (om * om * (zw - pos[i, 2]) - 2.0 * om * vel[i, 2])
            fx_ground = -m_node * 2.0 * om * vel[i, 0]
            fy_ground = -m_node * 2.0 * om * vel[i, 1]
        for j in range(3):
            dy[k + j] = vel[i, j]
        dy[k + 3] = (force[i, 0] + fx_ground) / m_node
        dy[k + 4] = (force[i, 1] + fy_ground) / m_node
        dy[k + 5] = (force[i, 2] + fz_ground) / m_node
    tmax = tension[0]
    tmin = tension[0]
    jmin = 0
    for j in range(n):
        if broken and j == n - 1:
            continue
        tmax = max(tmax, tension[j])
        if tension[j] < tmin:
            tmin = tension[j]
            jmin = j
    b = 6 * (n - 1)
    g = prm[P_G]
    # ---- hull kinematics -------------------------------------------------------------------
    u = y[b + 7]
    v = y[b + 8]
    w = y[b + 9]
    p = y[b + 10]
    q = y[b + 11]
    r = y[b + 12]
    xo = y[b]
    yo = y[b + 1]
    zo = y[b + 2]
    rho = air_density(zo, prm, rho_tab)
    wv = np.empty(6)
    wind3(t, xo, yo, zo, prm, wpar, wt, turb, wv)
    # wind and fluid acceleration in body axes (R^T U)
    nwx = rot[0, 0] * wv[0] + rot[1, 0] * wv[1] + rot[2, 0] * wv[2]
    nwy = rot[0, 1] * wv[0] + rot[1, 1] * wv[1] + rot[2, 1] * wv[2]
    nwz = rot[0, 2] * wv[0] + rot[1, 2] * wv[1] + rot[2, 2] * wv[2]
    awx = rot[0, 0] * wv[3] + rot[1, 0] * wv[4] + rot[2, 0] * wv[5]
    awy = rot[0, 1] * wv[3] + rot[1, 1] * wv[4] + rot[2, 1] * wv[5]
    awz = rot[0, 2] * wv[3] + rot[1, 2] * wv[4] + rot[2, 2] * wv[5]
    ur = u - nwx
    vr = v - nwy
    wr = w - nwz
    vc2 = vr * vr + wr * wr
    vcn = math.sqrt(vc2)
    vt2 = ur * ur + vc2
    vt = math.sqrt(vt2)
    alpha_t = math.atan2(vcn, ur)  # total incidence [0, pi]
    if vcn > 1e-12:
        ecy = vr / vcn
        ecz = wr / vcn
    else:
        ecy = 0.0
        ecz = 1.0
    q0d = 0.5 * rho * vt2
    al0 = prm[P_AL0]
    dal = prm[P_DAL]
    fx = 0.0
    fy = 0.0
    fz = 0.0
    mx = 0.0
    my = 0.0
    mz = 0.0
    if prm[P_AERO_INV] > 0.0:
        nrm = q0d * table_lookup(tab, T_N_INV, alpha_t, al0, dal)
        fx -= q0d * table_lookup(tab, T_A_INV, alpha_t, al0, dal)
        fy -= nrm * ecy
        fz -= nrm * ecz
        mi = q0d * table_lookup(tab, T_M_INV, alpha_t, al0, dal)
        # moment -T_M (x_B x e_c): x_B x (0, ecy, ecz) = (0, -ecz, ecy)
        my += mi * ecz
        mz -= mi * ecy
    if prm[P_AERO_AX] > 0.0:
        cd = cdv[0]
        if cdv.shape[0] > 1:
            sv = (vt - prm[P_V0]) / prm[P_DV]
            if sv <= 0.0:
                cd = cdv[0]
            elif sv >= cdv.shape[0] - 1:
                cd = cdv[cdv.shape[0] - 1]
            else:
                kv = int(sv)
                fv = sv - kv
                cd = cdv[kv] * (1.0 - fv) + cdv[kv + 1] * fv
        fx -= q0d * cd * table_lookup(tab, T_A_AX, alpha_t, al0, dal)
    # inputs that vary along the wind: the strips and the fins see their own wind (as 3-DOF)
    spatial = (wpar[W_TURB_ON] > 0.0 or (wpar[W_GUST_ON] > 0.0 and wpar[W_GUST_CONV] > 0.0)
               or prm[Q_GV_AMP] != 0.0)
    ns = strips.shape[1]
    x_hi = strips[0, 0]
    x_lo = strips[0, 0]
    for k in range(ns):
        x_hi = max(x_hi, strips[0, k])
        x_lo = min(x_lo, strips[0, k])
    dxs = (x_hi - x_lo) / (N_STATIONS - 1)
    nwy_st = np.empty(N_STATIONS)
    nwz_st = np.empty(N_STATIONS)
    ws = np.empty(6)
    if spatial and prm[P_AERO_CF] > 0.0:
        for j in range(N_STATIONS):
            xj = x_lo + j * dxs
            wind3(t, xo + rot[0, 0] * xj, yo + rot[1, 0] * xj, zo + rot[2, 0] * xj, prm, wpar,
                  wt, turb, ws)
            nwy_st[j] = rot[0, 1] * ws[0] + rot[1, 1] * ws[1] + rot[2, 1] * ws[2]
            nwz_st[j] = rot[0, 2] * ws[0] + rot[1, 2] * ws[1] + rot[2, 2] * ws[2]
    if prm[P_AERO_CF] > 0.0:
        kc = 0.5 * rho * prm[P_CDC]
        for k in range(ns):
            xk = strips[0, k]
            if spatial:
                sj = min(max((xk - x_lo) / dxs, 0.0), N_STATIONS - 1.0)
                j0 = min(int(sj), N_STATIONS - 2)
                fj = sj - j0
                vl = v - (nwy_st[j0] * (1.0 - fj) + nwy_st[j0 + 1] * fj) + r * xk
                wl = w - (nwz_st[j0] * (1.0 - fj) + nwz_st[j0 + 1] * fj) - q * xk
            else:
                vl = vr + r * xk
                wl = wr - q * xk
            sp = math.sqrt(vl * vl + wl * wl)
            dn = kc * strips[1, k] * sp
            fy -= dn * vl
            fz -= dn * wl
            my += xk * dn * wl
            mz -= xk * dn * vl
    xf = prm[P_XF]
    zf = prm[P_ZF]
    af = 0.0
    bf = 0.0
    fin_l = 0.0
    fin_s = 0.0
    if prm[P_AERO_FIN] > 0.0:
        if spatial:
            wind3(t, xo + rot[0, 0] * xf + rot[0, 2] * zf, yo + rot[1, 0] * xf + rot[1, 2] * zf,
                  zo + rot[2, 0] * xf + rot[2, 2] * zf, prm, wpar, wt, turb, ws)
            uf = u - (rot[0, 0] * ws[0] + rot[1, 0] * ws[1] + rot[2, 0] * ws[2]) + q * zf
            vf = v - (rot[0, 1] * ws[0] + rot[1, 1] * ws[1] + rot[2, 1] * ws[2]) + r * xf - p * zf
            wf = w - (rot[0, 2] * ws[0] + rot[1, 2] * ws[1] + rot[2, 2] * ws[2]) - q * xf
        else:
            uf = ur + q * zf
            vf = vr + r * xf - p * zf
            wf = wr - q * xf
        # pitch plane: the 3-DOF fin tables
        af = math.atan2(wf, uf)
        qf = 0.5 * rho * (uf * uf + wf * wf)
        fin_l = qf * table_lookup(tab, T_FIN_L, af, al0, dal)
        fin_d = qf * table_lookup(tab, T_FIN_D, af, al0, dal)
        ca = math.cos(af)
        sa = math.sin(af)
        nf = fin_l * ca + fin_d * sa
        a_f = fin_d * ca - fin_l * sa
        ffx = -a_f
        ffz = -nf
        # yaw plane: the same tables scaled to the vertical projected area, zero-lift drag once
        bf = math.atan2(vf, uf)
        qs = 0.5 * rho * (uf * uf + vf * vf)
        ks = prm[Q_FIN_SIDE]
        fin_s = ks * qs * table_lookup(tab, T_FIN_L, bf, al0, dal)
        fin_ds = ks * qs * (table_lookup(tab, T_FIN_D, bf, al0, dal) - prm[Q_FIN_CD0])
        cb = math.cos(bf)
        sb = math.sin(bf)
        ns = fin_s * cb + fin_ds * sb
        a_s = fin_ds * cb - fin_s * sb
        ffx -= a_s
        ffy = -ns
        fx += ffx
        fy += ffy
        fz += ffz
        cx, cy, cz = _cross(xf, 0.0, zf, ffx, ffy, ffz)
        mx += cx
        my += cy
        mz += cz
        # roll damping of the fin panels
        mx -= rho * abs(uf) * prm[Q_FIN_KP] * p
    m_roll = mx
    f_side = fy
    m_pitch = my
    m_yaw = mz
    # ---- gravity and buoyancy: earth down in body axes = -(third row of R_EB) --------------
    dbx = -rot[2, 0]
    dby = -rot[2, 1]
    dbz = -rot[2, 2]
    hm = prm[P_HM]
    vol = prm[P_HV]
    kgb = (hm - rho * vol) * g
    fx += kgb * dbx
    fy += kgb * dby
    fz += kgb * dbz
    cx, cy, cz = _cross(prm[P_XG], 0.0, prm[P_ZG], hm * g * dbx, hm * g * dby, hm * g * dbz)
    mx += cx
    my += cy
    mz += cz
    # ---- tether at C ----------------------------------------------------------------------
    if not broken:
        tbx = rot[0, 0] * force[n, 0] + rot[1, 0] * force[n, 1] + rot[2, 0] * force[n, 2]
        tby = rot[0, 1] * force[n, 0] + rot[1, 1] * force[n, 1] + rot[2, 1] * force[n, 2]
        tbz = rot[0, 2] * force[n, 0] + rot[1, 2] * force[n, 1] + rot[2, 2] * force[n, 2]
        fx += tbx
        fy += tby
        fz += tbz
        cx, cy, cz = _cross(prm[P_XC], 0.0, prm[P_ZC], tbx, tby, tbz)
        mx += cx
        my += cy
        mz += cz
    else:
        # the half segment at C stays with the hull (it is in the mass matrix): its weight
        wtop = 0.5 * prm[P_W] * l0 * g
        fx += wtop * dbx
        fy += wtop * dby
        fz += wtop * dbz
        cx, cy, cz = _cross(prm[P_XC], 0.0, prm[P_ZC], wtop * dbx, wtop * dby, wtop * dbz)
        mx += cx
        my += cy
        mz += cz
    # ---- rigid-body terms about O ---------------------------------------------------------
    mt = prm[P_MT]
    xgt = prm[P_XGT]
    zgt = prm[P_ZGT]
    wvx, wvy, wvz = _cross(p, q, r, u, v, w)  # omega x v
    wgx, wgy, wgz = _cross(p, q, r, xgt, 0.0, zgt)  # omega x r_g
    wwx, wwy, wwz = _cross(p, q, r, wgx, wgy, wgz)
    fx -= mt * (wvx + wwx)
    fy -= mt * (wvy + wwy)
    fz -= mt * (wvz + wwz)
    io = prm[Q_IO:Q_IO + 9]
    hx = io[0] * p + io[1] * q + io[2] * r
    hy = io[3] * p + io[4] * q + io[5] * r
    hz = io[6] * p + io[7] * q + io[8] * r
    cx, cy, cz = _cross(p, q, r, hx, hy, hz)
    mx -= cx
    my -= cy
    mz -= cz
    cx, cy, cz = _cross(xgt, 0.0, zgt, wvx, wvy, wvz)
    mx -= mt * cx
    my -= mt * cy
    mz -= mt * cz
    # ---- added mass with a current (Kirchhoff) ---------------------------------------------
    m_x = prm[P_MX]
    m_y = prm[Q_MY]
    m_z = prm[P_MZ]
    i_ax = prm[Q_IAX]
    i_a = prm[Q_IA]
    cx, cy, cz = _cross(p, q, r, m_x * ur, m_y * vr, m_z * wr)
    fx -= cx
    fy -= cy
    fz -= cz
    cx, cy, cz = _cross(p, q, r, i_ax * p, i_a * q, i_a * r)
    mx -= cx
    my -= cy
    mz -= cz
    if prm[P_KIRCHHOFF] > 0.0:
        cx, cy, cz = _cross(ur, vr, wr, m_x * ur, m_y * vr, m_z * wr)
        mx -= cx
        my -= cy
        mz -= cz
    if prm[P_UNSTEADY] > 0.0:
        ox, oy, oz = _cross(p, q, r, nwx, nwy, nwz)
        fx += m_x * (awx - ox) + rho * vol * awx
        fy += m_y * (awy - oy) + rho * vol * awy
        fz += m_z * (awz - oz) + rho * vol * awz
    # ---- accelerations --------------------------------------------------------------------
    f6 = (fx, fy, fz, mx, my, mz)
    for i in range(6):
        s = 0.0
        for j in range(6):
            s += prm[Q_MINV + 6 * i + j] * f6[j]
        dy[b + 7 + i] = s
    for j in range(3):
        dy[b + j] = rot[j, 0] * u + rot[j, 1] * v + rot[j, 2] * w
    q0 = y[b + 3]
    q1 = y[b + 4]
    q2 = y[b + 5]
    q3 = y[b + 6]
    kq = prm[Q_QSTAB] * (1.0 - (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3))
    dy[b + 3] = 0.5 * (-q1 * p - q2 * q - q3 * r) + kq * q0
    dy[b + 4] = 0.5 * (q0 * p + q2 * r - q3 * q) + kq * q1
    dy[b + 5] = 0.5 * (q0 * q + q3 * p - q1 * r) + kq * q2
    dy[b + 6] = 0.5 * (q0 * r + q1 * q - q2 * p) + kq * q3
    # ---- diagnostics ----------------------------------------------------------------------
    c0 = math.cos(prm[Q_AZ])
    s0 = math.sin(prm[Q_AZ])
    vex = dy[b]
    vey = dy[b + 1]
    dg[0] = math.atan2(wr, ur)
    dg[1] = vt
    dg[2] = wv[0] * c0 + wv[1] * s0
    dg[3] = wv[2]
    ttx = 0.0 if broken else -force[n, 0]
    tty = 0.0 if broken else -force[n, 1]
    ttz = 0.0 if broken else -force[n, 2]
    dg[4] = ttx * c0 + tty * s0
    dg[5] = ttz
    dg[6] = force[0, 0] * c0 + force[0, 1] * s0
    dg[7] = force[0, 2]
    dg[8] = tmax
    dg[9] = pos[n, 0] * c0 + pos[n, 1] * s0
    dg[10] = pos[n, 2]
    dg[11] = vel[n, 0] * c0 + vel[n, 1] * s0
    dg[12] = vel[n, 2]
    dg[13] = vex * c0 + vey * s0
    dg[14] = dy[b + 2]
    dg[15] = af
    dg[16] = fin_l
    dg[17] = m_pitch
    dg[18] = tmin
    dg[19] = wv[3] * c0 + wv[4] * s0
    dg[20] = jmin + 1
    dg[21] = math.asin(max(-1.0, min(1.0, vr / vt))) if vt > 0.0 else 0.0
    dg[22] = -wv[0] * s0 + wv[1] * c0
    dg[23] = -ttx * s0 + tty * c0
    dg[24] = -force[0, 0] * s0 + force[0, 1] * c0
    dg[25] = -pos[n, 0] * s0 + pos[n, 1] * c0
    dg[26] = -vel[n, 0] * s0 + vel[n, 1] * c0
    dg[27] = -vex * s0 + vey * c0
    dg[28] = math.sqrt(ttx * ttx + tty * tty + ttz * ttz)
    dg[29] = math.sqrt(force[0, 0] ** 2 + force[0, 1] ** 2 + force[0, 2] ** 2)
    dg[30] = length
    dg[31] = bf
    dg[32] = fin_s
    dg[33] = m_roll
    dg[34] = m_yaw
    dg[35] = f_side
    dg[36] = 1.0 if broken else 0.0
    for k in range(min(diag.size, ND6)):
        diag[k] = dg[k]


@njit(cache=True)
def check6_kernel(t, y, data, diag):  # pragma: no cover - numba
    """0 if the 6-DOF state is physical, else a status code: 3 non-finite, 11 a tether node below
    the winch level (through the ground; not checked after a break, when the line lies on the
    ground), 12 the confluence point below the winch level."""
    prm = data[0]
    for i in range(y.size):
        if not math.isfinite(y[i]):
            return 3
    n = int(prm[P_NSEG])
    zw = prm[Q_ZW]
    broken = t >= prm[Q_BREAK_T]
    if not broken:
        for i in range(1, n):
            if y[6 * (i - 1) + 2] < zw - 1.0:
                return 11
        if diag[10] < zw:
            return 12
    elif y[6 * (n - 1) + 2] < zw:
        return 12
    return 0
