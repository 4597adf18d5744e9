#!/usr/bin/python3
"""Writes box.obj, box.mtl and box_diffuse.png: a unit cube whose six faces each map one cell of a 3x2
texture atlas (a colour per face, checkered in 8-texel squares). Deterministic; rerun to regenerate."""
import struct
import zlib

CELL, CHECK = 32, 8
FACE_COLOURS = [(214, 69, 65), (65, 131, 215), (46, 204, 113), (241, 196, 15), (155, 89, 182), (236, 240, 241)]


def png(width, height, rows):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    raw = b"".join(b"\x00" + bytes(row) for row in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


width, height = 3 * CELL, 2 * CELL
rows = []
for y in range(height):
    row = []
    for x in range(width):
        r, g, b = FACE_COLOURS[(y // CELL) * 3 + x // CELL]
        if ((x // CHECK) + (y // CHECK)) % 2:
            r, g, b = (c // 2 for c in (r, g, b))
        row += [r, g, b]
    rows.append(row)
open("box_diffuse.png", "wb").write(png(width, height, rows))

# +x, -x, +y, -y, +z, -z: each face's corners counter-clockwise seen from outside.
faces = [
    [(1, -1, 1), (1, -1, -1), (1, 1, -1), (1, 1, 1)],
    [(-1, -1, -1), (-1, -1, 1), (-1, 1, 1), (-1, 1, -1)],
    [(-1, 1, 1), (1, 1, 1), (1, 1, -1), (-1, 1, -1)],
    [(-1, -1, -1), (1, -1, -1), (1, -1, 1), (-1, -1, 1)],
    [(-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)],
    [(1, -1, -1), (-1, -1, -1), (-1, 1, -1), (1, 1, -1)],
]
lines = ["# A unit cube, one atlas cell per face (make_box.py)", "mtllib box.mtl"]
for corners in faces:
    lines += ["v %g %g %g" % c for c in corners]
for i in range(6):
    u0, v1 = (i % 3) / 3, 1 - (i // 3) / 2  # v is up: row 0 of the atlas is the top half
    u1, v0 = u0 + 1 / 3, v1 - 1 / 2
    lines += ["vt %.6f %.6f" % uv for uv in [(u0, v0), (u1, v0), (u1, v1), (u0, v1)]]
lines.append("usemtl boxmat")
for i in range(6):
    a = 4 * i + 1
    lines.append("f %d/%d %d/%d %d/%d %d/%d" % (a, a, a + 1, a + 1, a + 2, a + 2, a + 3, a + 3))
open("box.obj", "w").write("\n".join(lines) + "\n")
open("box.mtl", "w").write("newmtl boxmat\nKd 1 1 1\nmap_Kd box_diffuse.png\n")
