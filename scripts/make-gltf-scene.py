#!/usr/bin/env python3
"""Writes the glTF sample scene samples/grass_render/scenes/hill.glb (standard library only):
a 32 m x 32 m terrain with a hill whose vertex colours (COLOR_0, red) give the grass density
with a winding path of thin grass, a few rocks and a shed (boxes), a camera, and a sphere and
a capsule collider. The convention it follows is in docs/gltf.md.

  python3 scripts/make-gltf-scene.py            # writes the file
  python3 scripts/make-gltf-scene.py --check    # exit 1 when the shipped file differs
"""
import json
import math
import os
import struct
import sys

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "samples", "grass_render", "scenes", "hill.glb")

FLOAT, UBYTE, USHORT = 5126, 5121, 5123
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963


def q(x):
    """Rounded so that the bytes do not depend on the last bit of libm."""
    return round(x, 4)


def height(x, z):
    hill = 2.4 * math.exp(-((x - 5.0) ** 2 + (z - 6.0) ** 2) / (2 * 5.0 ** 2))
    return hill + 0.25 * math.sin(0.35 * x) * math.cos(0.3 * z)


def density(x, z):
    # A path winding away from the camera: thin grass on it.
    centre = -1.0 + 2.0 * math.sin(0.25 * (z + 15.0))
    d = abs(x - centre) / 1.2
    return 0.08 + 0.92 * min(1.0, d * d)


class Builder:
    def __init__(self):
        self.bin = bytearray()
        self.views = []
        self.accessors = []

    def add(self, data, target, count, ctype, kind, normalized=False, minmax=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.views.append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data), "target": target})
        self.bin.extend(data)
        acc = {"bufferView": len(self.views) - 1, "componentType": ctype, "count": count, "type": kind}
        if normalized:
            acc["normalized"] = True
        if minmax:
            acc["min"], acc["max"] = minmax
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def positions(self, pts):
        lo = [min(p[k] for p in pts) for k in range(3)]
        hi = [max(p[k] for p in pts) for k in range(3)]
        data = b"".join(struct.pack("<3f", *p) for p in pts)
        return self.add(data, ARRAY_BUFFER, len(pts), FLOAT, "VEC3", minmax=(lo, hi))

    def vec3(self, vs):
        return self.add(b"".join(struct.pack("<3f", *v) for v in vs), ARRAY_BUFFER, len(vs), FLOAT, "VEC3")

    def indices(self, idx):
        return self.add(struct.pack("<%dH" % len(idx), *idx), ELEMENT_ARRAY_BUFFER, len(idx), USHORT, "SCALAR")


def terrain(b, n=48, size=32.0):
    pts, normals, colours, idx = [], [], [], []
    for j in range(n + 1):
        for i in range(n + 1):
            x, z = -size / 2 + size * i / n, -size / 2 + size * j / n
            pts.append((q(x), q(height(x, z)), q(z)))
            e = 0.01
            nx = height(x - e, z) - height(x + e, z)
            nz = height(x, z - e) - height(x, z + e)
            ln = math.sqrt(nx * nx + (2 * e) ** 2 + nz * nz)
            normals.append((q(nx / ln), q(2 * e / ln), q(nz / ln)))
            colours.append(int(round(density(x, z) * 255)))
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            idx += [a, a + n + 1, a + 1, a + 1, a + n + 1, a + n + 2]  # counter-clockwise from above
    colour_data = b"".join(struct.pack("<4B", c, c, c, 255) for c in colours)
    attributes = {
        "POSITION": b.positions(pts),
        "NORMAL": b.vec3(normals),
        "COLOR_0": b.add(colour_data, ARRAY_BUFFER, len(colours), UBYTE, "VEC4", normalized=True),
    }
    return {"name": "terrain", "primitives": [{"attributes": attributes, "indices": b.indices(idx), "material": 0}]}


def box(b, material):
    pts, normals, idx = [], [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            u, v = [(axis + 1) % 3, (axis + 2) % 3]
            base = len(pts)
            for cu, cv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = 0.5 * sign, 0.5 * cu, 0.5 * cv
                pts.append(tuple(p))
                normals.append(tuple(n))
            quad = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
            idx += [base + k for k in quad]
    attributes = {"POSITION": b.positions(pts), "NORMAL": b.vec3(normals)}
    return {"primitives": [{"attributes": attributes, "indices": b.indices(idx), "material": material}]}


def quaternion_y(degrees):
    a = math.radians(degrees) / 2
    return [0.0, q(math.sin(a)), 0.0, q(math.cos(a))]


def look_rotation(eye, target):
    """The quaternion turning a glTF camera (looking along -z, up +y) towards target."""
    f = [t - e for t, e in zip(target, eye)]
    lf = math.sqrt(sum(c * c for c in f))
    f = [c / lf for c in f]
    r = [-f[2], 0.0, f[0]]  # f x up
    lr = math.sqrt(sum(c * c for c in r))
    r = [c / lr for c in r]
    u = [r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]]
    m = [r, u, [-c for c in f]]  # columns x, y, z
    m00, m11, m22 = m[0][0], m[1][1], m[2][2]
    w = math.sqrt(max(0.0, 1 + m00 + m11 + m22)) / 2
    x = (m[1][2] - m[2][1]) / (4 * w)
    y = (m[2][0] - m[0][2]) / (4 * w)
    z = (m[0][1] - m[1][0]) / (4 * w)
    return [q(x), q(y), q(z), q(w)]


def scene():
    b = Builder()
    meshes = [terrain(b), box(b, 1), box(b, 2)]
    meshes[1]["name"], meshes[2]["name"] = "rock", "shed"
    rock = lambda name, x, z, s, turn: {
        "name": name, "mesh": 1, "rotation": quaternion_y(turn),
        "translation": [x, q(height(x, z) + 0.25 * s[1]), z], "scale": s}
    eye, target = [-1.0, 1.7, -15.5], [0.0, 0.3, -3.0]
    nodes = [
        {"name": "terrain", "mesh": 0, "extras": {"grass": {"role": "terrain", "cell_size": 0.25}}},
        rock("rock 1", 2.6, -8.5, [1.2, 0.8, 0.9], 20.0),
        rock("rock 2", -3.5, -6.0, [0.7, 0.6, 0.8], 65.0),
        rock("rock 3", 3.5, -3.0, [0.5, 0.4, 0.6], 10.0),
        {"name": "shed", "mesh": 2, "rotation": quaternion_y(-25.0),
         "translation": [-7.0, q(height(-7.0, 7.0) + 1.0), 7.0], "scale": [3.0, 2.6, 2.2]},
        {"name": "camera", "camera": 0, "translation": eye, "rotation": look_rotation(eye, target)},
        {"name": "ball", "translation": [1.0, q(height(1.0, -9.0) + 0.3), -9.0],
         "extras": {"grass": {"role": "collider", "shape": "sphere", "radius": 0.3}}},
        {"name": "walker", "translation": [-0.5, q(height(-0.5, -5.0) + 0.9), -5.0],
         "extras": {"grass": {"role": "collider", "shape": "capsule", "radius": 0.25, "height": 1.3}}},
    ]
    materials = [
        {"name": "soil", "pbrMetallicRoughness": {"baseColorFactor": [0.045, 0.036, 0.018, 1.0]}},
        {"name": "granite", "pbrMetallicRoughness": {"baseColorFactor": [0.32, 0.31, 0.29, 1.0]}},
        {"name": "painted wood", "pbrMetallicRoughness": {"baseColorFactor": [0.45, 0.08, 0.05, 1.0]}},
    ]
    while len(b.bin) % 4:
        b.bin.append(0)
    doc = {
        "asset": {"version": "2.0", "generator": "grass scripts/make-gltf-scene.py"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "cameras": [{"type": "perspective", "perspective": {"yfov": q(math.radians(55.0)), "znear": 0.05,
                                                            "zfar": 400.0}}],
        "buffers": [{"byteLength": len(b.bin)}],
        "bufferViews": b.views,
        "accessors": b.accessors,
    }
    text = json.dumps(doc, sort_keys=True, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    total = 12 + 8 + len(text) + 8 + len(b.bin)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(text), b"JSON") + text +
            struct.pack("<I4s", len(b.bin), b"BIN\0") + bytes(b.bin))


def main():
    data = scene()
    if "--check" in sys.argv[1:]:
        with open(OUT, "rb") as f:
            same = f.read() == data
        print("make-gltf-scene: %s %s" % (OUT, "is up to date" if same else "differs from what the script writes"))
        return 0 if same else 1
    with open(OUT, "wb") as f:
        f.write(data)
    print("make-gltf-scene: wrote %s (%d bytes)" % (OUT, len(data)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
