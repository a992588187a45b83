"""The package installs from the repo with pip (offline: no dependencies, no build isolation)."""
import importlib.util
import os
import subprocess
import sys

import shutil

import pytest

from conftest import PACKAGE_ROOT


def test_pip_installs_the_package(tmp_path):
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
    env = dict(os.environ, PYTHONPATH=str(target))
    code = "import grass; print(grass.__file__, grass.lib.grass_library_version())"
    out = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env, check=True, capture_output=True,
                         text=True).stdout
    assert out.startswith(str(target))
