"""histories=True gives the arrays `pound simulate --histories FILE.h5` writes (issue 25)."""

import h5py
import numpy as np
import pytest

import pound
from conftest import run, study

DATASETS = ["time", "displacement", "abs_acceleration", "contact_force", "storey_shear",
            "storey_drift", "foundation_sway", "foundation_rotation"]
SPRINGS = ["--building1.foundation=springs", "--building1.sway_stiffness=9.56e8",
           "--building1.rocking_stiffness=1.02e11", "--building1.sway_damping=7.2e7",
           "--building1.rocking_damping=4.49e9", "--building1.foundation_mass=2.4e5"]


@pytest.mark.parametrize("name,overrides", [
    ("ch6-sdof-pair", []),                  # lumped, two SDOF
    ("ch8-yielding", []),                   # damped Sears, yielding storeys
    ("ch3-steel-frames", ["--contact.model=hc-hertz"]),
    ("ch8-five-three", SPRINGS + ["--ground.apparent_velocity=400"]),  # SSI, wave passage
])
def test_histories_equal_the_file(tmp_path, name, overrides):
    path = tmp_path / "h.h5"
    code, _, err = run(["simulate", "--config", study(name), "--histories", path] + overrides)
    assert code == 0, err
    kwargs = {o[2:].split("=")[0].replace(".", "__"): o.split("=")[1] for o in overrides}
    h = pound.simulate(study(name), histories=True, **kwargs)["histories"]
    with h5py.File(path, "r") as f:
        for run_name in ("pounding", "free"):
            for d in DATASETS:
                expected = f[f"{run_name}/{d}"][()]
                got = h[run_name][d]
                assert got.shape == expected.shape, (run_name, d)
                assert got.tobytes() == expected.tobytes(), (run_name, d)
        for d in ("dof_building", "dof_floor", "site_pair", "site_floor"):
            assert list(h[d]) == list(f[f"row/{d}"][()]), d
        for d in ("time", "acceleration"):
            assert h["motion"][d].tobytes() == f[f"motion/{d}"][()].tobytes(), d
        for d in ("time", "acceleration", "displacement"):
            assert h["ground"][d].tobytes() == f[f"ground/{d}"][()].tobytes(), d
    # Many steps, not an empty table.
    assert h["pounding"]["time"].size > 1000


def test_storey_drifts_are_the_differences_of_floor_displacements():
    h = pound.simulate(study("ch8-yielding"), histories=True)["histories"]
    u, drift = h["free"]["displacement"], h["free"]["storey_drift"]
    floors = h["dof_floor"]
    assert list(floors) == [1, 2, 3, 4, 5, 1, 2, 3]
    for i, floor in enumerate(floors):
        expected = u[:, i] if floor == 1 else u[:, i] - u[:, i - 1]
        assert np.array_equal(drift[:, i], expected)
    # The peak of the drift ratio is the JSON's (3 m storeys; up to the instants recorded).
    peak = np.max(np.abs(drift[:, 1])) / 3.0
    reported = pound.simulate(study("ch8-yielding"))["buildings"][0]["floors"][1]
    assert peak == pytest.approx(reported["peak_drift_ratio_free"], rel=1e-3)


def test_wave_passage_delays_the_second_buildings_ground():
    # Chapter 8's pair side by side (slab lengths 2 x 7.5 m / 2 + gap): building 2's ground is
    # building 1's, later by its distance over the apparent velocity, and the first building
    # stands on the study's record.
    v = 150.0
    d = pound.simulate(study("ch8-five-three"), histories=True, ground__apparent_velocity=v)
    h = d["histories"]
    g, t = h["ground"]["acceleration"], h["ground"]["time"]
    assert g.shape == (t.size, 2)
    m = h["motion"]["acceleration"]
    assert np.array_equal(g[: m.size, 0], m)
    dt = t[1] - t[0]
    lag = np.argmax(np.correlate(g[:, 1], g[:, 0], "full")) - (t.size - 1)
    distance = d["buildings"][1]["position_m"] - d["buildings"][0]["position_m"]
    assert distance > 7.0
    assert abs(lag * dt - distance / v) <= dt


def test_a_fixed_base_has_no_sway():
    h = pound.simulate(study("ch8-yielding"), histories=True)["histories"]
    for run_name in ("pounding", "free"):
        assert h[run_name]["foundation_sway"].shape == (h[run_name]["time"].size, 2)
        assert not np.any(h[run_name]["foundation_sway"])
        assert not np.any(h[run_name]["foundation_rotation"])
