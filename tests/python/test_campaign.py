"""pound.read_campaign: a campaign file as a DataFrame whose columns are the file's datasets
(issue 25). The campaign is the smoke study with a 2-storey building beside the SDOF, run by
`pound campaign` on one rank (no mpirun: MPI's singleton start)."""

import shutil

import h5py
import numpy as np
import pytest

import pound
from conftest import small_campaign

SAMPLES = 16


@pytest.fixture(scope="module")
def campaign(tmp_path_factory):
    return small_campaign(tmp_path_factory.mktemp("campaign"), SAMPLES)


def test_one_row_per_sample_with_the_files_numbers(campaign):
    df = pound.read_campaign(campaign)
    with h5py.File(campaign, "r") as f:
        assert list(df.index) == list(f["samples/id"][()]) == list(range(SAMPLES))
        for name in ("status", "im", "scale", "e", "gap", "k_factor"):
            assert np.array_equal(df[name].to_numpy(), f[f"samples/{name}"][()]), name
        assert list(df["message"]) == [""] * SAMPLES
        levels = [float(x) for x in f.attrs["im_levels_mps2"].split(",")]
        r = {k: f[f"response/{k}"][()] for k in f["response"]}
    # Stripes: sample i at level i mod 4, its intensity the level's.
    assert list(df["stripe"]) == [i % 4 for i in range(SAMPLES)]
    assert df["im"].to_numpy() == pytest.approx(np.array(levels)[df["stripe"]], rel=1e-9)
    # Building 1 has two floors: its peak is the larger, its energy the sum; building 2 one.
    for run_name in ("pounding", "free"):
        for m in ("peak_disp", "peak_drift_ratio", "peak_accel", "residual_drift", "ductility"):
            key = f"{m}_{run_name}"
            assert np.array_equal(df[f"building1.{key}"], np.max(r[key][:, 0, :], axis=1),
                                  equal_nan=True), key
            assert np.array_equal(df[f"building2.{key}"], r[key][:, 1, 0], equal_nan=True), key
        e = f"hysteretic_energy_{run_name}"
        assert np.array_equal(df[f"building1.{e}"], r[e][:, 0, 0] + r[e][:, 0, 1])
    assert np.isnan(r["peak_disp_free"][:, 1, 1]).all()  # the 1-storey's missing floor
    assert (df["building1.peak_disp_free"] > 0).all()
    assert np.array_equal(df["pair1.peak_force"], r["peak_force"][:, 0, 0])
    assert np.array_equal(df["pair1.impacts"], r["impacts"][:, 0, 0])
    assert np.array_equal(df["pair1.approach_free"], r["approach_free"][:, 0, 0])
    assert df.attrs["samples"] == SAMPLES and df.attrs["seed"] == "7"
    assert df.attrs["building_names"] == "T0.50, T0.75"
    with h5py.File(campaign, "r") as f:  # a campaign of issue 23 or later: collapse per building
        for key in ("collapsed_pounding", "collapsed_free", "collapse_time_pounding"):
            for b in (0, 1):
                assert np.array_equal(df[f"building{b + 1}.{key}"], f[f"response/{key}"][:, b],
                                      equal_nan=True), key


def test_floors_give_a_column_per_floor_of_each_building(campaign):
    df = pound.read_campaign(campaign, floors=True)
    with h5py.File(campaign, "r") as f:
        drift = f["response/peak_drift_ratio_pounding"][()]
    assert np.array_equal(df["building1.floor2.peak_drift_ratio_pounding"], drift[:, 0, 1])
    assert "building2.floor1.peak_drift_ratio_pounding" in df.columns
    assert "building2.floor2.peak_drift_ratio_pounding" not in df.columns
    assert "pair1.level1.peak_force" in df.columns


def test_collapse_where_the_file_has_it(campaign, tmp_path):
    copy = tmp_path / "collapse.h5"
    shutil.copy(campaign, copy)
    flags = np.zeros((SAMPLES, 2))
    flags[3, 1] = 1
    with h5py.File(copy, "r+") as f:
        f["response/collapsed_pounding"][...] = flags
    df = pound.read_campaign(copy)
    assert list(df["building2.collapsed_pounding"]) == list(flags[:, 1])
    assert df["building1.collapsed_pounding"].sum() == 0
    # A file written before issue 23 has no collapse arrays, and no such columns.
    older = tmp_path / "older.h5"
    shutil.copy(campaign, older)
    with h5py.File(older, "r+") as f:
        for key in ("collapsed_pounding", "collapsed_free", "collapse_time_pounding",
                    "collapse_time_free"):
            del f[f"response/{key}"]
    assert not any("collapse" in c for c in pound.read_campaign(older).columns)


def test_files_that_are_not_campaigns(tmp_path):
    text = tmp_path / "x.h5"
    text.write_text("not hdf5")
    with pytest.raises(pound.Error, match=f"^{text}: cannot open the campaign file"):
        pound.read_campaign(text)
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f["x"] = [1]
    with pytest.raises(pound.Error, match=f"^{other}: not a campaign result file"):
        pound.read_campaign(other)
