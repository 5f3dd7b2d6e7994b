"""Bad input raises pound.Error with the line the command prints after 'pound COMMAND: error: ',
a numerical failure pound.NumericalError with the text after 'numerical failure: '; nothing is
written (issue 25)."""

import os

import numpy as np
import pytest

import pound
from conftest import ELCENTRO, cli_error, study

CH6 = study("ch6-sdof-pair")


def simulate_error(*args, **kwargs):
    with pytest.raises(pound.Error) as e:
        pound.simulate(*args, **kwargs)
    return str(e.value)


@pytest.mark.parametrize("overrides,argv", [
    ({"bogus": 1}, ["--bogus=1"]),
    ({"building1__masses": -5}, ["--building1.masses=-5"]),
    ({"building1__masses": [100, float("nan")]}, ["--building1.masses=100, nan"]),
    ({"pair1__gap": "abc"}, ["--pair1.gap=abc"]),
    ({"contact__e": 2}, ["--contact.e=2"]),
    ({"building2__hysteresis": "plastic"}, ["--building2.hysteresis=plastic"]),
    ({"motion__file": "no-such-record.dat"}, ["--motion.file=no-such-record.dat"]),
    ({"building1__mass": 100}, ["--building1.mass=100"]),
])
def test_bad_overrides_give_the_commands_message(overrides, argv):
    expected = cli_error("simulate", ["--config", CH6] + argv)
    assert simulate_error(CH6, **overrides) == expected


def test_the_message_names_what_is_wrong():
    # Equal to the command, and saying what a user needs (key, value, what is valid).
    message = simulate_error(CH6, pair1__gap="abc")
    assert message.startswith("command line: --pair1.gap: 'abc' is not a finite number")
    assert "[m]" in message
    assert isinstance(pound.Error("x"), ValueError)


def test_a_bad_study_file_names_its_line(tmp_path):
    path = tmp_path / "bad.ini"
    path.write_text(open(CH6).read().replace("masses = 100             # kg\n"
                                             "stiffnesses = 15791.37",
                                             "masses = -100\nstiffnesses = 15791.37", 1)
                    .replace("../motions/", str(ELCENTRO.parent) + "/"))
    expected = cli_error("simulate", ["--config", path])
    assert expected.startswith(f"{path}:10: key 'building1.masses'")
    assert simulate_error(path) == expected
    assert simulate_error(tmp_path / "missing.ini") == cli_error(
        "simulate", ["--config", tmp_path / "missing.ini"])


def test_a_record_with_nan_is_refused_in_a_file_and_in_an_array(tmp_path):
    bad = tmp_path / "nan.dat"
    bad.write_text("# units: g\n# dt: 0.02\n0.01\n0.02\nnan\n0.01\n")
    expected = cli_error("simulate", ["--config", CH6, f"--motion.file={bad}"])
    assert expected == f"{bad}:5: 'nan' is not finite; valid: an acceleration value"
    assert simulate_error(CH6, motion__file=bad) == expected
    rec = pound.motion.read_record(ELCENTRO)
    accel = rec.accel.copy()
    accel[12] = np.nan
    assert simulate_error(CH6, motion=(rec.dt, accel)) == (
        "motion: value 12 (t = 0.24 s) is nan; valid: finite accelerations in m/s2")
    with pytest.raises(pound.Error) as e:
        pound.motion.read_record(bad)
    assert str(e.value) == expected


def test_an_implausible_array_says_how_to_accept_it():
    message = simulate_error(CH6, motion=(0.01, np.zeros(100)))
    assert message.startswith("motion: peak ground acceleration 0 g (0 m/s2)")
    assert message.endswith("give motion__check_pga=False (or [motion] check_pga = false in the "
                            "study) to accept the record")
    assert simulate_error(CH6, motion=(0.0, [1.0, 2.0])) == (
        "motion: sample spacing dt = 0 s; valid: a finite dt > 0 s")
    assert simulate_error(CH6, motion=(0.01, [1.0])) == (
        "motion: the record holds 1 value; valid: at least 2 values")


def test_a_damped_sears_step_too_large():
    ch8 = study("ch8-five-three")
    assert simulate_error(ch8, sears__dt=1) == cli_error("simulate", ["--config", ch8,
                                                                      "--sears.dt=1"])


def test_a_numerical_failure_is_a_numerical_error():
    expected = cli_error("simulate", ["--config", CH6, "--contact.model=stereomechanical"],
                         kind="numerical failure")
    with pytest.raises(pound.NumericalError) as e:
        pound.simulate(CH6, contact__model="stereomechanical")
    assert str(e.value) == expected
    assert "chatter" in expected
    assert isinstance(e.value, RuntimeError) and not isinstance(e.value, pound.Error)


def test_keys_the_module_sets_itself_are_refused():
    with pytest.raises(pound.Error, match="^config: not a key here"):
        pound.simulate(CH6, config=CH6)
    with pytest.raises(pound.Error, match="^json: not a key here"):
        pound.simulate(CH6, json=True)
    with pytest.raises(TypeError, match="motion: give"):
        pound.simulate(CH6, motion=np.zeros(10))


@pytest.mark.parametrize("call,command,argv", [
    (lambda: pound.impact(model="lve", e=0.6), "impact", ["--model=lve", "--e=0.6"]),
    (lambda: pound.impact(model="bogus"), "impact", ["--model=bogus"]),
    (lambda: pound.impact(model="sears", m1=1), "impact", ["--model=sears", "--m1=1"]),
    (lambda: pound.impact(model="lve", k=1e6, v0_min=-1), "impact",
     ["--model=lve", "--k=1e6", "--v0-min=-1"]),
    (lambda: pound.hysteresis("imk", [0.01], k0=1), "hysteresis",
     ["--law=imk", "--k0=1", "--drifts=d.txt"]),
    (lambda: pound.hysteresis("bogus", [0.01], k0=1), "hysteresis",
     ["--law=bogus", "--k0=1", "--drifts=d.txt"]),
    (lambda: pound.hysteresis("bilinear", [0.01], k0=1e6, fy=1e3, hardening=1.5), "hysteresis",
     ["--law=bilinear", "--k0=1e6", "--fy=1e3", "--hardening=1.5", "--drifts=d.txt"]),
    (lambda: pound.motion.design_spectrum(spectrum="ec8", ag=-1), "motion",
     ["target", "--spectrum=ec8", "--ag=-1"]),
    (lambda: pound.motion.design_spectrum(spectrum="bogus"), "motion",
     ["target", "--spectrum=bogus"]),
    (lambda: pound.motion.generate(spectrum="ec8", ag=0.3, ground_type="C", count=0), "motion",
     ["generate", "--spectrum=ec8", "--ag=0.3", "--ground-type=C", "--count=0", "--out=x"]),
    (lambda: pound.motion.generate(spectrum="ec8", ag=0.3, ground_type="C",
                                   variability="spectral", sigma_lnsa=-1), "motion",
     ["generate", "--spectrum=ec8", "--ag=0.3", "--ground-type=C", "--variability=spectral",
      "--sigma-lnsa=-1", "--out=x"]),
    (lambda: pound.motion.read_record("no-such-file.AT2"), "motion",
     ["spectrum", "--input=no-such-file.AT2"]),
    (lambda: pound.motion.read_record(ELCENTRO, units="furlongs"), "motion",
     ["spectrum", f"--input={ELCENTRO}", "--units=furlongs"]),
    (lambda: pound.motion.response_spectrum(pound.motion.read_record(ELCENTRO), damping=1),
     "motion", ["spectrum", f"--input={ELCENTRO}", "--damping=1"]),
])
def test_the_other_calls_give_their_commands_messages(tmp_path, call, command, argv):
    (tmp_path / "d.txt").write_text("0.01\n")
    expected = cli_error(command, argv)
    os.remove(tmp_path / "d.txt")
    with pytest.raises(pound.Error) as e:
        call()
    assert str(e.value) == expected


def test_nothing_is_written(in_empty_folder):
    for call in (lambda: pound.simulate(CH6, pair1__gap="abc"),
                 lambda: pound.simulate(CH6, contact__model="stereomechanical"),
                 lambda: pound.motion.generate(spectrum="ec8", ag=0.3, ground_type="C", count=0)):
        with pytest.raises((pound.Error, pound.NumericalError)):
            call()
    pound.simulate(CH6, histories=True)
    pound.motion.generate(spectrum="ec8", ag=0.3, ground_type="C", duration=2)
    assert os.listdir(in_empty_folder) == []
