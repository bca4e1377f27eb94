"""Pillow's BILINEAR resize of a raw 8-bit RGB image, for tests/dataset/format/dataset_reader_test.cpp.

Usage: pil_resize.py WIDTH HEIGHT IN.u8 OUT_WIDTH OUT_HEIGHT OUT.u8
Reads WIDTH x HEIGHT x 3 bytes, writes the resized OUT_WIDTH x OUT_HEIGHT x 3 bytes.
"""
import sys

import numpy as np
from PIL import Image

width, height = int(sys.argv[1]), int(sys.argv[2])
pixels = np.fromfile(sys.argv[3], dtype=np.uint8).reshape((height, width, 3))
out_width, out_height = int(sys.argv[4]), int(sys.argv[5])
resized = Image.fromarray(pixels, "RGB").resize((out_width, out_height), Image.BILINEAR)
np.asarray(resized, dtype=np.uint8).tofile(sys.argv[6])
