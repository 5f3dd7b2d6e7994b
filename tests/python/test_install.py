"""`cmake --install build --prefix P` installs the package where Python finds it with
PYTHONPATH=P/lib/python3.X/dist-packages (Debian's python3 finds /usr/local's without), and the
installed module works on its own (issue 25)."""

import os
import shutil
import subprocess
import sys

from conftest import SOURCE, study


def test_the_installed_package_imports_and_simulates(tmp_path):
    cmake = os.environ.get("CMAKE_COMMAND") or shutil.which("cmake")
    build = os.environ.get("POUND_BUILD_DIR", str(SOURCE / "build"))
    prefix = tmp_path / "prefix"
    subprocess.run([cmake, "--install", build, "--prefix", str(prefix)], check=True,
                   capture_output=True)
    site = prefix / "lib" / f"python{sys.version_info.major}.{sys.version_info.minor}" / \
        "dist-packages"
    assert (site / "pound" / "__init__.py").is_file()
    assert (prefix / "bin" / "pound").is_file()
    script = ("import pound, sys; r = pound.simulate(sys.argv[1]); "
              "print(pound.__file__); print(r['contacts'][0]['impacts'])")
    env = dict(os.environ, PYTHONPATH=str(site))
    out = subprocess.run([sys.executable, "-c", script, study("ch6-sdof-pair")], env=env,
                         capture_output=True, text=True, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    where, impacts = out.stdout.split()
    assert where == str(site / "pound" / "__init__.py")
    assert int(impacts) > 0
