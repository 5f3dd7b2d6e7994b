"""pound.impact and pound.hysteresis give the numbers of `pound impact --json` and
`pound hysteresis --json` (issue 25)."""

import numpy as np
import pytest

import pound
from conftest import cli_json, study

DRIFTS = [0.001, 0.01, -0.02, 0.03, 0.0, -0.05, 0.08]


@pytest.mark.parametrize("keys", [
    {"model": "hc-hertz", "e": 0.6, "k": 3.21e9, "m1": 109, "m2": 108, "v0": 0.2},
    {"model": "lve", "e": 0.4, "k": 2e6, "m1": 1, "m2": 3, "v0": 0.5, "v0_min": 1e-6},
    {"model": "mlve", "e": 0.7, "k": 2e6, "dt": 1e-6},
])
def test_impact_equals_the_command(keys):
    argv = [f"--{k.replace('_', '-')}={v}" for k, v in keys.items()]
    assert pound.impact(**keys) == cli_json(["impact"] + argv)


def test_impact_of_an_options_file_equals_the_command():
    ch7 = study("ch7-pendulums")
    expected = cli_json(["impact", "--config", ch7])
    assert pound.impact(ch7) == expected
    assert pound.impact(ch7, v0=0.04) == cli_json(["impact", "--config", ch7, "--v0=0.04"])
    assert expected["internal_energy1_J"] > 0  # the damped Sears model's bars vibrate after


def test_elastic_hertz_impact_lasts_goldsmiths_time():
    # Elastic Hertz contact: duration = 2.9432 delta_max / v0 (Goldsmith 1960).
    r = pound.impact(model="hc-hertz", e=1, k=1e9, m1=10, m2=10, v0=0.3)
    assert r["contact_duration_s"] == pytest.approx(2.9432 * r["max_penetration_m"] / 0.3,
                                                    rel=1e-4)


@pytest.mark.parametrize("law,keys", [
    ("elastic", {"k0": 2e7}),
    ("bilinear", {"k0": 2e7, "fy": 2e5, "hardening": 0.05}),
    ("bouc-wen", {"k0": 2e7, "fy": 2e5, "bw_n": 3}),
    ("imk", {"k0": 2e7, "fy": 2e5, "height": 3, "energy_capacity": 60}),
])
def test_hysteresis_equals_the_command(tmp_path, law, keys):
    path = tmp_path / "drifts.txt"
    path.write_text("\n".join(repr(d) for d in DRIFTS) + "\n")
    argv = [f"--law={law}", f"--drifts={path}"] + [f"--{k}={v}" for k, v in keys.items()]
    expected = cli_json(["hysteresis"] + argv)
    shear = pound.hysteresis(law, np.array(DRIFTS), **keys)
    assert isinstance(shear, np.ndarray) and list(shear) == expected["shear_N"]


def test_hysteresis_laws_follow_their_rules():
    assert list(pound.hysteresis("elastic", DRIFTS, k0=2e7)) == [2e7 * d for d in DRIFTS]
    # Bilinear: yield at Fy = 2e5 N (uy = 0.01 m), then k0 b; unloading elastic.
    s = pound.hysteresis("bilinear", [0.005, 0.02, 0.015], k0=2e7, fy=2e5, hardening=0.05)
    assert s == pytest.approx([1e5, 2e5 + 0.05 * 2e7 * 0.01, 2e5 + 1e4 - 2e7 * 0.005], rel=1e-12)
