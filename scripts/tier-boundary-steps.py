#!/usr/bin/env python3
"""The colour step across each tier boundary and the row-to-row variation, for one camera
(issue 32, item 5; the record is docs/records/three-tiers.md).

For a scene and a camera, grass-render draws the view at the scene's lod setup (DEFAULT's
tiers) and with --debug-tiers. Each row's ground point on the view's centre column gives its
distance from the camera, and so which tiers draw it (the lod setup's distance bands, as
grass_default_lod_setup scales them by the cell size). At each edge of each transition zone
(where a tier starts to fade in, or the one before has faded out) a narrow window is drawn,
centred on that edge, with the full view's pixel size (72 rows of the full view's angle), by
DEFAULT and by the blades everywhere of two patch and mirror seeds (the truth and the seed
spread). Per window: the rows' mean green over the middle half (grass pixels), then

  step      the mean of the 12 rows beyond the edge minus the 12 rows before it (levels);
  kink      the centre row band's departure from the straight line through the rows either
            side (an arc is a lighter or darker line along the edge);
  offset    the window's mean green minus the truth's;
  rows      row-to-row variation (each row minus the mean of the two either side, RMS,
            as MoireTest measures it).

DEFAULT's step and kink are compared with the truth's (seed 1); the seed spread is the second
seed's against the first. The whole view's row-to-row variation is reported too, with the
debug view's tier colours per band of rows (r geometry, y volume, b image).

Usage: scripts/tier-boundary-steps.py --scene FILE --camera X,Y,Z --target X,Y,Z
         [--backend gl|vk] [--samples 1|4] [--size WxH] [--fov DEG] [--far M]
         [--render build/samples/grass_render/grass-render] [--out DIR] [--no-truth] [--no-ground]
         [--reuse-truth] [--edge TEXT]
"""
import argparse
import json
import math
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from importlib import import_module  # noqa: E402

read_png = import_module("compare-render-sets").read_png

# grass_default_lod_setup, in cells: (begin, end, transition_in, transition_out) per tier.
DEFAULT_BANDS = [("geometry", 0, 20, 0, 15), ("volume 8", 5, 80, 15, 30), ("volume 2", 50, 160, 30, 60),
                 ("volume 1", 100, 300, 60, 100), ("image", 200, math.inf, 100, 0)]
WINDOW_ROWS, WINDOW_COLS, BAND = 72, 128, 12


def load_scene(path):
    text = "\n".join(line for line in Path(path).read_text().splitlines() if not line.lstrip().startswith("//"))
    return json.loads(text)


def write_scene(scene, src, seed=None, mirror_seed=None, blades=False, directory=None):
    s = json.loads(json.dumps(scene))
    maps = s.get("field", {}).get("maps", {})
    for k, v in list(maps.items()):
        if isinstance(v, str):
            maps[k] = str((Path(src).parent / v).resolve())
    if seed is not None:
        s.setdefault("patch", {})["seed"] = seed
    if mirror_seed is not None:
        s.setdefault("field", {})["mirror_seed"] = mirror_seed
    if blades:
        s["field"]["tiers"] = [{"kind": "geometry"}]
        s["field"]["lod_tests"] = [{"kind": "band", "tier": 0, "begin": 0, "end": None}]
    out = Path(directory) / f"scene-{seed}-{mirror_seed}-{int(blades)}.json"
    out.write_text(json.dumps(s))
    return out


def render(args, scene_file, out, camera, target, fov, size, extra=(), reuse=False):
    if reuse and Path(out).exists():  # --reuse-truth: a truth rendered by an earlier run into --out
        w, h, c, rows = read_png(Path(out))
        return np.frombuffer(b"".join(rows), dtype=np.uint8).reshape(h, w, c)[:, :, :3].astype(float)
    if args.no_ground:
        extra = (*extra, "--no-ground")
    cmd = [args.render, "--scene", str(scene_file), "--backend", args.backend, "--samples", str(args.samples),
           "--size", f"{size[0]}x{size[1]}", "--camera", ",".join(map(str, camera)), "--target",
           ",".join(map(str, target)), "--fov", str(fov), "--far", str(args.far), "--output", str(out), *extra]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    w, h, c, rows = read_png(Path(out))
    return np.frombuffer(b"".join(rows), dtype=np.uint8).reshape(h, w, c)[:, :, :3].astype(float)


def basis(camera, target):
    f = np.subtract(target, camera).astype(float)
    f /= np.linalg.norm(f)
    r = np.cross(f, [0.0, 1.0, 0.0])
    r /= np.linalg.norm(r)
    return f, r, np.cross(r, f)


def row_distance(camera, target, fov, height, y):
    """Distance from the camera to the ground (y = 0) under row y's centre on the centre column."""
    f, _, u = basis(camera, target)
    v = (1.0 - 2.0 * (y + 0.5) / height) * math.tan(math.radians(fov) / 2)
    d = f + v * u
    if d[1] >= 0:
        return math.inf
    return abs(camera[1] / d[1]) * np.linalg.norm(d)


def ground_point(camera, target, fov, height, y):
    f, _, u = basis(camera, target)
    v = (1.0 - 2.0 * (y + 0.5) / height) * math.tan(math.radians(fov) / 2)
    d = f + v * u
    return [camera[0] + d[0] * camera[1] / -d[1], 0.0, camera[2] + d[2] * camera[1] / -d[1]]


def grass_mask(img):
    return (img[:, :, 1] > 70) & (img[:, :, 1] > img[:, :, 2] + 25)


def row_means(img):
    h, w, _ = img.shape
    mid = img[:, w // 4:3 * w // 4]
    m = grass_mask(mid)
    g = np.where(m, mid[:, :, 1], 0.0).sum(1)
    n = m.sum(1)
    return np.where(n > 0, g / np.maximum(n, 1), np.nan), n / mid.shape[1]


def row_to_row(means):
    v = [means[y] - 0.25 * (means[y - 2] + means[y - 1] + means[y + 1] + means[y + 2])
         for y in range(2, len(means) - 2)]
    v = np.array([x for x in v if not math.isnan(x)])
    return float(np.sqrt(np.mean(v * v))) if len(v) else math.nan


def window_figures(img):
    m, cover = row_means(img)
    c = len(m) // 2
    near, far = np.nanmean(m[c:c + BAND]), np.nanmean(m[c - BAND:c])
    # The kink: the middle band against the line through the bands 2 BAND either side.
    outer_far, outer_near = np.nanmean(m[c - 3 * BAND:c - 2 * BAND]), np.nanmean(m[c + 2 * BAND:c + 3 * BAND])
    mid = np.nanmean(m[c - BAND // 2:c + BAND // 2])
    return {"step": far - near, "kink": mid - 0.5 * (outer_far + outer_near), "mean": float(np.nanmean(m)),
            "rows": row_to_row(m), "cover": float(np.mean(cover))}


def zone_edges(cell):
    """(distance m, label) of each transition zone's edges: from where tier b begins to fade
    in to where tier a, before it, has faded out."""
    edges = []
    for (a, _, end_a, _, _), (b, begin_b, _, _, _) in zip(DEFAULT_BANDS, DEFAULT_BANDS[1:]):
        edges.append((begin_b * cell, f"{a} -> {b} starts"))
        edges.append((end_a * cell, f"{a} -> {b} ends"))
    return edges


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scene", required=True)
    p.add_argument("--camera", required=True)
    p.add_argument("--target", required=True)
    p.add_argument("--backend", default="gl")
    p.add_argument("--samples", type=int, default=4)
    p.add_argument("--size", default="640x360")
    p.add_argument("--fov", type=float, default=55.0)
    p.add_argument("--far", type=float, default=2000.0)
    p.add_argument("--render", default="build/samples/grass_render/grass-render")
    p.add_argument("--out", default=None, help="keep every render in DIR")
    p.add_argument("--no-truth", action="store_true", help="DEFAULT only (no blades everywhere)")
    p.add_argument("--edge", default="", help="only the zone edges whose label holds this text (e.g. 'image')")
    p.add_argument("--no-ground", action="store_true", help="no ground under the grass (grass-render --no-ground)")
    p.add_argument("--reuse-truth", action="store_true",
                   help="read the blades' windows from --out where an earlier run left them")
    args = p.parse_args()
    camera = [float(x) for x in args.camera.split(",")]
    target = [float(x) for x in args.target.split(",")]
    width, height = (int(x) for x in args.size.split("x"))
    scene = load_scene(args.scene)
    cell = float(scene.get("field", {}).get("cell_size", 0.25))
    if "tiers" in scene.get("field", {}):
        sys.exit("tier-boundary-steps: the scene names its own tiers; only the default lod setup is known")
    out = Path(args.out) if args.out else Path(tempfile.mkdtemp(prefix="tier-steps-"))
    out.mkdir(parents=True, exist_ok=True)
    tag = f"{Path(args.scene).stem}-{args.backend}-x{args.samples}{'-noground' if args.no_ground else ''}"
    base = write_scene(scene, args.scene, directory=out)
    full = render(args, base, out / f"{tag}.png", camera, target, args.fov, (width, height))
    tiers = render(args, base, out / f"{tag}-tiers.png", camera, target, args.fov, (width, height),
                   ["--debug-tiers"])
    means, _ = row_means(full)
    lo = int(np.argmax(~np.isnan(means)))
    print(f"{tag}: camera {args.camera} target {args.target}: whole view, rows {lo}-{height - 1}: "
          f"row-to-row {row_to_row(means[lo:]):.2f}, mean green {np.nanmean(means):.1f}")
    # The debug view's tier per band of 24 rows: the share of red, yellow and blue tints.
    for y0 in range(0, height, 24):
        band = tiers[y0:y0 + 24, width // 4:3 * width // 4]
        r, g, b = band[:, :, 0], band[:, :, 1], band[:, :, 2]
        red = np.mean((r > g * 1.6) & (r > b * 1.6))
        yellow = np.mean((r > b * 1.6) & (g > b * 1.6) & (r <= g * 1.6))
        blue = np.mean((b > r * 1.3) & (b > g * 1.0))
        d = row_distance(camera, target, args.fov, height, y0 + 12)
        print(f"  rows {y0:3d}-{y0 + 23:3d} ({d:6.1f} m): green {np.nanmean(means[y0:y0 + 24]):6.1f}, "
              f"debug tints r {red:.2f} y {yellow:.2f} b {blue:.2f}")
    window_fov = 2 * math.degrees(math.atan(math.tan(math.radians(args.fov) / 2) * WINDOW_ROWS / height))
    seeds = [] if args.no_truth else [(101, 7), (202, 8)]
    truths = [write_scene(scene, args.scene, s, m, True, out) for s, m in seeds]
    print(f"  {'edge':30s} {'m':>5s} {'row':>4s} | {'DEFAULT step kink offset rows':30s} | "
          f"{'truth step kink rows':22s} | spread step kink | err/spread")
    for dist, label in zone_edges(cell):
        if dist <= camera[1] or args.edge not in label:
            continue
        ys = [y for y in range(height) if row_distance(camera, target, args.fov, height, y) >= dist]
        if not ys or max(ys) < BAND or max(ys) > height - BAND:
            continue
        y = max(ys)
        reach = math.sqrt(dist * dist - camera[1] * camera[1])
        f, _, _ = basis(camera, target)
        h = np.array([f[0], 0.0, f[2]])
        h /= np.linalg.norm(h)
        aim = [camera[0] + h[0] * reach, 0.0, camera[2] + h[2] * reach]
        name = label.replace(" ", "_").replace(">", "").replace("-", "")
        d = window_figures(render(args, base, out / f"{tag}-{name}.png", camera, aim, window_fov,
                                  (WINDOW_COLS, WINDOW_ROWS)))
        line = (f"  {label:30s} {dist:5.1f} {y:4d} | {d['step']:+5.1f} {d['kink']:+5.1f} {{off}} {d['rows']:4.2f} "
                f"cover {d['cover']:.2f}")
        if not truths:
            print(line.replace("{off}", "  -  "))
            continue
        t = [window_figures(render(args, s, out / f"{tag}-{name}-truth{i}.png", camera, aim, window_fov,
                                   (WINDOW_COLS, WINDOW_ROWS), reuse=args.reuse_truth)) for i, s in enumerate(truths)]
        spread_step, spread_kink = abs(t[1]["step"] - t[0]["step"]), abs(t[1]["kink"] - t[0]["kink"])
        err_step, err_kink = abs(d["step"] - t[0]["step"]), abs(d["kink"] - t[0]["kink"])
        print(line.replace("{off}", f"{d['mean'] - t[0]['mean']:+5.1f}") +
              f" | {t[0]['step']:+5.1f} {t[0]['kink']:+5.1f} {t[0]['rows']:4.2f}/{t[1]['rows']:4.2f}"
              f" | {spread_step:4.1f} {spread_kink:4.1f} | step {err_step:4.1f} kink {err_kink:4.1f}")
    print(f"  renders in {out}")


if __name__ == "__main__":
    main()
