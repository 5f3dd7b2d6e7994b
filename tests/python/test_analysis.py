"""pound.fragility and pound.risk (issue 25): the commands' --json on a campaign file, number for
number, writing files only when asked. The campaign is the smoke study (two SDOFs) with spectral
variability at four stripes up to 0.8 g, run by `pound campaign` on one rank."""

import json
import os
from pathlib import Path

import pytest

import pound
from conftest import STUDIES, cli_error, cli_json, run

HAZARD = STUDIES / "hazard-los-angeles-pga.csv"
FILES = {"fragility": ["curves.csv", "shift.csv", "observations.csv", "sensitivity.csv"],
         "risk": ["risk_gaps.csv", "code_rules.csv", "damage_maf.csv"]}


@pytest.fixture(scope="module")
def campaign(tmp_path_factory):
    folder = tmp_path_factory.mktemp("campaign")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    path = folder / "run.h5"
    code, _, err = run(["campaign", "--config", STUDIES / "campaign-smoke.ini", "--samples", 160,
                        "--generator.variability", "spectral", "--intensity.levels",
                        "0.1, 0.2, 0.4, 0.8", "--out", path, "--quiet"], cwd=folder, env=env)
    assert code == 0, err
    return path


def without_files(result):
    return {k: v for k, v in result.items() if k not in ("out", "files")}


def test_fragility_is_the_commands_json_and_writes_nothing_unless_asked(campaign, tmp_path):
    py = pound.fragility(campaign, drift_limits=[0.005, 0.01, 0.02], replicates=200, seed=3)
    cli = cli_json(["fragility", "--input", campaign, "--drift-limits", "0.005, 0.01, 0.02",
                    "--replicates", 200, "--seed", 3, "--out", tmp_path / "cli"])
    assert without_files(py) == without_files(cli)
    # Numbers to compare: finite shifts, with and without pounding.
    assert sum(s["theta_ratio"] is not None for s in py["shift"]) >= 3
    assert py["files"] == [] and py["out"] == ""
    assert not (campaign.parent / "run-fragility").exists()
    assert list(tmp_path.iterdir()) == [tmp_path / "cli"]  # the test's folder: the CLI's only
    # With out=, the command's files, byte for byte the same CSVs.
    written = pound.fragility(campaign, out=tmp_path / "py", drift_limits=[0.005, 0.01, 0.02],
                              replicates=200, seed=3)
    assert [Path(f).name for f in written["files"]] == [Path(f).name for f in cli["files"]]
    for name in FILES["fragility"]:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()


def test_risk_is_the_commands_json_and_writes_nothing_unless_asked(campaign, tmp_path):
    py = pound.risk(campaign, HAZARD, design_im=0.5, replicates=100, years=30)
    cli = cli_json(["risk", "--input", campaign, "--hazard", HAZARD, "--design-im", 0.5,
                    "--replicates", 100, "--years", 30, "--out", tmp_path / "cli"])
    assert without_files(py) == without_files(cli)
    assert py["years"] == 30 and abs(py["design_im"] - 0.5 * 9.80665) < 1e-12
    rules = py["pairs"][0]["code_rules"]
    assert len(rules) == 4 and all(r["gap_m"] > 0 for r in rules)
    assert py["files"] == [] and not (campaign.parent / "run-risk").exists()
    written = pound.risk(campaign, HAZARD, out=tmp_path / "py", design_im=0.5, replicates=100,
                         years=30)
    assert len(written["files"]) == 4
    for name in FILES["risk"]:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()


@pytest.mark.parametrize("call, options, command, args", [
    ("fragility", {}, "fragility", ["--input", "missing.h5"]),
    ("fragility", {"drift_limits": "abc"}, "fragility",
     ["--input", "CAMPAIGN", "--drift-limits", "abc"]),
    ("fragility", {"drift_limits": [-0.01]}, "fragility",
     ["--input", "CAMPAIGN", "--drift-limits", "-0.01"]),
    ("fragility", {"replicates": 5}, "fragility", ["--input", "CAMPAIGN", "--replicates", 5]),
    ("risk", {"hazard": "missing.csv"}, "risk",
     ["--input", "CAMPAIGN", "--hazard", "missing.csv"]),
    ("risk", {"target_probability": 1.5}, "risk",
     ["--input", "CAMPAIGN", "--hazard", "HAZARD", "--target-probability", 1.5]),
])
def test_errors_are_the_commands_lines_and_nothing_is_written(campaign, tmp_path, call, options,
                                                              command, args):
    def real(a):
        return {"CAMPAIGN": campaign, "HAZARD": HAZARD}.get(a, a) if isinstance(a, str) else a
    expected = cli_error(command, [real(a) for a in args] + ["--out", tmp_path / "cli"])
    target = "missing.h5" if args[1] == "missing.h5" else campaign
    kwargs = dict(options)
    with pytest.raises(pound.Error) as e:
        if call == "fragility":
            pound.fragility(target, out=tmp_path / "py", **kwargs)
        else:
            hazard = kwargs.pop("hazard", HAZARD)
            pound.risk(target, hazard, out=tmp_path / "py", **kwargs)
    assert str(e.value) == expected
    assert not (tmp_path / "py").exists()


def test_keys_the_call_sets_itself_are_refused(campaign):
    with pytest.raises(pound.Error, match="^input: not a key here"):
        pound.fragility(campaign, input="other.h5")
    with pytest.raises(pound.Error, match="^json: not a key here"):
        pound.risk(campaign, HAZARD, json=True)


def test_the_json_is_plain_data(campaign):
    r = pound.fragility(campaign, drift_limits=[0.01], replicates=50)
    assert json.loads(json.dumps(r)) == r
