"""The examples run as a user runs them, each in a fresh interpreter, and write their PNGs."""
import os
import subprocess
import sys

import pytest

from conftest import PACKAGE_ROOT

EXAMPLES = os.path.join(PACKAGE_ROOT, "examples")


def run_example(name, tmp_path, *args):
    env = dict(os.environ, PYTHONPATH=PACKAGE_ROOT)
    return subprocess.run([sys.executable, os.path.join(EXAMPLES, name), *args], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=600)


def test_plan_only(tmp_path):
    result = run_example("plan_only.py", tmp_path)
    assert result.returncode == 0, result.stderr
    assert "camera at   1.7 m" in result.stdout and " 0 blades" not in result.stdout.splitlines()[0]


@pytest.mark.parametrize("name", ["render_png.py", "paint_density.py"])
def test_headless_renders_write_pngs(tmp_path, name):
    pytest.importorskip("numpy") if name == "paint_density.py" else None
    out = tmp_path / (name[:-3] + ".png")
    result = run_example(name, tmp_path, str(out))
    assert result.returncode == 0, result.stdout + result.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    keep = os.environ.get("GRASS_PYTHON_OUT")  # the test command keeps them for a look
    if keep:
        os.makedirs(keep, exist_ok=True)
        with open(os.path.join(keep, out.name), "wb") as f:
            f.write(out.read_bytes())
