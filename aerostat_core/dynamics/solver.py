"""Adaptive TR-BDF2 integrator for the stiff tethered-aerostat equations, compiled with numba.

Why this formulation (docs/dynamics.md §1.8). The tether's axial mode is 10^3-10^4 times faster than the
motions of interest (omega_ax = (2N/L) sqrt(EA/w) ~ 1400 rad/s for N = 32, EA = 1 MN, w = 20 g/m;
the surge mode has a period of ~60 s). Explicit schemes (MoorDyn's RK2 at dt = 2e-4 s) pay for
that stiffness with millions of steps; scipy's Radau/BDF with a finite-difference Jacobian pay
in Python overhead (~40 s for a 300 s case). Here:

* the right-hand side is a numba kernel; the integrator sees the model only through
  ``rhs_kernel(t, y, dy, data, diag)`` and ``check_kernel(t, y, data, diag)`` (:mod:`.kernel`):
  ``data`` and ``diag`` are opaque, no index of the aerostat model appears here;
* TR-BDF2 (Bank et al. 1985; Hosea & Shampine 1996, MATLAB's ode23tb): a one-step, L-stable,
  second-order ESDIRK with an embedded third-order error estimate. One Newton matrix
  W = I - h d J serves both implicit stages, L-stability damps the axial ringing in one step,
  and the step size follows the accuracy of the slow motions only;
* the Jacobian is banded (each node couples to its neighbours, the hull to the top node): it is
  built by finite differences with column colouring (kl + ku + 1 kernel calls, not n) and
  factorised by a banded LU with partial pivoting, all in numba; the Jacobian is reused across
  steps and refreshed only when Newton slows down, and a step that could grow by less than 20 %
  keeps its size so that the factorised Newton matrix is reused (Hairer & Wanner, Solving ODEs
  II, §IV.8);
* wind inputs are analytic in time and ramp corners are step boundaries ("stops").

Tableau (gamma = 2 - sqrt 2, d = gamma/2, w = sqrt(2)/4):
    c = (0, gamma, 1); stage 2: Y2 = y + h d (f(y) + f(Y2)) (trapezoidal to t + gamma h);
    stage 3: Y3 = y + h (w f(y) + w f(Y2) + d f(Y3)) (BDF2), y_new = Y3;
    error: W^-1 h [(4w - 1)/3 f1 - 1/3 f2 + 2d/3 f3] (Shampine's filtered estimate).
Dense output: cubic Hermite on (y_n, f_n, y_n+1, f_n+1).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

# The only two model functions the integrator calls; bound statically so numba can cache the
# compiled integrator (a function passed as an argument would be recompiled in every process).
from .kernel import ND, check_kernel, rhs_kernel

GAMMA = 2.0 - math.sqrt(2.0)
D_COEF = GAMMA / 2.0
W_COEF = math.sqrt(2.0) / 4.0
E1 = (4.0 * W_COEF - 1.0) / 3.0
E2 = -1.0 / 3.0
E3 = 2.0 * D_COEF / 3.0

# option vector layout
O_RTOL, O_HMAX, O_HMIN, O_MAXSTEPS, O_KAPPA, O_JAC_EVERY, O_MAXIT = 0, 1, 2, 3, 4, 5, 6
O_SIZE = 7
# integer statistics layout
S_STEPS, S_REJECT, S_FEVAL, S_JAC, S_LU, S_IOUT, S_STATUS, S_NFAIL = 0, 1, 2, 3, 4, 5, 6, 7
S_SIZE = 8
# float state layout (t, h, eta, jacobian age, stale flag)
F_T, F_H, F_ETA, F_AGE, F_STALE = 0, 1, 2, 3, 4
F_SIZE = 5

#: Status codes returned by the integrator and their meaning.
STATUS = {
    0: "finished",
    1: "step budget of this call used (continue)",
    2: "step size underflow: the solver cannot resolve the motion (diverging or too stiff)",
    3: "non-finite state (the simulation blew up)",
    4: "pitch beyond the model's limit: the aerostat diverged",
    5: "the aerostat or a tether node went below the winch level (ground not modelled)",
    6: "singular Newton matrix",
    # 6-DOF checks (:mod:`.sixdof_kernel`)
    11: "a tether node went below the winch level: the tether would pass through the ground",
    12: "the hull's confluence point went below the winch: the aerostat hit the ground",
}


def band_width(kl: int, ku: int) -> int:
    """Columns of the compact band storage of :func:`band_lu`: 2 kl + ku + 1."""
    return 2 * kl + ku + 1


def band_pack(a: np.ndarray, kl: int, ku: int) -> np.ndarray:
    """Compact row storage of a band matrix: w[i, j - i + kl] = a[i, j] for -kl <= j - i <= ku,
    with kl more zero columns on the right for the LU's fill-in."""
    n = a.shape[0]
    w = np.zeros((n, band_width(kl, ku)))
    for i in range(n):
        for j in range(max(0, i - kl), min(n, i + ku + 1)):
            w[i, j - i + kl] = a[i, j]
    return w


@njit(cache=True)
def band_lu(w, n, kl, ku, piv):  # pragma: no cover - numba
    """In-place LU with partial pivoting of a band matrix in compact row storage
    (:func:`band_pack`: w[i, j - i + kl] holds a[i, j]; columns beyond kl + ku, the fill-in,
    must be zero on entry). Row swaps are applied to the trailing columns only, as LAPACK's
    gbtrf does; :func:`band_solve` replays them. Returns False if a pivot is exactly zero.

    The compact storage (n x (2 kl + ku + 1)) keeps the factors in a few tens of kB, in cache,
    where a dense n x n matrix would not be.
    """
    uw = ku + kl
    for k in range(n):
        p = k
        amax = abs(w[k, kl])
        iend = min(n, k + kl + 1)
        for i in range(k + 1, iend):
            v = abs(w[i, k - i + kl])
            if v > amax:
                amax = v
                p = i
        piv[k] = p
        if amax == 0.0:
            return False
        jend = min(n, k + uw + 1)
        if p != k:
            for j in range(k, jend):
                tmp = w[k, j - k + kl]
                w[k, j - k + kl] = w[p, j - p + kl]
                w[p, j - p + kl] = tmp
        inv = 1.0 / w[k, kl]
        for i in range(k + 1, iend):
            lik = w[i, k - i + kl] * inv
            w[i, k - i + kl] = lik
            if lik != 0.0:
                for j in range(k + 1, jend):
                    w[i, j - i + kl] -= lik * w[k, j - k + kl]
    return True


@njit(cache=True)
def band_solve(w, n, kl, ku, piv, b):  # pragma: no cover - numba
    """Solve with the factors of :func:`band_lu` (``b`` overwritten by the solution)."""
    uw = ku + kl
    for k in range(n):
        p = piv[k]
        if p != k:
            tmp = b[k]
            b[k] = b[p]
            b[p] = tmp
        bk = b[k]
        if bk != 0.0:
            for i in range(k + 1, min(n, k + kl + 1)):
                b[i] -= w[i, k - i + kl] * bk
    for k in range(n - 1, -1, -1):
        s = b[k]
        for j in range(k + 1, min(n, k + uw + 1)):
            s -= w[k, j - k + kl] * b[j]
        b[k] = s / w[k, kl]


@njit(cache=True)
def band_jacobian(t, y, f0, data, kl, ku, jac, scale):  # pragma: no cover - numba
    """Banded Jacobian df/dy by forward differences with column colouring.

    Columns j and j' share a kernel call when |j - j'| >= kl + ku + 1 (their row supports cannot
    overlap). ``scale`` gives the typical size of each state for the increment
    h_j = sqrt(eps) max(|y_j|, scale_j). Returns the number of kernel calls.
    """
    n = y.size
    ng = min(kl + ku + 1, n)
    yp = y.copy()
    fp = np.empty(n)
    hs = np.empty(n)
    diag = np.empty(ND)
    for gi in range(ng):
        for j in range(gi, n, ng):
            h = 1.4901161193847656e-08 * max(abs(y[j]), scale[j])
            yp[j] = y[j] + h
            hs[j] = yp[j] - y[j]
        rhs_kernel(t, yp, fp, data, diag)
        for j in range(gi, n, ng):
            yp[j] = y[j]
            for i in range(max(0, j - ku), min(n, j + kl + 1)):
                jac[i, j] = (fp[i] - f0[i]) / hs[j]
    return ng


@njit(cache=True)
def _wnorm(v, y0, y1, atol, rtol):  # pragma: no cover - numba
    s = 0.0
    n = v.size
    for i in range(n):
        sc = atol[i] + rtol * max(abs(y0[i]), abs(y1[i]))
        r = v[i] / sc
        s += r * r
    return math.sqrt(s / n)


@njit(cache=True)
def _build_w(jac, wmat, n, kl, ku, hd):  # pragma: no cover - numba
    """Newton matrix W = I - hd J in compact band storage (fill-in columns zeroed)."""
    width = wmat.shape[1]
    for i in range(n):
        for o in range(width):
            wmat[i, o] = 0.0
        for j in range(max(0, i - kl), min(n, i + ku + 1)):
            wmat[i, j - i + kl] = -hd * jac[i, j]
        wmat[i, kl] += 1.0


@njit(cache=True)
def _newton(z, base, hd, tt, data, wmat, n, kl, ku, piv, yref, atol, rtol, kappa, maxit,
            eta0, fz, res, diag):  # pragma: no cover - numba
    """Solve z = base + hd f(tt, z) by simplified Newton. Returns (ok, iterations, eta, rate)."""
    dn_old = 0.0
    eta = max(eta0, 1e-16) ** 0.8
    rate = 0.0
    for it in range(maxit):
        rhs_kernel(tt, z, fz, data, diag)
        for i in range(n):
            res[i] = base[i] + hd * fz[i] - z[i]
        band_solve(wmat, n, kl, ku, piv, res)
        for i in range(n):
            z[i] += res[i]
        dn = _wnorm(res, yref, z, atol, rtol)
        if not math.isfinite(dn):
            return False, it + 1, eta, 1.0
        if it > 0:
            rate = dn / dn_old
            if rate >= 0.9:
                return False, it + 1, eta, rate
            eta = rate / (1.0 - rate)
        # the first correction is only trusted when it is already within the tolerance: the
        # previous contraction rate says little after a slack/taut switch or an input kink
        if (it > 0 and eta * dn <= kappa) or dn <= kappa:
            return True, it + 1, eta, rate
        dn_old = dn
    return False, maxit, eta, rate


@njit(cache=True)
def integrate_chunk(fs, y, f, t_end, data, opts, atol, stops, out_t, out_y, out_d, stats,
                    jac, wmat, piv, scale, kl, ku):  # pragma: no cover - numba
    """Advance (t, y) towards ``t_end`` with TR-BDF2 (module docstring).

    Parameters
    ----------
    fs : ndarray (F_SIZE,), in/out
        t [s], next step size h [s], Newton eta, Jacobian age, stale flag.
    y, f : ndarray, in/out
        State and its derivative at t (first-same-as-last).
    t_end : float
        Stop time of this call [s].
    data : tuple
        Model data, passed through to the model functions unread.
    opts : ndarray (O_SIZE,)
        rtol, h_max, h_min, step budget of this call, Newton tolerance kappa, Jacobian refresh
        interval (accepted steps), max Newton iterations.
    atol : ndarray
        Absolute tolerance per state.
    stops : ndarray
        Sorted times the steps must land on (input slope jumps).
    out_t : ndarray
        Sorted output times; ``out_y``/``out_d`` receive states/diagnostics at them.
    stats : int64 ndarray (S_SIZE,), in/out
        Counters (steps, rejected, kernel calls, Jacobians, LU, next output index, status,
        Newton failures).
    jac : ndarray (n, n)
        Work storage for the Jacobian (band entries only are used).
    wmat : ndarray (n, 2 kl + ku + 1)
        Work storage for the factorised Newton matrix, compact band storage (:func:`band_pack`).
    piv : int64 ndarray (n,)
    scale : ndarray
        Typical state sizes for the Jacobian increments.
    kl, ku : int
        Band widths of the Jacobian.
    """
    n = y.size
    rtol = opts[O_RTOL]
    hmax = opts[O_HMAX]
    hmin = opts[O_HMIN]
    maxsteps = int(opts[O_MAXSTEPS])
    kappa = opts[O_KAPPA]
    jac_every = int(opts[O_JAC_EVERY])
    maxit = int(opts[O_MAXIT])
    t = fs[F_T]
    h = fs[F_H]
    eta = fs[F_ETA]
    z2 = np.empty(n)
    z3 = np.empty(n)
    base = np.empty(n)
    fz = np.empty(n)
    res = np.empty(n)
    k2 = np.empty(n)
    k3 = np.empty(n)
    err = np.empty(n)
    diag = np.empty(ND)
    nsteps = 0
    hd = 0.0
    w_ok = False
    h_w = -1.0
    stats[S_STATUS] = 0
    while t < t_end - 1e-12 * max(1.0, abs(t_end)):
        if nsteps >= maxsteps:
            stats[S_STATUS] = 1
            break
        # next target: t_end or the next stop
        target = t_end
        for k in range(stops.size):
            if stops[k] > t + 1e-12 * max(1.0, abs(t)):
                if stops[k] < target:
                    target = stops[k]
                break
        h = min(h, hmax)
        hit = False
        if t + h >= target - 1e-12 * max(1.0, abs(target)):
            h = target - t
            hit = True
        elif t + 2.0 * h > target:
            h = 0.5 * (target - t)
        if h < hmin:
            stats[S_STATUS] = 2
            break
        # Jacobian and Newton matrix
        if fs[F_STALE] > 0.0:
            stats[S_FEVAL] += band_jacobian(t, y, f, data, kl, ku, jac, scale)
            stats[S_JAC] += 1
            fs[F_STALE] = 0.0
            fs[F_AGE] = 0.0
            w_ok = False
        if (not w_ok) or h != h_w:
            hd = D_COEF * h
            _build_w(jac, wmat, n, kl, ku, hd)
            stats[S_LU] += 1
            if not band_lu(wmat, n, kl, ku, piv):
                stats[S_STATUS] = 6
                break
            w_ok = True
            h_w = h
        # stage 2: trapezoidal rule to t + gamma h
        for i in range(n):
            base[i] = y[i] + hd * f[i]
            z2[i] = y[i] + GAMMA * h * f[i]
        ok, its, eta2, rate = _newton(z2, base, hd, t + GAMMA * h, data, wmat, n, kl, ku,
                                      piv, y, atol, rtol, kappa, maxit, eta, fz, res, diag)
        stats[S_FEVAL] += its
        if ok:
            for i in range(n):
                k2[i] = (z2[i] - base[i]) / hd
            # stage 3: BDF2 to t + h
            for i in range(n):
                base[i] = y[i] + h * W_COEF * (f[i] + k2[i])
                z3[i] = base[i] + hd * k2[i]
            ok, its3, eta, rate3 = _newton(z3, base, hd, t + h, data, wmat, n, kl, ku, piv,
                                           y, atol, rtol, kappa, maxit, eta2, fz, res, diag)
            stats[S_FEVAL] += its3
            its = max(its, its3)
            rate = max(rate, rate3)
        if not ok:
            stats[S_NFAIL] += 1
            if fs[F_AGE] > 0.0:
                fs[F_STALE] = 1.0  # retry with a fresh Jacobian first
            else:
                h *= 0.25
            eta = 1.0
            continue
        for i in range(n):
            k3[i] = (z3[i] - base[i]) / hd
            err[i] = h * (E1 * f[i] + E2 * k2[i] + E3 * k3[i])
        band_solve(wmat, n, kl, ku, piv, err)
        en = _wnorm(err, y, z3, atol, rtol)
        if not math.isfinite(en):
            en = 1e10
        if en > 1.0:
            stats[S_REJECT] += 1
            h *= max(0.2, 0.9 * en ** (-1.0 / 3.0))
            continue
        # accepted: dense output on (t, t + h]
        io = stats[S_IOUT]
        while io < out_t.size and out_t[io] <= t + h + 1e-12 * max(1.0, abs(t)):
            to = out_t[io]
            if to >= t - 1e-12 * max(1.0, abs(t)):
                s = (to - t) / h
                h00 = (1.0 + 2.0 * s) * (1.0 - s) ** 2
                h10 = s * (1.0 - s) ** 2
                h01 = s * s * (3.0 - 2.0 * s)
                h11 = s * s * (s - 1.0)
                for i in range(n):
                    out_y[io, i] = h00 * y[i] + h10 * h * f[i] + h01 * z3[i] + h11 * h * k3[i]
                rhs_kernel(to, out_y[io], fz, data, out_d[io])
            io += 1
        stats[S_IOUT] = io
        t = t + h
        if hit:
            t = target
        for i in range(n):
            y[i] = z3[i]
        nsteps += 1
        stats[S_STEPS] += 1
        fs[F_AGE] += 1.0
        if hit and target != t_end:
            # the input's slope jumps here: restart with the right-hand derivative
            rhs_kernel(t + 1e-9 * max(1.0, abs(t)), y, f, data, diag)
            stats[S_FEVAL] += 1
            fs[F_STALE] = 1.0
        else:
            # a fresh derivative, not the algebraic k3: the latter carries the Newton error / hd
            rhs_kernel(t, y, f, data, diag)
            stats[S_FEVAL] += 1
        code = check_kernel(t, y, data, diag)
        if code != 0:
            stats[S_STATUS] = code
            break
        if its > 2 or rate > 0.3 or fs[F_AGE] >= jac_every:
            fs[F_STALE] = 1.0
        fac = min(5.0, max(0.2, 0.9 * max(en, 1e-10) ** (-1.0 / 3.0)))
        if 1.0 <= fac <= 1.2 and not hit:
            fac = 1.0  # keep h: the factorised Newton matrix stays valid (Hairer & Wanner IV.8)
        h = h * fac
    fs[F_T] = t
    fs[F_H] = h
    fs[F_ETA] = eta
    return stats[S_STATUS]
