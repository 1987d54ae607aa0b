"""Added mass of the hull: Lamb's inertia factors and their numerical generalisation.

Lamb's closed forms for prolate and oblate spheroids, and a line-singularity panel method for
any body of revolution of the shape library (docs/methods.md; Lamb, *Hydrodynamics*, 1932).
"""

from __future__ import annotations

from functools import cache

import numpy as np

from aerostat_core.geometry.shapes import (
    SHAPE_INFO,
    profile_function,
    profile_nodes,
    profile_radius_ratio,
)


def lamb_factors(fineness_ratio):
    """Lamb's inertia (added-mass) factors of a prolate spheroid of the given fineness ratio.

    With e = sqrt(1 - 1/f^2):
    alpha0 = (2(1 - e^2)/e^3) (artanh(e) - e),  beta0 = 1/e^2 - ((1 - e^2)/e^3) artanh(e),
    k1 = alpha0/(2 - alpha0) (axial), k2 = k3 = beta0/(2 - beta0) (transverse),
    k' = e^4 (beta0 - alpha0) / ((2 - e^2)(2 e^2 - (2 - e^2)(beta0 - alpha0))) (rotation).

    Parameters
    ----------
    fineness_ratio : array_like
        l/d [-], > 1 (the sphere limit f -> 1 gives k1 = k2 = 0.5, k' = 0).

    Returns
    -------
    k1, k2, k_rot : ndarray [-]

    Notes
    -----
    Source: Lamb, *Hydrodynamics* (1932) §373; Tuckerman, NACA Report 210 (1926).

    Examples
    --------
    >>> [round(float(k), 3) for k in lamb_factors(4.0)]
    [0.082, 0.86, 0.608]
    """
    f = np.maximum(np.asarray(fineness_ratio, dtype=float), 1.0 + 1e-6)
    e = np.sqrt(1.0 - 1.0 / f**2)
    at = np.arctanh(e)
    alpha0 = 2.0 * (1.0 - e**2) / e**3 * (at - e)
    beta0 = 1.0 / e**2 - (1.0 - e**2) / e**3 * at
    k1 = alpha0 / (2.0 - alpha0)
    k2 = beta0 / (2.0 - beta0)
    dba = beta0 - alpha0
    k_rot = e**4 * dba / ((2.0 - e**2) * (2.0 * e**2 - (2.0 - e**2) * dba))
    return k1, k2, k_rot


# --- spheroids: Lamb's closed forms ----------------------------------------------------------
def spheroid_lamb_factors(fineness_ratio):
    """Lamb's inertia factors of a spheroid of revolution about x with l/d = f, prolate or oblate.

    With a the axial and b the equatorial semi-axis (f = a/b), Lamb's ellipsoid integrals
    alpha0 (axial) and beta0 (transverse), alpha0 + 2 beta0 = 2:
      prolate, e = sqrt(1 - 1/f^2): alpha0 = (2(1 - e^2)/e^3)(artanh e - e);
      oblate,  e = sqrt(1 - f^2):   alpha0 = (2/e^2)(1 - sqrt(1 - e^2) arcsin(e)/e);
    k1 = alpha0/(2 - alpha0), k2 = beta0/(2 - beta0),
    k' = (a^2 - b^2)^2 (beta0 - alpha0) / ((a^2 + b^2)(2(a^2 - b^2) - (a^2 + b^2)(beta0 - alpha0))).

    Parameters
    ----------
    fineness_ratio : array_like
        a/b [-], valid (0.05, 20); f = 1 (sphere) gives 0.5, 0.5, 0.

    Notes
    -----
    Source: Lamb, *Hydrodynamics* (1932) §§114, 373; the prolate branch equals
    :func:`aerostat_core.geometry.added_mass.lamb_factors`.

    Examples
    --------
    >>> [round(float(k), 3) for k in spheroid_lamb_factors(4.0)]
    [0.082, 0.86, 0.608]
    """
    f = np.asarray(fineness_ratio, dtype=float)
    pro = f > 1.0 + 1e-6
    obl = f < 1.0 - 1e-6
    k1p, k2p, krp = lamb_factors(np.where(pro, f, 2.0))
    fo = np.where(obl, f, 0.5)
    e = np.sqrt(1.0 - fo**2)
    a_obl = 2.0 / e**2 * (1.0 - np.sqrt(1.0 - e**2) * np.arcsin(e) / e)
    alpha0 = np.where(obl, a_obl, 2.0 / 3.0)
    beta0 = 0.5 * (2.0 - alpha0)
    a2, b2 = f**2, 1.0
    dba = beta0 - alpha0
    den = (a2 + b2) * (2.0 * (a2 - b2) - (a2 + b2) * dba)
    safe = np.where(np.abs(den) > 1e-12, den, 1.0)
    kr = np.where(np.abs(den) > 1e-12, (a2 - b2) ** 2 * dba / safe, 0.0)
    k1 = np.where(pro, k1p, alpha0 / (2.0 - alpha0))
    k2 = np.where(pro, k2p, beta0 / (2.0 - beta0))
    return k1, k2, np.where(pro, krp, kr)


# --- added mass of any body of revolution: line singularities (numerical) --------------------
def _body_points(shape: str, f: float, n: int, nose_fraction: float = 0.432):
    """Meridian points (x, rho), outward normals and arc weights on a body of length 1."""
    t, w = np.polynomial.legendre.leggauss(n)
    th = 0.5 * np.pi * (t + 1.0)
    wt = 0.5 * np.pi * w
    x = 0.5 * (1.0 - np.cos(th))
    dxdt = 0.5 * np.sin(th)
    d = 1.0 / f
    if shape == "npl":
        m = nose_fraction
        a = np.where(x <= m, m, 1.0 - m)
        u = (x - m) / a
        rho = 0.5 * d * np.sqrt(np.maximum(1.0 - u * u, 0.0))
        drdx = -0.5 * d * u / (a * np.sqrt(np.maximum(1.0 - u * u, 1e-300)))
        drdt = drdx * dxdt
    else:
        p, dp = profile_function(shape, x)
        p = np.maximum(p, 1e-300)
        rho = d * np.sqrt(p)
        drdt = d * 0.5 * dp / np.sqrt(p) * dxdt
    norm = np.hypot(dxdt, drdt)
    nx, nr = -drdt / norm, dxdt / norm
    return x, rho, nx, nr, norm * wt


def added_mass_numerical(
    shape: str, fineness_ratio: float, segments: int = 48, nose_fraction: float = 0.432
):
    """Inertia factors k1, k2, k' of a body of revolution by potential flow, numerically.

    Axial motion: a line of constant-strength source segments on the axis; transverse and
    pitching motion: a line of transverse doublet segments (cos phi mode). Strengths are fitted
    by least squares to the body boundary condition dphi/dn = V_body . n at 3 x ``segments``
    Gauss points of the meridian (von Karman's method, 1927), with a zero-net-source row for the
    axial case. The added masses follow from the kinetic energy of the flow,
    m = -rho oint phi (dphi/dn) dS (Lamb 1932 §§117-121), and
    k1 = m11/(rho V), k2 = m33/(rho V), k' = I55/(rho int ((x - x_cv)^2 + z^2) dV) about the
    centre of volume.

    Parameters
    ----------
    shape : str
        A name of ``SHAPES`` (the method needs an elongated body; f >= 1.5 recommended).
    fineness_ratio : float
        l/d [-].
    segments : int
        Singularity segments. With 48, Lamb's prolate-spheroid factors are reproduced within
        0.5 % (k2, k') and 2 % (k1) for f in [1.5, 6] (tests/core/test_shapes.py); k1 drifts to
        +3 % at f = 8, where the thin body needs more segments.

    Returns
    -------
    k1, k2, k_rot : float [-]
    """
    f = float(fineness_ratio)
    n_col = 3 * segments
    x, rho, nx, nr, ds = _body_points(shape, f, n_col, nose_fraction)
    # singularities between the centres of nose and tail curvature (inside the body)
    lo = float(x[0] + 0.5 * np.min(rho[: n_col // 4] ** 2 / np.maximum(x[: n_col // 4], 1e-12)))
    x_last, r_last = 1.0 - x[-1], rho[-1]
    hi = float(1.0 - x_last - 0.5 * r_last**2 / max(x_last, 1e-12))
    lo, hi = min(max(lo, 0.02), 0.3), max(min(hi, 0.98), 0.7)
    edges = np.linspace(lo, hi, segments + 1)
    x1, x2 = edges[:-1][None, :], edges[1:][None, :]
    xc, rc = x[:, None], rho[:, None]
    r1 = np.sqrt((xc - x1) ** 2 + rc**2)
    r2 = np.sqrt((xc - x2) ** 2 + rc**2)
    g = ((x2 - xc) / r2 - (x1 - xc) / r1) / rc  # int rho/R^3 dxi
    # axial: sources, phi = -(q/4pi) int dxi/R
    ux = (1.0 / r2 - 1.0 / r1) / (4.0 * np.pi)
    ur = g / (4.0 * np.pi)
    phi_s = -(np.arcsinh((x2 - xc) / rc) - np.arcsinh((x1 - xc) / rc)) / (4.0 * np.pi)
    a_ax = nx[:, None] * ux + nr[:, None] * ur
    scale = np.sqrt(ds)[:, None]
    closure = 10.0 * (edges[1:] - edges[:-1])[None, :] * np.sqrt(np.sum(a_ax**2) / n_col)
    q = np.linalg.lstsq(
        np.vstack([a_ax * scale, closure]), np.concatenate([nx * scale[:, 0], [0.0]]), rcond=None
    )[0]
    phi = phi_s @ q
    xv, wv, r2v = _vol_nodes(shape, f, nose_fraction)
    vol = np.sum(wv)
    m11 = -2.0 * np.pi * np.sum(phi * nx * rho * ds)
    # cos(phi) mode: transverse doublets, Phi = (mu/4pi) g
    gx = rc * (1.0 / r1**3 - 1.0 / r2**3)
    gr = -g / rc - (x2 - xc) / r2**3 + (x1 - xc) / r1**3
    a_tr = (nx[:, None] * gx + nr[:, None] * gr) / (4.0 * np.pi)
    phi_d = g / (4.0 * np.pi)
    mu = np.linalg.lstsq(a_tr * scale, nr * scale[:, 0], rcond=None)[0]
    m33 = -np.pi * np.sum((phi_d @ mu) * nr * rho * ds)
    x_cv = np.sum(wv * xv) / np.sum(wv)
    gb = rho * nx - (x - x_cv) * nr
    mu = np.linalg.lstsq(a_tr * scale, gb * scale[:, 0], rcond=None)[0]
    i55 = -np.pi * np.sum((phi_d @ mu) * gb * rho * ds)
    i_fluid = np.sum(wv * ((xv - x_cv) ** 2 + r2v / 4.0))
    return abs(m11) / vol, abs(m33) / vol, abs(i55) / i_fluid


def _vol_nodes(shape, f, nose_fraction):
    """Stations, volume weights pi r^2 dx and r^2 of a body of length 1 and l/d = f."""
    x, wx = profile_nodes(shape)
    r = profile_radius_ratio(shape, x, nose_fraction) / f
    return x, np.pi * r**2 * wx, r**2


@cache
def _added_mass_table(shape: str):
    lo, hi = SHAPE_INFO[shape].fineness_range
    fs = np.linspace(lo, hi, 33)
    ks = np.array([added_mass_numerical(shape, fv) for fv in fs])
    return fs, ks


def added_mass_factors(shape: str, fineness_ratio):
    """Inertia (added-mass) factors k1 (axial), k2 = k3 (transverse), k' (pitch) [-].

    * ``npl``: Lamb's factors of the prolate spheroid of the same l/d (the thesis' method,
      Appendix C; keeps the engine's established numbers);
    * sphere, oblate, Helikite hull: Lamb's closed forms (:func:`spheroid_lamb_factors`);
    * Gertler shapes and GNVR: :func:`added_mass_numerical` tabulated on 33 fineness ratios
      over the shape's valid range and interpolated linearly (vectorised for batches).

    Parameters
    ----------
    shape : str
    fineness_ratio : array_like
        l/d [-], within the shape's range.
    """
    f = np.asarray(fineness_ratio, dtype=float)
    if shape == "npl" or SHAPE_INFO[shape].family not in ("gertler", "piecewise"):
        return spheroid_lamb_factors(np.maximum(f, 1.0 + 1e-6) if shape == "npl" else f)
    fs, ks = _added_mass_table(shape)
    return tuple(np.interp(f, fs, ks[:, j]) for j in range(3))
