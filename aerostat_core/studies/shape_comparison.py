"""The thesis' hull-shape comparison (§2.2.1(b), Tables 2.1-2.2, Figure 2.5), then the full model.

:func:`thesis_shape_comparison` reproduces Table 2.2 and Figure 2.5 with the thesis' own
assumptions (the preset :data:`THESIS_SHAPE_PRESET`): equal 100 m3 hulls at 300 m, buoyancy
100 kg (1.0 kg of gross lift per m3, as the table states), tether sag ignored (a straight tether
at the angle of the resultant force at the top), the streamlined hull's lift ignored, the
table's drag coefficients (0.2 Helikite and sphere, 0.03 streamlined), hull fabric 130 g/m2,
helium 0.169 kg/m3, tether 20 g/m, fins 7.8 kg and miscellaneous 4.7 kg on the streamlined
(NPL, f = 2.7) hull only, kite 11.38 kg with 48 kg of dynamic lift at 15 m/s (scaled with q).
Reference areas (the thesis does not state them): frontal area pi d^2/4 for the bluff hulls
(sphere drag convention) and V^(2/3) for the streamlined hull (airship convention).

:func:`full_model_shape_comparison` designs the same three hulls with the whole engine
(:func:`aerostat_core.model.design.design`): ISA buoyancy, shape drag correlations, trim, hull and fin
lift, tether sag and weight; :func:`comparison_notes` explains the differences.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from aerostat_core.atmosphere.standard import isa
from aerostat_core.base import constants as c
from aerostat_core.geometry.shapes import SHAPE_INFO, dimensions
from aerostat_core.model.design import Design, design
from aerostat_core.model.inputs import HullSpec
from aerostat_core.model.presets import thesis_configuration, thesis_requirement

#: The three shapes of Table 2.2, in the thesis' column order: key -> (label, shape, l/d).
TABLE_SHAPES = {
    "helikite": ("Helikite", "helikite", SHAPE_INFO["helikite"].default_fineness),
    "sphere": ("Spherical", "sphere", 1.0),
    "streamlined": ("Streamlined (NPL, f = 2.7)", "npl", 2.7),
}

#: Thesis Table 2.2 as printed (kg unless stated; lengths m): the reference for the test and view.
THESIS_TABLE_2_2 = {
    "helikite": {
        "length": 6.2,
        "width": 5.0,
        "helium": 16.9,
        "hull": 13.72,
        "kite": 11.38,
        "fins": 0.0,
        "misc": 0.0,
        "tether": 6.0,
        "total": 48.0,
        "free_lift": 52.0,
        "dynamic_lift": 48.0,
        "cd": 0.2,
    },
    "sphere": {
        "length": 5.76,
        "width": 5.76,
        "helium": 16.9,
        "hull": 13.54,
        "kite": 0.0,
        "fins": 0.0,
        "misc": 0.0,
        "tether": 6.0,
        "total": 36.45,
        "free_lift": 63.55,
        "dynamic_lift": 0.0,
        "cd": 0.2,
    },
    "streamlined": {
        "length": 11.2,
        "width": 4.1,
        "helium": 16.9,
        "hull": 15.57,
        "kite": 0.0,
        "fins": 7.8,
        "misc": 4.7,
        "tether": 6.0,
        "total": 50.92,
        "free_lift": 47.0,
        "dynamic_lift": 0.0,
        "cd": 0.03,
    },
}


@dataclass(frozen=True)
class ShapePreset:
    """The thesis' assumptions for Table 2.2 / Figure 2.5 (SI; masses in kg).

    volume [m3], altitude [m], gross_lift_per_m3 [kg/m3] (buoyancy "100 kg" for 100 m3),
    fabric_areal_density [kg/m2], helium_density [kg/m3], tether_linear_density [kg/m],
    fin_mass, misc_mass [kg] (streamlined only), kite_mass [kg], kite_lift_kg [kg] at
    kite_lift_wind [m/s], drag_coefficients {key: C_D}, max_wind [m/s], wind_step [m/s].
    """

    volume: float = 100.0
    altitude: float = 300.0
    gross_lift_per_m3: float = 1.0
    fabric_areal_density: float = 0.130
    helium_density: float = c.THESIS_HELIUM_DENSITY
    tether_linear_density: float = 0.020
    fin_mass: float = 7.8
    misc_mass: float = 4.7
    kite_mass: float = c.HELIKITE_REF_KITE_MASS
    kite_lift_kg: float = c.HELIKITE_REF_DYNAMIC_LIFT_KG
    kite_lift_wind: float = c.HELIKITE_REF_WIND
    drag_coefficients: tuple = (("helikite", 0.2), ("sphere", 0.2), ("streamlined", 0.03))
    max_wind: float = 15.0
    wind_step: float = 0.5


#: The preset of the thesis' comparison (Table 2.2).
THESIS_SHAPE_PRESET = ShapePreset()


@dataclass(frozen=True)
class ShapeComparison:
    """Result of a shape comparison.

    rows : list of dict, one per shape (keys: key, label, shape, length_m, width_m, buoyancy_kg,
        helium_kg, hull_kg, kite_kg, fins_kg, misc_kg, tether_kg, total_kg, free_lift_kg,
        dynamic_lift_kg (at the design wind), drag_coefficient, reference_area_m2,
        blow_by_at_design_wind_m);
    wind : ndarray [m/s]; blow_by : {key: ndarray [m]} (Figure 2.5 curves).
    """

    rows: list
    wind: np.ndarray
    blow_by: dict


def _straight_tether_blow_by(length, drag, lift_up):
    """Blow-by of a straight (sag-free) tether [m]: L sin(atan2(D, T_z)), T_z = up force [N]."""
    return length * np.sin(np.arctan2(drag, lift_up))


def thesis_shape_comparison(preset: ShapePreset = THESIS_SHAPE_PRESET) -> ShapeComparison:
    """Table 2.2 and Figure 2.5 with the thesis' assumptions (module docstring).

    For each shape: d, l from the shape library at 100 m3; masses from fabric area x 130 g/m2,
    helium 0.169 V, tether 0.020 x 300 m (+ fins and misc for the streamlined hull, + kite for
    the Helikite); free lift = buoyancy - total; drag D = q C_D A_ref, q = rho_ISA(300 m) U^2/2;
    dynamic lift (Helikite only) = 48 kg (U/15)^2; blow-by of a straight tether
    L sin(atan2(D, (free lift + dynamic lift) g)).

    Returns
    -------
    ShapeComparison
    """
    from aerostat_core.geometry.hull import hull_geometry

    p = preset
    rho = float(isa(p.altitude).density)
    wind = np.arange(0.0, p.max_wind + 1e-9, p.wind_step)
    q = 0.5 * rho * wind**2
    q_design = 0.5 * rho * p.max_wind**2
    cds = dict(p.drag_coefficients)
    rows, curves = [], {}
    for key, (label, shape, f) in TABLE_SHAPES.items():
        g = hull_geometry(p.volume, f, 0.432, shape)
        length, d = float(g.length), float(g.diameter)
        hull = p.fabric_areal_density * float(g.surface_area)
        kite = p.kite_mass if shape == "helikite" else 0.0
        fins = p.fin_mass if key == "streamlined" else 0.0
        misc = p.misc_mass if key == "streamlined" else 0.0
        helium = p.helium_density * p.volume
        tether = p.tether_linear_density * p.altitude
        total = helium + hull + kite + fins + misc + tether
        buoy = p.gross_lift_per_m3 * p.volume
        free = buoy - total
        area = float(g.reference_area) if SHAPE_INFO[shape].streamlined else np.pi * d * d / 4
        drag = q * cds[key] * area
        dyn = p.kite_lift_kg * (wind / p.kite_lift_wind) ** 2 if shape == "helikite" else 0 * q
        bb = _straight_tether_blow_by(p.altitude, drag, (free + dyn) * c.G0)
        curves[key] = bb
        dyn_d = (
            p.kite_lift_kg * (p.max_wind / p.kite_lift_wind) ** 2 if shape == "helikite" else 0.0
        )
        rows.append(
            {
                "key": key,
                "label": label,
                "shape": shape,
                "length_m": length,
                "width_m": d,
                "buoyancy_kg": buoy,
                "helium_kg": helium,
                "hull_kg": hull,
                "kite_kg": kite,
                "fins_kg": fins,
                "misc_kg": misc,
                "tether_kg": tether,
                "total_kg": total,
                "free_lift_kg": free,
                "dynamic_lift_kg": dyn_d,
                "drag_coefficient": cds[key],
                "reference_area_m2": area,
                "blow_by_at_design_wind_m": float(
                    _straight_tether_blow_by(
                        p.altitude, q_design * cds[key] * area, (free + dyn_d) * c.G0
                    )
                ),
            }
        )
    return ShapeComparison(rows=rows, wind=wind, blow_by=curves)


def full_model_designs(preset: ShapePreset = THESIS_SHAPE_PRESET) -> dict[str, Design]:
    """The three Table 2.2 hulls designed with the whole engine at the preset's volume and
    altitude: thesis constants (fixed helium 0.169, 130 g/m2, 20 g/m tether, misc 0.30 x hull,
    fin area ratio 0.227), ISA buoyancy, shape drag, trim with hull and fin lift, tether sag."""
    req = replace(
        thesis_requirement(),
        altitude=preset.altitude,
        wind_max=preset.max_wind,
        wind_step=preset.wind_step,
        design_wind=preset.max_wind,
        blow_by_limit=preset.altitude,
    )
    base = thesis_configuration(preset.volume)
    out = {}
    for key, (_, shape, f) in TABLE_SHAPES.items():
        cfg = replace(base, hull=HullSpec(shape=shape, fineness_ratio=f, volume=preset.volume))
        out[key] = design(req, cfg)
    return out


def full_model_shape_comparison(preset: ShapePreset = THESIS_SHAPE_PRESET) -> ShapeComparison:
    """:func:`full_model_designs` as a :class:`ShapeComparison` (same row keys as the thesis
    version; drag_coefficient is the engine's total drag / (q A_ref) at the design wind)."""
    designs = full_model_designs(preset)
    rows, curves = [], {}
    wind = None
    for key, d in designs.items():
        label, shape, _ = TABLE_SHAPES[key]
        af = d.airframe
        m = af.mass.items
        h = af.hull
        g0 = af.g
        perf = d.performance
        wind = perf.wind_speed
        curves[key] = np.asarray(perf.blow_by, float)
        dp = d.design_point
        q = 0.5 * float(af.air_density) * d.requirement.design_wind**2
        area = (
            float(h.reference_area)
            if SHAPE_INFO[shape].streamlined
            else np.pi * float(h.diameter) ** 2 / 4
        )
        kite = float(m["fins"]) if shape == "helikite" else 0.0
        rows.append(
            {
                "key": key,
                "label": label,
                "shape": shape,
                "length_m": float(h.length),
                "width_m": float(h.diameter),
                "buoyancy_kg": d.buoyancy / g0,
                "helium_kg": float(m["lifting gas"]),
                "hull_kg": float(m["hull"]),
                "kite_kg": kite,
                "fins_kg": float(m["fins"]) - kite,
                "misc_kg": float(m["miscellaneous"]),
                "tether_kg": float(m["tether"]),
                "total_kg": d.total_mass - float(m["payload"]),
                "free_lift_kg": d.free_lift_kg + float(m["payload"]),
                "dynamic_lift_kg": dp["dynamic_lift_N"] / g0,
                "drag_coefficient": dp["drag_N"] / (q * area),
                "reference_area_m2": area,
                "blow_by_at_design_wind_m": dp["blow_by_m"],
            }
        )
    return ShapeComparison(rows=rows, wind=np.asarray(wind, float), blow_by=curves)


def comparison_notes(thesis: ShapeComparison, full: ShapeComparison) -> list[str]:
    """Plain-language reasons why the full model differs from the thesis' comparison, with the
    numbers of both (one sentence each)."""
    t = {r["key"]: r for r in thesis.rows}
    f = {r["key"]: r for r in full.rows}
    s, h, n = "sphere", "helikite", "streamlined"
    order_t = sorted(t, key=lambda k: t[k]["blow_by_at_design_wind_m"])
    order_f = sorted(f, key=lambda k: f[k]["blow_by_at_design_wind_m"])
    same = "the same" if order_t == order_f else "a different"
    return [
        f"Buoyancy: the thesis takes 100 kg for 100 m3 (1.0 kg/m3); ISA air at 300 m gives "
        f"{f[s]['buoyancy_kg']:.1f} kg gross, so every free lift is larger in the full model "
        f"(sphere {t[s]['free_lift_kg']:.1f} -> {f[s]['free_lift_kg']:.1f} kg, excluding payload).",
        f"Masses: the full model books miscellaneous items (0.30 x hull) on every hull, not only "
        f"the streamlined one (sphere misc {f[s]['misc_kg']:.1f} kg), and sizes the NPL fins from "
        f"the area ratio ({f[n]['fins_kg']:.2f} kg vs 7.8 kg).",
        f"Drag: the thesis fixes C_D; the model uses Hoerner's C_DV for the NPL hull plus the fins "
        f"({f[n]['drag_coefficient']:.3f} on V^(2/3) in total vs 0.03) and sphere data "
        f"(Achenbach 1972) at the hull Reynolds number for the bluff hulls "
        f"({f[s]['drag_coefficient']:.3f} on frontal area vs 0.2).",
        f"Lift: the streamlined hull trims nose-up and its hull and fins lift "
        f"{f[n]['dynamic_lift_kg']:.1f} kg at 15 m/s (ignored by the thesis); the Helikite kite "
        f"gives {f[h]['dynamic_lift_kg']:.1f} kg (48 kg in the thesis, scaled by the ISA density).",
        f"Tether: the full model lets the 20 g/m tether sag under its weight and drag, which the "
        f"thesis ignores; blow-by at 15 m/s: streamlined {t[n]['blow_by_at_design_wind_m']:.0f} -> "
        f"{f[n]['blow_by_at_design_wind_m']:.0f} m, Helikite {t[h]['blow_by_at_design_wind_m']:.0f} "
        f"-> {f[h]['blow_by_at_design_wind_m']:.0f} m, sphere {t[s]['blow_by_at_design_wind_m']:.0f} "
        f"-> {f[s]['blow_by_at_design_wind_m']:.0f} m.",
        f"Ordering: the full model gives {same} blow-by ranking as the thesis "
        f"({' < '.join(order_f)}).",
    ]


def table_2_2_rows(cmp: ShapeComparison) -> list[dict]:
    """Table 2.2 layout: one row per parameter, one column per shape (display values)."""
    r = {x["key"]: x for x in cmp.rows}
    items = [
        ("Hull length [m]", "length_m"),
        ("Hull width [m]", "width_m"),
        ("Buoyancy [kg]", "buoyancy_kg"),
        ("Helium [kg]", "helium_kg"),
        ("Hull [kg]", "hull_kg"),
        ("Kite [kg]", "kite_kg"),
        ("Fins [kg]", "fins_kg"),
        ("Miscellaneous [kg]", "misc_kg"),
        ("Tether [kg]", "tether_kg"),
        ("Total (no payload) [kg]", "total_kg"),
        ("Free lift (no payload) [kg]", "free_lift_kg"),
        ("Dynamic lift at 15 m/s [kg]", "dynamic_lift_kg"),
        ("Drag coefficient [-]", "drag_coefficient"),
        ("Blow-by at 15 m/s [m]", "blow_by_at_design_wind_m"),
    ]
    out = []
    for label, k in items:
        row = {"parameter": label}
        row.update({TABLE_SHAPES[key][0]: float(r[key][k]) for key in TABLE_SHAPES})
        out.append(row)
    return out


def thesis_reference_rows() -> list[dict]:
    """Thesis Table 2.2 as printed, in the :func:`table_2_2_rows` layout (no blow-by row)."""
    keys = [
        ("Hull length [m]", "length"),
        ("Hull width [m]", "width"),
        ("Helium [kg]", "helium"),
        ("Hull [kg]", "hull"),
        ("Kite [kg]", "kite"),
        ("Fins [kg]", "fins"),
        ("Miscellaneous [kg]", "misc"),
        ("Tether [kg]", "tether"),
        ("Total (no payload) [kg]", "total"),
        ("Free lift (no payload) [kg]", "free_lift"),
        ("Dynamic lift at 15 m/s [kg]", "dynamic_lift"),
        ("Drag coefficient [-]", "cd"),
    ]
    out = []
    for label, k in keys:
        row = {"parameter": label}
        row.update({TABLE_SHAPES[key][0]: THESIS_TABLE_2_2[key][k] for key in TABLE_SHAPES})
        out.append(row)
    return out


def shape_dimensions_rows(volume: float = 100.0) -> list[dict]:
    """Every library shape at its standard l/d and ``volume`` [m3]: l, d [m], C_p, area [m2],
    area / V^(2/3), centre of volume / l, k1, k2, k' (for the Shapes page)."""
    from aerostat_core.geometry.hull import hull_geometry

    out = []
    for name, info in SHAPE_INFO.items():
        g = hull_geometry(volume, info.default_fineness, 0.432, name)
        length, d = dimensions(name, volume, info.default_fineness)
        out.append(
            {
                "shape": name,
                "label": info.label,
                "fineness_ratio": info.default_fineness,
                "valid_fineness": f"{info.fineness_range[0]:g}-{info.fineness_range[1]:g}",
                "length_m": float(length),
                "diameter_m": float(d),
                "prismatic_coefficient": g.prismatic_coefficient,
                "surface_area_m2": float(g.surface_area),
                "area_coefficient": float(g.surface_area) / volume ** (2.0 / 3.0),
                "centre_of_volume_over_l": float(g.xi_cb / g.length),
                "k1": float(g.k1),
                "k2": float(g.k2),
                "k_rot": float(g.k_rot),
                "source": info.source,
            }
        )
    return out
