"""Dynamics page (AppTest): run the default gust case and check the plotted data against the
static engine and the wind input; turbulence statistics table; saved-case selection; bad input and
a diverging case end with a clear message, never a traceback."""

from __future__ import annotations

import math
import re

import numpy as np
import pandas as pd
import pytest
from streamlit.testing.v1 import AppTest

from aerostat_core import Configuration, HullSpec, Requirement, design
from aerostat_core.model.io import inputs_from_dict
from app_ui import dynamics_view as view
from app_ui import state
from tests.app.conftest import APP_PATH
from tests.app.helpers import chart, messages, metrics, trace, values

DYN_PAGE = "pages/5_Dynamics.py"


@pytest.fixture
def dyn() -> AppTest:
    at = AppTest.from_file(str(APP_PATH), default_timeout=180)
    at.run()
    at.switch_page(DYN_PAGE)
    at.run()
    assert not at.exception, [e.value for e in at.exception]
    return at


def _set(at: AppTest, key: str, value) -> None:
    for kind in ("text_input", "number_input", "selectbox", "radio", "checkbox"):
        for el in getattr(at, kind):
            if getattr(el, "key", None) == key:
                # the number boxes are text boxes (read like the Design form's)
                typed = (
                    f"{value:g}" if kind == "text_input" and not isinstance(value, str) else value
                )
                el.set_value(typed)
                return
    raise KeyError(key)


def _df(at: AppTest, column: str):
    """The table that has this column header (AppTest does not expose table keys); the
    result tables are static text, so numbers are read back with float()."""
    for df in [*at.dataframe, *at.table]:
        if column in df.value.columns:
            return df.value
    raise KeyError(f"no table with column {column!r}")


def _run(at: AppTest) -> AppTest:
    at.button(key="dyn_run").click()
    at.run()
    assert not at.exception, [e.value for e in at.exception]
    return at


def test_page_invites_a_run(dyn):
    assert dyn.title[0].value == "Dynamics"
    assert any("Run simulation" in i.value for i in dyn.info)
    assert len(dyn.get("plotly_chart")) == 0


def test_default_gust_run_plots_real_data(dyn):
    at = _run(dyn)
    assert any(s.value.startswith("Finished: 150 s simulated") for s in at.success)
    d = design(*inputs_from_dict(at.session_state["design_inputs"]))
    row = next(r for r in d.performance.rows() if r["wind_speed_m_s"] == 10.0)
    # the run starts from the engine's static equilibrium at 10 m/s
    pos = chart(at, "dyn_position")
    x = values(trace(pos, "blow-by x_C [m]"), "y")
    z = values(trace(pos, "altitude z_C [m]"), "y")
    assert x[0] == pytest.approx(row["blow_by_m"], abs=0.01)
    assert z[0] == pytest.approx(row["flying_height_m"], abs=0.01)
    # a 5 m/s gust pushes the aerostat downwind, then it settles back
    assert x.max() > x[0] + 5.0
    assert x[-1] == pytest.approx(x[0], abs=0.5)
    # wind input at the hull: 10 m/s + the full 1-cos gust of 5 m/s
    wind = chart(at, "dyn_wind")
    ux = values(trace(wind, view.SIGNALS["wind_x"][0]), "y")
    assert ux[0] == pytest.approx(10.0) and ux.max() == pytest.approx(15.0, abs=0.01)
    t = values(trace(wind, view.SIGNALS["wind_x"][0]), "x")
    # the frozen gust is convected at 10 m/s: it peaks at the hull 20 + 60/10 s after t = 0, plus
    # the time it takes to catch up with the hull's own downwind displacement
    k = int(np.argmax(ux))
    assert t[k] == pytest.approx(26.0 + (x[k] - x[0]) / 10.0, abs=0.15)
    # pitch and alpha start at the engine's trim angle
    pitch = chart(at, "dyn_pitch")
    th = values(trace(pitch, view.SIGNALS["theta"][0]), "y")
    assert th[0] == pytest.approx(row["alpha_eq_deg"], abs=1e-3)
    # tether profile figure: the two snapshots, from the winch to the confluence point
    teth = chart(at, "dyn_tether")
    names = [tr["name"] for tr in teth["data"]]
    assert names[0] == "tether, t = 0.0 s" and "tether, t = 150.0 s" in names
    tx = values(teth["data"][0], "x")
    assert tx[0] == 0.0 and tx[-1] == pytest.approx(x[0], abs=1e-6)
    # tensions: winch tension = engine's at t = 0
    ten = chart(at, "dyn_tension")
    tw = values(trace(ten, view.SIGNALS["tension_winch"][0]), "y")
    assert tw[0] == pytest.approx(row["tension_winch_N"], rel=1e-3)
    # settling metrics after the gust
    settling = _df(at, "Settling 5 % [s]")
    xc = settling[settling["Signal"] == view.SIGNALS["x_C"][0]].iloc[0]
    assert 0 < float(xc["Settling 5 % [s]"]) < 130
    assert {"dyn_snapshot", "dyn_hull"} <= {getattr(c, "key", None) for c in at.get("plotly_chart")}
    assert any(
        m.label == "Peak blow-by x_C [m]" and float(m.value) == pytest.approx(x.max(), abs=0.05)
        for m in metrics(at)
    )


def test_turbulence_statistics_table(dyn):
    _set(dyn, "dyn_scenario", "turbulence")
    dyn.run()
    _set(dyn, "dyn_duration", 80.0)
    _set(dyn, "dyn_int", "light")
    at = _run(dyn)
    stats = _df(at, "RMS fluctuation")
    assert list(stats.columns) == [
        "Signal",
        "Unit",
        "Mean",
        "RMS fluctuation",
        "Peak excursion",
        "Min",
        "Max",
    ]
    w = stats[stats["Signal"] == view.SIGNALS["wind_x"][0]].iloc[0]
    assert float(w["Mean"]) == pytest.approx(10.0, abs=1.0)
    rms, peak = float(w["RMS fluctuation"]), float(w["Peak excursion"])
    assert 0.1 < rms < 1.5  # light: sigma_u ~ 0.78 m/s over a short record
    assert peak >= rms
    assert any("RMS fluctuation" in c.value and "t ≥ 20 s" in c.value for c in at.caption)
    # light: W20 = 15 kt -> sigma_w = 0.77 m/s; at ~300 m sigma_u ~ sigma_w, L_u ~ 305 m
    cap = next(c.value for c in at.caption if c.value.startswith("Turbulence model"))
    lw = re.search(r"L_w = (\d+)", cap)
    assert "σ_w = 0.77 m/s" in cap and lw and 250 <= int(lw.group(1)) <= 310  # L_w = h here
    assert "MIL-HDBK-1797" in cap and "IEC 61400-1" in cap and "height levels" in cap


def test_saved_case_is_simulated(dyn):
    req = Requirement()
    cfg = Configuration(hull=HullSpec(volume=150.0, fineness_ratio=3.5))
    state.save_case("small", req, cfg, dyn.session_state)  # into the workspace, as the app does
    dyn.run()
    _set(dyn, "dyn_source", "Case: small")
    _set(dyn, "dyn_duration", 30.0)
    at = _run(dyn)
    row = next(r for r in design(req, cfg).performance.rows() if r["wind_speed_m_s"] == 10.0)
    x = values(trace(chart(at, "dyn_position"), "blow-by x_C [m]"), "y")
    assert x[0] == pytest.approx(row["blow_by_m"], abs=0.01)


def test_bad_input_names_field_value_and_range(dyn):
    _set(dyn, "dyn_speed", 45.0)
    at = _run(dyn)
    msg = " ".join(messages(at, "error"))  # plain text (Markdown escapes removed)
    assert "Mean wind at the aerostat = 45 m/s" in msg and "[0, 30] m/s" in msg
    assert len(at.get("plotly_chart")) == 0


def test_a_decimal_comma_is_a_decimal_point_never_ten_times(dyn):
    _set(dyn, "dyn_speed", "4,5")  # 45 m/s would be refused (valid range [0, 30])
    _set(dyn, "dyn_scenario", "steady")
    _set(dyn, "dyn_duration", "2,5e1")
    at = _run(dyn)
    assert not messages(at, "error")
    run_key = at.session_state["dyn_request"]
    assert isinstance(run_key, view.DynamicsKey)  # the typed request, no JSON on the way
    assert (run_key.request.speed, run_key.request.duration) == (4.5, 25.0)
    _set(at, "dyn_speed", "4.5,0")
    at = _run(at)
    assert any("Mean wind at the aerostat" in m and "ambiguous" in m for m in messages(at, "error"))


def test_reversed_wind_runs_on_and_flags_stall(dyn):
    """A -15 m/s gust at 5 m/s reverses the relative wind on the hull: the aerodynamics cover
    +-180 deg, so the run continues (it used to stop) and the limits say the fins stall."""
    _set(dyn, "dyn_speed", 5.0)
    _set(dyn, "dyn_gu", -15.0)
    _set(dyn, "dyn_gl", 20.0)
    _set(dyn, "dyn_duration", 60.0)
    at = _run(dyn)
    assert not any("relative wind reversed" in e.value for e in at.error)
    assert any(s.value.startswith("Finished: 60 s simulated") for s in at.success)
    warn = " ".join(w.value for w in at.warning)
    assert "Limits exceeded" in warn and "beyond stall" in warn
    lim = _df(at, "Limit value")
    stall = lim[lim["Limit"].str.contains("stall")].iloc[0]
    assert stall["Exceeded"] == "yes"
    assert float(stall["Worst in the run"]) > float(stall["Limit value"])
    pitch = chart(at, "dyn_pitch")
    assert "fin stall" in pitch["layout"]["title"]["text"]


def test_second_click_return_and_second_session_replay_from_the_store(dyn):
    """Issue 9 regression: the same case run again (second click, after leaving the page, and
    from a second session) is served from the store with no CacheReplayClosureError."""
    _set(dyn, "dyn_duration", 20.0)
    at = _run(dyn)
    first = chart(at, "dyn_position")
    done = next(s.value for s in at.success if s.value.startswith("Finished"))
    at = _run(at)  # second click
    assert not at.exception and any(s.value.startswith("Finished: 20 s") for s in at.success)
    at.switch_page("pages/1_Design.py")
    at.run()
    at.switch_page(DYN_PAGE)
    at.run()
    assert not at.exception
    at = _run(at)
    assert values(trace(chart(at, "dyn_position"), "blow-by x_C [m]"), "y") == pytest.approx(
        values(trace(first, "blow-by x_C [m]"), "y")
    )
    other = AppTest.from_file(str(APP_PATH), default_timeout=180)  # a second session
    other.run()
    other.switch_page(DYN_PAGE)
    other.run()
    _set(other, "dyn_duration", 20.0)
    other = _run(other)
    assert not other.exception
    # the very same stored result (its wall time included), not a new run
    assert [s.value for s in other.success if s.value.startswith("Finished")] == [done]
    assert not any("CacheReplay" in str(e.value) for e in other.exception)


def test_thesis_comparison_is_computed_live(dyn):
    dyn.button(key="dyn_thesis_run").click()
    dyn.run()
    assert not dyn.exception, [e.value for e in dyn.exception]
    shown = _df(dyn, "Claim holds")  # the static table, as text
    table = pd.DataFrame(view.thesis_comparison(1)["rows"])  # the numbers behind it (cached)
    assert set(shown["Scenario"]) == set(table["scenario"]) == {"varying", "gust", "turbulence"}
    assert [float(v) for v in shown["Thesis"]] == [40.0, 3.0, 40.0, 3.0, 1.2, 0.2, 3.5]
    assert list(shown["Ours (peak)"]) == [f"{v:.2f}" for v in table["ours"]]
    assert list(shown["Within ×1.5"]) == ["yes" if m else "no" for m in table["match"]]
    assert (table["ours"] > 0).all()
    ratio = table["ours"] / table["thesis"]
    assert ratio.to_numpy() == pytest.approx(table["ratio"].to_numpy())
    assert ((ratio.between(1 / 1.5, 1.5)) == table["match"]).all()
    # every miss is explained on the page
    if not table["match"].all():
        assert any("Not matched within ×1.5" in i.value and "Why:" in i.value for i in dyn.info)
    keys = {getattr(c, "key", None) for c in dyn.get("plotly_chart")}
    assert {"dyn_thesis_varying", "dyn_thesis_gust", "dyn_thesis_turbulence"} <= keys


def test_modes_table(dyn):
    _set(dyn, "dyn_modes", True)
    _set(dyn, "dyn_duration", 20.0)
    at = _run(dyn)
    modes = _df(at, "Period [s]")
    surge = modes[modes["Mode"] == "surge"].iloc[0]
    assert 10.0 < float(surge["Period [s]"]) < 80.0 and float(surge["Damping ratio [-]"]) > 0


def test_csv_of_the_time_histories():
    form = {
        "dyn_source": view.THESIS,
        "dyn_scenario": "steady",
        "dyn_speed": "8",
        "dyn_duration": "12",
        "dyn_exp": 1 / 7,
        "dyn_z0": "0,03",
        "dyn_body": "hull",
        "dyn_nseg": "10",
        "dyn_zeta": 1.0,
        "dyn_wall": "60",
        "dyn_unsteady": True,
        "dyn_profile": "uniform",
    }
    out = view.run(view.build_run(form, None, {}))
    assert out["csv_name"] == "aerostat_dynamics_steady.csv"
    meta = [ln for ln in out["csv"].splitlines() if ln.startswith("# ")]
    assert "# scenario = steady" in meta and "# speed = 8.0" in meta
    assert "# segments = 10" in meta and any(m.startswith("# status = ") for m in meta)
    lines = [ln for ln in out["csv"].splitlines() if not ln.startswith("#")]
    header = lines[0].split(",")
    assert header[:3] == ["t_s", "x_C_m", "z_C_m"] and "theta_deg" in header
    assert "tension_winch_N" in header and "wind_x_m_s" in header
    assert len(lines) == 1 + 121
    row = dict(zip(header, map(float, lines[-1].split(","))))
    assert row["t_s"] == pytest.approx(12.0)
    assert row["wind_x_m_s"] == pytest.approx(8.0)
    assert math.isfinite(row["theta_deg"])


def test_the_form_shows_every_field_of_the_request_from_the_registry():
    """Every field of the typed request (and of each scenario's part) has a box, and each box's
    label, unit and help are the registry's (nothing typed in the page)."""
    import dataclasses

    from aerostat_core.base.fields import specs
    from aerostat_core.dynamics.request import DynamicsRequest

    shown = {b.path for b in view.BOXES.values()}
    want = set()
    for name, spec in specs(DynamicsRequest).items():
        if spec.kind != "part":
            want.add(name)
            continue
        part = DynamicsRequest.PARTS[name]
        prefix = f"{name}.0" if name == "changes" else name
        want |= {f"{prefix}.{f.name}" for f in dataclasses.fields(part)}
    assert want <= shown, sorted(want - shown)
    for box in view.BOXES.values():
        s = DynamicsRequest.spec_at(box.path)
        assert box.label.startswith(s.label) and box.help == (s.help or None)
        if s.kind in ("number", "integer"):
            assert box.label.endswith(f"[{s.shown_unit}]")


def test_the_page_draws_the_registry_labels(dyn):
    from aerostat_core.base.fields import field_spec
    from aerostat_core.dynamics.request import DynamicsRequest, GustSettings, TurbulenceSettings

    def label(kind, key):
        return next(el.label for el in getattr(dyn, kind) if el.key == key)

    s = field_spec(DynamicsRequest, "speed")
    assert label("text_input", "dyn_speed") == f"{s.label} [m/s]"
    assert label("text_input", "dyn_gu") == f"{field_spec(GustSettings, 'amplitude_u').label} [m/s]"
    assert label("checkbox", "dyn_gconv") == field_spec(GustSettings, "convected").label
    assert label("radio", "dyn_scenario") == field_spec(DynamicsRequest, "scenario").label
    _set(dyn, "dyn_scenario", "turbulence")
    dyn.run()
    assert label("selectbox", "dyn_int") == field_spec(TurbulenceSettings, "intensity").label
    assert label("text_input", "dyn_seed") == "Random seed [-]"


def test_a_second_ramp_before_the_first_ends_is_refused_by_the_request(dyn):
    _set(dyn, "dyn_scenario", "varying")
    dyn.run()
    _set(dyn, "dyn_second", True)
    _set(dyn, "dyn_tc2", 22.0)  # the first ramp runs 20-25 s
    at = _run(dyn)
    msg = " ".join(messages(at, "error"))
    assert "Change starts at (change 2) = 22 s" in msg and "[25, 3600] s" in msg
    assert "dyn_request" not in at.session_state and len(at.get("plotly_chart")) == 0


def test_a_gust_without_amplitude_is_refused_by_the_request(dyn):
    _set(dyn, "dyn_gu", 0.0)
    at = _run(dyn)
    msg = " ".join(messages(at, "error"))
    assert "Gust amplitude, horizontal = 0 m/s" in msg and "both 0 m/s" in msg
