"""Compiled Heun march of the static tether (numba): the loop of
:func:`aerostat_core.tether.statics.march`, all columns of a batch in one call.

The numpy form of the march spends its time in numpy's per-call overhead (~25 calls a segment,
~1,250 a 50-segment line, whatever the batch width); this kernel steps every column and segment
in one compiled loop with the plain real arithmetic of
:func:`aerostat_core.tether.statics._line_load`. Importing this module imports numba; the kernel
is compiled on its first call (``cache=True``: later processes load it from ``__pycache__``). It
calls no kernel of another module, so numba's cache, keyed on this file's time stamp, cannot go
stale (see :mod:`aerostat_core.dynamics.kernel_cache` for the case where it can).

``error_model="numpy"``: divisions follow IEEE 754 as in numpy instead of raising
ZeroDivisionError, whose per-division check keeps the compiler from vectorising the loop over
columns (about 3 times slower on wide batches). The only divisor is |T| + 1e-300, never zero.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit


@njit(cache=True, error_model="numpy", inline="always")
def _load(tx, tz, u, kn, kt, w_line, inv_ea):  # pragma: no cover - compiled
    """The line load and slope of ``statics._line_load`` at one node, plain real arithmetic:
    tension (tx, tz) [N], wind u [m/s]; returns dT_x/ds, dT_z/ds [N/m] and dX/ds, dZ/ds [-]
    (stretched line, normal and tangential drag by the cross-flow principle, weight w_line)."""
    t = math.sqrt(tx * tx + tz * tz) + 1e-300
    ct = tx / t
    st = tz / t
    un = u * st
    ut = u * ct
    fn = kn * abs(un) * un
    ft = kt * abs(ut) * ut
    stretch = 1.0 + t * inv_ea
    return fn * st + ft * ct, ft * st - fn * ct - w_line, stretch * ct, stretch * st


@njit(cache=True, error_model="numpy")
def heun_march(tx0, tz0, u, kn, kt, w_line, inv_ea, ds):  # pragma: no cover - compiled
    """Heun's method for the tether ODE of :func:`aerostat_core.tether.statics.march` (its
    equation, units and validity) with the line load of ``statics._line_load``.

    tx0, tz0, kn, kt : float64[n] (top tension [N], 1/2 rho d C_dn and 1/2 rho pi d C_dt
    [kg/m2] per column); u : float64[segments + 1, n] wind at the nodes [m/s]; w_line [N/m],
    inv_ea = 1/EA [1/N], ds = length/segments [m]. Returns float64[4, segments + 1, n]:
    T_x, T_z, X, Z (offsets from the top) at every node.
    """
    nodes, n = u.shape
    out = np.empty((4, nodes, n))
    h = 0.5 * ds
    for j in range(n):
        out[0, 0, j] = tx0[j]
        out[1, 0, j] = tz0[j]
        out[2, 0, j] = 0.0
        out[3, 0, j] = 0.0
    for i in range(nodes - 1):
        for j in range(n):
            tx = out[0, i, j]
            tz = out[1, i, j]
            knj = kn[j]
            ktj = kt[j]
            # first stage: the load at the node
            fx1, fz1, cx1, cz1 = _load(tx, tz, u[i, j], knj, ktj, w_line, inv_ea)
            # second stage: the load at the Euler predictor, with the next node's wind
            fx2, fz2, cx2, cz2 = _load(tx + ds * fx1, tz + ds * fz1, u[i + 1, j], knj, ktj,
                                       w_line, inv_ea)
            out[0, i + 1, j] = tx + h * (fx1 + fx2)
            out[1, i + 1, j] = tz + h * (fz1 + fz2)
            out[2, i + 1, j] = out[2, i, j] - h * (cx1 + cx2)
            out[3, i + 1, j] = out[3, i, j] - h * (cz1 + cz2)
    return out
