"""The scripts that read campaign files through the package (issue 31): scripts/plot_results.py
(with plot_collapse.py), examples/campaign_fractions.py and slurm/pound_parts.py produce their
figures, tables and checks from a small campaign, invoked as the README, quickstart.sh, .ci/run
and slurm/test-local-slurm.sh invoke them. The campaign is the smoke study with a 2-storey
building beside the SDOF, two contact models and a collapse limit the stronger stripes pass."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import h5py
import pytest

from conftest import BINARY, SOURCE, run, small_campaign

SAMPLES = 24


@pytest.fixture(scope="module")
def analysed(tmp_path_factory):
    """The campaign file and the folder of its fragility analysis."""
    folder = tmp_path_factory.mktemp("scripts")
    path = small_campaign(folder, SAMPLES, ["--sample.model", "discrete(hc-linear: 1, lve: 1)",
                                            "--simulation.collapse_drift_ratio", "0.01"])
    code, _, err = run(["fragility", "--input", path, "--out", folder / "fragility",
                        "--drift-limits", "0.005, 0.01", "--replicates", 50])
    assert code == 0, err
    return path, folder / "fragility"


def script(args, env=None):
    """Debian's python on a script of the tree: (exit code, stdout, stderr)."""
    p = subprocess.run([sys.executable] + [str(a) for a in args], capture_output=True, text=True,
                       env=env)
    return p.returncode, p.stdout, p.stderr


def without_pythonpath():
    return {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}


def test_plot_results_draws_the_campaigns_figures(analysed, tmp_path):
    campaign, fragility = analysed
    code, out, err = script([SOURCE / "scripts" / "plot_results.py", "--campaign", campaign,
                             "--fragility", fragility, "--out", tmp_path / "plots"])
    assert code == 0, err
    drawn = {Path(line).name for line in out.splitlines()}
    for name in ("fragility_0_drift.png", "fragility_1_drift.png", "fragility_0_collapse.png",
                 "amplification_0.png", "amplification_1.png", "amplification_im_0.png",
                 "amplification_im_1.png", "collapse_fragility.png",
                 "collapse_fragility_hc-linear.png", "collapse_fragility_lve.png", "ida_0.png",
                 "ida_1.png"):
        assert name in drawn, (name, out)
        assert (tmp_path / "plots" / name).stat().st_size > 10000, name
    assert drawn == {p.name for p in (tmp_path / "plots").iterdir()}


def test_plot_results_finds_the_package_of_its_build_without_pythonpath(analysed, tmp_path):
    """As quickstart.sh runs it: /usr/bin/python3 scripts/plot_results.py, no PYTHONPATH (the
    tree's build/python); only where that build is the one under test."""
    if Path(os.environ.get("POUND_BUILD_DIR", SOURCE / "build")).resolve() != \
            (SOURCE / "build").resolve():
        pytest.skip("the build under test is not the tree's build/")
    campaign, _ = analysed
    code, out, err = script([SOURCE / "scripts" / "plot_results.py", "--campaign", campaign,
                             "--out", tmp_path], env=without_pythonpath())
    assert code == 0, err
    assert (tmp_path / "ida_0.png").stat().st_size > 10000


def test_campaign_fractions_tabulates_every_stripe(analysed, tmp_path):
    campaign, _ = analysed
    code, out, err = script([SOURCE / "examples" / "campaign_fractions.py", "--campaign",
                             campaign, "--out", tmp_path])
    assert code == 0, err
    assert f"{SAMPLES} samples (0 failed), drift limit 0.01; collapse: per building and run" in out
    rows = (tmp_path / "campaign_fractions.csv").read_text().splitlines()
    assert rows[0] == "building,run,stripe,im_g,samples,drift_exceeded,collapsed"
    assert len(rows) == 1 + 2 * 2 * 4  # buildings, runs, stripes
    assert {r.split(",")[0] for r in rows[1:]} == {"T0.50", "T0.75"}
    assert (tmp_path / "campaign_fractions.png").stat().st_size > 10000


def test_pound_parts_checks_and_compares_through_the_package(analysed, tmp_path):
    """As slurm/test-local-slurm.sh runs it: /usr/bin/python3 slurm/pound_parts.py with POUND
    the binary and no PYTHONPATH (the package beside the binary)."""
    campaign, _ = analysed
    parts = SOURCE / "slurm" / "pound_parts.py"
    env = dict(without_pythonpath(), POUND=str(BINARY))
    code, out, err = script([parts, "check", campaign], env)
    assert code == 0, err
    assert out == f"pound_parts: {campaign}: {SAMPLES} samples, ids 0..{SAMPLES - 1} each " \
                  "exactly once, 0 not ok\n"
    changed = tmp_path / "changed.h5"
    shutil.copy(campaign, changed)
    code, out, err = script([parts, "compare", campaign, changed], env)
    assert code == 0, err
    assert out.startswith(f"pound_parts: {campaign} == {changed} (")
    with h5py.File(changed, "r+") as f:
        f["response/peak_force"][3, 0, 0] += 1.0
    code, out, err = script([parts, "compare", campaign, changed], env)
    assert code == 1 and "differs: /response/peak_force" in err
    code, _, err = script([parts, "check", tmp_path / "missing.h5"], env)
    assert code == 1 and "cannot open the campaign file" in err
    # range and journal need no package (the C++ journal test runs them on any build).
    code, out, _ = script([parts, "range", "--chunk", 1, "--chunks", 2, "--samples", 24],
                          {"PATH": os.environ.get("PATH", "")})
    assert (code, out) == (0, "12 24\n")


@pytest.mark.parametrize("overrides,panels", [
    ([], 2),                                          # one motion under both: no ground panel
    (["--ground.apparent_velocity", "150"], 3),       # wave passage: the ground under each
    (["--building1.foundation", "springs", "--building1.sway_stiffness", "9.56e8",
      "--building1.rocking_stiffness", "1.02e11", "--building1.sway_damping", "7.2e7",
      "--building1.rocking_damping", "4.49e9"], 2),  # a flexible base on uniform ground
])
def test_plot_results_draws_the_histories(tmp_path, overrides, panels):
    """history.png and hysteresis.png from `pound simulate --histories`; the history figure has
    a third panel, the ground under each building, exactly when the grounds differ."""
    study = SOURCE / "studies" / "ch8-yielding.ini"
    hist = tmp_path / "h.h5"
    code, _, err = run(["simulate", "--config", study, "--histories", hist,
                        "--contact.model", "hc-linear", "--contact.k_factor", "50"] + overrides)
    assert code == 0, err
    code, out, err = script([SOURCE / "scripts" / "plot_results.py", "--histories", hist,
                             "--out", tmp_path / "plots"])
    assert code == 0, err
    for name in ("history.png", "hysteresis.png"):
        assert (tmp_path / "plots" / name).stat().st_size > 10000, name
    import matplotlib.image
    height = matplotlib.image.imread(tmp_path / "plots" / "history.png").shape[0]
    assert (height > 800) == (panels == 3), height  # 6.5 in against 9 in at the figure's dpi
