"""Shared helpers of the Python module's tests (issue 25): the program to compare with, the
source tree, and running commands. ctest runs every test_*.py here with PYTHONPATH=build/python
(tests/CMakeLists.txt); by hand:

    PYTHONPATH=build/python /usr/bin/python3 -m pytest tests/python
"""

import json
import os
import subprocess
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("POUND_SOURCE_DIR", Path(__file__).resolve().parents[2]))
BINARY = Path(os.environ.get("POUND_BINARY", SOURCE / "build" / "bin" / "pound"))
STUDIES = SOURCE / "studies"
ELCENTRO = SOURCE / "motions" / "elcentro-1940-ns.dat"
# The studies `pound simulate` runs (the others are a campaign, an impact and a hazard curve).
SIMULATE_STUDIES = ["ch3-steel-frames", "ch6-sdof-pair", "ch8-five-three", "ch8-three-five",
                    "ch8-yielding"]


def study(name):
    return str(STUDIES / f"{name}.ini")


def run(args, cwd=None, env=None):
    """The program with these arguments: (exit code, stdout, stderr)."""
    p = subprocess.run([str(BINARY)] + [str(a) for a in args], capture_output=True, text=True,
                       cwd=cwd, env=env)
    return p.returncode, p.stdout, p.stderr


def cli_json(args):
    """What the program prints with --json, parsed (it must succeed)."""
    code, out, err = run(list(args) + ["--json"])
    assert code == 0, err
    return json.loads(out)


def cli_error(command, args, kind="error"):
    """The text after 'pound COMMAND: error: ' (or 'numerical failure: ') of a failing run."""
    code, out, err = run([command] + list(args))
    assert code == (2 if kind == "error" else 3), (code, err)
    assert out == ""
    line = err.strip().splitlines()[-1]
    prefix = f"pound {command}: {kind}: "
    assert line.startswith(prefix), line
    return line[len(prefix):]


# The smoke study's first building made a 2-storey one (floors: 2 and 1), so that the buildings
# differ in height and the per-floor arrays carry NaN padding.
_ONE_STOREY = "masses = 100             # kg\nstiffnesses = 15791.37   # N/m"
_TWO_STOREY = "masses = 100, 80\nstiffnesses = 15791.37, 12000"


def small_campaign(folder, samples=16, args=(), name="run.h5"):
    """A campaign file FOLDER/NAME of the smoke study with a 2-storey beside the SDOF (study
    FOLDER/study.ini), run by `pound campaign` on one rank (no mpirun: MPI's singleton start),
    with these extra arguments (--sample.model ..., --chunk 1/2, ...)."""
    text = (STUDIES / "campaign-smoke.ini").read_text()
    assert _ONE_STOREY in text
    study = folder / "study.ini"
    study.write_text(text.replace(_ONE_STOREY, _TWO_STOREY, 1))
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    path = folder / name
    code, _, err = run(["campaign", "--config", study, "--samples", samples, "--out", path,
                        "--quiet"] + list(args), cwd=folder, env=env)
    assert code == 0, err
    return path


@pytest.fixture(autouse=True)
def in_empty_folder(tmp_path, monkeypatch):
    """Every test runs in an empty folder of its own (the module must write nothing there)."""
    monkeypatch.chdir(tmp_path)
    yield tmp_path
