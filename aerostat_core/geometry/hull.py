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
    """Length, diameter and ellipse semi-axes of an NPL hull of given volume and fineness.

    V = (2/3) pi b^2 (a1 + a2) = (pi/6) d^2 l, f = l/d  =>  d = (6V/(pi f))^(1/3), l = f d,
    a1 = nose_fraction * l, a2 = l - a1, b = d/2.

    Parameters
    ----------
    volume : array_like
        Hull volume [m3], > 0.
    fineness_ratio : array_like
        l/d [-], valid 1.5-8 (the NPL shape is a standard at 4.0).
    nose_fraction : array_like
        a1/l [-], 0.432 for the NPL standard (public Gertler-envelope tables, docs/methods.md S7).

    Returns
    -------
    length, diameter, a1, a2, b : ndarray [m]

    Notes
    -----
    Source: Khoury & Gillett, *Airship Technology* (1999); thesis §3.1.3(a).

    Examples
    --------
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
    """Curved surface of half a spheroid with polar semi-axis ``a`` and equatorial radius ``b``.

    Prolate (a > b), e = sqrt(1 - b^2/a^2):  S = pi b^2 + pi a b arcsin(e)/e.
    Oblate  (a < b), e = sqrt(1 - a^2/b^2):  S = pi b^2 + (pi a^2/e) artanh(e).
    Sphere (a = b): 2 pi b^2.

    Parameters
    ----------
    a, b : array_like
        Semi-axes [m], > 0.

    Returns
    -------
    ndarray
        Area [m2].

    Examples
    --------
    >>> round(float(half_spheroid_area(1.0, 1.0)), 6) == round(2 * np.pi, 6)
    True
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
    """Local hull radius r(xi) [m] of the NPL profile (zero outside the hull).

    r = b sqrt(1 - ((a1 - xi)/a1)^2) for 0 <= xi <= a1, and b sqrt(1 - ((xi - a1)/a2)^2) for
    a1 <= xi <= a1 + a2.  Source: thesis Fig. 3.4; docs/methods.md §1.4.
    """
    xi = np.asarray(xi, dtype=float)
    a = np.where(xi <= a1, a1, a2)
    u = np.clip((xi - a1) / a, -1.0, 1.0)
    return b * np.sqrt(1.0 - u * u)


def volume_to_station(xi, a1, a2, b):
    """Hull volume between the nose and station ``xi`` [m3] (closed form).

    With u = (xi - a1)/a:  V(xi) = pi b^2 a1 (u - u^3/3 + 2/3) in the forebody and
    (2/3) pi b^2 a1 + pi b^2 a2 (u - u^3/3) in the afterbody.
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
    """Build :class:`HullGeometry` from volume [m3], fineness ratio [-], a1/l [-] and shape.

    ``shape`` other than ``"npl"`` is integrated from its profile (:func:`_profile_geometry`;
    ``nose_fraction`` applies to NPL only); the sphere always has l/d = 1.

    Closed forms (docs/methods.md §1.4): S = S_half(a1, b) + S_half(a2, b);
    xi_CB = [a1 (5 a1/8) + a2 (a1 + 3 a2/8)] / (a1 + a2) (half-ellipsoid centroids 3a/8 from the
    base, volumes in proportion to a1, a2); planform J1 = pi b l / 2 with centroid
    [a1 (a1 - 4 a1/(3 pi)) + a2 (a1 + 4 a2/(3 pi))] / l.

    Examples
    --------
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
    """Jones & DeLaurier hull integrals (docs/methods.md §1.4, source S1).

    I1 = int_0^{l_h} dA/dxi dxi = A(l_h) = pi r(l_h)^2
    I3 = int_0^{l_h} (xi_m - xi) dA/dxi dxi = (xi_m - l_h) A(l_h) + V(0..l_h)   (by parts)
    J1 = int_0^l 2 r dxi = pi b l / 2
    J2 = int_0^l 2 r (xi_m - xi) dxi = J1 (xi_m - xi_J1)

    Parameters
    ----------
    g : HullGeometry
    cutoff_station : array_like
        l_h, station where the potential-flow term is cut off [m], 0 <= l_h <= l.
    moment_station : array_like
        xi_m, moment reference station [m].

    Returns
    -------
    I1 [m2], I3 [m3], J1 [m2], J2 [m3]

    Notes
    -----
    Check: l_h = l gives I1 = 0 and I3 = V (Munk's moment).
    """
    lh = np.clip(np.asarray(cutoff_station, dtype=float), 0.0, g.length)
    area = np.pi * g.radius_at(lh) ** 2
    i1 = area
    i3 = (moment_station - lh) * area + g.volume_to(lh)
    j1 = g.planform_area
    j2 = j1 * (moment_station - g.planform_centroid)
    return i1, i3, j1, j2


def profile_quadrature(g: HullGeometry):
    """Gauss-Legendre nodes along the hull for surface and volume integrals.

    Returns stations xi [m], radii r [m], surface weights w_s (so that sum(w_s F(xi)) =
    int F dS) [m2] and volume weights w_v (sum(w_v F) = int F dV) [m3]; arrays of shape
    (..., 96) over a batch (NPL) or (..., QUAD_ORDER) (other shapes; GNVR's nodes are
    composite over its three pieces, shapes.profile_nodes).
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
