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


@pytest.fixture(autouse=True)
def in_empty_folder(tmp_path, monkeypatch):
    """Every test runs in an empty folder of its own (the module must write nothing there)."""
    monkeypatch.chdir(tmp_path)
    yield tmp_path
