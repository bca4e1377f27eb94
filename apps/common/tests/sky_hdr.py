#!/usr/bin/env python3
"""Writes a latitude-longitude sky as a Radiance .hdr file (RGBE, flat scanlines), for tests that
need a real environment map file: a blue gradient above the horizon, grey ground below it and a
small bright sun.

usage: sky_hdr.py WIDTH HEIGHT OUT.hdr   (OUT's folder is created if needed)
"""
import math
import os
import sys


def rgbe(r, g, b):
    """Radiance's shared-exponent encoding of one pixel (Ward, Graphics Gems II, "Real Pixels")."""
    m = max(r, g, b)
    if m < 1e-32:
        return bytes((0, 0, 0, 0))
    mantissa, exponent = math.frexp(m)
    scale = mantissa * 256.0 / m
    return bytes((int(r * scale), int(g * scale), int(b * scale), exponent + 128))


def radiance(u, v):
    # The direction Cycles maps to (u, v): phi = pi (1 - 2u), theta = pi (1 - v).
    phi, theta = math.pi * (1.0 - 2.0 * u), math.pi * (1.0 - v)
    d = (math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta))
    sun = (0.5, 0.3, 0.812)
    norm = math.sqrt(sum(c * c for c in sun))
    if sum(a * b / norm for a, b in zip(d, sun)) > math.cos(math.radians(3.0)):
        return (4000.0, 3600.0, 3000.0)
    if d[2] < 0.0:
        return (0.25, 0.22, 0.2)
    return (0.3 + 0.5 * (1.0 - d[2]), 0.5 + 0.4 * (1.0 - d[2]), 1.0)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    width, height, path = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "wb") as out:
        out.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        out.write(f"-Y {height} +X {width}\n".encode())
        for y in range(height):  # the first scanline is the top row, v = 1
            v = 1.0 - (y + 0.5) / height
            out.write(b"".join(rgbe(*radiance((x + 0.5) / width, v)) for x in range(width)))


if __name__ == "__main__":
    main()
