#!/usr/bin/env python3
"""Compares two render sets of scripts/render-set.sh: every PNG pixel for pixel, every stats table
line for line. Exits 1 on any difference (and names it), 0 when both sets hold the same views and
each pair is identical. Guards against a vacuous pass: a set with fewer than two distinct images,
or with an image of a single colour, fails."""
import pathlib
import struct
import sys
import zlib


def read_png(path):
    """(width, height, channels, rows): the unfiltered rows of an 8-bit, non-interlaced PNG
    (grey, grey+alpha, RGB or RGBA), as grass-render writes them."""
    data = path.read_bytes()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    channels = {0: 1, 4: 2, 2: 3, 6: 4}.get(colour)
    if depth != 8 or channels is None or interlace:
        raise ValueError(f"{path}: only 8-bit non-interlaced grey/RGB(A) PNGs are read")
    raw, stride, bpp = zlib.decompress(idat), width * channels, channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - bpp] if i >= bpp else 0
            up, up_left = prev[i], (prev[i - bpp] if i >= bpp else 0)
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + ((left + up) >> 1)) & 255
            elif kind == 4:
                p = left + up - up_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - up_left)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else up_left)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, channels, rows


def main() -> int:
    if len(sys.argv) != 3:
        print(f"usage: {sys.argv[0]} SET_A SET_B", file=sys.stderr)
        return 2
    a, b = (pathlib.Path(p) for p in sys.argv[1:])
    names_a = sorted(p.name for p in a.iterdir() if p.suffix in (".png", ".txt"))
    names_b = sorted(p.name for p in b.iterdir() if p.suffix in (".png", ".txt"))
    failures = []
    if names_a != names_b:
        failures.append(f"the sets hold different files: only in {a}: {sorted(set(names_a) - set(names_b))}, "
                        f"only in {b}: {sorted(set(names_b) - set(names_a))}")
    digests = set()
    pngs = 0
    for name in sorted(set(names_a) & set(names_b)):
        if name.endswith(".txt"):
            if (a / name).read_text() != (b / name).read_text():
                failures.append(f"{name}: the stats tables differ")
            continue
        pngs += 1
        ia, ib = read_png(a / name), read_png(b / name)
        if ia[:3] != ib[:3]:
            failures.append(f"{name}: {ia[0]}x{ia[1]}x{ia[2]} against {ib[0]}x{ib[1]}x{ib[2]}")
            continue
        if ia[3] != ib[3]:
            diff = sum(1 for ra, rb in zip(ia[3], ib[3]) for x, y in zip(ra, rb) if x != y)
            failures.append(f"{name}: {diff} channel values differ")
        if len(set(ia[3])) < 2 and len(set(ia[3][0])) <= ia[2]:
            failures.append(f"{name}: a single colour (a vacuous comparison)")
        digests.add(zlib.crc32(b"".join(ia[3])))
    if pngs and len(digests) < 2:
        failures.append("every image is the same (a vacuous comparison)")
    for f in failures:
        print(f"compare-render-sets: {f}")
    if not failures:
        print(f"compare-render-sets: {pngs} images and {len(names_a) - pngs} tables identical")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
