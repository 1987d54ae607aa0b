"""Plain-data views of designs for the app, the CSV files and the comparison of saved cases.

Everything here is pure (no Streamlit): it turns :class:`~aerostat_core.model.design.Design` objects and
saved-case dicts (:func:`aerostat_core.model.io.inputs_to_dict` format) into lists of flat rows, the
typed :class:`DesignReport` (its parts in :mod:`aerostat_core.output.report_parts`) and 3-D outlines that
the UI layer plots. No physics is computed here beyond drawing the shapes the engine already
defines (hull profile r(xi), trapezoidal fins).

Units: SI, with the unit written into every column name of a CSV row (``blow_by_m``,
``payload_mass_kg``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from aerostat_core.geometry.fins import ARRANGEMENT_ANGLES_DEG
from aerostat_core.geometry.hull import radius
from aerostat_core.geometry.shapes import profile_radius_ratio
from aerostat_core.model import budget
from aerostat_core.model.design import Design, design
from aerostat_core.model.input_paths import report_table
from aerostat_core.model.inputs import Requirement
from aerostat_core.model.io import inputs_from_dict, inputs_to_dict, rows_to_csv
from aerostat_core.model.presets import practice_configuration
from aerostat_core.output.report_parts import (
    DesignLimits,
    DesignReport,
    FinView,
    HullDimensions,
    KeyPoints,
    MomentCurve,
    PerformanceCurves,
    TetherProfile,
    TetherProfiles,
    tether_profiles,
)

# --------------------------------------------------------------------------------------------
# Input fields: labels and units (display and CSV)
# --------------------------------------------------------------------------------------------

#: Every input field by dotted path: (label, display unit, display scale from SI, CSV unit token),
#: from the field registry (aerostat_core.base.fields). ``display = SI * scale``. Unknown paths fall
#: back to their path as label and no unit (see :func:`input_field_info`).
INPUT_FIELDS: dict[str, tuple[str, str, float, str]] = report_table()


def input_field_info(path: str) -> tuple[str, str, float, str]:
    """(label, display unit, display scale, CSV unit token) of an input path; unknown paths get
    their own name as label, no unit and scale 1.

    >>> input_field_info("requirement.payload_mass")
    ('Payload mass', 'kg', 1.0, 'kg')
    >>> input_field_info("configuration.new_thing")
    ('configuration.new_thing', '', 1.0, '')
    """
    return INPUT_FIELDS.get(path, (path, "", 1.0, ""))


def flatten_inputs(inputs: Mapping[str, Any]) -> dict[str, Any]:
    """Flatten an :func:`inputs_to_dict` dict to ``{"requirement.payload_mass": 10.0, ...}``.

    Only the ``requirement`` and ``configuration`` parts are kept (not format/version).

    >>> from aerostat_core.model.presets import thesis_baseline
    >>> flat = flatten_inputs(inputs_to_dict(*thesis_baseline()))
    >>> flat["requirement.payload_mass"], flat["configuration.hull.volume"]
    (10.0, 170.0)
    """
    out: dict[str, Any] = {}

    def walk(prefix: str, obj: Any) -> None:
        if isinstance(obj, Mapping):
            for k, v in obj.items():
                walk(f"{prefix}.{k}" if prefix else str(k), v)
        else:
            out[prefix] = obj

    for part in ("requirement", "configuration"):
        walk(part, inputs.get(part, {}))
    return out


def csv_column(path: str, unit_token: str) -> str:
    """CSV column name of an input path: last two path parts joined, plus the unit token.

    >>> csv_column("requirement.payload_mass", "kg")
    'payload_mass_kg'
    >>> csv_column("configuration.hull_fabric.areal_density", "kg_m2")
    'hull_fabric_areal_density_kg_m2'
    >>> csv_column("configuration.aero.fin_stall_angle_deg", "deg")
    'aero_fin_stall_angle_deg'
    """
    parts = path.split(".")
    name = "_".join(parts[1:]) if len(parts) > 1 else path
    if not unit_token or name.endswith(f"_{unit_token}"):
        return name
    return f"{name}_{unit_token}"


def _csv_value(value: Any) -> Any:
    """Inputs as CSV cells: ``None`` (auto) becomes an empty cell, numbers stay numbers."""
    if value is None:
        return ""
    return value


def _display_value(value: Any, scale: float) -> Any:
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return "auto" if value is None else value
    if isinstance(value, (int, float)):
        if isinstance(value, float) and math.isinf(value):
            return value
        return value * scale if scale != 1.0 else value
    return str(value)


# --------------------------------------------------------------------------------------------
# Shapes for the 3-D and side views
# --------------------------------------------------------------------------------------------


def _f(x: Any) -> float:
    return float(np.asarray(x, dtype=float).reshape(-1)[0])


def _ro(a: Any, dtype: Any) -> np.ndarray:
    """A read-only view of ``a`` as ``dtype``: the report is shared by every session through the
    app's cache (app_ui/cache.py), so a page that wrote into an array would change it for all
    of them; the design's own array stays as it is."""
    v = np.asarray(a, dtype).view()
    v.flags.writeable = False
    return v


def hull_outline(a1: float, a2: float, b: float, n: int = 121, shape: str = "npl"
                 ) -> tuple[np.ndarray, np.ndarray]:
    """Stations xi [m] (nose to tail, denser at both ends) and radii r(xi) [m] of the profile
    (NPL from a1, a2, b; any other ``shape`` from its dimensionless profile, l = a1 + a2, d = 2b).

    >>> xi, r = hull_outline(2.0, 3.0, 1.0, n=5)
    >>> float(r[0]), float(r[-1]), float(r.max())
    (0.0, 0.0, 1.0)
    """
    length = a1 + a2
    t = np.linspace(0.0, np.pi, n)
    xi = 0.5 * length * (1.0 - np.cos(t))  # cosine spacing: resolves the blunt nose and tail
    xi = np.unique(np.append(xi, a1))  # include the station of maximum radius exactly
    if shape != "npl":
        return xi, 2.0 * b * profile_radius_ratio(shape, xi / length)
    return xi, np.asarray(radius(xi, a1, a2, b), dtype=float)


def hull_surface(
    a1: float, a2: float, b: float, n_xi: int = 61, n_theta: int = 37, shape: str = "npl"
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Surface of revolution of the profile: X (axis, aft), Y (starboard), Z (up) grids [m].

    Shapes (n_theta, n_xi'): one row per azimuth. Body frame: origin at the nose, z up.
    """
    xi, r = hull_outline(a1, a2, b, n_xi, shape)
    theta = np.linspace(0.0, 2.0 * np.pi, n_theta)[:, None]
    x = np.broadcast_to(xi, (n_theta, xi.size))
    return np.array(x), r * np.cos(theta), r * np.sin(theta)


def fin_outlines(d: Design) -> list[np.ndarray]:
    """3-D corners of every fin, each an array (5, 3) of (xi, y, z) [m], closed (first = last).

    Root chord along the hull surface (radius r(xi) at the root LE and TE); tip at radius
    r(mid-root) + span; leading edge swept by the engine's sweep angle, trailing edge as the
    engine's planform (unswept when tan(sweep) = (RC - TC)/span). Azimuths from
    ``fins.ARRANGEMENT_ANGLES_DEG`` (0 = starboard, 90 = up).
    """
    h, f = d.airframe.hull, d.airframe.fins
    le, rc, tc, span = _f(f.xi_root_le), _f(f.root_chord), _f(f.tip_chord), _f(f.span)
    tan_le = math.tan(_f(f.sweep_le))
    r_le, r_te = (_f(h.radius_at(x)) for x in (le, le + rc))
    r_tip = _f(h.radius_at(le + 0.5 * rc)) + span
    tip_le = le + span * tan_le
    corners = [(le, r_le), (le + rc, r_te), (tip_le + tc, r_tip), (tip_le, r_tip), (le, r_le)]
    arrangement = d.configuration.fins.arrangement
    out = []
    for phi in np.radians(ARRANGEMENT_ANGLES_DEG[arrangement]):
        c, s = math.cos(phi), math.sin(phi)
        out.append(np.array([(x, rr * c, rr * s) for x, rr in corners]))
    return out


def confluence_lines(d: Design, n_lines: int = 3) -> list[np.ndarray]:
    """Schematic confluence lines in the side view: from the confluence point to ``n_lines``
    attachment points on the hull belly, spread over +-20 % of the length around the point's
    station (the engine models only the point; these lines are for the picture). Each line is an
    array (2, 2) of (xi, z) [m].
    """
    h, af = d.airframe.hull, d.airframe
    length = _f(h.length)
    xc, zc = _f(af.xi_c), _f(af.z_c)
    stations = np.clip(xc + np.linspace(-0.2, 0.2, n_lines) * length, 0.08 * length, 0.92 * length)
    return [np.array([[xc, zc], [x, -_f(h.radius_at(x))]]) for x in stations]


# --------------------------------------------------------------------------------------------
# One design as plain data
# --------------------------------------------------------------------------------------------


def performance_rows(d: Design) -> list[dict]:
    """The performance table rows (units in the keys) plus ``limit_exceeded`` (bool)."""
    limited = np.asarray(d.performance.limited, dtype=bool)
    rows = d.performance.rows()
    for row, lim in zip(rows, limited):
        row["limit_exceeded"] = bool(lim)
    return rows


def _design_wind_profile(d: Design) -> TetherProfile:
    """Tether shape at the design wind (x, z [m] from the winch; ``wind`` [m/s])."""
    wind = float(d.requirement.design_wind)
    if hasattr(d, "tether_profile"):
        x, z = d.tether_profile(wind)
        return TetherProfile(
            x=_ro(x, float).reshape(-1), z=_ro(z, float).reshape(-1), wind=wind
        )
    ws = _ro(d.performance.wind_speed, float)  # engines without Design.tether_profile
    j = int(np.argmin(np.abs(ws - wind)))
    return TetherProfile(
        x=_ro(d.tether_x, float)[:, j],
        z=_ro(d.tether_z, float)[:, j],
        wind=float(ws[j]),
    )


def tether_profile_rows(tether: TetherProfiles | Mapping[str, Any]) -> list[dict[str, float]]:
    """Tidy rows (wind_speed_m_s, node, x_m, z_m) of the sweep's tether profiles; node 0 is the
    confluence point, the last node the winch. ``tether`` is ``design_report(d).tether`` (a
    plain ``{"x", "z", "wind_speed"}`` mapping is accepted too)."""
    t = tether_profiles(tether)
    x, z, ws = t.x, t.z, t.wind_speed
    return [
        {
            "wind_speed_m_s": float(ws[j]),
            "node": int(i),
            "x_downwind_m": float(x[i, j]),
            "z_height_m": float(z[i, j]),
        }
        for j in range(ws.size)
        for i in range(x.shape[0])
    ]


def design_report(d: Design) -> DesignReport:
    """Everything the design page shows (:class:`DesignReport`), from the design as computed
    (nothing is solved again: the design-wind tether comes with the constraint table)."""
    p = d.performance
    req, cfg = d.requirement, d.configuration
    h, af = d.airframe.hull, d.airframe
    prow = performance_rows(d)
    return DesignReport(
        summary=d.summary(),
        constraints=d.constraint_rows(),
        violations=tuple(d.violations),
        feasible=bool(d.feasible),
        sized=bool(d.sized),
        geometry_rows=d.geometry_rows(),
        mass_rows=d.mass_rows(),
        performance_rows=prow,
        perf=PerformanceCurves(
            wind_speed=_ro(p.wind_speed, float),
            alpha_eq=_ro(p.alpha_eq, float),
            dynamic_lift=_ro(p.dynamic_lift, float),
            drag=_ro(p.drag, float),
            blow_by=_ro(p.blow_by, float),
            flying_height=_ro(p.flying_height, float),
            tension_top=_ro(p.tension_top, float),
            tension_winch=_ro(p.tension_winch, float),
            safety_factor=_ro(p.safety_factor, float),
            limited=_ro(p.limited, bool),
            flag_text=tuple(r["flags"] for r in prow),
        ),
        cm=MomentCurve(
            alpha_deg=_ro(d.cm_alpha_deg, float),
            cm=_ro(d.cm, float),
            alpha_eq_deg=float(d.design_point["alpha_eq_deg"]),
            wind=float(req.design_wind if req.design_wind > 0 else 10.0),
        ),
        tether=TetherProfiles(
            x=_ro(d.tether_x, float),
            z=_ro(d.tether_z, float),
            wind_speed=_ro(p.wind_speed, float),
            design=_design_wind_profile(d),
        ),
        shape=h.shape,
        hull=HullDimensions(
            a1=_f(h.a1),
            a2=_f(h.a2),
            b=_f(h.b),
            length=_f(h.length),
            diameter=_f(h.diameter),
            xi_cb=_f(h.xi_cb),
        ),
        fins=FinView(
            outlines=tuple(_ro(o, float) for o in fin_outlines(d)),
            arrangement=cfg.fins.arrangement,
        ),
        points=KeyPoints(
            cb=(_f(h.xi_cb), 0.0),
            cg=(_f(af.mass.xi_cg), _f(af.mass.z_cg)),
            c=(_f(af.xi_c), _f(af.z_c)),
        ),
        confluence_lines=[_ro(line, float) for line in confluence_lines(d)],
        limits=DesignLimits(
            blow_by_limit=float(req.blow_by_limit),
            design_wind=float(req.design_wind),
            min_safety_factor=float(req.min_tether_safety_factor),
            altitude=float(req.altitude),
            stall_deg=float(cfg.aero.fin_stall_angle_deg),
        ),
        inputs=inputs_to_dict(req, cfg),
    )


# --------------------------------------------------------------------------------------------
# Saved cases: comparison table and one tidy CSV
# --------------------------------------------------------------------------------------------

#: Result quantities of the comparison table: (summary key, label, unit, decimals).
SUMMARY_FIELDS: tuple[tuple[str, str, str], ...] = (
    ("volume_m3", "Hull volume", "m³"),
    ("length_m", "Hull length", "m"),
    ("diameter_m", "Hull diameter", "m"),
    ("total_mass_kg", "Total mass", "kg"),
    ("gross_buoyancy_N", "Gross buoyancy", "N"),
    ("free_lift_kg", "Free lift", "kg"),
    ("percent_static_lift", "Percent static lift", "%"),
    ("blow_by_at_design_wind_m", "Blow-by at the design wind", "m"),
    ("alpha_at_design_wind_deg", "Angle of attack at the design wind", "deg"),
    ("tension_top_at_design_wind_N", "Tether tension at the design wind", "N"),
    ("safety_factor_at_design_wind", "Tether safety factor at the design wind", "-"),
    ("gas_cost_USD", "Gas fill cost", "USD"),
    ("feasible", "Meets every requirement", ""),
)


def case_designs(cases: Mapping[str, Mapping[str, Any]]) -> dict[str, Design]:
    """Design every saved case (inputs dicts), in order. Raises ``ValueError`` naming the case."""
    budget.check_cases(cases)
    out = {}
    for name, inputs in cases.items():
        try:
            req, cfg = inputs_from_dict(dict(inputs))
        except ValueError as exc:
            raise ValueError(f"case {name!r}: {exc}") from None
        out[name] = design(req, cfg)
    return out


def comparison_rows(designs: Mapping[str, Design]) -> list[dict[str, Any]]:
    """Side-by-side table: one row per quantity, one column per case.

    Columns: ``section`` ("result" or "input"), ``quantity`` (label with unit in brackets),
    one column per case name (display units), and ``differs`` (True when the cases disagree).
    Results come first, then every input.
    """
    names = list(designs)
    rows: list[dict[str, Any]] = []

    def add(section: str, label: str, unit: str, values: list[Any]) -> None:
        quantity = f"{label} [{unit}]" if unit else label
        row: dict[str, Any] = {"section": section, "quantity": quantity}
        row.update(dict(zip(names, values)))
        row["differs"] = _differs(values)
        rows.append(row)

    add("result", "Hull shape", "", [d.airframe.hull.shape for d in designs.values()])
    add("result", "Hull fabric mass", "kg",
        [_f(d.airframe.mass.items["hull"]) for d in designs.values()])
    summaries = {n: d.summary() for n, d in designs.items()}
    for key, label, unit in SUMMARY_FIELDS:
        add("result", label, unit, [getattr(summaries[n], key) for n in names])
    not_met = ["; ".join(d.violations) if d.violations else "none" for d in designs.values()]
    add("result", "Requirements not met", "", not_met)
    flats = {
        n: flatten_inputs(inputs_to_dict(d.requirement, d.configuration))
        for n, d in designs.items()
    }
    paths: list[str] = []
    for flat in flats.values():
        paths.extend(p for p in flat if p not in paths)
    for path in paths:
        label, unit, scale, _ = input_field_info(path)
        add("input", label, unit, [_display_value(flats[n].get(path), scale) for n in names])
    return rows


def _differs(values: list[Any]) -> bool:
    if len(values) < 2:
        return False
    first = values[0]
    for v in values[1:]:
        if isinstance(first, float) and isinstance(v, float):
            if not math.isclose(first, v, rel_tol=1e-9, abs_tol=1e-12):
                return True
        elif v != first:
            return True
    return False


def cases_rows(
    cases: Mapping[str, Mapping[str, Any]], designs: Mapping[str, Design] | None = None
) -> list[dict[str, Any]]:
    """One tidy table of every saved case: one row per (case, wind speed).

    Columns: ``case``; every input (``payload_mass_kg``, ``hull_fabric_areal_density_kg_m2``,
    ... in SI units, an empty cell for "auto"); the headline results (``volume_m3``,
    ``total_mass_kg``, ...; repeated on each row of the case); then the performance columns of
    that wind speed (``wind_speed_m_s``, ``blow_by_m``, ...). Units are in the column names.
    ``designs`` (name -> Design of those cases, e.g. from a cache) avoids designing them again.
    """
    rows: list[dict[str, Any]] = []
    if designs is None:
        designs = case_designs(cases)
    for name, d in designs.items():
        base: dict[str, Any] = {"case": name}
        for path, value in flatten_inputs(inputs_to_dict(d.requirement, d.configuration)).items():
            base[csv_column(path, input_field_info(path)[3])] = _csv_value(value)
        summary = d.summary().to_dict()
        base.update({k: v for k, v in summary.items() if k != "design_wind_m_s"})
        base["violations"] = "; ".join(d.violations)
        for prow in performance_rows(d):
            rows.append({**base, **prow})
    return rows


def cases_csv(
    cases: Mapping[str, Mapping[str, Any]], designs: Mapping[str, Design] | None = None
) -> str:
    """CSV text of :func:`cases_rows` (header from the first case; every case shares it)."""
    rows = cases_rows(cases, designs)
    if not rows:
        return ""
    header: list[str] = []
    for row in rows:
        header.extend(k for k in row if k not in header)
    return rows_to_csv([{k: row.get(k, "") for k in header} for row in rows])


# --------------------------------------------------------------------------------------------
# The thesis' GUI test cases (Table 4.15)
# --------------------------------------------------------------------------------------------


def thesis_gui_cases() -> dict[str, dict[str, Any]]:
    """The thesis' GUI test cases as saved-case dicts: payload 10 vs 30 kg at 300 m, altitude
    100 vs 500 m with 10 kg (thesis §4.5, Table 4.15, Figs 4.24-4.35).

    Sized (``hull.volume = None``) under the default "practice" rule set and its configuration
    (aerostat_core.model.rules, presets.practice_configuration), so payload and altitude change the hull
    and every limit scales with the altitude; all four are feasible (tests/core/test_fielded.py).
    """
    cfg = practice_configuration()

    def case(payload: float, altitude: float) -> dict[str, Any]:
        req = Requirement(payload_mass=payload, altitude=altitude).resolved()
        return inputs_to_dict(req, cfg)

    return {
        "GUI test: payload 10 kg, 300 m": case(10.0, 300.0),
        "GUI test: payload 30 kg, 300 m": case(30.0, 300.0),
        "GUI test: altitude 100 m, 10 kg": case(10.0, 100.0),
        "GUI test: altitude 500 m, 10 kg": case(10.0, 500.0),
    }


__all__ = [
    "INPUT_FIELDS",
    "DesignLimits",
    "DesignReport",
    "FinView",
    "HullDimensions",
    "KeyPoints",
    "MomentCurve",
    "PerformanceCurves",
    "SUMMARY_FIELDS",
    "TetherProfile",
    "TetherProfiles",
    "case_designs",
    "cases_csv",
    "cases_rows",
    "comparison_rows",
    "confluence_lines",
    "csv_column",
    "design_report",
    "fin_outlines",
    "flatten_inputs",
    "hull_outline",
    "hull_surface",
    "input_field_info",
    "performance_rows",
    "tether_profile_rows",
    "tether_profiles",
    "thesis_gui_cases",
]
