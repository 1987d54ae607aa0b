"""Envelope structure: the internal pressure the hull needs, the membrane stresses it makes and
the fabric strength that carries them (issue 13 item 4; docs/methods.md §1.14).

Where the rules come from: the membrane loads are thin-shell statics; the pressure factor 1.2
and the safety factor 4 have no primary source found (docs/methods.md S18) and are inputs with
those defaults (constants.PRESSURE_DYNAMIC_FACTOR, constants.ENVELOPE_SAFETY_FACTOR).
"""

from __future__ import annotations

import numpy as np


def required_pressure(q, rho_air, rho_gas, g, diameter, factor):
    """Internal pressure needed at the top of the hull [Pa].

    p_req = factor q + (rho_air - rho_gas) g d: at least ``factor`` times the dynamic pressure
    at the lowest point of the hull (nose dimpling), plus the hydrostatic gas head, by which
    the pressure difference across the fabric grows from the bottom to the top.

    Parameters
    ----------
    q : array_like
        Dynamic pressure 0.5 rho U^2 [Pa].
    rho_air, rho_gas : array_like
        Air and lifting-gas densities [kg/m3].
    g : float
        [m/s2].
    diameter : array_like
        Hull maximum diameter [m].
    factor : float
        p / q rule [-] (constants.PRESSURE_DYNAMIC_FACTOR, 1.2).

    Notes
    -----
    Valid for a non-rigid, streamlined hull trimmed at small angle of attack (the stagnation
    pressure on the nose is about q); gusts and pitch raise the local pressure, which the
    factor and the fabric safety factor cover. Sources: the head term is the hydrostatics of a
    gas column of height d; the factor 1.2 is the rule of thumb quoted in issue 13, for which
    no primary source was found (constants.PRESSURE_DYNAMIC_FACTOR, docs/methods.md S18), so it
    is an engineering margin over the stagnation pressure q.

    Examples
    --------
    >>> round(float(required_pressure(100.0, 1.2, 0.2, 10.0, 4.0, 1.2)), 1)
    160.0
    """
    head = (np.asarray(rho_air) - np.asarray(rho_gas)) * g * np.asarray(diameter)
    return factor * np.asarray(q, float) + head


def membrane_loads(pressure, radius, moment=0.0):
    """Hoop and longitudinal membrane loads of a pressurised hull section [N/m].

    N_hoop = p r; N_long = p r/2 + |M|/(pi r^2) (thin-walled cylinder of radius r with a
    bending moment M about the section: the hoop and axial membrane loads of a closed pressure
    vessel, and the peak axial load M/(pi r^2) of a thin circular section in bending, of
    second moment pi r^3 per unit wall thickness). Source: thin-shell statics, derived here;
    no airship text was available to cross-check it.

    Valid for a thin membrane (fabric thickness << r), away from the nose and tail caps and the
    fin and confluence-line attachments (local patches carry those loads).

    Parameters
    ----------
    pressure : array_like
        Pressure difference across the fabric [Pa].
    radius : array_like
        Section radius [m] (the hull's maximum radius is the critical section for hoop load).
    moment : array_like
        Bending moment at the section [N m].

    Returns
    -------
    n_hoop, n_long : ndarray
        Hoop and longitudinal membrane loads [N/m].

    Examples
    --------
    >>> [float(x) for x in membrane_loads(200.0, 2.0)]
    [400.0, 200.0]
    """
    p, r = np.asarray(pressure, float), np.asarray(radius, float)
    return p * r, 0.5 * p * r + np.abs(np.asarray(moment, float)) / (np.pi * r**2)


def allowable_pressure(strength, safety_factor, radius, moment=0.0):
    """Largest pressure the fabric carries with the safety factor [Pa].

    From N_hoop and N_long <= F/SF: p <= F/(SF r) and p <= 2 (F/SF - |M|/(pi r^2))/r.

    Parameters
    ----------
    strength : float
        Fabric tensile strength F [N/m] (the weaker warp/fill direction).
    safety_factor : float
        [-] (default 4, constants.ENVELOPE_SAFETY_FACTOR: attributed to Carichner & Nicolai,
        unverified).
    radius : array_like
        [m].
    moment : array_like
        [N m].

    Notes
    -----
    Valid with the thin-membrane loads of :func:`membrane_loads`; a bending moment larger than
    pi r^2 F/SF makes the allowable pressure negative (the hull creases whatever the pressure).
    """
    r = np.asarray(radius, float)
    n = float(strength) / float(safety_factor)
    hoop = n / r
    long = 2.0 * (n - np.abs(np.asarray(moment, float)) / (np.pi * r**2)) / r
    return np.minimum(hoop, long)
