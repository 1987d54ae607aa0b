"""Hull geometry: profile, volume, area, centroids, inertia factors, J&D integrals.

The NPL double ellipsoid has closed forms (below); every other shape of
:mod:`aerostat_core.geometry.shapes` (Gertler profiles, spheroids) is integrated by Gauss-Legendre
quadrature of its dimensionless profile. All functions broadcast over numpy arrays, so one call
can size a whole batch of hulls. Body frame (docs/methods.md §1): station xi from the nose, aft
positive; z up.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from aerostat_core.geometry import shapes as _shapes
from aerostat_core.geometry.added_mass import added_mass_factors, lamb_factors

# Gauss-Legendre nodes for the smooth surface integrals (exact enough to 1e-12 for these profiles).
_GL_X, _GL_W = np.polynomial.legendre.leggauss(48)


def hull_dimensions(volume, fineness_ratio, nose_fraction=0.432):
    r"""Length, diameter and ellipse semi-axes of an NPL hull of given volume and fineness.

    .. math::

        V = \frac23 \pi b^2 (a_1 + a_2) = \frac{\pi}{6} d^2 l, \quad f = \frac{l}{d}
        \;\Rightarrow\; d = \left(\frac{6V}{\pi f}\right)^{1/3}, \quad l = f d, \quad
        a_1 = \nu\, l, \quad a_2 = l - a_1, \quad b = \frac d2

    with nu = ``nose_fraction``.

    Parameters
    ----------
    volume : array_like
        Hull volume [m3], valid {range:HullSpec.volume}.
    fineness_ratio : array_like
        l/d [-], valid in ``SHAPE_INFO["npl"].fineness_range`` (the NPL shape is a standard at 4.0).
    nose_fraction : array_like
        a1/l [-], valid {range:HullSpec.nose_fraction}; 0.432 for the NPL standard (public
        Gertler-envelope tables, docs/methods.md S7).

    Returns
    -------
    length, diameter, a1, a2, b : ndarray [m]

    Notes
    -----
    Source: Khoury & Gillett, *Airship Technology* (1999); thesis §3.1.3(a); docs/methods.md §1.4.

    Examples
    --------
    100 m3 at l/d 2.7: d = (600/(2.7 pi))^(1/3) = 4.135 m, l = 11.17 m (by hand):

    >>> l, d, a1, a2, b = hull_dimensions(100.0, 2.7)
    >>> round(float(l), 2), round(float(d), 2)
    (11.17, 4.14)
    """
    v = np.asarray(volume, dtype=float)
    f = np.asarray(fineness_ratio, dtype=float)
    d = np.cbrt(6.0 * v / (np.pi * f))
    length = f * d
    a1 = np.asarray(nose_fraction, dtype=float) * length
    return length, d, a1, length - a1, 0.5 * d


def half_spheroid_area(a, b):
    r"""Curved surface of half a spheroid with polar semi-axis ``a`` and equatorial radius ``b`` [m2].

    .. math::

        S = \begin{cases}
        \pi b^2 + \pi a b \dfrac{\arcsin e}{e}, & e = \sqrt{1 - b^2/a^2} \quad (a > b) \\
        \pi b^2 + \dfrac{\pi a^2}{e} \operatorname{artanh} e, & e = \sqrt{1 - a^2/b^2} \quad (a < b) \\
        2 \pi b^2 & (a = b)
        \end{cases}

    Parameters
    ----------
    a, b : array_like
        Semi-axes [m], valid > 0.

    Returns
    -------
    ndarray
        Area [m2].

    Notes
    -----
    Source: the surface of a spheroid of revolution (e.g. Abramowitz & Stegun 1964; docs/methods.md
    §1.4).

    Examples
    --------
    A hemisphere has 2 pi b^2; a prolate half with a = 2, b = 1 has
    pi + 2 pi arcsin(0.866)/0.866 = 10.7392 m2 (closed forms):

    >>> round(float(half_spheroid_area(1.0, 1.0)), 6) == round(2 * np.pi, 6)
    True
    >>> round(float(half_spheroid_area(2.0, 1.0)), 4)
    10.7392
    """
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    a, b = np.broadcast_arrays(a, b)
    ratio = a / b
    out = np.empty(a.shape)
    pro = ratio > 1.0 + 1e-9
    obl = ratio < 1.0 - 1e-9
    sph = ~(pro | obl)
    e = np.sqrt(1.0 - (b[pro] / a[pro]) ** 2)
    out[pro] = np.pi * b[pro] ** 2 + np.pi * a[pro] * b[pro] * np.arcsin(e) / e
    e = np.sqrt(1.0 - (a[obl] / b[obl]) ** 2)
    out[obl] = np.pi * b[obl] ** 2 + np.pi * a[obl] ** 2 / e * np.arctanh(e)
    out[sph] = 2.0 * np.pi * b[sph] ** 2
    return out if out.ndim else out[()]


def radius(xi, a1, a2, b):
    r"""Local hull radius r(xi) [m] of the NPL profile (zero outside the hull).

    .. math::

        r = b \sqrt{1 - \left(\frac{a_1 - \xi}{a_1}\right)^2} \quad (0 \le \xi \le a_1), \qquad
        r = b \sqrt{1 - \left(\frac{\xi - a_1}{a_2}\right)^2} \quad (a_1 \le \xi \le a_1 + a_2)

    Parameters
    ----------
    xi : array_like
        Station from the nose [m], valid 0 <= xi <= a1 + a2 (clipped outside).
    a1, a2, b : array_like
        Fore and aft semi-axes and the maximum radius [m] (:func:`hull_dimensions`).

    Returns
    -------
    ndarray [m]

    Notes
    -----
    Source: thesis Fig. 3.4; docs/methods.md §1.4.

    Examples
    --------
    >>> float(radius(4.32, 4.32, 5.68, 1.25))
    1.25
    """
    xi = np.asarray(xi, dtype=float)
    a = np.where(xi <= a1, a1, a2)
    u = np.clip((xi - a1) / a, -1.0, 1.0)
    return b * np.sqrt(1.0 - u * u)


def volume_to_station(xi, a1, a2, b):
    r"""Hull volume between the nose and station ``xi`` [m3] (closed form).

    With u = (xi - a1)/a (a = a1 forward, a2 aft):

    .. math::

        V(\xi) = \pi b^2 a_1 \left(u - \frac{u^3}{3} + \frac23\right) \; (\xi \le a_1), \qquad
        V(\xi) = \frac23 \pi b^2 a_1 + \pi b^2 a_2 \left(u - \frac{u^3}{3}\right) \; (\xi \ge a_1)

    Parameters
    ----------
    xi : array_like
        Station from the nose [m], valid 0 <= xi <= a1 + a2 (clipped).
    a1, a2, b : array_like
        Semi-axes [m] (:func:`hull_dimensions`).

    Returns
    -------
    ndarray [m3]

    Notes
    -----
    Source: integral of pi r^2 of :func:`radius`; docs/methods.md §1.4.

    Examples
    --------
    The forebody is half an ellipsoid: (2/3) pi 1.25^2 4.32 = 14.1372 m3 (closed form):

    >>> round(float(volume_to_station(4.32, 4.32, 5.68, 1.25)), 4)
    14.1372
    """
    xi = np.asarray(xi, dtype=float)
    fwd = xi <= a1
    u1 = np.clip((xi - a1) / a1, -1.0, 0.0)
    u2 = np.clip((xi - a1) / a2, 0.0, 1.0)
    v1 = np.pi * b**2 * a1 * (u1 - u1**3 / 3.0 + 2.0 / 3.0)
    v2 = (2.0 / 3.0) * np.pi * b**2 * a1 + np.pi * b**2 * a2 * (u2 - u2**3 / 3.0)
    return np.where(fwd, v1, v2)


def _surface_moment(a1, a2, b):
    """Integral of xi dS over the hull [m3], by Gauss-Legendre on each half (smooth integrand).

    dS/dxi = 2 pi b sqrt(1 - u^2 + (b/a)^2 u^2) with u = (xi - a1)/a.
    """
    a1 = np.asarray(a1, dtype=float)[..., None]
    a2 = np.asarray(a2, dtype=float)[..., None]
    b = np.asarray(b, dtype=float)[..., None]
    # forebody: u in [-1, 0] -> xi = a1 (1 + u); afterbody: u in [0, 1] -> xi = a1 + a2 u
    u = 0.5 * (_GL_X - 1.0)
    ds1 = 2 * np.pi * b * np.sqrt(1 - u**2 + (b / a1) ** 2 * u**2) * a1 * 0.5
    m1 = np.sum(_GL_W * ds1 * a1 * (1.0 + u), axis=-1)
    u = 0.5 * (_GL_X + 1.0)
    ds2 = 2 * np.pi * b * np.sqrt(1 - u**2 + (b / a2) ** 2 * u**2) * a2 * 0.5
    m2 = np.sum(_GL_W * ds2 * (a1 + a2 * u), axis=-1)
    return m1 + m2


@dataclass(frozen=True)
class HullGeometry:
    """Geometry of a hull (arrays broadcast over a batch of designs).

    Attributes (all SI): volume [m3], fineness_ratio [-], length, diameter, a1, a2, b [m]
    (for shapes other than NPL: a1 = station of maximum diameter, a2 = l - a1, b = d/2),
    surface_area [m2], xi_cb (centre of buoyancy) [m], xi_surface (fabric centroid) [m],
    planform_area J1 [m2], planform_centroid [m], reference_area V^(2/3) [m2],
    k1, k2, k_rot (inertia factors) [-], shape (a name of ``aerostat_core.geometry.shapes.SHAPES``).
    """

    volume: np.ndarray
    fineness_ratio: np.ndarray
    length: np.ndarray
    diameter: np.ndarray
    a1: np.ndarray
    a2: np.ndarray
    b: np.ndarray
    surface_area: np.ndarray
    xi_cb: np.ndarray
    xi_surface: np.ndarray
    planform_area: np.ndarray
    planform_centroid: np.ndarray
    reference_area: np.ndarray
    k1: np.ndarray
    k2: np.ndarray
    k_rot: np.ndarray
    shape: str = "npl"

    @property
    def prismatic_coefficient(self) -> float:
        """C_p = V / (pi d^2 l / 4) [-]."""
        return _shapes.prismatic_coefficient(self.shape)

    def radius_at(self, xi):
        """Local radius r(xi) [m] at stations ``xi`` [m] from the nose (0 outside the hull)."""
        if self.shape == "npl":
            return radius(xi, self.a1, self.a2, self.b)
        x = np.asarray(xi, dtype=float) / self.length
        return self.diameter * _shapes.profile_radius_ratio(self.shape, x)

    def volume_to(self, xi):
        """Hull volume between the nose and station ``xi`` [m3]."""
        if self.shape == "npl":
            return volume_to_station(xi, self.a1, self.a2, self.b)
        x = np.asarray(xi, dtype=float) / self.length
        q = _shapes.profile_volume_fraction(self.shape, x)
        return np.pi * self.diameter**2 * self.length * q


def _profile_geometry(volume, fineness_ratio, shape: str) -> HullGeometry:
    """:class:`HullGeometry` of a polynomial-profile shape by quadrature (shapes.profile_data).

    d = (4V/(pi f C_p))^(1/3), l = f d; S = 2 pi d l int sqrt(P + P'^2/(4 f^2)) dx;
    xi_CB = l x_cv; J1 = d l int 2 sqrt(P) dx with its centroid; inertia factors from
    :func:`aerostat_core.geometry.added_mass.added_mass_factors`.
    """
    pd = _shapes.profile_data(shape)
    f = np.asarray(fineness_ratio, dtype=float)
    v = np.asarray(volume, dtype=float)
    length, d = _shapes.dimensions(shape, v, f)
    v = v * np.ones_like(length)
    f = f * np.ones_like(length)
    fb = f[..., None]
    ds = np.sqrt(pd.p + pd.dp**2 / (4.0 * fb**2)) * pd.wx
    s = 2.0 * np.pi * d * length * np.sum(ds, axis=-1)
    xi_s = length * np.sum(ds * pd.x, axis=-1) / np.sum(ds, axis=-1)
    k1, k2, kr = added_mass_factors(shape, f)
    a1 = pd.x_max * length
    return HullGeometry(
        volume=v, fineness_ratio=f, length=length, diameter=d, a1=a1, a2=length - a1,
        b=0.5 * d, surface_area=s, xi_cb=pd.x_cv * length, xi_surface=xi_s,
        planform_area=pd.planform * d * length, planform_centroid=pd.x_planform * length,
        reference_area=v ** (2.0 / 3.0), k1=k1 * np.ones_like(length),
        k2=k2 * np.ones_like(length), k_rot=kr * np.ones_like(length), shape=shape,
    )


def hull_geometry(volume, fineness_ratio, nose_fraction=0.432, shape: str = "npl"
                  ) -> HullGeometry:
    r"""Build :class:`HullGeometry` from volume, fineness ratio, a1/l and shape.

    ``shape`` other than ``"npl"`` is integrated from its profile (``nose_fraction`` applies to
    NPL only); the sphere always has l/d = 1. NPL closed forms:

    .. math::

        S = S_{half}(a_1, b) + S_{half}(a_2, b), \qquad
        \xi_{CB} = \frac{a_1 \frac{5 a_1}{8} + a_2 \left(a_1 + \frac{3 a_2}{8}\right)}{a_1 + a_2},

        J_1 = \frac{\pi b l}{2}, \qquad
        \xi_{J_1} = \frac{a_1 \left(a_1 - \frac{4 a_1}{3\pi}\right)
        + a_2 \left(a_1 + \frac{4 a_2}{3 \pi}\right)}{l}

    (half-ellipsoid centroids 3a/8 from the base, volumes in proportion to a1, a2).

    Parameters
    ----------
    volume : array_like
        Hull volume [m3], valid {range:HullSpec.volume}.
    fineness_ratio : array_like
        l/d [-], valid in the shape's range (:func:`aerostat_core.geometry.shapes.check_fineness`).
    nose_fraction : array_like
        NPL a1/l [-], valid {range:HullSpec.nose_fraction}.
    shape : str
        A name of ``aerostat_core.geometry.shapes.SHAPES``.

    Returns
    -------
    HullGeometry

    Notes
    -----
    Source: Khoury & Gillett (1999) for NPL; docs/methods.md §1.4, §1.13.

    Examples
    --------
    The 100 m3, l/d 2.7 hull: S = S_half(4.825, 2.068) + S_half(6.344, 2.068) = 119.97 m2:

    >>> g = hull_geometry(100.0, 2.7)
    >>> round(float(g.surface_area), 2)
    119.97
    """
    if shape != "npl":
        _shapes.shape_info(shape)
        if shape == "sphere":
            fineness_ratio = np.ones_like(np.asarray(fineness_ratio, dtype=float))
        return _profile_geometry(volume, fineness_ratio, shape)
    length, d, a1, a2, b = hull_dimensions(volume, fineness_ratio, nose_fraction)
    v = np.asarray(volume, dtype=float) * np.ones_like(length)
    s = half_spheroid_area(a1, b) + half_spheroid_area(a2, b)
    xi_cb = (a1 * (5.0 * a1 / 8.0) + a2 * (a1 + 3.0 * a2 / 8.0)) / length
    xi_s = _surface_moment(a1, a2, b) / s
    j1 = 0.5 * np.pi * b * length
    xi_j = (a1 * (a1 - 4.0 * a1 / (3.0 * np.pi)) + a2 * (a1 + 4.0 * a2 / (3.0 * np.pi))) / length
    k1, k2, kr = lamb_factors(np.asarray(fineness_ratio, dtype=float) * np.ones_like(length))
    return HullGeometry(
        volume=v,
        fineness_ratio=length / d,
        length=length,
        diameter=d,
        a1=a1,
        a2=a2,
        b=b,
        surface_area=s,
        xi_cb=xi_cb,
        xi_surface=xi_s,
        planform_area=j1,
        planform_centroid=xi_j,
        reference_area=v ** (2.0 / 3.0),
        k1=k1,
        k2=k2,
        k_rot=kr,
    )


def shape_integrals(g: HullGeometry, cutoff_station, moment_station):
    r"""Jones & DeLaurier hull integrals.

    .. math::

        I_1 = \int_0^{l_h} \frac{dA}{d\xi} d\xi = A(l_h) = \pi r(l_h)^2, \qquad
        I_3 = \int_0^{l_h} (\xi_m - \xi) \frac{dA}{d\xi} d\xi = (\xi_m - l_h) A(l_h) + V(0..l_h),

        J_1 = \int_0^l 2 r\, d\xi, \qquad J_2 = \int_0^l 2 r (\xi_m - \xi)\, d\xi
        = J_1 (\xi_m - \xi_{J_1})

    (I3 by parts; J1 = pi b l/2 for NPL).

    Parameters
    ----------
    g : HullGeometry
        The hull.
    cutoff_station : array_like
        l_h, station where the potential-flow term is cut off [m], valid 0 <= l_h <= l
        (clipped).
    moment_station : array_like
        xi_m, moment reference station [m].

    Returns
    -------
    I1 [m2], I3 [m3], J1 [m2], J2 [m3]

    Notes
    -----
    Valid for a slender body of revolution. Source: Jones & DeLaurier (1983), docs/methods.md
    §1.4 (S1).

    Examples
    --------
    Cut off at the tail, l_h = l: I1 = 0 and I3 = V (Munk's moment):

    >>> g = hull_geometry(100.0, 4.0)
    >>> i1, i3, j1, j2 = shape_integrals(g, g.length, 0.0)
    >>> round(float(i1), 9), round(float(i3), 9)
    (0.0, 100.0)
    """
    lh = np.clip(np.asarray(cutoff_station, dtype=float), 0.0, g.length)
    area = np.pi * g.radius_at(lh) ** 2
    i1 = area
    i3 = (moment_station - lh) * area + g.volume_to(lh)
    j1 = g.planform_area
    j2 = j1 * (moment_station - g.planform_centroid)
    return i1, i3, j1, j2


def profile_quadrature(g: HullGeometry):
    r"""Gauss-Legendre nodes along the hull for surface and volume integrals.

    .. math::

        \sum_j w_{s,j} F(\xi_j) \approx \int F\, dS
        = \int 2 \pi r \sqrt{1 + r'^2}\, F\, d\xi, \qquad
        \sum_j w_{v,j} F(\xi_j) \approx \int F\, dV = \int \pi r^2 F\, d\xi

    Parameters
    ----------
    g : HullGeometry
        The hull.

    Returns
    -------
    xi [m], r [m], w_s [m2], w_v [m3]
        Arrays of shape (..., 96) over a batch (NPL) or (..., QUAD_ORDER) (other shapes; GNVR's
        nodes are composite over its three pieces, shapes.profile_nodes).

    Notes
    -----
    Valid for the smooth profiles of the shape library (exact to about 1e-12).
    Source: Gauss-Legendre quadrature; docs/methods.md §1.6 (inertia integrals).

    Examples
    --------
    The weights reproduce the hull's volume and surface area:

    >>> g = hull_geometry(100.0, 4.0)
    >>> xi, r, ws, wv = profile_quadrature(g)
    >>> round(float(wv.sum()), 9), bool(np.isclose(ws.sum(), g.surface_area, rtol=1e-12))
    (100.0, True)
    """
    if g.shape != "npl":
        pd = _shapes.profile_data(g.shape)
        ln = np.asarray(g.length, dtype=float)[..., None]
        d = np.asarray(g.diameter, dtype=float)[..., None]
        f = ln / d
        ds = 2.0 * np.pi * d * ln * np.sqrt(pd.p + pd.dp**2 / (4.0 * f**2)) * pd.wx
        dv = np.pi * d**2 * pd.p * ln * pd.wx
        return ln * pd.x, d * np.sqrt(pd.p), ds, dv
    a1 = np.asarray(g.a1, dtype=float)[..., None]
    a2 = np.asarray(g.a2, dtype=float)[..., None]
    b = np.asarray(g.b, dtype=float)[..., None]
    u1 = 0.5 * (_GL_X - 1.0)
    u2 = 0.5 * (_GL_X + 1.0)
    xi = np.concatenate([a1 * (1.0 + u1), a1 + a2 * u2], axis=-1)
    half = xi[..., :48].shape
    u = np.concatenate([np.broadcast_to(u1, half), np.broadcast_to(u2, half)], axis=-1)
    a = np.concatenate([np.broadcast_to(a1, half), np.broadcast_to(a2, half)], axis=-1)
    jac = 0.5 * a * np.concatenate([_GL_W, _GL_W])
    r = b * np.sqrt(1.0 - u**2)
    ds = 2.0 * np.pi * b * np.sqrt(1.0 - u**2 + (b / a) ** 2 * u**2)
    dv = np.pi * r**2
    return xi, r, ds * jac, dv * jac
