"""Compiled station loop of the envelope beam (numba): the part of
:func:`aerostat_core.structures.membrane.envelope_loads` that runs along the hull, every column
(design x speed) of a batch in one call.

The numpy form (:func:`aerostat_core.structures.membrane._envelope_loads_plain`, kept as the
reference definition; the test suite checks the two agree) spends its time in numpy's per-call
overhead (about 120 calls on arrays of 25 stations x a few columns, whatever the batch width);
this kernel does the same arithmetic, in the same order, in one compiled loop: the trapezoid
integrals on the stations, the scaling of the Jones & DeLaurier load shapes, the confluence
lines' closing load, the shear and moment of :func:`aerostat_core.structures.membrane.beam_moment`,
the governing section and the pressure (equations, units and sources in ``envelope_loads``;
docs/methods.md §1.17). Sums along the hull are taken station by station from the nose, so a
result may differ from numpy's (pairwise summation on some layouts) in the last bits only.

Importing this module imports numba; the kernel is compiled on its first call
(``cache=True``: later processes load it from ``__pycache__``). It calls no kernel of another
module, so numba's cache, keyed on this file's time stamp, cannot go stale.
``error_model="numpy"``: divisions follow IEEE 754 as in numpy.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit


@njit(cache=True, error_model="numpy", inline="always")
def _mx(a, b):  # pragma: no cover - compiled
    """np.maximum of two floats (NaN if either is NaN)."""
    if a != a:
        return a
    if b != b:
        return b
    return a if a >= b else b


@njit(cache=True, error_model="numpy")
def envelope_beam(x, r, wts, length, b, xi_m, xi_cb, lh, drho, g, ca, m_hull, sin2a,
                  lift_h, hull_moment, point_p, point_x, streamlined, span, min_radius,
                  p_dimple, factor, superpressure):  # pragma: no cover - compiled
    """The station loop of ``membrane.envelope_loads`` for n columns.

    x, r : float64[S, n] stations from the nose [m] and radius there [m]; wts : float64[S]
    trapezoid weights (1/2 at the ends); length, b, xi_m (hull moment reference), xi_cb,
    lh (cut-off station) [m], drho (air less gas density) [kg/m3], ca = cos(alpha),
    m_hull (hull fabric item mass) [kg], sin2a = sin(2 alpha), lift_h, hull_moment (the hull's
    normal force [N] and moment [N m] of the aerodynamic model), p_dimple [Pa]: float64[n];
    point_p, point_x : float64[P, n] point loads [N] (up) and their stations [m], in the
    order of the reference; g [m/s2], span (CONFLUENCE_SPAN), min_radius (WRINKLE_MIN_RADIUS
    of b), factor (pressure / q rule), superpressure [Pa]: floats; streamlined: the hull
    carries the aerodynamic load shapes (and the hull's point force and couple where they
    cannot carry it).

    Returns float64[7, n]: |M| at the governing section [N m], its radius rr [m], its station
    [m], the wrinkling pressure [Pa], the pressure at the top [Pa], the largest longitudinal
    load [N/m] and the largest |M| [N m].
    """
    ns, n = x.shape
    npt = point_p.shape[0]
    out = np.empty((7, n))
    area = np.empty(ns)
    d_area = np.empty(ns)
    per = np.empty(ns)
    load = np.empty(ns)
    s1v = np.empty(ns)
    s2v = np.empty(ns)
    patch = np.empty(ns)
    v = np.empty(ns)
    m = np.empty(ns)
    for j in range(n):
        L = length[j]
        dx = L / (ns - 1)
        dxs = _mx(dx, 1e-12)
        for s in range(ns):
            rs = r[s, j]
            area[s] = math.pi * (rs * rs)
            per[s] = (2.0 * math.pi) * rs
        # np.gradient (unit spacing, first-order ends) / dx
        for s in range(1, ns - 1):
            d_area[s] = ((area[s + 1] - area[s - 1]) / 2.0) / dxs
        d_area[0] = (area[1] - area[0]) / dxs
        d_area[ns - 1] = (area[ns - 1] - area[ns - 2]) / dxs
        acc = 0.0
        for s in range(ns):
            acc = acc + wts[s] * per[s]
        per_int = _mx(acc * dx, 1e-12)
        c_a = ca[j]
        dg = drho[j] * g
        wh = m_hull[j] * g * c_a
        for s in range(ns):
            load[s] = dg * area[s] * c_a - wh * per[s] / per_int
        couple = 0.0
        has_couple = False
        hull_p = 0.0
        if streamlined:
            sa = sin2a[j]
            xm = xi_m[j]
            f1 = f2 = m1 = m2 = 0.0
            for s in range(ns):
                xs = x[s, j]
                if xs <= lh[j]:
                    s1v[s] = sa * d_area[s]
                    s2v[s] = 0.0
                else:
                    s1v[s] = 0.0
                    s2v[s] = 2.0 * r[s, j] * 1.0
                arm = xs - xm
                w = wts[s]
                f1 = f1 + w * s1v[s]
                f2 = f2 + w * s2v[s]
                m1 = m1 + w * (s1v[s] * arm)
                m2 = m2 + w * (s2v[s] * arm)
            f1 *= dx
            f2 *= dx
            m1 *= dx
            m2 *= dx
            lh_j = lift_h[j]
            hm = hull_moment[j]
            couple_h = -hm
            det = f1 * m2 - f2 * m1
            ok = abs(det) > 1e-9 * (abs(f1 * m2) + abs(f2 * m1) + 1e-30)
            safe = det if ok else 1.0
            s1 = (lh_j * m2 - f2 * couple_h) / safe if ok else 0.0
            s2 = (f1 * couple_h - m1 * lh_j) / safe if ok else 0.0
            for s in range(ns):
                load[s] = load[s] + s1 * s1v[s] + s2 * s2v[s]
            couple = 0.0 if ok else hm
            has_couple = True
            hull_p = 0.0 if ok else lh_j
        # the confluence lines' reaction: a hat on the centre of buoyancy with a linear part
        half = 0.5 * span * L
        xc = xi_cb[j]
        w0 = 0.0
        for s in range(ns):
            patch[s] = _mx(1.0 - abs(x[s, j] - xc) / half, 0.0)
            w0 = w0 + wts[s] * patch[s]
        w0 = _mx(w0 * dx, 1e-12)
        xb = 0.0
        for s in range(ns):
            xb = xb + wts[s] * (patch[s] * x[s, j])
        x_bar = xb * dx / w0
        w2 = 0.0
        fl = 0.0
        fx = 0.0
        for s in range(ns):
            d = x[s, j] - x_bar
            w2 = w2 + wts[s] * (patch[s] * (d * d))
            fl = fl + wts[s] * load[s]
            fx = fx + wts[s] * (load[s] * x[s, j])
        w2 = _mx(w2 * dx, 1e-12)
        psum = 0.0
        pxsum = 0.0
        for i in range(npt):
            psum = psum + point_p[i, j]
            pxsum = pxsum + point_p[i, j] * point_x[i, j]
        if streamlined:
            psum = psum + hull_p
            pxsum = pxsum + hull_p * xi_m[j]
        force = fl * dx + psum
        first = fx * dx + pxsum
        c = (couple if has_couple else 0.0) - first + force * x_bar
        for s in range(ns):
            load[s] = load[s] - force * patch[s] / w0 + c * (x[s, j] - x_bar) * patch[s] / w2
        # beam_moment: shear and moment by the trapezoid rule, point loads and couples
        v[0] = 0.0
        for s in range(1, ns):
            v[s] = v[s - 1] + 0.5 * (load[s] + load[s - 1]) * (x[s, j] - x[s - 1, j])
        m[0] = 0.0
        for s in range(1, ns):
            m[s] = m[s - 1] + 0.5 * (v[s] + v[s - 1]) * (x[s, j] - x[s - 1, j])
        for i in range(npt + (1 if streamlined else 0)):
            if i < npt:
                p = point_p[i, j]
                xp = point_x[i, j]
            else:
                p = hull_p
                xp = xi_m[j]
            for s in range(ns):
                m[s] = m[s] + p * _mx(x[s, j] - xp, 0.0)
        if has_couple:
            xm = xi_m[j]
            for s in range(ns):
                m[s] = m[s] + couple * (1.0 if x[s, j] >= xm else 0.0)
        x0 = x[0, j]
        sp = x[ns - 1, j] - x0
        sp = sp if sp > 0 else 1.0
        m_last = m[ns - 1]
        for s in range(ns):
            m[s] = m[s] - m_last * (x[s, j] - x0) / sp
        # governing section: the largest |M| / r^3 among sections of radius >= min_radius b
        bj = b[j]
        rmin = 1e-3 * bj
        rlim = min_radius * bj
        k = 0
        best = 0.0
        for s in range(ns):
            rr = _mx(r[s, j], rmin)
            ratio = abs(m[s]) / rr ** 3.0 if r[s, j] >= rlim else 0.0
            if s == 0:
                best = ratio
            elif best == best and (ratio > best or ratio != ratio):
                best = ratio
                k = s
        m_gov = abs(m[k])
        r_gov = _mx(r[k, j], rmin)
        head = dg * bj
        p_w = factor * 2.0 * m_gov / (math.pi * r_gov ** 3.0) + head
        p_top = _mx(_mx(p_dimple[j], p_w), superpressure)
        n_long = 0.0
        bend = 0.0
        for s in range(ns):
            rr = _mx(r[s, j], rmin)
            am = abs(m[s])
            nl = 0.5 * p_top * rr + am / (math.pi * (rr * rr))
            if s == 0:
                n_long = nl
                bend = am
            else:
                n_long = _mx(n_long, nl)
                bend = _mx(bend, am)
        out[0, j] = m_gov
        out[1, j] = r_gov
        out[2, j] = x[k, j]
        out[3, j] = p_w
        out[4, j] = p_top
        out[5, j] = n_long
        out[6, j] = bend
    return out
