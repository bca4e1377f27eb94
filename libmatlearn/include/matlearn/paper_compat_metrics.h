#pragma once
// The MatPredict paper's numbers, reproduced: the conventions of the Python package
// image-similarity-measures (its metric functions as of its 0.3 releases, with their defaults)
// applied to 8-bit images, which is what the paper's table reports (docs/metrics.md). Use
// these only to compare with the paper; matlearn/image_metrics.h has the correct metrics. No
// masks: the package has none.
#include <cstdint>
#include <vector>

#include "matbase/image/float_image.h"

namespace matlearn::paper_compat {

// An 8-bit image as the package receives it from a PNG: HWC, values 0..255.
struct Image8 {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<uint8_t> values;
};

// Values in [0, 1] to 8 bits: round(255 v), clamped.
Image8 quantize_8bit(const matbase::FloatImage& image);
// The 8-bit values as floats 0..255, what numpy computes with once an array is cast.
matbase::FloatImage widen(const Image8& image);

// Its 12-bit default max_p = 4095, whatever the images' real range (an 8-bit image's RMSE comes
// out 16 times too small, its PSNR 24 dB too high).
constexpr double kMaxP = 4095.0;

// Per band sqrt(mean(((x - y) / 4095)^2)), averaged over bands.
double rmse(const Image8& truth, const Image8& prediction);
// 20 log10(4095 / sqrt(mean over bands of the per-band MSE)).
double psnr(const Image8& truth, const Image8& prediction);
// 10 log10 of the band average of mean(x)^2 / (||x - y||_2 / (rows cols)): the norm is not squared
// and the average is taken before the logarithm.
double sre(const Image8& truth, const Image8& prediction);
// scikit-image's SSIM with data_range = 4095 over the 8-bit values.
double ssim(const Image8& truth, const Image8& prediction);
// Q on 8 x 8 windows without special cases: a window where Q is 0 / 0 counts as 0 (numpy's
// nan_to_num), so two equal flat windows score 0, not 1.
double uiq(const Image8& truth, const Image8& prediction);
// Per band: phasepack's phase congruency (6 orientations, nscale 4, minWaveLength 6, mult 2,
// sigmaOnf 0.5978) summed over orientations, and OpenCV's Scharr into uint16 (negative
// derivatives clip to 0; the squares wrap modulo 2^16 in numpy); T1 = 0.85, T2 = 160; averaged.
double fsim(const Image8& truth, const Image8& prediction);
// Always 0 on 8-bit images: its Canny edge correlation is 0 / 0 there (paper_compat_metrics.cpp
// says why), and nan_to_num turns the NaN result into 0.
double issm(const Image8& truth, const Image8& prediction);
// Per pixel arccos(sum_c (x_c y_c mod 256) / (|x| |y|)) in degrees, averaged: the products
// overflow 8 bits as numpy's uint8 multiplication does, which puts near-identical images near
// 90 degrees. 0 as soon as one pixel is black in either image (its NaN makes the mean NaN, which
// nan_to_num turns into 0).
double sam_degrees(const Image8& truth, const Image8& prediction);

}  // namespace matlearn::paper_compat
