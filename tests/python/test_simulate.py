"""pound.simulate returns what `pound simulate --json` prints, number for number (issue 25)."""

import warnings

import numpy as np
import pytest

import pound
from conftest import ELCENTRO, SIMULATE_STUDIES, cli_json, run, study

# Overrides of the command line's keys: (study, overrides as keyword arguments).
VARIANTS = [
    ("ch6-sdof-pair", {"contact__model": "lve"}),
    ("ch6-sdof-pair", {"contact__model": "hertzdamp", "contact__e": 0.6}),
    ("ch6-sdof-pair", {"contact__model": "hc-hertz", "contact__k": 3e7, "pair1__gap": 0.005}),
    ("ch6-sdof-pair", {"integrator": "fixed", "dt": 1e-4}),
    ("ch8-yielding", {"building1__hysteresis": "imk", "building2__hysteresis": "imk"}),
    ("ch8-yielding", {"contact__model": "hc-linear", "contact__k_factor": 30}),
    ("ch8-yielding", {"building1__hysteresis": "bouc-wen",
                      "simulation__collapse_drift_ratio": 0.01}),
    ("ch8-five-three", {"contact__model": "nlve", "contact__k_factor": 30}),
    ("ch3-steel-frames", {"motion__scale": 2.5, "simulation__extra_time": 2}),
]


def command_line(overrides):
    """The same overrides as the program's arguments."""
    args = []
    for name, value in overrides.items():
        args += [f"--{name.replace('__', '.')}={value}"]
    return args


@pytest.mark.parametrize("name", SIMULATE_STUDIES)
def test_every_study_equals_the_command(name):
    assert pound.simulate(study(name)) == cli_json(["simulate", "--config", study(name)])


@pytest.mark.parametrize("name,overrides", VARIANTS)
def test_overrides_equal_the_command_line(name, overrides):
    expected = cli_json(["simulate", "--config", study(name)] + command_line(overrides))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", pound.UnusedKeyWarning)
        assert pound.simulate(study(name), **overrides) == expected


def test_a_result_holds_the_documented_numbers():
    # Not only equal to the command: the chapter 6 pair pounds, both floors move, and the
    # energy balance closes (the checks would fail on an empty or garbled result).
    r = pound.simulate(study("ch6-sdof-pair"))
    assert [b["name"] for b in r["buildings"]] == ["T0.50", "T0.75"]
    floor = r["buildings"][0]["floors"][0]
    assert floor["peak_disp_pounding_m"] > 0.01
    assert floor["disp_amplification"] == floor["peak_disp_pounding_m"] / floor["peak_disp_free_m"]
    assert r["contacts"][0]["impacts"] > 0
    e = r["energy_pounding"]
    assert abs(e["residual_J"]) < 1e-6 * e["input_J"]


def test_dotted_keys_and_keyword_arguments_are_the_same_overrides():
    a = pound.simulate(study("ch6-sdof-pair"), contact__e=0.5, pair1__gap=0.002)
    b = pound.simulate(study("ch6-sdof-pair"), **{"contact.e": 0.5, "pair1.gap": 0.002})
    assert a == b
    assert a != pound.simulate(study("ch6-sdof-pair"))


def test_a_dict_study_equals_its_file(tmp_path):
    sections = {
        "building1": {"name": "T0.50", "masses": [100], "stiffnesses": 15791.37, "damping": 0.05},
        "building2": {"name": "T0.75", "masses": 100.0, "stiffnesses": [7018.39]},
        "pair1": {"gap": 0},
        "contact": {"model": "hc-linear", "e": 0.8, "k_factor": 50},
        "motion": {"file": str(ELCENTRO), "duration": 8},
    }
    assert pound.simulate(sections) == cli_json(["simulate", "--config", study("ch6-sdof-pair")])
    # Overrides win over the dict's keys, as the command line over a file.
    changed = pound.simulate(sections, contact__e=0.6)
    assert changed == cli_json(["simulate", "--config", study("ch6-sdof-pair"), "--contact.e=0.6"])


def test_a_relative_path_in_a_dict_study_is_taken_from_the_current_folder(tmp_path):
    (tmp_path / "record.dat").write_text(ELCENTRO.read_text())
    sections = {"building1": {"masses": 100, "stiffnesses": 15791.37},
                "building2": {"masses": 100, "stiffnesses": 7018.39},
                "contact": {"k_factor": 50}, "motion": {"file": "record.dat", "duration": 2}}
    r = pound.simulate(sections)
    assert r == cli_json(["simulate", "--building1.masses=100", "--building1.stiffnesses=15791.37",
                          "--building2.masses=100", "--building2.stiffnesses=7018.39",
                          "--contact.k_factor=50", "--motion.file=record.dat",
                          "--motion.duration=2"])
    assert r["contacts"][0]["impacts"] > 0


def test_a_motion_array_replaces_the_record():
    rec = pound.motion.read_record(ELCENTRO)
    assert (rec.dt, len(rec.accel)) == (0.02, 1559)
    expected = cli_json(["simulate", "--config", study("ch6-sdof-pair")])
    assert pound.simulate(study("ch6-sdof-pair"), motion=rec) == expected
    assert pound.simulate(study("ch6-sdof-pair"), motion=(rec.dt, list(rec.accel))) == expected
    # The study's processing keys act on the array: twice the record at scale 0.5 is the record.
    twice = pound.simulate(study("ch6-sdof-pair"), motion=(rec.dt, 2 * rec.accel),
                           motion__scale=0.5)
    assert twice == expected
    halved = pound.simulate(study("ch6-sdof-pair"), motion=(rec.dt, 0.5 * rec.accel))
    assert halved != expected
    # A study without a record: the first 8 s of the record, read and cut by the module.
    sections = {"building1": {"name": "T0.50", "masses": 100, "stiffnesses": 15791.37},
                "building2": {"name": "T0.75", "masses": 100, "stiffnesses": 7018.39},
                "contact": {"model": "hc-linear", "e": 0.8, "k_factor": 50}}
    first8 = pound.motion.read_record(ELCENTRO, truncate=8)
    assert pound.simulate(sections, motion=first8) == expected


def test_the_note_on_unused_keys_is_a_warning_with_the_commands_text():
    args = ["simulate", "--config", study("ch8-five-three"), "--contact.k_factor=30"]
    code, out, err = run(args + ["--json"])
    notes = [line[len("pound simulate: note: "):] for line in err.splitlines()
             if line.startswith("pound simulate: note: ")]
    assert notes == ["command line: --contact.k_factor is not used by contact model sears"]
    with pytest.warns(pound.UnusedKeyWarning) as caught:
        pound.simulate(study("ch8-five-three"), contact__k_factor=30)
    assert [str(w.message) for w in caught] == notes


def test_histories_are_added_and_the_rest_unchanged():
    plain = pound.simulate(study("ch6-sdof-pair"))
    with_histories = pound.simulate(study("ch6-sdof-pair"), histories=True)
    h = with_histories.pop("histories")
    assert with_histories == plain
    assert isinstance(h["pounding"]["displacement"], np.ndarray)
