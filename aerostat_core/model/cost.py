"""Lifting-gas fill cost (thesis Appendix H)."""

from __future__ import annotations

import numpy as np


def gas_fill_cost(volume, price_per_m3):
    """Cost of filling the hull once [USD]: C = V * price.

    Parameters
    ----------
    volume : array_like
        Hull volume [m3] (the fill at operating conditions; purity top-ups and leakage ignored).
    price_per_m3 : float
        Gas price [USD/m3]; helium default 38.5 USD/m3 (INFERRED: USD 1925 per 50 m3, thesis
        abstract).

    Examples
    --------
    >>> float(gas_fill_cost(50.0, 38.5))
    1925.0
    """
    return np.asarray(volume, float) * price_per_m3
