// SSIM and UIQ, from the moments of square windows (window_moments.h).
#include "matlearn/image_metrics.h"
#include "metrics/image_pair.h"
#include "metrics/window_moments.h"

namespace matlearn {

double ssim(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, double data_range, const matbase::Mask& mask) {
  check_image_pair("SSIM", truth, prediction, mask);
  check_data_range("SSIM", data_range);
  constexpr int kWindow = 7;
  check_window_fits("SSIM", truth, kWindow);
  // scikit-image's structural_similarity defaults: K1 = 0.01, K2 = 0.03, and variances with
  // the sample normalisation N / (N - 1).
  const double c1 = (0.01 * data_range) * (0.01 * data_range), c2 = (0.03 * data_range) * (0.03 * data_range);
  constexpr double kSampleNormalisation = (kWindow * kWindow) / (kWindow * kWindow - 1.0);
  return average_over_windows(truth, prediction, mask, kWindow, kWindow / 2, [&](const WindowMoments& m) {
    const double var_x = kSampleNormalisation * m.var_x, var_y = kSampleNormalisation * m.var_y,
                 cov_xy = kSampleNormalisation * m.cov_xy;
    return (2.0 * m.mean_x * m.mean_y + c1) * (2.0 * cov_xy + c2) /
           ((m.mean_x * m.mean_x + m.mean_y * m.mean_y + c1) * (var_x + var_y + c2));
  });
}

double uiq(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask) {
  check_image_pair("UIQ", truth, prediction, mask);
  constexpr int kWindow = 8;
  check_window_fits("UIQ", truth, kWindow);
  return average_over_windows(truth, prediction, mask, kWindow, kWindow / 2, [](const WindowMoments& m) {
    // Q = 4 cov mu_x mu_y / ((var_x + var_y)(mu_x^2 + mu_y^2)), Wang and Bovik 2002, eq. 1.
    const double variances = m.var_x + m.var_y;
    const double means = m.mean_x * m.mean_x + m.mean_y * m.mean_y;
    if (variances > 0.0 && means > 0.0) return 4.0 * m.cov_xy * m.mean_x * m.mean_y / (variances * means);
    if (means > 0.0) return 2.0 * m.mean_x * m.mean_y / means;  // flat windows
    return 1.0;  // img_qi.m leaves Q = 1 where it cannot divide
  });
}

}  // namespace matlearn
