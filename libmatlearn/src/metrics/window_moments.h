#pragma once
// Means, variances and covariance of square windows moved one pixel at a time: what SSIM and UIQ
// (and their paper-compatible forms) are made of. Each window's moments are summed directly, in
// double, from the deviations from the window's own means, so a flat window gives exactly zero
// variance, which UIQ's special cases rely on.
#include <cstddef>
#include <stdexcept>

#include "matbase/image/float_image.h"
#include "metrics/image_pair.h"

namespace matlearn {

struct WindowMoments {
  double mean_x, mean_y;
  double var_x, var_y, cov_xy;  // divided by the pixel count (population moments)
};

// Moments of channel c over the size x size window whose top-left pixel is (x0, y0).
WindowMoments window_moments(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, int c, int x0, int y0, int size);

// Throws std::invalid_argument, naming `metric`, when the image is smaller than the window.
void check_window_fits(const char* metric, const matbase::FloatImage& image, int size);

// The mean over channels of `per_window` averaged over the windows whose anchor pixel, at
// offset (anchor, anchor) from the top-left, lies in the mask.
template <class PerWindow>
double average_over_windows(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask, int size, int anchor,
                            PerWindow per_window) {
  double total = 0.0;
  size_t count = 0;
  for (int c = 0; c < truth.channels; ++c)
    for (int y0 = 0; y0 + size <= truth.height; ++y0)
      for (int x0 = 0; x0 + size <= truth.width; ++x0) {
        const size_t pixel = static_cast<size_t>(y0 + anchor) * static_cast<size_t>(truth.width) +
                             static_cast<size_t>(x0 + anchor);
        if (!inside(mask, pixel)) continue;
        total += per_window(window_moments(truth, prediction, c, x0, y0, size));
        ++count;
      }
  if (count == 0) throw std::invalid_argument("the mask covers no whole window");
  return total / static_cast<double>(count);
}

}  // namespace matlearn
