"""``simulate --dof 6`` (issue 25 item 6): the JSON keys, reel and break figures, bad input."""

import json

from aerostat_core.cli.entry import main

KEYS_3DOF = {"status", "ok", "window_start_s", "window_end_s", "settling_time_s",
             "pitch_range_deg", "pitch_peak_deg", "u_peak_mps", "w_peak_mps", "pitch_rms_deg",
             "u_rms_mps", "w_rms_mps", "tension_range_N", "settings", "scenario", "wall_time_s"}
KEYS_6DOF = {"roll_peak_deg", "yaw_peak_deg", "lateral_peak_m", "lateral_unstable_above_m_s",
             "lateral_modes", "static_derivatives"}


def test_reel_in_json_has_the_3dof_and_lateral_keys(tmp_path, capsys):
    csv = tmp_path / "reel.csv"
    assert main(["simulate", "--dof", "6", "--scenario", "reel-in", "--duration", "60",
                 "--json", "--csv", str(csv)]) == 0
    m = json.loads(capsys.readouterr().out)
    assert KEYS_3DOF | KEYS_6DOF <= set(m)
    assert m["lateral_unstable_above_m_s"] is None  # the thesis design is stable to 15 m/s
    lo, hi = m["tether_length_range_m"]
    assert hi == 300.0 and abs(lo - (300.0 - 0.3048 * 32.0)) < 0.05  # 30 s + the two ramps
    assert {"C_Y_beta_per_rad", "C_n_beta_per_rad", "C_l_beta_per_rad",
            "C_m_alpha_cv_per_rad"} <= set(m["static_derivatives"])
    text = csv.read_text()
    assert "# Winch reel speed [m/s] = 0.3048" in text and "tether_length_m" in text


def test_tether_break_reports_the_free_ascent(capsys):
    assert main(["simulate", "--dof", "6", "--scenario", "tether-break", "--duration", "40",
                 "--json"]) == 0
    m = json.loads(capsys.readouterr().out)
    assert m["ascent_m"] > 50.0 and m["drift_m"] > 50.0


def test_bad_combinations_and_values_exit_2(capsys):
    assert main(["simulate", "--dof", "6", "--scenario", "gust"]) == 2
    assert "--dof 3" in capsys.readouterr().err
    assert main(["simulate", "--scenario", "veer"]) == 2
    assert "--dof 6" in capsys.readouterr().err
    assert main(["simulate", "--dof", "6", "--scenario", "veer", "--duration", "0.5"]) == 2
    assert "--duration" in capsys.readouterr().err
