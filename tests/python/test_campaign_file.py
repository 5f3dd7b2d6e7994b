"""pound.open_campaign (issue 31): the one reader of campaign files that the scripts use; the
root attribute floors the campaign and the merge write, and how a file written before it is
read; pound.G and pound.lognormal_cdf. The campaign is the smoke study with a 2-storey building
beside the SDOF (floors 2 and 1)."""

import math
import shutil

import h5py
import numpy as np
import pytest

import pound
from conftest import run, small_campaign

SAMPLES = 16


@pytest.fixture(scope="module")
def campaign(tmp_path_factory):
    return small_campaign(tmp_path_factory.mktemp("campaign"), SAMPLES,
                          ["--sample.model", "discrete(hc-linear: 1, lve: 1)"])


def without_floors(campaign, path):
    """A copy of the campaign as a file written before the attribute floors existed."""
    shutil.copy(campaign, path)
    with h5py.File(path, "r+") as f:
        del f.attrs["floors"]
    return path


def study_floors(c):
    """The floors of each building by its masses in the resolved study (one mass a floor)."""
    return [len(c.study_value(f"building{b}.masses").split(",")) for b in (1, 2)]


def test_the_floors_attribute_holds_the_studys_floor_counts(campaign):
    with h5py.File(campaign, "r") as f:
        stored = f.attrs["floors"]
        width = f["response/peak_disp_free"].shape[2]
    assert stored.dtype.kind == "i" and list(stored) == [2, 1]
    with pound.open_campaign(campaign) as c:
        assert c.floors == [2, 1] == study_floors(c)
        assert width == max(c.floors)
        assert c.attrs["floors"] == [2, 1]
    assert pound.read_campaign(campaign).attrs["floors"] == [2, 1]


def test_the_merge_keeps_the_floors_attribute(tmp_path):
    parts = [small_campaign(tmp_path, 8, ["--chunk", f"{k}/2"], f"part{k}.h5") for k in (0, 1)]
    merged = tmp_path / "merged.h5"
    code, _, err = run(["merge", "--out", merged, "--parts", ",".join(map(str, parts))])
    assert code == 0, err
    with h5py.File(merged, "r") as f:
        assert list(f.attrs["floors"]) == [2, 1]
    with pound.open_campaign(merged) as c:
        assert c.floors == [2, 1] and len(c) == c.sample_count == 8


def test_the_reader_gives_the_files_samples_buildings_and_results(campaign):
    with pound.open_campaign(campaign) as c, h5py.File(campaign, "r") as f:
        assert len(c) == c.sample_count == SAMPLES
        assert list(c.ids) == list(range(SAMPLES))
        assert np.array_equal(c.status, f["samples/status"][()]) and c.ok.all()
        assert np.array_equal(c.im, f["samples/im"][()])
        assert list(c.messages) == [""] * SAMPLES
        # The sampled parameters in the file's order, labels as text.
        assert list(c.parameters) == ["e", "gap", "k_factor", "model"]
        assert set(c.parameters["model"]) == {"hc-linear", "lve"}
        assert np.array_equal(c.parameters["gap"], f["samples/gap"][()])
        assert c.intensity_measure == "pga"
        assert c.im_levels == pytest.approx(np.array([0.1, 0.2, 0.3, 0.4]) * pound.G, rel=1e-6)
        assert list(c.stripes) == [i % 4 for i in range(SAMPLES)]
        assert c.buildings == 2 and c.pairs == 1
        assert c.building_names == ["T0.50", "T0.75"]
        assert c.study_value("simulation.collapse_drift_ratio") == "0.1"
        assert c.study_value("no.such_key") is None
        for name in ("peak_drift_ratio_pounding", "collapsed_free", "peak_force"):
            assert np.array_equal(c.response(name), f[f"response/{name}"][()], equal_nan=True)
        assert c.response("no_such_dataset") is None
        a = c.amplification
        assert np.array_equal(a["disp"]["median"], f["amplification/disp/median"][()],
                              equal_nan=True)
        assert a.attrs["design"] == "stripes"
        assert a["models"].attrs["labels"] == "hc-linear, lve"
        assert "samples/id" in c.datasets() and "run/rank" in c.datasets()
        assert c.datasets(("response",)) == sorted(f"response/{k}" for k in f["response"])
        assert np.array_equal(c.dataset("samples/k_factor"), f["samples/k_factor"][()])
    assert not c._file  # closed by the with block


def test_an_older_file_counts_the_floors_from_the_per_floor_arrays(campaign, tmp_path):
    older = without_floors(campaign, tmp_path / "older.h5")
    with pound.open_campaign(older) as c:
        assert "floors" not in c.attrs
        assert c.floors == [2, 1]
    new, old = (pound.read_campaign(p, floors=True) for p in (campaign, older))
    assert list(new.columns) == list(old.columns)
    assert "building2.floor2.peak_drift_ratio_pounding" not in old.columns
    for column in new.columns:
        assert new[column].equals(old[column]), column
    # A failed sample has NaN on every floor: a building's floors are those a sample reached.
    with h5py.File(older, "r+") as f:
        for name in ("peak_disp_free", "peak_disp_pounding"):
            data = f[f"response/{name}"][()]
            data[1:, 0, 1] = np.nan  # floor 2 of building 1 known in sample 0 only
            f[f"response/{name}"][...] = data
    with pound.open_campaign(older) as c:
        assert c.floors == [2, 1]


def test_an_older_file_gives_the_drift_ratios_under_their_current_names(campaign, tmp_path):
    # Files written before 2026-11-26 hold the peak drift ratios as peak_drift_pounding/_free.
    older = tmp_path / "older-names.h5"
    shutil.copy(campaign, older)
    with h5py.File(older, "r+") as f:
        for run_name in ("pounding", "free"):
            f.move(f"response/peak_drift_ratio_{run_name}", f"response/peak_drift_{run_name}")
    with pound.open_campaign(campaign) as c, pound.open_campaign(older) as o:
        assert sorted(o.response_names) == sorted(c.response_names)
        for run_name in ("pounding", "free"):
            name = f"peak_drift_ratio_{run_name}"
            assert np.array_equal(o.response(name), c.response(name), equal_nan=True)
    new, old = (pound.read_campaign(p, floors=True) for p in (campaign, older))
    assert sorted(new.columns) == sorted(old.columns)
    assert "building1.floor2.peak_drift_ratio_pounding" in old.columns
    for column in new.columns:
        assert new[column].equals(old[column]), column


def test_an_older_file_without_a_successful_sample_is_an_error(campaign, tmp_path):
    older = without_floors(campaign, tmp_path / "older.h5")
    with h5py.File(older, "r+") as f:
        for name in ("peak_disp_free", "peak_disp_pounding"):
            f[f"response/{name}"][:, 1, :] = np.nan
    with pound.open_campaign(older) as c:
        with pytest.raises(pound.Error, match="no attribute floors .* floors of building 2"):
            c.floors
    with pytest.raises(pound.Error, match="no attribute floors"):
        pound.read_campaign(older)


def test_a_floors_attribute_that_does_not_fit_the_file_is_an_error(campaign, tmp_path):
    for bad in ([2], [2, 1, 1], [3, 1], [0, 1]):
        path = tmp_path / "bad.h5"
        shutil.copy(campaign, path)
        with h5py.File(path, "r+") as f:
            f.attrs["floors"] = np.array(bad, dtype=np.int32)
        with pound.open_campaign(path) as c:
            with pytest.raises(pound.Error, match=r"attribute floors = .* does not fit the file"):
                c.floors


def test_files_that_are_not_campaigns(tmp_path):
    with pytest.raises(pound.Error, match="cannot open the campaign file"):
        pound.open_campaign(tmp_path / "missing.h5")
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f["x"] = [1]
    with pytest.raises(pound.Error, match=f"^{other}: not a campaign result file"):
        pound.open_campaign(other)


def test_g_is_the_engines_and_the_lognormal_cdf_the_fragility_curves():
    assert pound.G == 9.80665
    theta, beta = 0.8, 0.45
    x = np.array([0.05, 0.3, 0.8, 1.7, 4.0])
    erf_form = [0.5 * (1 + math.erf(math.log(v / theta) / (beta * math.sqrt(2)))) for v in x]
    assert pound.lognormal_cdf(x, theta, beta) == pytest.approx(erf_form, rel=1e-12, abs=1e-15)
    assert pound.lognormal_cdf(theta, theta, beta) == pytest.approx(0.5, abs=1e-15)
    assert isinstance(pound.lognormal_cdf([1.0], 1.0, 0.3), np.ndarray)
