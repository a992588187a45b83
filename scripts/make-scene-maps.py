#!/usr/bin/env python3
"""Writes the design maps of the park and hills sample scenes as PNG files (standard
library only: zlib + struct). Rerun to regenerate samples/grass_render/scenes/{park,hills}.

park  (40 m x 40 m, boulanger2006 figure 24): density with two worn paths, a pond and a
      building's footprint without grass; colour with a flower bed and subtle dry patches;
      diffuse light with the building's shadow; ambient occlusion at the building's foot.
hills (200 m x 200 m): a 16-bit height map of rolling hills.
"""
import math
import os
import struct
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "samples", "grass_render", "scenes")


def write_png(path, width, height, rows, channels, bits=8):
    colour_type = {1: 0, 4: 6}[channels]
    raw = bytearray()
    for row in rows:
        raw.append(0)
        if bits == 8:
            raw.extend(bytes(max(0, min(255, int(round(v * 255)))) for v in row))
        else:
            for v in row:
                raw.extend(struct.pack(">H", max(0, min(65535, int(round(v * 65535))))))

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, bits, colour_type, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(bytes(raw), 9)))
        f.write(chunk(b"IEND", b""))


def smooth(e0, e1, x):
    t = max(0.0, min(1.0, (x - e0) / (e1 - e0)))
    return t * t * (3 - 2 * t)


def value_noise(x, y, seed):
    def h(i, j):
        n = (i * 374761393 + j * 668265263 + seed * 982451653) & 0xFFFFFFFF
        n = ((n ^ (n >> 13)) * 1274126177) & 0xFFFFFFFF
        return ((n ^ (n >> 16)) & 0xFFFF) / 65535.0
    i, j = math.floor(x), math.floor(y)
    fx, fy = x - i, y - j
    fx, fy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
    a = h(i, j) + fx * (h(i + 1, j) - h(i, j))
    b = h(i, j + 1) + fx * (h(i + 1, j + 1) - h(i, j + 1))
    return a + fy * (b - a)


def park(n=256, size=40.0):
    # Field space: x east, z south-ish (rows run along +z), metres from the field's corner.
    building = (29.0, 28.0, 36.0, 35.0)      # x0, z0, x1, z1 (a 7 m x 7 m house, 9 m high)
    height = 9.0
    sun = (0.35, 0.8, 0.25)                  # the scene's sun direction
    shadow = (-sun[0] / sun[1] * height, -sun[2] / sun[1] * height)
    pond = (29.0, 11.0, 5.0)                 # centre x, z, radius
    bed = (5.0, 27.0, 13.0, 34.0)            # the flower bed

    def path_distance(x, z):
        d1 = abs(z - (20.0 + 4.0 * math.sin(x * 0.16)))            # east-west path
        d2 = abs(x - (16.0 + 3.0 * math.sin(z * 0.2 + 1.0)))       # north-south path
        return min(d1, d2)

    def in_box(x, z, b, pad=0.0):
        return b[0] - pad <= x <= b[2] + pad and b[1] - pad <= z <= b[3] + pad

    def box_distance(x, z, b):
        dx = max(b[0] - x, 0.0, x - b[2])
        dz = max(b[1] - z, 0.0, z - b[3])
        return math.hypot(dx, dz)

    density, colour, diffuse, ambient = [], [], [], []
    for j in range(n):
        drow, crow, lrow, arow = [], [], [], []
        for i in range(n):
            x, z = (i + 0.5) / n * size, (j + 0.5) / n * size
            d = 0.85 + 0.15 * value_noise(x * 0.3, z * 0.3, 1)
            d *= smooth(0.45, 1.4, path_distance(x, z))   # worn paths: bare in the middle, thin at the edges
            d *= smooth(0.0, 0.6, math.hypot(x - pond[0], z - pond[1]) - pond[2])  # the pond
            if in_box(x, z, building):
                d = 0.0
            drow.append(d)
            # Colour: dry patches (low alpha); the flower bed (high alpha, blobs of colour).
            dry = smooth(0.55, 0.8, value_noise(x * 0.12, z * 0.12, 7))
            c = [0.62, 0.58, 0.25, 0.35 * dry]
            if in_box(x, z, bed):
                k = value_noise(x * 1.3, z * 1.3, 3)
                c = [0.85, 0.12, 0.18, 0.9] if k < 0.35 else ([0.95, 0.8, 0.1, 0.9] if k < 0.65 else [0.55, 0.2, 0.75, 0.9])
                c[3] *= smooth(0.0, 0.4, min(x - bed[0], bed[2] - x, z - bed[1], bed[3] - z))
            crow.extend(c)
            # Diffuse light: the building's shadow, the footprint swept along the sun.
            lit = 1.0
            for s in range(0, 41):
                t = s / 40.0
                if in_box(x - shadow[0] * t, z - shadow[1] * t, building):
                    lit = 0.18
                    break
            lrow.append(lit)
            # Ambient: the building occludes the sky near its walls.
            arow.append(0.45 + 0.55 * smooth(0.0, 4.0, box_distance(x, z, building)))
        density.append(drow)
        colour.append(crow)
        diffuse.append(lrow)
        ambient.append(arow)
    out = os.path.join(ROOT, "park")
    write_png(os.path.join(out, "density.png"), n, n, density, 1)
    write_png(os.path.join(out, "color.png"), n, n, colour, 4)
    write_png(os.path.join(out, "diffuse.png"), n, n, diffuse, 1)
    write_png(os.path.join(out, "ambient.png"), n, n, ambient, 1)


def hills(n=256, size=200.0):
    rows = []
    for j in range(n):
        row = []
        for i in range(n):
            x, z = (i + 0.5) / n * size, (j + 0.5) / n * size
            h = 0.0
            for cx, cz, r, a in ((60, 150, 35, 1.0), (130, 120, 30, 0.8), (160, 170, 40, 0.9), (100, 60, 25, 0.45)):
                h += a * math.exp(-((x - cx) ** 2 + (z - cz) ** 2) / (2 * r * r))
            h += 0.08 * value_noise(x * 0.05, z * 0.05, 5)
            row.append(min(1.0, h * 0.85))
        rows.append(row)
    write_png(os.path.join(ROOT, "hills", "height.png"), n, n, rows, 1, bits=16)


if __name__ == "__main__":
    park()
    hills()
