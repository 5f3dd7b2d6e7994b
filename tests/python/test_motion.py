"""pound.motion gives the numbers of `pound motion spectrum|target|generate` (issue 25)."""

import h5py
import numpy as np
import pytest

import pound
from conftest import ELCENTRO, cli_json

G = 9.80665  # m/s2 (core/constants.hpp)


def test_read_record_reads_the_file_in_m_per_s2():
    rec = pound.motion.read_record(ELCENTRO)
    dt, accel = rec  # a pair, as pound.simulate takes it
    assert dt == 0.02 and accel.shape == (1559,)
    # El Centro 1940 NS: PGA 0.3188 g (pound simulate's line), in m/s2.
    assert np.max(np.abs(accel)) / G == pytest.approx(0.3188, abs=5e-5)
    short = pound.motion.read_record(ELCENTRO, truncate=8, scale=2)
    assert np.array_equal(short.accel, 2 * accel[:401])


def test_read_record_reads_at2_and_column_files(tmp_path):
    at2 = tmp_path / "rec.AT2"
    at2.write_text("PEER NGA STRONG MOTION DATABASE RECORD\nTEST 1999, STATION, 090\n"
                   "ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    5, DT=   .0100 SEC\n"
                   "  .0010000  -.0020000   .0030000\n  .1000000  -.0500000\n")
    rec = pound.motion.read_record(at2)
    assert rec.dt == 0.01
    assert list(rec.accel) == [x * G for x in (0.001, -0.002, 0.003, 0.1, -0.05)]
    cols = tmp_path / "rec.txt"
    cols.write_text("# time [s], acceleration [cm/s2]\n0 1\n0.005 -20\n0.010 30\n")
    rec = pound.motion.read_record(cols, units="cm/s2")
    assert rec.dt == pytest.approx(0.005, rel=1e-12)
    assert list(rec.accel) == [0.01, -0.2, 0.3]
    # The same file through the command: its spectrum equals the module's of the array.
    cli = cli_json(["motion", "spectrum", "--input", at2, "--periods=0.1, 0.2"])
    r = pound.motion.response_spectrum(pound.motion.read_record(at2), periods=[0.1, 0.2])
    assert list(r["psa_mps2"] / G) == cli["psa_g"]


def test_response_spectrum_equals_the_command():
    cli = cli_json(["motion", "spectrum", "--input", ELCENTRO])
    r = pound.motion.response_spectrum(pound.motion.read_record(ELCENTRO))
    assert list(r["period_s"]) == cli["period_s"]
    assert list(r["sd_m"]) == cli["sd_m"]
    assert list(r["psv_mps"]) == cli["psv_mps"]
    assert list(r["psa_mps2"] / G) == cli["psa_g"]
    assert list(r["sa_abs_mps2"] / G) == cli["sa_abs_g"]
    # The published El Centro values (README, "Validation"): PSA 0.916 g at 0.5 s, 5 %.
    at = pound.motion.response_spectrum(pound.motion.read_record(ELCENTRO), periods=[0.5, 1, 2])
    assert at["psa_mps2"] / G == pytest.approx([0.916, 0.454, 0.137], abs=6e-4)


def test_response_spectrum_options_equal_the_command():
    cli = cli_json(["motion", "spectrum", "--input", ELCENTRO, "--damping=0.02", "--substep=0",
                    "--periods=0, 0.3, 1.5"])
    r = pound.motion.response_spectrum(pound.motion.read_record(ELCENTRO), damping=0.02,
                                       substep=0, periods=np.array([0, 0.3, 1.5]))
    assert list(r["psa_mps2"] / G) == cli["psa_g"] and r["damping"] == 0.02
    assert r["psa_mps2"][0] == np.max(np.abs(pound.motion.read_record(ELCENTRO).accel))


def test_design_spectrum_equals_the_command():
    keys = ["--spectrum=ec8", "--ec8-type=1", "--ground-type=C", "--ag=0.3"]
    cli = cli_json(["motion", "target"] + keys)
    r = pound.motion.design_spectrum(spectrum="ec8", ec8_type=1, ground_type="C", ag=0.3)
    assert r["spectrum"] == cli["spectrum"]
    assert list(r["period_s"]) == cli["period_s"] and list(r["sd_m"]) == cli["sd_m"]
    assert list(r["psa_mps2"] / G) == cli["psa_g"]
    # EC8 type 1, ground C: plateau 2.5 S ag with S = 1.15 between TB = 0.2 and TC = 0.6 s.
    plateau = pound.motion.design_spectrum(spectrum="ec8", ec8_type=1, ground_type="C", ag=0.3,
                                           periods=[0.3, 0.5])
    assert plateau["psa_mps2"] == pytest.approx([2.5 * 1.15 * 0.3 * G] * 2, rel=1e-12)


def test_generate_equals_the_commands_files(tmp_path):
    keys = {"spectrum": "ec8", "ec8_type": 1, "ground_type": "C", "ag": 0.3, "count": 3,
            "duration": 8, "seed": 5, "variability": "spectral"}
    argv = ["--spectrum=ec8", "--ec8-type=1", "--ground-type=C", "--ag=0.3", "--count=3",
            "--duration=8", "--seed=5", "--variability=spectral", f"--out={tmp_path / 'm'}"]
    cli = cli_json(["motion", "generate"] + argv)
    g = pound.motion.generate(**keys)
    with h5py.File(tmp_path / "m" / "motions.h5", "r") as f:
        same = {"accel_mps2": "motions/acceleration", "psa_mps2": "motions/psa",
                "target_psa_mps2": "motions/target_psa", "epsilon": "motions/epsilon",
                "pga_mps2": "motions/pga", "final_velocity_mps": "motions/final_velocity",
                "final_displacement_m": "motions/final_displacement", "time_s": "motions/time",
                "period_s": "target/period", "design_psa_mps2": "target/psa",
                "mean_psa_mps2": "target/mean_psa", "geomean_psa_mps2": "target/geomean_psa",
                "sigma_lnsa": "target/sigma_lnsa", "iterations": "motions/iterations"}
        for key, dataset in same.items():
            assert np.array_equal(g[key], f[dataset][()]), key
    assert g["accel_mps2"].shape == (3, 801)
    for i, m in enumerate(cli["motions"]):
        assert (g["min_ratio"][i], g["max_ratio"][i], g["mean_ratio"][i]) == (
            m["min_ratio"], m["max_ratio"], m["mean_ratio"])
    assert g["variability"] == cli["variability"] and g["spectrum"] == cli["target"]
    # Each motion matches its own random target: mean ratio within 10 % (docs/motions.md).
    assert np.all(np.abs(g["mean_ratio"] - 1) < 0.1)


def test_a_generated_motion_drives_a_simulation():
    g = pound.motion.generate(spectrum="ec8", ec8_type=1, ground_type="C", ag=0.3, duration=8)
    r = pound.simulate(str(ELCENTRO.parent.parent / "studies" / "ch6-sdof-pair.ini"),
                       motion=(g["dt_s"], g["accel_mps2"][0]))
    assert r["buildings"][0]["floors"][0]["peak_disp_free_m"] > 0


def test_log_spaced_periods():
    p = pound.motion.log_spaced_periods(0.1, 10, 3)
    assert p[0] == 0.1 and p[2] == 10 and p[1] == pytest.approx(1.0, rel=1e-15)


def test_response_spectrum_refuses_the_keys_that_process_a_record_file():
    # They act on reading a file; the array is already read: silently dropped, scale=2 gave the
    # unscaled spectrum. read_record(path, scale=2) scales, and its spectrum doubles.
    rec = pound.motion.read_record(ELCENTRO)
    for key, value in (("scale", 2), ("truncate", 8), ("baseline", True), ("dt", 0.01),
                       ("units", "g"), ("accept_any_pga", True)):
        with pytest.raises(pound.Error, match=key.replace("_", "-") if key == "accept_any_pga"
                           else key):
            pound.motion.response_spectrum(rec, periods=[0.5], **{key: value})
    one = pound.motion.response_spectrum(rec, periods=[0.5])["psa_mps2"][0]
    two = pound.motion.response_spectrum(pound.motion.read_record(ELCENTRO, scale=2),
                                         periods=[0.5])["psa_mps2"][0]
    assert two == pytest.approx(2 * one, rel=1e-12)
