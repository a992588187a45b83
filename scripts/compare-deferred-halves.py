#!/usr/bin/env python3
"""Checks that grass-deferred's two halves (GL and --backend vk) draw the same picture: the same
scene, G-buffer and lighting shader on two drivers. Reads both PNGs and compares them in a grid
of regions: each region's mean colour (per channel, signed) and its mean absolute difference,
and the whole image's. Exits 1 past the tolerances below (or when the comparison would be
vacuous: a region grid of one colour, or images of different sizes), 0 otherwise, and prints
every figure.

usage: compare-deferred-halves.py GL.png VK.png"""
import importlib.util
import pathlib
import sys

import numpy

_spec = importlib.util.spec_from_file_location("render_sets", pathlib.Path(__file__).with_name("compare-render-sets.py"))
_render_sets = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_render_sets)

GRID = (4, 3)              # columns, rows of regions
MEAN_ABS_IMAGE = 0.25      # levels: the whole image's mean absolute difference
MEAN_ABS_REGION = 0.5      # levels: any region's mean absolute difference
MEAN_SIGNED_REGION = 0.25  # levels: any region's mean colour, per channel
DISTINCT_REGIONS = 20.0    # levels: the regions' means must differ by this much somewhere


def load(path):
    width, height, channels, rows = _render_sets.read_png(pathlib.Path(path))
    pixels = numpy.frombuffer(b"".join(rows), dtype=numpy.uint8).reshape(height, width, channels)
    return pixels[:, :, :3].astype(numpy.float64)


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    gl, vk = load(sys.argv[1]), load(sys.argv[2])
    if gl.shape != vk.shape:
        print(f"the images differ in size: {gl.shape} and {vk.shape}")
        return 1
    failures = []
    image_abs = float(numpy.abs(gl - vk).mean())
    print(f"whole image: mean absolute difference {image_abs:.2f} levels (at most {MEAN_ABS_IMAGE})")
    if image_abs > MEAN_ABS_IMAGE:
        failures.append("the whole image")
    height, width = gl.shape[:2]
    means = []
    for row in range(GRID[1]):
        for col in range(GRID[0]):
            ys = slice(row * height // GRID[1], (row + 1) * height // GRID[1])
            xs = slice(col * width // GRID[0], (col + 1) * width // GRID[0])
            a, b = gl[ys, xs].reshape(-1, 3), vk[ys, xs].reshape(-1, 3)
            region_abs = float(numpy.abs(a - b).mean())
            signed = b.mean(axis=0) - a.mean(axis=0)
            means.append(a.mean(axis=0))
            print(f"region row {row} column {col}: GL mean {numpy.round(a.mean(axis=0), 1)}, "
                  f"VK - GL {numpy.round(signed, 2)}, mean absolute difference {region_abs:.2f}")
            if region_abs > MEAN_ABS_REGION or float(numpy.abs(signed).max()) > MEAN_SIGNED_REGION:
                failures.append(f"region row {row} column {col}")
    spread = float(numpy.ptp(numpy.array(means), axis=0).max())
    print(f"the GL regions' means span {spread:.1f} levels (at least {DISTINCT_REGIONS})")
    if spread < DISTINCT_REGIONS:
        failures.append("a vacuous comparison: the regions are alike")
    if failures:
        print("the halves disagree: " + ", ".join(failures))
        return 1
    print("the halves agree")
    return 0


if __name__ == "__main__":
    sys.exit(main())
