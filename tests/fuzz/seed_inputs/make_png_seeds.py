#!/usr/bin/env python3
"""Writes the small PNG and PAM seeds of tests/fuzz/seed_inputs/grading/ (run once; the
files are committed). One PNG per colour type and bit depth libpng expands to
RGBA8 (common/image/image.h), one interlaced, and PAM frames as encode_pam writes them."""
import os
import struct
import zlib

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "grading")


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def png(name, width, height, depth, colour, rows, extra=b"", interlace=0):
    raw = b"".join(b"\x00" + r for r in rows)
    ihdr = struct.pack(">IIBBBBB", width, height, depth, colour, 0, 0, interlace)
    data = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + extra +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


def pam(width, height, pixel):
    header = b"P7\nWIDTH %d\nHEIGHT %d\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n" % (width, height)
    return header + bytes(pixel(i) for i in range(width * height * 4))


os.makedirs(HERE, exist_ok=True)
png("grey1.png", 3, 2, 1, 0, [b"\xa0", b"\x40"])
png("grey16_alpha.png", 2, 2, 16, 4, [b"\x12\x34\xff\xff\xab\xcd\x00\x00"] * 2)
png("rgb8.png", 3, 2, 8, 2, [bytes(range(9)), bytes(range(100, 109))])
png("palette_trns.png", 2, 2, 4, 3, [b"\x01", b"\x10"],
    extra=chunk(b"PLTE", b"\xff\x00\x00\x00\xff\x00") + chunk(b"tRNS", b"\x80"))
rgba = [[(x * 60, y * 60, 128, 255 - x * y) for x in range(4)] for y in range(4)]
adam7 = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]
passes = []  # Adam7: each pass a sub-image of its own rows, each row with its filter byte
for x0, y0, dx, dy in adam7:
    for y in range(y0, 4, dy):
        row = bytes(v for x in range(x0, 4, dx) for v in rgba[y][x])
        if row:
            passes.append(row)
png("rgba8_interlaced.png", 4, 4, 8, 6, passes, interlace=1)
with open(os.path.join(HERE, "frame.pam"), "wb") as f:
    f.write(pam(3, 2, lambda i: (i * 29) & 0xFF))
with open(os.path.join(HERE, "frames.pam"), "wb") as f:
    f.write(pam(1, 1, lambda i: 255) + pam(2, 1, lambda i: i))
