"""Design report: one self-contained HTML file (inline SVG plots, inline CSS, no scripts, no
network) that works offline and prints to PDF from any browser.

Sections (``id`` of each ``<section>``): verdict (feasible or not, what binds, the key
numbers), requirement (labels and units from the field registry), rules, geometry (with the side view), mass,
performance (table and plots, with the Monte Carlo bands when given), tether (profiles),
constraints (margins), envelope (heat map of the binding constraint with the limit boundaries),
flyable (site wind), uncertainty (bands, probabilities, rule-set spread), validation (reference
numbers and fielded aerostats) and version. Every text is HTML-escaped.

Layout: it fits a 1024 px window and an A4 page (tables wrap their headers and text cells and
are never wider than the text column; a table or figure is never split across printed pages).
Values are shown in the unit system asked for (``units="SI"`` or ``"US"``, from
:data:`aerostat_core.base.fields.US_CUSTOMARY`); the program's exports stay SI.
"""

from __future__ import annotations

import datetime as _dt
import html
import io

import numpy as np

from aerostat_core.base.fields import UNIT_SYSTEMS, spec_display, unit_in
from aerostat_core.model.constraints import BY_NAME
from aerostat_core.model.design import Design
from aerostat_core.model.input_paths import all_specs
from aerostat_core.output.report import confluence_lines, fin_outlines, hull_outline
from aerostat_core.studies.envelope import ENVELOPE_NAMES, Envelope
from aerostat_core.studies.site_wind import FlyableTime
from aerostat_core.studies.uncertainty import MonteCarloResult

#: Section ids in order (the browser test checks these).
SECTIONS = (
    "verdict",
    "requirement",
    "rules",
    "geometry",
    "mass",
    "performance",
    "tether",
    "constraints",
    "envelope",
    "flyable",
    "uncertainty",
    "validation",
    "version",
)

_CSS = """
body{font-family:system-ui,-apple-system,'Segoe UI',Roboto,sans-serif;margin:1.5em auto;
max-width:56em;padding:0 1em;color:#111;line-height:1.35}
h1{font-size:1.6em;margin-bottom:.2em}h2{font-size:1.25em;border-bottom:1px solid #999;
margin-top:1.6em}table{border-collapse:collapse;margin:.5em 0;font-size:.8em;max-width:100%}
td,th{border:1px solid #bbb;padding:.15em .4em;text-align:right;overflow-wrap:anywhere}
th{background:#eee;font-weight:600}td.t,th.t{text-align:left}.bad{color:#a00;font-weight:600}
.ok{color:#060;font-weight:600}.verdict{font-size:1.1em}ol.sources{font-size:.8em}
figure{margin:.6em 0;break-inside:avoid;page-break-inside:avoid}
figcaption{font-size:.85em;color:#444}svg{max-width:100%;height:auto}
table,figure{break-inside:avoid;page-break-inside:avoid}thead{display:table-header-group}
@page{size:A4;margin:14mm 12mm}
@media print{body{margin:0;max-width:none;padding:0;font-size:10pt}
h2{break-after:avoid;page-break-after:avoid}}
"""


def program_version() -> str:
    """Version of the package (installed metadata, else pyproject.toml of the source tree)."""
    try:
        from importlib.metadata import PackageNotFoundError, version

        return version("aerostat-design")
    except PackageNotFoundError:
        pass
    import tomllib
    from pathlib import Path

    p = Path(__file__).resolve().parents[2] / "pyproject.toml"  # aerostat_core/output/ -> root
    try:
        return tomllib.loads(p.read_text())["project"]["version"] + " (source tree)"
    except (OSError, KeyError, tomllib.TOMLDecodeError):
        return "unknown"


def _e(x) -> str:
    return html.escape(str(x), quote=True)


def _num(v) -> str:
    if isinstance(v, bool | np.bool_):
        return "yes" if v else "no"
    if v is None:
        return "not computed: not given"
    if isinstance(v, int | np.integer):
        return str(int(v))
    if isinstance(v, float | np.floating):
        v = float(v) + 0.0  # no "-0"
        if v == 0:
            return "0"
        if not np.isfinite(v):
            return "not computed: no finite value" if v != v else ("unbounded" if v > 0 else "−∞")
        if v != 0 and (abs(v) >= 1e5 or abs(v) < 1e-3):
            return f"{v:.3e}"
        return f"{v:.4g}" if abs(v) < 1000 else f"{v:.0f}"
    return _e(v)


def _cited_table(rows: list[dict], columns: list[tuple[str, str]]) -> str:
    """:func:`_table` of ``rows`` with their ``source`` texts as numbered references ("[1]")
    and the sources listed once below it: the texts in a column made the fielded-aerostat
    table taller than an A4 page, and a list breaks across pages where a table row cannot."""
    sources: dict[str, int] = {}
    cited = [
        {**r, "source": f"[{sources.setdefault(str(r.get('source', '')), len(sources) + 1)}]"}
        for r in rows
    ]
    listed = "".join(f"<li>{_e(text)}</li>" for text in sources)
    return _table(cited, [*columns, ("source", "source")]) + (
        f'<ol class="sources">{listed}</ol>' if sources else ""
    )


def _table(rows: list[dict], columns: list[tuple[str, str]] | None = None, cls=None) -> str:
    """HTML table of dict rows; ``columns`` = [(key, header)]; text columns left-aligned."""
    if not rows:
        return "<p>None in this design.</p>"
    columns = columns or [(k, k) for k in rows[0]]
    head = "".join(
        f'<th class="t">{_e(h)}</th>' if isinstance(rows[0].get(k), str) else f"<th>{_e(h)}</th>"
        for k, h in columns
    )
    body = []
    for r in rows:
        cells = []
        for k, _ in columns:
            v = r.get(k, "")
            c = ' class="t"' if isinstance(v, str) else ""
            if cls and k in cls:
                c = f' class="{cls[k](v)}"'
            cells.append(f"<td{c}>{_num(v)}</td>")
        body.append("<tr>" + "".join(cells) + "</tr>")
    return f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>"


def _svg(fig) -> str:
    # Reproducible bytes: no save date in the metadata and element ids hashed from a fixed salt
    # (matplotlib salts them at random otherwise), so one design always gives one report.
    buf = io.StringIO()
    import matplotlib as mpl

    with mpl.rc_context({"svg.hashsalt": "aerostat-report"}):
        fig.savefig(buf, format="svg", bbox_inches="tight", metadata={"Date": None})
    s = buf.getvalue()
    return s[s.index("<svg") :]


def _figure(fig, caption: str, name: str) -> str:
    return (
        f'<figure class="plot" data-plot="{_e(name)}">{_svg(fig)}'
        f"<figcaption>{_e(caption)}</figcaption></figure>"
    )


def _new_figure(w=7.0, h=3.2, ncols=1):
    import matplotlib

    matplotlib.rcParams["svg.fonttype"] = "none"  # text stays text: searchable, small
    from matplotlib.figure import Figure

    fig = Figure(figsize=(w, h), layout="constrained")
    axes = fig.subplots(1, ncols)
    return fig, axes


def side_view_figure(d: Design):
    """Side view to scale: NPL hull, fins, confluence lines, CB, CG and confluence point."""
    fig, ax = _new_figure(7.0, 2.6)
    h = d.airframe.hull
    a1, a2, b = (float(np.asarray(x).reshape(-1)[0]) for x in (h.a1, h.a2, h.b))
    xi, r = hull_outline(a1, a2, b)
    ax.fill_between(xi, -r, r, color="#cfd8e3", ec="#345", lw=1.0, label="hull")
    for k, fin in enumerate(fin_outlines(d)):
        ax.plot(fin[:, 0], fin[:, 2], color="#a35", lw=1.0, label="fins" if k == 0 else None)
    for k, line in enumerate(confluence_lines(d)):
        ax.plot(
            line[:, 0],
            line[:, 1],
            color="#777",
            lw=0.7,
            ls="--",
            label="confluence lines" if k == 0 else None,
        )
    af = d.airframe
    pts = {"CB": (h.xi_cb, 0.0), "CG": (af.mass.xi_cg, af.mass.z_cg), "C": (af.xi_c, af.z_c)}
    for name, (x, z) in pts.items():
        x, z = float(np.asarray(x).reshape(-1)[0]), float(np.asarray(z).reshape(-1)[0])
        ax.plot([x], [z], "o", ms=4)
        ax.annotate(name, (x, z), textcoords="offset points", xytext=(4, 4), fontsize=8)
    ax.set_aspect("equal")
    ax.set_xlabel("station from nose [m]")
    ax.set_ylabel("z [m]")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return fig


def performance_figure(d: Design, mc: MonteCarloResult | None = None):
    """Blow-by and top tension versus wind, with limits and the 5-95 % bands."""
    fig, (a, b) = _new_figure(7.5, 3.0, 2)
    p, req = d.performance, d.requirement
    a.plot(p.wind_speed, p.blow_by, "-", color="C0", label="blow-by")
    a.axhline(req.blow_by_limit, color="C3", ls="--", lw=0.8, label="limit")
    a.axvline(req.design_wind, color="#888", ls=":", lw=0.8, label="design wind")
    b.plot(p.wind_speed, p.tension_top, "-", color="C1", label="tension at confluence point")
    b.plot(p.wind_speed, p.tension_winch, "-", color="C2", label="tension at winch")
    sf_t = float(d.configuration.tether.breaking_strength) / float(req.min_tether_safety_factor)
    t_max = float(np.max(p.tension_top))
    if sf_t <= 2.0 * t_max:  # else it would flatten the curves: the table gives the factor
        b.axhline(sf_t, color="C3", ls="--", lw=0.8, label="breaking strength / safety factor")
    if mc is not None:
        a.fill_between(
            mc.speeds, mc.blow_by[0], mc.blow_by[2], color="C0", alpha=0.25, label="5-95 % band"
        )
        b.fill_between(
            mc.speeds, mc.tension[0], mc.tension[2], color="C1", alpha=0.25, label="5-95 % band"
        )
    a.set_xlabel("wind at the aerostat [m/s]")
    a.set_ylabel("blow-by [m]")
    b.set_xlabel("wind at the aerostat [m/s]")
    b.set_ylabel("tension [N]")
    a.legend(fontsize=7)
    b.legend(fontsize=7)
    return fig


def tether_figure(d: Design):
    """Tether shapes from the winch at every sweep speed."""
    fig, ax = _new_figure(5.0, 3.6)
    ws = np.asarray(d.performance.wind_speed)
    step = max(1, ws.size // 8)
    for j in range(0, ws.size, step):
        ax.plot(d.tether_x[:, j], d.tether_z[:, j], lw=1.0, label=f"{ws[j]:g} m/s")
    ax.set_aspect("equal")
    ax.set_xlabel("downwind x [m]")
    ax.set_ylabel("height z [m]")
    ax.legend(fontsize=7, ncols=2)
    return fig


def envelope_figure(env: Envelope, payload_index: int = 0):
    """Heat map of the largest constraint value g over wind x altitude, with the limit boundary
    (g = 0) of every constraint that crosses the map and the design point."""
    fig, ax = _new_figure(7.0, 3.8)
    mg = env.max_g[payload_index]
    im = ax.pcolormesh(
        env.wind,
        env.altitude,
        np.clip(mg, -1.0, 1.0),
        cmap="RdYlGn_r",
        vmin=-1.0,
        vmax=1.0,
        shading="nearest",
    )
    fig.colorbar(im, ax=ax, label="largest g (> 0: a limit is broken)")
    handles = []
    from matplotlib.lines import Line2D

    for k, name in enumerate(ENVELOPE_NAMES):
        gk = env.g[payload_index, :, :, k]
        if gk.shape[0] > 1 and gk.shape[1] > 1 and gk.min() < 0 < gk.max():
            ax.contour(
                env.wind, env.altitude, gk, levels=[0.0], colors=[f"C{k % 10}"], linewidths=1.2
            )
            handles.append(Line2D([], [], color=f"C{k % 10}", label=BY_NAME[name].label))
    ax.plot([env.design_wind], [env.design_altitude], "k*", ms=9)
    handles.append(Line2D([], [], color="k", marker="*", ls="", label="design point"))
    ax.set_xlabel("wind at the aerostat [m/s]")
    ax.set_ylabel("altitude = tether length [m]")
    ax.legend(handles=handles, fontsize=7, loc="upper right")
    return fig


def _shown(value, token: str, units: str) -> float:
    """An SI value in the report's unit system (``token`` the SI unit: "m", "m3", "N")."""
    return unit_in(token, units).show(float(value))


def _in(token: str, units: str) -> str:
    """The unit an SI ``token`` is shown in."""
    return unit_in(token, units).unit


def _unit_rows(rows: list[dict], keys: dict[str, str], units: str) -> list[dict]:
    """Rows with the values of ``keys`` (key -> SI unit token) in the report's unit system."""
    if units == "SI":
        return rows
    out = []
    for r in rows:
        r = dict(r)
        for k, token in keys.items():
            if isinstance(r.get(k), float | int) and not isinstance(r.get(k), bool):
                r[k] = _shown(r[k], token, units)
        out.append(r)
    return out


def requirement_rows(req, units: str = "SI") -> list[dict]:
    """The requirement as the form reads it: label, value in the display unit of the registry
    (in ``units``), unit; an empty optional field says what it takes instead.

    >>> from aerostat_core import thesis_baseline
    >>> rows = requirement_rows(thesis_baseline()[0], "US")
    >>> rows[0]["quantity"], round(rows[0]["value"], 2), rows[0]["unit"]
    ('Payload mass', 22.05, 'lb')
    """
    out = []
    for p in all_specs():
        if not p.path.startswith("requirement."):
            continue
        v = getattr(req, p.name)
        if p.spec.kind in ("number", "integer"):
            du = spec_display(p.spec, units)
            if v is None:
                value = f"from the {p.spec.empty}"
            else:
                value = du.show(float(v))
            unit = "" if du.unit == "-" else du.unit
        else:
            value, unit = str(v), ""
        out.append({"quantity": p.label, "value": value, "unit": unit})
    return out


def _verdict(d: Design, units: str) -> str:
    """The verdict first: feasible or not, what binds, and the key numbers at the design wind.

    The design's nominal verdict (:meth:`Design.verdict`): its word, headline and what to
    change, then what binds.
    """
    s = d.summary()
    req = d.requirement
    v = d.verdict()  # the nominal verdict (issue 22): meets, meets_nominal_only or fails
    word = {"meets": "Feasible", "meets_nominal_only": "Feasible (nominal margins only)",
            "fails": "NOT feasible"}.get(v.verdict, "NOT feasible")
    head = f"{word}: {_e(v.headline)}"
    if v.what_to_change:
        head += " What to change: " + _e("; ".join(v.what_to_change))
    if not d.feasible and d.violations:
        head += " (" + _e("; ".join(d.violations)) + ")"
    binds = s.binding_constraint.replace("_", " ") if s.binding_constraint else ""
    sized = f" The hull is sized by the {_e(binds)}." if binds else ""
    cls = "ok" if d.feasible else "bad"
    L, M, F, W = (_in(t, units) for t in ("m", "kg", "N", "m/s"))
    key = [
        {
            "quantity": f"Hull volume [{_in('m3', units)}]",
            "value": _shown(s.volume_m3, "m3", units),
        },
        {"quantity": f"Length [{L}]", "value": _shown(s.length_m, "m", units)},
        {"quantity": f"Diameter [{L}]", "value": _shown(s.diameter_m, "m", units)},
        {"quantity": f"Total mass [{M}]", "value": _shown(s.total_mass_kg, "kg", units)},
        {"quantity": f"Free lift [{M}]", "value": _shown(s.free_lift_kg, "kg", units)},
        {
            "quantity": f"Blow-by at {_shown(req.design_wind, 'm/s', units):.1f} {W} [{L}]",
            "value": _shown(s.blow_by_at_design_wind_m, "m", units),
        },
        {"quantity": f"Blow-by limit [{L}]", "value": _shown(req.blow_by_limit, "m", units)},
        {
            "quantity": f"Tension at the confluence point [{F}]",
            "value": _shown(s.tension_top_at_design_wind_N, "N", units),
        },
        {"quantity": "Tether safety factor", "value": s.safety_factor_at_design_wind},
        {"quantity": "Gas fill cost [USD]", "value": s.gas_cost_USD},
    ]
    return f'<p class="verdict"><span class="{cls}">{head}</span>{sized}</p>' + _table(
        key, [("quantity", "Key number"), ("value", "Value")]
    )


def _section(sid: str, title: str, body: str) -> str:
    return f'<section id="{sid}"><h2>{_e(title)}</h2>{body}</section>'


def _envelope_rows(env: Envelope) -> list[dict]:
    lw = env.limit_wind()
    names = env.binding_names()
    rows = []
    for ip, p in enumerate(env.payload):
        for ia, h in enumerate(env.altitude):
            row = names[ip, ia]
            fly = env.flyable[ip, ia]
            first_bad = np.flatnonzero(~fly)
            stops = BY_NAME[str(row[first_bad[0]])].label if first_bad.size else "none in range"
            up_to = float(lw[ip, ia]) if np.isfinite(lw[ip, ia]) else "not at any wind"
            rows.append(
                {
                    "payload_kg": float(p),
                    "altitude_m": float(h),
                    "flyable_up_to_m_s": up_to,
                    "stopped_by": stops,
                }
            )
    return rows


def render_report(
    d: Design,
    env: Envelope,
    flyable: FlyableTime | None = None,
    mc: MonteCarloResult | None = None,
    rules_rows: list[dict] | None = None,
    reference_rows: list[dict] | None = None,
    fielded=None,
    title: str | None = None,
    units: str = "SI",
) -> str:
    """The report as one HTML string.

    Parameters
    ----------
    d : Design
    env : Envelope
        :func:`aerostat_core.studies.envelope.operating_envelope` of ``d``.
    flyable : FlyableTime, optional
    mc : MonteCarloResult, optional
    rules_rows : list of dict, optional
        :func:`aerostat_core.studies.uncertainty.rule_set_spread`.
    reference_rows : list of dict, optional
        :func:`aerostat_core.studies.reference.reference_checks` (computed when ``None``).
    fielded : FieldedValidation, optional
        :func:`aerostat_core.studies.fielded.validate_fielded` (computed when ``None``).
    title : str, optional
    units : {"SI", "US"}
        Unit system of the values shown (the field registry's display units).
    """
    if units not in UNIT_SYSTEMS:
        raise ValueError(f"units = {units!r}: use one of {', '.join(UNIT_SYSTEMS)}")
    from aerostat_core.studies.fielded import validate_fielded
    from aerostat_core.studies.reference import reference_checks

    req, cfg = d.requirement, d.configuration
    s = d.summary()
    title = title or (
        f"Aerostat design report: {_shown(req.payload_mass, 'kg', units):.4g} "
        f"{_in('kg', units)} at {_shown(req.altitude, 'm', units):.4g} {_in('m', units)}"
    )
    parts = [
        f"<h1>{_e(title)}</h1>",
        f"<p>Generated {_e(_dt.datetime.now(_dt.UTC).strftime('%Y-%m-%d %H:%M UTC'))} by "
        f"aerostat-design {_e(program_version())}; values in "
        f"{'SI units' if units == 'SI' else 'US customary units'}.</p>",
    ]
    parts.append(_section("verdict", "Verdict", _verdict(d, units)))
    parts.append(
        _section(
            "requirement",
            "Requirement",
            _table(
                requirement_rows(req, units),
                [("quantity", "Requirement"), ("value", "Value"), ("unit", "Unit")],
            ),
        )
    )
    rs = req.rule_set
    parts.append(
        _section(
            "rules",
            "Rule set",
            (
                f"<p><b>{_e(rs.name)}</b>: {_e(rs.title)}. Limits left open take the rule set's value; "
                "the table above shows them as applied.</p>"
            ),
        )
    )
    parts.append(
        _section(
            "geometry",
            "Geometry",
            (
                _figure(side_view_figure(d), "Side view to scale (nose left).", "side_view")
                + _table(
                    [
                        {
                            "quantity": r["quantity"],
                            "value": _shown(r["value"], r["unit"], units),
                            "unit": "" if r["unit"] == "-" else _in(r["unit"], units),
                        }
                        for r in d.geometry_rows()
                    ],
                    [("quantity", "Quantity"), ("value", "Value"), ("unit", "Unit")],
                )
            ),
        )
    )
    parts.append(
        _section(
            "mass",
            "Mass breakdown",
            _table(
                _unit_rows(d.mass_rows(), {"mass_kg": "kg"}, units),
                [
                    ("item", "Item"),
                    ("mass_kg", f"Mass [{_in('kg', units)}]"),
                    ("share_pct", "Share [%]"),
                ],
            )
            + _table(
                [
                    {
                        "quantity": f"Gross buoyancy [{_in('N', units)}]",
                        "value": _shown(s.gross_buoyancy_N, "N", units),
                    },
                    {
                        "quantity": f"Free lift [{_in('kg', units)}]",
                        "value": _shown(s.free_lift_kg, "kg", units),
                    },
                    {"quantity": "Static lift share [%]", "value": s.percent_static_lift},
                    {"quantity": "Gas fill cost [USD]", "value": s.gas_cost_USD},
                ],
                [("quantity", "Quantity"), ("value", "Value")],
            ),
        )
    )
    L, F, W = _in("m", units), _in("N", units), _in("m/s", units)
    cols = [
        ("wind_speed_m_s", f"Wind [{W}]"),
        ("alpha_eq_deg", "α_eq [deg]"),
        ("dynamic_lift_N", f"Dynamic lift [{F}]"),
        ("drag_N", f"Drag [{F}]"),
        ("blow_by_m", f"Blow-by [{L}]"),
        ("flying_height_m", f"Flying height [{L}]"),
        ("tension_top_N", f"Tension at top [{F}]"),
        ("tension_winch_N", f"Tension at winch [{F}]"),
        ("tether_angle_winch_deg", "Tether angle at winch [deg]"),
        ("safety_factor", "Safety factor"),
        ("flags", "Limits exceeded"),
    ]
    perf_units = {
        "wind_speed_m_s": "m/s",
        "dynamic_lift_N": "N",
        "drag_N": "N",
        "blow_by_m": "m",
        "flying_height_m": "m",
        "tension_top_N": "N",
        "tension_winch_N": "N",
    }
    parts.append(
        _section(
            "performance",
            "Performance",
            (
                _figure(
                    performance_figure(d, mc),
                    "Blow-by and tether tension versus wind "
                    "(shaded: 5-95 % Monte Carlo band, when run).",
                    "performance",
                )
                + _table(_unit_rows(d.performance.rows(), perf_units, units), cols)
            ),
        )
    )
    parts.append(
        _section(
            "tether",
            "Tether profiles",
            _figure(tether_figure(d), "Tether shape from the winch at the sweep speeds.", "tether"),
        )
    )
    crow = d.constraint_rows()
    parts.append(
        _section(
            "constraints",
            "Constraint margins",
            _table(
                crow,
                [
                    ("label", "constraint"),
                    ("checked_at", "checked at"),
                    ("value", "value"),
                    ("limit", "limit"),
                    ("margin", "margin"),
                    ("unit", "unit"),
                    ("met", "met"),
                ],
                cls={"met": lambda v: "ok" if v else "bad"},
            ),
        )
    )
    parts.append(
        _section(
            "envelope",
            "Operating envelope",
            (
                f"<p>{env.points} points: wind {env.wind[0]:g}-{env.wind[-1]:g} m/s x altitude "
                f"{env.altitude[0]:g}-{env.altitude[-1]:g} m for the built aerostat "
                f"({env.volume:.1f} m3). Colour: the largest normalised constraint value g (binding "
                "constraint); lines: where each constraint reaches its limit.</p>"
                + _figure(
                    envelope_figure(env), "Binding constraint over wind and altitude.", "envelope"
                )
                + _table(
                    _envelope_rows(env),
                    [
                        ("payload_kg", "payload [kg]"),
                        ("altitude_m", "altitude [m]"),
                        ("flyable_up_to_m_s", "flyable up to [m/s]"),
                        ("stopped_by", "first limit"),
                    ],
                )
            ),
        )
    )
    if flyable is not None:
        f = flyable.summary()
        fly_rows = [
            {"quantity": "time flyable [%]", "value": f["percent_time_flyable"]},
            {"quantity": "longest expected outage [h]", "value": f["longest_outage_h"]},
            {
                "quantity": f"design wind for {100 * f['target_availability']:g} % "
                "availability [m/s]",
                "value": f["design_wind_for_target_m_s"],
            },
            {"quantity": "wind source", "value": f["wind_source"]},
            {"quantity": "at altitude [m]", "value": f["site_altitude_m"]},
            {
                "quantity": "flyable winds [m/s]",
                "value": "; ".join(f"{a:.1f}-{b:.1f}" for a, b in flyable.intervals),
            },
        ]
        body = _table(fly_rows)
    else:
        body = "<p>No site wind given.</p>"
    parts.append(_section("flyable", "Flyable time at the site", body))
    if mc is not None:
        m = mc.summary()
        body = (
            f"<p>{mc.n} samples, seed {mc.seed}. Bands at the design wind "
            f"{mc.design_wind:g} m/s and probability of meeting each constraint.</p>"
            + _table(
                [
                    {
                        "quantity": q,
                        "p05": m[f"{k}_p05_{u}"],
                        "p50": m[f"{k}_p50_{u}"],
                        "p95": m[f"{k}_p95_{u}"],
                    }
                    for q, k, u in (
                        ("blow-by [m]", "blow_by", "m"),
                        ("tension [N]", "tension", "N"),
                        ("free lift [kg]", "free_lift", "kg"),
                    )
                ]
            )
            + _table(
                [
                    {"constraint": BY_NAME[k].label, "probability met": v}
                    for k, v in mc.p_met.items()
                ]
                + [{"constraint": "all", "probability met": mc.p_feasible}]
            )
            + "<h3>Uncertain inputs</h3>"
            + _table(
                [
                    {
                        "input": u.label,
                        "sigma": u.sigma,
                        "kind": "relative" if u.relative else "absolute",
                        "source": u.source,
                    }
                    for u in mc.specs
                ]
            )
        )
    else:
        body = "<p>Monte Carlo not run.</p>"
    if rules_rows:
        # one column per rule set: 14 quantities side by side made the report 1735 px wide
        names = [str(r["rules"]) for r in rules_rows]
        spread = [
            {"quantity": k.replace("_", " "), **{n: r[k] for n, r in zip(names, rules_rows)}}
            for k in rules_rows[0]
            if k != "rules"
        ]
        body += "<h3>Rule sets (same mission, SI units)</h3>" + _table(
            spread, [("quantity", "Quantity"), *((n, n) for n in names)]
        )
    parts.append(_section("uncertainty", "Uncertainty", body))
    ref = reference_checks() if reference_rows is None else reference_rows
    fv = validate_fielded() if fielded is None else fielded
    n_pass = sum(r["passed"] for r in ref)
    body = (
        f"<p>Reference numbers: {n_pass} of {len(ref)} within tolerance. Fielded aerostats: "
        f"median |length error| {100 * fv.median_abs_length_error:.0f} %, largest "
        f"{100 * fv.max_abs_length_error:.0f} %.</p>"
        + _table(
            ref,
            [
                ("name", "check"),
                ("reference", "reference"),
                ("value", "model"),
                ("unit", "unit"),
                ("error_pct", "error [%]"),
                ("tolerance_pct", "tolerance [%]"),
                ("kind", "kind"),
                ("passed", "passed"),
            ],
            cls={"passed": lambda v: "ok" if v else "bad"},
        )
        + _cited_table(
            fv.table(),
            [
                ("system", "system"),
                ("role", "role"),
                ("published_length_m", "published length [m]"),
                ("predicted_length_m", "predicted length [m]"),
                ("length_error_pct", "error [%]"),
            ],
        )
    )
    parts.append(_section("validation", "Validation status", body))
    parts.append(
        _section(
            "version",
            "Program version",
            (
                f"<p>aerostat-design {_e(program_version())}; configuration: hull fabric "
                f"{_e(cfg.hull_fabric.name if hasattr(cfg.hull_fabric, 'name') else '')} "
                f"{cfg.hull_fabric.areal_density:g} kg/m2, tether breaking strength "
                f"{cfg.tether.breaking_strength:g} N, gas {_e(cfg.gas.kind)} purity "
                f"{cfg.gas.purity:g}.</p>"
            ),
        )
    )
    return (
        '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8">'
        f"<title>{_e(title)}</title><style>{_CSS}</style></head><body>"
        + "".join(parts)
        + "</body></html>"
    )


def build_report(
    d: Design,
    site=None,
    n_monte_carlo: int = 2000,
    seed: int = 0,
    base_requirement=None,
    client=None,
    units: str = "SI",
) -> str:
    """Compute the envelope, flyable time, Monte Carlo and rule-set spread of ``d`` and render
    the report (``n_monte_carlo = 0`` leaves the uncertainty out)."""
    from aerostat_core.studies.envelope import operating_envelope
    from aerostat_core.studies.site_wind import flyable_time
    from aerostat_core.studies.uncertainty import monte_carlo, rule_set_spread

    env = operating_envelope(d, client=client)
    ft = flyable_time(d, site)
    mc = rows = None
    if n_monte_carlo:
        mc = monte_carlo(d, n_monte_carlo, seed, client=client)
        rows = rule_set_spread(
            base_requirement or d.requirement, n=min(n_monte_carlo, 2000), seed=seed, client=client
        )
    return render_report(d, env, ft, mc, rows, units=units)
