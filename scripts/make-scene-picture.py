#!/usr/bin/env python3
"""Writes scenes/images/picture.png, the picture X of the animation scenes
(PITA Sec. 7.1, Fig. 23-24): a 160 x 120 landscape with a sun, a house and a
tree, asymmetric so that its rotation and mirroring show. Standard library
only (zlib); run it again to regenerate the same bytes."""
import math
import struct
import sys
import zlib

W, H = 160, 120


def color(x, y):
    # sky gradient, ground, sun, house with roof and door, tree
    if y > 88:
        return (70, 140, 60)
    if (x - 128) ** 2 + (y - 24) ** 2 < 14 ** 2:
        return (250, 200, 40)
    if 20 <= x < 70 and 56 <= y <= 88:
        if 40 <= x < 50 and y >= 70:
            return (110, 60, 30)
        if 26 <= x < 36 and 62 <= y < 70:
            return (190, 230, 250)
        return (200, 70, 60)
    if 14 <= x < 76 and y < 56 and y >= 56 - (30 - abs(x - 45)):
        return (120, 40, 40)
    if 102 <= x < 108 and 70 <= y <= 88:
        return (100, 70, 40)
    if (x - 105) ** 2 + (y - 62) ** 2 < 13 ** 2:
        return (40, 110, 50)
    t = y / 88.0
    return (int(120 + 80 * t), int(170 + 60 * t), 245)


def png(width, height, pixel):
    raw = bytearray()
    for y in range(height):
        raw.append(0)
        for x in range(width):
            raw.extend(pixel(x, y))
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b"")


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "scenes/images/picture.png"
    with open(out, "wb") as f:
        f.write(png(W, H, color))
