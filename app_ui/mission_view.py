"""UI of the Design page's Mission tab: payload power, endurance, ballonet, envelope, survival
wind and winch (issue 13). No physics here: every number comes from
:class:`aerostat_core.model.mission_report.MissionReport` (``Design.mission``); this module lays them out and
edits the mission inputs through :func:`app_ui.state.set_current_inputs`."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import pandas as pd
import streamlit as st

from aerostat_core import Requirement
from aerostat_core.base.validation import InputError
from aerostat_core.model.input_paths import spec_for_path
from aerostat_core.model.mission import MissionSpec

from . import cache, entry, formats, show, state
from .headline import Headline
from .text import plain

#: Labels of the choices (the values are the engine's).
POWER_LABELS = {"onboard": "Onboard battery", "tether": "Through the tether"}
BALLONET_LABELS = {
    "off": "Report only (not built)",
    "auto": "Build where the 500 m rule calls for one",
    "on": "Always build",
}
FORM_KEY = "mission_form"
ERROR_KEY = "mission_error"


def _fmt(v: float | None, digits: int = 1) -> str:
    return "never" if v is None else f"{v:,.{digits}f}"


#: The mission form's number boxes: key -> (input dataclass, field); label, unit and range come
#: from the field registry.
_BOXES = {
    "mission_power": (Requirement, "payload_power"),
    "mission_endurance": (Requirement, "endurance_days"),
    "mission_deployment": (Requirement, "deployment_days"),
    "mission_superheat": (MissionSpec, "superheat"),
}


def _read(key: str) -> float:
    """A mission box's SI number (a decimal comma is a decimal point); ValueError names the box."""
    return entry.spec_read(st.session_state.get(key), *_BOXES[key], key)


def _apply() -> None:
    """Form callback: write the mission inputs into the current design inputs."""
    ss = st.session_state
    req, cfg = state.current_inputs()
    try:
        req2 = replace(
            req,
            payload_power=_read("mission_power"),
            power_via=ss["mission_power_via"],
            endurance_days=_read("mission_endurance"),
            deployment_days=_read("mission_deployment"),
        )
        cfg2 = replace(
            cfg,
            mission=replace(
                cfg.mission,
                ballonet=ss["mission_ballonet"],
                superheat=_read("mission_superheat"),
            ),
        )
    except InputError as exc:  # in the form's words: the registry label, not Class.field
        ss[ERROR_KEY] = f"{exc.label}: {exc.reason}."
        return
    except ValueError as exc:
        ss[ERROR_KEY] = str(exc)
        return
    ss.pop(ERROR_KEY, None)
    state.set_current_inputs(req2, cfg2)


def _select(col: Any, path: str, key: str, value: str, shown: dict[str, str]) -> None:
    e = spec_for_path(path)
    options = list(e.spec.choices)
    col.selectbox(
        e.label,
        options,
        index=options.index(value),
        format_func=shown.get,
        key=key,
        help=e.spec.help,
    )


def _inputs(req, cfg) -> None:
    with st.form(FORM_KEY, border=True):
        st.markdown("**Mission inputs** (off by default: no power, no endurance requirement)")
        c = st.columns(3)
        entry.spec_box(c[0], Requirement, "payload_power", req.payload_power, "mission_power")
        _select(c[1], "requirement.power_via", "mission_power_via", req.power_via, POWER_LABELS)
        entry.spec_box(c[2], Requirement, "endurance_days", req.endurance_days, "mission_endurance")
        c = st.columns(3)
        entry.spec_box(
            c[0], Requirement, "deployment_days", req.deployment_days, "mission_deployment"
        )
        _select(
            c[1],
            "configuration.mission.ballonet",
            "mission_ballonet",
            cfg.mission.ballonet,
            BALLONET_LABELS,
        )
        entry.spec_box(c[2], MissionSpec, "superheat", cfg.mission.superheat, "mission_superheat")
        st.form_submit_button("Apply mission inputs", on_click=_apply, icon=":material/send:")
    err = st.session_state.get(ERROR_KEY)
    if err:
        st.error(plain(err), icon=":material/error:")


def render(d) -> None:
    """Draw the Mission tab of design ``d`` (an :class:`aerostat_core.Design`)."""
    m = d.mission
    s = d.summary().mission  # the mission headline numbers (MissionSummary)
    req, cfg = d.requirement, d.configuration
    _inputs(req, cfg)
    # a wrapping row (metrics as wide as their label): six fixed columns cut the labels to
    # "He top-up, 3…" even at 1400 px; volumes and forces in the sidebar's unit system
    show.headlines([
        Headline(
            formats.label("Ballonet", "volume"),
            formats.shown(s.ballonet_volume_m3, "volume"),
            help="Ballonet volume from launch to operating altitude plus the superheat.",
        ),
        Headline(
            "Days to top-up",
            _fmt(s.days_to_top_up),
            help="Days of helium permeation until the free lift falls to the required share.",
        ),
        Headline(
            formats.label(f"He top-up, {req.deployment_days:g} d", "volume"),
            formats.shown(s.helium_top_up_m3, "volume"),
            help=f"Helium to replace what permeates out; cost {m.top_up_cost:,.0f} USD.",
        ),
        Headline(
            "Envelope stress margin",
            _fmt(s.envelope_stress_margin, 2),
            help="Fabric strength / (safety factor × membrane load) − 1 at the design wind.",
        ),
        Headline(
            formats.label("Winch pull", "force"),
            formats.shown(s.winch_pull_N, "force"),
            help="Largest tether tension at the winch over the sweep and the survival wind.",
        ),
        Headline(
            "Winch power [W]", _fmt(s.winch_power_W, 0), help="Line pull × reel speed / efficiency."
        ),
    ])
    surv = req.survival_wind
    if m.stay_up:
        st.success(
            f"Can stay up at the survival wind {surv:g} m/s: tether safety factor "
            f"{m.survival_safety_factor:.2f} (needs {m.survival_safety_factor_required:g}), "
            f"envelope pressure margin {100 * m.survival_pressure_margin:.0f} %.",
            icon=":material/check_circle:",
        )
    else:
        when = (
            f"before {m.reel_in_wind:g} m/s"
            if m.reel_in_wind is not None
            else f"before the survival wind {surv:g} m/s"
        )
        st.warning(
            f"Must be reeled in {when}: at {surv:g} m/s the tether safety factor is "
            f"{m.survival_safety_factor:.2f} (needs {m.survival_safety_factor_required:g}) and "
            f"the envelope pressure margin {100 * m.survival_pressure_margin:.0f} %.",
            icon=":material/warning:",
        )
    if m.ballonet.needed and not m.ballonet.built:
        st.info(
            f"The thesis' 500 m rule calls for a ballonet here ({100 * m.ballonet.fraction:.1f} % "
            f"of the hull volume against {100 * m.ballonet.rule_fraction:.1f} % at 500 m); it is "
            "not in the mass breakdown until Ballonet is set to build one.",
            icon=":material/info:",
        )
    if m.decay is not None:
        dec = pd.DataFrame(
            {
                "Day": m.decay["day"],
                "Free lift [kg]": m.decay["free_lift_kg"],
                "Required free lift [kg]": m.decay["required_kg"],
            }
        )
        st.line_chart(dec, x="Day", y=["Free lift [kg]", "Required free lift [kg]"], height=260)
        st.caption(
            f"Free lift without top-up as helium permeates out (purity "
            f"{100 * m.decay['purity'][0]:.1f} % → {100 * m.decay['purity'][-1]:.1f} % in "
            f"{m.decay['day'][-1]:g} days)."
        )
    rows = m.rows()
    frame = pd.DataFrame(
        {
            "Group": [r["group"] for r in rows],
            "Quantity": [r["quantity"] for r in rows],
            "Value": [r["value"] for r in rows],
            "Unit": [formats.cell_unit(r["unit"]) for r in rows],  # "-" was a Markdown bullet
        }
    )
    # static, cells that wrap: every row and column in sight at 1024 px (the grid scrolled)
    st.table(
        frame.style.format({"Value": "{:.4g}"}, na_rep=formats.missing("no finite value")),
        hide_index=True,
    )
    st.download_button(
        "Mission table (CSV)",
        data=cache.csv_bytes(rows),
        file_name="mission.csv",
        mime="text/csv",
        on_click="ignore",
        icon=":material/download:",
        key="dl_mission",
    )
    st.caption(
        "Envelope: internal pressure ≥ 1.2 q + hydrostatic head, hoop p r and longitudinal "
        "p r/2 + M/(π r²) loads, safety factor 4 on the fabric strength (inputs; their sources "
        "and what could not be verified: docs/methods.md §1.14). "
        "Endurance: helium permeates at the fabric's rate and is replaced by air, so purity and "
        "free lift decay. Ballonet against the thesis' 500 m rule. Winch drum from the tether's "
        "minimum bend radius."
    )
