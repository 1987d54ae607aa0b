"""Zero-lift drag of the hull versus shape, fineness ratio and Reynolds number."""

from __future__ import annotations

import numpy as np

from aerostat_core.aerodynamics.forces import hoerner_volumetric_drag
from aerostat_core.geometry.shapes import SHAPE_INFO

# --- drag ------------------------------------------------------------------------------------
#: Sphere drag coefficient on frontal area versus Reynolds number on diameter, read from the
#: measurements of Achenbach (1972), "Experiments on the flow past spheres at very high Reynolds
#: numbers", J. Fluid Mech. 54(3) (smooth sphere; subcritical value 0.47 from Hoerner 1965 ch. 3).
#: Approximate readings (+-0.02), interpolated in log Re; held constant outside 1e4-1e7.
SPHERE_DRAG_TABLE = (
    (1.0e4, 0.47),
    (1.0e5, 0.47),
    (2.0e5, 0.45),
    (3.0e5, 0.30),
    (4.0e5, 0.09),
    (6.0e5, 0.10),
    (1.0e6, 0.13),
    (2.0e6, 0.16),
    (3.0e6, 0.18),
    (5.0e6, 0.20),
    (1.0e7, 0.20),
)


def sphere_drag_coefficient(reynolds_d):
    """Drag coefficient of a smooth sphere on frontal area, C_D(Re_d) (Achenbach 1972).

    Parameters
    ----------
    reynolds_d : array_like
        Reynolds number on diameter [-]; valid 1e4-1e7 (clamped outside).

    Notes
    -----
    A tethered sphere in natural (turbulent) wind measured C_D = 0.56 (Coulombe-Pontbriand &
    Nahon 2009, thesis §2.2.1(a)); pass that as ``AeroModel.hull_axial_drag`` (on V^(2/3):
    0.56 x 1.209) to model a rough, gusty site.
    """
    re = np.clip(np.asarray(reynolds_d, dtype=float), 1e4, 1e7)
    lr, cd = np.log10([r for r, _ in SPHERE_DRAG_TABLE]), [c for _, c in SPHERE_DRAG_TABLE]
    return np.interp(np.log10(re), lr, cd)


def volumetric_drag_coefficient(shape: str, fineness_ratio, reynolds):
    """Zero-lift hull drag coefficient on V^(2/3) versus l/d and length Reynolds number.

    Streamlined shapes (NPL, Gertler): Hoerner's C_DV(f, Re_l) (:func:`aerostat_core.aerodynamics.forces.hoerner_volumetric_drag`).
    Bluff shapes (sphere, oblate, Helikite hull): C_DV = C_D,sphere(Re_d) (pi d^2/4)/V^(2/3)
    with Re_d = Re_l / f (frontal area of the spheroid; Achenbach 1972 for the sphere, used for
    spheroids of l/d 0.5-1.6 as Hoerner 1965 ch. 3 shows supercritical ellipsoid drag of the
    same order).

    Parameters
    ----------
    shape : str
    fineness_ratio : array_like
        l/d [-].
    reynolds : array_like
        Reynolds number on hull length [-].

    Examples
    --------
    >>> round(float(volumetric_drag_coefficient("npl", 4.0, 1.72e7)), 4)
    0.0215
    >>> round(float(volumetric_drag_coefficient("sphere", 1.0, 5e6)), 3)
    0.242
    """
    f = np.asarray(fineness_ratio, dtype=float)
    if SHAPE_INFO[shape].streamlined:
        return hoerner_volumetric_drag(f, reynolds)
    # frontal / V^(2/3) for a spheroid of l/d = f: (pi/4)/((pi/6) f)^(2/3)
    ratio = (np.pi / 4.0) / ((np.pi / 6.0) * f) ** (2.0 / 3.0)
    return sphere_drag_coefficient(np.asarray(reynolds, dtype=float) / f) * ratio
