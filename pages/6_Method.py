"""Method page: the equations, assumptions and sources of the engine, which numbers are
calibrated and which predicted, and the live validation table (aerostat_core.studies.reference)."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
import streamlit as st

from aerostat_core.base.validation import short
from aerostat_core.model.io import rows_to_csv
from app_ui import formats, show, text
from app_ui.headline import Headline
from app_ui.shell import run_inside_the_app

run_inside_the_app()  # a page reached by its own address still runs inside app.py
st.title("Method")
st.caption(
    "How the design is computed, step by step. The method follows Mahmood (2020, USM MSc thesis, "
    "“Conceptual Design and Dynamical Analysis of Aerostat System”), rebuilt from the thesis "
    "text we hold (to §2.4.3), public code implementing the same textbook models, and the "
    "standard references listed at the end. SI units throughout."
)

# The design documents of the repository (docs/), shipped with the app and readable here.
_ROOT = Path(__file__).resolve().parents[1]
with st.expander("Design documents (docs/): method, dynamics, validation, architecture"):
    _doc = st.radio("Document", [f"docs/{d}.md" for d in ("methods", "dynamics", "validation",
                                                            "architecture")],
                    horizontal=True, key="method_doc")
    if (_ROOT / _doc).is_file():
        st.markdown((_ROOT / _doc).read_text(encoding="utf-8"))
    else:
        st.info(f"{_doc} is not part of this installation.", icon=":material/info:")


@st.cache_data(show_spinner="Running the reference checks...")
def _reference_rows() -> list[dict] | None:
    try:
        from aerostat_core.studies.reference import reference_checks
    except ImportError:
        return None
    return reference_checks()


@st.cache_data(show_spinner="Sizing the fielded aerostats...")
def _fielded_rows() -> list[dict]:
    from aerostat_core.studies.fielded import validate_fielded

    v = validate_fielded()
    return [v.statistics(), v.table()]


tab_eq, tab_val, tab_src = st.tabs(
    ["Equations and assumptions", "Validation (live)", "Sources and confidence"]
)

with tab_eq:
    st.markdown("""
**Design chain.** requirement → atmosphere and lifting gas → hull sizing (NPL shape) → fins →
mass budget → buoyancy → hull and fin aerodynamics → trim about the confluence point → tether
profile, tension and blow-by versus wind → (sensitivity, optimisation, dynamics on their pages).

**Frames.** Body frame: origin at the nose, ξ aft along the axis, z up. Earth frame: X downwind,
Z up; the aerostat faces into the wind. α is the pitch angle of the hull axis, nose-up positive
(with horizontal wind it is the angle of attack).
""")

    with st.expander("1 · Atmosphere (ISA troposphere)", expanded=True):
        st.markdown(
            "Air properties at the operating altitude (site elevation + altitude; h below "
            "is its geopotential altitude, h = r₀z/(r₀ + z) with r₀ = 6 356 766 m), with an "
            "optional temperature offset ΔT for an off-standard day:"
        )
        st.latex(
            r"T = 288.15 - 0.0065\,h + \Delta T,\qquad "
            r"P = 101\,325\left(\frac{288.15 - 0.0065\,h}{288.15}\right)^{5.25588},\qquad "
            r"\rho_{air} = \frac{P}{287.05\,T}"
        )
        st.latex(r"\mu = \frac{1.458\times10^{-6}\,T^{3/2}}{T + 110.4}\quad\text{(Sutherland)}")
        st.markdown(
            "Check values (ΔT = 0): ρ = 1.2250 / 1.2133 / 1.1901 / 1.1673 kg/m³ at "
            "0 / 100 / 300 / 500 m. The air density is taken at the operating altitude; "
            "the few metres of altitude loss in wind change it by < 0.1 %."
        )

    with st.expander("2 · Lifting gas and buoyancy"):
        st.markdown(
            "Gas at hull pressure P + ΔP (superpressure), ideal gas, mixed with air by "
            "the purity k (volume fraction):"
        )
        st.latex(
            r"\rho_{gas} = \frac{(P + \Delta P)\,M_{gas}}{R_u\,T},\qquad "
            r"\rho_{LTA} = k\,\rho_{gas} + (1 - k)\,\rho_{air}"
        )
        st.markdown(
            "The *fixed* density model uses the thesis constants instead (helium "
            "0.169 kg/m³, hydrogen 0.085 kg/m³, Table 2.5). Gross buoyancy and free "
            "lift — the gas mass is in the mass budget, so it is subtracted once only:"
        )
        st.latex(
            r"F_B = \rho_{air}\,g\,V,\qquad L_f = F_B - m_{total}\,g,\qquad "
            r"\mathrm{PSL} = 100\,\frac{L_f}{F_B}"
        )

    with st.expander("3 · Hull: NPL double ellipsoid"):
        st.markdown(
            "Two half ellipsoids of revolution (nose semi-axis a₁, tail semi-axis a₂) "
            "meet at the maximum radius b (Khoury & Gillett 1999):"
        )
        st.latex(
            r"r(\xi) = b\sqrt{1 - \left(\frac{a_1 - \xi}{a_1}\right)^2}\ (0 \le \xi \le "
            r"a_1),\qquad r(\xi) = b\sqrt{1 - \left(\frac{\xi - a_1}{a_2}\right)^2}\ "
            r"(a_1 \le \xi \le l)"
        )
        st.latex(
            r"V = \tfrac{2}{3}\pi b^2 (a_1 + a_2) = \tfrac{\pi}{6} d^2 l,\qquad "
            r"f = \frac{l}{d}\ \Rightarrow\ d = \left(\frac{6V}{\pi f}\right)^{1/3},\ "
            r"l = f\,d,\ a_1 = 0.432\,l"
        )
        st.markdown(
            "Surface area from the half-spheroid closed forms; centre of buoyancy from "
            "the half-ellipsoid centroids (3a/8 from the base):"
        )
        st.latex(
            r"S_{half}(a,b) = \pi b^2 + \pi a b\,\frac{\arcsin e}{e},\ "
            r"e = \sqrt{1 - b^2/a^2};\qquad "
            r"\xi_{CB} = \frac{a_1\cdot\frac{5a_1}{8} + a_2\left(a_1 + \frac{3a_2}{8}\right)}"
            r"{a_1 + a_2}"
        )
        st.markdown(
            "The split a₁/l = 0.432 is the NPL standard shape (public Gertler-envelope "
            "tables); it is an input."
        )

    with st.expander("4 · Added-mass (Lamb) inertia factors"):
        st.markdown("For the prolate spheroid of the same fineness ratio, e = √(1 − 1/f²):")
        st.latex(
            r"\alpha_0 = \frac{2(1-e^2)}{e^3}\left[\tfrac12\ln\frac{1+e}{1-e} - e\right],"
            r"\quad \beta_0 = \frac{1}{e^2} - \frac{1-e^2}{2e^3}\ln\frac{1+e}{1-e}"
        )
        st.latex(
            r"k_1 = \frac{\alpha_0}{2-\alpha_0},\quad k_2 = k_3 = \frac{\beta_0}{2-\beta_0},"
            r"\quad k' = \frac{e^4(\beta_0-\alpha_0)}{(2-e^2)\left[2e^2-(2-e^2)"
            r"(\beta_0-\alpha_0)\right]}"
        )
        st.markdown(
            "f = 4: k₁ = 0.082, k₃ = 0.860, k′ = 0.608 (Lamb's table; checked live on "
            "the Validation tab)."
        )

    with st.expander("5 · Hull aerodynamics (Jones & DeLaurier 1983) and Hoerner drag"):
        st.markdown(
            "With q = ½ρV², shape integrals up to the potential-flow cut-off station "
            "l_h (default: the fin root, the thesis' “distance of fin from nose”) and "
            "moments about ξ_m (the centre of buoyancy):"
        )
        st.latex(
            r"I_1 = \pi r(l_h)^2,\quad I_3 = \int_0^{l_h}(\xi_m-\xi)\frac{dA}{d\xi}d\xi,"
            r"\quad J_1 = \int_0^{l} 2r\,d\xi,\quad J_2 = \int_0^{l} 2r(\xi_m-\xi)\,d\xi"
        )
        st.latex(
            r"N_h = q\left[(k_3-k_1)\eta_k I_1 \sin 2\alpha\cos\tfrac{\alpha}{2} + "
            r"(C_{dc})_h J_1 \sin\alpha\,|\sin\alpha|\right]"
        )
        st.latex(
            r"A_h = q\left[C_{DV} V^{2/3}\cos^2\alpha - (k_3-k_1)\eta_k I_1\sin 2\alpha"
            r"\sin\tfrac{\alpha}{2}\right]"
        )
        st.latex(
            r"M_h = q\left[(k_3-k_1)\eta_k I_3 \sin 2\alpha\cos\tfrac{\alpha}{2} + "
            r"(C_{dc})_h J_2 \sin\alpha\,|\sin\alpha|\right]"
        )
        st.markdown(
            "Zero-α drag from Hoerner (Fluid-Dynamic Drag, 1965), Reynolds number on "
            "the hull length:"
        )
        st.latex(
            r"C_{DV} = \frac{0.172 f^{1/3} + 0.252 f^{-1.2} + 1.032 f^{-2.7}}"
            r"{Re_l^{1/6}}\quad\text{(on } V^{2/3})"
        )
        st.markdown(
            "Defaults: η_k = 1.19, (C_dc)_h = 0.32 (published airship coefficient "
            "sets); both are inputs under *Advanced model parameters*."
        )

    with st.expander("6 · Fins"):
        st.markdown(
            "Trapezoidal fins sized from statistical ratios and the two fin design "
            "variables (area change ΔS_f, position Δl_f):"
        )
        st.latex(
            r"S_f = r_S\,S_h\left(1 + \frac{\Delta S_f}{100}\right),\ S_1 = \frac{S_f}{n},"
            r"\ S_p = \sqrt{\frac{AR\,S_1}{2}},\ RC = \frac{2S_1}{(1+\lambda)S_p},\ "
            r"TC = \lambda\,RC,\ l_f = \Delta l_f\,l"
        )
        st.markdown(
            "Lift slope of an opposite pair taken as one wing (DATCOM/Helmbold), "
            "induced drag with Raymer's Oswald factor, forces at the quarter-MAC point:"
        )
        st.latex(
            r"C_{L\alpha} = \frac{2\pi AR}{2 + \sqrt{\frac{AR^2}{\kappa^2}"
            r"\left(1 + \tan^2\Lambda_{c/2}\right) + 4}},\quad "
            r"C_L = \eta_f C_{L\alpha}\alpha,\quad C_D = C_{D0} + \frac{C_L^2}{\pi e AR}"
        )
        st.markdown(
            "Only the horizontal projection of the fins lifts (factor Σcos²φ over the "
            "fin azimuths). Fin lift is held flat beyond the stall angle, and a trim "
            "beyond it is flagged. The statistical fin-area ratio 0.227 is calibrated "
            "to the thesis' 7.8 kg of fins (Table 2.2)."
        )

    with st.expander("7 · Mass budget"):
        st.latex(
            r"m_{hull} = GSM_h\,S_h,\quad m_{fin} = n\,GSM_f\,k_{fab}\,S_1,\quad "
            r"m_{gas} = \rho_{LTA}V,\quad m_{misc} = r_{misc}\,m_{hull}"
        )
        st.latex(
            r"m_a = m_{hull} + m_{fin} + m_{gas} + m_{misc} + m_p,\qquad "
            r"m_{total} = m_a + w_t\,l_t"
        )
        st.markdown(
            "Centre of gravity from the component centroids (fabric at its surface "
            "centroid, gas at the centre of buoyancy, fins at their planform centroid, "
            "payload and miscellaneous items at the hull belly)."
        )

    with st.expander("8 · Trim: moment balance about the confluence point"):
        st.markdown(
            "The confluence point C sits below the centre of net static lift (so the "
            "hull flies level in calm air), a drop of 0.6 d below the hull "
            "(engineering guess; an input):"
        )
        st.latex(
            r"\xi_C = \frac{F_B\,\xi_{CB} - m_a g\,\xi_{CG}}{F_B - m_a g},\qquad "
            r"z_C = -(b + 0.6\,d)"
        )
        st.markdown(
            "The sum of the moments about C of buoyancy (at CB), weight (at CG), hull "
            "force and moment, and fin force (at the fin aerodynamic centre) must vanish; "
            "the tether passes through C and has no moment about it. The equilibrium "
            "angle solves"
        )
        st.latex(
            r"M_C(\alpha_{eq}) = 0,\qquad \frac{dM_C}{d\alpha}\Big|_{\alpha_{eq}} < 0\ "
            r"\text{(stable)},\qquad C_m = \frac{M_C}{q V^{2/3} l}"
        )

    with st.expander("9 · Tether profile, tension and blow-by"):
        st.markdown(
            "Force balance on the aerostat gives the tether force at C; the tether is "
            "then marched segment by segment to the winch (Rajani, Pant & Sudhakar "
            "2010), with its weight and the cross-flow drag of the normal wind "
            "component (Heun's method, 50 segments):"
        )
        st.latex(
            r"T_x = D,\qquad T_z = F_B + L_{dyn} - m_a g,\qquad "
            r"\theta_c = \operatorname{atan2}(T_z, T_x)"
        )
        st.latex(
            r"dW = w_t g\,\Delta s,\quad dD = \tfrac12\rho_{air}(V\sin\theta)^2 d_t\,"
            r"\Delta s\,C_{d,t},\quad T_{x,i+1} = T_{x,i} + dD\sin\theta_i,\quad "
            r"T_{z,i+1} = T_{z,i} - dW - dD\cos\theta_i"
        )
        st.latex(
            r"x_{blow\text{-}by} = \sum \Delta s\cos\theta_i,\qquad H = \sum \Delta s\sin"
            r"\theta_i,\qquad SF = \frac{T_{break}}{\max T}"
        )
        st.markdown(
            "The tether length equals the operating altitude (thesis practice); the "
            "altitude loss in wind is reported. Wind is uniform along the tether by "
            "default (as in the thesis plots); power-law and log-law profiles are "
            "options."
        )

    with st.expander("10 · Sizing the hull"):
        st.markdown(
            "With *Sized* volume, the engine finds the smallest hull volume V* that "
            "meets the blow-by limit at the design wind with positive free lift and a "
            "taut tether (a 1-D root find on V: buoyancy grows with V, drag with "
            "V^(2/3), so blow-by falls as V rises). Requirements checked at the design "
            "wind: blow-by ≤ limit, free lift > 0, taut tether, stable trim below fin "
            "stall, tether safety factor ≥ required, fins on the hull."
        )

    st.markdown("""
**Calibrated versus predicted.** *Calibrated* numbers were used to fix a parameter and are
reproduced by construction: hull fabric 130 g/m² (sphere hull of Table 2.2), helium 0.169 kg/m³,
tether 20 g/m, miscellaneous mass 0.30 × hull, fin-area ratio 0.227 (7.8 kg of fins), helium
price 38.5 USD/m³ (USD 1925 for 50 m³). *Predicted* numbers were not used to tune anything:
the NPL hull mass of Table 2.2 and the baseline total mass of 90.65 kg (thesis abstract).
*Checks* compare against independent published values (ISA, Lamb's table, reference tether
solutions).
""")

with tab_val:
    st.markdown(
        "Each row recomputes a published number with the engine now. "
        "**Calibrated**: used to fix a parameter. **Predicted**: not used for tuning. "
        "**Check**: an independent reference value."
    )
    try:
        ref = _reference_rows()
    except Exception as exc:  # noqa: BLE001 - never show a traceback
        ref = []
        st.error(text.plain(short(f"The reference checks could not be run: {exc}")))
    if ref is None:
        st.info(
            "The live validation table needs `aerostat_core.studies.reference`, which is not "
            "installed in this version of the engine.",
            icon=":material/info:",
        )
    elif ref:
        df = pd.DataFrame(
            [
                {
                    "Quantity": r["name"],
                    "Kind": r["kind"],
                    "Reference": r["reference"],
                    "Engine": r["value"],
                    "Unit": r["unit"],
                    "Error [%]": r["error_pct"],
                    "Tolerance [%]": r["tolerance_pct"],
                    "Within tolerance": bool(
                        r.get("passed", abs(r["error_pct"]) <= r["tolerance_pct"])
                    ),
                    "Source": r["source"],
                }
                for r in ref
            ]
        )
        n_ok = int(df["Within tolerance"].sum())
        kinds = df["Kind"].value_counts().to_dict()
        show.headlines([
            Headline("Checks within tolerance", f"{n_ok} / {len(df)}"),
            Headline("Calibrated", str(kinds.get("calibrated", 0))),
            Headline("Predicted", str(kinds.get("predicted", 0))),
            Headline("Independent checks", str(kinds.get("check", 0))),
        ])
        st.dataframe(
            df,
            hide_index=True,
            width="stretch",
            height=36 * (len(df) + 1) + 3,
            key="validation_table",
            column_config={
                "Reference": st.column_config.NumberColumn(format="%.4g"),
                "Engine": st.column_config.NumberColumn(format="%.4g"),
                "Error [%]": st.column_config.NumberColumn(format="%+.3f"),
                "Tolerance [%]": st.column_config.NumberColumn(format="%.2f"),
            },
        )
        st.download_button(
            "Validation table (CSV)",
            data=rows_to_csv(ref).encode("utf-8"),
            file_name="validation.csv",
            mime="text/csv",
            on_click="ignore",
            icon=":material/download:",
            key="dl_validation",
        )

    st.markdown(
        "**Fielded aerostats, all three classes (thesis Table 2.3).** Each system sized from "
        "its published requirement: payload and altitude, its endurance and wind rating where "
        "published, else its class' (thesis §2.3: 5/7/30 days; operating wind 20 m/s "
        "tactical, 26 m/s operational; 36 m/s strategic survival), and the vendor's l/d where "
        "its published length and diameter (or length and volume) fix it; by the default *practice* rule set, fabrics and "
        "tether chosen by load, against its published hull length and volume. The fineness "
        "ratio and the hull-systems mass law were fitted on the systems marked *fit* (declared "
        "before fitting); the others are predictions. Where a published figure is ambiguous, "
        "the *Readings* column gives both readings and the one used (docs/validation.md §7). "
        "*Payload fraction* is the published payload over the air the hull displaces, a "
        "model-free check: where a hull at least as large, flying no higher, publishes less "
        "than half of it, the *Inconsistency* column gives the evidence. Those systems stay in "
        "every headline figure; the worst error without them is shown beside, not instead."
    )
    try:
        stats, rows = _fielded_rows()
    except Exception as exc:  # noqa: BLE001 - never show a traceback
        st.error(text.plain(short(f"The fielded-aerostat harness could not be run: {exc}")))
    else:
        show.headlines([
            Headline("Median |length error|, all [%]", f"{100 * stats['all_median']:.1f}",
                     help="Target: at most 6 %."),
            Headline("Worst |length error|, all [%]", f"{100 * stats['all_worst']:.1f}",
                     help="Target: none worse than 15 %."),
            Headline("Median |length error|, held out [%]",
                     f"{100 * stats['held_out_median']:.1f}",
                     help="The systems the fit did not see."),
            Headline("Median |volume error| [%]", f"{100 * stats['volume_median']:.1f}",
                     help="Where a volume is published. Target: at most 12 %."),
            Headline("Worst |length error|, consistent figures [%]",
                     f"{100 * stats['consistent_worst']:.1f}",
                     help="Without the systems whose published figures fail the model-free "
                     "payload-fraction check (Inconsistency column). Not the target's set."),
        ])
        fielded, names = formats.frame_in_system(pd.DataFrame([{
                "System": r["system"], "Class": r["class"], "Role": r["role"],
                "Payload [kg]": r["payload_kg"],
                "Altitude [m]": r["altitude_m"], "Published length [m]": r["published_length_m"],
                "Predicted length [m]": r["predicted_length_m"],
                "Error [%]": r["length_error_pct"],
                "Published volume [m³]": r["published_volume_m3"],
                "Predicted volume [m³]": r["predicted_volume_m3"],
                "Volume error [%]": r["volume_error_pct"],
                "Sized by": r["sized_by"], "Payload fraction": r["payload_fraction"],
                "Source": r["source"], "Readings": r["readings"],
                "Inconsistency": r["inconsistency"],
            } for r in rows]))  # in the chosen unit system: "Altitude [ft]" in US
        st.dataframe(
            fielded,
            hide_index=True, width="stretch", key="fielded_table",
            column_config={names.get(c, c): f for c, f in {
                "Predicted length [m]": st.column_config.NumberColumn(format="%.2f"),
                "Error [%]": st.column_config.NumberColumn(format="%+.1f"),
                "Predicted volume [m³]": st.column_config.NumberColumn(format="%.1f"),
                "Published volume [m³]": st.column_config.NumberColumn(format="%.1f"),
                "Volume error [%]": st.column_config.NumberColumn(format="%+.1f"),
                "Payload fraction": st.column_config.NumberColumn(format="%.3f"),
            }.items()},
        )

with tab_src:
    st.markdown("""
| # | Source | Used for |
|---|---|---|
| S0 | Mahmood K., *Conceptual Design and Dynamical Analysis of Aerostat System*, MSc thesis, Universiti Sains Malaysia, 2020 | design chain, symbols, Tables 2.1–2.5, abstract numbers (170 m³ / 90.65 kg baseline, 120 m³ / 71.6 kg optimum, USD 1925 helium saving) |
| S1 | Jones S.P. & DeLaurier J.D., “Aerodynamic estimation techniques for aerostats and airships”, *J. Aircraft* 20(2), 1983 | hull normal/axial force and moment, shape integrals |
| S2 | Rajani A., Pant R.S., Sudhakar K., “Dynamic stability analysis of a tethered aerostat”, *J. Aircraft* 47(5), 2010, doi:10.2514/1.47010 | moment balance about the confluence point, segment-by-segment tether |
| S3 | Raina, Gawale & Pant, PADS (IIT Bombay), c. 2008 | sanity band: 70–100 m³ aerostats lift 10–15 kg to 100–300 m |
| S9 | Lamb, *Hydrodynamics* (1932); Tuckerman, NACA Report 210 (1926) | inertia factors k₁, k₂, k′ |
| S10 | Hoerner, *Fluid-Dynamic Drag* (1965) | volumetric drag C_DV(f, Re) |
| S11 | USAF DATCOM / Helmbold; Raymer, *Aircraft Design* | fin lift slope, Oswald factor |
| S12 | Khoury & Gillett, *Airship Technology* (1999) | NPL double-ellipsoid hull |
| — | ISO 2533:1975 (ISA) | atmosphere |

**Confidence.** High for the atmosphere, NPL geometry, Lamb factors, Hoerner drag and the tether
march; medium for the gas model, J&D coefficients, fin model, mass budget and the confluence-point
trim; low (engineering guesses, all exposed as inputs) for the fin statistics, the confluence-line
drop, the blow-by limit (0.1 × altitude) and the design wind (15 m/s). The thesis chapters with its
own tables (Ch. 3–4) could not be obtained; where the thesis is silent the choice is documented in
the input's help text.
""")
