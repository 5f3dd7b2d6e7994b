"""The engine reads and prints numbers with a decimal point whatever locale Python set: a script
that calls locale.setlocale(locale.LC_ALL, "de_DE.UTF-8") gets the same numbers (issue 25).
The German locale is compiled into a folder of the test's own with localedef (Debian package
locales, installed by scripts/install-deps.sh); without localedef the test skips, saying so."""

import os
import shutil
import subprocess
import sys

import pytest

import pound
from conftest import cli_json, study

SCRIPT = """
import json, locale, sys
import pound
locale.setlocale(locale.LC_ALL, "de_DE.UTF-8")
assert locale.localeconv()["decimal_point"] == ",", locale.localeconv()["decimal_point"]
assert "%.1f" % 0.5 == "0.5"  # Python's own formatting ignores the locale; C's printf does not
r = pound.simulate(sys.argv[1], contact__e=0.75)
print(json.dumps({"simulate": r, "c_printf": locale.format_string("%.1f", 0.5)}))
"""


def test_a_comma_locale_changes_nothing(tmp_path):
    localedef = shutil.which("localedef")
    if not localedef or not os.path.exists("/usr/share/i18n/locales/de_DE"):
        pytest.skip("localedef or the locale sources are missing (Debian package locales)")
    subprocess.run([localedef, "-i", "de_DE", "-f", "UTF-8", str(tmp_path / "de_DE.UTF-8")],
                   check=True, capture_output=True)
    package = os.path.dirname(os.path.dirname(pound.__file__))  # the pound under test
    env = dict(os.environ, LOCPATH=str(tmp_path), PYTHONPATH=package)
    out = subprocess.run([sys.executable, "-c", SCRIPT, study("ch6-sdof-pair")], env=env,
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    result = __import__("json").loads(out.stdout)
    assert result["c_printf"] == "0,5"  # the locale is in force in that process
    assert result["simulate"] == cli_json(["simulate", "--config", study("ch6-sdof-pair"),
                                           "--contact.e=0.75"])
