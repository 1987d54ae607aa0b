"""UI of the Design page's Mission tab: payload power, endurance, ballonet, envelope, survival
wind and winch (issue 13). No physics here: every number comes from
:class:`aerostat_core.mission.MissionReport` (``Design.mission``); this module lays them out and
edits the mission inputs through :func:`app_ui.state.set_current_inputs`."""

from __future__ import annotations

from dataclasses import replace

import pandas as pd
import streamlit as st

from aerostat_core.mission import BALLONET_MODES, POWER_ROUTES

from . import cache, entry, state
from .widgets import plain

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


#: The mission form's number boxes: key -> (label, lowest, highest, unit).
_BOXES = {
    "mission_power": ("Payload power [W]", 0.0, 1e5, "W"),
    "mission_endurance": ("Endurance without top-up [day]", 0.0, 365.0, "day"),
    "mission_deployment": ("Deployment length [day]", 0.0, 3650.0, "day"),
    "mission_superheat": ("Gas superheat [K]", 0.0, 40.0, "K"),
}


def _read(key: str) -> float:
    """A mission box's number (a decimal comma is a decimal point); ValueError names the box."""
    label, lo, hi, unit = _BOXES[key]
    return float(entry.read(st.session_state.get(key), label, lo=lo, hi=hi, unit=unit))


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
    except ValueError as exc:
        ss[ERROR_KEY] = str(exc)
        return
    ss.pop(ERROR_KEY, None)
    state.set_current_inputs(req2, cfg2)


def _inputs(req, cfg) -> None:
    with st.form(FORM_KEY, border=True):
        st.markdown("**Mission inputs** (off by default: no power, no endurance requirement)")
        c = st.columns(3)
        entry.number_box(
            "Payload power [W]",
            key="mission_power",
            value=req.payload_power,
            container=c[0],
            help="Electrical power the payload draws (thesis Table 2.4); 0 models no supply.",
        )
        c[1].selectbox(
            "Power from",
            POWER_ROUTES,
            index=POWER_ROUTES.index(req.power_via),
            format_func=POWER_LABELS.get,
            key="mission_power_via",
            help="An onboard battery adds its mass; through the tether adds copper conductors "
            "to the tether (mass, diameter and drag, strength).",
        )
        entry.number_box(
            "Endurance without top-up [day]",
            key="mission_endurance",
            value=req.endurance_days,
            container=c[2],
            help="Days the free-lift margin must last while helium permeates out (thesis §2.3: "
            "tactical 5-7 days). 0: no requirement.",
        )
        c = st.columns(3)
        entry.number_box(
            "Deployment length [day]",
            key="mission_deployment",
            value=req.deployment_days,
            container=c[0],
            help="Period over which the helium top-up gas and its cost are reported.",
        )
        c[1].selectbox(
            "Ballonet",
            BALLONET_MODES,
            index=BALLONET_MODES.index(cfg.mission.ballonet),
            format_func=BALLONET_LABELS.get,
            key="mission_ballonet",
            help="The thesis flies below 500 m without one (§2.2.1(c)); a built ballonet adds its "
            "fabric to the mass breakdown.",
        )
        entry.number_box(
            "Gas superheat [K]",
            key="mission_superheat",
            value=cfg.mission.superheat,
            container=c[2],
            help="Day-time gas temperature above ambient at the operating altitude.",
        )
        st.form_submit_button("Apply mission inputs", on_click=_apply, icon=":material/send:")
    err = st.session_state.get(ERROR_KEY)
    if err:
        st.error(plain(err), icon=":material/error:")


def render(d) -> None:
    """Draw the Mission tab of design ``d`` (an :class:`aerostat_core.Design`)."""
    m = d.mission
    s = d.summary()
    req, cfg = d.requirement, d.configuration
    _inputs(req, cfg)
    c = st.columns(6)
    c[0].metric(
        "Ballonet [m³]",
        _fmt(s["ballonet_volume_m3"]),
        help="Ballonet volume from launch to operating altitude plus the superheat.",
    )
    c[1].metric(
        "Days to top-up",
        _fmt(s["days_to_top_up"]),
        help="Days of helium permeation until the free lift falls to the required share.",
    )
    c[2].metric(
        f"He top-up, {req.deployment_days:g} d [m³]",
        _fmt(s["helium_top_up_m3"]),
        help=f"Helium to replace what permeates out; cost {m.top_up_cost:,.0f} USD.",
    )
    c[3].metric(
        "Envelope stress margin",
        _fmt(s["envelope_stress_margin"], 2),
        help="Fabric strength / (safety factor × membrane load) − 1 at the design wind.",
    )
    c[4].metric(
        "Winch pull [N]",
        _fmt(s["winch_pull_N"], 0),
        help="Largest tether tension at the winch over the sweep and the survival wind.",
    )
    c[5].metric(
        "Winch power [W]", _fmt(s["winch_power_W"], 0), help="Line pull × reel speed / efficiency."
    )
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
            "Unit": [r["unit"] for r in rows],
        }
    )
    st.dataframe(
        frame,
        hide_index=True,
        width="stretch",
        height=560,
        column_config={"Value": st.column_config.NumberColumn(format="%.4g")},
        key="mission_table",
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
        "p r/2 + M/(π r²) loads, safety factor 4 on the fabric strength (Carichner & Nicolai). "
        "Endurance: helium permeates at the fabric's rate and is replaced by air, so purity and "
        "free lift decay. Ballonet against the thesis' 500 m rule. Winch drum from the tether's "
        "minimum bend radius."
    )
