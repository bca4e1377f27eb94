#pragma once
// The image metrics of the MatPredict paper's appendix ("Closed-form definitions of the eight
// similarity metrics"), computed as defined there on float images: the error metrics pool all
// covered pixels and channels (the appendix's flattened X and Y), the windowed and feature
// metrics work per channel and average; every function states the data range it assumes and
// restricts itself to a mask when one is given. `truth` and `prediction` must have the same
// width, height and channel count; a non-empty mask must have one entry per pixel. Violations
// throw std::invalid_argument naming the problem. Needs no torch: the renderer's benchmarks can
// use these too. (matlearn/paper_compat_metrics.h reproduces what the paper's table computed.)
#include "matbase/image/float_image.h"

namespace matlearn {

// sqrt(mean (Y - X)^2) / data_range.
double rmse(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, double data_range, const matbase::Mask& mask = {});

// 10 log10(range^2 / mean (Y - X)^2) in dB; +infinity for identical images.
double psnr(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, double data_range, const matbase::Mask& mask = {});

// Signal to reconstruction error, PSNR against the image's energy: 10 log10(sum X^2 /
// sum (Y - X)^2) in dB; +infinity for identical images.
double sre(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask = {});

// 1 / (1 + ||Y - X||_F / ||X||_F), in (0, 1]: the appendix's "relative Frobenius norm" form.
double issm(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask = {});

// Structural similarity (Wang et al. 2004) with scikit-image's defaults: 7 x 7 uniform windows,
// K1 = 0.01, K2 = 0.03, sample covariances; per channel, averaged. The map is averaged over the
// centres of the windows that fit inside the image, and of those only centres inside the mask.
double ssim(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, double data_range, const matbase::Mask& mask = {});

// Universal image quality index Q (Wang and Bovik 2002) on 8 x 8 windows moved by one pixel,
// per channel, averaged; windows without variance follow the authors' reference code
// (img_qi.m): Q = 2 mu_x mu_y / (mu_x^2 + mu_y^2), or 1 when both means are 0 too. A window
// counts when its pixel (4, 4) lies inside the mask.
double uiq(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask = {});

// Feature similarity (Zhang et al. 2011) per channel, averaged: phase congruency (Kovesi's,
// with the FSIM reference code's 4 scales and 4 orientations) and Scharr gradient magnitude,
// T1 = 0.85 and T2 = 160 (255 / data_range)^-2; summed over the mask. NaN where neither image
// has any phase congruency (flat images). No downsampling of large images.
double fsim(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, double data_range, const matbase::Mask& mask = {});

// Spectral angle between the channel vectors of each pixel, in degrees, averaged over pixels;
// pixels where either vector is zero have no angle and are left out (NaN when none is left).
double sam_degrees(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask = {});

}  // namespace matlearn
