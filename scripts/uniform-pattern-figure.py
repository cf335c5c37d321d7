#!/usr/bin/env python3
"""Draws one triangle patch's tessellation as a PNG line drawing (docs/uniform-subdivision.md).

    scripts/uniform-pattern-figure.py TESSREF LEVEL tpg|uniform OUT.png [SPACING]

tpg: the triangles `tessref tpg` emits for inner = outer = LEVEL; uniform: the n^2 grid triangles
with n = ceil(LEVEL) (stages/tpg_uniform.h). Plain Python (zlib) so that no imaging package is needed.
"""
import math
import struct
import subprocess
import sys
import zlib

SIZE, SS = 256, 4  # output pixels, supersampling per axis


def tpg_triangles(tessref, level, spacing):
    text = subprocess.run([tessref, "tpg", "--domain", "triangles", "--spacing", spacing, "--winding", "ccw",
                           "--outer", f"{level},{level},{level}", "--inner", str(level)],
                          check=True, capture_output=True, text=True).stdout
    pts = [tuple(float(x) for x in line.split()) for line in text.splitlines() if line.strip()]
    return [pts[k:k + 3] for k in range(0, len(pts), 3)]


def uniform_triangles(level):
    n = math.ceil(level)
    p = lambda i, j: (i / n, j / n, (n - i - j) / n)
    tris = []
    for j in range(n - 1, -1, -1):
        for i in range(n - j):
            tris.append([p(i, j + 1), p(i, j), p(i + 1, j)])
            if i + j + 2 <= n:
                tris.append([p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)])
    return tris


def to_screen(c):
    # u at the bottom left, v at the top, w at the bottom right of an equilateral triangle,
    # centred in the image.
    side = 0.88 * SIZE * SS
    h = side * math.sqrt(3) / 2
    left, top = (SIZE * SS - side) / 2, (SIZE * SS - h) / 2
    corners = [(left, top + h), (left + side / 2, top), (left + side, top + h)]
    return tuple(sum(c[k] * corners[k][a] for k in range(3)) for a in range(2))


def draw(tris, ink):
    w = SIZE * SS
    cov = bytearray(w * w)
    for tri in tris:
        for a, b in ((0, 1), (1, 2), (2, 0)):
            (x0, y0), (x1, y1) = to_screen(tri[a]), to_screen(tri[b])
            steps = int(max(abs(x1 - x0), abs(y1 - y0))) + 1
            for s in range(steps + 1):
                x, y = x0 + (x1 - x0) * s / steps, y0 + (y1 - y0) * s / steps
                for dx in range(-2, 3):  # a line SS/2 + 1 samples wide: about one output pixel
                    for dy in range(-2, 3):
                        xi, yi = int(x) + dx, int(y) + dy
                        if 0 <= xi < w and 0 <= yi < w:
                            cov[yi * w + xi] = 1
    rows = []
    for y in range(SIZE):
        row = bytearray([0])
        for x in range(SIZE):
            f = sum(cov[(y * SS + sy) * w + x * SS + sx] for sy in range(SS) for sx in range(SS)) / (SS * SS)
            row += bytes(round(255 + (ink[k] - 255) * f) for k in range(3))
        rows.append(bytes(row))
    return b"".join(rows)


def write_png(path, raw):
    chunk = lambda tag, data: struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def main():
    if len(sys.argv) not in (5, 6) or sys.argv[3] not in ("tpg", "uniform"):
        sys.exit(__doc__)
    tessref, level, kind, out = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
    spacing = sys.argv[5] if len(sys.argv) == 6 else "fractional_odd"
    if kind == "tpg":
        write_png(out, draw(tpg_triangles(tessref, level, spacing), (180, 0, 40)))
    else:
        write_png(out, draw(uniform_triangles(level), (0, 90, 170)))


if __name__ == "__main__":
    main()
