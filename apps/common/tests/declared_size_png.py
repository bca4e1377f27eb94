#!/usr/bin/python3
"""Writes a PNG whose header declares WIDTH x HEIGHT grey pixels but whose data holds only the
first rows, as a hostile or damaged file does: a reader that trusts the header allocates for the
whole image before it finds out. Usage: declared_size_png.py WIDTH HEIGHT OUT.png"""
import struct
import sys
import zlib


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


width, height, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
header = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)  # 8-bit grey, no interlace
rows = zlib.compress((b"\x00" + b"\x80" * width) * 4)
with open(out, "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", rows) + chunk(b"IEND", b""))
