"""docs/python.md's install, run exactly as written: the sh block after the marker
'<!-- install: run as written by integration/python/tests/test_install.py -->' runs in bash
-e from a temporary folder holding only `build` (a link to this build), with HOME a
temporary folder, no GRASS_LIBRARY or PYTHONPATH, and no network (unshare -rn where the
kernel allows it). Then the venv's Python imports the installed grass (the library found by
its _config.py) and plans a frame."""
import os
import re
import shutil
import subprocess

import pytest

from conftest import REPO_ROOT

MARKER = "<!-- install: run as written by integration/python/tests/test_install.py -->"
DOC = os.path.join(REPO_ROOT, "docs", "python.md")


def install_block():
    text = open(DOC, encoding="utf-8").read()
    match = re.search(re.escape(MARKER) + r"\s*```sh\n(.*?)```", text, flags=re.S)
    assert match, f"{DOC} has no sh block after {MARKER}"
    return match.group(1)


def header_version():
    text = open(os.path.join(REPO_ROOT, "api", "include", "grass", "grass.h"), encoding="utf-8").read()
    return ".".join(re.search(rf"#define GRASS_VERSION_{p} +(\d+)", text).group(1) for p in ("MAJOR", "MINOR", "PATCH"))


def offline(command):
    """command under a new network namespace (no network at all), when the kernel lets us."""
    if shutil.which("unshare") and subprocess.run(["unshare", "-rn", "true"], capture_output=True).returncode == 0:
        return ["unshare", "-rn"] + command
    return command


def test_the_documented_install_runs_as_written(tmp_path):
    library = os.environ.get("GRASS_LIBRARY")
    build = os.path.dirname(os.path.abspath(library)) if library else None
    if not build or not os.path.exists(os.path.join(build, "cmake_install.cmake")):
        pytest.skip("needs GRASS_LIBRARY in a CMake build folder (ctest -R python_binding sets it)")
    work, home = tmp_path / "work", tmp_path / "home"
    work.mkdir()
    home.mkdir()
    (work / "build").symlink_to(build)
    env = {"PATH": os.environ["PATH"], "HOME": str(home), "LANG": "C.UTF-8"}
    block = install_block()
    result = subprocess.run(offline(["bash", "-euo", "pipefail", "-c", block]), cwd=work, env=env,
                            capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, f"{block}\n{result.stdout}\n{result.stderr}"
    assert header_version() in result.stdout  # the block prints the package's version

    pythons = list(home.glob("*/bin/python"))
    assert len(pythons) == 1, pythons
    plan = ("import grass, importlib.metadata as m\n"
            "print(grass.__version__, m.version('grass'), grass.lib._name)\n"
            "with grass.Context() as ctx:\n"
            "    ctx.create_field(ctx.create_patch(blade_count=64), cells_x=32, cells_z=32)\n"
            "    with ctx.frame(grass.view_desc(eye=(4, 1.6, -1), target=(4, 0, 4), size=(64, 48))):\n"
            "        pass\n"
            "    print(ctx.frame_stats().blades_drawn)\n")
    out = subprocess.run([str(pythons[0]), "-c", plan], cwd=tmp_path, env=env, capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr
    version, metadata, loaded, blades = out.stdout.split()
    assert version == metadata == header_version()
    assert loaded.startswith(str(home)) and int(blades) > 0  # the installed library, not the build's
