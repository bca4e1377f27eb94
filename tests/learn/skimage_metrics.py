"""scikit-image's SSIM and PSNR of two raw float32 images (HWC), for tests/learn/image_metrics_test.cpp.

Usage: skimage_metrics.py WIDTH HEIGHT CHANNELS DATA_RANGE TRUTH.f32 PREDICTION.f32 MASK.u8
Prints "ssim", "psnr" and "ssim_masked" (the full SSIM map averaged over the window centres that
lie inside the mask and at least 3 pixels from the border) with their values.
"""
import sys

import numpy as np
from skimage.metrics import peak_signal_noise_ratio, structural_similarity

width, height, channels = (int(v) for v in sys.argv[1:4])
data_range = float(sys.argv[4])
shape = (height, width, channels)
truth = np.fromfile(sys.argv[5], dtype=np.float32).reshape(shape).astype(np.float64)
prediction = np.fromfile(sys.argv[6], dtype=np.float32).reshape(shape).astype(np.float64)
mask = np.fromfile(sys.argv[7], dtype=np.uint8).reshape((height, width)) != 0

mean_ssim, ssim_map = structural_similarity(truth, prediction, data_range=data_range, channel_axis=2, full=True)
pad = 3  # (win_size - 1) // 2 for the default 7 x 7 window
valid = np.zeros((height, width), dtype=bool)
valid[pad:height - pad, pad:width - pad] = True
centres = valid & mask
print("ssim", repr(float(mean_ssim)))
print("psnr", repr(float(peak_signal_noise_ratio(truth, prediction, data_range=data_range))))
print("ssim_masked", repr(float(ssim_map[centres].mean())))
