#!/usr/bin/env python3
"""Writes the small PNG inputs of the image fidelity scenes (image maps, bump maps, image
patterns, height fields) into assets/: python3 make-assets.py. Only the standard library."""
import math
import os
import struct
import zlib

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "assets")


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def png(name, width, height, rows, colour_type=0, depth=8, palette=None, trns=None):
    raw = b"".join(b"\0" + bytes(r) for r in rows)
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth, colour_type, 0, 0, 0))
    if palette:
        data += chunk(b"PLTE", bytes(sum(palette, [])))
    if trns:
        data += chunk(b"tRNS", bytes(trns))
    data += chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


# 16x8 RGB: red grows to the right, green downwards, blue marks the top-left quadrant.
png("map-rgb.png", 16, 8, [sum(([x * 17, y * 36, 255 if (x < 8 and y < 4) else 40] for x in range(16)), []) for y in range(8)], colour_type=2)
# Bump map: 32x32 grey, a raised ring and a diagonal ramp.
rows = []
for y in range(32):
    row = []
    for x in range(32):
        r = math.hypot(x - 15.5, y - 15.5)
        v = 200 if 7 <= r <= 11 else int(60 + 2 * (x + y) / 2)
        row.append(max(0, min(255, v)))
    rows.append(row)
png('bumps.png', 32, 32, rows)
# Terrain: 16-bit grey 33x33 hills.
rows = []
for y in range(33):
    row = []
    for x in range(33):
        u, v = x / 32, y / 32
        h = 0.5 + 0.25 * math.sin(7 * u) * math.cos(5 * v) + 0.2 * math.exp(-((u - 0.6) ** 2 + (v - 0.35) ** 2) * 30)
        q = max(0, min(65535, int(h * 65535)))
        row += [q >> 8, q & 255]
    rows.append(row)
png('terrain.png', 33, 33, rows, colour_type=0, depth=16)
# Alpha: grey + alpha 16x16, alpha falling off from the centre, grey stripes.
rows = []
for y in range(16):
    row = []
    for x in range(16):
        a = max(0, 255 - int(32 * math.hypot(x - 7.5, y - 7.5)))
        row += [255 if (x // 4) % 2 else 80, a]
    rows.append(row)
png('alpha.png', 16, 16, rows, colour_type=4)
# Palette: 8x8, four colours in quadrant stripes; index 1 made transparent by tRNS.
pal = [[200, 30, 30], [30, 200, 30], [30, 30, 200], [230, 230, 40]]
rows = [[((x // 2) + (y // 4)) % 4 for x in range(8)] for y in range(8)]
png('palette.png', 8, 8, rows, colour_type=3, palette=pal, trns=[255, 0, 255, 255])
