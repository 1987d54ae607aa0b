"""Reference numbers (thesis, docs/methods.md, docs/dynamics.md) next to what the engine gives now.

:func:`reference_checks` feeds the app's Method page and the validation tests, so the numbers a
user sees are the numbers CI checks. ``kind`` says whether a number was used to calibrate the
preset ("calibrated"), is a prediction of the model ("predicted"), or is an independent
textbook/solver check ("check").
"""

from __future__ import annotations

import numpy as np

from aerostat_core.atmosphere.standard import isa
from aerostat_core.base.constants import THESIS_HELIUM_DENSITY
from aerostat_core.geometry.added_mass import lamb_factors
from aerostat_core.geometry.hull import half_spheroid_area, hull_geometry
from aerostat_core.model.design import design
from aerostat_core.model.presets import thesis_baseline
from aerostat_core.structures.materials import TetherSpec
from aerostat_core.tether.statics import point_aerostat_tether

#: Lamb's tabulated inertia factors (l/d, k1, k2, k'), Lamb (1932) / Munk, as quoted in
#: airship texts (e.g. Khoury & Gillett 1999, Table 5.1).
LAMB_TABLE = (
    (1.50, 0.305, 0.621, 0.094),
    (2.00, 0.209, 0.702, 0.240),
    (2.51, 0.156, 0.763, 0.367),
    (2.99, 0.122, 0.803, 0.465),
    (3.99, 0.082, 0.860, 0.608),
    (4.99, 0.059, 0.895, 0.701),
    (6.01, 0.045, 0.918, 0.764),
    (6.97, 0.036, 0.933, 0.805),
    (8.01, 0.029, 0.945, 0.840),
    (9.02, 0.024, 0.954, 0.865),
    (9.97, 0.021, 0.960, 0.883),
)

#: docs/dynamics.md §3.1 case P: point aerostat, 320 m elastic tether, rho 1.225, g 9.81.
CASE_P = {
    "mass": 71.6, "volume": 120.0, "drag_area": 1.0, "length": 320.0, "rho": 1.225, "g": 9.81,
    "tether": TetherSpec("case P", 0.02, 0.004, 1.2, 0.01, 1.0e5, 1.0e6),
}


def case_p_static(wind) -> tuple[float, float]:
    """Aerostat (x, z) [m] of docs/dynamics.md case P for a wind function ``wind(z)`` [m/s]."""
    p = CASE_P
    s = point_aerostat_tether(p["mass"], p["volume"], p["drag_area"], p["tether"], p["length"],
                              p["rho"], wind, p["g"], segments=200)
    return float(s.blow_by), float(s.height)


def _row(name, reference, value, unit, tol_pct, kind, source):
    err = 100.0 * (value - reference) / reference if reference else value - reference
    return {"name": name, "reference": float(reference), "value": float(value), "unit": unit,
            "error_pct": float(err), "tolerance_pct": float(tol_pct), "kind": kind,
            "source": source, "passed": bool(abs(err) <= tol_pct)}


def reference_checks() -> list[dict]:
    """Every reference number with the engine's value and relative error [%].

    Returns
    -------
    list of dict
        Keys: name, reference, value, unit, error_pct, tolerance_pct, kind
        ("calibrated" | "predicted" | "check"), source, passed.
    """
    rows = []
    g = hull_geometry(100.0, 2.7)
    rows.append(_row("Table 2.2 NPL hull fabric mass (100 m3, f 2.7, 130 g/m2)", 15.57,
                     0.130 * float(g.surface_area), "kg", 1.0, "predicted",
                     "thesis Table 2.2"))
    d_sphere = (6 * 100.0 / np.pi) ** (1 / 3)
    rows.append(_row("Table 2.2 sphere hull fabric mass (100 m3)", 13.54,
                     0.130 * float(2 * half_spheroid_area(d_sphere / 2, d_sphere / 2)), "kg", 1.0,
                     "calibrated", "thesis Table 2.2 (fixes 130 g/m2)"))
    heli = hull_geometry(100.0, 6.2 / 5.0, 0.432, "helikite")
    rows.append(_row("Table 2.2 Helikite hull fabric mass (100 m3 spheroid, l/d 6.2/5)", 13.72,
                     0.130 * float(heli.surface_area), "kg", 2.0, "predicted",
                     "thesis Table 2.2"))
    rows.append(_row("Table 2.2 helium mass (100 m3, 0.169 kg/m3)", 16.9,
                     THESIS_HELIUM_DENSITY * 100.0, "kg",
                     0.5, "calibrated", "thesis Table 2.2 / Table 2.5"))
    req, cfg = thesis_baseline()
    from dataclasses import replace

    t22 = design(replace(req, altitude=300.0),
                 cfg.with_design_variables(fineness_ratio=2.7, volume=100.0))
    rows.append(_row("Table 2.2 fin mass (100 m3, f 2.7)", 7.8,
                     float(t22.airframe.mass.items["fins"]), "kg", 1.0, "calibrated",
                     "thesis Table 2.2 (fixes the fin area ratio)"))
    rows.append(_row("Table 2.2 miscellaneous mass", 4.7,
                     float(t22.airframe.mass.items["miscellaneous"]), "kg", 1.0, "calibrated",
                     "thesis Table 2.2 (fixes misc = 0.30 x hull)"))
    base = design(req, cfg)
    rows.append(_row("Baseline total mass (10 kg at 300 m, 170 m3)", 90.65, base.total_mass, "kg",
                     2.0, "predicted", "thesis abstract"))
    for h, rho in ((0.0, 1.2250), (100.0, 1.2133), (300.0, 1.1901), (500.0, 1.1673)):
        rows.append(_row(f"ISA air density at {h:g} m", rho, float(isa(h).density), "kg/m3",
                         0.01, "check", "ISO 2533 (docs/methods.md §1.2)"))
    for f, k1, k2, kr in LAMB_TABLE[1::3]:
        c1, c2, cr = (float(x) for x in lamb_factors(f))
        rows.append(_row(f"Lamb k1 at l/d {f:g}", k1, c1, "-", 1.5, "check", "Lamb (1932)"))
        rows.append(_row(f"Lamb k2 at l/d {f:g}", k2, c2, "-", 0.5, "check", "Lamb (1932)"))
        rows.append(_row(f"Lamb k' at l/d {f:g}", kr, cr, "-", 1.0, "check", "Lamb (1932)"))
    x1, z1 = case_p_static(lambda z: 10.0 * np.ones_like(np.asarray(z, float)))
    rows.append(_row("R1 point aerostat blow-by (U 10 m/s)", 48.539, x1, "m", 0.1, "check",
                     "docs/dynamics.md §3.1 (MoorDyn + shooting solver)"))
    rows.append(_row("R1 point aerostat height", 316.253, z1, "m", 0.02, "check",
                     "docs/dynamics.md §3.1"))
    x2, z2 = case_p_static(lambda z: 6.0 * (np.maximum(np.asarray(z, float), 1e-9) / 10) ** (1 / 7))
    rows.append(_row("R2 point aerostat blow-by (power law)", 44.443, x2, "m", 0.1, "check",
                     "docs/dynamics.md §3.1"))
    rows.append(_row("R2 point aerostat height", 316.958, z2, "m", 0.02, "check",
                     "docs/dynamics.md §3.1"))
    rows.append(_row("Helium cost of 50 m3", 1925.0, 50.0 * cfg.gas_price_value, "USD", 0.1,
                     "calibrated", "thesis abstract (USD 1925 for -50 m3)"))
    return rows
