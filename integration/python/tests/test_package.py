"""The package's version is the header's: pyproject.toml takes it from grass/_ffi.py, whose
GRASS_VERSION_* test_header_layout.py checks against grass.h. Built here the way a packager
would (pip, offline: no dependencies, no build isolation) into a target folder."""
import importlib.util
import shutil
import subprocess
import sys

import pytest

from conftest import PACKAGE_ROOT
from test_install import header_version


def test_pip_builds_the_package_with_the_headers_version(tmp_path):
    for module in ("pip", "setuptools"):  # found, not imported: setuptools would patch distutils here
        if importlib.util.find_spec(module) is None:
            pytest.skip(f"{module} is missing (python3-pip, python3-setuptools)")
    # From a copy: setuptools writes build/ and *.egg-info next to the pyproject.
    source, target = tmp_path / "source", tmp_path / "site"
    shutil.copytree(PACKAGE_ROOT, source, ignore=shutil.ignore_patterns("__pycache__", ".pytest_cache", "build",
                                                                         "*.egg-info"))
    subprocess.run([sys.executable, "-m", "pip", "install", "--quiet", "--no-deps", "--no-build-isolation",
                    "--no-index", "--target", str(target), str(source)], check=True, cwd=tmp_path)
    assert (target / "grass" / "_ffi.py").exists() and (target / "grass" / "headless.py").exists()
    assert [p.name for p in target.glob("grass-*.dist-info")] == [f"grass-{header_version()}.dist-info"]
