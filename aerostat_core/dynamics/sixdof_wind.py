"""3-D wind kernels of the 6-DOF model (docs/dynamics.md §7.3): the 3-DOF wind turned to an
azimuth, veering with height, stepping in direction, with a crosswind gust and the lateral Dryden
component read from rows appended to the turbulence table."""

from __future__ import annotations

import math

from numba import njit

from aerostat_core.dynamics.sixdof_layout import (
    Q_AZ,
    Q_DIR_STEP,
    Q_DIR_T0,
    Q_DIR_TR,
    Q_GV_AMP,
    Q_GV_CONV,
    Q_GV_T0,
    Q_GV_TR,
    Q_TV_ON,
    Q_VEER,
    Q_VEER_Z,
)
from aerostat_core.dynamics.wind import (
    W_TURB_NL,
    W_TURB_ON,
    W_UC,
    W_XREF,
    frozen_weights,
    hermite,
    wind_point,
)


@njit(cache=True)
def cosine_pulse(t, t0, tr, hold):  # pragma: no cover - numba
    """1 - cos pulse of rise time tr [s] from t0 [s] and its slope [1/s]: (1 - cos(pi s/tr))/2
    for s = t - t0 in [0, tr]; then back to 0 at 2 tr (``hold`` 0, MIL-F-8785C "full") or held at
    1 (``hold`` 1)."""
    s = t - t0
    if s <= 0.0:
        return 0.0, 0.0
    end = tr if hold else 2.0 * tr
    if s >= end:
        return (1.0 if hold else 0.0), 0.0
    a = math.pi * s / tr
    return 0.5 * (1.0 - math.cos(a)), 0.5 * math.pi / tr * math.sin(a)


@njit(cache=True)
def lateral_turbulence(tau, z, wpar, turb):  # pragma: no cover - numba
    """v' [m/s] and its tau-derivative of the lateral rows appended after the 4 L rows of u', w'
    (2 rows per level: v', dv'/dtau; cubic Hermite in tau, linear in z, unfaded), read as
    :func:`.wind.turbulence_at` reads u' and w'."""
    k0, k1, h00, h10, h01, h11, d00, d10, d01, d11, la, fz = frozen_weights(
        tau, z, wpar, turb.shape[1])
    r = 4 * int(wpar[W_TURB_NL]) + 2 * la
    v = hermite(turb, r, k0, k1, h00, h10, h01, h11)
    dv = hermite(turb, r, k0, k1, d00, d10, d01, d11)
    if fz > 0.0:
        r += 2
        v2 = hermite(turb, r, k0, k1, h00, h10, h01, h11)
        dv2 = hermite(turb, r, k0, k1, d00, d10, d01, d11)
        v += fz * (v2 - v)
        dv += fz * (dv2 - dv)
    return v, dv


@njit(cache=True)
def wind3(t, x, y, z, prm, wpar, wt, turb, out):  # pragma: no cover - numba
    """3-D wind at (x, y, z) [m], time t [s] (docs/dynamics.md §7.3): out = (U_x, U_y, U_z [m/s],
    DU_x/Dt, DU_y/Dt, DU_z/Dt [m/s2]).

    The along-wind speed and the vertical wind are the 3-DOF wind (:func:`.wind.wind_point`) at
    the along-wind coordinate s = x cos chi_0 + y sin chi_0; the lateral wind v_l is a 1 - cos
    crosswind gust plus the lateral Dryden turbulence, both frozen and convected along chi_0; the
    direction is chi = chi_0 + chi'(z - z_v) + Delta chi g(t) (veer with height, direction step):
    U = u_a (cos chi, sin chi, 0) + v_l (-sin chi, cos chi, 0) + (0, 0, u_z)."""
    c0 = math.cos(prm[Q_AZ])
    s0 = math.sin(prm[Q_AZ])
    sa = x * c0 + y * s0
    ua, uz, _d1, _d2, aa, az = wind_point(t, sa, z, wpar, wt, turb)
    vl = 0.0
    al = 0.0
    tau = t - (sa - wpar[W_XREF]) / wpar[W_UC]
    if prm[Q_GV_AMP] != 0.0:
        tg = tau if prm[Q_GV_CONV] > 0.0 else t
        g, dg = cosine_pulse(tg, prm[Q_GV_T0], prm[Q_GV_TR], 0)
        vl += prm[Q_GV_AMP] * g
        if prm[Q_GV_CONV] == 0.0:
            al += prm[Q_GV_AMP] * dg
    if prm[Q_TV_ON] > 0.0 and wpar[W_TURB_ON] > 0.0:
        v, _dv = lateral_turbulence(tau, z, wpar, turb)
        vl += wt[2] * v
        al += wt[3] * v
    chi = prm[Q_AZ] + prm[Q_VEER] * (z - prm[Q_VEER_Z])
    dchi = 0.0
    if prm[Q_DIR_STEP] != 0.0:
        g, dg = cosine_pulse(t, prm[Q_DIR_T0], prm[Q_DIR_TR], 1)
        chi += prm[Q_DIR_STEP] * g
        dchi = prm[Q_DIR_STEP] * dg
    c = math.cos(chi)
    s = math.sin(chi)
    out[0] = ua * c - vl * s
    out[1] = ua * s + vl * c
    out[2] = uz
    out[3] = aa * c - al * s - dchi * (ua * s + vl * c)
    out[4] = aa * s + al * c + dchi * (ua * c - vl * s)
    out[5] = az
