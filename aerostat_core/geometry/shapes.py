"""Hull-shape library: the envelope profiles the thesis compares (§2.2.1, §2.4.3(a), Fig. 2.16).

Every hull is a body of revolution about the x (wind) axis. A shape is a dimensionless profile
P(x) = (r/d)^2 of x = xi/l in [0, 1] (r local radius, d maximum diameter, l length), stretched to a
fineness ratio f = l/d and scaled to a volume V:

    V = (pi/4) d^2 l C_p,   C_p = 4 int_0^1 P dx (prismatic coefficient)
    =>  d = (4 V / (pi f C_p))^(1/3),  l = f d.

Shapes (``SHAPES``):

* ``npl``: National Physical Laboratory double ellipsoid, maximum diameter at 0.432 l (Khoury &
  Gillett, *Airship Technology*, 1999; thesis §2.4.3(a), §3.1.3(a)). Keeps the closed forms of
  :mod:`aerostat_core.geometry.hull`.
* ``gnvr``: the piecewise GNVR profile (:func:`gnvr_profile`). The thesis (§2.4.3(a))
  describes GNVR, after G. N. V. Rao, as "a combination of an ellipse, circle, and parabola
  (Ram and Pant, 2010)" (Ram C.V., Pant R.S., "Multidisciplinary shape optimization of aerostat
  envelopes", J. Aircraft 47(3), 2010; NOT seen). The constants, in units of the maximum
  diameter d, are an elliptic nose (semi-axes 1.25 d and 0.5 d), a circular arc of radius 4 d
  to 2.875 d, and a parabolic tail r^2 = 0.1373 d (3.05 d - xi). They come from one
  unattributed public script that states no source (docs/methods.md S22). They are NOT Ram &
  Pant's paper read first-hand. Two independent public Gertler tables (S7, S14) corroborate
  them. The second gives GNVR l/d = 3.0500, which is this profile's 3.05. The computed C_p
  0.6175 lies within 0.2 % of that table's 0.6163 and 0.4 % of S7's 0.615. V/l^3 (0.05214)
  agrees with the S7 fit within 0.02 %.
  Other fineness ratios stretch the profile along the axis (P(x) kept, x = xi/l). That is an
  engineering choice, valid for f in [2, 6] as for the Gertler shapes. The published GNVR is
  f = 3.05.
* ``wang``, ``zhiyuan-1``, ``lotte``: Gertler (1950, DTMB Report 604) sixth-order polynomial
  FITS of the standard envelopes (the thesis' Fig. 2.16 set), with the parameters
  (m, r0, r1, C_p, l/d) of ``GERTLER_TABLE``. The table's GNVR row is kept as the Gertler fit
  the tests hold the piecewise profile against.

  Where these numbers come from (docs/methods.md §1.13, S7, S14): the table is the
  ``STANDARD_ENVELOPES`` table of public Gertler-envelope generator code (S7), which states no
  source. A second public copy of such a table gives GNVR (0.4143, 0.5999, 0.1762, 0.6163,
  3.0500), Zhiyuan-1 (0.4193, 0.3306, 0.2500, 0.6489, 3.2592) and Wang (0.4040, 0.6000, 0.1000,
  0.6100, 3.8540), within 0.4 % of ours on C_p and l/d. The project attributes the table to
  Alam & Pant (2017), "Multi-objective multidisciplinary design analyses and optimization of
  high altitude airships", *Aerosp. Sci. Technol.* 78, whose comparison set it matches. That
  paper was NOT seen, so the attribution is unverified.

  Other original shapes: Wang et al. (2009) (GA-optimised); Zhiyuan-1, Wang & Shan (2006), Wang
  et al. (2010); Lotte, Lutz et al., University of Stuttgart solar airship. None of these papers
  was seen either, and no volume or surface-area coefficient published for GNVR, Wang or
  Zhiyuan-1 was found. The tests check the fits against the two public tables (C_p, m, l/d),
  and GNVR's pieces against their closed forms. For Lotte, the published envelope (16 m long,
  4 m diameter, 109 m3; German Wikipedia "LOTTE (Luftschiff)", docs/methods.md S21) gives
  V/l^3 = 0.02661. The fit at its l/d 3.9019 gives 0.02667 (+0.22 %,
  tests/core/test_shape_sources.py).
* ``sphere``: f = 1. ``oblate``: oblate spheroid of revolution about the wind axis, f < 1 (the
  spheroid family below the sphere; a pumpkin-shaped balloon flattened vertically is not a body
  of revolution about x and is outside this model).
* ``helikite``: the spheroidal hull of a Helikite-style kite balloon, f about 1.24 (Table 2.2:
  6.2 m long, 5 m wide); the kite is in :mod:`aerostat_core.aerodynamics.helikite`.

The Gertler profile: P(x) = sum_{i=1..6} a_i x^i with
  P'(0) = 2 r0 (nose radius R0 = r0 d^2/l),  P(1) = 0,  P'(1) = -2 r1 (tail radius),
  P(m) = 1/4,  P'(m) = 0,  4 int_0^1 P dx = C_p,
six linear conditions for a_1..a_6 (the sphere, m = r0 = r1 = 0.5, C_p = 2/3, gives P = x - x^2).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import numpy as np

from aerostat_core.base.fields import check, choice, number, validate
from aerostat_core.base.validation import InputError

#: Gertler parameters (m = station of maximum diameter / l, r0 nose and r1 tail radius
#: parameters, C_p prismatic coefficient, standard l/d) of the standard envelopes: the table of
#: public Gertler-envelope code (docs/methods.md S7, no source stated there), attributed by the
#: project to Alam & Pant (2017) (Aerosp. Sci. Technol. 78; not seen, unverified). Fits, not the
#: shapes' original definitions (module docstring). The "gnvr" row is the fit only; the shape
#: itself is the piecewise :func:`gnvr_profile`.
GERTLER_TABLE = {
    "sphere": (0.5, 0.5, 0.5, 0.667, 1.000),
    "gnvr": (0.415, 0.600, 0.180, 0.615, 3.044),
    "zhiyuan-1": (0.419, 0.337, 0.251, 0.651, 3.266),
    "wang": (0.404, 0.600, 0.100, 0.610, 3.859),
    "npl": (0.432, 0.589, 0.425, 0.667, 4.000),
    "lotte": (0.4502, 0.5759, 0.10, 0.5170, 3.9019),
}


#: GNVR profile, lengths in units of the maximum diameter d (docs/methods.md §1.13, S22):
#: elliptic nose of semi-axes 1.25 d (axial) and 0.5 d, maximum diameter at 1.25 d; circular
#: arc of radius 4 d centred 3.5 d below the axis at 1.25 d, to 2.875 d; parabolic tail
#: r^2 = k d (3.05 d - xi) closing at l = 3.05 d.
GNVR_FINENESS = 3.05
GNVR_NOSE = 1.25
GNVR_ARC_RADIUS = 4.0
GNVR_ARC_CENTRE = 3.5
GNVR_ARC_END = 2.875
#: Tail parabola coefficient k [-]. The source gives 0.1373. The value that joins the arc at
#: 2.875 d is k = r(2.875 d)^2 / (0.175 d^2) = 0.137371, so 0.1373 is it truncated to four
#: digits (0.05 % low, which would leave a 4e-5 d step in radius). The joining value is used,
#: so the profile is continuous.
GNVR_TAIL_K = (
    (GNVR_ARC_RADIUS**2 - (GNVR_ARC_END - GNVR_NOSE) ** 2) ** 0.5 - GNVR_ARC_CENTRE
) ** 2 / (GNVR_FINENESS - GNVR_ARC_END)


def gnvr_profile(x):
    """GNVR profile P(x) = (r/d)^2 and dP/dx at x = xi/l in [0, 1] (values clipped to it).

    With u = F x (F = 3.05, stations in units of d):

    * nose, u <= 1.25: ellipse, P = 0.25 (1 - (u/1.25 - 1)^2);
    * middle, 1.25 <= u <= 2.875: circular arc, P = (sqrt(16 - (u - 1.25)^2) - 3.5)^2;
    * tail, u >= 2.875: parabola, P = k (F - u), with k = 0.137371 (GNVR_TAIL_K; the
      source's 0.1373 truncated).

    The ellipse and the arc meet at the maximum diameter with zero slope (C1). Arc and tail
    meet with equal radius and slopes within 0.4 % (-0.4446 and -0.4430 in dr/dxi), so the
    join is not exactly C1. Source: docs/methods.md §1.13, S22.

    Parameters
    ----------
    x : array_like
        Station from the nose as a fraction of the hull length, xi/l [-]; values outside
        [0, 1] are clipped. The published profile is the one at l/d = 3.05; other fineness
        ratios stretch it along the axis (``SHAPE_INFO["gnvr"]`` gives the range, 2-6,
        enforced by :func:`check_fineness`).

    Returns
    -------
    P, dP/dx : ndarray [-]
        (r/d)^2 and its derivative with respect to x, each of the shape of ``x``.
    """
    x = np.clip(np.asarray(x, dtype=float), 0.0, 1.0)
    f = GNVR_FINENESS
    u = f * x
    t = u / GNVR_NOSE - 1.0
    p_nose = 0.25 * (1.0 - t * t)
    dp_nose = -0.5 * t * f / GNVR_NOSE
    v = np.clip(u - GNVR_NOSE, 0.0, GNVR_ARC_RADIUS)
    sq = np.sqrt(GNVR_ARC_RADIUS**2 - v * v)
    p_arc = (sq - GNVR_ARC_CENTRE) ** 2
    dp_arc = -2.0 * (sq - GNVR_ARC_CENTRE) * v / sq * f
    p_tail = GNVR_TAIL_K * (f - u)
    dp_tail = -GNVR_TAIL_K * f * np.ones_like(u)
    nose, tail = u <= GNVR_NOSE, u >= GNVR_ARC_END
    p = np.where(nose, p_nose, np.where(tail, p_tail, p_arc))
    dp = np.where(nose, dp_nose, np.where(tail, dp_tail, dp_arc))
    return np.maximum(p, 0.0), dp


def gnvr_volume_fraction(x):
    """Q(x) = int_0^x P dx of the GNVR profile, in closed form for each piece [-].

    V(0..xi) = pi d^2 l Q(xi/l), and C_p = 4 Q(1).

    Nose: (1.25/F) (t - t^3/3 + 2/3) / 4 with t = F x/1.25 - 1. Arc: with v = F x - 1.25,
    int (sqrt(R^2 - v^2) - c)^2 dv = (R^2 + c^2) v - v^3/3 - c (v s + R^2 asin(v/R)),
    s = sqrt(R^2 - v^2). Tail: k F ((x - x2) - (x^2 - x2^2)/2).

    Parameters
    ----------
    x : array_like
        Station xi/l [-], clipped to [0, 1] (validity as :func:`gnvr_profile`).

    Returns
    -------
    ndarray [-]
        Q(x); Q(1) = C_p / 4 = 0.1544. Source: docs/methods.md §1.13, S22 (the integrals of
        the three pieces of :func:`gnvr_profile`).
    """
    x = np.clip(np.asarray(x, dtype=float), 0.0, 1.0)
    f, a, rr, c = GNVR_FINENESS, GNVR_NOSE, GNVR_ARC_RADIUS, GNVR_ARC_CENTRE

    def q_nose(u):
        t = np.minimum(u, a) / a - 1.0
        return 0.25 * (a / f) * (t - t**3 / 3.0 + 2.0 / 3.0)

    def g_arc(v):
        sq = np.sqrt(rr * rr - v * v)
        return (rr * rr + c * c) * v - v**3 / 3.0 - c * (v * sq + rr * rr * np.arcsin(v / rr))

    x2 = GNVR_ARC_END / f
    u = f * x
    v = np.clip(u - a, 0.0, GNVR_ARC_END - a)
    q_arc_end = q_nose(a) + (g_arc(GNVR_ARC_END - a) - g_arc(0.0)) / f
    xt = np.maximum(x, x2)
    q_tail = GNVR_TAIL_K * f * ((xt - x2) - (xt * xt - x2 * x2) / 2.0)
    q_arc = q_nose(a) + (g_arc(v) - g_arc(0.0)) / f
    return np.where(u <= a, q_nose(u), np.where(u <= GNVR_ARC_END, q_arc, q_arc_end + q_tail))


def profile_function(shape: str, x):
    """P(x) = (r/d)^2 and dP/dx [-] of a non-NPL shape at stations x = xi/l in [0, 1].

    Gertler shapes: P is the published polynomial in x (:func:`profile_coefficients`); GNVR:
    the piecewise :func:`gnvr_profile`. Source: docs/methods.md §1.13.

    Parameters
    ----------
    shape : str
        A key of :data:`SHAPE_INFO` whose family is "gertler" or "piecewise".
    x : array_like
        Station xi/l [-], clipped to [0, 1].

    Returns
    -------
    P, dP/dx : ndarray [-]
    """
    if SHAPE_INFO[shape].family == "piecewise":
        return gnvr_profile(x)
    pp = np.polynomial.Polynomial(profile_coefficients(shape))
    xc = np.clip(np.asarray(x, dtype=float), 0.0, 1.0)
    return pp(xc), pp.deriv()(xc)


def profile_volume_fraction(shape: str, x):
    """Q(x) = int_0^x P dx [-] of a non-NPL shape, so that V(0..xi) = pi d^2 l Q(xi/l) [m3].

    Exact for both families: the polynomial's integral (Gertler shapes) or the closed form of
    each GNVR piece (:func:`gnvr_volume_fraction`). Source: docs/methods.md §1.13.

    Parameters
    ----------
    shape : str
        A key of :data:`SHAPE_INFO` whose family is "gertler" or "piecewise".
    x : array_like
        Station xi/l [-], clipped to [0, 1].

    Returns
    -------
    ndarray [-]
    """
    if SHAPE_INFO[shape].family == "piecewise":
        return gnvr_volume_fraction(x)
    q = np.polynomial.Polynomial(profile_coefficients(shape)).integ()
    return q(np.clip(np.asarray(x, dtype=float), 0.0, 1.0))


@dataclass(frozen=True)
class ShapeInfo:
    """One hull shape of the library.

    Attributes
    ----------
    name : str
        Key (``HullSpec.shape``).
    label : str
        Display name.
    family : {"double-ellipsoid", "gertler", "piecewise", "spheroid"}
    fineness_range : (float, float)
        Fineness ratios l/d the shape is valid for [-] (inclusive).
    default_fineness : float
        Standard l/d of the published shape [-].
    streamlined : bool
        True: Jones & DeLaurier hull model and Hoerner's streamlined-body drag apply. False
        (bluff: sphere, oblate, Helikite hull): sphere drag versus Reynolds number, no fins.
    kite : bool
        True for the Helikite (kite lift and drag from :mod:`aerostat_core.aerodynamics.helikite`).
    source : str
        Where the profile comes from.
    """

    name: str
    label: str
    family: str
    fineness_range: tuple
    default_fineness: float
    streamlined: bool
    kite: bool
    source: str


SHAPE_INFO: dict[str, ShapeInfo] = {
    s.name: s
    for s in (
        ShapeInfo(
            "npl",
            "NPL double ellipsoid",
            "double-ellipsoid",
            (1.5, 8.0),
            4.0,
            True,
            False,
            "Khoury & Gillett (1999); thesis §2.4.3(a), §3.1.3(a)",
        ),
        ShapeInfo(
            "gnvr",
            "GNVR",
            "piecewise",
            (2.0, 6.0),
            GNVR_FINENESS,
            True,
            False,
            "Ellipse + circular arc + parabola (thesis §2.4.3(a), after Ram & Pant 2010, not "
            "seen); constants from an unattributed public script (docs/methods.md S22), "
            "agreeing with the Gertler tables S7/S14",
        ),
        ShapeInfo(
            "wang",
            "Wang",
            "gertler",
            (2.0, 6.0),
            3.859,
            True,
            False,
            "Wang et al. (2009); Gertler fit, public table (docs/methods.md S7, attributed to "
            "Alam & Pant 2017, unverified)",
        ),
        ShapeInfo(
            "zhiyuan-1",
            "Zhiyuan-1",
            "gertler",
            (2.0, 6.0),
            3.266,
            True,
            False,
            "Wang & Shan (2006), Wang et al. (2010); Gertler fit, public table "
            "(docs/methods.md S7, attributed to Alam & Pant 2017, unverified)",
        ),
        ShapeInfo(
            "lotte",
            "Lotte",
            "gertler",
            (2.0, 6.0),
            3.9019,
            True,
            False,
            "Lutz et al. (Univ. Stuttgart); Gertler fit, public table (docs/methods.md S7, "
            "attributed to Alam & Pant 2017, unverified)",
        ),
        ShapeInfo(
            "sphere",
            "Sphere",
            "spheroid",
            (1.0, 1.0),
            1.0,
            False,
            False,
            "thesis §2.2.1(a), Table 2.2",
        ),
        ShapeInfo(
            "oblate",
            "Oblate spheroid",
            "spheroid",
            (0.5, 0.95),
            0.75,
            False,
            False,
            "Lamb (1932) §373 (spheroid family below f = 1)",
        ),
        ShapeInfo(
            "helikite",
            "Helikite (kite balloon)",
            "spheroid",
            (1.0, 1.6),
            6.2 / 5.0,
            False,
            True,
            "Allsopp Helikites Ltd; thesis Table 2.2 (6.2 m x 5 m at 100 m3)",
        ),
    )
}
#: Valid values of ``HullSpec.shape``.
SHAPES = tuple(SHAPE_INFO)


def shape_info(shape: str) -> ShapeInfo:
    """The :class:`ShapeInfo` of ``shape``; an unknown name raises ``ValueError`` listing the
    valid ones."""
    try:
        return SHAPE_INFO[shape]
    except (KeyError, TypeError):
        raise ValueError(
            f"HullSpec.shape = {shape!r} is not a known hull shape; valid: {', '.join(SHAPES)}"
        ) from None


def check_fineness(shape: str, fineness_ratio) -> None:
    """Raise ``ValueError`` when a fineness ratio is outside the shape's valid range.

    The message names the field, the value, the shape and the range, e.g.
    ``HullSpec.fineness_ratio = 4 is outside the valid range [1, 1] for shape 'sphere'``.
    """
    lo, hi = shape_info(shape).fineness_range
    f = np.asarray(fineness_ratio, dtype=float)
    bad = ~np.isfinite(f) | (f < lo - 1e-9) | (f > hi + 1e-9)
    if np.any(bad):
        v = float(f[bad][0]) if f.ndim else float(f)
        reason = (f"is outside the valid range [{lo:g}, {hi:g}] for shape {shape!r} "
                  f"({shape_info(shape).label})")
        raise InputError(f"HullSpec.fineness_ratio = {v:g} {reason}", owner="HullSpec",
                         field="fineness_ratio", value=v, lo=lo, hi=hi, reason=reason)


@cache
def gertler_coefficients(m: float, r0: float, r1: float, cp: float) -> np.ndarray:
    """Coefficients a_1..a_6 of the Gertler profile P(x) = (r/d)^2 = sum a_i x^i.

    Solves the six linear conditions of the module docstring (Gertler 1950, DTMB Report 604).

    Parameters
    ----------
    m : float
        Station of maximum diameter / length [-], (0, 1).
    r0, r1 : float
        Nose and tail radius parameters R l / d^2 [-], >= 0.
    cp : float
        Prismatic coefficient [-], (0.4, 0.8).

    Returns
    -------
    ndarray, shape (7,)
        a_0 (= 0) .. a_6, lowest power first (``numpy.polynomial.polynomial`` order).

    Examples
    --------
    >>> np.round(gertler_coefficients(0.5, 0.5, 0.5, 2 / 3), 9)[:3].tolist()
    [0.0, 1.0, -1.0]
    """
    i = np.arange(1, 7, dtype=float)
    a = np.array(
        [
            np.where(i == 1, 1.0, 0.0),  # P'(0) = a1
            np.ones(6),  # P(1)
            i,  # P'(1)
            m**i,  # P(m)
            i * m ** (i - 1),  # P'(m)
            4.0 / (i + 1),  # C_p = 4 int P
        ]
    )
    rhs = np.array([2.0 * r0, 0.0, -2.0 * r1, 0.25, 0.0, cp])
    coef = np.linalg.solve(a, rhs)
    return np.concatenate([[0.0], coef])


def profile_coefficients(shape: str) -> np.ndarray:
    """Polynomial P(x) = (r/d)^2 of a non-NPL shape, lowest power first.

    Spheroids (sphere, oblate, Helikite hull) have P = x - x^2 at every fineness ratio (an
    ellipse stretched along x); the Gertler shapes use :func:`gertler_coefficients` with the
    parameters of ``GERTLER_TABLE`` (public table, docs/methods.md S7).
    """
    if shape in ("sphere", "oblate", "helikite"):
        return np.array([0.0, 1.0, -1.0])
    if shape in GERTLER_TABLE and SHAPE_INFO[shape].family == "gertler":
        m, r0, r1, cp, _ = GERTLER_TABLE[shape]
        return gertler_coefficients(m, r0, r1, cp)
    raise ValueError(
        f"shape {shape!r} has no polynomial profile (npl is a double ellipsoid, gnvr is "
        "piecewise: use profile_function)"
    )


def profile_radius_ratio(shape: str, x, nose_fraction: float = 0.432):
    """Dimensionless profile r/d at stations x = xi/l (0 outside [0, 1]).

    NPL: r/d = 0.5 sqrt(1 - ((x - m)/m)^2) forward of m = nose_fraction, with (1 - m) aft.
    Others: sqrt(max(P(x), 0)) (:func:`profile_function`).
    """
    x = np.asarray(x, dtype=float)
    if shape == "npl":
        m = nose_fraction
        a = np.where(x <= m, m, 1.0 - m)
        u = np.clip((x - m) / a, -1.0, 1.0)
        return 0.5 * np.sqrt(1.0 - u * u)
    p, _ = profile_function(shape, x)
    return np.sqrt(np.maximum(p, 0.0)) * ((x >= 0.0) & (x <= 1.0))


# --- quadrature on the dimensionless profile -----------------------------------------------
#: Gauss-Legendre order of the profile integrals (x = (1 - cos t)/2 makes every integrand
#: smooth at the nose and tail, where r ~ sqrt(x)); see tests/core/test_shapes.py for convergence.
QUAD_ORDER = 64


@cache
def _nodes(order: int):
    t, w = np.polynomial.legendre.leggauss(order)
    theta = 0.5 * np.pi * (t + 1.0)
    x = 0.5 * (1.0 - np.cos(theta))
    wx = w * 0.5 * np.pi * 0.5 * np.sin(theta)  # dx = sin(theta)/2 dtheta
    return x, wx


@dataclass(frozen=True)
class ProfileData:
    """Dimensionless quadrature data of one polynomial profile (see :func:`profile_data`).

    x, wx : nodes in [0, 1] and dx weights; p, dp : P(x), P'(x) at the nodes;
    cp : prismatic coefficient 4 int P dx; x_cv : centre of volume / l;
    planform : int 2 sqrt(P) dx (planform area / (d l)); x_planform : its centroid / l;
    coef : polynomial coefficients of P (lowest power first; empty for GNVR, which is
    piecewise); x_max : station of max r / l.
    """

    x: np.ndarray
    wx: np.ndarray
    p: np.ndarray
    dp: np.ndarray
    cp: float
    x_cv: float
    planform: float
    x_planform: float
    coef: np.ndarray
    x_max: float


def _piecewise_nodes(order: int):
    """Composite nodes of the GNVR profile: :func:`_nodes` on each of its three pieces.

    The pieces join with a jump in curvature, which a single Gauss rule over [0, 1] would
    integrate slowly. Per piece, every integrand is smooth, and the cosine spacing of each piece
    also covers the square-root ends at the nose and tail. Orders 3/8, 1/4, 3/8 of ``order``.
    """
    n1 = (3 * order) // 8
    n2 = order - 2 * n1
    edges = (0.0, GNVR_NOSE / GNVR_FINENESS, GNVR_ARC_END / GNVR_FINENESS, 1.0)
    xs, ws = [], []
    for (lo, hi), n in zip(zip(edges[:-1], edges[1:]), (n1, n2, n1)):
        x, w = _nodes(n)
        xs.append(lo + (hi - lo) * x)
        ws.append((hi - lo) * w)
    return np.concatenate(xs), np.concatenate(ws)


def profile_nodes(shape: str, order: int = QUAD_ORDER):
    """Quadrature nodes x in [0, 1] and dx weights for the profile integrals of ``shape``."""
    if SHAPE_INFO[shape].family == "piecewise":
        return _piecewise_nodes(order)
    return _nodes(order)


@cache
def profile_data(shape: str, order: int = QUAD_ORDER) -> ProfileData:
    """Quadrature nodes and the fineness-independent integrals of a non-NPL profile.

    C_p = 4 int P dx, x_cv = int x P dx / int P dx (exact for a polynomial P; for GNVR C_p is
    the closed form of :func:`gnvr_volume_fraction` and x_cv uses the composite nodes);
    planform J1/(d l) = 2 int sqrt(P) dx and its centroid, by Gauss-Legendre in t with
    x = (1 - cos t)/2 (per piece for GNVR, :func:`_piecewise_nodes`).
    """
    if SHAPE_INFO[shape].family == "piecewise":
        x, wx = profile_nodes(shape, order)
        p, dp = gnvr_profile(x)
        sq = np.sqrt(p)
        planform = 2.0 * np.sum(wx * sq)
        return ProfileData(
            x=x,
            wx=wx,
            p=p,
            dp=dp,
            cp=4.0 * float(gnvr_volume_fraction(1.0)),
            x_cv=float(np.sum(wx * x * p) / np.sum(wx * p)),
            planform=float(planform),
            x_planform=float(2.0 * np.sum(wx * sq * x) / planform),
            coef=np.zeros(0),
            x_max=GNVR_NOSE / GNVR_FINENESS,
        )
    coef = profile_coefficients(shape)
    pp = np.polynomial.Polynomial(coef)
    integ = pp.integ()
    xinteg = (pp * np.polynomial.Polynomial([0.0, 1.0])).integ()
    x, wx = _nodes(order)
    p = np.maximum(pp(x), 0.0)
    dp = pp.deriv()(x)
    sq = np.sqrt(p)
    planform = 2.0 * np.sum(wx * sq)
    x_pl = 2.0 * np.sum(wx * sq * x) / planform
    fine = np.linspace(0.0, 1.0, 20001)
    return ProfileData(
        x=x,
        wx=wx,
        p=p,
        dp=dp,
        cp=4.0 * float(integ(1.0)),
        x_cv=float(xinteg(1.0) / integ(1.0)),
        planform=float(planform),
        x_planform=float(x_pl),
        coef=coef,
        x_max=float(fine[np.argmax(pp(fine))]),
    )


def prismatic_coefficient(shape: str, nose_fraction: float = 0.432) -> float:
    """C_p = V / (pi d^2 l / 4) [-]: 2/3 for the NPL double ellipsoid and every spheroid.

    Examples
    --------
    >>> round(prismatic_coefficient("gnvr"), 4)
    0.6175
    """
    if shape == "npl":
        return 2.0 / 3.0
    return profile_data(shape).cp


def dimensions(shape: str, volume, fineness_ratio):
    """Length l and maximum diameter d [m] of a hull of given volume [m3] and l/d [-].

    d = (4 V / (pi f C_p))^(1/3), l = f d.
    """
    cp = prismatic_coefficient(shape)
    v = np.asarray(volume, dtype=float)
    f = np.asarray(fineness_ratio, dtype=float)
    d = np.cbrt(4.0 * v / (np.pi * f * cp))
    return f * d, d


# --- input spec -----------------------------------------------------------------------------
#: Widest fineness-ratio range over the shapes (each shape narrows it, ``SHAPE_INFO``).
_FINENESS_LO = min(s.fineness_range[0] for s in SHAPE_INFO.values())
_FINENESS_HI = max(s.fineness_range[1] for s in SHAPE_INFO.values())
_FINENESS_RANGES = ", ".join(
    f"{s.label} {lo:g}" + (f"-{hi:g}" if hi > lo else "")
    for s in SHAPE_INFO.values() for lo, hi in [s.fineness_range])


@dataclass(frozen=True)
class HullSpec:
    """The hull: its shape, fineness ratio and (optionally) volume.

    Parameters
    ----------
    fineness_ratio : float or None
        Length / maximum diameter f [-] (design variable 1), valid in the shape's range
        (``aerostat_core.geometry.shapes.SHAPE_INFO``: NPL [1.5, 8], Gertler shapes [2, 6], sphere 1,
        oblate [0.5, 0.95], Helikite [1, 1.6]); ``None`` takes the shape's standard value
        (4.0 for NPL).
    nose_fraction : float
        Station of maximum diameter / length, a1/l [-], valid [0.2, 0.8]; NPL standard 0.432
        (NPL only; the other profiles fix their own).
    volume : float or None
        Hull volume [m3], valid [1, 1e5]; ``None`` sizes the smallest hull that meets the blow-by
        limit at the design wind with positive free lift.
    shape : str
        Hull shape, one of ``aerostat_core.geometry.shapes.SHAPES``: "npl" (default), "gnvr", "wang",
        "zhiyuan-1", "lotte", "sphere", "oblate", "helikite".
    """

    fineness_ratio: float | None = number(
        None, "Fineness ratio l/d", "", _FINENESS_LO, _FINENESS_HI, checked=False, step=0.1,
        fmt="%.2f", help="Design variable 1: hull length / maximum diameter (NPL standard 4.0, "
        "tactical aerostats 2.9-3.1). The valid range depends on the shape: "
        + _FINENESS_RANGES + ".", source="aerostat_core.geometry.shapes.SHAPE_INFO")
    nose_fraction: float = number(
        0.432, "Max-diameter station a1/l", "", 0.2, 0.8, step=0.01, fmt="%.3f",
        help="Where the two ellipsoids meet; NPL standard 0.432.")
    volume: float | None = number(
        None, "Hull volume", "m3", 1.0, 1e5, empty="sized", step=10.0, fmt="%.1f",
        help="The thesis baseline is 170 m³; empty sizes the smallest hull that meets every "
        "constraint.")
    shape: str = choice(
        "npl", "Hull shape", SHAPES, source="aerostat_core.geometry.shapes",
        help="Envelope profile (Shapes page). Changing it resets l/d to the shape's standard "
        "value; sphere, oblate and Helikite hulls carry no fins.")

    def __post_init__(self) -> None:
        validate(self)  # the shape first: the fineness ratio's range depends on it
        if self.fineness_ratio is None:
            object.__setattr__(self, "fineness_ratio", SHAPE_INFO[self.shape].default_fineness)
        lo, hi = SHAPE_INFO[self.shape].fineness_range
        check(self, "fineness_ratio", lo=lo, hi=hi, reason_suffix=f" for shape {self.shape!r}")
