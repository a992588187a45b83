#!/usr/bin/env python3
"""render_set_compare: scripts/compare-render-sets.py passes two identical sets, and fails a
changed pixel, a changed stats line, a missing view, a single-colour image and a set of
identical images."""
import pathlib
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
COMPARE = ROOT / "scripts" / "compare-render-sets.py"


def write_png(path, width, height, pixel):
    """An 8-bit RGB PNG, each row with a different filter (the reader must undo all five)."""
    raw = b""
    for y in range(height):
        row = bytes(c for x in range(width) for c in pixel(x, y))
        kind = y % 5
        out = bytearray(row)
        prev = raw_rows[y - 1] if y else bytes(len(row))
        for i in range(len(row)):
            left = row[i - 3] if i >= 3 else 0
            up, up_left = prev[i], (prev[i - 3] if i >= 3 else 0)
            if kind == 1:
                out[i] = (row[i] - left) & 255
            elif kind == 2:
                out[i] = (row[i] - up) & 255
            elif kind == 3:
                out[i] = (row[i] - ((left + up) >> 1)) & 255
            elif kind == 4:
                p = left + up - up_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - up_left)
                out[i] = (row[i] - (left if pa <= pb and pa <= pc else up if pb <= pc else up_left)) & 255
        raw_rows.append(row)
        raw += bytes([kind]) + bytes(out)

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    raw_rows.clear()
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                     chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


raw_rows = []


def make_set(folder, shift=0, stats="blades 10 drawn\n", flat=False, same=False):
    folder.mkdir()
    for k, name in enumerate(("eye-gl", "eye-vk")):
        k = 0 if same else k
        write_png(folder / f"{name}.png", 7, 6,
                  (lambda x, y: (40, 90, 30)) if flat else
                  (lambda x, y, k=k: ((x * 31 + k * 7 + shift * (x == 3 and y == 2)) % 256, y * 40, (x * y) % 256)))
        (folder / f"{name}.txt").write_text(stats)


def compare(a, b):
    r = subprocess.run([sys.executable, str(COMPARE), str(a), str(b)], capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def main():
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        make_set(tmp / "a")
        make_set(tmp / "b")
        make_set(tmp / "pixel", shift=1)
        make_set(tmp / "stats", stats="blades 11 drawn\n")
        make_set(tmp / "flat", flat=True)
        make_set(tmp / "same", same=True)
        shutil.copytree(tmp / "a", tmp / "missing")
        (tmp / "missing" / "eye-vk.png").unlink()
        cases = [("b", 0, "2 images and 2 tables identical"), ("pixel", 1, "eye-gl.png: 1 channel values differ"),
                 ("stats", 1, "the stats tables differ"), ("missing", 1, "different files"),
                 ("flat", 1, "a single colour"), ("same", 1, "every image is the same")]
        for other, want_rc, want_text in cases:
            rc, out = compare(tmp / ("flat" if other == "flat" else "same" if other == "same" else "a"), tmp / other)
            if rc != want_rc or want_text not in out:
                failures.append(f"{other}: rc {rc} (want {want_rc}), output: {out.strip()!r} (want {want_text!r})")
    for f in failures:
        print(f"render_set_compare: {f}")
    print("render_set_compare: " + ("FAILED" if failures else f"{len(cases)} cases as expected"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
